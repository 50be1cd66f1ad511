"""The integrator facade against stiff ODE / DAE references, RK4's order and event location."""

import numpy as np
import pytest
import scipy.sparse as sp

from transient import Problem, Steps, solve

ADAPTIVE = ["cvode", "ida", "bdf", "radau", "lsoda"]


def van_der_pol(mu=1000.0):
    """y1' = y2, y2' = mu (1 - y1^2) y2 - y1 with its analytic Jacobian (dense 2x2 in CSC order)."""

    def rhs(t, y, out):
        out[0] = y[1]
        out[1] = mu * (1.0 - y[0] ** 2) * y[1] - y[0]

    def jac(t, y, data):  # CSC order: (0,0) (1,0) (0,1) (1,1)
        data[0] = 0.0
        data[1] = -2.0 * mu * y[0] * y[1] - 1.0
        data[2] = 1.0
        data[3] = mu * (1.0 - y[0] ** 2)

    return Problem(y0=np.array([2.0, 0.0]), rhs=rhs, jac_pattern=sp.csc_matrix(np.ones((2, 2))),
                   jac_rhs=jac, name="van der Pol")


@pytest.fixture(scope="module")
def vdp_reference():
    """Independent reference: scipy Radau at rtol 1e-12 without the analytic Jacobian."""
    from scipy.integrate import solve_ivp
    mu = 1000.0
    f = lambda t, y: [y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]]
    t = np.linspace(0.0, 2000.0, 5)
    s = solve_ivp(f, (0, 2000.0), [2.0, 0.0], method="Radau", rtol=1e-12, atol=1e-12, t_eval=t)
    return t, s.y.T


@pytest.mark.parametrize("method", ADAPTIVE)
def test_stiff_van_der_pol_matches_reference(method, vdp_reference):
    t, ref = vdp_reference
    r = solve(van_der_pol(), t, method=method, rtol=1e-8, atol=1e-10)
    assert r.success, r.message
    assert r.y.shape == (t.size, 2)
    np.testing.assert_allclose(r.t, t)
    # y1 is O(1); the error of a rtol=1e-8 run on this stiff problem stays well below 1e-4
    assert np.max(np.abs(r.y[:, 0] - ref[:, 0])) < 1e-4
    assert r.stats.n_steps > 100 and r.stats.n_rhs >= r.stats.n_steps
    assert r.stats.n_jac > 0  # the analytic Jacobian was used
    assert 0.0 <= r.stats.callback_time <= r.stats.wall_time


def van_der_pol_dense(mu=1000.0):
    """The same system with its Jacobian as a dense (n, n) array (no pattern): the dense contract."""
    p = van_der_pol(mu)

    def jac(t, y, J):
        J[0, 0], J[0, 1] = 0.0, 1.0
        J[1, 0], J[1, 1] = -2.0 * mu * y[0] * y[1] - 1.0, mu * (1.0 - y[0] ** 2)

    return Problem(y0=p.y0, rhs=p.rhs, jac_rhs=jac, name="van der Pol, dense Jacobian")


@pytest.mark.parametrize("method", ADAPTIVE)
def test_dense_analytic_jacobian(method, vdp_reference):
    t, ref = vdp_reference
    r = solve(van_der_pol_dense(), t, method=method, rtol=1e-8, atol=1e-10)
    assert r.success, r.message
    assert np.max(np.abs(r.y[:, 0] - ref[:, 0])) < 1e-4
    assert r.stats.n_jac > 0  # the dense analytic Jacobian was called, not difference quotients


def test_tolerance_convergence_cvode(vdp_reference):
    t, ref = vdp_reference
    errs = []
    for rtol in (1e-5, 1e-7, 1e-9):
        r = solve(van_der_pol(), t, method="cvode", rtol=rtol, atol=rtol * 1e-2)
        errs.append(np.max(np.abs(r.y[:, 0] - ref[:, 0])))
    assert errs[0] > errs[1] > errs[2]
    assert errs[2] < 1e-5


def robertson(dae: bool):
    """Robertson kinetics; as a DAE the third equation is the conservation y1 + y2 + y3 = 1."""

    def rhs(t, y, out):
        out[0] = -0.04 * y[0] + 1e4 * y[1] * y[2]
        out[1] = 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2
        out[2] = 3e7 * y[1] ** 2

    def residual(t, y, yp, res):
        res[0] = yp[0] + 0.04 * y[0] - 1e4 * y[1] * y[2]
        res[1] = yp[1] - 0.04 * y[0] + 1e4 * y[1] * y[2] + 3e7 * y[1] ** 2
        res[2] = y[0] + y[1] + y[2] - 1.0

    def jac_res(t, y, yp, cj, data):  # full 3x3, CSC order
        data[0] = 0.04 + cj
        data[1] = -0.04
        data[2] = 1.0
        data[3] = -1e4 * y[2]
        data[4] = cj + 1e4 * y[2] + 6e7 * y[1]
        data[5] = 1.0
        data[6] = -1e4 * y[1]
        data[7] = 1e4 * y[1]
        data[8] = 1.0

    y0 = np.array([1.0, 0.0, 0.0])
    if dae:
        return Problem(y0=y0, residual=residual, jac_pattern=sp.csc_matrix(np.ones((3, 3))), jac_residual=jac_res,
                       algebraic=[2], name="Robertson DAE")
    return Problem(y0=y0, rhs=rhs, name="Robertson ODE")


def test_robertson_dae_ida_matches_tight_ode_reference():
    t = np.concatenate([[0.0], 4.0 * np.logspace(-5, 5, 11)])
    ref = solve(robertson(False), t, method="radau", rtol=1e-12, atol=1e-16)
    r = solve(robertson(True), t, method="ida", rtol=1e-8, atol=np.array([1e-10, 1e-16, 1e-10]))
    assert r.success and ref.success
    np.testing.assert_allclose(r.y[:, 0], ref.y[:, 0], rtol=2e-6, atol=1e-12)
    np.testing.assert_allclose(r.y[:, 1], ref.y[:, 1], rtol=2e-5, atol=1e-14)
    assert np.max(np.abs(r.y.sum(axis=1) - 1.0)) < 1e-9  # the algebraic constraint holds (measured 2.4e-11)
    assert r.yp is not None and r.yp.shape == r.y.shape


def oscillator():
    """x'' = -x, x(0)=1: exact x = cos t."""

    def rhs(t, y, out):
        out[0] = y[1]
        out[1] = -y[0]

    return Problem(y0=np.array([1.0, 0.0]), rhs=rhs, name="oscillator")


def test_rk4_is_fourth_order():
    t = np.array([0.0, 10.0])
    errs = []
    for dt in (0.04, 0.02, 0.01):
        r = solve(oscillator(), t, method="rk4", steps=Steps(dt=dt))
        errs.append(abs(r.y[-1, 0] - np.cos(10.0)))
        assert r.stats.n_steps == round(10.0 / dt)
        assert r.stats.n_rhs == 4 * r.stats.n_steps
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(np.abs(orders - 4.0) < 0.1), orders


def test_rk4_outputs_between_steps_are_rk4_values():
    t = np.array([0.0, 0.33, 1.0])  # 0.33 is not a multiple of dt
    r = solve(oscillator(), t, method="rk4", steps=Steps(dt=0.01))
    np.testing.assert_allclose(r.y[:, 0], np.cos(t), atol=1e-9)


def test_rk4_final_output_survives_rounding_of_the_step_count():
    """2 pi / 3000 * 3000 lands one rounding step below 2 pi: the last output must still be produced,
    and outputs on step ends must not cost partial steps."""
    tau = 2 * np.pi * np.linspace(0.0, 1.0, 21)
    r = solve(oscillator(), tau, method="rk4", steps=Steps(dt=2 * np.pi / 3000))
    assert r.success and r.t.size == tau.size
    assert r.stats.n_steps == 3000 and r.stats.n_rhs == 4 * 3000
    np.testing.assert_allclose(r.y[:, 0], np.cos(tau), atol=1e-12)


def test_rk4_inner_algebraic_solve_per_stage():
    """Semi-explicit DAE x' = -z, 0 = z - x (so x = e^-t); z comes from the per-stage hook."""
    calls = []

    def rhs(t, y, out):
        out[0] = -y[1]
        out[1] = 0.0

    def algebraic_solve(t, y):
        calls.append(t)
        y = y.copy()
        y[1] = y[0]
        return y

    p = Problem(y0=np.array([1.0, 0.0]), rhs=rhs, algebraic=[1], algebraic_solve=algebraic_solve, name="dae")
    r = solve(p, np.array([0.0, 1.0]), method="rk4", steps=Steps(dt=0.01))
    assert abs(r.y[-1, 0] - np.exp(-1.0)) < 1e-9
    assert abs(r.y[-1, 1] - r.y[-1, 0]) < 1e-15
    assert len(calls) >= 4 * 100  # one inner solve per stage


def falling_ball(terminal=True, direction=-1):
    """y'' = -g from y = 1 m: height crosses zero at sqrt(2/g)."""

    def rhs(t, y, out):
        out[0] = y[1]
        out[1] = -9.81

    def events(t, y, out):
        out[0] = y[0]

    return Problem(y0=np.array([1.0, 0.0]), rhs=rhs, events=events, n_events=1, event_terminal=[terminal],
                   event_direction=[direction], name="falling ball")


@pytest.mark.parametrize("method", ADAPTIVE + ["rk4"])
def test_terminal_event_located(method):
    t_hit = np.sqrt(2.0 / 9.81)
    r = solve(falling_ball(), np.linspace(0.0, 1.0, 11), method=method, rtol=1e-10, atol=1e-12, steps=Steps(dt=0.01))
    assert r.success, r.message
    assert r.t_events.size == 1
    assert abs(r.t_events[0] - t_hit) < 1e-8
    assert r.t[-1] <= t_hit  # nothing output after a terminal event
    assert r.t.size == np.searchsorted(np.linspace(0.0, 1.0, 11), t_hit)


def test_event_direction_filter_and_non_terminal():
    # rising crossings only: the falling ball never triggers it
    r = solve(falling_ball(terminal=True, direction=+1), np.linspace(0.0, 1.0, 5), method="cvode", rtol=1e-8)
    assert r.t_events.size == 0 and r.t[-1] == 1.0
    # non-terminal: integration goes on past the crossing
    r = solve(falling_ball(terminal=False), np.linspace(0.0, 1.0, 5), method="bdf", rtol=1e-8)
    assert r.t_events.size == 1 and r.t[-1] == 1.0


def test_observer_streams_without_storing():
    seen = []
    r = solve(oscillator(), np.linspace(0, 1, 6), method="cvode", store=False,
              observer=lambda t, y: seen.append((t, y[0])))
    assert r.y is None and len(seen) == 6
    np.testing.assert_allclose([s[1] for s in seen], np.cos(np.linspace(0, 1, 6)), atol=1e-5)


def test_ida_accepts_an_ode_problem():
    r = solve(van_der_pol(mu=1.0), np.linspace(0, 5, 6), method="ida", rtol=1e-9, atol=1e-11)
    ref = solve(van_der_pol(mu=1.0), np.linspace(0, 5, 6), method="radau", rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(r.y, ref.y, atol=1e-6)


@pytest.mark.parametrize("kwargs, match", [
    (dict(method="euler"), "method must be one of"),
    (dict(method="rk4"), "dt > 0"),
    (dict(method="cvode", rtol=0.0), "rtol"),
])
def test_bad_arguments_raise_clear_errors(kwargs, match):
    with pytest.raises(ValueError, match=match):
        solve(oscillator(), np.array([0.0, 1.0]), **kwargs)


def test_dae_rejected_by_ode_methods():
    with pytest.raises(ValueError, match="use method='ida'"):
        solve(robertson(True), np.array([0.0, 1.0]), method="cvode")
    with pytest.raises(ValueError, match="DAE"):
        solve(robertson(True), np.array([0.0, 1.0]), method="bdf")


@pytest.mark.parametrize("method", ["cvode", "ida", "bdf"])
def test_max_steps_reported_not_raised(method):
    r = solve(van_der_pol(), np.array([0.0, 2000.0]), method=method, steps=Steps(max_steps=5))
    assert not r.success and "max_steps=5" in r.message
    with pytest.raises(ValueError, match="max_steps must be an integer >= 1"):
        solve(van_der_pol(), np.array([0.0, 2000.0]), method=method, steps=Steps(max_steps=0))


def test_t_eval_must_increase():
    with pytest.raises(ValueError, match="strictly increasing"):
        solve(oscillator(), np.array([0.0, 1.0, 0.5]))


@pytest.mark.parametrize("method", ["cvode", "ida", "bdf", "lsoda", "rk4"])
def test_time_budget_stops_a_long_run(method):
    """A run that would take far longer than its wall-clock budget stops after it, with the outputs so far."""
    import time as _time

    def rhs(t, y, out):
        _time.sleep(2e-4)  # make every step cost wall time
        out[0] = -y[0]

    kw = dict(steps=Steps(dt=1e-4) if method == "rk4" else Steps(max_step=1e-4))
    t0 = _time.perf_counter()
    r = solve(Problem(y0=np.ones(1), rhs=rhs), np.linspace(0.0, 100.0, 11), method=method, time_budget=0.2, **kw)
    wall = _time.perf_counter() - t0
    assert not r.success and "time budget of 0.2 s used up" in r.message
    assert wall < 5.0 and r.t.size < 11


def test_a_back_end_is_one_entry_in_the_table(monkeypatch):
    """A new integration method is one function and one entry in ``BACKENDS``: the facade validates, guards and
    reports it like the others (here forward Euler on y' = -y, first order: error ~ dt / 2 * t e^-t)."""
    from transient.solvers.integrate import BACKENDS, Backend

    def euler(problem, t_eval, out, guard, settings):
        rhs = guard.wrap(problem.rhs, "rhs", poison=False)
        y, f, t = problem.y0.copy(), np.empty(problem.n), t_eval[0]
        out.put(y)
        for t_next in t_eval[1:]:
            n = int(np.ceil((t_next - t) / settings.dt - 1e-9))
            h = (t_next - t) / n
            for _ in range(n):
                rhs(t, y, f)
                y, t = y + h * f, t + h
                guard.n_steps += 1
            out.put(y)
        return True, "reached the final time"

    def decay(t, y, out):
        out[:] = -y

    monkeypatch.setitem(BACKENDS, "euler", Backend(euler, fixed_step=True))
    t = np.linspace(0.0, 1.0, 3)
    r = solve(Problem(y0=np.ones(1), rhs=decay), t, method="euler", steps=Steps(dt=1e-3))
    assert r.success and r.method == "euler" and r.stats.n_steps == 1000 and r.stats.n_rhs == 1000
    assert r.stats.n_error_test_failures == 0
    err = np.abs(r.y[:, 0] - np.exp(-t))
    assert np.all(err[1:] > 0.2 * 0.5e-3 * t[1:] * np.exp(-t[1:])) and np.all(err <= 0.5e-3 * t * np.exp(-t) * 1.2)
    with pytest.raises(ValueError, match="dt > 0"):
        solve(Problem(y0=np.ones(1), rhs=decay), t, method="euler")
