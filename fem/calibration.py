"""theta0 calibration: the braid angle at rest is not published, so each model fits it.

``fem/calibration.json`` is the versioned record every model reads its default theta0 from. Each
entry names the reference it was fitted to, the residual, the command and the date. Only theta0
is fitted; everything else in the physics stays as measured or published.
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.optimize import minimize_scalar

from fem.records import provenance

CALIBRATION_FILE = Path(__file__).with_name("calibration.json")
THETA0_BOUNDS_DEG = (15.0, 50.0)  # practical braids are 20-30 deg; 54.7 deg is the lock angle


@cache
def _load(path: Path = CALIBRATION_FILE) -> dict:
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def calibrated(key: str) -> dict:
    """The calibration entry ``key`` (for example ``"eq2-inner"``), with ``theta0_deg``."""
    entries = _load()
    if key not in entries:
        raise ValueError(f"no calibrated theta0 for model {key!r} in {CALIBRATION_FILE.name}: "
                         f"pass --theta0 or run `mkm fem calibrate --model {key.split('-')[0]}`")
    return entries[key]


class CalibratedTheta0:
    """Mixin of models whose braid angle defaults to their ``fem/calibration.json`` entry."""

    theta0_deg: float | None

    def _theta0(self) -> float:
        if self.theta0_deg is not None:
            return float(self.theta0_deg)
        return calibrated(self.calibration_key)["theta0_deg"]


def read_reference(path) -> pd.DataFrame:
    """A reference sweep: ``pressure_bar, D0_mm, t0_mm, eps, force_N`` (``L0_mm`` optional)."""
    df = pd.read_csv(path, comment="#")
    missing = {"pressure_bar", "D0_mm", "t0_mm", "eps", "force_N"} - set(df.columns)
    if missing:
        raise ValueError(f"reference {path} lacks columns {sorted(missing)}: expected "
                         "pressure_bar, D0_mm, t0_mm, eps, force_N")
    return df


def fit_theta0(make_model, reference: pd.DataFrame, bounds=THETA0_BOUNDS_DEG,
               xatol: float = 0.01) -> dict:
    """Least-squares fit of theta0 [deg] of ``make_model(theta0_deg)`` to ``reference`` forces.

    Returns the fitted angle, the RMSE and the largest residual [N], the fitted forces and how many
    model evaluations it took. Raises ``RuntimeError`` when the model cannot produce a valid force
    at the optimum (a fit on invalid points is no fit).
    """
    args = [reference[c].to_numpy() for c in ("pressure_bar", "D0_mm", "t0_mm", "eps")]
    target = reference["force_N"].to_numpy()
    n_eval = 0

    def rmse(theta0):
        nonlocal n_eval
        n_eval += 1
        pred = make_model(theta0).predict(*args)
        if not pred.valid.all():
            return 1e12
        return float(np.sqrt(np.mean((pred.force_N - target) ** 2)))

    res = minimize_scalar(rmse, bounds=bounds, method="bounded", options={"xatol": xatol})
    pred = make_model(res.x).predict(*args)
    if not pred.valid.all():
        raise RuntimeError(f"calibration failed: no theta0 in {bounds} deg gives valid forces")
    residual = pred.force_N - target
    return {"theta0_deg": round(float(res.x), 3), "rmse_N": float(np.sqrt(np.mean(residual**2))),
            "max_abs_residual_N": float(np.max(np.abs(residual))), "evaluations": n_eval,
            "force_N": pred.force_N, "seconds": pred.seconds}


def store_calibration(key: str, fit: dict, reference_path, model_params: dict) -> None:
    """Write (or replace) entry ``key`` of ``fem/calibration.json`` with the fit's provenance."""
    entries = json.loads(CALIBRATION_FILE.read_text()) if CALIBRATION_FILE.exists() else {}
    info = provenance()
    entries[key] = {
        "theta0_deg": fit["theta0_deg"],
        "rmse_N": round(fit["rmse_N"], 4),
        "max_abs_residual_N": round(fit["max_abs_residual_N"], 4),
        "reference": Path(reference_path).name,
        "model_params": {k: v for k, v in model_params.items() if k != "theta0_deg"},
        "command": info["command"],
        "date_utc": info["date_utc"],
        "versions": info["versions"],
    }
    CALIBRATION_FILE.write_text(json.dumps(entries, indent=2, sort_keys=True) + "\n")
    _load.cache_clear()
