"""scipy back end: ``scipy.integrate`` BDF, Radau and LSODA given the problem's sparse Jacobian (LSODA only
accepts a dense one: scipy's limitation), with the work-around for LSODA's work-array leak
(:class:`_LsodaWorkPool`)."""

from __future__ import annotations

import sys
import threading

import numpy as np
import scipy.integrate as si
import scipy.sparse as sp

from transient.checks import short_repr
from transient.solvers.integrate.guard import SIGINT, Guard, Stall, Stop
from transient.solvers.integrate.outputs import Events, Output, step_events
from transient.solvers.integrate.problem import Problem, Settings


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


def _scipy_failure(exc, guard, method, t):
    """An exception out of scipy: the model's own (or the facade's stop) propagates; scipy's internal
    ones (e.g. its LU refusing a matrix after the step size degenerated) are a failed run."""
    if isinstance(exc, Stop) or exc is guard.error:
        raise exc
    return False, f"{method} failed at t={float(t):.9g}: scipy raised {type(exc).__name__}: {short_repr(str(exc), 200)}"


def solve(problem: Problem, t_eval: np.ndarray, out: Output, guard: Guard, s: Settings):
    """``scipy.integrate`` BDF, Radau or LSODA (``s.method``); returns ``(success, message)``."""
    method, rtol, atol, max_step, first_step, max_steps = (s.method, s.rtol, s.atol, s.max_step, s.first_step,
                                                           s.max_steps)
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
    events = out.events = Events(problem, guard, poison=False) if problem.n_events else None
    try:
        solver = cls(fun, t_eval[0], problem.y0.copy(), t_eval[-1], **kw)
    except Exception as exc:  # noqa: BLE001
        return _scipy_failure(exc, guard, method, t_eval[0])
    pooled = _LSODA_POOL.install(solver) if method == "lsoda" else None
    try:
        out.put(problem.y0)
        g_prev = events.values(t_eval[0], problem.y0) if events is not None else None
        tiny, n_tiny = Stall.TINY, 0
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
            SIGINT.check()
            if solver.status == "failed":
                return False, f"{method} failed at t={solver.t:.9g}: {msg}"
            guard.n_steps += 1
            if solver.t - t_old <= tiny * abs(solver.t):
                n_tiny += 1
                if n_tiny >= Stall.WINDOW:
                    return False, Stall.message(method, t_old, solver.t)
            else:
                n_tiny = 0
            guard.check_state(solver.t, solver.y)
            dense = solver.dense_output()
            t_stop = solver.t
            if events is not None:
                g_prev, te = step_events(events, dense, t_old, solver.t, g_prev, solver.y, out)
                if te is not None:
                    return True, f"terminal event at t={te:.9g}"
            while out.k < t_eval.size and out.pending <= t_stop:
                out.put(solver.y if out.pending == t_stop else dense(out.pending))
            if solver.status == "finished" and out.k < t_eval.size:
                out.put(solver.y)
        return True, "reached the final time"
    finally:
        _LSODA_POOL.release(pooled)

