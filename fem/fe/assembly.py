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

import copy
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
        # K_e = B_flat X with X = (w H) B^T per point: two products of contiguous operands
        self._B_flat = np.ascontiguousarray(B.transpose(0, 2, 1, 3).reshape(e, i, q * a))
        self._Bt = np.ascontiguousarray(B.transpose(0, 1, 3, 2))
        # G's rows are B^T's (e, q, a) rows, its entries the (variable, dof) pairs B couples
        # anywhere, of the free dofs: a structure of the dof map alone, shared by the muscles
        # of one mesh level (an exact zero of B at some point is stored, and adds nothing)
        support = np.any(self._Bt != 0, axis=(0, 1))
        source, indices, indptr, t_order, t_indices, t_indptr = _operator_pattern(
            q, int(red.max()) + 1, support.tobytes(), support.shape,
            self.dofs.astype(np.int64).tobytes(), self.dofs.shape)
        data = np.take(self._Bt, source)
        self.G = sp.csr_matrix((data, indices, indptr), shape=(e * q * a, t_indptr.size - 1))
        self._GT = sp.csr_matrix((np.take(data, t_order), t_indices, t_indptr),
                                 shape=self.G.shape[::-1])
        keep_r = self.dofs >= 0
        # np.take is faster than a mask
        self._keep_K_flat = np.flatnonzero(keep_r[:, :, None] & keep_r[:, None, :])
        # work arrays of the element matrices, kept: a fresh array of a megabyte per assembly
        # costs its page faults again each time (the allocator returns freed memory to the
        # system), as much as the products themselves
        self._work()

    def _work(self) -> None:
        e, q, a, i = self._Bt.shape
        self._wH = np.empty((e, q, a, a))
        self._X = np.empty((e, q, a, i))
        self._Ke = np.empty((e, i, i))

    def fresh(self) -> Term:
        """This term with work arrays of its own (the operators shared, read only): one per
        muscle, so that muscles of one geometry assembling at once never share them."""
        term = copy.copy(self)
        term._work()
        return term

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
        matrices, ``K_e = sum_q B_q (w_q H_q) B_q^T`` (None where ``hess`` is None): those
        between free dofs, element by element in row-major order (as :class:`Assembler`
        reads them)."""
        if hess is None:
            return self.residual(grad), None
        e, q, a, i = self._Bt.shape
        np.multiply(hess, self.w[..., None, None], out=self._wH)
        np.matmul(self._wH, self._Bt, out=self._X)
        np.matmul(self._B_flat, self._X.reshape(e, q * a, i), out=self._Ke)
        return self.residual(grad), np.take(self._Ke, self._keep_K_flat)


class Assembler:
    """The CSR pattern of a list of terms over ``n`` reduced unknowns, found once per set of
    dof maps (kept for every later list of terms with the same maps: every muscle of a mesh
    level).

    :meth:`matrix` sums the kept element-matrix entries of each term (in the order of ``terms``)
    into that pattern.
    """

    def __init__(self, terms, n: int):
        self.n = n
        self._indices, self._indptr, self._slot = _assembly_pattern(
            n, tuple((t.dofs.astype(np.int64).tobytes(), t.dofs.shape) for t in terms))

    def entries(self) -> tuple[np.ndarray, np.ndarray]:
        """Row and column of every stored entry of :meth:`matrix`, in the order of its data."""
        return np.repeat(np.arange(self.n), np.diff(self._indptr)), self._indices

    def matrix(self, blocks) -> sp.csr_matrix:
        """Sparse matrix from the kept element entries of each term, concatenated in order."""
        data = np.bincount(self._slot, np.concatenate(blocks), minlength=self._indices.size)
        return sp.csr_matrix((data, self._indices, self._indptr), shape=(self.n, self.n))


@lru_cache(maxsize=8)
def _operator_pattern(q: int, n: int, support: bytes, support_shape: tuple, dofs: bytes,
                      dofs_shape: tuple):
    """The structure of a term's global operator ``G`` and of ``G^T``: ``(source, indices,
    indptr)`` of ``G`` (its data is ``B^T.flat[source]``) and ``(order, indices, indptr)`` of
    ``G^T`` (its data is ``G.data[order]``), for the ``(variables, dofs)`` ``support`` of the
    operator and the element dofs ``dofs`` (reduced, -1 where fixed; int64 bytes). Kept for
    the next muscle of the same mesh level; the arrays are read-only."""
    support = np.frombuffer(support, dtype=bool).reshape(support_shape)
    dofs = np.frombuffer(dofs, dtype=np.int64).reshape(dofs_shape)
    e, i = dofs.shape
    mask = np.broadcast_to(support[None, None] & (dofs[:, None, None, :] >= 0),
                           (e, q) + support.shape)
    source = np.flatnonzero(mask)
    indices = np.broadcast_to(dofs[:, None, None, :], mask.shape).reshape(-1)[source]
    indptr = np.concatenate([[0], np.cumsum(mask.sum(axis=-1).reshape(-1))])
    numbered = sp.csr_matrix((np.arange(source.size, dtype=float), indices, indptr),
                             shape=(indptr.size - 1, n))
    transposed = numbered.T.tocsr()
    pattern = (source, indices, indptr, transposed.data.astype(np.intp), transposed.indices,
               transposed.indptr)
    for array in pattern:
        array.flags.writeable = False
    return pattern


def _kept_entries(dofs) -> tuple[np.ndarray, np.ndarray]:
    """Row and column of the element-matrix entries between free dofs (``dofs``: elements x
    dofs, reduced, -1 where fixed), element by element in row-major order."""
    i = dofs.shape[1]
    rows, cols = np.repeat(dofs, i, axis=1).reshape(-1), np.tile(dofs, (1, i)).reshape(-1)
    kept = (rows >= 0) & (cols >= 0)
    return rows[kept], cols[kept]


@lru_cache(maxsize=8)
def _assembly_pattern(n: int, terms: tuple):
    """:func:`_csr_slots` of the kept element-matrix entries of terms given by their element
    dofs (``(int64 bytes, shape)`` each), in order: the pattern depends on the dof maps alone,
    so a muscle of a mesh level already seen finds it by them (a key a thirtieth of the
    entries' size), where finding it costs as much as a few assemblies on the fine mesh."""
    entries = [_kept_entries(np.frombuffer(b, dtype=np.int64).reshape(shape))
               for b, shape in terms]
    rows = np.concatenate([r for r, _ in entries])
    cols = np.concatenate([c for _, c in entries])
    return _csr_slots(n, rows, cols)


def _csr_slots(n: int, rows, cols) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """CSR ``indices`` and ``indptr`` of the entries ``(rows, cols)`` (int64) of an ``n x n``
    matrix, and the slot in its data where each entry lands (duplicates summed); read-only
    (kept by :func:`_assembly_pattern`, shared by every matrix of that pattern).
    """
    pattern = sp.csr_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n))
    pattern.sum_duplicates()  # sorted column indices, one entry per (row, column)
    # where each entry lands in the CSR data: stored entries are sorted by (row, column), so a
    # binary search of the same key finds it
    stored = np.repeat(np.arange(n), np.diff(pattern.indptr)) * n + pattern.indices
    slots = np.searchsorted(stored, rows * n + cols)
    for array in (pattern.indices, pattern.indptr, slots):
        array.flags.writeable = False
    return pattern.indices, pattern.indptr, slots
