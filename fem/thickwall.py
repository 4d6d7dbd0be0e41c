"""Thick-wall closed form of the McKibben muscle: the Klute-Hannaford virtual-work model.

The second rung of the physics ladder. An incompressible two-parameter Mooney-Rivlin tube bonded
to an inextensible braid; in the cylindrical mid-section the whole deformation follows from the
axial stretch ``lz = 1 - eps``, so the stored energy per unit rest length has a closed form and
so has its derivative: no quadrature, no iteration, exact to round-off.

Derivation (the wall as annulus ``Ri <= R <= Ro`` at rest, ``x = R^2``):

- braid of constant thread length: ``cos theta = lz cos theta0``, so the outer radius is
  ``r_o^2 = Ro^2 (1 - lz^2 cos^2 theta0) / sin^2 theta0``;
- incompressible wall: ``r^2 = r_o^2 - (Ro^2 - R^2) / lz = k + x / lz`` with
  ``k = r_o^2 - Ro^2 / lz``; stretches ``lz`` (axial), ``a = r^2 / R^2`` (hoop squared) and
  ``1 / (a lz^2)`` (radial squared);
- ``W = C10 (I1 - 3) + C01 (I2 - 3)`` with ``I1 = lz^2 + a + 1/(a lz^2)``,
  ``I2 = a lz^2 + 1/lz^2 + 1/a``; integrating ``2 pi R dR = pi dx`` gives the energy per unit rest
  length

  ``E = pi [C10 ((lz^2 + 2/lz - 3) D + k M) + C01 ((2 lz + 1/lz^2 - 3) D + k lz^2 M)]``

  with ``D = Ro^2 - Ri^2`` and ``M = ln(a_i / a_o)`` (hoop stretches squared at the inner and
  outer surfaces);
- virtual work of pressure, wall and load: ``F = -P dV/dL + dE/dlz``. The wall volume is
  constant, so ``dV/dL`` of the cavity equals that of the braid cylinder and the pressure term is
  Equation 2 written with the braid diameter ``D0 + 2 t0``.

A radial gap ``g`` between the tube and the sleeve at rest (``gap_mm``, default 0) changes only
the braid's rest radius, ``Rb = Ro + g``: the tube first inflates freely
(:func:`mooney_rivlin_tube_inflation_pressure`) until its outer surface reaches the sleeve at
:func:`gap_closing_pressure`, then follows the braid, ``r_o^2 = Rb^2 (1 - lz^2 cos^2 theta0) /
sin^2 theta0``, with ``k = r_o^2 - Ro^2 / lz``. The energy and force formulas above hold for any
``k`` (they integrate ``W`` over the material radii), the pressure term uses the braid diameter
``D0 + 2 t0 + 2 g``, and the force is affine in ``P`` again once in contact: a threshold even at
``eps = 0``. With ``g = 0`` every expression is the gap-free one, term for term.
"""

from __future__ import annotations

import numpy as np

from mkm.fem.calibration import CalibratedTheta0, Calibration
from mkm.fem.eq2 import check_theta0, chou_hannaford, chou_hannaford_eps_max
from mkm.fem.interface import Domain, ForceModel
from mkm.fem.limits import check_value
from mkm.fem.materials import SILASTIC_S, MooneyRivlin


def _rest_radii(D0_mm, t0_mm, gap_mm):
    """``Ri^2`` [mm^2], ``Ro`` [mm] and ``Rb^2 - Ro^2 = g (2 Ro + g)`` [mm^2] (0 without a gap)."""
    Ro = np.asarray(D0_mm, dtype=float) / 2.0 + np.asarray(t0_mm, dtype=float)
    gap = np.asarray(gap_mm, dtype=float)
    return (np.asarray(D0_mm, dtype=float) / 2.0) ** 2, Ro, gap * (2.0 * Ro + gap)


def mid_section_kinematics(D0_mm, t0_mm, eps, theta0_deg, gap_mm=0.0):
    """Squared radii [mm^2], ``lz``, ``k`` and the log hoop-stretch ratio ``M`` of the wall.

    Returns ``Ri^2, Ro^2, lz, k, r_i^2, r_o^2, M, cot^2 theta0`` of the tube in contact with the
    braid (``r_o`` the braid's radius; ``gap_mm`` [mm] the radial gap between tube and braid at
    rest). Written in ``eps`` rather than ``1 - lz`` so that nothing cancels at small shortening
    and the rest state (``eps = 0``, no gap) is exactly stress free.
    """
    Ri2, Ro, opening = _rest_radii(D0_mm, t0_mm, gap_mm)
    Ro2 = Ro**2
    Rb2 = Ro2 + opening
    eps = np.asarray(eps, dtype=float)
    lz = 1.0 - eps
    cot2 = 1.0 / np.tan(np.deg2rad(theta0_deg)) ** 2
    hoop_o = eps * (2.0 - eps) * cot2  # r_o^2 / Rb^2 - 1
    k = Ro2 * (hoop_o - eps / lz) + opening * (1.0 + hoop_o)  # r^2 = k + R^2 / lz
    ri2 = k + Ri2 / lz
    with np.errstate(invalid="ignore", divide="ignore"):
        # ln(a_i / a_o), a_o = (Rb^2 / Ro^2) (1 + hoop_o); NaN if r_i^2 < 0
        M = (np.log1p(k / Ri2 + eps / lz) - np.log1p(hoop_o)
             - 2.0 * np.log1p(np.asarray(gap_mm, dtype=float) / Ro))
    return Ri2, Ro2, lz, k, ri2, Rb2 * (1.0 + hoop_o), M, cot2


def braided_tube_energy(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa, gap_mm=0.0):
    """Mooney-Rivlin energy of the braided tube's mid-section per unit rest length [N = mJ/mm].

    Closed-form integral over the wall of ``W = C10 (I1 - 3) + C01 (I2 - 3)`` for the
    deformation the braid imposes at shortening ``eps`` (see the module docstring), the tube in
    contact with the braid (``gap_mm`` [mm] the radial gap at rest). NaN where the inner radius
    has collapsed (``r_i^2 <= 0``): no such deformation exists.
    """
    Ri2, Ro2, lz, k, ri2, _, M, _ = mid_section_kinematics(D0_mm, t0_mm, eps, theta0_deg, gap_mm)
    D = Ro2 - Ri2
    e2 = (1.0 - lz) ** 2
    # lz^2 + 2/lz - 3 = eps^2 (3 - eps) / lz and 2 lz + 1/lz^2 - 3 = eps^2 (1 + 2 lz) / lz^2
    energy = np.pi * (C10_MPa * (e2 * (2.0 + lz) / lz * D + k * M)
                      + C01_MPa * (e2 * (1.0 + 2.0 * lz) / lz**2 * D + k * lz**2 * M))
    return np.where(ri2 > 0, energy, np.nan)


def braided_tube_elastic_force(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa, gap_mm=0.0):
    """``dE/dlz`` [N]: the wall's share of the developed force (negative while shortened).

    The analytic derivative of :func:`braided_tube_energy` with respect to the axial stretch;
    since the total energy is ``L0 E`` and ``L = L0 lz``, it is also ``dW/dL`` of the whole wall.
    With a gap (``gap_mm`` [mm]) the tube in contact is inflated even at ``eps = 0`` and this is
    negative there. NaN where the inner radius has collapsed.
    """
    Ri2, Ro2, lz, k, ri2, ro2, M, cot2 = mid_section_kinematics(D0_mm, t0_mm, eps, theta0_deg,
                                                                gap_mm)
    D = Ro2 - Ri2
    e = 1.0 - lz
    dro2 = -2.0 * (Ro2 + _rest_radii(D0_mm, t0_mm, gap_mm)[2]) * lz * cot2  # d(r_o^2)/dlz
    dk = dro2 + Ro2 / lz**2
    with np.errstate(invalid="ignore", divide="ignore"):
        dM = (dro2 + D / lz**2) / ri2 - dro2 / ro2
    # 2 lz - 2/lz^2 = -2 eps (lz^2 + lz + 1) / lz^2, and 2 - 2/lz^3 the same over lz^3
    dD = -2.0 * e * (lz**2 + lz + 1.0) / lz**2 * D
    dE = np.pi * (C10_MPa * (dD + dk * M + k * dM)
                  + C01_MPa * (dD / lz + (dk * lz**2 + 2.0 * k * lz) * M + k * lz**2 * dM))
    return np.where(ri2 > 0, dE, np.nan)


def klute_hannaford(pressure_bar, D0_mm, t0_mm, eps, theta0_deg,
                    C10_MPa=SILASTIC_S.C10_MPa, C01_MPa=SILASTIC_S.C01_MPa, gap_mm=0.0):
    r"""Klute-Hannaford virtual-work force of a McKibben muscle with a thick Mooney-Rivlin wall.

    .. math::
        F = \frac{\pi D_b^2 P}{4 \sin^2\theta_0}\left(3(1-\varepsilon)^2\cos^2\theta_0 - 1\right)
            + \frac{dE}{d\lambda_z}, \qquad D_b = D_0 + 2 t_0 + 2 g

    where ``E`` is the wall's stored energy per unit rest length (:func:`braided_tube_energy`).

    Parameters
    ----------
    pressure_bar : array_like
        Gauge pressure [bar].
    D0_mm : array_like
        Inner tube diameter at rest [mm].
    t0_mm : array_like
        Wall thickness at rest [mm]; the braid lies on the outer surface.
    eps : array_like
        Shortening ratio dL/L0 [fraction], the mid-section's axial stretch is ``1 - eps``.
    theta0_deg : float
        Braid angle at rest, from the muscle axis [deg].
    C10_MPa, C01_MPa : float, default Silastic S
        Mooney-Rivlin constants [MPa]; default from the paper's Equation 3 (C10 = 0.0694,
        C01 = 0.0628).
    gap_mm : array_like, default 0
        Radial gap ``g`` between the tube's outer surface and the braid at rest [mm]. The
        formula is the force once the tube has met the braid (at :func:`gap_closing_pressure`,
        below the threshold pressure); ``E`` then includes the free inflation that closed the
        gap.

    Returns
    -------
    numpy.ndarray
        Force the muscle develops at fixed length [N], affine in pressure. Negative below the
        threshold pressure (the muscle would need pushing to be held at ``eps``) and, with a
        negative pressure term, beyond the braid lock ``eps >= chou_hannaford_eps_max``; callers
        decide what to do there. NaN where the inner radius has collapsed.

    Notes
    -----
    Holds in the cylindrical mid-section of a long muscle: the clamped end caps (which keep the
    ends narrow) are outside the model, as are braid friction and hysteresis. With ``C10 = C01 =
    0`` or ``t0 -> 0`` it is Equation 2 with the braid diameter exactly. A gap (a clearance
    between tube and sleeve at rest) makes the tube inflate freely before the braid carries
    load, so the force starts above a threshold pressure even at ``eps = 0``.

    References
    ----------
    .. [1] G. K. Klute, B. Hannaford, "Accounting for elastic energy storage in McKibben
       artificial muscle actuators", ASME J. Dyn. Syst. Meas. Control 122(2), 386-388, 2000,
       doi:10.1115/1.482478.
    .. [2] B. Tondu, "Modelling of the McKibben artificial muscle: a review", J. Intell. Mater.
       Syst. Struct. 23(3), 225-253, 2012, doi:10.1177/1045389X11435435.
    .. [3] M. G. Antonelli, P. Beomonte Zobel, M. A. Sarwar, N. Stampone, "Mechanical Design of
       McKibben Muscles Predicting Developed Force by Artificial Neural Networks", Actuators
       14(3), 153, 2025, doi:10.3390/act14030153, Equations 2 and 3.

    See Also
    --------
    fem.eq2.chou_hannaford, klute_hannaford_threshold_pressure, gap_closing_pressure
    """
    return (chou_hannaford(pressure_bar, _braid_diameter(D0_mm, t0_mm, gap_mm), eps, theta0_deg)
            + braided_tube_elastic_force(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa,
                                         gap_mm))


def _braid_diameter(D0_mm, t0_mm, gap_mm):
    """``D0 + 2 t0 + 2 g`` [mm]: the braid's diameter at rest."""
    return (np.asarray(D0_mm, dtype=float) + 2.0 * np.asarray(t0_mm, dtype=float)
            + 2.0 * np.asarray(gap_mm, dtype=float))


def klute_hannaford_threshold_pressure(D0_mm, t0_mm, eps, theta0_deg,
                                       C10_MPa=SILASTIC_S.C10_MPa, C01_MPa=SILASTIC_S.C01_MPa,
                                       gap_mm=0.0):
    """Pressure [bar] at which a free muscle has shortened by ``eps``: ``F(P*) = 0``.

    ``P* = -(dE/dlz) / A`` with ``A`` the force per bar of the pressure term. Without a gap zero
    at ``eps = 0``, growing with ``eps`` and ``t0``; a gap ``gap_mm`` [mm] adds the pressure that
    inflates the tube to the braid (:func:`gap_closing_pressure`) and the little more that
    overcomes the free tube's push on its ends there. NaN at and beyond the braid lock (``A <=
    0``: no pressure shortens the muscle that far) and where the inner radius has collapsed.
    """
    per_bar = chou_hannaford(1.0, _braid_diameter(D0_mm, t0_mm, gap_mm), eps, theta0_deg)
    elastic = braided_tube_elastic_force(D0_mm, t0_mm, eps, theta0_deg, C10_MPa, C01_MPa,
                                         gap_mm)
    with np.errstate(divide="ignore", invalid="ignore"):
        threshold = -elastic / per_bar + 0.0  # + 0.0 turns the -0.0 at eps = 0 into 0.0
    return np.where(per_bar > 0, threshold, np.nan)


def mooney_rivlin_tube_inflation_pressure(D0_mm, t0_mm, outer_radius_mm, eps,
                                          C10_MPa=SILASTIC_S.C10_MPa,
                                          C01_MPa=SILASTIC_S.C01_MPa):
    r"""Pressure [bar] that holds a free thick incompressible Mooney-Rivlin tube at outer radius
    ``outer_radius_mm`` and axial stretch ``lz = 1 - eps`` (no braid, no load on the surface).

    .. math::
        P = \int_{r_i}^{r_o} \frac{\sigma_{\theta\theta} - \sigma_{rr}}{r}\,dr
          = \frac{C_{10} + C_{01} \lambda_z^2}{\lambda_z}
            \left[\ln\frac{a_i}{a_o} + k\left(\frac{1}{r_i^2} - \frac{1}{r_o^2}\right)\right]

    with ``r^2 = k + R^2 / lz``, ``k = r_o^2 - Ro^2 / lz`` and ``a = r^2 / R^2`` at the inner and
    outer surfaces: radial equilibrium integrated through the wall, where for Mooney-Rivlin
    ``sigma_tt - sigma_rr = 2 (C10 + C01 lz^2) (a - 1 / (a lz^2))`` and the integral is
    elementary in ``r^2``.

    Parameters
    ----------
    D0_mm, t0_mm : array_like
        Inner diameter and wall thickness of the tube at rest [mm].
    outer_radius_mm : array_like
        Deformed outer radius [mm] (at least ``D0/2 + t0`` at ``eps = 0``).
    eps : array_like
        Shortening ratio [fraction]; the tube's axial stretch is ``1 - eps``.
    C10_MPa, C01_MPa : float, default Silastic S
        Mooney-Rivlin constants [MPa].

    Returns
    -------
    numpy.ndarray
        Gauge pressure [bar]; NaN where the inner radius would collapse.

    References
    ----------
    .. [1] R. W. Ogden, "Non-Linear Elastic Deformations", Dover 1997 (extension and inflation
       of a thick-walled tube).
    .. [2] D. M. Haughton, R. W. Ogden, "Bifurcation of inflated circular cylinders of elastic
       material under axial loading - II. Exact theory for thick-walled tubes", J. Mech. Phys.
       Solids 27, 489-512, 1979.
    """
    Ri2, Ro, _ = _rest_radii(D0_mm, t0_mm, 0.0)
    lz = 1.0 - np.asarray(eps, dtype=float)
    ro2 = np.asarray(outer_radius_mm, dtype=float) ** 2
    k = ro2 - Ro**2 / lz
    ri2 = k + Ri2 / lz
    with np.errstate(invalid="ignore", divide="ignore"):
        M = np.log(ri2 / Ri2) - np.log(ro2 / Ro**2)
        pressure_MPa = (C10_MPa + C01_MPa * lz**2) / lz * (M + k * (1.0 / ri2 - 1.0 / ro2))
    return np.where(ri2 > 0, 10.0 * pressure_MPa, np.nan)


def gap_closing_pressure(D0_mm, t0_mm, eps, theta0_deg, gap_mm,
                         C10_MPa=SILASTIC_S.C10_MPa, C01_MPa=SILASTIC_S.C01_MPa):
    """Pressure [bar] at which the freely inflating tube reaches the braid: the contact pressure.

    :func:`mooney_rivlin_tube_inflation_pressure` at the braid's radius ``r_o^2 = Rb^2 (1 - lz^2
    cos^2 theta0) / sin^2 theta0``, ``Rb = D0/2 + t0 + gap_mm`` [mm], at axial stretch ``1 -
    eps``. Zero without a gap at ``eps = 0``; below it the braid carries nothing. The threshold
    of :func:`klute_hannaford_threshold_pressure` lies at or above it (the free tube held at
    its length pushes on its ends).
    """
    ro2 = mid_section_kinematics(D0_mm, t0_mm, eps, theta0_deg, gap_mm)[5]
    return mooney_rivlin_tube_inflation_pressure(D0_mm, t0_mm, np.sqrt(ro2), eps, C10_MPa,
                                                 C01_MPa)


def outer_diameter_mm(D0_mm, t0_mm, theta0_deg, pressure_bar, C10_MPa=SILASTIC_S.C10_MPa,
                      C01_MPa=SILASTIC_S.C01_MPa, gap_mm=0.0):
    """Braid (outer) diameter [mm] of the unloaded muscle at ``pressure_bar``: its largest.

    An unloaded muscle contracts freely until the threshold pressure of its shortening equals the
    supply pressure, ``P*(eps_f) = P`` (thick-wall closed form,
    :func:`klute_hannaford_threshold_pressure`, solved by bisection on
    ``[0, eps_max)``); any load holds it at a smaller shortening and diameter. The braid of
    constant thread length then has ``D_out^2 = (D0 + 2 t0)^2 (1 + eps_f (2 - eps_f) cot^2
    theta0)`` (:func:`mid_section_kinematics`). Mid-section value: the caps keep the ends
    narrower. Rubber constants in [MPa] (default Silastic S); with a radial gap ``gap_mm``
    [mm] between tube and braid, the braid's rest diameter is ``D0 + 2 t0 + 2 gap`` (a muscle
    below its threshold at rest length keeps it).
    """
    D0, t0, theta0, P = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in
                                              (D0_mm, t0_mm, theta0_deg, pressure_bar)))
    low = np.zeros(D0.shape)
    high = np.broadcast_to(chou_hannaford_eps_max(theta0), D0.shape).copy()
    for _ in range(40):  # eps to 2^-40 of eps_max
        mid = 0.5 * (low + high)
        threshold = klute_hannaford_threshold_pressure(D0, t0, mid, theta0, C10_MPa, C01_MPa,
                                                       gap_mm)
        below = np.nan_to_num(threshold, nan=np.inf) <= P
        low, high = np.where(below, mid, low), np.where(below, high, mid)
    outer_radius_sq_mm2 = mid_section_kinematics(D0, t0, low, theta0, gap_mm)[5]
    return 2.0 * np.sqrt(outer_radius_sq_mm2)


def stretched_braid(D0_mm, t0_mm, eps, strain):
    """``(D0_mm, eps)`` at which a model with inextensible fibres gives the force of a muscle
    held at ``eps`` whose braid's fibres are ``1 + strain`` times as long.

    At a held length ``L`` such fibres are the braid of a muscle ``1 + strain`` times as long
    and wide at rest, same angle, at ``1 - (1 - eps) / (1 + strain)``; the tube's bore is
    taken with the braid, its wall as declared (the wall's share of the force is off by about
    the strain of itself: a tube that only meets the wider braid under pressure)."""
    braid_mm = D0_mm + 2.0 * t0_mm
    return braid_mm * (1.0 + strain) - 2.0 * t0_mm, 1.0 - (1.0 - eps) / (1.0 + strain)


def fibre_tension_N(force_N, pressure_bar, D0_mm, t0_mm, eps, theta0_deg, strain=0.0):
    """The braid's fibres' tension [N], all strands along them, of a muscle held at ``eps``
    pulling ``force_N`` at ``pressure_bar``, its fibres ``1 + strain`` times their rest length.

    The fibres carry the pull and the pressure's end load on the tube's bore, ``(F + P pi
    r_i^2) / cos theta`` with ``cos theta = (1 - eps) cos theta0 / (1 + strain)``; the braid's
    radius is ``(1 + strain) R_b sin theta / sin theta0`` and ``r_i`` follows from the wall's
    volume (a thin-membrane braid: the wall's own axial force left out; the hoop load is in it,
    as the braid's geometry ties it to the axial one). Never below zero: fibres do not push."""
    cos0 = np.cos(np.deg2rad(theta0_deg))
    cos_t = (1.0 - eps) * cos0 / (1.0 + strain)
    braid_mm = D0_mm + 2.0 * t0_mm
    outer_mm2 = (braid_mm * (1.0 + strain) / 2.0) ** 2 * (1.0 - cos_t**2) / (1.0 - cos0**2)
    wall_mm2 = ((braid_mm / 2.0) ** 2 - (D0_mm / 2.0) ** 2) / (1.0 - eps)
    bore_mm2 = np.maximum(outer_mm2 - wall_mm2, 0.0)
    return np.maximum(force_N + 0.1 * np.asarray(pressure_bar) * np.pi * bore_mm2, 0.0) / cos_t


def effective_eps_of_slope(slope_N_per_bar, D0_mm, t0_mm, theta0_deg):
    """The shortening ``e`` [fraction] at which the braid slope ``dF/dP`` equals ``slope``.

    The pressure term of :func:`klute_hannaford` per bar, ``A(e) = A(0) (3 (1 - e)^2 cos^2
    theta0 - 1) / (3 cos^2 theta0 - 1)``, inverted in closed form; ``slope`` in [N/bar]. A slope
    above ``A(0)`` gives a negative ``e`` (a lengthening); NaN where no stretch gives it.
    """
    c2 = np.cos(np.deg2rad(theta0_deg)) ** 2
    D_braid = np.asarray(D0_mm, dtype=float) + 2.0 * np.asarray(t0_mm, dtype=float)
    ratio = slope_N_per_bar / chou_hannaford(1.0, D_braid, 0.0, theta0_deg)
    with np.errstate(invalid="ignore"):
        return 1.0 - np.sqrt((ratio * (3.0 * c2 - 1.0) + 1.0) / (3.0 * c2))


def effective_eps_of_threshold(threshold_bar, D0_mm, t0_mm, theta0_deg, C10_MPa, C01_MPa):
    """The shortening ``e`` [fraction] at which :func:`klute_hannaford_threshold_pressure`
    equals ``threshold_bar`` [bar], one muscle per element (1-D arrays of equal length).

    The threshold grows monotonically with ``e`` up to the braid lock, so Brent's root search
    between 0 and 0.999 of the lock finds the one root; NaN where the threshold is not in that
    range (0 or below, or beyond what any shortening short of the lock needs).
    """
    from scipy.optimize import brentq

    out = np.full(np.shape(threshold_bar), np.nan)
    for i, (p, d, t, th, c10, c01) in enumerate(zip(threshold_bar, D0_mm, t0_mm, theta0_deg,
                                                    C10_MPa, C01_MPa, strict=True)):
        top = 0.999 * chou_hannaford_eps_max(th)

        def gap(e, p=p, d=d, t=t, th=th, c10=c10, c01=c01):
            return float(klute_hannaford_threshold_pressure(d, t, e, th, c10, c01)) - p

        if p > 0 and gap(top) > 0 > gap(1e-12):
            out[i] = brentq(gap, 1e-12, top, xtol=1e-12)
    return out


class ThickWall(CalibratedTheta0, ForceModel):
    """Klute-Hannaford thick-wall model under the paper's isometric lock (``--model thickwall``).

    The free end shortens freely until ``eps``, then is held: the force is zero below the
    threshold pressure (valid) and :func:`klute_hannaford` above it. Beyond the braid lock
    (``eps >= eps_max`` of Equation 2, where no pressure shortens the muscle that far) the force
    is NaN and ``valid`` False.

    Parameters
    ----------
    theta0_deg : float, optional
        Braid angle at rest [deg]. Default: the calibrated value in ``fem/calibration.json``.
    L0_mm : float
        Length at rest [mm]. Recorded only: the mid-section model does not depend on the length.
    C10_MPa, C01_MPa : float, optional
        Mooney-Rivlin constants of the wall [MPa]; default Silastic S (the paper's Equation 3).
    gap_mm : float, optional
        Radial gap between tube and braid at rest [mm] (:func:`klute_hannaford`); with a gap the
        threshold is above zero even at ``eps = 0``. Default: the calibration entry's
        ``gap_mm`` where a muscle was identified with one (``mkm identify --params ...,gap``),
        else 0.
    calibration : Calibration, optional
        Where the default angle (and an identified rubber and gap) comes from; default the shipped
        ``fem/calibration.json`` (:class:`mkm.fem.calibration.Calibration`).
    """

    name = "thickwall"
    has_threshold = True
    domain = Domain()

    def __init__(self, theta0_deg: float | None = None, L0_mm: float = 282.0,
                 C10_MPa: float | None = None, C01_MPa: float | None = None,
                 gap_mm: float | None = None, calibration: Calibration | None = None):
        if gap_mm is not None:
            gap_mm = check_value("gap_mm", gap_mm)
        self.theta0_deg = theta0_deg
        self.calibration = calibration
        self.L0_mm = L0_mm
        self.C10_MPa = C10_MPa
        self.C01_MPa = C01_MPa
        self.gap_mm = gap_mm

    @property
    def material(self) -> MooneyRivlin:
        return self._rubber()

    def params(self):
        """The parameters; ``gap_mm`` only when there is a gap, so that every record and cache
        key of a gap-free muscle stays what it was."""
        gap = {"gap_mm": self._gap()} if self._gap() else {}
        return {"theta0_deg": self._theta0(), "L0_mm": self.L0_mm,
                "C10_MPa": self.material.C10_MPa, "C01_MPa": self.material.C01_MPa, **gap}

    def _forces(self, P, D0, t0, eps):
        theta0 = check_theta0(self._theta0())
        C10, C01 = self.material.C10_MPa, self.material.C01_MPa
        gap = self._gap()
        threshold = klute_hannaford_threshold_pressure(D0, t0, eps, theta0, C10, C01, gap)
        reachable = eps < chou_hannaford_eps_max(theta0)
        force = np.where(reachable, klute_hannaford(P, D0, t0, eps, theta0, C10, C01, gap),
                         np.nan)
        # below P* the isometric lock is not yet engaged; the maximum only absorbs round-off
        # of A P - B just above P* (NaN passes through it)
        force = np.where(P <= threshold, 0.0, np.maximum(force, 0.0))
        return {"force_N": force, "valid": reachable & np.isfinite(force),
                "converged": np.ones(P.shape, dtype=bool),
                "threshold_pressure_bar": np.where(reachable, threshold, np.nan)}
