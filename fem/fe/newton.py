"""Newton's method with load stepping and automatic cut-back, apart from any physics.

A problem is a function ``fun(x, t) -> (residual, jacobian)`` of the unknowns ``x`` and a load
parameter ``t`` (a pressure, a cap displacement); ``jacobian`` is a scipy sparse matrix. An
optional ``check(x) -> str | None`` (``check(x, t)`` in :func:`load_path`) names a reason to
reject a state at once (element inversion).
Failure is reported, never hidden: a step that does not converge is cut back, and a target that
cannot be reached is returned with ``converged=False``, its iterations, residual and reason.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee
from scipy.sparse.linalg import splu


@dataclass
class NewtonReport:
    """Outcome of one Newton solve or of one load target reached by several steps."""

    converged: bool
    iterations: int = 0
    cutbacks: int = 0
    residual: float = np.nan  # last residual norm relative to the step's first one
    reason: str = ""
    # a load path that failed: its last (up to two) converged (load, state), newest last
    reached: tuple = ()
    # a path that stopped at a physical limit (no state beyond it), not a failure of the solver:
    # its name (one of mkm.fem.outcomes.PHYSICAL_LIMITS), "" otherwise
    limit: str = ""


class OrderedLU:
    """Sparse LU (SuperLU) of a sequence of matrices of one sparsity pattern, with the
    fill-reducing ordering found once.

    Newton's tangents share their pattern; SuperLU's default column ordering (COLAMD), found
    afresh at every factorisation, costs as much as the numerical factorisation of the FE
    tangents. Here the reverse Cuthill-McKee ordering of the pattern (symmetrised, dense rows
    last: :func:`_banded_order`) is found at the first matrix of a pattern and reused (by
    every instance: :func:`_ordering` keeps the last few patterns' orderings), and
    SuperLU factorises the symmetrically permuted matrix in its natural column order, in its
    symmetric mode (a diagonal pivot is taken while it is at least a tenth of the column's
    largest: the tangent of an energy is symmetric, and this keeps the band). The permuted
    matrix is gathered from the matrix's entries by one precomputed index, in whatever sparse
    format it comes, so no slicing or format conversion is repeated either. ``leading=m``
    factorises the leading ``m x m`` block only (the FE tangent without the held cap's row and
    column). A matrix of another pattern gets its own ordering. The FE model's free path (the
    pressure as the cap's unknown: symmetric but for that column, which is dense along the
    inner surface and numbered last) uses one too. Call it like ``splu``:
    ``OrderedLU()(A).solve(b)``.
    """

    def __init__(self, leading: int | None = None):
        self.leading = leading
        self._pattern = None

    def __call__(self, A) -> _PermutedLU:
        A = A if getattr(A, "format", None) in ("csr", "csc") else sp.csc_matrix(A)
        if not self._same_pattern(A):
            (self._perm, self._inverse, self._source, self._p_indices,
             self._p_indptr) = _ordering(A.format, A.shape, self.leading, A.indptr.tobytes(),
                                         A.indices.tobytes(), A.indices.dtype.str)
            self._pattern = (A.format, A.shape, A.indptr.copy(), A.indices.copy())
        permuted = sp.csc_matrix((A.data[self._source], self._p_indices, self._p_indptr),
                                 shape=(self._perm.size,) * 2)
        lu = splu(permuted, permc_spec="NATURAL", diag_pivot_thresh=0.1,
                  options={"SymmetricMode": True})
        return _PermutedLU(lu, self._perm, self._inverse)

    def _same_pattern(self, A) -> bool:
        if self._pattern is None:
            return False
        fmt, shape, indptr, indices = self._pattern
        return (A.format == fmt and A.shape == shape and np.array_equal(A.indptr, indptr)
                and np.array_equal(A.indices, indices))


@lru_cache(maxsize=4)
def _ordering(fmt: str, shape: tuple, leading: int | None, indptr: bytes, indices: bytes,
              index_dtype: str):
    """The ordering of :class:`OrderedLU` for one sparsity pattern (``indptr``, ``indices``
    as bytes): ``(perm, inverse, source, indices, indptr)``, where the permuted matrix's data
    is ``A.data[source]``. Kept for the next call: every muscle of one mesh level has the same
    pattern, and on the fine mesh the ordering costs as much as a factorisation."""
    indptr = np.frombuffer(indptr, dtype=index_dtype)
    indices = np.frombuffer(indices, dtype=index_dtype)
    # A's entries numbered 1..nnz in its own storage order (1-based: no zero is dropped)
    matrix = sp.csr_matrix if fmt == "csr" else sp.csc_matrix
    numbered = matrix((np.arange(1.0, indices.size + 1.0), indices, indptr), shape=shape).tocsc()
    if leading is not None:
        numbered = numbered[:leading, :leading]
    perm = _banded_order(numbered.tocsr())
    numbered = numbered[perm][:, perm].tocsc()
    numbered.sort_indices()
    ordering = (perm, np.argsort(perm), numbered.data.astype(np.intp) - 1, numbered.indices,
                numbered.indptr)
    for array in ordering:  # shared by every OrderedLU of the pattern
        array.flags.writeable = False
    return ordering


#: A row coupled to more than this many times the median row's unknowns is dense (a mesh node
#: couples to its neighbours only: a P2/P1 node's row length varies by less than 2x)
DENSE_ROW_FACTOR = 4.0


def _banded_order(A) -> np.ndarray:
    """Reverse Cuthill-McKee order of the symmetrised pattern of ``A`` with its dense rows last.

    A dense row and column (an unknown coupled to a whole boundary: the sliding sleeve's one
    tension) would put all its neighbours into one level of RCM and widen the band to the
    whole boundary; numbered last, it only adds its own row and column to the factors.
    """
    pattern = (A != 0) + (A != 0).T  # symmetrised
    degree = np.diff(pattern.tocsr().indptr)
    dense = degree > DENSE_ROW_FACTOR * np.median(degree)
    if not dense.any():
        return reverse_cuthill_mckee(pattern.tocsr(), symmetric_mode=True)
    sparse_rows = np.flatnonzero(~dense)
    inner = pattern.tocsr()[sparse_rows][:, sparse_rows]
    return np.concatenate([sparse_rows[reverse_cuthill_mckee(inner, symmetric_mode=True)],
                           np.flatnonzero(dense)])


class _PermutedLU:
    """Solves ``A x = b`` with the LU of ``A[perm][:, perm]``."""

    def __init__(self, lu, perm, inverse):
        self._lu, self._perm, self._inverse = lu, perm, inverse

    def solve(self, b):
        return self._lu.solve(np.asarray(b, dtype=float)[self._perm])[self._inverse]


def _splu(jacobian):
    return splu(jacobian.tocsc())


@dataclass
class Chord:
    """A factorised tangent kept across the Newton iterations and solves of one problem.

    A chord (modified Newton) iteration ``x <- x - J0^-1 r(x)`` with the tangent ``J0`` of an
    earlier state costs one residual and one back-substitution, where a Newton iteration
    assembles and factorises the tangent. It converges linearly: the residual shrinks by a
    rate that grows with the distance from ``J0``'s state. :func:`newton` keeps iterating
    with ``lu`` while that rate is at most ``max_rate`` and otherwise factorises the tangent
    at the current iterate (a Newton step), which becomes ``lu``. At 0.25 ten chord
    iterations (about the cost of one factorisation and assembly) gain six digits.
    """

    max_rate: float = 0.25
    lu: object = None


def newton(fun, x0, *, rtol: float = 1e-9, xtol: float = 1e-9, maxiter: int = 20,
           residual_floor: float = 0.0, check=None,
           factorize=None, accept=None, residual=None,
           chord: Chord | None = None) -> tuple[np.ndarray, NewtonReport]:
    """Solve ``fun(x) = 0`` from ``x0``; ``fun`` returns ``(residual, sparse jacobian)``.

    Converged when the residual fell below ``rtol`` times the first residual (or below
    ``residual_floor``, the size of a residual that is round-off for the caller) and the last
    increment, or the next one estimated with the last factorisation, is below ``xtol`` times
    ``|x|``; a start already below the floor (an exact predictor) is converged after zero
    iterations. ``factorize(jacobian)`` returns an object with ``solve(b)`` (default: SuperLU
    of the jacobian; or an :class:`OrderedLU` kept across the solves of one problem, which may
    read the jacobian as the leading block of a larger matrix). ``accept(x, step)``, the
    caller's own test of an iterate whose residual fell below the first one, given the
    correction still to come as estimated by the factorisation at hand, may call ``x``
    converged earlier (the FE model: when that correction would change the force it reports by
    less than it needs). An early rise of the residual is not called divergence (full Newton
    often overshoots in the first iterations); only non-finite numbers, a state rejected by
    ``check`` or ``maxiter`` iterations stop it.

    With ``residual(x)`` (the residual alone, cheaper than ``fun``) and a :class:`Chord` the
    iterations are chord iterations with ``chord.lu`` (a factorisation left there by an
    earlier solve, or the first one of this) while the residual contracts by at most
    ``chord.max_rate``; the estimated correction to come is then the next chord step over
    ``1 - rate`` (a geometric series).
    """
    factorize = factorize or _splu
    x = np.array(x0, dtype=float)
    chords = residual is not None and chord is not None
    lu = chord.lu if chords else None
    r, jac = (residual(x), None) if lu is not None else fun(x)
    first = norm = float(np.linalg.norm(r))
    if not np.isfinite(first):
        return x, NewtonReport(False, 0, residual=np.inf, reason="non-finite residual")
    if first <= residual_floor:
        return x, NewtonReport(True, 0, residual=0.0)
    tol = max(rtol * first, residual_floor)
    chord_step = None  # the next chord step, solved for the convergence test
    for it in range(1, maxiter + 1):
        if lu is None:  # a Newton step: the tangent at x, factorised
            if jac is None:
                r, jac = fun(x)
            try:
                lu = factorize(jac)
            except RuntimeError:  # SuperLU: "Factor is exactly singular"
                return x, NewtonReport(False, it, reason="singular tangent")
            if chords:
                chord.lu = lu
            chord_step = None
        dx = lu.solve(-r) if chord_step is None else chord_step
        if not np.all(np.isfinite(dx)):
            return x, NewtonReport(False, it, reason="singular tangent")
        x = x + dx
        if check is not None and (reason := check(x)):
            return x, NewtonReport(False, it, reason=reason)
        previous = norm
        r, jac = (residual(x), None) if chords else fun(x)
        if not np.all(np.isfinite(r)):
            return x, NewtonReport(False, it, reason="non-finite residual")
        norm = float(np.linalg.norm(r))
        rel, rate = norm / first, norm / previous
        # the increment that would come next, by the factorisation at hand (a chord step:
        # one back-substitution, no assembly or factorisation), tells whether x has
        # converged; near the solution it equals the Newton step to second order, and the
        # chord iterations' remaining steps sum to it over (1 - rate)
        chord_step = lu.solve(-r)
        step = chord_step / (1.0 - rate) if chords else chord_step
        if chords and rate >= 1.0:
            step = None  # not contracting: no estimate of what is still to come
        if accept is not None and norm < first and step is not None and accept(x, step):
            return x, NewtonReport(True, it, residual=rel)
        if norm <= tol:
            size = xtol * max(np.linalg.norm(x), 1.0)
            if np.linalg.norm(dx) <= size or (step is not None and np.linalg.norm(step) <= size):
                return x, NewtonReport(True, it, residual=rel)
        if not chords or rate > chord.max_rate:
            lu = None  # full Newton, or a chord contracting too slowly: a Newton step next
    return x, NewtonReport(False, maxiter, residual=rel,
                           reason=f"Newton did not converge in {maxiter} iterations")


def load_path(fun, x0, t0: float, targets, *, increments: int = 5, max_cutbacks: int = 6,
              grow: float = 1.5, easy_iterations: int = 4, check=None, residual=None,
              label=lambda t: f"t={t:.4g}", **newton_options):
    """Follow the equilibrium path ``fun(x, t) = 0`` from ``(x0, t0)`` through ``targets``.

    The span from ``t0`` to the last target is first cut into ``increments`` steps (steps also
    stop at every target); a step that fails is halved, one that took at most
    ``easy_iterations`` lets the next grow by ``grow``. A linear (secant) predictor starts each
    step from the last two converged states. After ``max_cutbacks`` halvings on the way to one
    target the target and all later ones are reported not converged; ``label(t)`` names the
    load where it failed in the reason. With ``residual(x, t)`` (the residual alone) the
    steps are solved by chord iterations with one :class:`Chord` (see :func:`newton`): a
    factorised tangent serves the steps after it while it contracts well.

    Returns a list with one ``(x or None, NewtonReport)`` per target, in order; the report of
    the target that failed holds the last two converged ``(load, state)`` (``reached``).
    """
    targets = [float(t) for t in targets]
    span = abs(targets[-1] - t0) if targets else 0.0
    dt = span / increments if span > 0 else 0.0
    x, t = np.array(x0, dtype=float), float(t0)
    x_prev, t_prev = None, None
    chord = Chord() if residual is not None else None
    out = []
    for i, target in enumerate(targets):
        report = NewtonReport(True, residual=0.0)
        while t != target:
            step = np.sign(target - t) * min(dt, abs(target - t))
            t_new = target if abs(target - (t + step)) <= 1e-12 * max(span, 1.0) else t + step
            guess = x if x_prev is None else x + (x - x_prev) * (t_new - t) / (t - t_prev)
            x_new, rep = newton(lambda y, tt=t_new: fun(y, tt), guess,
                                check=None if check is None else lambda y, tt=t_new: check(y, tt),
                                residual=None if residual is None
                                else lambda y, tt=t_new: residual(y, tt),
                                chord=chord, **newton_options)
            report.iterations += rep.iterations
            report.residual = rep.residual
            if rep.converged:
                x_prev, t_prev, x, t = x, t, x_new, t_new
                if rep.iterations <= easy_iterations:
                    dt = min(grow * dt, span)
                continue
            report.cutbacks += 1
            dt = abs(step) / 2.0
            if chord is not None:
                chord.lu = None  # a failed step's factorisation may be from far off the path
            if report.cutbacks > max_cutbacks:
                report.converged = False
                report.reason = f"{rep.reason} at {label(t_new)} after {max_cutbacks} cut-backs"
                report.reached = (((t_prev, x_prev.copy()),) if x_prev is not None
                                  else ()) + ((t, x.copy()),)
                break
        if not report.converged:
            out.append((None, report))
            out.extend((None, NewtonReport(False, reason=f"not reached: {report.reason}"))
                       for _ in targets[i + 1:])
            return out
        out.append((x.copy(), report))
    return out
