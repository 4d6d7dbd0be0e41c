"""Scores of predictions against a reference, the same for the report and the study.

A prediction is scored point by point with the paper's Equation 7 (|Err%| scaled by the largest
reference force, :func:`mkm.fem.paper.equation7_err_pct`) and summarised per model by
:func:`error_summary` (largest |Err%|, RMSE [N], largest |residual| [N] over the valid points);
:func:`pareto_front` marks the models no other beats in both cost and error. The report scores
bench steps (:func:`predict_steps`, :func:`score_run`, :func:`summarise_run`), the study FE
sweeps; neither renders anything here.
"""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd

from mkm.fem.interface import ForceModel, Prediction
from mkm.fem.muscle import Muscle
from mkm.fem.paper import equation7_err_pct
from mkm.prediction_cache import cached_predict
from mkm.registry import entries


def error_summary(reference_N, force_N, valid, err_pct) -> dict:
    """Over the valid points: how many, the largest |Err%|, the RMSE [N] and the largest
    absolute residual ``reference - force`` [N] (NaN where no point is valid)."""
    ok = np.asarray(valid, dtype=bool)
    residual = np.asarray(reference_N, dtype=float)[ok] - np.asarray(force_N, dtype=float)[ok]
    err = np.abs(np.asarray(err_pct, dtype=float)[ok])
    n = int(ok.sum())
    return {
        "valid_points": n,
        "max_abs_err_pct": float(np.nanmax(err)) if n and np.isfinite(err).any() else np.nan,
        "rmse_N": float(np.sqrt(np.mean(residual**2))) if n else np.nan,
        "max_abs_residual_N": float(np.max(np.abs(residual))) if n else np.nan,
    }


def predict_steps(model: ForceModel, steps: pd.DataFrame, muscle: Muscle, cache_dir,
                  pressure_tolerance_bar: float = 0.0) -> tuple[Prediction, bool]:
    """Model forces at each step's measured mean pressure (through the cache for FE models),
    timed on a warm model (the cheap ones are called twice, the second call timed).

    A measured pressure within ``pressure_tolerance_bar`` (the regulator's settling tolerance)
    outside a model's pressure domain is evaluated at the domain's edge: 2.5001 bar measured at
    the 2.5 bar step is the 2.5 bar the surrogate was trained to, not an extrapolation.
    """
    pressure = domain_pressures(model, evaluation_pressures(steps), pressure_tolerance_bar)
    args = (pressure, muscle.D0_mm, muscle.t0_mm, muscle.eps)
    known = entries().get(model.name)
    if known is not None and known.expensive:  # seconds per sweep: cached
        return cached_predict(model, *args, cache_dir=cache_dir)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain points are flagged in the report itself
        # a cheap model's first call pays one-off set-up (a surrogate's first prediction takes
        # ten times its later ones): the call timed is the second, as every later one will be
        model.predict(*args)
        return model.predict(*args), False


def domain_pressures(model: ForceModel, pressure_bar: np.ndarray,
                     tolerance_bar: float) -> np.ndarray:
    """``pressure_bar`` with values within ``tolerance_bar`` of the model's pressure domain
    moved onto its edge (models without a ``domain`` are left alone)."""
    domain = getattr(model, "domain", None)
    if domain is None or tolerance_bar <= 0:
        return pressure_bar
    lo, hi = domain.pressure_bar
    near = (pressure_bar >= lo - tolerance_bar) & (pressure_bar <= hi + tolerance_bar)
    return np.where(near, np.clip(pressure_bar, lo, hi), pressure_bar)


def evaluation_pressures(steps: pd.DataFrame) -> np.ndarray:
    """Measured mean pressure per step (set pressure where none was measured), floored at 0 bar:
    a mean of -0.003 bar at the vented step is sensor noise, not a vacuum."""
    measured = steps["pressure_bar_mean"].fillna(steps["set_pressure_bar"])
    return np.maximum(measured.to_numpy(dtype=float), 0.0)


def slack(steps: pd.DataFrame) -> bool:
    """Whether a run pulled no force to score a model against: every step's mean force at most
    0 N, or within its expanded uncertainty (``force_U_N``, or twice the standard ``force_u_N``
    where only that is held: a slack muscle read through its load cell's noise, whose largest
    reading, a tenth of a newton, would be Equation 7's scale)."""
    force = steps["force_N_mean"].to_numpy(dtype=float)
    if not np.nanmax(force, initial=0.0) > 0:
        return True
    if "force_U_N" in steps:
        U = steps["force_U_N"].to_numpy(dtype=float)
    elif "force_u_N" in steps:
        U = 2.0 * steps["force_u_N"].to_numpy(dtype=float)
    else:
        return False
    return bool(np.isfinite(U).all() and (np.abs(force) <= U).all())


def score_run(steps: pd.DataFrame, prediction: Prediction, label: str) -> pd.DataFrame:
    """One row per step: measurement, the model's force, validity, Err% (Equation 7) and the
    residual F_meas - F_model [N]. ``pressure_bar`` is where the model was evaluated,
    ``pressure_meas_bar`` the measured mean (they differ at a domain edge)."""
    scale = 0.0 if slack(steps) else float(np.nanmax(steps["force_N_mean"].to_numpy(float)))
    valid = np.ravel(prediction.valid)
    force = np.where(valid, np.ravel(prediction.force_N), np.nan)
    rows = pd.DataFrame({
        "model": label, "step": steps["step"].to_numpy(), "direction": steps["direction"],
        "set_pressure_bar": steps["set_pressure_bar"].to_numpy(),
        "pressure_meas_bar": evaluation_pressures(steps),
        "pressure_bar": np.ravel(prediction.pressure_bar),
        "force_meas_N": steps["force_N_mean"].to_numpy(),
        "force_meas_std_N": steps["force_N_std"].to_numpy(),
        "force_N": force, "valid": valid, "settled": steps["settled"].to_numpy(),
    })
    # a run without force (a slack muscle all the way, :func:`slack`) has no Err%; its residuals
    # still count
    rows["err_pct"] = (equation7_err_pct(rows["force_meas_N"], rows["force_N"], scale)
                       if scale > 0 else np.nan)
    rows["residual_N"] = rows["force_meas_N"] - rows["force_N"]
    for key, value in prediction.extras.items():
        rows[key] = np.ravel(value)
    return normalised_error(rows, steps)


def normalised_error(rows: pd.DataFrame, steps: pd.DataFrame) -> pd.DataFrame:
    """``rows`` with ``E_n`` = (F_meas - F_model) / sqrt(U_meas^2 + (c U_p)^2 + U_model^2).

    ``U_meas`` and ``U_p`` are the step's expanded uncertainties (``force_U_N``,
    ``pressure_U_bar`` of steps.csv, 95.45 %), ``c`` the model's force per bar (the slope of a
    straight line through its valid forces: the models are linear in pressure) so the pressure's
    uncertainty counts in newtons, ``U_model`` twice the prediction's ``force_u_N`` (0 when it
    has none). ``|E_n| <= 1``: the step and the model agree within their uncertainties. NaN for a
    run recorded without a budget.
    """
    if "force_U_N" not in steps:
        rows["E_n"] = np.nan
        return rows
    U_meas = steps["force_U_N"].to_numpy(dtype=float)
    U_p = steps["pressure_U_bar"].to_numpy(dtype=float)
    ok = rows["valid"].to_numpy(bool) & np.isfinite(rows["force_N"].to_numpy(float))
    pressure = rows["pressure_bar"].to_numpy(float)
    slope = 0.0
    if ok.sum() >= 2 and np.ptp(pressure[ok]) > 0:
        slope = float(np.polyfit(pressure[ok], rows["force_N"].to_numpy(float)[ok], 1)[0])
    u_model = rows["force_u_N"].to_numpy(float) if "force_u_N" in rows else 0.0
    U = np.sqrt(U_meas**2 + (slope * U_p) ** 2 + (2 * np.nan_to_num(u_model)) ** 2)
    rows["force_meas_U_N"] = U_meas
    rows["U_N"] = U
    rows["E_n"] = np.where(ok, rows["residual_N"].to_numpy(float) / U, np.nan)
    return rows


def summarise_run(scored: pd.DataFrame, seconds: float, cached: bool) -> dict:
    """Numbers per model and run: points, valid points, largest |Err%|, RMSE [N] and largest
    |residual| [N] over the valid points, seconds per predicted force, from the cache (1/0),
    the model's band (:func:`band_pct`) and the consistency verdict (:func:`consistency`)."""
    return {
        "model": scored["model"].iloc[0], "points": len(scored),
        **error_summary(scored["force_meas_N"], scored["force_N"], scored["valid"],
                        scored["err_pct"]),
        "seconds_per_point": seconds / max(len(scored), 1),
        "from_cache": int(cached),
        "band_pct": band_pct(scored),
        **consistency(scored),
    }


def band_pct(scored: pd.DataFrame) -> float:
    """The model's widest ± 2 u band (``force_u_N``, :mod:`mkm.uncertainty`) over its valid
    steps, in % of the run's largest measured force (Equation 7's scale, so it reads beside
    |Err%|); NaN for a prediction without a band."""
    if "force_u_N" not in scored:
        return np.nan
    u = scored["force_u_N"].to_numpy(float)[scored["valid"].to_numpy(bool)]
    scale = float(np.nanmax(scored["force_meas_N"].to_numpy(float)))
    if not np.isfinite(u).any() or not scale > 0:
        return np.nan
    return float(100.0 * 2.0 * np.nanmax(u) / scale)


def consistency(scored: pd.DataFrame) -> dict:
    """``consistent``: True when ``|E_n| <= 1`` at every step with a valid force, False otherwise,
    None when no step has an E_n (no budget, no valid force); ``worst_E_n`` and ``worst_step``:
    the step of largest ``|E_n|``."""
    en = scored["E_n"].to_numpy(float) if "E_n" in scored else np.array([np.nan])
    if not np.isfinite(en).any():
        return {"consistent": None, "worst_E_n": np.nan, "worst_step": None}
    k = int(np.nanargmax(np.abs(en)))
    return {"consistent": bool(np.nanmax(np.abs(en)) <= 1.0), "worst_E_n": float(en[k]),
            "worst_step": int(scored["step"].iloc[k])}


def pareto_front(cost: np.ndarray, error: np.ndarray) -> np.ndarray:
    """True for the points no other point beats in both cost and error (ties kept)."""
    cost, error = np.asarray(cost, float), np.asarray(error, float)
    front = np.isfinite(cost) & np.isfinite(error)
    for i in np.flatnonzero(front):
        others = np.isfinite(cost) & np.isfinite(error)
        dominated = others & (cost <= cost[i]) & (error <= error[i]) & (
            (cost < cost[i]) | (error < error[i]))
        front[i] = not dominated.any()
    return front
