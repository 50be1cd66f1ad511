"""A thermal journal bearing run up in speed: the film's temperature lags the shaft's speed by seconds.

    transient run scenarios/journal_thermal_runup.py [--quick] [--out DIR]

The bearing and oil of the thermal guide (D 0.1 m, L 0.05 m, C 100 um, full-length groove; 0.01902 Pa s at 323 K,
0.00772 Pa s at 353 K; supply 50 C, adiabatic, carry-over 0.8) with 50 J/K of bush and shaft metal next to the film,
a 10 kg rotor share under 2 kN with 2 um of unbalance. The shaft runs up from 1500 to 3000 rpm in 1 s and holds
3000 rpm for 2 s (--quick: 0.5 s and 0.5 s); the orbit on BDF2, the temperatures as states of the run on thermal
intervals of one revolution at 1500 rpm (:mod:`transient.models.journal.thermal_orbit`). Beside it: the steady THD
equilibrium at each speed (where the film would be if it followed the speed at once). Writes
DIR/journal_thermal_runup.png and DIR/journal_thermal_runup.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import JournalBearing, JournalOrbit, ThermalFilm
from transient.plots import save, thermal as plots
from transient.solvers.settings import Recording
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_thermal_runup"  # output folder name: ROOT/journal_thermal_runup (transient.study.scenario)
BEARING = dict(diameter=0.1, length=0.05, clearance=100e-6)
OIL = dict(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
           heat_capacity=1950.0, mixing=0.8, wall_heat_capacity=50.0)
LOAD, MASS, UNBALANCE = 2000.0, 10.0, 2e-6  # [N], [kg], [m]
START, END = 1500.0, 3000.0  # [rpm]
C0 = 273.15  # [K] at 0 C


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (40, 6)
    ramp, hold = (0.5, 0.5) if a.quick else (1.0, 2.0)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0, c0 = time.perf_counter(), time.process_time()
    bearing = JournalBearing(**BEARING, grid=grid, thermal=ThermalFilm(**OIL))
    orbit = JournalOrbit(bearing, MASS, UNBALANCE, LOAD, START, speed_profile=((0.0, START), (ramp, END)))
    revolutions = (ramp + hold) * START / 60.0  # revolutions at the orbit's (start) speed
    r = orbit.run(revolutions, thermal_interval=1.0,
                  recording=Recording(outputs_per_revolution=10, record=("shaft_speed", "max_temperature",
                                                                         "power_loss", "heat_flow", "stored_heat")))
    if not r.success:
        raise RuntimeError(f"the run-up failed: {r.message}")
    speeds = np.linspace(START, END, 4)
    steady = [bearing.equilibrium(load=LOAD, speed_rpm=n) for n in speeds]
    h = r.heat_balance
    balance = np.abs(h["stored"] - (h["dissipation"] - h["heat_out"])) / h["dissipation"]
    rec = JsonRecord(out / "journal_thermal_runup.json", dict(grid=grid, quick=a.quick, load=LOAD, mass=MASS,
                                                             unbalance=UNBALANCE, bearing=BEARING, oil=OIL,
                                                             ramp_s=ramp, hold_s=hold))
    e = np.hypot(r.x, r.y) / BEARING["clearance"]
    rec.put("run", dict(t=r.t, shaft_speed=r.shaft_speed, max_temperature=r.max_temperature, power_loss=r.power_loss,
                        heat_flow=r.heat_flow, eccentricity_ratio=e))
    rec.put("steady", dict(speed_rpm=speeds, max_temperature=[s.max_temperature for s in steady],
                           power_loss=[s.power_loss for s in steady],
                           eccentricity_ratio=[s.eccentricity_ratio for s in steady]))
    at_top = int(np.argmin(np.abs(r.t - ramp)))
    lag = steady[-1].max_temperature - r.max_temperature[at_top]
    rec.put("lag_at_full_speed_K", lag)
    rec.put("final_lag_K", steady[-1].max_temperature - r.max_temperature[-1])
    rec.put("heat_balance_max_error", float(balance.max()))
    log(f"  full speed at {ramp:g} s: T_max {r.max_temperature[at_top] - C0:.2f} C, steady {steady[-1].max_temperature - C0:.2f} C "
        f"(lag {lag:.2f} K); after {ramp + hold:g} s: {r.max_temperature[-1] - C0:.2f} C; heat balance per "
        f"interval within {balance.max():.1e} of the heat made")
    title = (f"thermal journal bearing run up {START:.0f} -> {END:.0f} rpm in {ramp:g} s: the film's temperature lags "
             f"the speed (D 0.1 m, L 0.05 m, C 100 um, {LOAD:g} N, {OIL['wall_heat_capacity']:g} J/K of wall metal, "
             f"grid {grid[0]} x {2 * grid[1]})")
    fig = plots.run_up(r.t, r.shaft_speed, r.max_temperature, r.power_loss, r.heat_flow, e,
                       dict(speed_rpm=speeds, max_temperature=[s.max_temperature for s in steady],
                            power_loss=[s.power_loss for s in steady],
                            eccentricity_ratio=[s.eccentricity_ratio for s in steady]), ramp, title)
    log(f"written: {save(fig, out / 'journal_thermal_runup.png')}")
    rec.put("cpu_s", time.process_time() - c0)
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[journal thermal run-up] done in {time.perf_counter() - t0:.0f} s; numbers in "
        f"{out / 'journal_thermal_runup.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
