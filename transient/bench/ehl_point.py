"""EHL point contact: FBNS Newton against pseudo-transient time marching, side by side, over grid sizes.

For a circular steel contact (Rx = 10 mm, 20 N, 1 m/s, eta0 = 0.04 Pa s, alpha = 2e-8 1/Pa,
E' = 220 GPa, Dowson-Higginson density: Moes M = 61, L = 10.8), fully flooded, on uniform n x n grids, in
one run and interleaved:

* ``FBNS Newton``: :meth:`PointContact.steady` -- Newton on pressure, content and h0 from the dry Hertz
  pressure with the node-wise Schur reduction and a dense LU of the elastic block;
* ``time marching``: the physical transient (variable-step BDF2, FBNS Newton per step) from the same start
  until the steady residual is below 1e-3, then the same steady Newton
  (:func:`~transient.models.point.stepping.steady_by_time_steps`; the route the steady solve takes for a
  starved inlet).

Reported: wall time, Newton iterations, the central and minimum films and their difference between the two
methods, and the cost of one Newton iteration against the unknown count N (dense LU: ~N^3).

``main(out, quick)`` writes ``ehl_point.json`` into ``out`` and returns the markdown section.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

from transient.models.point import PointContact
from transient.models.point.stepping import steady_by_time_steps

TITLE = "EHL point contact: FBNS Newton vs time marching to the steady film, cost against the grid"

CASE = dict(radius_x=0.01, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


def by_newton(pc: PointContact) -> dict:
    t0 = time.perf_counter()
    s = pc.steady(raise_on_failure=False)
    return dict(success=s.success, wall_s=time.perf_counter() - t0, newton=s.iterations, h_central=s.h_central,
                h_min=s.h_min)


def by_marching(pc: PointContact) -> dict:
    film = pc.film_problem()
    t0 = time.perf_counter()
    u, ok, norms, counts = steady_by_time_steps(film, pc.hertz_start(film))
    wall = time.perf_counter() - t0
    s = pc._result(film, u, ok, norms, wall, {})
    return dict(success=ok, wall_s=wall, newton=counts["newton"] + len(norms) - 1, steps=counts["steps"],
                h_central=s.h_central, h_min=s.h_min)


def main(out, quick: bool = False) -> str:
    out = Path(out)
    sizes = (33, 49) if quick else (33, 49, 65)
    rows = []
    for n in sizes:
        pc = PointContact(grid=(n, n), **CASE)
        unknowns = 2 * pc.film_problem().n + 1
        a = by_newton(pc)
        b = by_marching(pc)
        rows.append(dict(n=n, unknowns=unknowns, newton=a, marching=b,
                         hd_central=pc.hd_central, hd_minimum=pc.hd_minimum))
    (out / "ehl_point.json").write_text(json.dumps(rows, indent=1))
    lines = [f"## {TITLE}", "",
             "Circular contact, M = 61, L = 10.8, fully flooded; both methods in one run, interleaved per grid.", "",
             "| grid | unknowns | method | converged | wall [s] | Newton its | s per Newton it | h_c [nm] | h_min [nm] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        for name, key in (("FBNS Newton", "newton"), ("time marching", "marching")):
            m = r[key]
            lines.append(f"| {r['n']} x {r['n']} | {r['unknowns']} | {name} | {m['success']} | {m['wall_s']:.2f} | "
                         f"{m['newton']} | {m['wall_s'] / max(m['newton'], 1):.3f} | {m['h_central'] * 1e9:.2f} | "
                         f"{m['h_min'] * 1e9:.2f} |")
    lines += ["", "Difference of the two methods' films (same discrete problem): "
              + ", ".join(f"{r['n']}: {abs(r['newton']['h_central'] - r['marching']['h_central']) / r['newton']['h_central']:.1e}"
                          for r in rows),
              "", f"Hamrock-Dowson for this case: h_c = {rows[0]['hd_central'] * 1e9:.1f} nm, "
                  f"h_min = {rows[0]['hd_minimum'] * 1e9:.1f} nm."]
    return "\n".join(lines)
