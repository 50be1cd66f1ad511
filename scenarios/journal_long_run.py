"""Long orbit study (seed 003): many revolutions of the Rho & Kim rotor, crash-safe.

    transient run scenarios/journal_long_run.py [--revolutions 10000] [--grid 151 21] [--rpm 6000]
                                                [--method ida] [--rtol 1e-5] [--out DIR] [--fresh]

Prints progress after every chunk (revolutions done, eccentricity ratio, seconds per revolution), keeps
in memory only the journal centre and the film force at ``--outputs`` samples per revolution (no field
history), and rewrites a checkpoint (``DIR/orbit_checkpoint.npz``) after every chunk. Killed at any
moment, the same command resumes from the last checkpoint with nothing lost (``--fresh`` starts over).
At the end it writes ``DIR/long_run.png`` (eccentricity envelope per revolution and the last orbit) and
``DIR/long_run.npz`` (t, x, y, force).
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "out", "journal_long")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--revolutions", type=float, default=10000.0)
    ap.add_argument("--grid", type=int, nargs=2, default=(151, 21), metavar=("NT", "NZ"))
    ap.add_argument("--rpm", type=float, default=6000.0)
    ap.add_argument("--method", default="ida", choices=("cvode", "ida", "bdf", "lsoda", "rk4"))
    ap.add_argument("--rtol", type=float, default=1e-5)
    ap.add_argument("--outputs", type=int, default=20, help="samples per revolution kept in memory")
    ap.add_argument("--chunk", type=float, default=20.0, help="revolutions between checkpoints")
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--fresh", action="store_true", help="ignore an existing checkpoint")
    a = ap.parse_args(argv)
    if a.revolutions <= 0 or a.chunk <= 0 or a.outputs < 1:
        ap.error("--revolutions and --chunk must be > 0 and --outputs >= 1")
    os.makedirs(a.out, exist_ok=True)
    ckpt = os.path.join(a.out, "orbit_checkpoint.npz")
    if a.fresh and os.path.exists(ckpt):
        os.remove(ckpt)
    b = JournalBearing(**RHO_KIM_BEARING, grid=tuple(a.grid))
    o = JournalOrbit(b, speed_rpm=a.rpm, **RHO_KIM_ROTOR)
    resuming = os.path.exists(ckpt)
    print(f"[long run] {a.revolutions:g} revolutions at {a.rpm:g} rpm, grid {a.grid[0]} x {a.grid[1]}, "
          f"{a.method} rtol {a.rtol:g}; checkpoint {ckpt}" + (" (resuming)" if resuming else ""), flush=True)
    t0 = time.perf_counter()
    r = o.run(a.revolutions, method=a.method, rtol=a.rtol, atol=1e-3 * a.rtol, outputs_per_revolution=a.outputs,
              record=("force",), chunk_revolutions=a.chunk, checkpoint=ckpt, resume=True, progress=True)
    print(f"[long run] {r.message}; {time.perf_counter() - t0:.1f} s this session, {r.t.size} samples kept",
          flush=True)
    np.savez(os.path.join(a.out, "long_run.npz"), t=r.t, x=r.x, y=r.y, force=r.force)
    _plot(r, a, os.path.join(a.out, "long_run.png"))
    print(f"written: {os.path.join(a.out, 'long_run.png')}")
    return 0


def _plot(r, a, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    eps = r.eccentricity_ratio
    rev = r.revolutions
    k = np.floor(rev - 1e-9).astype(int)
    n_rev = int(k.max()) + 1 if k.size else 0
    lo = np.array([eps[k == i].min() for i in range(n_rev)])
    hi = np.array([eps[k == i].max() for i in range(n_rev)])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    ax1.fill_between(np.arange(1, n_rev + 1), lo, hi, alpha=0.4, label="min..max per revolution")
    ax1.set_xlabel("revolution")
    ax1.set_ylabel("eccentricity ratio e/C")
    ax1.set_title(f"{a.rpm:g} rpm, {n_rev} revolutions")
    ax1.legend()
    last = rev > rev[-1] - 1.0
    ax2.plot(r.y[last] / r.clearance, r.x[last] / r.clearance)
    ax2.invert_yaxis()
    ax2.set_xlabel("y / C")
    ax2.set_ylabel("x / C (towards the load)")
    ax2.set_title("last revolution")
    ax2.set_aspect("equal", adjustable="datalim")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
