"""Figures of the oil-feed design study (:mod:`transient.study.feeds`)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure

PANELS = (("load", 1e-3, "load capacity [kN]", "log"), ("attitude_angle_deg", 1.0, "attitude angle [deg]", "linear"),
          ("min_film", 1e6, "minimum film [um]", "linear"), ("supply_flow", 6e4, "supply flow [l/min]", "linear"),
          ("side_leakage", 6e4, "side leakage, both ends [l/min]", "linear"))


def feed_study(res: dict, title: str):
    """Load capacity, attitude, minimum film, supply flow and side leakage against the eccentricity ratio, one line
    per feed (``res``: :func:`transient.study.feeds.feed_sweep`)."""
    fig, axes = figure(2, 3, size=(14, 8))
    axes = axes.ravel()
    for ax, (q, scale, label, yscale) in zip(axes, PANELS):
        for name, r in res.items():
            ax.plot(r["eccentricity_ratio"], scale * np.asarray(r[q]), "o-", ms=3, label=name)
        ax.set(xlabel="eccentricity ratio e/C [-]", ylabel=label, yscale=yscale)
        ax.grid(True, which="both", lw=0.3)
    ax = axes[5]
    for name, r in res.items():
        ax.plot(r["eccentricity_ratio"], r["side_flow_ratio"], "o-", ms=3, label=name)
    ax.set(xlabel="eccentricity ratio e/C [-]", ylabel="side leakage / flow into the film  Q_s / Q [-]")
    ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(title, fontsize=11)
    return fig
