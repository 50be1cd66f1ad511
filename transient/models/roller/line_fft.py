"""Matrix-free Newton steps of the line contact's film-content iteration on fine uniform grids.

On a uniform grid the plane-strain influence matrix of :class:`~transient.models.roller.ehl_problem.EHLFilm`
is Toeplitz, so ``K p`` is one zero-padded FFT product (DC-FFT, Liu, Wang & Liu, *Wear* 243, 2000;
:class:`transient.physics.elasticity.LineConvolution`), ``O(N log N)``, and no ``N x N`` matrix is stored.
:class:`LineFFTFilm` is that film. The Newton step of :mod:`transient.models.roller.line_newton` (the Schur
system ``S z = r`` after the node-wise elimination of the Fischer-Burmeister rows,
:func:`~transient.models.roller.line_newton.schur_system`) is then solved by right-preconditioned GMRES
(the point film's :func:`~transient.models.ehl.krylov.gmres_solve`) with products of
:class:`SchurOperator` (one FFT product each) and the two-level preconditioner :class:`TwoLevel` -- the
point contact's (:mod:`transient.models.ehl.krylov`) for the line's one dimension:

* a coarse-grid correction: the dense Schur matrix of the same problem on every ``factor``-th node at the
  injected state, LU-factorised in single precision; the fine residual (rows divided by their scales) is
  unscaled, averaged onto the coarse nodes and divided by the coarse scales; the coarse step is
  interpolated linearly back;
* then a near-field correction of the remaining residual: the banded Schur matrix with ``K`` truncated to
  ``|i - k| <= near`` nodes, bordered by the ``h0`` column and the load row, by sparse LU.

Per Newton iteration: residuals and GMRES products ``O(N log N)``; the preconditioner ``O(N)`` plus the
coarse grid's fixed ``O(n_c^2)`` (``O(n_c^3)`` when it is refactorised).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.models.ehl.krylov import gmres_solve
from transient.models.roller.ehl_problem import EHLFilm
from transient.models.roller.grid import TensorGrid
from transient.models.roller.line_fbns import OFFSETS, LineContentFilm, schur_system
from transient.physics.elasticity import LineConvolution

#: uniform line grids with more nodes than this take the matrix-free path (measured at M = 1000, L = 0, the
#: finest level's Newton: 0.029 s CPU per iteration against 0.077 s dense at 2049 nodes, 0.032 against 0.32 s
#: at 4097; docs/bench/ehl_line.md)
MATRIX_FREE_ABOVE = 1025
#: the preconditioner's coarse grid has at most this many nodes (16385 nodes, M = 1000, one step: 30, 22, 12
#: GMRES iterations with 513, 1025, 2049 coarse nodes; set-up 0.05, 0.16, 0.5 s)
COARSE_MAX_NODES = 1025
#: near field of the banded correction (nodes either side): 0, the self-influence, needs the fewest GMRES
#: iterations (measured at 2049-16385 nodes, M = 1000: near 2, 8, 32 need 1-10x more or do not converge)
NEAR = 0
#: GMRES relative tolerance and restart length of a matrix-free Newton step
RTOL, RESTART = 1e-8, 40
#: GMRES iterations above which the coarse factorisation is refreshed at the next Newton iteration
REFRESH_ITERS = 30
#: forcing terms of a film that asks for them (``forcing = True``): Eisenstat & Walker's choice 2 (*SIAM J. Sci.
#: Comput.* 17, 1996), ``eta_k = gamma (|F_k| / |F_k-1|)^2`` safeguarded by ``gamma eta_k-1^2``, at most
#: ``FORCING_MAX``, at least :data:`RTOL` and half the Newton tolerance over ``|F_k|`` (no oversolving)
FORCING_GAMMA, FORCING_MAX = 0.9, 1e-2


def forcing_term(norms, eta_prev: float | None, tol: float) -> float:
    """GMRES's relative tolerance for the next Newton step (:data:`FORCING_GAMMA`): ``norms`` the Newton's scaled
    residual norms so far, ``eta_prev`` the last step's term (None at the first step), ``tol`` the Newton's."""
    if eta_prev is None or len(norms) < 2:
        eta = FORCING_MAX
    else:
        eta = FORCING_GAMMA * (norms[-1] / norms[-2]) ** 2
        guard = FORCING_GAMMA * eta_prev ** 2
        if guard > 0.1:
            eta = max(eta, guard)
    eta = max(eta, 0.5 * tol / max(norms[-1], 1e-300))
    return float(min(max(eta, RTOL), FORCING_MAX))


def matrix_free(grid: TensorGrid) -> bool:
    """Whether an elastic line film on ``grid`` takes the matrix-free path (uniform, > MATRIX_FREE_ABOVE nodes)."""
    return (not grid.two_d) and grid.x.size > MATRIX_FREE_ABOVE and grid.uniform


class LineFFTFilm(EHLFilm):
    """:class:`EHLFilm` of a uniform line grid whose elastic film ``k_el K p`` is a DC-FFT product
    (``conv``: a :class:`LineConvolution` of the grid to reuse). Its dense Jacobians are not available."""

    def __init__(self, grid: TensorGrid, rigid, rs, lam, w_bar, lubricant, p_scale, elastic_factor, order2,
                 conv: LineConvolution | None = None):
        if grid.two_d or not grid.uniform:
            raise ValueError("LineFFTFilm: a uniform line grid")
        super().__init__(grid, rigid, rs, lam, w_bar, lubricant, p_scale, elastic="rigid",
                         elastic_factor=elastic_factor, order2=order2)
        self.elastic = "line-fft"
        self.conv = conv if conv is not None else LineConvolution(grid.x.size, grid.x[1] - grid.x[0], elastic_factor)

    def deformation(self, p) -> np.ndarray:
        return self.conv.apply(self.grid.full(p).ravel())

    def deformation_approx(self, p) -> np.ndarray:
        return self.deformation(p)

    def jacobian(self, u, shift: float = 0.0):
        raise ValueError(f"LineFFTFilm ({self.grid.x.size} nodes) is matrix-free: no dense Jacobian")

    def reynolds_jacobian_dense(self, u):
        raise ValueError(f"LineFFTFilm ({self.grid.x.size} nodes) is matrix-free: no dense Jacobian")


def local_matrix(d, nf: int) -> sp.csr_matrix:
    """The local slots ``d`` (n, 4: centre, west, east, west-west) of the Reynolds rows as a sparse
    ``(n, nf)`` matrix over the full nodes."""
    n = d.shape[0]
    rows = np.repeat(np.arange(n), OFFSETS.size)
    cols = (np.arange(n)[:, None] + 1 + OFFSETS[None, :]).ravel()
    vals = d.ravel()
    keep = (cols >= 0) & (cols < nf) & (vals != 0.0)
    return sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape=(n, nf))


class SchurOperator:
    """The Schur matrix ``S`` of :func:`~transient.models.roller.line_newton.schur_system` (rows divided by
    their scales) as products: ``S [z; dh0] = [(J_p diag(b_p) + J_theta diag(b_t)) z + dR/dh0 dh0; w.(b_p z)]``."""

    def __init__(self, content, e, b_p, b_t):
        self.c, self.e, self.b_p, self.b_t = content, e, b_p, b_t
        self.inv_scale = 1.0 / e["scale"]
        self.j_h0 = e["dh"].sum(axis=1)
        self.n = content.n
        self.matvecs = 0

    def matvec(self, v):
        self.matvecs += 1
        n = self.n
        z = v[:n]
        dp = self.b_p * z
        out = np.empty(n + 1)
        out[:n] = (self.c.jacobian_product(self.e, dp, self.b_t * z) + self.j_h0 * v[n]) * self.inv_scale
        out[n] = self.c.weight @ dp
        return out


class NearField:
    """Sparse LU of ``S`` with ``K`` truncated to ``|i - k| <= near`` nodes, bordered by the ``h0`` column and
    the load row (solved by the bordering identity)."""

    def __init__(self, A: SchurOperator, near: int):
        c, e = A.c, A.e
        nf, n = c.nf, c.n
        conv = c.base.conv
        rows, cols, vals = [], [], []
        for d in range(-near, near + 1):  # K[i, k] (full node i, interior unknown k at full node k + 1)
            k = np.arange(n)
            i = k + 1 + d
            ok = (i >= 0) & (i < nf)
            rows.append(i[ok])
            cols.append(k[ok])
            vals.append(np.full(np.count_nonzero(ok), conv.coefficient(d)))
        Kn = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(nf, n))
        Dh, Dp, Dt = (local_matrix(e[k], nf) for k in ("dh", "dp", "dt"))
        B = (Dh @ Kn + Dp[:, 1:-1]) @ sp.diags(A.b_p) + Dt[:, 1:-1] @ sp.diags(A.b_t)
        self._factor((sp.diags(A.inv_scale) @ B).tocsc(), A)

    @classmethod
    def of_matrix(cls, B: sp.csc_matrix, A: SchurOperator, permc_spec: str = "NATURAL") -> NearField:
        """The bordered solve with a given near-field matrix ``B`` (n x n, rows by their scales) of ``A``."""
        out = cls.__new__(cls)
        out._factor(B, A, permc_spec)
        return out

    def _factor(self, B, A, permc_spec="NATURAL"):
        c = A.c
        self.lu = spla.splu(B, permc_spec=permc_spec)
        self.cvec = self.lu.solve(A.j_h0 * A.inv_scale)
        self.w = c.weight * A.b_p
        self.wc = float(self.w @ self.cvec)
        self.n = c.n

    def solve(self, b):
        x = self.lu.solve(np.ascontiguousarray(b[: self.n]))
        s = (self.w @ x - b[self.n]) / self.wc
        return np.append(x - s * self.cvec, s)


def prolongation(fine: np.ndarray, coarse: np.ndarray) -> sp.csr_matrix:
    """Linear interpolation from the interior nodes of ``coarse`` to those of ``fine`` (zero on the boundary)."""
    xf = fine[1:-1]
    k = np.clip(np.searchsorted(coarse, xf, side="right") - 1, 0, coarse.size - 2)
    w = (xf - coarse[k]) / (coarse[k + 1] - coarse[k])
    rows = np.r_[np.arange(xf.size), np.arange(xf.size)]
    cols = np.r_[k, k + 1] - 1
    vals = np.r_[1.0 - w, w]
    keep = (cols >= 0) & (cols < coarse.size - 2) & (vals != 0.0)
    return sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape=(xf.size, coarse.size - 2))


def coarsening_factor(nf: int, coarse_max: int = COARSE_MAX_NODES) -> int:
    """The smallest power of two that coarsens ``nf`` nodes (every ``f``-th kept) to at most ``coarse_max``."""
    f = 2
    while (nf - 1) % (2 * f) == 0 and (nf - 1) // f + 1 > coarse_max:
        f *= 2
    return f


class CoarseCorrection:
    """The coarse-grid part of a two-level preconditioner of a Schur operator ``A``: the coarse content film's
    Schur matrix by a single-precision LU, interpolation ``P`` to the fine grid and the row-sum-scaled
    restriction ``P^T`` between the two row scalings; ``solve`` adds the near field's correction of the residual
    the coarse step leaves. The line's :class:`TwoLevel` and the roller's
    :class:`~transient.models.roller.roller_fft.RollerTwoLevel` build it from their own coarse grids and near fields."""

    def _set_coarse(self, coarse, uc, P):
        """Factorise ``coarse``'s Schur matrix at ``uc``; ``P`` the fine-from-coarse interpolation of the nodes."""
        ec = coarse.equations(uc)
        Sc, _, _ = schur_system(coarse, uc, ec)
        self.lu = sla.lu_factor(Sc.astype(np.float32), check_finite=False, overwrite_a=True)
        R = P.T.tocsr()
        R = sp.diags(1.0 / np.maximum(np.asarray(R.sum(axis=1)).ravel(), 1e-300)) @ R
        self.P = sp.block_diag([P, sp.identity(1)], format="csr")
        self.R_unscaled = sp.block_diag([R, sp.identity(1)], format="csr")
        self.coarse_scale = ec["scale"]

    def _set_scales(self, A: SchurOperator):
        """Take the row scales of the operator ``A`` (the coarse factors kept)."""
        self.A = A
        self.R = (sp.diags(np.append(1.0 / self.coarse_scale, 1.0)) @ self.R_unscaled
                  @ sp.diags(np.append(1.0 / A.inv_scale, 1.0)))

    def solve(self, b):
        zc = sla.lu_solve(self.lu, (self.R @ b).astype(np.float32), check_finite=False).astype(float)
        z = self.P @ zc
        return z + self.near.solve(b - self.A.matvec(z))


class TwoLevel(CoarseCorrection):
    """The two-level preconditioner (module docstring) of the Schur operator ``A`` at the fine state ``u``."""

    def __init__(self, A: SchurOperator, u, factor: int, near: int = NEAR, coarse_kernel=None):
        fine = A.c
        base = fine.base
        xf = base.grid.x
        xc = xf[::factor]
        gc = TensorGrid(xc)
        cf = LineContentFilm(EHLFilm(gc, 0.5 * xc * xc, np.ones(1), base.lam, base.w_bar, base.lubricant,
                                     base.p_scale, elastic="dense", elastic_factor=base.k_el, order2=base.order2,
                                     kernel=coarse_kernel))
        self.coarse_kernel = cf.K
        pf, tf, h0 = fine.expand(u)
        uc = np.concatenate([pf[::factor][1:-1], tf[::factor][1:-1], [h0]])
        self._set_coarse(cf, uc, prolongation(xf, xc))
        self.set_operator(A, near)

    def set_operator(self, A: SchurOperator, near: int = NEAR):
        """Keep the coarse factors, take the near field (cheap) and the row scales of a new operator."""
        self._set_scales(A)
        self.near = NearField(A, near)


class MatrixFreeStep:
    """Newton steps of one matrix-free solve: ``solve(content, u, e, b_p, b_t, r, stats)`` -> ``z`` by GMRES
    with a preconditioner whose factors are kept while GMRES needs at most ``REFRESH_ITERS`` (or the film's
    ``refresh_iters``): ``content.two_level(A, u)`` where the film has one (the roller's), else the line's
    :class:`TwoLevel`. A step whose GMRES misses its tolerance after a fresh preconditioner is counted in
    ``stats.krylov_misses``."""

    def __init__(self, content, tol: float = 0.0):
        self.two_level = getattr(content, "two_level", None) or self._line_two_level
        self.refresh_iters = getattr(content, "refresh_iters", REFRESH_ITERS)
        self.factor = None if hasattr(content, "two_level") else coarsening_factor(content.nf)
        self.pre = None
        self.refresh = True
        self.coarse_kernel = None
        #: the film's ``forcing`` (default False: every step to :data:`RTOL`): Eisenstat-Walker terms
        #: (:func:`forcing_term`) toward the Newton tolerance ``tol``
        self.forcing, self.tol, self.eta = bool(getattr(content, "forcing", False)), tol, None

    def _line_two_level(self, A, u):
        pre = TwoLevel(A, u, self.factor, coarse_kernel=self.coarse_kernel)
        self.coarse_kernel = pre.coarse_kernel
        return pre

    def solve(self, content, u, e, b_p, b_t, r, stats):
        A = SchurOperator(content, e, b_p, b_t)
        if self.refresh or self.pre is None:
            self.pre = self.two_level(A, u)
            stats.factorisations += 1
            fresh = True
        else:
            self.pre.set_operator(A)
            fresh = False
        rtol = RTOL
        if self.forcing:
            rtol = self.eta = forcing_term(stats.norms, self.eta, self.tol)
        z, its, ok = gmres_solve(A, r, self.pre, rtol, restart=RESTART, max_iter=2 * RESTART)
        stats.krylov += its
        if not ok and not fresh:
            self.pre = self.two_level(A, u)
            stats.factorisations += 1
            z, more, ok = gmres_solve(A, r, self.pre, rtol, restart=RESTART, max_iter=4 * RESTART)
            stats.krylov += more
        self.refresh = its > self.refresh_iters or not ok
        if not ok:  # an inexact step: counted, and the Newton warns (line_newton.content_newton)
            stats.krylov_misses += 1
        return z
