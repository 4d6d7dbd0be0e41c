"""The one predictor registry: every force predictor by name, one spec syntax for every command.

A *spec* names a predictor and its parameters: ``NAME[:key=value[,key=value...]]``, for example
``eq2``, ``eq2:diameter=braid``, ``axisym:mesh=coarse``, ``surrogate:kind=gp``,
``surrogate:path=DIR`` or ``auto:tolerance=0.02``. ``mkm fem solve --model``, ``mkm report
--models``, ``mkm study`` and ``auto``'s candidates all read specs with :func:`parse_spec` and
build them with :meth:`Spec.build`; ``mkm models`` prints :func:`describe`.

There is one registry of force models, :data:`mkm.fem.ladder.MODELS`: the physics package
registers its rungs and the friction model, this module the application's own (the surrogate
and ``auto``). Each :class:`~mkm.fem.ladder.Entry` carries everything a list elsewhere would:
factory, parameters, label, colour, family, caching, study variants.

In a comma list of specs (``--models eq2,axisym:mesh=coarse,L0_mm=150,surrogate``) an item
with ``=`` and no ``:`` is one more parameter of the spec before it.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from mkm.core.ranges import list_items
from mkm.fem.ladder import (
    C01,
    C10,
    GAP,
    L0,
    MODELS,
    THETA0,
    Entry,
    Parameter,
    entry,
    register,
    unregister,
)
from mkm.fem.limits import range_text
from mkm.surrogate import kinds

if TYPE_CHECKING:  # annotations only: `mkm models` loads no model code
    from mkm.fem.calibration import Calibration
    from mkm.fem.interface import ForceModel
    from mkm.fem.muscle import Muscle


def _surrogate(kind: str | None = None, path: str | None = None,
               accept_mismatch: bool = False, calibration: Calibration | None = None,
               **muscle: float) -> ForceModel:
    """The surrogate of ``kind`` (trained on first use) or loaded from ``path``, at the muscle
    parameters given (``L0_mm``, ``theta0_deg``, ``C10_MPa``, ``C01_MPa``; the others from
    ``calibration``)."""
    if path is not None and kind is not None:
        raise ValueError("surrogate: give kind or path, not both")
    if path is not None:
        from mkm.surrogate.io import load_model

        model = load_model(str(path), accept_mismatch=accept_mismatch)
    else:
        from mkm.surrogate.train import cached_model

        model = cached_model(kind or "best")
    return model.with_parameters(calibration, **muscle) if muscle or calibration else model


def _auto(calibration: Calibration | None = None, **params) -> ForceModel:
    from functools import partial

    from mkm.auto import AutoModel  # here: auto reads its table with pandas

    # a gap not given is the candidates' own (their calibration's): AutoModel.resolved_gap_mm
    return AutoModel(build=partial(build_spec, calibration=calibration), **params)


#: the models ``mkm report`` predicts with unless told: one of each rung, the FE at its medium
#: mesh, and the default surrogate (auto's reference)
REPORT_MODELS = ("eq2", "thickwall", "axisym", "surrogate")

register(Entry(
    "surrogate", _surrogate, "Surrogate",
    "scikit-learn surrogate trained on the FE design (or another FE dataset); refuses "
    "muscle parameters its training did not cover", "surrogate",
    {"kind": Parameter(kinds.describe(), str),
     "path": Parameter("folder of a model saved by `mkm surrogate train`", str),
     "L0_mm": L0, "theta0_deg": THETA0, "C10_MPa": C10, "C01_MPa": C01,
     "accept_mismatch": Parameter("true: load a saved model whose code, calibration or data "
                                  "differ (default false)", bool)},
    colour="tab:red", contract_spec="surrogate"))
register(Entry(
    "auto", _auto, "auto (cheapest within tolerance)",
    "the cheapest predictor whose error bound at the point asked meets a tolerance", "auto",
    {"tolerance": Parameter("largest |Err%| against the finest FE, a fraction (or 2%); "
                            "default 0.02", fraction=True),
     "table": Parameter("study table (default: the shipped one, from `mkm study`)", str),
     "mesh_errors": Parameter("FE mesh error table (default: the shipped one, from `mkm "
                              "study --mesh-muscles N`)", str),
     "per_point": Parameter("true: choose per point instead of one model per sweep", bool),
     "L0_mm": L0, "theta0_deg": THETA0, "C10_MPa": C10, "C01_MPa": C01,
     "gap_mm": GAP},
    colour="tab:purple", contract_spec="auto:tolerance=0.05"))

__all__ = ["MODELS", "REPORT_MODELS", "Spec", "build_spec", "colour",
           "describe", "entries", "entry", "parse_spec", "parse_specs", "register", "unregister"]


def entries() -> dict[str, Entry]:
    """Every registered predictor by name, physics first, in the order they are listed."""
    return {e.name: e for e in MODELS.entries()}


def colour(name: str) -> str:
    """The colour of predictor ``name`` in every figure (grey if unknown)."""
    known = entries().get(name)
    return known.colour if known else "tab:gray"


@dataclass(frozen=True)
class Spec:
    """A parsed predictor spec: its name and parameters (converted to their declared types)."""

    name: str
    params: tuple[tuple[str, Any], ...] = ()

    @property
    def text(self) -> str:
        """The canonical spec text, e.g. ``axisym:mesh=coarse``."""
        if not self.params:
            return self.name
        return self.name + ":" + ",".join(f"{k}={_text(v)}" for k, v in self.params)

    def __str__(self) -> str:
        return self.text

    @property
    def canonical(self) -> str:
        """:attr:`text` less the parameters given at their factory's default
        (``axisym:mesh=medium`` is ``axisym``), so one model spelled two ways is one model. A
        muscle parameter (``L0_mm``) is kept: unset, it is the run's muscle's, not the
        default."""
        import inspect

        from mkm.fem.muscle import MODEL_PARAMETERS

        signature = inspect.signature(self.entry.resolve()).parameters
        kept = tuple((k, v) for k, v in self.params
                     if k in MODEL_PARAMETERS or k not in signature
                     or signature[k].default is inspect.Parameter.empty
                     or signature[k].default != v)
        return Spec(self.name, kept).text

    @property
    def entry(self) -> Entry:
        return entry(self.name)

    @property
    def display_name(self) -> str:
        """The paper's name, with the parameters that set it apart:
        ``Equation 2 (Chou-Hannaford), diameter=braid``."""
        extra = ", ".join(f"{k}={_text(v)}" for k, v in self.params)
        return self.entry.label + (f", {extra}" if extra else "")

    def with_params(self, **params) -> Spec:
        merged = dict(self.params)
        merged.update({k: v for k, v in params.items() if v is not None})
        return Spec(self.name, tuple(sorted(merged.items())))

    def build(self, calibration: Calibration | None = None, muscle: Muscle | None = None,
              **defaults) -> ForceModel:
        """The predictor, with ``calibration`` (None: the shipped one) where it takes one.
        ``defaults`` (a bench run's ``L0_mm``, say) and the ``muscle``'s length, angle and
        rubber (where known) apply where the predictor takes that parameter and the spec does
        not set it; ``defaults`` over the muscle's."""
        params = dict(self.params)
        for key, value in {**self.entry.muscle_defaults(muscle), **defaults}.items():
            if key in self.entry.parameters and value is not None:
                params.setdefault(key, value)
        given = self.entry.check_params(params, shown=self.text)
        return self.entry.construct(given, calibration)


def build_spec(text: str, calibration: Calibration | None = None,
               muscle: Muscle | None = None, **defaults) -> ForceModel:
    """The predictor a spec names: ``parse_spec(text).build(calibration, muscle, **defaults)``."""
    return parse_spec(text).build(calibration, muscle, **defaults)


def _text(value) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def parse_spec(text: str) -> Spec:
    """A :class:`Spec` from ``NAME[:key=value,...]``; ``ValueError`` names what is wrong."""
    name, _, rest = str(text).strip().partition(":")
    name = name.strip()
    if name not in MODELS:
        raise ValueError(f"unknown model {name!r} in {text!r}: expected one of "
                         f"{', '.join(MODELS)} (see `mkm models`)")
    declared = MODELS.entry(name).parameters
    params = {}
    for item in filter(None, (i.strip() for i in rest.split(","))):
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise ValueError(f"model {text!r}: {item!r} is not key=value "
                             "(expected for example axisym:mesh=coarse)")
        key = key.strip()
        if key not in declared:
            raise ValueError(f"model {text!r}: unknown parameter {key!r}: expected some of "
                             f"{', '.join(declared)}")
        params[key] = declared[key].convert(key, value.strip())
    return Spec(name, tuple(sorted(params.items())))


def parse_specs(text: str) -> list[Spec]:
    """Specs from a list (:func:`mkm.core.ranges.list_items`: commas, or semicolons between
    specs whose parameters take commas); ``key=value`` items without ``:`` belong to the spec
    before."""
    groups: list[str] = []
    for item in list_items(text):
        if not item:
            continue
        if "=" in item and ":" not in item and groups:
            groups[-1] += ("," if ":" in groups[-1] else ":") + item
        else:
            groups.append(item)
    if not groups:
        raise ValueError(f"--models {text!r} is empty: expected for example eq2,thickwall")
    specs = [parse_spec(g) for g in groups]
    seen: dict[str, str] = {}
    for group, spec in zip(groups, specs, strict=True):
        same = spec.canonical
        if same in seen:  # scored twice, its rows in every table twice
            raise ValueError(f"--models {text!r} names {same} twice ({seen[same]!r} "
                             f"and {group!r}): expected each model once")
        seen[same] = group
    return specs


def describe() -> str:
    """Every predictor with its parameters and a one-line description (``mkm models``)."""
    lines = []
    for name, known in entries().items():
        lines.append(f"{name:<10} {known.label}: {known.description}")
        for key, parameter in known.parameters.items():
            lines.append(f"{'':<12}{key}: {parameter.description}")
    lines.append("")
    lines.append("spec syntax: NAME[:key=value[,key=value]], e.g. axisym:mesh=coarse, "
                 "eq2:diameter=braid, surrogate:kind=gp, surrogate:path=DIR")
    lines.append("")
    lines += textwrap.wrap("practical range (every physics model accepts it; the FE converges "
                           "over it or names its reason): " + range_text(), 100)
    return "\n".join(lines)
