"""Design a muscle for required forces: surrogate search of the design box, FE verification.

The reference work's purpose is choosing a muscle's geometry "according to the required force"
(Antonelli et al. 2025); this module answers that question with the project's models:

1. **Search.** The candidates of the design box (``D0_mm`` x ``t0_mm``, coarse to fine, times
   the values of ``L0_mm``, ``theta0_deg`` and the rubber that the constraints allow) are
   predicted by the surrogate in vectorised calls, one per requirement and grid. A candidate is
   *feasible* when its predicted force minus the surrogate's uncertainty
   (:func:`surrogate_uncertainty`) meets every requirement, no requirement lies past its braid
   lock, and it fits the housing (outer diameter at the working pressure,
   :func:`outer_diameter_mm`). Feasible candidates are ranked by the objective.
2. **Verification.** The best ``top`` candidates (kept apart by :data:`MIN_SEPARATION` of the
   box so that they are alternatives, not neighbours) are solved with the axisymmetric FE model
   at the converged mesh over a pressure sweep at each requirement's eps. A design meets the
   requirements only when the FE says so; every margin reported is the FE's.
3. **Flags.** ``near_lock`` (eps at or past :data:`NEAR_LOCK_FRACTION` of Equation 2's
   ``eps_max``, or the FE failed at the braid's locking angle), ``threshold_above_pressure``
   (the FE threshold pressure of that eps is at or above the requirement's pressure: the muscle
   does not pull there), ``fe_not_converged``.

:func:`design` is the Python API (a DataFrame of the verified designs); :func:`run_design` also
writes ``designs.csv``, ``designs.json`` (provenance), ``design.html`` and its figures
(:mod:`mkm.design_page`).
"""

from __future__ import annotations

import re
import time
import tomllib
import warnings
from dataclasses import asdict, dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.fem.calibration import calibrated
from mkm.fem.eq2 import LOCKING_ANGLE_DEG, chou_hannaford_eps_max
from mkm.fem.interface import ForceModel
from mkm.fem.materials import MATERIALS
from mkm.fem.paper import L0_MM
from mkm.fem.ranges import parse_fraction, parse_number
from mkm.fem.thickwall import klute_hannaford_threshold_pressure, mid_section_kinematics
from mkm.registry import parse_spec

OBJECTIVES = ("min-outer-diameter", "min-rubber-volume", "max-margin")
DEFAULT_RUBBER = "silastic_s"
#: Search resolution: a coarse grid of 0.5 mm in D0 and 0.1 mm in t0 (the paper's box, 20 x
#: 2 mm: 41 x 21 = 861 candidates per family), refined to 0.05 mm and 0.01 mm over the coarse
#: cells around the best ``SEEDS`` coarse candidates (441 candidates each); 5 values across a
#: range of L0 or theta0. A Gaussian-process surrogate takes ~25 us a point with its std.
COARSE_STEPS, D0_STEP_MM, T0_STEP_MM, SEEDS, AXIS_VALUES = (0.5, 0.1), 0.05, 0.01, 8, 5
#: Verified designs differ by at least 5 % of the box span in some searched parameter.
MIN_SEPARATION = 0.05
#: A requirement is near the braid lock from 75 % of Equation 2's eps_max on: the pressure term
#: of the force has fallen to about a fifth of its value at rest there (theta0 = 32 deg).
NEAR_LOCK_FRACTION = 0.75
#: Surrogate uncertainty: 3 predictive standard deviations when the surrogate gives them (the
#: default surrogate records 95 % of held-out muscles' points within 2: within_2std), else
#: twice the largest held-out error recorded at training, else 5 % of the required force.
STD_FACTOR, RECORDED_ERROR_FACTOR, FALLBACK_RELATIVE_MARGIN = 3.0, 2.0, 0.05
CURVE_STEP_BAR = 0.25  # FE force-pressure curves of the verified designs


# --- the specification --------------------------------------------------------------------------


@dataclass(frozen=True)
class Requirement:
    """One operating point: the muscle must develop at least ``force_N`` [N] at gauge pressure
    ``pressure_bar`` [bar], held at shortening ratio ``eps`` [fraction]."""

    force_N: float
    pressure_bar: float
    eps: float

    def __post_init__(self):
        if not self.force_N > 0:
            raise ValueError(f"requirement {self.label}: force {self.force_N:g} N is invalid: "
                             "expected a force > 0 N")
        if not self.pressure_bar > 0:
            raise ValueError(f"requirement {self.label}: pressure {self.pressure_bar:g} bar is "
                             "invalid: expected a gauge pressure > 0 bar")
        if not 0 <= self.eps < 1:
            raise ValueError(f"requirement {self.label}: eps={self.eps:g} is invalid: expected "
                             "a shortening ratio in [0, 1) (a fraction, or a percentage with %)")

    @property
    def label(self) -> str:
        return f"{self.force_N:g}N@{self.pressure_bar:g}bar,eps={self.eps:g}"


_REQUIREMENT = re.compile(r"^\s*([^@\s]+?)\s*N?\s*@\s*([^,\s]+?)\s*(?:bar)?\s*,\s*eps\s*=\s*"
                          r"(\S+)\s*$", re.IGNORECASE)


def parse_requirement(text: str, name: str = "--require") -> Requirement:
    """A :class:`Requirement` from ``"400N@2bar,eps=0.10"`` (eps also as ``10%``)."""
    match = _REQUIREMENT.match(str(text))
    if not match:
        raise ValueError(f"{name} {text!r} is malformed: expected FORCE N@PRESSURE bar,eps=EPS, "
                         "for example 400N@2bar,eps=0.10")
    force, pressure, eps = match.groups()
    return Requirement(parse_number(force, f"{name} force"),
                       parse_number(pressure, f"{name} pressure"), parse_fraction(eps, name))


def parse_bounds(text, name: str) -> tuple[float, float]:
    """``(low, high)`` from a value (``"37"``, fixed) or a range ``"30:50"``; numbers pass."""
    if isinstance(text, int | float):
        value = parse_number(text, name)
        return value, value
    if isinstance(text, list | tuple):
        parts = list(text)
    else:
        parts = str(text).split(":")
    if len(parts) == 1:
        parts = parts * 2
    if len(parts) != 2:
        raise ValueError(f"{name} {text!r} is malformed: expected a value or low:high "
                         "(for example 30:50)")
    low, high = (parse_number(p, name) for p in parts)
    if low > high:
        raise ValueError(f"{name} {text!r} conflicts with itself: low {low:g} is above high "
                         f"{high:g}")
    return low, high


@dataclass(frozen=True)
class Constraints:
    """The design box and the housing. ``None`` means: D0 and t0 over the surrogate's training
    box, L0 the surrogate's (the paper's 282 mm), theta0 the FE model's calibration
    (``fem/calibration.json`` or ``--calibration FILE``); rubber a name of
    :data:`mkm.fem.materials.MATERIALS` (or several).

    Parameters
    ----------
    D0_mm, t0_mm, L0_mm, theta0_deg : (low, high) or float or "low:high", optional
        Ranges or fixed values [mm, deg].
    rubber : str or tuple of str
        Wall material(s).
    max_outer_diameter_mm : float, optional
        Largest braid diameter of the muscle at the working pressure [mm] (its housing).
    max_pressure_bar : float, optional
        Largest working pressure [bar]; also the pressure the housing check uses.
    """

    D0_mm: tuple[float, float] | None = None
    t0_mm: tuple[float, float] | None = None
    L0_mm: tuple[float, float] | None = None
    theta0_deg: tuple[float, float] | None = None
    rubber: tuple[str, ...] = (DEFAULT_RUBBER,)
    max_outer_diameter_mm: float | None = None
    max_pressure_bar: float | None = None

    def __post_init__(self):
        for key in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg"):
            value = getattr(self, key)
            if value is not None:
                object.__setattr__(self, key, parse_bounds(value, key))
        rubber = (self.rubber,) if isinstance(self.rubber, str) else tuple(self.rubber)
        unknown = [r for r in rubber if r not in MATERIALS]
        if unknown or not rubber:
            raise ValueError(f"rubber {', '.join(unknown) or 'none'} is unknown: expected some "
                             f"of {', '.join(MATERIALS)}")
        object.__setattr__(self, "rubber", rubber)
        for key in ("max_outer_diameter_mm", "max_pressure_bar"):
            value = getattr(self, key)
            if value is not None:
                value = parse_number(value, key)
                if not value > 0:
                    raise ValueError(f"{key}={value:g} is invalid: expected a value > 0")
                object.__setattr__(self, key, value)


SPEC_KEYS = {"objective", "top", "requirement", "constraints"}


def load_spec(path) -> dict:
    """A TOML design spec as ``design`` keyword arguments.

    ``[[requirement]]`` tables (``force_N``, ``pressure_bar``, ``eps``), ``[constraints]`` (the
    fields of :class:`Constraints`), ``objective`` and ``top``. Unknown keys are errors.
    """
    path = Path(path)
    try:
        table = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ValueError(f"--spec {path}: no such file") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"--spec {path} is not valid TOML: {exc}") from None
    unknown = sorted(set(table) - SPEC_KEYS)
    if unknown:
        raise ValueError(f"--spec {path}: unknown key(s) {', '.join(unknown)}: expected some of "
                         f"{', '.join(sorted(SPEC_KEYS))}")
    out: dict = {k: table[k] for k in ("objective", "top") if k in table}
    requirements = []
    for i, item in enumerate(table.get("requirement", []), start=1):
        keys = {"force_N", "pressure_bar", "eps"}
        if not isinstance(item, dict) or set(item) != keys:
            raise ValueError(f"--spec {path}: requirement {i} must have exactly force_N, "
                             "pressure_bar and eps")
        eps = item["eps"]
        eps = parse_fraction(eps) if isinstance(eps, str) else parse_number(eps, "eps")
        requirements.append(Requirement(parse_number(item["force_N"], "force_N"),
                                        parse_number(item["pressure_bar"], "pressure_bar"), eps))
    out["requirements"] = requirements
    constraints = table.get("constraints", {})
    fields = set(Constraints.__dataclass_fields__)
    unknown = sorted(set(constraints) - fields)
    if unknown:
        raise ValueError(f"--spec {path}: unknown constraint(s) {', '.join(unknown)}: expected "
                         f"some of {', '.join(sorted(fields))}")
    out["constraints"] = constraints
    return out


# --- physics of the housing and the lock --------------------------------------------------------


def outer_diameter_mm(D0_mm, t0_mm, theta0_deg, pressure_bar, material=MATERIALS[DEFAULT_RUBBER]):
    """Braid (outer) diameter [mm] of the unloaded muscle at ``pressure_bar``: its largest.

    An unloaded muscle contracts freely until the threshold pressure of its shortening equals the
    supply pressure, ``P*(eps_f) = P`` (thick-wall closed form,
    :func:`mkm.fem.thickwall.klute_hannaford_threshold_pressure`, solved by bisection on
    ``[0, eps_max)``); any load holds it at a smaller shortening and diameter. The braid of
    constant thread length then has ``D_out^2 = (D0 + 2 t0)^2 (1 + eps_f (2 - eps_f) cot^2
    theta0)`` (:func:`mkm.fem.thickwall.mid_section_kinematics`). Mid-section value: the caps
    keep the ends narrower.
    """
    D0, t0, theta0, P = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in
                                              (D0_mm, t0_mm, theta0_deg, pressure_bar)))
    low = np.zeros(D0.shape)
    high = np.broadcast_to(chou_hannaford_eps_max(theta0), D0.shape).copy()
    for _ in range(40):  # eps to 2^-40 of eps_max
        mid = 0.5 * (low + high)
        threshold = klute_hannaford_threshold_pressure(D0, t0, mid, theta0, material.C10_MPa,
                                                       material.C01_MPa)
        below = np.nan_to_num(threshold, nan=np.inf) <= P
        low, high = np.where(below, mid, low), np.where(below, high, mid)
    outer_radius_sq_mm2 = mid_section_kinematics(D0, t0, low, theta0)[5]
    return 2.0 * np.sqrt(outer_radius_sq_mm2)


def rubber_volume_cm3(D0_mm, t0_mm, L0_mm):
    """Volume of the tube wall at rest, ``pi t0 (D0 + t0) L0`` [cm^3] (caps excluded)."""
    return np.pi * np.asarray(t0_mm) * (np.asarray(D0_mm) + np.asarray(t0_mm)) * L0_mm / 1e3


def surrogate_uncertainty(model: ForceModel, prediction, force_N: float) -> tuple[np.ndarray,
                                                                                   str]:
    """Margin [N] the surrogate's force must clear a requirement by, and how it was obtained.

    ``STD_FACTOR`` predictive standard deviations (``force_std_N``) when the surrogate gives
    them; else ``RECORDED_ERROR_FACTOR`` times the largest held-out error recorded when it was
    trained (``metadata["metrics"]``: 80/20 splits and the off-grid test muscles); else
    ``FALLBACK_RELATIVE_MARGIN`` of the required force.
    """
    shape = np.shape(prediction.force_N)
    if "force_std_N" in prediction.extras:
        coverage = ((getattr(model, "metadata", None) or {}).get("metrics") or {}).get(
            "muscle_held_out", {}).get("within_2std", {}).get("median")
        told = (f"; held-out muscles within 2 std: {100 * coverage:.0f} %"
                if coverage is not None else "")
        return (STD_FACTOR * np.asarray(prediction.extras["force_std_N"], dtype=float),
                f"{STD_FACTOR:g} x the surrogate's predictive standard deviation{told}")
    metrics = (getattr(model, "metadata", None) or {}).get("metrics") or {}
    recorded = []
    for table in (metrics, metrics.get("muscle_held_out") or {}):  # per split / per muscle
        if isinstance(table.get("max_abs_test_N"), dict):
            recorded.append(float(table["max_abs_test_N"]["max"]))
    tests = metrics.get("test_muscles")
    if isinstance(tests, list):  # a dict says why they were not evaluated
        recorded += [float(m["max_abs_error_N"]) for m in tests if "max_abs_error_N" in m]
    if recorded:
        worst = max(recorded)
        return (np.full(shape, RECORDED_ERROR_FACTOR * worst),
                f"{RECORDED_ERROR_FACTOR:g} x the largest held-out error recorded at training "
                f"({worst:.3g} N)")
    return (np.full(shape, FALLBACK_RELATIVE_MARGIN * force_N),
            f"{100 * FALLBACK_RELATIVE_MARGIN:g} % of the required force (the surrogate records "
            "no error)")


# --- the search ---------------------------------------------------------------------------------


@dataclass
class Search:
    """Every candidate of the box (one row each) and what the search found."""

    candidates: pd.DataFrame
    requirements: list[Requirement]
    constraints: dict
    objective: str
    working_pressure_bar: float
    uncertainty: str
    seconds: float
    models: dict = field(default_factory=dict)  # (L0, theta0, rubber) -> surrogate

    @property
    def feasible(self) -> pd.DataFrame:
        return self.candidates[self.candidates["feasible"]]


def _axis(bounds, step=None, count=AXIS_VALUES) -> np.ndarray:
    """Values from ``low`` to ``high`` (both included): ``step`` apart or ``count`` of them."""
    low, high = bounds
    if low == high:
        return np.array([float(low)])
    if step:
        count = int(round((high - low) / step)) + 1
    return np.linspace(low, high, count)


PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")  # besides the predict() inputs


def _predicts_at(model) -> dict:
    """The muscle parameters a surrogate predicts at: its own ``parameters`` when it has them,
    else what its training data held fixed (``metadata["dataset"]["fixed"]``); Silastic S
    where nothing is recorded of the rubber."""
    at = dict(getattr(model, "parameters", None) or {})
    if not at:
        fixed = (getattr(model, "metadata", None) or {}).get("dataset", {}).get("fixed") or {}
        at = {k: float(fixed[k]) for k in PARAMETERS if fixed.get(k) is not None}
    rubber = MATERIALS[DEFAULT_RUBBER]
    return {"L0_mm": L0_MM, "C10_MPa": rubber.C10_MPa, "C01_MPa": rubber.C01_MPa} | at


def _surrogate_for(spec, base, L0, theta0, rubber):
    """The surrogate ``base`` (built from ``spec``) at ``(L0, theta0, rubber)``.

    A parameter is passed to the surrogate only when the registry entry lists it (a build
    parameter); any other must equal what the surrogate predicts at, or the constraint conflicts
    with it (named in the ``ValueError``).
    """
    listed = set(spec.entry.parameters) - {k for k, _ in spec.params}
    material = MATERIALS[rubber]
    wanted = {"L0_mm": float(L0), "theta0_deg": float(theta0), "C10_MPa": material.C10_MPa,
              "C01_MPa": material.C01_MPa}
    at = _predicts_at(base)
    params, conflicts = {}, []
    for key, value in wanted.items():
        if key in listed:
            params[key] = value
        elif key in at and not np.isclose(value, at[key], rtol=1e-9, atol=0.0):
            conflicts.append(f"rubber={rubber}" if key.startswith("C") else f"{key}={value:g}")
    if conflicts:
        told = ", ".join(f"{k}={v:g}" for k, v in at.items())
        raise ValueError(f"constraint {', '.join(dict.fromkeys(conflicts))} conflicts with the "
                         f"surrogate {spec.text!r}: it predicts at {told} only")
    if not params:
        return base
    if hasattr(base, "with_parameters"):
        return base.with_parameters(**params)  # the same fitted model, no reload
    return _build(spec.with_params(**params).text)


@lru_cache(maxsize=32)
def _build(text: str) -> ForceModel:
    """Surrogates by spec text, built once per process (loading one takes about a second)."""
    return parse_spec(text).build()


def search(requirements, constraints: Constraints | dict | None = None,
           objective: str = "min-outer-diameter", surrogate: str = "surrogate") -> Search:
    """Predict the candidates of the design box with the surrogate and rank the feasible ones.

    Coarse to fine: every candidate of a coarse grid (:data:`COARSE_STEPS` in D0 and t0, times
    the values of L0, theta0 and rubber), then a fine grid (:data:`D0_STEP_MM`,
    :data:`T0_STEP_MM`) over the coarse cells around the best :data:`SEEDS` coarse candidates
    (:func:`_seeds`): the optimum lies on the boundary of the feasible region, within a coarse
    cell of a feasible coarse candidate.

    Raises ``ValueError`` (one line) for conflicting constraints, requirements past the braid
    lock or outside the surrogate's training box, and when no candidate is feasible (naming the
    closest one and its shortfall per requirement).
    """
    requirements = [parse_requirement(r) if isinstance(r, str) else r for r in requirements]
    if not requirements:
        raise ValueError("no requirement given: expected at least one --require "
                         "FORCE N@PRESSURE bar,eps=EPS (for example 400N@2bar,eps=0.10)")
    if objective not in OBJECTIVES:
        raise ValueError(f"objective {objective!r} is unknown: expected one of "
                         f"{', '.join(OBJECTIVES)}")
    if not isinstance(constraints, Constraints):
        constraints = Constraints(**(constraints or {}))
    spec = parse_spec(surrogate)
    if spec.name != "surrogate":
        raise ValueError(f"--surrogate {surrogate!r}: expected a surrogate spec "
                         "(surrogate, surrogate:kind=gp, surrogate:path=DIR)")
    base = _build(spec.text)
    domain = base.domain
    at = _predicts_at(base)
    theta0_default = float(calibrated("axisym")["theta0_deg"])  # the FE model's, as verified
    box = {"D0_mm": constraints.D0_mm or tuple(domain.D0_mm),
           "t0_mm": constraints.t0_mm or tuple(domain.t0_mm),
           "L0_mm": constraints.L0_mm or (float(at["L0_mm"]),) * 2,
           "theta0_deg": constraints.theta0_deg or (theta0_default,) * 2}
    _check_conflicts(requirements, constraints, box, domain, getattr(base, "box", {}))
    P_work = constraints.max_pressure_bar or max(r.pressure_bar for r in requirements)
    models = {(float(L0), float(theta0), rubber): _surrogate_for(spec, base, L0, theta0, rubber)
              for L0 in _axis(box["L0_mm"]) for theta0 in _axis(box["theta0_deg"])
              for rubber in constraints.rubber}

    start = time.perf_counter()  # the search proper: the surrogates are loaded once
    evaluate = _Evaluator(models, requirements, P_work, constraints.max_outer_diameter_mm)
    D0c = _axis(box["D0_mm"], count=_coarse_count(box["D0_mm"], COARSE_STEPS[0]))
    t0c = _axis(box["t0_mm"], count=_coarse_count(box["t0_mm"], COARSE_STEPS[1]))
    D0, t0 = (a.ravel() for a in np.meshgrid(D0c, t0c, indexing="ij"))
    coarse = pd.concat([evaluate(family, D0, t0) for family in models], ignore_index=True)
    coarse = _rank(coarse, objective)
    seeds = _seeds(coarse)
    dD0 = D0c[1] - D0c[0] if D0c.size > 1 else 0.0
    dt0 = t0c[1] - t0c[0] if t0c.size > 1 else 0.0
    fine = []
    for _, seed in seeds.iterrows():
        D0f = _axis((max(seed["D0_mm"] - dD0, box["D0_mm"][0]),
                     min(seed["D0_mm"] + dD0, box["D0_mm"][1])), D0_STEP_MM)
        t0f = _axis((max(seed["t0_mm"] - dt0, box["t0_mm"][0]),
                     min(seed["t0_mm"] + dt0, box["t0_mm"][1])), T0_STEP_MM)
        D0, t0 = (a.ravel() for a in np.meshgrid(D0f, t0f, indexing="ij"))
        fine.append(evaluate((seed["L0_mm"], seed["theta0_deg"], seed["rubber"]), D0, t0))
    cand = pd.concat([coarse, *fine], ignore_index=True)
    cand = cand.round({"D0_mm": 9, "t0_mm": 9}).drop_duplicates(
        ["D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber"])
    cand = _rank(cand, objective)
    result = Search(cand, requirements, _describe_constraints(constraints, box), objective,
                    float(P_work), evaluate.uncertainty, time.perf_counter() - start, models)
    if not cand["feasible"].any():
        raise ValueError(_infeasible_message(result, constraints))
    return result


def _seeds(coarse: pd.DataFrame) -> pd.DataFrame:
    """Where to refine: the best ``SEEDS`` feasible coarse candidates; while there are fewer, the
    edges of what the coarse grid could not satisfy: the narrowest candidates meeting the forces
    (the housing stops them) and the strongest fitting the housing (the forces stop them)."""
    feasible = coarse[coarse["feasible"]].head(SEEDS)
    if len(feasible) == SEEDS:
        return feasible
    wide = coarse[coarse["meets_forces"] & ~coarse["fits_housing"]].sort_values(
        "outer_diameter_mm").head(SEEDS // 2)
    weak = coarse[coarse["fits_housing"] & ~coarse["meets_forces"]].sort_values(
        "min_margin_pct", ascending=False).head(SEEDS // 2)
    return pd.concat([feasible, wide, weak])


def _coarse_count(bounds, step) -> int:
    return int(np.ceil((bounds[1] - bounds[0]) / step - 1e-9)) + 1


class _Evaluator:
    """Surrogate forces, margins and the housing check of candidates of one design family."""

    def __init__(self, models, requirements, P_work, max_outer_diameter_mm):
        self.models, self.requirements = models, requirements
        self.P_work, self.limit = P_work, max_outer_diameter_mm
        self.uncertainty = ""

    def __call__(self, family, D0, t0) -> pd.DataFrame:
        L0, theta0, rubber = family
        model = self.models[(float(L0), float(theta0), rubber)]
        frame = pd.DataFrame({"D0_mm": D0, "t0_mm": t0, "L0_mm": float(L0),
                              "theta0_deg": float(theta0), "rubber": rubber})
        frame["outer_diameter_mm"] = outer_diameter_mm(D0, t0, theta0, self.P_work,
                                                       MATERIALS[rubber])
        frame["rubber_volume_cm3"] = rubber_volume_cm3(D0, t0, L0)
        eps_max = float(chou_hannaford_eps_max(theta0))
        shortfall = np.empty((len(frame), len(self.requirements)))
        for k, req in enumerate(self.requirements, start=1):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the box lies inside the domain
                pred = model.predict(req.pressure_bar, D0, t0, req.eps)
            u, self.uncertainty = surrogate_uncertainty(model, pred, req.force_N)
            force = np.where(pred.valid & (req.eps < eps_max), pred.force_N, np.nan)
            frame[f"r{k}_surrogate_N"] = force
            frame[f"r{k}_uncertainty_N"] = u
            shortfall[:, k - 1] = np.nan_to_num(req.force_N + u - force, nan=np.inf)
        forces = np.array([r.force_N for r in self.requirements])
        frame["min_margin_pct"] = 100.0 * np.min(-shortfall / forces, axis=1)
        frame["meets_forces"] = (shortfall <= 0).all(axis=1)
        frame["fits_housing"] = (True if self.limit is None
                                 else frame["outer_diameter_mm"] <= self.limit)
        frame["feasible"] = frame["meets_forces"] & frame["fits_housing"]
        return frame


def _check_conflicts(requirements, constraints, box, domain, parameter_box) -> None:
    """One ``ValueError`` naming every conflict between requirements, constraints and models.

    ``parameter_box``: the surrogate's training box of its muscle parameters (``L0_mm``, ...),
    empty for a surrogate of the geometry alone.
    """
    problems = []
    spans = {"D0_mm": tuple(domain.D0_mm), "t0_mm": tuple(domain.t0_mm)}
    spans |= {k: tuple(parameter_box[k]) for k in ("L0_mm", "theta0_deg") if k in parameter_box}
    for key, (dlo, dhi) in spans.items():
        low, high = box[key]
        if low < dlo - 1e-9 * max(abs(dlo), 1) or high > dhi + 1e-9 * max(abs(dhi), 1):
            problems.append(f"{key}={span_text(low, high)} reaches outside the surrogate's "
                            f"training box {dlo:g}:{dhi:g}")
    for rubber in constraints.rubber:
        for key in ("C10_MPa", "C01_MPa"):
            value = getattr(MATERIALS[rubber], key)
            if key in parameter_box and not (parameter_box[key][0] <= value
                                             <= parameter_box[key][1]):
                problems.append(f"rubber={rubber} ({key}={value:g}) lies outside the "
                                f"surrogate's training box {span_text(*parameter_box[key])}")
    if box["t0_mm"][1] >= box["D0_mm"][0] / 2:
        problems.append(f"t0_mm up to {box['t0_mm'][1]:g} mm conflicts with D0_mm from "
                        f"{box['D0_mm'][0]:g} mm: expected t0 < D0/2")
    if not box["L0_mm"][0] > 0:
        problems.append(f"L0_mm {box['L0_mm'][0]:g} is invalid: expected a length > 0 mm")
    low, high = box["theta0_deg"]
    angle_ok = 0 < low and high < LOCKING_ANGLE_DEG
    if not angle_ok:
        problems.append(f"theta0_deg={span_text(low, high)} is invalid: expected 0 < theta0 < "
                        f"{LOCKING_ANGLE_DEG:.1f} deg (the locking angle)")
    # the smallest theta0 has the largest locking shortening
    eps_max = float(chou_hannaford_eps_max(low)) if angle_ok else np.inf
    for k, req in enumerate(requirements, start=1):
        if req.eps >= eps_max:
            problems.append(f"requirement {k} ({req.label}) is past the braid lock: eps_max = "
                            f"{eps_max:.3f} at theta0 = {low:.4g} deg (Equation 2)")
        elif not domain.eps[0] <= req.eps <= domain.eps[1]:
            problems.append(f"requirement {k} ({req.label}): eps={req.eps:g} is outside the "
                            f"surrogate's training box {domain.eps[0]:g}:{domain.eps[1]:g}")
        if not domain.pressure_bar[0] <= req.pressure_bar <= domain.pressure_bar[1]:
            problems.append(f"requirement {k} ({req.label}): {req.pressure_bar:g} bar is outside "
                            f"the surrogate's training box {domain.pressure_bar[0]:g}:"
                            f"{domain.pressure_bar[1]:g} bar")
        if constraints.max_pressure_bar is not None and \
                req.pressure_bar > constraints.max_pressure_bar:
            problems.append(f"requirement {k} ({req.label}) at {req.pressure_bar:g} bar conflicts "
                            f"with the largest working pressure {constraints.max_pressure_bar:g}"
                            " bar")
    if constraints.max_outer_diameter_mm is not None and not problems:
        # the thinnest, narrowest tube of the box, at the largest theta0 and the working pressure
        P = constraints.max_pressure_bar or max(r.pressure_bar for r in requirements)
        smallest = min(float(outer_diameter_mm(box["D0_mm"][0], box["t0_mm"][0], theta0, P,
                                               MATERIALS[rubber]))
                       for theta0 in box["theta0_deg"] for rubber in constraints.rubber)
        if smallest > constraints.max_outer_diameter_mm:
            problems.append(f"max_outer_diameter_mm={constraints.max_outer_diameter_mm:g} "
                            f"conflicts with D0_mm >= {box['D0_mm'][0]:g} and t0_mm >= "
                            f"{box['t0_mm'][0]:g}: the smallest muscle of the box is "
                            f"{smallest:.1f} mm wide at {P:g} bar")
    if problems:
        raise ValueError("; ".join(problems))


def span_text(low: float, high: float) -> str:
    """``37`` for a fixed value, ``30:50`` for a range."""
    return f"{low:g}" if low == high else f"{low:g}:{high:g}"


def _describe_constraints(constraints: Constraints, box: dict) -> dict:
    out = {k: list(v) for k, v in box.items()}
    out["rubber"] = list(constraints.rubber)
    out["max_outer_diameter_mm"] = constraints.max_outer_diameter_mm
    out["max_pressure_bar"] = constraints.max_pressure_bar
    return out


def _rank(cand: pd.DataFrame, objective: str) -> pd.DataFrame:
    """Sort by the objective (ties: the larger margin first)."""
    keys = {"min-outer-diameter": (["outer_diameter_mm", "min_margin_pct"], [True, False]),
            "min-rubber-volume": (["rubber_volume_cm3", "min_margin_pct"], [True, False]),
            "max-margin": (["min_margin_pct", "outer_diameter_mm"], [False, True])}[objective]
    return cand.sort_values(keys[0], ascending=keys[1], kind="stable", ignore_index=True)


def geometry_text(row) -> str:
    """``D0 = ... mm, t0 = ... mm, L0 = ... mm, theta0 = ... deg`` of a design row."""
    text = f"D0 = {row['D0_mm']:.2f} mm, t0 = {row['t0_mm']:.2f} mm"
    return text + f", L0 = {row['L0_mm']:.4g} mm, theta0 = {row['theta0_deg']:.4g} deg"


def _infeasible_message(result: Search, constraints: Constraints) -> str:
    cand = result.candidates
    if cand["meets_forces"].any():  # only the housing is in the way
        best = cand[cand["meets_forces"]].sort_values("outer_diameter_mm").iloc[0]
        return (f"infeasible: no design meets every requirement within max_outer_diameter_mm="
                f"{constraints.max_outer_diameter_mm:g}: the narrowest that does, "
                f"{geometry_text(best)}, is {best['outer_diameter_mm']:.1f} mm wide at "
                f"{result.working_pressure_bar:g} bar")
    pool = cand[cand["fits_housing"]] if cand["fits_housing"].any() else cand
    closest = pool.sort_values("min_margin_pct", ascending=False).iloc[0]
    parts = []
    for k, req in enumerate(result.requirements, start=1):
        force = closest[f"r{k}_surrogate_N"]
        short = req.force_N - force
        parts.append(f"requirement {k} ({req.label}) " + (
            f"short by {short:.0f} N (predicted {force:.0f} N)" if short > 0 else
            f"met with {-short:.0f} N to spare" if np.isfinite(force) else "no valid force"))
    return (f"infeasible: no design in the box meets every requirement with the surrogate's "
            f"margin ({result.uncertainty}); closest: {geometry_text(closest)}: "
            + "; ".join(parts))


def pick(feasible: pd.DataFrame, top: int, box: dict) -> pd.DataFrame:
    """The best ``top`` feasible candidates in rank order, each at least
    :data:`MIN_SEPARATION` of the box span from those before it in some searched parameter."""
    spans = {k: v[1] - v[0] for k, v in box.items() if k != "rubber" and isinstance(v, list)
             and v[1] > v[0]}
    scaled = np.column_stack([feasible[k].to_numpy() / s for k, s in spans.items()]) \
        if spans else np.zeros((len(feasible), 0))
    rubber = feasible["rubber"].to_numpy()
    left = np.ones(len(feasible), dtype=bool)
    chosen = []
    while left.any() and len(chosen) < top:
        i = int(np.argmax(left))
        chosen.append(i)
        near = np.all(np.abs(scaled - scaled[i]) < MIN_SEPARATION, axis=1) & (rubber == rubber[i])
        left &= ~near
    return feasible.iloc[chosen].reset_index(drop=True)


# --- FE verification ----------------------------------------------------------------------------


def fe_model(mesh: str, L0_mm: float, theta0_deg: float, rubber: str) -> ForceModel:
    """The axisymmetric FE model (registry ``axisym``) of one design family."""
    material = MATERIALS[rubber]
    return parse_spec(f"axisym:mesh={mesh}").build(
        L0_mm=float(L0_mm), theta0_deg=float(theta0_deg), C10_MPa=material.C10_MPa,
        C01_MPa=material.C01_MPa)


def verify(designs: pd.DataFrame, requirements, mesh: str = "medium",
           curve_to_bar: float | None = None, progress: bool = False, cache_dir=None):
    """FE forces of ``designs`` at every requirement, and their force-pressure curves.

    One FE sweep per design and distinct eps, through the requirements' pressures and
    ``0:curve_to_bar:0.25`` bar (the curve also gets the FE threshold pressure, force 0), kept in
    the prediction cache ``cache_dir`` (:mod:`mkm.prediction_cache`; None: no cache). Adds per
    requirement ``r<k>_fe_N``, ``r<k>_fe_margin_N``,
    ``r<k>_fe_margin_pct``, ``r<k>_threshold_bar``, ``r<k>_meets``; then ``meets_all``,
    ``min_fe_margin_pct``, ``flags`` and ``fe_failure``. Returns the designs, the curves, the wall
    time [s], the FE models by ``(L0, theta0, rubber)`` and how many sweeps came from the cache.
    """
    from mkm.prediction_cache import cached_predict
    from mkm.progress import progress_bar

    start = time.perf_counter()
    designs = designs.copy()
    top_P = max([r.pressure_bar for r in requirements] + [curve_to_bar or 0.0])
    grid = np.round(np.arange(0.0, top_P + 1e-9, CURVE_STEP_BAR), 6)
    eps_levels = sorted({r.eps for r in requirements})
    models: dict = {}
    curves, per_design, hits = [], [], 0
    bar = progress_bar(len(designs) * len(eps_levels), "FE verification", progress, "sweep")
    with bar:
        for _, row in designs.iterrows():
            key = (row["L0_mm"], row["theta0_deg"], row["rubber"])
            if key not in models:
                models[key] = fe_model(mesh, *key)
            results = {}
            for eps in eps_levels:
                P = np.union1d(grid, [r.pressure_bar for r in requirements if r.eps == eps])
                pred, hit = cached_predict(models[key], P, row["D0_mm"], row["t0_mm"], eps,
                                           cache_dir=cache_dir)
                hits += hit
                frame = pred.to_frame()
                results[eps] = frame
                curve = frame[["eps", "pressure_bar", "force_N", "converged"]]
                threshold = float(frame["threshold_pressure_bar"].iloc[0])
                if 0 < threshold < P[-1]:  # the kink where the force leaves zero: no solve
                    curve = pd.concat([curve, pd.DataFrame({
                        "eps": [eps], "pressure_bar": [threshold], "force_N": [0.0],
                        "converged": [True]})], ignore_index=True)
                curves.append(curve.assign(design=row["rank"]).sort_values("pressure_bar"))
                bar.update()
            per_design.append(_judge(row, requirements, results))
    designs = pd.concat([designs, pd.DataFrame(per_design)], axis=1)
    curves = pd.concat(curves, ignore_index=True) if curves else pd.DataFrame()
    return designs, curves, time.perf_counter() - start, models, hits


def _judge(row, requirements, results) -> dict:
    out, flags, failures, margins = {}, [], [], []
    eps_max = float(chou_hannaford_eps_max(row["theta0_deg"]))
    for k, req in enumerate(requirements, start=1):
        frame = results[req.eps]
        point = frame[np.isclose(frame["pressure_bar"], req.pressure_bar)].iloc[0]
        force = float(point["force_N"]) if point["valid"] else np.nan
        failure = str(point.get("failure", "") or "")
        threshold = float(point.get("threshold_pressure_bar", np.nan))
        out[f"r{k}_fe_N"] = force
        out[f"r{k}_fe_margin_N"] = force - req.force_N
        out[f"r{k}_fe_margin_pct"] = 100.0 * (force - req.force_N) / req.force_N
        out[f"r{k}_threshold_bar"] = threshold
        out[f"r{k}_meets"] = bool(np.isfinite(force) and force >= req.force_N)
        margins.append(out[f"r{k}_fe_margin_pct"])
        if req.eps >= NEAR_LOCK_FRACTION * eps_max or "locking angle" in failure:
            flags.append(f"r{k}:near_lock")
        if np.isfinite(threshold) and threshold >= req.pressure_bar:
            flags.append(f"r{k}:threshold_above_pressure")
        if not point["converged"] or not np.isfinite(force):
            flags.append(f"r{k}:fe_not_converged")
            failures.append(f"r{k}: {failure or 'no valid force'}")
    out["meets_all"] = all(out[f"r{k}_meets"] for k in range(1, len(requirements) + 1))
    out["min_fe_margin_pct"] = float(np.min(margins)) if not np.isnan(margins).any() else np.nan
    out["flags"] = ";".join(flags)
    out["fe_failure"] = "; ".join(failures)
    return out


# --- the API ------------------------------------------------------------------------------------


@dataclass
class DesignResult:
    """What :func:`run_design` found: the verified designs, their FE curves, the search."""

    designs: pd.DataFrame
    curves: pd.DataFrame
    search: Search
    mesh: str
    fe_seconds: float
    fe_models: dict
    fe_cached: int = 0
    files: dict = field(default_factory=dict)

    @property
    def chosen(self):
        """The best design the FE confirms (a row), or None."""
        ok = self.designs[self.designs["meets_all"]]
        return ok.iloc[0] if len(ok) else None

    def summary(self) -> str:
        s = self.search
        cached = f" ({self.fe_cached} sweeps from the cache)" if self.fe_cached else ""
        ok = int(self.designs["meets_all"].sum())
        text = (f"{len(s.candidates)} candidates searched in {s.seconds:.2f} s, "
                f"{int(s.candidates['feasible'].sum())} feasible by the surrogate; "
                f"{len(self.designs)} verified by the FE (axisym, {self.mesh} mesh) in "
                f"{self.fe_seconds:.1f} s{cached}, {ok} meet{'s' if ok == 1 else ''} every "
                "requirement")
        best = self.chosen
        if best is None:
            return text + ": none confirmed, see the table's FE margins"
        return (text + f"; chosen: {geometry_text(best)}, outer diameter "
                f"{best['outer_diameter_mm']:.1f} mm at {s.working_pressure_bar:g} bar")


DESIGN_COLUMNS = ["rank", "D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber",
                  "outer_diameter_mm", "rubber_volume_cm3"]


def run_design(requirements=(), constraints=None, objective=None, top=None, spec=None,
               mesh: str = "medium", surrogate: str = "surrogate",
               progress: bool = False, cache_dir=None) -> DesignResult:
    """Search and verify (:func:`mkm.design_page.write_design` writes the files).

    ``spec``: a TOML file (:func:`load_spec`); ``requirements`` are added to its requirements,
    ``constraints`` (a dict) override its constraints, ``objective``/``top`` its own.
    ``cache_dir``: FE prediction cache (None: solve every sweep).
    """
    base = load_spec(spec) if spec else {"requirements": [], "constraints": {}}
    requirements = list(base["requirements"]) + [
        parse_requirement(r) if isinstance(r, str) else r for r in requirements]
    merged = dict(base["constraints"])
    if isinstance(constraints, Constraints):
        merged.update({k: v for k, v in asdict(constraints).items()
                       if v is not None and not (k == "rubber" and v == (DEFAULT_RUBBER,))})
    else:
        merged.update({k: v for k, v in (constraints or {}).items() if v is not None})
    objective = objective or base.get("objective", "min-outer-diameter")
    top = top if top is not None else base.get("top", 5)
    if isinstance(top, bool) or not isinstance(top, int) or top < 1:
        raise ValueError(f"top={top!r} is invalid: expected a whole number of designs >= 1")
    found = search(requirements, merged, objective, surrogate)
    chosen = pick(found.feasible, top, found.constraints)
    chosen.insert(0, "rank", np.arange(1, len(chosen) + 1))
    designs, curves, seconds, fe_models, hits = verify(
        chosen, found.requirements, mesh, found.working_pressure_bar, progress, cache_dir)
    order = ["min_fe_margin_pct", "rank"] if objective == "max-margin" else ["rank"]
    designs = designs.sort_values(["meets_all", *order], ascending=[False] + [
        objective != "max-margin"] + [True] * (len(order) - 1), kind="stable",
        ignore_index=True)
    n = len(found.requirements)
    columns = DESIGN_COLUMNS + [c for k in range(1, n + 1) for c in (
        f"r{k}_surrogate_N", f"r{k}_uncertainty_N", f"r{k}_fe_N", f"r{k}_fe_margin_N",
        f"r{k}_fe_margin_pct", f"r{k}_threshold_bar", f"r{k}_meets")] + [
        "meets_all", "min_fe_margin_pct", "flags", "fe_failure"]
    return DesignResult(designs[columns], curves, found, mesh, seconds, fe_models, hits)


def design(requirements, constraints=None, objective: str = "min-outer-diameter", *,
           top: int = 5, mesh: str = "medium", surrogate: str = "surrogate",
           progress: bool = False, cache_dir=None) -> pd.DataFrame:
    """Verified designs for force requirements, best first: the Python API of ``mkm design``.

    Parameters
    ----------
    requirements : list of Requirement or str
        Operating points, ``Requirement(force_N, pressure_bar, eps)`` or ``"400N@2bar,eps=0.10"``.
    constraints : Constraints or dict, optional
        Ranges or fixed values of ``D0_mm``, ``t0_mm``, ``L0_mm``, ``theta0_deg``; ``rubber``;
        ``max_outer_diameter_mm``, ``max_pressure_bar`` (see :class:`Constraints`).
    objective : {"min-outer-diameter", "min-rubber-volume", "max-margin"}
    top : int
        Designs verified with the FE model.
    mesh : {"coarse", "medium", "fine"}
        FE mesh; ``medium`` is the converged one (``coarse`` for quick checks only).
    surrogate : str
        Registry spec of the surrogate that searches the box.
    progress : bool
        Progress bar of the FE verification on stderr (when it is a terminal).
    cache_dir : path, optional
        FE prediction cache (:mod:`mkm.prediction_cache`); None solves every sweep.

    Returns
    -------
    pandas.DataFrame
        One row per verified design: geometry, outer diameter at the working pressure [mm],
        rubber volume [cm^3], per requirement ``k`` the surrogate's force and uncertainty and the
        FE force, margin [N, %], threshold pressure [bar] and verdict ``r<k>_meets``;
        ``meets_all`` (the FE's verdict), ``flags``. Sorted: designs the FE confirms first, in
        objective order. ``attrs`` holds the requirements, constraints and search summary.
    """
    result = run_design(requirements, constraints, objective, top, mesh=mesh,
                        surrogate=surrogate, progress=progress, cache_dir=cache_dir)
    frame = result.designs.copy()
    frame.attrs.update(design_record(result))
    return frame


def design_record(result: DesignResult) -> dict:
    """What ``designs.json`` records besides provenance (also the ``attrs`` of :func:`design`)."""
    s = result.search
    return {"requirements": [asdict(r) | {"label": f"r{k}: {r.label}"}
                             for k, r in enumerate(s.requirements, start=1)],
            "constraints": s.constraints, "objective": s.objective,
            "working_pressure_bar": s.working_pressure_bar,
            "surrogate_uncertainty": s.uncertainty,
            "search": {"candidates": len(s.candidates),
                       "feasible": int(s.candidates["feasible"].sum()),
                       "seconds": s.seconds,
                       "resolution": {"coarse_D0_mm": COARSE_STEPS[0],
                                      "coarse_t0_mm": COARSE_STEPS[1], "D0_mm": D0_STEP_MM,
                                      "t0_mm": T0_STEP_MM, "refined_seeds": SEEDS,
                                      "L0_mm and theta0_deg values per range": AXIS_VALUES}},
            "verification": {"model": "axisym", "mesh": result.mesh,
                             "seconds": result.fe_seconds,
                             "sweeps_from_cache": result.fe_cached,
                             "near_lock_fraction_of_eps_max": NEAR_LOCK_FRACTION},
            "summary": result.summary()}
