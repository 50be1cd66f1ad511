"""The Poiseuille flux of a shear-thinning (Gecim) bulk in the journal film (Jang).

In the journal's scales (``p0 = 6 mu_1 omega (R/C)^2``, ``H = h/C``, lengths ``/R``, flux ``/(C omega R)``)
the flux across a face is the classical film's content-upwinded Couette part plus the pressure part of the
layered Gecim flow law (:func:`transient.physics.layered.gecim_face_2d`, reference length ``C``, speed
``omega R``; the journal is the lower wall, moving at 1 along ``phi``, the bearing is at rest)::

    F = theta_up H_f / 2 e_phi . n  +  q_p(H_f, 6 grad P) . n,        H_f = (H_L + H_R) / 2

(``6 grad P`` is the pressure gradient in the law's units, ``mu_1 omega R / C^2``). The law couples the two
directions through the magnitude of the shear rate, so every face needs the full gradient vector
(:mod:`transient.fv.face_gradient`: the normal two-point difference and the mean of the two cells'
transverse gradients) and its Jacobian row has up to six cells (the 9-point pattern). The derivatives are
the law's exact ``dq_p/dG`` (2 x 2) and ``dq_p/dh``; no lagged viscosity.

In the cavitated zone ``grad P = 0`` and ``q_p = 0``: only the Couette part moves content there, as for the
Newtonian film (docs/layered.md, section 3), so the film stays mass-conserving.

The kernels evaluate the faces serially when they need them; the Python callers (the films' residual and Jacobian
methods, the orbit's callbacks) first :func:`prefetch` them on all cores at the same state.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit, prange

from transient.fv.face_gradient import WIDTH, face_gradients
from transient.physics.layered import GAUSS_POINTS, NO_LAYERS, Gecim, LayeredFilm, gecim_face_2d

GRAD_SCALE = 6.0  # p0 / R in units of mu_1 omega R / C^2: the law's G = 6 grad P


def face_accuracy(ratio):
    """Gauss points per quadrature panel and the continuity Newton's stop of the face law for the viscosity ratio
    mu_2/mu_1: (6, 1e-4) from 0.2 up, else (8, 1e-5); the law is smoother for larger ratios. Against 20 points and a
    1e-7 stop on the 19280 faces of Jang's case (241 x 40, kappa* 0.65, r 0.57), (6, 1e-4) gives the flow to
    2.6e-10 of the Couette flow, dq/dG to 2.2e-8 and dq/dh to 1.1e-9 (the stop adds nothing: 1.97 -> 1.64 us per
    face); over 4000 random states (|G| H up to 1e2 kappa) the worst dq/dG is 7.4e-8 at r = 0.2 and, with (8, 1e-5),
    4.6e-8 at r = 0.05 (a 1e-4 stop would give 2.7e-7 there)."""
    return (6, 1e-4) if ratio >= 0.2 else (8, 1e-5)


class BulkFaces(NamedTuple):
    """What the kernels know of a Gecim bulk (numba takes it as a named tuple of arrays)."""

    cells: np.ndarray    # (nf, 2) L and R cell of every face (-1 on the boundary side): fv.face_gradient
    dirn: np.ndarray     # (nf,) face direction
    length: np.ndarray   # (nf,) face length
    cols: np.ndarray     # (nf, 6) cells of the face gradient
    an: np.ndarray       # (nf, 6) their coefficients in the normal gradient
    at: np.ndarray       # (nf, 6) ... and in the transverse gradient
    const: np.ndarray    # (nf, 2) constant parts of both
    pos: np.ndarray      # (nf, 2, 6) CSC positions of (face cell, gradient cell)
    params: np.ndarray   # (delta, lam_a, lam_b, kappa, ratio, Newton stop): the law at this speed
    xg: np.ndarray       # Gauss nodes per panel
    wg: np.ndarray       # Gauss weights
    out: np.ndarray      # (nf, 4) scratch: q_p . n, dq/dG_n, dq/dG_t, dq/dh of every face
    last_P: np.ndarray   # (n_cells,) the cell pressure ...
    last_H: np.ndarray   # ... and film of the last evaluation (:func:`evaluate` skips a repeat)


def flow_law(viscosity, rheology, layers) -> LayeredFilm:
    """The film's flow law (:class:`~transient.physics.layered.LayeredFilm`) with the quadrature the kernels use: a
    Gecim bulk's :func:`face_accuracy` Gauss points per panel, the law's default otherwise. A bearing builds it once;
    the film's faces (:func:`bulk_tables`) and its wall friction both use it."""
    shear_thinning = isinstance(rheology, Gecim)
    points = face_accuracy(rheology.viscosity_ratio)[0] if shear_thinning else GAUSS_POINTS
    return LayeredFilm(viscosity, rheology, layers or NO_LAYERS, gauss_points=points)


def bulk_tables(op, law: LayeredFilm, clearance, sliding_speed) -> BulkFaces:
    """The :class:`BulkFaces` of the Gecim bulk ``law`` (:func:`flow_law`) on ``op`` (9-point pattern), with the
    reference length ``clearance`` [m] and speed ``sliding_speed`` [m/s] (``omega R``): the face-gradient tables,
    the law's dimensionless parameters and Newton stop (:func:`face_accuracy`), the Gauss rule and the scratch
    arrays."""
    tol = face_accuracy(law.rheology.viscosity_ratio)[1]
    params = np.array(law._parameters(clearance, sliding_speed) + (tol,))
    xg, wg = law._gauss()
    tables = face_gradients(op)
    nf, n = tables[0].shape[0], op.n_cells
    return BulkFaces(*tables, params, xg, wg, np.zeros((nf, 4)), np.full(n, np.nan), np.full(n, np.nan))


def no_bulk() -> BulkFaces:
    """Empty :class:`BulkFaces` of the same types (Newtonian bulk: the kernels skip the Gecim flux)."""
    i1, i2, i3 = np.zeros(0, np.int64), np.zeros((0, 2), np.int64), np.zeros((0, 2, WIDTH), np.int64)
    f1, f2, f6 = np.zeros(0), np.zeros((0, 2)), np.zeros((0, WIDTH))
    return BulkFaces(i2, i1, f1, np.zeros((0, WIDTH), np.int64), f6, f6.copy(), f2, i3, np.zeros(6), f1, f1.copy(),
                     np.zeros((0, 4)), f1.copy(), f1.copy())


@njit(cache=True)
def _same(a, b):
    for i in range(a.size):
        if a[i] != b[i]:
            return False
    return True


@njit(cache=True)
def is_current(P, H, bulk):
    """Whether ``bulk``'s face values are those of ``(P, H)``."""
    return _same(P, bulk.last_P) and _same(H, bulk.last_H)


@njit(cache=True)
def remember(P, H, bulk):
    """Mark ``bulk``'s face values as those of ``(P, H)``."""
    last_P, last_H = bulk.last_P, bulk.last_H
    for i in range(P.size):
        last_P[i] = P[i]
        last_H[i] = H[i]


@njit(cache=True)
def evaluate(P, H, bulk):
    """The face values at ``(P, H)`` unless they are those of the last evaluation (a residual and a Jacobian at the
    same state, or a :func:`prefetch`)."""
    if is_current(P, H, bulk):
        return
    for f in range(bulk.cells.shape[0]):
        _face(f, P, H, bulk)
    remember(P, H, bulk)


@njit(cache=True, parallel=True)
def _faces_parallel(P, H, bulk):
    for f in prange(bulk.cells.shape[0]):
        _face(f, P, H, bulk)


def prefetch(P, H, bulk):
    """:func:`evaluate` on all cores, called from Python: the kernels that follow at the same ``(P, H)`` find the
    face values ready. (A ``prange`` loop inside the cached kernels themselves segfaults when they load from
    numba's cache: numba issues #8578 and #10184, a parallel function nested in a cached non-parallel one.)"""
    if not is_current(P, H, bulk):
        _faces_parallel(P, H, bulk)
        remember(P, H, bulk)


@njit(cache=True)
def _face(f, P, H, bulk):
    """``(q_p . n, dq/dG_n, dq/dG_t, dq/dh)`` of face ``f`` (journal units) into ``bulk``'s scratch. A pure function
    of ``(P, H)``: the face's continuity Newton always starts from the same closed-form guess."""
    cells, dirn, cols, an, at, const, params, xg, wg, out = (bulk.cells, bulk.dirn, bulk.cols, bulk.an, bulk.at,
                                                             bulk.const, bulk.params, bulk.xg, bulk.wg, bulk.out)
    delta, lam_a, lam_b, kappa, ratio, tol = params[0], params[1], params[2], params[3], params[4], params[5]
    gn = const[f, 0]
    gt = const[f, 1]
    for m in range(WIDTH):
        c = cols[f, m]
        if c >= 0:
            gn += an[f, m] * P[c]
            gt += at[f, m] * P[c]
    L = cells[f, 0]
    R = cells[f, 1]
    h = 0.5 * (H[L] + H[R]) if (L >= 0 and R >= 0) else H[L if L >= 0 else R]
    if dirn[f] == 0:
        o = gecim_face_2d(h, GRAD_SCALE * gn, GRAD_SCALE * gt, 1.0, 0.0, 0.0, 0.0, delta, lam_a, lam_b,
                          kappa, ratio, xg, wg, tol)
        out[f, 0], out[f, 1], out[f, 2], out[f, 3] = o[0], GRAD_SCALE * o[2], GRAD_SCALE * o[3], o[6]
    else:
        o = gecim_face_2d(h, GRAD_SCALE * gt, GRAD_SCALE * gn, 1.0, 0.0, 0.0, 0.0, delta, lam_a, lam_b,
                          kappa, ratio, xg, wg, tol)
        out[f, 0], out[f, 1], out[f, 2], out[f, 3] = o[1], GRAD_SCALE * o[5], GRAD_SCALE * o[4], o[7]


@njit(cache=True)
def bulk_residual(P, H, free, bulk, R):
    """Add the Gecim pressure flux of every face to the net outflow ``R`` of its free cells."""
    cells, length, out = bulk.cells, bulk.length, bulk.out
    evaluate(P, H, bulk)
    for f in range(cells.shape[0]):
        q = out[f, 0] * length[f]
        L = cells[f, 0]
        R_ = cells[f, 1]
        if L >= 0 and free[L]:
            R[L] += q
        if R_ >= 0 and free[R_]:
            R[R_] -= q


@njit(cache=True)
def bulk_jacobian(P, dP, H, cosp, sinp, free, bulk, pos_col, n_extra, data):
    """Add the Gecim flux's derivatives to the CSC ``data``: ``dR/du`` over the face's gradient cells (``dP``
    = dP/du per cell) and, with ``n_extra >= 2``, ``dR/dX, dR/dY`` through ``H_f`` (``pos_col`` the positions
    of the extra columns)."""
    cells, length, cols, an, at, pos, out = bulk.cells, bulk.length, bulk.cols, bulk.an, bulk.at, bulk.pos, bulk.out
    evaluate(P, H, bulk)
    for f in range(cells.shape[0]):
        s = length[f]
        dn = out[f, 1] * s
        dt = out[f, 2] * s
        L = cells[f, 0]
        R_ = cells[f, 1]
        okL = L >= 0 and free[L]
        okR = R_ >= 0 and free[R_]
        for m in range(WIDTH):
            c = cols[f, m]
            if c < 0:
                continue
            d = (dn * an[f, m] + dt * at[f, m]) * dP[c]
            if okL:
                data[pos[f, 0, m]] += d
            if okR:
                data[pos[f, 1, m]] -= d
        if n_extra >= 2:
            if L >= 0 and R_ >= 0:
                hx = 0.5 * (cosp[L] + cosp[R_])
                hy = 0.5 * (sinp[L] + sinp[R_])
            else:
                i = L if L >= 0 else R_
                hx = cosp[i]
                hy = sinp[i]
            dh = out[f, 3] * s
            if okL:
                data[pos_col[L, 0]] += dh * hx
                data[pos_col[L, 1]] += dh * hy
            if okR:
                data[pos_col[R_, 0]] -= dh * hx
                data[pos_col[R_, 1]] -= dh * hy


@njit(cache=True)
def bulk_end_flow(P, H, free, n_interior, bulk):
    """Net outflow through the Dirichlet faces (``bulk`` lists them after the ``n_interior`` interior faces)
    of the Gecim pressure flux, from the free cells."""
    cells, length, out = bulk.cells, bulk.length, bulk.out
    evaluate(P, H, bulk)
    total = 0.0
    for f in range(n_interior, cells.shape[0]):
        L = cells[f, 0]
        R_ = cells[f, 1]
        if L >= 0 and free[L]:
            total += out[f, 0] * length[f]
        elif R_ >= 0 and free[R_]:
            total -= out[f, 0] * length[f]
    return total
