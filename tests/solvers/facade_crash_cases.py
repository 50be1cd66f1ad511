"""Crash-prone cases of the integrator facade, run in a child process by test_integrate_reliability.py.

Before the facade guarded its callbacks, these killed the interpreter (segfault, rc 139, or heap
corruption abort, rc 134) or lost the exception, so they must not run inside pytest itself.

Usage: ``python tests/solvers/facade_crash_cases.py GROUP [GROUP ...]`` (groups: exceptions, observer, sigint;
one process for all of them pays the package import once). Each case prints one line
``CASE <name> <outcome>`` (flushed at once, so a crash shows which case died) where outcome is
``raised <Type> <message> tb=<0|1> note=<0|1>`` (tb: the callback's own frame is in the traceback;
note: the facade's note names where it was raised) or ``returned success=<bool> <message>``.
The solver objects are freed by reference counting before the line is printed (the facade leaves no
reference cycle behind) and again by a full gc.collect() after each group.
"""

import gc
import os
import signal
import sys
import traceback

import numpy as np
import scipy.sparse as sp

from transient import Problem, Steps, solve


class Boom(Exception):
    pass


def van_der_pol(where, when, exc_type, sparse=True, mu=1000.0):
    """Van der Pol with a callback (rhs, jac or events) that raises on its ``when``-th call."""
    calls = {"rhs": 0, "jac": 0, "events": 0}

    def fail(kind):
        calls[kind] += 1
        if kind == where and calls[kind] >= when:
            raise exc_type(f"boom in {kind} #{calls[kind]}")

    def rhs(t, y, out):
        fail("rhs")
        out[0] = y[1]
        out[1] = mu * (1.0 - y[0] ** 2) * y[1] - y[0]

    def jac_sparse(t, y, data):
        fail("jac")
        data[0], data[1] = 0.0, -2.0 * mu * y[0] * y[1] - 1.0
        data[2], data[3] = 1.0, mu * (1.0 - y[0] ** 2)

    def jac_dense(t, y, J):
        fail("jac")
        J[0, 0], J[0, 1] = 0.0, 1.0
        J[1, 0], J[1, 1] = -2.0 * mu * y[0] * y[1] - 1.0, mu * (1.0 - y[0] ** 2)

    def events(t, y, g):
        fail("events")
        g[0] = y[0] + 10.0  # never crosses

    kw = dict(jac_pattern=sp.csc_matrix(np.ones((2, 2))), jac_rhs=jac_sparse) if sparse else dict(jac_rhs=jac_dense)
    return Problem(y0=np.array([2.0, 0.0]), rhs=rhs, events=events, n_events=1, name="vdp", **kw)


def robertson_dae(where, when, exc_type):
    """Robertson as a DAE with a residual or residual Jacobian that raises on its ``when``-th call; IDA
    computes consistent initial conditions first (calc_initcond), so call 1 is inside init_step."""
    calls = {"residual": 0, "jac": 0}

    def fail(kind):
        calls[kind] += 1
        if kind == where and calls[kind] >= when:
            raise exc_type(f"boom in {kind} #{calls[kind]}")

    def residual(t, y, yp, res):
        fail("residual")
        res[0] = yp[0] + 0.04 * y[0] - 1e4 * y[1] * y[2]
        res[1] = yp[1] - 0.04 * y[0] + 1e4 * y[1] * y[2] + 3e7 * y[1] ** 2
        res[2] = y[0] + y[1] + y[2] - 1.0

    def jac(t, y, yp, cj, d):
        fail("jac")
        d[:] = [0.04 + cj, -0.04, 1.0, -1e4 * y[2], cj + 1e4 * y[2] + 6e7 * y[1], 1.0, -1e4 * y[1], 1e4 * y[1], 1.0]

    return Problem(y0=np.array([1.0, 0.0, 0.0]), residual=residual, jac_pattern=sp.csc_matrix(np.ones((3, 3))),
                   jac_residual=jac, algebraic=[2], name="robertson")


def run(name, fn):
    try:
        r = fn()
        line = f"returned success={r.success} {r.message}"
    except BaseException as e:  # noqa: BLE001 -- the point is to see what comes out
        frames = [f.name for f in traceback.extract_tb(e.__traceback__)]
        own = int(any(n in ("fail", "observer", "rhs") for n in frames))
        note = int(any("[transient.solve]" in n for n in getattr(e, "__notes__", [])))
        line = f"raised {type(e).__name__} {e} tb={own} note={note}"
        del e  # the last reference: the solver is freed here (no cycle), where the old crashes happened
    print(f"CASE {name} {line}", flush=True)


def group_exceptions():
    t = np.linspace(0.0, 2000.0, 5)
    for method in ("cvode", "ida"):
        for sparse in (True, False):
            for where in ("rhs", "jac", "events"):
                for when in (1, 2, 5):
                    for exc in (Boom, KeyboardInterrupt):
                        name = f"{method}-{'sparse' if sparse else 'dense'}-{where}-{when}-{exc.__name__}"
                        run(name, lambda: solve(van_der_pol(where, when, exc, sparse), t, method=method))
    tr = np.array([0.0, 0.4, 4.0])
    for where in ("residual", "jac"):
        for when in (1, 3):
            run(f"ida-dae-{where}-{when}-Boom", lambda: solve(robertson_dae(where, when, Boom), tr, method="ida"))


def group_observer():
    """The observer raising at the first output: the solver is freed before it ever stepped."""
    t = np.linspace(0.0, 1.0, 3)
    for method in ("cvode", "ida"):
        for sparse in (True, False):
            def observer(tt, y):
                raise Boom("observer says no")
            run(f"observer-{method}-{'sparse' if sparse else 'dense'}",
                lambda: solve(van_der_pol("none", 1, Boom, sparse), t, method=method, observer=observer))


def group_sigint():
    """A real Ctrl-C (SIGINT to this process) delivered inside the rhs: it is deferred to the next
    callback/step boundary, the interrupted callback completes, and solve raises KeyboardInterrupt."""
    # Ctrl-C live as in a terminal, also when this process was started in the background of a shell without job
    # control (it then inherits SIGINT ignored, and Python keeps it ignored)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    t = np.linspace(0.0, 2000.0, 5)
    for method in ("cvode", "ida", "bdf", "lsoda", "rk4"):
        for when in (1, 3):
            state = {"calls": 0, "completed_after_signal": 0}
            mu = 1000.0

            def rhs(t_, y, out):
                state["calls"] += 1
                if state["calls"] == when:
                    os.kill(os.getpid(), signal.SIGINT)
                    for _ in range(1000):  # Python bytecode after the signal: where it would have hit
                        pass
                    state["completed_after_signal"] = 1
                out[0] = y[1]
                out[1] = mu * (1.0 - y[0] ** 2) * y[1] - y[0]

            p = Problem(y0=np.array([2.0, 0.0]), rhs=rhs, jac_pattern=sp.csc_matrix(np.ones((2, 2))), name="vdp")
            run(f"sigint-{method}-{when}", lambda: solve(p, t, method=method, steps=Steps(dt=1.0)))
            restored = signal.getsignal(signal.SIGINT) is signal.default_int_handler
            print(f"CASE sigint-{method}-{when}-after completed={state['completed_after_signal']} "
                  f"handler_restored={int(restored)}", flush=True)


if __name__ == "__main__":
    import time
    for group in sys.argv[1:]:
        t0 = time.perf_counter()
        {"exceptions": group_exceptions, "observer": group_observer, "sigint": group_sigint}[group]()
        gc.collect()
        print(f"GROUP {group} done in {time.perf_counter() - t0:.2f} s", flush=True)
    print("DONE", flush=True)
