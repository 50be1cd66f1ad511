"""Figures of the thrust ball bearing's starvation sequences (seed 002, Jeong et al. Figs. 7-11).

Readability rules: one colour per regime (the marker of each point), one line style and marker shape per
series (in the legend), the swept value on the x axis, the fixed values in the title, the paper's regime
boundaries drawn as labelled vertical lines."""

from __future__ import annotations

import numpy as np

from transient.plots import figure

REGIME_COLOURS = {"fully flooded": "tab:green", "starved": "tab:orange", "parched": "tab:red"}
LABELS = {"n_balls": "number of balls", "speed_rpm": "shaft speed [rpm]", "load": "axial load [N]",
          "ambient_film": "ambient film [um]"}
_STYLES = [("o", "-"), ("s", "--"), ("^", ":"), ("D", "-."), ("v", (0, (5, 1))), ("P", (0, (1, 1)))]


def fixed_title(fixed: dict, swept: str) -> str:
    """'30 N, 80 rpm, 6 balls, h_inf = 100 um' without the swept parameter."""
    parts = {"load": lambda v: f"{v:g} N", "speed_rpm": lambda v: f"{v:g} rpm", "n_balls": lambda v: f"{int(v)} balls",
             "ambient_film": lambda v: f"h_inf = {v * 1e6:g} um"}
    return ", ".join(f(fixed[k]) for k, f in parts.items() if k != swept and fixed.get(k) is not None)


def _regime_legend(ax, handles):
    for r, c in REGIME_COLOURS.items():
        handles.append(ax.plot([], [], "o", color=c, label=r)[0])


def regime_sweep(swept: str, values, series: dict, fixed: dict, paper: dict | None = None, title: str = ""):
    """Central film H_c = h_c / r_b of the periodic state (or the last pass) against the swept value.

    ``series``: label -> list of sequences (one per value); ``paper``: the paper's last flooded / starved
    values of this sweep (drawn as vertical lines)."""
    x = np.asarray(values, float) * (1e6 if swept == "ambient_film" else 1.0)
    fig, ax = figure(size=(6.4, 4.4))
    handles = []
    dodge = 0.012 * (np.ptp(x) or 1.0)  # series that coincide stay visible side by side
    all_hc = []
    for i, ((label, seqs), (mk, ls)) in enumerate(zip(series.items(), _STYLES)):
        hc = np.array([s.H_central[-1] for s in seqs])
        all_hc.append(hc)
        xi = x + (i - (len(series) - 1) / 2) * dodge
        ax.plot(xi, hc, ls=ls, color="0.35", lw=1)
        for xv, s, h in zip(xi, seqs, hc):
            ax.plot(xv, h, mk, color=REGIME_COLOURS[s.final_regime], ms=6, mec="k", mew=0.4)
        handles.append(ax.plot([], [], ls=ls, marker=mk, color="0.35", mfc="w", mec="k", label=label)[0])
    _regime_legend(ax, handles)
    if paper:
        for k, v in paper.items():
            ax.axvline(v, color=REGIME_COLOURS["fully flooded" if k == "flooded" else "starved"], ls="--", lw=1)
            ax.annotate(f"paper: {k} to {v:g}", (v, 0.02), xycoords=("data", "axes fraction"), rotation=90,
                        fontsize=7, ha="right", va="bottom")
    ax.set(xlabel=LABELS[swept], ylabel="H_c = h_c / r_b (periodic state or last pass)")
    hc = np.concatenate(all_hc)
    if hc.min() > 0 and hc.max() / hc.min() > 10:
        ax.set_yscale("log")
    ax.legend(handles=handles, fontsize=7, loc="best")
    ax.set_title(title or f"Central film against {LABELS[swept]} ({fixed_title(fixed, swept)})", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    return fig


def meniscus(values, series: dict, fixed: dict, swept: str = "load"):
    """Fig. 10: the meniscus position m of the last pass and the critical meniscus m_c against the swept value."""
    fig, ax = figure(size=(6.4, 4.4))
    first = None
    for (label, seqs), (mk, ls) in zip(series.items(), _STYLES):
        ax.plot(values, [s.m[-1] for s in seqs], marker=mk, ls=ls, color="tab:blue", label=f"m, {label}")
        first = first or seqs
    ax.plot(values, [s.m_c for s in first], "k-", lw=2, label="critical meniscus m_c")
    ax.set_yscale("log")
    ax.set(xlabel=LABELS[swept], ylabel="meniscus position m = x_in / b")
    ax.set_title(f"Inlet meniscus against {LABELS[swept]} ({fixed_title(fixed, swept)})", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    return fig


def inlet_sequence(series: dict, fixed: dict):
    """The inlet film met by each ball, pass after pass, for each series."""
    fig, ax = figure(size=(6.4, 4.4))
    for (label, s), (mk, ls) in zip(series.items(), _STYLES):
        ax.semilogy(np.arange(1, s.n_run + 1), np.maximum(s.h_inlet, 1e-10) * 1e6, ls=ls, label=label)
    ax.set(xlabel="ball pass n", ylabel="inlet film h_in [um]")
    ax.set_title(f"Inlet film ball after ball ({fixed_title(fixed, '')})", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    return fig
