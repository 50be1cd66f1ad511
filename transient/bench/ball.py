"""Work-precision of the ball-pass sequence (seed 002): CVODE vs scipy BDF / LSODA vs RK4, one run.

``run(out_dir="docs")`` integrates the same 200-ball-pass sequence (reference conditions of the paper:
30 N, 80 rpm, 6 balls, h_inf = 100 um; thin-film reflow on 100 cells) with every method through the
:mod:`transient.solvers.integrate` facade, against a CVODE reference at rtol = 1e-10, and writes
``bench_ball.md`` (table, ratios) and ``bench_ball.png`` (error vs wall time, log-log).
Error = max over the passes of |h_in - h_in,ref| / h_inf.

RK4 (explicit, fixed step) is stability-bound: the levelling operator's largest eigenvalue is
~ 16 max(h)^3 / dx^4 (scaled), so it is timed over a short slice of one pass and its cost for the
whole sequence is extrapolated (reported as such, no accuracy point).
"""

from __future__ import annotations

import os
import time

import numpy as np

from transient.solvers.integrate import solve
from transient.models.ball.bearing import ThrustBallBearing

CASE = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6)


def _seq(method, rtol, n_passes, n_cells, **kw):
    brg = ThrustBallBearing()
    t0 = time.perf_counter()
    s = brg.sequence(**CASE, n_passes=n_passes, n_cells=n_cells, method=method, rtol=rtol,
                     atol=rtol * 1e-4, stop_at_periodic=False, **kw)
    return s, time.perf_counter() - t0


def run(out_dir: str = "docs", n_passes: int = 200, n_cells: int = 100, quick: bool = False) -> dict:
    """Run the comparison, write ``bench_ball.png`` into ``out_dir``; return the rows and the markdown table
    (``transient bench ball`` writes it to docs/bench/ball.md)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(out_dir, exist_ok=True)
    ThrustBallBearing().sequence(**CASE, n_passes=2, n_cells=n_cells)  # JIT warm-up
    ref, t_ref = _seq("cvode", 1e-10, n_passes, n_cells)
    h_ref = ref.h_inlet
    plan = [("cvode", r, {}) for r in ((1e-3, 1e-5, 1e-7) if quick else (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8))]
    plan += [("cvode", r, {"linear_solver": "band"}) for r in ((1e-4, 1e-6) if quick else (1e-4, 1e-6, 1e-8))]
    plan += [("bdf", r, {}) for r in ((1e-3,) if quick else (1e-3, 1e-5))]
    plan += [("lsoda", r, {}) for r in ((1e-3,) if quick else (1e-3, 1e-5))]
    rows = []
    for method, rtol, kw in plan:
        s, wall = _seq(method, rtol, n_passes, n_cells, **kw)
        err = float(np.max(np.abs(s.h_inlet - h_ref)) / CASE["ambient_film"])
        label = method + ("/band" if kw.get("linear_solver") == "band" else ("/sparse" if method == "cvode" else ""))
        rows.append(dict(method=label, rtol=rtol, error=err, wall=wall, steps=s.stats["n_steps"],
                         rhs=s.stats["n_rhs"], jac=s.stats["n_jac"]))
    # RK4: time a slice of the first pass at the stability-limited step
    brg = ThrustBallBearing()
    c = brg.contact(CASE["load"])
    from transient.models.ball.levelling import LevellingGrid

    X = 0.5 * brg.ball_diameter / c.a
    g = LevellingGrid(n_cells, X, "reservoir", mobility_film=0.1)
    T = 3 * brg.viscosity * c.a ** 4 / (brg.surface_tension * CASE["ambient_film"] ** 3)
    tb_hat = brg.pass_interval(CASE["speed_rpm"]) / T
    h_peak = 2.6  # ridge height after the first pass (scaled), bounds the spectral radius
    lam_max = 16.0 * (h_peak ** 3 + 0.1 ** 3) / g.dx ** 4
    dt = 2.7 / lam_max  # RK4 real-axis stability limit ~2.785
    n_try = 2000
    res = solve(g.problem(np.ones(n_cells)), [0.0, n_try * dt], method="rk4", dt=dt)
    per_step = res.stats.wall_time / max(res.stats.n_steps, 1)
    steps_total = tb_hat / dt * (n_passes - 1)
    rk4_est = per_step * steps_total
    rows.append(dict(method="rk4 (extrapolated)", rtol=float("nan"), error=float("nan"), wall=rk4_est,
                     steps=int(steps_total), rhs=int(4 * steps_total), jac=0))

    best = {}
    for r in rows:
        if np.isfinite(r["error"]) and r["error"] < 1e-3:
            m = r["method"]
            if m not in best or r["wall"] < best[m]["wall"]:
                best[m] = r
    fastest = min((r["wall"] for r in best.values()), default=np.nan)
    lines = ["", "",
             f"Case: {n_passes} ball passes, 30 N, 80 rpm, 6 balls, h_inf = 100 um, thin-film reflow on "
             f"{n_cells} cells (half track, reservoir at the ball radius). Error = max_n |h_in^n - ref| / h_inf, "
             f"reference CVODE rtol 1e-10 ({t_ref:.2f} s). atol = 1e-4 rtol (scaled film).", "",
             "| method | rtol | error | wall [s] | steps | rhs | jac |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['method']} | {r['rtol']:.0e} | {r['error']:.2e} | {r['wall']:.3g} | {r['steps']} | "
                     f"{r['rhs']} | {r['jac']} |")
    lines += ["", "Cheapest run with error < 1e-3 per method, and its wall-time ratio to the fastest:", ""]
    for m, r in sorted(best.items(), key=lambda t: t[1]["wall"]):
        lines.append(f"- {m}: {r['wall']:.3g} s at rtol {r['rtol']:.0e} (error {r['error']:.1e}), "
                     f"ratio {r['wall'] / fastest:.1f}")
    lines.append(f"- rk4: stability-limited dt = {dt:.2e} (scaled; pass = {tb_hat:.3g}), {per_step*1e6:.1f} us/step "
                 f"measured over {n_try} steps -> {steps_total:.2e} steps, about {rk4_est:.3g} s "
                 f"(ratio {rk4_est / fastest:.2e}); not run to the end.")
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for m in dict.fromkeys(r["method"] for r in rows if np.isfinite(r["error"])):
        rr = [r for r in rows if r["method"] == m]
        ax.loglog([r["wall"] for r in rr], [max(r["error"], 1e-16) for r in rr], "o-", label=m)
    ax.axvline(rk4_est, color="k", ls=":", label="rk4 (extrapolated wall time)")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("max error in h_in / h_inf")
    ax.legend(fontsize=7)
    ax.set_title(f"{n_passes}-ball-pass sequence", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "bench_ball.png"), dpi=120)
    plt.close(fig)
    return {"rows": rows, "reference_wall": t_ref, "markdown": "\n".join(lines[2:])}


TITLE = "ball-pass sequence work-precision: CVODE sparse/band, scipy BDF/LSODA, RK4"


def main(out, quick: bool = False) -> str:
    """``transient bench ball``."""
    res = run(out_dir=str(out), quick=quick)
    return ("## Thrust ball bearing: 200-ball-pass sequence, work-precision (seed 002)\n"
            + res["markdown"] + "\n\n![work-precision](bench_ball.png)")
