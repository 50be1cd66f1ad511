"""Newton-Krylov linear solves for the EHL film (Park): exact Jacobian-vector products and
preconditioners, handed to :func:`transient.solvers.newton.newton` as its ``jacobian``.

The Newton matrix of :class:`~transient.models.roller.ehl_problem.EHLFilm` is ``J = D_a - D_b S (Sp + Sh K)``
bordered by the load row and the ``h0`` column (``D_a``, ``D_b``: Fischer-Burmeister derivatives, ``S``
the row scaling, ``Sp``, ``Sh`` the 6-slot local Jacobian, ``K`` the elastic influence operator). Its
product with a vector costs one deformation (dense ``K v``: ``O(N^2)``; DC-FFT: ``O(N log N)``) plus
``O(N)``. GMRES (restarted) solves ``J du = -r`` to a relative tolerance ``rtol`` (an inexact Newton
step) preconditioned by

* :class:`DenseLU` -- the LU factors of the dense Newton matrix of an earlier iterate, in single
  precision (a preconditioner needs no more; LAPACK ``sgetrf`` is ~2x faster than ``dgetrf``), kept
  while GMRES converges in at most ``refresh_after`` iterations;
* :class:`TwoLevel` -- for uniform grids (no dense matrix): a coarse-grid correction with the dense
  Newton matrix of the same problem on a grid coarser by ``factor`` (restriction by area-weighted
  aggregation, bilinear prolongation), followed by a sparse local correction: the sparse LU of the
  Newton matrix with ``K`` truncated to its near field (``|di|, |dj| <= near``).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numba import njit

from transient.models.ehl.rows import N_SLOTS


@njit(cache=True)
def local_matvec(Sp, Sh, colp, colh, dp, dh_full, out):
    """``out = Sp dp + Sh dh`` over the six slots of every row."""
    for r in range(Sp.shape[0]):
        acc = 0.0
        for s in range(N_SLOTS):
            cp = colp[r, s]
            if cp >= 0:
                acc += Sp[r, s] * dp[cp]
            ch = colh[r, s]
            if ch >= 0:
                acc += Sh[r, s] * dh_full[ch]
        out[r] = acc


class NewtonMatrix(spla.LinearOperator):
    """The exact Newton matrix of ``film`` at ``u`` (plus ``shift`` times its storage term) as a linear
    operator (module docstring)."""

    def __init__(self, film, u, shift: float = 0.0):
        n = film.n
        super().__init__(dtype=float, shape=(n + 1, n + 1))
        self.film = film
        p, h0 = u[:-1], u[-1]
        h = film.film(p, h0)
        F = film.reynolds(p, h, jac=True)
        if shift:
            film.add_storage(p, h, shift)
        film.complementarity(p, -F * film.row_scale, film.phi)
        self.Sp, self.Sh = film.Sp.copy(), film.Sh.copy()
        self.da = film.fb_a.copy()
        self.db = film.fb_b * film.row_scale
        self._tmp = np.empty(n)

    def _matvec(self, v):
        v = np.ravel(v)
        f = self.film
        dp = np.ascontiguousarray(v[:-1])
        dh = v[-1] + f.deformation_approx(dp)
        local_matvec(self.Sp, self.Sh, f.colp, f.colh, dp, dh, self._tmp)
        out = np.empty(f.n + 1)
        out[:-1] = self.da * dp - self.db * self._tmp
        out[-1] = f.area_w @ dp
        return out


class DenseLU:
    """Single-precision LU of a dense Newton matrix, as a preconditioner (``.solve``)."""

    def __init__(self, J: np.ndarray):
        self.lu = sla.lu_factor(np.asarray(J, dtype=np.float32), check_finite=False, overwrite_a=True)

    def solve(self, b):
        return sla.lu_solve(self.lu, np.asarray(b, dtype=np.float32), check_finite=False).astype(float)


class NewtonKrylov:
    """``jacobian(u, shift)`` for :func:`~transient.solvers.newton.newton`: returns an object whose
    ``solve(b)`` runs GMRES on the exact Newton matrix at ``u`` with the preconditioner made by
    ``make_preconditioner(film, u, shift)`` (rebuilt when GMRES needed more than ``refresh_after`` iterations
    or did not converge). ``gmres_iterations`` lists the iterations of every solve."""

    def __init__(self, film, make_preconditioner, rtol: float = 1e-4, restart: int = 60, max_iter: int = 400,
                 refresh_after: int = 40):
        self.film = film
        self.make = make_preconditioner
        self.rtol, self.restart, self.max_iter, self.refresh_after = rtol, restart, max_iter, refresh_after
        self.prec = None
        self.stale = True
        self.gmres_iterations: list[int] = []
        self.n_preconditioners = 0

    def __call__(self, u, shift=0.0):
        if self.prec is None or self.stale:
            self.prec = self.make(self.film, u, shift)
            self.n_preconditioners += 1
            self.stale = False
        return _KrylovSolve(self, NewtonMatrix(self.film, u, shift))


class _KrylovSolve:
    def __init__(self, owner: NewtonKrylov, A: NewtonMatrix):
        self.owner, self.A = owner, A

    def solve(self, b):
        o = self.owner
        M = spla.LinearOperator(self.A.shape, matvec=o.prec.solve, dtype=float)
        count = [0]

        def cb(_):
            count[0] += 1

        x, info = spla.gmres(self.A, b, rtol=o.rtol, atol=0.0, restart=o.restart, maxiter=o.max_iter // o.restart + 1,
                             M=M, callback=cb, callback_type="pr_norm")
        o.gmres_iterations.append(count[0])
        if info != 0 or count[0] > o.refresh_after:
            o.stale = True
        return x


def interpolation_matrix(fine: np.ndarray, coarse: np.ndarray) -> sp.csr_matrix:
    """Linear interpolation from the interior nodes of a coarse axis (values 0 at its boundary nodes) to
    the interior nodes of a fine axis spanning the same interval: ``(n_fine_interior, n_coarse_interior)``."""
    xf = fine[1:-1]
    k = np.clip(np.searchsorted(coarse, xf) - 1, 0, coarse.size - 2)
    w = (xf - coarse[k]) / (coarse[k + 1] - coarse[k])
    rows = np.r_[np.arange(xf.size), np.arange(xf.size)]
    cols = np.r_[k, k + 1] - 1  # coarse interior index
    vals = np.r_[1.0 - w, w]
    keep = (cols >= 0) & (cols < coarse.size - 2)
    return sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape=(xf.size, coarse.size - 2))


class TwoLevel:
    """Two-level preconditioner for a uniform grid with FFT elasticity (module docstring): a coarse-grid
    correction with the dense Newton matrix of ``coarse_film`` (single-precision LU), then one
    row-block relaxation -- for each grid row along x the exact block of the Newton matrix that couples
    that row's pressures with each other (its local terms and the in-row and neighbouring-row elastic
    coefficients, a dense ``nx x nx`` LU per row). ``A``: the fine :class:`NewtonMatrix`."""

    def __init__(self, film, coarse_film, u, shift, A: NewtonMatrix):
        g, gc = film.grid, coarse_film.grid
        px, py = interpolation_matrix(g.x, gc.x), interpolation_matrix(g.y, gc.y)
        P = sp.kron(py, px, format="csr")
        self.P = sp.block_diag([P, sp.identity(1)], format="csr")
        R = P.T.tocsr()
        R = sp.diags(1.0 / np.maximum(np.asarray(R.sum(axis=1)).ravel(), 1e-300)) @ R
        self.R = sp.block_diag([R, sp.identity(1)], format="csr")
        pc = interpolate_pressure(g, u[:-1], gc)
        self.coarse = DenseLU(coarse_film.jacobian(np.append(pc, u[-1]), shift))
        self.A = A
        self.blocks = _row_blocks(film, A)

    def solve(self, b):
        z = self.P @ self.coarse.solve(self.R @ b)
        r = b - self.A.matvec(z)
        nx, ny = self.A.film.grid.nx, self.A.film.grid.ny
        rr = r[:-1].reshape(ny, nx)
        zz = np.empty((ny, nx))
        for j, lu in enumerate(self.blocks):
            zz[j] = sla.lu_solve(lu, rr[j], check_finite=False)
        z[:-1] += zz.ravel()
        return z


def interpolate_pressure(grid_from, p, grid_to) -> np.ndarray:
    """Interior pressures of ``grid_from`` carried to the interior nodes of ``grid_to`` (bilinear)."""
    from scipy.interpolate import RegularGridInterpolator

    f = RegularGridInterpolator((grid_from.y, grid_from.x), grid_from.full(p), bounds_error=False, fill_value=0.0)
    yy, xx = np.meshgrid(grid_to.y[1:-1], grid_to.x[1:-1], indexing="ij")
    return f(np.stack([yy.ravel(), xx.ravel()], axis=1))


def _row_blocks(film, A: NewtonMatrix) -> list:
    """LU factors of the in-row blocks of the Newton matrix ``A`` (uniform grid, FFT elasticity)."""
    g = film.grid
    nx, ny, nxf = g.nx, g.ny, g.x.size
    conv = film.conv
    ii = np.arange(nx)
    blocks = []
    for j in range(ny):
        rows = j * nx + ii
        B = np.zeros((nx, nx))
        for s in range(N_SLOTS):
            ch = film.colh[rows, s]
            ok = ch >= 0
            if not np.any(ok):
                continue
            Jn, In = np.divmod(ch[ok], nxf)  # full-node indices of the slot's node
            dj = Jn - (j + 1)
            # K[(Jn, In), (j+1, i'+1)] = k(In - i' - 1, dj): Toeplitz along the row
            di = In[:, None] - (ii[None, :] + 1)
            kk = conv._offsets[conv.ny - 1 + dj[:, None], conv.nx - 1 + di]
            B[np.flatnonzero(ok)] += A.Sh[rows[ok], s][:, None] * kk
            cp = film.colp[rows, s]
            inrow = (cp >= j * nx) & (cp < (j + 1) * nx)
            B[np.flatnonzero(inrow), cp[inrow] - j * nx] += A.Sp[rows[inrow], s]
        B *= -A.db[rows][:, None]
        B[ii, ii] += A.da[rows]
        blocks.append(sla.lu_factor(B, check_finite=False))
    return blocks
