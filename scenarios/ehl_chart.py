"""The EHL line contact over the Moes chart: central and minimum film against Moes' formula and asymptotes.

    transient run scenarios/ehl_chart.py [--quick] [--out DIR] [--nodes N] [--grid clustered|uniform]
                                         [--density incompressible|dowson-higginson] [--law barus|roelands]

Each chart point (Moes groups M = W (2U)^-1/2 from 1 to 1000, L = G (2U)^1/4 from 0 to 25, U = 1e-11) is
solved from a cold start by LineContact.steady (Fischer-Burmeister-Newton-Schur on the film-content
form -- Woloszynski, Podsiadlo & Stachowiak, Tribol. Lett. 58 (2015) -- over grid levels and a load path
from the easy corner M <= 10, L <= 5) on a fully flooded domain (transient.study.ehl_chart). Moes' formula: Moes,
"Optimum similarity analysis with applications to elastohydrodynamic lubrication", Wear 159 (1992), as
quoted by Venner & Lubrecht, "Multilevel Methods in Lubrication" (2000). Writes moes_chart.png (H_c and H_min against M
per L with Moes' formula and its four asymptotes; H_c and H_min contours over the (M, L) plane) and
ehl_chart.json (every point: converged or not, H_c, H_min, deviation from Moes, iterations, wall time)
into transient_out/ehl_chart/.
"""

from __future__ import annotations

import time
from pathlib import Path

from transient.plots import save
from transient.plots.roller import moes_chart
from transient.study.ehl_chart import chart_point, moes_curves
from transient.study.scenario import JsonRecord, log, parser

OUT = "ehl_chart"  # output folder name: ROOT/ehl_chart (transient.study.scenario)
M_FULL, L_FULL = (1, 3, 10, 30, 100, 300, 1000), (0, 2, 5, 10, 20, 25)
M_QUICK, L_QUICK = (1, 10, 100), (0, 5, 20)


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--nodes", type=int, default=None, help="nodes per chart point (default 1025; --quick 257)")
    ap.add_argument("--grid", default="clustered", choices=("clustered", "uniform"))
    ap.add_argument("--density", default="incompressible", choices=("incompressible", "dowson-higginson"))
    ap.add_argument("--law", default="barus", choices=("barus", "roelands"))
    ap.add_argument("--resume", action="store_true", help="keep the points already in the JSON (same settings)")
    a = ap.parse_args(argv)
    out = Path(a.out)
    nodes = a.nodes or (257 if a.quick else 1025)
    Ms, Ls = (M_QUICK, L_QUICK) if a.quick else (M_FULL, L_FULL)
    kw = dict(nodes=nodes, grid=a.grid, density=a.density, viscosity_law=a.law)
    rec = JsonRecord(out / "ehl_chart.json", dict(M=Ms, L=Ls, U=1e-11, **kw), resume=a.resume)
    rows = rec.data.get("points", [])
    done = {(r["M"], r["L"]) for r in rows}
    t0 = time.perf_counter()
    for M in Ms:
        for L in Ls:
            if (M, L) in done:
                continue
            r = chart_point(float(M), float(L), **kw)
            rows.append(r)
            rec.put("points", rows)
            log(f"M = {M:5g}, L = {L:3g}: {'converged' if r['success'] else 'NOT converged'}, H_c = {r['H_c']:.4g} "
                f"(Moes {r['moes']:.4g}, {100 * r['deviation']:+.1f} %), H_min = {r['H_min']:.4g}, "
                f"{r['iterations']} Newton its, {r['wall_s']:.1f} s")
    ok = [r for r in rows if r["success"]]
    worst = max(ok, key=lambda r: abs(r["deviation"]), default=None)
    slowest = max(rows, key=lambda r: r["wall_s"])
    summary = dict(converged=len(ok), points=len(rows), wall_s=time.perf_counter() - t0,
                   slowest=dict(M=slowest["M"], L=slowest["L"], wall_s=slowest["wall_s"]),
                   largest_deviation=None if worst is None else dict(M=worst["M"], L=worst["L"],
                                                                     deviation=worst["deviation"]))
    rec.put("summary", summary)
    title = (f"EHL line contact, {a.grid} {nodes} nodes, {a.law}, {a.density}: {len(ok)} of {len(rows)} points "
             "converged")
    save(moes_chart(rows, moes_curves(rows), title), out / "moes_chart.png")
    log(f"{len(ok)} of {len(rows)} chart points converged; largest deviation from Moes "
        f"{100 * worst['deviation']:+.1f} % at M = {worst['M']:g}, L = {worst['L']:g}; slowest point "
        f"M = {slowest['M']:g}, L = {slowest['L']:g} ({slowest['wall_s']:.1f} s); outputs in {out}")


if __name__ == "__main__":
    main()
