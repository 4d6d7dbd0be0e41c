"""Vectorised total-Lagrangian assembly of energy terms, apart from any physics.

An energy ``Pi = sum_terms int psi(y) w`` whose pointwise variables are affine in the unknowns,
``y = y0 + B z`` at every quadrature point, with ``B`` constant (total-Lagrangian: integrals
over the reference configuration). Then the element vectors and matrices of every term are two
batched matrix products of ``B`` with the gradient and Hessian of ``psi`` with respect to ``y``,
and the global sparse pattern is fixed once: each assembly only sums entries into place.

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
        Map full dof -> reduced unknown, ``-1`` where the dof is fixed at zero.
    """

    def __init__(self, B, y0, dofs, w, red):
        self.B, self.y0, self.w = B, y0, w
        self.dofs = red[dofs].T  # (elements, dofs) in reduced numbering, -1 where fixed
        e, q, i, a = B.shape
        self.B_flat = B.transpose(0, 2, 1, 3).reshape(e, i, q * a)
        self.keep_r = self.dofs >= 0
        self.keep_K = self.keep_r[:, :, None] & self.keep_r[:, None, :]
        self._keep_K_flat = np.flatnonzero(self.keep_K)  # np.take is faster than a mask
        # work arrays of the element matrices, kept: a fresh array of a megabyte per assembly
        # costs its page faults again each time (the allocator returns freed memory to the
        # system), as much as the products themselves
        self._BH = np.empty((e, i, q, a))
        self._Ke = np.empty((e, i, i))

    def values(self, y_ext):
        """Variables at the quadrature points; ``y_ext`` ends with a zero read by fixed dofs."""
        e, q, _, a = self.B.shape
        return self.y0 + np.matmul(y_ext[self.dofs][:, None, :], self.B_flat).reshape(e, q, a)

    def element_vectors(self, grad):
        """Element vectors (e, i) of the density gradient ``grad`` (e, q, variables)."""
        e, q, i, a = self.B.shape
        return np.matmul(self.B_flat, (grad * self.w[..., None]).reshape(e, q * a, 1))[..., 0]

    def element_arrays(self, grad, hess):
        """Element vectors (e, i) and the kept entries of the element matrices,
        ``K_e = sum_q B_q (w_q H_q) B_q^T`` (None where ``hess`` is None: the vectors only)."""
        if hess is None:
            return self.element_vectors(grad), None
        e, q, i, a = self.B.shape
        # B (w H) written in (e, i, q, a) order, so that K_e is one product over (q, a)
        np.matmul(self.B, hess * self.w[..., None, None], out=self._BH.transpose(0, 2, 1, 3))
        np.matmul(self._BH.reshape(e, i, q * a), self.B_flat.transpose(0, 2, 1), out=self._Ke)
        return self.element_vectors(grad), np.take(self._Ke, self._keep_K_flat)

    def pattern(self):
        """Row and column of the kept element-matrix entries, in the order of their data."""
        e, i = self.dofs.shape
        rows = np.take(np.repeat(self.dofs, i, axis=1), self._keep_K_flat)
        cols = np.take(np.tile(self.dofs, (1, i)), self._keep_K_flat)
        return rows, cols

    def vector(self, re, n: int) -> np.ndarray:
        """The global vector (length ``n``) of element vectors ``re`` (fixed dofs dropped)."""
        return np.bincount(self.dofs[self.keep_r], re[self.keep_r], minlength=n)


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


@lru_cache(maxsize=4)
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
