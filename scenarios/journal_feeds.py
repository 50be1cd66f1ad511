"""Oil feed of a plain journal bearing: full groove, 3/4-length groove, two grooves at +-90 deg, an oil hole.

    transient run scenarios/journal_feeds.py [--quick] [--out DIR]

Pfeil's demonstration bearing (D 0.1 m, L 0.08 m, C 150 um, 0.01 Pa s, 3000 rpm; the oil supplied at 70 kPa above
an ambient at the cavitation pressure), 15-deg grooves, a hole of L/4 diameter; the load acts downwards (away from
the top, 0 deg). For each feed and load: the static equilibrium's eccentricity, attitude, minimum film, supply flow
and side leakage (Elrod film; the steady mass balance supply = leakage is checked at every point).
Writes DIR/journal_feeds.png and DIR/journal_feeds.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient.plots import feeds as plots, save
from transient.study.feeds import feed_designs, feed_sweep
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_feeds"  # output folder name: ROOT/journal_feeds (transient.study.scenario)
BEARING = dict(diameter=0.1, length=0.08, clearance=150e-6, viscosity=0.01, supply_pressure=70e3,
               ambient_pressure=0.0, cavitation_pressure=0.0)
SPEED_RPM = 3000.0


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (48, 8) if a.quick else (144, 24)
    loads = np.geomspace(200.0, 40e3, 5 if a.quick else 12)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rec = JsonRecord(out / "journal_feeds.json", dict(grid=grid, quick=a.quick, bearing=BEARING, speed_rpm=SPEED_RPM))
    feeds = feed_designs(BEARING["length"])
    res = feed_sweep(dict(BEARING, grid=grid), feeds, loads, SPEED_RPM)
    for name, r in res.items():
        rec.put(name, dict(r, loads=loads, feed=repr(feeds[name])))
        worst = np.nanmax(np.abs(r["balance"]))
        log(f"  {name}: mass balance (supply - leakage) / leakage within {worst:.1e}")
        for i, W in enumerate(loads):
            log(f"    {W:8.0f} N: e/C {r['eccentricity_ratio'][i]:.3f}, attitude {r['attitude_angle_deg'][i]:5.1f} deg, "
                f"h_min {1e6 * r['min_film'][i]:6.1f} um, supply {6e4 * r['supply_flow'][i]:.3f} l/min, "
                f"Q/(RCNL) {r['flow_variable'][i]:.3f}, Qs/Q {r['side_flow_ratio'][i]:.3f}")
    title = (f"oil feeds, D 0.1 m, L 0.08 m, C 150 um, 3000 rpm, supply 70 kPa, grid {grid[0]}x{grid[1]} "
             f"(Elrod film)")
    log(f"written: {save(plots.feed_study(res, title), out / 'journal_feeds.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[journal feeds] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'journal_feeds.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
