"""Figures of the journal orbit and its noise (Rho & Kim, "Noise estimation of oil lubricated journal bearings"):
Figs. 3-12, stability runs, long runs."""

from __future__ import annotations

import textwrap

import numpy as np

from transient.analysis.orbits import per_revolution
from transient.plots import figure


def orbit_settling(study, outputs_per_revolution, grid):
    """Fig. 3: the orbit from the static equilibrium settling onto its ellipse (left) and the distance of
    each revolution from the last (right). ``study``: the
    :class:`~transient.study.journal.EquilibriumOrbit` of :func:`transient.study.journal.orbit_from_equilibrium`."""
    result = study.orbit
    C = result.clearance
    X, Y = per_revolution(result.x, result.y, outputs_per_revolution, C)
    dist = np.asarray(study.settle_distance_per_rev)
    amp = study.settled_orbit["semi_major"]
    fig, (ax, bx) = figure(1, 2, size=(11, 4.8))
    ax.plot(result.y / C, result.x / C, lw=0.5, color="0.6", label="transient from equilibrium")
    ax.plot(np.append(Y[-1], Y[-1][0]), np.append(X[-1], X[-1][0]), lw=1.8, color="tab:red",
            label=f"{'settled orbit' if study.settled_within_1pct_after_revs else 'last revolution, NOT settled'} "
                  f"(rev {len(dist)})")
    eq = study.equilibrium
    ax.plot(eq[1], eq[0], "k+", ms=10, label="static equilibrium")
    ax.set(xlabel="y / C (90 deg ahead of the load, with the rotation) [-]", ylabel="x / C (towards the load) [-]",
           title=f"Fig. 3: journal orbit, {study.speed_rpm:g} rpm, {grid[0]}x{grid[1]}")
    ax.invert_yaxis()
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    bx.semilogy(np.arange(1, len(dist)), dist[:-1], "o-", ms=3)  # the last revolution is the reference
    bx.axhline(0.01 * amp, color="0.5", ls=":", lw=0.8)
    bx.set(xlabel="revolution [-]", ylabel="max distance from the last revolution [C]",
           title="settling (1 % of the amplitude: dotted):\n" + textwrap.fill(study.settling(), 64))
    bx.title.set_fontsize(9)
    bx.grid(True, which="both", lw=0.3)
    return fig


def x_spectrum(study):
    """Fig. 4: spectrum of x over the last revolutions of the settled orbit (orders of the shaft speed);
    ``study``: the :class:`~transient.study.journal.EquilibriumOrbit` of
    :func:`transient.study.journal.orbit_from_equilibrium`."""
    order = np.asarray(study.spectrum_order)
    spec = np.asarray(study.spectrum_amplitude_C)
    fig, ax = figure(size=(7, 4.2))
    ac = order > 0.05  # without the DC bin (the orbit's mean position), which would set the axis range
    ax.semilogy(order[ac], np.maximum(spec[ac], 1e-12), lw=1.0)
    for h, v in study.harmonics_C.items():
        if h != "0.5x":
            ax.annotate(h, (float(h[:-1]), v), textcoords="offset points", xytext=(3, 4), fontsize=8)
    ax.set_xlim(0, 8)
    ax.set_ylim(max(spec[ac].max() * 1e-6, 1e-12), spec[ac].max() * 3)
    ax.set(xlabel="frequency / shaft speed [-]", ylabel="amplitude of x [C]",
           title=f"Fig. 4: spectrum of x, {study.speed_rpm:g} rpm, last {study.fft_revolutions} revolutions "
                 f"(largest peak at {study.spectrum_peak_order:g}x)")
    ax.title.set_fontsize(10)
    ax.grid(True, which="both", lw=0.3)
    return fig


def settled_point(point: dict, settle_fraction: float = 1e-2) -> bool:
    """Whether a Fig. 8 point is a settled orbit: the shooting converged (``converged``) or the settling run's
    distance estimate (``settle_estimate``, relative to the amplitude) is within ``settle_fraction``."""
    return bool(point.get("converged", True)) and point.get("settle_estimate", 0.0) <= settle_fraction


def unbalance_response(points, linear, peaks, paper_peak_rpm=None):
    """Fig. 8: unbalance response amplitude [C] against speed: filled markers = nonlinear periodic (settled)
    orbits, open markers = points that did not converge or settle (:func:`settled_point`), lines = the
    linearised K, C response; ``peaks`` the peak speed of each curve."""
    fig, ax = figure(size=(7, 4.5))
    sp = [p["speed_rpm"] for p in points]
    ls = [p["speed_rpm"] for p in linear]
    for k, c, lab in (("semi_major", "k", "orbit semi-major axis"), ("amp_x", "tab:blue", "x amplitude"),
                      ("amp_y", "tab:orange", "y amplitude")):
        ax.plot(ls, [p[k] for p in linear], "-", color=c, lw=0.8, alpha=0.7)
        good = [settled_point(p) for p in points]
        ax.plot([v for v, g in zip(sp, good) if g], [p[k] for p, g in zip(points, good) if g], "o", color=c, ms=5,
                label=f"{lab} (peak {peaks[k]:.0f} rpm)")
        if not all(good):
            ax.plot([v for v, g in zip(sp, good) if not g], [p[k] for p, g in zip(points, good) if not g], "o",
                    mfc="white", color=c, ms=7, label=f"{lab}: NOT converged / settled")
    if paper_peak_rpm:
        ax.axvline(paper_peak_rpm, color="0.5", ls=":", lw=0.8)
        ax.text(paper_peak_rpm, ax.get_ylim()[1] * 0.98, " paper peak", va="top", fontsize=8, color="0.4")
    ax.set(xlabel="shaft speed [rpm]", ylabel="unbalance response amplitude [C]",
           title="Fig. 8: unbalance response (markers: nonlinear transient; lines: linearised K, C)")
    ax.title.set_fontsize(10)
    ax.legend(fontsize=8)
    ax.grid(True, lw=0.3)
    return fig


def stability_runs(runs, threshold_rpm, paper_rpm=None):
    """Distance from the equilibrium [C] against revolutions for the free-vibration runs around the
    threshold, with the measured and linear growth per revolution in the legend."""
    fig, ax = figure(size=(7, 4.5))
    for r in runs:
        ax.semilogy(r["revolutions_axis"], np.maximum(r["distance_C"], 1e-12), lw=0.6,
                    label=f"{r['speed_rpm']:.0f} rpm ({r['speed_rpm'] / threshold_rpm:.2f} x): "
                          f"{r['growth_per_rev']:+.3f}/rev (linear {r['linear_growth_per_rev']:+.3f})")
    ax.set(xlabel="revolutions [-]", ylabel="distance from the equilibrium [C]",
           title=f"Stability: linear threshold {threshold_rpm:.0f} rpm"
                 + (f" (paper ~{paper_rpm:g})" if paper_rpm else "") + ", nonlinear runs")
    ax.title.set_fontsize(10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    return fig


def long_run(result, outputs_per_revolution):
    """A long orbit: the eccentricity envelope per revolution (left) and the last revolution (right)."""
    C = result.clearance
    X, Y = per_revolution(result.x, result.y, outputs_per_revolution, C)
    eps = np.hypot(X, Y)
    fig, (ax, bx) = figure(1, 2, size=(11, 4.2))
    rev = np.arange(1, eps.shape[0] + 1)
    ax.fill_between(rev, eps.min(axis=1), eps.max(axis=1), color="tab:blue", alpha=0.4, lw=0)
    ax.plot(rev, eps.max(axis=1), lw=0.6, color="tab:blue")
    ax.set(xlabel="revolution [-]", ylabel="eccentricity ratio e/C, min-max per revolution [-]",
           title=f"{eps.shape[0]} revolutions at {result.speed_rpm:g} rpm")
    bx.plot(np.append(Y[-1], Y[-1][0]), np.append(X[-1], X[-1][0]), "-", color="tab:red")
    bx.set(xlabel="y / C [-]", ylabel="x / C (towards the load) [-]", title="last revolution")
    bx.invert_yaxis()
    bx.set_aspect("equal", adjustable="datalim")
    for a in (ax, bx):
        a.grid(True, lw=0.3)
    return fig


def noise_maps(noise, equilibrium, transitions):
    """Figs. 5/6: equilibrium pressure, RMS pressure fluctuation p_f and its level in the oil over the grid."""
    ang, zz = noise.angle_deg, noise.z * 1e3
    spl = np.asarray(noise.oil_spl(), dtype=float)
    top = np.nanmax(spl[np.isfinite(spl)])
    spl = np.where(np.isfinite(spl), np.maximum(spl, top - 100.0), top - 100.0)  # cavitated: p_f ~ 0
    fig, axs = figure(1, 3, size=(15, 4))
    for a, data, title, unit in ((axs[0], equilibrium.pressure / 1e6, "(a) equilibrium pressure", "MPa"),
                                 (axs[1], noise.p_fluct / 1e3, "(b) pressure fluctuation p_f", "kPa"),
                                 (axs[2], spl, "Fig. 6: level of p_f in the oil (floor: max - 100 dB)", "dB re 1 uPa")):
        m = a.pcolormesh(ang, zz, data, shading="nearest")
        fig.colorbar(m, ax=a, label=f"[{unit}]")
        a.set(xlabel="angle [deg]", ylabel="z from mid-plane [mm]", title=title)
        for key, c in (("rupture_deg", "r"), ("reformation_deg", "w")):
            if key in transitions:
                a.axvline(transitions[key], color=c, ls="--", lw=0.8)
    fig.suptitle(f"Fig. 5/6 at {noise.speed_rpm:g} rpm (grid {noise.p_fluct.shape[1]} x {noise.p_fluct.shape[0]}; "
                 "dashed: rupture red, reformation white)")
    return fig


def noise_spectra(noise, transitions):
    """Fig. 4 (journal x spectrum) and Fig. 7 (nodal pressure spectra on the mid-plane, in the oil)."""
    fig, axs = figure(1, 2, size=(12, 4))
    f, a = noise.x_spectrum
    ac = f > 0.05 * noise.frequency_hz  # without the DC bin
    axs[0].semilogy(f[ac] / noise.frequency_hz, a[ac] * 1e6, "o-", ms=3)
    axs[0].set(xlabel="frequency / shaft frequency [-]", ylabel="x amplitude [um]", title="Fig. 4: journal x spectrum",
               xlim=(0, noise.samples_per_revolution / 2))
    if ac.any() and a[ac].max() > 0:
        axs[0].set_ylim(max(a[ac].max() * 1e6 * 1e-6, 1e-12), a[ac].max() * 1e6 * 3)
    nodes = [("max p_f", int(np.argmax(noise.p_fluct[0])))]
    if transitions:
        nodes += [(f"rupture {transitions['rupture_deg']:.0f} deg", transitions["rupture_index"]),
                  (f"reformation {transitions['reformation_deg']:.0f} deg", transitions["reformation_index"])]
    nodes.append(("paper's reformation 96 deg", noise.node(96.0)[1]))
    for lab, col in nodes:
        f, L = noise.spectrum("pressure", node=(0, col), db=True)
        axs[1].plot(f[1:] / noise.frequency_hz, L[1:], "o-", ms=3, label=f"{lab} (node {col})")
    axs[1].set(xlabel="frequency / shaft frequency [-]", ylabel="pressure level in the oil [dB re 1 uPa]", title="Fig. 7: nodal spectra, mid-plane",
               xlim=(0, noise.samples_per_revolution / 2))
    axs[1].legend(fontsize=8)
    return fig


def noise_levels(points, grid):
    """Figs. 9-12: bearing noise N_b (and A-weighted) and the per-harmonic levels against speed."""
    ok = [p for p in points if "level_db" in p]
    sp = np.array([p["speed_rpm"] for p in ok])
    fig, axs = figure(1, 3, size=(15, 4))
    axs[0].plot(sp, [p["level_db"] for p in ok], "o-", label="N_b (eq. 16)")
    axs[0].plot(sp, [p["level_dba"] for p in ok], "s-", label="N_b, A-weighted")
    axs[0].set(xlabel="speed [rpm]", ylabel="noise level [dB re 20 uPa] (printed eq. 14)", title="Fig. 9/10: bearing noise")
    axs[0].legend()
    H = np.array([p["harmonic_levels_db"] for p in ok])
    HA = np.array([p["harmonic_levels_dba"] for p in ok])
    for k in range(H.shape[1]):
        axs[1].plot(sp, H[:, k], "o-", label=f"{k + 1}x")
        axs[2].plot(sp, HA[:, k], "o-", label=f"{k + 1}x")
    axs[1].set(xlabel="speed [rpm]", ylabel="level [dB]", title="Fig. 11: harmonic levels")
    axs[2].set(xlabel="speed [rpm]", ylabel="A-weighted level [dB(A)]", title="Fig. 12: A-weighted harmonic levels")
    axs[1].legend(fontsize=8)
    fig.suptitle(f"grid {grid[0]} x {grid[1]}")
    return fig


def whirl_amplitude(points):
    """The whirl amplitude max |r - r_mean| [um] of the settled orbit against speed (Fig. 8 of the noise sweep)."""
    ok = [p for p in points if "whirl_amplitude_um" in p]
    fig, ax = figure(size=(5, 4))
    ax.plot([p["speed_rpm"] for p in ok], [p["whirl_amplitude_um"] for p in ok], "o-")
    ax.set(xlabel="speed [rpm]", ylabel="max |r - r_mean| [um]", title="Fig. 8: unbalance response")
    return fig


def cavitation_modes(res):
    """Elrod against Reynolds film (:func:`transient.study.cavitation_modes.coefficients_by_mode`): the largest
    entry of (K_Elrod - K_Reynolds) and of the same for C, relative to the largest Reynolds entry, against the
    Reynolds equilibrium eccentricity, one line per groove angle (``dK_max``, ``dC_max`` of each
    :class:`~transient.study.cavitation_modes.ModeComparison`)."""
    fig, axes = figure(1, 2, size=(11, 4.2))
    for ang, r in res.items():
        for ax, q in zip(axes, ("K", "C")):
            ax.plot(r.eps_reynolds, 100 * getattr(r, f"d{q}_max"), "o-", label=f"groove at {ang:g} deg")
    for ax, q in zip(axes, ("stiffness K", "damping C")):
        ax.set(xlabel="equilibrium e/C (Reynolds film) [-]", ylabel="largest |Elrod - Reynolds| / max |Reynolds| [%]",
               title=f"{q}: mass-conserving vs Reynolds-condition film")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
    return fig
