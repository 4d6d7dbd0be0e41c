"""The ``auto`` force model: the cheapest model whose measured error meets a tolerance.

"Model no more than a scene needs", as a feature. ``mkm study`` measures, for every model of
the ladder, the error (the paper's Equation 7) against the finest converged FE model on a set of
study muscles, and the cost per predicted force; the point-by-point table ships as
``mkm/data/model_errors.csv``. The scene is the query: by default ``auto`` answers a whole call
(a sweep, a bench run) with ONE model, the cheapest whose worst bound over all its points meets
the tolerance and whose prediction is valid at every point, so a curve never mixes models.
With ``per_point=True`` (``--per-point``) it chooses for each query point instead:

1. bounds each candidate's error at the point by the worst |Err%| the study measured for that
   candidate on the :data:`NEIGHBOURS` study muscles nearest to the query muscle (distance in
   D0, t0 and eps scaled by :data:`DOMAIN_SPAN`; muscles farther than :data:`MAX_DISTANCE` do
   not count) at the two study pressures bracketing the query pressure;
2. takes the cheapest candidate (measured seconds per force) whose bound meets the tolerance and
   whose own prediction is valid there (Equation 2 beyond eps_max, a surrogate out of its
   domain or a solve that did not converge never qualify);
3. falls back to the reference itself, the finest FE mesh, where nothing cheaper qualifies (a
   query outside the study's pressures or far from every study muscle included).

Either way each point records which model answered (extra ``model_used``) and the error bound that
justified it (``error_bound_pct``; NaN for the fallback); :func:`explain` says it in words.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from functools import cache
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.fem.interface import ForceModel
from mkm.fem.records import file_sha256, package_file

MODEL_ERRORS_FILE = package_file("mkm", "data", "model_errors.csv")
NEIGHBOURS = 2  # two study muscles: one alone would trust a single geometry's luck
# Distances in (D0, t0, eps) are scaled by the span of the paper's dataset (Table 1 of
# Antonelli et al. 2025: D0 30-50 mm, t0 2-4 mm, eps 0-20 %); a study muscle farther than half
# that span says nothing about the query.
DOMAIN_SPAN = np.array([20.0, 2.0, 0.2])
MAX_DISTANCE = 0.5
PRESSURE_SLACK_BAR = 0.01  # a measured 2.5002 bar is the study's 2.5 bar: below bench resolution
FALLBACK = "axisym-fine"


@cache
def read_model_errors(path: Path | str = MODEL_ERRORS_FILE) -> pd.DataFrame:
    """The study table written by ``mkm study``: one row per predictor, muscle and pressure."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"no study table at {path}: run `mkm study` to measure model errors")
    table = pd.read_csv(path)
    needed = {"predictor", "spec", "muscle", "D0_mm", "t0_mm", "eps", "pressure_bar", "err_pct",
              "seconds_per_point"}
    missing = needed - set(table.columns)
    if missing:
        raise ValueError(f"study table {path} lacks columns {sorted(missing)}: "
                         "re-run `mkm study`")
    return table


def error_bounds(table: pd.DataFrame, predictor: str, pressure_bar, D0_mm, t0_mm,
                 eps) -> np.ndarray:
    """Upper bound of |Err%| of ``predictor`` at each query point from the study table (NaN where
    the study does not cover the point); the rule is in the module docstring."""
    rows = table[table["predictor"] == predictor]
    muscles = rows.groupby(["D0_mm", "t0_mm", "eps"], sort=True)
    keys = np.array(list(muscles.groups), dtype=float).reshape(-1, 3)
    P, D0, t0, e = (np.ravel(a) for a in np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (pressure_bar, D0_mm, t0_mm, eps))))
    query = np.stack([D0, t0, e], axis=1)
    bound = np.full(P.shape, np.nan)
    if len(keys) == 0:
        return bound
    distance = np.linalg.norm((query[:, None, :] - keys[None, :, :]) / DOMAIN_SPAN, axis=2)
    sweeps = [group.sort_values("pressure_bar") for _, group in muscles]
    for i in range(P.size):
        order = np.argsort(distance[i])[:NEIGHBOURS]
        near = [j for j in order if distance[i, j] <= MAX_DISTANCE]
        if not near:
            continue
        worst = 0.0
        for j in near:
            p = sweeps[j]["pressure_bar"].to_numpy()
            err = np.abs(sweeps[j]["err_pct"].to_numpy())
            if not p.min() - PRESSURE_SLACK_BAR <= P[i] <= p.max() + PRESSURE_SLACK_BAR:
                worst = np.nan
                break
            q = np.clip(P[i], p.min(), p.max())
            lo = p[p <= q + 1e-9].max()
            hi = p[p >= q - 1e-9].min()
            bracket = err[(p >= lo - 1e-9) & (p <= hi + 1e-9)]
            worst = max(worst, np.inf if np.isnan(bracket).any() else bracket.max())
        bound[i] = worst
    return bound


def candidates(table: pd.DataFrame) -> pd.DataFrame:
    """Predictors auto may use, cheapest first: one row each with spec and seconds per force."""
    pick = table[table["spec"].notna() & (table["spec"] != "")]
    cost = pick.groupby(["predictor", "spec"], as_index=False)["seconds_per_point"].median()
    return cost.sort_values("seconds_per_point", kind="stable").reset_index(drop=True)


class AutoModel(ForceModel):
    """The cheapest model meeting ``tolerance`` over the query (``--model auto --tolerance 2%``).

    Parameters
    ----------
    tolerance : float
        Largest acceptable |Err%| against the finest FE model, a fraction (0.02 = 2 %).
    table : str, optional
        Study table to read (default ``mkm/data/model_errors.csv``, written by ``mkm study``).
    per_point : bool
        False (default): one model for the whole call, the cheapest whose largest bound over
        all points meets the tolerance. True: the cheapest model per point.
    build : callable
        ``build(spec) -> ForceModel``: makes a candidate from a study-table spec (the
        registry's :func:`mkm.registry.build_spec`, which passes itself when it builds auto).
    """

    name = "auto"

    def __init__(self, tolerance: float = 0.02, table: str | None = None,
                 per_point: bool = False, *, build: Callable[[str], ForceModel]):
        self.tolerance = tolerance
        self.table = table
        self.per_point = bool(per_point)
        self.build = build

    def params(self):
        path = Path(self.table or MODEL_ERRORS_FILE)
        digest = file_sha256(path)[:12] if path.exists() else None
        return {"tolerance": self.tolerance, "table": path.name, "table_sha256": digest,
                "per_point": self.per_point}

    def choose(self, P, D0, t0, eps) -> dict[str, np.ndarray]:
        """Per point: the predictor that answers (``model_used``, the same for every point
        unless ``per_point``), its error bound, and the forces of the cheaper candidate that
        qualified; the fallback's points are left to :meth:`_forces` (NaN force,
        ``model_used`` = :data:`FALLBACK`)."""
        if not 0.0 < self.tolerance < 1.0:
            raise ValueError(f"tolerance={self.tolerance:g} is invalid: expected a fraction in "
                             "(0, 1), for example 0.02 or 2%")
        table = read_model_errors(self.table or MODEL_ERRORS_FILE)
        P, D0, t0, eps = (np.ravel(a) for a in np.broadcast_arrays(
            *(np.asarray(v, dtype=float) for v in (P, D0, t0, eps))))
        force = np.full(P.shape, np.nan)
        used = np.full(P.shape, FALLBACK, dtype=object)
        bound_used = np.full(P.shape, np.nan)
        todo = np.ones(P.shape, dtype=bool)
        for row in candidates(table).itertuples():
            if not todo.any():
                break
            if row.predictor == FALLBACK:
                continue
            bound = error_bounds(table, row.predictor, P, D0, t0, eps)
            meets = bound <= 100.0 * self.tolerance  # NaN (not covered) never meets it
            if not self.per_point and not meets.all():
                continue
            idx = np.flatnonzero(todo & meets)
            if idx.size == 0:
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # a point a candidate flags goes to the next one
                pred = self.build(row.spec).predict(P[idx], D0[idx], t0[idx], eps[idx])
            if not self.per_point and not pred.valid.all():
                continue  # one model for the whole query: it must answer every point
            ok = idx[pred.valid]
            force[ok] = pred.force_N[pred.valid]
            used[ok] = row.predictor
            bound_used[ok] = bound[ok]
            todo[ok] = False
        return {"force_N": force, "model_used": used.astype(str), "error_bound_pct": bound_used}

    def _forces(self, P, D0, t0, eps):
        out = self.choose(P, D0, t0, eps)
        valid = np.isfinite(out["force_N"])
        converged = valid.copy()
        fallback = np.flatnonzero(out["model_used"] == FALLBACK)
        if fallback.size:
            table = read_model_errors(self.table or MODEL_ERRORS_FILE)
            spec = candidates(table).set_index("predictor")["spec"].get(
                FALLBACK, "axisym:mesh=fine")
            args = (np.ravel(a)[fallback] for a in (P, D0, t0, eps))
            pred = self.build(spec).predict(*args)
            out["force_N"][fallback] = pred.force_N
            valid[fallback] = pred.valid
            converged[fallback] = pred.converged
        return {key: value.reshape(P.shape) for key, value in
                {**out, "valid": valid, "converged": converged}.items()}


def explain(prediction, tolerance: float | None = None) -> str:
    """One line per model used: how many points it answered and why it was chosen.

    ``prediction``: a :class:`Prediction` of :class:`AutoModel`, or the dict of
    :meth:`AutoModel.choose` with ``tolerance`` given.
    """
    if isinstance(prediction, dict):
        extras = prediction
    else:
        extras, tolerance = prediction.extras, prediction.params["tolerance"]
    tol = 100.0 * tolerance
    used = np.ravel(extras["model_used"])
    bound = np.ravel(extras["error_bound_pct"])
    lines = []
    for name in dict.fromkeys(used):
        here = used == name
        if name == FALLBACK:
            why = (f"nothing cheaper has a study error <= {tol:g}% there (or the study does not "
                   "cover the point), so the finest FE mesh, the study's reference, answers")
        else:
            why = (f"cheapest model whose study error near these points is <= {tol:g}% "
                   f"(bound {np.nanmax(bound[here]):.2f}%)")
        lines.append(f"auto: {name} for {here.sum()} of {used.size} points: {why}")
    return "\n".join(lines)
