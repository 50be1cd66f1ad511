"""Per-call overhead of the integrator callbacks (``transient bench reynolds-operator`` part 2).

A linear test system y' = -lambda * y (n states, diagonal Jacobian) is integrated by CVODE three ways:
scikit-sundae called directly with a numba right-hand side, the same through :func:`transient.solve`
(which adds call counting, timing and its one-step output loop), and with a pure-Python right-hand
side. Dividing the wall time by the number of right-hand-side calls gives the cost of one call;
the numba kernel's own cost is timed separately so the difference is the callback overhead.
"""

from __future__ import annotations

import time

import numpy as np
import scipy.sparse as sp
from numba import njit

from transient.solvers.integrate import Problem, solve


@njit(cache=True)
def _decay_rhs(y, lam, out):
    for i in range(y.size):
        out[i] = -lam[i] * y[i]


def _problem(n):
    lam = np.logspace(0, 3, n)  # stiff-ish spread of rates

    def rhs(t, y, out):
        _decay_rhs(y, lam, out)

    def jac(t, y, data):
        data[:] = -lam

    return Problem(y0=np.ones(n), rhs=rhs, jac_pattern=sp.identity(n, format="csc"), jac_rhs=jac,
                   name="decay"), lam


def _raw_sundials(n, t_end, rtol):
    from sksundae.cvode import CVODE
    p, lam = _problem(n)
    calls = [0]

    def rhs(t, y, yp):
        calls[0] += 1
        _decay_rhs(y, lam, yp)

    def jac(t, y, yp, data):
        data[:] = -lam

    s = CVODE(rhs, method="BDF", rtol=rtol, atol=1e-10, linsolver="sparse", sparsity=p.jac_pattern,
              jacfn=jac, max_num_steps=100000)
    t0 = time.perf_counter()
    r = s.solve(np.array([0.0, t_end / 2, t_end]), p.y0)
    return time.perf_counter() - t0, calls[0], r


def run(n=1000, t_end=20.0, rtol=1e-8, repeats=3) -> list[dict]:
    """Rows: how each variant spends its time per right-hand-side call [us]."""
    import warnings
    warnings.simplefilter("ignore", UserWarning)
    p, lam = _problem(n)
    out = np.empty(n)
    _decay_rhs(p.y0, lam, out)  # JIT warm-up
    k = 20000
    t0 = time.perf_counter()
    for _ in range(k):
        _decay_rhs(p.y0, lam, out)
    kernel_us = (time.perf_counter() - t0) / k * 1e6
    rows = [{"variant": f"numba kernel alone (n={n})", "us_per_call": kernel_us, "calls": k, "steps": None}]

    best = min((_raw_sundials(n, t_end, rtol) for _ in range(repeats)), key=lambda x: x[0])
    rows.append({"variant": "CVODE via scikit-sundae directly, numba rhs", "us_per_call": best[0] / best[1] * 1e6,
                 "calls": best[1], "steps": None, "wall_s": best[0]})

    te = np.array([0.0, t_end / 2, t_end])
    r = min((solve(p, te, method="cvode", rtol=rtol, atol=1e-10) for _ in range(repeats)),
            key=lambda r: r.stats.wall_time)
    rows.append({"variant": "CVODE via transient.solve, numba rhs", "us_per_call": r.stats.wall_time / r.stats.n_rhs * 1e6,
                 "calls": r.stats.n_rhs, "steps": r.stats.n_steps, "wall_s": r.stats.wall_time,
                 "callback_share": r.stats.callback_share})

    def py_rhs(t, y, o):
        o[:] = -lam * y

    pp = Problem(y0=np.ones(n), rhs=py_rhs, jac_pattern=p.jac_pattern, jac_rhs=p.jac_rhs, name="decay-numpy")
    r = min((solve(pp, te, method="cvode", rtol=rtol, atol=1e-10) for _ in range(repeats)),
            key=lambda r: r.stats.wall_time)
    rows.append({"variant": "CVODE via transient.solve, numpy rhs", "us_per_call": r.stats.wall_time / r.stats.n_rhs * 1e6,
                 "calls": r.stats.n_rhs, "steps": r.stats.n_steps, "wall_s": r.stats.wall_time,
                 "callback_share": r.stats.callback_share})
    return rows


def markdown(rows) -> str:
    lines = ["| variant | us per rhs call | rhs calls | steps | share in callbacks |", "|---|---:|---:|---:|---:|"]
    for r in rows:
        share = f"{r['callback_share']:.0%}" if "callback_share" in r else ""
        lines.append(f"| {r['variant']} | {r['us_per_call']:.2f} | {r['calls']} | {r['steps'] or ''} | {share} |")
    return "\n".join(lines)
