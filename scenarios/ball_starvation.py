"""Seed 002 (Jeong et al.): central film of a thrust ball bearing against the number of balls, speed, load and
ambient film (Figs. 7-11); prints the regime boundaries beside the paper's.

    transient run scenarios/ball_starvation.py [--quick] [--out DIR]

Each point is a ball-pass sequence run to its periodic steady state (or parched decline, at most 100
passes) with the nonlinear thin-film reflow (CVODE, band) and, for comparison, Chiu's linear kernel.
Figures ball_fig7..11 and ball_starvation.json into scenarios/out/ball/.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import ThrustBallBearing
from transient.params import jeong
from transient.plots import ball as plots, save
from transient.study.ball import boundaries, sweep
from transient.study.scenario import JsonRecord, log, parser

OUT = Path(__file__).resolve().parent / "out" / "ball"
THIN = dict(replenishment="thin_film", n_cells=100, rtol=1e-4, linear_solver="band")
CHIU = dict(replenishment="chiu")
FIGS = {"n_balls": "fig7_balls", "speed_rpm": "fig8_speed", "load": "fig9_load"}


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    out = Path(a.out)
    values = {"n_balls": np.arange(1, 12, 2 if a.quick else 1), "speed_rpm": np.arange(70, 91, 5 if a.quick else 2),
              "load": np.arange(10, 61, 10 if a.quick else 5)}
    ambients = (100e-6, 50e-6)
    rec = JsonRecord(out / "ball_starvation.json", dict(quick=a.quick, values=values, ambients=ambients))
    brg = ThrustBallBearing(**jeong.BEARING)
    t0 = time.perf_counter()
    runs = {}
    for swept, vals in values.items():
        series = {}
        for hinf in ambients:
            for name, kw in (("thin film", THIN), ("Chiu linear", CHIU)):
                seqs = sweep(brg, swept, vals, dict(ambient_film=hinf), **kw)
                series[f"{name}, h_inf = {hinf * 1e6:.0f} um"] = seqs
                runs[f"{swept} | {name} | {hinf * 1e6:.0f} um"] = dict(
                    values=vals, boundaries=boundaries(vals, seqs), H_central=[s.H_central[-1] for s in seqs],
                    h_inlet_um=[s.h_inlet[-1] * 1e6 for s in seqs], regime=[s.final_regime for s in seqs])
        fixed = dict(jeong.REFERENCE, ambient_film=None)  # the series differ in ambient film
        save(plots.regime_sweep(swept, vals, series, fixed, jeong.REPORTED[swept]), out / f"ball_{FIGS[swept]}.png")
        if swept == "load":
            save(plots.meniscus(vals, {k: v for k, v in series.items() if "thin" in k}, fixed),
                 out / "ball_fig10_meniscus.png")
        rec.put("sweeps", runs)
    series = {f"h_inf = {h * 1e6:.0f} um": sweep(brg, "n_balls", values["n_balls"], dict(ambient_film=h), **THIN)
              for h in (50e-6, 100e-6, 125e-6, 150e-6)}
    rec.put("ambient_film_sweep", {k: dict(boundaries=boundaries(values["n_balls"], v),
                                           regime=[s.final_regime for s in v]) for k, v in series.items()})
    save(plots.regime_sweep("n_balls", values["n_balls"], series, dict(jeong.REFERENCE, ambient_film=None),
                            jeong.REPORTED["n_balls"], title="Fig. 11: central film against the number of balls for "
                            "four ambient films (30 N, 80 rpm)"), out / "ball_fig11_ambient.png")
    ref = jeong.REFERENCE
    seqs = {f"{name}, h_inf = {h * 1e6:.0f} um": brg.sequence(load=ref["load"], speed_rpm=ref["speed_rpm"], ambient_film=h,
                                                               n_passes=60, stop_at_periodic=False, **kw)
            for h in ambients for name, kw in (("thin film", THIN), ("Chiu", CHIU))}
    save(plots.inlet_sequence(seqs, dict(ref, ambient_film=None)), out / "ball_sequence.png")
    log(f"{sum(len(v['values']) for v in runs.values())} sequences in {time.perf_counter() - t0:.1f} s")
    log("paper: flooded to 5 balls / 78 rpm / 25 N; starved to 6 balls / 82 rpm / 40 N; parched beyond")
    for k, v in runs.items():
        log(f"{k:40s}: " + "; ".join(f"{r} {lo:g}-{hi:g}" for r, (lo, hi) in v["boundaries"].items()))
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
