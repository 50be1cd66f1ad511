"""Oil whip of the rotor of Rho & Kim, "Noise estimation of oil lubricated journal bearings": run-up through
the Lund threshold, long runs above it.

    transient run scenarios/journal_whip.py [--quick] [--out DIR] [--grid 151 21] [--revolutions 300]
                                            [--rtol 1e-4] [--method bdf2|ida] [--fresh]

1. The Lund threshold of the bearing (linearised K, C from the discrete film).
2. A quasi-static run-up from 0.8 to 1.6 times the threshold: constant-speed segments, each continuing the
   previous state (film content and journal velocity carried over, unbalance phase kept); per speed the
   eccentricity range over the last revolutions, whether it settled (a limit cycle) and the whirl frequency
   ratio (~0.5 above the threshold).
3. Long runs at 1.2x and 1.5x the threshold from the static equilibrium, checkpointed (killed or
   interrupted, the same command resumes; --fresh starts over): the whirl amplitude, whether it is a limit
   cycle, the whirl frequency ratio, the Poincare section (centre once per revolution), the smallest film and the touch
   event (the run stops with a message if the journal reaches e/C = 1 - 1e-3).
Every run is integrated by BDF2 on the content film (--method ida: by IDA): the same whirl numbers and verdicts,
at ~8x less CPU on 64 x 8 and ~15x per whip revolution on 151 x 21 (docs/journal.md).
"Limit cycle" is printed only when the eccentricity envelope (max and min over a block of 4 revolutions)
moved by less than 1e-3 C per revolution between the last two blocks; otherwise "NOT settled" with the
measured growth.

Writes DIR/run_up.png, DIR/whirl_1.2x.png, DIR/whirl_1.5x.png, DIR/whip.json (every number) and the saved
results DIR/run_up.npz, DIR/whirl_*.npz (transient.load_result reads them).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import JournalBearing, JournalOrbit
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import save, whip as plots
from transient.study.scenario import JsonRecord, fresh_advice, log, parser
from transient.study.whip import ENVELOPE_TOL, METHOD, METHODS, long_whip, run_up, settled_text

OUT = "journal_whip"  # output folder name: ROOT/journal_whip (transient.study.scenario)
OPR = 64  # outputs per revolution
QUICK_REVOLUTIONS = 10.0  # of each long run with --quick: the whirl is still growing (reported as not settled)


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--grid", type=int, nargs=2, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 32 6)")
    ap.add_argument("--revolutions", type=float, help="revolutions of each long run (default 300; quick 10)")
    ap.add_argument("--rtol", type=float, default=1e-4)
    ap.add_argument("--method", default=METHOD, choices=METHODS,
                    help=f"integrator of every run (JournalOrbit.run(method=); default {METHOD})")
    ap.add_argument("--fresh", action="store_true", help="ignore existing checkpoints")
    a = ap.parse_args(argv)
    announce("journal")
    grid = tuple(a.grid) if a.grid else ((32, 6) if a.quick else (151, 21))
    revs = a.revolutions or (QUICK_REVOLUTIONS if a.quick else 300.0)
    steps, per_step = (5, 3) if a.quick else (9, 20)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    rec = JsonRecord(out / "whip.json", dict(grid=grid, revolutions=revs, rtol=a.rtol, method=a.method, quick=a.quick))
    bearing = JournalBearing(**rho_kim.BEARING, grid=grid)
    make = lambda rpm: JournalOrbit(bearing, speed_rpm=rpm, **rho_kim.ROTOR)  # noqa: E731
    t0 = time.perf_counter()
    th = bearing.stability_threshold(rho_kim.ROTOR["rotor_mass"], rho_kim.ROTOR["load"])
    log(f"[whip] grid {grid[0]} x {grid[1]}, {a.method} rtol {a.rtol:g}: Lund threshold {th:.1f} rpm (paper ~{rho_kim.REPORTED['threshold_rpm']:g})")
    rec.put("threshold_rpm", th)

    speeds = th * np.linspace(0.8, 1.6, steps)
    log(f"[whip] run-up {speeds[0]:.0f} ... {speeds[-1]:.0f} rpm, {per_step} revolutions per speed")
    ru = run_up(make, speeds, per_step, rtol=a.rtol, outputs_per_revolution=OPR, threshold_rpm=th, method=a.method)
    ru.save(out / "run_up.npz")
    rec.put("run_up", dict(speeds_rpm=ru.speeds, speed_over_threshold=ru.speeds / th, eps_min=ru.eps_min,
                           eps_max=ru.eps_max, whirl_ratio=ru.whirl_ratio, envelope_growth=ru.envelope_growth,
                           settled=ru.settled, steps_per_revolution=ru.steps_per_revolution, message=ru.message))
    for s, lo, hi, wr, g, ok in zip(ru.speeds, ru.eps_min, ru.eps_max, ru.whirl_ratio, ru.envelope_growth, ru.settled):
        verdict = "settled" if ok else "NOT settled"
        log(f"  {s:7.0f} rpm ({s / th:.2f}x): e/C {lo:.3f} - {hi:.3f} over the last revolutions, {verdict} "
            f"(envelope {g:+.1e} C/rev, tolerance {ENVELOPE_TOL:g}), whirl ratio {wr:.3f}")
    log(f"written: {save(plots.run_up(ru), out / 'run_up.png')}")

    for factor in (1.2, 1.5):
        tag = f"{factor:g}x"
        ckpt = out / f"whirl_{tag}_{a.method}_checkpoint.npz"
        if a.fresh and ckpt.exists():
            ckpt.unlink()
        o = make(factor * th)
        log(f"[whip] {revs:g} revolutions at {o.speed_rpm:.0f} rpm ({tag} threshold); checkpoint {ckpt}")
        with fresh_advice():
            r, w = long_whip(o, revs, rtol=a.rtol, outputs_per_revolution=OPR, checkpoint=ckpt,
                             chunk_revolutions=10.0, method=a.method)
        r.save(out / f"whirl_{tag}.npz")
        rec.put(f"whirl_{tag}", w)
        touch = "no touch" if w["touched_at_s"] is None else f"touches at t = {w['touched_at_s']:.4f} s"
        log(f"  {r.message}; e/C {w['eps_min']:.4f} - {w['eps_max']:.4f} over the last {w['last_revolutions']} rev: "
            f"{settled_text(w)}; whirl ratio "
            f"{w['whirl_ratio']:.3f}, min film {w['min_film_m'] * 1e6:.2f} um, {touch}; "
            f"{w['steps'] / max(w['revolutions'], 1):.0f} steps per revolution, {w['wall_s']:.0f} s")
        log(f"written: {save(plots.whirl(r, w, OPR, label=f'{tag} threshold, '), out / f'whirl_{tag}.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[whip] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'whip.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
