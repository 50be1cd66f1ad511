"""The upper fold of the damper's jump: the circular orbits on refined circumferential grids against the whole
system's periodic orbits, traced in speed by pseudo-arclength continuation of the shooting.

    transient run scenarios/damper_upper_fold.py [--quick] [--out DIR]

The rotor of ``scenarios/damper_jump.py`` (20 kg on one end-fed, cavitated squeeze-film damper). The circular orbits
(each film steady in the whirling frame) are traced from 4000 rpm upwards (the upper branch) and from the top speed
downwards (the lower branch, its fold, and the saddle branch back up) on each grid; the whole system's orbits (films
and rotor, BDF2 period map) are traced from the upper branch at 6000 rpm upwards on 24 x 4 cells
(``models/rotor/periodic_branch.py``), with their Floquet multipliers. Writes DIR/damper_upper_fold.png and
DIR/damper_upper_fold.json.
"""

from __future__ import annotations

import importlib
import sys
import time
from pathlib import Path

import numpy as np

from transient.models.rotor.circular_orbits import orbits_at_speed
from transient.models.rotor.periodic_branch import trace_branch
from transient.plots import damper as plots
from transient.plots import save
from transient.study.scenario import JsonRecord, log, parser

sys.path.insert(0, str(Path(__file__).parent))
jump = importlib.import_module("damper_jump")  # the rotor of the jump scenario

OUT = "damper_upper_fold"
START_RPM = 6000.0


def circular(grid, top_rpm):
    """The circular orbits on ``grid`` up from 4000 rpm and down from ``top_rpm``: {label: curve}."""
    s = jump.system(grid)
    out = {}
    for start in (4000.0, top_rpm):
        t0 = time.process_time()
        c = s.circular_orbits((3000.0, top_rpm), start_rpm=start, max_step=0.1)
        log(f"  circular orbits {grid[0]}x{grid[1]} from {start:.0f} rpm: {c.speed_rpm.size} points, folds at "
            f"{', '.join(f'{f:.1f} rpm (e/c {e:.4f})' for f, e in zip(c.folds_rpm, c.fold_eccentricity)) or 'none'}; "
            f"{time.process_time() - t0:.0f} s CPU")
        out[start] = c
    return out


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    top = 9000.0 if a.quick else 16000.0
    grids = [(24, 4), (48, 4)] if a.quick else [(24, 4), (48, 4), (96, 8)]
    rec = JsonRecord(out / "damper_upper_fold.json", dict(grids=grids, quick=a.quick, damper=jump.DAMPER))
    curves = {}
    for g in grids:
        for start, c in circular(g, top).items():
            curves[f"circular orbits {g[0]}x{g[1]} from {start:.0f} rpm"] = c
            rec.put(f"circular_{g[0]}x{g[1]}_from_{start:.0f}", dict(
                speed_rpm=c.speed_rpm, eccentricity_ratio=c.eccentricity_ratio[:, 0],
                transmitted_force=c.transmitted_force[:, 0], folds_rpm=c.folds_rpm,
                fold_eccentricity=c.fold_eccentricity))
    s = jump.system()
    c = curves["circular orbits 24x4 from 4000 rpm"]
    t0 = time.process_time()
    b = trace_branch(s, START_RPM, (3000.0, top), s.circular_orbit_state(START_RPM, orbits_at_speed(s, c, START_RPM)[0]),
                     step=0.05, max_step=0.2, max_points=6 if a.quick else 30)
    eps = b.radius[:, 0] / jump.C
    log(f"  the whole system's branch (24x4): {b.speed_rpm.size} points {b.speed_rpm.min():.0f}-{b.speed_rpm.max():.0f} "
        f"rpm, e/c {eps.min():.4f}-{eps.max():.4f}, |mu| {b.max_multiplier.min():.3f}-{b.max_multiplier.max():.3f}, "
        f"folds {b.folds_rpm}; {b.periods} periods, {time.process_time() - t0:.0f} s CPU; {b.message}")
    rec.put("system_branch", dict(speed_rpm=b.speed_rpm, eccentricity_ratio=eps, max_multiplier=b.max_multiplier,
                                  multipliers=np.abs(b.multipliers), folds_rpm=b.folds_rpm, periods=b.periods,
                                  message=b.message))
    title = ("rigid rotor 20 kg on a squeeze-film damper (scenarios/damper_jump.py): circular orbits on refined grids "
             "and the whole system's branch (24x4, shooting continued in speed)")
    log(f"written: {save(plots.upper_fold(curves, b.speed_rpm, eps, b.max_multiplier, title), out / 'damper_upper_fold.png')}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
