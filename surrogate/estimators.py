"""Surrogate force estimators (scikit-learn API) and the named kinds the project trains.

Every kind maps ``X = [pressure_bar, D0_mm, t0_mm, eps]`` to the force in N:

- ``mlp-paper``: the paper's best net (3 x 100 ReLU) trained as MATLAB's ``fitrnet`` does;
- ``mlp-standardised``: the same net with the response standardised too;
- ``gp``: a Gaussian process (Matern 5/2, one length scale per input, noise term) on physics
  features, with a predictive standard deviation;
- ``physics``: :class:`ThresholdLinearRegressor`, ``F = A max(0, P - P*)`` with the slope ``A``
  and threshold ``P*`` of the closed-form models corrected by smooth functions of the geometry:
  non-negative and non-decreasing in pressure by construction;
- ``net-<layers>x<size>-<activation>[-standardised]``: the 27 nets of the paper's Table 2.

``best`` names the kind chosen by the numbers (see the README's surrogate section).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import least_squares
from sklearn.base import BaseEstimator, RegressorMixin
from sklearn.compose import TransformedTargetRegressor
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import ConstantKernel, Matern, WhiteKernel
from sklearn.neural_network import MLPRegressor
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import FunctionTransformer, PolynomialFeatures, StandardScaler
from sklearn.utils.validation import check_is_fitted, validate_data
from threadpoolctl import threadpool_limits

from surrogate.features import default_theta0_deg, physics_features

EXP_CLIP = 30.0  # keeps exp() finite while least squares explores; e^30 is far beyond any slope


def fit_threshold_linear(P, Z, y, slope_prior, threshold_prior, degree, alpha):
    """Least-squares fit of ``y = A max(0, P - P*)`` with smooth ``A(Z)`` and ``P*(Z)``.

    ``A = slope_prior exp(phi(Z) a)`` and ``P* = max(0, threshold_prior + phi(Z) b)``, ``phi``
    the polynomial features of ``Z`` up to ``degree`` (with intercept). ``alpha`` is a ridge
    penalty on the non-intercept coefficients (relative to the scale of ``y``). Returns
    ``(a, b, powers, result)``: ``phi(Z) = prod(Z ** powers, axis=-1)``, scipy's result.
    """
    poly = PolynomialFeatures(degree=degree if Z.shape[1] else 0, include_bias=True)
    powers = poly.fit(Z if Z.shape[1] else np.zeros((len(P), 1))).powers_
    phi = _monomials(Z, powers)
    n = phi.shape[1]
    y_scale = max(float(np.std(y)), float(np.max(np.abs(y), initial=0.0)) * 1e-3, 1e-12)
    a0 = np.zeros(n)
    if np.all(slope_prior == 1.0):  # no prior: start from the least-squares slope of y on P
        slope = np.sum(P * y) / max(np.sum(P * P), 1e-300)
        a0[0] = np.log(max(abs(slope), 1e-12))
    x0 = np.concatenate([a0, np.zeros(n)])
    penalty = np.sqrt(alpha) * np.concatenate([[0.0], np.ones(n - 1), [0.0], np.ones(n - 1)])

    def parts(x):
        A = slope_prior * np.exp(np.clip(phi @ x[:n], -EXP_CLIP, EXP_CLIP))
        raw = threshold_prior + phi @ x[n:]
        return A, raw, P - np.maximum(raw, 0.0)

    def residuals(x):
        A, _, excess = parts(x)
        return np.concatenate([(A * np.maximum(excess, 0.0) - y) / y_scale, penalty * x])

    def jacobian(x):
        A, raw, excess = parts(x)
        active = excess > 0.0
        d_a = (A * np.where(active, excess, 0.0) / y_scale)[:, None] * phi
        d_b = -(A * (active & (raw >= 0.0)) / y_scale)[:, None] * phi  # one-sided at 0
        return np.vstack([np.hstack([d_a, d_b]), np.diag(penalty)])

    # Small dense problems: BLAS threads only spin against each other (100x slower on a busy
    # machine), so the solve runs on one thread.
    with threadpool_limits(limits=1):
        result = least_squares(residuals, x0, jac=jacobian, method="trf", max_nfev=2000)
    return result.x[:n], result.x[n:], powers, result


def _monomials(Z, powers):
    """``phi[i, k] = prod_j Z[i, j] ** powers[k, j]`` (PolynomialFeatures without its checks)."""
    if Z.shape[1] == 0:
        return np.ones((len(Z), 1))
    return np.prod(Z[:, None, :] ** powers[None, :, :], axis=2)


class ThresholdLinearRegressor(RegressorMixin, BaseEstimator):
    """``y = A(z) max(0, P - P*(z))``: affine above a threshold, zero below, in one input ``P``.

    The exact structure of the muscle force at fixed geometry (modelling notes): zero until the
    pressure reaches the threshold ``P*`` at which the muscle has shortened by ``eps``, linear
    above it. ``A = prior_A exp(poly(z))`` is positive and ``P* >= 0``, so predictions are
    non-negative and non-decreasing in ``P`` whatever the coefficients.

    Parameters
    ----------
    pressure_column : int, default 0
        Column of ``X`` holding the pressure ``P``.
    geometry_columns : sequence of int or None, default None
        Columns ``z`` the slope and threshold depend on (standardised before the polynomial).
        None: every column that is neither the pressure nor a prior.
    slope_prior_column, threshold_prior_column : int or None, default None
        Columns holding a physics prior for ``A`` (multiplied) and ``P*`` (added); None: no prior.
    degree : int, default 2
        Degree of the polynomial in ``z`` of ``log(A / prior_A)`` and ``P* - prior_P*``.
    alpha : float, default 1e-3
        Ridge penalty on the polynomial coefficients (intercepts are free).
    """

    def __init__(self, pressure_column=0, geometry_columns=None, slope_prior_column=None,
                 threshold_prior_column=None, degree=2, alpha=1e-3):
        self.pressure_column = pressure_column
        self.geometry_columns = geometry_columns
        self.slope_prior_column = slope_prior_column
        self.threshold_prior_column = threshold_prior_column
        self.degree = degree
        self.alpha = alpha

    def __sklearn_tags__(self):
        tags = super().__sklearn_tags__()
        # The model is non-negative and monotone in one column by design: generic check data
        # (negative targets, no threshold) cannot be fitted well, and is not meant to be.
        tags.regressor_tags.poor_score = True
        return tags

    def _columns(self, n_features):
        special = [c for c in (self.pressure_column, self.slope_prior_column,
                               self.threshold_prior_column) if c is not None]
        for c in special:
            if not 0 <= c < n_features:
                raise ValueError(f"column {c} is invalid: X has {n_features} columns")
        if self.geometry_columns is None:
            return [c for c in range(n_features) if c not in special]
        geometry = list(self.geometry_columns)
        for c in geometry:
            if not 0 <= c < n_features:
                raise ValueError(f"geometry column {c} is invalid: X has {n_features} columns")
        return geometry

    def _priors(self, X):
        slope = X[:, self.slope_prior_column] if self.slope_prior_column is not None else 1.0
        threshold = (X[:, self.threshold_prior_column]
                     if self.threshold_prior_column is not None else 0.0)
        return np.broadcast_to(slope, len(X)), np.broadcast_to(threshold, len(X))

    def fit(self, X, y):
        X, y = validate_data(self, X, y, y_numeric=True)
        if self.degree < 0 or int(self.degree) != self.degree:
            raise ValueError(f"degree={self.degree!r} is invalid: expected an integer >= 0")
        if self.alpha < 0:
            raise ValueError(f"alpha={self.alpha!r} is invalid: expected a penalty >= 0")
        self.geometry_columns_ = self._columns(X.shape[1])
        slope, threshold = self._priors(X)
        if np.any(slope <= 0) or not np.all(np.isfinite(threshold)):
            raise ValueError("slope prior must be > 0 and threshold prior finite on every row")
        Z = X[:, self.geometry_columns_]
        self.z_mean_ = Z.mean(axis=0)
        self.z_scale_ = np.where(Z.std(axis=0) > 0, Z.std(axis=0), 1.0)
        a, b, self.powers_, result = fit_threshold_linear(
            X[:, self.pressure_column], (Z - self.z_mean_) / self.z_scale_, y, slope, threshold,
            int(self.degree), float(self.alpha))
        self.slope_coef_, self.threshold_coef_ = a, b
        self.n_iter_ = int(result.nfev)
        return self

    def decompose(self, X):
        """Slope ``A`` [y per unit P] and threshold ``P*`` [unit of P] for each row of ``X``."""
        check_is_fitted(self)
        return self._decompose(validate_data(self, X, reset=False))

    def _decompose(self, X):
        slope, threshold = self._priors(X)
        phi = _monomials((X[:, self.geometry_columns_] - self.z_mean_) / self.z_scale_,
                         self.powers_)
        A = slope * np.exp(np.clip(phi @ self.slope_coef_, -EXP_CLIP, EXP_CLIP))
        return A, np.maximum(threshold + phi @ self.threshold_coef_, 0.0)

    def predict(self, X):
        check_is_fitted(self)
        return self.predict_validated(validate_data(self, X, reset=False))

    def predict_validated(self, X):
        """:meth:`predict` on a float array the caller has validated (no per-call checks)."""
        A, threshold = self._decompose(X)
        return A * np.maximum(X[:, self.pressure_column] - threshold, 0.0)


# --- The kinds --------------------------------------------------------------------------------

ACTIVATIONS = {"relu": "relu", "tanh": "tanh", "sigmoid": "logistic"}  # paper name -> sklearn


def paper_net(layers: int, size: int, activation: str, standardise_response: bool = False,
              random_state: int = 0):
    """One of the paper's Table 2 nets, trained as MATLAB's ``fitrnet`` in Regression Learner.

    fitrnet: L-BFGS on the mean squared error, ``Lambda = 0`` (no L2), ``IterationLimit = 1000``,
    ``Standardize = true`` (inputs only; the response stays in N), Glorot-initialised weights.
    Here: ``MLPRegressor(solver="lbfgs", alpha=0, max_iter=1000)`` after a ``StandardScaler``.
    Differences: scikit-learn minimises half the MSE (same minimiser), initialises biases
    randomly (fitrnet: zeros) and the logistic layers' weights in a narrower Glorot range,
    stops at a projected gradient of ``tol`` (set to fitrnet's ``GradientTolerance`` 1e-6) or
    at SciPy's relative loss change 2.2e-9 (fitrnet: ``LossTolerance`` 1e-6, ``StepTolerance``
    1e-6); both stop at 1000 iterations, fitrnet silently, scikit-learn with a warning.
    ``standardise_response=True`` also standardises the force (the fix of the tanh and
    sigmoid rows).
    """
    if activation not in ACTIVATIONS:
        raise ValueError(f"activation={activation!r} is invalid: expected one of "
                         f"{', '.join(ACTIVATIONS)}")
    net = Pipeline([
        ("scale", StandardScaler()),
        ("net", MLPRegressor(hidden_layer_sizes=(size,) * layers,
                             activation=ACTIVATIONS[activation], solver="lbfgs", alpha=0.0,
                             max_iter=1000, tol=1e-6, random_state=random_state)),
    ])
    if standardise_response:
        return TransformedTargetRegressor(regressor=net, transformer=StandardScaler())
    return net


# Table 2 of the paper, in its order (# 1..27): activation, then size, then layers.
PAPER_NETS = [(layers, size, act) for act in ACTIVATIONS for size in (25, 50, 100)
              for layers in (1, 2, 3)]


def net_kind(layers: int, size: int, activation: str, standardise_response=False) -> str:
    return f"net-{layers}x{size}-{activation}" + ("-standardised" if standardise_response else "")


def _features(columns, theta0):
    """Transformer from ``[P, D0, t0, eps]`` to the named physics features (theta0 frozen)."""
    return FunctionTransformer(physics_features, kw_args={"columns": tuple(columns), **theta0})


GP_FEATURES = ("pressure_bar", "D0_mm", "t0_mm", "eps", "thickwall_force_N")


def gp_model(random_state: int = 0, theta0=None, features=GP_FEATURES):
    """Gaussian process on physics features: Matern 5/2 with one length scale per feature."""
    theta0 = theta0 or default_theta0_deg()
    kernel = (ConstantKernel(1.0, (1e-3, 1e3))
              * Matern(length_scale=np.ones(len(features)), length_scale_bounds=(1e-2, 1e3),
                       nu=2.5)
              + WhiteKernel(1e-4, (1e-10, 1e-1)))
    return Pipeline([
        ("features", _features(features, theta0)),
        ("scale", StandardScaler()),
        ("gp", GaussianProcessRegressor(kernel=kernel, normalize_y=True, n_restarts_optimizer=2,
                                        random_state=random_state)),
    ])


# z of the physics model: the thick-wall threshold carries the shape in eps that a quadratic in
# eps alone cannot (3 levels of eps in the dataset); measured on the test muscles, see README.
PHYSICS_GEOMETRY = ("D0_mm", "t0_mm", "eps", "thickwall_threshold_bar")


def physics_model(theta0=None, degree: int = 2, alpha: float = 1e-3,
                  geometry=PHYSICS_GEOMETRY):
    """``F = A max(0, P - P*)``: braid slope and thick-wall threshold, corrected in geometry."""
    theta0 = theta0 or default_theta0_deg()
    columns = ("pressure_bar", "braid_slope_N_per_bar", "thickwall_threshold_bar", *geometry)
    return Pipeline([
        ("features", _features(columns, theta0)),
        ("model", ThresholdLinearRegressor(
            pressure_column=0, slope_prior_column=1, threshold_prior_column=2,
            geometry_columns=tuple(range(3, len(columns))), degree=degree, alpha=alpha)),
    ])


KINDS = ("mlp-paper", "mlp-standardised", "gp", "physics")
BEST = "physics"


def kind_names(include_nets: bool = True) -> list[str]:
    """Every kind :func:`make_estimator` builds: the named ones, then the 54 Table 2 nets."""
    names = list(KINDS)
    if include_nets:
        names += [net_kind(*cfg, std) for std in (False, True) for cfg in PAPER_NETS]
    return names


def make_estimator(kind: str, random_state: int = 0):
    """A fresh, unfitted estimator of ``kind`` (``best`` resolves to :data:`BEST`)."""
    kind = BEST if kind == "best" else kind
    if kind == "mlp-paper":
        return paper_net(3, 100, "relu", random_state=random_state)
    if kind == "mlp-standardised":
        return paper_net(3, 100, "relu", standardise_response=True, random_state=random_state)
    if kind == "gp":
        return gp_model(random_state=random_state)
    if kind == "physics":
        return physics_model()
    if kind.startswith("net-"):
        parts = kind.split("-")
        try:
            layers, size = (int(v) for v in parts[1].split("x"))
            activation = parts[2]
        except (ValueError, IndexError):
            parts = None
        if parts and len(parts) <= 4 and (len(parts) == 3 or parts[3] == "standardised"):
            return paper_net(layers, size, activation, len(parts) == 4, random_state)
    raise ValueError(f"unknown surrogate kind {kind!r}: expected best, {', '.join(KINDS)} or "
                     "net-<layers>x<size>-<relu|tanh|sigmoid>[-standardised]")
