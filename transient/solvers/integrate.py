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

Output is produced only at the requested times ``t_eval``; an ``observer(t, y)`` receives each
output so long runs need not store anything (``store=False``).
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
import scipy.integrate as si
import scipy.sparse as sp
from scipy.optimize import brentq

from transient.results import Result, record_type, result_type

METHODS = ("cvode", "ida", "bdf", "radau", "lsoda", "rk4")


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
        self.y0 = np.ascontiguousarray(self.y0, dtype=float)
        if self.y0.ndim != 1 or self.y0.size == 0:
            raise ValueError(f"Problem '{self.name}': y0 must be a non-empty 1-D array, got shape {self.y0.shape}")
        if self.rhs is None and self.residual is None:
            raise ValueError(f"Problem '{self.name}': give rhs (ODE) or residual (DAE), or both")
        if self.yp0 is not None:
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


class _Counter:
    """Wraps the problem's callables: counts calls and the time spent inside them."""

    def __init__(self):
        self.n_rhs = 0
        self.n_jac = 0
        self.seconds = 0.0

    def timed(self, fn, kind):
        clock = time.perf_counter

        def wrapped(*args):
            t0 = clock()
            fn(*args)
            self.seconds += clock() - t0
            if kind == "rhs":
                self.n_rhs += 1
            else:
                self.n_jac += 1

        return wrapped


def _check_t_eval(t_eval) -> np.ndarray:
    t_eval = np.asarray(t_eval, dtype=float)
    if t_eval.ndim != 1 or t_eval.size < 2:
        raise ValueError(f"t_eval must be a 1-D array of at least 2 times [s], got shape {t_eval.shape}")
    if not np.all(np.diff(t_eval) > 0):
        raise ValueError("t_eval must be strictly increasing [s]")
    return t_eval


class _Output:
    """Collects (or streams to an observer) the states at the requested output times."""

    def __init__(self, t_eval, n, store, observer, with_yp):
        self.t_eval = t_eval
        self.k = 0
        self.store = store
        self.observer = observer
        self.y = np.empty((t_eval.size, n)) if store else None
        self.yp = np.empty((t_eval.size, n)) if (store and with_yp) else None

    @property
    def pending(self) -> float:
        return self.t_eval[self.k] if self.k < self.t_eval.size else np.inf

    def put(self, y, yp=None):
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

    def __init__(self, problem: Problem):
        self.p = problem
        self.t, self.y, self.i = [], [], []
        self.counts = np.zeros(problem.n_events, dtype=np.int64)
        self.buf = np.empty(problem.n_events)

    def values(self, t, y):
        self.p.events(t, y, self.buf)
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
          observer: Callable | None = None, options: dict | None = None) -> Solution:
    """Integrate ``problem`` and return the state at the times ``t_eval`` (the first is the start).

    Parameters
    ----------
    method : one of ``"cvode"``, ``"ida"``, ``"bdf"``, ``"radau"``, ``"lsoda"``, ``"rk4"``.
    rtol, atol : tolerances of the adaptive methods (ignored by ``rk4``).
    dt : the fixed step of ``rk4`` [same unit as t]; required for ``rk4``.
    max_step, first_step : step limits of the adaptive methods (0 = free).
    max_steps : upper bound on the number of steps in the whole run.
    linear_solver : ``"auto"`` (sparse if the problem has a Jacobian pattern, band if it declares a
        band, dense otherwise), ``"sparse"``, ``"band"`` or ``"dense"`` (SUNDIALS methods).
    store : keep the outputs in ``Solution.y`` (False: only pass them to ``observer``).
    observer : ``observer(t, y)`` called at every output time, in order.
    options : extra keyword options for the SUNDIALS solver (e.g. ``max_nonlin_iters``, ``max_order``).
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    if not (rtol > 0):
        raise ValueError(f"rtol must be > 0, got {rtol}")
    if np.any(np.asarray(atol) <= 0):
        raise ValueError("atol must be > 0")
    if isinstance(max_steps, bool) or int(max_steps) != max_steps or max_steps < 1:
        raise ValueError(f"max_steps must be an integer >= 1, got {max_steps!r}")
    t_eval = _check_t_eval(t_eval)
    out = _Output(t_eval, problem.n, store, observer, with_yp=(method == "ida"))
    counter = _Counter()
    events = _Events(problem) if problem.n_events else None
    wall0 = time.perf_counter()
    if method in ("cvode", "ida"):
        success, message, n_steps = _solve_sundials(problem, method, t_eval, out, counter, events, rtol, atol,
                                                    max_step, first_step, max_steps, linear_solver, options or {})
    elif method == "rk4":
        success, message, n_steps = _solve_rk4(problem, t_eval, out, counter, events, dt, max_steps)
    else:
        success, message, n_steps = _solve_scipy(problem, method, t_eval, out, counter, events, rtol, atol,
                                                 max_step, first_step, max_steps)
    stats = Stats(n_steps=n_steps, n_rhs=counter.n_rhs, n_jac=counter.n_jac,
                  wall_time=time.perf_counter() - wall0, callback_time=counter.seconds)
    if method == "rk4":
        stats.n_error_test_failures = 0
        stats.n_nonlinear_failures = 0
    res = out.result(success=success, message=message, method=method, stats=stats)
    if events is not None:
        events.fill(res)
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


def _ida_from_rhs(problem: Problem):
    """IDA residual ``F = y' - f(t, y)`` and its Jacobian ``cj I - df/dy`` from an ODE problem."""
    n = problem.n
    f = np.empty(n)
    rhs = problem.rhs

    def residual(t, y, yp, res):
        rhs(t, y, f)
        res[:] = yp - f

    pattern = jac = None
    if problem.jac_pattern is None and problem.jac_rhs is not None:  # dense analytic Jacobian
        jac_rhs = problem.jac_rhs

        def jac(t, y, yp, cj, J):
            jac_rhs(t, y, J)
            J *= -1.0
            J[np.diag_indices(n)] += cj
    elif problem.jac_pattern is not None:
        pattern, p_map, diag = _with_diagonal(problem.jac_pattern)
        if problem.jac_rhs is not None:
            tmp = np.empty(problem.jac_pattern.nnz)
            jac_rhs = problem.jac_rhs

            def jac(t, y, yp, cj, data):
                jac_rhs(t, y, tmp)
                data[:] = 0.0
                data[p_map] = -tmp
                data[diag] += cj
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
    raise ValueError(f"linear_solver must be 'auto', 'sparse', 'band' or 'dense', got {linear_solver!r}")


def _solve_sundials(problem, method, t_eval, out, counter, events, rtol, atol, max_step, first_step,
                    max_steps, linear_solver, extra):
    from sksundae.cvode import CVODE
    from sksundae.ida import IDA

    opts = {"rtol": rtol, "atol": atol, "max_step": max_step, "first_step": first_step,
            "max_num_steps": max_steps, **extra}
    if method == "cvode":
        if problem.rhs is None:
            raise ValueError(f"method 'cvode' needs an ODE right-hand side; problem '{problem.name}' only has "
                             "a residual (use method='ida')")
        if problem.is_dae:
            raise ValueError(f"method 'cvode' cannot integrate the DAE '{problem.name}' (use method='ida')")
        rhs = counter.timed(problem.rhs, "rhs")
        lin, use_jac = _linear_solver_options(problem, problem.jac_pattern, problem.jac_rhs is not None,
                                              linear_solver)
        opts.update(lin)
        if use_jac:
            jr = counter.timed(problem.jac_rhs, "jac")
            opts["jacfn"] = lambda t, y, yp, data: jr(t, y, data)
        if events is not None:
            ev = lambda t, y, g: problem.events(t, y, g)
            ev.direction = list(problem.event_direction)
            opts["eventsfn"], opts["num_events"] = ev, problem.n_events
        with warnings.catch_warnings():  # sksundae notes that jacfn replaces its FD Jacobian: intended
            warnings.simplefilter("ignore", UserWarning)
            solver = CVODE(lambda t, y, yp: rhs(t, y, yp), method="BDF", **opts)
        solver.init_step(t_eval[0], problem.y0)
    else:
        if problem.residual is not None:
            residual, pattern, jac = problem.residual, problem.jac_pattern, problem.jac_residual
        else:
            residual, pattern, jac = _ida_from_rhs(problem)
        res = counter.timed(residual, "rhs")
        lin, use_jac = _linear_solver_options(problem, pattern, jac is not None, linear_solver)
        opts.update(lin)
        if use_jac:
            jj = counter.timed(jac, "jac")
            opts["jacfn"] = lambda t, y, yp, r, cj, data: jj(t, y, yp, cj, data)
        if problem.is_dae:
            opts["algebraic_idx"] = problem.algebraic
        yp0 = problem.yp0
        if yp0 is None:
            yp0 = np.zeros(problem.n)
            if problem.rhs is not None:
                problem.rhs(t_eval[0], problem.y0, yp0)
                yp0[problem.algebraic] = 0.0
            if problem.is_dae or problem.rhs is None:
                opts["calc_initcond"] = "yp0"
                opts["calc_init_dt"] = t_eval[1] - t_eval[0]
        if events is not None:
            ev = lambda t, y, yp, g: problem.events(t, y, g)
            ev.direction = list(problem.event_direction)
            opts["eventsfn"], opts["num_events"] = ev, problem.n_events
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            solver = IDA(lambda t, y, yp, r: res(t, y, yp, r), **opts)
        r0 = solver.init_step(t_eval[0], problem.y0, yp0)
        if not r0.success:
            return False, f"IDA initialisation failed: {r0.message}", 0
    out.put(problem.y0, yp0 if method == "ida" else None)
    t_end = t_eval[-1]
    n_steps = 0
    t_now = t_eval[0]
    while out.k < t_eval.size:
        if n_steps >= max_steps:
            return False, f"reached max_steps={max_steps} at t={t_now:.9g}", n_steps
        r = solver.step(t_end, method="onestep", tstop=t_end)
        if not r.success:
            return False, f"{method.upper()} failed at t={float(r.t):.6g}: {r.message}", n_steps
        n_steps += 1
        t_now = float(np.atleast_1d(r.t)[-1])
        while out.k < t_eval.size and out.pending <= t_now:
            if out.pending == t_now:
                out.put(r.y, getattr(r, "yp", None))
            else:
                ri = solver.step(out.pending, method="normal")
                out.put(ri.y, getattr(ri, "yp", None))
        if events is not None and r.t_events is not None:
            idx = [int(i) for i in np.flatnonzero(np.atleast_2d(r.i_events)[-1])]
            if events.record(t_now, r.y, idx):
                return True, f"terminal event at t={t_now:.9g}", n_steps
    return True, "reached the final time", n_steps


# --------------------------------------------------------------------------------------------------
# scipy.integrate
# --------------------------------------------------------------------------------------------------

def _scipy_jacobian(problem, counter, dense):
    if problem.jac_pattern is None:
        if problem.jac_rhs is None:
            return {}
        jd = counter.timed(problem.jac_rhs, "jac")
        full = np.empty((problem.n, problem.n))

        def jac_dense(t, y):
            jd(t, y, full)
            return full.copy()

        return {"jac": jac_dense}
    pat = problem.jac_pattern
    if problem.jac_rhs is None:
        return {} if dense else {"jac_sparsity": pat}
    data = np.empty(pat.nnz)
    jr = counter.timed(problem.jac_rhs, "jac")

    def jac(t, y):
        jr(t, y, data)
        m = sp.csc_matrix((data.copy(), pat.indices, pat.indptr), shape=pat.shape)
        return m.toarray() if dense else m

    return {"jac": jac}


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


def _solve_scipy(problem, method, t_eval, out, counter, events, rtol, atol, max_step, first_step, max_steps):
    if problem.rhs is None or problem.is_dae:
        raise ValueError(f"method '{method}' integrates ODEs only; problem '{problem.name}' is a DAE "
                         "(use method='ida')")
    rhs = counter.timed(problem.rhs, "rhs")

    def fun(t, y):
        f = np.empty_like(y)
        rhs(t, y, f)
        return f

    cls = {"bdf": si.BDF, "radau": si.Radau, "lsoda": si.LSODA}[method]
    kw = dict(rtol=rtol, atol=atol, **_scipy_jacobian(problem, counter, dense=(method == "lsoda")))
    if max_step > 0:
        kw["max_step"] = max_step
    if first_step > 0:
        kw["first_step"] = first_step
    solver = cls(fun, t_eval[0], problem.y0.copy(), t_eval[-1], **kw)
    out.put(problem.y0)
    g_prev = events.values(t_eval[0], problem.y0) if events is not None else None
    n_steps = 0
    while out.k < t_eval.size:
        if n_steps >= max_steps:
            return False, f"reached max_steps={max_steps} at t={solver.t}", n_steps
        t_old = solver.t
        msg = solver.step()
        if solver.status == "failed":
            return False, f"{method} failed at t={solver.t:.6g}: {msg}", n_steps
        n_steps += 1
        dense = solver.dense_output()
        t_stop = solver.t
        if events is not None:
            g_prev, te = _step_events(events, dense, t_old, solver.t, g_prev, solver.y, out)
            if te is not None:
                return True, f"terminal event at t={te:.9g}", n_steps
        while out.k < t_eval.size and out.pending <= t_stop:
            out.put(solver.y if out.pending == t_stop else dense(out.pending))
        if solver.status == "finished" and out.k < t_eval.size:
            out.put(solver.y)
    return True, "reached the final time", n_steps


# --------------------------------------------------------------------------------------------------
# Fixed-step RK4
# --------------------------------------------------------------------------------------------------

def _solve_rk4(problem, t_eval, out, counter, events, dt, max_steps):
    if dt is None or not dt > 0:
        raise ValueError(f"method 'rk4' needs a fixed step dt > 0, got dt={dt}")
    if problem.rhs is None:
        raise ValueError(f"method 'rk4' needs a right-hand side; problem '{problem.name}' has only a residual")
    if problem.is_dae and problem.algebraic_solve is None:
        raise ValueError(f"method 'rk4' on the DAE '{problem.name}' needs problem.algebraic_solve "
                         "(the per-stage inner solve)")
    rhs = counter.timed(problem.rhs, "rhs")
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

    t, y = t_eval[0], consistent(t_eval[0], problem.y0.copy())
    out.put(y)
    g_prev = events.values(t, y) if events is not None else None
    n_steps = 0
    t_end = t_eval[-1]
    n_total = int(np.ceil((t_end - t) / dt * (1 - 1e-12)))
    if n_total > max_steps:
        raise ValueError(f"rk4 with dt={dt} needs {n_total} steps > max_steps={max_steps}")
    snap = 1e-9 * dt  # an output within rounding of a step end is that step end
    for j in range(1, n_total + 1):
        t_new = t_end if j == n_total else t_eval[0] + j * dt
        h = t_new - t
        y_new = step(t, y, h)
        n_steps += 1
        if events is not None:
            partial = lambda s, t=t, y=y: consistent(s, step(t, y, s - t)) if s > t else y
            g_prev, te = _step_events(events, partial, t, t_new, g_prev, consistent(t_new, y_new), out)
            if te is not None:
                return True, f"terminal event at t={te:.9g}", n_steps
        while out.k < t_eval.size and out.pending <= t_new + snap:
            # an output inside the step is an RK4 step of the partial length from t
            out.put(consistent(t_new, y_new) if out.pending >= t_new - snap
                    else consistent(out.pending, step(t, y, out.pending - t)))
        t, y = t_new, y_new
        if not np.all(np.isfinite(y)):
            return False, f"rk4 diverged (non-finite state) at t={t:.6g}; reduce dt", n_steps
    if out.k < t_eval.size:  # cannot happen unless t_eval and dt disagree beyond rounding
        return False, f"rk4 stopped at t={t:.9g} before the output time {out.pending:.9g}", n_steps
    return True, "reached the final time", n_steps
