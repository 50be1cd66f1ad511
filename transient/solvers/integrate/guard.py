"""The callback guard of one solve: counts and times the model's callbacks, checks their outputs for
non-finite values, turns a model's exception into a stopped run (re-raised unchanged by
:func:`~transient.solvers.integrate.solve`), defers Ctrl-C to a safe point (:class:`Sigint`) and detects a time
that stops advancing (:class:`Stall`)."""

from __future__ import annotations

import io
import math
import signal
import sys
import threading
import time
from typing import Callable

import numba
import numpy as np

from transient.checks import short_repr
from transient.solvers.integrate.problem import Problem

EPS = np.finfo(float).eps


@numba.njit(cache=True, nogil=True, fastmath={"reassoc"})
def nonfinite_probe(a):
    """0.0 if every entry of the 1-D array ``a`` is finite, NaN otherwise (``x * 0`` is 0 for finite x and
    NaN for inf/NaN, so the sum cannot overflow; ``reassoc`` only lets LLVM vectorise the sum)."""
    s = 0.0
    for i in range(a.size):
        s += a[i] * 0.0
    return s


def first_nonfinite(a: np.ndarray):
    """(index, value) of the first non-finite entry of ``a`` (index a tuple for 2-D arrays), or None."""
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size == 0:
        return None
    k = int(bad[0])
    idx = np.unravel_index(k, a.shape) if a.ndim > 1 else k
    return idx, a.reshape(-1)[k], int(bad.size)


def all_finite(a: np.ndarray) -> bool:
    a = np.asarray(a, dtype=float)
    if a.ndim != 1 or not a.flags.c_contiguous:
        a = np.ascontiguousarray(a).reshape(-1)
    return nonfinite_probe(a) == 0.0


class Stop(Exception):
    """Internal: ends a run with success=False and this message (never escapes :func:`solve`)."""


class Abort(Exception):
    """Internal: raised by a poisoned SUNDIALS callback once that is safe, to end the step at once
    (scikit-sundae turns it into an unrecoverable callback failure and re-raises it from ``step``)."""


class Sigint:
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


SIGINT = Sigint()

_WHAT = {"rhs": "the right-hand side f(t, y)", "residual": "the residual F(t, y, y')",
         "jac": "the Jacobian", "events": "the event functions"}


class Guard:
    """Wraps the problem's callables for one solve: counts calls, times them, checks their outputs.

    ``poison=True`` (SUNDIALS): the model's exception never escapes into scikit-sundae. On an
    exception or a non-finite output the wrapper records the failure and from then on never calls the
    model again. Until the first step has succeeded it answers with NaN (zeros for a Jacobian, so the
    linear solver only sees finite numbers): CVODE/IDA then fail the step by themselves, after they have
    set up their linear solver (a sparse SUNDIALS solver freed before that setup crashes, see
    :func:`transient.solvers.integrate.sundials.settle`); that costs a few dozen calls (about 10 n with a difference-quotient Jacobian).
    After a successful step the setup has certainly happened and the wrapper raises :class:`Abort`
    instead, which SUNDIALS takes as an unrecoverable callback failure: the step ends at once.
    ``poison=False`` (scipy, rk4): the exception propagates; a non-finite output raises :class:`Stop`.
    """

    def __init__(self, problem: Problem, method: str):
        self.problem = problem
        self.method = method
        self.n_rhs = 0
        self.n_jac = 0
        self.n_steps = 0
        self.n_error_test_failures: int | None = None  # set by a back end that counts them itself (bdf2)
        self.n_nonlinear_failures: int | None = None
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
                            f"{short_repr(str(exc), 200)}")
            try:
                exc.add_note(f"[transient.solve] raised inside {_WHAT[kind]} of problem '{self.problem.name}' "
                             f"at t={float(t):.9g} (method {self.method}); the integration was stopped")
            except Exception:  # an exception type that refuses notes: still re-raised unchanged
                pass

    def record_nonfinite(self, kind: str, t, out: np.ndarray, y=None) -> str:
        found = first_nonfinite(out)
        if found is None:  # cannot happen: the probe saw a non-finite value
            found = ("?", float("nan"), 1)
        idx, val, count = found
        label = {"rhs": "f", "residual": "F", "jac": "J", "events": "g"}[kind]
        idx = ", ".join(str(int(i)) for i in idx) if isinstance(idx, tuple) else idx
        msg = (f"{self._where(kind, t)} returned a non-finite value at t={float(t):.9g}: {label}[{idx}] = {val} "
               f"(first of {count} non-finite of {out.size})")
        bad_y = first_nonfinite(np.asarray(y, dtype=float)) if isinstance(y, np.ndarray) else None
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
            raise Abort
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
            raise Abort
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
            raise Stop(msg)
        g.poison()
        if g.n_steps > 0:
            raise Abort
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
            "clock": time.perf_counter, "sigint": SIGINT, "Abort": Abort, "Stop": Stop,
            "probe": nonfinite_probe if check is not False else (lambda a: 0.0), "fixed": fixed,
            "fill": 0.0 if kind == "jac" else np.nan,
            "counts_rhs": counted and kind in ("rhs", "residual"), "counts_jac": counted and kind == "jac",
        }
        exec(code, scope)
        return scope["wrapped"]

    # -- states ------------------------------------------------------------------------------------
    def check_state(self, t, y, what="state"):
        """Raise :class:`Stop` if the state ``y`` at ``t`` has a non-finite entry."""
        y = np.asarray(y)
        if not all_finite(y):
            idx, val, count = first_nonfinite(y)
            msg = (f"{self.method}: the {what} of problem '{self.problem.name}' became non-finite at "
                   f"t={float(t):.9g}: y[{idx}] = {val} (first of {count} of {y.size}); integration stopped")
            if self.message is None:
                self.message = msg
            raise Stop(msg)


class Stall:
    """A time that no longer advances: ``WINDOW`` consecutive steps each at most ``FACTOR`` roundoff
    units of ``|t|`` long, i.e. each moving t by a handful of representable numbers (the state of
    the CVODE/IDA stall on a NaN region: h ~ 1e-17 at t = 0.5 for a million steps). Relative to
    ``|t|`` only, so tiny steps near t = 0 (a fast initial layer) are never taken for a stall."""

    WINDOW = 50
    FACTOR = 4.0
    TINY = FACTOR * EPS

    @classmethod
    def message(cls, method, t_old, t_new) -> str:
        return (f"{method}: time stalled at t={t_new:.12g}: {cls.WINDOW} consecutive steps of at most "
                f"{cls.FACTOR:g} roundoff units of t (last step {t_new - t_old:.3g}); the problem is singular, "
                "discontinuous or non-finite there")

