"""Coverage of a predictive standard deviation: the fraction of errors within ``k`` std, and the
calibration of a std model to the 68 / 95 % a normal error would give."""

from __future__ import annotations

import numpy as np

#: Issue 13's coverage targets: ``(k, fraction within k std, tolerance)``, 68 +- 7 % within 1
#: std and 95 +- 4 % within 2.
COVERAGE_TARGETS = ((1.0, 0.6827, 0.07), (2.0, 0.9545, 0.04))
#: Grid of :func:`coverage_fit`: the scale ``c`` (log-spaced) and the power ``beta``.
STD_SCALES = np.geomspace(0.1, 10.0, 161)
STD_POWERS = np.linspace(-0.5, 2.5, 31)
#: What a normal error gives within 1, 2 and 3 std: :func:`rescale_fit`'s targets.
NORMAL_COVERAGE = ((1.0, 0.6827), (2.0, 0.9545), (3.0, 0.9973))
#: Grid of :func:`rescale_fit`: factors 0.25-4, 0.5 % apart, powers of eps and of the braid angle.
STD_RESCALES = np.geomspace(0.25, 4.0, 557)
RESCALE_POWERS = np.round(np.linspace(-0.5, 1.5, 41), 3)
RESCALE_ANGLE_POWERS = np.round(np.linspace(-2.0, 1.0, 16), 3)
#: The rescale's shortening is relative to this one [fraction] (mid-box), and never taken
#: below the smallest (at eps = 0 the force has no end-effect error: the std is the floor's).
RESCALE_EPS_REF = 0.1
RESCALE_EPS_MIN = 1e-3
#: The rescale's braid angle is relative to this one [deg].
RESCALE_THETA_REF_DEG = 30.0
#: :func:`rescale_fit` asks the bands to hold in each of this many equal shares of the points
#: sorted by braid angle, as well as in all of them.
RESCALE_ANGLE_GROUPS = 3


def informative(error, std) -> np.ndarray:
    """The points :func:`coverage` counts: those where the model or the FE has a force (points
    both say are exactly zero, below the threshold, say nothing of the std)."""
    return (np.abs(np.asarray(error)) > 0) | (np.asarray(std) > 0)


def coverage(error, std, k: float) -> float:
    """Fraction of points with ``|error| <= k std`` among the :func:`informative` ones."""
    error, std = np.abs(np.asarray(error)), np.asarray(std)
    counted = informative(error, std)
    if not counted.any():
        return float("nan")
    return float(np.mean(error[counted] <= k * std[counted]))


def coverage_fit(error, std_of) -> tuple[float, float]:
    """The ``(c, beta)`` whose bands ``std_of(c, beta)`` hold closest to 68.27 and 95.45 % of
    ``|error|`` within 1 and 2 std: least squares on the two fractions, each miss in units of
    its tolerance (:data:`COVERAGE_TARGETS`: a 7-point miss of the 1-std fraction costs as much
    as a 4-point miss of the 2-std one), on the grid :data:`STD_SCALES` x :data:`STD_POWERS`
    (the fractions are step functions of the parameters: no gradient); of equal misfits, the
    smallest scale of the power closest to 0. ``std_of`` is called with ``c`` a column of every
    scale of the grid and returns one row of stds per scale.

    Errors heavier-tailed than normal cannot meet both fractions: weighting the misses by the
    tolerances keeps the 2-std fraction, the one the issue allows least room, nearer its target.
    """
    error = np.abs(np.asarray(error, dtype=float))
    best, best_misfit = (1.0, 0.0), np.inf
    for beta in sorted(STD_POWERS, key=abs):
        std = std_of(STD_SCALES[:, None], beta)
        misfit = sum(((np.mean(error <= k * std, axis=1) - target) / tolerance) ** 2
                     for k, target, tolerance in COVERAGE_TARGETS)
        i = int(np.argmin(misfit))
        if misfit[i] < best_misfit:
            best, best_misfit = (float(STD_SCALES[i]), float(beta)), misfit[i]
    return best


def rescale_factor(shortening, theta0_deg, k: float, power: float, angle_power: float = 0.0):
    """``k (shortening / RESCALE_EPS_REF)^power (theta0 / RESCALE_THETA_REF_DEG)^angle_power``:
    the factor of the whole std at an (effective) shortening [fraction] and braid angle [deg]."""
    return (k * (np.maximum(shortening, RESCALE_EPS_MIN) / RESCALE_EPS_REF) ** power
            * (np.asarray(theta0_deg, dtype=float) / RESCALE_THETA_REF_DEG) ** angle_power)


def _band_miss(ratio) -> np.ndarray:
    """For each factor of :data:`STD_RESCALES`, the largest miss of the 1, 2 and 3 std
    fractions (:data:`NORMAL_COVERAGE`) of the sorted ``|error| / std`` ratios ``ratio``."""
    # |error| <= n k std  <=>  |error| / std <= n k: the sorted ratios count them
    return np.max([np.abs(np.searchsorted(ratio, n * STD_RESCALES, side="right") / ratio.size
                          - target) for n, target in NORMAL_COVERAGE], axis=0)


def rescale_fit(error, std, shortening, theta0_deg) -> tuple[float, float, float]:
    """The ``(k, power, angle_power)`` whose bands ``rescale_factor(shortening, theta0_deg, k,
    power, angle_power) std`` hold closest to the normal fractions within 1, 2 and 3 std
    (:data:`NORMAL_COVERAGE`) over all the points and in each of :data:`RESCALE_ANGLE_GROUPS`
    equal shares of them sorted by braid angle: the smallest largest miss on the grid
    :data:`STD_RESCALES` x :data:`RESCALE_POWERS` x :data:`RESCALE_ANGLE_POWERS` (of equal
    misses, the powers closest to 0, then the smallest factor); ``(1, 0, 0)`` when no point is
    informative (:func:`coverage`).

    Pooled alone, a std too wide at high braid angles and too narrow at low ones can hold the
    right fractions on average while the low angles' errors make the tails: the shares keep
    the bands right where the errors are (the braid's slope near its lock, steepest at low
    angles)."""
    error, std = np.abs(np.asarray(error, dtype=float)), np.asarray(std, dtype=float)
    eps = np.broadcast_to(np.asarray(shortening, dtype=float), error.shape)
    theta = np.broadcast_to(np.asarray(theta0_deg, dtype=float), error.shape)
    informative = (error > 0) | (std > 0)
    if not informative.any():
        return 1.0, 0.0, 0.0
    error, std, eps, theta = (a[informative] for a in (error, std, eps, theta))
    order = np.argsort(theta, kind="stable")
    shares = [order] + ([] if theta.size < 3 * RESCALE_ANGLE_GROUPS else
                        np.array_split(order, RESCALE_ANGLE_GROUPS))
    best, best_miss = (1.0, 0.0, 0.0), np.inf
    for angle_power in sorted(RESCALE_ANGLE_POWERS, key=abs):
        for power in sorted(RESCALE_POWERS, key=abs):
            with np.errstate(divide="ignore"):
                ratio = error / (rescale_factor(eps, theta, 1.0, power, angle_power) * std)
            miss = np.max([_band_miss(np.sort(ratio[rows])) for rows in shares], axis=0)
            i = int(np.argmin(miss))
            if miss[i] < best_miss - 1e-12:
                best, best_miss = ((float(STD_RESCALES[i]), float(power), float(angle_power)),
                                   miss[i])
    return best
