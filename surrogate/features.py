"""Physics features of the surrogates: what the closed-form models already know about the force.

Every function takes the raw inputs ``pressure_bar, D0_mm, t0_mm, eps`` (arrays, broadcast) and
returns numbers in the units its name says. The surrogates learn only what these miss (the end
effects of the clamped caps, which the mid-section models do not see).
"""

from __future__ import annotations

import numpy as np

from fem.calibration import calibrated
from fem.eq2 import chou_hannaford
from fem.thickwall import klute_hannaford_threshold_pressure

FEATURE_NAMES = ("pressure_bar", "D0_mm", "t0_mm", "eps", "one_minus_eps_sq",
                 "eq2_inner_force_N", "braid_slope_N_per_bar", "thickwall_threshold_bar",
                 "thickwall_force_N")


def braid_slope_N_per_bar(D0_mm, t0_mm, eps, theta0_deg):
    """Slope dF/dP of a muscle with an incompressible wall in an inextensible braid [N/bar].

    The pressure term of the virtual work is exactly Equation 2 written with the braid (outer)
    diameter ``D0 + 2 t0`` (modelling notes, "Physics of the muscle"); the wall only shifts the
    force down by its elastic term, so above the threshold pressure ``dF/dP`` is this.
    """
    return chou_hannaford(1.0, np.asarray(D0_mm) + 2.0 * np.asarray(t0_mm), eps, theta0_deg)


def thickwall_threshold_bar(D0_mm, t0_mm, eps, theta0_deg):
    """Threshold pressure P* of the closed-form thick-wall model [bar] (0 at ``eps = 0``).

    Below P* the muscle has not yet shortened by ``eps`` and pulls nothing (the isometric lock).
    NaN beyond the braid lock, where no pressure shortens the muscle that far.
    """
    return klute_hannaford_threshold_pressure(D0_mm, t0_mm, eps, theta0_deg)


def physics_features(X, columns, theta0_deg: float, thickwall_theta0_deg: float):
    """The features named in ``columns`` (from ``FEATURE_NAMES``) of ``X = [P, D0, t0, eps]``.

    ``theta0_deg`` is used for Equation 2 in the paper's inner-diameter form,
    ``thickwall_theta0_deg`` for the braid slope and the thick-wall threshold (the braid-diameter
    physics it was calibrated with); both are fixed when the estimator is built so that a saved
    surrogate never changes with a later calibration. Only the requested columns are computed:
    prediction latency is what a surrogate is for.
    """
    X = np.asarray(X, dtype=float)
    if X.ndim != 2 or X.shape[1] != 4:
        raise ValueError(f"X has shape {X.shape}: expected (n, 4) columns "
                         "pressure_bar, D0_mm, t0_mm, eps")
    unknown = [c for c in columns if c not in FEATURE_NAMES]
    if unknown:
        raise ValueError(f"unknown feature {unknown[0]!r}: expected some of "
                         f"{', '.join(FEATURE_NAMES)}")
    P, D0, t0, eps = X.T
    values = {"pressure_bar": P, "D0_mm": D0, "t0_mm": t0, "eps": eps}
    if "one_minus_eps_sq" in columns:
        values["one_minus_eps_sq"] = (1.0 - eps) ** 2
    if "eq2_inner_force_N" in columns:
        values["eq2_inner_force_N"] = chou_hannaford(P, D0, eps, theta0_deg)
    if {"braid_slope_N_per_bar", "thickwall_force_N"} & set(columns):
        values["braid_slope_N_per_bar"] = braid_slope_N_per_bar(D0, t0, eps,
                                                                thickwall_theta0_deg)
    if {"thickwall_threshold_bar", "thickwall_force_N"} & set(columns):
        values["thickwall_threshold_bar"] = thickwall_threshold_bar(D0, t0, eps,
                                                                    thickwall_theta0_deg)
    if "thickwall_force_N" in columns:  # the thick-wall force under the isometric lock
        values["thickwall_force_N"] = values["braid_slope_N_per_bar"] * np.maximum(
            P - values["thickwall_threshold_bar"], 0.0)
    return np.column_stack([values[c] for c in columns])


def default_theta0_deg() -> dict[str, float]:
    """The calibrated braid angles the features use by default (``fem/calibration.json``)."""
    return {"theta0_deg": calibrated("eq2-inner")["theta0_deg"],
            "thickwall_theta0_deg": calibrated("thickwall")["theta0_deg"]}
