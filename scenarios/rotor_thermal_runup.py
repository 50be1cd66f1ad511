"""A rigid rotor on two thermal journal bearings run up in speed: each film's temperature lags the shaft's speed.

    transient run scenarios/rotor_thermal_runup.py [--quick] [--out DIR]

Two bearings of the thermal guide (D 0.1 m, L 0.05 m, C 100 um, full-length groove; 0.01902 Pa s at 323 K,
0.00772 Pa s at 353 K; supply 50 C, adiabatic, carry-over 0.8) with 50 J/K of bush and shaft metal next to each
film, under a rigid 20 kg rotor (0.3 kg m^2) whose centre of mass sits 0.2 m from bearing 0 on a 0.5 m span
(bearing 0 carries 1.2 kN, bearing 1 0.8 kN under 100 m/s^2, a test-rig load), 4 um of unbalance at bearing 0.
The shaft runs up from 1500 to 3000 rpm in 1 s and holds 3000 rpm for 2 s (--quick: 0.5 s and 0.5 s); the rotor
system on BDF2 with each bearing's temperatures as states of the run on thermal intervals of one (mean)
revolution (:mod:`transient.models.rotor.thermal_films`). Beside it: the rotor's thermal equilibrium at each
speed (where the films would be if they followed the speed at once). Writes DIR/rotor_thermal_runup.png and
DIR/rotor_thermal_runup.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import JournalBearing, ThermalFilm
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.plots import save, thermal as plots
from transient.solvers.settings import Recording
from transient.study.scenario import JsonRecord, log, parser

OUT = "rotor_thermal_runup"  # output folder name: ROOT/rotor_thermal_runup (transient.study.scenario)
BEARING = dict(diameter=0.1, length=0.05, clearance=100e-6)
OIL = dict(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
           heat_capacity=1950.0, mixing=0.8, wall_heat_capacity=50.0)
MASS, INERTIA, SPAN, CENTRE = 20.0, 0.3, 0.5, 0.4  # [kg], [kg m^2], [m], centre of mass from bearing 0 [span]
GRAVITY, UNBALANCE = 100.0, 4e-6  # [m/s^2], [m]
START, END = 1500.0, 3000.0  # [rpm]
C0 = 273.15  # [K] at 0 C


def rotor() -> Rotor:
    """The rigid rotor: its mass matrix from the kinetic energy of its centre ``x_c = (1 - a) x_0 + a x_1`` and of
    its tilt ``(x_1 - x_0) / span``."""
    c = np.array([1.0 - CENTRE, CENTRE])
    t = MASS * np.outer(c, c) + INERTIA / SPAN ** 2 * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return Rotor(mass=np.kron(t, np.eye(2)), stiffness=np.zeros((4, 4)), nodes=[0, 1])


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (40, 6)
    ramp, hold = (0.5, 0.5) if a.quick else (1.0, 2.0)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0, c0 = time.perf_counter(), time.process_time()
    bearing = JournalBearing(**BEARING, grid=grid, thermal=ThermalFilm(**OIL))
    system = RotorBearingSystem(rotor(), {0: bearing, 1: bearing}, unbalance=[(0, MASS * UNBALANCE, 0.0)],
                                gravity=GRAVITY)

    def speed(t):
        return START + (END - START) * min(t / ramp, 1.0)

    revolutions = (0.5 * (START + END) * ramp + END * hold) / 60.0
    r = system.run(revolutions, speed, thermal_interval=1.0, recording=Recording(outputs_per_revolution=10))
    if not r.success:
        raise RuntimeError(f"the run-up failed: {r.message}")
    speeds = np.linspace(START, END, 4)
    steady = [system.equilibrium(n) for n in speeds]
    nodes = r.thermal_nodes
    balance = max(float(np.max(np.abs(h["stored"] - (h["dissipation"] - h["heat_out"])) / h["dissipation"]))
                  for h in r.heat_balance)
    e = np.column_stack([r.eccentricity_ratio(n) for n in nodes])
    rec = JsonRecord(out / "rotor_thermal_runup.json", dict(grid=grid, quick=a.quick, mass=MASS, inertia=INERTIA,
                                                           span=SPAN, centre=CENTRE, gravity=GRAVITY,
                                                           unbalance=UNBALANCE, bearing=BEARING, oil=OIL,
                                                           ramp_s=ramp, hold_s=hold))
    rec.put("run", dict(t=r.t, shaft_speed=r.speed_rpm, nodes=nodes, max_temperature=r.max_temperature,
                        power_loss=r.power_loss, heat_flow=r.heat_flow, eccentricity_ratio=e))
    table = dict(speed_rpm=speeds, max_temperature=[s.max_temperature for s in steady],
                 power_loss=[s.power_loss for s in steady],
                 eccentricity_ratio=[s.eccentricity_ratio for s in steady],
                 bearing_load=[s.bearing_load for s in steady])
    rec.put("steady", table)
    at_top = int(np.argmin(np.abs(r.t - ramp)))
    lag = steady[-1].max_temperature - r.max_temperature[at_top]
    rec.put("lag_at_full_speed_K", lag)
    rec.put("final_lag_K", steady[-1].max_temperature - r.max_temperature[-1])
    rec.put("heat_balance_max_error", balance)
    rec.put("steps", r.stats.n_steps)
    for k, node in enumerate(nodes):
        log(f"  bearing {node} ({steady[-1].bearing_load[k]:.0f} N): at full speed ({ramp:g} s) T_max "
            f"{r.max_temperature[at_top, k] - C0:.2f} C, steady {steady[-1].max_temperature[k] - C0:.2f} C (lag "
            f"{lag[k]:.2f} K); after {ramp + hold:g} s: {r.max_temperature[-1, k] - C0:.2f} C")
    log(f"  heat balance per interval within {balance:.1e} of the heat made")
    title = (f"rotor on two thermal journal bearings run up {START:.0f} -> {END:.0f} rpm in {ramp:g} s: the films' "
             f"temperatures lag the speed ({MASS:g} kg rigid rotor, bearing loads "
             f"{steady[-1].bearing_load[0]:.0f} / {steady[-1].bearing_load[1]:.0f} N, "
             f"{OIL['wall_heat_capacity']:g} J/K of wall metal per bearing, grid {grid[0]} x {2 * grid[1]})")
    fig = plots.rotor_run_up(r.t, r.speed_rpm, nodes, r.max_temperature, r.power_loss, e, table, ramp, title)
    log(f"written: {save(fig, out / 'rotor_thermal_runup.png')}")
    rec.put("cpu_s", time.process_time() - c0)
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[rotor thermal run-up] done in {time.perf_counter() - t0:.0f} s; numbers in "
        f"{out / 'rotor_thermal_runup.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
