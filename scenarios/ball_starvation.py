"""Seed 002 scenarios: central film of a thrust ball bearing against number of balls, speed, load and
ambient film (analogues of Figs. 7-11 of Jeong, Lee, Yoo & Cho 2017); prints the regime boundaries.

Run: ``python scenarios/ball_starvation.py [--fast]`` (figures into scenarios/out/). Each point is a
ball-pass sequence run to its periodic steady state (or parched decline, at most N_PASSES passes)
with the nonlinear thin-film reflow (CVODE) and, for comparison, Chiu's linear kernel.
"""

from __future__ import annotations

import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from transient.models.ball.bearing import ThrustBallBearing

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "out")
N_PASSES = 100
KW = dict(n_cells=100, rtol=1e-4, linear_solver="band")
REF = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6, n_balls=6)
COLORS = {"fully flooded": "tab:green", "starved": "tab:orange", "parched": "tab:red"}


def run_point(brg, load, speed, hinf, replenishment="thin_film"):
    kw = KW if replenishment == "thin_film" else {}
    s = brg.sequence(load=load, speed_rpm=speed, ambient_film=hinf, n_passes=N_PASSES,
                     replenishment=replenishment, **kw)
    return s


def sweep(name, values, hinf, replenishment="thin_film"):
    brg0 = ThrustBallBearing()
    out = []
    for v in values:
        p = dict(REF, ambient_film=hinf)
        p[name] = v
        brg = brg0.with_(n_balls=int(p["n_balls"]))
        out.append(run_point(brg, p["load"], p["speed_rpm"], p["ambient_film"], replenishment))
    return out


def boundaries(values, seqs):
    """Last value of each regime (the paper's way: 'flooded up to X, starved up to Y')."""
    res = {}
    for v, s in zip(values, seqs):
        res.setdefault(s.final_regime, []).append(v)
    return {k: (min(v), max(v)) for k, v in res.items()}


def plot_sweep(ax, values, seqs, label, marker="o"):
    hc = np.array([s.H_central[-1] for s in seqs])
    ax.plot(values, hc, "-", color="0.6", lw=1)
    for v, s, h in zip(values, seqs, hc):
        ax.plot(v, h, marker, color=COLORS[s.final_regime], ms=6)
    ax.plot([], [], "-", color="0.6", label=label)


def save(fig, name):
    """Lay out, write ``OUT/name`` (PNG, 120 dpi) and close the figure."""
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, name), dpi=120)
    plt.close(fig)


def main(fast=False):
    os.makedirs(OUT, exist_ok=True)
    t0 = time.perf_counter()
    balls = np.arange(1, 12)
    speeds = np.arange(70, 91, 2 if not fast else 5)
    loads = np.arange(10, 61, 5 if not fast else 10)
    ambients = (100e-6, 50e-6)
    results = {}
    for hinf in ambients:
        for rep in ("thin_film", "chiu"):
            results[(hinf, rep, "n_balls")] = sweep("n_balls", balls, hinf, rep)
            results[(hinf, rep, "speed_rpm")] = sweep("speed_rpm", speeds, hinf, rep)
            results[(hinf, rep, "load")] = sweep("load", loads, hinf, rep)
    for hinf in (125e-6, 150e-6):
        results[(hinf, "thin_film", "n_balls")] = sweep("n_balls", balls, hinf)
    t_sweep = time.perf_counter() - t0

    xs = {"n_balls": balls, "speed_rpm": speeds, "load": loads}
    labels = {"n_balls": "number of balls", "speed_rpm": "shaft speed [rpm]", "load": "axial load [N]"}
    figs = {"n_balls": "fig7_balls", "speed_rpm": "fig8_speed", "load": "fig9_load"}
    for key in ("n_balls", "speed_rpm", "load"):
        fig, ax = plt.subplots(figsize=(5.5, 4))
        for hinf, mk in zip(ambients, ("o", "s")):
            plot_sweep(ax, xs[key], results[(hinf, "thin_film", key)], f"thin film, h_inf={hinf*1e6:.0f} um", mk)
            plot_sweep(ax, xs[key], results[(hinf, "chiu", key)], f"Chiu linear, h_inf={hinf*1e6:.0f} um", "^")
        for r, c in COLORS.items():
            ax.plot([], [], "o", color=c, label=r)
        ax.set_xlabel(labels[key])
        ax.set_ylabel("H_c = h_c / r_b (periodic state / last pass)")
        ax.set_yscale("symlog", linthresh=1e-7)
        ax.legend(fontsize=7)
        ax.set_title(f"Central film vs {labels[key]} (30 N, 80 rpm, 6 balls)", fontsize=9)
        save(fig, f"ball_{figs[key]}.png")
    # Fig. 10: m and m_c vs load
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for hinf, mk in zip(ambients, ("o", "s")):
        seqs = results[(hinf, "thin_film", "load")]
        ax.plot(loads, [s.m[-1] for s in seqs], mk + "-", label=f"m (thin film, {hinf*1e6:.0f} um)")
        seqs = results[(hinf, "chiu", "load")]
        ax.plot(loads, [s.m[-1] for s in seqs], "^--", label=f"m (Chiu, {hinf*1e6:.0f} um)")
    ax.plot(loads, [s.m_c for s in results[(100e-6, "thin_film", "load")]], "k-", lw=2, label="m_c")
    ax.set_yscale("log")
    ax.set_xlabel("axial load [N]")
    ax.set_ylabel("meniscus position m = x_in / b")
    ax.legend(fontsize=7)
    save(fig, "ball_fig10_meniscus.png")
    # Fig. 11: ambient film
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for hinf, mk in zip((50e-6, 100e-6, 125e-6, 150e-6), ("v", "o", "s", "D")):
        plot_sweep(ax, balls, results[(hinf, "thin_film", "n_balls")], f"h_inf = {hinf*1e6:.0f} um", mk)
    for r, c in COLORS.items():
        ax.plot([], [], "o", color=c, label=r)
    ax.set_xlabel("number of balls")
    ax.set_ylabel("H_c (periodic state / last pass)")
    ax.set_yscale("symlog", linthresh=1e-7)
    ax.legend(fontsize=7)
    save(fig, "ball_fig11_ambient.png")
    # the inlet-film sequence at the reference point (thin film vs Chiu)
    brg = ThrustBallBearing()
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for hinf in (100e-6, 50e-6):
        for rep, ls in (("thin_film", "-"), ("chiu", "--")):
            s = brg.sequence(load=30, speed_rpm=80, ambient_film=hinf, n_passes=60, replenishment=rep,
                             stop_at_periodic=False, **(KW if rep == "thin_film" else {}))
            ax.semilogy(np.arange(1, s.n_run + 1), np.maximum(s.h_inlet, 1e-10) * 1e6, ls,
                        label=f"{rep}, h_inf={hinf*1e6:.0f} um")
    ax.set_xlabel("ball pass n")
    ax.set_ylabel("inlet film h_in^n [um]")
    ax.legend(fontsize=7)
    save(fig, "ball_sequence.png")

    print(f"sweep: {sum(len(v) for v in results.values())} sequences in {t_sweep:.1f} s")
    print("paper: flooded to 5 balls / 78 rpm / 25 N; starved to 6 balls / 82 rpm / 40 N; parched beyond")
    for (hinf, rep, key), seqs in sorted(results.items(), key=lambda t: (t[0][0], t[0][1], t[0][2])):
        b = boundaries(list(xs[key]), seqs)
        txt = "; ".join(f"{k} {lo:g}-{hi:g}" for k, (lo, hi) in b.items())
        hin = ", ".join(f"{s.h_inlet[-1]*1e6:.3g}" for s in seqs)
        print(f"h_inf={hinf*1e6:5.0f} um {rep:9s} vs {key:9s}: {txt}   [h_in(um): {hin}]")
    return results


if __name__ == "__main__":
    main(fast="--fast" in sys.argv)
