"""Newton's method and load stepping on problems with known solutions and known failures."""

import numpy as np
import scipy.sparse as sp

from fem.fe.newton import load_path, newton


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
