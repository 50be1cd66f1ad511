"""Stribeck curve of a rough journal bearing: friction torque, minimum film and asperity load against speed.

    transient run scenarios/stribeck.py [--quick] [--out DIR]

The Rho & Kim bearing (D = 80 mm, L = 24 mm, C = 80 um, 0.029 Pa s) with steel surfaces of composite roughness
1 um (Greenwood-Tripp asperities of transient.steel_asperity_contact, isotropic, the journal 80 % of the roughness
variance, boundary friction 0.12) under 5 kN (2.6 MPa), 27 speeds from 5 to 6000 rpm (--quick: 12 speeds on a
48 x 8 grid; else 151 x 21): the equilibrium at each speed from the highest down (transient.stribeck_curve).
Writes DIR/stribeck.png and DIR/stribeck.json.
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import numpy as np

from transient import JournalBearing, Roughness, steel_asperity_contact, stribeck_curve
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import mixed as plots, save
from transient.study.scenario import JsonRecord, log, parser

OUT = "stribeck"  # output folder name: ROOT/stribeck (transient.study.scenario)
SIGMA = 1e-6  # [m] composite RMS roughness
LOAD = 5000.0  # [N]


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    announce("journal")
    grid = (48, 8) if a.quick else (151, 21)
    speeds = np.geomspace(5.0, 6000.0, 12 if a.quick else 27)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    c0 = time.process_time()
    roughness = Roughness(steel_asperity_contact(SIGMA), gamma=1.0, boundary_friction=0.12, journal_variance_share=0.8)
    bearing = JournalBearing(**rho_kim.BEARING, grid=grid, roughness=roughness)
    with warnings.catch_warnings():  # contact pressures above the isoviscous film's range at the lowest speeds
        warnings.simplefilter("ignore", UserWarning)
        curve = stribeck_curve(bearing, LOAD, speeds)
    cpu = time.process_time() - c0
    for row in zip(curve.speed_rpm, curve.friction_torque, curve.friction_coefficient, curve.h_min, curve.contact_load):
        log(f"  {row[0]:8.1f} rpm: torque {row[1]:7.3f} N m, f = {row[2]:.4f}, h_min {1e6 * row[3]:6.2f} um, "
            f"contact {row[4]:8.1f} N")
    k = int(np.argmin(curve.friction_torque))
    log(f"  lift-off (contact < {100 * curve.lift_off_fraction:g} % of the load) at {curve.lift_off_speed_rpm:.0f} rpm; "
        f"least torque {curve.friction_torque[k]:.3f} N m at {curve.speed_rpm[k]:.0f} rpm")
    rec = JsonRecord(out / "stribeck.json", dict(grid=grid, quick=a.quick))
    rec.put("curve", dict(speed_rpm=curve.speed_rpm, friction_torque=curve.friction_torque,
                          friction_coefficient=curve.friction_coefficient, h_min=curve.h_min,
                          contact_load=curve.contact_load, lift_off_speed_rpm=curve.lift_off_speed_rpm,
                          load=LOAD, sigma=SIGMA, cpu_s=cpu))
    title = (f"Rough journal bearing (sigma = {1e6 * SIGMA:g} um, mu_b = 0.12), {LOAD:g} N, grid {grid[0]} x {grid[1]}")
    log(f"written: {save(plots.stribeck(curve, SIGMA, title), out / 'stribeck.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[stribeck] done in {time.perf_counter() - t0:.0f} s ({cpu:.0f} s CPU); numbers in {out / 'stribeck.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
