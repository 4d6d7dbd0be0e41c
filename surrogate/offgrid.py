"""Off-grid evaluation: fresh random muscles the FE computes now, against a surrogate.

Muscle-held-out splits still draw the test muscles from the design the surrogate was built on.
:func:`evaluate_offgrid` draws new muscles uniformly in the surrogate's box (every muscle
parameter it takes; the recorded value of the others), with a seed it records (a fresh one by
default, so repeated runs are new draws), computes their FE sweeps (:mod:`mkm.surrogate.design`,
through the dataset cache), and scores the surrogate on them: the largest |Err%| of each muscle
(the paper's Equation 7), the pooled RMSE (``sklearn.metrics``), the fraction of points within 1,
2 and 3 predictive std, and whether every point just outside the box is flagged.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import provenance, write_atomic, write_json_atomic
from mkm.fem.paper import equation7_err_pct
from mkm.surrogate.coverage import coverage
from mkm.surrogate.design import EVAL_PRESSURES, MUSCLE_PARAMETERS, fe_sweeps, random_muscles
from mkm.surrogate.model import OutOfDomainWarning, SurrogateForceModel
from mkm.surrogate.training_data import PARAMETERS
from mkm.surrogate.validation import rmse

OUTSIDE_MARGIN = 0.05  # a point outside the box: 5 % of the range beyond one of its ends


def muscle_box(model: SurrogateForceModel) -> dict[str, tuple[float, float]]:
    """The range of each muscle parameter to draw from: the model's box, or its recorded value."""
    return {p: tuple(model.box[p]) if p in model.box else (model.fixed[p], model.fixed[p])
            for p in MUSCLE_PARAMETERS}


def evaluate_offgrid(model: SurrogateForceModel, n_muscles: int = 12, seed: int | None = None,
                     mesh: str = "fine", workers: int | None = None, cache_dir=None,
                     progress: bool = True,
                     scheduler: str | None = None) -> tuple[pd.DataFrame, dict]:
    """Score ``model`` on ``n_muscles`` fresh random muscles (FE at ``mesh``).

    Returns ``(points, summary)``: one row per point (inputs, ``force_fe_N``, ``force_N``,
    ``force_std_N``, ``err_pct``, ``valid``) and the summary (seed, FE budget, worst and median
    per-muscle largest |Err%|, pooled RMSE, coverage, the out-of-box check, provenance): the
    errors and the coverage over the points the model answers (``valid``), counted in
    ``valid_points``.
    """
    if int(n_muscles) != n_muscles or n_muscles < 1:
        raise ValueError(f"--muscles {n_muscles!r} is invalid: expected an FE budget of at "
                         "least 1 muscle")
    if seed is None:
        seed = int(np.random.SeedSequence().entropy % 2**32)  # fresh, and recorded
    muscles = random_muscles(n_muscles, seed, muscle_box(model))
    frame, done = fe_sweeps(muscles, mesh, EVAL_PRESSURES, workers=workers,
                            scheduler=scheduler, cache_dir=cache_dir, progress=progress,
                            desc=f"FE of {n_muscles} off-grid muscles ({mesh})")
    rows, per_muscle = [], []
    for k, muscle in muscles.iterrows():
        sweep = frame[frame["muscle"] == k]
        if not sweep["converged"].all():
            per_muscle.append({"muscle": k, "fe_failed": True})
            continue
        local = model.with_parameters(**{p: float(muscle[p]) for p in PARAMETERS
                                         if p not in model.fixed})
        prediction = local.predict(sweep["pressure_bar"].to_numpy(), muscle["D0_mm"],
                                   muscle["t0_mm"], muscle["eps"])
        points = sweep[["muscle", "pressure_bar", *MUSCLE_PARAMETERS]].copy()
        points["force_fe_N"] = sweep["force_N"].to_numpy()
        points["force_N"] = prediction.force_N
        points["force_std_N"] = prediction.extras.get("force_std_N", np.full(len(sweep),
                                                                             np.nan))
        points["valid"] = ok = np.ravel(prediction.valid)
        top = points["force_fe_N"].max()
        # a point the model flags invalid has no error: its number is one the model disowns
        points["err_pct"] = (np.where(ok, equation7_err_pct(points["force_fe_N"],
                                                            points["force_N"]), np.nan)
                             if top > 0 else np.nan)
        rows.append(points)
        answered = points[ok]
        per_muscle.append({"muscle": k, "fe_failed": False,
                           "max_abs_err_pct": float(np.nanmax(np.abs(points["err_pct"])))
                           if top > 0 and ok.any() else float("nan"),
                           "max_force_N": float(top), "valid_points": int(ok.sum()),
                           "rmse_N": rmse(answered["force_fe_N"], answered["force_N"])
                           if ok.any() else float("nan")})
    points = pd.concat(rows, ignore_index=True)
    answered = points[points["valid"]]
    errors = answered["force_fe_N"] - answered["force_N"]
    per = pd.DataFrame(per_muscle)
    summary = {
        "seed": seed, "fe_budget_muscles": int(n_muscles), "mesh": mesh,
        "fe_jobs_computed": done["computed"], "fe_jobs_from_cache": done["cached"],
        "fe_failed_muscles": int(per["fe_failed"].sum()),
        "worst_max_abs_err_pct": float(per["max_abs_err_pct"].max()),
        "median_max_abs_err_pct": float(per["max_abs_err_pct"].median()),
        "pooled_rmse_N": rmse(answered["force_fe_N"], answered["force_N"]),
        "all_valid": bool(points["valid"].all()), "valid_points": len(answered),
        "per_muscle": per.to_dict(orient="records"),
        "model": model.name, "model_params": model.params(), **provenance()}
    if answered["force_std_N"].notna().all():
        summary["within_1std"] = coverage(errors, answered["force_std_N"], 1.0)
        summary["within_2std"] = coverage(errors, answered["force_std_N"], 2.0)
        summary["within_3std"] = coverage(errors, answered["force_std_N"], 3.0)
    summary["outside_box"] = outside_box_check(model, muscles.iloc[0])
    return points, summary


def outside_box_check(model: SurrogateForceModel, muscle) -> dict:
    """Predict one point just outside each end of the box of every input (``muscle`` elsewhere)
    and count those flagged ``valid=False``: all of them must be."""
    inside = {p: float(muscle[p]) for p in MUSCLE_PARAMETERS}
    inside["pressure_bar"] = float(np.mean(model.box["pressure_bar"]))
    n, flagged = 0, 0
    for name, (lo, hi) in model.box.items():
        for value in (lo - OUTSIDE_MARGIN * (hi - lo), hi + OUTSIDE_MARGIN * (hi - lo)):
            if value < 0:
                continue  # not a physical input (refused outright, not flagged)
            point = {**inside, name: value}
            local = model.with_parameters(**{p: point[p] for p in PARAMETERS
                                             if p not in model.fixed})
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", OutOfDomainWarning)
                prediction = local.predict(point["pressure_bar"], point["D0_mm"],
                                           point["t0_mm"], point["eps"])
            n += 1
            flagged += int(not prediction.valid.all())
    return {"points": n, "flagged": flagged}


def write_offgrid(points: pd.DataFrame, summary: dict, out) -> tuple[Path, Path]:
    """:func:`evaluate_offgrid`'s points and summary as ``offgrid_points.csv`` and
    ``offgrid_summary.json`` in the folder ``out``, written atomically."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    csv = write_atomic(out / "offgrid_points.csv",
                       points.to_csv(index=False, float_format="%.6g", lineterminator="\n"))
    return csv, write_json_atomic(out / "offgrid_summary.json", summary)
