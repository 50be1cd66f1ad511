"""The full pressure-gradient vector at every face of a :class:`~transient.fv.reynolds.ReynoldsOperator`, for
flow laws that couple the two directions (a shear-thinning bulk: its viscosity depends on the magnitude of
the shear rate, Jang eq. 12).

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


def cell_gradients(op, direction):
    """Per cell: Green-Gauss gradient along ``direction`` as (cols (n, 3), weights (n, 3), constant (n,)): the
    lower neighbour, the cell, the upper neighbour (-1 where there is none); the constant holds the prescribed P
    of Dirichlet faces."""
    grid = op.grid
    n, nx = grid.n, grid.nx
    k = np.arange(n)
    axis = grid.x if direction == 0 else grid.z
    index = (lambda c: c % nx) if direction == 0 else (lambda c: c // nx)
    w = axis.widths[index(k)]
    cols = np.full((n, 3), -1, dtype=np.int64)
    wts = np.zeros((n, 3))
    const = np.zeros(n)
    cols[:, 1] = k
    dirichlet = {sign: np.zeros(n, dtype=bool) for sign in (-1, 1)}
    value = np.zeros(n)
    for sign in (-1, 1):
        sel = (op.bdir == direction) & (op.bside == sign)
        dirichlet[sign][op.bcell[sel]] = True
        value[:] = 0.0
        value[op.bcell[sel]] = op.bP[sel]
        nbr = op.stencil.nb[:, 2 * direction + (sign > 0)]
        inner = nbr >= 0
        wn = np.where(inner, axis.widths[index(np.maximum(nbr, 0))], 0.0)
        slot = 0 if sign < 0 else 2
        cols[inner, slot] = nbr[inner]
        wts[inner, slot] = sign * w[inner] / (w[inner] + wn[inner]) / w[inner]  # linear interpolation
        wts[inner, 1] += sign * wn[inner] / (w[inner] + wn[inner]) / w[inner]
        given = ~inner & dirichlet[sign]  # Dirichlet face: the prescribed value
        const[given] += sign * value[given] / w[given]
        mirror = ~inner & ~dirichlet[sign]  # symmetry face: the cell's own value
        wts[mirror, 1] += sign / w[mirror]
    return cols, wts, const


def cell_gradient_values(op, P):
    """The Green-Gauss gradient of the cell field ``P`` along x and z, shape ``(n_cells, 2)`` (per unit of the grid's
    coordinates; the prescribed boundary values are ``op``'s)."""
    out = np.empty((op.n_cells, 2))
    for d in (0, 1):
        cols, wts, const = cell_gradients(op, d)
        out[:, d] = np.sum(np.where(cols >= 0, wts * P[np.maximum(cols, 0)], 0.0), axis=1) + const
    return out


def face_gradients(op):
    """Tables of the face gradients of ``op`` (module docstring), interior faces first, then Dirichlet faces::

        cells (nf, 2)  L and R cell of the face (-1 on the boundary side)
        dirn (nf,)     face direction (0 = x, 1 = z);  length (nf,) its length
        cols (nf, 6)   cells of the gradient (-1 unused);  an, at (nf, 6) their coefficients in G_n, G_t
        const (nf, 2)  constant parts of (G_n, G_t) (prescribed boundary pressures)
        pos (nf, 2, 6) CSC positions of (cells[f, r], cols[f, m]) in the operator's pattern (-1: none)

    Slots of an interior face: L, R, then L's and R's lower and upper neighbours across the face direction (a
    cell may appear twice on a tiny periodic grid: the kernels add both). ``op`` must have the 9-point pattern
    (``diagonals=True``)."""
    grads = [cell_gradients(op, 0), cell_gradients(op, 1)]
    fL, fR, fdir = op.fL, op.fR, op.fdir
    nf_int, nb = fL.size, op.bcell.size
    nf = nf_int + nb
    cells = np.full((nf, 2), -1, dtype=np.int64)
    dirn = np.concatenate([fdir, op.bdir]).astype(np.int64)
    length = np.concatenate([op.fs, op.bs])
    cols = np.full((nf, WIDTH), -1, dtype=np.int64)
    an = np.zeros((nf, WIDTH))
    at = np.zeros((nf, WIDTH))
    const = np.zeros((nf, 2))
    fi = np.arange(nf_int)
    cells[fi, 0], cells[fi, 1] = fL, fR
    cols[fi, 0], cols[fi, 1] = fL, fR
    an[fi, 0], an[fi, 1] = -1.0 / op.fd, 1.0 / op.fd
    bi = nf_int + np.arange(nb)
    side = op.bside
    cells[bi, 0] = np.where(side > 0, op.bcell, -1)
    cells[bi, 1] = np.where(side > 0, -1, op.bcell)
    cols[bi, 0] = op.bcell
    an[bi, 0] = -side / op.bd
    const[bi, 0] = side * op.bP / op.bd
    for a in (0, 1):  # faces along a take the cells' gradients along the other direction
        gc, gw, g0 = grads[1 - a]
        f = fi[fdir == a]
        for c, half, lo, up in ((fL[f], 0, 2, 3), (fR[f], 1, 4, 5)):
            at[f, half] += 0.5 * gw[c, 1]
            cols[f, lo], at[f, lo] = gc[c, 0], np.where(gc[c, 0] >= 0, 0.5 * gw[c, 0], 0.0)
            cols[f, up], at[f, up] = gc[c, 2], np.where(gc[c, 2] >= 0, 0.5 * gw[c, 2], 0.0)
            const[f, 1] += 0.5 * g0[c]
        sel = op.bdir == a
        f, c = bi[sel], op.bcell[sel]
        at[f, 0] = gw[c, 1]
        cols[f, 2], at[f, 2] = gc[c, 0], np.where(gc[c, 0] >= 0, gw[c, 0], 0.0)
        cols[f, 3], at[f, 3] = gc[c, 2], np.where(gc[c, 2] >= 0, gw[c, 2], 0.0)
        const[f, 1] = g0[c]
    pos = np.full((nf, 2, WIDTH), -1, dtype=np.int64)
    for r in range(2):
        for m in range(WIDTH):
            ok = (cells[:, r] >= 0) & (cols[:, m] >= 0)
            pos[ok, r, m] = op.stencil.position(cells[ok, r], cols[ok, m])
    return cells, dirn, length, cols, an, at, const, pos
