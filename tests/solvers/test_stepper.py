"""The stepper contract (solvers/integrate/stepper.py) on a linear test problem with an exact step solve: the BDF2
history is exact for quadratics, the fixed-step error falls at second order, the adaptive error follows rtol, and
the one loop (drive, through the integrator facade) gives outputs at the requested times, events on the dense
output, max_steps, the time budget and a refused non-finite state."""

import math

import numpy as np
import pytest

from transient.solvers.integrate import Problem, solve
from transient.solvers.integrate.stepper import (BDF2, StepBounds, StepSolve, _history, bdf_coefficients, divided_difference,
                                                 extrapolate)
from transient import Steps

LAM = -2.0  # y' = LAM y + sin(t), exact step solve


def exact(t, y0=1.0):
    a = LAM
    c = y0 + 1.0 / (1.0 + a * a)
    return c * math.exp(a * t) - (a * math.sin(t) + math.cos(t)) / (1.0 + a * a)


class LinearStep(StepSolve):
    """cj y + b = LAM y + sin(t): y = (sin t - b) / (cj - LAM) (one "Newton" that is exact)."""

    error_components = None

    def __init__(self, fail_at=None):
        self.fail_at, self.n = fail_at, 0

    def solve(self, t, cj, history, ts, ys, y_pred):
        self.n += 1
        y = (math.sin(t) - history(ys)) / (cj - LAM)
        if self.fail_at is not None and t > self.fail_at:
            y = y * np.nan
        return 0, y

    def counts(self):
        return self.n, 1  # (residuals, Jacobians): one "Jacobian", the constant cj - LAM


def test_history_is_exact_for_quadratics():
    q = lambda t: 1.0 + 2.0 * t - 3.0 * t * t
    dq = lambda t: 2.0 - 6.0 * t
    t_prev, t_n, h = 0.0, 0.3, 0.5
    w = h / (t_n - t_prev)
    cj = (1.0 + 2.0 * w) / (h * (1.0 + w))
    assert cj * q(t_n + h) + _history(h, w, 2)([q(t_prev), q(t_n)]) == pytest.approx(dq(t_n + h), rel=1e-12)
    assert (1.0 / h) * q(h) + _history(h, 0.0, 1)([q(0.0)]) == pytest.approx((q(h) - q(0.0)) / h, rel=1e-12)


def test_fixed_steps_converge_at_second_order():
    errors = []
    for n in (40, 80, 160):
        s = BDF2(LinearStep(), np.array([1.0]), 0.0, 2.0, rtol=1e-3, atol=1e-6, bounds=StepBounds(fixed_step=2.0 / n))
        while s.t < 2.0:
            assert s.step() is None
        assert s.t == 2.0 and s.n_steps == n
        errors.append(abs(s.y[0] - exact(2.0)))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 1.8) and np.all(orders < 2.2), orders


def test_adaptive_error_follows_rtol_and_outputs_come_at_the_requested_times():
    t_eval = np.linspace(0.0, 3.0, 7)
    errs = []
    for rtol in (1e-3, 1e-5):
        step = LinearStep()
        sol = solve(Problem(y0=np.array([1.0]), step_solve=step, name="linear"), t_eval, method="bdf2",
                    rtol=rtol, atol=1e-9)
        assert sol.success and np.array_equal(sol.t, t_eval)
        errs.append(max(abs(sol.y[k, 0] - exact(t)) for k, t in enumerate(t_eval)))
        assert sol.stats.n_rhs == step.n >= sol.stats.n_steps and sol.stats.n_jac == 1
    assert errs[1] < errs[0] / 10.0, errs


def test_event_located_on_the_dense_output():
    def events(t, y, out):
        out[0] = y[0] - 0.5
    sol = solve(Problem(y0=np.array([1.0]), step_solve=LinearStep(), events=events, n_events=1,
                        event_terminal=[True], event_direction=[-1], name="linear"),
                np.linspace(0.0, 3.0, 31), method="bdf2", rtol=1e-6, atol=1e-10)
    assert sol.success and "terminal event" in sol.message
    te = sol.t_events[0]
    assert exact(te) == pytest.approx(0.5, abs=1e-4)


def test_max_steps_and_non_finite_state_stop_the_run_with_a_message():
    p = Problem(y0=np.array([1.0]), step_solve=LinearStep(), name="linear")
    sol = solve(p, np.linspace(0.0, 3.0, 4), method="bdf2", rtol=1e-8, atol=1e-12, steps=Steps(max_steps=5))
    assert not sol.success and "max_steps=5" in sol.message
    p = Problem(y0=np.array([1.0]), step_solve=LinearStep(fail_at=1.0), name="linear")
    sol = solve(p, np.linspace(0.0, 3.0, 31), method="bdf2", rtol=1e-4, atol=1e-8)
    assert not sol.success and sol.t[-1] <= 1.0 + 1e-12


def test_a_scaled_cap_is_scaled_at_each_step():
    """A loose tolerance leaves the cap in charge: ``max_step=(cap, scale)`` multiplies it by ``scale(t)`` at each
    step's start (a cap in shaft angle on a run whose speed changes), so every step ends within the scaled cap and
    the steps follow it."""
    scale = lambda t: 1.0 if t < 1.0 else 3.0  # noqa: E731
    s = BDF2(LinearStep(), np.array([1.0]), 0.0, 2.0, rtol=1e-1, atol=1e-1, bounds=StepBounds(max_step=(0.01, scale)))
    plain = BDF2(LinearStep(), np.array([1.0]), 0.0, 2.0, rtol=1e-1, atol=1e-1, bounds=StepBounds(max_step=0.01))
    ts = [0.0]
    while s.t < 2.0:
        assert s.step() is None
        assert s.t - s.t_old <= 0.01 * scale(s.t_old) * (1 + 1e-12)
        ts.append(s.t)
    while plain.t < 2.0:
        assert plain.step() is None
    h = np.diff(ts)
    assert h[np.array(ts[:-1]) >= 1.1].max() > 2.5 * 0.01  # the scaled cap is used, not only allowed
    assert plain.n_steps > 1.4 * s.n_steps  # 200 steps against 100 + 100 / 3


def test_bdf_coefficients_are_exact_for_polynomials_of_their_order():
    """The order-k derivative ``cj q(t) + sum a_j q(t_j)`` on k past points of uneven spacing is exact for a
    polynomial of degree k (here k = 4, a quartic)."""
    q = lambda t: 1.0 - 2.0 * t + 0.5 * t ** 2 + 3.0 * t ** 3 - t ** 4
    dq = lambda t: -2.0 + t + 9.0 * t ** 2 - 4.0 * t ** 3
    ts, t = [0.0, 0.3, 0.45, 0.8], 1.1
    cj, a = bdf_coefficients(t, ts)
    assert cj * q(t) + sum(aj * q(tj) for aj, tj in zip(a, ts)) == pytest.approx(dq(t), rel=1e-12)
    assert extrapolate(ts + [t], [q(s) for s in ts + [t]], 0.6) == pytest.approx(q(0.6), rel=1e-12)
    assert divided_difference(ts + [t], [q(s) for s in ts + [t]]) == pytest.approx(-1.0, rel=1e-10)


def test_a_higher_order_reaches_a_tight_tolerance_in_fewer_steps():
    """``max_order`` > 2: the order rises where the solution is smooth; at rtol 1e-8 the variable-order BDF (up to
    5) takes far fewer steps than BDF2 for an error no larger (against the exact solution), and its error still
    follows rtol."""
    runs = {}
    for max_order in (2, 5):
        for rtol in (1e-6, 1e-8):
            s = BDF2(LinearStep(), np.array([1.0]), 0.0, 10.0, rtol=rtol, atol=1e-2 * rtol, max_order=max_order)
            orders = set()
            while s.t < 10.0:
                assert s.step() is None
                orders.add(s.order)
            runs[max_order, rtol] = (s.n_steps, abs(s.y[0] - exact(10.0)), max(orders))
    assert runs[2, 1e-8][2] == 2 and runs[5, 1e-8][2] >= 4
    assert runs[5, 1e-8][0] < runs[2, 1e-8][0] / 5 and runs[5, 1e-8][1] <= runs[2, 1e-8][1]
    assert runs[5, 1e-8][1] < runs[5, 1e-6][1] / 10


def test_max_order_out_of_range_is_refused():
    with pytest.raises(ValueError, match="max_order = 6"):
        BDF2(LinearStep(), np.array([1.0]), 0.0, 1.0, rtol=1e-3, atol=1e-6, max_order=6)


def test_a_travel_function_bounds_the_steps_as_the_components_do():
    """``max_travel=(travel, distance)`` with ``travel(dy)`` a function (e.g. the largest of several journals'
    travels, each a combination of the states): the same steps as the components' form for the same measure, and
    a measure twice as large takes about twice the steps (the travel, not the loose error test, sets them)."""
    def steps(measure, distance=0.02):
        s = BDF2(LinearStep(), np.array([1.0]), 0.0, 3.0, rtol=1e-1, atol=1e-1, max_order=5,
                 bounds=StepBounds(max_travel=(measure, distance)))
        ts = [0.0]
        while s.t < 3.0:
            assert s.step() is None
            ts.append(s.t)
        return np.array(ts)

    by_components = steps([0])
    assert np.array_equal(steps(lambda dy: abs(dy[0])), by_components)
    doubled = steps(lambda dy: 2.0 * abs(dy[0]))
    assert 1.8 < (doubled.size - 1) / (by_components.size - 1) < 2.2, (doubled.size, by_components.size)
    free = steps([0], distance=1e3)  # no effective bound: the error test alone
    assert by_components.size > 2 * free.size


class KinkStep(StepSolve):
    """Two components: y0 = sin(t) (smooth) and y1 = max(0, t - T_KINK), an algebraic
    component with a corner in time (a node crossing a complementarity's kink); ``report`` says whether the step
    solve reports y1 as switched over a step whose ends lie on both sides of the corner."""

    T_KINK = 0.5 + 1e-3 * math.pi

    def __init__(self, report):
        self.report = report

    def solve(self, t, cj, history, ts, ys, y_pred):  # both components known in closed form
        return 0, np.array([math.sin(t), max(0.0, t - self.T_KINK)])

    def switched(self, y_new, ys):
        if not self.report:
            return None
        return np.array([False, any((y_new[1] > 0.0) != (y[1] > 0.0) for y in ys)])


def test_components_switched_over_a_step_are_left_out_of_its_error_test():
    fails = {}
    for report in (False, True):
        s = BDF2(KinkStep(report), np.array([0.0, 0.0]), 0.0, 1.0, rtol=1e-6, atol=1e-6)
        while s.t < 1.0:
            assert s.step() is None
        assert s.y[1] == pytest.approx(1.0 - KinkStep.T_KINK, rel=1e-12)
        fails[report] = s.n_error_test_failures
    assert fails[False] >= 10 and fails[True] <= fails[False] - 4, fails  # measured 14 and 8: the corner's rejections


class CircleStep(StepSolve):
    """x' = -y, y' = x (a circular orbit of radius 1) with an exact step solve."""

    error_components = None

    def solve(self, t, cj, history, ts, ys, y_pred):
        b = history(ys)
        M = np.array([[cj, 1.0], [-1.0, cj]])
        return 0, np.linalg.solve(M, -b)

    def counts(self):
        return 0, 0


def test_a_plane_vector_is_weighed_by_its_length():
    """On a circular orbit x and y pass through zero; weighed each by itself (atol tiny) the error test holds them to
    atol there and rejects steps, weighed as a pair by the radius (``error_pairs``) it does not: fewer steps and
    rejections at the same rtol, and a smaller error for about the same number of steps (the per-component test
    spends its steps at the axes, not where the error is)."""
    def run(rtol, pairs):
        s = BDF2(CircleStep(), np.array([1.0, 0.0]), 0.0, 4 * math.pi, rtol=rtol, atol=1e-12, error_pairs=pairs)
        while s.t < 4 * math.pi:
            assert s.step() is None
        return s.n_steps, s.n_error_test_failures, math.hypot(s.y[0] - 1.0, s.y[1])

    n_each, rejected_each, err_each = run(1e-4, None)
    n_pair, rejected_pair, _ = run(1e-4, [[0, 1]])
    assert n_pair < 0.8 * n_each and rejected_pair < rejected_each / 2
    n_fine, _, err_fine = run(1e-5, [[0, 1]])
    assert n_fine < 1.3 * n_each and err_fine < err_each / 1.5
