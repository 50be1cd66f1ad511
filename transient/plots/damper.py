"""Figures of a squeeze-film damper's circular centred orbits (:meth:`transient.SqueezeFilmDamper.circular_orbit`)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure, suptitle


def orbit_forces(curves: dict, closed: dict, title: str):
    """The tangential and radial film forces against the eccentricity ratio: ``curves`` name -> (eccentricity ratios,
    radial forces [N], tangential forces [N]) of the film (markers), ``closed`` name -> the same of a closed form
    (black lines). Forces are drawn as magnitudes ``-F_t`` and ``-F_r`` (a damping film and a centring pull)."""
    fig, axes = figure(1, 2, size=(12.0, 4.8))
    for (name, (eps, fr, ft)), style in zip(closed.items(), ("-", "--", ":", "-.")):
        axes[0].plot(eps, -np.asarray(ft), style, color="k", lw=1.0, label=name)
        axes[1].plot(eps, -np.asarray(fr), style, color="k", lw=1.0, label=name)
    for name, (eps, fr, ft) in curves.items():
        axes[0].plot(eps, -np.asarray(ft), "o", ms=4, mfc="none", label=name)
        axes[1].plot(eps, -np.asarray(fr), "o", ms=4, mfc="none", label=name)
    for ax, what in zip(axes, ("tangential force -F_t [N] (damping)", "radial force -F_r [N] (towards the centre)")):
        ax.set(xlabel="orbit radius / clearance  e/c [-]", ylabel=what, yscale="log")
        ax.grid(True, which="both", lw=0.3)
    axes[0].legend(fontsize=8)
    suptitle(fig, title)
    return fig


def supply_sweep(pressure_ratio, radial_share, tangential_share, cavitated, title: str):
    """The film forces on one orbit against the supply pressure (``pressure_ratio``: over mu w (L/c)^2), as shares of
    the pi-film's closed forms, and the cavitated share of the film."""
    fig, axes = figure(1, 2, size=(12.0, 4.5))
    ax = axes[0]
    ax.plot(pressure_ratio, tangential_share, "o-", ms=4, label="tangential F_t / F_t(pi-film)")
    ax.plot(pressure_ratio, radial_share, "s-", ms=4, label="radial F_r / F_r(pi-film)")
    for level, text in ((1.0, "pi-film"), (2.0, "2-pi film: F_t")):
        ax.axhline(level, color="0.5", lw=0.8, ls="--")
        ax.annotate(text, (pressure_ratio[0], level), fontsize=8, va="bottom")
    ax.set(xscale="log", xlabel="supply pressure / (mu w (L/c)^2) [-]", ylabel="force / pi-film closed form [-]")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    axes[1].plot(pressure_ratio, cavitated, "o-", ms=4)
    axes[1].set(xscale="log", xlabel="supply pressure / (mu w (L/c)^2) [-]", ylabel="cavitated share of the film [-]",
                ylim=(-0.02, 1.02))
    axes[1].grid(True, which="both", lw=0.3)
    suptitle(fig, title)
    return fig


def jump(curve, ramps: dict, floquet: list, title: str):
    """The damper's jump: orbit radius and transmitted force against speed along the circular-orbit path ``curve``
    (a :class:`~transient.models.rotor.circular_orbits.CircularOrbitCurve`, first damper; solid where the path runs
    forwards in speed, dashed where it runs back between the folds), the folds marked, the speed ramps on top
    (``ramps`` name -> (speed [rpm], e/c, transmitted force [N]) of a time run) and the shooting's orbits
    (``floquet``: (speed [rpm], e/c, transmitted force [N], stable) each, filled when stable)."""
    fig, axes = figure(1, 2, size=(13.0, 5.0))
    n, back = curve.speed_rpm, curve.backward
    series = (curve.eccentricity_ratio[:, 0], curve.transmitted_force[:, 0])
    for ax, y in zip(axes, series):
        for mask, style, label in ((~back, "-", "circular orbits, forward branches"),
                                   (back, "--", "circular orbits, between the folds")):
            ax.plot(n, np.where(mask | np.roll(mask, 1) | np.roll(mask, -1), y, np.nan), style, color="k", lw=1.4,
                    label=label)
        for name, (speed, eps, force) in ramps.items():
            ax.plot(speed, eps if y is series[0] else force, lw=0.6, alpha=0.8, label=name)
        for k, i in enumerate(curve.fold_index):
            f = curve.folds_rpm[k]
            ax.axvline(f, color="r", lw=0.8, ls=":")
            ax.annotate(f"fold {f:.0f} rpm", (f, ax.get_ylim()[0]), rotation=90, fontsize=8, color="r", va="bottom")
        for speed, eps, force, stable in floquet:
            ax.plot(speed, eps if y is series[0] else force, "o", ms=6, color="tab:blue",
                    mfc="tab:blue" if stable else "white")
    axes[0].set(xlabel="speed [rpm]", ylabel="orbit radius / clearance  e/c [-]")
    axes[1].set(xlabel="speed [rpm]", ylabel="transmitted force (film + centring spring) [N]")
    for ax in axes:
        ax.grid(True, lw=0.3)
    axes[0].plot([], [], "o", color="tab:blue", label="shooting: stable (filled), unstable (open)")
    axes[0].legend(fontsize=8, loc="upper left")
    suptitle(fig, title)
    return fig


def upper_fold(curves: dict, speed_rpm, eccentricity_ratio, max_multiplier, title: str,
               label="whole system (24x4), pseudo-arclength shooting"):
    """The damper's folds on several grids: orbit radius against speed along each circular-orbit path (``curves``
    label -> :class:`~transient.models.rotor.circular_orbits.CircularOrbitCurve`; one colour per grid, solid
    forwards in speed, dashed where the path runs back, its folds marked) with the whole system's periodic orbits
    (``speed_rpm``, ``eccentricity_ratio``; filled where the dominant Floquet multiplier ``max_multiplier`` is
    inside the unit circle; ``label`` names them), and that multiplier against speed."""
    fig, (ax, bx) = figure(1, 2, size=(13.0, 5.0))
    colours = {}
    for name, c in curves.items():
        grid = name.split(" from ")[0]
        colour = colours.setdefault(grid, f"C{len(colours)}")
        n, y, back = c.speed_rpm, c.eccentricity_ratio[:, 0], c.backward
        for mask, style in ((~back, "-"), (back, "--")):
            ax.plot(n, np.where(mask | np.roll(mask, 1) | np.roll(mask, -1), y, np.nan), style, color=colour, lw=1.2,
                    label=grid if mask is not back and name.endswith("4000 rpm") else None)
        for f, e in zip(c.folds_rpm, c.fold_eccentricity):
            ax.plot(f, e, "x", color=colour, ms=8)
    stable = np.asarray(max_multiplier) < 1.0
    ax.plot(speed_rpm, eccentricity_ratio, "o-", color="k", ms=5, lw=0.8, mfc="none",
            label=label)
    ax.plot(np.asarray(speed_rpm)[stable], np.asarray(eccentricity_ratio)[stable], "o", color="k", ms=5)
    ax.set(xlabel="speed [rpm]", ylabel="orbit radius / clearance  e/c [-]")
    ax.legend(fontsize=8, loc="lower right")
    bx.plot(speed_rpm, max_multiplier, "o-", color="k", ms=5)
    bx.axhline(1.0, color="r", lw=0.8, ls=":")
    bx.set(xlabel="speed [rpm]", ylabel="whole system: dominant Floquet multiplier |mu| [-]")
    for a in (ax, bx):
        a.grid(True, lw=0.3)
    suptitle(fig, title)
    return fig
