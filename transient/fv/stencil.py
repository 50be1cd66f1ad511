"""CSC sparsity pattern of the 5-point finite-volume stencil on a :class:`Grid2D`, with optional dense
trailing unknowns (the "arrow" of a film coupled to a rotor), and index maps into the CSC data array.

Unknowns ``0 .. n-1`` are the cells (flat index ``k = i + nx*j``), ``n .. n+n_extra-1`` the extra
unknowns (e.g. journal position and velocity). The pattern holds

* for every cell row ``k``: columns ``k`` and its west/east/south/north neighbours (periodic wrap
  included; no entry across a Dirichlet or symmetry face);
* dense columns ``n + e`` (every row depends on the extras) and dense rows ``n + e`` (the extras'
  equations depend on every unknown);
* with ``diagonals=True`` also the four corner neighbours of every cell (the 9-point stencil of a face flux
  that depends on the full gradient vector, :mod:`transient.fv.face_gradient`).

The maps give the position of an entry ``(row, col)`` in the CSC ``data`` array (column-major, rows
sorted within a column, the order scikit-sundae and scipy use), so numba kernels can fill ``data``
directly. Built once with numpy; nothing here is called per time step.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from transient.fv.grid import Grid2D

# column order of Stencil.pos
CENTRE, WEST, EAST, SOUTH, NORTH = range(5)


def neighbours(grid: Grid2D) -> np.ndarray:
    """(n, 4) int64: flat index of the west, east, south, north neighbour of each cell, -1 where the face
    is a boundary (Dirichlet or symmetry). West/east = -x/+x, south/north = -z/+z."""
    nx, nz = grid.nx, grid.nz
    k = np.arange(grid.n, dtype=np.int64)
    i, j = k % nx, k // nx
    nb = np.full((grid.n, 4), -1, dtype=np.int64)
    w = np.where(i > 0, k - 1, (k + nx - 1) if grid.x.periodic else -1)
    e = np.where(i < nx - 1, k + 1, (k - nx + 1) if grid.x.periodic else -1)
    s = np.where(j > 0, k - nx, (k + nx * (nz - 1)) if grid.z.periodic else -1)
    n_ = np.where(j < nz - 1, k + nx, (k - nx * (nz - 1)) if grid.z.periodic else -1)
    nb[:, 0], nb[:, 1], nb[:, 2], nb[:, 3] = w, e, s, n_
    return nb


class Stencil:
    """Pattern and position maps.

    Attributes
    ----------
    n_cells, n_extra, n (= n_cells + n_extra), nnz
    pattern : scipy CSC matrix (data = 1.0, sorted indices), shape (n, n)
    indices, indptr : its CSC index arrays (int64)
    nb : (n_cells, 4) neighbour cells (W, E, S, N), -1 at boundary faces
    pos : (n_cells, 5) int64, position in ``data`` of the entries (k, k), (k, W), (k, E), (k, S), (k, N);
        -1 where that neighbour does not exist
    pos_col_extra : (n, n_extra) int64, position of entry (r, n_cells + e) for every row r
    pos_row_extra : (n_extra, n) int64, position of entry (n_cells + e, c) for every column c
    pos_diag : (n,) int64, position of the diagonal entries
    """

    def __init__(self, grid: Grid2D, n_extra: int = 0, diagonals: bool = False):
        if isinstance(n_extra, bool) or int(n_extra) != n_extra or n_extra < 0:
            raise ValueError(f"n_extra must be an integer >= 0, got {n_extra!r}")
        n_extra = int(n_extra)
        self.grid = grid
        self.n_cells = nc = grid.n
        self.n_extra = n_extra
        self.n = N = nc + n_extra
        self.nb = nb = neighbours(grid)
        k = np.arange(nc, dtype=np.int64)
        rows = [k]
        cols = [k]
        for d in range(4):
            ok = nb[:, d] >= 0
            rows.append(k[ok])
            cols.append(nb[ok, d])
        if diagonals:
            for a in (0, 1):  # west, east; then their south and north neighbours
                for b in (2, 3):
                    side = nb[:, a]
                    corner = np.where(side >= 0, nb[np.maximum(side, 0), b], -1)
                    ok = corner >= 0
                    rows.append(k[ok])
                    cols.append(corner[ok])
        if n_extra:
            allr = np.arange(N, dtype=np.int64)
            for e in range(n_extra):
                rows += [allr, np.full(N, nc + e, dtype=np.int64)]
                cols += [np.full(N, nc + e, dtype=np.int64), allr]
        rows = np.concatenate(rows)
        cols = np.concatenate(cols)
        keys = np.sort(cols * N + rows)  # sorted by column, then row: CSC order (np.unique hashes first: 10x slower)
        self._keys = keys = keys[np.concatenate(([True], keys[1:] != keys[:-1]))]
        self.indices = (keys % N).astype(np.int64)
        kcol = keys // N
        self.indptr = np.zeros(N + 1, dtype=np.int64)
        np.cumsum(np.bincount(kcol, minlength=N), out=self.indptr[1:])
        self.nnz = keys.size
        self.pattern = sp.csc_matrix((np.ones(self.nnz), self.indices, self.indptr), shape=(N, N))
        self.pos = np.full((nc, 5), -1, dtype=np.int64)
        self.pos[:, CENTRE] = self.position(k, k)
        for d in range(4):
            ok = nb[:, d] >= 0
            self.pos[ok, d + 1] = self.position(k[ok], nb[ok, d])
        self.pos_diag = self.position(np.arange(N), np.arange(N))
        allr = np.arange(N, dtype=np.int64)
        self.pos_col_extra = np.empty((N, n_extra), dtype=np.int64)
        self.pos_row_extra = np.empty((n_extra, N), dtype=np.int64)
        for e in range(n_extra):
            self.pos_col_extra[:, e] = self.position(allr, np.full(N, nc + e))
            self.pos_row_extra[e, :] = self.position(np.full(N, nc + e), allr)

    def position(self, rows, cols) -> np.ndarray:
        """Positions in the CSC data array of the entries (rows, cols) (vectorised); KeyError if absent."""
        rows = np.asarray(rows, dtype=np.int64)
        cols = np.asarray(cols, dtype=np.int64)
        key = cols * self.n + rows
        p = np.searchsorted(self._keys, key)
        p_clip = np.minimum(p, self.nnz - 1)
        bad = (p >= self.nnz) | (self._keys[p_clip] != key)
        if np.any(bad):
            b = int(np.flatnonzero(np.atleast_1d(bad))[0])
            raise KeyError(f"entry (row {np.atleast_1d(rows)[b]}, col {np.atleast_1d(cols)[b]}) is not in the pattern")
        return p.astype(np.int64)

    def to_matrix(self, data) -> sp.csc_matrix:
        """CSC matrix with the given data array (copied) on this pattern."""
        data = np.asarray(data, dtype=float)
        if data.shape != (self.nnz,):
            raise ValueError(f"data must have shape ({self.nnz},), got {data.shape}")
        return sp.csc_matrix((data.copy(), self.indices.copy(), self.indptr.copy()), shape=(self.n, self.n))


def five_point_mask(stencil: Stencil) -> sp.csc_matrix:
    """Ones on the 5-point pattern of the cells (no extras), e.g. to keep the 5-point part of a 9-point Jacobian
    by ``J.multiply(mask)``."""
    nb, k = stencil.nb, np.arange(stencil.n_cells)
    rows = np.concatenate([k] + [k[nb[:, d] >= 0] for d in range(4)])
    cols = np.concatenate([k] + [nb[nb[:, d] >= 0, d] for d in range(4)])
    return sp.csc_matrix((np.ones(rows.size), (rows, cols)), shape=(stencil.n_cells, stencil.n_cells))
