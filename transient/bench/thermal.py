"""Steady THD against the isothermal steady solve on the same grid, side by side in one run.

The bearing of the validation record (D 0.1 m, L 0.05 m, C 100 um, one full-length groove, 3000 rpm; ROSS's
fixed-bearing oil through (323 K, 0.01902 Pa s) and (353 K, 0.00772 Pa s), supply 323.15 K, adiabatic, carry-over
0.8) at e/C 0.3, 0.6, 0.9 on 151 x 21 (half length): ``steady_state`` of the thermal bearing and of the isothermal
bearing at the supply viscosity, interleaved, CPU time (``time.process_time``), best of the rounds. The issue's
target: the thermal solve at most 3x the isothermal one.

And one orbit revolution (BDF2, from the static equilibrium, rotor 10 kg per bearing, 2 kN, unbalance 0.1 C) of the
thermal bearing (its temperatures states of the run, :mod:`~transient.models.journal.thermal_orbit`, thermal
intervals of 1 and 0.5 revolutions) beside the isothermal bearing's on the same stepper; target: at most 1.5x.

And one revolution of a rigid rotor (20 kg, two of these bearings 0.5 m apart, 2 kN each, unbalance 0.1 C at each)
on the thermal bearings (:mod:`~transient.models.rotor.thermal_films`) beside the same rotor on the isothermal ones,
BDF2 (``method="bdf2"``); target: at most 1.5x. ``transient bench thermal [--quick]``.
"""

from __future__ import annotations

import time

import numpy as np

from transient.bench import save_raw, table
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.models.rotor.rotor import Rotor
from transient.models.rotor.system import RotorBearingSystem
from transient.solvers.settings import Integration, Recording
from transient.models.journal.thermal_settings import ThermalFilm

TITLE = "steady THD journal film against the isothermal steady solve (CPU time ratio)"
RPM = 3000.0
OIL = ThermalFilm(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
                  heat_capacity=1950.0)


def bearings(grid) -> tuple[JournalBearing, JournalBearing]:
    """(thermal, isothermal at the supply viscosity) on ``grid``."""
    hot = JournalBearing(0.1, 0.05, 1e-4, None, grid=grid, thermal=OIL)
    return hot, JournalBearing(0.1, 0.05, 1e-4, hot.viscosity, grid=grid)


def _cpu(fn):
    t = time.process_time()
    out = fn()
    return time.process_time() - t, out


def _fastest(runs, rounds) -> dict:
    """``{name: (CPU seconds, result)}``: the fastest of ``rounds`` rounds of the ``runs`` (name -> callable), the
    cases alternating within each round."""
    best = {}
    for _ in range(rounds):
        for name, go in runs.items():
            seconds, r = _cpu(go)
            if name not in best or seconds < best[name][0]:
                best[name] = (seconds, r)
    return best


def orbit_revolution(quick=False) -> dict:
    """CPU seconds of one BDF2 orbit revolution of the thermal and the isothermal bearing, best of the rounds."""
    grid, rounds = ((60, 10), 1) if quick else ((151, 21), 3)
    hot, iso = bearings(grid)
    orbits = {name: JournalOrbit(b, 10.0, 1e-5, 2000.0, RPM) for name, b in (("thermal", hot), ("isothermal", iso))}
    bdf2, rec = Integration(method="bdf2"), Recording(outputs_per_revolution=20)
    runs = {"isothermal": lambda: orbits["isothermal"].run(1, integration=bdf2, recording=rec),
            "thermal": lambda: orbits["thermal"].run(1, thermal_interval=1.0, recording=rec),
            "thermal, interval 0.5 rev": lambda: orbits["thermal"].run(1, thermal_interval=0.5, recording=rec)}
    for o in orbits.values():
        o.equilibrium()
    for name in runs:  # compile / load the kernels once
        orbits["thermal" if name.startswith("thermal") else "isothermal"].run(
            0.1, **({} if name.startswith("thermal") else dict(integration=bdf2)),
            recording=Recording(outputs_per_revolution=20))
    best = _fastest(runs, rounds)
    iso_s = best["isothermal"][0]
    return dict(grid=list(grid), rounds=rounds, cases=[
        dict(run=name, seconds=sec, ratio=sec / iso_s, steps=int(r.stats.n_steps),
             eccentricity_ratio=float(np.hypot(r.x[-1], r.y[-1]) / hot.clearance)) for name, (sec, r) in best.items()])


def rotor_revolution(quick=False) -> dict:
    """CPU seconds of one BDF2 revolution of the rigid rotor on the two thermal and on the two isothermal bearings,
    each from a tenth of a revolution after its (thermal) equilibrium, best of the rounds."""
    grid, rounds = ((60, 10), 1) if quick else ((151, 21), 3)
    hot, iso = bearings(grid)
    rotor = Rotor.rigid(20.0, 0.3, 0.5)
    unbalance = [(0, 10.0 * 1e-5, 0.0), (1, 10.0 * 1e-5, 0.0)]
    systems = {name: RotorBearingSystem(rotor, {0: b, 1: b}, unbalance=unbalance, gravity=200.0)
               for name, b in (("thermal", hot), ("isothermal", iso))}
    bdf2, rec = Integration(method="bdf2"), Recording(outputs_per_revolution=20)
    start = {"isothermal": systems["isothermal"].run(0.1, RPM, integration=bdf2, recording=rec),
             "thermal": systems["thermal"].run(0.1, RPM, thermal_interval=0.1, recording=rec)}
    runs = {"isothermal": lambda: systems["isothermal"].run(1, RPM, start=start["isothermal"], integration=bdf2,
                                                            recording=rec),
            "thermal": lambda: systems["thermal"].run(1, RPM, start=start["thermal"], thermal_interval=1.0,
                                                      recording=rec),
            "thermal, interval 0.5 rev": lambda: systems["thermal"].run(1, RPM, start=start["thermal"],
                                                                        thermal_interval=0.5, recording=rec)}
    best = _fastest(runs, rounds)
    iso_s = best["isothermal"][0]
    return dict(grid=list(grid), rounds=rounds, cases=[
        dict(run=name, seconds=sec, ratio=sec / iso_s, steps=int(r.stats.n_steps),
             eccentricity_ratio=float(r.eccentricity_ratio(0)[-1])) for name, (sec, r) in best.items()])


def run(quick=False) -> dict:
    grid, rounds = ((60, 10), 1) if quick else ((151, 21), 3)
    hot, iso = bearings(grid)
    hot.steady_state(0.6, RPM)  # compile / load the kernels once
    iso.steady_state(0.6, RPM)
    cases = []
    for ecc in (0.3, 0.6, 0.9):
        best = {}
        for _ in range(rounds):
            for name, b in (("thermal", hot), ("isothermal", iso)):
                seconds, s = _cpu(lambda: b.steady_state(ecc, RPM))
                if name not in best or seconds < best[name][0]:
                    best[name] = (seconds, s)
        (th, s), (ti, si) = best["thermal"], best["isothermal"]
        cases.append(dict(eccentricity_ratio=ecc, thermal_s=th, isothermal_s=ti, ratio=th / ti,
                          alternations=s.thermal_iterations, newton=s.newton_iterations,
                          max_temperature_C=s.max_temperature - 273.15, load_ratio=s.load / si.load,
                          power_ratio=s.power_loss / si.power_loss))
    return dict(quick=quick, grid=list(grid), rounds=rounds, rpm=RPM, cases=cases, orbit=orbit_revolution(quick),
                rotor=rotor_revolution(quick))


def markdown(r) -> str:
    rows = [f"| {c['eccentricity_ratio']} | {c['thermal_s']:.3f} | {c['isothermal_s']:.3f} | {c['ratio']:.2f} | "
            f"{c['alternations']} | {c['newton']} | {c['max_temperature_C']:.2f} | {c['load_ratio']:.3f} | "
            f"{c['power_ratio']:.3f} |" for c in r["cases"]]
    g = r["grid"]
    return "\n".join([
        f"## {TITLE}", "",
        f"Bearing of the validation record (\"Thermal journal film\"), {g[0]} x {g[1]} cells, {r['rpm']:g} rpm, "
        f"adiabatic; CPU seconds, best of {r['rounds']} interleaved rounds"
        + (" -- quick smoke run" if r["quick"] else "") + ". Target: ratio at most 3.", "",
        *table(("e/C", "THD [s]", "isothermal [s]", "ratio", "alternations", "Newton iterations", "T_max [C]",
                "load THD/iso", "power THD/iso"), rows), "", *orbit_markdown(r.get("orbit")),
        *rotor_markdown(r.get("rotor"))])


def main(out, quick: bool = False) -> str:
    r = run(quick=quick)
    save_raw(out, "thermal", r)
    return markdown(r)


def orbit_markdown(o) -> list:
    """The orbit revolution's table (nothing without one)."""
    if not o:
        return []
    g = o["grid"]
    return revolution_table(o, "One orbit revolution, thermal against isothermal (BDF2)",
                            f"{g[0]} x {g[1]} cells, {RPM:g} rpm, 2 kN, rotor 10 kg, unbalance 0.1 C, from the static "
                            "equilibrium", "e/C at the end")


def rotor_markdown(o) -> list:
    """The rotor revolution's table (nothing without one)."""
    if not o:
        return []
    g = o["grid"]
    return revolution_table(o, "One rotor revolution on two bearings, thermal against isothermal (BDF2)",
                            f"Rigid rotor 20 kg on two bearings of {g[0]} x {g[1]} cells, {RPM:g} rpm, 2 kN each, "
                            "unbalance 0.1 C at each", "e/C at bearing 0 at the end")


def revolution_table(o, title: str, setup: str, last: str) -> list:
    """A revolution's cost table, thermal against isothermal: ``o["cases"]`` rows under ``title`` and ``setup``."""
    return [f"### {title}", "",
            f"{setup}; CPU seconds, best of {o['rounds']} interleaved rounds. Target: ratio at most 1.5.", "",
            *table(("run", "CPU [s]", "ratio", "steps", last),
                   [f"| {c['run']} | {c['seconds']:.2f} | {c['ratio']:.2f} | {c['steps']} | "
                    f"{c['eccentricity_ratio']:.4f} |" for c in o["cases"]]), ""]
