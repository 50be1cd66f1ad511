"""Steady THD against the isothermal steady solve on the same grid, side by side in one run.

The bearing of the validation record (D 0.1 m, L 0.05 m, C 100 um, one full-length groove, 3000 rpm; ROSS's
fixed-bearing oil through (323 K, 0.01902 Pa s) and (353 K, 0.00772 Pa s), supply 323.15 K, adiabatic, carry-over
0.8) at e/C 0.3, 0.6, 0.9 on 151 x 21 (half length): ``steady_state`` of the thermal bearing and of the isothermal
bearing at the supply viscosity, interleaved, CPU time (``time.process_time``), best of the rounds. The issue's
target: the thermal solve at most 3x the isothermal one. ``transient bench thermal [--quick]``.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

from transient.models.journal.bearing import JournalBearing
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
    return dict(quick=quick, grid=list(grid), rounds=rounds, rpm=RPM, cases=cases)


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
        "| e/C | THD [s] | isothermal [s] | ratio | alternations | Newton iterations | T_max [C] | load THD/iso "
        "| power THD/iso |",
        "|---|---|---|---|---|---|---|---|---|", *rows, ""])


def main(out, quick: bool = False) -> str:
    r = run(quick=quick)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_thermal.json").write_text(json.dumps(r, indent=1))
    return markdown(r)
