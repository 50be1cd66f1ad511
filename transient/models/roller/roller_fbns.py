"""Mass-conserving (film-content) film of the tilted tapered roller for the Fischer-Burmeister-Newton-Schur
iteration.

Park's finite line contact (:mod:`transient.models.roller.contact`) in the fractional-film form of
Jakobsson-Floberg-Olsson / Elrod as solved by FBNS (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.* 58,
2015; Hansen, Kacan, Frohnapfel & Codrignani, *Tribol. Lett.* 70, 2022, with the elastic film). Scaled units
and finite volumes of :mod:`transient.models.ehl.rows` on the full (not mirrored: the tilted roller is
not symmetric) non-uniform tensor grid; per interior node::

    R = { Poiseuille fluxes along x and y - lam Rs(y) dy (q_{I+1/2} - q_{I-1/2}) } / A = 0,   m = rho theta h
    FB(p, 1 - theta) = 0,   FB(a, b) = a + b - sqrt(a^2 + b^2)     (p >= 0, theta <= 1, p (1 - theta) = 0)
    sum A p / w_bar - 1 = 0                                         (the unknown h0)

with ``h = h0 + h_rigid + K p`` (:class:`~transient.models.roller.ehl_problem.EHLFilm`'s dense influence
matrix). Where ``theta = 1`` the Reynolds rows are those of the Reynolds-condition form (``EHLFilm``); the
two discrete problems differ only where the film ruptures. The Fischer-Burmeister pair is linear in the
unknowns, so Newton's steps stay meaningful far from the solution (no pseudo-time).

:class:`RollerContentFilm` gives the residual pieces as
:class:`transient.models.roller.line_fbns.LineContentFilm` (``equations``, ``fb_derivatives``,
``schur_matrix``, ``jacobian_product``), so that the line contact's Newton with a reused single-precision
factorisation (:func:`transient.models.roller.line_newton.content_newton`) and the node-wise elimination of
:func:`transient.models.ehl.reduced.schur` solve it unchanged.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
from numba import njit

from transient.checks import check_memory
from transient.models.ehl.complementarity import CavitationRows, fb_residual
from transient.models.ehl.reduced import schur_rows
from transient.models.roller.ehl_problem import EHLFilm
from transient.models.roller.grid import TensorGrid
from transient.models.roller.line_newton import content_newton
from transient.models.roller.roller_fft import RollerTwoLevel
from transient.models.roller.roller_lines import LineBlocks
from transient.solvers.newton import NewtonError


class RollerContentFilm(CavitationRows):
    """The film-content form (module docstring) of a 2-D :class:`EHLFilm`; unknowns ``u = [p (n), theta (n),
    h0]``, interior nodes x fastest. The Schur matrix needs the dense influence matrix: a uniform grid's
    DC-FFT film gets it built (``K``, ``n_full x n`` doubles)."""

    def __init__(self, film: EHLFilm, coarse: RollerContentFilm | None = None):
        if not film.grid.two_d or film.elastic == "rigid":
            raise ValueError("RollerContentFilm: a 2-D grid with an elastic film")
        self.base = film
        self.grid = film.grid
        self.n = film.n
        #: ``coarse`` given (a DC-FFT film): the Schur matrix is never formed; ``content_newton`` takes matrix-free
        #: steps (:mod:`transient.models.roller.roller_fft`) preconditioned on ``coarse`` (a dense content film);
        #: an FFT-in-x film (``"xfft"``): matrix-free steps preconditioned by its x-line blocks
        #: (:mod:`transient.models.roller.roller_lines`)
        self.lines = film.elastic == "xfft"
        self.matrix_free = coarse is not None or self.lines
        self.coarse = coarse
        if coarse is not None and film.elastic != "fft":
            raise ValueError(f"RollerContentFilm: matrix-free steps need a DC-FFT film, got elastic = {film.elastic!r}")
        if self.lines:
            self.refresh_iters = LineBlocks.refresh_iters
            self.forcing = LineBlocks.forcing
        if film.elastic != "dense" and not self.matrix_free:
            check_memory(f"the dense influence matrix of this {film.grid.nx} x {film.grid.ny} grid",
                         dict(influence=8.0 * film.n_full * film.n, schur=12.0 * (film.n + 1) ** 2),
                         "use a clustered grid or method='reynolds' (Newton-Krylov with DC-FFT products)")
        self.K = None if self.matrix_free else film.K if film.elastic == "dense" else film.influence_matrix()
        self.weight = film.area_w
        self.colp, self.colh = film.colp, film.colh
        self._hp = self.colh >= 0

    def split(self, u):
        """``(p, theta full (ny_full, nx_full), h0)``: theta = 1 on the boundary (a flooded inlet)."""
        n = self.n
        return u[:n], self.grid.full(u[n: 2 * n], boundary=1.0), float(u[-1])

    def film(self, u) -> np.ndarray:
        """Film ``h`` at every full node (flat)."""
        return self.base.film(u[: self.n], u[-1])

    def equations(self, u, load_ratio=1.0):
        """Residual pieces at ``u`` (as :meth:`transient.models.point.ehl_problem.PointFilm.equations`): the
        film ``H``, Reynolds rows ``res`` and their scales, the local derivatives ``dp``, ``dh``, ``dt``
        (n, 6 slots), the Fischer-Burmeister rows ``fb`` and the load balance."""
        b = self.base
        p, t, h0 = self.split(u)
        H = b.film(p, h0)
        b.reynolds(p, H, jac=True, content=t)
        fb, rad = fb_residual(p, u[self.n: 2 * self.n])
        return dict(H=H, res=b.F.copy(), scale=b.scale.copy(), dp=b.Sp.copy(), dh=b.Sh.copy(), dt=b.St.copy(),
                    fb=fb, rad=rad, load=self.weight @ p - load_ratio)

    def schur_matrix(self, e, b_p, b_t) -> np.ndarray:
        """Dense ``(n + 1)`` Schur matrix of the Newton step after ``dp = b_p z``, ``dtheta = b_t z``
        (:func:`~transient.models.ehl.reduced.schur_rows`)."""
        S = np.empty((self.n + 1, self.n + 1))
        schur_rows(e["dp"], e["dh"], e["dt"], self.colp, self.colh, self.K, True, b_p, b_t, self.weight, S)
        return S

    def two_level(self, A, u):
        """The matrix-free step's preconditioner: :class:`~transient.models.roller.roller_lines.LineBlocks` on an
        FFT-in-x film, else :class:`~transient.models.roller.roller_fft.RollerTwoLevel` on the coarse film."""
        if self.lines:
            return LineBlocks(A)
        return RollerTwoLevel(A, carry_content(self.grid, u, self.coarse.grid), self.coarse)

    def storage_terms(self):
        """``(rho, rho h, d(rho h)/dp)`` at the interior nodes of the last :meth:`equations`: the pieces of the
        transient's storage ``q = rho theta h`` (:mod:`transient.models.roller.line_step`)."""
        c = self.colh[:, 0]
        props = self.base.props
        return props[0][c], props[5][c], props[6][c]

    def local_columns(self) -> np.ndarray:
        """The interior node of each local slot of each row (n, 6; -1: none), as ``equations``' ``dt``."""
        return self.colp

    def jacobian_product(self, e, v_p, v_t) -> np.ndarray:
        """``J_p v_p + J_theta v_t``: the Reynolds rows' response to pressure and content changes."""
        return local_product(e["dh"], e["dp"], e["dt"], self.colh, self.colp, self.base.deformation(v_p), v_p, v_t)

    def residual(self, u) -> np.ndarray:
        """The whole residual ``[R, FB, load]`` (tests: finite differences)."""
        e = self.equations(u)
        return np.concatenate([e["res"], e["fb"], [e["load"]]])

    def jacobian_dense(self, u) -> np.ndarray:
        """The whole Newton matrix in ``[p, theta, h0]`` (tests; ``O(n^2)`` memory)."""
        n = self.n
        e = self.equations(u)
        J = np.zeros((2 * n + 1, 2 * n + 1))
        eye = np.eye(n)
        for k in range(n):  # columns by products (tests only)
            J[:n, k] = self.jacobian_product(e, eye[k], np.zeros(n))
            J[:n, n + k] = self.jacobian_product(e, np.zeros(n), eye[k])
        J[:n, -1] = e["dh"].sum(axis=1, where=self._hp)
        a, g = self.fb_derivatives(u, e)
        J[n: 2 * n, :n] = np.diag(a)
        J[n: 2 * n, n: 2 * n] = np.diag(g)
        J[-1, :n] = self.weight
        return J


@njit(cache=True)
def local_product(dh, dp, dt, colh, colp, h, v_p, v_t):
    """Per row ``r``: ``sum_s dh[r, s] h[colh[r, s]] + dp[r, s] v_p[colp[r, s]] + dt[r, s] v_t[colp[r, s]]`` over the
    slots present (column index >= 0): the Reynolds rows' response to a film change ``h`` (full nodes) and
    pressure and content changes (interior nodes)."""
    n, m = dh.shape
    out = np.empty(n)
    for r in range(n):
        a = 0.0
        for s in range(m):
            if colh[r, s] >= 0:
                a += dh[r, s] * h[colh[r, s]]
        b = 0.0
        for s in range(m):
            q = colp[r, s]
            if q >= 0:
                b += dp[r, s] * v_p[q] + dt[r, s] * v_t[q]
        out[r] = a + b
    return out


def carry_content(grid_from: TensorGrid, u, grid_to: TensorGrid, p_factor: float = 1.0) -> np.ndarray:
    """``[p, theta, h0]`` of one grid on another (bilinear interpolation; ``p = 0``, ``theta = 1`` on the
    boundary and outside), the pressure times ``p_factor``."""
    from scipy.interpolate import RegularGridInterpolator

    n = grid_from.n
    yy, xx = np.meshgrid(grid_to.y[1:-1], grid_to.x[1:-1], indexing="ij")
    pts = np.stack([yy.ravel(), xx.ravel()], axis=1)
    out = []
    for part, edge in ((u[:n] * p_factor, 0.0), (u[n: 2 * n], 1.0)):
        f = RegularGridInterpolator((grid_from.y, grid_from.x), grid_from.full(part, boundary=edge),
                                    bounds_error=False, fill_value=edge)
        out.append(f(pts))
    return np.concatenate(out + [[u[-1]]])


def content_start(contact, cfilm: RollerContentFilm) -> np.ndarray:
    """``[p, theta, h0]``: the Reynolds-condition start of ``contact`` (its dry pressure, an inlet ramp and the
    Dowson-Toyoda central film, :meth:`RollerContact.initial_guess`) with, downstream of the centre line where
    the dry pressure is zero, the content ``theta = h_c/h`` of a film carried at the central flux (so that no
    node starts at the kink ``p = 1 - theta = 0`` except upstream, where the film is full)."""
    g = cfilm.grid
    u = contact.initial_guess(cfilm.base)
    p, h0 = u[:-1], u[-1]
    h = cfilm.base.film(p, h0).reshape(g.shape_full)
    hc = h[int(np.argmin(np.abs(g.y))), int(np.argmin(np.abs(g.x)))]
    hi = h[1:-1, 1:-1].ravel()
    x = np.broadcast_to(g.x[None, 1:-1], (g.ny, g.nx)).ravel()
    theta = np.where((x > 0.0) & (p <= 0.0), np.clip(hc / np.where(hi > 0.0, hi, np.inf), 0.0, 1.0), 1.0)
    return np.concatenate([p, theta, [h0]])


def solve_content(cfilm: RollerContentFilm, u0, tol: float, max_iter: int, name: str):
    """:func:`~transient.models.roller.line_newton.content_newton` on ``cfilm`` from ``u0``: a result with ``x``,
    ``iterations``, ``factorisations``, ``residual_norms``, or :class:`~transient.solvers.newton.NewtonError`
    carrying it."""
    u, ok, st = content_newton(cfilm, u0, tol=tol, max_iter=max_iter)
    out = SimpleNamespace(x=u, iterations=st.iterations, factorisations=st.factorisations, krylov=st.krylov,
                          krylov_misses=st.krylov_misses, residual_norms=st.norms)
    if not ok:
        raise NewtonError(f"{name}: no convergence in {st.iterations} iterations (scaled residual "
                          f"{st.norms[-1]:.3g} > {tol:g})", out)
    return out
