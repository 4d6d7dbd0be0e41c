"""Equation 2 of the reference work: the Chou-Hannaford force, and the braid's locking angle.

Naming follows the published model; inputs carry their unit in the name.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mkm.fem.calibration import CalibratedTheta0, Calibration, calibrated
from mkm.fem.interface import Domain, ForceModel
from mkm.fem.limits import LOCKING_ANGLE_DEG, check_theta0, lock_eps

BAR_TO_MPA = 0.1  # 1 bar = 0.1 MPa = 0.1 N/mm^2, so N/mm^2 * mm^2 = N


def chou_hannaford(pressure_bar, D_mm, eps, theta0_deg):
    r"""Chou-Hannaford static force of a McKibben muscle (the paper's Equation 2).

    .. math::
        F = \frac{\pi D^2 P}{4 \sin^2\theta_0}\left(3(1-\varepsilon)^2\cos^2\theta_0 - 1\right)

    Parameters
    ----------
    pressure_bar : array_like
        Gauge pressure [bar].
    D_mm : array_like
        Diameter the formula is written with [mm]: the inner tube diameter D0 in the paper
        (Antonelli et al. 2025), the braid diameter D0 + 2 t0 in the thin-wall derivation.
    eps : array_like
        Shortening ratio dL/L0 [fraction].
    theta0_deg : float
        Braid angle at rest, from the muscle axis [deg].

    Returns
    -------
    numpy.ndarray
        Force [N]. Negative where ``eps > eps_max``: the formula leaves its range there (see
        :func:`chou_hannaford_eps_max`); callers decide what to do with it.

    References
    ----------
    .. [1] C.-P. Chou, B. Hannaford, "Measurement and modeling of McKibben pneumatic artificial
       muscles", IEEE Trans. Robot. Autom. 12(1), 90-102, 1996, doi:10.1109/70.481753.
    .. [2] M. G. Antonelli, P. Beomonte Zobel, M. A. Sarwar, N. Stampone, "Mechanical Design of
       McKibben Muscles Predicting Developed Force by Artificial Neural Networks", Actuators
       14(3), 153, 2025, doi:10.3390/act14030153, Equation 2.
    """
    theta = np.deg2rad(theta0_deg)
    P_MPa = np.asarray(pressure_bar, dtype=float) * BAR_TO_MPA
    D = np.asarray(D_mm, dtype=float)
    e = np.asarray(eps, dtype=float)
    return (np.pi * D**2 * P_MPa / 4.0 / np.sin(theta) ** 2
            * (3.0 * (1.0 - e) ** 2 * np.cos(theta) ** 2 - 1.0))


def chou_hannaford_eps_max(theta0_deg):
    """Largest shortening ratio at which Equation 2 is non-negative [fraction].

    ``eps_max = 1 - 1 / (sqrt(3) cos theta0)``: the braid reaches its locking angle (54.7 deg)
    there, and beyond it the formula turns negative (:func:`mkm.fem.limits.lock_eps`).
    """
    return lock_eps(theta0_deg)


@dataclass(frozen=True)
class BraidLock:
    """Where a muscle's braid locks: the shortening ``eps_max`` (a fraction) reached from the
    braid angle at rest ``theta0_deg`` [deg], and where that angle comes from."""

    eps_max: float
    theta0_deg: float
    source: str

    def __str__(self) -> str:
        return (f"eps_max {self.eps_max:.3f} (the braid reaches its locking angle "
                f"{LOCKING_ANGLE_DEG:.1f} deg from theta0 {self.theta0_deg:.2f} deg, "
                f"{self.source})")


def braid_lock(theta0_deg: float | None = None,
               calibration: Calibration | None = None) -> BraidLock:
    """The one braid-lock limit of a muscle, for every command (check, acquire, report, design).

    The lock is the braid's geometry (:func:`chou_hannaford_eps_max`), the same whatever the
    force model; only the angle at rest differs: the muscle's own ``theta0_deg`` when known,
    else the calibrated angle of the FE model, the toolkit's reference (``axisym`` in
    ``calibration``, default the shipped ``fem/calibration.json``).
    """
    if theta0_deg is not None:
        theta0, source = check_theta0(theta0_deg), "the muscle's theta0"
    else:
        theta0 = float(calibrated("axisym", calibration)["theta0_deg"])
        source = "the FE model's calibrated theta0 (axisym)"
    return BraidLock(float(chou_hannaford_eps_max(theta0)), theta0, source)


class Eq2(CalibratedTheta0, ForceModel):
    """Equation 2 as a force model (``--model eq2``).

    Parameters
    ----------
    theta0_deg : float, optional
        Braid angle at rest [deg]. Default: the calibrated value in ``fem/calibration.json``.
    diameter : {"inner", "braid"}
        ``inner`` uses D0 as the paper does; ``braid`` uses D0 + 2 t0.
    L0_mm : float
        Length at rest [mm]. Recorded only: Equation 2 does not depend on the length.
    calibration : Calibration, optional
        Where the default angle (and an identified rubber) comes from; default the shipped
        ``fem/calibration.json`` (:class:`mkm.fem.calibration.Calibration`).
    """

    name = "eq2"
    domain = Domain()

    def __init__(self, theta0_deg: float | None = None, diameter: str = "inner",
                 L0_mm: float = 282.0, calibration: Calibration | None = None):
        self.theta0_deg = theta0_deg
        self.calibration = calibration
        self.diameter = diameter
        self.L0_mm = L0_mm

    @property
    def calibration_key(self) -> str:
        return f"eq2-{self.diameter}"

    def params(self):
        return {"theta0_deg": self._theta0(), "diameter": self.diameter, "L0_mm": self.L0_mm}

    def _forces(self, P, D0, t0, eps):
        if self.diameter not in ("inner", "braid"):
            raise ValueError(f"diameter={self.diameter!r} is invalid: expected 'inner' or 'braid'")
        theta0 = check_theta0(self._theta0())
        D = D0 if self.diameter == "inner" else D0 + 2.0 * t0
        force = chou_hannaford(P, D, eps, theta0)
        return {"force_N": force, "valid": eps < chou_hannaford_eps_max(theta0)}
