"""A thermal (THD) journal bearing: its temperature and viscosity maps, and eccentricity, maximum temperature and
power loss against speed beside the isothermal film.

    transient run scenarios/journal_thermal.py [--quick] [--out DIR]

The bearing of the thermal guide (D 0.1 m, L 0.05 m, C 100 um; the default feed: a full-length 6-deg groove at the
top at 1 atm, ends and cavitation at 0) under 3 kN on ROSS's fixed-bearing oil (0.01902 Pa s at 323 K, 0.00772 Pa s
at 353 K, the exponential law through both; 870 kg/m^3, 1950 J/(kg K)) supplied at 50 C, adiabatic walls, hot-oil
carry-over 0.8. The thermal equilibrium at speeds from 1000 to 6000 rpm (--quick: 5 on a 60 x 10 half grid; else 9
on 120 x 20), each beside the isothermal film at the supply viscosity; the maps at the highest speed. Writes
DIR/journal_thermal.png and DIR/journal_thermal.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import JournalBearing, ThermalFilm
from transient.plots import save, thermal as plots
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_thermal"  # output folder name: ROOT/journal_thermal (transient.study.scenario)
BEARING = dict(diameter=0.1, length=0.05, clearance=100e-6)
OIL = dict(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
           heat_capacity=1950.0, boundary="adiabatic", mixing=0.8)
LOAD = 3000.0  # [N]
C0 = 273.15  # [K] at 0 C


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (60, 10) if a.quick else (120, 20)
    speeds = np.linspace(1000.0, 6000.0, 5 if a.quick else 9)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0, c0 = time.perf_counter(), time.process_time()
    oil = ThermalFilm(**OIL)
    supply_viscosity = float(oil.viscosity(oil.supply_temperature))
    thd_bearing = JournalBearing(**BEARING, grid=grid, thermal=oil)
    iso_bearing = JournalBearing(**BEARING, grid=grid, viscosity=supply_viscosity)
    rec = JsonRecord(out / "journal_thermal.json", dict(grid=grid, quick=a.quick, load=LOAD, bearing=BEARING,
                                                       oil={k: v for k, v in OIL.items() if k != "boundary"},
                                                       supply_viscosity=supply_viscosity))
    thd = [thd_bearing.equilibrium(load=LOAD, speed_rpm=n) for n in speeds]
    iso = [iso_bearing.equilibrium(load=LOAD, speed_rpm=n) for n in speeds]
    table = dict(
        thd=dict(eccentricity_ratio=[s.eccentricity_ratio for s in thd], max_temperature=[s.max_temperature for s in thd],
                 outlet_temperature=[s.outlet_temperature for s in thd], power_loss=[s.power_loss for s in thd],
                 min_film=[s.min_film for s in thd], dissipation=[s.dissipation for s in thd],
                 heat_convected=[s.heat_convected for s in thd], heat_conducted=[s.heat_conducted for s in thd],
                 min_viscosity=[float(np.min(s.viscosity_field)) for s in thd],
                 thermal_iterations=[s.thermal_iterations for s in thd]),
        iso=dict(eccentricity_ratio=[s.eccentricity_ratio for s in iso], max_temperature=[oil.supply_temperature] * len(iso),
                 power_loss=[s.power_loss for s in iso], min_film=[s.min_film for s in iso]))
    rec.put("speed_rpm", speeds)
    rec.put("thd", table["thd"])
    rec.put("iso", table["iso"])
    t, i = table["thd"], table["iso"]
    balance = [abs(d - v - c) / d for d, v, c in zip(t["dissipation"], t["heat_convected"], t["heat_conducted"])]
    pump = [float(np.sum((thd_bearing.feed_pressures - thd_bearing.ambient_pressure) * s.supply_flow)) for s in thd]
    # independent of the energy equation: the shaft's friction power plus the supply's flow work against the heat
    friction = [(p + w) / (v + c) - 1.0 for p, w, v, c in zip(t["power_loss"], pump, t["heat_convected"],
                                                              t["heat_conducted"])]
    rec.put("energy_balance_error", balance)
    rec.put("pump_power", pump)
    rec.put("friction_balance_error", friction)
    log(f"  {'rpm':>6} | {'e/C THD':>7} {'e/C iso':>7} | {'T_max C':>7} {'T_out C':>7} | {'P THD W':>8} {'P iso W':>8}"
        f" | {'h_min THD um':>12} {'h_min iso um':>12} | (P + pump) / heat - 1")
    for k, n in enumerate(speeds):
        log(f"  {n:6.0f} | {t['eccentricity_ratio'][k]:7.3f} {i['eccentricity_ratio'][k]:7.3f} | "
            f"{t['max_temperature'][k] - C0:7.1f} {t['outlet_temperature'][k] - C0:7.1f} | {t['power_loss'][k]:8.1f} "
            f"{i['power_loss'][k]:8.1f} | {1e6 * t['min_film'][k]:12.1f} {1e6 * i['min_film'][k]:12.1f} | "
            f"{friction[k]:+.1e}")
    de = np.asarray(t["eccentricity_ratio"]) - np.asarray(i["eccentricity_ratio"])
    ratio = np.asarray(t["power_loss"]) / np.asarray(i["power_loss"])
    log(f"  THD e/C minus isothermal e/C: {de.min():+.3f} to {de.max():+.3f}; THD power loss / isothermal: "
        f"{ratio.min():.2f} to {ratio.max():.2f}; energy equation closes to {max(balance):.0e}, "
        f"friction power + pump work against heat to {max(abs(f) for f in friction):.1e}")
    title = (f"thermal journal bearing, D 0.1 m, L 0.05 m, C 100 um, {LOAD:g} N, supply 50 C, adiabatic walls, "
             f"carry-over {OIL['mixing']:g}, grid {grid[0]} x {2 * grid[1]}; maps at {speeds[-1]:.0f} rpm "
             f"(white line: edge of the cavitated film)")
    fig = plots.thd_against_isothermal(thd[-1], speeds, t, i, oil.supply_temperature, title)
    log(f"written: {save(fig, out / 'journal_thermal.png')}")
    rec.put("cpu_s", time.process_time() - c0)
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[journal thermal] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'journal_thermal.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
