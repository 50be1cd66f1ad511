"""EHL line contact over the Moes chart: the film-content FBNS solver against the Reynolds-condition solver.

In one run (fully flooded domains and clustered grids of :mod:`transient.study.ehl_chart`, cold starts):

* the whole chart (M = 1 ... 1000 x L = 0 ... 25, Barus, incompressible) by :meth:`LineContact.steady`
  (film-content Fischer-Burmeister-Newton-Schur along grid levels and the load path,
  :mod:`transient.models.roller.line_sequence`): converged, wall and CPU time, Newton iterations (all
  levels and load steps), H_c against Moes' formula;
* side by side, interleaved, at a few points: :meth:`LineContact.steady_reynolds` (the semismooth Newton
  on the Reynolds-condition equations with load continuation) on the same contact, and the largest
  difference of the two films (the same discrete problem);
* Roelands viscosity and Dowson-Higginson density at a few points;
* the cost of the pieces of one Newton iteration against the node count n: residual, Schur matrix
  assembly (both O(n^2), dense elasticity), single-precision LU (O(n^3), made only when the reused one
  stops preconditioning), one preconditioned GMRES solve.

``main(out, quick)`` writes ``ehl_line.json`` into ``out`` and returns the markdown section.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np

from transient.bench import best_of
from transient.models.roller.line_fbns import LineContentFilm
from transient.models.roller.line_newton import _gmres, _Preconditioner, schur_system
from transient.models.roller.line_sequence import solve_sequence
from transient.study.ehl_chart import chart_contact, chart_point

TITLE = "EHL line contact over the Moes chart: film-content FBNS vs Reynolds-condition Newton, cost per iteration"

M_CHART, L_CHART = (1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0), (0.0, 2.0, 5.0, 10.0, 20.0, 25.0)


def reynolds_solver(M, L, nodes) -> dict:
    """:meth:`LineContact.steady_reynolds` at a chart point: converged, wall, CPU, iterations, film."""
    c = chart_contact(M, L, nodes=nodes)
    t0, c0 = time.perf_counter(), time.process_time()
    s = c.steady_reynolds(raise_on_failure=False)
    return dict(success=bool(s.success), wall_s=time.perf_counter() - t0, cpu_s=time.process_time() - c0,
                iterations=s.iterations, film=s.film)


def iteration_cost(n: int, repeat: int = 3) -> dict:
    """Seconds of the pieces of one Newton iteration on ``n`` nodes (M = 100, L = 10, at the solution of
    a coarse sequence carried over: a representative state)."""
    c = chart_contact(100.0, 10.0, nodes=n)
    lf = LineContentFilm(c.film_problem())
    seq = solve_sequence(chart_contact(100.0, 10.0, nodes=257))
    from transient.models.roller.line_sequence import carry

    u = carry(seq.content.base.grid, seq.state, lf.base.grid)
    e = lf.equations(u)
    S, r, _ = schur_system(lf, u, e)
    pre = _Preconditioner(S)
    return dict(nodes=n, residual=best_of(lambda: lf.equations(u), repeat)[0],
                schur=best_of(lambda: schur_system(lf, u, e), repeat)[0],
                lu=best_of(lambda: _Preconditioner(S), repeat)[0],
                gmres=best_of(lambda: _gmres(S, r, pre), repeat)[0])


def main(out, quick: bool = False) -> str:
    out = Path(out)
    nodes = 513 if quick else 1025
    Ms, Ls = ((1.0, 100.0, 1000.0), (0.0, 25.0)) if quick else (M_CHART, L_CHART)
    pairs = [(10.0, 0.0)] if quick else [(10.0, 0.0), (100.0, 10.0), (1000.0, 0.0)]
    chart_point(10.0, 5.0, nodes=257)  # JIT warm-up
    reynolds_solver(10.0, 5.0, 129)
    rows = []
    for M in Ms:
        for L in Ls:
            r = chart_point(M, L, nodes=nodes)
            r.pop("asymptotes")
            rows.append(r)
    side = []
    for M, L in pairs:  # interleaved: the new solver, then the Reynolds-condition solver, same contact
        c = chart_contact(M, L, nodes=nodes)
        t0, c0 = time.perf_counter(), time.process_time()
        new = c.steady(raise_on_failure=False)
        new_wall, new_cpu = time.perf_counter() - t0, time.process_time() - c0
        old = reynolds_solver(M, L, nodes)
        diff = float(np.max(np.abs(new.film / old.pop("film") - 1.0))) if old["success"] else float("nan")
        side.append(dict(M=M, L=L, new=dict(success=bool(new.success), wall_s=new_wall, cpu_s=new_cpu,
                                            iterations=new.iterations), old=old, film_difference=diff))
    rheo = []
    for M, L in ([(100.0, 10.0)] if quick else [(1.0, 10.0), (100.0, 10.0), (1000.0, 10.0), (1000.0, 25.0)]):
        for density, law in (("incompressible", "roelands"), ("dowson-higginson", "barus"),
                             ("dowson-higginson", "roelands")):
            r = chart_point(M, L, nodes=nodes, density=density, viscosity_law=law)
            rheo.append(dict(M=M, L=L, density=density, law=law, success=r["success"], wall_s=r["wall_s"],
                             cpu_s=r["cpu_s"], iterations=r["iterations"], deviation=r["deviation"],
                             message=r["message"]))
    costs = [iteration_cost(n) for n in ((257, 513, 1025) if quick else (257, 513, 1025, 2049, 4097))]
    threads = os.environ.get("OPENBLAS_NUM_THREADS", "unset")
    (out / "ehl_line.json").write_text(json.dumps(dict(nodes=nodes, chart=rows, side_by_side=side, rheology=rheo,
                                                       iteration_cost=costs, openblas_threads=threads),
                                                  indent=1, default=float))
    ok = [r for r in rows if r["success"]]
    slow = max(rows, key=lambda r: r["wall_s"])
    slow_cpu = max(rows, key=lambda r: r["cpu_s"])
    lines = ["## EHL line contact over the Moes chart", "",
             f"`transient bench ehl_line`{' --quick' if quick else ''}; clustered grids of {nodes} nodes, fully "
             "flooded domains (`transient.study.ehl_chart`), cold starts, Barus, incompressible unless said; "
             f"BLAS on one thread inside the solver (OPENBLAS_NUM_THREADS = {threads} outside it); 2 cores "
             "shared with other jobs (wall time is the elapsed "
             "time and grows with the machine's load; CPU time is this process's, all threads).", "",
             f"**Whole chart with `LineContact.steady` (film-content FBNS): {len(ok)} of {len(rows)} points "
             f"converged.** Slowest point: M = {slow['M']:g}, L = {slow['L']:g} ({slow['wall_s']:.2f} s wall, "
             f"{slow['cpu_s']:.2f} s CPU); largest CPU: M = {slow_cpu['M']:g}, L = {slow_cpu['L']:g} "
             f"({slow_cpu['cpu_s']:.2f} s). Median wall {np.median([r['wall_s'] for r in rows]):.2f} s, "
             f"CPU {np.median([r['cpu_s'] for r in rows]):.2f} s.", "",
             "| M | L | converged | wall [s] | CPU [s] | Newton its | H_c | H_c / Moes - 1 |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['M']:g} | {r['L']:g} | {'yes' if r['success'] else 'NO'} | {r['wall_s']:.2f} | "
                     f"{r['cpu_s']:.2f} | {r['iterations']} | {r['H_c']:.4g} | {100 * r['deviation']:+.1f} % |")
    lines += ["", "Side by side on the same contacts (interleaved): film-content FBNS (`steady`) and the "
              "Reynolds-condition Newton with load continuation (`steady_reynolds`); max |h_new/h_old - 1| "
              "over the nodes:", "",
              "| M | L | FBNS wall [s] | CPU [s] | its | Reynolds-condition: converged | wall [s] | CPU [s] | its | "
              "film difference |", "|---|---|---|---|---|---|---|---|---|---|"]
    for s in side:
        n_, o = s["new"], s["old"]
        lines.append(f"| {s['M']:g} | {s['L']:g} | {n_['wall_s']:.2f} | {n_['cpu_s']:.2f} | {n_['iterations']} | "
                     f"{'yes' if o['success'] else 'NO'} | {o['wall_s']:.1f} | {o['cpu_s']:.1f} | {o['iterations']} | "
                     f"{s['film_difference']:.1e} |")
    lines += ["", "Other rheology (same grids, `steady`):", "",
              "| M | L | density | viscosity | converged | wall [s] | CPU [s] | its | H_c / Moes - 1 |",
              "|---|---|---|---|---|---|---|---|---|"]
    for r in rheo:
        lines.append(f"| {r['M']:g} | {r['L']:g} | {r['density']} | {r['law']} | {'yes' if r['success'] else 'NO'} | "
                     f"{r['wall_s']:.2f} | {r['cpu_s']:.2f} | {r['iterations']} | {100 * r['deviation']:+.1f} % |")
    lines += ["", "Cost of the pieces of one Newton iteration against n (best of 3, wall):", "",
              "| nodes | residual [ms] | Schur matrix [ms] | LU, single precision [ms] | preconditioned GMRES [ms] |",
              "|---|---|---|---|---|"]
    lines += [f"| {c['nodes']} | {1e3 * c['residual']:.2f} | {1e3 * c['schur']:.2f} | {1e3 * c['lu']:.1f} | "
              f"{1e3 * c['gmres']:.2f} |" for c in costs]
    lines += ["", "Residual, Schur assembly and GMRES products are O(n^2) (the dense influence matrix of a "
              "non-uniform grid), the LU O(n^3); an iteration costs O(n^2) except when the factorisation is "
              "renewed. Not O(n log n): that needs a uniform grid (DC-FFT products) or multilevel "
              "multi-integration, and a preconditioner that does not factorise the dense matrix."]
    return "\n".join(lines)
