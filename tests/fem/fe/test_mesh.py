"""Graded half-muscle meshes (fem/fe/mesh.py)."""

import numpy as np
import pytest

from mkm.fem.fe.mesh import graded_spacing, half_muscle_mesh
from mkm.fem.options import MESH_LEVELS


@pytest.mark.parametrize(("n", "ratio"), [(16, 8.0), (96, 32.0), (1, 5.0)])
def test_spacing_shrinks_geometrically_towards_the_cap(n, ratio):
    x = graded_spacing(141.0, n, ratio)
    h = np.diff(x)
    assert x[0] == 0.0 and x[-1] == pytest.approx(141.0, rel=1e-15) and len(x) == n + 1
    if n > 1:
        assert h[0] / h[-1] == pytest.approx(ratio, rel=1e-12)
        np.testing.assert_allclose(h[1:] / h[:-1], ratio ** (-1.0 / (n - 1)), rtol=1e-12)


@pytest.mark.parametrize("level", list(MESH_LEVELS))
def test_mesh_covers_the_wall(level):
    n_r, n_z, _ = MESH_LEVELS[level]
    m = half_muscle_mesh(35.0, 2.5, 282.0, level)
    assert m.t.shape[1] == 2 * n_r * n_z  # two triangles per tensor cell
    np.testing.assert_allclose(m.p.min(axis=1), [17.5, 0.0])
    np.testing.assert_allclose(m.p.max(axis=1), [20.0, 141.0])


def test_unknown_level_is_named():
    with pytest.raises(ValueError, match="^mesh='huge' is invalid: expected one of coarse"):
        half_muscle_mesh(35.0, 2.5, 282.0, "huge")
