"""The one registry of force models: every predictor by name, physics and application alike.

An :class:`Entry` is everything the toolkit knows about a force model, in one place: how to build
it (``"module:Class"``, imported on first use so that a cheap model never loads the FE machinery),
its parameters (declared once, as scikit-learn declares ``_parameter_constraints``; the contract
tests check them against the constructor), its label and colour in every figure, its family,
whether its predictions are worth caching, and the variants the speed-accuracy study scores.

:data:`MODELS` holds them: the physics rungs (Equation 2, the thick-wall closed form, the FE
model) and the friction-and-creep model are registered here; the application registers the
surrogate and ``auto`` (:mod:`mkm.registry`, which also parses specs); :func:`register` adds a
model from outside (a plug-in, a test). Every list of models elsewhere (the static rungs, the
closed forms identify refits, the study's variants and stability maps, the choices of the
command line) is derived from it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import import_module
from typing import TYPE_CHECKING, Any

from mkm.core.registry import Registry
from mkm.fem.limits import check_value
from mkm.fem.options import BRAIDS, MESH_LEVELS

if TYPE_CHECKING:  # annotations only: the registry loads without numpy
    from mkm.fem.calibration import Calibration
    from mkm.fem.interface import ForceModel
    from mkm.fem.muscle import Muscle


@dataclass(frozen=True)
class Parameter:
    """A parameter of a force model: what it is (with its unit and default) and its type.

    ``kind`` converts a spec's text (``float``, ``str`` or ``bool``); ``choices`` lists the
    values a text parameter may take (empty: any), or is a function that derives them (from the
    registry, when it is read); ``fraction`` marks a float that is a fraction, which a spec may
    write as a percentage too (``tolerance=2%``); ``limit`` names the muscle number of
    :data:`mkm.fem.limits.LIMITS` a float must lie in (a spec's ``L0_mm=5`` is a typo, refused
    as ``--L0 5`` is); ``unit`` is a float's unit (default: the limit's, from its name), in
    which a number typed with another unit of its kind (``gap_mm=500um``) is converted."""

    description: str
    kind: type = float
    choices: tuple[str, ...] | Callable[[], tuple[str, ...]] = ()
    fraction: bool = False
    limit: str = ""
    unit: str | None = None

    def options(self) -> tuple[str, ...]:
        """The values a text parameter may take (empty: any)."""
        return tuple(self.choices()) if callable(self.choices) else self.choices

    def number_unit(self) -> str | None:
        """The unit a float's number is in: ``unit``, else its limit's (``gap_mm``: mm)."""
        return self.unit or (self.limit.rpartition("_")[2] if self.limit else None)

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
            if self.fraction and isinstance(value, str):
                from mkm.core.ranges import parse_fraction

                return parse_fraction(value, name)
            try:
                number = float(value)
            except (TypeError, ValueError):
                if not isinstance(value, str):
                    raise ValueError(f"{name}={value!r} is invalid: expected a number "
                                     f"({self.description})") from None
                from mkm.core.ranges import parse_number

                try:  # a unit, a decimal comma: read as the CLI's options are
                    number = parse_number(value, name, self.number_unit())
                except ValueError as exc:
                    raise ValueError(f"{exc} ({self.description})") from None
            if self.limit:
                return check_value(self.limit, number)
            return number
        value = str(value)
        options = self.options()
        if options and value not in options:
            raise ValueError(f"{name}={value!r} is invalid: expected one of "
                             f"{', '.join(options)}")
        return value


# Parameters several models share, declared once
THETA0 = Parameter("braid angle at rest [deg]; default calibrated", limit="theta0_deg")
L0 = Parameter("length at rest [mm]; default 282", limit="L0_mm")
C10 = Parameter("rubber Mooney-Rivlin C10 [MPa]; default Silastic S (0.0694)", limit="C10_MPa")
C01 = Parameter("rubber Mooney-Rivlin C01 [MPa]; default Silastic S (0.0628)", limit="C01_MPa")
GAP = Parameter("radial gap between tube and braid at rest [mm]; default the calibration's "
                "(an identified muscle), else 0", limit="gap_mm")
MESH = Parameter(f"mesh level: {', '.join(MESH_LEVELS)} (default medium)", str,
                 tuple(MESH_LEVELS))
#: the families whose models are static physics rungs (friction's static model, the rungs the
#: dataset builder and the simulated bench may use)
STATIC_FAMILIES = ("closed form", "FE")


@dataclass(frozen=True)
class StudyVariant:
    """A variant the speed-accuracy study scores: its label, its spec, whether ``auto`` may
    choose it (a model of other physics than the reference, a sliding braid, may not) and
    whether the study maps where it fails (``stability``)."""

    label: str
    spec: str
    auto_candidate: bool = True
    stability: bool = True


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

    def build(self, calibration: Calibration | None = None, muscle: Muscle | None = None,
              **params) -> ForceModel:
        """The model with ``params`` (None values mean "use the default") and, for a model that
        takes one, ``calibration`` (None: the shipped one); ``muscle``: the model of that muscle
        (its length, and its angle and rubber where known, where the model takes them and
        ``params`` do not set them)."""
        given = self.muscle_defaults(muscle)
        given.update({k: v for k, v in params.items() if v is not None})
        return self.construct(self.check_params(given), calibration)

    def muscle_defaults(self, muscle: Muscle | None) -> dict[str, Any]:
        """What of ``muscle`` (:meth:`Muscle.model_parameters`) this model takes."""
        if muscle is None:
            return {}
        return {k: v for k, v in muscle.model_parameters().items() if k in self.parameters}

    def construct(self, params: dict[str, Any], calibration: Calibration | None = None
                  ) -> ForceModel:
        """The model from checked ``params``, given ``calibration`` if it takes one."""
        factory = self.resolve()
        if calibration is not None and self.takes_calibration:
            return factory(**params, calibration=calibration)
        return factory(**params)

    @property
    def takes_calibration(self) -> bool:
        """Whether the factory takes a ``calibration`` (a model with a calibrated default)."""
        import inspect

        return "calibration" in inspect.signature(self.resolve()).parameters


MODELS: Registry[Entry] = Registry("model", "see `mkm models`")


def register(entry: Entry) -> Entry:
    """Add ``entry`` to :data:`MODELS` (a name already taken is refused)."""
    return MODELS.register(entry)


def unregister(name: str) -> None:
    """Remove model ``name`` from :data:`MODELS` (an unknown name is refused)."""
    MODELS.unregister(name)


def entry(name: str) -> Entry:
    """The entry of model ``name``; a one-line ``ValueError`` naming the choices otherwise."""
    return MODELS.entry(name)


def names() -> tuple[str, ...]:
    """Every registered model, in registration order."""
    return MODELS.names()


def static_names() -> tuple[str, ...]:
    """The static physics rungs (:data:`STATIC_FAMILIES`), in registration order."""
    return MODELS.names(lambda e: e.family in STATIC_FAMILIES)


def make_model(name: str, calibration: Calibration | None = None,
               muscle: Muscle | None = None, **params) -> ForceModel:
    """Instantiate model ``name`` with ``params`` (None values mean "use the default"),
    ``calibration`` (None: the shipped one) and, given a ``muscle``, its length, angle and rubber
    (:meth:`Entry.build`)."""
    return entry(name).build(calibration, muscle, **params)


register(Entry(
    "eq2", "mkm.fem.eq2:Eq2", "Equation 2 (Chou-Hannaford)",
    "Equation 2 of the paper (Chou-Hannaford), thin-walled, no rubber", "closed form",
    {"diameter": Parameter("inner (the paper's D0, default) or braid (D0 + 2 t0)", str,
                           ("inner", "braid")),
     "theta0_deg": THETA0,
     "L0_mm": Parameter("length at rest [mm] (recorded only)", limit="L0_mm")},
    colour="tab:blue",
    study=(StudyVariant("eq2-inner", "eq2:diameter=inner"),
           StudyVariant("eq2-braid", "eq2:diameter=braid")),
    contract_spec="eq2"))
register(Entry(
    "thickwall", "mkm.fem.thickwall:ThickWall", "Thick-wall (Klute-Hannaford)",
    "thick-walled Mooney-Rivlin tube in the braid, mid-section closed form "
    "(Klute-Hannaford)", "closed form",
    {"theta0_deg": THETA0, "L0_mm": L0, "C10_MPa": C10, "C01_MPa": C01,
     "gap_mm": GAP},
    colour="tab:orange", study=(StudyVariant("thickwall", "thickwall"),),
    contract_spec="thickwall"))
register(Entry(
    "axisym", "mkm.fem.fe.model:Axisym", "FE model (axisymmetric)",
    "axisymmetric finite-element model (scikit-fem), caps and braid included", "FE",
    {"mesh": MESH, "theta0_deg": THETA0, "L0_mm": L0, "C10_MPa": C10, "C01_MPa": C01,
     "braid": Parameter("bonded (default: fibres glued to the rubber) or sliding "
                        "(frictionless sleeve), each with its own calibrated theta0", str,
                        BRAIDS),
     "gap_mm": GAP},
    colour="tab:green", expensive=True,
    study=(*(StudyVariant(f"axisym-{m}", f"axisym:mesh={m}", stability=m == "medium")
             for m in MESH_LEVELS),
           StudyVariant("axisym-sliding", "axisym:braid=sliding", auto_candidate=False,
                        stability=False)),
    contract_spec="axisym:mesh=coarse"))
register(Entry(
    "friction", "mkm.fem.friction:FrictionCreep", "Static model + friction and creep",
    "a static rung with braid friction (rising and falling branches) and one creep mode, "
    "at the values `mkm identify` wrote into the calibration (default none)", "friction",
    {"static": Parameter("the static rung (default axisym)", str, static_names),
     "direction": Parameter("rising (default), falling or mean (the static force)", str,
                            ("rising", "falling", "mean")),
     "hold_s": Parameter("time held at the pressure [s]; default 0, inf: relaxed", unit="s"),
     "hysteresis_fraction": Parameter("friction band half-width (a fraction); default "
                                      "calibrated, else 0", fraction=True),
     "creep_fraction": Parameter("share of the force creep relaxes (a fraction); default "
                                 "calibrated, else 0", fraction=True),
     "creep_tau_s": Parameter("creep time constant [s]; default calibrated, else 30",
                              unit="s"),
     "mesh": MESH, "L0_mm": L0, "theta0_deg": THETA0, "C10_MPa": C10, "C01_MPa": C01},
    colour="tab:brown", expensive=True,
    contract_spec="friction:static=thickwall,hysteresis_fraction=0.03,creep_fraction=0.02,"
                  "hold_s=30"))
