"""One integrator facade for every model: SUNDIALS CVODE/IDA, scipy BDF/Radau/LSODA and fixed-step RK4.

The package: :mod:`.problem` (what goes in and comes out), :mod:`.guard` (callback guard, stall and Ctrl-C),
:mod:`.outputs` (outputs and events), one module per back end (:mod:`.sundials`, :mod:`.scipy_backend`,
:mod:`.rk4`), and here :func:`solve` with the back-end table :data:`BACKENDS`. A new back end is one module
with ``solve(problem, t_eval, out, guard, settings) -> (success, message)`` and one entry in the table.

A model hands :func:`solve` a :class:`Problem` (state size, initial state, right-hand side
``y' = f(t, y)`` and/or residual ``F(t, y, y') = 0``, the sparse Jacobian pattern and numba fill
routines, algebraic indices, events) and gets back one :class:`Solution` whatever the method.

* ``"cvode"`` / ``"ida"`` -- scikit-sundae (SUNDIALS 7), BDF with a sparse direct solver
  (SuperLU_MT) fed by the analytic Jacobian in the fixed CSC pattern order, or band / dense with
  SUNDIALS' own difference quotients when the problem says so.
* ``"bdf"`` / ``"radau"`` / ``"lsoda"`` -- ``scipy.integrate`` given the same sparse Jacobian
  (LSODA only accepts a dense one; that is scipy's limitation, not ours).
* ``"bdf2"`` -- variable-step BDF2 with its own compiled Newton on a bordered band LU (:mod:`.bdf2`), for a
  model that hands its kernels as ``options={"bdf2": Bdf2Model}``.
* ``"rk4"`` -- the classical fixed-step 4th-order Runge-Kutta scheme the users' hand-coded codes
  use, with a hook (:attr:`Problem.algebraic_solve`) for the inner algebraic solve per stage (how the
  papers treat the film: the film is solved to convergence for the rotor state of every stage).

Output is produced only at the requested times ``t_eval``; an ``observer(t, y)`` receives each
output so long runs need not store anything (``store=False``).

Failures are reported, never hidden, and never crash the interpreter (see :func:`solve`):

* an exception raised inside any callback (``KeyboardInterrupt`` included) stops the integration
  and is re-raised from :func:`solve` unchanged, with its original traceback (plus a note saying
  where it was raised). SUNDIALS never sees the model's exception: scikit-sundae 1.2 ignores
  callback return values, so the wrappers stop CVODE/IDA themselves -- by handing them NaN until
  the step fails while the linear solver may not be set up yet (a sparse solver freed before that
  setup crashes the interpreter), by raising an internal abort once a step has succeeded;
* a non-finite value returned by the right-hand side, residual, Jacobian or event functions, a
  non-finite output state, or a time that stops advancing (steps collapsing to the roundoff of t)
  ends the run at once with ``success=False`` and a message naming the method, the time and the
  first bad component;
* Ctrl-C during a solve (main thread) is deferred to the next callback or step boundary and
  raised from :func:`solve` as ``KeyboardInterrupt``; a second Ctrl-C interrupts at once.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Callable

from transient.checks import (check_atol, check_choice, check_rtol, check_step, check_times,
                              short_repr)
from transient.solvers.integrate import bdf2, rk4, scipy_backend, sundials
from transient.solvers.integrate.guard import SIGINT, Guard, Stop, first_nonfinite
from transient.solvers.integrate.guard import nonfinite_probe as _nonfinite_probe  # noqa: F401 (tests probe it)
from transient.solvers.integrate.outputs import Output
from transient.solvers.integrate.problem import Problem, Settings, Solution, Stats, Steps
from transient.solvers.integrate.sundials import LINEAR_SOLVERS
from transient.solvers.legacy import run_settings

__all__ = ["BACKENDS", "LINEAR_SOLVERS", "METHODS", "Backend", "Problem", "Settings", "Solution", "Stats", "check_method",
           "methods_for", "solve", "Steps"]


@dataclass(frozen=True)
class Backend:
    """One integration method: ``solve(problem, t_eval, out, guard, settings) -> (success, message)``.

    ``fixed_step``: takes the step ``dt`` (required) and has no error test (its failure counts are 0);
    ``outputs_yp``: also returns ``y'`` at the outputs (``Solution.yp``); ``step_solve``: integrates only a model
    that hands it its own compiled step solve (``options={"bdf2": Bdf2Model}``), so a model offers it by saying so
    (:func:`check_method`)."""

    solve: Callable
    fixed_step: bool = False
    outputs_yp: bool = False
    step_solve: bool = False


#: The methods :func:`solve` knows, in the order of :data:`METHODS`: a new back end is one entry here.
BACKENDS: dict[str, Backend] = {
    "cvode": Backend(sundials.solve),
    "ida": Backend(sundials.solve, outputs_yp=True),
    "bdf": Backend(scipy_backend.solve),
    "radau": Backend(scipy_backend.solve),
    "lsoda": Backend(scipy_backend.solve),
    "rk4": Backend(rk4.solve, fixed_step=True),
    "bdf2": Backend(bdf2.solve, step_solve=True),
}
METHODS = tuple(BACKENDS)
#: The loose step keywords of :func:`solve` of earlier releases, now fields of ``steps=Steps(...)``.
STEP_KEYWORDS = {name: ("steps", Steps, name) for name in ("dt", "max_step", "first_step", "max_steps")}


def methods_for(step_solve: bool = False, among=METHODS) -> tuple:
    """The methods of ``among`` that can integrate a model: every back end, except those that need the model's own
    step solve when the model has none (``step_solve`` False)."""
    return tuple(m for m in among if step_solve or not BACKENDS[m].step_solve)


def check_method(owner: str, method, *, step_solve: bool = False, among=METHODS) -> str:
    """``method`` if ``owner`` (the model's entry point, e.g. ``"ThrustPad.descent"``) can be integrated by it,
    else a ``ValueError`` before any work naming the entry point, the method and the methods it takes
    (:func:`methods_for`): a capability check at the door, not a failure inside the integrator."""
    offered = methods_for(step_solve, among)
    if isinstance(method, str) and method in offered:
        return method
    why = ""
    if isinstance(method, str) and method in BACKENDS and BACKENDS[method].step_solve and method in among:
        why = f" ({method!r} integrates only models that hand it their own step solve; {owner} has none)"
    raise ValueError(f"{owner}: method = {short_repr(method)} is not available{why}; it takes one of "
                     f"{', '.join(offered)}")


def solve(problem: Problem, t_eval, method: str = "cvode", rtol: float = 1e-6, atol=1e-8, *,
          steps: Steps | None = None, linear_solver: str = "auto", store: bool = True,
          observer: Callable | None = None, options: dict | None = None, time_budget: float | None = None,
          **legacy) -> Solution:
    """Integrate ``problem`` and return the state at the times ``t_eval`` (the first is the start).

    Parameters
    ----------
    method : one of ``"cvode"``, ``"ida"``, ``"bdf"``, ``"radau"``, ``"lsoda"``, ``"rk4"``, ``"bdf2"``.
    rtol, atol : tolerances of the adaptive methods (ignored by ``rk4``): ``rtol`` in (0, 1); ``atol``
        a finite number > 0 or an array of such numbers, one per state.
    steps : :class:`Steps` -- ``dt``, the fixed step of ``rk4`` [same unit as t] (required for ``rk4``);
        ``max_step``, ``first_step``, the step limits of the adaptive methods (0 = free); ``max_steps``, the most
        steps of the whole run (default 1,000,000). E.g. ``solve(p, t, "rk4", steps=Steps(dt=0.01))``; the loose
        keywords ``dt=``, ``max_step=``, ``first_step=``, ``max_steps=`` are deprecated (they still work for one
        release, with a ``DeprecationWarning``).
    linear_solver : ``"auto"`` (sparse if the problem has a Jacobian pattern, band if it declares a
        band, dense otherwise), ``"sparse"``, ``"band"`` or ``"dense"`` (SUNDIALS methods).
    store : keep the outputs in ``Solution.y`` (False: only pass them to ``observer``).
    observer : ``observer(t, y)`` called at every output time, in order.
    options : extra keyword options for the SUNDIALS solver (e.g. ``max_nonlin_iters``, ``max_order``); for
        ``"bdf2"`` the model's ``{"bdf2": Bdf2Model}`` (and ``"fixed_step"``, ``"max_step_scale"``).
    time_budget : wall-clock seconds the run may take (None: no limit); checked once per step, so a run
        stops at most one step after it (``success=False``, the message says where it stopped).

    Failures
    --------
    Bad arguments raise ``ValueError`` naming the parameter, the value and the allowed range.
    An exception raised by any callback (rhs, residual, Jacobian, events, observer, the rk4 hooks),
    ``KeyboardInterrupt`` included, stops the integration and is re-raised from here unchanged
    (same object, original traceback; the model callbacks add a note saying where and when). Everything else that stops a run returns a
    :class:`Solution` with ``success=False`` and a one-line message with the method and the time:
    a non-finite value from a callback (the first bad component is named), a non-finite state, a
    stalled time (steps collapsing to the roundoff of t), ``max_steps``, or the backend's own
    failure. ``success=True`` guarantees every returned state is finite.
    """
    backend = BACKENDS[check_choice("method", method, tuple(BACKENDS))]
    if not isinstance(problem, Problem):
        raise TypeError(f"problem must be a transient.Problem, got {type(problem).__name__}")
    steps = run_settings("solve", legacy, STEP_KEYWORDS, steps=steps)["steps"]
    rtol = check_rtol(rtol)
    atol = check_atol(atol, problem.n)
    if backend.fixed_step and steps.dt is None:
        raise ValueError(f"method {method!r} needs a fixed step dt > 0, got dt=None")
    check_choice("linear_solver", linear_solver, LINEAR_SOLVERS)
    if observer is not None and not callable(observer):
        raise ValueError(f"observer must be callable(t, y) or None, got {short_repr(observer)}")
    if options is not None and not isinstance(options, dict):
        raise ValueError(f"options must be a dict of SUNDIALS options or None, got {short_repr(options)}")
    t_eval = check_times("t_eval", t_eval)
    bad = first_nonfinite(problem.y0)
    if bad is not None:
        raise ValueError(f"problem '{problem.name}': y0 must be finite, got y0[{bad[0]}] = {float(bad[1])!r}")
    if problem.yp0 is not None and first_nonfinite(problem.yp0) is not None:
        k, v, _ = first_nonfinite(problem.yp0)
        raise ValueError(f"problem '{problem.name}': yp0 must be finite, got yp0[{k}] = {float(v)!r}")
    settings = Settings(method=method, rtol=rtol, atol=atol, dt=steps.dt, max_step=steps.max_step,
                        first_step=steps.first_step, max_steps=steps.max_steps, linear_solver=linear_solver,
                        options=options or {})

    guard = Guard(problem, method)
    out = Output(t_eval, problem.n, store, observer, with_yp=backend.outputs_yp, guard=guard)
    wall0 = time.perf_counter()
    if time_budget is not None:
        guard.budget = check_step("time_budget", time_budget)
        guard.deadline = wall0 + guard.budget
    with SIGINT:
        try:
            success, message = backend.solve(problem, t_eval, out, guard, settings)
        except Stop as stop:
            success, message = False, str(stop)
        finally:
            guard.unpoison_output()
            guard.solver = None
            err = guard.take_error()  # drop the guard's reference (the exception may hold the guard)
        if err is not None:
            try:
                raise err
            finally:  # this frame is in err's traceback: no cycle keeping the solver for the GC
                del err
    if success and guard.message is not None:  # a backend that carried on after a callback failed
        success, message = False, guard.message
    stats = Stats(n_steps=guard.n_steps, n_rhs=guard.n_rhs, n_jac=guard.n_jac,
                  wall_time=time.perf_counter() - wall0, callback_time=guard.seconds)
    if backend.fixed_step:  # no error test, no nonlinear solve of its own
        stats.n_error_test_failures = 0
        stats.n_nonlinear_failures = 0
    else:  # the back ends that count their own failures leave them on the guard (None: not counted)
        stats.n_error_test_failures = guard.n_error_test_failures
        stats.n_nonlinear_failures = guard.n_nonlinear_failures
    res = out.result(success=success, message=message, method=method, stats=stats)
    if out.events is not None:
        out.events.fill(res)
    return res
