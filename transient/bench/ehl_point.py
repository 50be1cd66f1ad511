"""EHL point contact at scale: dense LU against Newton-Krylov, side by side, over grid sizes; films against
Hamrock-Dowson and Nijenbanning-Venner-Moes.

1. Solver cost. A circular steel contact (Rx = 10 mm, 20 N, 0.2 m/s, eta0 = 0.04 Pa s, alpha = 2e-8 1/Pa,
   E' = 220 GPa, Barus, Dowson-Higginson density: Moes M = 205, L = 7.2), fully flooded, on uniform n x n
   grids, the FBNS Newton (:func:`~transient.models.point.fbns.fbns`, tolerance 1e-8 on the scaled
   residual) with its reduced linear systems solved, in one run and interleaved per grid, by

   * ``dense LU``: the dense reduced Newton matrix, LAPACK LU (O(N^3); grids up to 65 x 65);
   * ``Newton-Krylov``: GMRES on the matrix-free reduced matrix (DC-FFT products) with the two-level
     preconditioner of :mod:`transient.models.ehl.krylov`, from the dry Hertz start;
   * ``Newton-Krylov, nested``: the same from the solution on every second node (itself nested down to the
     dense size) -- what :meth:`PointContact.steady` does by default above the dense size.

   Reported: converged, wall and CPU time, Newton iterations on the grid itself (and on the coarser grids
   of the nested start), GMRES iterations, preconditioner set-up and GMRES seconds, seconds per Newton
   iteration, the films, and the cost of one Newton-Krylov iteration against the unknown count N.
2. Fully flooded films against Hamrock & Dowson (*J. Lubr. Technol.* 99, 1977) over loads and speeds.
3. Central films against Nijenbanning, Venner & Moes (*Wear* 176, 1994) over Moes' chart (Barus,
   incompressible).
4. Grid convergence of h_c and h_min (circular, Dowson-Higginson density) at M = 31 ... 1726: 129, 257 and
   513 nodes per side on the default domain and on a compact one around the contact (the same nodes, finer
   spacing), the observed order and Richardson's extrapolation; the compact domain's inlet and sides grown
   at the same spacing to show the films do not depend on them; on the default domain (M = 31 ... 518) the same
   grids with the second-order upwind Couette flux (``upwind="second"``) in the same run, interleaved per grid, with the
   Newton iterations and wall times of both fluxes side by side.

``main(out, quick)`` writes ``ehl_point.json`` into ``out`` and returns the markdown section
(:func:`report` of that data).
"""

from __future__ import annotations

import json
import math
import time
import warnings
from pathlib import Path

import numpy as np

from transient.models.point import PointContact
from transient.models.point.fbns import fbns, linear_solver
from transient.models.point.formulas import nvm_central_film
from transient.models.ehl.krylov import KrylovSolver

TITLE = "EHL point contact at scale: dense LU vs Newton-Krylov, cost against the grid; films against formulas"

CASE = dict(radius_x=0.01, load=20.0, speed=0.2, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11,
            upwind="first")

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
                 modulus=2.2e11, radius_x=0.01, check_grid=False) -> dict:
    pc = PointContact(radius_x=radius_x, load=load, speed=speed, viscosity=viscosity,
                      pressure_viscosity=pressure_viscosity, modulus=modulus, density=density, grid=(grid, grid),
                      upwind="first")
    t0 = time.perf_counter()
    with warnings.catch_warnings():  # the grid check's verdict is a column of the table
        warnings.simplefilter("ignore", UserWarning)
        s = pc.steady(raise_on_failure=False, check_grid=check_grid)
    M, L = pc.moes
    return dict(load=load, speed=speed, M=M, L=L, grid=grid, success=s.success, wall_s=time.perf_counter() - t0,
                newton=s.iterations, h_central=s.h_central, h_min=s.h_min, p_max_ratio=s.p_max / pc.hertz.p_max,
                hd_central=pc.hd_central, hd_minimum=pc.hd_minimum,
                nvm_central=nvm_central_film(load, speed, viscosity, pressure_viscosity, modulus, radius_x),
                grid_settled=s.grid_settled if check_grid else None,
                change_h_min=s.grid_change.get("change_h_min") if check_grid else None)


def chart_case(M, L, grid, density="incompressible") -> dict:
    """The contact of Moes' (M, L) with Rx = 10 mm, E' = 220 GPa, eta0 = 0.04 Pa s, 20 N (speed from M,
    alpha from L), Barus."""
    E, R, w, eta = 2.2e11, 0.01, 20.0, 0.04
    two_u = (w / (E * R * R) / M) ** (4.0 / 3.0)
    speed = two_u * E * R / (2.0 * eta)
    alpha = L / (E * two_u ** 0.25)
    return dict(formula_case(w, speed, alpha, grid, density=density), density=density)


#: grid-convergence cases (w [N], u [m/s]): M = 31, 173, 518, 1726 at G = 4400, Rx = 10 mm
GRID_CASES = ((10.0, 1.0), (10.0, 0.1), (30.0, 0.1), (100.0, 0.1))
GRID_SIZES = (129, 257, 513)


def compact_domain(pc: PointContact) -> tuple:
    """The domain around the contact [units of b]: the inlet at 2.5 b or 1.25 Hamrock-Dowson critical
    menisci (the further), the outlet at 1.5 b, the sides at 1.6 b (circular)."""
    return (-max(2.5, 1.25 * pc.m_c), 1.5, 1.6)


def grid_point(w, u, grid, domain, upwind="first") -> dict:
    pc = PointContact(radius_x=0.01, load=w, speed=u, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11,
                      grid=grid, domain=domain, upwind=upwind)
    t0 = time.perf_counter()
    s = pc.steady(raise_on_failure=False, check_grid=False)
    return dict(grid=list(grid), domain=list(pc.domain), dx=float(pc.x_nodes[1] - pc.x_nodes[0]),
                success=s.success, wall_s=time.perf_counter() - t0, h_central=s.h_central, h_min=s.h_min,
                newton=s.iterations, upwind=upwind,
                x_of_h_min=s.x_of_h_min / pc.b, y_of_h_min=s.y_of_h_min / pc.b, flooded=s.flooded_inlet)


def richardson(values, scheme_order: int = 1) -> dict:
    """Observed order ``p = log2((f1 - f2)/(f2 - f3))`` of three grids halving the spacing (when the changes
    have one sign and shrink), and the extrapolations ``f3 + (f3 - f2)/(2^p - 1)`` at that order (only for
    ``p >= 0.5``: below it the grids are not in the asymptotic range and the extrapolation runs away) and at
    the scheme's formal order ``k`` (``f3 + (f3 - f2)/(2^k - 1)``: ``2 f3 - f2`` at first order)."""
    f1, f2, f3 = values
    d1, d2 = f1 - f2, f2 - f3
    p = math.log2(d1 / d2) if d1 * d2 > 0 and abs(d1) > abs(d2) else None
    extrapolated = f3 + (f3 - f2) / (2.0 ** p - 1.0) if p is not None and p >= 0.5 else None
    return dict(order=p, extrapolated=extrapolated, at_scheme_order=f3 + (f3 - f2) / (2.0 ** scheme_order - 1.0),
                scheme_order=scheme_order)


#: the name of the default domain's rows with the second-order upwind Couette flux
SECOND = "default, 2nd-order upwind"


def grid_convergence(quick: bool) -> list:
    sizes = GRID_SIZES[:2] if quick else GRID_SIZES
    out = []
    for w, u in (GRID_CASES[2:3] if quick else GRID_CASES):
        pc = PointContact(radius_x=0.01, load=w, speed=u, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)
        M, L = pc.moes
        case = dict(load=w, speed=u, M=M, L=L, hd_central=pc.hd_central, hd_minimum=pc.hd_minimum,
                    m_c=pc.m_c, rows=[])
        compact = compact_domain(pc)
        for name, dom in (("default", None), ("compact", compact)):
            for n in sizes:
                case["rows"].append(dict(grid_point(w, u, (n, n), dom), domain_name=name))
                if name == "default" and M < 1000:  # the second-order flux interleaved (M = 31 ... 518)
                    case["rows"].append(dict(grid_point(w, u, (n, n), dom, "second"), domain_name=SECOND))
        # the compact domain grown at its 257-node spacing: the inlet by half the length, the sides by 0.4 b
        n = sizes[1]
        length = compact[1] - compact[0]
        case["inlet_grown"] = grid_point(w, u, (n + (n - 1) // 2, n), (compact[0] - 0.5 * length, 1.5, 1.6))
        case["sides_grown"] = grid_point(w, u, (n, n + (n - 1) // 4), (compact[0], 1.5, 2.0))
        case["compact_257"] = next(r for r in case["rows"] if r["domain_name"] == "compact" and r["grid"][0] == n)
        for name in ("default", "compact", SECOND):
            rows = [r for r in case["rows"] if r["domain_name"] == name]
            if len(rows) == 3:
                k = 2 if name == SECOND else 1
                case[f"richardson_{name}"] = {q: richardson([r[q] for r in rows], k) for q in ("h_central", "h_min")}
        out.append(case)
    return out


def grid_report(cases) -> list:
    lines = ["", "### Grid convergence of h_c and h_min (circular, Barus, Dowson-Higginson density, steady())", "",
             "Default domain X in [-4.5, 1.5] b (further upstream when Hamrock-Dowson's critical meniscus "
             "needs it), |Y| <= 2.5 b; compact: the inlet at max(2.5, 1.25 m_c) b, |Y| <= 1.6 b. n x n nodes; "
             "h_min/HD against Hamrock-Dowson's h_min.", "",
             "| M | L | domain | grid | dx [b] | converged | wall [s] | h_c [nm] | h_c/HD | h_min [nm] | h_min/HD | "
             "h_min at (x, y) [b] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        for r in c["rows"] + [dict(c["inlet_grown"], domain_name="compact, inlet grown"),
                              dict(c["sides_grown"], domain_name="compact, sides grown")]:
            d = r["domain"]
            lines.append(f"| {c['M']:.0f} | {c['L']:.1f} | {r['domain_name']} [{d[0]:.2f}, {d[1]:.1f}] x "
                         f"{d[2]:.1f} | {r['grid'][0]} x {r['grid'][1]} | {r['dx']:.4f} | {r['success']} | "
                         f"{r['wall_s']:.1f} | {r['h_central'] * 1e9:.2f} | {r['h_central'] / c['hd_central']:.3f} | "
                         f"{r['h_min'] * 1e9:.2f} | {r['h_min'] / c['hd_minimum']:.3f} | "
                         f"({r['x_of_h_min']:.2f}, {r['y_of_h_min']:.2f}) |")
    lines += ["", "Richardson extrapolation over the three grids of each domain (observed order p from the "
              "changes where they have one sign and shrink; extrapolated at p only for p >= 0.5; at the scheme's "
              "formal order k: f_513 + (f_513 - f_257)/(2^k - 1), k = 1 or 2). Domain: h_c and h_min on the compact domain's 257-node spacing with "
              "the inlet or the sides grown, relative to the compact domain.", "",
              "| M | domain | h_c: p | h_c extrap. [nm] | h_c at order k [nm] | h_min: p | h_min extrap. [nm] | "
              "h_min at order k [nm] | h_min at order k / HD |", "|---|---|---|---|---|---|---|---|---|"]
    fmt = lambda v, k=1e9: "-" if v is None else f"{v * k:.2f}"
    for c in cases:
        for name in ("default", "compact", SECOND):
            rc = c.get(f"richardson_{name}")
            if rc is None:
                continue
            a, b = rc["h_central"], rc["h_min"]
            lines.append(f"| {c['M']:.0f} | {name} | {fmt(a['order'], 1)} | {fmt(a['extrapolated'])} | "
                         f"{fmt(a['at_scheme_order'])} | {fmt(b['order'], 1)} | {fmt(b['extrapolated'])} | "
                         f"{fmt(b['at_scheme_order'])} | {b['at_scheme_order'] / c['hd_minimum']:.3f} |")
    lines += ["", "First- against second-order upwind Couette flux on the default domain (the same run, interleaved "
              "per grid; ratios second/first):", "",
              "| M | grid | h_c 1st [nm] | h_c 2nd [nm] | h_min 1st [nm] | h_min 2nd [nm] | Newton its 1st / 2nd | "
              "wall 1st / 2nd [s] | wall ratio |", "|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        first = [r for r in c["rows"] if r["domain_name"] == "default"]
        second = [r for r in c["rows"] if r["domain_name"] == SECOND]
        for a, b in zip(first, second):
            lines.append(f"| {c['M']:.0f} | {a['grid'][0]} | {a['h_central'] * 1e9:.2f} | "
                         + (f"{b['h_central'] * 1e9:.2f}" if b["success"] else "not converged") +
                         f" | {a['h_min'] * 1e9:.2f} | " + (f"{b['h_min'] * 1e9:.2f}" if b["success"] else "-") +
                         f" | {a.get('newton', '-')} / {b.get('newton', '-')} | {a['wall_s']:.1f} / {b['wall_s']:.1f} | "
                         f"{b['wall_s'] / a['wall_s']:.2f} |")
    lines += [""]
    for c in cases:
        base = c["compact_257"]
        di = c["inlet_grown"]["h_central"] / base["h_central"] - 1.0
        ds = c["sides_grown"]["h_central"] / base["h_central"] - 1.0
        dm_i = c["inlet_grown"]["h_min"] / base["h_min"] - 1.0
        dm_s = c["sides_grown"]["h_min"] / base["h_min"] - 1.0
        lines.append(f"- M = {c['M']:.0f}: inlet grown: h_c {di:+.2%}, h_min {dm_i:+.2%}; sides grown: h_c {ds:+.2%}, "
                     f"h_min {dm_s:+.2%} (flooded inlet: {base['flooded']})")
    return lines


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
    hd = [formula_case(w, u, 2e-8, hd_grid, check_grid=True) for w, u in hd_points]
    if not quick:
        hd += [formula_case(w, u, 2e-8, 257, check_grid=True) for w, u in ((10.0, 0.1), (30.0, 0.1), (100.0, 0.3))]
    chart = ([(100.0, 10.0)] if quick else [(M, L) for L in (5.0, 10.0, 20.0) for M in (20.0, 50.0, 100.0, 300.0, 1000.0)])
    nvm = [chart_case(M, L, 65 if quick else 129, d) for M, L in chart for d in ("incompressible", "dowson-higginson")]
    grids = grid_convergence(quick)
    data = dict(scaling=rows, variants=var, hamrock_dowson=hd, nvm=nvm, grid_convergence=grids)
    (out / "ehl_point.json").write_text(json.dumps(data, indent=1))
    return report(data)


def report(data: dict) -> str:
    """The markdown section from the measured ``data`` (what :func:`main` writes to ``ehl_point.json``)."""
    rows, var, hd, nvm = data["scaling"], data["variants"], data["hamrock_dowson"], data["nvm"]
    lines = [f"## {TITLE}", "",
             "Circular contact, M = 205, L = 7.2, fully flooded, Hertz start, tolerance 1e-8; the methods in one "
             "run, interleaved per grid. Newton its: on the grid itself (in brackets: on the coarser grids of "
             "the nested start). s per Newton it: the time on the grid itself over its Newton iterations. "
             "Couette flux: first-order upwind (`upwind=\"first\"`) in every section unless named.", "",
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
              "Grid-settled: steady()'s check, h_c and h_min within 5 % of the solution on every second node "
              "(in brackets the change of h_min); wall time includes that check.", "",
              "| w [N] | u [m/s] | M | L | grid | converged | wall [s] | h_c [nm] | h_c / HD | h_c / NVM | "
              "h_min [nm] | h_min / HD | p_max / p_H | grid-settled |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in hd:
        lines.append(f"| {c['load']:g} | {c['speed']:g} | {c['M']:.0f} | {c['L']:.1f} | {c['grid']} | {c['success']} | "
                     f"{c['wall_s']:.1f} | {c['h_central'] * 1e9:.1f} | {_ratio(c['h_central'], c['hd_central']):.3f} | "
                     f"{_ratio(c['h_central'], c['nvm_central']):.3f} | {c['h_min'] * 1e9:.1f} | "
                     f"{_ratio(c['h_min'], c['hd_minimum']):.3f} | {c['p_max_ratio']:.3f} | "
                     + ("-" if c.get("grid_settled") is None else
                        f"{c['grid_settled']} ({c['change_h_min']:.1%})" if c.get("change_h_min") is not None
                        else f"{c['grid_settled']} (not measured)") + " |")
    lines += ["", "### Central film against Nijenbanning-Venner-Moes over Moes' chart (circular, Barus)",
              "", "| M | L | density | grid | converged | wall [s] | Newton its | H_c = (h_c/Rx)(2U)^-1/2 | NVM | ratio |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for c in nvm:
        two_u = 2.0 * 0.04 * c["speed"] / (2.2e11 * 0.01)
        H = c["h_central"] / 0.01 / math.sqrt(two_u)
        Hn = c["nvm_central"] / 0.01 / math.sqrt(two_u)
        lines.append(f"| {c['M']:.0f} | {c['L']:.0f} | {c['density']} | {c['grid']} | {c['success']} | {c['wall_s']:.1f} | "
                     f"{c['newton']} | {H:.3f} | {Hn:.3f} | {H / Hn:.3f} |")
    if data.get("grid_convergence"):
        lines += grid_report(data["grid_convergence"])
    return "\n".join(lines)
