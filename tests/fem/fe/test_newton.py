"""Newton's method and load stepping on problems with known solutions and known failures."""

import numpy as np
import scipy.sparse as sp

from mkm.fem.fe.newton import load_path, newton


def cubic(x, t=8.0):
    """x^3 = t, one unknown: the root is t^(1/3)."""
    return np.array([x[0] ** 3 - t]), sp.csr_matrix([[3 * x[0] ** 2]])


def test_newton_finds_the_root_quadratically():
    x, report = newton(cubic, [1.0])
    assert report.converged and report.reason == ""
    # to xtol = 1e-9 relative, as documented: the last step is checked by a chord estimate
    assert abs(x[0] - 2.0) < 1e-9 * 2.0
    assert report.iterations <= 7  # quadratic convergence from x = 1 takes 6 iterations


def test_newton_reports_no_root_instead_of_a_number():
    def no_root(x):  # x^2 + 1 = 0 has no real root: Newton wanders
        return np.array([x[0] ** 2 + 1.0]), sp.csr_matrix([[2 * x[0]]])

    _, report = newton(no_root, [0.5], maxiter=15)
    assert not report.converged
    assert report.iterations == 15
    assert "did not converge" in report.reason


def test_newton_rejects_a_state_the_check_refuses():
    _, report = newton(cubic, [1.0], check=lambda x: "inverted" if x[0] > 1.5 else None)
    assert not report.converged and report.reason == "inverted"


def test_load_path_reaches_every_target():
    targets = [1.0, 8.0, 27.0]
    path = load_path(cubic, [1.0], 1.0, targets)
    roots = [x[0] for x, _ in path]
    np.testing.assert_allclose(roots, [1.0, 2.0, 3.0], rtol=1e-10)
    assert all(report.converged for _, report in path)


def test_load_path_cuts_back_and_reports_the_unreachable():
    # states with x > 2.5 are "inverted": the first target (x = 2) is reached, possibly after
    # cut-backs; the second (x = 3) cannot be, nor anything after it
    path = load_path(cubic, [1.0], 1.0, [8.0, 27.0, 64.0], increments=1, max_cutbacks=3,
                     check=lambda x, t: "inverted" if x[0] > 2.5 else None)
    (x1, r1), (x2, r2), (x3, r3) = path
    assert r1.converged and abs(x1[0] - 2.0) < 1e-10
    assert x2 is None and not r2.converged and r2.cutbacks == 4
    assert "inverted" in r2.reason and "3 cut-backs" in r2.reason
    assert x3 is None and r3.reason.startswith("not reached")


def _laplacian_saddle(n: int, seed: int) -> sp.csc_matrix:
    """A symmetric indefinite matrix shaped like the FE tangents: a 1-D Laplacian block with a
    constraint row and column per pair of unknowns (zero diagonal there), numbered badly."""
    rng = np.random.default_rng(seed)
    K = sp.diags([-1.0, 2.0 + rng.random(n), -1.0], [-1, 0, 1], shape=(n, n))
    C = sp.csr_matrix((np.ones(n), (np.arange(n) // 2, np.arange(n))), shape=(n // 2, n))
    A = sp.bmat([[K, C.T], [C, None]]).tocsc()
    shuffle = rng.permutation(A.shape[0])
    return A[shuffle][:, shuffle].tocsc()


def test_ordered_lu_solves_as_superlu_and_keeps_its_ordering():
    from scipy.sparse.linalg import splu

    from mkm.fem.fe.newton import OrderedLU

    factorize = OrderedLU()
    A = _laplacian_saddle(200, 0)
    b = np.random.default_rng(1).standard_normal(A.shape[0])
    x = factorize(A).solve(b)
    np.testing.assert_allclose(A @ x, b, atol=1e-10)
    np.testing.assert_allclose(x, splu(A.copy()).solve(b), rtol=1e-8, atol=1e-10)
    perm = factorize._perm
    B = A.copy()  # same pattern arrays, new values (as a Newton tangent's next assembly)
    B.data = np.where(B.data == 0, 0.0, B.data * 1.5 + 0.25 * (B.data > 1.5))
    np.testing.assert_allclose(B @ factorize(B).solve(b), b, atol=1e-9)
    assert factorize._perm is perm  # the ordering was found once
    C = _laplacian_saddle(120, 3)  # another pattern: ordered afresh
    c = np.ones(C.shape[0])
    np.testing.assert_allclose(C @ factorize(C).solve(c), c, atol=1e-10)
    assert factorize._perm is not perm


def test_ordered_lu_of_the_leading_block_in_csr():
    from mkm.fem.fe.newton import OrderedLU

    A = _laplacian_saddle(200, 4)
    m = A.shape[0] - 3
    b = np.random.default_rng(5).standard_normal(m)
    x = OrderedLU(leading=m)(A.tocsr()).solve(b)  # the block is read, not sliced by the caller
    np.testing.assert_allclose(A[:m, :m] @ x, b, atol=1e-10)


def test_newton_reports_a_singular_tangent_through_ordered_lu():
    from mkm.fem.fe.newton import OrderedLU

    def flat(x):  # residual 1 everywhere, tangent zero: no Newton step exists
        return np.ones(2), sp.csr_matrix((2, 2))

    _, report = newton(flat, [0.0, 0.0], factorize=OrderedLU())
    assert not report.converged and report.reason == "singular tangent"


def test_accept_stops_newton_early_and_only_when_asked():
    # x^3 = 8 from x = 1: the caller accepts once the estimated next step is below 1e-3
    steps = []

    def accept(x, step):
        steps.append(abs(step[0]))
        return abs(step[0]) < 1e-3

    x, report = newton(cubic, [1.0], accept=accept)
    strict, strict_report = newton(cubic, [1.0])
    assert report.converged and report.iterations < strict_report.iterations
    # the estimated next step is the error left, to second order
    assert abs(abs(x[0] - strict[0]) - steps[-1]) < 0.01 * steps[-1]
    assert steps[-1] < 1e-3 <= min(steps[:-1])


def test_ordered_lu_numbers_a_dense_row_last():
    # The sliding sleeve's single tension couples to every unknown of the outer surface: one
    # dense row and column. Numbered last, it adds at most its own row and column to the
    # factors (2 n entries); inside the RCM band it would widen the band to the whole boundary.
    from mkm.fem.fe.newton import OrderedLU

    A = _laplacian_saddle(400, 6)
    n = A.shape[0]
    coupled = np.arange(0, n, 3)  # a third of the unknowns, spread over the band
    dense = sp.csc_matrix((np.ones(coupled.size), (coupled, np.zeros(coupled.size, int))),
                          shape=(n, 1))
    B = sp.bmat([[A, dense], [dense.T, None]]).tocsc()
    b = np.random.default_rng(7).standard_normal(n + 1)
    lu_sparse, lu_dense = OrderedLU()(A), OrderedLU()(B)
    np.testing.assert_allclose(B @ lu_dense.solve(b), b, atol=1e-9)
    fill_sparse = lu_sparse._lu.L.nnz + lu_sparse._lu.U.nnz
    assert lu_dense._lu.L.nnz + lu_dense._lu.U.nnz <= fill_sparse + 2 * (n + 1)
