"""Verification study of the finite-volume Reynolds operator against closed forms (the discretisations of
tests/fv/test_reynolds_accuracy.py, set-ups from :mod:`transient.verification.cases`):

1. Sommerfeld infinitely long bearing (eps = 0.6): pressure profile against the closed form, and the grid
   convergence of the max pressure error on uniform and stretched grids (observed orders);
2. short full-film bearing: tangential force against Ocvirk's short-bearing force for L/D = 0.1, 0.05,
   0.025 (the short-bearing model error, ~ (L/D)^2);
3. squeeze film between rectangular plates: load against the series solution vs grid for aspect ratios
   1, 2, 4 (uniform) and 2 (stretched).
"""

from __future__ import annotations

import csv
import json
import time
from pathlib import Path

import numpy as np

from transient.plots import reynolds_operator as plots, save
from transient.study.scenario import log
from transient.verification import reference as ref
from transient.verification.cases import EPS, observed_orders, short_bearing_case, sommerfeld_case, squeeze_plate_case

#: full settings = the grids of tests/fv/test_reynolds_accuracy.py (plus coarser/finer squeeze grids)
FULL = dict(sommerfeld_grids=(40, 80, 160, 320), sommerfeld_delta=0.5, profile_n=40,
            short_LD=(0.1, 0.05, 0.025), short_grid=(240, 160),
            squeeze_grids=(16, 32, 64), squeeze_ratios=(1, 2, 4), squeeze_delta=0.5)
#: coarse settings for a fast smoke run (``--quick``, the test)
QUICK = dict(sommerfeld_grids=(32, 64, 128), sommerfeld_delta=0.5, profile_n=32,
             short_LD=(0.1, 0.05, 0.025), short_grid=(120, 80),
             squeeze_grids=(8, 16, 32), squeeze_ratios=(1, 2, 4), squeeze_delta=0.5)


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
    log(f"[1/3] Sommerfeld infinitely long bearing, eps = {EPS}: grids {sommerfeld_grids}, "
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
        log(f"      {kind:9s}: max p error {cases[0].p_err:.3g} .. {cases[-1].p_err:.3g}, "
             f"orders {' '.join(f'{o:.2f}' for o in orders)}")
    profile = sommerfeld_case(profile_n)
    tt = np.linspace(0, 2 * np.pi, 400)
    result["sommerfeld"] = somm
    result["sommerfeld_profile"] = {"n": profile_n, "p_err": profile.p_err, "theta": profile.theta.tolist(),
                                    "p": profile.p.tolist(), "theta_exact": tt.tolist(),
                                    "p_exact": ref.sommerfeld_pressure(tt, EPS, 0.02, 3.0, 0.05, 1e-4).tolist()}

    # 2. short bearing ------------------------------------------------------------------------------
    nt, nz = short_grid
    log(f"[2/3] short full-film bearing vs Ocvirk, L/D = {tuple(short_LD)}, grid {nt} x {nz}")
    short = [short_bearing_case(ld, nt=nt, nz=nz) for ld in short_LD]
    ld_orders = observed_orders(1.0 / np.asarray(short_LD), [c.fy_err for c in short])
    result["short_bearing"] = {"grid": [nt, nz], "L_over_D": list(short_LD), "fy_err": [c.fy_err for c in short],
                               "fx_rel": [c.fx_rel for c in short], "iterations": [c.iterations for c in short],
                               "orders_in_L_over_D": ld_orders.tolist()}
    for c in short:
        rows.append(dict(check="short_bearing", case=f"{nt}x{nz}", parameter=f"L/D={c.L_over_D}", error=c.fy_err,
                         error2=c.fx_rel, iterations=c.iterations))
    log(f"      Fy error {' '.join(f'{c.fy_err:.3g}' for c in short)}; "
         f"order in L/D {' '.join(f'{o:.2f}' for o in ld_orders)}")

    # 3. squeeze plates -----------------------------------------------------------------------------
    log(f"[3/3] squeeze film between rectangular plates, ratios {tuple(squeeze_ratios)}, grids {squeeze_grids}")
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
        log(f"      {label:17s}: load error {' '.join(f'{c.err:.3g}' for c in cases)}, "
             f"orders {' '.join(f'{o:.2f}' for o in orders)}")
    result["squeeze"] = sq

    # files -----------------------------------------------------------------------------------------
    files = {"json": out_dir / "film_validation.json", "csv": out_dir / "film_validation.csv"}
    if make_plot:
        files["png"] = save(plots.validation(result), out_dir / "film_validation.png")
    with open(files["csv"], "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=["check", "case", "parameter", "error", "error2", "iterations"])
        w.writeheader()
        w.writerows(rows)
    result["files"] = {k: str(v) for k, v in files.items()}
    result["wall_time_s"] = time.perf_counter() - t_start
    files["json"].write_text(json.dumps(result, indent=2) + "\n")
    return result
