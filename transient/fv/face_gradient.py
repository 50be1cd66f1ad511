"""The full pressure-gradient vector at every face of a :class:`~transient.fv.reynolds.ReynoldsOperator`, for
flow laws that couple the two directions (a shear-thinning bulk: its viscosity depends on the magnitude of
the shear rate, seed 004 eq. 12).

At a face between cells ``L -> R`` along direction ``a`` (0 = x, 1 = z) the normal component is the
two-point difference of the Reynolds operator and the transverse one the mean of the two cells' Green-Gauss
gradients along the other direction ``b``::

    G_n = (P_R - P_L) / d_LR,        G_t = (g_b(L) + g_b(R)) / 2,
    g_b(i) = (P_b+(i) - P_b-(i)) / w_b(i)

with the face value ``P_b+-`` interpolated linearly between the two cells, the prescribed ``P`` on a
Dirichlet face and the cell's own ``P`` on a symmetry face (zero normal gradient). On a uniform grid
``g_b`` is the central difference, so both components are second-order accurate. A Dirichlet face of cell
``i`` has ``G_n`` = the difference to the prescribed value over the half cell and ``G_t = g_b(i)``.

Everything is linear in the cell pressures: face ``f`` has ``G = sum_m (an, at)[f, m] P[cols[f, m]] +
(a0n, a0t)[f]`` over at most :data:`WIDTH` = 6 cells (the face's two cells and their neighbours across
the face direction), so a flux ``F(G)`` has Jacobian entries in the 9-point pattern
(``ReynoldsOperator(..., diagonals=True)``). Built once with numpy; the kernels only read the arrays.
"""

from __future__ import annotations

import numpy as np

WIDTH = 6  # cells per face gradient: L, R and their two neighbours across the face direction


def _cell_gradients(op, direction):
    """Per cell: Green-Gauss gradient along ``direction`` as (cols (n, 3), weights (n, 3), constant (n,)),
    cols -1 where unused; the constant holds the prescribed P of Dirichlet faces."""
    grid = op.grid
    n, nx = grid.n, grid.nx
    k = np.arange(n)
    axis = grid.x if direction == 0 else grid.z
    idx = k % nx if direction == 0 else k // nx
    w = axis.widths[idx]
    lower_nb, upper_nb = op.stencil.nb[:, 2 * direction], op.stencil.nb[:, 2 * direction + 1]
    bvalue = {}
    for b in range(op.bcell.size):
        if op.bdir[b] == direction:
            bvalue[(int(op.bcell[b]), int(op.bside[b]))] = op.bP[b]
    cols = np.full((n, 3), -1, dtype=np.int64)
    wts = np.zeros((n, 3))
    const = np.zeros(n)
    cols[:, 1] = k
    for i in range(n):
        for slot, nbr, sign in ((0, lower_nb[i], -1), (2, upper_nb[i], 1)):
            if nbr >= 0:  # interior face: linear interpolation between the centres
                wn = axis.widths[nbr % nx if direction == 0 else nbr // nx]
                cols[i, slot] = nbr
                wts[i, slot] += sign * w[i] / (w[i] + wn) / w[i]
                wts[i, 1] += sign * wn / (w[i] + wn) / w[i]
            elif (i, sign) in bvalue:  # Dirichlet face: the prescribed value
                const[i] += sign * bvalue[(i, sign)] / w[i]
            else:  # symmetry face: the cell's own value
                wts[i, 1] += sign / w[i]
    return cols, wts, const


def face_gradients(op):
    """Tables of the face gradients of ``op`` (module docstring), interior faces first, then Dirichlet faces::

        cells (nf, 2)  L and R cell of the face (-1 on the boundary side)
        dirn (nf,)     face direction (0 = x, 1 = z);  length (nf,) its length
        cols (nf, 6)   cells of the gradient (-1 unused);  an, at (nf, 6) their coefficients in G_n, G_t
        const (nf, 2)  constant parts of (G_n, G_t) (prescribed boundary pressures)
        pos (nf, 2, 6) CSC positions of (cells[f, r], cols[f, m]) in the operator's pattern (-1: none)

    ``op`` must have the 9-point pattern (``diagonals=True``)."""
    grads = [_cell_gradients(op, 0), _cell_gradients(op, 1)]
    nf_int, nb = op.fL.size, op.bcell.size
    nf = nf_int + nb
    cells = np.full((nf, 2), -1, dtype=np.int64)
    dirn = np.concatenate([op.fdir, op.bdir]).astype(np.int64)
    length = np.concatenate([op.fs, op.bs])
    cols = np.full((nf, WIDTH), -1, dtype=np.int64)
    an = np.zeros((nf, WIDTH))
    at = np.zeros((nf, WIDTH))
    const = np.zeros((nf, 2))

    def add(f, cell, cn, ct):
        row = cols[f]
        hit = np.flatnonzero(row == cell)
        m = int(hit[0]) if hit.size else int(np.flatnonzero(row < 0)[0])
        row[m] = cell
        an[f, m] += cn
        at[f, m] += ct

    for f in range(nf_int):
        L, R, a = int(op.fL[f]), int(op.fR[f]), int(op.fdir[f])
        cells[f] = L, R
        add(f, L, -1.0 / op.fd[f], 0.0)
        add(f, R, 1.0 / op.fd[f], 0.0)
        gc, gw, g0 = grads[1 - a]
        for c in (L, R):
            for m in range(3):
                if gc[c, m] >= 0:
                    add(f, int(gc[c, m]), 0.0, 0.5 * gw[c, m])
            const[f, 1] += 0.5 * g0[c]
    for b in range(nb):
        f = nf_int + b
        i, a, side = int(op.bcell[b]), int(op.bdir[b]), int(op.bside[b])
        cells[f] = (i, -1) if side > 0 else (-1, i)
        add(f, i, -side / op.bd[b], 0.0)
        const[f, 0] = side * op.bP[b] / op.bd[b]
        gc, gw, g0 = grads[1 - a]
        for m in range(3):
            if gc[i, m] >= 0:
                add(f, int(gc[i, m]), 0.0, gw[i, m])
        const[f, 1] = g0[i]
    pos = np.full((nf, 2, WIDTH), -1, dtype=np.int64)
    for r in range(2):
        for m in range(WIDTH):
            ok = (cells[:, r] >= 0) & (cols[:, m] >= 0)
            pos[ok, r, m] = op.stencil.position(cells[ok, r], cols[ok, m])
    return cells, dirn, length, cols, an, at, const, pos
