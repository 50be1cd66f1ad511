"""The periodic unbalance response of a rotor on journal bearings by shooting: a fixed point of the
once-per-revolution map of the whole system (films and rotor), by Newton-Picard
(:func:`transient.solvers.shooting.newton_picard`: Lust, Roose, Spence & Champneys 1998) on the subspace of the
least damped modes of the linearisation with the film states, with the Floquet multipliers of that subspace.

The map starts every period at shaft angle 0 (``tau = 0``, the unbalance forcing's phase); its unknowns are the
free film cells and the rotor's coordinates and velocities (the groove cells are held, the angle is the time).
The fixed-point tolerance is on the rotor's coordinates and velocities, in units of the smallest clearance.

The period map's time integrator (``integrator``, :data:`INTEGRATORS`): IDA on the system's universal film
(:class:`~transient.models.rotor.model.SystemDAE`), or the conservative BDF2 on the films' content form
(:class:`~transient.models.rotor.content_form.ContentSystem`, the step solve of ``run(method="bdf2")``: at least
``BDF2_STEPS_PER_REVOLUTION`` steps per revolution, its error test on the rotor's states), mapped from and back to the
universal state, so that the map's unknowns, the start and the result are the same either way.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import scipy.sparse.linalg as spla

from transient.checks import check_choice
from transient.compile_notice import announce
from transient.models.rotor.content_form import BDF2_STEPS_PER_REVOLUTION, ContentSystem
from transient.models.rotor.model import SystemDAE
from transient.models.rotor.results import PeriodicResponse, RotorResponseCurve
from transient.solvers.integrate import Problem, Steps, solve
from transient.solvers.shooting import ShootingSettings, extrapolate_state, newton_picard, stability_onset_speed

#: time integrators of the period map: IDA on the universal films, or the conservative BDF2 on their content form
INTEGRATORS = ("ida", "bdf2")
#: the iteration where no ``shooting=ShootingSettings(...)`` is given (one relaxing period: the start's film is the
#: linearisation's, not the periodic one)
SHOOTING_DEFAULTS = dict(max_iter=25, relax=1)


class PeriodMap:
    """``flow(z, t0, T, rtol)``: the reduced state ``z`` (free cells, q~, v) after ``T`` of the time tau at
    constant speed by ``integrator`` (module docstring), keeping the outputs of the tightest flow of the last few
    states (``samples``: the orbit of the accepted state without integrating it again)."""

    def __init__(self, dae: SystemDAE, outputs_per_revolution: int, atol: float, integrator: str = "ida"):
        self.dae = dae
        self.integrator = check_choice("integrator", integrator, INTEGRATORS)
        self.form = self.model = None  # the content form and its step solve, built at the first BDF2 flow
        keep = np.ones(dae.n, dtype=bool)
        for b in dae.blocks:
            keep[b.offset:b.offset + b.n] = b.film.op.free
        keep[dae.P0] = False
        self.keep = keep
        self.fixed = np.zeros(dae.n)
        for b in dae.blocks:
            self.fixed[b.offset:b.offset + b.n] = b.film.op.u_fixed
        self.opr = outputs_per_revolution
        self.atol = dae.absolute_tolerance(atol)
        self.samples = {}
        self.rotor = slice(int(np.count_nonzero(keep[:dae.Q0])), int(np.count_nonzero(keep)))

    def embed(self, z) -> np.ndarray:
        y = self.fixed.copy()
        y[self.dae.P0] = 0.0
        y[self.keep] = z
        return y

    def reduce(self, y) -> np.ndarray:
        return np.asarray(y)[self.keep] if np.ndim(y) == 1 else np.asarray(y)[self.keep, :]

    def _solve(self, y, t_eval, rtol):
        """The run over ``t_eval`` from the universal state ``y``: (solution, its final state in the universal
        layout). The rotor's states sit at the same places in both layouts."""
        dae = self.dae
        if self.integrator == "ida":
            p = Problem(y0=y, yp0=dae.consistent_yp(t_eval[0], y), residual=dae.residual, jac_pattern=dae.pattern,
                        jac_residual=dae.jacobian, name="rotor period map")
            s = solve(p, t_eval, method="ida", rtol=rtol, atol=self.atol)
            return s, (s.y[-1] if s.y.size else None)
        if self.form is None:
            announce("rotor_bdf2")  # a cold cache compiles the films' content kernels and the Newton once
            self.form = ContentSystem(dae)
            self.model = self.form.model()
        form = self.form
        s = solve(form.problem(form.content_state(y), t_eval[0]), t_eval, method="bdf2", rtol=rtol, atol=self.atol,
                  steps=Steps(max_step=2 * np.pi / BDF2_STEPS_PER_REVOLUTION, first_step=2 * np.pi * 1e-4),
                  options={"bdf2": self.model})
        return s, (form.universal_state(s.y[-1]) if s.y.size else None)

    def __call__(self, z, t0, T, rtol):
        t_eval = np.linspace(t0, t0 + T, self.opr + 1)
        s, end = self._solve(self.embed(z), t_eval, rtol)
        if not s.success or s.t.size < t_eval.size:
            return np.full(z.size, np.nan)
        key = np.asarray(z, dtype=float).tobytes()
        if key not in self.samples or rtol <= self.samples[key][0]:  # keep the tightest run of a state
            if len(self.samples) > 8:
                self.samples.pop(next(iter(self.samples)))
            self.samples[key] = (rtol, s.t, np.array(s.y[:, self.dae.Q0:self.dae.V0]))
        return end[self.keep]

    def norm(self, d) -> float:
        """The rotor's coordinates and velocities, in the smallest clearance (per radian)."""
        return float(np.max(np.abs(d[self.rotor])))


def dominant_basis(lin, shifts, modes) -> np.ndarray:
    """(n, 2 modes) real basis of the ``modes`` least damped eigenvectors of the linearisation ``lin``
    (:class:`~transient.models.rotor.system.Linearisation`) nearest the ``shifts`` [1/s]."""
    w = lin.dae.omega
    cols = []
    for sigma in np.asarray(shifts, dtype=complex)[:modes] / w:
        lu = spla.splu((lin.A + sigma * lin.B).tocsc())
        op = spla.LinearOperator(lin.A.shape, matvec=lambda x, lu=lu: lu.solve(lin.B @ x), dtype=complex)
        mu, vec = spla.eigs(op, k=1, which="LM", tol=1e-10)
        cols += [vec[:, 0].real, vec[:, 0].imag]
    return np.column_stack(cols)


def periodic_response(system, speed_rpm, rtol=1e-6, tol=None, modes=2, outputs_per_revolution=64,
                      shooting: ShootingSettings | None = None, integrator="ida", start=None,
                      basis=None) -> PeriodicResponse:
    """The settled orbit of ``system`` at ``speed_rpm`` (module docstring) as a
    :class:`~transient.models.rotor.results.PeriodicResponse`: Newton-Picard with ``shooting`` (its tolerances
    ``tol``, ``rtol``), from ``start`` (a state at angle 0; default the linear response with the film states)
    on the ``basis`` (the map's reduced layout; default the ``modes`` least damped modes of the linearisation). With
    squeeze-film dampers (which give no quasi-static K and C) the default start is the circular orbit reached from
    small unbalance where the system has one (:func:`~transient.models.rotor.circular_orbits.default_start`), and the
    default basis the rotor's coordinates and velocities (:func:`~transient.models.rotor.circular_orbits.rotor_basis`)."""
    dae = system.dae(speed_rpm)
    F = PeriodMap(dae, outputs_per_revolution, atol=1e-3 * rtol, integrator=integrator)
    if system.dampers:  # no quasi-static K and C: the circular orbit and the rotor's own states
        from transient.models.rotor.circular_orbits import default_start, rotor_basis

        start = default_start(system, speed_rpm) if start is None else start
        basis = rotor_basis(system, speed_rpm) if basis is None else basis
    if start is None or basis is None:
        eq = system.equilibrium(speed_rpm)
        lin = system.linearisation(speed_rpm, eq)
    if basis is None:
        qs = system.quasi_static_eigenvalues(speed_rpm, eq)
        qs = qs[np.imag(qs) > 0]
        basis = dominant_basis(lin, qs[np.argsort(-qs.real)], modes)
    y0 = eq.state + lin.forced_response().real if start is None else np.array(start, dtype=float)
    tol = rtol if tol is None else tol
    settings = replace(shooting or ShootingSettings(**SHOOTING_DEFAULTS), tol=tol, rtol=rtol,
                       rtol_max=max(rtol, 1e-4))
    sh = newton_picard(F, F.reduce(y0), 2 * np.pi, basis, norm=F.norm, settings=settings)
    periods = int(sh.periods)
    key = np.asarray(sh.state, dtype=float).tobytes()
    if key not in F.samples and np.all(np.isfinite(sh.state)):  # the orbit of a state not integrated yet
        F(sh.state, 0.0, 2 * np.pi, rtol)
        periods += 1
    _, tau, q = F.samples.get(key, (None, np.zeros(0), np.zeros((0, dae.nq))))
    mu = np.asarray(sh.multipliers)
    stable = bool(mu.size and np.abs(mu).max() < 1.0)
    message = sh.message or "converged"
    if sh.success and not stable:
        message = (f"no stable periodic orbit at {speed_rpm:g} rpm (dominant multiplier |mu| = {np.abs(mu).max():.4f} "
                   f"> 1): the periodic orbit found is unstable; {message}")
    return PeriodicResponse(t=tau / dae.omega, displacement=system._node_displacements(q * dae.L),
                            multipliers=mu, error_estimate=float(sh.error_estimate), periods=periods,
                            nodes=list(system.rotor.nodes), speed_rpm=float(speed_rpm), state=F.embed(sh.state),
                            stable=stable, converged=bool(sh.success), integrator=F.integrator,
                            basis=None if sh.basis is None else np.asarray(sh.basis),
                            success=bool(sh.success) and stable, message=message)


def response_curve(system, speeds, rtol, tol, modes, outputs_per_revolution, shooting, integrator, predictor,
                   progress=False) -> RotorResponseCurve:
    """Periodic responses of ``system`` along the monotone ``speeds`` [rpm] by continuation: each speed's shooting
    starts from the ``predictor`` (``"secant"`` or ``"quadratic"``) extrapolation in speed of the last converged
    states, on the last refined basis while its dominant multiplier is above the shooting's ``refine_floor`` (below
    it the derivatives' noise swamps the dominant pair: afresh from the linearisation); a start that does not converge is retried from the linear response. The Floquet
    multipliers of every orbit give its stability and the onset speed where the dominant one crosses 1."""
    from transient.solvers.progress import progress_bar

    done, path, orbits = [], [], []
    basis = None
    bar = progress_bar(progress, len(speeds), "speed", "periodic responses")
    for n in speeds:
        start = extrapolate_state(np.array(path), [p.state for p in done], n, 3 if predictor == "quadratic" else 2)
        p = periodic_response(system, n, rtol, tol, modes, outputs_per_revolution, shooting, integrator, start,
                              basis if start is not None else None)
        if not p.converged and start is not None:  # the extrapolation went astray: start afresh
            q = periodic_response(system, n, rtol, tol, modes, outputs_per_revolution, shooting, integrator)
            q.periods += p.periods
            p = q
        orbits.append(p)
        if p.converged:
            done, path = (done + [p])[-3:], (path + [n])[-3:]
            basis = p.basis if p.max_multiplier > shooting.refine_floor else None
        if bar:
            bar.set_postfix_str(f"{n:.0f} rpm: |mu| {p.max_multiplier:.4f}" + ("" if p.converged else ", NOT CONVERGED"))
            bar.update()
    if bar:
        bar.close()
    return _curve(system, np.asarray(speeds, dtype=float), orbits, integrator)


def _curve(system, speeds, orbits, integrator) -> RotorResponseCurve:
    nan = float("nan")
    nodes = list(system.rotor.nodes)
    amp = np.full((len(orbits), len(nodes), 2), nan)
    mu = np.full((len(orbits), 2), nan, dtype=complex)
    for i, p in enumerate(orbits):
        if p.t.size:
            amp[i] = 0.5 * np.ptp(p.displacement, axis=0)
        m = np.asarray(p.multipliers)[:2]
        mu[i, :m.size] = m
    mmax = np.array([p.max_multiplier for p in orbits])
    onset = stability_onset_speed(speeds, mmax)
    bad = [f"{n:g}" for n, p in zip(speeds, orbits) if not p.converged]
    return RotorResponseCurve(speed_rpm=speeds, amplitude=amp, multipliers=mu, max_multiplier=mmax,
                              stable=np.array([p.stable for p in orbits]),
                              converged=np.array([p.converged for p in orbits]),
                              periods=np.array([p.periods for p in orbits]), nodes=nodes, onset_rpm=onset,
                              integrator=integrator, orbits=orbits, success=not bad,
                              message="" if not bad else f"shooting did not converge at {', '.join(bad)} rpm")
