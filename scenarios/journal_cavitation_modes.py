"""Elrod (mass-conserving) against Reynolds-condition film: stiffness and damping of the Rho & Kim bearing.

    transient run scenarios/journal_cavitation_modes.py [--quick] [--out DIR]

Loads 50 N ... 8 kN at 6000 rpm, the supply groove at 0 deg (the top: the maximum film under a downward load),
90 deg and 270 deg; equilibrium, K and C of both films (JournalBearing(cavitation="elrod" | "reynolds")).
Writes DIR/cavitation_modes.png and DIR/cavitation_modes.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import journal as plots, save
from transient.study.cavitation_modes import coefficients_by_mode
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_cavitation_modes"  # output folder name: ROOT/journal_cavitation_modes (transient.study.scenario)


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    announce("journal")
    grid = (48, 8) if a.quick else (151, 21)
    loads = np.geomspace(50.0, 8000.0, 4 if a.quick else 7)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    res = coefficients_by_mode(dict(rho_kim.BEARING, grid=grid), loads, 6000.0, (0.0, 90.0, 270.0))
    rec = JsonRecord(out / "cavitation_modes.json", dict(grid=grid, quick=a.quick))
    for ang, r in res.items():
        dK, dC = r.dK_max, r.dC_max
        rec.put(f"groove_{ang:g}deg", r.record())
        for i, W in enumerate(loads):
            log(f"  groove {ang:5.0f} deg, {W:7.0f} N: e/C Elrod {r.eps_elrod[i]:.3f}, Reynolds "
                f"{r.eps_reynolds[i]:.3f}; K differs {100 * dK[i]:5.1f} %, C {100 * dC[i]:5.1f} %")
    log(f"written: {save(plots.cavitation_modes(res), out / 'cavitation_modes.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[cavitation modes] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'cavitation_modes.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
