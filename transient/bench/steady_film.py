"""The steady Elrod film on fine grids: the solve from rest against grid sequencing, side by side in one run.

Pfeil's demonstration bearing (D 0.1 m, L 0.08 m, C 150 um, 0.01 Pa s, a 15-deg groove 60 mm long at 270 deg held
70 kPa above an ambient at the cavitation pressure; ``steady_state(0.5, 3000)``) on grids up to 800 x 102 cells (half
length). Per grid, interleaved: the pseudo-transient Newton solve from rest
(:meth:`Film.solve <transient.models.journal.film.Film.solve>`, the steady solve of every grid before grid
sequencing) and :meth:`JournalBearing.film_solve <transient.models.journal.bearing.JournalBearing.film_solve>`
(grid sequencing over the circumferential cells, each level's Newton from the coarser level's film, chord while the
residual falls twofold per iteration); each followed by the SI film state. Newton iterations and LU factorisations
(all levels), seconds, load, and the mass balance (supply - side leakage, relative to the leakage).
``transient bench steady-film [--quick]``.
"""

from __future__ import annotations

import time

import numpy as np

from transient.bench import save_raw, table
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.feeds import Groove

TITLE = "steady Elrod film on fine grids: pseudo-transient Newton from rest against grid sequencing"
RPM, ECC = 3000.0, 0.5


def pfeil_bearing(grid) -> JournalBearing:
    """Pfeil's demonstration bearing with its 60 mm groove (docs/validation.md) on ``grid`` (half length)."""
    return JournalBearing(0.1, 0.08, 150e-6, 0.01, groove=Groove(270.0, 15.0, length=0.06), grid=grid,
                          supply_pressure=70e3, ambient_pressure=0.0, cavitation_pressure=0.0)


def _from_rest(b):
    f = b.film(RPM)
    u, its = f.solve(ECC, 0.0)
    return f.state(u, ECC, 0.0, its), [(b.grid_shape, its, f.factorisations)]


def _sequenced(b):
    f = b.film(RPM)
    u, its, levels = b.film_solve(f, ECC, 0.0)
    return f.state(u, ECC, 0.0, its), levels


METHODS = {"from rest": _from_rest, "grid sequencing": _sequenced}


def _numbers(state, levels, seconds) -> dict:
    supply, leak = float(np.sum(state.supply_flow)), float(np.sum(state.side_leakage))
    return dict(seconds=seconds, iterations=int(sum(lv[1] for lv in levels)), fine_iterations=int(levels[-1][1]),
                factorisations=int(sum(lv[2] for lv in levels)), load=float(state.load),
                supply_ml_min=supply * 6e7, mass_balance=(supply - leak) / leak,
                levels=[[list(g), int(i), int(k)] for g, i, k in levels])


def run(quick=False) -> dict:
    grids = [(100, 13), (200, 26), (400, 51)] if quick else [(200, 26), (400, 51), (800, 102)]
    rounds = {g: (2 if g[0] * g[1] < 50_000 else 1) for g in grids}
    _sequenced(pfeil_bearing((64, 8)))  # compile / load the kernels once
    cases = []
    for g in grids:
        b = pfeil_bearing(g)
        best = {}
        for _ in range(rounds[g]):  # interleaved: both methods in every round
            for name, method in METHODS.items():
                t = time.perf_counter()
                state, levels = method(b)
                seconds = time.perf_counter() - t
                if name not in best or seconds < best[name]["seconds"]:
                    best[name] = _numbers(state, levels, seconds)
        ref = best["from rest"]
        for c in best.values():
            c["load_rel_diff"] = c["load"] / ref["load"] - 1.0
            c["speed_up"] = ref["seconds"] / c["seconds"]
        cases.append(dict(grid=list(g), rounds=rounds[g], methods=best))
    return dict(quick=quick, rpm=RPM, eccentricity_ratio=ECC, cases=cases)


def markdown(r) -> str:
    rows = []
    for case in r["cases"]:
        g = case["grid"]
        for name, c in case["methods"].items():
            levels = " -> ".join(f"{a} x {b}: {i}/{k}" for (a, b), i, k in c["levels"])
            rows.append(f"| {g[0]} x {g[1]} | {name} | {c['iterations']} | {c['factorisations']} | "
                        f"{c['seconds']:.2f} | {c['speed_up']:.1f} | {c['load']:.6f} | {c['load_rel_diff']:.1e} | "
                        f"{c['mass_balance']:.1e} | {levels} |")
    return "\n".join([
        f"## {TITLE}", "",
        "Pfeil's demonstration bearing (60 mm groove at 270 deg, 70 kPa), e/C 0.5, 3000 rpm; grids on the half length. "
        "Per grid both methods interleaved, best of the rounds (1 round above 50,000 cells), each including the SI "
        "film state" + (" -- quick smoke run" if r["quick"] else "") + ". Iterations and factorisations summed "
        "over the levels; levels: grid: Newton iterations / LU factorisations, coarsest first. Load difference "
        "relative to the solve from rest; mass balance (supply - side leakage) / side leakage.", "",
        *table(("grid", "method", "iterations", "factorisations", "time [s]", "speed-up", "load [N]", "load diff",
                "mass balance", "levels"), rows), ""])


def main(out, quick: bool = False) -> str:
    r = run(quick=quick)
    save_raw(out, "steady_film", r)
    return markdown(r)
