"""Physics features of the surrogates: what the closed-form models already know about the force.

Every function takes the muscle's inputs (arrays, broadcast) and returns numbers in the units its
name says. The braid angle and the rubber are those of the muscle itself (a column of the
surrogate's inputs, or the one value its training data held), never a calibration looked up at
prediction time, so a saved surrogate does not move when the calibration does. The surrogates
learn only what these miss (mostly the end effects of the clamped caps, which the mid-section
models do not see).
"""

from __future__ import annotations

import numpy as np

from mkm.fem.eq2 import chou_hannaford
from mkm.fem.thickwall import klute_hannaford_threshold_pressure

FEATURE_NAMES = ("pressure_bar", "D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg", "C10_MPa",
                 "C01_MPa", "one_minus_eps_sq", "eq2_inner_force_N", "braid_slope_N_per_bar",
                 "thickwall_threshold_bar", "thickwall_force_N")


def braid_slope_N_per_bar(D0_mm, t0_mm, eps, theta0_deg):
    """Slope dF/dP of a muscle with an incompressible wall in an inextensible braid [N/bar].

    The pressure term of the virtual work is exactly Equation 2 written with the braid (outer)
    diameter ``D0 + 2 t0`` (modelling notes, "Physics of the muscle"); the wall only shifts the
    force down by its elastic term, so above the threshold pressure ``dF/dP`` is this.
    """
    return chou_hannaford(1.0, np.asarray(D0_mm) + 2.0 * np.asarray(t0_mm), eps, theta0_deg)


def thickwall_threshold_bar(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa):
    """Threshold pressure P* of the closed-form thick-wall model [bar] (0 at ``eps = 0``).

    Below P* the muscle has not yet shortened by ``eps`` and pulls nothing (the isometric lock).
    NaN beyond the braid lock, where no pressure shortens the muscle that far.
    """
    return klute_hannaford_threshold_pressure(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa)


def columns_of(X, inputs, fixed) -> dict[str, np.ndarray]:
    """The muscle's values by name: the columns ``inputs`` of ``X``, then the ``fixed`` ones."""
    X = np.asarray(X, dtype=float)
    if X.ndim != 2 or X.shape[1] != len(inputs):
        raise ValueError(f"X has shape {X.shape}: expected (n, {len(inputs)}) columns "
                         f"{', '.join(inputs)}")
    values = {name: X[:, i] for i, name in enumerate(inputs)}
    values.update({k: np.full(len(X), float(v)) for k, v in (fixed or {}).items()
                   if k not in values})
    return values


def physics_features(X, columns, inputs, fixed=None):
    """The features named in ``columns`` (from :data:`FEATURE_NAMES`) of ``X``.

    ``X`` holds the columns ``inputs`` (``pressure_bar, D0_mm, t0_mm, eps`` and any of
    ``L0_mm, theta0_deg, C10_MPa, C01_MPa``); ``fixed`` gives the value of each parameter that
    is not a column. Only the requested columns are computed: prediction latency is what a
    surrogate is for.
    """
    unknown = [c for c in columns if c not in FEATURE_NAMES]
    if unknown:
        raise ValueError(f"unknown feature {unknown[0]!r}: expected some of "
                         f"{', '.join(FEATURE_NAMES)}")
    values = columns_of(X, inputs, fixed)
    P, D0, t0, eps = (values[k] for k in ("pressure_bar", "D0_mm", "t0_mm", "eps"))
    need = set(columns)
    if "one_minus_eps_sq" in need:
        values["one_minus_eps_sq"] = (1.0 - eps) ** 2
    if "eq2_inner_force_N" in need:
        values["eq2_inner_force_N"] = chou_hannaford(P, D0, eps, values["theta0_deg"])
    if need & {"braid_slope_N_per_bar", "thickwall_force_N"}:
        values["braid_slope_N_per_bar"] = braid_slope_N_per_bar(D0, t0, eps,
                                                                values["theta0_deg"])
    if need & {"thickwall_threshold_bar", "thickwall_force_N"}:
        values["thickwall_threshold_bar"] = thickwall_threshold_bar(
            D0, t0, eps, values["theta0_deg"], values["C10_MPa"], values["C01_MPa"])
    if "thickwall_force_N" in need:  # the thick-wall force under the isometric lock
        values["thickwall_force_N"] = values["braid_slope_N_per_bar"] * np.maximum(
            P - values["thickwall_threshold_bar"], 0.0)
    return np.column_stack([values[c] for c in columns])
