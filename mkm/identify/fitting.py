"""Least-squares fit of a muscle's braid angle, rubber, friction and creep to its bench runs.

The model of a run is the one the simulated bench is made of (:mod:`mkm.fem.friction`): a static
force ``F(P; theta0, rubber)`` put through the friction play operator and one creep mode along
the run's own pressure trace, sample by sample. The residuals are model minus measured force at
every sample of every settled hold, both branches and every run at once
(:func:`scipy.optimize.least_squares`, trust-region reflective within bounds). A step of an
imported table whose lab declared its accuracy is weighed by the inverse of its declared noise
(:func:`weights`): a 1 % bound makes the steps of a 500 N muscle ten times as uncertain as
those of a 50 N one, and an unweighted fit would let the strong muscle's steps drown the weak
one's.

The rubber is one scale on Silastic S's two constants (``C10 = s C10_S``, ``C01 = s C01_S``): a
force-pressure curve mostly carries one rubber stiffness, not two constants' ratio. The share of
C01 in ``C10 + C01`` (``c01_fraction``, Silastic S's by default) is fitted only where the runs
separate it (:func:`mkm.identify.procedure.identify` tests it). The tube's wall ``t0_mm`` and
diameter ``D0_mm`` are the runs' declared ones unless fitted (``--params t0``, ``D0``: one tube
for every run; each run keeps its own length ``L0_mm``). The rest length ``L0_mm`` is fitted
when asked (``--params L0``: one muscle, one rest length): each run keeps its held length
``L0 (1 - eps)``, so its shortening follows from the fitted rest length. A table's longest
length may already be shortened (a Festo map starts at 296 mm of a 300 mm muscle), and a
threshold at the declared rest length may be a rest length a little longer. The pressure
monitor's offset
``pressure_offset_bar`` (what it reads above the truth) is a nuisance parameter within the
monitor's declared accuracy: it moves the threshold, which the runs see. The radial gap
between tube and braid (``gap``, :func:`mkm.fem.thickwall.klute_hannaford`) is fitted only when
asked, with a static model that takes it. The load cell's zero ``force_zero_N`` (what it reads
when the muscle pulls nothing: a tare left out of a lab's table, a zero drifted since the tare)
is fitted only when asked (``--params ...,zero``): one for every run, told from the muscle by
the steps where it is slack, and searched within :data:`ZERO_SEARCH_FRACTION` of the largest
force the runs read.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from mkm.core.ranges import list_items
from mkm.fem.friction import DEFAULTS as TERM_DEFAULTS
from mkm.fem.friction import force_history
from mkm.fem.limits import PRACTICAL_RANGE
from mkm.fem.materials import SILASTIC_S
from mkm.fem.muscle import eps_at_rest_length
from mkm.identify.groups import DEFAULT_GROUPS, GROUPS
from mkm.identify.runs import offset_search_bar
from mkm.prediction_cache import DEFAULT_CACHE_DIR, predict_many

ORDER = ("theta0_deg", "rubber_scale", "c01_fraction", "t0_mm", "D0_mm", "L0_mm", "gap_mm",
         "pressure_offset_bar", "pressure_hysteresis_bar", "force_zero_N",
         "hysteresis_fraction", "creep_fraction", "log_tau")
#: the parameters of the static force (the rest are friction, creep and the monitor)
STATIC_NAMES = ("theta0_deg", "rubber_scale", "c01_fraction", "t0_mm", "D0_mm", "L0_mm",
                "gap_mm")
#: the tube's geometry, which a fit may take from the runs or fit (one tube for every run)
GEOMETRY = ("D0_mm", "t0_mm")
#: the values fitted only when asked (a gap, the wall, the diameter, the rest length, the
#: pressure monitor's offset and hysteresis, the load cell's zero)
OPTIONAL = ("gap_mm", *GEOMETRY, "L0_mm", "pressure_offset_bar", "pressure_hysteresis_bar",
            "force_zero_N")
#: the load cell's zero searched within +- this share of the largest force the runs read: a
#: tare left out is a preload or a cell's offset, a fraction of what the muscle pulls
ZERO_SEARCH_FRACTION = 0.1
TERM_BOUNDS = {"hysteresis_fraction": (0.0, 0.3), "creep_fraction": (0.0, 0.3),
               "log_tau": (math.log(1.0), math.log(1000.0)), "c01_fraction": (0.0, 0.9)}
#: a fitted wall or diameter searched within these factors of the declared one
GEOMETRY_FACTORS = {"t0_mm": (0.5, 1.5), "D0_mm": (0.8, 1.2)}
#: a fitted rest length searched from the longest held length (no run stretched beyond its
#: rest length) up to this factor of the declared one
REST_LENGTH_FACTOR = 1.05
#: how far the rubber scale may move once C01's share is freed (its box on the surrogate)
SCALE_MARGIN = 0.02
#: Silastic S's share of C01 in C10 + C01 (the rubber's assumed ratio)
SILASTIC_C01_FRACTION = SILASTIC_S.C01_MPa / (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
#: the FE model's search box where the surrogate's does not apply: the rubber up to the
#: practical range's stiffest (C10 0.6 MPa, natural rubber and chloroprene) at Silastic's ratio
FE_BOX = {"theta0_deg": (15.0, 50.0),
          "rubber_scale": (0.2, PRACTICAL_RANGE.C10_MPa[1] / SILASTIC_S.C10_MPa),
          "gap_mm": (0.0, 5.0)}
#: grid of the surrogate's static table [bar] (the simulated bench tabulates at 0.05 bar too)
TABLE_STEP_BAR = 0.05
#: one residual scale for every parameter (least_squares' x_scale)
X_SCALE = {"theta0_deg": 0.3, "rubber_scale": 0.05, "gap_mm": 0.05, "t0_mm": 0.05,
           "D0_mm": 0.1, "L0_mm": 0.5, "c01_fraction": 0.05, "force_zero_N": 0.5}
#: an optimum this close to a box edge (a fraction of the box) is at the edge
EDGE_FRACTION = 1e-3


def parse_groups(text: str | None) -> tuple[str, ...]:
    """``--params`` as group names in canonical order; ``ValueError`` names an unknown one."""
    if text is None:
        return DEFAULT_GROUPS
    names = list(filter(None, list_items(text)))
    unknown = [n for n in names if n not in GROUPS]
    if unknown:
        raise ValueError(f"--params {text!r}: unknown parameter {unknown[0]!r}: expected some "
                         f"of {','.join(GROUPS)}")
    if not names:
        raise ValueError(f"--params {text!r} is empty: expected some of {','.join(GROUPS)}")
    return tuple(g for g in GROUPS if g in names)


def rubber(values: dict[str, float]) -> tuple[float, float]:
    """``(C10_MPa, C01_MPa)`` of the internal values: the scale on Silastic S's C10 + C01 and
    C01's share of the sum (:func:`assumed_share` where not given)."""
    total = values["rubber_scale"] * (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
    share = assumed_share(values)
    return total * (1.0 - share), total * share


def assumed_ratio(values: dict[str, float]) -> tuple[float, str]:
    """C01/C10 of one rubber scale's fit (``values``: its internal values) and whose ratio it
    is, as a note says it: Silastic S's, or the rubber the runs declare."""
    share = assumed_share(values)
    said = ("Silastic S's" if math.isclose(share, SILASTIC_C01_FRACTION, rel_tol=1e-5)
            else "the declared rubber's")
    return share / (1.0 - share), said


def assumed_share(values: dict[str, float]) -> float:
    """C01's share of C10 + C01 in the internal values: the one given (fitted, or the rubber
    the runs declare), else Silastic S's."""
    return values.get("c01_fraction", SILASTIC_C01_FRACTION)


def full_parameters(values: dict[str, float]) -> dict[str, float]:
    """The parameters as the toolkit names them, from the internal ones."""
    C10, C01 = rubber(values)
    return {"theta0_deg": values["theta0_deg"], "C10_MPa": C10, "C01_MPa": C01,
            "hysteresis_fraction": values["hysteresis_fraction"],
            "creep_fraction": values["creep_fraction"], "creep_tau_s": math.exp(values["log_tau"]),
            **_optional(values)}


def internal_values(values: dict[str, float]) -> dict[str, float]:
    """The internal parameters from the toolkit's names (:func:`full_parameters`'s inverse)."""
    return {"theta0_deg": values["theta0_deg"],
            **internal_rubber(values["C10_MPa"], values["C01_MPa"]),
            "hysteresis_fraction": values["hysteresis_fraction"],
            "creep_fraction": values["creep_fraction"],
            "log_tau": math.log(values["creep_tau_s"]), **_optional(values)}


def _optional(values: dict) -> dict:
    """Those of :data:`OPTIONAL` that ``values`` holds."""
    return {k: values[k] for k in OPTIONAL if k in values}


def geometry(run, values: dict) -> tuple[float, float, float]:
    """``(D0_mm, t0_mm, eps)`` of ``run``, the tube's fitted wall or diameter in place of the
    declared one where ``values`` has it, and the shortening of its held length
    ``L0 (1 - eps)`` from the fitted rest length where it has one."""
    D0_mm, t0_mm, eps = run.geometry
    if "L0_mm" in values:
        eps = eps_at_rest_length(float(run.muscle["L0_mm"]), eps, float(values["L0_mm"]))
    return values.get("D0_mm", D0_mm), values.get("t0_mm", t0_mm), eps


def by_length(runs) -> dict[float, list[int]]:
    """The runs' indices grouped by their length ``L0_mm`` (one model per length)."""
    groups: dict[float, list[int]] = {}
    for k, run in enumerate(runs):
        groups.setdefault(float(run.muscle["L0_mm"]), []).append(k)
    return groups


class NoValidForce(RuntimeError):
    """A static model gives no valid force for a run at the values asked (past its braid lock,
    or its solve failed there)."""


class StaticSource:
    """Static force tables of the runs at the internal ``values`` (see the module doc)."""

    name = "static"
    box: dict[str, tuple[float, float]] = FE_BOX

    def tables(self, runs, values: dict) -> list[tuple]:
        """Per run: pressures [bar] and the static force there [N]."""
        raise NotImplementedError

    def share_bounds(self, rubber_scale: float) -> tuple[float, float]:
        """Where C01's share of the rubber is searched at this rubber scale."""
        return TERM_BOUNDS["c01_fraction"]

    def scale_bounds(self, share: float) -> tuple[float, float]:
        """Where the rubber scale is searched at C01's share ``share``."""
        return self.box["rubber_scale"]


class ModelStatic(StaticSource):
    """A registry spec (``axisym``, ``axisym:mesh=coarse``, ``thickwall``) solved at each run's
    holds' true pressures (:meth:`mkm.identify.runs.RunData.table_pressures`) and length: the
    runs' sweeps of one call together on the FE batch runner ``runner``
    (:func:`mkm.prediction_cache.predict_many`: local workers or a Dask cluster), through the
    prediction cache ``cache_dir`` (a repeated identification solves nothing
    again; None: no cache). A model the registry does not call expensive (thick-wall: a sweep
    in microseconds) is solved without the cache: its entry would cost more to write than the
    sweep, and a fit's thousands of trial points would fill the cache with entries no later
    call asks for."""

    def __init__(self, spec: str, runner=None, cache_dir=DEFAULT_CACHE_DIR):
        from mkm.fem.ladder import STATIC_FAMILIES
        from mkm.registry import parse_spec

        self.spec = parse_spec(spec)
        if self.spec.entry.family not in STATIC_FAMILIES:
            # auto, friction and the surrogate pick, add to or stand for a static physics model:
            # none is the physics the fit is confirmed with
            raise ValueError(f"--model {spec!r} is not a static physics model (its family: "
                             f"{self.spec.entry.family}): expected one that takes theta0_deg, "
                             "C10_MPa and C01_MPa (axisym, thickwall)")
        if "C10_MPa" not in self.spec.entry.parameters:
            raise ValueError(f"--model {spec!r} has no rubber: expected a model that takes "
                             "theta0_deg, C10_MPa and C01_MPa (axisym, thickwall)")
        self.name = self.spec.text
        self.runner = runner
        self.cache_dir = cache_dir if self.spec.entry.expensive else None
        self.calls = 0

    def model(self, values: dict, L0_mm: float):
        """The static model of length ``L0_mm`` (the fitted rest length where ``values`` has
        one) at the internal ``values``."""
        gap = {"gap_mm": float(values["gap_mm"])} if values.get("gap_mm") else {}
        C10, C01 = rubber(values)
        L0_mm = values.get("L0_mm", L0_mm)
        return self.spec.with_params(L0_mm=float(L0_mm), theta0_deg=float(values["theta0_deg"]),
                                     C10_MPa=C10, C01_MPa=C01, **gap).build()

    def tables(self, runs, values):
        grids = [run.table_pressures(values) for run in runs]
        models = {L0: self.model(values, L0) for L0 in by_length(runs)}
        solved = predict_many([(models[float(run.muscle["L0_mm"])], grid,
                                *geometry(run, values))
                               for grid, run in zip(grids, runs, strict=True)], self.cache_dir,
                              runner=self.runner, desc=f"{self.name} sweeps")
        self.calls += len(runs)
        out = []
        for grid, run, (pred, _) in zip(grids, runs, solved, strict=True):
            if not pred.valid.all():
                raise NoValidForce(f"{self.name} gives no valid force for run {run.name} at "
                                   + ", ".join(f"{k}={v:.4g}" for k, v in values.items()))
            out.append((grid, np.maximum(pred.force_N, 0.0)))
        return out


class SurrogateStatic(StaticSource):
    """The surrogate, tabulated every :data:`TABLE_STEP_BAR` over each run's pressures and at
    its holds' true pressures."""

    def __init__(self, surrogate):
        from mkm.surrogate.kinds import BEST

        self.surrogate = surrogate
        kind = getattr(surrogate, "kind", BEST)
        self.name = "surrogate" if kind == BEST else f"surrogate:kind={kind}"
        box = surrogate.box
        self.box = {"theta0_deg": box["theta0_deg"],
                    "rubber_scale": self.scale_bounds(SILASTIC_C01_FRACTION),
                    "t0_mm": box["t0_mm"], "D0_mm": box["D0_mm"], "L0_mm": box["L0_mm"]}

    def scale_bounds(self, share):
        """The rubber scale keeping both constants inside the box at C01's share ``share``."""
        # each constant per unit scale, written so that Silastic S's share gives its own
        box, silastic = self.surrogate.box, SILASTIC_C01_FRACTION
        parts = {"C10_MPa": SILASTIC_S.C10_MPa * (1.0 - share) / (1.0 - silastic),
                 "C01_MPa": SILASTIC_S.C01_MPa * share / silastic}
        low = max(box[k][0] / v if v > 0 else (0.0 if box[k][0] <= 0 else math.inf)
                  for k, v in parts.items())
        high = min(box[k][1] / v for k, v in parts.items() if v > 0)
        return (low, high)

    def share_bounds(self, rubber_scale):
        """C01's share keeping both constants inside the box at this scale give or take
        :data:`SCALE_MARGIN` (the scale moves little once the ratio is freed: fitted first)."""
        box, total = self.surrogate.box, rubber_scale * (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
        small, large = total * (1 - SCALE_MARGIN), total * (1 + SCALE_MARGIN)
        low = max(box["C01_MPa"][0] / small, 1.0 - box["C10_MPa"][1] / large)
        high = min(box["C01_MPa"][1] / large, 1.0 - box["C10_MPa"][0] / small)
        return (low, high) if low < high else (SILASTIC_C01_FRACTION,) * 2

    def outside(self, runs, nominal: dict | None = None, fits_rubber: bool = True) -> list[str]:
        """What of the runs' muscle the surrogate's box does not cover; with the ``nominal``
        muscle's internal values, its rubber too: the assumed ratio where the rubber is fitted
        (some scale inside the box at it), else the rubber's constants."""
        box, out = self.surrogate.box, []
        for run in runs:
            values = {"D0_mm": run.geometry[0], "t0_mm": run.geometry[1], "eps": run.eps,
                      "L0_mm": float(run.muscle["L0_mm"]),
                      "pressure_bar": float(run.steps["set_pressure_bar"].max())}
            out += [f"{k}={v:g} not in [{box[k][0]:g}, {box[k][1]:g}]"
                    for k, v in values.items() if not box[k][0] <= v <= box[k][1] + 1e-9]
        if nominal is not None and fits_rubber:
            low, high = self.scale_bounds(assumed_share(nominal))
            if not low < high:
                ratio, said = assumed_ratio(nominal)
                out.append(f"{said} C01/C10 {ratio:.3g} has no rubber scale with C10_MPa in "
                           f"[{box['C10_MPa'][0]:g}, {box['C10_MPa'][1]:g}] and C01_MPa in "
                           f"[{box['C01_MPa'][0]:g}, {box['C01_MPa'][1]:g}]")
        elif nominal is not None:
            out += [f"{k}={v:g} not in [{box[k][0]:g}, {box[k][1]:g}]"
                    for k, v in zip(("C10_MPa", "C01_MPa"), rubber(nominal), strict=True)
                    if not box[k][0] - 1e-12 <= v <= box[k][1] + 1e-12]
        return sorted(set(out))

    def tables(self, runs, values):
        if values.get("gap_mm"):
            raise ValueError("the surrogate has no gap between tube and braid")
        C10, C01 = rubber(values)
        top = self.surrogate.box["pressure_bar"][1]
        out: list = [None] * len(runs)
        for L0_mm, members in by_length(runs).items():
            model = self.surrogate.with_parameters(
                L0_mm=values.get("L0_mm", L0_mm), theta0_deg=float(values["theta0_deg"]),
                C10_MPa=C10, C01_MPa=C01)
            # and at the holds' own pressures: exact there, near a threshold too
            grids = [np.unique(np.r_[np.arange(0.0, min(top, runs[k].pressure_bar.max())
                                               + TABLE_STEP_BAR, TABLE_STEP_BAR),
                                     runs[k].table_pressures(values)].clip(max=top))
                     for k in members]
            P = np.concatenate(grids)
            columns = zip(*(geometry(runs[k], values) for k in members), strict=True)
            geom = [np.concatenate([np.full(g.size, v) for g, v in
                                    zip(grids, column, strict=True)]) for column in columns]
            force = np.maximum(model.predict(P, *geom).force_N, 0.0)
            parts = np.split(force, np.cumsum([g.size for g in grids])[:-1])
            for k, grid, F in zip(members, grids, parts, strict=True):
                out[k] = (grid, F)
        return out


class Corrected(StaticSource):
    """A source plus, per run, the difference another model showed at one point (FE minus
    surrogate at the optimum, at the FE's pressures; interpolated between them)."""

    def __init__(self, base: StaticSource, corrections: list[tuple[np.ndarray, np.ndarray]]):
        self.base, self.corrections = base, corrections
        self.name, self.box = f"{base.name} corrected by the FE model", base.box

    def tables(self, runs, values):
        tables = self.base.tables(runs, values)
        return [(grid, np.maximum(F + np.interp(grid, *self.corrections[k]), 0.0))
                for k, (grid, F) in enumerate(tables)]

    def share_bounds(self, rubber_scale):
        return self.base.share_bounds(rubber_scale)

    def scale_bounds(self, share):
        return self.base.scale_bounds(share)

    def without(self, k: int) -> Corrected:
        """The same correction for the runs but the ``k``-th (a run held out)."""
        return Corrected(self.base, [c for j, c in enumerate(self.corrections) if j != k])


def fe_correction(base: StaticSource, fe: ModelStatic, runs, values) -> list[tuple]:
    """Per run: the FE model's pressures and FE minus ``base`` there, at ``values``."""
    fe_tables = fe.tables(runs, values)
    base_tables = base.tables(runs, values)
    return [(grid, F - static_force(grid, *base_tables[k]))
            for k, (grid, F) in enumerate(fe_tables)]


def traces(source: StaticSource, runs, values: dict, lag_s: float = 0.0) -> list[np.ndarray]:
    """The model's force trace [N] at every sample of each run as the load cell reads it: the
    static force at the true pressure (:meth:`mkm.identify.runs.RunData.true_pressure_bar`),
    with friction and creep, plus the cell's zero where fitted. ``lag_s``: the muscle's
    pressure trails an imported ramp's by its rate times this (tubing between the monitor and
    the muscle), on the tables of the pressures as read."""
    tables = source.tables(runs, values)
    zero_N = values.get("force_zero_N", 0.0)
    return [zero_N + force_history(run.time_s, static_force(run.true_pressure_bar(values)
                                                            - lag_s * run.ramp_rate_at_samples(),
                                                            *tables[k]),
                                   values["hysteresis_fraction"], values["creep_fraction"],
                                   math.exp(values["log_tau"]))
            for k, run in enumerate(runs)]


def static_force(pressure_bar, grid, force_N) -> np.ndarray:
    """The tabulated static force [N] at ``pressure_bar``, continued along the table's last
    slope above its top: a monitor reading low puts the top step's true pressure above the
    highest set pressure (the FE's table) or the surrogate's box, where a force held at the top
    value would misfit the step by the slope times the offset."""
    grid, force_N = np.asarray(grid, dtype=float), np.asarray(force_N, dtype=float)
    out = np.interp(pressure_bar, grid, force_N)
    below_top = np.flatnonzero(grid < grid[-1])  # the surrogate's grid may end on the top twice
    above = np.asarray(pressure_bar) > grid[-1]
    if below_top.size and above.any():
        k = below_top[-1]
        slope = (force_N[-1] - force_N[k]) / (grid[-1] - grid[k])
        out[above] = force_N[-1] + slope * (np.asarray(pressure_bar)[above] - grid[-1])
    return out


def bounds_of(name: str, source: StaticSource, runs, start: dict,
              share_fitted: bool = False) -> tuple[float, float]:
    """Where ``name`` is searched: the source's box (the rubber scale's at the share ``start``
    holds; at Silastic S's where ``share_fitted``), the terms' bounds, the declared wall and
    diameter within :data:`GEOMETRY_FACTORS` and the rest length from the longest held length
    to :data:`REST_LENGTH_FACTOR` of the declared one (inside the source's box), the monitor's
    offset within its declared bound (the smallest of the runs') or about its vented reading
    (:func:`mkm.identify.runs.offset_search_bar`), how far each branch's reading is off
    within half the monitor's declared hysteresis, the load cell's zero within
    :data:`ZERO_SEARCH_FRACTION` of the largest force the runs read."""
    if name == "force_zero_N":
        largest = max(float(np.max(np.abs(run.force_N), initial=0.0)) for run in runs)
        return (-ZERO_SEARCH_FRACTION * largest, ZERO_SEARCH_FRACTION * largest)
    if name == "c01_fraction":
        return source.share_bounds(start["rubber_scale"])
    if name == "rubber_scale":
        # at the share held; a fitted share moves within :meth:`StaticSource.share_bounds` of
        # the scale, which moves within the box at Silastic S's
        return source.scale_bounds(SILASTIC_C01_FRACTION if share_fitted
                                   else assumed_share(start))
    if name == "pressure_offset_bar":
        return offset_search_bar(runs)
    if name == "pressure_hysteresis_bar":
        return (0.0, min(run.monitor_hysteresis_bar for run in runs) / 2)
    if name in GEOMETRY_FACTORS or name == "L0_mm":
        declared = float(runs[0].muscle[name])
        if name == "L0_mm":
            low = max(run.held_mm for run in runs)
            high = REST_LENGTH_FACTOR * declared
        else:
            low, high = (f * declared for f in GEOMETRY_FACTORS[name])
        if name in source.box:
            low, high = max(low, source.box[name][0]), min(high, source.box[name][1])
        return (low, high)
    return source.box.get(name) or TERM_BOUNDS[name]


class NotConverged(RuntimeError):
    """A fit that stopped at its evaluations' limit (or the optimiser's failure) without
    converging: the ``source``'s name, ``values`` where it stopped (every value, fixed ones
    included), ``bounds`` of the fitted ``names``, the ``evaluations`` it took."""

    def __init__(self, source: str, reason: str, names: tuple[str, ...],
                 values: dict[str, float], bounds: dict[str, tuple[float, float]],
                 evaluations: int):
        super().__init__(f"the fit on {source} did not converge: {reason}")
        self.source, self.names, self.values, self.bounds = source, names, values, bounds
        self.evaluations = evaluations


@dataclass
class Fit:
    """One least-squares fit: the fitted names, all values (fixed ones included), the residuals
    at the holds and their Jacobian, and which run and step each residual belongs to."""

    names: tuple[str, ...]
    values: dict[str, float]
    residual_N: np.ndarray
    measured_N: np.ndarray
    jacobian: np.ndarray
    cluster: np.ndarray  # (run index, step index) per residual, as one integer
    run_of_cluster: np.ndarray
    bounds: dict[str, tuple[float, float]]
    source: str
    evaluations: int
    message: str
    at_edge: list[str] = field(default_factory=list)
    tare_se_N: np.ndarray = field(default_factory=lambda: np.zeros(0))  # per run
    #: each residual's weight in the fit (:func:`weights`); the residuals and the Jacobian
    #: above are the unweighted ones [N]
    weight: np.ndarray | None = None

    @property
    def n(self) -> int:
        return int(self.residual_N.size)

    @property
    def w(self) -> np.ndarray:
        return np.ones(self.n) if self.weight is None else self.weight

    @property
    def weighted_residual(self) -> np.ndarray:
        return self.w * self.residual_N

    @property
    def weighted_jacobian(self) -> np.ndarray:
        return self.w[:, None] * self.jacobian

    @property
    def rss(self) -> float:
        """The sum of the weighted residuals' squares: what the fit minimises."""
        return float(np.sum(self.weighted_residual ** 2))

    @property
    def bic(self) -> float:
        """Bayesian information criterion of the hold residuals (Gaussian, variance fitted)."""
        return self.n * math.log(self.rss / self.n) + len(self.names) * math.log(self.n)


def nominal_values(theta0_deg: float, C10_MPa: float | None = None,
                   C01_MPa: float | None = None) -> dict[str, float]:
    """The nominal muscle: the angle, the rubber (Silastic S where not given), no friction, no
    creep."""
    return {"theta0_deg": float(theta0_deg),
            **(internal_rubber(C10_MPa, C01_MPa) if C10_MPa is not None and C01_MPa is not None
               else {"rubber_scale": 1.0}),
            "hysteresis_fraction": TERM_DEFAULTS["hysteresis_fraction"],
            "creep_fraction": TERM_DEFAULTS["creep_fraction"],
            "log_tau": math.log(TERM_DEFAULTS["creep_tau_s"])}


def internal_rubber(C10_MPa: float, C01_MPa: float) -> dict[str, float]:
    """``rubber_scale`` and, where not Silastic S's, ``c01_fraction`` of a rubber."""
    total = C10_MPa + C01_MPa
    share = C01_MPa / total
    return {"rubber_scale": total / (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa),
            **({} if math.isclose(share, SILASTIC_C01_FRACTION, rel_tol=1e-5) else {
                "c01_fraction": share})}


#: what a run may declare of its muscle that the nominal model takes (run.json's ``muscle``)
DECLARED = ("theta0_deg", "C10_MPa", "C01_MPa")


def declared(runs, name: str) -> float | None:
    """The value of ``name`` every run declares alike (run.json's ``muscle``); None where one
    declares none or two differ."""
    values = {run.muscle.get(name) for run in runs}
    return float(values.pop()) if len(values) == 1 and None not in values else None


def nominal_muscle(spec, runs, calibration=None) -> dict[str, float]:
    """The nominal muscle of ``runs`` for the model ``spec`` (a :class:`mkm.registry.Spec`):
    the braid angle and rubber the runs declare, as the report's models take them
    (:meth:`mkm.fem.muscle.Muscle.model_parameters`), else ``calibration``'s (None: the shipped
    one); no friction, no creep."""
    known = {n: v for n in DECLARED if (v := declared(runs, n)) is not None}
    params = spec.with_params(L0_mm=float(runs[0].muscle["L0_mm"]), **known).build(
        calibration).params()
    return nominal_values(params["theta0_deg"], params.get("C10_MPa"), params.get("C01_MPa"))


def weights(runs) -> list[np.ndarray]:
    """Each run's weight per hold sample: 1, except on the steps of a run whose noise its lab
    declared (:meth:`~mkm.identify.runs.RunData.declared_noise_N`), weighed by the inverse of
    that noise relative to the median of every declared step's (so a fit of tables alone
    minimises the chi-square, and their weights stay of the order of one beside bench runs)."""
    noise = [run.declared_noise_N() for run in runs]
    declared = [n for n in noise if n is not None]
    reference = float(np.median(np.concatenate(declared))) if declared else 1.0
    return [np.ones(int((run.hold >= 0).sum())) if n is None
            else reference / np.maximum(n, 1e-12)[run.hold[run.hold >= 0]]
            for run, n in zip(runs, noise, strict=True)]


def fit(source: StaticSource, runs, names, start: dict[str, float],
        max_nfev: int = 400, given: dict[str, tuple[float, float]] | None = None) -> Fit:
    """Fit ``names`` (of :data:`ORDER`) from ``start`` (every value), the rest held fixed,
    each within :func:`bounds_of` unless ``given`` names its bounds.

    Raises ``RuntimeError`` when a parameter has no room to move or the residuals are not
    finite, :class:`NotConverged` when the optimiser stops without converging.
    """
    names = tuple(n for n in ORDER if n in names)
    given = given or {}
    bounds = {n: given[n] if n in given else
              bounds_of(n, source, runs, start, "c01_fraction" in names) for n in names}
    empty = [f"{n} in [{b[0]:.6g}, {b[1]:.6g}]" for n, b in bounds.items() if not b[0] < b[1]]
    if empty:
        raise RuntimeError(f"the fit on {source.name} has nothing to search: {empty[0]}")
    x0 = np.array([min(max(start[n], bounds[n][0]), bounds[n][1]) for n in names])
    holds = [run.hold >= 0 for run in runs]
    w = np.concatenate(weights(runs))
    counter = [0]

    def values_of(x):
        return {**start, **dict(zip(names, map(float, x), strict=True))}

    def residuals(x):
        counter[0] += 1
        out = traces(source, runs, values_of(x))
        return w * np.concatenate([(t - run.force_N)[h]
                                   for t, run, h in zip(out, runs, holds, strict=True)])

    if names:
        scale = np.array([X_SCALE.get(n, 0.01) for n in names])
        res = least_squares(residuals, x0, bounds=tuple(np.array(b) for b in zip(
            *bounds.values(), strict=True)), x_scale=scale, diff_step=1e-4, method="trf",
            xtol=1e-10, ftol=1e-10, max_nfev=max_nfev)
        if not res.success and res.status <= 0:
            raise NotConverged(source.name, res.message, names, values_of(res.x), bounds,
                               res.nfev)
        x, r, J, message = res.x, res.fun, res.jac, res.message
    else:
        x, r, J, message = x0, residuals(x0), np.zeros((0, 0)), "nothing to fit"
        J = np.zeros((r.size, 0))
    if not np.all(np.isfinite(r)):
        raise RuntimeError(f"the fit on {source.name} gave non-finite residuals")
    r, J = r / w, J / w[:, None]
    steps = [run.hold[h] for run, h in zip(runs, holds, strict=True)]
    offsets = np.cumsum([0] + [len(run.steps) for run in runs])
    cluster = np.concatenate([s + offsets[k] for k, s in enumerate(steps)])
    run_of_cluster = np.repeat(np.arange(len(runs)), [len(run.steps) for run in runs])
    values = values_of(x)
    edges = [n for n in names if n in source.box and at_edge(values[n], bounds[n])]
    measured = np.concatenate([run.force_N[h] for run, h in zip(runs, holds, strict=True)])
    return Fit(names, values, r, measured, J, cluster, run_of_cluster, bounds, source.name,
               counter[0], str(message), edges, np.array([run.tare_se_N for run in runs]),
               None if np.all(w == 1) else w)


def at_edge(value: float, box: tuple[float, float]) -> bool:
    width = box[1] - box[0]
    return min(value - box[0], box[1] - value) <= EDGE_FRACTION * width


def step_predictions(source: StaticSource, runs, values: dict) -> list[np.ndarray]:
    """Each run's predicted step means over its settled holds [N]."""
    return [run.step_means(t) for run, t in zip(runs, traces(source, runs, values), strict=True)]
