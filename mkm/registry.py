"""The one predictor registry: every force predictor by name, one spec syntax for every command.

A *spec* names a predictor and its parameters: ``NAME[:key=value[,key=value...]]``, for example
``eq2``, ``eq2:diameter=braid``, ``axisym:mesh=coarse``, ``surrogate:kind=gp``,
``surrogate:path=DIR`` or ``auto:tolerance=0.02``. ``mkm fem solve --model``, ``mkm report
--models``, ``mkm study`` and ``auto``'s candidates all read specs with :func:`parse_spec` and
build them with :meth:`Spec.build`; ``mkm models`` prints :func:`describe`.

In a comma list of specs (``--models eq2,axisym:mesh=coarse,L0_mm=150,surrogate``) an item
with ``=`` and no ``:`` is one more parameter of the spec before it.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass, field
from functools import partial
from typing import Any

from mkm.auto import AutoModel
from mkm.fem.interface import ForceModel
from mkm.fem.ladder import model_class
from mkm.surrogate import kinds


@dataclass(frozen=True)
class Entry:
    """A registered predictor: a one-line description, the paper's name for it, its family."""

    description: str
    paper_name: str
    family: str
    params: dict[str, str] = field(default_factory=dict)


ENTRIES: dict[str, Entry] = {
    "eq2": Entry("Equation 2 of the paper (Chou-Hannaford), thin-walled, no rubber",
                 "Equation 2 (Chou-Hannaford)", "closed form",
                 {"diameter": "inner (the paper's D0) or braid (D0 + 2 t0); default inner",
                  "theta0_deg": "braid angle at rest [deg]; default calibrated",
                  "L0_mm": "length at rest [mm] (recorded only)"}),
    "thickwall": Entry("thick-walled Mooney-Rivlin tube in the braid, mid-section closed form "
                       "(Klute-Hannaford)", "Thick-wall (Klute-Hannaford)", "closed form",
                       {"theta0_deg": "braid angle at rest [deg]; default calibrated",
                        "L0_mm": "length at rest [mm]; default 282"}),
    "axisym": Entry("axisymmetric finite-element model (scikit-fem), caps and braid included",
                    "FE model (axisymmetric)", "FE",
                    {"mesh": "coarse, medium (default) or fine",
                     "theta0_deg": "braid angle at rest [deg]; default calibrated",
                     "L0_mm": "length at rest [mm]; default 282",
                     "braid": "bonded (default: fibres glued to the rubber) or sliding "
                              "(frictionless sleeve), each with its own calibrated theta0"}),
    "surrogate": Entry("scikit-learn surrogate trained on the FE design (or another FE "
                       "dataset); refuses muscle parameters its training did not cover",
                       "Surrogate", "surrogate",
                       {"kind": kinds.describe(),
                        "path": "folder of a model saved by `mkm surrogate train`",
                        "L0_mm": "length at rest [mm]; default 282",
                        "theta0_deg": "braid angle at rest [deg]; default calibrated",
                        "C10_MPa": "rubber Mooney-Rivlin C10 [MPa]; default Silastic S",
                        "C01_MPa": "rubber Mooney-Rivlin C01 [MPa]; default Silastic S",
                        "accept_mismatch": "true: load a saved model whose code, calibration "
                                           "or data differ (default false)"}),
    "auto": Entry("the cheapest predictor whose measured error meets a tolerance",
                  "auto (cheapest within tolerance)", "auto",
                  {"tolerance": "largest |Err%| against the finest FE, a fraction; default 0.02",
                   "table": "study table (default: the shipped one, from `mkm study`)",
                   "per_point": "true: choose per point instead of one model per sweep"}),
}


@dataclass(frozen=True)
class Spec:
    """A parsed predictor spec: its name and parameters (numbers as floats)."""

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
    def entry(self) -> Entry:
        return ENTRIES[self.name]

    @property
    def display_name(self) -> str:
        """The paper's name, with the parameters that set it apart:
        ``Equation 2 (Chou-Hannaford), diameter=braid``."""
        extra = ", ".join(f"{k}={_text(v)}" for k, v in self.params)
        return self.entry.paper_name + (f", {extra}" if extra else "")

    def with_params(self, **params) -> Spec:
        merged = dict(self.params)
        merged.update({k: v for k, v in params.items() if v is not None})
        return Spec(self.name, tuple(sorted(merged.items())))

    def build(self, **defaults) -> ForceModel:
        """The predictor. ``defaults`` (a bench run's ``L0_mm``, say) apply where the predictor
        takes that parameter and the spec does not set it."""
        params = dict(self.params)
        if self.name == "surrogate":
            for key in SURROGATE_PARAMETERS:
                if defaults.get(key) is not None:
                    params.setdefault(key, defaults[key])
            return _surrogate(params)
        if self.name == "auto":
            factory = partial(AutoModel, build=build_spec)
        else:
            factory = model_class(self.name)
        accepted = inspect.signature(factory).parameters
        unknown = sorted(set(params) - set(accepted))
        if unknown:
            raise ValueError(f"model {self.text!r} takes no parameter {', '.join(unknown)}: "
                             f"expected some of {', '.join(accepted) or 'none'}")
        for key, value in defaults.items():
            if key in accepted and value is not None:
                params.setdefault(key, value)
        return factory(**params)


SURROGATE_PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")


def _surrogate(params: dict) -> ForceModel:
    unknown = sorted(set(params) - set(ENTRIES["surrogate"].params))
    if unknown:
        raise ValueError(f"surrogate takes no parameter {', '.join(unknown)}: expected some of "
                         f"{', '.join(ENTRIES['surrogate'].params)} (surrogate:kind=gp, "
                         "surrogate:path=DIR,L0_mm=150)")
    if "path" in params and "kind" in params:
        raise ValueError("surrogate: give kind or path, not both")
    muscle = {k: float(params[k]) for k in SURROGATE_PARAMETERS if k in params}
    if "path" in params:
        from mkm.surrogate.io import load_model

        model = load_model(str(params["path"]),
                           accept_mismatch=bool(params.get("accept_mismatch", False)))
    else:
        from mkm.surrogate.train import cached_model

        model = cached_model(str(params.get("kind", "best")))
    return model.with_parameters(**muscle) if muscle else model


def _text(value) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def _value(text: str):
    low = text.lower()
    if low in ("true", "false"):
        return low == "true"
    try:
        return float(text)
    except ValueError:
        return text


def parse_spec(text: str) -> Spec:
    """A :class:`Spec` from ``NAME[:key=value,...]``; ``ValueError`` names what is wrong."""
    name, _, rest = str(text).strip().partition(":")
    name = name.strip()
    if name not in ENTRIES:
        raise ValueError(f"unknown model {name!r} in {text!r}: expected one of "
                         f"{', '.join(ENTRIES)} (see `mkm models`)")
    params = {}
    for item in filter(None, (i.strip() for i in rest.split(","))):
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise ValueError(f"model {text!r}: {item!r} is not key=value "
                             "(expected for example axisym:mesh=coarse)")
        key = key.strip()
        if key not in ENTRIES[name].params:
            raise ValueError(f"model {text!r}: unknown parameter {key!r}: expected some of "
                             f"{', '.join(ENTRIES[name].params)}")
        params[key] = _value(value.strip())
    return Spec(name, tuple(sorted(params.items())))


def build_spec(text: str, **defaults) -> ForceModel:
    """The predictor a spec names: ``parse_spec(text).build(**defaults)``."""
    return parse_spec(text).build(**defaults)


def parse_specs(text: str) -> list[Spec]:
    """Specs from a comma list; ``key=value`` items without ``:`` belong to the spec before."""
    groups: list[str] = []
    for item in (i.strip() for i in str(text).split(",")):
        if not item:
            continue
        if "=" in item and ":" not in item and groups:
            groups[-1] += ("," if ":" in groups[-1] else ":") + item
        else:
            groups.append(item)
    if not groups:
        raise ValueError(f"--models {text!r} is empty: expected for example eq2,thickwall")
    return [parse_spec(g) for g in groups]


def describe() -> str:
    """Every predictor with its parameters and a one-line description (``mkm models``)."""
    lines = []
    for name, entry in ENTRIES.items():
        lines.append(f"{name:<10} {entry.paper_name}: {entry.description}")
        for key, text in entry.params.items():
            lines.append(f"{'':<12}{key}: {text}")
    lines.append("")
    lines.append("spec syntax: NAME[:key=value[,key=value]], e.g. axisym:mesh=coarse, "
                 "eq2:diameter=braid, surrogate:kind=gp, surrogate:path=DIR")
    return "\n".join(lines)
