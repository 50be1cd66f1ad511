"""Work-precision benchmark of the journal orbit (Rho & Kim Table 1 at 6000 rpm).

Unbalanced rigid rotor (m = 100 kg, e = 0.01 C, W = 981 N) on the 151 x 21 half-grid Elrod journal
bearing, started from the static equilibrium. Every method integrates the same ``revolutions`` shaft
revolutions in one run:

* CVODE and IDA (SUNDIALS BDF, sparse direct solver, analytic Jacobian) over rtol 1e-3 ... 1e-8;
* scipy BDF (sparse analytic Jacobian) and LSODA (dense Jacobian: scipy's limitation);
* the paper's scheme: classical RK4 on the rotor with N = 500 ... 10000 steps per revolution and the
  film solved at every stage, once with the paper's inner criterion sum|d theta| / sum theta < 1e-6
  and once with a tight one (1e-10) so the baseline is not handicapped by its iteration error.

Error = distance of the journal centre from the reference (CVODE, rtol 1e-10, atol 1e-13) in units of
the radial clearance C, at the final time and as the maximum over the outputs of the last revolution
(the latter is the one matched between methods). A second tight run (IDA, rtol 1e-10) bounds the
reference's own error. Wall times are after the JIT warm-up; ``callback share`` is the fraction of the
wall time spent inside the Python callbacks (numba kernels included) -- the rest is SUNDIALS / scipy
/ the linear algebra.

Matched error: the error E* of RK4 with 3000 steps per revolution (the paper's setting, paper
criterion). For each method the cost to reach E* is interpolated log-log on its work-precision curve
(lower envelope); ratios are quoted against CVODE. Finally the best suited SUNDIALS method at the
loosest tolerance that reaches E* integrates 100 revolutions (target: under 30 s).

Cost control: each method's runs go from cheap to expensive; once a run takes longer than
``time_budget_s`` the method's remaining (tighter) settings are skipped, scipy runs are stopped by the
facade's ``time_budget`` when they pass it, and RK4 settings whose cost predicted from the 500-step run exceeds the
budget are skipped. Skips are listed in the table.

``run()`` returns a dict; :func:`markdown` formats it, :func:`plot` writes the log-log figure;
``transient bench journal [--quick]`` writes docs/bench/journal.md, docs/benchmarks.md,
docs/bench_journal.png and docs/bench_journal.json.
"""

from __future__ import annotations

import json
import math
import platform
import sys
import time
from pathlib import Path

import numpy as np

from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.solvers.settings import Integration, LongRun, Recording

BEARING, ROTOR = RHO_KIM_BEARING, RHO_KIM_ROTOR
CLEARANCE = BEARING["clearance"]
REF_RTOL, REF_ATOL = 1e-10, 1e-13
PAPER_STEPS = 3000
PAPER_INNER, TIGHT_INNER = 1e-6, 1e-10

FULL = dict(revolutions=1.0, outputs_per_revolution=20, long_revolutions=100,
            cvode=(1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8), ida=(1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8),
            bdf=(1e-3, 1e-4, 1e-5, 1e-6), lsoda=(1e-3, 1e-4, 1e-5, 1e-6),
            rk4=(500, 1000, 2000, 3000, 5000, 10000), rk4_tight=(500, 1000, 2000, 3000, 5000, 10000))
QUICK = dict(revolutions=0.5, outputs_per_revolution=20, long_revolutions=2,
             cvode=(1e-3, 1e-6), ida=(1e-3, 1e-6), bdf=(1e-3,), lsoda=(1e-3,),
             rk4=(500, 3000), rk4_tight=(500,))
LINES = (("cvode", "CVODE"), ("ida", "IDA"), ("bdf", "scipy BDF"), ("lsoda", "scipy LSODA"),
         ("rk4", f"RK4, inner {PAPER_INNER:g} (paper)"), ("rk4_tight", f"RK4, inner {TIGHT_INNER:g}"))


def atol_for(rtol: float) -> float:
    """Absolute tolerance on the dimensionless states (film variable ~ O(1), position in C)."""
    return min(1e-9, 1e-3 * rtol)


def _log(msg, progress):
    if progress:
        print(msg, file=sys.stderr, flush=True)


def _orbit(grid, speed_rpm, switch_width=None):
    b = JournalBearing(**BEARING, grid=tuple(grid), switch_width=switch_width)
    return JournalOrbit(b, speed_rpm=speed_rpm, **ROTOR)


def _integration(line, setting) -> Integration:
    if line in ("rk4", "rk4_tight"):
        return Integration(method="rk4", steps_per_revolution=int(setting),
                           inner_tolerance=PAPER_INNER if line == "rk4" else TIGHT_INNER)
    return Integration(method=line, rtol=float(setting), atol=atol_for(setting))


def _errors(res, ref, opr):
    """(final, max over the last revolution) distance from the reference [C], and a note (unused: "")."""
    if res.t.size != ref.t.size or not np.allclose(res.t, ref.t, rtol=1e-9, atol=1e-12):
        raise RuntimeError(f"output times differ from the reference's ({res.t.size} vs {ref.t.size} outputs)")
    d = np.hypot(res.x - ref.x, res.y - ref.y) / CLEARANCE
    return float(d[-1]), float(np.max(d[-(opr + 1):])), ""


def cost_at(rows, line, target):
    """Wall time [s] for ``line`` to reach error ``target`` (log-log interpolation on the lower envelope
    of its work-precision points, error = max over the last revolution). Returns (time, how) where how
    is "interpolated", "upper bound" (even its cheapest run is more accurate) or "not reached"."""
    pts = sorted((r["error_max"], r["wall"]) for r in rows
                 if r["line"] == line and r["status"] == "ok" and r["error_max"] > 0)
    if not pts:
        return math.nan, "not run"
    # Pareto front: drop every run that another run beats on both error and time
    env = sorted(p for p in set(pts) if not any(q != p and q[0] <= p[0] and q[1] <= p[1] for q in pts))
    if target < env[0][0]:
        return math.nan, "not reached"
    if target >= env[-1][0]:
        return env[-1][1], "upper bound"
    for (e0, w0), (e1, w1) in zip(env[:-1], env[1:]):
        if e0 <= target <= e1:
            if e1 == e0:
                return min(w0, w1), "interpolated"
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0))), "interpolated"
    return math.nan, "not reached"


def run(revolutions=None, grid=(151, 21), quick=False, time_budget_s=300.0, speed_rpm=6000.0,
        long_revolutions=None, progress=True, settings=None):
    """Run the whole benchmark; returns a dict with ``rows`` (one per method and setting), ``reference``,
    ``matched`` (cost at RK4-3000's error), ``long`` (the 100-revolution timing) and ``config``.

    ``quick`` uses few revolutions and settings (smoke test); ``settings`` overrides entries of the
    configuration (e.g. ``{"cvode": (1e-4,)}``)."""
    cfg = dict(QUICK if quick else FULL)
    cfg.update(settings or {})
    if revolutions is not None:
        cfg["revolutions"] = float(revolutions)
    if long_revolutions is not None:
        cfg["long_revolutions"] = float(long_revolutions)
    revs, opr = cfg["revolutions"], int(cfg["outputs_per_revolution"])
    if any(int(s) % opr for s in (*cfg["rk4"], *cfg["rk4_tight"])):
        raise ValueError(f"RK4 steps per revolution must be multiples of outputs_per_revolution={opr}")
    o = _orbit(grid, speed_rpm)
    t0 = time.perf_counter()
    eq = o.equilibrium()
    t_eq = time.perf_counter() - t0
    _log(f"[journal bench] grid {grid[0]} x {grid[1]} ({o.n} states), {speed_rpm:g} rpm, {revs:g} rev; "
         f"equilibrium e/C = {eq.eccentricity_ratio:.4f} ({t_eq:.2f} s)", progress)
    for m in ("cvode", "ida", "bdf", "lsoda"):  # JIT / import warm-up, not timed
        o.run(0.01, integration=Integration(method=m, rtol=1e-3, atol=1e-9),
              recording=Recording(outputs_per_revolution=100))
    o.run(10 / min(cfg["rk4"] or (500,)),
          integration=Integration(method="rk4", steps_per_revolution=min(cfg["rk4"] or (500,))),
          recording=Recording(outputs_per_revolution=min(cfg["rk4"] or (500,))))

    common = dict(revolutions=revs, recording=Recording(outputs_per_revolution=opr))
    _log(f"  reference: CVODE rtol {REF_RTOL:g} ...", progress)
    ref = o.run(integration=Integration(method="cvode", rtol=REF_RTOL, atol=REF_ATOL), **common)
    _log(f"  reference: {ref.stats.wall_time:.1f} s, {ref.stats.n_steps} steps; check: IDA rtol {REF_RTOL:g} ...",
         progress)
    chk = o.run(integration=Integration(method="ida", rtol=REF_RTOL, atol=REF_ATOL), **common)
    ref_err = _errors(chk, ref, opr)[:2]
    reference = dict(method="cvode", rtol=REF_RTOL, atol=REF_ATOL, wall=ref.stats.wall_time,
                     n_steps=ref.stats.n_steps, check_wall=chk.stats.wall_time, check_error_final=ref_err[0],
                     check_error_max=ref_err[1], x_final=float(ref.x[-1] / CLEARANCE),
                     y_final=float(ref.y[-1] / CLEARANCE), eps_equilibrium=float(eq.eccentricity_ratio))
    _log(f"  reference check (IDA vs CVODE at rtol {REF_RTOL:g}): {ref_err[1]:.2e} C", progress)

    rows = []
    for line, label in LINES:
        over = None  # reason the remaining settings are skipped
        per_step = None  # RK4 seconds per step, from its first run
        for s in cfg[line]:
            ig = _integration(line, s)
            setting = f"{s:g}" if line in ("rk4", "rk4_tight") else f"{s:.0e}"
            row = dict(line=line, label=label, setting=setting, method=ig.method, status="ok",
                       error_final=math.nan, error_max=math.nan, wall=math.nan, n_steps=0, n_rhs=0, n_jac=0,
                       callback_share=math.nan, note="")
            if line.startswith("rk4") and per_step is not None and over is None:
                predicted = per_step * int(s) * revs
                if predicted > time_budget_s:
                    over = f"predicted {predicted:.0f} s > budget {time_budget_s:g} s"
            if over is not None:
                row["status"] = f"skipped ({over})"
                rows.append(row)
                _log(f"  {label:28s} {setting:>7s}  {row['status']}", progress)
                continue
            budget = LongRun(time_budget=time_budget_s) if line in ("bdf", "lsoda") else None
            try:
                res = o.run(integration=ig, long_run=budget, **common)
            except Exception as exc:  # a failed run is a result, not a crash of the benchmark
                row["status"] = f"failed: {str(exc)[:80]}"
                over = "a looser setting failed"
            else:
                if not res.success and "time budget" in res.message:
                    row.update(status=f"aborted (> {time_budget_s:g} s)", wall=time_budget_s)
                    over = f"a looser setting took > {time_budget_s:g} s"
                    rows.append(row)
                    _log(f"  {label:28s} {setting:>7s}  {row['status']}", progress)
                    continue
                if not res.success:
                    row["status"] = f"failed: {res.message[:80]}"
                    over = "a looser setting failed"
                    rows.append(row)
                    continue
                st = res.stats
                row.update(wall=st.wall_time, n_steps=st.n_steps, n_rhs=st.n_rhs, n_jac=st.n_jac,
                           callback_share=st.callback_share)
                row["error_final"], row["error_max"], row["note"] = _errors(res, ref, opr)
                if line.startswith("rk4"):
                    per_step = st.wall_time / max(st.n_steps, 1)
                if st.wall_time > time_budget_s:
                    over = f"a looser setting took {st.wall_time:.0f} s > budget {time_budget_s:g} s"
            rows.append(row)
            _log(f"  {label:28s} {setting:>7s}  error {row['error_max']:.2e} C  {row['wall']:7.2f} s  "
                 f"{row['status']}", progress)

    matched = _matched(rows)
    long = _long_run(o, rows, matched, cfg, progress)
    config = dict(grid=list(grid), states=o.n, speed_rpm=speed_rpm, revolutions=revs, outputs_per_revolution=opr,
                  time_budget_s=time_budget_s, quick=quick, bearing=BEARING, rotor=ROTOR,
                  machine=platform.processor() or platform.machine())
    return dict(rows=rows, reference=reference, matched=matched, long=long, config=config)


def _matched(rows):
    """Cost of every line at the error of RK4 with 3000 steps per revolution (paper criterion), and at
    the error of the tight-criterion RK4-3000 if it ran."""
    out = {}
    for key, line in (("paper", "rk4"), ("tight", "rk4_tight")):
        base = [r for r in rows if r["line"] == line and r["setting"] == f"{PAPER_STEPS:g}" and r["status"] == "ok"]
        if not base:
            continue
        target = base[0]["error_max"]
        costs = {ln: cost_at(rows, ln, target) for ln, _ in LINES}
        ref_cost = costs["cvode"][0]
        out[key] = dict(target=target, rk4_wall=base[0]["wall"],
                        lines={ln: dict(wall=c[0], how=c[1],
                                        ratio_to_cvode=(c[0] / ref_cost if ref_cost > 0 else math.nan))
                               for ln, c in costs.items()})
    return out


def _long_run(o, rows, matched, cfg, progress):
    """Time ``long_revolutions`` with the better of CVODE / IDA at the loosest tolerance that reaches
    RK4-3000's error (or the tightest run tolerance if none does)."""
    n = cfg["long_revolutions"]
    if not n:
        return None
    target = matched.get("paper", {}).get("target", math.inf)
    best = None
    for line in ("cvode", "ida"):
        ok = [r for r in rows if r["line"] == line and r["status"] == "ok"]
        good = [r for r in ok if r["error_max"] <= target]
        pick = max(good, key=lambda r: float(r["setting"])) if good else (
            min(ok, key=lambda r: float(r["setting"])) if ok else None)
        if pick is not None and (best is None or pick["wall"] < best["wall"]):
            best = pick
    if best is None:
        return None
    rtol = float(best["setting"])
    _log(f"  long run: {n:g} revolutions, {best['line'].upper()} rtol {rtol:.0e} ...", progress)
    res = o.run(n, integration=Integration(method=best["line"], rtol=rtol, atol=atol_for(rtol)),
                recording=Recording(outputs_per_revolution=cfg["outputs_per_revolution"]),
                long_run=LongRun(chunk_revolutions=max(1.0, n / 10), progress=progress))
    st = res.stats
    return dict(method=best["line"], rtol=rtol, revolutions=n, wall=st.wall_time, per_revolution=st.wall_time / n,
                n_steps=st.n_steps, callback_share=st.callback_share,
                eps_final=float(res.eccentricity_ratio[-1]), touched=res.touched_at is not None)


# ---------------------------------------------------------------------------------------------------
def _fmt(v, spec=".2e"):
    return "—" if v is None or (isinstance(v, float) and not math.isfinite(v)) else format(v, spec)


def markdown(result) -> str:
    """Markdown section (table + summary) of a :func:`run` result."""
    c, ref, rows = result["config"], result["reference"], result["rows"]
    lines = [f"Rho & Kim Table 1 bearing (D = 80 mm, L/D = 0.3, C = 80 um, mu = 0.029 Pa s, beta = 1e9 Pa, "
             f"p_s = 1 atm), rotor m = 100 kg, unbalance 0.01 C, W = 981 N, {c['speed_rpm']:g} rpm, "
             f"{c['grid'][0]} x {c['grid'][1]} half grid ({c['states']} states), {c['revolutions']:g} revolution(s) "
             f"from the static equilibrium (e/C = {ref['eps_equilibrium']:.4f})"
             + (" — **quick smoke run, not the benchmark**" if c["quick"] else "") + ".",
             "",
             f"Error = journal-centre distance from the reference (CVODE rtol {ref['rtol']:g}, atol {ref['atol']:g}, "
             f"{ref['wall']:.1f} s) in units of C: at the final time and max over the last revolution "
             f"({c['outputs_per_revolution']} outputs per revolution). Reference check: IDA at the same tolerance "
             f"differs by {_fmt(ref['check_error_max'])} C (errors below this are not resolved). "
             f"atol = min(1e-9, 1e-3 rtol) on the dimensionless states. Time budget per run "
             f"{c['time_budget_s']:g} s.",
             "",
             "| method | rtol / steps per rev | error final [C] | error max last rev [C] | wall [s] | steps | rhs "
             "| Jacobians | callback share | note |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        note = "; ".join(v for v in (r["status"] if r["status"] != "ok" else "", r.get("note", "")) if v)
        share = _fmt(r["callback_share"], ".0%") if not r["line"].startswith("rk4") else "(all Python)"
        lines.append(f"| {r['label']} | {r['setting']} | {_fmt(r['error_final'])} | {_fmt(r['error_max'])} | "
                     f"{_fmt(r['wall'], '.3g')} | {r['n_steps'] or '—'} | {r['n_rhs'] or '—'} | {r['n_jac'] or '—'} "
                     f"| {share} | {note} |")
    lines.append("")
    lines.append("RK4 rows: 'Jacobians' = sparse LU factorisations of the film Newton iteration; its inner film "
                 "solves run in Python + numba + SuperLU, so no callback share is separated.")
    for key, title in (("paper", "paper criterion"), ("tight", "tight inner criterion")):
        m = result["matched"].get(key)
        if not m:
            continue
        lines += ["", f"**Cost at the error of RK4 with {PAPER_STEPS} steps per revolution ({title}): "
                      f"E* = {m['target']:.2e} C, RK4 {m['rk4_wall']:.3g} s.**", "",
                  "| method | wall to reach E* [s] | how | time / CVODE's |", "|---|---:|---|---:|"]
        for line, label in LINES:
            d = m["lines"][line]
            lines.append(f"| {label} | {_fmt(d['wall'], '.3g')} | {d['how']} | {_fmt(d['ratio_to_cvode'], '.3g')} |")
        cv = m["lines"]["cvode"]["wall"]
        ida = m["lines"]["ida"]["wall"]
        best = np.nanmin([cv, ida]) if np.isfinite([cv, ida]).any() else math.nan
        rk = m["lines"]["rk4"]["wall"] if key == "paper" else m["lines"]["rk4_tight"]["wall"]
        bdf = m["lines"]["bdf"]["wall"]
        lines.append("")
        lines.append(f"Speed-up of the faster of IDA/CVODE: {_fmt(rk / best, '.3g')}x over RK4 (target >= 50x), "
                     f"{_fmt(bdf / best, '.3g')}x over scipy BDF (target >= 10x; '—' if BDF did not reach E*).")
    lg = result.get("long")
    if lg:
        lines += ["", f"**{lg['revolutions']:g} revolutions** with {lg['method'].upper()} rtol {lg['rtol']:.0e} "
                      f"(loosest tolerance reaching E*): {lg['wall']:.1f} s ({lg['per_revolution']:.3f} s per revolution, "
                      f"{lg['n_steps'] / lg['revolutions']:.0f} steps per revolution, callback share "
                      f"{lg['callback_share']:.0%}; target: 100 revolutions in under 30 s); final e/C = "
                      f"{lg['eps_final']:.4f}."]
    lines += ["", "![work-precision](bench_journal.png)", "",
              f"Machine: {c['machine']}, 1 thread. Reproduce: `transient bench journal"
              + (" --quick" if c["quick"] else "") + "`."]
    return "\n".join(lines)


def plot(result, path):
    """Log-log error (max over the last revolution) vs wall time, one line per method."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    styles = {"cvode": "o-", "ida": "s-", "bdf": "^-", "lsoda": "v-", "rk4": "D-", "rk4_tight": "d--"}
    fig, ax = plt.subplots(figsize=(7.0, 5.0))
    for line, label in LINES:
        pts = [r for r in result["rows"] if r["line"] == line and r["status"] == "ok" and r["error_max"] > 0]
        if not pts:
            continue
        ax.loglog([r["wall"] for r in pts], [r["error_max"] for r in pts], styles[line], label=label, ms=5)
        for r in pts:
            ax.annotate(r["setting"], (r["wall"], r["error_max"]), textcoords="offset points", xytext=(4, 3),
                        fontsize=6, color="0.35")
    m = result["matched"].get("paper")
    if m:
        ax.axhline(m["target"], color="0.5", lw=0.8, ls=":")
        ax.annotate(f"RK4 {PAPER_STEPS}/rev error", (ax.get_xlim()[0], m["target"]), xytext=(3, 3),
                    textcoords="offset points", fontsize=7, color="0.4")
    chk = result["reference"]["check_error_max"]
    lo, hi = ax.get_ylim()
    if chk > lo:  # shade the errors the reference does not resolve
        ax.axhspan(lo, chk, color="0.9", zorder=0)
        ax.set_ylim(lo, hi)
    c = result["config"]
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("journal-centre error, max over last revolution [C]")
    ax.set_title(f"Journal orbit, {c['speed_rpm']:g} rpm, {c['grid'][0]}x{c['grid'][1]}, "
                 f"{c['revolutions']:g} rev" + (" (quick)" if c["quick"] else ""), fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def write(result, out: Path):
    """The figure and the raw numbers next to the docs: out/bench_journal.png and .json."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    plot(result, out / "bench_journal.png")
    (out / "bench_journal.json").write_text(json.dumps(result, indent=1, default=float))
    return out / "bench_journal.png"


TITLE = "journal orbit work-precision: CVODE, IDA, scipy BDF/LSODA, the paper's RK4"


def main(out, quick: bool = False) -> str:
    """``transient bench journal``: the work-precision run, its figure and raw numbers in ``out``."""
    result = run(quick=quick)
    write(result, out)
    return "## Journal orbit (Rho & Kim): work-precision at 6000 rpm\n\n" + markdown(result)
