"""Orbit size benchmark (Rho & Kim's rotor): integrator cost from small orbits to oil whip, IDA, BDF2 and RK4 side by side.

The Rho & Kim bearing and rotor (m = 100 kg, W = 981 N) on the paper grid, three cases:

* **large**: unbalance 0.3 C at 6000 rpm, one revolution from the static equilibrium (the journal swings
  over 0.7 C and the cavitation fronts sweep the film);
* **whip**: 1.5x the Lund threshold, one revolution on the settled whirl (the state after ``spin_up``
  revolutions from the equilibrium), and a longer stretch timed to extrapolate 1000 revolutions;
* **small**: unbalance 0.01 C at 6000 rpm (the paper's case), one revolution from the equilibrium, and 100
  revolutions timed.

Candidates, in one run at the same settings: IDA on the universal film (state u, ``A H D(u) u' + R = 0``) at the
rtols of the config; the variable-step BDF2 of :mod:`transient.solvers.integrate.bdf2` on the content film (``A m' + R = 0``,
its own Newton on a bordered band LU, error test on the rotor) at the (step cap, rtol) pairs of the config (the cap:
least steps per revolution); in the large case the paper's RK4 (3000 steps per revolution). IDA on the content
film and on a 10x wider switch are compared in docs/journal.md (section 5). Error = the largest journal-centre
distance over the run's outputs from a reference (IDA universal, rtol ``REF_RTOL``) in units of C. Step, Jacobian
(= factorisation) and residual counts are exact; times are wall and CPU seconds on a shared 2-core machine
(compare ratios within one run; the BDF2 and IDA long runs alternate, twice, and keep the faster of each).
"Cost at RK4's error" (large) and "cost at IDA rtol 1e-3's error" (whip, small) interpolate each candidate's curve
log-log.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from transient.bench import save_raw, timed
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "Orbit size: IDA, BDF2 on the content film and RK4 from small orbits to oil whip"
CLEARANCE = BEARING["clearance"]
FORMS = ("universal", "bdf2")
REF_RTOL = 1e-8
BDF2_RTOL = 1e-4  # the whip's spin-up
#: BDF2 candidates (step cap [steps per revolution], rtol on the rotor) per case, paired with IDA's rtols; the long
#: runs take IDA at the loosest rtol and BDF2 at ``*_long``
LARGE_BDF2 = ((300, 1e-4), (550, 1e-4))
SMALL_BDF2 = ((100, 1e-3), (100, 1e-4))
FULL = dict(grid=(151, 21), rtols=(1e-3, 1e-4), bdf2=LARGE_BDF2, small_bdf2=SMALL_BDF2, whip_long=(300, 1e-4),
            small_long=(100, 1e-3), rk4_steps=3000, whip_offset=0.4, spin_up=6, whip_timed=3, small_revs=100, opr=20)
QUICK = dict(grid=(48, 8), rtols=(1e-3, 1e-4), bdf2=LARGE_BDF2, small_bdf2=SMALL_BDF2, whip_long=(300, 1e-4),
             small_long=(100, 1e-3), rk4_steps=600, whip_offset=0.4, spin_up=3, whip_timed=2, small_revs=10, opr=20)


def atol_for(rtol):
    return min(1e-9, 1e-3 * rtol)


def _orbit(grid, unbalance_C, speed_rpm):
    b = JournalBearing(**BEARING, grid=tuple(grid))
    return JournalOrbit(b, ROTOR["rotor_mass"], unbalance_C * CLEARANCE, ROTOR["load"], speed_rpm)


def _row(case, label, r, wall, cpu, ref, revs):
    err = float(np.max(np.hypot(r.x - ref.x, r.y - ref.y)) / CLEARANCE) if ref is not None else math.nan
    s = r.stats
    return dict(case=case, label=label, steps_per_rev=s.n_steps / revs, jac_per_rev=s.n_jac / revs,
                res_per_rev=s.n_rhs / revs, wall_per_rev=wall / revs, cpu_per_rev=cpu / revs, error=err,
                ok=bool(r.success), message=r.message)


def _run(o, form, setting, revs, opr, start=None):
    """One candidate: IDA universal at rtol ``setting`` or BDF2 at ``setting`` = (step cap, rtol)."""
    if form == "bdf2":
        cap, rtol = setting
        return o.run(revs, integration=Integration(method="bdf2", rtol=rtol, steps_per_revolution=cap),
                     recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False), start=start)
    return o.run(revs, integration=Integration(rtol=setting, atol=atol_for(setting)),
                 recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False), start=start)


def _label(form, setting):
    return f"IDA universal rtol {setting:.0e}" if form == "ida" else f"BDF2 >= {setting[0]} steps/rev rtol {setting[1]:.0e}"


def _side_by_side(case, o, rtols, bdf2, revs, ref, start=None, opr=20, log=print):
    """IDA at every rtol and BDF2 at every (cap, rtol), alternating (IDA, BDF2, BDF2, IDA, ...)."""
    rows = []
    pairs = list(zip(rtols, bdf2))
    for k, (rt, cap) in enumerate(pairs):
        order = (("ida", rt), ("bdf2", cap)) if k % 2 == 0 else (("bdf2", cap), ("ida", rt))
        for form, setting in order:
            r, w, c = timed(lambda: _run(o, form, setting, revs, opr, start))
            rows.append(_row(case, _label(form, setting), r, w, c, ref, revs)
                        | dict(form="universal" if form == "ida" else "bdf2", setting=setting))
            log(f"  {rows[-1]['label']}: {rows[-1]['steps_per_rev']:.0f} steps/rev, {rows[-1]['jac_per_rev']:.0f} "
                f"jac/rev, {w / revs:.2f} s/rev, error {rows[-1]['error']:.2e} C")
    return rows


def _warm(o):
    for form in ("ida", "bdf2"):  # warm-up (a cold numba cache compiles here), not timed
        _run(o, form, 1e-3 if form == "ida" else (500, 1e-4), 0.05, 20)


def cost_at(rows, form, target, case=None, key="wall_per_rev"):
    """Seconds per revolution (``key``: wall or CPU) for ``form`` to reach ``target`` error (log-log on its points;
    rows of ``case``)."""
    pts = sorted((r["error"], r[key]) for r in rows if r.get("form") == form and r["error"] > 0
                 and case in (None, r["case"]))
    if not pts or target < pts[0][0]:
        return math.nan
    for (e0, w0), (e1, w1) in zip(pts[:-1], pts[1:]):
        if e0 <= target <= e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0)) if e1 > e0 else 0.0
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0)))
    return pts[-1][1]  # even the loosest run is more accurate: an upper bound


def _reference(o, revs, opr, start=None):
    return o.run(revs, integration=Integration(rtol=REF_RTOL, atol=atol_for(REF_RTOL)),
                 recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False), start=start)


def _long(o, revs, opr, bdf2, rtol, start=None):
    """IDA (rtol) and BDF2 ((cap, rtol)) over ``revs`` revolutions, alternating twice; the faster run of each."""
    out = {}
    for form in ("bdf2", "ida", "ida", "bdf2"):
        setting = bdf2 if form == "bdf2" else rtol
        r, w, c = timed(lambda: _run(o, form, setting, revs, opr, start))
        prev = out.get(form)
        if prev is None or w < prev["wall"]:
            out[form] = dict(revolutions=revs, wall=w, cpu=c, steps_per_rev=r.stats.n_steps / revs,
                             jac_per_rev=r.stats.n_jac / revs, setting=setting, ok=bool(r.success),
                             minutes_per_1000_rev=w / revs * 1000 / 60)
    return out


def run(quick=False, log=print) -> dict:
    cfg = dict(QUICK if quick else FULL)
    grid, rtols, bdf2, opr = cfg["grid"], cfg["rtols"], cfg["bdf2"], cfg["opr"]
    out = dict(config=dict(cfg, quick=quick, ref_rtol=REF_RTOL, bdf2_rtol=BDF2_RTOL), rows=[])
    rows = out["rows"]
    out["work_precision"] = work_precision(quick, log)

    # ---- large orbit: 0.3 C from equilibrium --------------------------------------------------------------
    o = _orbit(grid, 0.3, 6000.0)
    _warm(o)
    log(f"[orbit_size] large: 0.3 C, 6000 rpm, {grid[0]} x {grid[1]}; reference IDA rtol {REF_RTOL:g} ...")
    ref, w, _ = timed(lambda: _reference(o, 1, opr))
    out["large_reference"] = dict(wall=w, steps=ref.stats.n_steps, excursion_C=float(np.max(np.hypot(
        ref.x - ref.x[0], ref.y - ref.y[0])) / CLEARANCE))
    rows += _side_by_side("large", o, rtols, bdf2, 1.0, ref, opr=opr, log=log)
    n_rk4 = cfg["rk4_steps"]
    o.run(0.01, integration=Integration(method="rk4", steps_per_revolution=n_rk4), long_run=LongRun(progress=False))
    r, w, c = timed(lambda: o.run(1, integration=Integration(method="rk4", steps_per_revolution=n_rk4),
                                   recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False)))
    rows.append(_row("large", f"RK4 {n_rk4} steps/rev (paper)", r, w, c, ref, 1.0) | dict(form="rk4"))
    log(f"  RK4 {n_rk4}: {w:.1f} s, error {rows[-1]['error']:.2e} C")
    e_rk4, w_rk4 = rows[-1]["error"], rows[-1]["wall_per_rev"]
    c_rk4 = rows[-1]["cpu_per_rev"]
    out["large_matched"] = {f: dict(wall_per_rev=cost_at(rows, f, e_rk4), cpu_per_rev=cost_at(rows, f, e_rk4,
                                                                                              key="cpu_per_rev"))
                            for f in FORMS}
    for f in FORMS:
        m = out["large_matched"][f]
        m["speedup_vs_rk4"] = w_rk4 / m["wall_per_rev"]
        m["cpu_speedup_vs_rk4"] = c_rk4 / m["cpu_per_rev"]

    # ---- oil whip at 1.5x the threshold --------------------------------------------------------------------
    th = o.bearing.stability_threshold(ROTOR["rotor_mass"], ROTOR["load"])
    ow = _orbit(grid, 0.01, 1.5 * th)
    _warm(ow)
    log(f"[orbit_size] whip: 1.5 x threshold ({th:.0f} rpm) = {ow.speed_rpm:.0f} rpm; {cfg['spin_up']} revolutions "
        f"from {cfg['whip_offset']} C off the equilibrium (BDF2) ...")
    y0 = ow.perturbed_start(cfg["whip_offset"])
    sp, w, _ = timed(lambda: ow.run(cfg["spin_up"], integration=Integration(method="bdf2", rtol=BDF2_RTOL),
                                     recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False),
                                     y0=y0))
    eps = sp.eccentricity_ratio
    out["whip_spin_up"] = dict(threshold_rpm=th, speed_rpm=ow.speed_rpm, revolutions=cfg["spin_up"], wall=w,
                               steps=sp.stats.n_steps, eps_last_rev=(float(eps[-opr:].min()), float(eps[-opr:].max())),
                               message=sp.message)
    wref = _reference(ow, 1, opr, start=sp)
    rows += _side_by_side("whip", ow, rtols, bdf2, 1.0, wref, start=sp, opr=opr, log=log)
    out["whip_long"] = _long(ow, cfg["whip_timed"], opr, tuple(cfg["whip_long"]), max(rtols), start=sp)
    for form, v in out["whip_long"].items():
        log(f"  whip {v['revolutions']} revolutions {form}: {v['wall']:.0f} s -> {v['minutes_per_1000_rev']:.0f} min "
            f"per 1000 revolutions")

    # ---- small orbit: the paper's 0.01 C --------------------------------------------------------------------
    os_ = _orbit(grid, 0.01, 6000.0)
    _warm(os_)
    log("[orbit_size] small: 0.01 C, 6000 rpm ...")
    sref = _reference(os_, 1, opr)
    rows += _side_by_side("small", os_, rtols, cfg["small_bdf2"], 1.0, sref, opr=opr, log=log)
    out["small_long"] = _long(os_, cfg["small_revs"], opr, tuple(cfg["small_long"]), max(rtols))
    for case in ("whip", "small"):
        e = next(r["error"] for r in rows if r["case"] == case and r["label"] == _label("ida", max(rtols)))
        out[f"{case}_matched"] = dict(error=e, **{f: cost_at(rows, f, e, case) for f in FORMS},
                                      **{f"{f}_cpu": cost_at(rows, f, e, case, "cpu_per_rev") for f in FORMS})
    for form, v in out["small_long"].items():
        log(f"  small {v['revolutions']} revolutions {form}: {v['wall']:.1f} s, {v['steps_per_rev']:.0f} steps/rev")
    return out


#: Work-precision at the journal's own settings (one run): the cases (unbalance [C], revolutions), IDA's rtols, the
#: BDF at its defaults over rtols (``Integration(method="bdf2", rtol=...)``: variable order up to 5, journal-travel
#: bound) and plain BDF2 at the earlier default (order 2, cap 550 per revolution); the reference IDA at ``WP_REF``.
WP = dict(grid=(76, 11), cases=((0.01, 1.0), (0.05, 1.0), (0.3, 1.0)), ida=(1e-4, 1e-5, 1e-6, 1e-7),
          bdf=(1e-5, 1e-6, 1e-7), bdf_capped=((5000, 1e-8),), bdf2_plain=((550, 1e-4), (550, 1e-6)), opr=20)
WP_QUICK = dict(WP, grid=(48, 8), ida=(1e-4, 1e-6), bdf=(1e-5, 1e-6), bdf_capped=(), bdf2_plain=((550, 1e-6),))
WP_REF = 1e-9


def _wp_run(o, cand, opr):
    kind, setting = cand
    rec, lr = Recording(outputs_per_revolution=opr), LongRun(progress=False)
    if kind == "ida":
        ig = Integration(rtol=setting, atol=atol_for(setting))
    elif kind == "bdf":
        ig = Integration(method="bdf2", rtol=setting)
    elif kind == "bdf_capped":
        ig = Integration(method="bdf2", rtol=setting[1], steps_per_revolution=setting[0])
    else:
        ig = Integration(method="bdf2", rtol=setting[1], steps_per_revolution=setting[0], max_order=2)
    return lambda revs: o.run(revs, integration=ig, recording=rec, long_run=lr)


def _wp_label(kind, setting):
    return {"ida": lambda: f"IDA rtol {setting:.0e}",
            "bdf": lambda: f"BDF (defaults: order <= 5, travel bound) rtol {setting:.0e}",
            "bdf_capped": lambda: f"BDF (order <= 5, cap {setting[0]}) rtol {setting[1]:.0e}",
            "bdf2": lambda: f"BDF2 (order 2, cap {setting[0]}) rtol {setting[1]:.0e}"}[kind]()


def work_precision(quick=False, log=print, cases=None) -> dict:
    """Error against a tight reference (IDA rtol ``WP_REF``) against CPU seconds, IDA at its rtols and the BDF of
    ``method="bdf2"`` at its defaults over rtols (and plain BDF2 at the earlier default), on small and large orbits,
    candidates interleaved in one run; and each one's cost at the error of IDA at rtol 1e-6 (the default's)."""
    cfg = WP_QUICK if quick else WP
    out = dict(config=dict(cfg, ref_rtol=WP_REF), rows=[], matched=[])
    for unb, revs in cases or cfg["cases"]:
        o = _orbit(cfg["grid"], unb, 6000.0)
        _warm(o)
        ref = _reference_at(o, revs, cfg["opr"])
        case = f"{unb:g} C"
        cands = ([("ida", r) for r in cfg["ida"]] + [("bdf", r) for r in cfg["bdf"]]
                 + [("bdf_capped", c) for c in cfg["bdf_capped"]] + [("bdf2", c) for c in cfg["bdf2_plain"]])
        for kind, setting in _interleave(cands):
            r, w, c = timed(lambda: _wp_run(o, (kind, setting), cfg["opr"])(revs))
            row = _row(case, _wp_label(kind, setting), r, w, c, ref, revs) | dict(form=kind, setting=setting)
            out["rows"].append(row)
            log(f"  {case} {row['label']}: {row['steps_per_rev']:.0f} steps, {row['cpu_per_rev']:.2f} s CPU, "
                f"error {row['error']:.2e} C")
        rows = [x for x in out["rows"] if x["case"] == case]
        target = next(x["error"] for x in rows if x["form"] == "ida" and x["setting"] == 1e-6) if 1e-6 in cfg["ida"] \
            else min(x["error"] for x in rows if x["form"] == "ida")
        out["matched"].append(dict(case=case, error=target, ida=_cost_pareto(rows, "ida", target),
                                   bdf=_cost_pareto(rows, ("bdf", "bdf_capped"), target)))
    return out


def _interleave(cands):
    """IDA and BDF candidates alternating (so a change of the machine's load falls on both)."""
    ida = [c for c in cands if c[0] == "ida"]
    other = [c for c in cands if c[0] != "ida"]
    out = []
    for k in range(max(len(ida), len(other))):
        pair = [x[k] for x in (ida, other) if k < len(x)]
        out += pair if k % 2 == 0 else pair[::-1]
    return out


def _cost_pareto(rows, form, target, key="cpu_per_rev"):
    """CPU seconds per revolution for ``form`` (a name or several) to reach ``target`` error, log-log on the lower
    envelope of its points (``nan``: not reached)."""
    forms = (form,) if isinstance(form, str) else form
    pts = [(r["error"], r[key]) for r in rows if r["form"] in forms and r["error"] > 0]
    env = sorted(p for p in pts if not any(q != p and q[0] <= p[0] and q[1] <= p[1] for q in pts))
    if not env or target < env[0][0]:
        return math.nan
    if target >= env[-1][0]:
        return env[-1][1]
    for (e0, w0), (e1, w1) in zip(env[:-1], env[1:]):
        if e0 <= target <= e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0)) if e1 > e0 else 0.0
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0)))
    return math.nan


def _reference_at(o, revs, opr):
    return o.run(revs, integration=Integration(rtol=WP_REF, atol=atol_for(WP_REF)),
                 recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=False))


def wp_markdown(wp) -> str:
    c = wp["config"]
    L = [f"**Work-precision at the journal's own settings** ({c['grid'][0]} x {c['grid'][1]}, 6000 rpm, one revolution "
         f"from the static equilibrium; error = largest journal-centre distance from IDA at rtol {c['ref_rtol']:g} "
         f"[C]; CPU seconds of one process, candidates interleaved):", "",
         "| orbit | run | steps | Jacobians | CPU s | error [C] |", "|---|---|---|---|---|---|"]
    for r in wp["rows"]:
        L.append(f"| {r['case']} | {r['label']} | {r['steps_per_rev']:.0f} | {r['jac_per_rev']:.0f} | "
                 f"{r['cpu_per_rev']:.2f} | {_fmt(r['error'])} |")
    L += ["", "Cost at IDA rtol 1e-6's error (the default's), CPU s per revolution (log-log on each method's lower "
              "envelope; BDF: its defaults and the capped runs): " + "; ".join(f"{m['case']} ({_fmt(m['error'])} C): IDA {_fmt(m['ida'], '{:.2f}')}, BDF "
                                        f"{_fmt(m['bdf'], '{:.2f}')} ({_fmt(m['ida'] / m['bdf'], '{:.1f}')}x)"
                                        for m in wp["matched"]) + "."]
    return "\n".join(L)


def _fmt(v, f="{:.2e}"):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f.format(v)


def _long_text(d):
    return ", ".join(f"{_label(f, v['setting'])} {v['wall']:.1f} s wall, {v['cpu']:.1f} s CPU ({v['steps_per_rev']:.0f} steps and "
                     f"{v['jac_per_rev']:.0f} Jacobians per revolution; {v['minutes_per_1000_rev']:.0f} min per 1000 "
                     f"revolutions)" for f, v in d.items())


def markdown(res) -> str:
    c = res["config"]
    lr, sp = res["large_reference"], res["whip_spin_up"]
    L = [f"Rho & Kim bearing and rotor, {c['grid'][0]} x {c['grid'][1]} half grid. IDA on the universal film "
         f"(atol = min(1e-9, 1e-3 rtol)); BDF2 on the content film (the rtol on the rotor as labelled, film Newton "
         f"tolerance 1e-8 in p0 and content, at least the given steps per revolution); RK4 with the film per stage"
         + (" — **quick smoke run, not the benchmark**" if c["quick"] else "") + ".", "",
         f"References: IDA universal rtol {c['ref_rtol']:g} (large case: {lr['steps']} steps, excursion "
         f"{lr['excursion_C']:.3f} C). Whip: {sp['speed_rpm']:.0f} rpm = 1.5 x the Lund threshold "
         f"{sp['threshold_rpm']:.0f} rpm, after {sp['revolutions']} revolutions (BDF2) from {c['whip_offset']} C off "
         f"the equilibrium (e/C {sp['eps_last_rev'][0]:.3f} - {sp['eps_last_rev'][1]:.3f} over the last one).", "",
         "| case | run | steps/rev | Jacobians/rev | residuals/rev | wall s/rev | CPU s/rev | error [C] |",
         "|---|---|---|---|---|---|---|---|"]
    for r in res["rows"]:
        L.append(f"| {r['case']} | {r['label']} | {r['steps_per_rev']:.0f} | {r['jac_per_rev']:.0f} | "
                 f"{r['res_per_rev']:.0f} | {r['wall_per_rev']:.2f} | {r['cpu_per_rev']:.2f} | {_fmt(r['error'])} |")
    m = res["large_matched"]
    rk4 = next(r for r in res["rows"] if r.get("form") == "rk4")
    L += ["", f"**Large orbit at RK4's error** ({_fmt(rk4['error'])} C, {rk4['wall_per_rev']:.1f} s wall, "
              f"{rk4['cpu_per_rev']:.1f} s CPU): "
          + ", ".join(f"{'IDA universal' if f == 'universal' else 'BDF2'} {m[f]['wall_per_rev']:.2f} s wall "
                      f"({m[f]['speedup_vs_rk4']:.1f}x RK4), {m[f]['cpu_per_rev']:.2f} s CPU "
                      f"({m[f]['cpu_speedup_vs_rk4']:.1f}x RK4)" if math.isfinite(m[f]["wall_per_rev"])
                      else f"{f}: RK4's error not reached at the settings run" for f in FORMS)
          + " (a candidate whose loosest run is already more accurate is charged that run).",
          *(f"**{case.capitalize()} at IDA rtol {max(c['rtols']):.0e}'s error** ({_fmt(res[case + '_matched']['error'])} C): "
            + ", ".join(f"{'IDA universal' if f == 'universal' else 'BDF2'} {_fmt(res[case + '_matched'][f], '{:.2f}')} "
                        f"s wall / {_fmt(res[case + '_matched'][f + '_cpu'], '{:.2f}')} s CPU per revolution"
                        for f in FORMS) + "." for case in ("whip", "small")),
          f"**Whip, {c['whip_timed']} revolutions** (the faster of two alternating runs): "
          + _long_text(res["whip_long"]) + ".",
          f"**Small orbit, {c['small_revs']} revolutions** (the faster of two alternating runs): "
          + _long_text(res["small_long"]) + "."]
    L += ["", wp_markdown(res["work_precision"])]
    short = [f"{k} = {c[k]} (the benchmark's {FULL[k]})" for k in ("whip_timed", "small_revs")
             if not c["quick"] and c[k] != FULL[k]]
    if short:
        L.append("**Shortened long runs** (a shared 2-core machine; the per-revolution figures above are unaffected): " + ", ".join(short) + ".")
    return "\n".join(L)


def plot(res, path):
    from transient.plots import figure, save

    fig, axes = figure(1, 3, size=(15, 4.2))
    for ax, case in zip(axes, ("large", "whip", "small")):
        for form, mk, name in (("universal", "o-", "IDA universal"), ("bdf2", "s-", "BDF2 content")):
            pts = sorted((r["wall_per_rev"], r["error"]) for r in res["rows"] if r["case"] == case
                         and r.get("form") == form)
            if pts:
                ax.loglog(*zip(*pts), mk, label=name)
        for r in res["rows"]:
            if r["case"] == case and r.get("form") == "rk4":
                ax.loglog(r["wall_per_rev"], r["error"], "k*", ms=10, label=r["label"])
        ax.set(xlabel="wall s per revolution", ylabel="error [C]", title=case)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
    return save(fig, path)


def main(out, quick=False) -> str:
    res = run(quick=quick)
    save_raw(out, "orbit_size", res)
    plot(res, Path(out) / "bench_orbit_size.png")
    return f"## {TITLE}\n\n{markdown(res)}\n\n![work-precision](bench_orbit_size.png)\n"
