"""The surrogate search of the design box: candidates, feasibility, ranking, alternatives."""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field, replace
from functools import lru_cache

import numpy as np
import pandas as pd

from mkm.auto import RANGE_SPEC, RANGE_STD_FACTOR, REFERENCE_SPEC, STD_FACTOR
from mkm.design.robust import describe, requirement_margin
from mkm.design.spec import (
    DEFAULT_OBJECTIVE,
    DEFAULT_RUBBER,
    NEAR_LOCK_FRACTION,
    OBJECTIVES,
    Constraints,
    Hints,
    Requirement,
    parse_requirement,
    rubber_of,
)
from mkm.fem.calibration import Calibration, calibrated
from mkm.fem.eq2 import LOCKING_ANGLE_DEG, chou_hannaford_eps_max
from mkm.fem.interface import ForceModel
from mkm.fem.limits import PRACTICAL_RANGE, check_gap, limit_text, outside
from mkm.fem.paper import L0_MM
from mkm.fem.thickwall import outer_diameter_mm
from mkm.registry import parse_spec
from mkm.surrogate import kinds

#: Search resolution: a coarse grid of 0.5 mm in D0 and 0.1 mm in t0 (the paper's box, 20 x
#: 2 mm: 41 x 21 = 861 candidates per family), refined to 0.05 mm and 0.01 mm over the coarse
#: cells around the best ``SEEDS`` coarse candidates (441 candidates each); 5 values across a
#: range of L0 or theta0, refined around the best design by halving steps down to
#: ``AXIS_RESOLUTION`` (:func:`_refine_axes`). A Gaussian-process surrogate answers each point
#: with its std in microseconds (benchmarks/bench_design.py times the search:
#: docs/measured/design.json).
COARSE_STEPS, D0_STEP_MM, T0_STEP_MM, SEEDS, AXIS_VALUES = (0.5, 0.1), 0.05, 0.01, 8, 5
#: The finest step of a searched range of L0 [mm] or theta0 [deg]: 0.1 deg moves the outer
#: diameter of a design by about 0.15 mm (1.4 mm per deg near the paper's muscle)
AXIS_RESOLUTION = {"L0_mm": 1.0, "theta0_deg": 0.1}
#: Coarse cells of D0 and t0 either side of the best design where a new L0 or theta0 is tried:
#: a step of the angle moves the boundary of what meets a force by a few of them. The FE
#: search's cells (:data:`FE_SEARCH_STEPS`) are four times the surrogate's in D0 and five in
#: t0: one either side, 9 FE sweeps a value tried.
AXIS_NEIGHBOURHOOD_CELLS = 4
FE_AXIS_NEIGHBOURHOOD_CELLS = 1
#: Verified designs differ by at least 5 % of the box span in some searched parameter.
MIN_SEPARATION = 0.05
#: Surrogate uncertainty: the predictive standard deviation times auto's factor of the kind
#: (:func:`std_factor`), else twice the largest held-out error recorded at training, else 5 %
#: of the required force.
RECORDED_ERROR_FACTOR, FALLBACK_RELATIVE_MARGIN = 2.0, 0.05


#: Where the surrogate was not trained (a requirement above its pressures or outside its eps,
#: a box beyond its geometry or muscle parameters), the FE model itself searches: on its coarse
#: mesh (a few tenths of a second a sweep), a coarser grid of D0 x t0 without a fine one, the
#: ranges of L0 and theta0 refined as the surrogate's are (:func:`_refine_axes`), and the
#: requirements' margin of :data:`FALLBACK_RELATIVE_MARGIN`; the verification then solves the
#: converged mesh.
#: Its box, and the largest pressure it designs for, are the practical range's.
FE_SEARCH_BOX = {"D0_mm": PRACTICAL_RANGE.D0_mm, "t0_mm": PRACTICAL_RANGE.t0_mm}
#: The geometry the search box spans (the surrogate's training box spans them too)
BOX_KEYS = ("D0_mm", "t0_mm")
BOX_NAMES = {"D0_mm": "D0", "t0_mm": "t0", "L0_mm": "L0", "theta0_deg": "theta0"}
_KEY_OF = {name: key for key, name in BOX_NAMES.items()}
FE_SEARCH_MAX_PRESSURE_BAR = PRACTICAL_RANGE.pressure_bar[1]
FE_SEARCH_STEPS = (2.0, 0.5)
FE_SEARCH_MESH = "coarse"


# --- physics of the housing and the lock --------------------------------------------------------


def _constants(rubber: str, calibration: Calibration | None) -> tuple[float, float]:
    """``(C10_MPa, C01_MPa)`` of a named rubber."""
    material = rubber_of(rubber, calibration)
    return material.C10_MPa, material.C01_MPa


def rubber_volume_cm3(D0_mm, t0_mm, L0_mm):
    """Volume of the tube wall at rest, ``pi t0 (D0 + t0) L0`` [cm^3] (caps excluded)."""
    return np.pi * np.asarray(t0_mm) * (np.asarray(D0_mm) + np.asarray(t0_mm)) * L0_mm / 1e3


def std_factor(model: ForceModel) -> float:
    """How many of ``model``'s predictive standard deviations bound its error: the factor
    :mod:`mkm.auto` bounds the same surrogate with, :data:`mkm.auto.RANGE_STD_FACTOR` for the
    practical range's (its std is heavy-tailed per call), else :data:`mkm.auto.STD_FACTOR`."""
    return RANGE_STD_FACTOR if getattr(model, "kind", None) == kinds.RANGE else STD_FACTOR


def surrogate_uncertainty(model: ForceModel, prediction, force_N: float) -> tuple[np.ndarray,
                                                                                   str]:
    """Margin [N] the surrogate's force must clear a requirement by, and how it was obtained.

    :func:`std_factor` predictive standard deviations (``force_std_N``) when the surrogate
    gives them; else ``RECORDED_ERROR_FACTOR`` times the largest held-out error recorded when it was
    trained (``metadata["metrics"]``: 80/20 splits and the off-grid test muscles); else
    ``FALLBACK_RELATIVE_MARGIN`` of the required force.
    """
    shape = np.shape(prediction.force_N)
    margin = model.error_margin() if hasattr(model, "error_margin") else None
    if "force_std_N" in prediction.extras:
        covered = margin.within_2std if margin is not None else None
        told = (f"; held-out muscles within 2 std: {100 * covered:.0f} %"
                if covered is not None else "")
        factor = std_factor(model)
        return (factor * np.asarray(prediction.extras["force_std_N"], dtype=float),
                f"{factor:g} x the surrogate's predictive standard deviation{told}")
    if margin is not None and margin.worst_abs_error_N is not None:
        worst = margin.worst_abs_error_N
        return (np.full(shape, RECORDED_ERROR_FACTOR * worst),
                f"{RECORDED_ERROR_FACTOR:g} x the largest held-out error recorded at training "
                f"({worst:.3g} N, {margin.measured_on})")
    return (np.full(shape, FALLBACK_RELATIVE_MARGIN * force_N),
            f"{100 * FALLBACK_RELATIVE_MARGIN:g} % of the required force (the searching model "
            "records no error)")


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
    #: why the FE model searched instead of the surrogate ("" when the surrogate did)
    fe_search: str = ""
    #: the spec of the surrogate that searched, and why when it is not the one asked for
    searcher: str = "surrogate"
    searcher_note: str = ""
    #: the default braid angle's and the ``calibrated`` rubber's (None: the shipped one)
    calibration: Calibration | None = None
    #: the surrogate's training box of the geometry, ``{"D0_mm": [low, high], "t0_mm": ...}``
    surrogate_box: dict = field(default_factory=dict)
    #: what set each searched range of :data:`BOX_KEYS`: "as constrained", "the practical
    #: range" (the FE search's default) or "the surrogate's"
    box_origin: dict = field(default_factory=dict)
    #: the radial gap between tube and braid of the muscles as built [mm] (0: none)
    gap_mm: float = 0.0
    #: the length searched when no L0 was given, where it came from (the default, or the
    #: identified muscle's of ``calibration``: :func:`mkm.identify.band.identified_lengths`) and
    #: how to set it (:func:`_length_note`), else ""
    length_note: str = ""
    #: how the user set the options: the form every hint names them in, and the user's bounds
    hints: Hints = field(default_factory=Hints)

    @property
    def feasible(self) -> pd.DataFrame:
        return self.candidates[self.candidates["feasible"]]

    @property
    def box(self) -> dict:
        """The searched ranges of :data:`BOX_KEYS`, ``{key: [low, high]}``."""
        return {k: list(self.constraints[k]) for k in BOX_KEYS}

    def edges(self, row) -> list[str]:
        """What of a design ``row`` sits on an end of what was searched: the box and the
        rubbers (:func:`box_edges`). A requirement's pressure is none: it is the requirement's,
        not searched, and a design at another pressure would not meet that requirement."""
        return box_edges(row, self.constraints, self.calibration, self.hints)

    def box_note(self) -> str:
        """The searched D0 x t0 box where it is not the surrogate's training box (and
        whether it reaches beyond it), else ""."""
        if not self.surrogate_box or all(np.allclose(self.box[k], self.surrogate_box[k])
                                         for k in BOX_KEYS):
            return ""
        beyond = any(low < slo - 1e-9 or high > shi + 1e-9 for (low, high), (slo, shi) in
                     ((self.box[k], self.surrogate_box[k]) for k in BOX_KEYS))
        origins = set(self.box_origin.values())
        origin = (origins.pop() if len(origins) == 1 else ", ".join(
            f"{BOX_NAMES[k]} {o}" for k, o in self.box_origin.items()))
        where = "beyond" if beyond else "inside"
        return (f"searched the box {box_text(self.box)} ({origin}), {where} the surrogate's "
                f"{box_text(self.surrogate_box)}")


def _axis(bounds, step=None, count=AXIS_VALUES) -> np.ndarray:
    """Values from ``low`` to ``high`` (both included): ``step`` apart or ``count`` of them."""
    low, high = bounds
    if low == high:
        return np.array([float(low)])
    if step:
        count = int(round((high - low) / step)) + 1
    return np.linspace(low, high, count)


PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")  # besides the predict() inputs


def _predicts_at(model, calibration: Calibration | None) -> dict:
    """The muscle parameters a surrogate predicts at: its own ``parameters`` when it has them,
    else what its training data held fixed (``metadata["dataset"]["fixed"]``); Silastic S
    where nothing is recorded of the rubber."""
    at = dict(getattr(model, "parameters", None) or {})
    if not at:
        fixed = (getattr(model, "metadata", None) or {}).get("dataset", {}).get("fixed") or {}
        at = {k: float(fixed[k]) for k in PARAMETERS if fixed.get(k) is not None}
    rubber = rubber_of(DEFAULT_RUBBER, calibration)
    return {"L0_mm": L0_MM, "C10_MPa": rubber.C10_MPa, "C01_MPa": rubber.C01_MPa} | at


def _surrogate_for(spec, base, L0, theta0, rubber, calibration: Calibration | None):
    """The surrogate ``base`` (built from ``spec``) at ``(L0, theta0, rubber)``.

    A parameter is passed to the surrogate only when the registry entry lists it (a build
    parameter); any other must equal what the surrogate predicts at, or the constraint conflicts
    with it (named in the ``ValueError``).
    """
    listed = set(spec.entry.parameters) - {k for k, _ in spec.params}
    material = rubber_of(rubber, calibration)
    wanted = {"L0_mm": float(L0), "theta0_deg": float(theta0), "C10_MPa": material.C10_MPa,
              "C01_MPa": material.C01_MPa}
    at = _predicts_at(base, calibration)
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
        return base.with_parameters(calibration, **params)  # the same fitted model, no reload
    return _build(spec.with_params(**params).text, calibration)


@lru_cache(maxsize=32)
def _build(text: str, calibration: Calibration | None) -> ForceModel:
    """Surrogates by spec text, built once per process (loading one takes about a second)."""
    return parse_spec(text).build(calibration)


def search(requirements, constraints: Constraints | dict | None = None,
           objective: str = DEFAULT_OBJECTIVE, surrogate: str = "surrogate",
           tolerances=None, probability: float = 0.95,
           calibration: Calibration | None = None, hints: Hints | None = None) -> Search:
    """Predict the candidates of the design box with the surrogate and rank the feasible ones.

    Coarse to fine: every candidate of a coarse grid (:data:`COARSE_STEPS` in D0 and t0, times
    the values of L0, theta0 and rubber), then a fine grid (:data:`D0_STEP_MM`,
    :data:`T0_STEP_MM`) over the coarse cells around the best :data:`SEEDS` coarse candidates
    (:func:`_seeds`): the optimum lies on the boundary of the feasible region, within a coarse
    cell of a feasible coarse candidate.

    ``calibration`` gives the default braid angle and the ``calibrated`` rubber (None: the
    shipped one). ``hints``: how the user set the options (:class:`~mkm.design.spec.Hints`;
    None: the flags, none given).

    With ``tolerances`` (:class:`mkm.fem.tolerances.Tolerances`), a candidate must meet every
    requirement with ``probability`` when built to them (:mod:`mkm.design.robust`) instead of
    clearing the surrogate's margin.

    Raises ``ValueError`` (one line) for conflicting constraints, requirements past the braid
    lock or outside the surrogate's training box, and when no candidate is feasible (naming the
    closest one and its shortfall per requirement).
    """
    requirements = [parse_requirement(r) if isinstance(r, str) else r for r in requirements]
    hints = hints or Hints()
    if not requirements:
        raise ValueError("no requirement given: expected at least one --require "
                         "FORCE N@PRESSURE bar,eps=EPS (for example 400N@2bar,eps=0.10)")
    if objective not in OBJECTIVES:
        raise ValueError(f"objective {objective!r} is unknown: expected one of "
                         f"{', '.join(OBJECTIVES)}")
    if not isinstance(constraints, Constraints):
        constraints = Constraints(**(constraints or {}))
    constraints, rubber_note = _distinct_rubbers(constraints, calibration)
    constraints, length_origin = _identified_length(constraints, calibration)
    spec = parse_spec(surrogate)
    if spec.name != "surrogate":
        raise ValueError(f"--surrogate {surrogate!r}: expected a surrogate spec "
                         "(surrogate, surrogate:kind=gp, surrogate:path=DIR)")
    base = _build(spec.text, calibration)
    domain = base.domain
    parameter_box = getattr(base, "box", {})
    # the FE model's, as verified: searched where no --theta0 is given, so held to the box too
    theta0_default = float(calibrated("axisym", calibration)["theta0_deg"])
    outside = _outside_surrogate(requirements, constraints, domain, parameter_box, calibration,
                                 theta0_default)
    searcher_note = ""
    gap = constraints.gap_mm or 0.0
    # with a gap the FE model searches wherever the request lies: no surrogate models one
    if outside and spec.text == REFERENCE_SPEC and not gap:
        # the practical range's surrogate searches where it covers what the default's box does not
        wider = parse_spec(RANGE_SPEC)
        wide = _build(wider.text, calibration)
        if not _outside_surrogate(requirements, constraints, wide.domain,
                                  getattr(wide, "box", {}), calibration, theta0_default):
            searcher_note = (f"outside the default surrogate's training box ("
                             f"{'; '.join(outside)}): the practical range's surrogate searched")
            spec, base, domain, outside = wider, wide, wide.domain, []
    at = _predicts_at(base, calibration)
    # the surrogate has no gap: the FE model, which takes it, searches (in the surrogate's box)
    unmodelled = [f"gap_mm={gap:g}, which the surrogate does not model"] if gap else []
    surrogate_box = {"D0_mm": list(domain.D0_mm), "t0_mm": list(domain.t0_mm)}
    default_box = FE_SEARCH_BOX if outside else surrogate_box
    box_origin = {k: "as constrained" if getattr(constraints, k) else
                  "the practical range" if outside else "the surrogate's" for k in BOX_KEYS}
    box = {"D0_mm": constraints.D0_mm or default_box["D0_mm"],
           "t0_mm": constraints.t0_mm or default_box["t0_mm"],
           "L0_mm": constraints.L0_mm or (float(at["L0_mm"]),) * 2,
           "theta0_deg": constraints.theta0_deg or (theta0_default,) * 2}
    length_note = _length_note(constraints, box, length_origin, hints)
    _check_conflicts(requirements, constraints, box, bool(outside), calibration)
    P_work = constraints.max_pressure_bar or max(r.pressure_bar for r in requirements)
    families = [(float(L0), float(theta0), rubber) for L0 in _axis(box["L0_mm"])
                for theta0 in _axis(box["theta0_deg"]) for rubber in constraints.rubber]
    if outside or unmodelled:
        from mkm.design.fe_verification import fe_model

        def model_at(family):
            return fe_model(FE_SEARCH_MESH, *family, calibration, gap)

        models = {f: model_at(f) for f in families}
        steps, refine = FE_SEARCH_STEPS, False
        why = "; ".join(([f"outside the surrogate's training box ({'; '.join(outside)})"]
                         if outside else []) + unmodelled)
        fe_search = (f"{why}: the FE model ({FE_SEARCH_MESH} mesh) searched instead, on a "
                     f"{steps[0]:g} x {steps[1]:g} mm grid of D0 x t0 (slower and coarser)")
    else:
        def model_at(family):
            return _surrogate_for(spec, base, *family, calibration)

        models = {f: model_at(f) for f in families}
        steps, refine, fe_search = COARSE_STEPS, True, ""

    start = time.perf_counter()  # the search proper: the surrogates are loaded once
    evaluate = _Evaluator(models, requirements, P_work, constraints.max_outer_diameter_mm,
                          tolerances, probability, calibration, gap)
    D0c = _axis(box["D0_mm"], count=_coarse_count(box["D0_mm"], steps[0]))
    t0c = _axis(box["t0_mm"], count=_coarse_count(box["t0_mm"], steps[1]))
    D0, t0 = _walls(*np.meshgrid(D0c, t0c, indexing="ij"))
    coarse = pd.concat([evaluate(family, D0, t0) for family in models], ignore_index=True)
    coarse = _rank(coarse, objective)
    seeds = _seeds(coarse) if refine else coarse.iloc[:0]
    dD0, dt0 = _spacing(D0c), _spacing(t0c)
    fine = [_fine(evaluate, _family(seed), seed, dD0, dt0, box)
            for _, seed in seeds.iterrows()]
    cand = _refine_axes(_merge([coarse, *fine], objective), evaluate, model_at, box, D0c, t0c,
                        objective, fine=refine)
    result = Search(cand, requirements, _describe_constraints(constraints, box), objective,
                    float(P_work), evaluate.uncertainty, time.perf_counter() - start, models,
                    fe_search, spec.text, "; ".join(n for n in (searcher_note, rubber_note) if n),
                    calibration, surrogate_box, box_origin, gap, length_note, hints)
    if not cand["feasible"].any():
        raise ValueError(_infeasible_message(result, constraints))
    return result


def _spacing(axis: np.ndarray) -> float:
    """The step of an evenly spaced grid axis; 0 for a single value."""
    return float(axis[1] - axis[0]) if axis.size > 1 else 0.0


def _family(row) -> tuple[float, float, str]:
    """``(L0_mm, theta0_deg, rubber)`` of a candidate row: the surrogate that predicts it."""
    return float(row["L0_mm"]), float(row["theta0_deg"]), row["rubber"]


def _merge(frames, objective: str) -> pd.DataFrame:
    """The candidates of ``frames``, each once, ranked by ``objective``."""
    cand = pd.concat(frames, ignore_index=True).round({"D0_mm": 9, "t0_mm": 9})
    return _rank(cand.drop_duplicates(["D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber"]),
                 objective)


def _fine(evaluate, family, seed, dD0: float, dt0: float, box: dict) -> pd.DataFrame:
    """The fine grid of ``family`` over the coarse cells around ``seed``'s D0 and t0."""
    D0f = _axis((max(seed["D0_mm"] - dD0, box["D0_mm"][0]),
                 min(seed["D0_mm"] + dD0, box["D0_mm"][1])), D0_STEP_MM)
    t0f = _axis((max(seed["t0_mm"] - dt0, box["t0_mm"][0]),
                 min(seed["t0_mm"] + dt0, box["t0_mm"][1])), T0_STEP_MM)
    return evaluate(family, *_walls(*np.meshgrid(D0f, t0f, indexing="ij")))


def _refine_axes(cand: pd.DataFrame, evaluate, model_at, box: dict, D0c: np.ndarray,
                 t0c: np.ndarray, objective: str, fine: bool = True) -> pd.DataFrame:
    """``cand`` with the searched ranges of L0 and theta0 refined around the best design.

    The coarse grid holds :data:`AXIS_VALUES` of each range, and the best design lies between
    them as often as not (a braid angle between two of them meets a force with a narrower
    tube). So, halving the step down to :data:`AXIS_RESOLUTION`, the best design's value one
    step either way is tried: its coarse D0 x t0 neighbourhood
    (:data:`AXIS_NEIGHBOURHOOD_CELLS`), then, with ``fine``, the fine grid around the best
    there; without (the FE search, whose grid has no fine one), the neighbourhood of
    :data:`FE_AXIS_NEIGHBOURHOOD_CELLS` alone. ``model_at(family)`` builds the model of a
    family not yet searched."""
    axes = [k for k in AXIS_RESOLUTION if box[k][1] > box[k][0]]
    step = {k: (box[k][1] - box[k][0]) / (AXIS_VALUES - 1) for k in axes}
    dD0, dt0 = _spacing(D0c), _spacing(t0c)
    reach = (AXIS_NEIGHBOURHOOD_CELLS if fine else FE_AXIS_NEIGHBOURHOOD_CELLS) + 1e-6
    while any(step[k] > AXIS_RESOLUTION[k] for k in axes):
        step = {k: v / 2 for k, v in step.items()}
        seeds = _seeds(cand)
        if seeds.empty:
            break
        best = seeds.iloc[0].to_dict()
        D0 = D0c[np.abs(D0c - best["D0_mm"]) <= reach * dD0]
        t0 = t0c[np.abs(t0c - best["t0_mm"]) <= reach * dt0]
        D0, t0 = _walls(*np.meshgrid(D0, t0, indexing="ij"))
        frames = []
        for key in axes:
            for sign in (-1.0, 1.0):
                value = float(np.clip(best[key] + sign * step[key], *box[key]))
                family = _family({**best, key: value})
                if family in evaluate.models:
                    continue
                evaluate.models[family] = model_at(family)
                near = _rank(evaluate(family, D0, t0), objective)
                frames += [near, *(_fine(evaluate, family, seed, dD0, dt0, box)
                                   for _, seed in _seeds(near).head(int(fine)).iterrows())]
        if frames:
            cand = _merge([cand, *frames], objective)
    return cand


def _distinct_rubbers(constraints: Constraints, calibration: Calibration | None
                      ) -> tuple[Constraints, str]:
    """``constraints`` with each rubber once (two names of the same constants, ``calibrated``
    being Silastic S in the shipped calibration, made every design twice and took half the FE
    verifications), and the note that says which name was searched for which; "" if none."""
    first: dict[tuple[float, float], str] = {}
    for name in constraints.rubber:
        first.setdefault(_constants(name, calibration), name)
    kept = tuple(first.values())
    if kept == constraints.rubber:
        return constraints, ""
    same = [f"{name} is {first[_constants(name, calibration)]}"
            for name in constraints.rubber if name not in kept]
    return (replace(constraints, rubber=kept),
            f"rubber {', '.join(same)} here (the same C10 and C01): searched once")


def _identified_length(constraints: Constraints, calibration: Calibration | None
                       ) -> tuple[Constraints, str]:
    """``constraints`` with L0 the identified muscle's where none was given and the
    calibration was identified on one length (its braid angle and rubber, the search's
    defaults, are that muscle's), and where the length comes from: "identified" then; with
    several lengths, the constraints as they are and the clause naming them; "" where the
    calibration records none or L0 was given."""
    from mkm.identify.band import identified_lengths

    lengths = [] if constraints.L0_mm is not None else identified_lengths(calibration)
    if len(lengths) == 1:
        return replace(constraints, L0_mm=(lengths[0],) * 2), "identified"
    if lengths:
        *others, last = (f"{v:g}" for v in lengths)
        return constraints, f"the identified muscles are {', '.join(others)} and {last} mm long"
    return constraints, ""


def _length_note(constraints: Constraints, box: dict, origin: str,
                 hints: Hints | None = None) -> str:
    """The note of a length not given (:attr:`Search.length_note`, and the end of an
    infeasible search's message: a force out of reach may be in reach at another length): the
    one designed (``box["L0_mm"]``), where it came from (``origin`` of
    :func:`_identified_length`, else the surrogate's length), that the force depends on it and
    how to set it (in the form of ``hints``: :class:`~mkm.design.spec.Hints`), and the tubes of
    the box it is short for (below the practical range's L0 >= 3 D0); "" where L0 was given. A
    design is verified at one length, and its clamped ends take a larger share of a shorter
    muscle's force (the FE: a 10 x 0.5 mm tube at 6 bar, eps 0.1 pulls 129.4 N 282 mm long,
    117.5 N 60 mm long; a 50 x 4 mm one at 2.5 bar, eps 0.1, 1211 N and 1352 N 1000 mm
    long)."""
    if constraints.L0_mm is not None and origin != "identified":
        return ""
    hints = hints or Hints()
    L0 = float(box["L0_mm"][0])
    where = ("the identified muscle's length (--calibration)" if origin == "identified" else
             "the default, the length of the paper's muscle" if L0 == L0_MM else
             "the length the surrogate's training data held")
    if origin and origin != "identified":
        where += f" ({origin})"
    k = PRACTICAL_RANGE.L0_per_D0_min
    short = (f"; it is below {k:g} D0 for the tubes wider than {L0 / k:.4g} mm searched, "
             "outside the practical range, where the ends are much of the muscle"
             if L0 < k * box["D0_mm"][1] else "")
    return (f"L0 {L0:g} mm assumed, not given: {where}; the force depends on the length "
            "through the clamped ends, a shorter muscle pulling less: "
            f"{hints.option('L0_mm', 'MM')} designs the length to be built, "
            f"{hints.option('L0_mm', 'A:B')} searches a range of it{short}")


def _walls(D0: np.ndarray, t0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The tubes of a grid that have a wall (t0 < D0/2), flattened."""
    ok = t0 < D0 / 2
    return D0[ok], t0[ok]


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

    def __init__(self, models, requirements, P_work, max_outer_diameter_mm, tolerances=None,
                 probability: float = 0.95, calibration: Calibration | None = None,
                 gap_mm: float = 0.0):
        self.models, self.requirements, self.calibration = models, requirements, calibration
        self.gap_mm = gap_mm
        self.P_work, self.limit = P_work, max_outer_diameter_mm
        self.tolerances, self.probability = tolerances, probability
        self.uncertainty = ""

    def __call__(self, family, D0, t0) -> pd.DataFrame:
        L0, theta0, rubber = family
        model = self.models[(float(L0), float(theta0), rubber)]
        frame = pd.DataFrame({"D0_mm": D0, "t0_mm": t0, "L0_mm": float(L0),
                              "theta0_deg": float(theta0), "rubber": rubber})
        frame["outer_diameter_mm"] = outer_diameter_mm(D0, t0, theta0, self.P_work,
                                                       *_constants(rubber, self.calibration),
                                                       self.gap_mm)
        frame["rubber_volume_cm3"] = rubber_volume_cm3(D0, t0, L0)
        eps_max = float(chou_hannaford_eps_max(theta0))
        shortfall = np.empty((len(frame), len(self.requirements)))
        for k, req in enumerate(self.requirements, start=1):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the box lies inside the domain
                pred = model.predict(req.pressure_bar, D0, t0, req.eps)
            if self.tolerances is None:
                u, self.uncertainty = surrogate_uncertainty(model, pred, req.force_N)
            else:
                u, p, u_tol = requirement_margin(model, pred, req, D0, t0, self.tolerances,
                                                 self.probability)
                self.uncertainty = describe(self.tolerances, self.probability)
                frame[f"probability_r{k}_search"] = p
                frame[f"r{k}_tolerance_u_N"] = u_tol
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


def _outside_surrogate(requirements, constraints, domain, parameter_box,
                       calibration: Calibration | None = None,
                       theta0_default: float | None = None) -> list[str]:
    """What of the request lies outside the surrogate's training box (empty: it can search).

    ``parameter_box``: the surrogate's training box of its muscle parameters (``L0_mm``, ...),
    empty for a surrogate of the geometry alone. ``theta0_default`` [deg]: the braid angle
    searched where the constraints give none (the calibration's).
    """
    out = []
    spans = {"D0_mm": tuple(domain.D0_mm), "t0_mm": tuple(domain.t0_mm)}
    spans |= {k: tuple(parameter_box[k]) for k in ("L0_mm", "theta0_deg") if k in parameter_box}
    for key, (dlo, dhi) in spans.items():
        given, whose = getattr(constraints, key), ""
        if given is None and key == "theta0_deg" and theta0_default is not None:
            given, whose = (theta0_default,) * 2, "the calibration's "
        if given is None:
            continue
        low, high = given
        if low < dlo - 1e-9 * max(abs(dlo), 1) or high > dhi + 1e-9 * max(abs(dhi), 1):
            out.append(f"{whose}{key}={span_text(low, high)} beyond {dlo:g}:{dhi:g}")
    for rubber in constraints.rubber:
        for key in ("C10_MPa", "C01_MPa"):
            value = getattr(rubber_of(rubber, calibration), key)
            if key in parameter_box and not (parameter_box[key][0] <= value
                                             <= parameter_box[key][1]):
                out.append(f"rubber={rubber} ({key}={value:g}) beyond "
                           f"{span_text(*parameter_box[key])}")
    for req in requirements:
        if not domain.eps[0] <= req.eps <= domain.eps[1]:
            out.append(f"eps={req.eps:g} beyond {domain.eps[0]:g}:{domain.eps[1]:g}")
        if not domain.pressure_bar[0] <= req.pressure_bar <= domain.pressure_bar[1]:
            out.append(f"{req.pressure_bar:g} bar beyond {domain.pressure_bar[0]:g}:"
                       f"{domain.pressure_bar[1]:g} bar")
    return list(dict.fromkeys(out))


def _check_conflicts(requirements, constraints, box, fe_search: bool,
                     calibration: Calibration | None = None) -> None:
    """One ``ValueError`` naming every conflict between requirements, constraints and the
    search's own box (the FE search's :data:`FE_SEARCH_BOX` when ``fe_search``)."""
    problems = []
    if fe_search:
        for key, (flo, fhi) in FE_SEARCH_BOX.items():
            low, high = box[key]
            if low < flo or high > fhi:
                problems.append(f"{key}={span_text(low, high)} reaches outside the FE search's "
                                f"box {flo:g}:{fhi:g} (the practical range)")
        for k, req in enumerate(requirements, start=1):
            if req.pressure_bar > FE_SEARCH_MAX_PRESSURE_BAR:
                problems.append(f"requirement {k} ({req.label}) at {req.pressure_bar:g} bar is "
                                f"above {FE_SEARCH_MAX_PRESSURE_BAR:g} bar, the top of the "
                                "practical range a design is searched in")
    if (constraints.max_pressure_bar or 0.0) > FE_SEARCH_MAX_PRESSURE_BAR:
        # the housing is checked at it: no model of the toolkit is trusted above it
        problems.append(f"max_pressure_bar={constraints.max_pressure_bar:g} is invalid: "
                        f"expected at most {FE_SEARCH_MAX_PRESSURE_BAR:g} bar, the top of the "
                        "practical range a design is searched in")
    if constraints.gap_mm:
        try:  # the narrowest tube of the box, which the search may choose
            check_gap(box["D0_mm"][0], box["t0_mm"][0], constraints.gap_mm)
        except ValueError as exc:
            problems.append(f"{exc} (the narrowest tube of the box)")
    if box["t0_mm"][0] >= box["D0_mm"][1] / 2:
        problems.append(f"t0_mm from {box['t0_mm'][0]:g} mm conflicts with D0_mm up to "
                        f"{box['D0_mm'][1]:g} mm: expected t0 < D0/2")
    low, high = box["L0_mm"]
    if outside("L0_mm", low) or outside("L0_mm", high):  # a typo, not a muscle (--L0 1e9)
        problems.append(f"L0_mm={span_text(low, high)} is invalid: {limit_text('L0_mm')}")
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
        if constraints.max_pressure_bar is not None and \
                req.pressure_bar > constraints.max_pressure_bar:
            problems.append(f"requirement {k} ({req.label}) at {req.pressure_bar:g} bar conflicts "
                            f"with the largest working pressure {constraints.max_pressure_bar:g}"
                            " bar")
    if constraints.max_outer_diameter_mm is not None and not problems:
        # the thinnest, narrowest tube of the box, at the largest theta0 and the working pressure
        P = constraints.max_pressure_bar or max(r.pressure_bar for r in requirements)
        smallest = min(float(outer_diameter_mm(box["D0_mm"][0], box["t0_mm"][0], theta0, P,
                                               *_constants(rubber, calibration)))
                       for theta0 in box["theta0_deg"] for rubber in constraints.rubber)
        if smallest > constraints.max_outer_diameter_mm:
            problems.append(f"max_outer_diameter_mm={constraints.max_outer_diameter_mm:g} "
                            f"conflicts with D0_mm >= {box['D0_mm'][0]:g} and t0_mm >= "
                            f"{box['t0_mm'][0]:g}: the smallest muscle of the box is "
                            f"{smallest:.1f} mm wide at {P:g} bar")
    if problems:
        raise ValueError("; ".join(problems))


def box_text(box: dict, widest_D0_mm: float | None = None) -> str:
    """``D0 30:50 mm x t0 2:4 mm`` of a box ``{key: [low, high]}``; where the widest tube's
    half diameter (its D0 range's, else ``widest_D0_mm``: a D0 held at one value) cuts the walls
    (a tube has a wall: t0 < D0/2, :func:`_walls`), the walls searched say so: ``t0 0.5:6 mm
    (walls below D0/2, 3.465 mm)``."""
    widest = box["D0_mm"][1] if "D0_mm" in box else widest_D0_mm

    def text(key, span):
        said = f"{BOX_NAMES[key]} {span_text(*span)} {'deg' if key.endswith('deg') else 'mm'}"
        if key == "t0_mm" and widest is not None and span[1] >= widest / 2:
            said += f" (walls below D0/2, {widest / 2:g} mm)"
        return said

    return " x ".join(text(k, v) for k, v in box.items())


def box_edges(row, box: dict, calibration: Calibration | None = None,
              hints: Hints | None = None) -> list[str]:
    """The searched ranges of ``box`` (D0, t0, L0, theta0; a fixed value is no range) whose
    end a design ``row`` sits on, as ``D0 = 30 mm (the lower end of 30:50)``, ``L0 = 250 mm
    (the upper end of 50:250, your --L0)`` where the user gave that range (``hints``:
    :class:`~mkm.design.spec.Hints`, in the form they gave it), and its rubber
    where several were searched and it is the softest or the stiffest of them (by C10; the
    ``calibrated`` one is ``calibration``'s): there a larger box might hold a better design.
    An end at the practical range's limit or beyond it is none (:func:`range_limits`): no box
    is widened past that limit."""
    hints = hints or Hints()
    edges = [f"{name} = {at:.4g} {unit} (the {end} end of {span_text(low, high)}"
             + (f", {own})" if (own := hints.own(_KEY_OF[name])) else ")")
             for name, at, unit, end, (low, high), limit in _ends(row, box) if limit is None]
    end, C10 = _rubber_end(row, box, calibration)
    if end:
        searched = ", ".join(f"{r} {c:.4g}" for r, c in C10.items())
        edges.append(f"rubber = {row['rubber']} (C10 {C10[str(row['rubber'])]:.4g} MPa, the "
                     f"{end}est of those searched: {searched} MPa)")
    return edges


def _rubber_end(row, box: dict, calibration: Calibration | None) -> tuple[str, dict]:
    """``("soft" or "stiff" or "", {rubber: C10_MPa})``: whether a design ``row``'s rubber is
    the softest or the stiffest of several searched in ``box``."""
    C10 = {r: rubber_of(r, calibration).C10_MPa for r in box.get("rubber", [])}
    if len(set(C10.values())) < 2 or "rubber" not in row:
        return "", C10
    at = C10[str(row["rubber"])]
    return ("soft" if at == min(C10.values()) else "stiff" if at == max(C10.values())
            else ""), C10


def larger_box(row, box: dict, calibration: Calibration | None = None,
               what: str = "a better design", hints: Hints | None = None,
               within: str = "this design is the best found") -> str:
    """``a larger box might hold WHAT: widen it, e.g. --D0 20:50 --t0 1:4``: the options that
    widen each searched range whose end a design ``row`` sits on (:func:`box_edges`), that end
    alone moved out by half the range's span, no further than the practical range's limit (an
    end at that limit or beyond it is widened no further: :func:`range_limits`), and
    ``--rubber`` where the rubber is an end of those searched; in the form the user set them
    (``hints``: :class:`~mkm.design.spec.Hints`). An end the user gave is their own bound,
    perhaps the application's (the longest muscle that fits): said, widened only where the
    application allows, and ``within`` it what holds."""
    hints = hints or Hints()
    options, own = {}, []
    for name, at, unit, end, (low, high), limit in _ends(row, box):
        if limit is None:
            key = _KEY_OF[name]
            limit_low, limit_high = getattr(PRACTICAL_RANGE, key)
            half = (high - low) / 2
            options[key] = (span_text(max(low - half, limit_low), high) if end == "lower" else
                            span_text(low, min(high + half, limit_high)))
            if key in hints.given:
                own.append(f"{name} {at:.4g} {unit}")
    widen = f": widen it, e.g. {hints.options(options)}" if options else ""
    if own:
        *others, last = own
        bounds = f"{', '.join(others)} and {last} are" if others else f"{last} is"
        widen += (f" ({bounds} your own bound{'s' if others else ''}: past "
                  f"{'them' if others else 'it'} only where the application allows; within "
                  f"{'them' if others else 'it'}, {within})")
    if end := _rubber_end(row, box, calibration)[0]:
        widen += (f"{'; or' if options else ':'} add a {end}er rubber to "
                  f"{hints.name('rubber')}")
    return f"a larger box might hold {what}{widen}"


def range_limits(row, box: dict) -> list[str]:
    """The searched ranges of ``box`` whose end a design ``row`` sits on where that end is the
    practical range's limit or beyond it (which :func:`box_edges` leaves out: no box is widened
    past that limit), as ``t0 = 0.5 mm, its lower limit`` or ``theta0 = 45 deg, beyond its
    upper limit 40 deg``."""
    return [f"{name} = {at:.4g} {unit}, " + (
                f"its {end} limit" if abs(at - limit) <= 1e-6 * (high - low) else
                f"beyond its {end} limit {limit:g} {unit}")
            for name, at, unit, end, (low, high), limit in _ends(row, box) if limit is not None]


def _ends(row, box: dict):
    """``(name, value, unit, "lower" or "upper", (low, high), limit)`` of each searched range
    of ``box`` (a fixed value is no range) whose end a design ``row`` sits on; ``limit`` is the
    practical range's limit on that side where the end is at it or beyond it (a lower end at
    or below the lower limit, an upper end at or above the upper one), else None."""
    for key, name in BOX_NAMES.items():
        low, high = box.get(key, (0.0, 0.0))
        if not high > low:
            continue
        at, unit = float(row[key]), "deg" if key.endswith("deg") else "mm"
        tol = 1e-6 * (high - low)  # the grids hold both ends exactly
        limit_low, limit_high = getattr(PRACTICAL_RANGE, key)
        if abs(at - low) <= tol:
            yield name, at, unit, "lower", (low, high), (limit_low if low <= limit_low + tol
                                                         else None)
        if abs(at - high) <= tol:
            yield name, at, unit, "upper", (low, high), (limit_high if high >= limit_high - tol
                                                          else None)


def span_text(low: float, high: float) -> str:
    """``37`` for a fixed value, ``30:50`` for a range."""
    return f"{low:g}" if low == high else f"{low:g}:{high:g}"


def _describe_constraints(constraints: Constraints, box: dict) -> dict:
    out = {k: list(v) for k, v in box.items()}
    out["rubber"] = list(constraints.rubber)
    out["max_outer_diameter_mm"] = constraints.max_outer_diameter_mm
    out["max_pressure_bar"] = constraints.max_pressure_bar
    if constraints.gap_mm:  # a gap-free design's record keeps its keys
        out["gap_mm"] = constraints.gap_mm
    return out


def _rank(cand: pd.DataFrame, objective: str) -> pd.DataFrame:
    """Sorted by the objective's columns (:data:`~mkm.design.spec.OBJECTIVES`)."""
    keys = OBJECTIVES[objective]
    return cand.sort_values([column for column, _ in keys], ascending=[up for _, up in keys],
                            kind="stable", ignore_index=True)


def geometry_text(row) -> str:
    """``D0 = ... mm, t0 = ... mm, L0 = ... mm, theta0 = ... deg`` of a design row."""
    text = f"D0 = {row['D0_mm']:.2f} mm, t0 = {row['t0_mm']:.2f} mm"
    return text + f", L0 = {row['L0_mm']:.4g} mm, theta0 = {row['theta0_deg']:.4g} deg"


def outside_practical_range(best, requirements,
                            calibration: Calibration | None = None) -> list[str]:
    """What of the design ``best`` (a row: its rubber by name, the calibration's where it says
    ``calibrated``) and the requirements it is held to lies outside
    :data:`~mkm.fem.limits.PRACTICAL_RANGE`, one phrase each; empty inside."""
    geometry = {k: float(best[k]) for k in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg")}
    C10, C01 = _constants(str(best["rubber"]), calibration)
    found = PRACTICAL_RANGE.violations(**geometry, C10_MPa=C10, C01_MPa=C01)
    for req in requirements:
        found += PRACTICAL_RANGE.violations(pressure_bar=req.pressure_bar, eps=req.eps,
                                            theta0_deg=geometry["theta0_deg"])
    return list(dict.fromkeys(found))


def _beyond_practical_range(row, requirements, calibration: Calibration | None = None) -> str:
    """The clause an infeasible search's message ends with when ``row`` lies outside the
    practical range (where no model's force is validated), else empty."""
    outside = outside_practical_range(row, requirements, calibration)
    return (f"; it lies outside the practical range the models are validated over "
            f"({'; '.join(outside)}): its forces are an extrapolation (`mkm models` states "
            "the range)" if outside else "")


def _near_lock(req: Requirement, theta0_low_deg: float, hints: Hints | None = None) -> str:
    """The clause a short requirement's part of an infeasible search's message ends with when
    its eps is near the braid lock even at the smallest braid angle searched (the largest
    lock), where no tube delivers much force, else empty."""
    eps_max = float(chou_hannaford_eps_max(theta0_low_deg))
    if req.eps < NEAR_LOCK_FRACTION * eps_max:
        return ""
    return (f": eps {req.eps:g} is near the braid lock (eps_max {eps_max:.3g} at theta0 "
            f"{theta0_low_deg:.4g} deg, the smallest braid angle searched), where the force "
            "falls to zero: ask for a lower eps, or search smaller braid angles "
            f"({(hints or Hints()).name('theta0_deg')}), whose lock lies at a larger eps")


def _slack(req: Requirement, hints: Hints | None = None) -> str:
    """The clause a short requirement's part ends with where the closest design pulls nothing:
    slack, below the pressure at which it starts to pull at that eps (which grows with the
    wall's stiffness over the tube's width: Klute and Hannaford's threshold)."""
    hints = hints or Hints()
    return (f": at {req.pressure_bar:g} bar it is slack, below the pressure at which a muscle "
            f"held at eps {req.eps:g} starts to pull: a thinner wall ({hints.name('t0_mm')}), "
            f"a wider tube ({hints.name('D0_mm')}) or a softer rubber "
            f"({hints.name('rubber')}) lowers that pressure, as does asking for a lower eps")


def _angle_unsearched(result: Search, may: str = "hold a narrower muscle") -> str:
    """The clause an infeasible search ends with where it held the braid angle at one value: at
    a given width the force depends on the angle both ways (a smaller one pulls more per braid
    diameter and swells wider), so a range of it ``may`` do what the one angle did not."""
    low, high = result.constraints["theta0_deg"]
    if high > low:
        return ""
    lowest, highest = PRACTICAL_RANGE.theta0_deg
    return (f"; the braid angle was held at {low:.4g} deg: a range of it may {may} "
            f"({result.hints.option('theta0_deg', f'{lowest:g}:{highest:g}')})")


def _edge_clause(result: Search, row, what: str) -> str:
    """The clause an infeasible search's message says where its closest design ``row`` sits on
    an end of a searched range (the box, not the physics, may be short), with the options that
    widen it (:func:`larger_box`: a larger box might hold ``what``), else ""."""
    edges = result.edges(row)
    if not edges:
        return ""
    ranges = {k: v for k, v in result.constraints.items() if k in BOX_NAMES and v[1] > v[0]}
    return (f"; it sits on the edge of the search box "
            f"{box_text(ranges, result.constraints['D0_mm'][1])}: {', '.join(edges)}; "
            + larger_box(row, result.constraints, result.calibration, what, result.hints,
                         "none does"))


def _infeasible_message(result: Search, constraints: Constraints) -> str:
    cand = result.candidates
    if cand["meets_forces"].any():  # only the housing is in the way
        best = cand[cand["meets_forces"]].sort_values("outer_diameter_mm").iloc[0]
        return (f"infeasible: no design meets every requirement within max_outer_diameter_mm="
                f"{constraints.max_outer_diameter_mm:g}: the narrowest that does, "
                f"{geometry_text(best)}, is {best['outer_diameter_mm']:.1f} mm wide at "
                f"{result.working_pressure_bar:g} bar"
                + _edge_clause(result, best, "a narrower one that meets them")
                + _angle_unsearched(result)
                + (f"; {result.length_note}" if result.length_note else "")
                + _beyond_practical_range(best, result.requirements, result.calibration))
    pool = cand[cand["fits_housing"]] if cand["fits_housing"].any() else cand
    closest = pool.sort_values("min_margin_pct", ascending=False).iloc[0]
    parts, near_lock = [], False
    for k, req in enumerate(result.requirements, start=1):
        force = closest[f"r{k}_surrogate_N"]
        short = req.force_N - force
        lock = (_near_lock(req, result.constraints["theta0_deg"][0], result.hints)
                if short > 0 else "")
        near_lock |= bool(lock)
        if short > 0 and not lock and force == 0.0:
            lock = _slack(req, result.hints)
        margin = float(closest[f"r{k}_uncertainty_N"])
        parts.append(f"requirement {k} ({req.label}) " + (
            f"short by {short:.0f} N (predicted {force:.0f} N)" if short > 0 else
            # met by the prediction, not by its margin: that is why it is infeasible
            f"met with {-short:.0f} N to spare, short of the margin of {margin:.0f} N"
            if np.isfinite(force) and -short < margin else
            f"met with {-short:.0f} N to spare" if np.isfinite(force) else "no valid force")
            + lock)
    edge = _edge_clause(result, closest, "a design that meets them")
    return (f"infeasible: no design in the box meets every requirement with the surrogate's "
            f"margin ({result.uncertainty}); closest: {geometry_text(closest)}: "
            + "; ".join(parts) + edge
            # near the lock, that clause says to search smaller angles already
            + ("" if near_lock else _angle_unsearched(result, "meet them, a smaller one "
                                                      "pulling more"))
            # the length a force out of reach may be in reach at, where none was given
            + (f"; {result.length_note}" if result.length_note and not near_lock else "")
            + _beyond_practical_range(closest, result.requirements, result.calibration))


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
