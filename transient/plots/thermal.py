"""Figures of a thermal (THD) journal film (:mod:`transient.models.journal.thd`)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from transient.plots import suptitle

KELVIN_AT_0C = 273.15


def _whole(s, field):
    """``field`` on the unrolled bearing surface: a half model mirrored about the mid-plane (row 0 next to it) and
    closed at 360 deg; returns (angle [deg], z [m], field, film content)."""
    z, f, theta = np.asarray(s.z), np.asarray(field), np.asarray(s.film_content)
    if z.min() > 0:
        z, f, theta = np.r_[-z[::-1], z], np.r_[f[::-1], f], np.r_[theta[::-1], theta]
    angle = np.r_[s.angle_deg, s.angle_deg[0] + 360.0]
    return angle, z, np.c_[f, f[:, :1]], np.c_[theta, theta[:, :1]]


def _map(fig, ax, s, field, label, cmap):
    angle, z, f, theta = _whole(s, field)
    mesh = ax.pcolormesh(angle, 1e3 * z, f, cmap=cmap, shading="nearest")
    if (theta < 1.0 - 1e-6).any() and (theta >= 1.0 - 1e-6).any():
        ax.contour(angle, 1e3 * z, theta, levels=[1.0 - 1e-6], colors="w", linewidths=1.0)
    ax.set(xlabel="angle from the top, in the direction of rotation [deg]", ylabel="z [mm]", xlim=(0, 360),
           xticks=range(0, 361, 90))
    fig.colorbar(mesh, ax=ax, label=label)


def thd_against_isothermal(state, speeds_rpm, thd: dict, iso: dict, supply_temperature: float, title: str):
    """Top: the temperature [C] and viscosity [mPa s] maps of one thermal steady ``state`` (a
    :class:`~transient.models.journal.results.FilmState`; the white line bounds the cavitated film). Bottom: the
    eccentricity ratio, the maximum temperature [C] and the power loss [W] against the speed ``speeds_rpm``,
    ``thd`` and ``iso`` each a dict of arrays ``eccentricity_ratio``, ``max_temperature`` [K] and ``power_loss``
    [W] (the isothermal film's maximum temperature is the supply temperature [K])."""
    fig = Figure(figsize=(13.0, 7.5), layout="constrained")
    ax = fig.subplot_mosaic([["T", "T", "T", "mu", "mu", "mu"], ["e", "e", "tm", "tm", "p", "p"]])
    _map(fig, ax["T"], state, np.asarray(state.temperature) - KELVIN_AT_0C, "temperature [C]", "inferno")
    ax["T"].set_title(f"temperature: max {state.max_temperature - KELVIN_AT_0C:.1f} C, supply "
                      f"{supply_temperature - KELVIN_AT_0C:.1f} C", fontsize=9, loc="left")
    _map(fig, ax["mu"], state, 1e3 * np.asarray(state.viscosity_field), "viscosity [mPa s]", "viridis_r")
    mu = np.asarray(state.viscosity_field)
    ax["mu"].set_title(f"viscosity: {1e3 * mu.min():.2f} to {1e3 * mu.max():.2f} mPa s", fontsize=9, loc="left")
    n = np.asarray(speeds_rpm, dtype=float)
    for key, a, shift, ylabel in (("eccentricity_ratio", ax["e"], 0.0, "eccentricity ratio e/C [-]"),
                                  ("max_temperature", ax["tm"], -KELVIN_AT_0C, "maximum temperature [C]"),
                                  ("power_loss", ax["p"], 0.0, "power loss [W]")):
        a.plot(n, np.asarray(thd[key]) + shift, "o-", ms=3, color="C3", label="thermal (THD)")
        a.plot(n, np.asarray(iso[key]) + shift, "s--", ms=3, color="C0", label="isothermal")
        a.set(xlabel="speed [rpm]", ylabel=ylabel)
        a.grid(True, lw=0.3)
    ax["e"].legend(fontsize=8)
    suptitle(fig, title)
    return fig


def run_up(t, shaft_speed, max_temperature, power_loss, heat_flow, eccentricity_ratio, steady: dict, ramp_end: float,
           title: str):
    """A thermal orbit's run-up against time [s]: the shaft speed [rpm]; the film's hottest temperature beside the
    steady THD film's at the same speed (``steady``: ``speed_rpm``, ``max_temperature`` [K], ``power_loss`` [W],
    ``eccentricity_ratio``, interpolated in speed); its dissipation and the heat carried away [W]; the eccentricity
    ratio. A grey line at ``ramp_end`` [s]."""
    fig = Figure(figsize=(11.0, 7.0), layout="constrained")
    ax = fig.subplots(2, 2, sharex=True)

    def at(key):
        return np.interp(shaft_speed, steady["speed_rpm"], steady[key])

    ax[0, 0].plot(t, shaft_speed, color="k")
    ax[0, 0].set_ylabel("shaft speed [rpm]")
    ax[0, 1].plot(t, np.asarray(max_temperature) - KELVIN_AT_0C, label="thermal orbit")
    ax[0, 1].plot(t, at("max_temperature") - KELVIN_AT_0C, "--", label="steady THD at the same speed")
    ax[0, 1].set_ylabel("maximum film temperature [C]")
    ax[0, 1].legend()
    ax[1, 0].plot(t, power_loss, label="dissipation")
    ax[1, 0].plot(t, heat_flow, label="heat carried away")
    ax[1, 0].plot(t, at("power_loss"), "--", label="steady THD power loss")
    ax[1, 0].set_ylabel("power [W]")
    ax[1, 0].legend()
    ax[1, 1].plot(t, eccentricity_ratio, lw=0.6, label="thermal orbit")
    ax[1, 1].plot(t, at("eccentricity_ratio"), "--", label="steady THD at the same speed")
    ax[1, 1].set_ylabel("eccentricity ratio e/C [-]")
    ax[1, 1].legend()
    return _run_up_frame(fig, ax, ramp_end, title)


def rotor_run_up(t, shaft_speed, nodes, max_temperature, power_loss, eccentricity_ratio, steady: dict,
                 ramp_end: float, title: str):
    """A rotor's run-up on thermal bearings against time [s]: the shaft speed [rpm]; each bearing's (``nodes``,
    the columns of the (n_t, n_bearings) series) hottest film temperature beside its steady THD film's in the
    rotor's thermal equilibrium at the same speed (``steady``: ``speed_rpm``, and ``max_temperature`` [K],
    ``power_loss`` [W], ``eccentricity_ratio`` as (n_speeds, n_bearings), interpolated in speed); the power loss
    [W]; the eccentricity ratio. A grey line at ``ramp_end`` [s]."""
    fig = Figure(figsize=(11.0, 7.0), layout="constrained")
    ax = fig.subplots(2, 2, sharex=True)
    shaft_speed = np.asarray(shaft_speed)

    def at(key, k):
        return np.interp(shaft_speed, steady["speed_rpm"], np.asarray(steady[key])[:, k])

    ax[0, 0].plot(t, shaft_speed, color="k")
    ax[0, 0].set_ylabel("shaft speed [rpm]")
    for k, node in enumerate(nodes):
        color = f"C{k}"
        ax[0, 1].plot(t, np.asarray(max_temperature)[:, k] - KELVIN_AT_0C, color=color, label=f"bearing {node}")
        ax[0, 1].plot(t, at("max_temperature", k) - KELVIN_AT_0C, "--", color=color,
                      label=f"bearing {node}: steady THD at the same speed")
        ax[1, 0].plot(t, np.asarray(power_loss)[:, k], color=color, label=f"bearing {node}")
        ax[1, 0].plot(t, at("power_loss", k), "--", color=color, label=f"bearing {node}: steady THD")
        ax[1, 1].plot(t, np.asarray(eccentricity_ratio)[:, k], lw=0.6, color=color, label=f"bearing {node}")
        ax[1, 1].plot(t, at("eccentricity_ratio", k), "--", color=color, label=f"bearing {node}: steady THD")
    ax[0, 1].set_ylabel("maximum film temperature [C]")
    ax[1, 0].set_ylabel("power loss [W]")
    ax[1, 1].set_ylabel("eccentricity ratio e/C [-]")
    for a in (ax[0, 1], ax[1, 0], ax[1, 1]):
        a.legend(fontsize=7)
    return _run_up_frame(fig, ax, ramp_end, title)


def _run_up_frame(fig, ax, ramp_end: float, title: str):
    """The run-up figures' frame: time on the lower axes, the ramp's end as a grey line, grids, the title."""
    for a in ax[1]:
        a.set_xlabel("time [s]")
    for a in ax.flat:
        a.axvline(ramp_end, color="0.7", lw=0.8)
        a.grid(alpha=0.3)
    suptitle(fig, title)
    return fig
