"""One integrator facade for every model: SUNDIALS CVODE/IDA, scipy BDF/Radau/LSODA and fixed-step RK4.

A model hands :func:`solve` a :class:`Problem` (state size, initial state, right-hand side
``y' = f(t, y)`` and/or residual ``F(t, y, y') = 0``, the sparse Jacobian pattern and numba fill
routines, algebraic indices, events) and gets back one :class:`Solution` whatever the method.

* ``"cvode"`` / ``"ida"`` -- scikit-sundae (SUNDIALS 7), BDF with a sparse direct solver
  (SuperLU_MT) fed by the analytic Jacobian in the fixed CSC pattern order, or band / dense with
  SUNDIALS' own difference quotients when the problem says so.
* ``"bdf"`` / ``"radau"`` / ``"lsoda"`` -- ``scipy.integrate`` given the same sparse Jacobian
  (LSODA only accepts a dense one; that is scipy's limitation, not ours).
* ``"rk4"`` -- the classical fixed-step 4th-order Runge-Kutta scheme the users' hand-coded codes
  use, with a hook (:attr:`Problem.algebraic_solve`) for the inner algebraic solve per stage (how the
  papers treat the film: the film is solved to convergence for the rotor state of every stage).
* ``"bdf2"`` -- variable-step BDF2 with its own compiled Newton on a bordered band LU
  (:mod:`transient.solvers.bdf2`), for a model that hands its kernels as ``options={"bdf2": Bdf2Model}``.

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

import io
import math
import numbers
import signal
import sys
import threading
import time
import warnings
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numba
import numpy as np
import scipy.integrate as si
import scipy.sparse as sp
from scipy.optimize import brentq

from transient.results import Result, record_type, result_type

METHODS = ("cvode", "ida", "bdf", "radau", "lsoda", "rk4", "bdf2")
LINEAR_SOLVERS = ("auto", "sparse", "band", "dense")
_EPS = np.finfo(float).eps


@dataclass
class Problem:
    """What a model hands to :func:`solve`.

    Callables fill their last argument in place (no return value), as SUNDIALS wants:

    * ``rhs(t, y, out)``: ``out = f(t, y)`` for ``y' = f(t, y)``. For a semi-explicit DAE the entries
      of ``out`` at the algebraic indices are ignored (used by ``rk4`` only).
    * ``residual(t, y, yp, out)``: ``out = F(t, y, y')`` (IDA). If absent, IDA uses ``y' - f(t, y)``.
    * ``jac_rhs(t, y, data)``: the CSC data array of ``df/dy`` in the order of ``jac_pattern``; with no
      ``jac_pattern`` the Jacobian is dense and ``data`` is the (n, n) array to fill (small or dense
      problems, e.g. elastic contact).
    * ``jac_residual(t, y, yp, cj, data)``: ``dF/dy + cj dF/dy'``, CSC data in pattern order, or the
      (n, n) array when there is no pattern.
    * ``events(t, y, out)``: event functions; a zero crossing is an event.
    * ``algebraic_solve(t, y) -> y``: for ``rk4`` on a DAE, returns ``y`` with its algebraic part
      solved for the given differential part (the per-stage inner solve).
    * ``step_begin(t, y)``: for ``rk4``, called at the start of every step (e.g. to store the history
      a time-discretised inner solve needs).
    """

    y0: np.ndarray
    rhs: Callable | None = None
    residual: Callable | None = None
    yp0: np.ndarray | None = None
    jac_pattern: sp.spmatrix | None = None
    jac_rhs: Callable | None = None
    jac_residual: Callable | None = None
    algebraic: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    band: tuple[int, int] | None = None
    events: Callable | None = None
    n_events: int = 0
    event_terminal: Sequence[bool] | None = None
    event_direction: Sequence[int] | None = None
    algebraic_solve: Callable | None = None
    step_begin: Callable | None = None
    name: str = "problem"

    def __post_init__(self):
        if np.ndim(self.y0) != 1:
            raise ValueError(f"Problem '{self.name}': y0 must be a non-empty 1-D array (one entry per state), "
                             f"got {np.ndim(self.y0)}-D {np.asarray(self.y0).shape!r}: {_short(self.y0)}")
        self.y0 = np.ascontiguousarray(self.y0, dtype=float)
        if self.y0.ndim != 1 or self.y0.size == 0:
            raise ValueError(f"Problem '{self.name}': y0 must be a non-empty 1-D array, got shape {self.y0.shape}")
        if self.rhs is None and self.residual is None:
            raise ValueError(f"Problem '{self.name}': give rhs (ODE) or residual (DAE), or both")
        if self.yp0 is not None:
            if np.ndim(self.yp0) != 1:
                raise ValueError(f"Problem '{self.name}': yp0 must be a 1-D array like y0, got {_short(self.yp0)}")
            self.yp0 = np.ascontiguousarray(self.yp0, dtype=float)
            if self.yp0.shape != self.y0.shape:
                raise ValueError(f"Problem '{self.name}': yp0 shape {self.yp0.shape} != y0 shape {self.y0.shape}")
        self.algebraic = np.asarray(self.algebraic, dtype=np.int64)
        if self.jac_pattern is not None:
            pat = sp.csc_matrix(self.jac_pattern, dtype=float)
            pat.sort_indices()
            if pat.shape != (self.n, self.n):
                raise ValueError(f"Problem '{self.name}': jac_pattern shape {pat.shape} != ({self.n}, {self.n})")
            self.jac_pattern = pat
        if self.n_events:
            if self.events is None:
                raise ValueError(f"Problem '{self.name}': n_events={self.n_events} but no events function")
            self.event_terminal = list(self.event_terminal or [True] * self.n_events)
            self.event_direction = list(self.event_direction or [0] * self.n_events)

    @property
    def n(self) -> int:
        """Number of states."""
        return self.y0.size

    @property
    def is_dae(self) -> bool:
        return self.algebraic.size > 0


@record_type
@dataclass
class Stats:
    """Solver statistics, counted by the facade's own wrappers so they mean the same for every method.

    ``None`` means the backend does not report that number (scikit-sundae 1.2 and scipy expose no
    error-test or nonlinear-failure counts; fixed-step RK4 has none by construction, reported as 0).
    """

    n_steps: int = 0
    n_rhs: int = 0
    n_jac: int = 0
    n_error_test_failures: int | None = None
    n_nonlinear_failures: int | None = None
    wall_time: float = 0.0
    callback_time: float = 0.0

    @property
    def callback_share(self) -> float:
        """Fraction of the wall time spent inside the Python callbacks (rhs, residual, Jacobian)."""
        return self.callback_time / self.wall_time if self.wall_time > 0 else 0.0


@result_type
class Solution(Result):
    """What :func:`solve` returns, for every method. ``y[k]`` is the state at ``t[k]`` (rows = output times;
    ``t`` in the problem's own time unit)."""

    t: np.ndarray
    y: np.ndarray | None
    yp: np.ndarray | None
    success: bool
    message: str
    method: str
    stats: Stats
    t_events: np.ndarray = field(default_factory=lambda: np.zeros(0))
    y_events: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    i_events: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    @property
    def y_final(self) -> np.ndarray:
        return self.y[-1]


# --------------------------------------------------------------------------------------------------
# Callback guard: counting, timing, exceptions, non-finite values, Ctrl-C
# --------------------------------------------------------------------------------------------------

def _short(x, limit=60) -> str:
    r = repr(x)
    return r if len(r) <= limit else r[:limit - 3] + "..."


@numba.njit(cache=True, nogil=True, fastmath={"reassoc"})
def _nonfinite_probe(a):
    """0.0 if every entry of the 1-D array ``a`` is finite, NaN otherwise (``x * 0`` is 0 for finite x and
    NaN for inf/NaN, so the sum cannot overflow; ``reassoc`` only lets LLVM vectorise the sum)."""
    s = 0.0
    for i in range(a.size):
        s += a[i] * 0.0
    return s


def _first_nonfinite(a: np.ndarray):
    """(index, value) of the first non-finite entry of ``a`` (index a tuple for 2-D arrays), or None."""
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size == 0:
        return None
    k = int(bad[0])
    idx = np.unravel_index(k, a.shape) if a.ndim > 1 else k
    return idx, a.reshape(-1)[k], int(bad.size)


def _all_finite(a: np.ndarray) -> bool:
    a = np.asarray(a, dtype=float)
    if a.ndim != 1 or not a.flags.c_contiguous:
        a = np.ascontiguousarray(a).reshape(-1)
    return _nonfinite_probe(a) == 0.0


class _Stop(Exception):
    """Internal: ends a run with success=False and this message (never escapes :func:`solve`)."""


class _Abort(Exception):
    """Internal: raised by a poisoned SUNDIALS callback once that is safe, to end the step at once
    (scikit-sundae turns it into an unrecoverable callback failure and re-raises it from ``step``)."""


class _Sigint:
    """Ctrl-C during a solve sets a flag instead of raising wherever Python happens to be.

    A KeyboardInterrupt raised at an arbitrary bytecode boundary may land inside scikit-sundae's
    Cython glue, outside the facade's wrappers, where it can corrupt the solver. So while a solve runs
    in the main thread with Python's default SIGINT handler, the first Ctrl-C is only recorded; the
    next callback (inside its guard) or step boundary raises it. A second Ctrl-C raises at once (the
    old behaviour, for a callback that never returns). Nested solves share the one handler."""

    def __init__(self):
        self.pending = False
        self.depth = 0
        self.installed = False
        self.owner = None  # the thread whose solve installed the handler: only it consumes Ctrl-C
        self.lock = threading.Lock()

    def _handler(self, signum, frame):
        if self.pending:  # second Ctrl-C: give the user the interpreter back now
            self.pending = False
            raise KeyboardInterrupt
        self.pending = True

    def __enter__(self):
        with self.lock:
            self.depth += 1
            if self.depth == 1 and threading.current_thread() is threading.main_thread():
                try:
                    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
                        signal.signal(signal.SIGINT, self._handler)
                        self.installed = True
                        self.owner = threading.get_ident()
                except (ValueError, OSError):  # not the main interpreter / no signals: leave it alone
                    self.installed = False
        return self

    def __exit__(self, *exc):
        with self.lock:
            self.depth -= 1
            if self.depth == 0 and self.installed:
                signal.signal(signal.SIGINT, signal.default_int_handler)
                self.installed = False
                self.owner = None
                pending, self.pending = self.pending, False
                if pending and exc[0] is None:  # noticed but not yet raised: raise it now
                    raise KeyboardInterrupt
        return False

    def take(self) -> bool:
        """True (once) if a deferred Ctrl-C is waiting and this thread owns it."""
        if self.pending and self.owner == threading.get_ident():
            self.pending = False
            return True
        return False

    def check(self):
        """Raise the deferred KeyboardInterrupt (step boundaries of the facade's own loops)."""
        if self.pending and self.take():
            raise KeyboardInterrupt


_SIGINT = _Sigint()

_WHAT = {"rhs": "the right-hand side f(t, y)", "residual": "the residual F(t, y, y')",
         "jac": "the Jacobian", "events": "the event functions"}


class _Guard:
    """Wraps the problem's callables for one solve: counts calls, times them, checks their outputs.

    ``poison=True`` (SUNDIALS): the model's exception never escapes into scikit-sundae. On an
    exception or a non-finite output the wrapper records the failure and from then on never calls the
    model again. Until the first step has succeeded it answers with NaN (zeros for a Jacobian, so the
    linear solver only sees finite numbers): CVODE/IDA then fail the step by themselves, after they have
    set up their linear solver (a sparse SUNDIALS solver freed before that setup crashes, see
    :func:`_settle`); that costs a few dozen calls (about 10 n with a difference-quotient Jacobian).
    After a successful step the setup has certainly happened and the wrapper raises :class:`_Abort`
    instead, which SUNDIALS takes as an unrecoverable callback failure: the step ends at once.
    ``poison=False`` (scipy, rk4): the exception propagates; a non-finite output raises :class:`_Stop`.
    """

    def __init__(self, problem: Problem, method: str):
        self.problem = problem
        self.method = method
        self.n_rhs = 0
        self.n_jac = 0
        self.n_steps = 0
        self.seconds = 0.0
        self.poisoned = False
        self.error: BaseException | None = None  # the first exception raised inside a callback
        self.message: str | None = None  # the first failure, as reported
        self.solver = None  # the SUNDIALS solver, kept alive by a failing callback's frame
        self._stdout = None
        self.deadline = math.inf  # wall-clock end of the time budget (time.perf_counter)
        self.budget = None

    def over_budget(self, t) -> str | None:
        """The failure message once the wall-clock time budget is used up (checked once per step)."""
        if time.perf_counter() > self.deadline:
            return f"time budget of {self.budget:g} s used up at t={float(t):.9g} ({self.n_steps} steps)"
        return None

    # -- failure records ---------------------------------------------------------------------------
    def _where(self, kind, t) -> str:
        return f"{self.method}: {_WHAT[kind]} of problem '{self.problem.name}'"

    def record_exception(self, exc: BaseException, kind: str, t):
        if self.message is None:
            self.error = exc
            self.message = (f"{self._where(kind, t)} raised {type(exc).__name__} at t={float(t):.9g}: "
                            f"{_short(str(exc), 200)}")
            try:
                exc.add_note(f"[transient.solve] raised inside {_WHAT[kind]} of problem '{self.problem.name}' "
                             f"at t={float(t):.9g} (method {self.method}); the integration was stopped")
            except Exception:  # an exception type that refuses notes: still re-raised unchanged
                pass

    def record_nonfinite(self, kind: str, t, out: np.ndarray, y=None) -> str:
        found = _first_nonfinite(out)
        if found is None:  # cannot happen: the probe saw a non-finite value
            found = ("?", float("nan"), 1)
        idx, val, count = found
        label = {"rhs": "f", "residual": "F", "jac": "J", "events": "g"}[kind]
        idx = ", ".join(str(int(i)) for i in idx) if isinstance(idx, tuple) else idx
        msg = (f"{self._where(kind, t)} returned a non-finite value at t={float(t):.9g}: {label}[{idx}] = {val} "
               f"(first of {count} non-finite of {out.size})")
        bad_y = _first_nonfinite(np.asarray(y, dtype=float)) if isinstance(y, np.ndarray) else None
        if bad_y is not None:  # the solver handed the model a non-finite state: say so
            msg += f"; its input state was already non-finite (y[{bad_y[0]}] = {bad_y[1]})"
        msg += "; integration stopped"
        if self.message is None:
            self.message = msg
        return msg

    def poison(self):
        """Answer every further callback with NaN; hide scikit-sundae's printed SUNDIALS error for the
        step that is now bound to fail (the facade reports the real cause)."""
        self.poisoned = True
        if self._stdout is None:
            self._stdout = sys.stdout
            sys.stdout = io.StringIO()

    def unpoison_output(self):
        if self._stdout is not None:
            sys.stdout = self._stdout
            self._stdout = None

    def stopped(self) -> bool:
        """After a solver call: restore stdout; True if a callback failed."""
        if self._stdout is not None:
            self.unpoison_output()
        return self.message is not None

    def take_error(self):
        err, self.error = self.error, None
        return err

    # -- wrappers ----------------------------------------------------------------------------------
    # The hot path (10^4-10^6 calls per run) is generated for the callback's exact arity from this
    # one template: ``*args`` costs ~0.5 us per call, as much as the whole non-finite check.
    _TEMPLATE = """
def wrapped(t, {params}):
    if g.poisoned:
        if g.n_steps > 0:
            raise _Abort
        out.fill(fill)
        return
    t0 = clock()
    try:
        if sigint.pending and sigint.take():
            raise KeyboardInterrupt
        fn(t, {params})
    except BaseException as exc:
        if timed:
            g.seconds += clock() - t0
        g.record_exception(exc, kind, t)
        if not poison:
            raise
        keep_alive = g.solver  # noqa: F841 -- this frame is in exc's traceback and its arrays view
        g.poison()             # the solver's memory, which must outlive the traceback
        out.fill(fill)
        abort = g.n_steps > 0
    else:
        abort = None
    if abort is not None:  # the model raised: stop (outside the except block: no chained context)
        if abort:
            raise _Abort
        return
    if timed:
        g.seconds += clock() - t0
    if counts_rhs:
        g.n_rhs += 1
    elif counts_jac:
        g.n_jac += 1
    arr = out if fixed is None else fixed
    if probe(arr if arr.ndim == 1 else arr.reshape(-1)) != 0.0:
        msg = g.record_nonfinite(kind, t, arr, y)
        if not poison:
            raise _Stop(msg)
        g.poison()
        if g.n_steps > 0:
            raise _Abort
        out.fill(fill)
"""
    _PARAMS = {3: "y, out", 4: "y, a2, out", 5: "y, a2, a3, out"}
    _COMPILED: dict = {}

    def wrap(self, fn: Callable, kind: str, poison: bool, timed: bool = True, counted: bool = True,
             check=None, arity: int = 3) -> Callable:
        """``wrapped(t, y, ..., out)`` (``arity`` arguments) calls ``fn`` with the same arguments; the
        last one is the output array.

        ``check``: None checks that output, an array checks that array (an adapter's inner buffer
        holding the model's own values), False checks nothing."""
        code = self._COMPILED.get(arity)
        if code is None:
            code = self._COMPILED[arity] = compile(self._TEMPLATE.format(params=self._PARAMS[arity]),
                                                   f"<transient guard, {arity} arguments>", "exec")
        fixed = check if isinstance(check, np.ndarray) else None
        if fixed is not None and (fixed.ndim != 1 or not fixed.flags.c_contiguous):
            raise ValueError("check array must be 1-D and contiguous")
        scope = {
            "g": self, "fn": fn, "kind": kind, "poison": poison, "timed": timed,
            "clock": time.perf_counter, "sigint": _SIGINT, "_Abort": _Abort, "_Stop": _Stop,
            "probe": _nonfinite_probe if check is not False else (lambda a: 0.0), "fixed": fixed,
            "fill": 0.0 if kind == "jac" else np.nan,
            "counts_rhs": counted and kind in ("rhs", "residual"), "counts_jac": counted and kind == "jac",
        }
        exec(code, scope)
        return scope["wrapped"]

    # -- states ------------------------------------------------------------------------------------
    def check_state(self, t, y, what="state"):
        """Raise :class:`_Stop` if the state ``y`` at ``t`` has a non-finite entry."""
        y = np.asarray(y)
        if not _all_finite(y):
            idx, val, count = _first_nonfinite(y)
            msg = (f"{self.method}: the {what} of problem '{self.problem.name}' became non-finite at "
                   f"t={float(t):.9g}: y[{idx}] = {val} (first of {count} of {y.size}); integration stopped")
            if self.message is None:
                self.message = msg
            raise _Stop(msg)


class _Stall:
    """A time that no longer advances: ``WINDOW`` consecutive steps each at most ``FACTOR`` roundoff
    units of ``|t|`` long, i.e. each moving t by a handful of representable numbers (the state of
    the CVODE/IDA stall on a NaN region: h ~ 1e-17 at t = 0.5 for a million steps). Relative to
    ``|t|`` only, so tiny steps near t = 0 (a fast initial layer) are never taken for a stall."""

    WINDOW = 50
    FACTOR = 4.0
    TINY = FACTOR * _EPS

    @classmethod
    def message(cls, method, t_old, t_new) -> str:
        return (f"{method}: time stalled at t={t_new:.12g}: {cls.WINDOW} consecutive steps of at most "
                f"{cls.FACTOR:g} roundoff units of t (last step {t_new - t_old:.3g}); the problem is singular, "
                "discontinuous or non-finite there")


# --------------------------------------------------------------------------------------------------
# Arguments and outputs
# --------------------------------------------------------------------------------------------------

def _real(value):
    """``value`` as a float if it is a real number (not a bool, a string or an array), else None."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        return None
    return float(value)


def _show(value) -> str:
    """A value for an error message: numbers plainly (0.5, nan; not np.float64(0.5))."""
    x = _real(value)
    return repr(x) if x is not None else _short(value)


def _positive_number(name, value, upper=None) -> float:
    rng = f"(0, {upper:g})" if upper is not None else "(0, inf)"
    x = _real(value)
    if x is None or not (0.0 < x < (upper if upper is not None else math.inf)):
        raise ValueError(f"{name} must be a finite number in {rng}, got {_show(value)}")
    return x


def _nonnegative_number(name, value) -> float:
    x = _real(value)
    if x is None or not (0.0 <= x < math.inf):
        raise ValueError(f"{name} must be a finite number >= 0 (0 = free), got {_show(value)}")
    return x


ATOL_FLOOR = 1e-30  # smaller absolute tolerances overflow the weighted norms of states at zero (IDA segfaults)


def _check_atol(atol, n):
    """A positive finite scalar, or one positive finite value per state."""
    if isinstance(atol, (bool, np.bool_)):
        raise ValueError(f"atol must be a finite number > 0 or an array of {n} such numbers (one per state), "
                         f"got {atol!r}")
    try:
        a = np.asarray(atol, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"atol must be a finite number > 0 or an array of {n} such numbers (one per state), "
                         f"got {_short(atol)}") from None
    if a.ndim == 0:
        v = _positive_number("atol", atol if _real(atol) is not None else float(a))
        if v < ATOL_FLOOR:
            raise ValueError(f"atol = {v!r} is below {ATOL_FLOOR:g}: the error weights 1/atol of states at zero "
                             f"would overflow SUNDIALS' weighted norms")
        return v
    if a.shape != (n,):
        raise ValueError(f"atol must be a scalar or an array of length n={n} (one per state), got shape {a.shape}")
    bad = np.flatnonzero(~(np.isfinite(a) & (a >= ATOL_FLOOR)))
    if bad.size:
        raise ValueError(f"atol[{bad[0]}] must be a finite number > 0 (at least {ATOL_FLOOR:g}), got {_show(a[bad[0]])} "
                         f"({bad.size} bad of {n})")
    return np.ascontiguousarray(a)


def _check_t_eval(t_eval) -> np.ndarray:
    try:
        t_eval = np.asarray(t_eval, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"t_eval must be a 1-D array of at least 2 increasing finite times, got "
                         f"{_short(t_eval)}") from None
    if t_eval.ndim != 1 or t_eval.size < 2:
        raise ValueError(f"t_eval must be a 1-D array of at least 2 times [s], got shape {t_eval.shape}")
    bad = np.flatnonzero(~np.isfinite(t_eval))
    if bad.size:
        raise ValueError(f"t_eval must be finite, got t_eval[{bad[0]}] = {_show(t_eval[bad[0]])}")
    d = np.flatnonzero(~(np.diff(t_eval) > 0))
    if d.size:
        k = d[0]
        raise ValueError(f"t_eval must be strictly increasing [s], got t_eval[{k + 1}] = {_show(t_eval[k + 1])} <= "
                         f"t_eval[{k}] = {_show(t_eval[k])}")
    return t_eval


class _Output:
    """Collects (or streams to an observer) the states at the requested output times; every state
    is checked finite before anyone sees it."""

    def __init__(self, t_eval, n, store, observer, with_yp, guard):
        self.t_eval = t_eval
        self.k = 0
        self.store = store
        self.observer = observer
        self.guard = guard
        self.y = np.empty((t_eval.size, n)) if store else None
        self.yp = np.empty((t_eval.size, n)) if (store and with_yp) else None
        self.events: _Events | None = None  # set by the backend if the problem has events

    @property
    def pending(self) -> float:
        return self.t_eval[self.k] if self.k < self.t_eval.size else np.inf

    def put(self, y, yp=None):
        self.guard.check_state(self.t_eval[self.k], y)
        if self.store:
            self.y[self.k] = y
            if self.yp is not None and yp is not None:
                self.yp[self.k] = yp
        if self.observer is not None:
            self.observer(self.t_eval[self.k], y)
        self.k += 1

    def result(self, **kw) -> Solution:
        k = self.k
        return Solution(t=self.t_eval[:k].copy(), y=None if self.y is None else self.y[:k],
                        yp=None if self.yp is None else self.yp[:k], **kw)


class _Events:
    """Event bookkeeping shared by all methods: direction filter, terminal counts, records."""

    def __init__(self, problem: Problem, guard: _Guard, poison: bool):
        self.p = problem
        self.guard = guard
        self.fn = guard.wrap(problem.events, "events", poison=poison, timed=False)
        self.t, self.y, self.i = [], [], []
        self.counts = np.zeros(problem.n_events, dtype=np.int64)
        self.buf = np.empty(problem.n_events)

    def values(self, t, y):
        self.fn(t, y, self.buf)
        return self.buf.copy()

    def crossed(self, g0, g1):
        """Indices of events whose sign change from g0 to g1 matches their direction."""
        out = []
        for i in range(self.p.n_events):
            d = self.p.event_direction[i]
            up = g0[i] < 0 <= g1[i]
            down = g0[i] > 0 >= g1[i]
            if (up and d >= 0) or (down and d <= 0):
                out.append(i)
        return out

    def record(self, t, y, idx) -> bool:
        """Record events idx at t; True if one of them is terminal."""
        stop = False
        if idx:
            self.guard.check_state(t, y, "state at an event")
        for i in idx:
            self.t.append(t)
            self.y.append(np.array(y, dtype=float))
            self.i.append(i)
            self.counts[i] += 1
            term = self.p.event_terminal[i]
            if term is True or (not isinstance(term, bool) and term and self.counts[i] >= term):
                stop = True
        return stop

    def fill(self, res: Solution):
        if self.t:
            res.t_events = np.array(self.t)
            res.y_events = np.array(self.y)
            res.i_events = np.array(self.i, dtype=np.int64)


def solve(problem: Problem, t_eval, method: str = "cvode", rtol: float = 1e-6, atol=1e-8, *,
          dt: float | None = None, max_step: float = 0.0, first_step: float = 0.0,
          max_steps: int = 1_000_000, linear_solver: str = "auto", store: bool = True,
          observer: Callable | None = None, options: dict | None = None,
          time_budget: float | None = None) -> Solution:
    """Integrate ``problem`` and return the state at the times ``t_eval`` (the first is the start).

    Parameters
    ----------
    method : one of ``"cvode"``, ``"ida"``, ``"bdf"``, ``"radau"``, ``"lsoda"``, ``"rk4"``, ``"bdf2"``.
    rtol, atol : tolerances of the adaptive methods (ignored by ``rk4``): ``rtol`` in (0, 1); ``atol``
        a finite number > 0 or an array of such numbers, one per state.
    dt : the fixed step of ``rk4`` [same unit as t], finite and > 0; required for ``rk4``.
    max_step, first_step : step limits of the adaptive methods (0 = free), finite and >= 0.
    max_steps : upper bound on the number of steps in the whole run (an integer >= 1).
    linear_solver : ``"auto"`` (sparse if the problem has a Jacobian pattern, band if it declares a
        band, dense otherwise), ``"sparse"``, ``"band"`` or ``"dense"`` (SUNDIALS methods).
    store : keep the outputs in ``Solution.y`` (False: only pass them to ``observer``).
    observer : ``observer(t, y)`` called at every output time, in order.
    options : extra keyword options for the SUNDIALS solver (e.g. ``max_nonlin_iters``, ``max_order``); for
        ``"bdf2"`` the model's ``{"bdf2": Bdf2Model}`` (and ``"fixed_step"``).
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
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    if not isinstance(problem, Problem):
        raise TypeError(f"problem must be a transient.Problem, got {type(problem).__name__}")
    rtol = _positive_number("rtol", rtol, upper=1.0)
    atol = _check_atol(atol, problem.n)
    if (isinstance(max_steps, (bool, np.bool_)) or not isinstance(max_steps, (int, np.integer, float))
            or not math.isfinite(max_steps) or int(max_steps) != max_steps or max_steps < 1):
        raise ValueError(f"max_steps must be an integer >= 1, got {max_steps!r}")
    max_steps = int(max_steps)
    max_step = _nonnegative_number("max_step", max_step)
    first_step = _nonnegative_number("first_step", first_step)
    if dt is not None or method == "rk4":
        if dt is None:
            raise ValueError("method 'rk4' needs a fixed step dt > 0, got dt=None")
        dt = _positive_number("dt", dt)
    if not isinstance(linear_solver, str) or linear_solver not in LINEAR_SOLVERS:
        raise ValueError(f"linear_solver must be one of {LINEAR_SOLVERS}, got {linear_solver!r}")
    if observer is not None and not callable(observer):
        raise ValueError(f"observer must be callable(t, y) or None, got {_short(observer)}")
    if options is not None and not isinstance(options, dict):
        raise ValueError(f"options must be a dict of SUNDIALS options or None, got {_short(options)}")
    t_eval = _check_t_eval(t_eval)
    bad = _first_nonfinite(problem.y0)
    if bad is not None:
        raise ValueError(f"problem '{problem.name}': y0 must be finite, got y0[{bad[0]}] = {_show(bad[1])}")
    if problem.yp0 is not None and _first_nonfinite(problem.yp0) is not None:
        k, v, _ = _first_nonfinite(problem.yp0)
        raise ValueError(f"problem '{problem.name}': yp0 must be finite, got yp0[{k}] = {_show(v)}")

    guard = _Guard(problem, method)
    out = _Output(t_eval, problem.n, store, observer, with_yp=(method == "ida"), guard=guard)
    wall0 = time.perf_counter()
    if time_budget is not None:
        guard.budget = _positive_number("time_budget", time_budget)
        guard.deadline = wall0 + guard.budget
    with _SIGINT:
        try:
            if method in ("cvode", "ida"):
                success, message = _solve_sundials(problem, method, t_eval, out, guard, rtol, atol, max_step,
                                                   first_step, max_steps, linear_solver, options or {})
            elif method == "rk4":
                success, message = _solve_rk4(problem, t_eval, out, guard, dt, max_steps)
            elif method == "bdf2":  # variable-step BDF2 on a bordered band LU (solvers/bdf2.py)
                from transient.solvers.bdf2 import integrate_bdf2

                out.events = _Events(problem, guard, poison=False) if problem.n_events else None
                success, message = integrate_bdf2(problem, t_eval, out, guard, rtol, atol, max_step, first_step,
                                                  max_steps, options or {}, _step_events, _SIGINT.check)
            else:
                success, message = _solve_scipy(problem, method, t_eval, out, guard, rtol, atol, max_step,
                                                 first_step, max_steps)
        except _Stop as stop:
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
    if method == "rk4":
        stats.n_error_test_failures = 0
        stats.n_nonlinear_failures = 0
    elif method == "bdf2":
        stats.n_error_test_failures = getattr(guard, "n_error_test_failures", None)
        stats.n_nonlinear_failures = getattr(guard, "n_nonlinear_failures", None)
    res = out.result(success=success, message=message, method=method, stats=stats)
    if out.events is not None:
        out.events.fill(res)
    return res


# --------------------------------------------------------------------------------------------------
# SUNDIALS (scikit-sundae)
# --------------------------------------------------------------------------------------------------

def _with_diagonal(pattern: sp.csc_matrix):
    """Pattern P + I, and where P's data and the diagonal sit in its CSC data array."""
    n = pattern.shape[0]
    aug = sp.csc_matrix(pattern + sp.identity(n, format="csc"))
    aug.data[:] = 1.0
    aug.sort_indices()
    pos = sp.csc_matrix((np.arange(aug.nnz, dtype=float) + 1, aug.indices, aug.indptr), shape=aug.shape)
    r, c = pattern.nonzero()
    order = np.lexsort((r, c))  # CSC order: by column, then row
    r, c = r[order], c[order]
    p_map = np.asarray(pos[r, c]).ravel().astype(np.int64) - 1
    diag = np.asarray(pos[np.arange(n), np.arange(n)]).ravel().astype(np.int64) - 1
    return aug, p_map, diag


def _ida_from_rhs(problem: Problem, guard: _Guard):
    """IDA residual ``F = y' - f(t, y)`` and its Jacobian ``cj I - df/dy`` from an ODE problem, already
    guarded: the residual's guard checks the model's own ``f`` and the Jacobian's the model's ``df/dy``,
    so a failure names f or J (not F) with the model's value."""
    n = problem.n
    f = np.empty(n)
    rhs = problem.rhs

    def adapter(t, y, yp, res):
        rhs(t, y, f)
        np.subtract(yp, f, out=res)

    residual = guard.wrap(adapter, "rhs", poison=True, check=f, arity=4)

    pattern = jac = None
    if problem.jac_pattern is None and problem.jac_rhs is not None:  # dense analytic Jacobian
        jac_rhs = guard.wrap(problem.jac_rhs, "jac", poison=True)  # checked before the sign change
        diag_n = np.diag_indices(n)

        def dense_adapter(t, y, yp, cj, J):
            jac_rhs(t, y, J)
            J *= -1.0
            J[diag_n] += cj

        jac = guard.wrap(dense_adapter, "jac", poison=True, timed=False, counted=False, check=False, arity=5)
    elif problem.jac_pattern is not None:
        pattern, p_map, diag = _with_diagonal(problem.jac_pattern)
        if problem.jac_rhs is not None:
            tmp = np.empty(problem.jac_pattern.nnz)
            jac_rhs = problem.jac_rhs

            def sparse_adapter(t, y, yp, cj, data):
                jac_rhs(t, y, tmp)
                data[:] = 0.0
                data[p_map] = -tmp
                data[diag] += cj

            jac = guard.wrap(sparse_adapter, "jac", poison=True, check=tmp, arity=5)
    return residual, pattern, jac


def _linear_solver_options(problem, pattern, have_jac, linear_solver):
    kind = linear_solver
    if kind == "auto":
        kind = "sparse" if pattern is not None else ("band" if problem.band is not None else "dense")
    if kind == "sparse":
        if pattern is None:
            raise ValueError("linear_solver='sparse' needs a Jacobian pattern in the problem")
        return {"linsolver": "sparse", "sparsity": pattern, "nthreads": 1}, have_jac
    if kind == "band":
        if problem.band is None:
            raise ValueError("linear_solver='band' needs problem.band = (lower, upper)")
        return {"linsolver": "band", "lband": int(problem.band[0]), "uband": int(problem.band[1])}, False
    if kind == "dense":  # an analytic Jacobian only if the problem's is dense (no pattern)
        return {"linsolver": "dense"}, have_jac and pattern is None
    raise ValueError(f"linear_solver must be one of {LINEAR_SOLVERS}, got {linear_solver!r}")


def _settle(solver, guard, t_end):
    """Let a SUNDIALS solver that never stepped set up its linear solver before it is freed.

    SUNDIALS 7's SuperLU_MT linear solver frees memory it only allocates at its first setup, so a
    sparse CVODE/IDA object freed after ``init_step`` but before any step crashes the interpreter
    (segfault or heap-corruption abort; reproduced with scikit-sundae alone). One poisoned step
    performs that setup (the first step always sets up the linear solver) and then fails at once."""
    guard.poison()
    try:
        solver.step(t_end, method="onestep", tstop=t_end)
    except BaseException:  # noqa: BLE001 -- only the setup matters; the run is already over
        pass
    finally:
        guard.unpoison_output()


def _solve_sundials(problem, method, t_eval, out, guard, rtol, atol, max_step, first_step, max_steps,
                    linear_solver, extra):
    from sksundae.cvode import CVODE
    from sksundae.ida import IDA

    t0, t_end = float(t_eval[0]), float(t_eval[-1])
    opts = {"rtol": rtol, "atol": atol, "max_step": max_step, "first_step": first_step,
            "max_num_steps": max_steps, **extra}
    events = None
    if method == "cvode":
        if problem.rhs is None:
            raise ValueError(f"method 'cvode' needs an ODE right-hand side; problem '{problem.name}' only has "
                             "a residual (use method='ida')")
        if problem.is_dae:
            raise ValueError(f"method 'cvode' cannot integrate the DAE '{problem.name}' (use method='ida')")
        rhs = guard.wrap(problem.rhs, "rhs", poison=True)
        lin, use_jac = _linear_solver_options(problem, problem.jac_pattern, problem.jac_rhs is not None,
                                              linear_solver)
        opts.update(lin)
        if use_jac:
            jr = guard.wrap(problem.jac_rhs, "jac", poison=True)
            opts["jacfn"] = lambda t, y, yp, data: jr(t, y, data)
        if problem.n_events:
            events = out.events = _Events(problem, guard, poison=True)
            ev_fn = events.fn
            ev = lambda t, y, g: ev_fn(t, y, g)
            ev.direction = list(problem.event_direction)
            opts["eventsfn"], opts["num_events"] = ev, problem.n_events
        with warnings.catch_warnings():  # sksundae notes that jacfn replaces its FD Jacobian: intended
            warnings.simplefilter("ignore", UserWarning)
            solver = CVODE(rhs, method="BDF", **opts)  # the guard has the (t, y, out) signature
        yp0 = None
    else:
        if problem.residual is not None:
            residual, pattern, jac = problem.residual, problem.jac_pattern, problem.jac_residual
            res = guard.wrap(residual, "residual", poison=True, arity=4)
        else:  # an ODE: F = y' - f, guarded inside
            res, pattern, jac = _ida_from_rhs(problem, guard)
        lin, use_jac = _linear_solver_options(problem, pattern, jac is not None, linear_solver)
        opts.update(lin)
        if use_jac:
            jj = guard.wrap(jac, "jac", poison=True, arity=5) if problem.residual is not None else jac
            opts["jacfn"] = lambda t, y, yp, r, cj, data: jj(t, y, yp, cj, data)
        if problem.is_dae:
            opts["algebraic_idx"] = problem.algebraic
        yp0 = problem.yp0
        if yp0 is None:
            yp0 = np.zeros(problem.n)
            if problem.rhs is not None:  # before any solver exists: an ordinary guarded call
                guard.wrap(problem.rhs, "rhs", poison=False)(t0, problem.y0, yp0)
                yp0[problem.algebraic] = 0.0
            if problem.is_dae or problem.rhs is None:
                opts["calc_initcond"] = "yp0"
                opts["calc_init_dt"] = t_eval[1] - t_eval[0]
        if problem.n_events:
            events = out.events = _Events(problem, guard, poison=True)
            ev_fn = events.fn
            ev = lambda t, y, yp, g: ev_fn(t, y, g)
            ev.direction = list(problem.event_direction)
            opts["eventsfn"], opts["num_events"] = ev, problem.n_events
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            solver = IDA(res, **opts)  # the guard has the (t, y, yp, out) signature
    guard.solver = solver
    stepped = False
    try:
        if method == "cvode":
            solver.init_step(t0, problem.y0)
        else:
            try:  # with calc_initcond, IDACalcIC runs the callbacks; scikit-sundae raises if it fails
                r0 = solver.init_step(t0, problem.y0, yp0)
                init_message = None if r0.success else r0.message
            except RuntimeError as exc:
                init_message = str(exc)
            if guard.stopped():
                return False, guard.message
            if init_message is not None:
                return False, f"IDA initialisation failed at t={t0:.9g}: {init_message}"
        out.put(problem.y0, yp0 if method == "ida" else None)
        tiny, n_tiny, sigint = _Stall.TINY, 0, _SIGINT
        t_now = t0
        while out.k < t_eval.size:
            if guard.n_steps >= max_steps:
                return False, f"reached max_steps={max_steps} at t={t_now:.9g}"
            late = guard.over_budget(t_now)
            if late:
                return False, late
            stepped = True
            try:
                r = solver.step(t_end, method="onestep", tstop=t_end)
            except Exception as exc:  # noqa: BLE001 -- scikit-sundae's own (a callback's never gets here)
                guard.stopped()
                if guard.message is not None:
                    return False, guard.message
                return False, f"{method.upper()} failed at t={t_now:.9g}: {type(exc).__name__}: {_short(str(exc), 200)}"
            if guard.message is not None or guard.poisoned:
                guard.stopped()
                return False, guard.message
            if sigint.pending:
                sigint.check()
            t_old, t_now = t_now, float(r.t)  # scikit-sundae: a float for a one-step call
            if not r.success:
                return False, f"{method.upper()} failed at t={t_now:.9g}: {r.message}"
            guard.n_steps += 1
            if t_now - t_old <= tiny * abs(t_now):
                n_tiny += 1
                if n_tiny >= _Stall.WINDOW:
                    return False, _Stall.message(method, t_old, t_now)
            else:
                n_tiny = 0
            while out.k < t_eval.size and out.pending <= t_now:
                if out.pending == t_now:
                    out.put(r.y, getattr(r, "yp", None))
                else:
                    ri = solver.step(out.pending, method="normal")
                    out.put(ri.y, getattr(ri, "yp", None))
            if events is not None and r.t_events is not None:
                idx = [int(i) for i in np.flatnonzero(np.atleast_2d(r.i_events)[-1])]
                if events.record(t_now, r.y, idx):
                    return True, f"terminal event at t={t_now:.9g}"
        return True, "reached the final time"
    finally:
        if not stepped:
            _settle(solver, guard, t_end)


# --------------------------------------------------------------------------------------------------
# scipy.integrate
# --------------------------------------------------------------------------------------------------

def _scipy_jacobian(problem, guard, dense):
    if problem.jac_pattern is None:
        if problem.jac_rhs is None:
            return {}
        jd = guard.wrap(problem.jac_rhs, "jac", poison=False)
        full = np.empty((problem.n, problem.n))

        def jac_dense(t, y):
            jd(t, y, full)
            return full.copy()

        return {"jac": jac_dense}
    pat = problem.jac_pattern
    if problem.jac_rhs is None:
        return {} if dense else {"jac_sparsity": pat}
    data = np.empty(pat.nnz)
    jr = guard.wrap(problem.jac_rhs, "jac", poison=False)

    def jac(t, y):
        jr(t, y, data)
        m = sp.csc_matrix((data.copy(), pat.indices, pat.indptr), shape=pat.shape)
        return m.toarray() if dense else m

    return {"jac": jac}


class _LsodaWorkPool:
    """Work arrays for scipy's LSODA that survive its reference leak.

    scipy 1.17's ``_odepack.lsoda`` keeps one extra reference to its ``rwork`` and ``iwork`` arrays
    per call, so every LSODA solve leaked both (``8 (22 + 9n + n^2) + 4 (20 + n)`` bytes: 16 kB at
    n = 40, 72 MB at n = 3000). The facade hands LSODA arrays from this pool instead of the ones scipy
    allocates and takes them back after the solve: the leaked references then pin one pair of arrays
    per size (and per concurrently running LSODA solve) for the life of the process instead of one
    pair per solve. Whether this scipy leaks is measured once, on a 1-state problem; if it does not,
    nothing is pooled."""

    def __init__(self):
        self.free: dict = {}
        self.lock = threading.Lock()
        self.leaky: bool | None = None

    @staticmethod
    def _measure_leak() -> bool:
        try:
            s = si.LSODA(lambda t, y: -y, 0.0, np.ones(1), 1.0)
            rw = s._lsoda_solver._integrator.rwork
            before = sys.getrefcount(rw)
            s.step()
            s.step()
            return sys.getrefcount(rw) > before
        except Exception:  # another scipy layout: do not touch it
            return False

    def install(self, solver):
        if self.leaky is None:
            self.leaky = self._measure_leak()
        if not self.leaky:
            return None
        try:
            integ = solver._lsoda_solver._integrator
            args = integ.call_args
            fresh = (integ.rwork, integ.iwork)
            if args[4] is not fresh[0] or args[5] is not fresh[1]:
                return None
        except (AttributeError, IndexError, TypeError):  # another scipy layout: leave it alone
            return None
        taken = []
        for a in fresh:
            key = (a.dtype.str, a.shape)
            with self.lock:
                stack = self.free.get(key)
                b = stack.pop() if stack else None
            if b is None:
                b = np.empty_like(a)
            b[...] = a
            taken.append(b)
        integ.rwork, integ.iwork = taken
        args[4], args[5] = taken
        return taken

    def release(self, taken):
        """Back to the pool once the solve is over (the dead solver never runs again)."""
        if taken is None:
            return
        with self.lock:
            for b in taken:
                self.free.setdefault((b.dtype.str, b.shape), []).append(b)


_LSODA_POOL = _LsodaWorkPool()


def _locate(events, fn_y, ta, tb, ga, gb, idx):
    """Earliest root in (ta, tb] among the crossing events idx; fn_y(t) gives the state at t."""
    best_t, best = np.inf, []
    for i in idx:
        gi = lambda s: events.values(s, fn_y(s))[i]
        ti = tb if gb[i] == 0 else brentq(gi, ta, tb, xtol=1e-14 * max(1.0, abs(tb)), rtol=4 * np.finfo(float).eps)
        if ti < best_t - 1e-15:
            best_t, best = ti, [i]
        elif abs(ti - best_t) <= 1e-15:
            best.append(i)
    return best_t, best


def _step_events(events, state_at, ta, tb, g_prev, y_b, out):
    """Events over the step (ta, tb]: locate the earliest crossing on the interpolant ``state_at(t)``,
    emit the outputs before it, record it. Returns (event values at tb, terminal event time or None)."""
    g_new = events.values(tb, y_b)
    idx = events.crossed(g_prev, g_new)
    if idx:
        te, which = _locate(events, state_at, ta, tb, g_prev, g_new, idx)
        while out.k < out.t_eval.size and out.pending <= te:
            out.put(state_at(out.pending))
        if events.record(te, state_at(te), which):
            return g_new, te
    return g_new, None


def _scipy_failure(exc, guard, method, t):
    """An exception out of scipy: the model's own (or the facade's stop) propagates; scipy's internal
    ones (e.g. its LU refusing a matrix after the step size degenerated) are a failed run."""
    if isinstance(exc, _Stop) or exc is guard.error:
        raise exc
    return False, f"{method} failed at t={float(t):.9g}: scipy raised {type(exc).__name__}: {_short(str(exc), 200)}"


def _solve_scipy(problem, method, t_eval, out, guard, rtol, atol, max_step, first_step, max_steps):
    if problem.rhs is None or problem.is_dae:
        raise ValueError(f"method '{method}' integrates ODEs only; problem '{problem.name}' is a DAE "
                         "(use method='ida')")
    rhs = guard.wrap(problem.rhs, "rhs", poison=False)

    def fun(t, y):
        f = np.empty_like(y)
        rhs(t, y, f)
        return f

    cls = {"bdf": si.BDF, "radau": si.Radau, "lsoda": si.LSODA}[method]
    kw = dict(rtol=rtol, atol=atol, **_scipy_jacobian(problem, guard, dense=(method == "lsoda")))
    if max_step > 0:
        kw["max_step"] = max_step
    if first_step > 0:
        kw["first_step"] = first_step
    events = out.events = _Events(problem, guard, poison=False) if problem.n_events else None
    try:
        solver = cls(fun, t_eval[0], problem.y0.copy(), t_eval[-1], **kw)
    except Exception as exc:  # noqa: BLE001
        return _scipy_failure(exc, guard, method, t_eval[0])
    pooled = _LSODA_POOL.install(solver) if method == "lsoda" else None
    try:
        out.put(problem.y0)
        g_prev = events.values(t_eval[0], problem.y0) if events is not None else None
        tiny, n_tiny = _Stall.TINY, 0
        while out.k < t_eval.size:
            if guard.n_steps >= max_steps:
                return False, f"reached max_steps={max_steps} at t={solver.t:.9g}"
            late = guard.over_budget(solver.t)
            if late:
                return False, late
            t_old = solver.t
            try:
                msg = solver.step()
            except Exception as exc:  # noqa: BLE001
                return _scipy_failure(exc, guard, method, t_old)
            _SIGINT.check()
            if solver.status == "failed":
                return False, f"{method} failed at t={solver.t:.9g}: {msg}"
            guard.n_steps += 1
            if solver.t - t_old <= tiny * abs(solver.t):
                n_tiny += 1
                if n_tiny >= _Stall.WINDOW:
                    return False, _Stall.message(method, t_old, solver.t)
            else:
                n_tiny = 0
            guard.check_state(solver.t, solver.y)
            dense = solver.dense_output()
            t_stop = solver.t
            if events is not None:
                g_prev, te = _step_events(events, dense, t_old, solver.t, g_prev, solver.y, out)
                if te is not None:
                    return True, f"terminal event at t={te:.9g}"
            while out.k < t_eval.size and out.pending <= t_stop:
                out.put(solver.y if out.pending == t_stop else dense(out.pending))
            if solver.status == "finished" and out.k < t_eval.size:
                out.put(solver.y)
        return True, "reached the final time"
    finally:
        _LSODA_POOL.release(pooled)


# --------------------------------------------------------------------------------------------------
# Fixed-step RK4
# --------------------------------------------------------------------------------------------------

def _solve_rk4(problem, t_eval, out, guard, dt, max_steps):
    if problem.rhs is None:
        raise ValueError(f"method 'rk4' needs a right-hand side; problem '{problem.name}' has only a residual")
    if problem.is_dae and problem.algebraic_solve is None:
        raise ValueError(f"method 'rk4' on the DAE '{problem.name}' needs problem.algebraic_solve "
                         "(the per-stage inner solve)")
    rhs = guard.wrap(problem.rhs, "rhs", poison=False)
    alg = problem.algebraic
    solve_alg = problem.algebraic_solve
    n = problem.n
    k1, k2, k3, k4 = (np.empty(n) for _ in range(4))

    def f(t, y, k):
        """Stage derivative; the algebraic part is solved first (the paper's inner iteration)."""
        if solve_alg is not None:
            y = solve_alg(t, y)
        rhs(t, y, k)
        if alg.size:
            k[alg] = 0.0
        return y

    begin = problem.step_begin

    def step(t, y, h):
        if begin is not None:
            begin(t, y)
        y = f(t, y, k1)
        f(t + 0.5 * h, y + 0.5 * h * k1, k2)
        f(t + 0.5 * h, y + 0.5 * h * k2, k3)
        f(t + h, y + h * k3, k4)
        return y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)

    def consistent(t, y):
        return solve_alg(t, y) if solve_alg is not None else y

    t_end = t_eval[-1]
    n_total = int(np.ceil((t_end - t_eval[0]) / dt * (1 - 1e-12)))
    if n_total > max_steps:
        raise ValueError(f"rk4 with dt={dt} needs {n_total} steps > max_steps={max_steps}")
    events = out.events = _Events(problem, guard, poison=False) if problem.n_events else None
    t, y = t_eval[0], consistent(t_eval[0], problem.y0.copy())
    out.put(y)
    g_prev = events.values(t, y) if events is not None else None
    snap = 1e-9 * dt  # an output within rounding of a step end is that step end
    for j in range(1, n_total + 1):
        t_new = t_end if j == n_total else t_eval[0] + j * dt
        h = t_new - t
        y_new = step(t, y, h)
        _SIGINT.check()
        if not _all_finite(y_new):
            idx, val, count = _first_nonfinite(y_new)
            return False, (f"rk4: the state of problem '{problem.name}' became non-finite at t={t_new:.9g}: "
                           f"y[{idx}] = {val} ({count} of {n}); the step diverged, reduce dt (dt={dt:g})")
        guard.n_steps += 1
        late = guard.over_budget(t_new)
        if late:
            return False, late
        if events is not None:
            partial = lambda s, t=t, y=y: consistent(s, step(t, y, s - t)) if s > t else y
            g_prev, te = _step_events(events, partial, t, t_new, g_prev, consistent(t_new, y_new), out)
            if te is not None:
                return True, f"terminal event at t={te:.9g}"
        while out.k < t_eval.size and out.pending <= t_new + snap:
            # an output inside the step is an RK4 step of the partial length from t
            out.put(consistent(t_new, y_new) if out.pending >= t_new - snap
                    else consistent(out.pending, step(t, y, out.pending - t)))
        t, y = t_new, y_new
    if out.k < t_eval.size:  # cannot happen unless t_eval and dt disagree beyond rounding
        return False, f"rk4 stopped at t={t:.9g} before the output time {out.pending:.9g}"
    return True, "reached the final time"
