"""The default surrogate kind ``muscle-gp``: per muscle ``F = A max(0, P - P*)``, slope and
threshold of the thick-wall closed form at effective shortenings two Gaussian processes learn
over the muscle parameters (:class:`MuscleThresholdGP`); :func:`muscle_slopes` reads each FE
sweep's slope and threshold."""

from __future__ import annotations

from numbers import Integral

import numpy as np
from sklearn.base import BaseEstimator, RegressorMixin
from sklearn.utils._param_validation import Interval
from sklearn.utils.validation import check_is_fitted, validate_data
from threadpoolctl import threadpool_limits

from mkm.fem.thickwall import effective_eps_of_slope, effective_eps_of_threshold
from mkm.surrogate.coverage import coverage_fit, rescale_fit
from mkm.surrogate.gp import fit_gaussian_process, leave_one_out, predict_mean_std
from mkm.surrogate.muscle_predictor import (
    LINEARITY_BINS_BAR,
    MusclePredictor,
    calibrated_factor,
    force_parts,
    from_log_k,
    log_k,
    muscle_values,
    process_inputs,
    threshold_factor,
)


def muscle_slopes(P, y, groups, threshold=None):
    """Slope ``A`` [N/bar] and threshold ``P*`` [bar] of each muscle's sweep, and the lines' error.

    The FE force of one muscle is close to threshold-linear in the pressure: ``A`` and
    ``P*`` are the least-squares line through the points above the threshold (two or more; with
    one, the line through it and the FE threshold ``threshold``). Returns ``(muscles, A, P*,
    linearity)``: NaN where a sweep has too few points above its threshold (a muscle whose
    threshold lies above every pressure); ``linearity`` the RMS of the lines' residuals divided
    by their slope [bar] in each bin of ``P - P*`` (:data:`LINEARITY_BINS_BAR`; the FE bends
    most right above the threshold): the error floor of a threshold-linear model.
    """
    muscles = np.unique(groups)
    A = np.full(muscles.size, np.nan)
    Pstar = np.full(muscles.size, np.nan)
    above_threshold, residual_bar = [], []
    scale = max(float(np.max(np.abs(y), initial=0.0)), 1e-300)
    for k, m in enumerate(muscles):
        rows = groups == m
        p, f = P[rows], y[rows]
        fe_threshold = np.nan if threshold is None else float(np.nanmax(threshold[rows],
                                                                       initial=np.nan))
        above = f > 1e-9 * scale
        if above.sum() >= 2:
            slope, intercept = np.polyfit(p[above], f[above], 1)
            if slope > 0:
                A[k], Pstar[k] = slope, -intercept / slope
                above_threshold.append(p[above] - Pstar[k])
                residual_bar.append((f[above] - (slope * p[above] + intercept)) / slope)
        elif above.sum() == 1 and np.isfinite(fe_threshold) and p[above][0] > fe_threshold:
            A[k] = f[above][0] / (p[above][0] - fe_threshold)
            Pstar[k] = fe_threshold
        elif np.isfinite(fe_threshold):
            Pstar[k] = fe_threshold
    linearity = np.zeros(len(LINEARITY_BINS_BAR) - 1)
    if residual_bar:
        x, r = np.concatenate(above_threshold), np.concatenate(residual_bar)
        which = np.digitize(x, LINEARITY_BINS_BAR[1:-1])
        overall = float(np.sqrt(np.mean(r**2)))
        linearity = np.array([np.sqrt(np.mean(r[which == b] ** 2)) if (which == b).any()
                              else overall for b in range(linearity.size)])
    return muscles, A, Pstar, linearity


def bend_below_line_bar(Pstar, fe_threshold) -> float:
    """How far below the lines' thresholds ``Pstar`` the FE forces start [bar]: the largest
    ``P*_line - P*_FE`` over the sweeps (0 without FE thresholds). The FE force rises from its
    own threshold with a bend, so the straight line through the points above it crosses zero
    a little higher (0.002 bar typically, 0.006 at most over the shipped design)."""
    if fe_threshold is None:
        return 0.0
    gap = np.asarray(Pstar, dtype=float) - np.asarray(fe_threshold, dtype=float)
    gap = gap[np.isfinite(gap)]
    return float(max(gap.max(initial=0.0), 0.0))


class MuscleThresholdGP(RegressorMixin, BaseEstimator):
    """``F = A max(0, P - P*)``: slope and threshold of the thick-wall closed form at effective
    shortenings learnt by Gaussian processes over the muscle parameters.

    Held at ``eps``, a muscle with clamped caps is the closed form's mid-section model at a
    larger shortening: the ends, kept narrow by the caps, shorten less, so the middle shortens
    more (the FE design: the threshold is the thick-wall one at ``k_P eps``, ``k_P`` growing with
    ``D_braid / L0``; the slope at ``k_A eps``, ``k_A`` above 1). Fit:
    each sweep's ``A`` and ``P*`` (:func:`muscle_slopes`) give ``k_A`` and ``k_P``
    (:func:`effective_eps_of_slope`, :func:`effective_eps_of_threshold`); two Gaussian
    processes (Matern 5/2, one length scale per input, a noise term) learn ``log k_A`` and
    ``log k_P`` over the standardised muscle parameters and ``D_braid / L0`` (the slope's with
    ``sqrt(eps)`` for ``eps``: ``log k_A`` is close to linear in it). Predict:
    ``A = A_tw(k_A eps)``, ``P* = P*_tw(k_P eps)``: non-negative and non-decreasing in
    pressure by construction, and the closed form itself at ``eps = 0``, where the FE is too.
    The standard deviation carries the processes' std ``s`` of ``log k``, calibrated as
    ``c s (log k_A / m_ref)^beta`` (:meth:`_calibrated`), through ``A`` and ``P*`` (first
    order) to the force exactly for a Gaussian ``P*`` and a log-normal ``A`` (the moments of
    ``max(0, P - P*)``), plus the error of the threshold-linear form itself from a little below
    the threshold up (``linearity_bar_`` and ``bend_bar_``, measured on the training sweeps:
    :func:`~mkm.surrogate.muscle_predictor.linearity_floor_bar`). ``log k_A``, the slope
    process's mean, is the size of the end-effect correction (largest for short, wide muscles
    at a low braid angle): the processes' own std misses that their errors grow with it (with
    one scale the short muscles at low braid angles were off by more std than the others), so
    errors pooled over the box were heavier-tailed than normal and no single scale can hold
    both 68 % within 1 std and 95 % within 2. ``c`` (``std_scale_``) and ``beta``
    (``std_power_``; ``m_ref``, ``std_reference_``, the median ``log k_A`` of the points) are
    fitted (:func:`coverage_fit`) to leave-one-muscle-out errors at fit time, then by
    :meth:`calibrate_std` to muscles the fit did not see; last, a factor of the whole std
    (``std_rescale_ (k_A eps / 0.1)^std_rescale_power_ (theta0 / 30)^std_rescale_angle_power_``,
    :meth:`rescale_std`) fitted on a held-out set of further muscles makes 1, 2 and 3 std hold
    68, 95 and 99.7 % of the errors, in all of them and in each third of the braid angles.

    Parameters
    ----------
    inputs : sequence of str
        Names of the columns of ``X``; ``pressure_bar`` first.
    fixed : dict, optional
        Values of the muscle parameters (``theta0_deg``, ``C10_MPa``, ...) that are not columns.
    restarts : int, default 3
        Optimiser restarts of each process's marginal likelihood.
    random_state : int, default 0
    """

    _parameter_constraints: dict = {
        "inputs": ["array-like"],
        "fixed": [dict, None],
        "restarts": [Interval(Integral, 0, None, closed="left")],
        "random_state": ["random_state"],
    }

    def __init__(self, inputs=("pressure_bar", "D0_mm", "t0_mm", "eps"), fixed=None,
                 restarts: int = 3, random_state: int = 0):
        self.inputs = inputs
        self.fixed = fixed
        self.restarts = restarts
        self.random_state = random_state

    def _muscle(self, X):
        return muscle_values(X, self.inputs, self.fixed)

    def fit(self, X, y, threshold_pressure_bar=None):
        """Fit on FE sweeps (rows of several pressures per muscle); ``threshold_pressure_bar``:
        the FE's threshold per row (used for sweeps with fewer than two points above it)."""
        self._validate_params()
        X, y = validate_data(self, X, y, y_numeric=True)
        if tuple(self.inputs)[0] != "pressure_bar" or len(self.inputs) != X.shape[1]:
            raise ValueError(f"inputs={self.inputs!r} do not name the {X.shape[1]} columns of "
                             "X with pressure_bar first")
        _, groups = np.unique(X[:, 1:], axis=0, return_inverse=True)
        groups = groups.ravel()
        threshold = (None if threshold_pressure_bar is None
                     else np.asarray(threshold_pressure_bar, dtype=float))
        muscles, A, Pstar, self.linearity_bar_ = muscle_slopes(X[:, 0], y, groups, threshold)
        first = np.array([np.flatnonzero(groups == m)[0] for m in muscles])
        self.bend_bar_ = bend_below_line_bar(Pstar, None if threshold is None
                                             else threshold[first])
        self.std_rescale_, self.std_rescale_power_, self.std_rescale_angle_power_ = 1.0, 0.0, 0.0
        v, z = self._muscle(X[first])
        with np.errstate(divide="ignore", invalid="ignore"):  # eps = 0: no k, not used
            k_A = effective_eps_of_slope(A, v["D0_mm"], v["t0_mm"], v["theta0_deg"]) / v["eps"]
            k_P = effective_eps_of_threshold(Pstar, v["D0_mm"], v["t0_mm"], v["theta0_deg"],
                                             v["C10_MPa"], v["C01_MPa"]) / v["eps"]
        self.z_mean_ = z.mean(axis=0)
        self.z_scale_ = np.where(z.std(axis=0) > 0, z.std(axis=0), 1.0)
        zs = process_inputs((z - self.z_mean_) / self.z_scale_, self.inputs)
        processes, fitted = [], []
        with threadpool_limits(limits=1):
            for name, k, z_process in (("slope", k_A, zs[0]), ("threshold", k_P, zs[1])):
                ok = (v["eps"] > 0) & np.isfinite(k) & (k > 0)
                if ok.sum() < 2:
                    raise ValueError(f"{int(ok.sum())} muscle sweep(s) with eps > 0 and a "
                                     f"measurable {name}: expected at least 2")
                processes.append(fit_gaussian_process(z_process[ok], np.log(k[ok]),
                                                      self.random_state, self.restarts))
                fitted.append(np.flatnonzero(ok))
            (self.slope_gp_, self.slope_posterior_), (self.threshold_gp_,
                                                      self.threshold_posterior_) = processes
            # processes fitted at shipped hyperparameters (fit_gaussian_process), for provenance
            self.kernels_reused_ = sum(gp.optimizer is None for gp, _ in processes)
            self._calibrate_std(X, y, v, zs, first, groups, fitted)
        self.n_muscles_ = int(muscles.size)
        return self

    def decompose(self, X):
        """``(A, sd_A, P*, sd_P*)`` per row: slope [N/bar] and threshold [bar] with std."""
        check_is_fitted(self)
        return self._decompose(validate_data(self, X, reset=False))

    def _log_k(self, X):
        """Muscle parameters, then mean and (uncalibrated) std of ``log k_A`` and ``log k_P``."""
        return log_k(X, self.inputs, self.fixed, self.z_mean_, self.z_scale_,
                     self.slope_posterior_, self.threshold_posterior_)

    def _decompose(self, X):
        return self.predictor().decompose(X)

    def _calibrated(self, m_A, c=None, beta=None, reference=None):
        """``c (log k_A / m_ref)^beta`` (:func:`~mkm.surrogate.muscle_predictor.
        calibrated_factor`); the fitted values by default."""
        return calibrated_factor(m_A, self.std_scale_ if c is None else c,
                                 self.std_power_ if beta is None else beta,
                                 self.std_reference_ if reference is None else reference)

    _from_logk = staticmethod(from_log_k)

    #: Whether :meth:`fit` calibrates the threshold process's std on its own errors
    #: (:meth:`_fit_threshold_std`) before the force's calibration; the default kind does not.
    own_threshold_std = False

    def _force_parts(self, P, A, s_A, Pstar, s_P):
        return force_parts(P, A, s_A, Pstar, s_P, self.linearity_bar_, self.bend_bar_)

    def _calibrate_std(self, X, y, v, zs, first, groups, fitted):
        """Fit ``std_scale_`` and ``std_power_`` (:func:`coverage_fit`) to leave-one-muscle-out
        errors, from the closed-form leave-one-out posteriors (Rasmussen and Williams 2006,
        eq. 5.12) at the fitted hyperparameters; ``c = 1``, ``beta = 0`` when too few muscles
        are in both processes."""
        loo = []
        for gp, post, rows, z_process in zip((self.slope_gp_, self.threshold_gp_),
                                             (self.slope_posterior_, self.threshold_posterior_),
                                             fitted, zs, strict=True):
            # muscles it did not learn: posterior
            mean, std = predict_mean_std(gp, post, z_process)
            mean[rows], std[rows] = leave_one_out(gp, post)
            loo.append((mean, std))
        self.std_scale_, self.std_power_, self.std_reference_ = 1.0, 0.0, 1.0
        self.threshold_std_scale_, self.threshold_std_power_ = 1.0, 0.0
        self.threshold_std_reference_ = 1.0
        both = np.zeros(len(first), dtype=bool)
        both[np.intersect1d(*fitted)] = True
        if both.sum() < 5:
            return
        muscle_of_row = np.searchsorted(np.unique(groups), groups)
        rows = both[muscle_of_row]
        points = (X[rows, 0], y[rows], {k: val[muscle_of_row][rows] for k, val in v.items()},
                  *(a[muscle_of_row][rows] for a in (*loo[0], *loo[1])))
        self._fit_std(*points)
        if self.own_threshold_std:
            post, at = self.threshold_posterior_, fitted[1]
            target = post["y_std"] * np.ravel(self.threshold_gp_.y_train_) + post["y_mean"]
            self._fit_threshold_std(target, loo[1][0][at],
                                    loo[1][1][at] * self._calibrated(loo[0][0][at]))
            self._fit_std(*points)  # the force's calibration again, with the threshold's

    def _fit_threshold_std(self, target, mean, std):
        """Set ``threshold_std_scale_``, ``threshold_std_power_`` and
        ``threshold_std_reference_``: the further factor ``c_P max(1, log k_P /
        m_P,ref)^beta_P`` of the threshold process's std (:func:`threshold_factor`;
        :func:`coverage_fit` on the leave-one-muscle-out errors of
        ``log k_P``, ``target``, from their means ``mean`` and their stds ``std`` calibrated as
        the force's calibration scales both processes). ``log k_P``, the threshold's own
        end-effect correction, is largest for short, thick-walled muscles at a low braid angle,
        where its errors are largest for their std: the factor of ``log k_A`` the force's
        calibration fits for both processes, fitted mostly on pressures far above the threshold
        where the slope's error dominates, leaves those too narrow."""
        reference = float(np.median(np.maximum(mean, 1e-3))) if mean.size else 1.0
        self.threshold_std_reference_ = reference
        self.threshold_std_scale_, self.threshold_std_power_ = coverage_fit(
            target - mean, lambda c, beta: std * threshold_factor(mean, c, beta, reference))

    def _fit_std(self, P, y, v, m_A, s_A, m_P, s_P):
        """Set ``std_reference_``, ``std_scale_`` and ``std_power_`` from forces ``y`` [N] at
        pressures ``P`` [bar] of muscles ``v`` with ``log k`` means ``m`` and stds ``s``; the
        points both the FE and the model put at zero force say nothing and are left out."""
        s_P = s_P * threshold_factor(m_P, self.threshold_std_scale_, self.threshold_std_power_,
                                     self.threshold_std_reference_)
        # sd_A and sd_P* are linear in the std of log k (first order): their gains once
        A, gain_A, Pstar, gain_P = self._from_logk(v, m_A, np.ones_like(s_A), m_P,
                                                   np.ones_like(s_P))
        error = np.abs(y - A * np.maximum(P - Pstar, 0.0))
        reference = float(np.median(np.maximum(m_A, 1e-3))) if y.size else 1.0

        def std_of(c, beta, rows=slice(None)):
            factor = self._calibrated(m_A[rows], c, beta, reference)
            _, var, floor = self._force_parts(P[rows], A[rows], gain_A[rows] * factor * s_A[rows],
                                              Pstar[rows], gain_P[rows] * factor * s_P[rows])
            return np.sqrt(var + floor**2)

        informative = np.flatnonzero((error > 0) | (std_of(1.0, 0.0) > 0))
        self.std_reference_ = reference
        self.std_scale_, self.std_power_ = (
            coverage_fit(error[informative], lambda c, beta: std_of(c, beta, informative))
            if informative.size else (1.0, 0.0))
        self.std_calibration_points_ = int(informative.size)

    def calibrate_std(self, X, y):
        """Set ``std_scale_`` and ``std_power_`` (and ``std_reference_``) from FE sweeps
        ``(X, y)`` of muscles the fit did not see (random muscles of the box): the
        ``(c, beta)`` whose 1 and 2 std bands hold closest to 68 and 95 % of their points
        (:func:`coverage_fit`). Returns ``self``."""
        check_is_fitted(self)
        X = validate_data(self, X, reset=False)
        self._fit_std(X[:, 0], np.asarray(y, dtype=float), *self._log_k(X))
        return self

    def rescale_std(self, X, y):
        """Set ``std_rescale_``, ``std_rescale_power_`` and ``std_rescale_angle_power_``, the
        factor ``k (k_A eps / 0.1)^power (theta0 / 30 deg)^angle_power`` of the whole predictive
        std, from FE sweeps ``(X, y)`` of muscles neither the fit nor :meth:`calibrate_std` saw
        (the held-out set): the one whose 1, 2 and 3 std bands hold closest to 68.27, 95.45 and
        99.73 % of their points, over all of them and in each third by braid angle
        (:func:`~mkm.surrogate.coverage.rescale_fit`). The power of the slope's effective
        shortening ``k_A eps``: with the std calibrated on ``log k_A`` alone, the errors of the
        largest eps fell outside 1 std more often than those of the smallest. The power of the
        braid angle: over the practical range the held-out errors at the lowest angles were the
        largest for their std and those at the highest the smallest (the braid's slope falls
        fastest near its lock at low angles), so the pooled errors had heavy tails made of the
        low angles. Returns ``self``."""
        check_is_fitted(self)
        X = validate_data(self, X, reset=False)
        force, std, shortening, theta0 = self.predictor().std_parts(X)
        self.std_rescale_, self.std_rescale_power_, self.std_rescale_angle_power_ = rescale_fit(
            np.asarray(y, dtype=float) - force, std, shortening, theta0)
        return self

    def predict(self, X, return_std: bool = False):
        check_is_fitted(self)
        return self.predict_validated(validate_data(self, X, reset=False), return_std)

    def predict_validated(self, X, return_std: bool = False):
        """:meth:`predict` on a float array the caller has validated (no per-call checks)."""
        return self.predictor().predict(X, return_std)

    def predictor(self) -> MusclePredictor:
        """The fitted arrays that predict, without scikit-learn (:mod:`mkm.surrogate.
        muscle_predictor`)."""
        check_is_fitted(self)
        return MusclePredictor(tuple(self.inputs), dict(self.fixed or {}), self.z_mean_,
                               self.z_scale_, self.slope_posterior_, self.threshold_posterior_,
                               float(self.std_scale_), float(self.std_power_),
                               float(self.std_reference_), float(self.bend_bar_),
                               float(self.std_rescale_), float(self.std_rescale_power_),
                               float(self.std_rescale_angle_power_),
                               self.linearity_bar_, float(self.threshold_std_scale_),
                               float(self.threshold_std_power_),
                               float(self.threshold_std_reference_))
