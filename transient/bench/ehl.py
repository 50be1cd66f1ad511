"""EHL of the tapered roller (Park): cost of the steady and transient solves, measured side by side.

1. The paper's case on the paper's 94 x 45 non-uniform grid: this package's solver (nested iteration
   47 x 45 -> 94 x 45, pseudo-transient continuation on the coarse level, GMRES with a reused
   single-precision LU on the fine one) against the paper's method -- the same finite-volume equations
   on the 94 x 45 grid alone, full Newton with the dense Jacobian factorised (LAPACK, double precision)
   at every iteration, globalised by the same pseudo-transient continuation from the dry pressure.
2. Uniform grids (DC-FFT elasticity, Newton-Krylov with the two-level preconditioner): wall time and
   the cost of one Newton iteration on the finest level against the number of unknowns N.
3. Transients (IDA, dense Jacobian) from the dry contact to the steady film, as multiples of one steady
   solve of the same problem: the line contact (401 nodes) and a coarse 2-D grid.
4. Service loads: the paper's case tilted +0.002 deg at 1x, 5x, 10x and 50x its load (W = 2e-5 ... 1e-3)
   on the paper grid by the film-content FBNS solve, and at 1x by the Reynolds-condition solve, side by
   side: converged, refused (``UnderResolvedGridError``) or not (the named failure's message), wall and CPU
   time and their ratio to the paper case, Newton iterations, H_c, H_min, P_max, and the worst row's x spacing
   against 4 b/M of its own load (``RollerContact.local_resolution``).

``main(out, quick)`` writes ``ehl.json`` into ``out`` and returns the markdown section.
"""

from __future__ import annotations

import json
import math
import os
import platform
import time
import warnings
from pathlib import Path

import numpy as np

from transient.models.roller import LineContact, RollerContact, TaperedRoller
from transient.models.roller.ehl_problem import solve_steady
from transient.models.roller.results import UnderResolvedGridError
from transient.models.roller.transient import GAMMA
from transient.solvers.settings import Integration
from transient.params import park

TITLE = "tapered-roller EHL (Park): paper grid vs the paper's dense Newton, uniform FFT grids, transients"


def _paper_contact(grid):
    return RollerContact.from_dimensionless(**park.DIMENSIONLESS, roller=TaperedRoller(**park.ROLLER),
                                            speed=park.SPEED, grid=grid)


def _summary(s):
    rm = s.mean_radius
    return dict(H_central=s.h_central / rm, H_min=s.h_min / rm, P_max=s.p_max / s.modulus)


def paper_case(grid) -> dict:
    """Ours vs the paper's method on ``grid`` (fresh contacts; the dry solve is timed separately)."""
    c = _paper_contact(grid)
    t0 = time.perf_counter()
    c.dry()
    t_dry = time.perf_counter() - t0
    t0 = time.perf_counter()
    ours = c.steady(method="fbns")
    t_ours = time.perf_counter() - t0
    c1 = _paper_contact(grid)
    c1._dry = c.dry()
    t0 = time.perf_counter()
    rc = c1.steady(method="reynolds")
    t_rc = time.perf_counter() - t0
    c2 = _paper_contact(grid)
    c2._dry = c.dry()  # the same footprint: both methods start from the same dry contact
    t0 = time.perf_counter()
    film = c2.film_problem(c2.grid)
    t_k = time.perf_counter() - t0
    nr = solve_steady(film, c2.initial_guess(film), tol=1e-8, max_iter=80, pseudo_time=0.3,
                      name="paper's method (dense Newton)")
    t_paper = time.perf_counter() - t0
    base = c2.result(film, nr.x, True, "", nr.iterations, nr.residual_norms, t_paper)
    diff = {k: abs(v / _summary(ours)[k] - 1) for k, v in _summary(base).items()}
    diff_rc = max(abs(v / _summary(ours)[k] - 1) for k, v in _summary(rc).items())
    return dict(grid=list(c.grid_spec[1:]), unknowns=int(film.n + 1), dry_s=t_dry, ours_s=t_ours,
                reynolds_s=t_rc, reynolds_levels=rc.solver_info["levels"], reynolds=_summary(rc),
                fbns_vs_reynolds=diff_rc, pressure_difference=float(np.max(np.abs(rc.pressure - ours.pressure)) / ours.p_max),
                paper_s=t_paper, influence_matrix_s=t_k, paper_iterations=int(nr.iterations),
                paper_factorisations=int(nr.n_factorisations), ours_levels=ours.solver_info["levels"],
                ours=_summary(ours), paper=_summary(base), max_relative_difference=max(diff.values()))


def uniform_case(grid) -> dict:
    c = _paper_contact(grid)
    c.dry()
    t0 = time.perf_counter()
    s = c.steady()
    wall = time.perf_counter() - t0
    fine = s.solver_info["levels"][-1]
    return dict(grid=list(grid), unknowns=int(c.grid.n + 1), wall_s=wall, levels=s.solver_info["levels"],
                fine_iterations=fine["iterations"], gmres=fine.get("gmres_iterations"), **_summary(s))


def _time_fine_level(grid) -> float:
    """Wall time of the finest uniform level alone (the nested levels before it solved first, untimed)."""
    c = _paper_contact(grid)
    c.dry()
    specs = c.levels()
    prev = _paper_contact(specs[-2][1:] if specs[-2][0] == "uniform" else specs[-2])
    prev._dry = c.dry()
    sp = prev.steady(tol=1e-8)
    from transient.models.roller.ehl_problem import interpolate_state
    from transient.models.roller.krylov import NewtonKrylov, NewtonMatrix, TwoLevel

    coarse_c = _paper_contact(specs[0])
    coarse_c._dry = c.dry()
    coarse = coarse_c.film_problem(coarse_c.grid)
    film = c.film_problem(c.grid, "fft")
    g_prev = prev.grid
    u0 = interpolate_state(g_prev, sp.state, c.grid)
    jac = NewtonKrylov(film, lambda f, v, shift: TwoLevel(f, coarse, v, shift, NewtonMatrix(f, v, shift)),
                       restart=80, max_iter=400, refresh_after=60)
    t0 = time.perf_counter()
    nr = solve_steady(film, u0, tol=1e-8, jacobian=jac, max_iter=60)
    return dict(wall_s=time.perf_counter() - t0, iterations=int(nr.iterations), gmres=jac.gmres_iterations,
                preconditioners=jac.n_preconditioners, unknowns=int(film.n + 1))


def service_loads(quick: bool) -> list:
    """The tilted paper case at multiples of its load on the paper grid (``quick``: 1x and 5x on 62 x 45), side
    by side: the film-content FBNS solve (the default above the paper case's load) at 1x, 5x, 10x and 50x, and the Reynolds-condition solve
    at 1x; at 10x also on the clustered 94 x 89 and on the default grid (x uniform, y clustered; at 50x the
    default grid is refused: it would need more x nodes than it is verified on). Wall and CPU time, Newton iterations; a load that is refused or does not converge gives the named
    error's message (docs/ehl.md, section 8)."""
    out = []
    grid = ("clustered", 62, 45) if quick else "paper"
    cases = [(1.0, "reynolds", grid), (1.0, "fbns", grid), (5.0, "fbns", grid)]
    if not quick:
        cases += [(10.0, "fbns", grid), (10.0, "fbns", ("clustered", 94, 89)), (10.0, "fbns", None),
                  (50.0, "fbns", grid)]
    for factor, method, grid in cases:
        c = RollerContact.from_dimensionless(**dict(park.DIMENSIONLESS, W=park.DIMENSIONLESS["W"] * factor),
                                             roller=TaperedRoller(**dict(park.ROLLER, tilt_deg=0.002)),
                                             speed=park.SPEED, grid=grid)
        dry = c.dry()
        t0, c0 = time.perf_counter(), time.process_time()
        try:
            s = c.steady(raise_on_failure=False, method=method)
        except UnderResolvedGridError as exc:
            out.append(dict(factor=factor, method=method, W=c.W, M=c.mid_plane_M, success=False, refused=True,
                            wall_s=time.perf_counter() - t0, cpu_s=time.process_time() - c0, iterations=0,
                            message=str(exc), worst_ratio=exc.resolution["worst_ratio"],
                            grid=[int(c.grid.x.size), int(c.grid.y.size)]))
            continue
        cont = s.solver_info.get("continuation", {})
        out.append(dict(factor=factor, method=method, W=c.W, M=c.mid_plane_M, refused=False,
                        grid=[int(c.grid.x.size), int(c.grid.y.size)], success=bool(s.success),
                        wall_s=time.perf_counter() - t0, cpu_s=time.process_time() - c0, iterations=int(s.iterations),
                        steps=cont.get("steps", 0), rejected=cont.get("rejected", 0), message=s.message,
                        h_central=s.h_central, h_min=s.h_min, y_of_h_min=s.y_of_h_min / c.roller.mean_radius,
                        H_central=s.h_central / c.roller.mean_radius, H_min=s.h_min / c.roller.mean_radius,
                        P_max=s.p_max / c.modulus, p_max=s.p_max, p_dry=dry.p_max, load_error=s.load_error,
                        worst_ratio=c.local_resolution(s)["worst_ratio"] if np.any(s.pressure > 0) else float("nan")))
    return out


def transients(quick: bool) -> list:
    out = []
    lc = LineContact(0.01, 3.1e4, 1.0, 0.022, 2500 / 220e9, 220e9, grid=201 if quick else 401, domain=(-5.0, 2.5))
    lc.steady(penalty=GAMMA)  # JIT warm-up
    t0 = time.perf_counter()
    s = lc.steady(penalty=GAMMA)
    ts = time.perf_counter() - t0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # the penalty form (ida), beside the film content's row
        r = lc.transient(t_end=40 * lc.time_scale, start="dry", n_out=21, integration=Integration(method="ida", rtol=1e-5))
    out.append(dict(case=f"line contact, {lc.grid.x.size} nodes", steady_s=ts, transient_s=r.wall_time,
                    ratio=r.wall_time / ts, steps=r.n_steps, jacobians=r.n_jacobians, success=r.success,
                    limit_error=abs(r.h_central[-1] / s.h_central - 1)))
    t0 = time.perf_counter()
    s = lc.steady()  # the exact complementarity: the film-content transient's limit
    ts = time.perf_counter() - t0
    r = lc.transient(t_end=40 * lc.time_scale, start="dry", n_out=21, integration=Integration(method="bdf2", rtol=1e-5))
    out.append(dict(case=f"line contact, {lc.grid.x.size} nodes, film content (BDF2)", steady_s=ts,
                    transient_s=r.wall_time, ratio=r.wall_time / ts, steps=r.n_steps, jacobians=r.n_jacobians,
                    success=r.success, limit_error=abs(r.h_central[-1] / s.h_central - 1)))
    ro = TaperedRoller(0.01, 10.0, 0.02, 0.005, 0.002, 0.0)
    c = RollerContact.from_dimensionless(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=220e9, roller=ro,
                                         grid=("clustered", 32, 25))
    c.dry()
    t0 = time.perf_counter()
    s = c.steady(penalty=GAMMA)
    ts = time.perf_counter() - t0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # the penalty form (ida), against steady(penalty=GAMMA)
        r = c.transient(t_end=(20 if quick else 40) * c.time_scale, start="dry", n_out=11,
                        integration=Integration(method="ida", rtol=1e-5))
    out.append(dict(case=f"roller (Y_d = 0.2 R_m), clustered 32 x 25 ({c.grid.n + 1} unknowns)", steady_s=ts,
                    transient_s=r.wall_time, ratio=r.wall_time / ts, steps=r.n_steps, jacobians=r.n_jacobians,
                    success=r.success, limit_error=abs(r.h_central[-1] / s.h_central - 1)))
    return out


def main(out, quick: bool = False) -> str:
    out = Path(out)
    t_all = time.perf_counter()
    _paper_contact(("clustered", 47, 45)).steady()  # JIT warm-up of every kernel (both forms)
    _paper_contact(("clustered", 47, 45)).steady(method="reynolds")
    paper = paper_case(("clustered", 62, 45) if quick else "paper")
    uni_grids = [(64, 512)] if quick else [(64, 512), (128, 512), (256, 512)]
    uniform = [uniform_case(g) for g in uni_grids]
    fine = [_time_fine_level(g) for g in uni_grids[1:]]
    trans = transients(quick)
    service = service_loads(quick)
    data = dict(service=service, machine=platform.processor() or platform.machine(), paper=paper, uniform=uniform, fine_levels=fine,
                openblas_threads=os.environ.get("OPENBLAS_NUM_THREADS"), transients=trans,
                total_s=time.perf_counter() - t_all)
    (out / "ehl.json").write_text(json.dumps(data, indent=1, default=float))
    p = paper
    levels = p["ours_levels"]
    ours_its = f"{sum(v['iterations'] for v in levels)} ({' + '.join(str(v['iterations']) for v in levels)})"
    rlev = p["reynolds_levels"]
    rc_its = f"{sum(v['iterations'] for v in rlev)} ({' + '.join(str(v['iterations']) for v in rlev)})"
    lines = [
        "## Tapered-roller EHL (Park)", "",
        f"`transient bench ehl`{' --quick' if quick else ''}; 2 cores, possibly shared with other work (absolute "
        "seconds then vary by up to 2x; the ratios measured in one run are the numbers); "
        f"OPENBLAS_NUM_THREADS={data['openblas_threads']}.", "",
        f"### The paper's case (U = 1e-11, G = 2500, W = 2e-5, tilt 0) on {p['grid'][0]} x {p['grid'][1]} nodes "
        f"({p['unknowns']} unknowns)", "",
        "| method | wall [s] | Newton iterations | factorisations | H_central | H_min | P_max |",
        "|---|---|---|---|---|---|---|",
        f"| this package, film-content FBNS (`method=\"fbns\"`; the default above the paper case's load): x levels {' -> '.join(str(v['grid'][0]) for v in levels)}, "
        f"GMRES + reused float32 LU | {p['ours_s']:.1f} | {ours_its} | "
        f"{sum(v.get('factorisations', 0) for v in levels)} | "
        f"{p['ours']['H_central']:.4e} | {p['ours']['H_min']:.4e} | {p['ours']['P_max']:.4e} |",
        f"| this package, Reynolds-condition form (`method=\"reynolds\"`; the default at and below the paper case's load), same levels and linear algebra | "
        f"{p['reynolds_s']:.1f} | {rc_its} | {sum(v.get('preconditioners', 0) for v in rlev)} | "
        f"{p['reynolds']['H_central']:.4e} | {p['reynolds']['H_min']:.4e} | {p['reynolds']['P_max']:.4e} |",
        f"| paper's method: full Newton, dense LU every iteration | {p['paper_s']:.1f} | {p['paper_iterations']} | "
        f"{p['paper_factorisations']} | {p['paper']['H_central']:.4e} | {p['paper']['H_min']:.4e} | "
        f"{p['paper']['P_max']:.4e} |",
        "",
        f"Speed-up over the paper's method {p['paper_s'] / p['ours_s']:.1f}x (FBNS), {p['paper_s'] / p['reynolds_s']:.1f}x "
        f"(Reynolds condition); FBNS and the paper's method agree to {p['max_relative_difference']:.1e} in "
        f"H_c, H_min, P_max, FBNS and the Reynolds-condition form to {p['fbns_vs_reynolds']:.1e} (pressure field: "
        f"{p['pressure_difference']:.1e} of P_max; both solved to a scaled residual of 1e-8). Not included in either: the dry contact that sizes the domain ({p['dry_s']:.1f} s, two "
        f"Polonsky-Keer passes); included in both: the dense influence matrix ({p['influence_matrix_s']:.1f} s on "
        f"the fine grid). GMRES iterations per Newton step (fine level): {levels[-1].get('gmres_iterations')}.", "",
        "### Uniform grids: DC-FFT elasticity, Newton-Krylov with the two-level preconditioner", "",
        "A uniform grid must resolve the profiled ends (1.2 c long): y spacing <= 0.6 c, i.e. >= 450 nodes over "
        "the paper's +-0.55 d; 256 x 128 (2.1 c) is rejected by the grid check (its ends have one node). Each "
        "solve: clustered 47 x 45 first (also the coarse grid of the preconditioner), then uniform levels "
        "doubling nx.", "",
        "| grid | unknowns | wall [s] | Newton its per level | GMRES its, finest level | H_central | H_min |",
        "|---|---|---|---|---|---|---|"]
    for u in uniform:
        its = " + ".join(str(v["iterations"]) for v in u["levels"])
        lines.append(f"| {u['grid'][0]} x {u['grid'][1]} | {u['unknowns']} | {u['wall_s']:.1f} | {its} | "
                     f"{u['gmres']} | {u['H_central']:.4e} | {u['H_min']:.4e} |")
    if fine:
        lines += ["", "Finest level alone (started from the previous uniform level):", "",
                  "| unknowns N | wall [s] | Newton its | s per Newton it | s per it / (N log2 N) x 1e6 |",
                  "|---|---|---|---|---|"]
        for f in fine:
            per = f["wall_s"] / max(f["iterations"], 1)
            lines.append(f"| {f['unknowns']} | {f['wall_s']:.1f} | {f['iterations']} | {per:.2f} | "
                         f"{per / (f['unknowns'] * math.log2(f['unknowns'])) * 1e6:.2f} |")
    lines += ["", "### Transients from the dry contact to the steady film: IDA on the penalty form (dense analytic "
              "Jacobian; limit vs steady(penalty)), BDF2 on the film content (one FBNS Newton per step; Jacobians: "
              "its factorisations; limit vs steady())", "",
              "| case | steady [s] | transient [s] | ratio | steps | Jacobians | limit vs steady |",
              "|---|---|---|---|---|---|---|"]
    for t in trans:
        lines.append(f"| {t['case']} | {t['steady_s']:.2f} | {t['transient_s']:.1f} | {t['ratio']:.0f} | "
                     f"{t['steps']} | {t['jacobians']} | {t['limit_error']:.1e} |")
    lines += ["", "IDA's dense linear solver (SUNDIALS' own LU; the facade offers no LAPACK variant) refactorises "
              "the (N+1)^2 Jacobian hundreds of times: on the paper grid (3957 unknowns) one factorisation is "
              "~40 GFlop, so a transient there would take hours; the 2-D transient is therefore run on a coarse "
              "grid."]
    base = next(r for r in service if r["method"] == "fbns" and r["factor"] == 1.0)
    lines += ["", "### Service loads: the paper's case tilted +0.002 deg at multiples of its load", "",
              "fbns: the mass-conserving film-content form by Fischer-Burmeister-Newton-Schur (the default above the paper case's load); "
              "reynolds: the Reynolds-condition form (Fischer-Burmeister exit condition, pseudo-time and load "
              "continuation). Times include the dry contact that sizes the domain.", "",
              "| load | W | mid-plane M | grid | method | converged | wall [s] | CPU [s] | wall / fbns 1x | Newton its | "
              "H_c | H_min (Y/R_m) | P_max | p_max / dry p_max | worst row: spacing / (4 b/M) |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in service:
        head = (f"| {r['factor']:g}x | {r['W']:.0e} | {r['M']:.1f} | {r['grid'][0]} x {r['grid'][1]} | {r['method']} | "
                f"{'refused' if r['refused'] else 'yes' if r['success'] else 'NO'} | {r['wall_s']:.1f} | "
                f"{r['cpu_s']:.1f} | {r['wall_s'] / base['wall_s']:.2f} | {r['iterations']} |")
        if r["refused"]:
            lines.append(head + f" - | - | - | - | {r['worst_ratio']:.2f} (dry pressure) |")
        else:
            lines.append(head + f" {r['H_central']:.4e} | {r['H_min']:.3e} ({r['y_of_h_min']:+.4f}) | "
                         f"{r['P_max']:.4e} | {r['p_max'] / r['p_dry']:.3f} | {r['worst_ratio']:.2f} |")
    for r in service:
        if not r["success"]:
            lines.append(f"\n{r['factor']:g}x ({r['grid'][0]} x {r['grid'][1]}, {r['method']}): {r['message']}")
    lines += ["", f"Total bench time {data['total_s']:.0f} s."]
    return "\n".join(lines)
