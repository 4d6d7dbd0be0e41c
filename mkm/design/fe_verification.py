"""FE verification of the chosen designs: forces, margins and flags from the FE model."""

from __future__ import annotations

import time

import numpy as np
import pandas as pd

from mkm.design.spec import CALIBRATED_RUBBER, DEFAULT_OBJECTIVE, NEAR_LOCK_FRACTION, rubber_of
from mkm.fem.calibration import Calibration
from mkm.fem.eq2 import chou_hannaford_eps_max
from mkm.fem.interface import ForceModel
from mkm.fem.options import MESH_LEVELS
from mkm.fem.outcomes import BRAID_LOCKS
from mkm.mesh_errors import point_error_N
from mkm.registry import parse_spec

CURVE_STEP_BAR = 0.25  # FE force-pressure curves of the verified designs
#: The flag of a requirement met by less than the mesh's force may lie from the fine mesh's: the
#: chosen design so met is verified again on a finer mesh (:func:`verify`)
MARGIN_WITHIN_MESH_ERROR = "margin_within_mesh_error"


# --- FE verification ----------------------------------------------------------------------------


def fe_model(mesh: str, L0_mm: float, theta0_deg: float, rubber: str,
             calibration: Calibration | None = None, gap_mm: float = 0.0) -> ForceModel:
    """The axisymmetric FE model (registry ``axisym``) of one design family (``calibration``:
    where the ``calibrated`` rubber comes from; ``gap_mm``: the radial gap between tube and
    braid [mm], 0 for none)."""
    material = rubber_of(rubber, calibration)
    return parse_spec(f"axisym:mesh={mesh}").build(
        L0_mm=float(L0_mm), theta0_deg=float(theta0_deg), C10_MPa=material.C10_MPa,
        C01_MPa=material.C01_MPa, gap_mm=float(gap_mm))


#: The braid angle a built muscle may be off by [deg] where no identification says better: the
#: spread of a fitted braid angle the packaged bench configuration declares
#: (``[muscle.tolerances] theta0_deg``)
BUILT_ANGLE_TOLERANCE_DEG = 1.0


def steeper_braid_N(row, requirements, calibration: Calibration | None,
                    gap_mm: float = 0.0, cache_dir=None) -> list[float]:
    """Per requirement, the FE force [N] of design ``row`` with its braid
    :data:`BUILT_ANGLE_TOLERANCE_DEG` steeper (the force falls as the angle grows), on the
    mesh of its row; 0 where the braid locks there or the FE gives no force. Each solve is
    kept in the prediction cache ``cache_dir`` as the verification's sweeps are (None: no
    cache)."""
    from mkm.prediction_cache import cached_predict

    model = fe_model(row["fe_mesh"], row["L0_mm"],
                     float(row["theta0_deg"]) + BUILT_ANGLE_TOLERANCE_DEG, row["rubber"],
                     calibration, gap_mm)
    out = []
    for r in requirements:
        prediction, _ = cached_predict(model, r.pressure_bar, float(row["D0_mm"]),
                                       float(row["t0_mm"]), r.eps, cache_dir=cache_dir)
        force = float(np.ravel(prediction.force_N)[0])
        out.append(force if bool(np.ravel(prediction.valid)[0]) and np.isfinite(force)
                   else 0.0)
    return out


def identified_ends_N(row, requirements, calibration: Calibration | None,
                      gap_mm: float = 0.0, cache_dir=None) -> list[tuple[float, float] | None]:
    """Per requirement, how far [N] the 95 % band of design ``row``'s FE force that the
    identified muscle's own uncertainty gives reaches below and above it
    (:func:`mkm.identify.band.prediction_ends`: the intervals ``mkm identify`` wrote into
    ``calibration``, carried through the FE model at the design's geometry, its solves kept in
    the prediction cache ``cache_dir``; below it the linearisation, above it farther where the
    force is not linear in the parameters); None where the calibration holds no identified FE
    muscle, or the design takes another braid angle or rubber than the identified one, or a
    gap."""
    from mkm.identify.band import prediction_ends

    return [None if ends is None else (float(np.ravel(ends[0])[0]), float(np.ravel(ends[1])[0]))
            for ends in _identified(prediction_ends, row, requirements, calibration, gap_mm,
                                    cache_dir)]


def _identified(function, row, requirements, calibration, gap_mm, cache_dir) -> list:
    """``function`` (a band of :mod:`mkm.identify.band`) of design ``row``'s FE force at each
    requirement; None where the design is not the identified FE muscle."""
    from mkm.identify.band import identified_entry

    found = identified_entry(calibration) if calibration is not None else None
    if (found is None or found[0] != "axisym" or gap_mm or row["rubber"] != CALIBRATED_RUBBER
            or not np.isclose(float(row["theta0_deg"]), float(found[1]["theta0_deg"]))):
        return [None] * len(requirements)
    spec = parse_spec(f"axisym:mesh={row['fe_mesh']}").with_params(L0_mm=float(row["L0_mm"]))
    return [function(spec, calibration, np.array([float(row[f"r{k}_fe_N"])]),
                     np.array([r.pressure_bar]), float(row["D0_mm"]), float(row["t0_mm"]),
                     r.eps, cache_dir) for k, r in enumerate(requirements, start=1)]


def verify(designs: pd.DataFrame, requirements, mesh: str = "medium",
           curve_to_bar: float | None = None, progress: bool = False, cache_dir=None,
           workers: int | None = None, scheduler: str | None = None,
           calibration: Calibration | None = None, gap_mm: float = 0.0,
           objective: str = DEFAULT_OBJECTIVE, demoted: frozenset = frozenset()):
    """FE forces of ``designs`` at every requirement on ``mesh`` (:func:`verify_on_mesh`), the
    chosen design's verdict made to hold: while the best design that meets every requirement
    (the first by :func:`ordered` for ``objective`` and ``demoted``) meets one by less than its
    mesh's force may lie from the fine mesh's (:func:`mkm.mesh_errors.point_error_N`), it is
    verified again on the next finer mesh
    (:data:`~mkm.fem.options.MESH_LEVELS`' order), and the best is found again: the cheapest
    mesh whose verdict holds, for the one design built. The others keep their flag. Column
    ``fe_mesh`` names the mesh of each design's forces and curves. Returns what
    :func:`verify_on_mesh` returns (best first), its time and cache hits summed over the
    meshes and the models of every mesh used."""
    levels = list(MESH_LEVELS)

    def order(frame):
        return ordered(frame, objective, demoted)

    args = (curve_to_bar, progress, cache_dir, workers, scheduler, calibration, gap_mm)
    judged, curves, seconds, models, hits = verify_on_mesh(designs, requirements, mesh, *args)
    judged = order(judged.assign(fe_mesh=mesh))
    while judged["meets_all"].any():
        best = judged[judged["meets_all"]].iloc[0]
        if MARGIN_WITHIN_MESH_ERROR not in best["flags"] or best["fe_mesh"] == levels[-1]:
            break
        finer = levels[levels.index(best["fe_mesh"]) + 1]
        again, recurves, more_seconds, more_models, more_hits = verify_on_mesh(
            designs[designs["rank"] == best["rank"]].reset_index(drop=True), requirements,
            finer, *args)
        judged = order(pd.concat([judged[judged["rank"] != best["rank"]],
                                  again.assign(fe_mesh=finer)], ignore_index=True))
        curves = pd.concat([curves[curves["design"] != best["rank"]], recurves],
                           ignore_index=True)
        seconds, hits = seconds + more_seconds, hits + more_hits
        models.update(more_models)
    return judged, curves, seconds, models, hits


def ordered(designs: pd.DataFrame, objective: str = DEFAULT_OBJECTIVE,
            demoted: frozenset = frozenset()) -> pd.DataFrame:
    """The verified designs best first: those the FE confirms, those whose ``rank`` is not in
    ``demoted`` (a robust design below the probability asked:
    :func:`mkm.design.robust.below_target`) before those that are, each by rank (the
    objective's order in the search), or by FE margin for ``max-margin``."""
    order = ["min_fe_margin_pct", "rank"] if objective == "max-margin" else ["rank"]
    return (designs.assign(_demoted=designs["rank"].isin(demoted))
            .sort_values(["meets_all", "_demoted", *order],
                         ascending=[False, True, objective != "max-margin"]
                         + [True] * (len(order) - 1), kind="stable", ignore_index=True)
            .drop(columns="_demoted"))


def verify_on_mesh(designs: pd.DataFrame, requirements, mesh: str = "medium",
                   curve_to_bar: float | None = None, progress: bool = False, cache_dir=None,
                   workers: int | None = None, scheduler: str | None = None,
                   calibration: Calibration | None = None, gap_mm: float = 0.0):
    """FE forces of ``designs`` at every requirement on ``mesh``, and their force-pressure
    curves.

    One FE sweep per design and distinct eps, through the requirements' pressures and
    ``0:curve_to_bar:0.25`` bar (the curve also gets the FE threshold pressure, force 0), kept in
    the prediction cache ``cache_dir`` (:mod:`mkm.prediction_cache`; None: no cache), the missing
    ones solved as one batch on ``workers`` local processes or the Dask cluster at ``scheduler``
    (:func:`mkm.prediction_cache.predict_many`). Adds per
    requirement ``r<k>_fe_N``, ``r<k>_fe_margin_N``,
    ``r<k>_fe_margin_pct``, ``r<k>_threshold_bar``, ``r<k>_meets``; then ``meets_all``,
    ``min_fe_margin_pct``, ``flags`` and ``fe_failure``. Returns the designs, the curves, the wall
    time [s], the FE models by ``(mesh, L0, theta0, rubber)`` and how many sweeps came from the
    cache.
    """
    from mkm.prediction_cache import predict_many

    start = time.perf_counter()
    designs = designs.copy()
    top_P = max([r.pressure_bar for r in requirements] + [curve_to_bar or 0.0])
    grid = np.round(np.arange(0.0, top_P + 1e-9, CURVE_STEP_BAR), 6)
    eps_levels = sorted({r.eps for r in requirements})
    pressures = {eps: np.union1d(grid, [r.pressure_bar for r in requirements if r.eps == eps])
                 for eps in eps_levels}
    models: dict = {}
    requests = []
    for _, row in designs.iterrows():
        key = (mesh, row["L0_mm"], row["theta0_deg"], row["rubber"])
        if key not in models:
            models[key] = fe_model(*key, calibration, gap_mm)
        requests += [(models[key], pressures[eps], row["D0_mm"], row["t0_mm"], eps)
                     for eps in eps_levels]
    solved = iter(predict_many(requests, cache_dir, workers=workers, scheduler=scheduler,
                               progress=progress, desc="FE verification"))
    curves, per_design, hits = [], [], 0
    for _, row in designs.iterrows():
        results = {}
        for eps in eps_levels:
            P = pressures[eps]
            pred, hit = next(solved)
            hits += hit
            frame = pred.to_frame()
            results[eps] = frame
            curve = frame[["eps", "pressure_bar", "force_N", "converged"]]
            threshold = float(frame["threshold_pressure_bar"].iloc[0])
            if 0 < threshold < P[-1]:  # the kink where the force leaves zero: no solve
                curve = pd.concat([curve, pd.DataFrame({
                    "eps": [eps], "pressure_bar": [threshold], "force_N": [0.0],
                    "converged": [True]})], ignore_index=True)
            curves.append(curve.assign(design=row["rank"], mesh=mesh)
                          .sort_values("pressure_bar"))
        per_design.append(_judge(row, requirements, results, mesh))
    designs = pd.concat([designs, pd.DataFrame(per_design)], axis=1)
    curves = pd.concat(curves, ignore_index=True) if curves else pd.DataFrame()
    return designs, curves, time.perf_counter() - start, models, hits


def _judge(row, requirements, results, mesh: str = "medium") -> dict:
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
        # the outcome by the one classification (mkm.fem.outcomes): the braid locking before
        # eps is the muscle's physical limit, not a solve that failed
        locks = point.get("limit", "") == BRAID_LOCKS
        if req.eps >= NEAR_LOCK_FRACTION * eps_max or locks:
            flags.append(f"r{k}:near_lock")
        if np.isfinite(threshold) and threshold >= req.pressure_bar:
            flags.append(f"r{k}:threshold_above_pressure")
        if out[f"r{k}_meets"] and force - req.force_N <= point_error_N(
                mesh, force, req.pressure_bar, threshold, row["D0_mm"], row["t0_mm"],
                row["L0_mm"]):
            # met by less than the mesh may be off: the fine mesh may say otherwise
            flags.append(f"r{k}:{MARGIN_WITHIN_MESH_ERROR}")
        if not point["converged"] or not np.isfinite(force):
            if not locks:
                flags.append(f"r{k}:fe_not_converged")
            failures.append(f"r{k}: {failure or 'no valid force'}")
    out["meets_all"] = all(out[f"r{k}_meets"] for k in range(1, len(requirements) + 1))
    out["min_fe_margin_pct"] = float(np.min(margins)) if not np.isnan(margins).any() else np.nan
    out["flags"] = ";".join(flags)
    out["fe_failure"] = "; ".join(failures)
    return out
