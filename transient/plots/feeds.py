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


def pressure_maps(states: dict, title: str | None = None):
    """The film pressure over the unrolled bearing surface, one panel per feed (``states``: name -> a steady
    :class:`~transient.models.journal.results.FilmState`), on one colour scale; the white line bounds the
    cavitated film (film content below 1). A half-length model is mirrored about the mid-plane."""
    n = len(states)
    fig, axes = figure(n, 1, size=(8.0, 1.2 + 1.9 * n), squeeze=False, sharex=True)
    top = max(float(s.pressure.max()) for s in states.values()) * 1e-3
    for ax, (name, s) in zip(axes[:, 0], states.items()):
        z, p, theta = np.asarray(s.z), np.asarray(s.pressure), np.asarray(s.film_content)
        if z.min() > 0:  # half model, row 0 next to the mid-plane
            z, p, theta = np.r_[-z[::-1], z], np.r_[p[::-1], p], np.r_[theta[::-1], theta]
        angle = np.r_[s.angle_deg, s.angle_deg[0] + 360.0]  # the film is periodic: close it at 360 deg
        p, theta = np.c_[p, p[:, :1]], np.c_[theta, theta[:, :1]]
        mesh = ax.pcolormesh(angle, 1e3 * z, 1e-3 * p, vmin=0.0, vmax=top, cmap="viridis", shading="nearest")
        if (theta < 1.0 - 1e-6).any() and (theta >= 1.0 - 1e-6).any():
            ax.contour(angle, 1e3 * z, theta, levels=[1.0 - 1e-6], colors="w", linewidths=1.0)
        ax.set(ylabel="z [mm]", xlim=(0, 360), xticks=range(0, 361, 45))
        ax.set_title(f"{name}: e/C {s.eccentricity_ratio:.2f}, supply {6e4 * float(np.sum(s.supply_flow)):.2f} l/min",
                     fontsize=9, loc="left")
    axes[-1, 0].set_xlabel("angle from the top, in the direction of rotation [deg]")
    fig.colorbar(mesh, ax=axes[:, 0], label="pressure [kPa, absolute]")
    note = "white line: edge of the cavitated film"
    fig.suptitle(f"{title} ({note})" if title else note, fontsize=10)
    return fig
