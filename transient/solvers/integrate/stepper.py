"""One implicit step at a time (SciPy's ``OdeSolver`` pattern, the step solve pluggable): :class:`Stepper` is the
contract, :class:`BDF2` the variable-step BDF2 on it, :class:`StepSolve` what a model hands it to solve one
step, and :func:`drive` the loop every stepper runs in (outputs, events, Ctrl-C, time budget, step count, finite
states), written once.

With ``h = t_(n+1) - t_n`` and ``w = h / h_(n-1)`` the variable-step BDF2 derivative (the first step of every
solve is backward Euler) of a stored quantity ``q`` (the state itself, or what the model stores: a film content)::

    q'_(n+1) = cj q_(n+1) + b,   cj = (1 + 2 w) / (h (1 + w)),   b = -(1 + w) / h q_n + w^2 / (h (1 + w)) q_(n-1)

Its local error ``h^3 y''' (1 + w)^2 / (6 w (1 + 2 w))`` is estimated from the distance between the converged
step and the quadratic predictor through the last three points (Hermite with y'(t_0) after the first step), on
the declared ``error_components`` only, in the weighted RMS norm of ``rtol |y| + atol``. The step follows a PI
controller (Gustafsson; Hairer & Wanner, Solving ODEs II, IV.2: exponents 0.7/3 and 0.4/3), its ratio kept in
[0.2, 2] (BDF2 is zero-stable for ratios below 1 + sqrt 2) and the step below ``max_step`` (or ``cap * scale(t)``
for ``max_step=(cap, scale)``). A failed step solve cuts the step by 4. ``fixed_step = h`` takes steps of exactly h with no error test (convergence studies).
"""

from __future__ import annotations

import math

import numpy as np

MIN_RATIO, MAX_RATIO, SAFETY = 0.2, 2.0, 0.9


class StepSolve:
    """What a model hands a stepper: the solve of one implicit step, in its own variables and linear algebra.

    ``solve(t, cj, history, ts, ys, y_pred) -> (code, y)``: the state ``y`` at ``t`` with the stepper's
    derivative ``q' = cj q + b`` of whatever the model stores, ``b = history(qs)`` from that quantity at the
    accepted points (``qs`` aligned with ``ts``; ``ts``, ``ys``: the accepted times and states, oldest first, the
    last at ``t_n``; ``y_pred``: the stepper's predictor); code 0 converged, else failed. ``retry()``: after a failure, whether the same step may be tried once more with a
    more careful solve (the stepper then calls ``solve`` again before it cuts the step).
    ``accepted(t, y)``: the step ending at ``t`` in ``y`` was accepted (the model's own history).
    ``counts()``: ``(residuals, jacobians)`` evaluated so far. Attributes read by the facade's back end:
    ``error_components`` (None: all) and ``test_first_step`` (:class:`BDF2`)."""

    error_components = None
    test_first_step = True

    def solve(self, t, cj, history, ts, ys, y_pred):
        raise NotImplementedError

    def retry(self) -> bool:
        return False

    def accepted(self, t, y):
        pass

    def counts(self) -> tuple[int, int]:
        return 0, 0


class Stepper:
    """The contract of a one-step-at-a-time integrator: ``t``, ``y`` (the last accepted point), ``t_old``;
    ``step()`` advances by one accepted step (returns None) or returns why it cannot; ``dense_output()`` the
    interpolant ``s -> y(s)`` of the last step on ``[t_old, t]``; counters ``n_steps``, ``n_error_test_failures``,
    ``n_nonlinear_failures``."""

    t: float
    y: np.ndarray
    t_old: float
    t_end: float
    n_steps = 0
    n_error_test_failures = 0
    n_nonlinear_failures = 0

    def step(self) -> str | None:
        raise NotImplementedError

    def dense_output(self):
        raise NotImplementedError


def quadratic(ts, ys, t, slope=None):
    """The quadratic through the points ``(ts[k], ys[k])`` (3 of them), or through 2 points with the slope at
    the first (Hermite), or the line through 1 point with its slope, at ``t``."""
    if len(ts) == 3:
        t0, t1, t2 = ts
        return (ys[0] * ((t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)))
                + ys[1] * ((t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)))
                + ys[2] * ((t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1))))
    if len(ts) == 2:
        h1 = ts[1] - ts[0]
        c = (ys[1] - ys[0] - slope * h1) / (h1 * h1)
        s = t - ts[0]
        return ys[0] + slope * s + c * (s * s)
    return ys[0] + slope * (t - ts[0])


def _history(h, w, points):
    """``history(qs) -> b``, the past of the BDF2 derivative ``q' = cj q + b`` (module docstring) from the stored
    quantity at the accepted points: ``-q_n / h`` on a first step (``points`` = 1), else
    ``-(1 + w) / h q_n + w^2 / (h (1 + w)) q_(n-1)``."""
    if points == 1:
        return lambda qs: -qs[-1] / h
    return lambda qs: (-(1.0 + w) / h) * qs[-1] + (w * w / (h * (1.0 + w))) * qs[-2]


class BDF2(Stepper):
    """Variable-step BDF2 (module docstring) around a model's :class:`StepSolve`, from ``y0`` (with the slope
    ``yp0``, zero if None) at ``t0`` to ``t_end``; error test on ``error_components`` with ``rtol`` and ``atol``
    (a number or one per state); first step ``first_step`` (0: 1e-4 of the span), at most ``max_step``
    (0: free), or a pair ``(max_step, scale)``: at most ``max_step * scale(t)`` at the step's start (e.g. a cap in
    shaft angle on a run whose speed changes); ``fixed_step`` > 0: steps of exactly that size, no error test; ``test_first_step`` False: the
    first step is not error-tested (a DAE started from an inconsistent state, whose first step measures the
    jump of its algebraic part onto the constraint, not a truncation error)."""

    def __init__(self, solver: StepSolve, y0, t0, t_end, *, rtol, atol, error_components=None, yp0=None,
                 first_step=0.0, max_step=0.0, fixed_step=0.0, test_first_step=True):
        self.solver = solver
        self.test_first_step = test_first_step
        n = y0.size
        self.err_idx = (np.arange(n) if error_components is None
                        else np.ascontiguousarray(error_components, dtype=np.int64))
        self.rtol = rtol
        self.atol = np.broadcast_to(np.asarray(atol, dtype=float), (n,))[self.err_idx]
        self.t = self.t_old = self.t_start = float(t0)
        self.t_end = float(t_end)
        self.y = y0.copy()
        self.slope = np.zeros(n) if yp0 is None else yp0.copy()
        span = self.t_end - self.t
        self.fixed = float(fixed_step)
        self.h = self.fixed if self.fixed > 0 else (first_step if first_step > 0 else 1e-4 * span)
        max_step, self.cap_scale = max_step if isinstance(max_step, tuple) else (max_step, None)
        self.h_cap = max_step if max_step > 0 else span
        if max_step <= 0:
            self.cap_scale = None
        self.ts, self.ys = [self.t], [self.y]  # the last (up to 3) accepted points, oldest first
        self.err_prev = 1.0
        self._dense = None

    def step(self) -> str | None:
        """Attempts until one is accepted (None) or the step collapses / a fixed step fails (the message)."""
        t, y, ts, ys = self.t, self.y, self.ts, self.ys
        while True:
            if self.fixed > 0:  # step k ends at t_start + k h exactly (no drift), the last one at t_end
                t_new = min(self.t_end, self.t_start + (self.n_steps + 1) * self.fixed)
                h = t_new - t
            else:
                h = min(self.h, self.h_cap if self.cap_scale is None else self.h_cap * self.cap_scale(t))
                if t + h >= self.t_end - 1e-9 * h:
                    h = self.t_end - t
                t_new = t + h
            self.h = h
            if t_new <= t or h <= 1e-14 * max(1.0, abs(t)):
                return (f"bdf2: the step size collapsed to {h:.3g} at t={t:.9g} ({self.n_nonlinear_failures} "
                        f"Newton failures, {self.n_error_test_failures} error-test failures)")
            if len(ts) == 1:  # backward Euler
                cj = 1.0 / h
                h1 = h2 = w = 0.0
            else:
                h1 = t - ts[-2]
                w = h / h1
                cj = (1.0 + 2.0 * w) / (h * (1.0 + w))
                h2 = ts[-2] - ts[-3] if len(ts) == 3 else 0.0
            y_pred = quadratic(ts, ys, t_new, self.slope)
            code, y_new = self.solver.solve(t_new, cj, _history(h, w, len(ts)), ts, ys, y_pred)
            if code != 0:
                self.n_nonlinear_failures += 1
                if self.solver.retry():
                    continue
                if self.fixed > 0:
                    return f"bdf2: Newton failed at t={t_new:.9g} with the fixed step {self.fixed:.4g}"
                self.h = h * 0.25
                continue
            idx = self.err_idx
            d = (y_new - y_pred)[idx]
            if len(ts) == 1:
                est = 0.5 * d
            else:
                est = d * (h * h * (1.0 + w) ** 2 / (w * (1.0 + 2.0 * w)) / ((h + h1) * (h + h1 + h2)))
            err = math.sqrt(float(np.mean((est / (self.rtol * np.abs(y_new[idx]) + self.atol)) ** 2)))
            if not math.isfinite(err):
                self.n_nonlinear_failures += 1
                self.h = h * 0.25
                continue
            if err > 1.0 and self.fixed == 0 and (self.test_first_step or len(ts) > 1):
                self.n_error_test_failures += 1
                self.h = h * max(MIN_RATIO, SAFETY * err ** (-1.0 / 3.0))
                continue
            break
        self.n_steps += 1
        y_acc = y_new.copy()
        self._dense = (ts[-2:] + [t_new], ys[-2:] + [y_acc]) if len(ts) >= 2 else ([t, t_new], [y, y_acc])
        self.solver.accepted(t_new, y_acc)
        self.ts, self.ys = (ts + [t_new])[-3:], (ys + [y_acc])[-3:]
        self.t_old, self.t, self.y = t, t_new, y_acc
        e = max(err, 1e-10)
        ratio = SAFETY * e ** (-0.7 / 3.0) * self.err_prev ** (0.4 / 3.0)
        self.h = h * min(MAX_RATIO, max(MIN_RATIO, ratio))
        self.err_prev = e
        return None

    def dense_output(self):
        """The step's quadratic through the last three accepted points (Hermite with the start's slope after the
        first step)."""
        pts_t, pts_y = self._dense
        t_new, y_acc, slope = self.t, self.y, self.slope

        def state_at(s):
            return y_acc if s >= t_new else quadratic(pts_t, pts_y, s, slope)
        return state_at


def drive(stepper: Stepper, out, guard, interrupt, max_steps, step_events=None) -> tuple[bool, str]:
    """Run ``stepper`` until every output time of ``out`` (the facade's collector; its first time is the start)
    is filled: outputs from the step's dense output, events located on it (``out.events``, ``step_events``),
    Ctrl-C (``interrupt``) after every step, the time budget and ``max_steps`` of ``guard``'s run. Every state
    handed out is checked finite by ``out``. Returns ``(success, message)``; the counters go to ``guard``."""
    events = out.events
    t_eval = out.t_eval
    out.put(stepper.y)
    g_prev = events.values(stepper.t, stepper.y) if events is not None else None

    def finish(success, message):
        residuals, jacobians = stepper.solver.counts()
        guard.n_rhs += residuals
        guard.n_jac += jacobians
        guard.n_error_test_failures = stepper.n_error_test_failures
        guard.n_nonlinear_failures = stepper.n_nonlinear_failures
        return success, message

    while out.k < t_eval.size:
        why = stepper.step()
        interrupt()
        if why is not None:
            return finish(False, why)
        guard.n_steps += 1
        t_new, y_acc = stepper.t, stepper.y
        h = t_new - stepper.t_old
        state_at = stepper.dense_output()
        if events is not None:
            g_prev, te = step_events(events, state_at, stepper.t_old, t_new, g_prev, y_acc, out)
            if te is not None:
                return finish(True, f"terminal event at t={te:.9g}")
        while out.k < t_eval.size and out.pending <= t_new + 1e-9 * h:
            out.put(state_at(out.pending) if out.pending < t_new - 1e-9 * h else y_acc)
        late = guard.over_budget(t_new)
        if late:
            return finish(False, late)
        if guard.n_steps >= max_steps and out.k < t_eval.size:
            return finish(False, f"bdf2: max_steps={max_steps} reached at t={stepper.t:.9g}")
    return finish(True, "reached the final time")
