"""Newton-Krylov solve of the Schur-reduced FBNS Newton system of the point film on uniform DC-FFT grids.

The reduced system of :func:`transient.models.point.fbns.newton_step` (one unknown ``z`` per node: the
pressure change where the Fischer-Burmeister row leaves the pressure free, the content change elsewhere,
``dP = a_P + b_P z``, ``dtheta = a_theta + b_theta z``; plus ``dH0``) has the matrix::

    A = [ D_H K diag(b_P) + L    D_H 1 ]      L = A_P diag(b_P) + A_theta diag(b_theta)
        [ w^T diag(b_P)            0   ]

with ``A_P``, ``A_theta``, ``D_H`` the five-point local Jacobians of the Reynolds rows and ``K`` the elastic
influence (:meth:`~transient.models.point.ehl_problem.PointFilm.local_newton`). Its product with a vector
costs one DC-FFT deformation (``O(N log N)``) plus ``O(N)``, so the dense ``O(N^2)`` memory and ``O(N^3)`` LU
of the direct path are avoided. The system is solved by right-preconditioned restarted GMRES (Saad &
Schultz, *SIAM J. Sci. Stat. Comput.* 7, 1986; written here because scipy's ``gmres`` spent ~0.5 s per
call on a 65k system beyond its products, and right preconditioning controls the true residual) to a
relative tolerance (inexact Newton: Dembo, Eisenstat & Steihaug, *SIAM J. Numer. Anal.* 19, 1982) with the
two-level preconditioner :class:`TwoLevel` -- the roller's idea (:class:`transient.models.roller.krylov.TwoLevel`)
for this film's half grid and reduced unknowns:

* a coarse-grid correction: the dense reduced matrix of the same problem on every ``factor``-th node, at the
  injected state, LU-factorised in single precision (restriction by averaging, bilinear prolongation);
* then a near-field correction of the remaining residual: the sparse LU (SuperLU) of ``A`` with ``K``
  truncated to its near field (``|di|, |dj| <= near``, mirror images included; default 0, the
  self-influence), bordered by the ``H0`` column and the load row.

Without the near-field correction GMRES does not converge (100+ iterations); with it 1-10 per Newton step
on grids 49 x 49 to 257 x 257 (``transient bench ehl_point``).
"""

from __future__ import annotations

import time

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.models.ehl.reduced import dense_reduced, schur


class ReducedOperator(spla.LinearOperator):
    """The reduced Newton matrix ``A`` (module docstring) of ``film`` as a matrix-free operator.

    ``local``: ``(A_P, D_H, A_theta)`` from ``film.local_newton``; ``b_p``, ``b_t`` the elimination
    coefficients of the Fischer-Burmeister rows."""

    def __init__(self, film, local, b_p, b_t):
        n = film.n
        super().__init__(dtype=float, shape=(n + 1, n + 1))
        a_p, d_h, a_t = local
        self.film, self.d_h, self.b_p, self.b_t = film, d_h, b_p, b_t
        self.L = (a_p @ sp.diags(b_p) + a_t @ sp.diags(b_t)).tocsr()
        self.j_h0 = np.asarray(d_h.sum(axis=1)).ravel()
        self.w = film.weight / film.load
        self.matvecs = 0

    def _matvec(self, v):
        self.matvecs += 1
        v = np.ravel(v)
        n = self.film.n
        z = v[:n]
        dp = self.b_p * z
        out = np.empty(n + 1)
        out[:n] = self.d_h @ self.film.deformation(dp) + self.L @ z + self.j_h0 * v[n]
        out[n] = self.w @ dp
        return out


def near_kernel(film, near: int) -> sp.csr_matrix:
    """``K`` truncated to ``|di|, |dj| <= near`` (mirror images about ``Y = 0`` added): sparse, rows the
    half-grid nodes, columns the unknowns."""
    off = film.conv._offsets
    cy, cx = film.conv.ny - 1, film.conv.nx - 1
    m, nx = film.m, film.nx
    rows, cols, vals = [], [], []
    col = np.arange(film.n)
    for dj in range(-near, near + 1):
        for di in range(-near, near + 1):
            jo, io = film.j + dj, film.i + di
            ok = (jo >= 0) & (jo < m) & (io >= 0) & (io < nx)
            v = np.full(film.n, off[cy + dj, cx + di])
            # mirror image of the column's node at -j: offset jo + j, present for j > 0
            mj = jo + film.j
            mirror = (film.j > 0) & (mj <= near)
            v = v + np.where(mirror, off[cy + np.minimum(mj, near), cx + di], 0.0)
            rows.append((jo * nx + io)[ok])
            cols.append(col[ok])
            vals.append(v[ok])
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(m * nx, film.n))


class NearField:
    """Sparse LU of the reduced matrix with the elastic kernel truncated to its near field, bordered by the
    ``H0`` column and the load row (solved by the bordering identity)."""

    def __init__(self, A: ReducedOperator, near: int = 0):
        B = (A.d_h @ near_kernel(A.film, near) @ sp.diags(A.b_p) + A.L).tocsc()
        self.lu = spla.splu(B, permc_spec="MMD_AT_PLUS_A")
        self.c = self.lu.solve(A.j_h0)
        self.w = A.w * A.b_p
        self.wc = float(self.w @ self.c)
        self.n = A.film.n

    def solve(self, b):
        n = self.n
        x = self.lu.solve(np.ascontiguousarray(b[:n]))
        s = (self.w @ x - b[n]) / self.wc
        return np.append(x - s * self.c, s)


def interpolation(fine, coarse, fine_free, coarse_free) -> sp.csr_matrix:
    """Linear interpolation along one axis from the coarse unknowns (``coarse[coarse_free]``; the other coarse
    nodes carry zero) to the fine unknowns ``fine[fine_free]``."""
    xf = np.asarray(fine)[fine_free]
    k = np.clip(np.searchsorted(coarse, xf, side="right") - 1, 0, coarse.size - 2)
    w = (xf - coarse[k]) / (coarse[k + 1] - coarse[k])
    index = -np.ones(coarse.size, dtype=np.int64)
    index[coarse_free] = np.arange(len(coarse_free))
    rows = np.r_[np.arange(xf.size), np.arange(xf.size)]
    cols = index[np.r_[k, k + 1]]
    vals = np.r_[1.0 - w, w]
    keep = (cols >= 0) & (vals != 0.0)
    return sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape=(xf.size, int(index.max()) + 1))


def prolongation(film, coarse) -> sp.csr_matrix:
    """Bilinear interpolation of the unknowns of ``coarse`` to those of ``film`` (half grids, zero on the
    outer boundary, the symmetry row free)."""
    px = interpolation(film.x, coarse.x, np.arange(1, film.nx - 1), np.arange(1, coarse.nx - 1))
    py = interpolation(film.y, coarse.y, np.arange(film.m - 1), np.arange(coarse.m - 1))
    return sp.kron(py, px, format="csr")


def transfers(film, coarse):
    """``(P, R)``: bilinear prolongation of the reduced unknowns from ``coarse`` and the restriction by
    averaging (its transpose with rows scaled to sum 1), both with the ``H0`` entry passed through."""
    P = prolongation(film, coarse)
    R = P.T.tocsr()
    R = sp.diags(1.0 / np.maximum(np.asarray(R.sum(axis=1)).ravel(), 1e-300)) @ R
    return sp.block_diag([P, sp.identity(1)], format="csr"), sp.block_diag([R, sp.identity(1)], format="csr")


class TwoLevel:
    """Two-level preconditioner (module docstring): the coarse-grid correction, then (``near`` not None) the
    near-field correction of the remaining residual. ``transfer``: :func:`transfers` of the two grids."""

    def __init__(self, A: ReducedOperator, transfer, coarse_matrix, near: int | None = 0):
        self.P, self.R = transfer
        self.coarse = sla.lu_factor(np.asarray(coarse_matrix, np.float32), check_finite=False)
        self.A = A
        self.near = None if near is None else NearField(A, near)

    def coarse_solve(self, b):
        return self.P @ sla.lu_solve(self.coarse, (self.R @ b).astype(np.float32), check_finite=False).astype(float)

    def solve(self, b):
        z = self.coarse_solve(b)
        if self.near is not None:
            z = z + self.near.solve(b - self.A.matvec(z))
        return z


def gmres_solve(A, b, M, rtol: float, restart: int = 60, max_iter: int = 600):
    """Right-preconditioned restarted GMRES (Saad & Schultz, 1986; modified Gram-Schmidt) on ``A x = b``
    with the preconditioner ``M`` (``.solve``), from ``x = 0``, until ``|b - A x| <= rtol |b|`` (the true
    residual of right preconditioning). Returns ``(x, iterations, converged)``."""
    n = b.size
    x = np.zeros(n)
    beta0 = float(np.linalg.norm(b))
    if beta0 == 0.0:
        return x, 0, True
    r = b.copy()
    its = 0
    while its < max_iter:
        beta = float(np.linalg.norm(r))
        if beta <= rtol * beta0:
            return x, its, True
        m = min(restart, max_iter - its)
        V = np.empty((m + 1, n))
        Z = np.empty((m, n))
        H = np.zeros((m + 1, m))
        V[0] = r / beta
        k = 0
        for k in range(m):
            Z[k] = M.solve(V[k])
            w = A.matvec(Z[k])
            for i in range(k + 1):
                H[i, k] = V[i] @ w
                w -= H[i, k] * V[i]
            H[k + 1, k] = float(np.linalg.norm(w))
            its += 1
            e1 = np.zeros(k + 2)
            e1[0] = beta
            y, *_ = np.linalg.lstsq(H[: k + 2, : k + 1], e1, rcond=None)
            res = float(np.linalg.norm(H[: k + 2, : k + 1] @ y - e1))
            if res <= rtol * beta0 or H[k + 1, k] == 0.0:
                break
            V[k + 1] = w / H[k + 1, k]
        x += y @ Z[: k + 1]
        r = b - A.matvec(x)
    return x, its, bool(np.linalg.norm(r) <= rtol * beta0)


#: the largest nodal unknown count of the preconditioner's coarse grid (dense LU)
COARSE_MAX_UNKNOWNS = 2500


def coarsening_factor(film, coarse_max: int = COARSE_MAX_UNKNOWNS) -> int:
    """The smallest power of two that coarsens ``film`` to at most ``coarse_max`` nodal unknowns; 1 when
    the grid does not coarsen so."""
    f = 2
    while (film.nx - 1) % f == 0 and (film.m - 1) % f == 0 and (film.m - 1) // f >= 2:
        if ((film.m - 1) // f) * ((film.nx - 1) // f - 1) <= coarse_max:
            return f
        f *= 2
    return 1


def inject(film, coarse, factor: int, u) -> np.ndarray:
    """The state of ``coarse`` (every ``factor``-th node of ``film``) at the fine state ``u``."""
    P, T, h0 = film.split(u)
    Pc, Tc = P[::factor, ::factor].ravel()[coarse.flat], T[::factor, ::factor].ravel()[coarse.flat]
    return np.concatenate([Pc, Tc, [h0]])


def prolong_state(coarse, film, uc) -> np.ndarray:
    """The state of ``film`` interpolated bilinearly from the state ``uc`` of ``coarse`` (pressure zero and
    content one on the outer boundary; ``H0`` the same)."""
    P = prolongation(film, coarse)
    n = coarse.n
    return np.concatenate([P @ uc[:n], 1.0 + P @ (uc[n: 2 * n] - 1.0), [uc[-1]]])


class KrylovSolver:
    """The reduced Newton system by GMRES with the :class:`TwoLevel` preconditioner, rebuilt at every
    Newton step. ``rtol``: GMRES's relative tolerance; ``near``: the near field of the sparse correction
    (0: the self-influence only, the fastest measured; None: no sparse correction);
    ``factor``: the coarsening (default :func:`coarsening_factor`). ``stats``: Newton steps, GMRES
    iterations, matrix-vector products and the seconds spent in the preconditioner's set-up and in GMRES.
    The preconditioner of an earlier Newton step is kept while GMRES needs at most ``refresh_after``
    iterations with it (0: rebuilt at every step); a kept one that does not converge within
    ``2 refresh_after`` iterations is rebuilt and the solve repeated. :meth:`tighten` (called by
    :func:`~transient.models.point.fbns.fbns` when Newton stagnates near the solution) lowers ``rtol``."""

    name = "Newton-Krylov"

    def __init__(self, film, rtol: float = 1e-3, near: int | None = 0, factor: int | None = None,
                 restart: int = 60, max_iter: int = 600, refresh_after: int = 0):
        self.factor = coarsening_factor(film) if factor is None else int(factor)
        if self.factor < 2:
            raise ValueError(f"factor = {self.factor}: the grid {film.nx} x {film.y_full.size} does not coarsen")
        self.coarse = film.coarsened(self.factor)
        self.rtol, self.near, self.restart, self.max_iter = rtol, near, restart, max_iter
        self.transfer = transfers(film, self.coarse)
        self.refresh_after = refresh_after
        self.M = None
        self.stats = dict(newton=0, gmres=0, matvecs=0, failures=0, setups=0, setup_s=0.0, gmres_s=0.0,
                          gmres_its=[])

    def preconditioner(self, film, u, A, cj):
        cf = self.coarse
        uc = inject(film, cf, self.factor, u)
        ec = cf.equations(uc)
        _, b_pc, _, b_tc = schur(cf, uc, ec)
        Ac = dense_reduced(cf, cf.local_newton(uc, ec, cj), b_pc, b_tc)
        return TwoLevel(A, self.transfer, Ac, near=self.near)

    def solve(self, film, u, e, local, b_p, b_t, r, cj):
        s = self.stats
        A = ReducedOperator(film, local, b_p, b_t)
        fresh = self.M is None
        if fresh:
            self._build(film, u, A, cj)
        else:
            self.M.A = A
        t0 = time.perf_counter()
        x, its, ok = gmres_solve(A, r, self.M, self.rtol, self.restart,
                                 self.max_iter if fresh else 2 * self.refresh_after)
        s["gmres_s"] += time.perf_counter() - t0
        if not ok and not fresh:  # a stale preconditioner: rebuild and retry
            self._build(film, u, A, cj)
            t0 = time.perf_counter()
            x, more, ok = gmres_solve(A, r, self.M, self.rtol, self.restart, self.max_iter)
            s["gmres_s"] += time.perf_counter() - t0
            its += more
        if its > self.refresh_after or not ok:
            self.M = None
        s["newton"] += 1
        s["gmres"] += its
        s["gmres_its"].append(its)
        s["matvecs"] += A.matvecs
        s["failures"] += not ok
        return x

    def tighten(self, factor: float = 1e-3, floor: float = 1e-10):
        """Lower GMRES's relative tolerance by ``factor`` (not below ``floor``): near the solution the inexact
        step with ``rtol = 1e-3`` can leave the residual of the complementarity rows at a cavitation boundary
        where it was (Newton stagnating at ~1e-4), the exact step converges quadratically."""
        self.rtol = max(self.rtol * factor, floor)
        self.stats["tightened"] = self.stats.get("tightened", 0) + 1

    def _build(self, film, u, A, cj):
        t0 = time.perf_counter()
        self.M = self.preconditioner(film, u, A, cj)
        self.stats["setups"] += 1
        self.stats["setup_s"] += time.perf_counter() - t0
