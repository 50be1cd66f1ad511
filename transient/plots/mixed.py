"""Figures of mixed lubrication: the Stribeck curve (:func:`transient.study.stribeck.stribeck_curve`)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure, suptitle

#: Contact share of the load above which a speed counts as boundary lubrication in the figure (the asperities carry
#: nearly all of it); below the curve's lift-off fraction it is hydrodynamic, between the two mixed.
BOUNDARY_SHARE = 0.9


def regimes(curve):
    """The speed ranges [rpm] of the three regimes of a :class:`~transient.study.stribeck.StribeckCurve`:
    ``{"boundary": (lo, hi), "mixed": ..., "hydrodynamic": ...}`` by the contact share of the load (above
    ``BOUNDARY_SHARE``; between it and the lift-off fraction; below), each range between the speeds' midpoints
    in log(speed) (None where the curve has no speed in that regime)."""
    s = np.asarray(curve.speed_rpm, dtype=float)
    share = np.asarray(curve.contact_load) / curve.load
    edges = np.concatenate([[s[0]], np.sqrt(s[1:] * s[:-1]), [s[-1]]])
    kind = np.where(share >= BOUNDARY_SHARE, "boundary", np.where(share >= curve.lift_off_fraction, "mixed",
                                                                   "hydrodynamic"))
    out = {}
    for name in ("boundary", "mixed", "hydrodynamic"):
        i = np.nonzero(kind == name)[0]
        out[name] = None if i.size == 0 else (float(edges[i[0]]), float(edges[i[-1] + 1]))
    return out


def stribeck(curve, sigma=None, title=None):
    """The Stribeck curve: friction torque and coefficient against speed with the regimes shaded and the lift-off
    speed marked; the minimum film (and ``h_min / sigma`` with the composite roughness ``sigma`` [m]) and the
    asperities' share of the load against speed."""
    fig, ax = figure(1, 3, size=(14, 4.2))
    s = curve.speed_rpm
    colours = {"boundary": "tab:red", "mixed": "tab:orange", "hydrodynamic": "tab:blue"}
    for a in ax:
        for name, rng in regimes(curve).items():
            if rng is not None:
                a.axvspan(*rng, color=colours[name], alpha=0.08, lw=0, label=name)
        if np.isfinite(curve.lift_off_speed_rpm):
            a.axvline(curve.lift_off_speed_rpm, color="k", ls="--", lw=0.8,
                      label=f"lift-off {curve.lift_off_speed_rpm:.0f} rpm")
        a.set_xscale("log")
        a.grid(True, which="both", lw=0.3)
        a.set_xlabel("speed [rpm]")
    ax[0].plot(s, curve.friction_torque, "o-", color="k", ms=3, label="friction torque")
    ax[0].set_ylabel("friction torque [N m]")
    ax[0].set_yscale("log")
    f = ax[0].twinx()  # the coefficient is the torque over R W: a second scale on the same line
    f.set_yscale("log")
    f.set_ylim(*(np.array(ax[0].get_ylim()) * curve.friction_coefficient[0] / curve.friction_torque[0]))
    f.set_ylabel("friction coefficient T / (R W) [-]")
    ax[0].legend(fontsize=7, loc="upper center")
    ax[0].set_title("Stribeck curve")
    ax[1].plot(s, 1e6 * curve.h_min, "o-", ms=3)
    ax[1].set_ylabel("minimum film h_min [um]")
    ax[1].set_yscale("log")
    if sigma:
        h = ax[1].twinx()
        h.set_yscale("log")
        h.set_ylim(*(np.array(ax[1].get_ylim()) * 1e-6 / sigma))
        h.set_ylabel("h_min / sigma [-]")
    ax[1].set_title("minimum film")
    ax[2].plot(s, 100 * curve.contact_load / curve.load, "o-", ms=3, color="tab:red")
    ax[2].set_ylabel("asperity share of the load [%]")
    ax[2].set_ylim(-2, 102)
    ax[2].set_title(f"contact load (load {curve.load:g} N)")
    if title:
        suptitle(fig, title)
    return fig


def rig_torque(curves, measured, peer=None, measured_h_min=None, title=None):
    """The friction rig's shaft torque against speed: per load the computed torque
    (:class:`~transient.study.sander.RigCurve`: the test bearing plus its two supports, with the test bearing's own
    share dashed) beside the measured points ``measured`` = ``{load: (speeds [rpm], torques [N m])}`` and a peer
    code's points ``peer`` (same form); the least-torque speeds marked. Right: the test bearing's minimum film
    (with ``measured_h_min`` = ``{load: (speeds, h_min [m])}``) and the asperities' share of its load."""
    fig, ax = figure(1, 2, size=(13, 4.6))
    colours = ("tab:blue", "tab:red", "tab:green", "tab:purple")
    for c, curve in zip(colours, curves):
        lab = f"{curve.load:g} N"
        s = curve.speed_rpm
        ax[0].plot(s, curve.torque, "-", color=c, lw=1.5, label=f"computed, rig ({lab})")
        ax[0].plot(s, curve.test.friction_torque, "--", color=c, lw=0.9, label=f"computed, test bearing ({lab})")
        ax[0].axvline(curve.minimum_speed_rpm, color=c, ls=":", lw=0.8)
        ms, mt = measured[curve.load]
        ax[0].plot(ms, mt, "o", color=c, mfc="none", label=f"measured ({lab})")
        if peer and curve.load in peer:
            ps, pt = peer[curve.load]
            ax[0].plot(ps, pt, "x", color=c, label=f"peer code, elastic ({lab})")
        ax[1].plot(s, 1e6 * curve.test.h_min, "-", color=c, label=f"h_min, computed ({lab})")
        if measured_h_min and curve.load in measured_h_min:
            hs, hh = measured_h_min[curve.load]
            ax[1].plot(hs, 1e6 * np.asarray(hh), "s", color=c, mfc="none", label=f"h_min, source ({lab})")
    for a in ax:
        a.set_xscale("log")
        a.grid(True, which="both", lw=0.3)
        a.set_xlabel("speed [rpm]")
    ax[0].set_ylabel("shaft torque [N m]")
    ax[0].set_title("shaft torque (dotted: computed least-torque speed)")
    ax[0].legend(fontsize=7)
    ax[1].set_ylabel("test bearing minimum film [um]")
    ax[1].set_title("minimum film; contact share (right scale)")
    share = ax[1].twinx()
    for c, curve in zip(colours, curves):
        share.plot(curve.speed_rpm, 100 * curve.test.contact_load / curve.load, ":", color=c)
    share.set_ylabel("asperity share of the test bearing's load [%] (dotted)")
    share.set_ylim(-2, 102)
    ax[1].legend(fontsize=7, loc="upper left")
    if title:
        suptitle(fig, title)
    return fig


def speed_histories(runs, load, sigma=None, title=None):
    """Start-up and coast-down histories of rough journal orbits (:class:`~transient.models.journal.results.
    OrbitResult` recorded with ``"shaft_speed"``, ``"friction_torque"``, ``"min_film"``, ``"contact_load"``): ``runs`` maps a
    label to its result; one column each, rows shaft speed, friction torque, minimum film (and ``h_min / sigma``),
    the asperities' share of the ``load`` [N] with the peak asperity pressure; contact events marked."""
    fig, ax = figure(4, len(runs), size=(6.5 * len(runs), 11), sharex="col")
    ax = np.asarray(ax).reshape(4, len(runs))
    for j, (label, r) in enumerate(runs.items()):
        a = ax[:, j]
        a[0].plot(r.t, r.shaft_speed, color="k")
        a[0].set_ylabel("shaft speed [rpm]")
        a[0].set_title(label)
        a[1].plot(r.t, r.friction_torque, color="tab:purple")
        a[1].set_ylabel("friction torque [N m]")
        a[2].plot(r.t, 1e6 * r.min_film)
        a[2].set_ylabel("minimum film h_min [um]")
        if sigma:
            a[2].axhline(3e6 * sigma, color="k", ls=":", lw=0.8, label="h_min = 3 sigma")
            a[2].legend(fontsize=7)
        a[3].plot(r.t, 100 * r.contact_load / load, color="tab:red", label="asperity share of the load")
        a[3].set_ylabel("asperity share of the load [%]")
        p = a[3].twinx()
        p.plot(r.t, 1e-6 * r.contact_pressure, color="tab:orange", lw=0.8, ls="--")
        p.set_ylabel("peak asperity pressure [MPa]", color="tab:orange")
        a[3].set_xlabel("time [s]")
        for t, what in r.contact_events or ():
            for b in a:
                b.axvline(t, color="tab:red" if what == "begins" else "tab:green", lw=0.6, ls="--")
        for b in a:
            b.grid(True, lw=0.3)
    if title:
        suptitle(fig, title)
    return fig
