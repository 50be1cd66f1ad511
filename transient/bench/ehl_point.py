"""EHL point contact at scale: dense LU against Newton-Krylov, side by side, over grid sizes; films against
Hamrock-Dowson and Nijenbanning-Venner-Moes.

1. Solver cost. A circular steel contact (Rx = 10 mm, 20 N, 0.2 m/s, eta0 = 0.04 Pa s, alpha = 2e-8 1/Pa,
   E' = 220 GPa, Barus, Dowson-Higginson density: Moes M = 205, L = 7.2), fully flooded, on uniform n x n
   grids, the FBNS Newton (:func:`~transient.models.point.fbns.fbns`, tolerance 1e-8 on the scaled
   residual) with its reduced linear systems solved, in one run and interleaved per grid, by

   * ``dense LU``: the dense reduced Newton matrix, LAPACK LU (O(N^3); grids up to 65 x 65);
   * ``Newton-Krylov``: GMRES on the matrix-free reduced matrix (DC-FFT products) with the two-level
     preconditioner of :mod:`transient.models.point.krylov`, from the dry Hertz start;
   * ``Newton-Krylov, nested``: the same from the solution on every second node (itself nested down to the
     dense size) -- what :meth:`PointContact.steady` does by default above the dense size.

   Reported: converged, wall and CPU time, Newton iterations on the grid itself (and on the coarser grids
   of the nested start), GMRES iterations, preconditioner set-up and GMRES seconds, seconds per Newton
   iteration, the films, and the cost of one Newton-Krylov iteration against the unknown count N.
2. Fully flooded films against Hamrock & Dowson (*J. Lubr. Technol.* 99, 1977) over loads and speeds.
3. Central films against Nijenbanning, Venner & Moes (*Wear* 176, 1994) over Moes' chart (Barus,
   incompressible).

``main(out, quick)`` writes ``ehl_point.json`` into ``out`` and returns the markdown section
(:func:`report` of that data).
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from transient.models.point import PointContact
from transient.models.point.fbns import fbns, linear_solver
from transient.models.point.formulas import nvm_central_film
from transient.models.point.krylov import KrylovSolver

TITLE = "EHL point contact at scale: dense LU vs Newton-Krylov, cost against the grid; films against formulas"

CASE = dict(radius_x=0.01, load=20.0, speed=0.2, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)

#: (method name, linear solver, nested start)
METHODS = (("dense LU", "dense", False), ("Newton-Krylov", "krylov", False), ("Newton-Krylov, nested", "krylov", True))


#: preconditioner variants of the Newton-Krylov path: (name, KrylovSolver keywords)
VARIANTS = (("coarse LU + near-field LU (self-influence only), rebuilt every step (default)", dict(near=0)),
            ("coarse LU + near-field LU (offsets up to 1 node)", dict(near=1)),
            ("coarse LU only (GMRES capped at 100)", dict(near=None, max_iter=100)),
            ("default, kept while GMRES needs at most 10 iterations", dict(near=0, refresh_after=10)))


def solve(pc: PointContact, method, nested: bool) -> dict:
    """One steady FBNS solve with the given linear solver (a name, or KrylovSolver keywords); timings,
    counts and films."""
    film = pc.film_problem()
    u0 = pc.hertz_start(film)
    solver = KrylovSolver(film, **method) if isinstance(method, dict) else linear_solver(film, method)
    w0, c0 = time.perf_counter(), time.process_time()
    u, ok, norms = fbns(film, u0, 1e-8, 60, solver=solver, nested=nested)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    s = pc._result(film, u, ok, norms, wall, {})
    st = solver.stats
    fine = wall - st.get("coarse_s", 0.0)
    return dict(success=bool(ok), wall_s=wall, cpu_s=cpu, newton=len(norms) - 1, fine_wall_s=fine,
                coarse=[list(c) for c in st.get("coarse_newton", [])], gmres=st.get("gmres"),
                setup_s=st.get("setup_s"), gmres_s=st.get("gmres_s"), gmres_its=st.get("gmres_its"),
                setups=st.get("setups"), h_central=s.h_central, h_min=s.h_min,
                state=u)


def scaling(sizes, quick) -> list:
    rows = []
    for n in sizes:
        pc = PointContact(grid=(n, n), **CASE)
        unknowns = 2 * pc.film_problem().n + 1
        row = dict(n=n, unknowns=unknowns, hd_central=pc.hd_central, hd_minimum=pc.hd_minimum,
                   nvm_central=nvm_central_film(CASE["load"], CASE["speed"], CASE["viscosity"],
                                                CASE["pressure_viscosity"], CASE["modulus"], CASE["radius_x"]))
        for name, method, nested in METHODS:
            if method == "dense" and n > 65:
                continue
            if method == "krylov" and n < 49:
                continue
            if nested and (n - 1) % 4:
                continue
            if name == "Newton-Krylov" and n > (129 if quick else 257):
                continue
            row[name] = solve(pc, method, nested)
        ref = (row.get("dense LU") or row.get("Newton-Krylov") or row["Newton-Krylov, nested"])["state"]
        for name in (k for k, _, _ in METHODS):
            if name in row:
                r = row[name]
                r["state_diff"] = float(np.max(np.abs(r.pop("state") - ref)) / np.max(np.abs(ref)))
        rows.append(row)
    return rows


def variants(sizes) -> list:
    rows = []
    for n in sizes:
        pc = PointContact(grid=(n, n), **CASE)
        for name, kw in VARIANTS:
            r = solve(pc, kw, True)
            r.pop("state")
            rows.append(dict(n=n, variant=name, **r))
    return rows


def formula_case(load, speed, pressure_viscosity, grid, density="dowson-higginson", viscosity=0.04,
                 modulus=2.2e11, radius_x=0.01) -> dict:
    pc = PointContact(radius_x=radius_x, load=load, speed=speed, viscosity=viscosity,
                      pressure_viscosity=pressure_viscosity, modulus=modulus, density=density, grid=(grid, grid))
    t0 = time.perf_counter()
    s = pc.steady(raise_on_failure=False)
    M, L = pc.moes
    return dict(load=load, speed=speed, M=M, L=L, grid=grid, success=s.success, wall_s=time.perf_counter() - t0,
                newton=s.iterations, h_central=s.h_central, h_min=s.h_min, p_max_ratio=s.p_max / pc.hertz.p_max,
                hd_central=pc.hd_central, hd_minimum=pc.hd_minimum,
                nvm_central=nvm_central_film(load, speed, viscosity, pressure_viscosity, modulus, radius_x))


def chart_case(M, L, grid, density="incompressible") -> dict:
    """The contact of Moes' (M, L) with Rx = 10 mm, E' = 220 GPa, eta0 = 0.04 Pa s, 20 N (speed from M,
    alpha from L), Barus."""
    E, R, w, eta = 2.2e11, 0.01, 20.0, 0.04
    two_u = (w / (E * R * R) / M) ** (4.0 / 3.0)
    speed = two_u * E * R / (2.0 * eta)
    alpha = L / (E * two_u ** 0.25)
    return dict(formula_case(w, speed, alpha, grid, density=density), density=density)


def _ratio(a, b):
    return a / b if b else math.nan


def main(out, quick: bool = False) -> str:
    out = Path(out)
    sizes = (33, 49, 65) if quick else (33, 49, 65, 129, 257)
    rows = scaling(sizes, quick)
    var = variants((65,) if quick else (129, 257))
    hd_grid = 65 if quick else 129
    hd_points = ((10.0, 0.3), (30.0, 1.0)) if quick else \
        tuple((w, u) for w in (10.0, 30.0, 100.0) for u in (0.1, 0.3, 1.0))
    hd = [formula_case(w, u, 2e-8, hd_grid) for w, u in hd_points]
    if not quick:
        hd += [formula_case(w, u, 2e-8, 257) for w, u in ((10.0, 0.1), (30.0, 0.1), (100.0, 0.3))]
    chart = ([(100.0, 10.0)] if quick else [(M, L) for L in (5.0, 10.0, 20.0) for M in (20.0, 50.0, 100.0, 300.0, 1000.0)])
    nvm = [chart_case(M, L, 65 if quick else 129, d) for M, L in chart for d in ("incompressible", "dowson-higginson")]
    data = dict(scaling=rows, variants=var, hamrock_dowson=hd, nvm=nvm)
    (out / "ehl_point.json").write_text(json.dumps(data, indent=1))
    return report(data)


def report(data: dict) -> str:
    """The markdown section from the measured ``data`` (what :func:`main` writes to ``ehl_point.json``)."""
    rows, var, hd, nvm = data["scaling"], data["variants"], data["hamrock_dowson"], data["nvm"]
    lines = [f"## {TITLE}", "",
             "Circular contact, M = 205, L = 7.2, fully flooded, Hertz start, tolerance 1e-8; the methods in one "
             "run, interleaved per grid. Newton its: on the grid itself (in brackets: on the coarser grids of "
             "the nested start). s per Newton it: the time on the grid itself over its Newton iterations.", "",
             "| grid | unknowns | method | converged | wall [s] | CPU [s] | Newton its | GMRES its | "
             "set-up [s] | GMRES [s] | s per Newton it | h_c [nm] | h_min [nm] | state vs first |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        for name, _, _ in METHODS:
            if name not in r:
                continue
            m = r[name]
            coarse = " (" + ", ".join(f"{c[1]} on {c[0]}" for c in m["coarse"]) + ")" if m["coarse"] else ""
            kr = m["gmres"] is not None
            lines.append(f"| {r['n']} x {r['n']} | {r['unknowns']} | {name} | {m['success']} | {m['wall_s']:.2f} | "
                         f"{m['cpu_s']:.2f} | {m['newton']}{coarse} | {m['gmres'] if kr else '-'} | "
                         f"{m['setup_s']:.2f} | {m['gmres_s']:.2f} | " if kr else
                         f"| {r['n']} x {r['n']} | {r['unknowns']} | {name} | {m['success']} | {m['wall_s']:.2f} | "
                         f"{m['cpu_s']:.2f} | {m['newton']} | - | - | - | ")
            lines[-1] += (f"{m['fine_wall_s'] / max(m['newton'], 1):.3f} | {m['h_central'] * 1e9:.2f} | "
                          f"{m['h_min'] * 1e9:.2f} | {m['state_diff']:.1e} |")
    kry = [(r["unknowns"], r["Newton-Krylov"]["fine_wall_s"] / max(r["Newton-Krylov"]["newton"], 1))
           for r in rows if "Newton-Krylov" in r]
    if len(kry) > 1:
        lines += ["", "Cost of one Newton-Krylov iteration against N (exponent between successive grids; "
                  "N log N would give the second number):", ""]
        pairs = list(zip(kry, kry[1:])) + ([(kry[0], kry[-1])] if len(kry) > 2 else [])
        for (n1, t1), (n2, t2) in pairs:
            p = math.log(t2 / t1) / math.log(n2 / n1)
            q = math.log(n2 * math.log(n2) / (n1 * math.log(n1))) / math.log(n2 / n1)
            lines.append(f"- N = {n1} -> {n2}: {t1:.3f} -> {t2:.3f} s, exponent {p:.2f} ({q:.2f})")
    lines += ["", "### Preconditioner variants (nested start; the grid itself)", "",
              "| grid | preconditioner | converged | wall [s] | CPU [s] | Newton its | GMRES its per Newton it | "
              "set-ups | set-up [s] | GMRES [s] |", "|---|---|---|---|---|---|---|---|---|---|"]
    for v in var:
        lines.append(f"| {v['n']} x {v['n']} | {v['variant']} | {v['success']} | {v['wall_s']:.1f} | {v['cpu_s']:.1f} | "
                     f"{v['newton']} | {v['gmres_its']} | {v['setups']} | {v['setup_s']:.1f} | {v['gmres_s']:.1f} |")
    r0 = rows[0]
    lines += ["", f"Formulas for this case: Hamrock-Dowson h_c = {r0['hd_central'] * 1e9:.1f} nm, "
                  f"h_min = {r0['hd_minimum'] * 1e9:.1f} nm; Nijenbanning-Venner-Moes h_c = "
                  f"{r0['nvm_central'] * 1e9:.1f} nm.", "",
              "### Films against Hamrock-Dowson (circular, Barus, Dowson-Higginson density, steady())", "",
              "| w [N] | u [m/s] | M | L | grid | converged | wall [s] | h_c [nm] | h_c / HD | h_c / NVM | "
              "h_min [nm] | h_min / HD | p_max / p_H |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in hd:
        lines.append(f"| {c['load']:g} | {c['speed']:g} | {c['M']:.0f} | {c['L']:.1f} | {c['grid']} | {c['success']} | "
                     f"{c['wall_s']:.1f} | {c['h_central'] * 1e9:.1f} | {_ratio(c['h_central'], c['hd_central']):.3f} | "
                     f"{_ratio(c['h_central'], c['nvm_central']):.3f} | {c['h_min'] * 1e9:.1f} | "
                     f"{_ratio(c['h_min'], c['hd_minimum']):.3f} | {c['p_max_ratio']:.3f} |")
    lines += ["", "### Central film against Nijenbanning-Venner-Moes over Moes' chart (circular, Barus)",
              "", "| M | L | density | grid | converged | wall [s] | Newton its | H_c = (h_c/Rx)(2U)^-1/2 | NVM | ratio |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for c in nvm:
        two_u = 2.0 * 0.04 * c["speed"] / (2.2e11 * 0.01)
        H = c["h_central"] / 0.01 / math.sqrt(two_u)
        Hn = c["nvm_central"] / 0.01 / math.sqrt(two_u)
        lines.append(f"| {c['M']:.0f} | {c['L']:.0f} | {c['density']} | {c['grid']} | {c['success']} | {c['wall_s']:.1f} | "
                     f"{c['newton']} | {H:.3f} | {Hn:.3f} | {H / Hn:.3f} |")
    return "\n".join(lines)
