"""Newton-Krylov linear solves for the EHL film (Park, seed 001): exact Jacobian-vector products and
preconditioners, handed to :func:`transient.solvers.newton.newton` as its ``jacobian``.

The Newton matrix of :class:`~transient.models.roller.film.EHLFilm` is ``J = D_a - D_b S (Sp + Sh K)``
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

from transient.models.roller.kernels import N_SLOTS, fischer_burmeister


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
        fischer_burmeister(p, -F * film.row_scale, film.phi, film.fb_a, film.fb_b)
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


def truncated_stencil_matrix(film, A: NewtonMatrix, near: int) -> sp.csr_matrix:
    """Sparse Newton matrix of ``film`` at the state of ``A`` with the elastic coupling truncated to
    ``|di|, |dj| <= near`` (uniform grid, FFT elasticity: ``K`` is Toeplitz)."""
    g = film.grid
    nxf, nyf = g.x.size, g.y.size
    n = film.n
    offs = [(di, dj) for dj in range(-near, near + 1) for di in range(-near, near + 1)]
    kval = np.array([film.conv.coefficient(di, dj) for di, dj in offs])
    rows, cols, vals = [], [], []
    jf, i_f = np.divmod(np.arange(nxf * nyf), nxf)  # full-node (J, I)
    for s in range(N_SLOTS):
        ch = film.colh[:, s]
        ok = ch >= 0
        w = -A.db * A.Sh[:, s]
        for (di, dj), kv in zip(offs, kval):
            I = i_f[ch] + di
            J = jf[ch] + dj
            inside = ok & (I >= 1) & (I <= nxf - 2) & (J >= 1) & (J <= nyf - 2)
            r = np.flatnonzero(inside)
            rows.append(r)
            cols.append((J[inside] - 1) * g.nx + (I[inside] - 1))
            vals.append(w[inside] * kv)
        cp = film.colp[:, s]
        okp = cp >= 0
        r = np.flatnonzero(okp)
        rows.append(r)
        cols.append(cp[okp])
        vals.append(-A.db[okp] * A.Sp[okp, s])
    rows.append(np.arange(n))
    cols.append(np.arange(n))
    vals.append(A.da)
    # h0 column and load row
    hcol = -A.db * np.where(film.colh >= 0, A.Sh, 0.0).sum(axis=1)
    rows += [np.arange(n), np.full(n, n)]
    cols += [np.full(n, n), np.arange(n)]
    vals += [hcol, film.area_w]
    m = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n + 1, n + 1))
    return m.tocsc()
