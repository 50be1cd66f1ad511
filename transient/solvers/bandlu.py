"""Bordered band LU of an "arrow" matrix: a sparse block with a narrow band after reordering, plus a few dense
border rows and columns (a film coupled to a rotor).

With the unknowns split into the ``n`` block unknowns and the ``nb`` border unknowns (the trailing ones)::

    [A  B] [x1]   [r1]        A x1' = r1,   Z = A^-1 B,   S = D - C Z   (nb x nb Schur complement)
    [C  D] [x2] = [r2]   ->   x2 = S^-1 (r2 - C x1'),   x1 = x1' - Z x2

Only the border columns that reach the block (``B``'s nonzero columns) and the border rows that do (``C``'s) enter
``Z`` and ``C Z`` (a rotor on a few bearings: the films see only the coordinates of the bearing nodes, a few of its
many); the rest of ``S`` is ``D``.

``A`` is reordered once per pattern by reverse Cuthill-McKee (``scipy.sparse.csgraph.reverse_cuthill_mckee``)
and factored by LAPACK's band LU with partial pivoting (``dgbtrf`` / ``dgbtrs``), called from numba through
the addresses scipy exports in ``scipy.linalg.cython_lapack`` (an intrinsic that calls a function pointer
passed as an integer, so the kernels stay cacheable). The CSC data of the whole matrix (fixed pattern order)
is scattered into the band, border and corner arrays by a map built once (:class:`BorderedBandLU`).

The block's independent diagonal blocks (the films of a rotor on several bearings: RCM orders each connected
component of the block's graph contiguously) are factored and solved one by one (``segments``): a factorisation
refactors only the segments whose entries (band, border column and border row) changed since the last one, keeps
the others' band LU and their part of ``Z``, and forms ``S`` again. A rotor whose Newton refreshes the Jacobian of
one film (cells of that film crossed the cavitation switch) so pays for that film's band alone.

The kernels :func:`band_factor` and :func:`band_solve` take the :class:`BandLU` tuple, so a compiled Newton
iteration factors and solves without returning to Python.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.sparse as sp
from llvmlite import ir
from numba import njit, types
from numba.extending import get_cython_function_address, intrinsic
from scipy.sparse.csgraph import connected_components, reverse_cuthill_mckee

from transient.solvers.inner_kernel import inner_kernel

_BAND, _BORDER_COL, _BORDER_ROW, _CORNER = range(4)
#: the least size of a segment (independent diagonal blocks of the band, in RCM order): smaller connected components
#: (a film's prescribed groove cells, each a component of its own) join their neighbours
MIN_SEGMENT = 64


_VOIDP = ir.IntType(8).as_pointer()


def _codegen(n_args):
    def codegen(context, builder, signature, args):
        fn = builder.inttoptr(args[0], ir.FunctionType(ir.VoidType(), [_VOIDP] * n_args).as_pointer())
        builder.call(fn, [builder.inttoptr(a, _VOIDP) for a in args[1:]])
        return context.get_dummy_value()

    return codegen


@intrinsic
def _call8(typingctx, address, a1, a2, a3, a4, a5, a6, a7, a8):
    """Call the C function at ``address`` (an integer) with 8 pointer arguments (integers): dgbtrf."""
    return types.void(address, a1, a2, a3, a4, a5, a6, a7, a8), _codegen(8)


@intrinsic
def _call11(typingctx, address, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11):
    """Call the C function at ``address`` with 11 pointer arguments: dgbtrs."""
    return types.void(address, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11), _codegen(11)


class BandLU(NamedTuple):
    """The arrays of a bordered band LU (filled by :func:`band_factor`, used by :func:`band_solve`).

    ``ints`` = (n, n, kl, ku, ldab, info, nrhs=1, nrhs=len(cols), ldb=n) as LAPACK's int32 arguments; ``trans`` =
    b"N"; ``address`` = (dgbtrf, dgbtrs); ``perm[k]`` = original index of band row k; ``cols`` / ``rows``: the border
    columns / rows with entries in the block; ``kind``/``target``: where each CSC data entry goes (band: flat index
    into ``ab``; border column ``cols[e]``: flat index ``e * n + i'`` into ``B``; border row ``rows[e]``: ``e * n +
    j'`` into ``C``; corner: ``e * nb + f`` into ``D``). ``ab`` (n, ldab), ``B`` and ``Z`` (len(cols), n) are stored
    C-ordered, i.e. as LAPACK's column-major (ldab, n) band and (n, len(cols)) right-hand sides. ``segments``: the
    band rows where each independent diagonal block starts, and n; ``segment`` the segment of each CSC data entry
    (-1: the corner); ``held`` the data of the last factorisation (NaN: none); ``dirty`` per segment;
    ``seg_ints`` = (rows of a segment, info), int32 scratch for LAPACK."""

    ints: np.ndarray
    trans: np.ndarray
    address: np.ndarray
    perm: np.ndarray
    cols: np.ndarray
    rows: np.ndarray
    kind: np.ndarray
    target: np.ndarray
    ab: np.ndarray
    ipiv: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    Z: np.ndarray
    S: np.ndarray
    spiv: np.ndarray
    x1: np.ndarray
    x2: np.ndarray
    segments: np.ndarray
    segment: np.ndarray
    held: np.ndarray
    dirty: np.ndarray
    seg_ints: np.ndarray


@inner_kernel
def _small_lu(S, piv):
    """In-place LU with partial pivoting of the small dense ``S`` (row-major); False if singular."""
    m = S.shape[0]
    for k in range(m):
        p = k
        for i in range(k + 1, m):
            if abs(S[i, k]) > abs(S[p, k]):
                p = i
        piv[k] = p
        if S[p, k] == 0.0:
            return False
        if p != k:
            for j in range(m):
                S[k, j], S[p, j] = S[p, j], S[k, j]
        for i in range(k + 1, m):
            S[i, k] /= S[k, k]
            for j in range(k + 1, m):
                S[i, j] -= S[i, k] * S[k, j]
    return True


@inner_kernel
def _small_solve(S, piv, b):
    m = S.shape[0]
    for k in range(m):
        p = piv[k]
        if p != k:
            b[k], b[p] = b[p], b[k]
    for i in range(m):
        for j in range(i):
            b[i] -= S[i, j] * b[j]
    for i in range(m - 1, -1, -1):
        for j in range(i + 1, m):
            b[i] -= S[i, j] * b[j]
        b[i] /= S[i, i]


@inner_kernel
def _gbtrs(lu, b, nrhs_slot, s):
    """b <- A_s^-1 b on segment ``s`` of the factored band (b C-ordered (nrhs, n), its rows of the segment; nrhs in
    ints[nrhs_slot])."""
    ints, si = lu.ints, lu.seg_ints
    a = lu.segments[s]
    si[0] = lu.segments[s + 1] - a
    _call11(lu.address[1], lu.trans.ctypes.data, si[0:].ctypes.data, ints[2:].ctypes.data, ints[3:].ctypes.data,
            ints[nrhs_slot:].ctypes.data, lu.ab.ctypes.data + 8 * a * lu.ab.shape[1], ints[4:].ctypes.data,
            lu.ipiv.ctypes.data + 4 * a, b.ctypes.data + 8 * a, ints[8:].ctypes.data, si[1:].ctypes.data)
    return si[1]


@inner_kernel
def _gbtrf(lu, s):
    """Band LU of segment ``s`` (its rows of ``ab``, pivots in its rows of ``ipiv``); LAPACK's info."""
    ints, si = lu.ints, lu.seg_ints
    a = lu.segments[s]
    si[0] = lu.segments[s + 1] - a
    _call8(lu.address[0], si[0:].ctypes.data, si[0:].ctypes.data, ints[2:].ctypes.data, ints[3:].ctypes.data,
           lu.ab.ctypes.data + 8 * a * lu.ab.shape[1], ints[4:].ctypes.data, lu.ipiv.ctypes.data + 4 * a,
           si[1:].ctypes.data)
    return si[1]


@inner_kernel
def _copy2(src, dst):
    """``dst[:, :] = src`` for two arrays of the same shape."""
    for i in range(src.shape[0]):
        for j in range(src.shape[1]):
            dst[i, j] = src[i, j]


@njit(cache=True)
def band_factor(data, lu):
    """Factor the matrix with CSC ``data`` (pattern order): band LU of A, Z = A^-1 B, LU of S = D - C Z (on the
    border rows and columns that reach the block); of A and Z only the segments whose entries differ from the last
    factorisation's (module docstring). Returns 0, or LAPACK's info > 0 (a zero pivot in A), or -1 (S singular)."""
    ab, B, C, D = lu.ab, lu.B, lu.C, lu.D
    kind, target, segment, held, dirty, segs = lu.kind, lu.target, lu.segment, lu.held, lu.dirty, lu.segments
    m = dirty.size
    for s in range(m):
        dirty[s] = False
    for p in range(data.size):
        if segment[p] >= 0 and not data[p] == held[p]:  # NaN in held (no factorisation): dirty
            dirty[segment[p]] = True
    ldab = ab.shape[1]
    flat = ab.reshape(-1)
    Bf = B.reshape(-1)
    Cf = C.reshape(-1)
    Df = D.reshape(-1)
    n = lu.perm.size
    for s in range(m):
        if dirty[s]:
            for i in range(segs[s] * ldab, segs[s + 1] * ldab):
                flat[i] = 0.0
    for p in range(data.size):
        k = kind[p]
        if k == 3:
            Df[target[p]] = data[p]
        elif dirty[segment[p]]:
            held[p] = data[p]
            if k == 0:
                flat[target[p]] = data[p]
            elif k == 1:
                Bf[target[p]] = data[p]
            else:
                Cf[target[p]] = data[p]
    Z, S = lu.Z, lu.S
    cols, rows = lu.cols, lu.rows
    for s in range(m):
        if dirty[s]:
            info = _gbtrf(lu, s)
            if info != 0:
                for p in range(held.size):
                    held[p] = np.nan
                return info + segs[s] if info > 0 else info
            for b in range(cols.size):
                for i in range(segs[s], segs[s + 1]):
                    Z[b, i] = B[b, i]
            if cols.size > 0:
                _gbtrs(lu, Z, 7, s)
    nb = D.shape[0]
    if nb == 0:
        return 0
    _copy2(D, S)  # element loops: an array assignment compiles numba's shape-mismatch error path (~8 s cold)
    for a in range(rows.size):
        for b in range(cols.size):
            v = S[rows[a], cols[b]]
            for i in range(n):
                v -= C[a, i] * Z[b, i]
            S[rows[a], cols[b]] = v
    return 0 if _small_lu(S, lu.spiv) else -1


@njit(cache=True)
def band_solve(lu, rhs, out):
    """``out = M^-1 rhs`` for the matrix last factored by :func:`band_factor` (``out`` may be ``rhs``)."""
    perm, x1, x2, Z, C = lu.perm, lu.x1, lu.x2, lu.Z, lu.C
    n = perm.size
    nb = x2.size
    for k in range(n):
        x1[k] = rhs[perm[k]]
    for e in range(nb):
        x2[e] = rhs[n + e]
    for s in range(lu.dirty.size):
        _gbtrs(lu, x1, 6, s)
    if nb > 0:
        rows, cols = lu.rows, lu.cols
        for a in range(rows.size):
            s = x2[rows[a]]
            for i in range(n):
                s -= C[a, i] * x1[i]
            x2[rows[a]] = s
        _small_solve(lu.S, lu.spiv, x2)
        for b in range(cols.size):
            v = x2[cols[b]]
            for i in range(n):
                x1[i] -= Z[b, i] * v
    for k in range(n):
        out[perm[k]] = x1[k]
    for e in range(nb):
        out[n + e] = x2[e]


def _segments(block, perm) -> np.ndarray:
    """The band rows where the independent diagonal blocks of ``block`` in the order ``perm`` start, and its size:
    the connected components of its graph, each contiguous in RCM's order, those smaller than ``MIN_SEGMENT`` joined
    to their neighbours (one segment if a component is not contiguous)."""
    n = perm.size
    if n == 0:
        return np.array([0, 0], dtype=np.int64)
    _, label = connected_components(block, directed=True, connection="weak")
    lab = label[perm]
    starts = np.flatnonzero(np.diff(lab)) + 1
    if np.unique(lab).size != starts.size + 1:  # a component in pieces: no independent blocks to keep apart
        return np.array([0, n], dtype=np.int64)
    bounds = [0]
    for b in list(starts) + [n]:
        if b - bounds[-1] >= MIN_SEGMENT:
            bounds.append(int(b))
    if bounds[-1] != n:  # a short tail joins the last segment
        bounds[-1] = n
    return np.array(bounds if len(bounds) > 1 else [0, n], dtype=np.int64)


class BorderedBandLU:
    """Bordered band LU for the CSC ``pattern`` (sorted indices) of an ``N x N`` arrow matrix whose last ``n_border``
    unknowns are dense border rows and columns. Built once per pattern: the reverse Cuthill-McKee order of the
    block (``perm``), its band widths ``kl``, ``ku`` and the scatter map of the CSC data; ``arrays`` is the
    :class:`BandLU` tuple the numba kernels take. ``factor(data)`` / ``solve(rhs)`` call them from Python."""

    def __init__(self, pattern, n_border: int):
        pat = sp.csc_matrix(pattern)
        pat.sort_indices()
        N = pat.shape[0]
        if pat.shape != (N, N) or not 0 <= n_border < N:
            raise ValueError(f"n_border = {n_border} [-] for a {pat.shape} pattern; allowed: 0 <= n_border < {N}")
        n = N - n_border
        block = pat[:n, :n]
        sym = sp.csr_matrix((block + block.T) != 0)
        perm = np.asarray(reverse_cuthill_mckee(sym, symmetric_mode=True), dtype=np.int64)
        inv = np.empty(n, dtype=np.int64)
        inv[perm] = np.arange(n)
        cols = np.repeat(np.arange(N), np.diff(pat.indptr))
        rows = pat.indices.astype(np.int64)
        in_block = (rows < n) & (cols < n)
        ri, ci = inv[rows[in_block]], inv[cols[in_block]]
        kl = int(max(0, np.max(ri - ci))) if ri.size else 0
        ku = int(max(0, np.max(ci - ri))) if ri.size else 0
        ldab = 2 * kl + ku + 1
        kind = np.empty(rows.size, dtype=np.int64)
        target = np.empty(rows.size, dtype=np.int64)
        kind[in_block] = _BAND
        target[in_block] = ci * ldab + (kl + ku + ri - ci)
        bc = (rows < n) & (cols >= n)
        b_cols = np.unique(cols[bc] - n)  # the border columns / rows that reach the block
        kind[bc], target[bc] = _BORDER_COL, np.searchsorted(b_cols, cols[bc] - n) * n + inv[rows[bc]]
        br = (rows >= n) & (cols < n)
        b_rows = np.unique(rows[br] - n)
        kind[br], target[br] = _BORDER_ROW, np.searchsorted(b_rows, rows[br] - n) * n + inv[cols[br]]
        co = (rows >= n) & (cols >= n)
        kind[co], target[co] = _CORNER, (rows[co] - n) * n_border + (cols[co] - n)
        segments = _segments(block, perm)
        band_row = np.where(kind == _BORDER_COL, inv[np.minimum(rows, n - 1)], 0)
        band_row = np.where((kind == _BAND) | (kind == _BORDER_ROW), inv[np.minimum(cols, n - 1)], band_row)
        segment = np.searchsorted(segments, band_row, side="right") - 1
        segment[kind == _CORNER] = -1
        self.n, self.n_border, self.kl, self.ku, self.perm = n, n_border, kl, ku, perm
        address = np.array([get_cython_function_address("scipy.linalg.cython_lapack", name)
                            for name in ("dgbtrf", "dgbtrs")], dtype=np.int64)
        self.arrays = BandLU(
            ints=np.array([n, n, kl, ku, ldab, 0, 1, b_cols.size, n], dtype=np.int32),
            trans=np.frombuffer(b"N", dtype=np.uint8).copy(), address=address, perm=perm,
            cols=b_cols.astype(np.int64), rows=b_rows.astype(np.int64), kind=kind, target=target,
            ab=np.zeros((n, ldab)), ipiv=np.zeros(n, dtype=np.int32),
            B=np.zeros((b_cols.size, n)), C=np.zeros((b_rows.size, n)), D=np.zeros((n_border, n_border)),
            Z=np.zeros((b_cols.size, n)), S=np.zeros((n_border, n_border)),
            spiv=np.zeros(n_border, dtype=np.int64), x1=np.zeros(n), x2=np.zeros(n_border), segments=segments,
            segment=segment.astype(np.int64), held=np.full(rows.size, np.nan),
            dirty=np.zeros(segments.size - 1, dtype=np.bool_), seg_ints=np.zeros(2, dtype=np.int32))
        self.segments = segments

    def factor(self, data) -> int:
        """Factor the matrix with these CSC data; 0 on success (:func:`band_factor`)."""
        return int(band_factor(np.ascontiguousarray(data, dtype=float), self.arrays))

    def solve(self, rhs) -> np.ndarray:
        """The solution for ``rhs`` of the matrix last factored."""
        out = np.empty(self.n + self.n_border)
        band_solve(self.arrays, np.ascontiguousarray(rhs, dtype=float), out)
        return out
