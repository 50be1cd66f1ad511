"""Orbit size benchmark (seed 003, issue 18): integrator cost from small orbits to oil whip, side by side.

The Rho & Kim bearing and rotor (m = 100 kg, W = 981 N) on the paper grid, three cases:

* **large**: unbalance 0.3 C at 6000 rpm, one revolution from the static equilibrium (the journal swings
  over 0.7 C and the cavitation fronts sweep the film);
* **whip**: 1.5x the Lund threshold, one revolution on the settled whirl (the state after ``spin_up``
  revolutions from the equilibrium), and a longer stretch timed to extrapolate 1000 revolutions;
* **small**: unbalance 0.01 C at 6000 rpm (the paper's case), one revolution from the equilibrium, and 100
  revolutions timed.

Each case runs IDA on both film formulations of :class:`~transient.models.journal.JournalOrbit` -- ``universal``
(state u, ``A H D(u) u'``) and ``content`` (state H theta, ``A m' + R = 0``, the default) -- at the same user
tolerances, alternating the two; the large case also runs the paper's RK4 (3000 steps per revolution, paper
criterion). Error = the largest journal-centre distance over the run's outputs from a reference (content, rtol
``REF_RTOL``) in units of C; the reference's own error is bounded by a universal run at the same tolerance.
Step, Jacobian (= factorisation) and residual counts are exact; times are wall and CPU seconds on a shared
2-core machine (compare ratios within one run). "IDA at RK4's error" interpolates the content curve log-log.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR

TITLE = "Orbit size: IDA cost from small orbits to oil whip, universal vs content film formulation, RK4"
CLEARANCE = BEARING["clearance"]
FORMS = ("universal", "content")
REF_RTOL = 1e-7
FULL = dict(grid=(151, 21), rtols=(1e-3, 1e-4, 1e-5), rk4_steps=3000, spin_up=40, whip_timed=10, small_revs=100,
            opr=20)
QUICK = dict(grid=(48, 8), rtols=(1e-3, 1e-4), rk4_steps=600, spin_up=20, whip_timed=3, small_revs=10, opr=20)


def atol_for(rtol):
    return min(1e-9, 1e-3 * rtol)


def _orbit(grid, unbalance_C, speed_rpm):
    b = JournalBearing(**BEARING, grid=tuple(grid))
    return JournalOrbit(b, ROTOR["rotor_mass"], unbalance_C * CLEARANCE, ROTOR["load"], speed_rpm)


def _timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    r = fn()
    return r, time.perf_counter() - w0, time.process_time() - c0


def _row(case, label, r, wall, cpu, ref, revs):
    err = float(np.max(np.hypot(r.x - ref.x, r.y - ref.y)) / CLEARANCE) if ref is not None else math.nan
    s = r.stats
    return dict(case=case, label=label, steps_per_rev=s.n_steps / revs, jac_per_rev=s.n_jac / revs,
                res_per_rev=s.n_rhs / revs, wall_per_rev=wall / revs, cpu_per_rev=cpu / revs, error=err,
                ok=bool(r.success), message=r.message)


def _side_by_side(case, o, rtols, revs, ref, start=None, opr=20, log=print):
    """Both formulations at every rtol, alternating (universal, content, content, universal, ...)."""
    rows = []
    for k, rt in enumerate(rtols):
        order = FORMS if k % 2 == 0 else FORMS[::-1]
        for form in order:
            r, w, c = _timed(lambda: o.run(revs, rtol=rt, atol=atol_for(rt), outputs_per_revolution=opr,
                                           start=start, formulation=form, progress=False))
            rows.append(_row(case, f"IDA {form} rtol {rt:.0e}", r, w, c, ref, revs) | dict(form=form, rtol=rt))
            log(f"  {rows[-1]['label']}: {rows[-1]['steps_per_rev']:.0f} steps/rev, {rows[-1]['jac_per_rev']:.0f} "
                f"jac/rev, {w / revs:.2f} s/rev, error {rows[-1]['error']:.2e} C")
    return rows


def cost_at(rows, form, target):
    """Wall seconds per revolution for ``form`` to reach ``target`` error (log-log on its points)."""
    pts = sorted((r["error"], r["wall_per_rev"]) for r in rows if r.get("form") == form and r["error"] > 0)
    if not pts or target < pts[0][0]:
        return math.nan
    for (e0, w0), (e1, w1) in zip(pts[:-1], pts[1:]):
        if e0 <= target <= e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0)) if e1 > e0 else 0.0
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0)))
    return pts[-1][1]  # even the loosest run is more accurate: an upper bound


def run(quick=False, log=print) -> dict:
    cfg = dict(QUICK if quick else FULL)
    grid, rtols, opr = cfg["grid"], cfg["rtols"], cfg["opr"]
    out = dict(config=dict(cfg, quick=quick, ref_rtol=REF_RTOL), rows=[])
    rows = out["rows"]

    # ---- large orbit: 0.3 C from equilibrium --------------------------------------------------------------
    o = _orbit(grid, 0.3, 6000.0)
    o.run(0.01, rtol=1e-3, formulation="universal", progress=False)  # JIT warm-up, not timed
    o.run(0.01, rtol=1e-3, formulation="content", progress=False)
    log(f"[orbit_size] large: 0.3 C, 6000 rpm, {grid[0]} x {grid[1]}; reference content rtol {REF_RTOL:g} ...")
    ref, w, _ = _timed(lambda: o.run(1, rtol=REF_RTOL, atol=atol_for(REF_RTOL), outputs_per_revolution=opr,
                                     progress=False))
    chk = o.run(1, rtol=REF_RTOL, atol=atol_for(REF_RTOL), outputs_per_revolution=opr, formulation="universal",
                progress=False)
    out["large_reference"] = dict(wall=w, steps=ref.stats.n_steps, excursion_C=float(np.max(np.hypot(
        ref.x - ref.x[0], ref.y - ref.y[0])) / CLEARANCE), check_C=float(np.max(np.hypot(chk.x - ref.x, chk.y - ref.y))
                                                                         / CLEARANCE))
    rows += _side_by_side("large", o, rtols, 1.0, ref, opr=opr, log=log)
    n_rk4 = cfg["rk4_steps"]
    r, w, c = _timed(lambda: o.run(1, method="rk4", steps_per_revolution=n_rk4, outputs_per_revolution=opr,
                                   progress=False))
    rows.append(_row("large", f"RK4 {n_rk4} steps/rev (paper)", r, w, c, ref, 1.0) | dict(form="rk4"))
    log(f"  RK4 {n_rk4}: {w:.1f} s, error {rows[-1]['error']:.2e} C")
    e_rk4, w_rk4 = rows[-1]["error"], rows[-1]["wall_per_rev"]
    out["large_matched"] = {f: dict(wall_per_rev=cost_at(rows, f, e_rk4)) for f in FORMS}
    for f in FORMS:
        out["large_matched"][f]["speedup_vs_rk4"] = w_rk4 / out["large_matched"][f]["wall_per_rev"]

    # ---- oil whip at 1.5x the threshold --------------------------------------------------------------------
    b = JournalBearing(**BEARING, grid=tuple(grid))
    th = b.stability_threshold(ROTOR["rotor_mass"], ROTOR["load"])
    ow = JournalOrbit(b, speed_rpm=1.5 * th, **ROTOR)
    log(f"[orbit_size] whip: 1.5 x threshold ({th:.0f} rpm) = {ow.speed_rpm:.0f} rpm; spin-up "
        f"{cfg['spin_up']} revolutions ...")
    spin, w, _ = _timed(lambda: ow.run(cfg["spin_up"], rtol=1e-4, outputs_per_revolution=opr, chunk_revolutions=5,
                                       progress=False))
    eps = spin.eccentricity_ratio
    out["whip_spin_up"] = dict(threshold_rpm=th, speed_rpm=ow.speed_rpm, revolutions=cfg["spin_up"], wall=w,
                               steps=spin.stats.n_steps, eps_last_rev=(float(eps[-opr:].min()), float(eps[-opr:].max())),
                               message=spin.message)
    wref = ow.run(1, rtol=REF_RTOL, atol=atol_for(REF_RTOL), outputs_per_revolution=opr, start=spin, progress=False)
    rows += _side_by_side("whip", ow, rtols, 1.0, wref, start=spin, opr=opr, log=log)
    nt = cfg["whip_timed"]
    r, w, c = _timed(lambda: ow.run(nt, rtol=1e-4, outputs_per_revolution=opr, start=spin, chunk_revolutions=10,
                                    progress=False))
    out["whip_long"] = dict(revolutions=nt, wall=w, cpu=c, steps_per_rev=r.stats.n_steps / nt,
                            jac_per_rev=r.stats.n_jac / nt, minutes_per_1000_rev=w / nt * 1000 / 60,
                            cpu_minutes_per_1000_rev=c / nt * 1000 / 60, message=r.message)
    log(f"  {nt} revolutions content rtol 1e-4: {w:.0f} s -> {out['whip_long']['minutes_per_1000_rev']:.0f} min "
        f"per 1000 revolutions")

    # ---- small orbit: the paper's 0.01 C --------------------------------------------------------------------
    os_ = _orbit(grid, 0.01, 6000.0)
    log("[orbit_size] small: 0.01 C, 6000 rpm ...")
    sref = os_.run(1, rtol=REF_RTOL, atol=atol_for(REF_RTOL), outputs_per_revolution=opr, progress=False)
    rows += _side_by_side("small", os_, rtols, 1.0, sref, opr=opr, log=log)
    nl = cfg["small_revs"]
    out["small_long"] = {}
    for form in FORMS + FORMS[::-1]:  # alternate, twice: keep the faster of each
        r, w, c = _timed(lambda: os_.run(nl, rtol=1e-3, atol=1e-9, outputs_per_revolution=opr, formulation=form,
                                         progress=False))
        prev = out["small_long"].get(form)
        if prev is None or w < prev["wall"]:
            out["small_long"][form] = dict(revolutions=nl, wall=w, cpu=c, steps_per_rev=r.stats.n_steps / nl,
                                           jac_per_rev=r.stats.n_jac / nl)
    for form in FORMS:
        s = out["small_long"][form]
        log(f"  {nl} revolutions IDA {form} rtol 1e-3: {s['wall']:.1f} s, {s['steps_per_rev']:.0f} steps/rev")
    return out


def _fmt(v, f="{:.2e}"):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f.format(v)


def markdown(res) -> str:
    c = res["config"]
    lr, sp, wl = res["large_reference"], res["whip_spin_up"], res["whip_long"]
    L = [f"Rho & Kim bearing and rotor, {c['grid'][0]} x {c['grid'][1]} half grid, IDA (atol = min(1e-9, 1e-3 rtol)), "
         f"user rtol as given (the content formulation hands IDA rtol / 10)"
         + (" — **quick smoke run, not the benchmark**" if c["quick"] else "") + ".", "",
         f"References: content rtol {c['ref_rtol']:g}; universal at that tolerance differs by {_fmt(lr['check_C'])} C "
         f"(large case, excursion {lr['excursion_C']:.3f} C). Whip: {sp['speed_rpm']:.0f} rpm = 1.5 x the Lund threshold "
         f"{sp['threshold_rpm']:.0f} rpm, after {sp['revolutions']} revolutions from the equilibrium (e/C "
         f"{sp['eps_last_rev'][0]:.3f} - {sp['eps_last_rev'][1]:.3f} over the last one).", "",
         "| case | run | steps/rev | Jacobians/rev | residuals/rev | wall s/rev | CPU s/rev | error [C] |",
         "|---|---|---|---|---|---|---|---|"]
    for r in res["rows"]:
        L.append(f"| {r['case']} | {r['label']} | {r['steps_per_rev']:.0f} | {r['jac_per_rev']:.0f} | "
                 f"{r['res_per_rev']:.0f} | {r['wall_per_rev']:.2f} | {r['cpu_per_rev']:.2f} | {_fmt(r['error'])} |")
    m = res["large_matched"]
    rk4 = next(r for r in res["rows"] if r.get("form") == "rk4")
    L += ["", f"**Large orbit at RK4's error** ({_fmt(rk4['error'])} C, {rk4['wall_per_rev']:.1f} s): IDA content "
          f"{_fmt(m['content']['wall_per_rev'], '{:.2f}')} s ({m['content']['speedup_vs_rk4']:.1f}x faster than RK4), "
          f"IDA universal {_fmt(m['universal']['wall_per_rev'], '{:.2f}')} s ({m['universal']['speedup_vs_rk4']:.1f}x).",
          f"**Whip, {wl['revolutions']} revolutions** (content, rtol 1e-4): {wl['steps_per_rev']:.0f} steps and "
          f"{wl['jac_per_rev']:.0f} Jacobians per revolution, {wl['wall']:.0f} s -> "
          f"{wl['minutes_per_1000_rev']:.0f} min per 1000 revolutions ({wl['cpu_minutes_per_1000_rev']:.0f} CPU min).",
          "**Small orbit, {} revolutions** (rtol 1e-3, the faster of two alternating runs): ".format(
              res["small_long"]["content"]["revolutions"])
          + ", ".join(f"{f} {res['small_long'][f]['wall']:.1f} s ({res['small_long'][f]['steps_per_rev']:.0f} steps/rev)"
                      for f in FORMS) + "."]
    return "\n".join(L)


def plot(res, path):
    from transient.plots import figure, save

    fig, axes = figure(1, 3, size=(15, 4.2))
    for ax, case in zip(axes, ("large", "whip", "small")):
        for form, mk in (("universal", "o-"), ("content", "s-")):
            pts = [(r["wall_per_rev"], r["error"]) for r in res["rows"] if r["case"] == case and r.get("form") == form]
            if pts:
                ax.loglog(*zip(*pts), mk, label=f"IDA {form}")
        for r in res["rows"]:
            if r["case"] == case and r.get("form") == "rk4":
                ax.loglog(r["wall_per_rev"], r["error"], "k*", ms=10, label=r["label"])
        ax.set(xlabel="wall s per revolution", ylabel="error [C]", title=case)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
    return save(fig, path)


def main(out, quick=False) -> str:
    out = Path(out)
    res = run(quick=quick)
    (out / "bench_orbit_size.json").write_text(json.dumps(res, indent=1, default=float))
    plot(res, out / "bench_orbit_size.png")
    return f"## {TITLE}\n\n{markdown(res)}\n\n![work-precision](bench_orbit_size.png)\n"
