"""The surrogate kinds that are scikit-learn pipelines on physics features
(:func:`mkm.surrogate.features.physics_features`): ``physics``, the threshold-linear regressor
around the closed form's slope and threshold, and ``gp``, a Gaussian process row by row."""

from __future__ import annotations

from sklearn.pipeline import Pipeline
from sklearn.preprocessing import FunctionTransformer, StandardScaler

from mkm.surrogate.features import physics_features
from mkm.surrogate.gp import gaussian_process
from mkm.surrogate.threshold_linear import ThresholdLinearRegressor

CALL_INPUTS = ("pressure_bar", "D0_mm", "t0_mm", "eps")
GP_FEATURES = ("pressure_bar", "D0_mm", "t0_mm", "eps", "thickwall_force_N")
# z of the physics model: the thick-wall threshold carries the shape in eps that a quadratic in
# eps alone cannot (3 levels of eps in the paper grid); measured on the test muscles.
PHYSICS_GEOMETRY = ("D0_mm", "t0_mm", "eps", "thickwall_threshold_bar")


def _features(columns, inputs, fixed):
    """Transformer from the surrogate's inputs to the named physics features."""
    return FunctionTransformer(physics_features, kw_args={"columns": tuple(columns),
                                                         "inputs": tuple(inputs),
                                                         "fixed": dict(fixed or {})})


def gp_model(inputs=CALL_INPUTS, fixed=None, random_state: int = 0, restarts: int = 2):
    """Gaussian process on physics features: Matern 5/2 with one length scale per feature;
    ``restarts`` of the marginal likelihood's optimiser."""
    features = (*GP_FEATURES[:4], *inputs[4:], GP_FEATURES[4])
    return Pipeline([
        ("features", _features(features, inputs, fixed)),
        ("scale", StandardScaler()),
        ("gp", gaussian_process(len(features), random_state, restarts)),
    ])


def physics_model(inputs=CALL_INPUTS, fixed=None, degree: int = 2, alpha: float = 1e-3):
    """``F = A max(0, P - P*)``: braid slope and thick-wall threshold, corrected in geometry by
    polynomials of ``degree`` with the ridge penalty ``alpha``
    (:class:`~mkm.surrogate.threshold_linear.ThresholdLinearRegressor`)."""
    columns = ("pressure_bar", "braid_slope_N_per_bar", "thickwall_threshold_bar",
               *PHYSICS_GEOMETRY, *inputs[4:])
    return Pipeline([
        ("features", _features(columns, inputs, fixed)),
        ("model", ThresholdLinearRegressor(
            pressure_column=0, slope_prior_column=1, threshold_prior_column=2,
            geometry_columns=tuple(range(3, len(columns))), degree=degree, alpha=alpha)),
    ])
