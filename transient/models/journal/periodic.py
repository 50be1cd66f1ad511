"""Periodic unbalance response of the journal orbit without settling runs (Rho & Kim: the settled
orbits of Figs. 3-12, the unbalance response of Fig. 8 and the onset of oil whirl at ~7800 rpm).

The unbalance force ``m e Omega^2 (cos tau, sin tau)`` has the period 2 pi in ``tau = omega t``, so the settled
response is a fixed point of the once-per-revolution map ``y(0) -> y(2 pi)`` of the whole method-of-lines state
(film cells u and the rotor X, Y, VX, VY of :class:`~transient.models.journal.JournalOrbit`; the groove cells
are fixed and left out). It is found by shooting (:func:`transient.solvers.shooting.newton_picard`): the map's
Jacobian (the monodromy) has two multipliers that matter -- the rotor's whirl pair, |mu| = 0.64 at 6000 rpm on
the paper grid, 0.9-1 near the onset -- and all others below 5e-3 (the second rotor pair and the film modes, which the
film's compressibility and its content transport through the cavitated zone wipe out within a
revolution; Arnoldi, docs/periodic.md). So Newton acts on that pair only (two directional derivatives, one
period each) and a plain iteration of the map handles everything else.

* Start (first speed): the linearised unbalance response (:meth:`JournalOrbit.linear_start`) and one relaxing
  period; the whirl subspace: the dominant eigenvector of the linearised rotor (K, C of the same discrete
  film) lifted onto the film by its quasi-steady sensitivity ``du = -G_u^-1 G_q dq``, refined by the
  directional derivatives (one step of subspace iteration).
* Floquet multipliers: the Ritz values of the monodromy on that subspace; the orbit is stable when
  |mu| < 1 (the nonlinear stability verdict). :func:`floquet_check` runs Arnoldi on the full monodromy.
* Continuation in speed (:func:`response_curve`): each orbit starts from a polynomial (secant or quadratic)
  extrapolation of the previous ones, with the previous speed's refined subspace (a fresh one where the whirl
  pair was below the derivatives' noise floor); the speed where the
  dominant multiplier leaves the unit circle is interpolated (:func:`stability_onset` refines it by secant
  steps in speed).
* Past the onset the periodic orbit exists but is unstable and the response is quasi-periodic (oil whirl):
  :func:`quasi_periodic_response` integrates it in time and reports the Poincare section and the whirl
  frequency ratio.
"""

from __future__ import annotations

import time
from dataclasses import field, replace
from typing import Any

import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla

from transient.checks import check_choice, check_positive, check_range
from transient.models.journal.kernels import N_ROTOR
from transient.results import StatusResult, quantity, result_type
from transient.solvers.integrate import Steps, solve
from transient.solvers.settling import settled_stop, settles
from transient.solvers.progress import progress_bar
from transient.solvers.shooting import (ShootingSettings, extrapolate_state, floquet_multipliers, newton_krylov,
                                         newton_picard, stability_onset_speed)
from transient.solvers.legacy import keyword_table, run_settings
from transient.solvers.settings import Integration, LongRun, Recording, check_unused

METHODS = ("shooting", "newton-krylov")
#: :func:`periodic_response`'s iteration settings (``shooting=ShootingSettings(...)``) where none are given, and
#: the loose keywords of earlier releases that are now fields of it
SHOOTING_DEFAULTS = {"shooting": {"fd_step": 1e-3, "max_iter": 25, "relax": 1}}
SHOOTING_KEYWORDS = keyword_table("shooting", ShootingSettings, ("fd_step", "max_iter", "relax"))
#: time integrators of the period map: IDA on the universal film, or the conservative BDF2 on the content film
#: (:mod:`transient.solvers.integrate.bdf2`, the step solve of :meth:`JournalOrbit.bdf2_model`)
INTEGRATORS = ("ida", "bdf2")
#: below this dominant multiplier the derivatives' noise (~rtol / fd_step) swamps the whirl pair: a continuation
#: then takes the whirl basis afresh at the next speed instead of following the noisy subspace
REFINE_FLOOR = 0.05
#: IDA's first step [rad of shaft angle] in each period of the map: its own guess restarts every period at ~1e-4 of
#: it and spends steps and Jacobians growing the step back (41 x 6 grid, rtol 1e-5, the 27 Fig. 8 speeds: 17,845 steps
#: and 2,524 Jacobians against 18,863 and 2,623, the same 135 periods; a small gain, docs/periodic.md section 6)
IDA_FIRST_STEP = 0.01

#: What shooting and continuation take: a :class:`~transient.models.journal.orbit.JournalOrbit` (not imported here:
#: ``orbit.py`` offers these functions as its methods, so the import would close a circle).
Orbit = Any


def _check_orbit(orbit):
    """Shooting and continuation take an orbit object: a :class:`~transient.models.journal.JournalOrbit` (this
    module never imports orbit.py, which offers these functions as its methods)."""
    if not all(callable(getattr(orbit, a, None)) for a in ("run", "linear_start", "at_speed")):
        raise TypeError(f"orbit must be a JournalOrbit, got {type(orbit).__name__}")


@result_type
class PeriodicOrbit(StatusResult):
    """One revolution of the periodic unbalance response at ``speed_rpm``.

    ``t`` [s] (``outputs_per_revolution + 1`` samples over one period, the unbalance at angle 0 at t = 0),
    ``x``, ``y`` [m] (journal centre, x towards the load); ``state``: the dimensionless film + rotor state at
    t = 0 (``JournalOrbit.run(..., y0=state)`` continues the orbit); ``multipliers``: the dominant Floquet
    multipliers (modulus first); ``stable``: all inside the unit circle; ``error_estimate`` [m]: distance of
    ``state`` from the fixed point estimated by the last Newton step (rotor position and velocity);
    ``residual_norms`` [m]: ``|Phi(y) - y|`` of the rotor state per iteration; ``revolutions_integrated``:
    periods integrated, directional derivatives included; ``residual`` [m]: the measured ``|x(T) - x(0)|`` of the
    rotor state at the accepted ``state`` (``converged`` means both it and ``error_estimate`` are below ``tol``);
    ``integrator``: the period map's time integrator. ``success`` is False when the shooting did not
    converge or the orbit is unstable (the message says which; the fields hold what was found).
    """

    t: np.ndarray = quantity("s")
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    speed_rpm: float = quantity("rpm", 0.0)
    clearance: float = quantity("m", 0.0)
    state: np.ndarray | None = quantity("-", None, repr=False)
    multipliers: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0, dtype=complex))
    stable: bool = False
    converged: bool = False
    iterations: int = 0
    revolutions_integrated: int = 0
    error_estimate: float = quantity("m", float("nan"))
    residual_norms: list = quantity("m", default_factory=list)
    rtol: float = 0.0
    method: str = "shooting"
    wall_time: float = quantity("s", 0.0)
    basis: np.ndarray | None = quantity("-", None, repr=False)
    integrator: str = "ida"
    success: bool = field(default=False, kw_only=True)

    @property
    def harmonic(self) -> np.ndarray:
        """First (1x) harmonic [m], complex: ``x(t) ~ x_mean + Re(Z_x e^{i Omega t})`` (the convention of
        :meth:`JournalBearing.unbalance_response`)."""
        n = self.t.size - 1
        e = np.exp(-2j * np.pi * np.arange(n) / n)
        return np.array([2.0 * np.mean(self.x[:n] * e), 2.0 * np.mean(self.y[:n] * e)])

    @property
    def semi_major(self) -> float:
        """Semi-major axis [m] of the 1x ellipse."""
        Z = self.harmonic
        return float(np.linalg.svd(np.array([[Z[0].real, -Z[0].imag], [Z[1].real, -Z[1].imag]]), compute_uv=False)[0])

    @property
    def residual(self) -> float:
        """The measured ``|x(T) - x(0)|`` [m] (rotor position and velocity, largest component) of the last
        iterate integrated (the accepted ``state`` when ``converged``)."""
        return float(self.residual_norms[-1]) if self.residual_norms else float("nan")

    @property
    def max_multiplier(self) -> float:
        """Modulus of the dominant Floquet multiplier."""
        return float(np.abs(self.multipliers).max()) if self.multipliers.size else float("nan")


@result_type
class ResponseCurve(StatusResult):
    """Periodic orbits along a path of speeds (continuation), one row per speed.

    ``semi_major`` [m] of the 1x ellipse, ``amplitude_x``, ``amplitude_y`` [m] (half peak-to-peak over the
    period), ``phase_x``, ``phase_y`` [deg] (of the 1x harmonic against the unbalance force ``cos(Omega t)``),
    ``multipliers`` (speed, dominant pair), ``max_multiplier``, ``unstable`` (|mu| > 1: the periodic orbit exists
    but the response is quasi-periodic), ``converged``, ``iterations``, ``revolutions_integrated``,
    ``wall_time`` [s] per speed; ``onset_rpm``: speed where the dominant multiplier crosses 1, interpolated
    between the bracketing speeds (nan if not bracketed); ``whirl_frequency_ratio`` and ``whirl_amplitude`` [m]
    of the quasi-periodic response where it was integrated (nan elsewhere); ``orbits``: the
    :class:`PeriodicOrbit` of every speed.
    """

    time_axis = "speed_rpm"
    speed_rpm: np.ndarray = quantity("rpm")
    semi_major: np.ndarray = quantity("m")
    amplitude_x: np.ndarray = quantity("m")
    amplitude_y: np.ndarray = quantity("m")
    phase_x: np.ndarray = quantity("deg")
    phase_y: np.ndarray = quantity("deg")
    multipliers: np.ndarray = quantity("-")
    max_multiplier: np.ndarray = quantity("-")
    unstable: np.ndarray = quantity("-")
    converged: np.ndarray = quantity("-")
    iterations: np.ndarray = quantity("-")
    revolutions_integrated: np.ndarray = quantity("-")
    wall_time: np.ndarray = quantity("s")
    whirl_frequency_ratio: np.ndarray = quantity("-")
    whirl_amplitude: np.ndarray = quantity("m")
    onset_rpm: float = quantity("rpm", float("nan"))
    orbits: list = field(default_factory=list, repr=False)


@result_type
class WhirlResponse(StatusResult):
    """Time-integrated response past the onset (quasi-periodic: oil whirl).

    ``t`` [s], ``x``, ``y`` [m] at ``outputs_per_revolution``; ``poincare_x``, ``poincare_y`` [m]: once per
    revolution (t = k T); ``whirl_frequency_ratio``: frequency of the largest sub-synchronous component of
    x over the last half of the run (the 1x, 2x and 3x parts fitted and removed first), in shaft orders;
    ``whirl_amplitude`` [m] and ``synchronous_amplitude`` [m]: its amplitude and the 1x amplitude there;
    ``poincare_spread`` [m]: the largest distance of the last half's Poincare points from their mean (0 for a
    periodic response)."""

    t: np.ndarray = quantity("s")
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    poincare_x: np.ndarray = quantity("m")
    poincare_y: np.ndarray = quantity("m")
    speed_rpm: float = quantity("rpm", 0.0)
    whirl_frequency_ratio: float = quantity("-", float("nan"))
    whirl_amplitude: float = quantity("m", float("nan"))
    synchronous_amplitude: float = quantity("m", float("nan"))
    poincare_spread: float = quantity("m", float("nan"))


class _Flow:
    """The once-per-revolution map of an orbit on the free film cells + rotor, keeping the journal centre at
    ``opr`` outputs of the last few periods integrated (the orbit of the accepted iterate). ``integrator``:
    ``"ida"`` (the universal film) or ``"bdf2"`` (the content film, mapped from and back to the universal
    state: the map's unknowns are the same either way).

    Only a period that can be the accepted one -- integrated at ``accept_rtol`` (the solve's final tolerance) or
    tighter -- is sampled at ``opr`` outputs; the others (loose early iterations, relaxing periods, the
    directional derivatives of :meth:`derivative`) integrate to the period's end only (the same steps for IDA;
    the BDF map saves mapping the outputs back to the universal layout). IDA starts each period with the step
    ``first_step`` [rad] (:data:`IDA_FIRST_STEP`)."""

    def __init__(self, orbit: Orbit, opr: int, atol_factor: float = 1e-3, integrator: str = "ida",
                 accept_rtol: float = 0.0, fd_step: float = 1e-3, first_step: float = 0.0):
        f = orbit.film
        self.o, self.opr, self.atol_factor = orbit, int(opr), atol_factor
        self.integrator = check_choice("integrator", integrator, INTEGRATORS)
        self.accept_rtol, self.fd_step, self.first_step = accept_rtol, fd_step, first_step
        self.keep = np.concatenate([np.flatnonzero(f.op.free), f.n + np.arange(N_ROTOR)])
        self.template = np.zeros(orbit.n)
        self.template[: f.n][~f.op.free] = f.u_supply
        self.samples = {}
        self._bdf2 = {}

    def _solve(self, y, t_eval, rtol):
        """The run over ``t_eval`` from the universal state ``y``: (solution, states in the universal layout)."""
        o = self.o
        if self.integrator == "ida":
            s = solve(o.problem(y, t_eval[0], touch_gap=1e-3), t_eval, method="ida", rtol=rtol,
                      atol=o.absolute_tolerance(self.atol_factor * rtol), steps=Steps(first_step=self.first_step))
            return s, s.y
        if rtol not in self._bdf2:  # the step solve's model (its work arrays, its travel cap) once per tolerance
            self._bdf2[rtol] = o._stepper(Integration(method="bdf2", rtol=rtol), "content", 1e-3)
        st = self._bdf2[rtol]
        s = solve(st.problem_at(o.content_state(y), t_eval[0]), t_eval, method="bdf2", rtol=rtol,
                  atol=self.atol_factor * rtol, steps=Steps(max_step=st.max_step, first_step=st.first_step),
                  options=st.options)
        return s, (np.array([o.universal_state(v) for v in s.y]) if s.y.size else s.y)

    def reduce(self, y):
        return np.asarray(y, dtype=float)[self.keep]

    def embed(self, z) -> np.ndarray:
        y = self.template.copy()
        y[self.keep] = z
        return y

    def __call__(self, z, t0, T, rtol, sample: bool = True):
        o, n = self.o, self.o.film.n
        sample = sample and rtol <= self.accept_rtol
        t_eval = t0 + T * np.linspace(0.0, 1.0, self.opr + 1 if sample else 2)
        s, ys = self._solve(self.embed(z), t_eval, rtol)
        if not s.success or s.t.size < t_eval.size:
            return np.full(z.size, np.nan)
        key = z.tobytes()
        if sample and (key not in self.samples or rtol <= self.samples[key][0]):  # the tightest run of a state
            if len(self.samples) > 8:
                self.samples.pop(next(iter(self.samples)))
            self.samples[key] = (rtol, s.t / o.film.omega, ys[:, n] * o.bearing.clearance,
                                 ys[:, n + 1] * o.bearing.clearance)
        return ys[-1][self.keep]

    def derivative(self, z, fz, v, rtol):
        """``M v`` by the one-sided difference ``(Phi(z + e v) - Phi(z)) / e``, ``norm(e v) = fd_step`` (the
        shooting's default derivative: :class:`~transient.solvers.shooting.ShootingSettings`), the perturbed
        period integrated to its end only."""
        size = self.norm(v)
        if not size > 1e-3 * float(np.max(np.abs(v))):  # v hardly moves the rotor: scale on the whole vector
            size = float(np.max(np.abs(v)))
        eps = self.fd_step / size
        return (self(z + eps * v, 0.0, 2.0 * np.pi, rtol, sample=False) - fz) / eps

    @staticmethod
    def norm(d) -> float:
        """Rotor position and velocity, in C (per radian)."""
        return float(np.max(np.abs(d[-N_ROTOR:])))


def whirl_basis(orbit: Orbit, y) -> np.ndarray:
    """(n, 2) basis of the whirl subspace at state ``y``: real and imaginary parts of the dominant eigenvector of
    the linearised rotor ``q' = A q``, ``A = [[0, I], [kappa dF/dq, kappa dF/dq']]`` (the K, C of
    :meth:`JournalBearing.coefficients`, dimensionless in tau, here from the film sensitivities at ``y``'s film
    and journal position rather than at the static equilibrium: one sparse LU, no equilibrium solve), the film
    lifted onto it by :func:`lift`."""
    f, n = orbit.film, orbit.film.n
    _, dF_dq, dF_dv = f.force_sensitivity(y[:n], y[n], y[n + 1])
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [orbit.kappa * dF_dq, orbit.kappa * dF_dv]])
    lam, vec = sla.eig(A)
    q = vec[:, int(np.argmax(lam.real))]
    return lift(orbit, y, np.column_stack([q.real, q.imag]))


def lift(orbit: Orbit, y, dq) -> np.ndarray:
    """Film + rotor directions from rotor directions ``dq`` (4, p) at state ``y``: the film's quasi-steady
    sensitivity ``du = -G_u^-1 G_q dq`` (the film slaved to the rotor)."""
    f, n = orbit.film, orbit.film.n
    M = f.op.matrix(f.jacobian_data(y[:n], *y[n:n + N_ROTOR]))
    du = -spla.splu(M[:n, :n].tocsc()).solve(M[:n, n:n + N_ROTOR].toarray() @ dq)
    return np.vstack([du, dq])


def periodic_response(orbit: Orbit, rtol: float = 1e-6, tol: float | None = None, method: str = "shooting",
                      start=None, basis=None, outputs_per_revolution: int = 64, fallback: bool = False,
                      max_revolutions: int = 200, *, integrator: str = "ida", shooting: ShootingSettings | None = None,
                      **legacy) -> PeriodicOrbit:
    """The periodic unbalance response of ``orbit`` (module docstring).

    Parameters
    ----------
    rtol : integration tolerance of the final iterations (IDA); early ones run looser.
    tol : fixed-point tolerance [C] on the rotor position and velocity (default ``rtol``; the map's own noise,
        from the integration error, is ~0.2 rtol C).
    method : ``"shooting"`` (Newton-Picard on the whirl pair, multipliers included) or ``"newton-krylov"``
        (matrix-free Newton-GMRES; no multipliers).
    start : state at t = 0 (dimensionless, as :meth:`JournalOrbit.initial_state`) or a :class:`PeriodicOrbit`
        (e.g. at a nearby speed); default the linearised response.
    basis : (n, 2) whirl subspace (default :func:`whirl_basis` at the start; a continuation passes the previous
        speed's refined one while its whirl pair is above the derivatives' noise floor).
    fallback : if the shooting does not converge, settle by time integration from its last iterate
        (at most ``max_revolutions``, until two consecutive once-per-revolution steps are below ``tol``).
    integrator : time integrator of the period map, ``"ida"`` or ``"bdf2"`` (:data:`INTEGRATORS`; docs/periodic.md
        measures both).
    shooting : :class:`~transient.solvers.shooting.ShootingSettings`, the iteration, taken as given (``None``:
        ``ShootingSettings(fd_step=1e-3, max_iter=25, relax=1)``): ``fd_step``, the size [C] of the perturbations
        of the finite-difference directional derivatives; ``max_iter``; ``relax``, periods integrated at a loose
        tolerance before the first Newton step: the film of a start --
        the linearised response's quasi-steady film, an extrapolation in speed -- is not the periodic one, and its
        error would spoil the first step, docs/periodic.md; and Newton-Krylov's ``krylov_tol``, ``max_krylov``).
        Its tolerances are ``rtol`` and ``tol`` above. The loose keywords ``fd_step=``, ``max_iter=``, ``relax=``
        still work for one release, with a ``DeprecationWarning``.
    """
    sh_settings = run_settings("periodic_response", legacy, SHOOTING_KEYWORDS, SHOOTING_DEFAULTS,
                               shooting=shooting)["shooting"]
    check_unused("periodic_response", "shooting", sh_settings, ("tol", "rtol", "rtol_max", "eta", "fd_rtol",
                                                                "second_ritz", "refine_floor"))
    _check_orbit(orbit)
    check_choice("method", method, METHODS)
    rtol = check_range("rtol", rtol, "-", 1e-13, 1e-2)
    tol = rtol if tol is None else check_positive("tol", tol, "C")
    opr = int(check_range("outputs_per_revolution", outputs_per_revolution, "1/rev", 4, 1e5))
    wall0 = time.perf_counter()
    F = _Flow(orbit, opr, integrator=integrator, accept_rtol=rtol, fd_step=sh_settings.fd_step,
              first_step=IDA_FIRST_STEP)
    y0 = orbit.linear_start() if start is None else np.array(getattr(start, "state", start), dtype=float)
    if y0.shape != (orbit.n,):
        raise ValueError(f"start has shape {y0.shape}; this orbit has {orbit.n} states")
    two_pi = 2.0 * np.pi
    settings = replace(sh_settings, tol=tol, rtol=rtol, rtol_max=max(rtol, 1e-4))
    if method == "shooting":
        V = whirl_basis(orbit, y0) if basis is None else np.asarray(basis, dtype=float)
        sh = newton_picard(F, F.reduce(y0), two_pi, F.reduce(V), norm=_Flow.norm, derivative=F.derivative,
                           settings=replace(settings, second_ritz=basis is None, refine_floor=REFINE_FLOOR))
    else:
        sh = newton_krylov(F, F.reduce(y0), two_pi, norm=_Flow.norm, derivative=F.derivative, settings=settings)
    C = orbit.bearing.clearance
    state = F.embed(sh.state)
    periods, message, converged = sh.periods, sh.message, sh.success
    if not sh.success and fallback and np.all(np.isfinite(state)):
        state, extra, message, converged = _settle(orbit, state, rtol, tol, max_revolutions)
        periods += extra
    samples = F.samples.get(F.reduce(state).tobytes())
    if samples is None and np.all(np.isfinite(state)):  # the orbit of a state not integrated yet
        F(F.reduce(state), 0.0, two_pi, rtol)
        periods += 1
        samples = F.samples.get(F.reduce(state).tobytes())
    t, x, y = samples[1:] if samples else (np.zeros(0), np.zeros(0), np.zeros(0))
    mu = sh.multipliers
    stable = bool(mu.size and np.abs(mu).max() < 1.0)
    success = converged and (stable or method != "shooting")
    if converged and method == "shooting" and not stable:
        message = (f"no stable periodic orbit at {orbit.speed_rpm:g} rpm (dominant multiplier |mu| = "
                   f"{np.abs(mu).max():.4f} > 1): the periodic orbit found is unstable and the response is "
                   f"quasi-periodic (oil whirl; quasi_periodic_response integrates it)")
    elif not converged:
        message = (f"periodic response at {orbit.speed_rpm:g} rpm: {message}; residual history [C]: "
                   + ", ".join(f"{v:.2e}" for v in sh.residual_norms))
    return PeriodicOrbit(t=t, x=x, y=y, speed_rpm=orbit.speed_rpm, clearance=C, state=state, multipliers=mu,
                         stable=stable, converged=converged, iterations=sh.iterations, revolutions_integrated=periods,
                         error_estimate=sh.error_estimate * C, residual_norms=[v * C for v in sh.residual_norms],
                         rtol=rtol, method=method, wall_time=time.perf_counter() - wall0,
                         basis=None if sh.basis is None else _embed_basis(F, sh.basis), integrator=integrator,
                         success=success, message=message)


def _embed_basis(F: _Flow, V) -> np.ndarray:
    out = np.zeros((F.o.n, V.shape[1]))
    out[F.keep] = V
    return out


def _settle(orbit: Orbit, state, rtol, tol, max_revolutions):
    """Time integration from ``state`` until two consecutive once-per-revolution steps of the rotor are below
    ``tol`` (largest component, in C: :func:`~transient.solvers.settling.settles`, checked every two
    revolutions); returns (state at the last revolution, revolutions, message, settled)."""
    C = orbit.bearing.clearance
    criterion = settles(tol, confirm=2, norm="max")
    rotor = lambda r: np.column_stack([r.x, r.y]) / C  # noqa: E731
    r = orbit.run(int(max_revolutions), y0=state, integration=Integration(rtol=rtol, atol=1e-3 * rtol),
                  recording=Recording(outputs_per_revolution=1),
                  long_run=LongRun(chunk_revolutions=2, stop=settled_stop(rotor, criterion), progress=False))
    ok = r.success and criterion(rotor(r)) is not None
    msg = (f"shooting did not converge; settled by time integration in {len(r.t) - 1} revolutions" if ok else
           f"shooting did not converge and time integration did not settle in {len(r.t) - 1} revolutions: {r.message}")
    y = r.final_state.copy()
    return y, len(r.t) - 1, msg, ok


def response_curve(orbit: Orbit, speeds_rpm, rtol: float = 1e-5, tol: float | None = None,
                   outputs_per_revolution: int = 64, whirl_revolutions: int = 0, predictor: str = "quadratic",
                   previous=None, progress: bool = False, fd_step: float = 1e-3,
                   integrator: str = "ida") -> ResponseCurve:
    """Periodic unbalance responses along ``speeds_rpm`` (monotone) by continuation (module docstring): the
    rotor, bearing and unbalance of ``orbit``, each speed warm-started from the previous ones (``predictor``:
    ``"secant"`` or ``"quadratic"`` extrapolation of the states in speed) with the previous whirl subspace;
    ``previous``: a :class:`ResponseCurve` or a list of :class:`PeriodicOrbit` to continue (its last orbits
    start the path). Speeds past the onset give the unstable
    periodic orbit (flagged ``unstable``); with ``whirl_revolutions`` > 0 the quasi-periodic response there is
    also integrated (:func:`quasi_periodic_response`). ``integrator``: the period map's (:data:`INTEGRATORS`)."""
    _check_orbit(orbit)
    speeds = np.asarray(speeds_rpm, dtype=float).ravel()
    if speeds.size == 0 or np.any(speeds <= 0):
        raise ValueError(f"speeds_rpm must be positive speeds [rpm], got {speeds_rpm!r}")
    if speeds.size > 1 and not (np.all(np.diff(speeds) > 0) or np.all(np.diff(speeds) < 0)):
        raise ValueError("speeds_rpm must be strictly monotone (a continuation path) [rpm]")
    check_choice("predictor", predictor, ("secant", "quadratic"))
    shooting = ShootingSettings(**{**SHOOTING_DEFAULTS["shooting"], "fd_step": fd_step})
    check_choice("integrator", integrator, INTEGRATORS)
    done = [p for p in getattr(previous, "orbits", previous or []) if p.converged][-3:]
    path = [p.speed_rpm for p in done]
    orbits, whirls = [], []
    basis = done[-1].basis if done and done[-1].max_multiplier > REFINE_FLOOR else None
    bar = progress_bar(progress, speeds.size, "speed", "periodic responses")
    for s in speeds:
        o = orbit if s == orbit.speed_rpm else orbit.at_speed(s)
        start = extrapolate_state(np.array(path), [p.state for p in done], s, 3 if predictor == "quadratic" else 2)
        p = periodic_response(o, rtol=rtol, tol=tol, start=start, basis=basis, shooting=shooting,
                              outputs_per_revolution=outputs_per_revolution, integrator=integrator)
        if not p.converged and start is not None:  # the extrapolation went astray: start afresh
            q = periodic_response(o, rtol=rtol, tol=tol, shooting=shooting, outputs_per_revolution=outputs_per_revolution,
                                  integrator=integrator)
            q.revolutions_integrated += p.revolutions_integrated
            p = q
        orbits.append(p)
        if p.converged:  # the refined basis, unless it was refined from noise: then afresh at the next start
            done, path = done + [p], path + [s]
            basis = p.basis if p.max_multiplier > REFINE_FLOOR else None
        w = None
        if whirl_revolutions > 0 and p.converged and not p.stable:
            w = quasi_periodic_response(o, whirl_revolutions, start=p.state, rtol=rtol)
        whirls.append(w)
        if bar:
            bar.set_postfix_str(f"{s:.0f} rpm: semi-major {p.semi_major / o.bearing.clearance if p.t.size else np.nan:.5f}"
                                f" C, |mu| {p.max_multiplier:.4f}, {p.iterations} iterations"
                                + ("" if p.converged else ", NOT CONVERGED"))
            bar.update()
    if bar:
        bar.close()
    return _curve(speeds, orbits, whirls)


def _curve(speeds, orbits, whirls) -> ResponseCurve:
    nan = float("nan")
    ok = [p.t.size > 0 for p in orbits]
    Z = np.array([p.harmonic if good else [nan, nan] for p, good in zip(orbits, ok)], dtype=complex)
    half_ptp = lambda v: 0.5 * float(np.ptp(v)) if v.size else nan  # noqa: E731
    mu = np.full((len(orbits), 2), nan, dtype=complex)
    for i, p in enumerate(orbits):
        mu[i, : min(2, p.multipliers.size)] = p.multipliers[:2]
    mmax = np.array([p.max_multiplier for p in orbits])
    onset = stability_onset_speed(speeds, mmax)
    bad = [f"{s:g}" for s, p in zip(speeds, orbits) if not p.converged]
    return ResponseCurve(
        speed_rpm=speeds, semi_major=np.array([p.semi_major if good else nan for p, good in zip(orbits, ok)]),
        amplitude_x=np.array([half_ptp(p.x) for p in orbits]), amplitude_y=np.array([half_ptp(p.y) for p in orbits]),
        phase_x=np.degrees(np.angle(Z[:, 0])), phase_y=np.degrees(np.angle(Z[:, 1])), multipliers=mu,
        max_multiplier=mmax,
        unstable=np.array([p.converged and not p.stable for p in orbits]),
        converged=np.array([p.converged for p in orbits]), iterations=np.array([p.iterations for p in orbits]),
        revolutions_integrated=np.array([p.revolutions_integrated for p in orbits]),
        wall_time=np.array([p.wall_time for p in orbits]),
        whirl_frequency_ratio=np.array([w.whirl_frequency_ratio if w else nan for w in whirls]),
        whirl_amplitude=np.array([w.whirl_amplitude if w else nan for w in whirls]), onset_rpm=onset, orbits=orbits,
        success=not bad, message="" if not bad else f"shooting did not converge at {', '.join(bad)} rpm")


def stability_onset(orbit: Orbit, below: PeriodicOrbit, above: PeriodicOrbit, rtol: float = 1e-5,
                    tol_rpm: float = 2.0, max_steps: int = 12) -> ResponseCurve:
    """Speed where the dominant Floquet multiplier of the periodic orbit crosses the unit circle, between the
    periodic orbits ``below`` (stable) and ``above`` (unstable) of the rotor and bearing of ``orbit`` (e.g. the
    last stable and the first unstable speed of a :func:`response_curve`): secant steps on
    ``|mu|(speed) - 1``, each orbit warm-started from the nearest one and kept inside the bracket, until the
    bracket or the step is below ``tol_rpm``. Returns the orbits computed, in speed order, as a
    :class:`ResponseCurve` whose ``onset_rpm`` is the last secant estimate."""
    pts = {below.speed_rpm: below, above.speed_rpm: above}
    g = {s: p.max_multiplier - 1.0 for s, p in pts.items()}
    lo, hi = below.speed_rpm, above.speed_rpm
    if not (lo < hi and g[lo] < 0 < g[hi]):
        raise ValueError(f"need a stable orbit below an unstable one; got |mu| = {g[lo] + 1:.4f} at {lo:g} rpm and "
                         f"{g[hi] + 1:.4f} at {hi:g} rpm")
    onset = lo - g[lo] * (hi - lo) / (g[hi] - g[lo])
    for _ in range(int(max_steps)):
        if hi - lo <= tol_rpm:
            break
        s = float(np.clip(onset, lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo)))
        a, b = pts[lo], pts[hi]
        start = a.state + (s - lo) / (hi - lo) * (b.state - a.state)
        o = orbit.at_speed(s)
        p = periodic_response(o, rtol=rtol, start=start, basis=(a if s - lo < hi - s else b).basis)
        if not p.converged:
            break
        pts[s], g[s] = p, p.max_multiplier - 1.0
        lo, hi = (s, hi) if g[s] < 0 else (lo, s)
        new = lo - g[lo] * (hi - lo) / (g[hi] - g[lo])
        done = abs(new - onset) <= tol_rpm
        onset = new
        if done:
            break
    speeds = sorted(pts)
    out = _curve(np.array(speeds), [pts[s] for s in speeds], [None] * len(speeds))
    out.onset_rpm = float(onset)
    return out


def quasi_periodic_response(orbit: Orbit, revolutions: int = 100, start=None, perturbation: float = 1e-3,
                            rtol: float = 1e-5, outputs_per_revolution: int = 32) -> WhirlResponse:
    """Time integration of the response past the onset (quasi-periodic oil whirl): ``revolutions`` from
    ``start`` (a state at t = 0, e.g. the unstable periodic orbit's; default the linearised response) with
    the journal moved by ``perturbation`` [C] towards the load, the Poincare section (once per revolution)
    and the whirl frequency ratio from the spectrum of x over the last half."""
    revolutions = int(check_range("revolutions", revolutions, "rev", 8, 1e6))
    opr = int(outputs_per_revolution)
    y0 = orbit.linear_start() if start is None else np.array(getattr(start, "state", start), dtype=float)
    y0[orbit.film.n] += perturbation
    r = orbit.run(revolutions, y0=y0, integration=Integration(rtol=rtol, atol=1e-3 * rtol),
                  recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False))
    px, py = r.x[::opr], r.y[::opr]
    half = (len(r.x) - 1) // opr // 2 * opr
    phase = 2.0 * np.pi * np.arange(half) / opr
    H = np.column_stack([np.ones(half)] + [f(k * phase) for k in (1, 2, 3) for f in (np.cos, np.sin)])
    coef = np.linalg.lstsq(H, r.x[-half:], rcond=None)[0]
    sync = float(np.hypot(coef[1], coef[2]))
    xs = r.x[-half:] - H @ coef  # the forced (1x, 2x, 3x) part removed: what is left is the whirl
    spec = np.abs(np.fft.rfft(xs * np.hanning(xs.size))) * 4.0 / xs.size  # Hann: coherent gain 1/2
    order = np.fft.rfftfreq(xs.size, d=1.0 / opr)
    sub = (order > 0.05) & (order < 0.95)
    k = int(np.flatnonzero(sub)[np.argmax(spec[sub])])
    a, b, c = np.log(spec[k - 1:k + 2] + 1e-300)
    shift = 0.5 * (a - c) / (a - 2 * b + c) if (a - 2 * b + c) < 0 else 0.0
    ratio = float(order[k] + shift * (order[1] - order[0]))
    hp = np.hypot(px[len(px) // 2:] - px[len(px) // 2:].mean(), py[len(py) // 2:] - py[len(py) // 2:].mean())
    spread = float(hp.max())
    C = orbit.bearing.clearance
    msg = (f"{orbit.speed_rpm:g} rpm: sub-synchronous whirl at {ratio:.3f} x shaft speed ({spec[k] / C:.2e} C); the "
           f"Poincare points of the last half spread over {spread / C:.2e} C")
    if not r.success or r.touched_at is not None:
        msg = f"{orbit.speed_rpm:g} rpm: {r.message}"
    return WhirlResponse(t=r.t, x=r.x, y=r.y, poincare_x=px, poincare_y=py, speed_rpm=orbit.speed_rpm,
                         whirl_frequency_ratio=ratio, whirl_amplitude=float(spec[k]), synchronous_amplitude=sync,
                         poincare_spread=spread, success=bool(r.success and r.touched_at is None), message=msg)


def floquet_check(orbit: Orbit, p: PeriodicOrbit, k: int = 6, rtol: float = 1e-9,
                  fd_step: float = 1e-6) -> tuple[np.ndarray, np.ndarray, int]:
    """The ``k`` multipliers of largest modulus of the periodic orbit ``p`` by Arnoldi on the full monodromy
    (free film cells + rotor; one period per product). Returns (multipliers, the share of each eigenvector
    on the rotor states, periods integrated)."""
    F = _Flow(orbit, 4)
    mu, vec, periods = floquet_multipliers(F, F.reduce(p.state), 2.0 * np.pi, k, rtol=rtol, fd_step=fd_step,
                                           norm=_Flow.norm)
    share = np.linalg.norm(vec[-N_ROTOR:], axis=0) / np.linalg.norm(vec, axis=0)
    return mu, share, periods
