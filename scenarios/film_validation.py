"""Film operator validation: the finite-volume Reynolds operator against closed forms.

    python scenarios/film_validation.py [--out DIR] [--quick]
    transient run scenarios/film_validation.py [--out DIR] [--quick]

Checks (the discretisations of tests/test_film_accuracy.py, from transient.verification.cases):

1. Sommerfeld infinitely long bearing (eps = 0.6): pressure profile numeric vs closed form, and the
   grid convergence of the max pressure error on uniform and stretched grids (observed orders);
2. short full-film bearing: tangential force error against Ocvirk's short-bearing force for
   L/D = 0.1, 0.05, 0.025 (the short-bearing model error, ~ (L/D)^2);
3. squeeze film between rectangular plates: load error against the series solution vs grid for
   aspect ratios 1, 2, 4 (uniform) and 2 (stretched).

Writes ``film_validation.png`` (2 x 2 panels), ``film_validation.json`` (all numbers) and
``film_validation.csv`` (one row per solve) into DIR (default: scenarios/out/film_validation/ next to
this file). ``--quick`` uses coarse grids (a few seconds; what the test runs). Takes ~10 s in full.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
import time
from pathlib import Path

import numpy as np

from transient.verification.cases import EPS, observed_orders, short_bearing_case, sommerfeld_case, squeeze_plate_case

DEFAULT_OUT = Path(__file__).resolve().parent / "out" / "film_validation"

#: full settings = the grids of tests/test_film_accuracy.py (plus coarser/finer squeeze grids)
FULL = dict(sommerfeld_grids=(40, 80, 160, 320), sommerfeld_delta=0.5, profile_n=40,
            short_LD=(0.1, 0.05, 0.025), short_grid=(240, 160),
            squeeze_grids=(16, 32, 64), squeeze_ratios=(1, 2, 4), squeeze_delta=0.5)
#: coarse settings for a fast smoke run (``--quick``, the test)
QUICK = dict(sommerfeld_grids=(32, 64, 128), sommerfeld_delta=0.5, profile_n=32,
             short_LD=(0.1, 0.05, 0.025), short_grid=(120, 80),
             squeeze_grids=(8, 16, 32), squeeze_ratios=(1, 2, 4), squeeze_delta=0.5)


def _log(msg):
    print(msg, flush=True)


def _check_grids(name, grids, minimum):
    grids = tuple(grids)
    if len(grids) < 2 or any(isinstance(n, bool) or int(n) != n or n < minimum for n in grids):
        raise ValueError(f"{name} must be >= 2 integers >= {minimum}, got {grids!r}")
    if any(b <= a for a, b in zip(grids, grids[1:])):
        raise ValueError(f"{name} must be strictly increasing, got {grids!r}")
    return tuple(int(n) for n in grids)


def run_validation(out_dir, *, sommerfeld_grids, sommerfeld_delta, profile_n, short_LD, short_grid,
                   squeeze_grids, squeeze_ratios, squeeze_delta, make_plot=True) -> dict:
    """Run the three checks, write figure + JSON + CSV into ``out_dir`` and return the numbers.

    The returned dict has ``sommerfeld`` (per grid kind: n, p_err, fy_err, fx_rel, iterations, orders),
    ``short_bearing`` (L/D, fy_err, fx_rel, iterations, observed order in L/D), ``squeeze`` (per case:
    n, err, iterations, orders), ``files`` and ``wall_time_s``.
    """
    sommerfeld_grids = _check_grids("sommerfeld_grids", sommerfeld_grids, 3)
    squeeze_grids = _check_grids("squeeze_grids", squeeze_grids, 2)
    if not (0.0 <= sommerfeld_delta < 1.0 and 0.0 <= squeeze_delta < 1.0):
        raise ValueError(f"stretching deltas must be in [0, 1), got {sommerfeld_delta!r}, {squeeze_delta!r}")
    if len(short_LD) < 2 or any(not (0 < ld < 10) for ld in short_LD):
        raise ValueError(f"short_LD must hold >= 2 values in (0, 10), got {short_LD!r}")
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise ValueError(f"output path exists and is not a directory: {out_dir}")
    out_dir.mkdir(parents=True, exist_ok=True)
    t_start = time.perf_counter()
    rows = []  # CSV rows
    result = {"eps": EPS}

    # 1. Sommerfeld ---------------------------------------------------------------------------------
    _log(f"[1/3] Sommerfeld infinitely long bearing, eps = {EPS}: grids {sommerfeld_grids}, "
         f"uniform and stretched (delta = {sommerfeld_delta})")
    somm = {}
    for kind, delta in (("uniform", 0.0), ("stretched", sommerfeld_delta)):
        cases = [sommerfeld_case(n, delta) for n in sommerfeld_grids]
        orders = observed_orders(sommerfeld_grids, [c.p_err for c in cases])
        somm[kind] = {"delta": delta, "n": list(sommerfeld_grids), "p_err": [c.p_err for c in cases],
                      "fy_err": [c.fy_err for c in cases], "fx_rel": [c.fx_rel for c in cases],
                      "iterations": [c.iterations for c in cases], "orders": orders.tolist()}
        for c in cases:
            rows.append(dict(check="sommerfeld", case=kind, parameter=f"n={c.n}", error=c.p_err,
                             error2=c.fy_err, iterations=c.iterations))
        _log(f"      {kind:9s}: max p error {cases[0].p_err:.3g} .. {cases[-1].p_err:.3g}, "
             f"orders {' '.join(f'{o:.2f}' for o in orders)}")
    profile = sommerfeld_case(profile_n)
    result["sommerfeld"] = somm
    result["sommerfeld_profile"] = {"n": profile_n, "p_err": profile.p_err}

    # 2. short bearing ------------------------------------------------------------------------------
    nt, nz = short_grid
    _log(f"[2/3] short full-film bearing vs Ocvirk, L/D = {tuple(short_LD)}, grid {nt} x {nz}")
    short = [short_bearing_case(ld, nt=nt, nz=nz) for ld in short_LD]
    ld_orders = observed_orders(1.0 / np.asarray(short_LD), [c.fy_err for c in short])
    result["short_bearing"] = {"grid": [nt, nz], "L_over_D": list(short_LD), "fy_err": [c.fy_err for c in short],
                               "fx_rel": [c.fx_rel for c in short], "iterations": [c.iterations for c in short],
                               "orders_in_L_over_D": ld_orders.tolist()}
    for c in short:
        rows.append(dict(check="short_bearing", case=f"{nt}x{nz}", parameter=f"L/D={c.L_over_D}", error=c.fy_err,
                         error2=c.fx_rel, iterations=c.iterations))
    _log(f"      Fy error {' '.join(f'{c.fy_err:.3g}' for c in short)}; "
         f"order in L/D {' '.join(f'{o:.2f}' for o in ld_orders)}")

    # 3. squeeze plates -----------------------------------------------------------------------------
    _log(f"[3/3] squeeze film between rectangular plates, ratios {tuple(squeeze_ratios)}, grids {squeeze_grids}")
    sq = {}
    series = [(f"b/a={r}", r, 0.0) for r in squeeze_ratios] + [("b/a=2 stretched", 2, squeeze_delta)]
    for label, ratio, delta in series:
        cases = [squeeze_plate_case(ratio, n=n, delta=delta) for n in squeeze_grids]
        orders = observed_orders(squeeze_grids, [c.err for c in cases])
        sq[label] = {"ratio": ratio, "delta": delta, "n": list(squeeze_grids), "err": [c.err for c in cases],
                     "W_exact": cases[0].W_exact, "iterations": [c.iterations for c in cases],
                     "orders": orders.tolist()}
        for c in cases:
            rows.append(dict(check="squeeze", case=label, parameter=f"n={c.n}", error=c.err, error2="",
                             iterations=c.iterations))
        _log(f"      {label:17s}: load error {' '.join(f'{c.err:.3g}' for c in cases)}, "
             f"orders {' '.join(f'{o:.2f}' for o in orders)}")
    result["squeeze"] = sq

    # files -----------------------------------------------------------------------------------------
    files = {"json": out_dir / "film_validation.json", "csv": out_dir / "film_validation.csv"}
    if make_plot:
        files["png"] = out_dir / "film_validation.png"
        _plot(files["png"], profile, somm, result["short_bearing"], sq)
    with open(files["csv"], "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=["check", "case", "parameter", "error", "error2", "iterations"])
        w.writeheader()
        w.writerows(rows)
    result["files"] = {k: str(v) for k, v in files.items()}
    result["wall_time_s"] = time.perf_counter() - t_start
    files["json"].write_text(json.dumps(result, indent=2) + "\n")
    return result


def _plain_ticks(axis, values):
    """Major ticks at exactly ``values`` (plain numbers), no minor labels, on a log axis."""
    from matplotlib.ticker import FixedLocator, NullFormatter
    axis.set_major_locator(FixedLocator(list(values)))
    axis.set_major_formatter(lambda v, _: f"{v:g}")
    axis.set_minor_formatter(NullFormatter())


def _plot(path, profile, somm, short, sq):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    # (a) Sommerfeld pressure profile
    a = ax[0, 0]
    order = np.argsort(np.mod(profile.theta, 2 * np.pi))
    th = np.mod(profile.theta, 2 * np.pi)[order]
    tt = np.linspace(0, 2 * np.pi, 400)
    from transient.verification import reference as ref
    a.plot(np.degrees(tt), ref.sommerfeld_pressure(tt, EPS, 0.02, 3.0, 0.05, 1e-4) / 1e6, "k-", label="closed form")
    a.plot(np.degrees(th), profile.p[order] / 1e6, "o", ms=4, mfc="none", label=f"finite volume, n = {profile.n}")
    a.set(xlabel=r"$\theta$ [deg] (from the maximum film)", ylabel="p [MPa]",
          title=rf"(a) Sommerfeld pressure, $\varepsilon$ = {EPS} (max error {profile.p_err:.1e})")
    a.set_xticks(range(0, 361, 60))
    a.legend()
    a.grid(alpha=0.3)
    # (b) Sommerfeld convergence
    a = ax[0, 1]
    for kind, mk in (("uniform", "o-"), ("stretched", "s-")):
        s = somm[kind]
        lab = kind if kind == "uniform" else f"stretched ($\\delta$ = {s['delta']})"
        a.loglog(s["n"], s["p_err"], mk, label=lab + f", orders {' '.join(f'{o:.2f}' for o in s['orders'])}")
    n = np.array(somm["uniform"]["n"], dtype=float)
    e0 = somm["uniform"]["p_err"][0]
    a.loglog(n, 1.5 * e0 * (n / n[0]) ** -2, "k--", lw=1, label="slope 2")
    a.set(xlabel=r"cells around the circumference", ylabel="max |p - p_exact| / max |p_exact|",
          title="(b) Sommerfeld grid convergence")
    _plain_ticks(a.xaxis, somm["uniform"]["n"])
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    # (c) short bearing
    a = ax[1, 0]
    ld = np.array(short["L_over_D"])
    a.loglog(ld, short["fy_err"], "o-", label=f"finite bearing, {short['grid'][0]} x {short['grid'][1]} cells")
    a.loglog(ld, short["fy_err"][0] * (ld / ld[0]) ** 2, "k--", lw=1, label="slope 2")
    a.set(xlabel="L/D", ylabel="|Fy / Fy_Ocvirk - 1|", title="(c) full-film bearing -> short-bearing limit")
    _plain_ticks(a.xaxis, ld)
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    # (d) squeeze plates
    a = ax[1, 1]
    for label, s in sq.items():
        a.loglog(s["n"], s["err"], "o-" if s["delta"] == 0 else "s--",
                 label=f"{label}, orders {' '.join(f'{o:.2f}' for o in s['orders'])}")
    first = next(iter(sq.values()))
    n = np.array(first["n"], dtype=float)
    a.loglog(n, 1.5 * max(s["err"][0] for s in sq.values()) * (n / n[0]) ** -2, "k--", lw=1, label="slope 2")
    a.set(xlabel="cells across the short side a", ylabel="|W / W_exact - 1|",
          title="(d) squeeze film between rectangular plates")
    _plain_ticks(a.xaxis, first["n"])
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    fig.suptitle("transient.film: finite-volume Reynolds operator against closed forms")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _summary(res) -> str:
    lines = ["", "check                         case               errors (coarse .. fine)          orders"]
    for kind, s in res["sommerfeld"].items():
        lines.append(f"Sommerfeld max p error        {kind:18s} {s['p_err'][0]:.3e} .. {s['p_err'][-1]:.3e}"
                     f"         {' '.join(f'{o:.2f}' for o in s['orders'])}")
    for kind, s in res["sommerfeld"].items():
        lines.append(f"Sommerfeld force error        {kind:18s} {s['fy_err'][0]:.3e} .. {s['fy_err'][-1]:.3e}")
    sb = res["short_bearing"]
    lines.append(f"short bearing Fy error        L/D {'/'.join(str(x) for x in sb['L_over_D']):14s} "
                 f"{' '.join(f'{e:.3e}' for e in sb['fy_err'])}  "
                 f"{' '.join(f'{o:.2f}' for o in sb['orders_in_L_over_D'])} (in L/D)")
    for label, s in res["squeeze"].items():
        lines.append(f"squeeze load error            {label:18s} {s['err'][0]:.3e} .. {s['err'][-1]:.3e}"
                     f"         {' '.join(f'{o:.2f}' for o in s['orders'])}")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="film_validation", description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=str(DEFAULT_OUT), help=f"output folder (default: {DEFAULT_OUT})")
    parser.add_argument("--quick", action="store_true", help="coarse grids (smoke run, a few seconds)")
    parser.add_argument("--no-plot", action="store_true", help="numbers only, no figure")
    a = parser.parse_args(argv)
    if not a.out.strip():
        parser.error("--out must be a non-empty directory path")
    out = Path(a.out)
    if out.exists() and not out.is_dir():
        parser.error(f"--out must be a directory, but {out} is a file")
    settings = QUICK if a.quick else FULL
    res = run_validation(out, make_plot=not a.no_plot, **settings)
    print(_summary(res))
    print(f"\nwall time {res['wall_time_s']:.1f} s")
    for kind, p in res["files"].items():
        print(f"written: {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
