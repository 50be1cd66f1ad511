"""Orbit size benchmark (Rho & Kim's rotor): integrator cost from small orbits to oil whip, side by side.

The Rho & Kim bearing and rotor (m = 100 kg, W = 981 N) on the paper grid, three cases:

* **large**: unbalance 0.3 C at 6000 rpm, one revolution from the static equilibrium (the journal swings
  over 0.7 C and the cavitation fronts sweep the film);
* **whip**: 1.5x the Lund threshold, one revolution on the settled whirl (the state after ``spin_up``
  revolutions from the equilibrium), and a longer stretch timed to extrapolate 1000 revolutions;
* **small**: unbalance 0.01 C at 6000 rpm (the paper's case), one revolution from the equilibrium, and 100
  revolutions timed.

Each case runs the candidate integrators side by side at the same user tolerances: IDA on the default
``universal`` film (state u, ``A H D(u) u' + R = 0``), IDA on the ``content`` film (state H theta, ``A m' + R = 0``:
the cavity crossing conserves mass exactly), and IDA on the universal film with a 10x wider switch
(``WIDE``: 2e-2 p0 and content width 5e-3, whose bias is second order in the widths since the prescribed
pressures sit on the sharp curve); the large case also runs the paper's RK4 (3000 steps per revolution). Error =
the largest journal-centre distance over the run's outputs from a reference (universal, rtol ``REF_RTOL``) in
units of C -- the wide switch's error includes its bias. Step, Jacobian (= factorisation) and residual counts
are exact; times are wall and CPU seconds on a shared 2-core machine (compare ratios within one run). "IDA at
RK4's error" interpolates each candidate's curve log-log.
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
FORMS = ("universal", "content", "wide")
WIDE = dict(switch_width_p0=2e-2, switch_content_width=5e-3)
REF_RTOL = 1e-8
FULL = dict(grid=(151, 21), rtols=(1e-3, 1e-4), rk4_steps=3000, whip_offset=0.4, spin_up=6, whip_timed=3,
            small_revs=100, opr=20)
QUICK = dict(grid=(48, 8), rtols=(1e-3, 1e-4), rk4_steps=600, whip_offset=0.4, spin_up=3, whip_timed=2, small_revs=10,
             opr=20)


def atol_for(rtol):
    return min(1e-9, 1e-3 * rtol)


def _orbit(grid, unbalance_C, speed_rpm, wide=False):
    kw = {}
    if wide:
        p0 = JournalBearing(**BEARING, grid=tuple(grid)).pressure_scale(speed_rpm)
        kw = dict(switch_width=WIDE["switch_width_p0"] * p0, switch_content_width=WIDE["switch_content_width"])
    b = JournalBearing(**BEARING, grid=tuple(grid), **kw)
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


def _side_by_side(case, orbits, rtols, revs, ref, start=None, opr=20, log=print):
    """Every candidate at every rtol, the order alternating between tolerances. ``orbits``: form -> orbit
    (``wide`` is a universal run of its own wide-switch orbit); ``start``: form -> start state or None."""
    rows = []
    for k, rt in enumerate(rtols):
        for form in (FORMS if k % 2 == 0 else FORMS[::-1]):
            o = orbits[form]
            st = None if start is None else start[form]
            r, w, c = _timed(lambda: o.run(revs, rtol=rt, atol=atol_for(rt), outputs_per_revolution=opr, start=st,
                                           formulation="content" if form == "content" else "universal",
                                           progress=False))
            rows.append(_row(case, f"IDA {form} rtol {rt:.0e}", r, w, c, ref, revs) | dict(form=form, rtol=rt))
            log(f"  {rows[-1]['label']}: {rows[-1]['steps_per_rev']:.0f} steps/rev, {rows[-1]['jac_per_rev']:.0f} "
                f"jac/rev, {w / revs:.2f} s/rev, error {rows[-1]['error']:.2e} C")
    return rows


def _warm(orbits):
    for form, o in orbits.items():  # JIT warm-up, not timed
        o.run(0.01, rtol=1e-3, formulation="content" if form == "content" else "universal", progress=False)


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


def _candidates(grid, unbalance_C, speed_rpm):
    o = _orbit(grid, unbalance_C, speed_rpm)
    orbits = dict(universal=o, content=o, wide=_orbit(grid, unbalance_C, speed_rpm, wide=True))
    _warm(orbits)
    return orbits


def _reference(o, revs, opr, start=None):
    return o.run(revs, rtol=REF_RTOL, atol=atol_for(REF_RTOL), outputs_per_revolution=opr, start=start,
                 progress=False)


def run(quick=False, log=print) -> dict:
    cfg = dict(QUICK if quick else FULL)
    grid, rtols, opr = cfg["grid"], cfg["rtols"], cfg["opr"]
    out = dict(config=dict(cfg, quick=quick, ref_rtol=REF_RTOL, wide=WIDE), rows=[])
    rows = out["rows"]

    # ---- large orbit: 0.3 C from equilibrium --------------------------------------------------------------
    orbits = _candidates(grid, 0.3, 6000.0)
    o = orbits["universal"]
    log(f"[orbit_size] large: 0.3 C, 6000 rpm, {grid[0]} x {grid[1]}; reference universal rtol {REF_RTOL:g} ...")
    ref, w, _ = _timed(lambda: _reference(o, 1, opr))
    out["large_reference"] = dict(wall=w, steps=ref.stats.n_steps, excursion_C=float(np.max(np.hypot(
        ref.x - ref.x[0], ref.y - ref.y[0])) / CLEARANCE))
    rows += _side_by_side("large", orbits, rtols, 1.0, ref, opr=opr, log=log)
    n_rk4 = cfg["rk4_steps"]
    o.run(0.01, method="rk4", steps_per_revolution=n_rk4, progress=False)
    r, w, c = _timed(lambda: o.run(1, method="rk4", steps_per_revolution=n_rk4, outputs_per_revolution=opr,
                                   progress=False))
    rows.append(_row("large", f"RK4 {n_rk4} steps/rev (paper)", r, w, c, ref, 1.0) | dict(form="rk4"))
    log(f"  RK4 {n_rk4}: {w:.1f} s, error {rows[-1]['error']:.2e} C")
    e_rk4, w_rk4 = rows[-1]["error"], rows[-1]["wall_per_rev"]
    out["large_matched"] = {f: dict(wall_per_rev=cost_at(rows, f, e_rk4)) for f in FORMS}
    for f in FORMS:
        out["large_matched"][f]["speedup_vs_rk4"] = w_rk4 / out["large_matched"][f]["wall_per_rev"]

    # ---- oil whip at 1.5x the threshold --------------------------------------------------------------------
    th = o.bearing.stability_threshold(ROTOR["rotor_mass"], ROTOR["load"])
    orbits = _candidates(grid, 0.01, 1.5 * th)
    ow = orbits["universal"]
    log(f"[orbit_size] whip: 1.5 x threshold ({th:.0f} rpm) = {ow.speed_rpm:.0f} rpm; {cfg['spin_up']} revolutions "
        f"from {cfg['whip_offset']} C off the equilibrium ...")
    starts = {}
    for form in ("universal", "wide"):
        y0 = orbits[form].perturbed_start(cfg["whip_offset"])
        sp, w, _ = _timed(lambda: orbits[form].run(cfg["spin_up"], rtol=1e-4, atol=atol_for(1e-4), y0=y0,
                                                   outputs_per_revolution=opr, progress=False))
        starts[form] = sp
        if form == "universal":
            eps = sp.eccentricity_ratio
            out["whip_spin_up"] = dict(threshold_rpm=th, speed_rpm=ow.speed_rpm, revolutions=cfg["spin_up"], wall=w,
                                       steps=sp.stats.n_steps, eps_last_rev=(float(eps[-opr:].min()),
                                                                             float(eps[-opr:].max())),
                                       message=sp.message)
    starts["content"] = starts["universal"]
    wref = _reference(ow, 1, opr, start=starts["universal"])
    rows += _side_by_side("whip", orbits, rtols, 1.0, wref, start=starts, opr=opr, log=log)
    nt = cfg["whip_timed"]
    r, w, c = _timed(lambda: ow.run(nt, rtol=1e-4, atol=atol_for(1e-4), outputs_per_revolution=opr,
                                    start=starts["universal"], progress=False))
    out["whip_long"] = dict(revolutions=nt, wall=w, cpu=c, steps_per_rev=r.stats.n_steps / nt,
                            jac_per_rev=r.stats.n_jac / nt, minutes_per_1000_rev=w / nt * 1000 / 60,
                            cpu_minutes_per_1000_rev=c / nt * 1000 / 60, message=r.message)
    log(f"  {nt} revolutions universal rtol 1e-4: {w:.0f} s -> {out['whip_long']['minutes_per_1000_rev']:.0f} min "
        f"per 1000 revolutions")

    # ---- small orbit: the paper's 0.01 C --------------------------------------------------------------------
    orbits = _candidates(grid, 0.01, 6000.0)
    log("[orbit_size] small: 0.01 C, 6000 rpm ...")
    sref = _reference(orbits["universal"], 1, opr)
    rows += _side_by_side("small", orbits, rtols, 1.0, sref, opr=opr, log=log)
    nl = cfg["small_revs"]
    out["small_long"] = {}
    for form in ("universal", "content", "content", "universal"):  # alternate, twice: keep the faster of each
        r, w, c = _timed(lambda: orbits[form].run(nl, rtol=1e-3, atol=1e-9, outputs_per_revolution=opr,
                                                  formulation=form, progress=False))
        prev = out["small_long"].get(form)
        if prev is None or w < prev["wall"]:
            out["small_long"][form] = dict(revolutions=nl, wall=w, cpu=c, steps_per_rev=r.stats.n_steps / nl,
                                           jac_per_rev=r.stats.n_jac / nl)
    for form in ("universal", "content"):
        s_ = out["small_long"][form]
        log(f"  {nl} revolutions IDA {form} rtol 1e-3: {s_['wall']:.1f} s, {s_['steps_per_rev']:.0f} steps/rev")
    return out


def _fmt(v, f="{:.2e}"):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f.format(v)


def markdown(res) -> str:
    c = res["config"]
    lr, sp, wl = res["large_reference"], res["whip_spin_up"], res["whip_long"]
    L = [f"Rho & Kim bearing and rotor, {c['grid'][0]} x {c['grid'][1]} half grid, IDA (atol = min(1e-9, 1e-3 rtol)), "
         f"user rtol as given (the content formulation hands IDA rtol / 10); wide switch "
         f"{c['wide']['switch_width_p0']:g} p0 / {c['wide']['switch_content_width']:g} (default 1e-4 p0 / 1e-2)"
         + (" — **quick smoke run, not the benchmark**" if c["quick"] else "") + ".", "",
         f"References: universal rtol {c['ref_rtol']:g} (large case: {lr['steps']} steps, excursion "
         f"{lr['excursion_C']:.3f} C). Whip: {sp['speed_rpm']:.0f} rpm = 1.5 x the Lund threshold "
         f"{sp['threshold_rpm']:.0f} rpm, after {sp['revolutions']} revolutions from {c['whip_offset']} C off the "
         f"equilibrium (e/C {sp['eps_last_rev'][0]:.3f} - {sp['eps_last_rev'][1]:.3f} over the last one).", "",
         "| case | run | steps/rev | Jacobians/rev | residuals/rev | wall s/rev | CPU s/rev | error [C] |",
         "|---|---|---|---|---|---|---|---|"]
    for r in res["rows"]:
        L.append(f"| {r['case']} | {r['label']} | {r['steps_per_rev']:.0f} | {r['jac_per_rev']:.0f} | "
                 f"{r['res_per_rev']:.0f} | {r['wall_per_rev']:.2f} | {r['cpu_per_rev']:.2f} | {_fmt(r['error'])} |")
    m = res["large_matched"]
    rk4 = next(r for r in res["rows"] if r.get("form") == "rk4")
    L += ["", f"**Large orbit at RK4's error** ({_fmt(rk4['error'])} C, {rk4['wall_per_rev']:.1f} s): "
          + ", ".join(f"IDA {f} {m[f]['wall_per_rev']:.2f} s ({m[f]['speedup_vs_rk4']:.1f}x RK4)"
                      if math.isfinite(m[f]["wall_per_rev"]) else f"IDA {f}: RK4's error not reached at the rtols run"
                      for f in FORMS) + " (a candidate whose loosest run is already more accurate is charged that run).",
          f"**Whip, {wl['revolutions']} revolutions** (universal, rtol 1e-4): {wl['steps_per_rev']:.0f} steps and "
          f"{wl['jac_per_rev']:.0f} Jacobians per revolution, {wl['wall']:.0f} s -> "
          f"{wl['minutes_per_1000_rev']:.0f} min per 1000 revolutions ({wl['cpu_minutes_per_1000_rev']:.0f} CPU min).",
          "**Small orbit, {} revolutions** (rtol 1e-3, the faster of two alternating runs): ".format(
              res["small_long"]["universal"]["revolutions"])
          + ", ".join(f"{f} {v['wall']:.1f} s ({v['steps_per_rev']:.0f} steps/rev)" for f, v in res["small_long"].items())
          + "."]
    return "\n".join(L)


def plot(res, path):
    from transient.plots import figure, save

    fig, axes = figure(1, 3, size=(15, 4.2))
    for ax, case in zip(axes, ("large", "whip", "small")):
        for form, mk in (("universal", "o-"), ("content", "s-"), ("wide", "^-")):
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
