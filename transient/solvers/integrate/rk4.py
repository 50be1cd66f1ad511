"""Fixed-step RK4 back end: the classical 4th-order Runge-Kutta scheme of the users' hand-coded codes, with a
hook (:attr:`Problem.algebraic_solve`) for the inner algebraic solve per stage (how the papers treat the film:
the film is solved to convergence for the rotor state of every stage). Events are located on the RK4 step of
partial length."""

from __future__ import annotations

import numpy as np

from transient.solvers.integrate.guard import SIGINT, Guard, all_finite, first_nonfinite
from transient.solvers.integrate.outputs import Events, Output, step_events
from transient.solvers.integrate.problem import Problem, Settings


def solve(problem: Problem, t_eval: np.ndarray, out: Output, guard: Guard, s: Settings):
    """Fixed-step RK4 with step ``s.dt``; returns ``(success, message)``."""
    dt, max_steps = s.dt, s.max_steps
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
    events = out.events = Events(problem, guard, poison=False) if problem.n_events else None
    t, y = t_eval[0], consistent(t_eval[0], problem.y0.copy())
    out.put(y)
    g_prev = events.values(t, y) if events is not None else None
    snap = 1e-9 * dt  # an output within rounding of a step end is that step end
    for j in range(1, n_total + 1):
        t_new = t_end if j == n_total else t_eval[0] + j * dt
        h = t_new - t
        y_new = step(t, y, h)
        SIGINT.check()
        if not all_finite(y_new):
            idx, val, count = first_nonfinite(y_new)
            return False, (f"rk4: the state of problem '{problem.name}' became non-finite at t={t_new:.9g}: "
                           f"y[{idx}] = {val} ({count} of {n}); the step diverged, reduce dt (dt={dt:g})")
        guard.n_steps += 1
        late = guard.over_budget(t_new)
        if late:
            return False, late
        if events is not None:
            partial = lambda s, t=t, y=y: consistent(s, step(t, y, s - t)) if s > t else y
            g_prev, te = step_events(events, partial, t, t_new, g_prev, consistent(t_new, y_new), out)
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

