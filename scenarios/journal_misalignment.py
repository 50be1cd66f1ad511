"""A misaligned journal bearing: the pressure map, the minimum film at the edge, the moments against the tilt.

    transient run scenarios/journal_misalignment.py [--quick] [--out DIR]

Pfeil's demonstration bearing (D 0.1 m, L 0.08 m, C 150 um, 0.01 Pa s, 3000 rpm; his 15-deg groove 0.06 m long,
90 deg after the minimum film, at 70 kPa; the ends at the cavitation pressure), the journal held at e/C 0.5 on the
load line (+x) and tilted about y (its centre moves along the load line across the length) up to the tilt that
brings the film at one end to 0.3 C. Elrod film (the whole length when tilted). Writes DIR/journal_misalignment.png and DIR/journal_misalignment.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import Groove, JournalBearing
from transient.plots import save, tilt as plots
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_misalignment"  # output folder name: ROOT/journal_misalignment (transient.study.scenario)
BEARING = dict(diameter=0.1, length=0.08, clearance=150e-6, viscosity=0.01, supply_pressure=70e3,
               ambient_pressure=0.0, cavitation_pressure=0.0, groove=Groove(270.0, 15.0, length=0.06))
SPEED_RPM = 3000.0
ECCENTRICITY = 0.5


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (48, 8) if a.quick else (144, 24)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    b = JournalBearing(**BEARING, grid=grid)
    C, half = BEARING["clearance"], 0.5 * BEARING["length"]
    edge = 0.2 * C / half  # the tilt about y that takes one end from e/C 0.5 to 0.7: a film of 0.3 C there
    tilts = np.linspace(0.0, edge, 4 if a.quick else 9)
    rec = JsonRecord(out / "journal_misalignment.json", dict(grid=grid, quick=a.quick, speed_rpm=SPEED_RPM,
                                                             eccentricity_ratio=ECCENTRICITY,
                                                             bearing={k: v for k, v in BEARING.items() if k != "groove"}))
    states = [b.steady_state(ECCENTRICITY, SPEED_RPM, tilt=(0.0, t)) for t in tilts]
    for t, s in zip(tilts, states):
        log(f"  tilt {1e3 * t:.3f} mrad: force ({s.force[0]:.1f}, {s.force[1]:.1f}) N, moment ({s.moment[0]:.2f}, "
            f"{s.moment[1]:.2f}) N m, h_min {1e6 * s.min_film:.1f} um, p_max {1e-6 * s.max_pressure:.2f} MPa")
    rec.put("tilt", tilts)
    rec.put("force", [s.force for s in states])
    rec.put("moment", [s.moment for s in states])
    rec.put("min_film", [s.min_film for s in states])
    rec.put("max_pressure", [s.max_pressure for s in states])
    maps = {"aligned": states[0], f"tilted {1e3 * edge:.2f} mrad about y": states[-1]}
    title = (f"misaligned journal, D 0.1 m, L 0.08 m, C 150 um, 3000 rpm, e/C {ECCENTRICITY} on the load line, "
             f"grid {grid[0]}x{2 * grid[1]} (Elrod film; white line: edge of the cavitated film)")
    fig = plots.misalignment(maps, 1e3 * tilts, [s.moment for s in states], [s.min_film for s in states], title)
    log(f"written: {save(fig, out / 'journal_misalignment.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[journal misalignment] done in {time.perf_counter() - t0:.0f} s; numbers in "
        f"{out / 'journal_misalignment.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
