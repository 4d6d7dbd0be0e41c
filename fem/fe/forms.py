"""Pointwise physics of the axisymmetric muscle model, as plain functions of quadrature values.

Each function takes the kinematic variables at the quadrature points, stacked on the last axis,
and returns the energy density's gradient and Hessian with respect to them. The assembly in
:mod:`mkm.fem.fe.assembly` contracts them with constant (total-Lagrangian) operator arrays, so no
form
indexes basis functions one by one; that keeps an assembly of the whole tangent vectorised.

Variables (all in mm, MPa, so energies are in N mm):

* rubber: ``y = (F_rr, F_rz, F_zr, F_zz, F_tt, p)``, the axisymmetric deformation gradient
  ``F = [[1 + du_r/dR, du_r/dZ, 0], [du_z/dR, 1 + du_z/dZ, 0], [0, 0, 1 + u_r/R]]`` and the
  pressure-like Lagrange multiplier ``p`` of incompressibility;
* cavity: ``y = (r, dz/dZ)`` on the inner surface (deformed radius and axial stretch);
* braid: ``y = (u_r, du_r/dZ, du_z/dZ)`` on the outer surface.
"""

from __future__ import annotations

import numpy as np

from mkm.fem.materials import MooneyRivlin

# d(j')/d(F_rr, F_rz, F_zr, F_zz) with j' = (F_zz, -F_zr, -F_rz, F_rr), see the tangent below
_DJ_DF2 = np.array([[0, 0, 0, 1], [0, 0, -1, 0], [0, -1, 0, 0], [1, 0, 0, 0.0]])


def mooney_rivlin_incompressible(y: np.ndarray, material: MooneyRivlin) -> np.ndarray:
    r"""Gradient of the incompressible Mooney-Rivlin energy density with respect to ``y``.

    .. math::
        \psi(F, p) = C_{10}(I_1 - 3) + C_{01}(I_2 - 3) - p\,(J - 1)

    with the (not isochoric) invariants of ``C = F^T F``; ``p`` enforces ``J = 1`` exactly (a
    Taylor-Hood u-p formulation without bulk modulus, as ANSYS does with C10, C01 and no D1).
    For the axisymmetric block form ``F = diag(F2, F_tt)``:
    ``I1 = |F2|^2 + F_tt^2``, ``I2 = F_tt^2 |F2|^2 + det(F2)^2``, ``J = F_tt det(F2)``.

    Parameters
    ----------
    y : numpy.ndarray, shape (..., 6)
        ``(F_rr, F_rz, F_zr, F_zz, F_tt, p)``; ``p`` in MPa.
    material : MooneyRivlin
        ``C10_MPa``, ``C01_MPa``.

    Returns
    -------
    numpy.ndarray, shape (..., 6)
        ``d psi / d y``: the first Piola-Kirchhoff components [MPa] and ``-(J - 1)``.
    """
    # one contiguous row per variable (a copy): numpy's operations on rows are faster
    a, b, c, d, t, p = np.moveaxis(y, -1, 0).copy()
    C10, C01 = material.C10_MPa, material.C01_MPa
    j = a * d - b * c
    # dpsi/dF2 = (2 C10 + 2 C01 F_tt^2) F2 + (2 C01 j - p F_tt) j', j' = dj/dF2 = (d, -c, -b, a)
    k_F, k_j = 2 * C10 + 2 * C01 * t * t, 2 * C01 * j - p * t
    g = np.empty((6,) + t.shape, dtype=np.result_type(y, float))  # complex for a complex step
    g[0] = k_F * a + k_j * d
    g[1] = k_F * b - k_j * c
    g[2] = k_F * c - k_j * b
    g[3] = k_F * d + k_j * a
    g[4] = 2 * C10 * t + 2 * C01 * t * (a * a + b * b + c * c + d * d) - p * j
    g[5] = 1.0 - t * j
    return np.moveaxis(g, 0, -1)


def mooney_rivlin_incompressible_tangent(y: np.ndarray, material: MooneyRivlin) -> np.ndarray:
    """Hessian of the density of :func:`mooney_rivlin_incompressible` with respect to ``y``.

    Analytic (the density is a polynomial in ``y``): with ``j = det(F2)`` and
    ``j' = dj/d(F_rr, F_rz, F_zr, F_zz) = (F_zz, -F_zr, -F_rz, F_rr)``, shape (..., 6, 6).
    """
    a, b, c, d, t, p = np.moveaxis(y, -1, 0).copy()
    C10, C01 = material.C10_MPa, material.C01_MPa
    x = np.stack([a, b, c, d])
    jp = np.stack([d, -c, -b, a])
    j = a * d - b * c
    # built as H[row, column, ...] (whole rows of points at a time), returned as a view
    H = np.empty((6, 6) + t.shape, dtype=np.result_type(y, float))
    H[:4, :4] = (2 * C01 * jp[:, None] * jp[None, :]
                 + (2 * C01 * j - p * t) * _DJ_DF2.reshape(_DJ_DF2.shape + (1,) * t.ndim))
    H[range(4), range(4)] += 2 * C10 + 2 * C01 * t * t
    H[:4, 4] = H[4, :4] = 4 * C01 * t * x - p * jp
    H[:4, 5] = H[5, :4] = -t * jp
    H[4, 4] = 2 * C10 + 2 * C01 * np.sum(x * x, axis=0)
    H[4, 5] = H[5, 4] = -j
    H[5, 5] = 0.0
    return np.moveaxis(H, (0, 1), (-2, -1))


def cavity_volume(y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""Volume density of the closed cavity along the inner surface, ``v = pi r^2 dz/dZ``.

    ``V = \int v\,dZ`` over the inner surface from the mid-plane to the cap is the volume of the
    solid of revolution enclosed by the rubber and the rigid cap, so ``-P V`` is the potential of
    the (follower) pressure load on the inner surface and on the cap. Returns ``v``, its gradient
    and Hessian with respect to ``y = (r, dz/dZ)``.
    """
    r, zs = y[..., 0], y[..., 1]
    v = np.pi * r * r * zs
    grad = np.stack([2 * np.pi * r * zs, np.pi * r * r], axis=-1)
    hess = np.empty(y.shape + (2,))
    hess[..., 0, 0] = 2 * np.pi * zs
    hess[..., 0, 1] = hess[..., 1, 0] = 2 * np.pi * r
    hess[..., 1, 1] = 0.0
    return v, grad, hess


def braid_inextensibility(y: np.ndarray, theta0_deg: float, Ro_mm: float,
                          braid_radius_mm: float | None = None):
    r"""Stretch constraint of two inextensible helical fibre families at +-theta0.

    A fibre element of length ``dS`` at rest spans ``dS cos theta0`` along the axis and
    ``dS sin theta0`` around it; bonded to the outer surface it is stretched by
    ``l_f^2 = cos^2 theta0 l_s^2 + sin^2 theta0 l_t^2`` with the meridional stretch
    ``l_s^2 = (1 + du_z/dZ)^2 + (du_r/dZ)^2`` and the hoop stretch ``l_t = 1 + u_r / R_o``.
    Inextensible fibres: ``g = l_f^2 - 1 = 0``. Both families give the same constraint in an
    axisymmetric state (no torsion).

    A braid of rest radius ``R_b = braid_radius_mm`` above the tube's ``R_o`` (a radial gap)
    lies on the tube where the tube reaches it; there its hoop stretch is the tube's radius
    over its own, ``l_t = (1 + u_r / R_o) R_o / R_b`` (the same as above when ``R_b = R_o``,
    bit for bit: the factor is exactly 1). Where the tube is inside it, ``g < 0``: the fibres
    are slack, which the tension-only braid of the model (``g <= 0``, tension ``>= 0``,
    complementary) lets them be. That complementarity is then the unilateral contact of tube
    and braid: no penetration (the braid's radius is bounded by its threads) and a contact
    pressure, the hoop share of the tension, only where they touch.

    Returns ``g``, its gradient and Hessian with respect to ``y = (u_r, du_r/dZ, du_z/dZ)``.
    """
    c2 = np.cos(np.deg2rad(theta0_deg)) ** 2
    s2 = 1.0 - c2
    ratio = 1.0 if braid_radius_mm is None else Ro_mm / braid_radius_mm
    ur, urZ, uzZ = y[..., 0], y[..., 1], y[..., 2]
    lt = (1.0 + ur / Ro_mm) * ratio
    g = c2 * ((1.0 + uzZ) ** 2 + urZ**2) + s2 * lt * lt - 1.0
    grad = np.stack([2 * s2 * lt * ratio / Ro_mm, 2 * c2 * urZ, 2 * c2 * (1.0 + uzZ)], axis=-1)
    hess = np.zeros(y.shape + (3,))
    hess[..., 0, 0] = 2 * s2 * ratio**2 / Ro_mm**2
    hess[..., 1, 1] = 2 * c2
    hess[..., 2, 2] = 2 * c2
    return g, grad, hess


def sliding_sleeve_length(y: np.ndarray, theta0_deg: float, Ro_mm: float):
    r"""Sleeve length density of a frictionless braided sleeve on the outer surface, minus one.

    A sleeve that slides on the rubber is a braid of its own: its local net keeps
    ``cos^2 theta0 L_s^2 + sin^2 theta0 l_t^2 = 1`` in its own meridional stretch ``L_s``, while
    its radius is the rubber's (hoop stretch ``l_t = 1 + u_r / R_o``). Sleeve material is
    ``dS = c l_s dZ / sqrt(1 - s^2 l_t^2)`` per rubber length ``dZ`` (``l_s`` the rubber
    surface's meridional stretch, ``c = cos theta0``, ``s = sin theta0``), and the sleeve ends
    are held by the caps, so the one constraint is its total length,
    ``\int (c l_s / sqrt(1 - s^2 l_t^2) - 1) dZ = 0``, with one uniform fibre tension (no
    friction). A uniform state satisfies it exactly where the bonded braid does.

    Returns the density, its gradient and Hessian with respect to ``y = (u_r, du_r/dZ,
    du_z/dZ)``; NaN past the sleeve's lock (``s l_t >= 1``).
    """
    c = np.cos(np.deg2rad(theta0_deg))
    s2 = 1.0 - c * c
    ur, urZ, uzZ = y[..., 0], y[..., 1], y[..., 2]
    lt = 1.0 + ur / Ro_mm
    q = 1.0 - s2 * lt * lt
    with np.errstate(invalid="ignore", divide="ignore"):
        B = q ** -0.5
        dB = s2 * lt * q ** -1.5  # dB/dl_t
        d2B = s2 * q ** -1.5 + 3.0 * s2 * s2 * lt * lt * q ** -2.5
    ls = np.sqrt((1.0 + uzZ) ** 2 + urZ**2)
    n1, n2 = urZ / ls, (1.0 + uzZ) / ls
    f = c * ls * B - 1.0
    grad = np.stack([c * ls * dB / Ro_mm, c * B * n1, c * B * n2], axis=-1)
    hess = np.empty(y.shape + (3,))
    hess[..., 0, 0] = c * ls * d2B / Ro_mm**2
    hess[..., 0, 1] = hess[..., 1, 0] = c * dB * n1 / Ro_mm
    hess[..., 0, 2] = hess[..., 2, 0] = c * dB * n2 / Ro_mm
    hess[..., 1, 1] = c * B * (1.0 - n1 * n1) / ls
    hess[..., 2, 2] = c * B * (1.0 - n2 * n2) / ls
    hess[..., 1, 2] = hess[..., 2, 1] = -c * B * n1 * n2 / ls
    return f, grad, hess
