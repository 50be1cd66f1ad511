"""One implicit step at a time (SciPy's ``OdeSolver`` pattern, the step solve pluggable): :class:`Stepper` is the
contract, :class:`BDF2` the variable-step BDF2 on it, :class:`StepSolve` what a model hands it to solve one
step, and :func:`drive` the loop every stepper runs in (outputs, events, Ctrl-C, time budget, step count, finite
states), written once.

With ``h = t_(n+1) - t_n`` and ``w = h / h_(n-1)`` the variable-step BDF2 derivative (the first step of every
solve is backward Euler) of a stored quantity ``q`` (the state itself, or what the model stores: a film content)::

    q'_(n+1) = cj q_(n+1) + b,   cj = (1 + 2 w) / (h (1 + w)),   b = -(1 + w) / h q_n + w^2 / (h (1 + w)) q_(n-1)

Its local error ``h^3 y''' (1 + w)^2 / (6 w (1 + 2 w))`` is estimated from the distance between the converged
step and the quadratic predictor through the last three points (Hermite with y'(t_0) after the first step), on
the declared ``error_components`` only, in the weighted RMS norm of ``rtol |y| + atol`` (``error_pairs``: the
components of a plane vector, e.g. a journal's x and y, weighed by the vector's length, not each by its own: the
test then does not depend on the axes, and a component passing through zero on an orbit is not held to atol),
leaving out the
components the step solve reports as switched over the predictor's points (``StepSolve.switched``: a node that
crossed a complementarity's kink, e.g. the cavitation boundary of an EHL film, has a corner in time there that is
no truncation error; held in the test, one such node cuts every step across it). The step follows a PI
controller (Gustafsson; Hairer & Wanner, Solving ODEs II, IV.2: exponents 0.7/3 and 0.4/3), its ratio kept in
[0.2, 2] (BDF2 is zero-stable for ratios below 1 + sqrt 2) and the step below ``max_step`` (or ``cap * scale(t)``
for ``max_step=(cap, scale)``). A failed step solve cuts the step by 4. ``fixed_step = h`` takes steps of exactly h with no error test (convergence studies).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

MIN_RATIO, MAX_RATIO, SAFETY = 0.2, 2.0, 0.9
MAX_ORDER = 5
#: step ratio bound above order 2 (variable-step BDF3 is zero-stable for ratios up to ~1.5, Grigorieff 1983)
MAX_RATIO_HIGH = 1.5
#: a higher or lower order is taken only if its step is this much longer than the current order's
ORDER_BIAS = 1.2


class StepBounds(NamedTuple):
    """What bounds a :class:`BDF2` step besides its error test: the first step ``first_step`` (0: 1e-4 of the span);
    at most ``max_step`` (0: free), or a pair ``(max_step, scale)``: at most ``max_step * scale(t)`` at the step's
    start (e.g. a cap in shaft angle on a run whose speed changes); ``fixed_step`` > 0: steps of exactly that size,
    no error test; ``max_travel = (components, distance)``: steps over which those components (e.g. a journal's
    position) move at most ``distance`` (Euclidean) at their last step's speed; ``components`` may instead be a
    function ``travel(dy) -> float``, the travel of a change ``dy`` of the state (e.g. the largest of several
    journals' travels, each a combination of the states)."""

    first_step: float = 0.0
    max_step: object = 0.0
    fixed_step: float = 0.0
    max_travel: tuple | None = None


class StepSolve:
    """What a model hands a stepper: the solve of one implicit step, in its own variables and linear algebra.

    ``solve(t, cj, history, ts, ys, y_pred) -> (code, y)``: the state ``y`` at ``t`` with the stepper's
    derivative ``q' = cj q + b`` of whatever the model stores, ``b = history(qs)`` from that quantity at the
    accepted points (``qs`` aligned with ``ts``; ``ts``, ``ys``: the accepted times and states, oldest first, the
    last at ``t_n``; ``y_pred``: the stepper's predictor); code 0 converged, else failed. ``retry()``: after a failure, whether the same step may be tried once more with a
    more careful solve (the stepper then calls ``solve`` again before it cuts the step).
    ``accepted(t, y)``: the step ending at ``t`` in ``y`` was accepted (the model's own history).
    ``counts()``: ``(residuals, jacobians)`` evaluated so far. ``switched(y_new, ys)``: the components whose
    regime at ``y_new`` differs from theirs at any of the points ``ys`` the predictor was drawn through (a node
    crossing a complementarity's kink, whose corner in time is no truncation error), a boolean mask, left out of
    this step's error test; None (the default) leaves none out. Attributes read by the
    facade's back end: ``error_components`` (None: all) and ``test_first_step`` (:class:`BDF2`)."""

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

    def switched(self, y_new, ys):
        return None


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


def magnitude(y, pairs=None) -> np.ndarray:
    """``|y|`` per component, the components of each row ``(i, j)`` of ``pairs`` both ``hypot(y_i, y_j)`` (the length
    of the plane vector they make: the error weight of :class:`BDF2`'s ``error_pairs``)."""
    out = np.abs(y)
    if pairs is not None and pairs.size:
        length = np.hypot(y[pairs[:, 0]], y[pairs[:, 1]])
        out[pairs[:, 0]] = length
        out[pairs[:, 1]] = length
    return out


def extrapolate(ts, ys, t):
    """The polynomial through the points ``(ts[k], ys[k])`` (Lagrange, degree ``len(ts) - 1``) at ``t``."""
    out = 0.0
    for j, tj in enumerate(ts):
        c = 1.0
        for m, tm in enumerate(ts):
            if m != j:
                c *= (t - tm) / (tj - tm)
        out = out + c * ys[j]
    return out


def bdf_coefficients(t, ts):
    """The variable-step BDF of order ``len(ts)`` at ``t`` on the past points ``ts`` (oldest first):
    ``q'(t) = cj q(t) + sum_j a[j] q(ts[j])``, the derivative at ``t`` of the polynomial through ``t`` and ``ts``;
    returns ``(cj, a)``."""
    cj = sum(1.0 / (t - tm) for tm in ts)
    a = []
    for j, tj in enumerate(ts):
        num = 1.0
        den = tj - t
        for m, tm in enumerate(ts):
            if m != j:
                num *= t - tm
                den *= tj - tm
        a.append(num / den)
    return cj, a


def divided_difference(ts, ys):
    """The divided difference ``y[ts[0], ..., ts[-1]]`` (the leading coefficient of the polynomial through the
    points)."""
    d = list(ys)
    for level in range(1, len(ts)):
        d = [(d[k + 1] - d[k]) / (ts[k + level] - ts[k]) for k in range(len(d) - 1)]
    return d[0]


def _history(h, w, points):
    """``history(qs) -> b``, the past of the BDF2 derivative ``q' = cj q + b`` (module docstring) from the stored
    quantity at the accepted points: ``-q_n / h`` on a first step (``points`` = 1), else
    ``-(1 + w) / h q_n + w^2 / (h (1 + w)) q_(n-1)``."""
    if points == 1:
        return lambda qs: -qs[-1] / h
    return lambda qs: (-(1.0 + w) / h) * qs[-1] + (w * w / (h * (1.0 + w))) * qs[-2]


def _history_k(a):
    """``history(qs) -> b`` of a BDF of order ``len(a)`` (:func:`bdf_coefficients`), ``qs`` aligned with the
    stepper's points (the last ``len(a)`` used)."""
    k = len(a)
    return lambda qs: sum(a[j] * qs[len(qs) - k + j] for j in range(k))


class BDF2(Stepper):
    """Variable-step BDF2 (module docstring) around a model's :class:`StepSolve`, from ``y0`` (with the slope
    ``yp0``, zero if None) at ``t0`` to ``t_end``; error test on ``error_components`` with ``rtol`` and ``atol``
    (a number or one per state); the steps bounded by ``bounds`` (:class:`StepBounds`: first, largest, fixed step,
    travel); ``max_order`` in [2, 5]: the highest order of the variable-order BDF (module docstring), 2 the plain
    BDF2; ``test_first_step`` False: the first step is not error-tested (a DAE started from an inconsistent state,
    whose first step measures the jump of its algebraic part onto the constraint, not a truncation error)."""

    def __init__(self, solver: StepSolve, y0, t0, t_end, *, rtol, atol, error_components=None, yp0=None,
                 bounds: StepBounds = StepBounds(), test_first_step=True, max_order=2, error_pairs=None):
        first_step, max_step, fixed_step, max_travel = bounds
        self.solver = solver
        self.travel = None
        if max_travel is not None:
            comps = max_travel[0]
            self.travel = (comps if callable(comps) else np.asarray(comps, dtype=np.int64), float(max_travel[1]))
        self.max_order = int(max_order)
        if not 2 <= self.max_order <= MAX_ORDER:
            raise ValueError(f"max_order = {max_order!r} [-] is out of range; allowed: 2 to {MAX_ORDER}")
        self.order, self.same_order = 2, 0  # the order after the first (backward Euler) step; steps taken at it
        self.keep = max(3, self.max_order + 2)  # accepted points kept (order k+1's error estimate needs k+2)
        self.test_first_step = test_first_step
        n = y0.size
        self.err_idx = (np.arange(n) if error_components is None
                        else np.ascontiguousarray(error_components, dtype=np.int64))
        self.rtol = rtol
        self.atol = np.broadcast_to(np.asarray(atol, dtype=float), (n,))
        self.pairs = None if error_pairs is None else np.asarray(error_pairs, dtype=np.int64).reshape(-1, 2)
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
                h = min(self.h, self.h_cap if self.cap_scale is None else self.h_cap * self.cap_scale(t),
                        self._travel_cap())
                if t + h >= self.t_end - 1e-9 * h:
                    h = self.t_end - t
                t_new = t + h
            self.h = h
            if t_new <= t or h <= 1e-14 * max(1.0, abs(t)):
                return (f"bdf2: the step size collapsed to {h:.3g} at t={t:.9g} ({self.n_nonlinear_failures} "
                        f"Newton failures, {self.n_error_test_failures} error-test failures)")
            k = 1 if len(ts) == 1 else min(self.order, max(2, len(ts) - 1))
            if k >= 3:  # the order-k BDF on the last k points, its predictor through the last k + 1
                cj, a = bdf_coefficients(t_new, ts[-k:])
                history = _history_k(a)
                y_pred = extrapolate(ts[-k - 1:], ys[-k - 1:], t_new)
            else:
                if k == 1:  # backward Euler
                    cj = 1.0 / h
                    h1 = h2 = w = 0.0
                else:
                    h1 = t - ts[-2]
                    w = h / h1
                    cj = (1.0 + 2.0 * w) / (h * (1.0 + w))
                    h2 = ts[-2] - ts[-3] if len(ts) >= 3 else 0.0
                history = _history(h, w, k)
                y_pred = quadratic(ts[-3:], ys[-3:], t_new, self.slope)
            code, y_new = self.solver.solve(t_new, cj, history, ts, ys, y_pred)
            if code != 0:
                self.n_nonlinear_failures += 1
                if self.solver.retry():
                    continue
                if self.fixed > 0:
                    return f"bdf2: Newton failed at t={t_new:.9g} with the fixed step {self.fixed:.4g}"
                self.h = h * 0.25
                continue
            idx = self.err_idx
            kinked = self.solver.switched(y_new, ys[-k - 1:] if k >= 3 else ys[-3:])
            if kinked is not None:
                idx = idx[~kinked[idx]]
            d = (y_new - y_pred)[idx]
            if k == 1:
                est = 0.5 * d
            elif k == 2:
                est = d * (h * h * (1.0 + w) ** 2 / (w * (1.0 + 2.0 * w)) / ((h + h1) * (h + h1 + h2)))
            else:
                est = d / (cj * (t_new - ts[-k - 1]))
            scale = self.rtol * magnitude(y_new, self.pairs)[idx] + self.atol[idx]
            err = math.sqrt(float(np.mean((est / scale) ** 2))) if idx.size else 0.0
            if not math.isfinite(err):
                self.n_nonlinear_failures += 1
                self.h = h * 0.25
                continue
            if err > 1.0 and self.fixed == 0 and (self.test_first_step or len(ts) > 1):
                self.n_error_test_failures += 1
                self.h = h * max(MIN_RATIO, SAFETY * err ** (-1.0 / (max(k, 2) + 1.0)))
                if k >= 3:  # a rejected step at order 3 and above retries one order lower
                    self.order, self.same_order = k - 1, 0
                continue
            break
        self.n_steps += 1
        y_acc = y_new.copy()
        if k >= 3:
            self._dense = (k, ts[-k:] + [t_new], ys[-k:] + [y_acc])
        else:
            self._dense = (k, ts[-2:] + [t_new], ys[-2:] + [y_acc]) if len(ts) >= 2 else (k, [t, t_new], [y, y_acc])
        self.solver.accepted(t_new, y_acc)
        self.ts, self.ys = (ts + [t_new])[-self.keep:], (ys + [y_acc])[-self.keep:]
        self.t_old, self.t, self.y = t, t_new, y_acc
        e = max(err, 1e-10)
        q = max(k, 2) + 1.0
        ratio = SAFETY * e ** (-0.7 / q) * self.err_prev ** (0.4 / q)
        self.err_prev = e
        if self.max_order > 2 and self.fixed == 0 and k >= 2:
            ratio = self._select_order(k, ratio, scale, idx)
        top = MAX_RATIO if self.order <= 2 else MAX_RATIO_HIGH
        self.h = h * min(top, max(MIN_RATIO, ratio))
        return None

    def _travel_cap(self):
        """The longest step over which the ``max_travel`` components (e.g. a journal's position; or the travel
        function's measure) move at most the given distance at their speed over the last step (no bound before the
        second point or at rest)."""
        if self.travel is None or len(self.ts) < 2:
            return math.inf
        idx, dist = self.travel
        dy = self.ys[-1] - self.ys[-2]
        travel = float(idx(dy)) if callable(idx) else float(np.linalg.norm(dy[idx]))
        speed = travel / (self.ts[-1] - self.ts[-2])
        return dist / speed if speed > 0.0 else math.inf

    def _select_order(self, k, ratio, scale, idx):
        """Order control (as DASSL's and SciPy's BDF): after ``k + 1`` steps at order ``k``, the local errors at
        orders ``k - 1`` (not below 2) and ``k + 1`` (up to ``max_order``) from the divided differences of the
        accepted points (``scale``: the error weights of the components ``idx``); the order whose step would be longest (by ``ORDER_BIAS``)
        is taken. Returns the step ratio."""
        self.same_order = self.same_order + 1 if k == self.order else 0
        if k != self.order or self.same_order < k + 1:
            return ratio
        ts, ys = self.ts, self.ys
        t_new = ts[-1]
        best, best_ratio = k, ratio
        for q in (k - 1, k + 1):
            if q < 2 or q > self.max_order or len(ts) < q + 2:
                continue
            past = ts[-q - 1:-1]
            lte = (divided_difference(ts[-q - 2:], [v[idx] for v in ys[-q - 2:]])
                   * math.prod(t_new - tm for tm in past) / sum(1.0 / (t_new - tm) for tm in past))
            e_q = max(math.sqrt(float(np.mean((lte / scale) ** 2))), 1e-10)
            r_q = SAFETY * e_q ** (-1.0 / (q + 1.0))
            if r_q > ORDER_BIAS * best_ratio:
                best, best_ratio = q, r_q
        if best != k:
            self.order, self.same_order, self.err_prev = best, 0, 1.0
        return best_ratio

    def dense_output(self):
        """The step's interpolant: the polynomial of the step's order through its last points (order <= 2: the
        quadratic through the last three accepted points, Hermite with the start's slope after the first step)."""
        k, pts_t, pts_y = self._dense
        t_new, y_acc, slope = self.t, self.y, self.slope

        def state_at(s):
            if s >= t_new:
                return y_acc
            return extrapolate(pts_t, pts_y, s) if k >= 3 else quadratic(pts_t, pts_y, s, slope)
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
