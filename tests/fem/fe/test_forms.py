"""The braid forms of the FE model (fem/fe/forms.py) against finite differences and geometry.

The rubber and cavity forms are tested in tests/fem/test_materials.py (closed-form stretches)
and, assembled, at a deformed state in test_model.py.
"""

import numpy as np
import pytest

from mkm.fem.fe.forms import braid_inextensibility, cavity_volume, sliding_sleeve_length

RO = 20.0


def states(n=50, seed=0):
    """Outer-surface states (u_r, du_r/dZ, du_z/dZ) of 0-15 % strain, well inside the lock."""
    rng = np.random.default_rng(seed)
    return rng.uniform([-0.5, -0.1, -0.15], [3.0, 0.1, 0.05], size=(n, 3))


@pytest.mark.parametrize("form", [braid_inextensibility, sliding_sleeve_length,
                                  lambda y, theta0, ro: cavity_volume(y[..., :2])])
def test_gradient_and_hessian_match_central_differences(form):
    y = states()
    value, grad, hess = form(y, 32.0, RO)
    k = grad.shape[-1]
    h = 1e-6  # central differences: truncation 1e-12, round-off 1e-10
    for j in range(k):
        step = np.zeros(y.shape[-1])
        step[j] = h
        plus, minus = form(y + step, 32.0, RO), form(y - step, 32.0, RO)
        np.testing.assert_allclose((plus[0] - minus[0]) / (2 * h), grad[..., j],
                                   rtol=1e-6, atol=1e-8)
        np.testing.assert_allclose((plus[1] - minus[1]) / (2 * h), hess[..., :, j],
                                   rtol=1e-6, atol=1e-8)


@pytest.mark.parametrize("theta0", [20.0, 32.0, 45.0])
def test_uniform_braided_state_satisfies_both_sleeves(theta0):
    # A cylinder shortened uniformly by eps with the braid's own kinematics (constant thread
    # length: cos theta = (1 - eps) cos theta0, the outer radius from the hoop stretch) is
    # inextensible for the bonded braid and keeps the sliding sleeve's length density at 1.
    c2 = np.cos(np.deg2rad(theta0)) ** 2
    for eps in (0.0, 0.05, 0.2):
        lz = 1.0 - eps
        lt = np.sqrt((1.0 - lz**2 * c2) / (1.0 - c2))
        y = np.array([(lt - 1.0) * RO, 0.0, lz - 1.0])
        assert braid_inextensibility(y, theta0, RO)[0] == pytest.approx(0.0, abs=1e-14)
        assert sliding_sleeve_length(y, theta0, RO)[0] == pytest.approx(0.0, abs=1e-14)


def test_sliding_sleeve_needs_more_sleeve_where_the_tube_bulges():
    # at fixed meridional stretch, a wider tube needs more sleeve per unit length (its threads
    # lie flatter), without bound as the hoop stretch nears the lock 1 / sin(theta0)
    theta0 = 32.0
    lock = 1.0 / np.sin(np.deg2rad(theta0))
    lt = np.array([1.0, 1.2, 1.5, 0.999 * lock])
    y = np.stack([(lt - 1.0) * RO, 0 * lt, 0 * lt], axis=-1)
    density = sliding_sleeve_length(y, theta0, RO)[0]
    assert density[0] == pytest.approx(0.0, abs=1e-15)
    assert np.all(np.diff(density) > 0) and density[-1] > 10.0
