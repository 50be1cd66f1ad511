"""Generalised Reynolds equation: finite-volume residual and analytic Jacobian (numba kernels).

One unknown ``u`` per cell. The model supplies per-cell arrays (all unit-agnostic; the model scales):

* ``P(u), dP/du`` -- pressure (Elrod: ``beta g(theta) (theta - 1)``; incompressible: ``P = u``),
* ``C(u), dC/du`` -- transported content/density (Elrod: ``theta``; incompressible: 1),
* ``kx(u), dkx/du``, ``kz(u), dkz/du`` -- Poiseuille coefficients (e.g. ``phi_x h^3 / (12 mu)``),
* ``cx, cz`` -- Couette flux densities per unit content (e.g. ``U/2 h phi_c``); they multiply ``C``.

Flux density across a face between cells L (lower side) and R (upper side) along x (same along z)::

    F = -k_f (P_R - P_L) / d_LR + G,    k_f = (k_L + k_R) / 2    (arithmetic mean of the two cells)
    G = (cx_L C_L + cx_R C_R) / 2                                  (central), or
    G = cx_f C_L if cx_f >= 0 else cx_f C_R,  cx_f = (cx_L + cx_R) / 2   (content upwind, velocity at the face)

``d_LR`` is the centre-to-centre distance (half a cell to a Dirichlet face). A Dirichlet face has a
virtual neighbour with the prescribed ``P_b, C_b`` and the cell's own ``k, c``; a symmetry face carries
no flux. The residual of a free cell is its net volume outflow::

    R_i = sum over faces of (F . n_out) * face length

so the conservation law reads ``A_i d(C h)_i/dt + R_i = 0`` (the model adds the storage/squeeze term;
the steady solver adds a source). A prescribed cell has ``R_i = u_i - u_fixed_i``; its neighbours use
its ``P, C`` like any other cell (at the solution ``u_i = u_fixed_i``).

Arithmetic-mean faces are second-order accurate on uniform and smoothly stretched grids.

Extra (non-cell) unknowns ``q_e`` (e.g. the journal position) enter through ``k`` and ``c``: give
``dkx/dq_e, dkz/dq_e, dcx/dq_e, dcz/dq_e`` per cell (shape ``(n_extra, n_cells)``) and the Jacobian
kernel fills the dense columns ``dR_i/dq_e``. The dense rows (the rotor equations) are the model's;
:func:`integrate` / :func:`integrate_gradient` give the force integrals and their gradients.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from transient.fv.grid import Grid2D
from transient.fv.stencil import CENTRE, EAST, NORTH, Stencil

SIDES = ("x-", "x+", "z-", "z+")


class Fields(NamedTuple):
    """Per-cell model fields at a state ``u`` (each a float array of length ``n_cells``)."""

    P: np.ndarray
    dP: np.ndarray
    C: np.ndarray
    dC: np.ndarray
    kx: np.ndarray
    dkx: np.ndarray
    kz: np.ndarray
    dkz: np.ndarray
    cx: np.ndarray
    cz: np.ndarray


# --------------------------------------------------------------------------------------------------
# numba kernels (every parameter is an argument; the face lists travel as tuples, see FACE_TUPLES)
# --------------------------------------------------------------------------------------------------

#: What the kernels' tuple arguments hold (built by :class:`ReynoldsOperator`):
#: ``faces = (fL, fR, fdir, fd, fs, fpos)``: interior faces ``f`` between cells ``fL[f] -> fR[f]``, direction
#: ``fdir`` (0 = x, 1 = z), centre distance ``fd``, face length ``fs``, Jacobian positions ``fpos`` of
#: (L, L), (L, R), (R, L), (R, R); ``boundary = (bcell, bside, bdir, bd, bs, bP, bC, bpos)``: Dirichlet faces
#: ``b`` of cell ``bcell``, ``bside`` +1 (face on the cell's upper side) or -1, direction, half-cell distance,
#: length, prescribed ``P, C``, position of (cell, cell); ``cells = (free, u_fixed, pos_c)``;
#: ``face_k = (kf, dkf_L, dkf_R, dkf_q, kb, dkb, dkb_q)``: per-face Poiseuille conductances (the seam of a
#: film whose conductance depends on the face's own pressure gradient, e.g. shear-thinning) with their
#: derivatives by the left / right cell's unknown and by the extras ((n_extra, n_faces)), and the same on
#: the Dirichlet faces; empty arrays (``ReynoldsOperator.no_face_k``) select the arithmetic mean of the cells.
FACE_TUPLES = ("faces", "boundary", "cells", "face_k")


@njit(cache=True)
def residual_kernel(u, P, C, kx, kz, cx, cz, upwind, faces, boundary, cells, face_k, out):
    """``out[i] = R_i`` for the cells ``i < n_cells`` (net volume outflow; ``u_i - u_fixed_i`` if fixed).
    Tuple arguments: :data:`FACE_TUPLES`. Entries ``out[n_cells:]`` are not touched."""
    fL, fR, fdir, fd, fs, fpos = faces
    bcell, bside, bdir, bd, bs, bP, bC, bpos = boundary
    free, u_fixed, pos_c = cells
    kf, dkf_L, dkf_R, dkf_q, kb, dkb, dkb_q = face_k
    per_face = kf.size > 0
    n = free.size
    for i in range(n):
        out[i] = 0.0
    for f in range(fL.size):
        L = fL[f]
        R = fR[f]
        if fdir[f] == 0:
            kL = kx[L]
            kR = kx[R]
            cL = cx[L]
            cR = cx[R]
        else:
            kL = kz[L]
            kR = kz[R]
            cL = cz[L]
            cR = cz[R]
        if upwind:
            cf = 0.5 * (cL + cR)
            G = cf * C[L] if cf >= 0.0 else cf * C[R]
        else:
            G = 0.5 * (cL * C[L] + cR * C[R])
        k_face = kf[f] if per_face else 0.5 * (kL + kR)
        q = (-k_face * (P[R] - P[L]) / fd[f] + G) * fs[f]
        if free[L]:
            out[L] += q
        if free[R]:
            out[R] -= q
    for b in range(bcell.size):
        i = bcell[b]
        if not free[i]:
            continue
        if bdir[b] == 0:
            k = kx[i]
            c = cx[i]
        else:
            k = kz[i]
            c = cz[i]
        if per_face:
            k = kb[b]
        if bside[b] > 0:  # cell = L, boundary = R; outflow = +F
            if upwind:
                G = c * C[i] if c >= 0.0 else c * bC[b]
            else:
                G = 0.5 * c * (C[i] + bC[b])
            out[i] += (-k * (bP[b] - P[i]) / bd[b] + G) * bs[b]
        else:  # boundary = L, cell = R; outflow = -F
            if upwind:
                G = c * bC[b] if c >= 0.0 else c * C[i]
            else:
                G = 0.5 * c * (bC[b] + C[i])
            out[i] -= (-k * (P[i] - bP[b]) / bd[b] + G) * bs[b]
    for i in range(n):
        if not free[i]:
            out[i] = u[i] - u_fixed[i]


@njit(cache=True)
def jacobian_kernel(P, dP, C, dC, kx, dkx, kz, dkz, cx, cz, dkx_dq, dkz_dq, dcx_dq, dcz_dq, upwind,
                    faces, boundary, cells, face_k, pos_col_extra, data):
    """CSC ``data`` of ``dR/du`` (cell rows) and ``dR/dq`` (dense extra columns, cell rows).

    Zeroes the whole ``data`` first (fill the extra rows afterwards). Tuple arguments: :data:`FACE_TUPLES`;
    ``pos_col_extra[r, e]`` = position of (r, n_cells + e). ``d*_dq`` have shape (n_extra, n_cells) (use
    shape (0, n_cells) when there are no extras). Derivatives of the face flux::

        dF/du_L = -dk_f/du_L (P_R - P_L)/d + k_f dP_L/d + dG/du_L,   dG/du_L = cx_L dC_L / 2 (central),
                                                                     cx_f dC_L or 0 (upwind)
        dF/du_R = -dk_f/du_R (P_R - P_L)/d - k_f dP_R/d + dG/du_R
        dF/dq_e = -dk_f/dq_e (P_R - P_L)/d + dG/dq_e

    with ``dk_f/du_L = dk_L / 2`` for the arithmetic mean, or the per-face derivatives of ``face_k``.
    """
    fL, fR, fdir, fd, fs, fpos = faces
    bcell, bside, bdir, bd, bs, bP, bC, bpos = boundary
    free, u_fixed, pos_c = cells
    kf, dkf_L, dkf_R, dkf_q, kb, dkb, dkb_q = face_k
    per_face = kf.size > 0
    n = free.size
    ne = dkx_dq.shape[0]
    for p in range(data.size):
        data[p] = 0.0
    for f in range(fL.size):
        L = fL[f]
        R = fR[f]
        if fdir[f] == 0:
            kL = kx[L]
            kR = kx[R]
            dkL = dkx[L]
            dkR = dkx[R]
            cL = cx[L]
            cR = cx[R]
        else:
            kL = kz[L]
            kR = kz[R]
            dkL = dkz[L]
            dkR = dkz[R]
            cL = cz[L]
            cR = cz[R]
        d = fd[f]
        s = fs[f]
        dPd = (P[R] - P[L]) / d
        if per_face:
            k_face = kf[f]
            dk_L = dkf_L[f]
            dk_R = dkf_R[f]
        else:
            k_face = 0.5 * (kL + kR)
            dk_L = 0.5 * dkL
            dk_R = 0.5 * dkR
        cf = 0.5 * (cL + cR)  # face velocity of the content (upwind scheme)
        up_left = cf >= 0.0
        if upwind:
            if up_left:
                gL = cf * dC[L]
                gR = 0.0
            else:
                gL = 0.0
                gR = cf * dC[R]
        else:
            gL = 0.5 * cL * dC[L]
            gR = 0.5 * cR * dC[R]
        dFL = (-dk_L * dPd + k_face * dP[L] / d + gL) * s
        dFR = (-dk_R * dPd - k_face * dP[R] / d + gR) * s
        fl = free[L]
        fr = free[R]
        if fl:
            data[fpos[f, 0]] += dFL
            data[fpos[f, 1]] += dFR
        if fr:
            data[fpos[f, 2]] -= dFL
            data[fpos[f, 3]] -= dFR
        for e in range(ne):
            if fdir[f] == 0:
                dkq = 0.5 * (dkx_dq[e, L] + dkx_dq[e, R])
                dcL = dcx_dq[e, L]
                dcR = dcx_dq[e, R]
            else:
                dkq = 0.5 * (dkz_dq[e, L] + dkz_dq[e, R])
                dcL = dcz_dq[e, L]
                dcR = dcz_dq[e, R]
            if per_face:
                dkq = dkf_q[e, f]
            if upwind:
                gq = 0.5 * (dcL + dcR) * (C[L] if up_left else C[R])
            else:
                gq = 0.5 * (dcL * C[L] + dcR * C[R])
            dFq = (-dkq * dPd + gq) * s
            if fl:
                data[pos_col_extra[L, e]] += dFq
            if fr:
                data[pos_col_extra[R, e]] -= dFq
    for b in range(bcell.size):
        i = bcell[b]
        if not free[i]:
            continue
        if bdir[b] == 0:
            k = kx[i]
            dk = dkx[i]
            c = cx[i]
        else:
            k = kz[i]
            dk = dkz[i]
            c = cz[i]
        if per_face:
            k = kb[b]
            dk = dkb[b]
        d = bd[b]
        s = bs[b]
        if bside[b] > 0:  # outflow = +F, F = -k (Pb - Pi)/d + G(cell -> boundary)
            dPd = (bP[b] - P[i]) / d
            if upwind:
                g = c * dC[i] if c >= 0.0 else 0.0
            else:
                g = 0.5 * c * dC[i]
            data[bpos[b]] += (-dk * dPd + k * dP[i] / d + g) * s
        else:  # outflow = -F, F = -k (Pi - Pb)/d + G(boundary -> cell)
            dPd = (P[i] - bP[b]) / d
            if upwind:
                g = 0.0 if c >= 0.0 else c * dC[i]
            else:
                g = 0.5 * c * dC[i]
            data[bpos[b]] -= (-dk * dPd - k * dP[i] / d + g) * s
        for e in range(ne):
            if bdir[b] == 0:
                dkq = dkx_dq[e, i]
                dcq = dcx_dq[e, i]
            else:
                dkq = dkz_dq[e, i]
                dcq = dcz_dq[e, i]
            if per_face:
                dkq = dkb_q[e, b]
            if bside[b] > 0:
                if upwind:
                    gq = dcq * (C[i] if c >= 0.0 else bC[b])
                else:
                    gq = 0.5 * dcq * (C[i] + bC[b])
                data[pos_col_extra[i, e]] += (-dkq * dPd + gq) * s
            else:
                if upwind:
                    gq = dcq * (bC[b] if c >= 0.0 else C[i])
                else:
                    gq = 0.5 * dcq * (bC[b] + C[i])
                data[pos_col_extra[i, e]] -= (-dkq * dPd + gq) * s
    for i in range(n):
        if not free[i]:
            data[pos_c[i]] = 1.0


@njit(cache=True)
def integrate(field, weight, area):
    """``sum_i field_i weight_i A_i`` (e.g. a force component ``-sum p cos(theta) dA`` with weight
    ``-cos(theta)``; the model multiplies by its length scales, e.g. R for a theta axis)."""
    s = 0.0
    for i in range(field.size):
        s += field[i] * weight[i] * area[i]
    return s


@njit(cache=True)
def integrate_gradient(dfield, weight, area, out):
    """``out_i = d/du_i sum_j field_j(u_j) weight_j A_j = dfield_i weight_i A_i`` (a dense Jacobian row)."""
    for i in range(dfield.size):
        out[i] = dfield[i] * weight[i] * area[i]


@njit(cache=True)
def scale_rows(data, indices, scale):
    """``data[p] *= scale[indices[p]]`` -- left-multiply the CSC matrix by ``diag(scale)`` (e.g. turn
    ``dR/du`` into the Jacobian of ``du/dt = -R/(A h)``)."""
    for p in range(data.size):
        data[p] *= scale[indices[p]]


# --------------------------------------------------------------------------------------------------
# Python binding
# --------------------------------------------------------------------------------------------------

def _as_float(x, n, name):
    a = np.asarray(x, dtype=float)
    if a.ndim == 0:
        return np.full(n, float(a))
    if a.shape != (n,):
        raise ValueError(f"{name} must be a scalar or of shape ({n},), got {a.shape}")
    return np.ascontiguousarray(a)


class ReynoldsOperator:
    """Binds a :class:`Grid2D`, its :class:`Stencil` (with ``n_extra`` dense trailing unknowns) and the
    face lists the kernels need.

    Parameters
    ----------
    grid : the grid (its fixed cells are taken at construction).
    n_extra : number of dense trailing unknowns (rotor coupling).
    upwind : Couette face value by upwinding (True; needed for Elrod's cavitated zone) or central.
    boundary_P, boundary_C : default prescribed P and C on every Dirichlet face (change per side with
        :meth:`set_boundary`).
    diagonals : add the corner neighbours to the pattern (:class:`~transient.fv.stencil.Stencil`).

    Attributes: ``grid, stencil, pattern, n (= cells + extras), n_cells, n_extra, nnz, upwind`` and the
    kernel arrays ``fL, fR, fdir, fd, fs, fpos`` (interior faces), ``bcell, bside, bdir, bd, bs, bP, bC,
    bpos`` (Dirichlet faces), ``free, u_fixed, pos_c, pos_col_extra``, bundled as the kernels take them in
    :attr:`faces`, :attr:`boundary`, :attr:`cells` and :attr:`no_face_k` (:data:`FACE_TUPLES`). Models that
    call the kernels from their own numba code pass :attr:`face_tuples` after the field arrays.
    """

    def __init__(self, grid: Grid2D, n_extra: int = 0, upwind: bool = False, boundary_P=0.0, boundary_C=1.0,
                 diagonals: bool = False):
        self.grid = grid
        self.stencil = st = Stencil(grid, n_extra, diagonals)
        self.pattern = st.pattern
        self.n, self.n_cells, self.n_extra, self.nnz = st.n, st.n_cells, st.n_extra, st.nnz
        self.upwind = bool(upwind)
        nx = grid.nx
        k = np.arange(grid.n, dtype=np.int64)
        i, j = k % nx, k // nx
        dx_lo, dx_up = grid.x.d_lower[i], grid.x.d_upper[i]
        dz_lo, dz_up = grid.z.d_lower[j], grid.z.d_upper[j]
        wx, wz = grid.x.widths[i], grid.z.widths[j]
        # interior faces: each cell's east and north face when the neighbour exists
        fl, fr, fdir, fd, fs = [], [], [], [], []
        for d, (col, dist, length) in enumerate(((EAST, dx_up, wz), (NORTH, dz_up, wx))):
            ok = st.nb[:, col - 1] >= 0
            fl.append(k[ok])
            fr.append(st.nb[ok, col - 1])
            fdir.append(np.full(int(ok.sum()), d, dtype=np.int64))
            fd.append(dist[ok])
            fs.append(length[ok])
        self.fL = np.concatenate(fl).astype(np.int64)
        self.fR = np.concatenate(fr).astype(np.int64)
        self.fdir = np.concatenate(fdir)
        self.fd = np.concatenate(fd)
        self.fs = np.concatenate(fs)
        self.fpos = np.stack([st.position(self.fL, self.fL), st.position(self.fL, self.fR),
                              st.position(self.fR, self.fL), st.position(self.fR, self.fR)], axis=1)
        # Dirichlet faces, grouped by side
        bc, bsd, bdr, bdd, bss, self._side_slices = [], [], [], [], [], {}
        start = 0
        for side, axis, first, sign, d_arr, length, direction in (
                ("x-", grid.x, i == 0, -1, dx_lo, wz, 0), ("x+", grid.x, i == nx - 1, 1, dx_up, wz, 0),
                ("z-", grid.z, j == 0, -1, dz_lo, wx, 1), ("z+", grid.z, j == grid.nz - 1, 1, dz_up, wx, 1)):
            kind = axis.lower if sign < 0 else axis.upper
            cells = k[first] if kind == "dirichlet" else k[:0]
            bc.append(cells)
            bsd.append(np.full(cells.size, sign, dtype=np.int64))
            bdr.append(np.full(cells.size, direction, dtype=np.int64))
            bdd.append(d_arr[cells])
            bss.append(length[cells])
            self._side_slices[side] = slice(start, start + cells.size)
            start += cells.size
        self.bcell = np.concatenate(bc).astype(np.int64)
        self.bside = np.concatenate(bsd)
        self.bdir = np.concatenate(bdr)
        self.bd = np.concatenate(bdd)
        self.bs = np.concatenate(bss)
        self.bP = np.zeros(self.bcell.size)
        self.bC = np.zeros(self.bcell.size)
        self.bpos = st.position(self.bcell, self.bcell)
        self.free = np.ascontiguousarray(grid.free.copy())
        self.u_fixed = np.ascontiguousarray(grid.fixed_values.copy())
        self.pos_c = np.ascontiguousarray(st.pos[:, CENTRE])
        self.pos_col_extra = np.ascontiguousarray(st.pos_col_extra)
        self._no_dq = np.zeros((0, self.n_cells))
        e1, e2 = np.zeros(0), np.zeros((n_extra, 0))
        self.no_face_k = (e1, e1, e1, e2, e1, e1, e2)
        for side in SIDES:
            self.set_boundary(side, boundary_P, boundary_C)

    def boundary_cells(self, side: str) -> np.ndarray:
        """Cells adjacent to the Dirichlet faces of ``side`` (``"x-"``, ``"x+"``, ``"z-"``, ``"z+"``)."""
        if side not in SIDES:
            raise ValueError(f"side must be one of {SIDES}, got {side!r}")
        return self.bcell[self._side_slices[side]]

    def set_boundary(self, side: str, P=None, C=None):
        """Prescribed ``P`` and/or ``C`` (scalar or one value per boundary cell, in the order of
        :meth:`boundary_cells`) on the Dirichlet faces of ``side``. No-op on a non-Dirichlet side."""
        if side not in SIDES:
            raise ValueError(f"side must be one of {SIDES}, got {side!r}")
        sl = self._side_slices[side]
        m = sl.stop - sl.start
        if P is not None:
            self.bP[sl] = _as_float(P, m, f"boundary P on side {side}")
        if C is not None:
            self.bC[sl] = _as_float(C, m, f"boundary C on side {side}")

    @property
    def faces(self):
        """Interior-face tuple of the kernels (:data:`FACE_TUPLES`)."""
        return (self.fL, self.fR, self.fdir, self.fd, self.fs, self.fpos)

    @property
    def boundary(self):
        """Dirichlet-face tuple of the kernels (:data:`FACE_TUPLES`); ``bP, bC`` are the arrays themselves, so
        :meth:`set_boundary` after taking it still counts."""
        return (self.bcell, self.bside, self.bdir, self.bd, self.bs, self.bP, self.bC, self.bpos)

    @property
    def cells(self):
        """Cell tuple of the kernels (:data:`FACE_TUPLES`)."""
        return (self.free, self.u_fixed, self.pos_c)

    @property
    def face_tuples(self):
        """``(faces, boundary, cells)``: what every kernel takes after the field arrays."""
        return (self.faces, self.boundary, self.cells)

    def residual(self, u, P, C, kx, kz, cx, cz, out=None, face_k=None) -> np.ndarray:
        """``R`` (length ``n_cells``, or written into ``out[:n_cells]``). See the module docstring;
        ``face_k``: per-face conductances (:data:`FACE_TUPLES`) instead of the cells' arithmetic mean."""
        if out is None:
            out = np.empty(self.n_cells)
        residual_kernel(u, P, C, kx, kz, cx, cz, self.upwind, *self.face_tuples,
                        self.no_face_k if face_k is None else face_k, out)
        return out

    def jacobian(self, *fields, dq=None, data=None, face_k=None) -> np.ndarray:
        """CSC data (pattern order) of ``dR/du`` for the ten per-cell fields ``P, dP, C, dC, kx, dkx, kz, dkz, cx,
        cz`` (in the order of :class:`Fields`) and, if ``dq = (dkx_dq, dkz_dq, dcx_dq, dcz_dq)`` (each
        (n_extra, n_cells)) is given, the dense columns ``dR/dq``. Extra rows are left zero. ``face_k``: per-face
        conductances (:data:`FACE_TUPLES`) instead of the cells' arithmetic mean."""
        if len(fields) != len(Fields._fields):
            raise TypeError(f"ReynoldsOperator.jacobian takes the {len(Fields._fields)} fields "
                            f"{', '.join(Fields._fields)}; got {len(fields)}")
        P, dP, C, dC, kx, dkx, kz, dkz, cx, cz = fields
        if data is None:
            data = np.empty(self.nnz)
        if dq is None:
            dq = (self._no_dq,) * 4
        elif self.n_extra == 0:
            raise ValueError("dq given but the operator has n_extra=0")
        jacobian_kernel(P, dP, C, dC, kx, dkx, kz, dkz, cx, cz, *dq, self.upwind, *self.face_tuples,
                        self.no_face_k if face_k is None else face_k, self.pos_col_extra, data)
        return data

    def residual_of(self, u, f: Fields, out=None) -> np.ndarray:
        """:meth:`residual` with the fields bundled in a :class:`Fields`."""
        return self.residual(u, f.P, f.C, f.kx, f.kz, f.cx, f.cz, out)

    def jacobian_of(self, f: Fields, dq=None, data=None) -> np.ndarray:
        """:meth:`jacobian` with the fields bundled in a :class:`Fields`."""
        return self.jacobian(f.P, f.dP, f.C, f.dC, f.kx, f.dkx, f.kz, f.dkz, f.cx, f.cz, dq=dq, data=data)

    def matrix(self, data):
        """CSC matrix on the operator's pattern with this data."""
        return self.stencil.to_matrix(data)
