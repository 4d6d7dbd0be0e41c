"""Predictions of the ``muscle-gp`` kind from its fitted arrays alone.

numpy only: a saved default surrogate predicts without loading scikit-learn or skops
(the estimator file holds the whole fitted estimator, for refits and calibration; the predictor
file, ``predictor.npz``, holds these arrays and is read with ``allow_pickle=False``, so it cannot
run code either). :class:`~mkm.surrogate.muscle_gp.MuscleThresholdGP` predicts through the same
functions, so both give the same numbers to the bit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mkm.fem.eq2 import chou_hannaford_eps_max
from mkm.surrogate.coverage import rescale_factor
from mkm.surrogate.features import braid_slope_N_per_bar, columns_of, thickwall_threshold_bar
from mkm.surrogate.gp import posterior_mean_std

LINEARITY_BINS_BAR = (0.0, 0.1, 0.25, 0.5, 1.0, 2.0, np.inf)  # of P - P*
#: The arrays of a Gaussian process's posterior (:func:`mkm.surrogate.gp.posterior`): name, ndim.
POSTERIOR_ARRAYS = {"X_scaled": 2, "length_scale": 1, "alpha": 1, "L_inv": 2, "amplitude": 0,
                    "noise": 0, "y_mean": 0, "y_std": 0}
SCALARS = ("std_scale", "std_power", "std_reference", "bend_bar", "std_rescale",
           "std_rescale_power", "std_rescale_angle_power")
#: The threshold process's own calibration (:class:`~mkm.surrogate.range_gp.RangeThresholdGP`):
#: neutral (1, 0, 1) where a model has none, as a predictor file without them is read.
THRESHOLD_SCALARS = {"threshold_std_scale": 1.0, "threshold_std_power": 0.0,
                     "threshold_std_reference": 1.0}


def muscle_values(X, inputs, fixed):
    """The muscle's values by name and ``z``: the muscle parameters of ``X``, the braid
    diameter over the length and ``sqrt(eps)`` (:func:`process_inputs` picks each process's)."""
    v = columns_of(X, tuple(inputs), fixed)
    z = np.column_stack([X[:, 1:], (v["D0_mm"] + 2.0 * v["t0_mm"]) / v["L0_mm"],
                         np.sqrt(np.maximum(v["eps"], 0.0))])
    return v, z


def process_inputs(zs, inputs):
    """The columns of ``zs`` (standardised :func:`muscle_values`) that the slope and the
    threshold process take: ``sqrt(eps)`` for the slope, ``eps`` for the threshold."""
    # log k_A falls steeply as eps leaves 0 and then flattens, most for short wide muscles
    # (the end zones' share of the shortening shrinks): close to linear in sqrt(eps), which a
    # stationary process with one length scale follows; log k_P varies slowly with eps, and
    # sqrt(eps) would crowd its large-eps end, where the threshold is steepest near the lock
    slope = np.delete(zs, tuple(inputs).index("eps") - 1, axis=1)
    return slope, zs[:, :-1]


def log_k(X, inputs, fixed, z_mean, z_scale, slope, threshold):
    """Muscle values, then mean and (uncalibrated) std of ``log k_A`` and ``log k_P`` from the
    posteriors ``slope`` and ``threshold`` over ``z`` standardised with ``z_mean, z_scale``."""
    v, z = muscle_values(X, inputs, fixed)
    z_slope, z_threshold = process_inputs((z - z_mean) / z_scale, inputs)
    return (v, *posterior_mean_std(slope, z_slope), *posterior_mean_std(threshold, z_threshold))


def calibrated_factor(m_A, c, beta, reference):
    """``c (log k_A / m_ref)^beta``: the factor of both processes' std of ``log k`` at the
    slope process's mean ``m_A``."""
    # k_A > 1 (the caps stretch the shortening); the clip keeps the power finite if not
    return c * (np.maximum(m_A, 1e-3) / reference) ** beta


def threshold_factor(m_P, c, beta, reference):
    """``c max(1, log k_P / m_ref)^beta``: the further factor of the threshold process's std of
    ``log k_P`` at its mean ``m_P``, widening it where the threshold's own end-effect correction
    exceeds ``m_ref`` (neutral at ``c = 1, beta = 0``)."""
    return c * np.maximum(m_P / reference, 1.0) ** beta


def effective_shortening(v, m):
    """``k eps`` [fraction] at ``log k`` = ``m`` of the muscles ``v``, kept short of the braid
    lock."""
    return np.minimum(v["eps"] * np.exp(m), 0.999 * chou_hannaford_eps_max(v["theta0_deg"]))


def from_log_k(v, m_A, s_A, m_P, s_P):
    """Slope [N/bar] and threshold [bar], with first-order std, from ``log k`` of each (mean
    and std) of the muscles ``v``."""
    theta0 = v["theta0_deg"]
    e_A, e_P = effective_shortening(v, m_A), effective_shortening(v, m_P)
    A0 = braid_slope_N_per_bar(v["D0_mm"], v["t0_mm"], 0.0, theta0)
    c2 = np.cos(np.deg2rad(theta0)) ** 2
    A = np.maximum(A0 * (3.0 * (1.0 - e_A) ** 2 * c2 - 1.0) / (3.0 * c2 - 1.0), 0.0)
    sd_A = A0 * 6.0 * (1.0 - e_A) * c2 / (3.0 * c2 - 1.0) * e_A * s_A  # |dA/dlog k| s
    args, rubber = (v["D0_mm"], v["t0_mm"]), (v["C10_MPa"], v["C01_MPa"])
    Pstar = np.maximum(thickwall_threshold_bar(*args, e_P, theta0, *rubber), 0.0)
    step = 1e-6
    dP_dlogk = (thickwall_threshold_bar(*args, e_P * (1 + step), theta0, *rubber)
                - Pstar) / step
    return A, sd_A, Pstar, np.abs(dP_dlogk) * s_P


def _normal_cdf(t):
    """The standard normal CDF per element: ``math.erfc(-t / sqrt 2) / 2`` for a few sweeps (a
    command that predicts one needs no scipy, whose import costs more than the sweep), scipy's
    ``ndtr`` for the large arrays of training (element by element in Python would dominate it).
    Both are accurate to a few ulp; the choice depends on the size alone, so the same arrays give
    the same bits."""
    t = np.asarray(t, dtype=float)
    if t.size > PYTHON_CDF_MAX:
        from scipy.special import ndtr

        return ndtr(t)
    return 0.5 * _ERFC(-t / math.sqrt(2.0)).astype(float)


PYTHON_CDF_MAX = 10_000  # elements: up to this many, element by element is cheaper than the import
_ERFC = np.frompyfunc(math.erfc, 1, 1)


def linearity_floor_bar(x_bar, linearity_bar, bend_bar):
    """The threshold-linear form's own error [bar] at ``x_bar = P - P*``: the training sweeps'
    RMS residual per bin of :data:`LINEARITY_BINS_BAR` (``linearity_bar``), made non-increasing
    in ``x`` (the bin where the line crosses the FE curve has a small RMS, not small errors),
    and applied from ``bend_bar`` below the line's threshold, where the FE force already starts
    (the FE curve bends in above its own threshold, which lies up to ``bend_bar`` below the
    line's); 0 further below."""
    envelope = np.maximum.accumulate(np.asarray(linearity_bar)[::-1])[::-1]
    floor = envelope[np.digitize(np.maximum(x_bar, 0.0), LINEARITY_BINS_BAR[1:-1])]
    return np.where(x_bar > -bend_bar, floor, 0.0)


def force_parts(P, A, s_A, Pstar, s_P, linearity_bar, bend_bar=0.0):
    """Force [N], its variance [N^2] from the std of ``A`` and ``P*``, and the linearity floor
    [N] (:func:`linearity_floor_bar` times the slope)."""
    force = A * np.maximum(P - Pstar, 0.0)
    # E[max(0, x)] and E[max(0, x)^2] for x = P - P* ~ N(mu, s^2); A log-normal with
    # relative std s_A / A
    mu, s = P - Pstar, np.maximum(s_P, 1e-12)
    t = mu / s
    cdf, pdf = _normal_cdf(t), np.exp(-0.5 * t**2) / np.sqrt(2.0 * np.pi)
    e1 = mu * cdf + s * pdf
    e2 = (mu**2 + s**2) * cdf + mu * s * pdf
    rel = np.divide(s_A, A, out=np.zeros(np.broadcast_shapes(np.shape(s_A), np.shape(A))),
                    where=A > 0)
    # a slope whose std dwarfs it (far outside the training data) overflows: its variance is
    # unbounded, said as inf rather than a NaN
    with np.errstate(over="ignore", invalid="ignore"):
        var = A**2 * (np.exp(2 * rel**2) * e2 - np.exp(rel**2) * e1**2)
    var = np.where(np.isfinite(var), np.maximum(var, 0.0), np.inf)
    floor = A * linearity_floor_bar(P - Pstar, linearity_bar, bend_bar)
    # no pressure, no pull: at 0 bar every muscle's force is 0 N exactly, whatever its threshold
    pressurised = np.asarray(P) > 0
    return force, np.where(pressurised, var, 0.0), np.where(pressurised, floor, 0.0)


@dataclass(frozen=True)
class MusclePredictor:
    """A fitted muscle GP's predictions (:class:`~mkm.surrogate.muscle_gp.MuscleThresholdGP`
    documents the model): its inputs, recorded parameters and fitted arrays."""

    inputs: tuple[str, ...]
    fixed: dict
    z_mean: np.ndarray
    z_scale: np.ndarray
    slope: dict
    threshold: dict
    std_scale: float
    std_power: float
    std_reference: float
    bend_bar: float
    std_rescale: float
    std_rescale_power: float
    std_rescale_angle_power: float
    linearity_bar: np.ndarray
    threshold_std_scale: float = THRESHOLD_SCALARS["threshold_std_scale"]
    threshold_std_power: float = THRESHOLD_SCALARS["threshold_std_power"]
    threshold_std_reference: float = THRESHOLD_SCALARS["threshold_std_reference"]

    has_std = True

    def calibrated(self, m_A, s_A, m_P, s_P):
        """The std of ``log k_A`` and ``log k_P`` calibrated: both times ``c (log k_A /
        m_ref)^beta``, the threshold's also times its own :func:`threshold_factor`."""
        factor = calibrated_factor(m_A, self.std_scale, self.std_power, self.std_reference)
        return factor * s_A, factor * s_P * threshold_factor(
            m_P, self.threshold_std_scale, self.threshold_std_power,
            self.threshold_std_reference)

    def decompose(self, X):
        """``(A, sd_A, P*, sd_P*)`` per row of a validated ``X``."""
        return self._parts(X)[:4]

    def _parts(self, X):
        """:meth:`decompose`, then the effective shortening of the slope ``k_A eps``."""
        v, m_A, s_A, m_P, s_P = log_k(X, self.inputs, self.fixed, self.z_mean, self.z_scale,
                                      self.slope, self.threshold)
        sd_A, sd_P = self.calibrated(m_A, s_A, m_P, s_P)
        return *from_log_k(v, m_A, sd_A, m_P, sd_P), effective_shortening(v, m_A)

    def std_parts(self, X):
        """Per row of a validated ``X``: force [N], its std before the rescale [N], and the
        effective shortening ``k_A eps`` [fraction] and braid angle [deg] the rescale takes."""
        A, s_A, Pstar, s_P, shortening = self._per_muscle(X)
        force, var, floor = force_parts(X[:, 0], A, s_A, Pstar, s_P, self.linearity_bar,
                                        self.bend_bar)
        theta0 = columns_of(X, self.inputs, self.fixed)["theta0_deg"]
        return force, np.sqrt(var + floor**2), shortening, theta0

    def _per_muscle(self, X):
        """:meth:`_parts` once per muscle of ``X``, per row."""
        # a sweep is many pressures of a few muscles
        Z = np.ascontiguousarray(X[:, 1:])
        keys = Z.view(np.dtype((np.void, Z.dtype.itemsize * Z.shape[1]))).ravel()
        _, first, which = np.unique(keys, return_index=True, return_inverse=True)
        return tuple(part[which] for part in self._parts(X[first]))

    def predict(self, X, return_std: bool = False):
        """Force [N] (and std [N]) at the rows of a validated float ``X``."""
        if not return_std:
            A, _, Pstar, _, _ = self._per_muscle(X)
            return A * np.maximum(X[:, 0] - Pstar, 0.0)
        force, std, shortening, theta0 = self.std_parts(X)
        return force, std * rescale_factor(shortening, theta0, self.std_rescale,
                                           self.std_rescale_power, self.std_rescale_angle_power)

    def arrays(self) -> dict[str, np.ndarray]:
        """The fitted numbers as flat named arrays (``numpy.savez``)."""
        out = {"z_mean": self.z_mean, "z_scale": self.z_scale,
               "linearity_bar": self.linearity_bar}
        out.update({f"{process}.{name}": np.asarray(getattr(self, process)[name])
                    for process in ("slope", "threshold") for name in POSTERIOR_ARRAYS})
        out.update({name: np.array(getattr(self, name)) for name in (*SCALARS,
                                                                      *THRESHOLD_SCALARS)})
        return out

    @classmethod
    def from_arrays(cls, arrays, inputs, fixed) -> MusclePredictor:
        """The predictor of :meth:`arrays` for ``inputs`` and ``fixed``; a one-line
        ``ValueError`` naming the first array missing or of the wrong type or shape."""
        # each process: the muscle parameters of X and the braid diameter over the length; z
        # also sqrt(eps) (process_inputs)
        d = len(inputs)
        expected = {"z_mean": (d + 1,), "z_scale": (d + 1,),
                    "linearity_bar": (len(LINEARITY_BINS_BAR)
                                                                       - 1,),
                    **{name: () for name in SCALARS}}
        for process in ("slope", "threshold"):
            n = np.shape(arrays.get(f"{process}.alpha", ()))[:1] or (0,)
            expected.update({f"{process}.{name}": {2: (*n, d), 1: n, 0: ()}[ndim]
                             for name, ndim in POSTERIOR_ARRAYS.items()})
            expected[f"{process}.length_scale"] = (d,)
            expected[f"{process}.L_inv"] = (*n, *n)
        for name, shape in expected.items():
            value = arrays.get(name)
            if (value is None or value.dtype != np.float64 or value.shape != shape
                    or not np.all(np.isfinite(value))):
                got = "missing" if value is None else f"{value.dtype} {value.shape}"
                raise ValueError(f"predictor array {name} is {got}: expected finite float64 "
                                 f"of shape {shape}")
        for name in THRESHOLD_SCALARS:
            value = arrays.get(name)
            if value is not None and (value.dtype != np.float64 or value.shape != ()
                                      or not np.isfinite(value)):
                raise ValueError(f"predictor array {name} is {value.dtype} {value.shape}: "
                                 "expected a finite float64 of shape ()")
        return cls(tuple(inputs), dict(fixed), arrays["z_mean"], arrays["z_scale"],
                   *({name: arrays[f"{process}.{name}"] for name in POSTERIOR_ARRAYS}
                     for process in ("slope", "threshold")),
                   *(float(arrays[name]) for name in SCALARS), arrays["linearity_bar"],
                   *(float(arrays.get(name, default))
                     for name, default in THRESHOLD_SCALARS.items()))
