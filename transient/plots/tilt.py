"""Figures of a journal tilted in its bearing (:mod:`transient.models.journal.tilt`)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure, suptitle


def misalignment(states: dict, tilts, moments, min_films, title: str):
    """The film pressure over the unrolled bearing surface, one panel per state (``states``: name -> a steady
    :class:`~transient.models.journal.results.FilmState`; a half model is mirrored about the mid-plane; the white
    line bounds the cavitated film), and the film's moments (about x, about y) [N m] and its minimum film [um] against the tilt ``tilts``
    [mrad]."""
    n = len(states)
    fig, axes = figure(n + 1, 1, size=(8.0, 2.2 + 2.1 * (n + 1)), squeeze=False)
    top = max(float(s.pressure.max()) for s in states.values()) * 1e-6
    for ax, (name, s) in zip(axes[:n, 0], states.items()):
        z, p, theta = np.asarray(s.z), np.asarray(s.pressure), np.asarray(s.film_content)
        if z.min() > 0:  # half model (an aligned journal), row 0 next to the mid-plane
            z, p, theta = np.r_[-z[::-1], z], np.r_[p[::-1], p], np.r_[theta[::-1], theta]
        angle = np.r_[s.angle_deg, s.angle_deg[0] + 360.0]  # the film is periodic: close it at 360 deg
        p, theta = np.c_[p, p[:, :1]], np.c_[theta, theta[:, :1]]
        mesh = ax.pcolormesh(angle, 1e3 * z, 1e-6 * p, vmin=0.0, vmax=top, cmap="viridis", shading="nearest")
        if (theta < 1.0 - 1e-6).any() and (theta >= 1.0 - 1e-6).any():
            ax.contour(angle, 1e3 * z, theta, levels=[1.0 - 1e-6], colors="w", linewidths=1.0)
        ax.set(xlabel="angle from the top, in the direction of rotation [deg]", ylabel="z [mm]", xlim=(0, 360),
               xticks=range(0, 361, 45))
        ax.set_title(f"{name}: h_min {1e6 * s.min_film:.0f} um, M = ({s.moment[0]:.1f}, {s.moment[1]:.1f}) N m",
                     fontsize=9, loc="left")
        fig.colorbar(mesh, ax=ax, label="pressure [MPa]")
    ax = axes[n, 0]
    m = np.asarray(moments, dtype=float)
    ax.plot(tilts, m[:, 0], "o-", ms=3, label="moment about x")
    ax.plot(tilts, m[:, 1], "s-", ms=3, label="moment about y")
    ax.set(xlabel="tilt of the journal about y [mrad]", ylabel="film moment [N m]")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, loc="upper left")
    right = ax.twinx()
    right.plot(tilts, 1e6 * np.asarray(min_films), "k--", lw=1.0)
    right.set(ylabel="minimum film (dashed) [um]")
    suptitle(fig, title)
    return fig
