"""The generic assembler (fem/fe/assembly.py) against scikit-fem's own assembly."""

import numpy as np
from skfem import Basis, BilinearForm, ElementTriP2, LinearForm, MeshTri, asm
from skfem.helpers import dot, grad

from mkm.fem.fe.assembly import Assembler, Term, operator


def test_quadratic_energy_gives_scikit_fems_matrix_and_vector():
    # Pi(u) = int (|grad u|^2 / 2 + a u^2 / 2 - f u) on a distorted P2 mesh, with the boundary
    # dofs fixed: y = (du/dx, du/dy, u) with a constant Hessian diag(1, 1, a) and gradient
    # (du/dx, du/dy, a u - f). Our operator path and skfem's forms must agree to round-off.
    m = MeshTri.init_sqsymmetric().refined(2)
    m = MeshTri(m.p + 0.05 * np.sin(3 * m.p[::-1]), m.t)
    basis = Basis(m, ElementTriP2())
    a, f = 2.0, 3.0
    fixed = basis.get_dofs().flatten()
    red = np.full(basis.N, -1)
    free = np.setdiff1d(np.arange(basis.N), fixed)
    red[free] = np.arange(free.size)
    B = operator(basis, lambda v, g: (g[0], g[1], v))
    term = Term(B, np.zeros(3), basis.element_dofs, basis.dx, red)
    n = free.size
    z = np.sin(np.arange(n))  # any state: the energy is quadratic
    y = term.values(np.append(z, 0.0))
    g = np.stack([y[..., 0], y[..., 1], a * y[..., 2] - f], axis=-1)
    h = np.broadcast_to(np.diag([1.0, 1.0, a]), y.shape + (3,))
    r, Ke = term.arrays(g, h)
    K = Assembler([term], n).matrix([Ke])

    K_ref = asm(BilinearForm(lambda u, v, w: dot(grad(u), grad(v)) + a * u * v), basis)
    b_ref = asm(LinearForm(lambda v, w: f * v), basis)
    K_ref = K_ref[free][:, free]
    scale = abs(K_ref).max()
    assert abs(K - K_ref).max() < 1e-12 * scale
    np.testing.assert_allclose(r, K_ref @ z - b_ref[free], rtol=0, atol=1e-12 * scale)
