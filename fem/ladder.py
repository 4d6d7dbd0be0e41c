"""The registry of force models: the physics ladder here, the application adds the rest.

An :class:`Entry` is everything the toolkit knows about a force model, in one place: how to build
it (``"module:Class"``, imported on first use so that a cheap model never loads the FE machinery),
its parameters (declared once, as scikit-learn declares ``_parameter_constraints``; the contract
tests check them against the constructor), its label and colour in every figure, its family,
whether its predictions are worth caching, and the variants the speed-accuracy study scores.

:data:`LADDER` holds the physics rungs (Equation 2, the thick-wall closed form, the FE model).
The application's registry (:mod:`mkm.registry`) reads them and adds the surrogate and ``auto``;
:func:`register` adds a model from outside (a plug-in, a test).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # annotations only: the registry loads without numpy
    from mkm.fem.interface import ForceModel


@dataclass(frozen=True)
class Parameter:
    """A parameter of a force model: what it is (with its unit and default) and its type.

    ``kind`` converts a spec's text (``float``, ``str`` or ``bool``); ``choices`` lists the
    values a text parameter may take (empty: any)."""

    description: str
    kind: type = float
    choices: tuple[str, ...] = ()

    def convert(self, name: str, value: Any) -> Any:
        """``value`` as this parameter's type; ``ValueError`` names the parameter otherwise."""
        if value is None:
            return None
        if self.kind is bool:
            if isinstance(value, bool):
                return value
            if str(value).lower() in ("true", "false"):
                return str(value).lower() == "true"
            raise ValueError(f"{name}={value!r} is invalid: expected true or false")
        if self.kind is float:
            try:
                return float(value)
            except (TypeError, ValueError):
                raise ValueError(f"{name}={value!r} is invalid: expected a number "
                                 f"({self.description})") from None
        value = str(value)
        if self.choices and value not in self.choices:
            raise ValueError(f"{name}={value!r} is invalid: expected one of "
                             f"{', '.join(self.choices)}")
        return value


# Parameters several models share, declared once
THETA0 = Parameter("braid angle at rest [deg]; default calibrated")
L0 = Parameter("length at rest [mm]; default 282")
C10 = Parameter("rubber Mooney-Rivlin C10 [MPa]; default Silastic S (0.0694)")
C01 = Parameter("rubber Mooney-Rivlin C01 [MPa]; default Silastic S (0.0628)")
MESH = Parameter("coarse, medium (default) or fine", str, ("coarse", "medium", "fine"))


@dataclass(frozen=True)
class StudyVariant:
    """A variant the speed-accuracy study scores: its label, its spec, and whether ``auto`` may
    choose it (a model of other physics than the reference, a sliding braid, may not)."""

    label: str
    spec: str
    auto_candidate: bool = True


@dataclass(frozen=True)
class Entry:
    """A registered force model (see the module docstring).

    ``factory`` is a ``"module:Class"`` string or a callable taking the parameters as keywords.
    """

    name: str
    factory: str | Callable[..., ForceModel]
    label: str
    description: str
    family: str
    parameters: dict[str, Parameter] = field(default_factory=dict)
    colour: str = "tab:gray"
    #: seconds per sweep: predictions go through the prediction cache
    expensive: bool = False
    study: tuple[StudyVariant, ...] = ()
    #: the cheapest spec that exercises the model in the contract tests
    contract_spec: str = ""

    def resolve(self) -> Callable[..., ForceModel]:
        """The factory itself (a ``"module:Class"`` string is imported here)."""
        if callable(self.factory):
            return self.factory
        module, name = self.factory.split(":")
        return getattr(import_module(module), name)

    @property
    def module(self) -> str:
        """The module that defines the model (its source version is the model's version)."""
        if callable(self.factory):
            return self.factory.__module__
        return self.factory.split(":")[0]

    def check_params(self, params: dict[str, Any], shown: str | None = None) -> dict[str, Any]:
        """``params`` converted to their declared types; ``ValueError`` names an unknown one."""
        unknown = sorted(set(params) - set(self.parameters))
        if unknown:
            raise ValueError(f"model {shown or self.name!r} takes no parameter "
                             f"{', '.join(unknown)}: expected some of "
                             f"{', '.join(self.parameters) or 'none'}")
        return {k: self.parameters[k].convert(k, v) for k, v in params.items()}

    def build(self, **params) -> ForceModel:
        """The model with ``params`` (None values mean "use the default")."""
        given = self.check_params({k: v for k, v in params.items() if v is not None})
        return self.resolve()(**given)


LADDER: dict[str, Entry] = {
    "eq2": Entry(
        "eq2", "mkm.fem.eq2:Eq2", "Equation 2 (Chou-Hannaford)",
        "Equation 2 of the paper (Chou-Hannaford), thin-walled, no rubber", "closed form",
        {"diameter": Parameter("inner (the paper's D0, default) or braid (D0 + 2 t0)", str,
                               ("inner", "braid")),
         "theta0_deg": THETA0,
         "L0_mm": Parameter("length at rest [mm] (recorded only)")},
        colour="tab:blue",
        study=(StudyVariant("eq2-inner", "eq2:diameter=inner"),
               StudyVariant("eq2-braid", "eq2:diameter=braid")),
        contract_spec="eq2"),
    "thickwall": Entry(
        "thickwall", "mkm.fem.thickwall:ThickWall", "Thick-wall (Klute-Hannaford)",
        "thick-walled Mooney-Rivlin tube in the braid, mid-section closed form "
        "(Klute-Hannaford)", "closed form",
        {"theta0_deg": THETA0, "L0_mm": L0, "C10_MPa": C10, "C01_MPa": C01,
         "gap_mm": Parameter("radial gap between tube and braid at rest [mm]; default the "
                             "calibration's (an identified muscle), else 0")},
        colour="tab:orange", study=(StudyVariant("thickwall", "thickwall"),),
        contract_spec="thickwall"),
    "axisym": Entry(
        "axisym", "mkm.fem.fe.model:Axisym", "FE model (axisymmetric)",
        "axisymmetric finite-element model (scikit-fem), caps and braid included", "FE",
        {"mesh": MESH, "theta0_deg": THETA0, "L0_mm": L0, "C10_MPa": C10, "C01_MPa": C01,
         "braid": Parameter("bonded (default: fibres glued to the rubber) or sliding "
                            "(frictionless sleeve), each with its own calibrated theta0", str,
                            ("bonded", "sliding"))},
        colour="tab:green", expensive=True,
        study=(*(StudyVariant(f"axisym-{m}", f"axisym:mesh={m}")
                 for m in ("coarse", "medium", "fine")),
               StudyVariant("axisym-sliding", "axisym:braid=sliding", auto_candidate=False)),
        contract_spec="axisym:mesh=coarse"),
}


def register(entry: Entry) -> None:
    """Add ``entry`` to the ladder (a name already taken is refused)."""
    if entry.name in LADDER:
        raise ValueError(f"model {entry.name!r} is already registered")
    LADDER[entry.name] = entry


def unregister(name: str) -> None:
    LADDER.pop(name, None)


def model_names() -> list[str]:
    return list(LADDER)


def entry(name: str) -> Entry:
    if name not in LADDER:
        raise ValueError(f"unknown model {name!r}: expected one of {', '.join(LADDER)}")
    return LADDER[name]


def model_class(name: str) -> Callable[..., ForceModel]:
    return entry(name).resolve()


def make_model(name: str, **params) -> ForceModel:
    """Instantiate rung ``name`` with ``params`` (None values mean "use the default")."""
    return entry(name).build(**params)
