"""SUNDIALS back end (scikit-sundae): CVODE for ODEs, IDA for DAEs (and for ODEs as ``F = y' - f``), BDF with a
sparse direct solver (SuperLU_MT) fed by the analytic Jacobian in the fixed CSC pattern order, or band / dense
with SUNDIALS' own difference quotients when the problem says so."""

from __future__ import annotations

import warnings

import numpy as np
import scipy.sparse as sp

from transient.checks import short_repr
from transient.solvers.integrate.guard import SIGINT, Guard, Stall
from transient.solvers.integrate.outputs import Events, Output
from transient.solvers.integrate.problem import Problem, Settings

LINEAR_SOLVERS = ("auto", "sparse", "band", "dense")


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


def _ida_from_rhs(problem: Problem, guard: Guard):
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


def settle(solver, guard, t_end):
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


def solve(problem: Problem, t_eval: np.ndarray, out: Output, guard: Guard, s: Settings):
    """CVODE (``s.method == "cvode"``) or IDA; returns ``(success, message)``."""
    method, rtol, atol, max_step, first_step = s.method, s.rtol, s.atol, s.max_step, s.first_step
    max_steps, linear_solver, extra = s.max_steps, s.linear_solver, s.options
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
            events = out.events = Events(problem, guard, poison=True)
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
            events = out.events = Events(problem, guard, poison=True)
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
        tiny, n_tiny, sigint = Stall.TINY, 0, SIGINT
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
                return False, f"{method.upper()} failed at t={t_now:.9g}: {type(exc).__name__}: {short_repr(str(exc), 200)}"
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
                if n_tiny >= Stall.WINDOW:
                    return False, Stall.message(method, t_old, t_now)
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
            settle(solver, guard, t_end)

