"""Finite plain journal bearing with a mass-conserving Elrod film: steady film, static equilibrium,
linearised stiffness/damping and the Lund stability threshold (Rho & Kim, seed 003).

All public arguments and results are SI (m, Pa, Pa s, N, rpm). The discretisation and the
dimensionless groups are in :mod:`transient.models.journal.kernels`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla
from scipy.optimize import brentq

from transient.physics.cavitation import softplus
from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import ReynoldsOperator
from transient.solvers.newton import NewtonError, newton
from transient.models.journal.kernels import N_ROTOR, FilmWork, film_force, film_jacobian, film_residual
from transient.checks import check_positive, check_range




#: Default pressure width of the Elrod switch as a fraction of p0 = 6 mu omega (R/C)^2 (docs/journal.md).
SWITCH_WIDTH_P0 = 1e-4


@dataclass(frozen=True)
class Groove:
    """Axial oil-supply groove: centre angle from the top of the bearing (opposite the load) in the
    direction of rotation [deg], angular width [deg]. It spans the whole length; its cells are held
    at the bearing's supply pressure."""

    angle_deg: float = 0.0
    width_deg: float = 6.0

    def __post_init__(self):
        check_range("groove.width_deg", self.width_deg, "deg", 0.0, 90.0, low_open=True)


@dataclass
class FilmState:
    """A film solution with the journal at a fixed position (and, optionally, moving).

    ``pressure`` [Pa, absolute] and ``film_content`` (theta = rho/rho_c) are (n_axial, n_theta) arrays on
    the modelled grid (half bearing when symmetric; row 0 next to the mid-plane); ``angle_deg`` and
    ``z`` [m] are the cell-centre coordinates. ``force`` [N] is the film force on the journal
    (x towards the load, y at +90 deg in the direction of rotation), ``load`` [N] its magnitude (the
    external load it carries) and ``attitude_angle_deg`` the angle from the load line to the line of
    centres, in the direction of rotation.
    """

    eccentricity_ratio: float
    attitude_angle_deg: float
    position: tuple[float, float]
    force: tuple[float, float]
    load: float
    min_film: float
    speed_rpm: float
    pressure: np.ndarray
    film_content: np.ndarray
    angle_deg: np.ndarray
    z: np.ndarray
    u: np.ndarray = field(repr=False)
    newton_iterations: int = 0

    @property
    def max_pressure(self) -> float:
        return float(self.pressure.max())


class JournalBearing:
    """Plain journal bearing, Elrod (JFO) mass-conserving film, rigid journal.

    Parameters (SI)
    ----------
    diameter, length, clearance [m] : journal diameter D, bearing length L, radial clearance C.
    viscosity [Pa s], bulk_modulus [Pa] : mu and beta (paper: 1e9; 1e12 is the incompressible limit).
    supply_pressure [Pa, absolute] : pressure in the groove (paper: 1 atm).
    groove : :class:`Groove` or None (no groove: the film is fed only through its ends).
    grid : (n_theta, n_axial) cells; n_axial covers the half length when ``symmetric`` (paper 151 x 21).
    cavitation_pressure, ambient_pressure [Pa, absolute] : p_c and the pressure at the bearing ends
        (paper: both 0).
    switch_width [Pa] : pressure width of the smooth Elrod switch; it biases the load linearly
        (convergence study in docs/journal.md). Default ``None``: ``SWITCH_WIDTH_P0`` p0 at each speed
        (p0 = 6 mu omega (R/C)^2; 2.7 kPa for the paper's bearing at 6000 rpm), which keeps the bias
        the same at every speed (about +0.15 % on the load).
    switch_content_width [-] : content width of the switch (the film-content deficit over which a cell
        fills or empties); it hardly biases the film but sets how abruptly a cell turns at rupture and
        reformation, so a wider one saves the orbit integrator time steps (docs/journal.md, section 3).
    symmetric : model half the length with a symmetry plane at the mid-plane (exact for this model).
    """

    def __init__(self, diameter, length, clearance, viscosity, bulk_modulus=1e9, supply_pressure=101325.0,
                 groove: Groove | None = Groove(), grid=(151, 21), cavitation_pressure=0.0, ambient_pressure=0.0,
                 switch_width=None, switch_content_width=1e-2, symmetric=True):
        self.diameter = check_positive("diameter", diameter, "m")
        self.length = check_positive("length", length, "m")
        self.clearance = check_positive("clearance", clearance, "m")
        check_range("clearance", clearance, "m", 0.0, 0.1 * diameter, low_open=True,
                    why="(a clearance above D/10 is not a journal bearing)")
        self.viscosity = check_positive("viscosity", viscosity, "Pa s")
        self.bulk_modulus = check_positive("bulk_modulus", bulk_modulus, "Pa")
        self.cavitation_pressure = float(cavitation_pressure)
        self.ambient_pressure = check_range("ambient_pressure", ambient_pressure, "Pa", cavitation_pressure, np.inf,
                                            why="(must be >= cavitation_pressure)")
        self.supply_pressure = check_range("supply_pressure", supply_pressure, "Pa", cavitation_pressure, np.inf,
                                           why="(must be >= cavitation_pressure)")
        self.switch_width = None if switch_width is None else check_positive("switch_width", switch_width, "Pa")
        self.switch_content_width = check_range("switch_content_width", switch_content_width, "-", 0.0, 0.1,
                                                low_open=True, why="(a content deficit; above 0.1 the switch "
                                                "smears the cavitated zone)")
        if groove is not None and not isinstance(groove, Groove):
            raise TypeError(f"groove must be a Groove or None, got {type(groove).__name__}")
        self.groove = groove
        try:
            n_theta, n_axial = (int(v) for v in grid)
        except (TypeError, ValueError):
            raise ValueError(f"grid must be (n_theta, n_axial), got {grid!r}") from None
        check_range("grid[0] (n_theta)", n_theta, "cells", 8, 20000)
        check_range("grid[1] (n_axial)", n_axial, "cells", 1, 5000)
        self.grid_shape = (n_theta, n_axial)
        self.symmetric = bool(symmetric)
        self.radius = 0.5 * self.diameter
        self._build_grid()

    # ---------------------------------------------------------------------------------------------
    def _build_grid(self):
        n_theta, n_axial = self.grid_shape
        R = self.radius
        half = 0.5 * self.length / R
        x = Axis.uniform(n_theta, 2 * np.pi, start=0.0, centred=True, periodic=True, name="theta")
        if self.symmetric:
            z = Axis.uniform(n_axial, half, start=0.0, lower="symmetry", upper="dirichlet", name="z")
        else:
            z = Axis.uniform(n_axial, 2 * half, start=-half, lower="dirichlet", upper="dirichlet", name="z")
        fixed = None
        if self.groove is not None:
            phi = x.centres
            dphi = np.angle(np.exp(1j * (phi - np.radians(self.groove.angle_deg))))
            in_groove = np.abs(dphi) <= 0.5 * np.radians(self.groove.width_deg) + 1e-12
            if not in_groove.any():
                in_groove[np.argmin(np.abs(dphi))] = True  # a groove narrower than a cell takes the nearest cell
            fixed = np.tile(in_groove, z.n)
        self.grid = Grid2D(x, z, fixed=fixed, fixed_values=0.0)
        self.phi = self.grid.xc.copy()
        self.n_cells = self.grid.n

    def pressure_scale(self, speed_rpm) -> float:
        """p0 = 6 mu omega (R/C)^2 [Pa], the dimensionless pressure unit at this speed."""
        return 6.0 * self.viscosity * omega(speed_rpm) * (self.radius / self.clearance) ** 2

    def film(self, speed_rpm, n_extra=N_ROTOR) -> "Film":
        """The discretised film at a shaft speed (scales, operator, scratch arrays)."""
        return Film(self, speed_rpm, n_extra)

    # ---------------------------------------------------------------------------------------------
    def steady_state(self, eccentricity_ratio, speed_rpm, position_angle_deg=0.0) -> FilmState:
        """Film with the journal held at eccentricity ratio ``eps`` in the direction ``position_angle_deg``
        (from the load line +x, in the direction of rotation); a direct Newton solve."""
        eps = check_range("eccentricity_ratio", eccentricity_ratio, "-", 0.0, 1.0, high_open=True)
        check_positive("speed_rpm", speed_rpm, "rpm")
        a = np.radians(position_angle_deg)
        f = self.film(speed_rpm)
        u, its = f.solve(eps * np.cos(a), eps * np.sin(a))
        return f.state(u, eps * np.cos(a), eps * np.sin(a), its)

    def equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40) -> FilmState:
        """Static equilibrium under ``load`` [N] (in +x): 2-D Newton on the journal position with the
        exact derivative of the discrete film force (implicit differentiation of the film equations)."""
        f, u, q, it, _ = self._equilibrium(load, speed_rpm, tol, max_iter)
        return f.state(u, q[0], q[1], it)

    def coefficients(self, load, speed_rpm) -> tuple[np.ndarray, np.ndarray]:
        """Linearised stiffness K [N/m] and damping C [N s/m] (2x2, x towards the load) at the static
        equilibrium, from the same discrete film: ``K = -dF/dx``, ``C = -dF/d(dx/dt)``."""
        f, _, _, _, (dF_dq, dF_dv) = self._equilibrium(load, speed_rpm)
        K = -dF_dq * f.force_scale / self.clearance
        Cmat = -dF_dv * f.force_scale / (self.clearance * omega(speed_rpm))
        return K, Cmat

    def _equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40):
        """Newton on the journal position; returns (film, u, (X, Y), iterations, (dF/dq, dF/dv)) with the
        force sensitivities at the converged state (they are the Newton matrix and the damping)."""
        W = check_positive("load", load, "N")
        check_positive("speed_rpm", speed_rpm, "rpm")
        f = self.film(speed_rpm)
        wbar = W / f.force_scale
        q = np.array([0.3, 0.3])  # eccentric start in the loaded quadrant
        u = None
        for it in range(max_iter):
            u, _ = f.solve(q[0], q[1], u0=u)
            F, dF_dq, dF_dv = f.force_sensitivity(u, q[0], q[1])
            r = np.array([F[0] + wbar, F[1]])
            if np.max(np.abs(r)) <= tol * max(wbar, 1e-300):
                return f, u, q, it, (dF_dq, dF_dv)
            dq = -np.linalg.solve(dF_dq, r)
            lam = 1.0  # keep the journal inside the clearance
            while np.hypot(*(q + lam * dq)) >= 0.995:
                lam *= 0.5
            q = q + lam * dq
        raise RuntimeError(f"equilibrium(load={W} N, speed_rpm={speed_rpm}) did not converge in {max_iter} "
                           f"iterations; last eccentricity ratio {np.hypot(*q):.4f}, force residual "
                           f"{np.max(np.abs(r)) * f.force_scale:.3e} N")

    def growth_rate(self, rotor_mass, load, speed_rpm) -> float:
        """Largest real part [1/s] of the eigenvalues of the linearised rotor (m x'' + C x' + K x = 0)."""
        K, Cm = self.coefficients(load, speed_rpm)
        m = rotor_mass
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K / m, -Cm / m]])
        return float(np.max(sla.eigvals(A).real))

    def stability_threshold(self, rotor_mass, load, speed_range_rpm=(500.0, 30000.0), rtol=1e-4) -> float:
        """Onset speed of oil whirl [rpm] of a rigid rotor of mass ``rotor_mass`` [kg] carried by this
        bearing under ``load`` [N]: the speed at which the linearised system (Lund's method, with K and C
        from the same discrete film) first has an eigenvalue with zero real part."""
        m = check_positive("rotor_mass", rotor_mass, "kg")
        check_positive("load", load, "N")
        lo, hi = speed_range_rpm
        g = lambda n: self.growth_rate(m, load, n)
        speeds = np.geomspace(lo, hi, 9)
        vals = [g(n) for n in speeds]
        for k in range(len(speeds) - 1):
            if vals[k] < 0 <= vals[k + 1]:
                return float(brentq(g, speeds[k], speeds[k + 1], rtol=rtol))
        raise ValueError(f"no stability threshold between {lo} and {hi} rpm for rotor_mass={m} kg, load={load} N "
                         f"(largest growth rates {vals[0]:.3g} ... {vals[-1]:.3g} 1/s)")


def omega(speed_rpm) -> float:
    """Shaft angular speed [rad/s] from [rpm]."""
    return 2.0 * np.pi * float(speed_rpm) / 60.0


class Film:
    """The discretised film of a bearing at one shaft speed: scales, the operator with ``n_extra``
    trailing unknowns, scratch arrays, and the steady / sensitivity solves."""

    def __init__(self, bearing: JournalBearing, speed_rpm, n_extra=N_ROTOR):
        b = bearing
        self.bearing = b
        self.speed_rpm = float(speed_rpm)
        self.omega = omega(speed_rpm)
        self.p0 = b.pressure_scale(speed_rpm)
        self.beta_bar = b.bulk_modulus / self.p0
        self.width = SWITCH_WIDTH_P0 if b.switch_width is None else b.switch_width / self.p0
        self.content_scale = b.switch_content_width / self.width  # r: content width / pressure width
        self.force_scale = self.p0 * b.radius ** 2  # N per unit of Fbar
        u_supply = (b.supply_pressure - b.cavitation_pressure) / self.p0
        u_amb = (b.ambient_pressure - b.cavitation_pressure) / self.p0
        P_amb, _ = softplus(np.array([u_amb]), self.width)
        C_amb = 1.0 + P_amb[0] / self.beta_bar + self.content_scale * (u_amb - P_amb[0])  # theta = C(u_amb)
        self.op = ReynoldsOperator(b.grid, n_extra=n_extra, upwind=True, boundary_P=float(P_amb[0]),
                                   boundary_C=float(C_amb))
        self.op.u_fixed[~self.op.free] = u_supply  # groove cells at the supply pressure
        self.w = FilmWork(self.op, b.phi, b.symmetric)
        self.n = self.op.n_cells
        self.u_supply = u_supply

    # residual / Jacobian of the prescribed-motion film equations G(u) = 0 --------------------------
    def residual(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, C_ref=None, out=None):
        """G(u) of :func:`~transient.models.journal.kernels.film_residual`; also leaves the fields (P, theta,
        ...) of ``u`` in the scratch arrays ``self.w``."""
        w, op = self.w, self.op
        out = np.empty(self.n) if out is None else out
        film_residual(u, X, Y, VX, VY, rate, w.zero if C_ref is None else C_ref, out, self.beta_bar, self.width,
                      self.content_scale, w.cosp, w.sinp, w.area, *w.fields(), w.zero, *op.residual_args)
        return out

    def jacobian_data(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, data=None):
        """CSC data of dG/du (+ the rotor columns if the operator has them), pattern order."""
        w, op = self.w, self.op
        data = np.empty(op.nnz) if data is None else data
        ne = op.n_extra
        film_jacobian(u, X, Y, VX, VY, rate, data, self.beta_bar, self.width, self.content_scale,
                      w.cosp, w.sinp, w.area,
                      *w.fields(), w.zero, w.dk_dq[:ne], w.dc_dq[:ne], w.no_dq[:ne], w.pos_col, *op.jacobian_face_args)
        return data

    def solve(self, X, Y, VX=0.0, VY=0.0, u0=None, tol=1e-10, max_iter=400):
        """Steady film G(u) = 0 for a prescribed journal state (X, Y, VX, VY), returns (u, iterations).

        Pseudo-transient continuation (:func:`~transient.solvers.newton.newton`): Newton steps on the
        backward-Euler system ``A H (theta(u) - theta(u_old))/dtau + G(u) = 0`` whose pseudo-step grows as
        the residual falls, ending with plain Newton. Every iterate is a state of the film's own dynamics,
        so the solve cannot wander off into unphysical branches. Converged when the Newton step and the
        residual are below ``tol`` and 1e-8 of ``max(1, |u|)``.
        """
        n = self.n
        u = np.where(self.op.free, 0.0, self.u_supply) if u0 is None else np.array(u0, dtype=float)
        u[~self.op.free] = self.u_supply
        data = np.empty(self.op.nnz)
        G = lambda v: self.residual(v, X, Y, VX, VY)  # noqa: E731
        J = lambda v, rate: self.op.matrix(self.jacobian_data(v, X, Y, VX, VY, rate=rate, data=data))[:n, :n]  # noqa: E731

        def converged(v, r, dv):
            scale = max(1.0, float(np.max(np.abs(v))))
            return float(np.max(np.abs(dv))) <= tol * scale and float(np.max(np.abs(r))) <= 1e-8 * scale

        try:
            res = newton(G, J, u, pseudo_time=1.0 if u0 is None else 1e3, max_iter=max_iter, converged=converged,
                         name="film solve")
        except NewtonError as e:
            raise RuntimeError(f"film solve did not converge in {max_iter} iterations at X={X:.4g}, Y={Y:.4g}: "
                               f"residual {e.result.residual_norm:.3e}") from None
        return res.x, res.iterations

    def force(self, u, X, Y):
        """Dimensionless film force (Fbar_x, Fbar_y) at the state u (the fields are evaluated first)."""
        self.residual(u, X, Y)
        return film_force(self.w.P, self.w.cosp, self.w.sinp, self.w.area, self.w.sym)

    def force_sensitivity(self, u, X, Y):
        """Fbar and its exact derivatives dFbar/d(X, Y) and dFbar/d(VX, VY) at a steady solution ``u``
        (implicit differentiation: G_u du/dq = -G_q, dF/dq = F_u du/dq)."""
        if self.op.n_extra < 4:
            raise ValueError("force_sensitivity needs a film built with n_extra=4")
        n, w = self.n, self.w
        F = np.array(self.force(u, X, Y))
        M = self.op.matrix(self.jacobian_data(u, X, Y))
        Guu = M[:n, :n].tocsc()
        Gq = M[:n, n:n + 4].toarray()
        du = -spla.splu(Guu).solve(Gq)
        gx = w.sym * w.dP * w.cosp * w.area
        gy = w.sym * w.dP * w.sinp * w.area
        dF = np.vstack([gx @ du, gy @ du])
        return F, dF[:, :2], dF[:, 2:]

    def mass_flows(self, u, X, Y):
        """Global mass balance terms of the film at state ``u`` (dimensionless, whole bearing)::

            M      = sym * sum_free A_i H_i theta_i          film content (liquid volume / (C R^2))
            q_ends = net outflow through the bearing ends   (volume rate / (C R^2 omega))
            q_grv  = net outflow into the groove cells      (negative: the supply)

        The semi-discrete film equations give exactly ``dM/dtau = -(q_ends + q_grv)`` (the squeeze term
        of the free cells is part of ``dM/dtau``), so a time integrator's drift from this identity
        measures its own conservation error."""
        w, op = self.w, self.op
        R = self.residual(u, X, Y)  # VX = VY = 0: pure net outflow of each cell; fills H, P, theta
        free = op.free
        M = w.sym * float(np.sum((w.area * w.H * w.C)[free]))
        total = w.sym * float(np.sum(R[free]))
        b = op.bcell
        ok = free[b]
        if np.any(op.bdir[ok] != 1):
            raise NotImplementedError("mass_flows assumes Dirichlet faces only at the bearing ends")
        ends = w.sym * float(np.sum((-w.k[b] * (op.bP - w.P[b]) / op.bd * op.bs)[ok]))
        return M, ends, total - ends

    def state(self, u, X, Y, iterations=0) -> FilmState:
        b = self.bearing
        F = self.force(u, X, Y)
        Fx, Fy = F[0] * self.force_scale, F[1] * self.force_scale
        eps = float(np.hypot(X, Y))
        # attitude: from the load line (the load balances -F) to the line of centres
        load_dir = np.arctan2(-Fy, -Fx)
        att = np.degrees(np.angle(np.exp(1j * (np.arctan2(Y, X) - load_dir)))) if eps > 0 else 0.0
        P = self.w.P
        grid = b.grid
        return FilmState(
            eccentricity_ratio=eps, attitude_angle_deg=float(att), position=(X * b.clearance, Y * b.clearance),
            force=(Fx, Fy), load=float(np.hypot(Fx, Fy)), min_film=b.clearance * (1.0 - eps),
            speed_rpm=self.speed_rpm,
            pressure=grid.to_2d(b.cavitation_pressure + self.p0 * P).copy(),
            film_content=grid.to_2d(self.w.C).copy(),
            angle_deg=np.degrees(grid.x.centres), z=grid.z.centres * b.radius, u=u.copy(), newton_iterations=iterations)
