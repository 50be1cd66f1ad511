"""Figures of a parameter sweep, drawn from its table (one row per point): scalars against the swept value,
and regimes by colour over one or two swept values."""

from __future__ import annotations

import numpy as np

from transient.plots import figure

REGIME_COLOURS = {"fully flooded": "tab:green", "starved": "tab:orange", "parched": "tab:red", "failed": "0.5"}


def scalar_curves(table: dict, x: str, ys: list):
    """One panel per scalar ``ys`` against the swept parameter ``x`` (failed points left out)."""
    ok = np.asarray(table.get("status", ["ok"] * len(table[x]))) == "ok"
    fig, axs = figure(1, max(len(ys), 1), size=(4.5 * max(len(ys), 1), 3.8), squeeze=False)
    xv = np.asarray(table[x], float)
    order = np.argsort(xv)
    for ax, y in zip(axs[0], ys):
        yv = np.asarray(table[y], float)
        sel = order[ok[order]]
        ax.plot(xv[sel], yv[sel], "o-")
        ax.set(xlabel=x, ylabel=y)
        ax.grid(True, lw=0.3)
    return fig


def regime_map(table: dict, swept: list, column: str = "final_regime"):
    """Regime of each point by colour over one (a strip) or two swept values."""
    regimes = [r if s == "ok" else "failed" for r, s in zip(table[column], table.get("status", ["ok"] * len(table[column])))]
    colours = [REGIME_COLOURS.get(r, "k") for r in regimes]
    x = np.asarray(table[swept[0]], float)
    y = np.asarray(table[swept[1]], float) if len(swept) > 1 else np.zeros_like(x)
    fig, ax = figure(size=(6.0, 4.2 if len(swept) > 1 else 2.4))
    ax.scatter(x, y, c=colours, s=120, marker="s", edgecolors="k", linewidths=0.4)
    for r, c in REGIME_COLOURS.items():
        if r in regimes:
            ax.scatter([], [], c=c, marker="s", label=r)
    ax.set(xlabel=swept[0], ylabel=swept[1] if len(swept) > 1 else "")
    if len(swept) == 1:
        ax.set_yticks([])
    ax.legend(fontsize=8, loc="best")
    ax.set_title(f"{column} over {' x '.join(swept)}", fontsize=9)
    return fig
