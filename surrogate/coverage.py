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


def coverage(error, std, k: float) -> float:
    """Fraction of points with ``|error| <= k std`` among those where the model or the FE has
    a force (points both say are exactly zero, below the threshold, say nothing of the std)."""
    error, std = np.abs(np.asarray(error)), np.asarray(std)
    informative = (error > 0) | (std > 0)
    if not informative.any():
        return float("nan")
    return float(np.mean(error[informative] <= k * std[informative]))


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
