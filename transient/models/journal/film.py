"""The discretised Elrod film of a journal bearing at one shaft speed (Rho & Kim).

Scales (``p0 = 6 mu omega (R/C)^2``, the switch widths), the finite-volume operator with the rotor's
trailing unknowns, the scratch arrays of :mod:`transient.models.journal.kernels`, and the evaluations
every journal computation needs: the film equations and their Jacobian for a prescribed journal
motion, the steady film (pseudo-transient Newton), the film force and its exact sensitivities, the
global mass balance, and the SI :class:`~transient.models.journal.results.FilmState`.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla

from transient.fv.face_gradient import cell_gradient_values
from transient.fv.reynolds import ReynoldsOperator
from transient.models.journal.feeds import apply_feed_edges
from transient.models.journal.flows import flow_fields
from transient.models.journal.gecim_film import bulk_end_flow, bulk_tables, no_bulk, prefetch
from transient.models.journal.kernels import (N_ROTOR, content_universal, film_force, film_jacobian, film_residual,
                                              state_fields)
from transient.models.journal.results import FilmState
from transient.models.journal.tilt import moment, set_gap, tilt_groups, tilt_min_film
from transient.models.journal.scales import (ContentScratch, FilmScales, RotorColumns, Scratch, cell_geometry,
                                             operator_tables)
from transient.physics.layered import NO_LAYERS, Gecim, LayeredFilm
from transient.solvers.newton import NewtonError, NewtonSettings, newton


#: Residual [max(1, |u|)] at which the chord iteration from a prolonged start stops (Film.solve(chord=True)).
CHORD_RESIDUAL = 1e-13
#: Residual [max(1, |u|)] at which a steady film solve that ran out of iterations is a solution (Film.solve)
ROUNDING_RESIDUAL = 1e-14
#: SuperLU's column ordering in the solve from a prolonged start: minimum degree on A^T + A (the 5-point pattern is
#: symmetric) fills 35 % less than the default COLAMD at 800 x 102 and made the sequenced solve 21 % faster
#: (docs/validation.md); the solve from rest keeps the default.
PROLONGED_ORDERING = "MMD_AT_PLUS_A"


def read_only(u):
    """A read-only view of the state ``u``: SUNDIALS hands its callbacks read-only arrays, so the steady solves
    pass the same array type and the kernels compile one signature, not two."""
    v = np.asarray(u).view()
    v.setflags(write=False)
    return v

class FilmBlock:
    """What both films are made of: the ``grid``, the :class:`~.scales.FilmScales` at one speed and the flow law
    (:class:`~transient.physics.layered.LayeredFilm`). A film knows no bearing: it is a block a rotor on several
    bearings can hold."""

    def __init__(self, grid, scales: FilmScales, law: LayeredFilm):
        self.grid = grid
        self.scales = scales
        self.law = law
        self.shear_thinning = isinstance(law.rheology, Gecim)
        self.speed_rpm = scales.speed_rpm
        self.omega = scales.omega
        self.p0 = scales.p0
        self.force_scale = scales.force_scale  # N per unit of Fbar
        self.u_supply = scales.u_supply
        self.sym = scales.sym
        self.geo = cell_geometry(grid)
        self.cosp, self.sinp, self.area, self.gap0 = self.geo
        self.tilt = (0.0, 0.0)  # the tilt groups (a, b) of the journal in its bush (models.journal.tilt)
        self.tilt_rad = (0.0, 0.0)  # the same tilt (about x, about y) [rad]

    def set_tilt(self, tilt):
        """Tilt the journal relative to its bush by ``tilt = (t_x, t_y)`` [rad] (:mod:`~transient.models.journal.tilt`):
        the gap of the centred journal becomes ``1 + zbar (a cos + b sin)``, in place (the kernels and orbits holding
        the geometry see it)."""
        a, b = tilt_groups(tilt, self.scales.radius, self.scales.clearance)
        if (a, b) != (0.0, 0.0) and self.sym != 1.0:
            raise ValueError("a tilted journal needs the film of the whole length (symmetric=False)")
        set_gap(self.geo, self.grid.zc, a, b)
        self.tilt = (a, b)
        self.tilt_rad = (float(tilt[0]), float(tilt[1]))


class Film(FilmBlock):
    """The discretised Elrod film of a bearing at one shaft speed (:class:`FilmBlock`): the operator with ``n_extra``
    trailing unknowns (the rotor), the kernels' named data (:mod:`~transient.models.journal.scales`: ``switch``,
    ``geo``, ``fields`` = the scratch arrays its kernels fill (H, P, theta = C, ... of the last state evaluated),
    ``extras`` = the rotor columns, ``fv`` = the operator, ``work`` = the content formulation's scratch), and the
    steady, sensitivity and mass-balance evaluations."""

    def __init__(self, grid, scales: FilmScales, law: LayeredFilm, n_extra=N_ROTOR):
        super().__init__(grid, scales, law)
        s = scales
        self.beta_bar = s.beta_bar
        self.width = s.width
        self.content_scale = s.content_scale  # r: content width / pressure width
        u_amb = s.u_ambient
        # prescribed pressures sit on the sharp Elrod curve, not on the rounded switch (physics.cavitation:
        # P(0) = w ln 2 at an end held at p_c biased the load linearly in w): P = u, theta = 1 + u / beta_bar
        self.op = ReynoldsOperator(grid, n_extra=n_extra, upwind=True, boundary_P=u_amb,
                                   boundary_C=1.0 + u_amb / self.beta_bar, diagonals=self.shear_thinning)
        self.op.u_fixed[~self.op.free] = s.u_supply  # each feed's cells at its pressure
        apply_feed_edges(self.op, s)
        self.n = n = self.op.n_cells
        op = self.op
        # scratch arrays shared by the kernels (allocated once)
        self.fields = Scratch(*(np.empty(n) for _ in range(8)), np.zeros(n), np.empty(n))
        self.H, self.P, self.dP, self.C, self.D, self.dD, self.k, self.c, self.zero, self.R = self.fields
        self.scale = np.ones(op.n)  # row scaling of the ODE Jacobian; the rotor rows keep 1
        ne = op.n_extra
        self.extras = RotorColumns(np.zeros((ne, n)), np.zeros((ne, n)), np.zeros((ne, n)),
                                   np.ascontiguousarray(op.stencil.pos_row_extra),
                                   np.ascontiguousarray(op.stencil.pos_col_extra), op.stencil.indices, self.scale)
        self.switch = s.switch
        self.bulk = bulk_tables(op, law, s.clearance, s.omega * s.radius) if self.shear_thinning else no_bulk()
        self.fv = operator_tables(op, self.bulk if self.shear_thinning else None)  # None: no Gecim code compiled
        self.work = ContentScratch(np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n),
                                   np.ascontiguousarray(op.stencil.indptr, dtype=np.int64), np.full(2, np.nan),
                                   np.zeros(0), np.zeros(0, dtype=np.int64))

    # residual / Jacobian of the prescribed-motion film equations G(u) = 0 --------------------------
    def prefetch(self, u, X, Y):
        """A Gecim bulk's face values at ``(u, X, Y)`` on all cores (:func:`~transient.models.journal.gecim_film.prefetch`),
        so the kernel called next at the same state finds them; nothing for a Newtonian bulk."""
        if self.shear_thinning:
            state_fields(read_only(u), X, Y, self.switch, self.geo, self.fields, self.fv)
            prefetch(self.P, self.H, self.bulk)

    def prefetch_content(self, y):
        """:meth:`prefetch` at the content state ``y = [m, X, Y, ...]`` of the content formulation."""
        if self.shear_thinning:
            u = self.work.u
            content_universal(y, self.switch, self.geo, self.op.free, self.op.u_fixed, self.work.theta, u)
            self.prefetch(u, y[self.n], y[self.n + 1])

    def residual(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, C_ref=None, out=None):
        """G(u) of :func:`~transient.models.journal.kernels.film_residual`; also leaves the fields (P, theta,
        ...) of ``u`` in the film's scratch arrays."""
        out = np.empty(self.n) if out is None else out
        self.prefetch(u, X, Y)
        film_residual(read_only(u), X, Y, VX, VY, rate, self.zero if C_ref is None else C_ref, out, self.switch, self.geo,
                      self.fields, self.fv)
        return out

    def jacobian_data(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, data=None):
        """CSC data of dG/du (+ the rotor columns if the operator has them), pattern order."""
        data = np.empty(self.op.nnz) if data is None else data
        self.prefetch(u, X, Y)
        film_jacobian(read_only(u), X, Y, VX, VY, rate, data, self.switch, self.geo, self.fields, self.extras, self.fv)
        return data

    def solve(self, X, Y, VX=0.0, VY=0.0, u0=None, tol=1e-10, max_iter=400, chord=False):
        """Steady film G(u) = 0 for a prescribed journal state (X, Y, VX, VY), returns (u, iterations).

        Pseudo-transient continuation (:func:`~transient.solvers.newton.newton`): Newton steps on the
        backward-Euler system ``A H (theta(u) - theta(u_old))/dtau + G(u) = 0`` whose pseudo-step grows as
        the residual falls, ending with plain Newton. Every iterate is a state of the film's own dynamics,
        so the solve cannot wander off into unphysical branches. Converged when the Newton step and the
        residual are below ``tol`` and 1e-8 of ``max(1, |u|)``; a solve that ends with the residual at the rounding
        level (``ROUNDING_RESIDUAL`` of ``max(1, |u|)``) is a solution too: there a nearly singular Jacobian -- seen
        on a rough film whose asperities carry the load, on another CPU's rounding -- can keep the Newton step from
        shrinking while every equation holds.

        ``chord=True``: ``u0`` is the steady film of a coarser grid interpolated to this one (a prolonged start: grid
        sequencing, :meth:`~transient.models.journal.bearing.JournalBearing.film_solve`), next to the solution
        (not a film at another journal position: from there plain Newton wanders, measured): plain Newton with the
        line search, keeping the factorisation while the residual falls at least twofold per iteration (chord;
        SuperLU with the ``PROLONGED_ORDERING``), until also the residual is below ``CHORD_RESIDUAL`` of
        ``max(1, |u|)`` (a chord converges linearly: this takes the solution and the mass balance to the rounding
        level a Newton step reaches); should that fail, the pseudo-transient solve from the same start. The number
        of factorisations of the last solve is ``self.factorisations``.
        """
        n = self.n
        u = np.zeros(n) if u0 is None else np.array(u0, dtype=float)
        u[~self.op.free] = self.u_supply
        data = np.empty(self.op.nnz)
        G = lambda v: self.residual(v, X, Y, VX, VY)  # noqa: E731
        J = lambda v, rate: self.op.matrix(self.jacobian_data(v, X, Y, VX, VY, rate=rate, data=data))[:n, :n]  # noqa: E731

        def converged(v, r, dv, r_tol=1e-8):
            scale = max(1.0, float(np.max(np.abs(v))))
            return float(np.max(np.abs(dv))) <= tol * scale and float(np.max(np.abs(r))) <= r_tol * scale

        self.factorisations = 0
        if chord and u0 is not None:
            try:
                lu = lambda v, rate: spla.splu(J(v, rate), permc_spec=PROLONGED_ORDERING)  # noqa: E731
                res = newton(G, lu, u, settings=NewtonSettings(max_iter=max_iter), chord=True, name="film solve",
                             converged=lambda v, r, dv: converged(v, r, dv, CHORD_RESIDUAL))
                self.factorisations = res.n_factorisations
                return res.x, res.iterations
            except NewtonError as e:
                self.factorisations = e.result.n_factorisations  # and on from the same start, pseudo-transient
        try:
            res = newton(G, J, u, settings=NewtonSettings(pseudo_time=1.0 if u0 is None else 1e3, max_iter=max_iter),
                         converged=converged, name="film solve")
        except NewtonError as e:
            res = e.result
            if not res.residual_norm <= ROUNDING_RESIDUAL * max(1.0, float(np.max(np.abs(res.x)))):
                raise RuntimeError(f"film solve did not converge in {max_iter} iterations at X={X:.4g}, Y={Y:.4g}: "
                                   f"residual {res.residual_norm:.3e}") from None
        self.factorisations += res.n_factorisations
        return res.x, res.iterations

    def content(self, u, X, Y):
        """The content state ``m = H theta(u)`` of the content formulation (groove cells included)."""
        self.residual(u, X, Y)
        return self.H * self.C

    def universal(self, m, X, Y):
        """The universal variable ``u`` of the content state ``m`` (groove cells: their prescribed u)."""
        y = np.concatenate([np.asarray(m, dtype=float), [X, Y]])
        u = np.empty(self.n)
        content_universal(read_only(y), self.switch, self.geo, self.op.free, self.op.u_fixed, np.empty(self.n), u)
        return u

    def force(self, u, X, Y):
        """Dimensionless film force (Fbar_x, Fbar_y) at the state u (the fields are evaluated first)."""
        self.residual(u, X, Y)
        return film_force(self.P, self.cosp, self.sinp, self.area, self.sym)

    def force_sensitivity(self, u, X, Y):
        """Fbar and its exact derivatives dFbar/d(X, Y) and dFbar/d(VX, VY) at a steady solution ``u``
        (implicit differentiation: G_u du/dq = -G_q, dF/dq = F_u du/dq)."""
        if self.op.n_extra < 4:
            raise ValueError("force_sensitivity needs a film built with n_extra=4")
        n, w = self.n, self
        F = np.array(self.force(u, X, Y))
        M = self.op.matrix(self.jacobian_data(u, X, Y))
        Guu = M[:n, :n].tocsc()
        Gq = M[:n, n:n + 4].toarray()
        du = -spla.splu(Guu).solve(Gq)
        gx = w.sym * w.dP * w.cosp * w.area
        gy = w.sym * w.dP * w.sinp * w.area
        dF = np.vstack([gx @ du, gy @ du])
        return F, dF[:, :2], dF[:, 2:]

    def linear_response(self, u, G_u, G_q):
        """``du = -G_u^{-1} G_q``: the response of the steady film ``u`` to the columns ``G_q`` of its equations'
        derivatives (:func:`~transient.models.journal.tilt.sensitivity`)."""
        return -spla.splu(G_u.tocsc()).solve(G_q)

    def pressure_slope(self, u):
        """``dP/du`` of every cell at the state last evaluated (``u``)."""
        return self.dP.copy()

    def mass_flows(self, u, X, Y):
        """Global mass balance terms of the film at state ``u`` (dimensionless, whole bearing)::

            M      = sym * sum_free A_i H_i theta_i          film content (liquid volume / (C R^2))
            q_ends = net outflow through the bearing ends   (volume rate / (C R^2 omega))
            q_grv  = net outflow into the groove cells      (negative: the supply)

        The semi-discrete film equations give exactly ``dM/dtau = -(q_ends + q_grv)`` (the squeeze term
        of the free cells is part of ``dM/dtau``), so a time integrator's drift from this identity
        measures its own conservation error."""
        w, op = self, self.op
        R = self.residual(u, X, Y)  # VX = VY = 0: pure net outflow of each cell; fills H, P, theta
        free = op.free
        M = w.sym * float(np.sum((w.area * w.H * w.C)[free]))
        total = w.sym * float(np.sum(R[free]))
        b = op.bcell
        ok = free[b]
        if np.any(op.bdir[ok] != 1):
            raise NotImplementedError("mass_flows assumes Dirichlet faces only at the bearing ends")
        if w.shear_thinning:
            ends = w.sym * bulk_end_flow(w.P, w.H, free, op.fL.size, w.bulk)
        else:
            ends = w.sym * float(np.sum((-w.k[b] * (op.bP - w.P[b]) / op.bd * op.bs)[ok]))
        return M, ends, total - ends

    def state(self, u, X, Y, iterations=0):
        """The SI :class:`~transient.models.journal.results.FilmState` of the film ``u`` at (X, Y)."""
        F = self.force(u, X, Y)  # fills P and C
        return film_state(self, u, X, Y, F, self.P, self.C, iterations)


def film_state(film, u, X, Y, F, P, content, iterations=0, contact=None, viscosity_factor=None, gap=None):
    """The SI :class:`~transient.models.journal.results.FilmState` of a film (:class:`Film` or
    :class:`~transient.models.journal.reynolds_film.ReynoldsFilm`) at journal position (X, Y): its dimensionless
    force ``F``, pressure ``P`` (p0 units above p_c) and film content per cell. The attitude is measured from
    the load line (the load balances -F) to the line of centres. ``contact`` of a rough film
    (:class:`~transient.models.journal.rough_film.RoughFilm`): (asperity pressure per cell [Pa], asperity force [N],
    its normal load ``sum p_a dA`` [N], boundary friction coefficient); the friction torque then adds
    ``mu_b R sum p_a dA`` to the film's ``R * friction_force``. ``viscosity_factor``: ``mu / mu0`` per cell of a
    pressure-viscous film (:func:`wall_friction`). ``gap``: the film thickness per cell [C] of a film whose bore
    deforms, in place of the rigid journal's (its least cell value the minimum film)."""
    s, law, grid = film.scales, film.law, film.grid
    C, R = s.clearance, s.radius
    Fx, Fy = F[0] * film.force_scale, F[1] * film.force_scale
    eps = float(np.hypot(X, Y))
    load_dir = np.arctan2(-Fy, -Fx)
    att = np.degrees(np.angle(np.exp(1j * (np.arctan2(Y, X) - load_dir)))) if eps > 0 else 0.0
    pressure = grid.to_2d(s.cavitation_pressure + film.p0 * np.asarray(P)).copy()
    theta = grid.to_2d(np.asarray(content, dtype=float)).copy()
    h, G, Gz = film_geometry(film, X, Y, P, gap)
    friction = wall_friction(film, h, G, Gz, theta, viscosity_factor)
    ly = None if law.layers is NO_LAYERS else law.layers
    rh = law.rheology
    pa, Fc, normal, mu_b = (None, (0.0, 0.0), 0.0, 0.0) if contact is None else contact
    return FilmState(
        contact_pressure=None if pa is None else grid.to_2d(pa).copy(), contact_force=Fc,
        contact_load=float(np.hypot(*Fc)), contact_normal_load=normal,
        friction_torque=R * (friction[0] + mu_b * normal),
        eccentricity_ratio=eps, attitude_angle_deg=float(att), position=(X * C, Y * C),
        force=(Fx, Fy), load=float(np.hypot(Fx, Fy)),
        min_film=C * (tilt_min_film(film, X, Y) if gap is None else float(np.min(gap))),
        moment=moment(film, P), tilt=film.tilt_rad,
        speed_rpm=film.speed_rpm, pressure=pressure, film_content=theta, angle_deg=np.degrees(grid.x.centres),
        z=grid.z.centres * R, u=np.array(u, dtype=float), newton_iterations=iterations, iterations=iterations,
        friction_force=friction[0], bearing_friction_force=friction[1], film_thickness=h, pressure_gradient=G,
        axial_pressure_gradient=Gz, viscosity=law.viscosity, sliding_speed=s.omega * R,
        layers=None if ly is None else (ly.thickness, ly.viscosity[0], ly.viscosity[1], ly.alpha),
        gecim=(rh.kappa, rh.viscosity_ratio) if film.shear_thinning else None, **flow_fields(film, u, X, Y))


def film_geometry(film, X, Y, P, gap=None):
    """Film thickness ``h`` [m], circumferential pressure gradient ``dp/ds`` (``s = R phi`` along the rotation) and
    axial gradient ``dp/dz`` [Pa/m] per cell, as (n_axial, n_theta) arrays, from the dimensionless pressure ``P``:
    the cells' Green-Gauss gradients of the operator (:func:`~transient.fv.face_gradient.cell_gradient_values`:
    central differences on this uniform grid; the prescribed pressure at an end, the cell's own at the symmetry
    plane). ``gap``: the cells' film thickness [C] if not the rigid journal's."""
    s, grid = film.scales, film.grid
    h = s.clearance * grid.to_2d(film.gap0 + X * film.cosp + Y * film.sinp if gap is None else gap)
    g = cell_gradient_values(film.op, np.asarray(P, dtype=float)) * (film.p0 / s.radius)
    return h, grid.to_2d(g[:, 0]), grid.to_2d(g[:, 1])


def wall_friction(film, h, G, Gz, theta, viscosity_factor=None) -> tuple[float, float]:
    """Friction forces [N] of the film on the journal (its drag, against the rotation) and on the bearing (along the
    rotation): ``-sum tau(0) min(theta, 1) dA`` and ``-sum tau(h) min(theta, 1) dA`` over the bearing, with the
    wall shear stresses ``tau(0)``, ``tau(h) = tau(0) + G h`` of the film's flow law (Jang's layered film;
    ``tau(0) = -mu U / h - (h/2) dp/ds`` for a Newtonian bulk without layers) at each cell's film ``h`` and pressure
    gradients ``G = dp/ds``, ``Gz = dp/dz`` (:func:`film_geometry`), the journal speed ``U = omega R``; a cavitated
    cell shears only its content fraction theta (Elrod's striated film). A Gecim bulk couples the directions: its
    circumferential wall stresses are those of the 2-D law at ``(G, Gz)``; the Newtonian law is linear and uses
    ``G`` alone. The two differ by ``sum G h theta dA``: the moment of the pressure force about the journal centre
    over R (test). ``viscosity_factor`` (per cell, Newtonian bulk without layers): the cell's viscosity over the
    law's, which scales the Couette stress ``-mu U / h`` (the Poiseuille stress ``h G / 2`` does not depend on it)."""
    sc, law = film.scales, film.law
    U = sc.omega * sc.radius
    if film.shear_thinning:
        s = law.stresses_2d(h, np.stack([G, Gz], axis=-1), (U, 0.0), (0.0, 0.0))
        lower, upper = s.lower_wall[..., 0], s.upper_wall[..., 0]
    else:
        s = law.stresses(h, G, U, 0.0)
        lower, upper = s.lower_wall, s.upper_wall
        if viscosity_factor is not None:
            extra = -(film.grid.to_2d(viscosity_factor) - 1.0) * law.viscosity * U / h
            lower, upper = lower + extra, upper + extra
    weight = sc.sym * np.minimum(theta, 1.0) * film.grid.to_2d(film.area) * sc.radius ** 2
    return float(-np.sum(lower * weight)), float(-np.sum(upper * weight))
