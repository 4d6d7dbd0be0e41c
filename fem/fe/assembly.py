"""Vectorised total-Lagrangian assembly of energy terms, apart from any physics.

An energy ``Pi = sum_terms int psi(y) w`` whose pointwise variables are affine in the unknowns,
``y = y0 + B z`` at every quadrature point, with ``B`` constant (total-Lagrangian: integrals
over the reference configuration). Then the variables at every point and the residual are one
sparse product each with the global form of ``B`` (``y = y0 + G z``, ``r = G^T w dpsi/dy``),
the element matrices two batched matrix products of ``B`` with the Hessian of ``psi`` with
respect to ``y``, and the global sparse pattern is fixed once: each assembly only sums entries
into place.

The physics (which variables, which density) lives in :mod:`mkm.fem.fe.forms` and
:mod:`mkm.fem.fe.model`; this module knows scikit-fem bases, dof maps and sparse matrices only.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import scipy.sparse as sp


def operator(basis, columns) -> np.ndarray:
    """Stack ``columns(value, grad)`` of each basis function: shape (elements, points, dofs, k).

    ``basis`` is a scikit-fem ``Basis`` or ``FacetBasis``; ``columns`` maps one basis function's
    value and gradient at the quadrature points to the ``k`` variables it contributes to.
    """
    return np.stack([np.stack(columns(np.asarray(phi), phi.grad), axis=-1)
                     for phi in (b[0] for b in basis.basis)], axis=2)


class Term:
    """One energy term ``int psi(y) w``: its variables are ``y = y0 + B z`` at quadrature points.

    Parameters
    ----------
    B : numpy.ndarray, shape (elements, points, dofs, variables)
        Constant operator from the element's dofs to the variables (see :func:`operator`).
    y0 : numpy.ndarray, broadcastable to (elements, points, variables)
        The variables at ``z = 0``.
    dofs : numpy.ndarray, shape (dofs, elements)
        Global (full) dof numbers of each element, as scikit-fem's ``element_dofs``.
    w : numpy.ndarray, shape (elements, points)
        Quadrature weights times any measure factor (``2 pi R dx`` in axisymmetry).
    red : numpy.ndarray of int
        Map full dof -> reduced unknown (onto ``0 .. n - 1``), ``-1`` where the dof is fixed
        at zero.

    The variables and the residual go through one global sparse operator ``G`` (rows: the
    variables at every quadrature point; columns: the reduced unknowns; the nonzeros of ``B``
    of the free dofs), so both are one sparse product each, ``y = y0 + G z`` and
    ``r = G^T (w dpsi/dy)``, with no gather, per-element product or scatter.
    """

    def __init__(self, B, y0, dofs, w, red):
        self.w = w
        self.dofs = red[dofs].T  # (elements, dofs) in reduced numbering, -1 where fixed
        e, q, i, a = B.shape
        self.shape = (e, q, a)
        self._y0 = np.broadcast_to(y0, self.shape).reshape(-1).copy()
        n = int(red.max()) + 1
        # K_e = B_flat X with X = (w H) B^T per point: two products of contiguous operands
        self._B_flat = np.ascontiguousarray(B.transpose(0, 2, 1, 3).reshape(e, i, q * a))
        self._Bt = np.ascontiguousarray(B.transpose(0, 1, 3, 2))
        # G row by row straight from B^T's (e, q, a, i) order: no sorting
        nonzero = (self._Bt != 0) & (self.dofs[:, None, None, :] >= 0)
        indptr = np.concatenate([[0], np.cumsum(nonzero.sum(axis=-1).ravel())])
        indices = np.broadcast_to(self.dofs[:, None, None, :], nonzero.shape)[nonzero]
        self.G = sp.csr_matrix((self._Bt[nonzero], indices, indptr), shape=(e * q * a, n))
        self._GT = self.G.T.tocsr()
        keep_r = self.dofs >= 0
        # np.take is faster than a mask
        self._keep_K_flat = np.flatnonzero(keep_r[:, :, None] & keep_r[:, None, :])
        # work arrays of the element matrices, kept: a fresh array of a megabyte per assembly
        # costs its page faults again each time (the allocator returns freed memory to the
        # system), as much as the products themselves
        self._wH = np.empty((e, q, a, a))
        self._X = np.empty((e, q, a, i))
        self._Ke = np.empty((e, i, i))

    def values(self, y):
        """Variables at the quadrature points, shape (elements, points, variables), of the
        reduced unknowns ``y`` (entries past the ``n`` unknowns, if any, are not read)."""
        return (self._y0 + self.G @ y[:self.G.shape[1]]).reshape(self.shape)

    def residual(self, grad) -> np.ndarray:
        """The global vector (length ``n``, fixed dofs dropped) of the density gradient
        ``grad`` (elements, points, variables): ``int dpsi/dy . B phi_i w`` for every unknown."""
        return self._GT @ (grad * self.w[..., None]).reshape(-1)

    def arrays(self, grad, hess):
        """The global vector of ``grad`` (:meth:`residual`) and the kept entries of the element
        matrices, ``K_e = sum_q B_q (w_q H_q) B_q^T`` (None where ``hess`` is None), in the
        order of :meth:`pattern`."""
        if hess is None:
            return self.residual(grad), None
        e, q, a, i = self._Bt.shape
        np.multiply(hess, self.w[..., None, None], out=self._wH)
        np.matmul(self._wH, self._Bt, out=self._X)
        np.matmul(self._B_flat, self._X.reshape(e, q * a, i), out=self._Ke)
        return self.residual(grad), np.take(self._Ke, self._keep_K_flat)

    def pattern(self):
        """Row and column of the kept element-matrix entries, in the order of their data."""
        e, i = self.dofs.shape
        rows = np.take(np.repeat(self.dofs, i, axis=1), self._keep_K_flat)
        cols = np.take(np.tile(self.dofs, (1, i)), self._keep_K_flat)
        return rows, cols


class Assembler:
    """The CSR pattern of a list of terms over ``n`` reduced unknowns, built once.

    :meth:`matrix` sums the kept element-matrix entries of each term (in the order of ``terms``)
    into that pattern.
    """

    def __init__(self, terms, n: int):
        self.n = n
        patterns = [t.pattern() for t in terms]
        rows = np.concatenate([p[0] for p in patterns])
        cols = np.concatenate([p[1] for p in patterns])
        self._indices, self._indptr, self._slot = csr_slots(
            n, rows.astype(np.int64).tobytes(), cols.astype(np.int64).tobytes())

    def entries(self) -> tuple[np.ndarray, np.ndarray]:
        """Row and column of every stored entry of :meth:`matrix`, in the order of its data."""
        return np.repeat(np.arange(self.n), np.diff(self._indptr)), self._indices

    def matrix(self, blocks) -> sp.csr_matrix:
        """Sparse matrix from the kept element entries of each term, concatenated in order."""
        data = np.bincount(self._slot, np.concatenate(blocks), minlength=self._indices.size)
        return sp.csr_matrix((data, self._indices, self._indptr), shape=(self.n, self.n))


@lru_cache(maxsize=8)
def csr_slots(n: int, rows: bytes, cols: bytes) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """CSR ``indices`` and ``indptr`` of the entries ``(rows, cols)`` (int64 bytes) of an
    ``n x n`` matrix, and the slot in its data where each entry lands (duplicates summed).

    Kept for the next call with the same entries: every muscle of one mesh level and boundary
    conditions has the same pattern, and finding it costs as much as a few assemblies on the
    fine mesh. The arrays are read-only, shared by every matrix of that pattern.
    """
    rows, cols = np.frombuffer(rows, dtype=np.int64), np.frombuffer(cols, dtype=np.int64)
    pattern = sp.csr_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n))
    pattern.sum_duplicates()  # sorted column indices, one entry per (row, column)
    # where each entry lands in the CSR data: stored entries are sorted by (row, column), so a
    # binary search of the same key finds it
    stored = np.repeat(np.arange(n), np.diff(pattern.indptr)) * n + pattern.indices
    slots = np.searchsorted(stored, rows * n + cols)
    for array in (pattern.indices, pattern.indptr, slots):
        array.flags.writeable = False
    return pattern.indices, pattern.indptr, slots
