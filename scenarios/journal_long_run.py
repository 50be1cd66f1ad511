"""Long orbit study: many revolutions of the rotor of Rho & Kim, "Noise estimation of oil lubricated journal
bearings", crash-safe.

    transient run scenarios/journal_long_run.py [--quick] [--out DIR] [--revolutions 10000] [--grid 151 21]
                                                [--rpm 6000] [--method ida] [--rtol 1e-5] [--fresh]

A progress bar over the revolutions (eccentricity ratio, time left); only the journal centre and the film
force are kept, at --outputs samples per revolution; a checkpoint (DIR/orbit_checkpoint.npz) is rewritten
every --chunk revolutions. Killed or interrupted (Ctrl-C) at any moment, the same command resumes from the
last checkpoint with nothing lost (--fresh starts over). At the end: DIR/long_run.png (eccentricity envelope
per revolution and the last orbit) and DIR/long_run.npz (the saved result: transient.load_result reads it).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Recording
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import journal as plots, save
from transient.study.scenario import fresh_advice, log, parser

OUT = "journal_long"  # output folder name: ROOT/journal_long (transient.study.scenario)


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--revolutions", type=float, help="revolutions (default 10000; quick 40)")
    ap.add_argument("--grid", type=int, nargs=2, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 41 6)")
    ap.add_argument("--rpm", type=float, default=6000.0)
    ap.add_argument("--method", default="ida", choices=("cvode", "ida", "bdf", "lsoda", "rk4"))
    ap.add_argument("--rtol", type=float, default=1e-5)
    ap.add_argument("--outputs", type=int, default=20, help="samples per revolution kept in memory")
    ap.add_argument("--chunk", type=float, default=20.0, help="revolutions between checkpoints")
    ap.add_argument("--fresh", action="store_true", help="ignore an existing checkpoint")
    a = ap.parse_args(argv)
    announce("journal")
    revolutions = a.revolutions or (40.0 if a.quick else 10000.0)
    grid = tuple(a.grid) if a.grid else ((41, 6) if a.quick else (151, 21))
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    ckpt = out / "orbit_checkpoint.npz"
    if a.fresh and ckpt.exists():
        ckpt.unlink()
    o = JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=grid), speed_rpm=a.rpm, **rho_kim.ROTOR)
    log(f"[long run] {revolutions:g} revolutions at {a.rpm:g} rpm, grid {grid[0]} x {grid[1]}, {a.method} rtol "
        f"{a.rtol:g}; checkpoint {ckpt}" + (" (resuming)" if ckpt.exists() else ""))
    t0 = time.perf_counter()
    with fresh_advice():
        r = o.run(revolutions, integration=Integration(method=a.method, rtol=a.rtol, atol=1e-3 * a.rtol),
                  recording=Recording(outputs_per_revolution=a.outputs, record=("force",)),
                  long_run=LongRun(chunk_revolutions=a.chunk, checkpoint=ckpt, resume=True, progress=True))
    log(f"[long run] {r.message}; {time.perf_counter() - t0:.1f} s this run, {r.t.size} samples kept")
    r.save(out / "long_run.npz")
    log(f"written: {save(plots.long_run(r, a.outputs), out / 'long_run.png')} and {out / 'long_run.npz'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
