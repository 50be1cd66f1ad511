"""The integrator facade never crashes, hangs or reports a false success (issue 17).

Reproductions of a hostile tester's reports, each failing on the facade before the guard (commit
02ba1ff) and passing after:

* an exception in a Jacobian/rhs/event callback under CVODE/IDA killed the interpreter (segfault,
  rc 139; abort, rc 134) -- run in a child process (tests/solvers/facade_crash_cases.py) so a crash fails
  the test instead of killing pytest;
* a NaN right-hand side stalled CVODE/IDA at h ~ 1e-17 for a million steps, LSODA returned
  success=True with NaN states, scipy's BDF raised from its LU;
* LSODA leaked ~16 kB per solve (scipy 1.17 keeps a reference to its work arrays per call);
* a NaN event function silently disabled the event (success=True for every method);
* argument errors did not name the value and the allowed range.
"""

import gc
import math
import os
import re
import subprocess
import sys
import tracemalloc

import numpy as np
import pytest
import scipy.sparse as sp

from transient import Problem, Steps, solve

ADAPTIVE = ["cvode", "ida", "bdf", "radau", "lsoda"]
ALL = ADAPTIVE + ["rk4"]
HERE = os.path.dirname(os.path.abspath(__file__))


# --------------------------------------------------------------------------------------------------
# 1. Exceptions inside callbacks (child process: the old facade crashed the interpreter)
# --------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def crash_cases():
    """One child process runs every crash-prone case (one package import); its lines by case name."""
    env = dict(os.environ)
    root = os.path.dirname(os.path.dirname(HERE))
    env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    proc = subprocess.run([sys.executable, os.path.join(HERE, "facade_crash_cases.py"), "exceptions", "observer",
                           "sigint"], capture_output=True, text=True, timeout=600, env=env)
    lines = {}
    for line in proc.stdout.splitlines():
        if line.startswith("CASE "):
            name, _, rest = line[5:].partition(" ")
            lines[name] = rest
    return proc, lines


def _check_child(proc):
    tail = "\n".join(proc.stdout.splitlines()[-3:])
    # rc 139 = segfault, 134 = abort (heap corruption): what the unguarded facade did
    assert proc.returncode == 0, f"child died with rc {proc.returncode}; last lines:\n{tail}\n{proc.stderr[-2000:]}"
    assert proc.stdout.rstrip().endswith("DONE")


@pytest.mark.parametrize("method", ["cvode", "ida"])
def test_callback_exceptions_come_back_unchanged_from_sundials(crash_cases, method):
    """rhs, Jacobian (sparse and dense) and event functions raising on their 1st, 2nd or 5th call,
    ValueError-like or KeyboardInterrupt: solve raises that very exception, whose traceback holds the
    callback's frame and whose note says where it was raised; nothing crashes."""
    proc, lines = crash_cases
    _check_child(proc)
    n = 0
    for sparse in ("sparse", "dense"):
        for where in ("rhs", "jac", "events"):
            for when in (1, 2, 5):
                for exc in ("Boom", "KeyboardInterrupt"):
                    name = f"{method}-{sparse}-{where}-{when}-{exc}"
                    assert lines.get(name) == f"raised {exc} boom in {where} #{when} tb=1 note=1", (name, lines.get(name))
                    n += 1
    if method == "ida":  # the DAE: call 1 happens inside IDA's initial-condition computation
        for where in ("residual", "jac"):
            for when in (1, 3):
                name = f"ida-dae-{where}-{when}-Boom"
                assert lines.get(name) == f"raised Boom boom in {where} #{when} tb=1 note=1", (name, lines.get(name))
                n += 1
    assert n >= 36


def test_observer_failing_before_the_first_step_does_not_crash(crash_cases):
    """A sparse SUNDIALS solver freed before its first step used to crash (SuperLU_MT frees memory
    it only allocates at its first setup)."""
    proc, lines = crash_cases
    _check_child(proc)
    for method in ("cvode", "ida"):
        for lin in ("sparse", "dense"):
            assert lines[f"observer-{method}-{lin}"] == "raised Boom observer says no tb=1 note=0"


@pytest.mark.parametrize("method", ["cvode", "ida", "bdf", "lsoda", "rk4"])
def test_ctrl_c_is_deferred_to_a_safe_point_and_raised(crash_cases, method):
    """A real SIGINT delivered inside the rhs: the rhs completes, solve raises KeyboardInterrupt
    (with the facade's note), and Python's own SIGINT handler is back afterwards."""
    proc, lines = crash_cases
    _check_child(proc)
    for when in (1, 3):
        assert lines[f"sigint-{method}-{when}"].startswith("raised KeyboardInterrupt"), lines[f"sigint-{method}-{when}"]
        assert lines[f"sigint-{method}-{when}"].endswith("note=1")
        assert lines[f"sigint-{method}-{when}-after"] == "completed=1 handler_restored=1"


class Boom(Exception):
    pass


def decay_problem(where, when, exc, n=3, rate=1.0):
    """y' = -rate y with a sparse Jacobian and an event; ``where`` raises ``exc`` on its ``when``-th call."""
    calls = {"rhs": 0, "jac": 0, "events": 0}

    def rhs(t, y, out):
        calls["rhs"] += 1
        if where == "rhs" and calls["rhs"] >= when:
            raise exc
        out[:] = -rate * y

    def jac(t, y, data):
        calls["jac"] += 1
        if where == "jac" and calls["jac"] >= when:
            raise exc
        data[:] = -rate

    def events(t, y, g):
        calls["events"] += 1
        if where == "events" and calls["events"] >= when:
            raise exc
        g[0] = y[0] + 1.0

    return Problem(y0=np.ones(n), rhs=rhs, jac_pattern=sp.identity(n, format="csc"), jac_rhs=jac,
                   events=events, n_events=1, name="decay")


@pytest.mark.parametrize("method", ["bdf", "radau", "lsoda", "rk4"])
@pytest.mark.parametrize("where", ["rhs", "jac", "events"])
@pytest.mark.parametrize("exc_type", [Boom, KeyboardInterrupt])
def test_callback_exceptions_propagate_from_scipy_and_rk4(method, where, exc_type):
    if method == "rk4" and where == "jac":
        pytest.skip("rk4 uses no Jacobian")
    exc = exc_type("raised by the model")
    # scipy evaluates a linear problem's Jacobian once or twice, and LSODA only once it has switched to
    # its stiff method: a stiff rate and the first call
    when, rate = (1, 1000.0) if where == "jac" else (3, 1.0)
    with pytest.raises(exc_type) as info:
        solve(decay_problem(where, when, exc, rate=rate), np.linspace(0.0, 5.0, 6), method=method,
              steps=Steps(dt=0.01))
    assert info.value is exc  # the very object, not a wrapper
    assert any(f.name in ("rhs", "jac", "events") for f in info.traceback)  # raised where it was raised
    assert any("at t=" in note and "[transient.solve]" in note for note in exc.__notes__)


# --------------------------------------------------------------------------------------------------
# 2. Non-finite values and stalls stop at once, for every method
# --------------------------------------------------------------------------------------------------

def nan_at_half(value):
    """y0' = -y0, y1' = y0 - y1, y2' = 0; from t = 0.5 on the rhs puts ``value`` in component 1."""

    def rhs(t, y, out):
        out[0] = -y[0]
        out[1] = y[0] - y[1]
        out[2] = 0.0
        if t >= 0.5:
            out[1] = value

    return Problem(y0=np.array([1.0, 0.0, 1.0]), rhs=rhs, name="nan-at-half")


@pytest.mark.parametrize("method", ALL)
@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_nonfinite_rhs_stops_at_once_with_time_method_and_component(method, value, capsys):
    """Before: CVODE/IDA stalled at h ~ 1e-17 for a million steps (105-163 s; here capped by
    max_steps=5000, which the old facade reached), LSODA returned success=True with NaN states, BDF
    raised from scipy's LU. Measured after: 11-50 steps, milliseconds."""
    r = solve(nan_at_half(value), np.linspace(0.0, 1.0, 11), method=method, steps=Steps(dt=0.01, max_steps=5000))
    assert not r.success
    m = re.search(r"non-finite value at t=([0-9.e+-]+): f\[1\] = (nan|inf)", r.message)
    assert m, r.message
    assert 0.5 <= float(m.group(1)) < 0.6
    assert r.message.startswith(f"{method}:") and "nan-at-half" in r.message
    assert r.stats.n_steps < 200  # 11-50 measured; the stall took ~10^6
    assert r.t[-1] <= 0.5 and np.isfinite(r.y).all()
    assert capsys.readouterr().out == ""  # no stray SUNDIALS error print for the step that was stopped


def test_nonfinite_residual_of_a_dae_names_the_residual():
    def residual(t, y, yp, res):
        res[0] = yp[0] + y[0]
        res[1] = y[1] - 2.0 * y[0] if t < 0.5 else np.nan

    p = Problem(y0=np.array([1.0, 2.0]), residual=residual, yp0=np.array([-1.0, 0.0]), algebraic=[1], name="dae")
    r = solve(p, np.linspace(0.0, 1.0, 5), method="ida", steps=Steps(max_steps=5000))
    assert not r.success and r.stats.n_steps < 200
    assert re.search(r"^ida: the residual .* at t=0\.5[0-9]*: F\[1\] = nan", r.message), r.message


@pytest.mark.parametrize("method", ADAPTIVE)
@pytest.mark.parametrize("dense", [False, True])
def test_nonfinite_jacobian_is_reported(method, dense):
    """A Jacobian with a NaN entry (its first call already; stiff, so LSODA calls it too): the run
    stops and names the entry."""
    def rhs(t, y, out):
        out[:] = [-y[0], -1000.0 * y[1]]

    def jac_sparse(t, y, d):
        d[:] = [-1.0, np.nan]

    def jac_dense(t, y, J):
        J[:] = [[-1.0, 0.0], [0.0, np.nan]]

    kw = dict(jac_rhs=jac_dense) if dense else dict(jac_rhs=jac_sparse, jac_pattern=sp.identity(2, format="csc"))
    r = solve(Problem(y0=np.ones(2), rhs=rhs, name="jac-nan", **kw), np.array([0.0, 1.0]), method=method)
    assert not r.success
    assert "the Jacobian of problem 'jac-nan' returned a non-finite value" in r.message
    assert ("J[1, 1] = nan" if dense else "J[1] = nan") in r.message, r.message


@pytest.mark.parametrize("method", ALL)
def test_nonfinite_event_function_is_reported(method):
    """Before: every method returned success=True and the event never fired."""
    def rhs(t, y, out):
        out[0] = -y[0]

    def events(t, y, g):
        g[0] = 1.0 if t < 0.5 else np.nan

    p = Problem(y0=np.ones(1), rhs=rhs, events=events, n_events=1, name="ev")
    r = solve(p, np.linspace(0.0, 3.0, 4), method=method, steps=Steps(dt=0.01))
    assert not r.success
    assert re.search(r"the event functions of problem 'ev' returned a non-finite value at t=0\.5[0-9]*: g\[0\] = nan",
                     r.message), r.message


@pytest.mark.parametrize("method", ALL)
def test_finite_time_blowup_stops_quickly(method):
    """y' = y^2, y(0) = 1 blows up at t = 1 with finite values all the way (y ~ 1e16 when t is one
    ulp from 1): the step collapses to the roundoff of t. Before: IDA and LSODA ran into max_steps
    (200 000 steps, 49 s for IDA). After: the stall detector or the backend stops within ~1100 steps."""
    def rhs(t, y, out):
        out[0] = y[0] * y[0]

    with np.errstate(over="ignore"):
        r = solve(Problem(y0=np.ones(1), rhs=rhs, name="blowup"), np.linspace(0.0, 2.0, 5), method=method,
                  steps=Steps(dt=1e-3, max_steps=20000))
    assert not r.success
    assert r.stats.n_steps < 3000, (r.stats.n_steps, r.message)
    assert np.isfinite(r.y).all() and r.t[-1] <= 1.0
    assert re.search(r"t=(0\.99|1\.00)", r.message), r.message


@pytest.mark.parametrize("method", ALL)
def test_success_is_never_reported_with_nonfinite_states(method):
    """Exponential growth from 1e300 overflows near t = 19: whatever the method, either a failure
    or finite states -- never success=True with inf in the solution."""
    def rhs(t, y, out):
        out[0] = y[0]

    with np.errstate(over="ignore", invalid="ignore"):
        r = solve(Problem(y0=np.array([1e300]), rhs=rhs, name="growth"), np.array([0.0, 10.0, 30.0]), method=method,
                  steps=Steps(dt=0.01, max_steps=20000))
    assert np.isfinite(r.y).all()
    assert not r.success and r.t[-1] == 10.0, r.message


def test_probe_finds_every_nonfinite_entry():
    """The hot-path check (sum of x * 0 in numba, fastmath 'reassoc' only): NaN, inf, -inf found at
    any position and size; huge finite values, -0.0 and subnormals pass (no overflow false alarm)."""
    from transient.solvers.integrate import _nonfinite_probe

    for n in (1, 2, 7, 64, 1000, 4099):
        ok = np.linspace(-1.0, 1.0, n) * 1.7e308
        ok[0] = -0.0
        ok[-1] = 5e-324
        assert _nonfinite_probe(ok) == 0.0
        for bad in (np.nan, np.inf, -np.inf):
            for pos in {0, n // 2, n - 1}:
                a = ok.copy()
                a[pos] = bad
                assert math.isnan(_nonfinite_probe(a)), (n, bad, pos)


# --------------------------------------------------------------------------------------------------
# 3. Memory of failing solves
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("method", ALL)
def test_failing_solves_do_not_leak(method):
    """100 failing solves (alternately a raising and a NaN rhs) of a 40-state problem with its dense
    analytic Jacobian. Measured with
    tracemalloc over 1,000 such solves: LSODA grew 16.3 kB per solve before (scipy 1.17 keeps a
    reference to its 8 (22 + 9n + n^2) + 4 (20 + n) byte work arrays per call, n = 40), every
    method < 0.1 kB after. The bound, 2 kB per solve, is 8x below that leak and well above the
    noise (caches that fill once, spread over the 100 solves)."""
    n, k = 40, 100

    def make(mode):
        def rhs(t, y, out):
            out[:] = -y
            if t >= 0.05:
                if mode == "raise":
                    raise Boom("fails")
                out[3] = np.nan

        def jac(t, y, J):
            J[:] = -np.eye(n)

        return Problem(y0=np.ones(n), rhs=rhs, jac_rhs=jac, name="failing")

    problems = [make("raise"), make("nan")]

    def one(i):
        try:
            r = solve(problems[i % 2], np.array([0.0, 1.0]), method=method, steps=Steps(dt=0.01, max_steps=2000))
            assert not r.success
        except Boom:
            pass

    for i in range(10):  # caches, lazily built tables, the LSODA work-array pool
        one(i)
    tracemalloc.start()
    try:  # scipy's BDF/Radau objects are cyclic garbage (closures over self): collect at both ends
        gc.collect()
        before = tracemalloc.get_traced_memory()[0]
        for i in range(k):
            one(i)
        gc.collect()
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert grown / k < 2048, f"{method}: {grown / k:.0f} bytes per failing solve"


def test_lsoda_pooled_work_arrays_do_not_mix_nested_solves():
    """An observer that runs another LSODA solve of the same size while the outer one is running:
    each gets its own work arrays, both results are right."""
    def oscillator():
        def rhs(t, y, out):
            out[0], out[1] = y[1], -y[0]
        return Problem(y0=np.array([1.0, 0.0]), rhs=rhs, name="osc")

    inner = []

    def observer(t, y):
        inner.append(solve(oscillator(), np.array([0.0, t + 0.5]), method="lsoda", rtol=1e-10, atol=1e-12).y[-1, 0])

    t = np.linspace(0.0, 3.0, 7)
    for _ in range(2):
        inner.clear()
        r = solve(oscillator(), t, method="lsoda", rtol=1e-10, atol=1e-12, observer=observer)
        np.testing.assert_allclose(r.y[:, 0], np.cos(t), atol=1e-7)
        np.testing.assert_allclose(inner, np.cos(t + 0.5), atol=1e-7)


# --------------------------------------------------------------------------------------------------
# 4. Argument validation: one line naming the parameter, the value and the allowed range
# --------------------------------------------------------------------------------------------------

def oscillator2():
    def rhs(t, y, out):
        out[0], out[1] = y[1], -y[0]
    return Problem(y0=np.array([1.0, 0.0]), rhs=rhs, name="osc")


@pytest.mark.parametrize("kwargs, fragments", [
    (dict(rtol=0.0), ["rtol", "got 0.0", "(0, 1)"]),
    (dict(rtol=float("nan")), ["rtol", "got nan", "(0, 1)"]),
    (dict(rtol=2.0), ["rtol", "got 2.0", "(0, 1)"]),
    (dict(rtol="1e-6"), ["rtol", "got '1e-6'", "(0, 1)"]),
    (dict(atol=-1.0), ["atol", "got -1.0", "(0, inf)"]),
    (dict(atol=np.inf), ["atol", "got inf", "(0, inf)"]),
    (dict(atol=[1e-8, 1e-8, 1e-8]), ["atol", "length n=2", "shape (3,)"]),
    (dict(atol=[1e-8, np.nan]), ["atol[1]", "got nan", "> 0"]),
    (dict(atol=[1e-8, 0.0]), ["atol[1]", "got 0.0", "> 0"]),
    (dict(t_eval=[0.0]), ["t_eval", "shape (1,)", "at least 2"]),
    (dict(t_eval=[0.0, np.nan]), ["t_eval[1]", "nan", "finite"]),
    (dict(t_eval=[0.0, 1.0, 0.5]), ["t_eval[2] = 0.5", "t_eval[1] = 1.0", "strictly increasing"]),
    (dict(max_steps=0), ["max_steps", "got 0", ">= 1"]),
    (dict(max_steps=2.5), ["max_steps", "got 2.5", "integer"]),
    (dict(max_steps=True), ["max_steps", "got True", "integer"]),
    (dict(method="rk4", dt=-1.0), ["dt", "got -1.0", "(0, inf)"]),
    (dict(method="rk4", dt=np.inf), ["dt", "got inf", "(0, inf)"]),
    (dict(method="rk4"), ["dt", "dt=None", "> 0"]),
    (dict(method="euler"), ["method", "'euler'", "'cvode'", "'rk4'"]),
    (dict(linear_solver="klu"), ["linear_solver", "'klu'", "'sparse'", "'dense'"]),
    (dict(max_step=-1.0), ["max_step", "got -1.0", ">= 0"]),
    (dict(first_step=np.nan), ["first_step", "got nan", ">= 0"]),
])
def test_bad_arguments_are_named_with_value_and_range(kwargs, fragments):
    kwargs = dict(kwargs)
    t_eval = kwargs.pop("t_eval", [0.0, 1.0])
    steps = {k: kwargs.pop(k) for k in ("dt", "max_step", "first_step", "max_steps") if k in kwargs}
    with pytest.raises(ValueError) as info:
        solve(oscillator2(), t_eval, **kwargs, **({"steps": Steps(**steps)} if steps else {}))
    msg = str(info.value)
    assert "\n" not in msg
    for frag in fragments:
        assert frag in msg, (frag, msg)


def test_scalar_or_nonfinite_initial_state_is_a_clear_error():
    with pytest.raises(ValueError, match=r"y0 must be a non-empty 1-D array .* got 0-D \(\): 1\.0"):
        Problem(y0=1.0, rhs=lambda t, y, out: None, name="scalar")
    with pytest.raises(ValueError, match=r"problem 'bad': y0 must be finite, got y0\[1\] = nan"):
        solve(Problem(y0=np.array([1.0, np.nan]), rhs=lambda t, y, out: None, name="bad"), [0.0, 1.0])


def test_a_vanishing_atol_is_refused_before_ida_overflows():
    """atol = 1e-300 made IDA's error weights overflow and segfault the process (fuzzing, issue 17)."""
    def rhs(t, y, out):
        out[:] = -y

    p = Problem(y0=np.zeros(2), rhs=rhs)
    with pytest.raises(ValueError, match="atol"):
        solve(p, [0.0, 1.0], method="ida", atol=1e-300)
