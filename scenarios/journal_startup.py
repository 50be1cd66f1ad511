"""Start-up from rest and coast-down to rest of a rough journal bearing under load: friction torque, minimum film
and asperity load against time.

    transient run scenarios/journal_startup.py [--quick] [--out DIR]

The Rho & Kim bearing (D = 80 mm, L = 24 mm, C = 80 um, 0.029 Pa s) with steel surfaces of composite roughness
1 um (as scenarios/stribeck.py: isotropic, the journal 80 % of the roughness variance, boundary friction 0.12)
carrying a 500 kg rotor's 5 kN. Start-up: from rest (the asperities carrying the load) to 600 rpm in 1 s, then
0.2 s at speed. Coast-down: from the equilibrium at 600 rpm to rest in 1 s, then 0.5 s at rest, the journal
sinking onto the asperities. The orbit integrates the average Reynolds equation with the Greenwood-Tripp contact
(transient.JournalOrbit with speed_profile, BDF2; --quick: 24 x 4 cells, else 75 x 11).
Writes DIR/journal_startup.png and DIR/journal_startup.json.
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import numpy as np

from transient import JournalBearing, JournalOrbit, Roughness, steel_asperity_contact
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import mixed as plots, save
from transient.solvers.settings import Integration, Recording
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_startup"  # output folder name: ROOT/journal_startup (transient.study.scenario)
SIGMA = 1e-6  # [m] composite RMS roughness
LOAD = 5000.0  # [N]
MASS = 500.0  # [kg]
SPEED = 600.0  # [rpm] full speed
RAMP = 1.0  # [s] start-up and coast-down time
RECORD = ("shaft_speed", "friction_torque", "min_film", "contact_load")


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    announce("bdf2")
    grid = (24, 4) if a.quick else (75, 11)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    roughness = Roughness(steel_asperity_contact(SIGMA), gamma=1.0, boundary_friction=0.12, journal_variance_share=0.8)
    bearing = JournalBearing(**rho_kim.BEARING, grid=grid, roughness=roughness)
    rev = 60.0 / SPEED  # [s] one revolution at full speed: the orbit's time unit
    cases = {"start-up from rest": (((0.0, 0.0), (RAMP, SPEED)), RAMP + 0.2, "rest"),
             "coast-down to rest": (((0.0, SPEED), (RAMP, 0.0)), RAMP + 0.5, "equilibrium")}
    rec = JsonRecord(out / "journal_startup.json", dict(grid=grid, quick=a.quick))
    runs = {}
    with warnings.catch_warnings():  # contact pressures above the isoviscous film's range near rest
        warnings.simplefilter("ignore", UserWarning)
        for label, (profile, duration, start) in cases.items():
            o = JournalOrbit(bearing, MASS, 0.0, LOAD, SPEED, speed_profile=profile)
            c0 = time.process_time()
            y0 = o.rest_state() if start == "rest" else o.initial_state()
            r = o.run(duration / rev, y0=y0, integration=Integration(method="bdf2"),
                      recording=Recording(outputs_per_revolution=20, record=RECORD))
            cpu = time.process_time() - c0
            runs[label] = r
            finite = bool(np.all(np.isfinite(r.x)) and np.all(np.isfinite(r.friction_torque)))
            log(f"  {label}: {'ok' if r.success else r.message}, {r.stats.n_steps} steps, {cpu:.1f} s CPU; "
                f"torque {r.friction_torque[0]:.2f} -> {r.friction_torque[-1]:.2f} N m (max "
                f"{np.max(r.friction_torque):.2f}), h_min {1e6 * r.min_film[0]:.2f} -> {1e6 * r.min_film[-1]:.2f} um, "
                f"contact {r.contact_load[0]:.0f} -> {r.contact_load[-1]:.0f} N, peak asperity pressure "
                f"{r.peak_contact_pressure / 1e6:.1f} MPa, contact {r.contact_events}")
            rec.put(label.split()[0], dict(success=bool(r.success), finite=finite, steps=int(r.stats.n_steps),
                                           cpu_s=cpu, t=r.t, speed_rpm=r.shaft_speed, friction_torque=r.friction_torque,
                                           h_min=r.min_film, contact_load=r.contact_load,
                                           contact_pressure=r.contact_pressure,
                                           peak_contact_pressure=r.peak_contact_pressure,
                                           contact_events=[[t, w] for t, w in r.contact_events]))
    title = (f"Rough journal bearing (sigma = {1e6 * SIGMA:g} um, mu_b = 0.12), {LOAD:g} N, {MASS:g} kg rotor, "
             f"0 <-> {SPEED:g} rpm in {RAMP:g} s, grid {grid[0]} x {grid[1]}")
    log(f"written: {save(plots.speed_histories(runs, LOAD, SIGMA, title), out / 'journal_startup.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[journal_startup] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'journal_startup.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
