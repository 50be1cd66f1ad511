"""Unbalanced rigid rotor on a journal bearing with the Elrod film, in the time domain (Rho & Kim).

:class:`JournalOrbit` assembles the film + rotor method-of-lines system of
:mod:`transient.models.journal.kernels` and integrates it through :func:`transient.solvers.integrate.solve`:

* ``"cvode"``, ``"bdf"``, ``"radau"``, ``"lsoda"`` -- the ODE form ``y' = f(tau, y)`` with the analytic
  sparse arrow Jacobian (LSODA gets it dense: scipy's limitation);
* ``"ida"`` -- the residual form ``F(tau, y, y') = 0`` with its analytic Jacobian ``dF/dy + cj dF/dy'``;
* ``"bdf2"`` (the default of :meth:`JournalOrbit.run`) -- the content formulation by
  :mod:`transient.solvers.integrate.bdf2`: variable-step BDF of variable order (2 to ``BDF2_MAX_ORDER``) whose steps
  follow the rotor (error test on X, Y, VX, VY), bounded in journal travel per step (``BDF2_TRAVEL``) and by
  ``BDF2_MIN_STEPS`` per revolution, or by an explicit ``steps_per_revolution``; the film solved by Newton in
  the universal variable to a tight pressure/content tolerance every step, mass conserved through every cavity
  crossing;
* ``"rk4"`` -- the users' hand-coded scheme (the paper's): classical RK4 on the rotor with N steps per
  revolution, the film solved at every stage for the stage's rotor state, its time derivative by a
  backward-Euler step from the film of the last completed step (Elrod 1981), Newton iterations to the
  paper's criterion ``sum|theta^k - theta^(k-1)| / sum theta^k < 1e-6`` (eq. 6), reusing one sparse LU
  per step (a chord iteration, refactorised when it stalls) -- the paper's method done well.

The run starts from the static equilibrium (paper: found by 2-D Newton-Raphson). Long runs go in
chunks: each chunk appends the recorded outputs, prints progress and (optionally) writes a checkpoint
from which ``run(..., resume=True)`` continues after a crash with nothing lost.
"""

from __future__ import annotations

import math
import warnings

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from transient.checks import ATOL_FLOOR, ATOL_WHY, check_choice, check_memory, check_positive, check_range
from transient.compile_notice import announce
from transient.models.journal.bearing import GRID_ADVICE, SPEED_RANGE_RPM, JournalBearing, check_speed
from transient.models.journal.rest import rest_equilibrium
from transient.models.journal.film import read_only
from transient.models.journal.flows import film_flows
from transient.models.journal.driven_film import driven_newton, driven_residual
from transient.models.journal.kernels import (N_ROTOR, content_jacobian, content_ode_jacobian, content_residual,
                                              content_rhs, dae_jacobian, dae_jacobian_at, dae_residual,
                                              dae_residual_at, ode_jacobian, ode_rhs, ode_rhs_at)
from transient.models.journal.results import OrbitResult
from transient.models.journal.speed_law import CONSTANT, SpeedProfile, shaft_speed, step_cap_scale
from transient.models.journal.scales import Rotor
from transient.models.journal.tilt import half_length, moment
from transient.models.journal.time_domain import check_time_domain
from transient.models.journal.rk4 import FilmStageSolver
from transient.models.journal.thermal_orbit import THERMAL_FIELDS, THERMAL_RECORDABLE, thermal_long_run, thermal_parts
from transient.models.journal.content_newton import bdf2_newton, bdf2_residual, decoupled_pattern, forget_fields
from transient.models.journal.rough_orbit import (CONTACT_LAMBDA, orbit_tribology, peak_asperity_pressure, rough_bdf2_newton, rough_cells,
                                                  rough_content_rhs, rough_dae_jacobian, rough_dae_residual,
                                                  rough_ode_rhs)
from transient.solvers.integrate.bdf2 import Bdf2Model
from transient.solvers.integrate import Problem, Steps, check_method
from transient.solvers.model_run import (ModelRun, RunParts, check_run_memory, start_point, state_array,
                                         wall_crossing)
from transient.solvers.settings import (FORMULATIONS, Integration, LongRun, Recording, keyword_table,
                                       requested_method, run_settings)
from transient.units import rpm_to_hz

#: The content formulation's film state is O(1) in the full film, where the pressure is only its 1/beta_bar
#: part, so ``run`` hands the integrator ``rtol * CONTENT_RTOL_FACTOR`` there: a user's rtol then buys about
#: the orbit accuracy of the universal form (docs/journal.md, section 5).
CONTENT_RTOL_FACTOR = 0.1
#: ``method="bdf2"`` at its defaults: the variable-order BDF up to ``BDF2_MAX_ORDER``, each step at most
#: ``BDF2_TRAVEL`` of journal travel [C] at rtol ``BDF2_TRAVEL_RTOL``, as sqrt(rtol) at others (at the journal's speed
#: over the last step: the film's cavitation fronts move with the journal, and the rotor's error test does not see
#: their error; 0.3 C, 76 x 11: the error grows about linearly with the travel) and at least ``BDF2_MIN_STEPS`` steps per
#: revolution (a safety bound); the rotor's error test sets the step where the journal moves slowly (a small orbit).
#: An explicit ``steps_per_revolution`` is the cap in shaft angle instead of both. ``BDF2_FILM_TOL``: the film's
#: Newton tolerance on the pressure (p0) and the content H theta of every cell.
BDF2_MIN_STEPS = 50
BDF2_TRAVEL = 1e-3
BDF2_TRAVEL_RTOL = 1e-6
BDF2_MAX_ORDER = 5
BDF2_FILM_TOL = 1e-8
#: :meth:`JournalOrbit.run`'s method when no ``integration`` is given (``transient bench orbit-size``: at equal error
#: no slower than IDA on small and large orbits, docs/bench/orbit_size.md)
DEFAULT_METHOD = "bdf2"
#: ``method="bdf2"``: rows of LAPACK band storage (2 kl + ku + 1) of its bordered band LU per cell of the grid's
#: smaller dimension, reverse Cuthill-McKee on the Newton pattern: 3.0 with a full-length groove, up to 6.2 with a
#: partial one (measured on 151 x 21, 64 x 64, 100 x 30, 40 x 100 and 300 x 42); 8 bytes each per film cell.
BDF2_BAND_ROWS = 6.2
RECORDABLE = ("force", "moment", "pressure", "film_content", "min_film", "mass", "outflow", "supply_flow",
              "side_leakage", "friction_torque", "contact_load", "shaft_speed")
#: The methods that integrate a rough bearing's orbit (:mod:`~transient.models.journal.rough_orbit`).
ROUGH_METHODS = ("ida", "bdf2")
#: The methods that integrate an orbit with a ``speed_profile`` (:mod:`~transient.models.journal.speed_law`).
SPEED_LAW_METHODS = ("ida", "bdf2")
#: The records of the film's flows: at the orbit's ``speed_rpm``, refused with a speed law.
FLOW_RECORDS = ("outflow", "supply_flow", "side_leakage")
FIELD_SERIES = ("pressure", "film_content")
#: The loose keywords of :meth:`JournalOrbit.run` of earlier releases and the settings field each now is.
RUN_KEYWORDS = (keyword_table("integration", Integration, ("method", "rtol", "atol", "steps_per_revolution",
                                                           "inner_tolerance", "formulation"))
                | keyword_table("recording", Recording) | keyword_table("long_run", LongRun))


class JournalOrbit:
    """Rigid rotor (2 DOF) with unbalance on one journal bearing.

    Parameters (SI)
    ----------
    bearing : :class:`~transient.models.journal.JournalBearing`.
    rotor_mass [kg] : mass carried by this bearing (paper: m = W / g).
    unbalance [m] : mass eccentricity e of the rotor (unbalance force m e Omega^2; paper: 0.01 C).
    load [N] : static load on the bearing, acting in +x (towards the bottom).
    speed_rpm [rpm] : shaft speed (with ``speed_profile``: the reference speed of the dimensionless time and the
        pressure unit, usually the largest; ``run``'s revolutions are revolutions at it).
    speed_profile : the shaft speed as a function of time (:class:`~transient.models.journal.speed_law.SpeedProfile`):
        a table ``((t_0 [s], n_0 [rpm]), (t_1, n_1), ...)`` (t ascending, linear between, constant outside; e.g. a
        start-up from rest ``((0, 0), (2, 3000))``), a function ``n(t)`` [rpm] of the time [s], or a
        ``SpeedProfile``; smooth, rough and thermal bearings alike: the film's Couette flux follows the speed, the
        unbalance force ``m e (Omega^2, dOmega/dt)`` the shaft angle (:mod:`~transient.models.journal.speed_law`);
        methods ``"bdf2"`` and ``"ida"``. Default: ``speed_rpm`` throughout.

    A rough bearing (``JournalBearing(..., roughness=Roughness(...))``) integrates the average Reynolds equation
    with the asperity contact in the rotor's equations (:mod:`~transient.models.journal.rough_orbit`; methods
    ``"ida"`` and ``"bdf2"``): the journal may run through contact, which its results record (``contact_events``,
    ``contact_pressure``) instead of stopping.
    """

    def __init__(self, bearing: JournalBearing, rotor_mass, unbalance, load, speed_rpm, speed_profile=None):
        if not isinstance(bearing, JournalBearing):
            raise TypeError(f"bearing must be a JournalBearing, got {type(bearing).__name__}")
        check_time_domain("JournalOrbit", bearing)
        if bearing.misalignment != (0.0, 0.0):
            bearing = bearing.whole_length()  # a tilted gap: the film of the whole length
        self.bearing = bearing
        self.rotor_mass = check_positive("rotor_mass", rotor_mass, "kg")
        self.unbalance = check_range("unbalance", unbalance, "m", 0.0, bearing.clearance, high_open=True,
                                     why="(mass eccentricity, must be below the clearance)")
        self.load = check_range("load", load, "N", 0.0, np.inf, high_open=True)
        self.speed_rpm = check_speed(speed_rpm)
        self.speed_profile = None if speed_profile is None else SpeedProfile(speed_profile)
        if self.speed_profile is not None and bearing.shear_thinning:
            raise ValueError("speed_profile with rheology = Gecim(...): its bulk flux is tabulated at one sliding "
                             "speed; allowed: speed_profile=None (a constant speed)")
        check_orbit_grid_memory(bearing.n_cells)
        self.film = bearing.film(speed_rpm)
        f = self.film
        mc_w2 = self.rotor_mass * bearing.clearance * f.omega ** 2
        self.kappa = f.force_scale / mc_w2
        self.wbar = self.load / mc_w2
        self.ebar = self.unbalance / bearing.clearance
        self._ends = (f.tilt, half_length(bearing.grid))  # the journal's tilt groups in its bush, the half length
        self._equilibrium = None
        self._equilibria = {}
        self._newton_pattern = None
        #: the kernels' speed law (speed_law.speed_knots): a table's own knots; a function's are set per run
        self.knots = CONSTANT if self.speed_profile is None else self.speed_profile.knots(f.omega, self.speed_rpm, 0.0)
        self.rough = None
        if bearing.roughness is not None:
            self.rough = rough_cells(bearing.roughness, bearing.clearance, f.p0, f.n, self.knots)
            f.rough_cells = self.rough

    def shaft_speed_rpm(self, t) -> np.ndarray:
        """The shaft speed [rpm] at the times ``t`` [s] (``speed_profile``, else ``speed_rpm``)."""
        if self.speed_profile is None:
            return np.full(np.shape(t), self.speed_rpm)
        return np.asarray(self.speed_profile.value(t))

    def _set_knots(self, knots):
        """The kernels' speed law (:attr:`knots`, and the rough film's)."""
        self.knots = knots
        if self.rough is not None:
            self.rough = self.film.rough_cells = self.rough._replace(knots=knots)

    # ---------------------------------------------------------------------------------------------
    @property
    def n(self) -> int:
        return self.film.n + N_ROTOR

    def reach(self, X, Y):
        """The journal's largest eccentricity ratio over the bearing length at (X, Y) [C] (arrays too): at the
        mid-plane for an aligned journal, at the worse end in a misaligned bush (:mod:`~.tilt`)."""
        (a, b), half = self._ends
        if (a, b) == (0.0, 0.0):
            return np.hypot(X, Y)
        return np.maximum(np.hypot(X - a * half, Y - b * half), np.hypot(X + a * half, Y + b * half))

    def _reach_si(self, x, y):
        """:meth:`reach` of the journal at (x, y) [m]."""
        C = self.bearing.clearance
        return np.hypot(x, y) / C if self._ends[0] == (0.0, 0.0) else self.reach(x / C, y / C)

    def equilibrium(self):
        """Static equilibrium of the bearing under ``load`` (cached)."""
        if self._equilibrium is None:
            if self.load > 0:
                self._equilibrium = self.bearing.equilibrium(self.load, self.speed_rpm)
            else:
                self._equilibrium = self.bearing.steady_state(0.0, self.speed_rpm)
        return self._equilibrium

    def initial_state(self) -> np.ndarray:
        """Film and journal at the static equilibrium, journal at rest (the paper's start); with a
        ``speed_profile``, the equilibrium at its speed at t = 0 (:meth:`equilibrium_state`)."""
        if self.speed_profile is not None and self.speed_profile.start_rpm() != self.speed_rpm:
            return self.equilibrium_state(self.speed_profile.start_rpm())
        e = self.equilibrium()
        y0 = np.zeros(self.n)
        y0[: self.film.n] = e.u
        y0[self.film.n] = e.position[0] / self.bearing.clearance
        y0[self.film.n + 1] = e.position[1] / self.bearing.clearance
        return y0

    def equilibrium_state(self, speed_rpm) -> np.ndarray:
        """Film and journal at the static equilibrium at another shaft speed [rpm] (the start of a run-up or a
        coast-down), its film content carried over into this orbit's units (the pressure unit of ``speed_rpm`` of the
        orbit), the journal at rest. A rough bearing at rest (below ``SPEED_RANGE_RPM[0]``): :meth:`rest_state`."""
        if self.rough is not None and speed_rpm < SPEED_RANGE_RPM[0]:
            return self.rest_state()
        if speed_rpm < SPEED_RANGE_RPM[0]:
            raise ValueError(f"speed_profile starts at {speed_rpm:g} [rpm]: a smooth film carries no load at rest, "
                             "there is no equilibrium to start from; allowed: a profile that starts above "
                             f"{SPEED_RANGE_RPM[0]:g} rpm, run(y0=...), or a rough bearing (rest_state)")
        return self._content_start(speed_rpm)

    def start_equilibrium(self):
        """The static equilibrium a run starts from: :meth:`equilibrium`, or with a ``speed_profile`` the one at its
        speed at t = 0 (cached)."""
        n0 = self.speed_rpm if self.speed_profile is None else self.speed_profile.start_rpm()
        return self.equilibrium() if n0 == self.speed_rpm else self._equilibrium_at(n0)

    def _equilibrium_at(self, speed_rpm):
        """The static equilibrium at ``speed_rpm`` (cached per speed)."""
        if speed_rpm not in self._equilibria:
            self._equilibria[speed_rpm] = self.bearing.equilibrium(self.load, speed_rpm) if self.load > 0 else \
                self.bearing.steady_state(0.0, speed_rpm)
        return self._equilibria[speed_rpm]

    def _content_start(self, speed_rpm) -> np.ndarray:
        """:meth:`equilibrium_state` at ``speed_rpm`` in ``SPEED_RANGE_RPM``."""
        e = self._equilibrium_at(speed_rpm)
        X, Y = e.position[0] / self.bearing.clearance, e.position[1] / self.bearing.clearance
        y0 = np.zeros(self.n)
        y0[:self.film.n] = self.film.universal(self.bearing.film(speed_rpm).content(e.u, X, Y), X, Y)
        y0[self.film.n:self.film.n + 2] = X, Y
        return y0

    def rest_state(self) -> np.ndarray:
        """Film and journal at rest under ``load`` (a rough bearing's start-up from rest): the static contact
        equilibrium at 0 rpm (:mod:`~transient.models.journal.rest`: the asperities carry the load, the film is at
        the feed pressures), in this orbit's pressure unit, the journal still."""
        if self.rough is None:
            raise ValueError("rest_state with roughness = None: a smooth journal at rest sits on the bush, which only "
                             "a rough bearing's asperities carry; allowed: a JournalBearing with roughness=Roughness(...)")
        _, u, q, _ = rest_equilibrium(self.bearing, self.load, self.speed_rpm)
        y0 = np.zeros(self.n)
        y0[:self.film.n] = u
        y0[self.film.n:self.film.n + 2] = q
        return y0

    def linear_start(self) -> np.ndarray:
        """State at t = 0 on the linearised unbalance response (position and velocity from K and C, the
        film solved quasi-steadily for them): a start that is already close to the settled orbit."""
        C = self.bearing.clearance
        Z = self.bearing.unbalance_response(self.rotor_mass, self.unbalance, self.load, self.speed_rpm)
        e = self.equilibrium()
        X, Y = e.position[0] / C + Z[0].real / C, e.position[1] / C + Z[1].real / C
        VX, VY = (1j * Z[0]).real / C, (1j * Z[1]).real / C
        u, _ = self.film.solve(X, Y, VX, VY, u0=e.u)
        y0 = np.empty(self.n)
        y0[:self.film.n] = u
        y0[self.film.n:] = X, Y, VX, VY
        return y0

    def perturbed_start(self, offset) -> np.ndarray:
        """State at t = 0 with the journal moved by ``offset`` [C] towards the load from the equilibrium, at
        rest, the film solved for it (a start for free-vibration and stability runs)."""
        y0 = self.initial_state()
        n = self.film.n
        y0[n] += offset
        y0[:n] = self.film.solve(y0[n], y0[n + 1], u0=self.equilibrium().u)[0]
        return y0

    def content_state(self, y) -> np.ndarray:
        """A state of the universal layout ``[u (cells), X, Y, VX, VY]`` (what :meth:`initial_state`,
        :meth:`linear_start`, ``OrbitResult.final_state`` hold) in the content layout ``[m, X, Y, VX, VY]``
        of ``formulation="content"`` (``m = H theta``, the film content per unit area of each cell)."""
        y = np.array(y, dtype=float)
        n = self.film.n
        y[:n] = self.film.content(y[:n], y[n], y[n + 1])
        return y

    def universal_state(self, y) -> np.ndarray:
        """The inverse of :meth:`content_state`."""
        y = np.array(y, dtype=float)
        n = self.film.n
        y[:n] = self.film.universal(y[:n], y[n], y[n + 1])
        return y

    def problem(self, y0=None, tau0=0.0, touch_gap=0.0, formulation="universal") -> Problem:
        """The method-of-lines :class:`Problem` in dimensionless time tau = omega t.

        ``y0`` is a state of the universal layout (default: :meth:`initial_state`). ``formulation``:
        ``"universal"`` -- the state is ``[u, X, Y, VX, VY]`` and the film equation carries ``A H D(u) u'``
        (module docstring of :mod:`~transient.models.journal.kernels`); ``"content"`` -- the state is
        ``[m, X, Y, VX, VY]`` with ``m = H theta`` (:meth:`content_state`; the problem's ``y0`` and every
        state it produces are in that layout, :meth:`universal_state` maps back) and the film equation is
        the conservation law ``A m' + R = 0`` itself (docs/journal.md, section 5).

        ``touch_gap`` > 0 adds a terminal event when the eccentricity ratio reaches ``1 - touch_gap``
        (the journal touches the bearing)."""
        self._isothermal_only("problem")
        check_choice("formulation", formulation, FORMULATIONS)
        if self.speed_profile is not None and self.speed_profile.function is not None:
            raise ValueError("problem with speed_profile = a function: its kernels take it on knots over a run's span; "
                             "allowed: a table ((t, rpm), ...), or run(...)")
        y0 = self.initial_state() if y0 is None else np.asarray(y0, dtype=float)
        if y0.shape != (self.n,):
            raise ValueError(f"the initial state has shape {y0.shape}; this orbit has {self.n} states")
        if formulation == "content":
            y0 = self.content_state(y0)
        return self._problem(y0, tau0, touch_gap, formulation)

    def _problem(self, y0, tau0, touch_gap, formulation, pattern=None) -> Problem:
        """:meth:`problem` with ``y0`` already in the formulation's own layout; ``pattern``: the BDF2 Newton's
        (:meth:`newton_pattern`; the problem then has no Jacobian callbacks: its Jacobian is :meth:`bdf2_model`'s),
        default the operator's."""
        f = self.film
        n = f.n
        switch, geo, fields, extras, fv, work = f.switch, f.geo, f.fields, f.extras, f.fv, f.work
        rotor = Rotor(self.kappa, self.wbar, self.ebar, f.sym)
        fbuf = np.empty(self.n)

        rough = self.rough
        if rough is not None and formulation == "content":  # BDF2 only (its Newton is the model's Jacobian)
            def rhs(t, y, out):
                rough_content_rhs(t, y, out, switch, rotor, geo, fields, fv, work, rough)

            residual = jac_rhs = jac_residual = None
        elif rough is not None:
            def rhs(t, y, out):
                rough_ode_rhs(t, y, out, switch, rotor, geo, fields, fv, rough)

            def residual(t, y, yp, out):
                rough_dae_residual(t, y, yp, out, switch, rotor, geo, fields, fv, rough)

            def jac_residual(t, y, yp, cj, data):
                rough_dae_jacobian(t, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, rough)

            jac_rhs = None
        elif pattern is not None or (self.speed_profile is not None and formulation == "content"):
            # BDF2 on the content film: its Newton's Jacobian; y' from the Newton's own residual, so a first run
            # compiles no ODE kernel
            args, kernel = ((self.bdf2_model().args, driven_residual) if self.speed_profile is not None
                            else (self.content_args(), bdf2_residual))

            def residual(t, y, yp, out):
                kernel(t, y, yp, out, args)

            rhs = _content_slope(residual, np.where(fv.cells.free, geo.area, 1.0), fv.cells.free, n,
                                 args[0] if self.speed_profile is not None else args)

            jac_rhs = jac_residual = None
        elif self.speed_profile is not None:
            knots = self.knots

            def rhs(t, y, out):
                ode_rhs_at(t, y, out, switch, rotor, geo, fields, fv, *shaft_speed(t, knots))

            def residual(t, y, yp, out):
                dae_residual_at(t, y, yp, out, switch, rotor, geo, fields, fv, *shaft_speed(t, knots))

            def jac_residual(t, y, yp, cj, data):
                dae_jacobian_at(t, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, shaft_speed(t, knots)[0])

            jac_rhs = None
        elif formulation == "content":
            def rhs(t, y, out):
                content_rhs(t, y, out, switch, rotor, geo, fields, fv, work)

            def jac_rhs(t, y, data):
                content_ode_jacobian(t, y, data, switch, rotor, geo, fields, extras, fv, work)

            def residual(t, y, yp, out):
                content_residual(t, y, yp, out, switch, rotor, geo, fields, fv, work)

            def jac_residual(t, y, yp, cj, data):
                content_jacobian(t, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, work)
        else:
            def rhs(t, y, out):
                ode_rhs(t, y, out, switch, rotor, geo, fields, fv)

            def jac_rhs(t, y, data):
                ode_rhs(t, y, fbuf, switch, rotor, geo, fields, fv)
                ode_jacobian(t, y, data, fbuf, switch, rotor, geo, fields, extras, fv)

            def residual(t, y, yp, out):
                dae_residual(t, y, yp, out, switch, rotor, geo, fields, fv)

            def jac_residual(t, y, yp, cj, data):
                dae_jacobian(t, y, yp, cj, data, switch, rotor, geo, fields, extras, fv)

        if self.bearing.shear_thinning:  # the Gecim faces on all cores first (film.prefetch)
            rhs, jac_rhs, residual, jac_residual = (_prefetching(f, cb, formulation) for cb in
                                                    (rhs, jac_rhs, residual, jac_residual))
        if pattern is not None:  # the BDF2 Newton's pattern: its Jacobian is the Bdf2Model's, none of these
            jac_rhs = jac_residual = None
        yp0 = np.empty(self.n)
        rhs(tau0, read_only(y0), yp0)  # the array type SUNDIALS passes: one compiled signature
        events = None
        if touch_gap > 0 and f.tilt == (0.0, 0.0):
            limit = (self.bearing.max_eccentricity_ratio - touch_gap) ** 2

            def events(t, y, out):
                out[0] = limit - (y[n] ** 2 + y[n + 1] ** 2)
        elif touch_gap > 0:  # a misaligned bush: the gap closes first at an end
            limit = (self.bearing.max_eccentricity_ratio - touch_gap) ** 2
            (a, b), half = self._ends
            ah, bh = a * half, b * half

            def events(t, y, out):
                X, Y = y[n], y[n + 1]
                out[0] = limit - max((X - ah) ** 2 + (Y - bh) ** 2, (X + ah) ** 2 + (Y + bh) ** 2)

        return Problem(y0=y0, yp0=yp0, rhs=rhs, residual=residual,
                       jac_pattern=f.op.pattern if pattern is None else pattern, jac_rhs=jac_rhs,
                       jac_residual=jac_residual, events=events, n_events=1 if events else 0,
                       event_terminal=[True], event_direction=[-1], name=f"journal orbit ({formulation})")

    def bdf2_model(self) -> Bdf2Model:
        """The compiled kernels of the content formulation for ``method="bdf2"``
        (:class:`~transient.solvers.integrate.bdf2.Bdf2Model`, kernels in :mod:`~transient.models.journal.content_newton`;
        with a ``speed_profile`` those of :mod:`~transient.models.journal.driven_film`, a rough bearing's of
        :mod:`~transient.models.journal.rough_orbit`): error test on the rotor, the film solved by Newton to
        ``BDF2_FILM_TOL`` in pressure (p0) and content per cell. Its Jacobian fills the problem's pattern: the
        operator's (:meth:`problem`) or, faster to factor, the one without the prescribed cells' couplings
        (:meth:`newton_pattern`, what ``run(method="bdf2")`` uses)."""
        f = self.film
        args = self.content_args()
        if self.rough is not None:
            newton, args = rough_bdf2_newton, args + (self.rough,)
        elif self.speed_profile is not None:
            newton, args = driven_newton, (args, np.ones(f.n), self.knots)
        else:
            newton = bdf2_newton
        return Bdf2Model(newton=newton, args=args, error_components=np.arange(f.n, self.n), n_border=N_ROTOR)

    def content_args(self) -> tuple:
        """The arguments of the smooth content kernels (:mod:`~transient.models.journal.content_newton`)."""
        f = self.film
        pattern, gather = self.newton_pattern()
        work = f.work._replace(jac=np.zeros(f.op.nnz), gather=gather)
        return (f.switch, Rotor(self.kappa, self.wbar, self.ebar, f.sym), f.geo, f.fields, f.extras, f.fv, work,
                (BDF2_FILM_TOL, BDF2_FILM_TOL), np.zeros(f.n, dtype=np.int8))

    def newton_pattern(self):
        """The content problem's Jacobian pattern without the entries that are zero by construction (a prescribed
        cell's couplings) and their positions in the operator's pattern
        (:func:`~transient.models.journal.content_newton.decoupled_pattern`; computed once)."""
        if self._newton_pattern is None:
            self._newton_pattern = decoupled_pattern(self.film.op.pattern, self.film.op.free)
        return self._newton_pattern

    def parameters(self) -> dict:
        """Every parameter of the bearing and the rotor that changes an orbit (SI), e.g. to key a checkpoint."""
        return dict(**self.bearing.parameters(), rotor_mass=self.rotor_mass, unbalance=self.unbalance,
                    load=self.load, speed_rpm=self.speed_rpm)

    # ---------------------------------------------------------------------------------------------
    def memory_estimate(self, revolutions, outputs_per_revolution=100, record=(), record_from_revolution=0.0, *,
                        method="ida") -> dict:
        """Bytes a :meth:`run` will need, by part (:func:`orbit_memory`; ``method="bdf2"`` adds its band LU)."""
        return orbit_memory(self.film.n, revolutions, outputs_per_revolution, record, record_from_revolution,
                            band_rows=self._band_rows(method))

    def _band_rows(self, method) -> float:
        """Band storage rows per film cell of ``method``'s linear solver (``bdf2``: ``BDF2_BAND_ROWS`` times the
        grid's smaller dimension, plus the diagonal; the others: none)."""
        return BDF2_BAND_ROWS * min(self.bearing.grid_shape) + 1.0 if method == "bdf2" else 0.0

    def run(self, revolutions, *, start=None, y0=None, touch_gap=1e-3, integration: Integration | None = None,
            recording: Recording | None = None, long_run: LongRun | None = None, speed=None, thermal_interval=1.0,
            temperature=None, **legacy) -> OrbitResult:
        """Integrate ``revolutions`` shaft revolutions from the static equilibrium, from ``y0`` (a state at
        t = 0) or from ``start`` (a previous :class:`OrbitResult`, or ``(time [s], state)``: the run goes on
        from its final state and time, so the unbalance keeps its phase). The first output is the start.

        The settings that are not physics come as objects: ``integration``
        (:class:`~transient.solvers.settings.Integration`: ``method``, ``rtol``, ``atol``, ``steps_per_revolution``,
        ``inner_tolerance``, ``formulation``, ``max_order``; default ``Integration(method="bdf2")``: rtol 1e-6,
        atol 1e-9; an ``Integration`` given without a method is IDA's, its class default), ``recording``
        (:class:`~transient.solvers.settings.Recording`: ``outputs_per_revolution``, ``record``,
        ``record_from_revolution``; default 100 outputs per revolution, nothing extra) and ``long_run``
        (:class:`~transient.solvers.settings.LongRun`: ``chunk_revolutions``, ``checkpoint``, ``resume``,
        ``progress``, ``stop``, ``time_budget``), e.g.
        ``run(20, integration=Integration(method="bdf2", rtol=1e-7), recording=Recording(record=("force",)))``.
        The same settings as loose keywords (``rtol=1e-7``) are deprecated: they still work for one release, with a
        ``DeprecationWarning`` naming the new spelling (beside the object they belong in: an error). The fields of
        the settings objects, and the run's own ``touch_gap``, are these:

        Other Parameters
        ----------------
        method : ``"cvode"``, ``"ida"``, ``"bdf"``, ``"radau"``, ``"lsoda"``, ``"rk4"`` or ``"bdf2"`` (the default:
            variable-step, variable-order BDF, up to ``max_order``, on the content film with its own Newton and a
            bordered band LU, error test on the rotor only: :mod:`transient.solvers.integrate.bdf2`; rtol and atol act
            on the rotor states, the film is solved every step to ``BDF2_FILM_TOL``). ``transient bench orbit-size``
            (docs/bench/orbit_size.md) measures ``"bdf2"`` at its defaults no slower than ``"ida"`` at equal error on
            small (0.01 C, 0.05 C) and large (0.3 C) orbits. The deprecated loose keywords without ``method`` keep
            IDA.
        rtol, atol : tolerances of the adaptive methods; atol is absolute on the dimensionless quantities:
            the journal position and velocity (units of C and C omega) and, per cell, the film content
            theta and the pressure p / p0 (see :meth:`absolute_tolerance`).
        steps_per_revolution : fixed steps of ``"rk4"`` (default 3000, the paper's); for ``"bdf2"`` the least
            number of steps per revolution (its step cap in shaft angle, rtol refining further where the rotor's
            local error asks for it); left out: ``BDF2_MIN_STEPS`` = 50 as a safety bound and each step at most
            ``BDF2_TRAVEL`` = 1e-3 C of journal travel at rtol 1e-6, as sqrt(rtol) at others (the film's fronts
            move with the journal).
        max_order : ``"bdf2"`` only: the highest order of its BDF, 2 to 5 (default ``BDF2_MAX_ORDER`` = 5; 2: plain
            BDF2).
        inner_tolerance : ``"rk4"`` only: the per-stage film criterion sum|d theta| / sum theta (paper: 1e-6).
        outputs_per_revolution : output (sampling) rate.
        record : extra series to keep at the outputs: any of ``"force"`` [N], ``"moment"`` [N m] ((n, 2): the
            film's moment about the bearing centre, about x and y, :mod:`~transient.models.journal.tilt`; zero but
            in a misaligned bush), ``"min_film"`` [m] (the smallest gap over the bearing: at an end in a
            misaligned bush),
            ``"mass"`` [m^3] (film content as liquid volume at the cavitation density, whole bearing),
            ``"outflow"`` [m^3/s] ((n, 2): through the ends, into the groove -- negative: the supply;
            see :meth:`mass_balance`), ``"supply_flow"`` [m^3/s] ((n, feeds): each feed's net supply) and
            ``"side_leakage"`` [m^3/s] ((n, 2): the ends z = -L/2, +L/2; :mod:`~transient.models.journal.flows`),
            ``"pressure"`` [Pa] and ``"film_content"`` (fields: stored only from
            ``record_from_revolution`` (counted from t = 0) on, so a long run keeps only the window it needs).
        chunk_revolutions : integrate in chunks of this many revolutions (progress and checkpoints
            between chunks); default: the whole run in one chunk unless a checkpoint is asked for (10).
        checkpoint : path of an ``.npz`` file rewritten after every chunk; ``resume=True`` continues
            from it; it is keyed on every parameter and setting of the run and refused (naming the one
            that differs) if any changed. Ctrl-C says where it is and how to resume.
        progress : a progress bar over the chunks (default: when the run has more than one chunk).
        touch_gap : stop (``success=False``, ``touched_at``) with a clear message when the eccentricity ratio
            (in a misaligned bush: at the worse end, :meth:`reach`) reaches ``1 - touch_gap`` (with boundary
            layers ``1 - 2 delta / C - touch_gap``: "boundary layers touch at t = ..."); 0 turns the detection off, but a run whose journal reaches the wall (a negative film) is
            still never a success: its message says when and how far.
        stop : ``stop(result_so_far) -> str | None`` called after every chunk; a non-empty string ends
            the run early and becomes its message (e.g. "settled").
        time_budget : wall-clock seconds the whole run may take (None: no limit); past it the run stops with
            ``success=False`` and keeps the outputs so far.
        formulation : ``"universal"`` (default; state u, every method) or ``"content"`` (state H theta, IDA and
            CVODE; :meth:`problem`). The content form conserves a cell's mass exactly through a cavity crossing
            but, at equal rtol, is measured less accurate on the rotor (its full-film pressure is the 1/beta_bar
            part of the content) and no faster (``transient bench orbit-size``, docs/journal.md section 5).
            ``y0``, ``start`` and ``final_state`` are in the universal layout either way.

        A thermal bearing (``JournalBearing(thermal=ThermalFilm(...))``): the temperatures are states of the run on
        their own time scale (:mod:`~transient.models.journal.thermal_orbit`), ``method="bdf2"`` (its default
        there). ``thermal_interval`` [rev, rounded to whole output intervals]: the film runs on the viscosities of the
        temperatures at an interval's start, the temperatures take one implicit step at its end (default 1; the
        splitting error is first order in it); ``temperature`` [K]: the start's
        temperatures, a number or one per cell and feed (default: those of ``start``, else of the static
        equilibrium); ``speed``: deprecated, the shaft's speed ``speed(t)`` [rpm] as a function of time [s] for this run
        (a ``DeprecationWarning``; the same law as ``JournalOrbit(..., speed_profile=speed)``, which every orbit takes).
        ``record`` also takes ``"max_temperature"`` [K], ``"power_loss"`` [W] (the film's dissipation),
        ``"heat_flow"`` [W] (carried away by the oil and into the walls), ``"stored_heat"`` [J] (in the oil and the
        walls above the supply temperature), ``"shaft_speed"`` [rpm] and the field ``"temperature"`` [K]; the
        result's ``final_temperature`` continues with ``start=result``.
        """
        check_method("JournalOrbit.run", requested_method(integration, legacy), step_solve=True)
        revolutions = check_positive("revolutions", revolutions, "rev")
        thermal = self.bearing.thermal is not None
        if not thermal and (speed is not None or temperature is not None):
            raise ValueError("speed, temperature given for an isothermal bearing; allowed: None (they are the thermal "
                             "orbit's: JournalBearing(thermal=ThermalFilm(...)))")
        law = self.speed_profile
        if speed is not None:
            if not callable(speed) or law is not None:
                raise ValueError(f"speed = {speed!r} with speed_profile = {law!r}; allowed: speed(t) -> rpm, callable, "
                                 "and no speed_profile (better: JournalOrbit(..., speed_profile=speed(t)))")
            warnings.warn("run(speed=...) is deprecated; give the law to the orbit: JournalOrbit(..., "
                          "speed_profile=speed) (a function of t [s] or a table ((t, rpm), ...))", DeprecationWarning,
                          stacklevel=2)
            law = SpeedProfile(speed)
        if thermal and integration is None and "method" not in legacy:
            integration = Integration(method="bdf2")
        # the default method only where no integration setting is given (the deprecated keywords keep IDA's)
        default = "ida" if any(RUN_KEYWORDS.get(k, ("",))[0] == "integration" for k in legacy) else DEFAULT_METHOD
        ig, rc, lr = run_settings("JournalOrbit.run", legacy, RUN_KEYWORDS, {"integration": {"method": default}},
                                  integration=integration, recording=recording, long_run=long_run).values()
        method = ig.method
        if ig.dt is not None:
            raise ValueError(f"dt = {ig.dt!r} [-] is not used by the orbit; allowed: steps_per_revolution (the fixed "
                             "steps of method \"rk4\" per revolution), or leave dt out")
        formulation = ig.formulation or ("content" if method == "bdf2" else "universal")
        rc.check_names(RECORDABLE + (THERMAL_RECORDABLE if thermal else ()))
        if thermal and method != "bdf2":
            raise ValueError(f"method = {method!r} with a thermal bearing; allowed: 'bdf2' (the thermal orbit's kernels "
                             "are the content formulation's)")
        if law is not None and set(rc.record) & set(FLOW_RECORDS):
            raise ValueError(f"record = {rc.record!r} with a speed_profile; allowed: without {', '.join(FLOW_RECORDS)} "
                             "(the flow records are at the orbit's speed_rpm)")
        if law is not None and not thermal and self.rough is None and (
                method not in SPEED_LAW_METHODS or (method == "ida" and formulation != "universal")):
            raise ValueError(f"method = {method!r}, formulation = {formulation!r} with a speed_profile: the orbit "
                             "with a speed law integrates with method \"ida\" (formulation \"universal\") or \"bdf2\" "
                             "(formulation \"content\")")
        if method == "bdf2" and formulation != "content":
            raise ValueError('method "bdf2" integrates the content formulation (conservative across a cavity crossing); '
                             'formulation must be "content" (the default for "bdf2")')
        if method == "rk4" and formulation != "universal":
            raise ValueError('method "rk4" solves the film in the universal variable; formulation must be "universal"')
        if self.rough is not None:
            if method not in ROUGH_METHODS or (method == "ida" and formulation != "universal"):
                raise ValueError(f"method = {method!r}, formulation = {formulation!r} with roughness = Roughness(...): "
                                 "the rough orbit integrates with method \"ida\" (formulation \"universal\") or "
                                 "\"bdf2\" (formulation \"content\")")
            touch_gap = 0.0  # the asperities carry the journal through contact: a record, not a stop
        opr = rc.outputs_per_revolution
        if thermal:
            lr = thermal_long_run(lr, thermal_interval, opr)
        run = ModelRun(revolutions, opr, lr, touch_gap)
        check_orbit_memory(self.film.n, revolutions, opr, rc.record, rc.record_from_revolution,
                           band_rows=self._band_rows(method))
        t0, y = start_point(start, OrbitResult)
        if y is None:
            y = self.initial_state() if y0 is None else state_array(y0)
        tau0 = t0 * self.film.omega
        self._set_knots(CONSTANT if law is None else
                        law.knots(self.film.omega, self.speed_rpm, t0 + revolutions * 60.0 / self.speed_rpm))
        run.check_state(y, self.n, "orbit", self._journal)
        step = self._stepper(ig, formulation, run.touch_gap)
        content = formulation == "content"
        solver = dict(method=method, rtol=step.rtol, atol=step.atol, linear_solver=ig.linear_solver,
                      options=step.options,
                      steps=Steps(dt=step.dt, max_step=step.max_step, first_step=step.first_step))
        key = dict(self.parameters(), **ig.key(), outputs_per_revolution=opr, record=sorted(rc.record),
                   record_from_revolution=rc.record_from_revolution, formulation=formulation,
                   **({} if law is None else {"speed_profile": law.key(self.film.omega, self.speed_rpm,
                                                                          t0 + revolutions * 60.0 / self.speed_rpm)}))
        series = ("x", "y", *rc.record, *(("contact_pressure",) if self.rough is not None else ()))
        parts = RunParts(label=f"orbit {self.speed_rpm:g} rpm", omega=self.film.omega, revolution=2 * np.pi,
                         problem_at=step.problem_at, solver=solver, series=series, sparse=FIELD_SERIES,
                         sample=self._sampler(rc.record, 2 * np.pi * rc.record_from_revolution),
                         journals=self._journal,
                         eccentricities=lambda r: [("journal", self._reach_si(r.x, r.y),
                                                    self.bearing.max_eccentricity_ratio)],
                         touch_message=lambda tau, y_: self._touch_message(tau, run.touch_gap),
                         result=lambda rec, stats, touched, message, tau_end: self._result(
                             rec, rc.record, method, stats, touched, message, tau_end),
                         to_run=self.content_state if content else None,
                         universal=self.universal_state if content else None, key=key)
        if thermal:
            parts = thermal_parts(self, parts, run, rc.record, rc.record_from_revolution, self.knots, temperature, start,
                                  tau0, 2 * np.pi / opr)
        r = run.go(parts, y, tau0, 2 * np.pi / opr)
        if method == "rk4":
            r.stats.n_jac = sum(s.n_factorisations for s in step.steppers)
        return r

    def _journal(self, y) -> list:
        """The journal's place in a state of the universal layout (:class:`~transient.solvers.model_run.RunParts`)."""
        n = self.film.n
        return [("journal", float(self.reach(y[n], y[n + 1])), self.bearing.max_eccentricity_ratio)]

    def _touch_message(self, tau, touch_gap) -> str:
        t = tau / self.film.omega
        what = "journal touches the bearing" if self.bearing.layers is None else "boundary layers touch"
        return (f"{what} (eccentricity ratio {self.bearing.max_eccentricity_ratio - touch_gap:.4f}) at t = "
                f"{t:.6g} s ({t * rpm_to_hz(self.speed_rpm):.2f} revolutions)")

    def _sampler(self, record, tau_fields) -> Callable:
        """``sample(tau, y)``: the outputs of a run at one output time, ``y`` in the universal layout: x, y [m]
        always, the ``record`` series asked for (fields from ``tau_fields`` on)."""
        o, f = self, self.film
        n = f.n
        C = o.bearing.clearance
        fields = [k for k in record if k in FIELD_SERIES]
        if self.rough is not None:
            record = tuple(record) + ("contact_pressure",)

        def sample(tau, y):
            row = dict(x=y[n] * C, y=y[n + 1] * C)
            if not record:
                return row
            if "force" in record:
                F = f.force(y[:n], y[n], y[n + 1])
                row["force"] = (F[0] * f.force_scale, F[1] * f.force_scale)
            if "min_film" in record:
                row["min_film"] = C * (1.0 - o.reach(y[n], y[n + 1]))
            if "moment" in record:
                f.residual(y[:n], y[n], y[n + 1])  # the pressure of this state
                row["moment"] = moment(f, f.P)
            if "shaft_speed" in record:
                row["shaft_speed"] = shaft_speed(tau, o.knots)[0] * o.speed_rpm
            if "contact_pressure" in record:
                row["contact_pressure"] = f.p0 * peak_asperity_pressure(y[n], y[n + 1], f.geo, o.rough)
            tribology = [k for k in ("friction_torque", "contact_load") if k in record]
            if tribology:
                row.update({k: v for k, v in orbit_tribology(f, o.bearing, y[:n], y[n], y[n + 1],
                                                             shaft_speed(tau, o.knots)[0] * o.speed_rpm).items()
                            if k in tribology})
            if "mass" in record or "outflow" in record:
                M, q_ends, q_groove = f.mass_flows(y[:n], y[n], y[n + 1])
                vol = C * o.bearing.radius ** 2
                if "mass" in record:
                    row["mass"] = M * vol
                if "outflow" in record:
                    row["outflow"] = (q_ends * vol * f.omega, q_groove * vol * f.omega)
            if "supply_flow" in record or "side_leakage" in record:
                supply, _, leak = film_flows(f, y[:n], y[n], y[n + 1])
                unit = C * o.bearing.radius ** 2 * f.omega
                for k, v in (("supply_flow", supply), ("side_leakage", leak)):
                    if k in record:
                        row[k] = v * unit
            if fields and tau >= tau_fields - 1e-12:
                f.residual(y[:n], y[n], y[n + 1])  # fills P and theta = C(u) (u is not theta - 1 in cavitation)
                grid = o.bearing.grid
                if "pressure" in record:
                    row["pressure"] = grid.to_2d(o.bearing.cavitation_pressure + f.p0 * f.P).astype(np.float32)
                if "film_content" in record:
                    row["film_content"] = grid.to_2d(f.C).astype(np.float32)
            return row

        return sample

    def _result(self, rec, record, method, stats, touched, message, tau_end) -> OrbitResult:
        a = rec.arrays()
        extra = {}
        if self.rough is not None:
            record = tuple(record) + ("contact_pressure",)
            lam = self.bearing.clearance * (1.0 - np.hypot(a["x"], a["y"]) / self.bearing.clearance) / \
                self.bearing.roughness.sigma
            extra["contact_events"] = contact_events(a["t"], lam)
            extra["peak_contact_pressure"] = float(np.max(a["contact_pressure"])) if a["t"].size else 0.0
        for k in record:
            extra[k] = a[k]
            if k in FIELD_SERIES or k in THERMAL_FIELDS:
                if not a[k].size:
                    extra[k] = np.zeros((0, self.bearing.grid.z.n, self.bearing.grid.x.n), dtype=np.float32)
                extra[k + "_t"] = a[k + "_t"]
        return OrbitResult(t=a["t"], x=a["x"], y=a["y"], method=method, stats=stats, speed_rpm=self.speed_rpm,
                           clearance=self.bearing.clearance, touched_at=touched, message=message,
                           final_state=rec.last_y, final_time=float(tau_end) / self.film.omega, **extra)

    def _stepper(self, ig: Integration, formulation: str, touch_gap: float) -> "_Step":
        """The problem at a chunk's start and what :func:`~transient.solvers.integrate.solve` needs for ``ig``:
        ``rk4`` a fixed step of 1 / ``steps_per_revolution`` revolution and a film solver per chunk; ``bdf2`` the
        step cap and its Newton model; the adaptive methods the per-state atol (content form: rtol scaled)."""
        two_pi = 2 * np.pi
        if ig.method == "rk4":
            step = _Step(problem_at=None, dt=two_pi / (3000 if ig.steps_per_revolution is None
                                                       else ig.steps_per_revolution))

            def problem_at(y_, t_):
                step.steppers.append(FilmStageSolver(self, criterion=ig.inner_tolerance))
                return step.steppers[-1].problem(y_, t_)

            step.problem_at = problem_at
            return step
        problem_at = lambda y_, t_: self._problem(y_, t_, touch_gap, formulation)  # noqa: E731
        atol = self.absolute_tolerance(ig.atol, formulation)
        if ig.method == "bdf2":
            announce("bdf2")  # a cold cache compiles the content kernels and the Newton once (~30 s)
            spr = BDF2_MIN_STEPS if ig.steps_per_revolution is None else ig.steps_per_revolution
            n = self.film.n  # the journal's x, y and its velocity weighed each as a plane vector in the error test
            options = {"bdf2": self.bdf2_model(), "max_order": BDF2_MAX_ORDER if ig.max_order is None else ig.max_order,
                       "error_pairs": [[n, n + 1], [n + 2, n + 3]]}
            if ig.steps_per_revolution is None:
                options["max_travel"] = (np.arange(self.film.n, self.film.n + 2),
                                         BDF2_TRAVEL * math.sqrt(ig.rtol / BDF2_TRAVEL_RTOL))
            if self.knots is not CONSTANT:  # a speed law: the cap in shaft angle
                options["max_step_scale"] = step_cap_scale(self.knots)
            pattern = self.newton_pattern()[0]
            return _Step(lambda y_, t_: self._problem(y_, t_, touch_gap, formulation, pattern), rtol=ig.rtol,
                         atol=atol, max_step=two_pi / spr, first_step=two_pi * 1e-4, options=options)
        return _Step(problem_at, rtol=ig.rtol * (CONTENT_RTOL_FACTOR if formulation == "content" else 1.0), atol=atol)

    def at_speed(self, speed_rpm) -> "JournalOrbit":
        """The same rotor on the same bearing at another shaft speed [rpm]."""
        return JournalOrbit(self.bearing, self.rotor_mass, self.unbalance, self.load, speed_rpm)

    def periodic_response(self, **kwargs):
        """The periodic orbit of this rotor at its speed by shooting, with its Floquet multipliers:
        :func:`transient.models.journal.periodic.periodic_response` (its arguments); an orbit that reaches the
        bearing wall is no success."""
        from transient.models.journal.periodic import periodic_response

        self._isothermal_only("periodic_response")
        self._constant_speed_only("periodic_response")
        p = periodic_response(self, **kwargs)
        through = wall_crossing(p.t, self._reach_si(p.x, p.y), self.bearing.max_eccentricity_ratio)
        if through:  # a periodic orbit through the wall is no result, converged or not
            p.success, p.message = False, f"the journal {through}; {p.message}"
        return p

    def response_curve(self, speeds_rpm, **kwargs):
        """Periodic orbits along ``speeds_rpm`` by continuation (amplitude, phase, multipliers, unstable speeds):
        :func:`transient.models.journal.periodic.response_curve` (its arguments)."""
        from transient.models.journal.periodic import response_curve

        self._isothermal_only("response_curve")
        self._constant_speed_only("response_curve")
        return response_curve(self, speeds_rpm, **kwargs)

    def _constant_speed_only(self, what):
        """Refuse ``what`` (a periodic orbit at one speed) on an orbit with a ``speed_profile``."""
        if self.speed_profile is not None:
            raise ValueError(f"{what} with a speed_profile: a periodic orbit turns at one speed; allowed: "
                             "speed_profile=None (at_speed(rpm) gives the orbit at another constant speed)")

    def _isothermal_only(self, what):
        """Refuse ``what`` (the isothermal film's kernels) on a thermal bearing, naming the thermal orbit's way."""
        if self.bearing.thermal is not None:
            raise ValueError(f"{what} with thermal = ThermalFilm(...): it integrates the isothermal film; allowed: "
                             "thermal=None, or run(...) (the thermal orbit, its temperatures as states)")

    def absolute_tolerance(self, atol, formulation="universal") -> np.ndarray:
        """Per-state absolute tolerance for a user ``atol`` on theta, p / p0 and the rotor states.

        Universal layout: a cell's unknown is ``u = p / p0`` in the full film but ``(theta - 1) / r`` in the
        cavitated zone (:mod:`transient.physics.cavitation`, ``r`` = content width / pressure width of the
        switch), so the cells get ``atol min(1, 1 / r)``: neither the content nor the pressure is held more
        loosely than ``atol``. Content layout: the cells' unknown is the content ``H theta`` itself and gets
        ``atol``."""
        atol = check_range("atol", atol, "-", ATOL_FLOOR, 1.0, why=ATOL_WHY)
        out = np.full(self.n, atol)
        if formulation == "universal":
            out[: self.film.n] = atol * min(1.0, 1.0 / self.film.content_scale)
        elif formulation != "content":
            raise ValueError(f"formulation = {formulation!r}; allowed: {', '.join(FORMULATIONS)}")
        return out

    # ---------------------------------------------------------------------------------------------
    @staticmethod
    def mass_balance(result: OrbitResult) -> dict:
        """Global mass balance of a run recorded with ``record=("mass", "outflow")``, per revolution::

            error_k = M(t_k+1) - M(t_k) + int_{t_k}^{t_k+1} (q_ends + q_groove) dt

        (exactly zero for the semi-discrete model, so it measures the time integration), relative to the
        throughput of that revolution ``int |q_ends| dt`` (the leakage the supply replaces). The
        integral is taken with the composite Simpson rule on the outputs (use an even number of
        outputs per revolution; its own error is reported as the difference to the trapezoidal rule).

        Returns ``revolution_end_times`` [s], ``error`` [m^3], ``throughput`` [m^3], ``relative``
        (error / throughput) and ``quadrature_relative`` (|Simpson - trapezoid| / throughput).
        """
        from scipy.integrate import simpson, trapezoid

        if "mass" not in result.fields or "outflow" not in result.fields:
            raise ValueError('mass_balance needs a run recorded with record=("mass", "outflow")')
        t, M, q = result.t, result.mass, result.outflow
        per_rev = 60.0 / result.speed_rpm
        k_end = int(np.floor((t[-1] - t[0]) / per_rev + 1e-9))
        out = {"revolution_end_times": [], "error": [], "throughput": [], "relative": [],
               "quadrature_relative": []}
        for k in range(k_end):
            a = int(np.argmin(np.abs(t - (t[0] + k * per_rev))))
            b = int(np.argmin(np.abs(t - (t[0] + (k + 1) * per_rev))))
            s = slice(a, b + 1)
            net = q[s, 0] + q[s, 1]
            flow = simpson(net, x=t[s])
            err = M[b] - M[a] + flow
            thr = simpson(np.abs(q[s, 0]), x=t[s])
            out["revolution_end_times"].append(t[b])
            out["error"].append(err)
            out["throughput"].append(thr)
            out["relative"].append(abs(err) / thr)
            out["quadrature_relative"].append(abs(flow - trapezoid(net, x=t[s])) / thr)
        return {k: np.array(v) for k, v in out.items()}


def contact_events(t, lam, onset=CONTACT_LAMBDA) -> list:
    """``[(t [s], "begins" | "ends"), ...]`` where the film parameter ``lam = h_min / sigma`` at the times ``t``
    falls below (contact begins) or rises above (ends) ``onset``, linearly interpolated between outputs; a run that
    starts in contact begins with ``(t_0, "begins")``."""
    t, lam = np.asarray(t, dtype=float), np.asarray(lam, dtype=float)
    out = [(float(t[0]), "begins")] if t.size and lam[0] < onset else []
    for k in np.flatnonzero((lam[1:] < onset) != (lam[:-1] < onset)):
        a, b = lam[k] - onset, lam[k + 1] - onset
        out.append((float(t[k] + (t[k + 1] - t[k]) * a / (a - b)), "begins" if b < 0 else "ends"))
    return out


def orbit_memory(cells, revolutions, outputs_per_revolution=100, record=(), record_from_revolution=0.0, *,
                 band_rows=0.0) -> dict:
    """Bytes an orbit run on ``cells`` film cells will need, by part: ``model`` (the film's arrays and operator
    tables, 1.1 kB per cell) and ``solver`` (sparse Jacobian, LU factors, integrator workspace, 5.5 kB per
    cell) -- both measured (peak resident memory of a 0.02-revolution IDA run on the 151 x 21, 300 x 42 and
    600 x 84 grids: 4.8, 6.6 and 6.4 kB per cell in all, docs/validation.md) -- and ``recordings`` (per output:
    40 bytes per recorded number while running, then the arrays; fields 8 bytes per cell from
    ``record_from_revolution`` on); ``band_rows`` > 0 (``method="bdf2"``) adds the band LU, 8 bytes per row and
    cell."""
    outputs = revolutions * outputs_per_revolution + 1
    scalars = 3 + sum(dict(force=2, moment=2, min_film=1, mass=1, outflow=2).get(k, 0) for k in record)
    fields = sum(k in FIELD_SERIES for k in record)
    field_outputs = max(0.0, revolutions - record_from_revolution) * outputs_per_revolution + 1
    parts = dict(model=1100.0 * cells, solver=5500.0 * (cells + N_ROTOR))
    if band_rows:
        parts["band LU"] = 8.0 * band_rows * cells
    return dict(parts, recordings=40.0 * scalars * outputs + 8.0 * cells * fields * field_outputs)


def check_orbit_memory(cells, revolutions, outputs_per_revolution=100, record=(), record_from_revolution=0.0, *,
                       band_rows=0.0):
    """Refuse (one line, :class:`~transient.checks.MemoryLimitError`) an orbit run whose :func:`orbit_memory`
    exceeds the stated share of the machine's memory, naming the parameters to change: the grid when the film and
    its solver alone do not fit, else the run's length and recordings."""
    parts = orbit_memory(cells, revolutions, outputs_per_revolution, record, record_from_revolution,
                         band_rows=band_rows)
    check_run_memory(f"this orbit run ({revolutions:g} rev x {outputs_per_revolution} outputs/rev on {cells} cells)",
                     parts, GRID_ADVICE, "lower revolutions or outputs_per_revolution, or record fewer series "
                     "(record=, record_from_revolution=) (a long run can go on in parts with start=)")


def check_orbit_grid_memory(cells):
    """Refuse, before its film is built, an orbit whose film and integrator alone (:func:`orbit_memory` of a run of
    one output) do not fit this machine, naming the grid."""
    parts = orbit_memory(cells, 0.0, 1)
    parts.pop("recordings")
    check_memory(f"an orbit on {cells} film cells", parts, GRID_ADVICE)


@dataclass
class _Step:
    """How one orbit run is integrated: the problem at a chunk's start and the arguments of
    :func:`~transient.solvers.integrate.solve` (its defaults where the method takes none); ``rk4`` keeps its
    film solvers in ``steppers`` (their factorisations count as Jacobians)."""

    problem_at: Callable | None
    rtol: float = 1e-6
    atol: float | np.ndarray = 1e-8
    dt: float | None = None
    max_step: float = 0.0
    first_step: float = 0.0
    options: dict | None = None
    steppers: list = field(default_factory=list)


def _prefetching(film, callback, formulation):
    """``callback(t, y, ...)`` preceded by the film's :meth:`~transient.models.journal.film.Film.prefetch` at ``y``."""
    n = film.n
    if formulation == "content":
        def wrapped(t, y, *args):
            film.prefetch_content(y)
            callback(t, y, *args)
    else:
        def wrapped(t, y, *args):
            film.prefetch(y[:n], y[n], y[n + 1])
            callback(t, y, *args)
    return wrapped


def _content_slope(residual, scale, free, n, args):
    """``rhs(t, y, out)``: ``y'`` of a content state from its ``residual`` at ``y' = 0`` (``A m' + R = 0`` solved for
    ``m'`` on the ``free`` cells with ``scale = A``, zero on the others; the rotor rows ``y' - f(y)``), on the fields
    of ``y`` itself, not those the content kernels' ``args`` hold (:func:`~.content_newton.forget_fields`)."""
    def rhs(t, y, out):
        forget_fields(args)
        residual(t, np.array(y), np.zeros(y.size), out)  # writable, as the Newton calls it: one compiled signature
        out[:n] /= -scale
        out[:n][~free] = 0.0
        out[n:] *= -1.0

    return rhs
