"""Unbalanced rigid rotor on a journal bearing with the Elrod film, in the time domain (seed 003).

:class:`JournalOrbit` assembles the film + rotor method-of-lines system of
:mod:`transient.models.journal.kernels` and integrates it through :func:`transient.solvers.integrate.solve`:

* ``"cvode"``, ``"bdf"``, ``"radau"``, ``"lsoda"`` -- the ODE form ``y' = f(tau, y)`` with the analytic
  sparse arrow Jacobian (LSODA gets it dense: scipy's limitation);
* ``"ida"`` -- the residual form ``F(tau, y, y') = 0`` with its analytic Jacobian ``dF/dy + cj dF/dy'``;
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

import os
import sys
import time
from dataclasses import dataclass, field

import numpy as np

from transient.solvers.integrate import Problem, Stats, solve
from transient.solvers.newton import Chord, NewtonError, newton
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.kernels import (N_ROTOR, dae_jacobian, dae_residual, film_force, ode_jacobian,
                                           ode_rhs)
from transient.checks import check_positive, check_range

RECORDABLE = ("force", "pressure", "film_content", "min_film", "mass", "outflow")


@dataclass
class OrbitResult:
    """Time series of one orbit run (outputs at ``outputs_per_revolution`` per revolution).

    ``t`` [s], ``x``, ``y`` [m] (journal centre; x towards the load), ``eccentricity_ratio``,
    ``force`` [N] (film force on the journal, (n, 2), if recorded), ``pressure`` [Pa] ((n, nz, ntheta),
    only if recorded and only over the recorded window), ``stats`` (integrator statistics, summed over
    chunks), ``touched_at`` [s] if the journal reached the wall (then the run stopped there).
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    method: str
    stats: Stats
    speed_rpm: float
    clearance: float
    fields: dict = field(default_factory=dict)
    touched_at: float | None = None
    message: str = ""
    final_state: np.ndarray | None = None  # full state vector (film + rotor) at the end, to continue a run

    @property
    def eccentricity_ratio(self) -> np.ndarray:
        return np.hypot(self.x, self.y) / self.clearance

    @property
    def revolutions(self) -> np.ndarray:
        return self.t * self.speed_rpm / 60.0

    def __getattr__(self, name):
        fields = self.__dict__.get("fields", {})
        if name in fields:
            return fields[name]
        raise AttributeError(name)


class JournalOrbit:
    """Rigid rotor (2 DOF) with unbalance on one journal bearing.

    Parameters (SI)
    ----------
    bearing : :class:`~transient.models.journal.JournalBearing`.
    rotor_mass [kg] : mass carried by this bearing (paper: m = W / g).
    unbalance [m] : mass eccentricity e of the rotor (unbalance force m e Omega^2; paper: 0.01 C).
    load [N] : static load on the bearing, acting in +x (towards the bottom).
    speed_rpm [rpm] : shaft speed.
    """

    def __init__(self, bearing: JournalBearing, rotor_mass, unbalance, load, speed_rpm):
        if not isinstance(bearing, JournalBearing):
            raise TypeError(f"bearing must be a JournalBearing, got {type(bearing).__name__}")
        self.bearing = bearing
        self.rotor_mass = check_positive("rotor_mass", rotor_mass, "kg")
        self.unbalance = check_range("unbalance", unbalance, "m", 0.0, bearing.clearance, high_open=True,
                                     why="(mass eccentricity, must be below the clearance)")
        self.load = check_range("load", load, "N", 0.0, np.inf, high_open=True)
        self.speed_rpm = check_positive("speed_rpm", speed_rpm, "rpm")
        self.film = bearing.film(speed_rpm)
        f = self.film
        mc_w2 = self.rotor_mass * bearing.clearance * f.omega ** 2
        self.kappa = f.force_scale / mc_w2
        self.wbar = self.load / mc_w2
        self.ebar = self.unbalance / bearing.clearance
        self._equilibrium = None

    # ---------------------------------------------------------------------------------------------
    @property
    def n(self) -> int:
        return self.film.n + N_ROTOR

    def equilibrium(self):
        """Static equilibrium of the bearing under ``load`` (cached)."""
        if self._equilibrium is None:
            if self.load > 0:
                self._equilibrium = self.bearing.equilibrium(self.load, self.speed_rpm)
            else:
                self._equilibrium = self.bearing.steady_state(0.0, self.speed_rpm)
        return self._equilibrium

    def initial_state(self) -> np.ndarray:
        """Film and journal at the static equilibrium, journal at rest (the paper's start)."""
        e = self.equilibrium()
        y0 = np.zeros(self.n)
        y0[: self.film.n] = e.u
        y0[self.film.n] = e.position[0] / self.bearing.clearance
        y0[self.film.n + 1] = e.position[1] / self.bearing.clearance
        return y0

    def problem(self, y0=None, tau0=0.0, touch_gap=0.0) -> Problem:
        """The method-of-lines :class:`Problem` in dimensionless time tau = omega t.

        ``touch_gap`` > 0 adds a terminal event when the eccentricity ratio reaches ``1 - touch_gap``
        (the journal touches the bearing)."""
        f, w, op = self.film, self.film.w, self.film.op
        y0 = self.initial_state() if y0 is None else np.asarray(y0, dtype=float)
        common = (f.beta_bar, f.width, f.content_scale)
        scratch = (*w.fields(), w.zero, w.R)
        rargs = op.residual_args
        n = f.n
        kappa, wbar, ebar, sym = self.kappa, self.wbar, self.ebar, w.sym
        geo = (w.cosp, w.sinp, w.area)
        jargs = op.jacobian_face_args
        fbuf = np.empty(self.n)

        def rhs(t, y, out):
            ode_rhs(t, y, out, *common, kappa, wbar, ebar, sym, *geo, *scratch, *rargs)

        def jac_rhs(t, y, data):
            ode_rhs(t, y, fbuf, *common, kappa, wbar, ebar, sym, *geo, *scratch, *rargs)
            ode_jacobian(t, y, data, fbuf, *common, kappa, sym, *geo, *w.fields(), w.zero,
                         w.dk_dq, w.dc_dq, w.no_dq, w.pos_row, w.pos_col, w.indices, w.scale, *jargs)

        def residual(t, y, yp, out):
            dae_residual(t, y, yp, out, *common, kappa, wbar, ebar, sym, *geo, *scratch, *rargs)

        def jac_residual(t, y, yp, cj, data):
            dae_jacobian(t, y, yp, cj, data, *common, kappa, sym, *geo, *w.fields(),
                         w.zero, w.dk_dq, w.dc_dq, w.no_dq, w.pos_row, w.pos_col, *jargs)

        yp0 = np.empty(self.n)
        rhs(tau0, y0, yp0)
        events = None
        if touch_gap > 0:
            limit = (1.0 - touch_gap) ** 2

            def events(t, y, out):
                out[0] = limit - (y[n] ** 2 + y[n + 1] ** 2)

        return Problem(y0=y0, yp0=yp0, rhs=rhs, residual=residual, jac_pattern=op.pattern, jac_rhs=jac_rhs,
                       jac_residual=jac_residual, events=events, n_events=1 if events else 0,
                       event_terminal=[True], event_direction=[-1], name="journal orbit")

    # ---------------------------------------------------------------------------------------------
    def run(self, revolutions, method="ida", rtol=1e-6, atol=1e-9, steps_per_revolution=3000,
            outputs_per_revolution=100, record=(), record_from_revolution=0.0, chunk_revolutions=None,
            checkpoint=None, resume=False, progress=None, touch_gap=1e-3, y0=None,
            inner_tolerance=1e-6) -> OrbitResult:
        """Integrate ``revolutions`` shaft revolutions from the static equilibrium (or ``y0``).

        Parameters
        ----------
        method : ``"cvode"``, ``"ida"``, ``"bdf"``, ``"radau"``, ``"lsoda"`` or ``"rk4"``.
        rtol, atol : tolerances of the adaptive methods; atol is absolute on the dimensionless quantities:
            the journal position and velocity (units of C and C omega) and, per cell, the film content
            theta and the pressure p / p0 (see :meth:`absolute_tolerance`).
        steps_per_revolution : fixed steps of ``"rk4"`` (paper: 3000).
        inner_tolerance : ``"rk4"`` only: the per-stage film criterion sum|d theta| / sum theta (paper: 1e-6).
        outputs_per_revolution : output (sampling) rate.
        record : extra series to keep at the outputs: any of ``"force"`` [N], ``"min_film"`` [m],
            ``"mass"`` [m^3] (film content as liquid volume at the cavitation density, whole bearing),
            ``"outflow"`` [m^3/s] ((n, 2): through the ends, into the groove -- negative: the supply;
            see :meth:`mass_balance`), ``"pressure"`` [Pa] and ``"film_content"`` (fields: stored only from
            ``record_from_revolution`` on, so a long run keeps only the window it needs).
        chunk_revolutions : integrate in chunks of this many revolutions (progress and checkpoints
            between chunks); default: the whole run in one chunk unless a checkpoint is asked for (10).
        checkpoint : path of an ``.npz`` file rewritten after every chunk; ``resume=True`` continues
            from it (same parameters) instead of starting again.
        progress : print progress after each chunk (default: when the run has more than one chunk).
        touch_gap : stop with a clear message when the eccentricity ratio reaches ``1 - touch_gap``.
        """
        revolutions = check_positive("revolutions", revolutions, "rev")
        bad = [r for r in record if r not in RECORDABLE]
        if bad:
            raise ValueError(f"record: unknown series {bad}; allowed: {RECORDABLE}")
        if outputs_per_revolution < 1:
            raise ValueError(f"outputs_per_revolution must be >= 1, got {outputs_per_revolution}")
        if chunk_revolutions is None:
            chunk_revolutions = 10.0 if checkpoint else revolutions
        chunk_revolutions = check_positive("chunk_revolutions", chunk_revolutions, "rev")
        n_chunks = int(np.ceil(revolutions / chunk_revolutions - 1e-9))
        progress = (n_chunks > 1) if progress is None else progress
        rec = _Recorder(self, record, record_from_revolution)
        y = self.initial_state() if y0 is None else np.array(y0, dtype=float)
        done = 0.0
        if resume and checkpoint and os.path.exists(checkpoint):
            y, done = rec.load(checkpoint, self, method)
        done0 = done
        stats = Stats()
        touched, message = None, "reached the final time"
        wall0 = time.perf_counter()
        while done < revolutions - 1e-9 and touched is None:
            span = min(chunk_revolutions, revolutions - done)
            k_out = max(1, int(round(span * outputs_per_revolution)))
            tau = 2 * np.pi * (done + np.linspace(0.0, span, k_out + 1))
            if method == "rk4":
                res = self._run_rk4(y, tau, steps_per_revolution, rec, inner_tolerance)
            else:
                prob = self.problem(y, tau[0], touch_gap)
                res = solve(prob, tau, method=method, rtol=rtol, atol=self.absolute_tolerance(atol), store=False,
                            observer=rec.observe)
            _accumulate(stats, res.stats)
            if not res.success:
                raise RuntimeError(f"orbit integration ({method}) failed after {done:.3f} revolutions: {res.message}")
            y = rec.last_y
            if res.t_events.size:
                touched = float(res.t_events[0]) / self.film.omega
                message = (f"journal touches the bearing (eccentricity ratio {1 - touch_gap:.4f}) at t = "
                           f"{touched:.6g} s ({touched * self.speed_rpm / 60:.2f} revolutions)")
                rec.observe(float(res.t_events[0]), res.y_events[0])
            done += span
            if checkpoint:
                rec.save(checkpoint, y, done, method)
            if progress:
                el = time.perf_counter() - wall0
                print(f"  [{method}] {done:8.1f}/{revolutions:g} rev  e/C = {rec.last_eps:.4f}  "
                      f"{el:7.1f} s elapsed  ({el / max(done - done0, 1e-9):.3f} s/rev)", file=sys.stderr, flush=True)
        stats.wall_time = time.perf_counter() - wall0
        return rec.result(method, stats, touched, message)

    def absolute_tolerance(self, atol) -> np.ndarray:
        """Per-state absolute tolerance for a user ``atol`` on theta, p / p0 and the rotor states.

        A cell's unknown is ``u = p / p0`` in the full film but ``(theta - 1) / r`` in the cavitated zone
        (:mod:`transient.physics.cavitation`, ``r`` = content width / pressure width of the switch), so the
        cells get ``atol min(1, 1 / r)``: neither the content nor the pressure is held more loosely than
        ``atol``."""
        atol = check_positive("atol", atol, "-")
        out = np.full(self.n, atol)
        out[: self.film.n] = atol * min(1.0, 1.0 / self.film.content_scale)
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

    # ---------------------------------------------------------------------------------------------
    def _run_rk4(self, y0, tau, steps_per_revolution, rec, inner_tolerance):
        """The paper's scheme through the facade's RK4 with its per-stage inner film solve."""
        stepper = FilmStageSolver(self, criterion=check_positive("inner_tolerance", inner_tolerance, "-"))
        prob = stepper.problem(y0, tau[0])
        dtau = 2 * np.pi / check_range("steps_per_revolution", steps_per_revolution, "1/rev", 4, 1e7)
        res = solve(prob, tau, method="rk4", dt=dtau, store=False, observer=rec.observe)
        res.stats.n_jac = stepper.n_factorisations
        return res


class FilmStageSolver:
    """Per-stage film solve of the RK4 baseline (paper: Elrod iteration every time step).

    For the rotor state of a stage at time ``tau_s`` it solves the film equations with the squeeze rate
    of the stage and a backward-Euler time derivative from the film ``u_n`` of the step start::

        A_i (theta_i H'_i + H_i / beta_bar (u_i - u_n,i) / (tau_s - tau_n)) + R_i(u) = 0

    by Newton iterations until the paper's criterion (eq. 6) ``sum|d theta| / sum theta < 1e-6``. The
    LU factorisation is reused across iterations, stages and steps, and refreshed when an iteration
    fails to contract (chord Newton).
    """

    def __init__(self, orbit: JournalOrbit, criterion=1e-6, max_iter=50):
        self.orbit = orbit
        self.film = orbit.bearing.film(orbit.speed_rpm, n_extra=0)
        self.n = self.film.n
        self.criterion = criterion
        self.max_iter = max_iter
        self.chord = Chord()
        self.n_iterations = 0
        self.t_hist = None
        self.u_hist = None
        self.theta_hist = None
        self.data = np.empty(self.film.op.nnz)

    def problem(self, y0, tau0) -> Problem:
        o, f = self.orbit, self.film
        n = self.n
        w = f.w

        def rhs(t, y, out):  # rotor only; the cells' entries are ignored (algebraic)
            fx, fy = film_force(w.P, w.cosp, w.sinp, w.area, w.sym)  # P of the film just solved for y
            out[:n] = 0.0
            out[n] = y[n + 2]
            out[n + 1] = y[n + 3]
            out[n + 2] = o.kappa * fx + o.wbar + o.ebar * np.cos(t)
            out[n + 3] = o.kappa * fy + o.ebar * np.sin(t)

        def step_begin(t, y):
            if self.t_hist is None:
                self.u_hist = y[:n].copy()
            elif t > self.t_hist:  # film at the new step start, for the rotor state RK4 produced
                self.u_hist = self._solve(t, y)
            else:
                return
            self.t_hist = t
            f.residual(self.u_hist, y[n], y[n + 1], y[n + 2], y[n + 3])
            self.theta_hist = f.w.C.copy()

        def algebraic_solve(t, y):
            if self.t_hist is None:  # the initial state: its film is the history
                step_begin(t, y)
            y = y.copy()
            y[:n] = self._solve(t, y) if t > self.t_hist else self.u_hist
            if t <= self.t_hist:  # the fields (P) must correspond to this film for rhs
                f.residual(y[:n], y[n], y[n + 1], y[n + 2], y[n + 3])
            return y

        return Problem(y0=np.asarray(y0, dtype=float), rhs=rhs, algebraic=np.arange(n),
                       algebraic_solve=algebraic_solve, step_begin=step_begin, name="journal orbit (RK4 + film)")

    def _solve(self, t, y):
        """Film at stage time t for the stage's rotor state y: chord Newton (one factorisation kept across
        iterations, stages and steps while it contracts) to the paper's criterion on theta."""
        n, f = self.n, self.film
        X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
        rate = 1.0 / (t - self.t_hist)
        G = lambda v: f.residual(v, X, Y, VX, VY, rate=rate, C_ref=self.theta_hist)  # noqa: E731
        J = lambda v, shift: f.op.matrix(f.jacobian_data(v, X, Y, VX, VY, rate=rate, data=self.data))  # noqa: E731
        G(self.u_hist)
        theta = [f.w.C.copy()]

        def converged(v, r, dv):  # paper eq. (6); the scratch fields hold the last iterate's film
            new = f.w.C.copy()
            done = np.sum(np.abs(new - theta[0])) < self.criterion * np.sum(new)
            theta[0] = new
            return done

        try:
            res = newton(G, J, self.u_hist, chord=self.chord, converged=converged, max_iter=self.max_iter,
                         name="RK4 film iteration")
        except NewtonError:
            raise RuntimeError(f"RK4 film iteration did not reach the criterion {self.criterion} in {self.max_iter} "
                               f"iterations at tau = {t:.6g}") from None
        self.n_iterations += res.iterations
        return res.x

    @property
    def n_factorisations(self) -> int:
        return self.chord.n_factorisations


class _Recorder:
    """Keeps x, y (always) and the requested series at the output times; streams, never the whole state."""

    def __init__(self, orbit: JournalOrbit, record, record_from_revolution):
        self.o = orbit
        self.record = tuple(record)
        self.tau0_fields = 2 * np.pi * record_from_revolution
        self.t, self.x, self.y = [], [], []
        self.series = {k: [] for k in self.record}
        self.last_y = None
        self.last_tau = -np.inf

    def observe(self, tau, y):
        o, f = self.o, self.o.film
        n = f.n
        self.last_y = np.array(y)
        if tau <= self.last_tau:  # a chunk starts with the last output of the previous one
            return
        self.last_tau = tau
        C = o.bearing.clearance
        self.t.append(tau / f.omega)
        self.x.append(y[n] * C)
        self.y.append(y[n + 1] * C)
        if not self.record:
            return
        if "force" in self.record:
            F = f.force(y[:n], y[n], y[n + 1])
            self.series["force"].append((F[0] * f.force_scale, F[1] * f.force_scale))
        if "min_film" in self.record:
            self.series["min_film"].append(C * (1.0 - np.hypot(y[n], y[n + 1])))
        if "mass" in self.record or "outflow" in self.record:
            M, q_ends, q_groove = f.mass_flows(y[:n], y[n], y[n + 1])
            vol = C * o.bearing.radius ** 2
            if "mass" in self.record:
                self.series["mass"].append(M * vol)
            if "outflow" in self.record:
                self.series["outflow"].append((q_ends * vol * f.omega, q_groove * vol * f.omega))
        if tau >= self.tau0_fields - 1e-12:
            grid = o.bearing.grid
            if "pressure" in self.record:
                f.residual(y[:n], y[n], y[n + 1])
                self.series["pressure"].append((tau / f.omega, grid.to_2d(o.bearing.cavitation_pressure
                                                                          + f.p0 * f.w.P).astype(np.float32)))
            if "film_content" in self.record:
                f.residual(y[:n], y[n], y[n + 1])  # theta = C(u) (u is not theta - 1 in cavitation)
                self.series["film_content"].append((tau / f.omega, grid.to_2d(f.w.C).astype(np.float32)))

    @property
    def last_eps(self):
        n = self.o.film.n
        return float(np.hypot(self.last_y[n], self.last_y[n + 1]))

    def result(self, method, stats, touched, message) -> OrbitResult:
        fields = {}
        for k, v in self.series.items():
            if k in ("pressure", "film_content"):
                fields[k + "_t"] = np.array([a for a, _ in v])
                fields[k] = np.array([b for _, b in v]) if v else np.zeros((0,))
            else:
                fields[k] = np.array(v)
        return OrbitResult(t=np.array(self.t), x=np.array(self.x), y=np.array(self.y), method=method, stats=stats,
                           speed_rpm=self.o.speed_rpm, clearance=self.o.bearing.clearance, fields=fields,
                           touched_at=touched, message=message, final_state=self.last_y)

    # checkpoints ---------------------------------------------------------------------------------
    def save(self, path, y, done, method):
        tmp = f"{path}.tmp.npz"
        np.savez(tmp, y=y, done=done, method=method, last_tau=self.last_tau, t=np.array(self.t), x=np.array(self.x), yy=np.array(self.y),
                 signature=_signature(self.o),
                 **{f"series_{k}": np.array(v, dtype=object) for k, v in self.series.items()})
        os.replace(tmp, path)

    def load(self, path, orbit, method):
        d = np.load(path, allow_pickle=True)
        if str(d["signature"]) != _signature(orbit) or str(d["method"]) != method:
            raise ValueError(f"checkpoint {path} was written by a different orbit or method; delete it or "
                             f"run with resume=False")
        self.t, self.x, self.y = list(d["t"]), list(d["x"]), list(d["yy"])
        for k in self.series:
            if f"series_{k}" in d:  # scalar / pair series back as floats (not object arrays)
                v = d[f"series_{k}"]
                self.series[k] = list(v) if k in ("pressure", "film_content") else v.tolist()
        self.last_y = np.array(d["y"])
        self.last_tau = float(d["last_tau"])
        return np.array(d["y"]), float(d["done"])


def _signature(o: JournalOrbit) -> str:
    b = o.bearing
    return repr((b.diameter, b.length, b.clearance, b.viscosity, b.bulk_modulus, b.supply_pressure, b.groove,
                 b.grid_shape, b.switch_width, b.switch_content_width, b.symmetric, b.cavitation_pressure, b.ambient_pressure,
                 o.rotor_mass, o.unbalance, o.load, o.speed_rpm))


def _accumulate(total: Stats, part: Stats):
    total.n_steps += part.n_steps
    total.n_rhs += part.n_rhs
    total.n_jac += part.n_jac
    total.callback_time += part.callback_time
