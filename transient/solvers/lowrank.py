"""A factored sparse matrix with a few of its columns replaced exactly (Woodbury), for a Newton whose Jacobian
changes in a few columns only (cells of a film crossing the cavitation switch).

With ``M`` factored (:class:`~transient.solvers.bandlu.BorderedBandLU`) and the columns ``c_1 .. c_k`` of ``M``
replaced by new ones, ``M' = M + U V^T`` with ``U = [new - old columns]`` and ``V = [e_c1 .. e_ck]``, and
(Woodbury; Golub & Van Loan, Matrix Computations, 2.1.4)::

    M'^-1 r = y - W (I + V^T W)^-1 V^T y,   y = M^-1 r,   W = M^-1 U

``W`` costs one solve per replaced column, the k x k capacitance ``I + V^T W`` (entries of ``W`` at the
replaced columns' rows) one small LU; every later solve one solve of ``M`` plus O(k N). Which columns to
replace is measured on the Jacobian data (CSC, fixed pattern): those that moved by more than a fraction of their
largest entry since the matrix that is in effect (:func:`column_update`); columns replaced earlier stay replaced
(with their newest values) until the next factorisation (:func:`reset`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from transient.solvers.bandlu import BandLU, BorderedBandLU, _small_lu, _small_solve, band_solve


class UpdatedLU(NamedTuple):
    """A :class:`~transient.solvers.bandlu.BandLU` factorisation and its column update. ``indptr``, ``indices`` (CSC pattern);
    ``data_fact``: the data factored; ``data_eff``: the data in effect (``data_fact`` with the replaced columns'
    newest values); ``cols[:k[0]]``: the replaced columns; ``W`` (kmax, N): ``M^-1 U``; ``cap``/``cpiv``: the LU
    of the capacitance matrix; ``work`` (N): a right-hand side; ``moved`` (N, bool) and ``scratch`` (nnz): scratch."""

    band: BandLU
    indptr: np.ndarray
    indices: np.ndarray
    data_fact: np.ndarray
    data_eff: np.ndarray
    cols: np.ndarray
    k: np.ndarray
    W: np.ndarray
    cap: np.ndarray
    cpiv: np.ndarray
    work: np.ndarray
    moved: np.ndarray
    scratch: np.ndarray


def updated_lu(band: BorderedBandLU, pattern, kmax: int) -> UpdatedLU:
    """The :class:`UpdatedLU` arrays for the factorisation ``band`` of the CSC ``pattern`` (sorted indices, as
    the one ``band`` was built on), at most ``kmax`` replaced columns."""
    N = pattern.shape[0]
    return UpdatedLU(band=band.arrays, indptr=np.asarray(pattern.indptr, dtype=np.int64),
                     indices=np.asarray(pattern.indices, dtype=np.int64),
                     data_fact=np.zeros(pattern.nnz), data_eff=np.zeros(pattern.nnz),
                     cols=np.zeros(max(kmax, 1), dtype=np.int64), k=np.zeros(1, dtype=np.int64),
                     W=np.zeros((max(kmax, 1), N)), cap=np.zeros((max(kmax, 1), max(kmax, 1))),
                     cpiv=np.zeros(max(kmax, 1), dtype=np.int64), work=np.zeros(N), moved=np.zeros(N, np.bool_), scratch=np.zeros(pattern.nnz))


@njit(cache=True)
def reset(ulu, data):
    """``data`` was just factored: no replaced columns."""
    ulu.data_fact[:] = data
    ulu.data_eff[:] = data
    ulu.k[0] = 0


@njit(cache=True)
def lu_solve(ulu, rhs, out):
    """``out = M'^-1 rhs`` (``out`` may be ``rhs``): the band solve, then the Woodbury correction."""
    band_solve(ulu.band, rhs, out)
    k = ulu.k[0]
    if k == 0:
        return
    W, cols, s = ulu.W, ulu.cols, ulu.work
    for a in range(k):
        s[a] = out[cols[a]]
    _small_solve(ulu.cap[:k, :k], ulu.cpiv[:k], s[:k])
    for a in range(k):
        v = s[a]
        if v != 0.0:
            for i in range(out.size):
                out[i] -= W[a, i] * v


@njit(cache=True)
def column_update(ulu, data, tau):
    """Replace the columns of the matrix in effect whose entries in ``data`` (a new Jacobian, same pattern) moved
    by more than ``tau`` times the column's largest entry, keeping those replaced before. Returns the number of
    replaced columns, 0 if none moved, or -1 if more than ``kmax`` would be replaced or the capacitance matrix is
    singular (then the caller factors ``data`` afresh)."""
    indptr, eff, fact, moved = ulu.indptr, ulu.data_eff, ulu.data_fact, ulu.moved
    N = indptr.size - 1
    kmax = ulu.cols.size
    moved[:] = False
    for a in range(ulu.k[0]):
        moved[ulu.cols[a]] = True
    sel = np.empty(kmax, dtype=np.int64)
    k = 0
    new = 0
    for c in range(N):
        if not moved[c]:
            big = 0.0
            d = 0.0
            for p in range(indptr[c], indptr[c + 1]):
                big = max(big, abs(eff[p]), abs(data[p]))
                d = max(d, abs(data[p] - eff[p]))
            if d > tau * big:
                moved[c] = True
                new += 1
        if moved[c]:
            if k == kmax:
                return -1
            sel[k] = c
            k += 1
    if new == 0:
        return 0
    ulu.cols[:k] = sel[:k]
    W, rhs = ulu.W, ulu.work
    for a in range(k):
        c = ulu.cols[a]
        rhs[:] = 0.0
        for p in range(indptr[c], indptr[c + 1]):
            eff[p] = data[p]
            rhs[ulu.indices[p]] = data[p] - fact[p]
        band_solve(ulu.band, rhs, W[a])
    cap = ulu.cap
    for a in range(k):
        for b in range(k):
            cap[a, b] = (1.0 if a == b else 0.0) + W[b, ulu.cols[a]]
    if not _small_lu(cap[:k, :k], ulu.cpiv[:k]):
        ulu.k[0] = 0
        return -1
    ulu.k[0] = k
    return k

