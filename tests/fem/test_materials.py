"""The incompressible Mooney-Rivlin law of the FE model against closed-form stretches."""

import numpy as np
import pytest

from mkm.fem.fe.forms import mooney_rivlin_incompressible, mooney_rivlin_incompressible_tangent
from mkm.fem.materials import SILASTIC_S

C10, C01 = SILASTIC_S.C10_MPa, SILASTIC_S.C01_MPa
STRETCHES = np.array([0.6, 0.9, 1.0, 1.3, 2.0, 3.0])


def cauchy_zz(F_rr, F_zz, F_tt):
    """Axial Cauchy stress of a diagonal stretch with a traction-free radial face.

    The radial condition P_rr(p) = 0 is linear in p, so p follows from two evaluations; with
    J = 1 and F diagonal, sigma_zz = P_zz F_zz.
    """
    y = np.stack(np.broadcast_arrays(F_rr, 0.0, 0.0, F_zz, F_tt, 0.0), axis=-1)
    y1 = y.copy()
    y1[..., 5] = 1.0
    P0 = mooney_rivlin_incompressible(y, SILASTIC_S)
    P1 = mooney_rivlin_incompressible(y1, SILASTIC_S)
    p = -P0[..., 0] / (P1[..., 0] - P0[..., 0])
    y[..., 5] = p
    P = mooney_rivlin_incompressible(y, SILASTIC_S)
    assert np.allclose(P[..., 0], 0.0, atol=1e-14)
    return P[..., 3] * F_zz


def test_uniaxial_stretch_matches_closed_form():
    # sigma = 2 (l^2 - 1/l)(C10 + C01/l) for uniaxial tension of incompressible Mooney-Rivlin
    # (Treloar; Ogden, Non-linear elastic deformations, 1984). Both sides are exact
    # polynomials: agreement to round-off (1e-12 relative).
    lam = STRETCHES
    expected = 2.0 * (lam**2 - 1.0 / lam) * (C10 + C01 / lam)
    got = cauchy_zz(1.0 / np.sqrt(lam), lam, 1.0 / np.sqrt(lam))
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-15)


def test_equibiaxial_stretch_matches_closed_form():
    # stretch l in z and theta, 1/l^2 radially: sigma = 2 (l^2 - 1/l^4)(C10 + C01 l^2)
    lam = STRETCHES
    expected = 2.0 * (lam**2 - lam**-4) * (C10 + C01 * lam**2)
    got = cauchy_zz(lam**-2, lam, lam)
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-15)


def test_stress_is_the_derivative_of_the_published_energy():
    # At J = 1 and diagonal F the first Piola-Kirchhoff stress (p = 0) is dW/dl_i of
    # MooneyRivlin.energy; central differences with h = 1e-6 are accurate to ~1e-10.
    l1, l2, l3 = 1.3, 0.8, 1.0 / (1.3 * 0.8)
    P = mooney_rivlin_incompressible(np.array([l1, 0, 0, l2, l3, 0.0]), SILASTIC_S)
    h = 1e-6
    dW = [(SILASTIC_S.energy(*(np.add((l1, l2, l3), h * e))) -
           SILASTIC_S.energy(*(np.subtract((l1, l2, l3), h * e)))) / (2 * h) for e in np.eye(3)]
    np.testing.assert_allclose([P[0], P[3], P[4]], dW, rtol=1e-8)


def complex_step_jacobian(y):
    """Jacobian of the stress by complex step: exact to round-off, an independent reference."""
    h = 1e-30
    columns = []
    for e in np.eye(y.shape[-1]):
        columns.append(mooney_rivlin_incompressible(y + 1j * h * e, SILASTIC_S).imag / h)
    return np.stack(columns, axis=-1)


def test_analytic_tangent_matches_complex_step_and_finite_differences():
    rng = np.random.default_rng(3)  # seed fixed: reproducible random deformations
    y = np.array([1.1, 0.2, -0.1, 0.9, 1.2, 0.3]) + 0.05 * rng.standard_normal((5, 6))
    H = mooney_rivlin_incompressible_tangent(y, SILASTIC_S)
    np.testing.assert_allclose(H, complex_step_jacobian(y), rtol=1e-13, atol=1e-15)
    h = 1e-6
    fd = np.stack([(mooney_rivlin_incompressible(y + h * e, SILASTIC_S) -
                    mooney_rivlin_incompressible(y - h * e, SILASTIC_S)) / (2 * h)
                   for e in np.eye(6)], axis=-1)
    np.testing.assert_allclose(H, fd, rtol=1e-7, atol=1e-9)  # central differences: O(h^2)
    np.testing.assert_allclose(H, np.swapaxes(H, -1, -2), atol=1e-15)  # an energy's Hessian


@pytest.mark.parametrize("shape", [(6,), (4, 3, 6)])
def test_tangent_keeps_batch_shape(shape):
    y = np.ones(shape)
    assert mooney_rivlin_incompressible_tangent(y, SILASTIC_S).shape == shape + (6,)


@pytest.mark.parametrize(("spec", "name"), [
    ("thickwall:C10_MPa=-1", "C10_MPa"), ("axisym:mesh=coarse,C10_MPa=-1", "C10_MPa"),
    ("thickwall:C01_MPa=-1", "C01_MPa"), ("thickwall:C10_MPa=1e9", "C10_MPa")])
def test_a_rubber_outside_the_limits_is_refused(spec, name):
    """A spec's rubber used to bypass the limits: thickwall:C10_MPa=-1 pulled 378 N at 0 bar
    (threshold -1.03 bar) and the FE -51 N at 1 bar, both valid=True."""
    from mkm.registry import parse_spec

    with pytest.raises(ValueError, match=rf"^{name}=\S+ is invalid: expected a Mooney-Rivlin"):
        parse_spec(spec).build().predict([0.0, 1.0], 35, 2.5, 0.05)
