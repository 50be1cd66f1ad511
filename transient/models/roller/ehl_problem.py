"""The discrete EHL problem on a tensor grid (Park): unknowns, residual, Jacobians, film.

Scaled units (chosen by the model): lengths by the half-width ``b`` of the contact, pressure by
``p_h``, film by ``b^2/R``, so that the rigid gap is ``x^2/(2 Rs) + ...`` and the elastic film is
``k_el K p`` with ``K`` the raw influence integrals of :mod:`transient.physics.elasticity` and
``k_el = 1/(2 pi)`` (surface, ``p_h/b = E'/(4R)`` as in Hertz) or ``-1/pi`` (line contact)::

    h = h0 + g_rigid + k_el K p                                           (paper eq. 4)
    F(p, h) = 0 where p > 0, p = 0 where the film cavitates:  phi(p, -F) = 0  (eqs. 1, 6; kernels)
    (sum_i A_i p_i - W) / W = 0                                            (eq. 5)

Unknowns ``u = [p_1 .. p_n, h0]``. :class:`EHLFilm` evaluates the residual and the exact (semismooth)
Newton matrix ``[[diag(phi_a) - diag(phi_b) (Sp + Sh K), -diag(phi_b) Sh 1], [A/W, 0]]`` densely
(non-uniform grids), or its product with a vector through FFT deformation (uniform grids,
:mod:`transient.models.roller.krylov`). The transient adds the squeeze term
``-kappa (rho' h dp/dt + rho dh/dt)``, ``dh/dt = dh0/dt + k_el K dp/dt``.
"""

from __future__ import annotations

import numpy as np

from transient.models.ehl.complementarity import SYMMETRIC_KINK, fb_gradient, fb_value
from transient.models.ehl.rows import ALL_SLOTS, N_SLOTS, rows_kernel
from transient.models.roller.grid import TensorGrid
from transient.models.roller.kernels import assemble_dense, penalty
from transient.physics.elasticity import RowConvolution, SurfaceConvolution, line_influence, surface_influence
from transient.physics.lubricant import Lubricant
from transient.solvers.newton import NewtonSettings, newton

ELASTIC = ("dense", "fft", "xfft", "rigid")


def slot_maps(grid: TensorGrid) -> tuple[np.ndarray, np.ndarray]:
    """Interior (``colp``) and full (``colh``) node index of each Jacobian slot of each row (-1: none)."""
    nx, ny = grid.nx, grid.ny
    nxf = grid.x.size
    j, i = np.divmod(np.arange(grid.n), nx)
    J = j + 1 if grid.two_d else j
    I = i + 1
    c = J * nxf + I
    colh = np.full((grid.n, N_SLOTS), -1, np.int64)
    colp = np.full((grid.n, N_SLOTS), -1, np.int64)
    r = np.arange(grid.n)
    colh[:, 0], colp[:, 0] = c, r
    colh[:, 1], colp[:, 1] = c - 1, np.where(i >= 1, r - 1, -1)
    colh[:, 2], colp[:, 2] = c + 1, np.where(i <= nx - 2, r + 1, -1)
    if grid.two_d:
        colh[:, 3], colp[:, 3] = c - nxf, np.where(j >= 1, r - nx, -1)
        colh[:, 4], colp[:, 4] = c + nxf, np.where(j <= ny - 2, r + nx, -1)
    colh[:, 5], colp[:, 5] = np.where(I >= 2, c - 2, -1), np.where(i >= 2, r - 2, -1)
    return colp, colh


class EHLFilm:
    """Residual and Jacobian of the scaled EHL equations (module docstring).

    ``rigid``: the rigid gap at every full node (flat, full grid); ``rs``: the local radius ratio
    (entrainment speed and curvature) per full y row; ``lam``: the wedge coefficient; ``w_bar``: the
    scaled load; ``p_scale`` [Pa]: the pressure unit (for the lubricant laws); ``elastic``: ``"dense"``
    (influence matrix), ``"fft"`` (uniform grids: 2-D DC-FFT), ``"xfft"`` (grids uniform in x: FFT along x, dense
    along y, :class:`~transient.physics.elasticity.RowConvolution`) or ``"rigid"``; ``elastic_factor``: ``k_el``;
    ``order2``: second-order upwind Couette flux (else first order); ``limiter``: second order with van
    Albada's limiter (:mod:`transient.models.ehl.rows`).
    """

    def __init__(self, grid: TensorGrid, rigid, rs, lam: float, w_bar: float, lubricant: Lubricant, p_scale: float,
                 elastic: str = "dense", elastic_factor: float = 1.0, order2: bool = True, kernel=None, *,
                 limiter: bool = False):
        if elastic not in ELASTIC:
            raise ValueError(f"elastic = {elastic!r} is not one of {ELASTIC}")
        if elastic == "fft" and not (grid.two_d and grid.uniform):
            raise ValueError("FFT elasticity needs a uniform 2-D grid")
        if elastic == "xfft" and not (grid.two_d and grid.uniform_x):
            raise ValueError("FFT-in-x elasticity needs a 2-D grid uniform in x")
        self.grid = grid
        self.n = grid.n
        self.n_full = grid.x.size * (grid.y.size if grid.two_d else 1)
        self.rigid = np.ascontiguousarray(rigid, dtype=float).ravel()
        if self.rigid.size != self.n_full:
            raise ValueError(f"rigid gap has {self.rigid.size} values, the grid {self.n_full} nodes")
        self.rs = np.ascontiguousarray(rs, dtype=float)
        self.lam = float(lam)
        self.w_bar = float(w_bar)
        self.lubricant = lubricant
        self.p_scale = float(p_scale)
        self.rheo_args = lubricant.kernel_args()
        self.elastic = elastic
        self.k_el = float(elastic_factor)
        self.order2 = bool(order2)
        #: Couette flux of the kernel: 0 first-order upwind, 1 second-order, 2 second-order with van Albada's limiter
        self.scheme_code = 2 if limiter else int(self.order2)
        self.area = grid.area
        self.area_w = self.area / self.w_bar
        self.colp, self.colh = slot_maps(grid)
        self.y_nodes = grid.y if grid.two_d else np.zeros(1)
        self.K = None
        self._K32 = None
        self.conv = None
        if elastic == "dense":
            self.K = kernel if kernel is not None else self.influence_matrix()
        elif elastic == "fft":
            g = grid
            self.conv = SurfaceConvolution(g.x.size, g.y.size, g.x[1] - g.x[0], g.y[1] - g.y[0], scale=self.k_el)
        elif elastic == "xfft":
            g = grid
            self.conv = RowConvolution(g.x.size, g.x[1] - g.x[0], g.y, g.y_edges, scale=self.k_el)
        self.F = np.empty(self.n)
        self.Sp = np.zeros((self.n, N_SLOTS))
        self.Sh = np.zeros((self.n, N_SLOTS))
        self.St = np.zeros((self.n, N_SLOTS))
        self.scale = np.empty(self.n)
        self._t_ones = np.ones(grid.shape_full)
        self.props = np.empty((7, self.n_full))
        self.fb_a = np.empty(self.n)
        self.fb_b = np.empty(self.n)
        self.phi = np.empty(self.n)
        self._p_full = np.zeros(grid.shape_full)
        self.row_scale = np.ones(self.n)
        #: complementarity form: None for Fischer-Burmeister, else the penalty factor gamma (the transient's)
        self.penalty = None

    # -- elasticity ------------------------------------------------------------------------------
    def influence_matrix(self) -> np.ndarray:
        """Dense ``dh/dp`` (n_full, n): scaled film at every node per unit scaled pressure of each patch."""
        g = self.grid
        if g.two_d:
            return self.k_el * surface_influence(g.x, g.y, g.x_edges, g.y_edges)
        return self.k_el * line_influence(g.x, g.x_edges)

    def deformation(self, p) -> np.ndarray:
        """Elastic film (flat, full grid) of the interior pressures ``p``."""
        if self.elastic == "dense":
            return self.K @ p
        if self.elastic == "fft":
            return self.conv.apply(self.grid.full(p)).ravel()
        if self.elastic == "xfft":
            return self.conv.apply(self.grid.full(p)[1:-1]).ravel()
        return np.zeros(self.n_full)

    def deformation_approx(self, p) -> np.ndarray:
        """:meth:`deformation` with the dense matrix in single precision (relative error ~1e-7; half
        the memory traffic): for Jacobian-vector products inside GMRES, never for residuals."""
        if self.elastic == "dense":
            if self._K32 is None:
                self._K32 = self.K.astype(np.float32)
            return self._K32 @ p.astype(np.float32)
        return self.deformation(p)

    def film(self, p, h0) -> np.ndarray:
        """Film ``h`` at every full node (flat)."""
        return h0 + self.rigid + self.deformation(p)

    def step_limit(self, u, du) -> float:
        """Largest fraction (<= 1) of the step ``du`` that keeps the film at every node above a tenth of
        its value at ``u`` (the film is affine in ``u``); 1 where the film is not positive already."""
        h = self.film(u[:-1], u[-1])
        dh = du[-1] + self.deformation(du[:-1])
        shrink = (dh < 0.0) & (h > 0.0)
        if not np.any(shrink):
            return 1.0
        return float(min(1.0, np.min(0.9 * h[shrink] / -dh[shrink])))

    # -- equations -------------------------------------------------------------------------------
    def full_pressure(self, p) -> np.ndarray:
        pf = self._p_full
        if self.grid.two_d:
            pf[1:-1, 1:-1] = p.reshape(self.grid.ny, self.grid.nx)
        else:
            pf[0, 1:-1] = p
        return pf

    def reynolds(self, p, h, jac: bool = False, content=None) -> np.ndarray:
        """Reynolds residual ``F`` (per unit area) at the interior nodes and the row scales ``scale``; ``jac``:
        also ``Sp``, ``Sh`` (and ``St``). ``content``: the film content theta at every full node (flat or
        ``shape_full``; None: a full film, the Reynolds-condition form)."""
        v, al, ln0, d, c1, c2 = self.rheo_args
        t = self._t_ones if content is None else np.asarray(content, float).reshape(self.grid.shape_full)
        rows_kernel(self.full_pressure(p), h.reshape(self.grid.shape_full), t, self.grid.x, self.y_nodes, self.rs,
                    self.lam, self.grid.two_d, self.scheme_code, v, al, ln0, d, c1, c2, self.p_scale, jac, self.F,
                    self.Sp, self.Sh, self.St, self.scale, self.props, ALL_SLOTS)
        return self.F

    def set_row_scale(self, u) -> None:
        """Scale each Reynolds row by ``1/d_i``, ``d_i`` the magnitude of its Poiseuille diagonal plus
        ``lam Rs`` at ``u``, so that ``-F_i/d_i`` is a pressure-like quantity comparable with ``p_i`` in
        the Fischer-Burmeister pair and in the Newton merit function. A positive row scaling does not
        change the complementarity solution; the penalty form is not invariant, so there the scale is 1."""
        if self.penalty is not None:
            self.row_scale = np.ones(self.n)
            return
        p, h0 = u[:-1], u[-1]
        self.reynolds(p, self.film(p, h0))
        g = self.grid
        eps = self.props[2].reshape(g.shape_full)
        x = g.x
        dxc = g.dx[1:-1]
        rows = eps[1:-1] if g.two_d else eps
        d = (0.5 * (rows[:, 1:-1] + rows[:, 2:]) / np.diff(x)[1:]
             + 0.5 * (rows[:, 1:-1] + rows[:, :-2]) / np.diff(x)[:-1]) / dxc
        rs = self.rs[1:-1] if g.two_d else self.rs
        d = d + self.lam * rs[:, None]
        if g.two_d:
            y = g.y
            dyc = g.dy[1:-1][:, None]
            cols = eps[:, 1:-1]
            d += (0.5 * (cols[1:-1] + cols[2:]) / np.diff(y)[1:, None]
                  + 0.5 * (cols[1:-1] + cols[:-2]) / np.diff(y)[:-1, None]) / dyc
        self.row_scale = 1.0 / np.abs(d.ravel())

    def complementarity(self, p, b, out) -> None:
        """``out = phi(p, b)`` and its derivatives into ``fb_a``, ``fb_b``: Fischer-Burmeister, or the
        penalty form when ``self.penalty`` is set (:mod:`transient.models.roller.kernels`); the Fischer-Burmeister
        gradient's element at the kink is the symmetric one (:mod:`transient.models.ehl.complementarity`)."""
        if self.penalty is None:
            out[:], rad = fb_value(p, b)
            self.fb_a[:], self.fb_b[:] = fb_gradient(p, b, rad, SYMMETRIC_KINK)
        else:
            penalty(p, b, out, self.fb_a, self.fb_b, self.penalty)

    def residual(self, u) -> np.ndarray:
        """``[phi(p, -F/d); (sum A p - W)/W]`` at ``u = [p, h0]`` (``1/d``: :meth:`set_row_scale`)."""
        p, h0 = u[:-1], u[-1]
        F = self.reynolds(p, self.film(p, h0))
        out = np.empty(self.n + 1)
        self.complementarity(p, -F * self.row_scale, out[:-1])
        out[-1] = self.area_w @ p - 1.0
        return out

    def add_storage(self, p, h, shift: float) -> None:
        """Add ``shift`` times the storage term of the transient, ``-lam d(rho h)/du`` (time in units of
        b/u), to the local Jacobian ``Sp``, ``Sh`` (after :meth:`reynolds` with ``jac=True``): a
        pseudo-transient Newton step is then a backward-Euler step of the physical squeeze-film
        dynamics (:func:`~transient.solvers.newton.newton`, ``pseudo_time``)."""
        c = self.colh[:, 0]
        rho, drho = self.props[0][c], self.props[1][c]
        self.Sp[:, 0] -= shift * self.lam * drho * h[c]
        self.Sh[:, 0] -= shift * self.lam * rho

    def jacobian(self, u, shift: float = 0.0) -> np.ndarray:
        """Dense semismooth Newton matrix at ``u`` (plus ``shift`` times the storage term)."""
        p, h0 = u[:-1], u[-1]
        h = self.film(p, h0)
        F = self.reynolds(p, h, jac=True)
        if shift:
            self.add_storage(p, h, shift)
        self.complementarity(p, -F * self.row_scale, self.phi)
        J = np.empty((self.n + 1, self.n + 1))
        K = self.K if self.elastic == "dense" else np.zeros((1, 1))
        assemble_dense(self.Sp, self.Sh, self.colp, self.colh, K, self.elastic == "dense", self.fb_a,
                       self.fb_b * self.row_scale, self.area_w, J)
        return J

    def reynolds_jacobian_dense(self, u) -> np.ndarray:
        """Dense ``[dF/dp, dF/dh0]`` (n, n+1) of the Reynolds residual alone (tests, the squeeze DAE)."""
        p, h0 = u[:-1], u[-1]
        self.reynolds(p, self.film(p, h0), jac=True)
        J = np.empty((self.n + 1, self.n + 1))
        K = self.K if self.elastic == "dense" else np.zeros((1, 1))
        ones = np.ones(self.n)
        assemble_dense(self.Sp, self.Sh, self.colp, self.colh, K, self.elastic == "dense", np.zeros(self.n), -ones,
                       self.area_w, J)
        return J[:-1]


def solve_steady(film: EHLFilm, u0, *, tol: float = 1e-9, max_iter: int = 60, jacobian=None,
                 pseudo_time: float | None = None, name: str = "EHL Newton"):
    """Semismooth Newton on ``film``'s equations (:func:`transient.solvers.newton.newton`).

    Steps are shortened so that the film stays above a tenth of its current value
    (:meth:`EHLFilm.step_limit`); with ``pseudo_time`` (initial step, units of b/u) the first iterations
    are backward-Euler steps of the physical squeeze-film transient (:meth:`EHLFilm.add_storage`) with
    a growing step, else a backtracking line search globalises. Converged when
    ``|residual|_inf <= tol`` and the last step ``<= tol max(1, |u|_inf)`` (scaled units).
    ``jacobian(u, shift)``: the film's dense matrix by default, or e.g. a Krylov solver object.
    Raises :class:`~transient.solvers.newton.NewtonError` (with the histories) otherwise."""
    film.set_row_scale(u0)

    def converged(u, r, du):
        return float(np.max(np.abs(r))) <= tol and float(np.max(np.abs(du))) <= tol * max(1.0, float(np.max(np.abs(u))))

    return newton(film.residual, jacobian or film.jacobian, u0, converged=converged,
                  settings=NewtonSettings(max_iter=max_iter, pseudo_time=pseudo_time), max_step=film.step_limit,
                  name=name)


def interpolate_state(grid_from: TensorGrid, u_from, grid_to: TensorGrid) -> np.ndarray:
    """``[p, h0]`` of one grid carried to another: pressure interpolated linearly (zero on the boundary),
    ``h0`` kept (nested iteration: coarse solution as the fine initial guess)."""
    pf = grid_from.full(u_from[:-1])
    if grid_to.two_d:
        from scipy.interpolate import RegularGridInterpolator

        f = RegularGridInterpolator((grid_from.y, grid_from.x), pf, bounds_error=False, fill_value=0.0)
        yy, xx = np.meshgrid(grid_to.y[1:-1], grid_to.x[1:-1], indexing="ij")
        p = f(np.stack([yy.ravel(), xx.ravel()], axis=1))
    else:
        p = np.interp(grid_to.x[1:-1], grid_from.x, pf[0])
    return np.append(p, u_from[-1])
