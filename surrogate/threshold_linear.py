"""The threshold-linear regressor: ``y = A(z) max(0, P - P*(z))``, the structure of the muscle
force at fixed geometry, fitted by least squares (``scipy.optimize.least_squares``)."""

from __future__ import annotations

from numbers import Integral, Real

import numpy as np
from scipy.optimize import least_squares
from sklearn.base import BaseEstimator, RegressorMixin
from sklearn.preprocessing import PolynomialFeatures
from sklearn.utils._param_validation import Interval
from sklearn.utils.validation import check_is_fitted, validate_data
from threadpoolctl import threadpool_limits

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
    phi = monomials(Z, powers)
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


def monomials(Z, powers):
    """``phi[i, k] = prod_j Z[i, j] ** powers[k, j]`` (PolynomialFeatures without its checks)."""
    if Z.shape[1] == 0:
        return np.ones((len(Z), 1))
    return np.prod(Z[:, None, :] ** powers[None, :, :], axis=2)


COLUMN = Interval(Integral, 0, None, closed="left")


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

    _parameter_constraints: dict = {
        "pressure_column": [COLUMN],
        "geometry_columns": ["array-like", None],
        "slope_prior_column": [COLUMN, None],
        "threshold_prior_column": [COLUMN, None],
        "degree": [Interval(Integral, 0, None, closed="left")],
        "alpha": [Interval(Real, 0, None, closed="left")],
    }

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
        self._validate_params()
        X, y = validate_data(self, X, y, y_numeric=True)
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
        phi = monomials((X[:, self.geometry_columns_] - self.z_mean_) / self.z_scale_,
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
