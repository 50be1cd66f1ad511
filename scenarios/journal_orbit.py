"""Rho & Kim, "Noise estimation of oil lubricated journal bearings": unbalance orbit of a rigid rotor on the Elrod
journal bearing, Figs. 3, 4, 8 and the stability threshold.

    transient run scenarios/journal_orbit.py [--quick] [--out DIR] [--grid NT NZ] [--rtol R] [--resume]
                                             [--only fig3 fig8 stability] [--settle]

Default: the paper's 151 x 21 half grid; figures and journal_orbit.json in transient_out/journal/.
* Fig. 3: orbit from the static equilibrium at 6000 rpm settling onto the ellipse; Fig. 4: spectrum of x(t)
  over an integer number of revolutions of the settled orbit (transient.study.journal.orbit_from_equilibrium);
* Fig. 8: unbalance response amplitude against speed, 1000-7500 rpm in 250 rpm steps: periodic orbits by
  shooting and continuation in speed, continued until the dominant Floquet multiplier leaves the unit circle
  (the onset of whirl of the periodic orbit, refined by secant steps), the whirl past it integrated in time
  (transient.study.journal.continuation_response); --settle: settled orbits from the linear start instead
  (the former way); lines: the linearised K, C response;
* stability: the linear (Lund) threshold bracketed by free-vibration runs of a perturbed, balanced rotor
  just below and above it (decay vs growth, against the linear growth rate), beside the periodic onset.
The JSON is rewritten after every stage (and sweep speed with --settle); --resume reuses those points.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import JournalBearing, JournalOrbit
from transient.analysis.orbits import peak_abscissa
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import journal as plots, save
from transient.study.journal import (continuation_response, linear_response_curve, orbit_from_equilibrium,
                                     settled_unbalance_orbit, stability_run)
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal"  # output folder name: ROOT/journal (transient.study.scenario)
ROTOR, PAPER = rho_kim.ROTOR, rho_kim.REPORTED
PERTURB = 0.01  # initial offset of the balanced rotor in the stability runs [C]
OPR = 64  # outputs per revolution (spectrum up to 32x)
FULL = dict(grid=(151, 21), fig3_revs=30, fft_revs=10, speeds=tuple(range(1000, 7501, 250)), whirl_revs=120,
            sweep_min_revs=4, sweep_max_revs=40, stab_revs=20, stab_factor=0.1, linear_speeds=40)
QUICK = dict(grid=(41, 6), fig3_revs=12, fft_revs=4, speeds=(1000, 3000, 5000, 6000, 7500), whirl_revs=40,
             sweep_min_revs=3, sweep_max_revs=8, stab_revs=8, stab_factor=0.15, linear_speeds=15)


def orbit(bearing, speed, unbalance=ROTOR["unbalance"]):
    return JournalOrbit(bearing, rotor_mass=ROTOR["rotor_mass"], unbalance=unbalance, load=ROTOR["load"], speed_rpm=speed)


def fig3_fig4(bearing, cfg, rtol, out, rec):
    o = orbit(bearing, PAPER["speed_rpm"])
    log(f"[fig 3] {o.speed_rpm:g} rpm, {cfg['fig3_revs']} revolutions from the equilibrium (IDA rtol {rtol:g}) ...")
    r = orbit_from_equilibrium(o, cfg["fig3_revs"], rtol, OPR, cfg["fft_revs"])
    rec.put("fig3_fig4", r.record())
    r.orbit.save(out / "orbit_6000rpm.npz")
    save(plots.orbit_settling(r, OPR, bearing.grid_shape), out / "journal_fig3_orbit.png")
    save(plots.x_spectrum(r), out / "journal_fig4_spectrum.png")
    so = r.settled_orbit
    log(f"[fig 3] {r.wall_s:.1f} s; semi-axes {so['semi_major']:.4f} / {so['semi_minor']:.4f} C, {r.settling()}; "
        f"[fig 4] peak at {r.spectrum_peak_order:g}x, "
        f"2x/1x = {r.ratio_2x_to_1x:.2e}")


def fig8(bearing, cfg, rtol, out, rec, settle=False):
    old = rec.data.get("fig8", {})
    sweep = {int(p["speed_rpm"]): p for p in old.get("points", [])}
    sp = cfg["speeds"]
    lin = old.get("linear") or linear_response_curve(bearing, ROTOR, np.linspace(min(sp), max(sp), cfg["linear_speeds"]))
    if not settle:
        log(f"[fig 8] continuation over {len(sp)} speeds {sp[0]}-{sp[-1]} rpm (rtol {rtol:g}) ...")
        curve, r = continuation_response(bearing, ROTOR, sp, rtol, OPR, whirl_revolutions=cfg["whirl_revs"], progress=True)
        curve.save(out / "fig8_response_curve.npz")
        sweep = {int(p["speed_rpm"]): p for p in r.pop("points")}
        rec.put("periodic_onset", r)
        log(f"[fig 8] {r['wall_s']:.1f} s, {r['periods']} periods in all; the periodic orbit loses stability at "
            f"{r['onset_rpm'] or float('nan'):.0f} rpm (paper ~{PAPER['threshold_rpm']:g}); past it: "
            + "; ".join(f"{b['speed_rpm']:.0f} rpm whirl {b['whirl_frequency_ratio']:.3f}x" for b in r["beyond"][-1:]))
    for s in sp if settle else ():
        if s in sweep:
            continue
        u = settled_unbalance_orbit(orbit(bearing, s), rtol, OPR, cfg["sweep_min_revs"], cfg["sweep_max_revs"])
        sweep[s] = dict(speed_rpm=s, revolutions=u.revolutions, settle_estimate=u.settle_estimate, n_steps=u.n_steps,
                        wall_s=u.wall_s, settled=u.success, **u.shape)
        rec.put("fig8", dict(points=[sweep[k] for k in sorted(sweep)], linear=lin))
        log(f"[fig 8] {s:5d} rpm: semi-major {u.shape['semi_major']:.4f} C; {u.message}; {u.wall_s:.1f} s")
    for s, p in sweep.items():
        (lp,) = linear_response_curve(bearing, ROTOR, [s])
        p.update(linear_amp_x=lp["amp_x"], linear_amp_y=lp["amp_y"], linear_semi_major=lp["semi_major"])
    pts = [sweep[k] for k in sorted(sweep)]
    keys = ("semi_major", "amp_x", "amp_y")
    peak = {k: peak_abscissa([p["speed_rpm"] for p in pts], [p[k] for p in pts]) for k in keys}
    peak_lin = {k: peak_abscissa([p["speed_rpm"] for p in lin], [p[k] for p in lin]) for k in keys}
    rec.put("fig8", dict(points=pts, linear=lin, peak_speed_rpm=peak, linear_peak_speed_rpm=peak_lin))
    save(plots.unbalance_response(pts, lin, peak, PAPER["peak_speed_rpm"]), out / "journal_fig8_response.png")
    log(f"[fig 8] peak at {peak['semi_major']:.0f} rpm (linear {peak_lin['semi_major']:.0f}; paper ~{PAPER['peak_speed_rpm']:g})")


def stability(bearing, cfg, rtol, out, rec):
    t0 = time.perf_counter()
    th = bearing.stability_threshold(rotor_mass=ROTOR["rotor_mass"], load=ROTOR["load"])
    log(f"[stability] linear threshold {th:.0f} rpm ({time.perf_counter() - t0:.1f} s; paper ~{PAPER['threshold_rpm']:g})")
    runs = []
    for f in (1 - cfg["stab_factor"], 1 + cfg["stab_factor"]):
        _, r = stability_run(orbit(bearing, f * th, unbalance=0.0), PERTURB, cfg["stab_revs"], rtol, OPR)
        runs.append(r)
        log(f"[stability] {r['speed_rpm']:.0f} rpm: {r['growth_per_rev']:+.4f}/rev (linear "
            f"{r['linear_growth_per_rev']:+.4f}) -> {r['verdict']}")
    st = dict(threshold_rpm=th, runs=runs)
    a, b = runs
    if a["growth_per_rev"] < 0 < b["growth_per_rev"]:
        st["transient_threshold_rpm"] = a["speed_rpm"] - a["growth_per_rev"] * (b["speed_rpm"] - a["speed_rpm"]) / (
            b["growth_per_rev"] - a["growth_per_rev"])
        log(f"[stability] zero growth between the runs at {st['transient_threshold_rpm']:.0f} rpm")
    st["periodic_onset_rpm"] = rec.data.get("periodic_onset", {}).get("onset_rpm")
    log(f"[stability] Lund {th:.0f} rpm, periodic orbit (Floquet) {st['periodic_onset_rpm'] or float('nan'):.0f} rpm, "
        f"paper ~{PAPER['threshold_rpm']:g} rpm")
    rec.put("stability", st)
    save(plots.stability_runs(runs, th, PAPER["threshold_rpm"]), out / "journal_stability.png")


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--grid", nargs=2, type=int, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 41 6)")
    ap.add_argument("--rtol", type=float, default=1e-5, help="IDA relative tolerance (default 1e-5)")
    ap.add_argument("--resume", action="store_true", help="reuse the sweep points already in the JSON")
    ap.add_argument("--only", choices=("fig3", "fig8", "stability"), nargs="+", help="run only these stages")
    ap.add_argument("--settle", action="store_true", help="Fig. 8 by settling runs instead of continuation")
    a = ap.parse_args(argv)
    announce("journal")
    cfg = dict(QUICK if a.quick else FULL)
    if a.grid:
        cfg["grid"] = tuple(a.grid)
    out = Path(a.out)
    meta = dict(grid=list(cfg["grid"]), quick=a.quick, rtol=a.rtol, settle=a.settle, bearing=rho_kim.BEARING, rotor=ROTOR,
                speeds=list(cfg["speeds"]))
    rec = JsonRecord(out / "journal_orbit.json", meta, a.resume)
    bearing = JournalBearing(**rho_kim.BEARING, grid=cfg["grid"])
    log(f"journal orbit scenarios: grid {cfg['grid'][0]} x {cfg['grid'][1]}, rtol {a.rtol:g}, out {out}")
    t0 = time.perf_counter()
    for stage, run in (("fig3", fig3_fig4), ("fig8", fig8), ("stability", stability)):
        if stage in (a.only or (stage,)):
            run(bearing, cfg, a.rtol, out, rec, **(dict(settle=a.settle) if stage == "fig8" else {}))
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"total {time.perf_counter() - t0:.0f} s; numbers in {rec.path}, figures in {out}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
