"""Figures of oil whip (the rotor of Rho & Kim, "Noise estimation of oil lubricated journal bearings"): the
run-up through the threshold and the long whirl runs above it. An eccentricity range is called a limit cycle
only where :func:`transient.study.whip.envelope_growth` says it settled.

Inputs are Results and the number dicts of :mod:`transient.study.whip` (``whirl_numbers``): this module
imports no model."""

from __future__ import annotations

import numpy as np

from transient.analysis.orbits import per_revolution, revolution_spectrum
from transient.plots import figure


def run_up(ru):
    """The run-up (a :class:`~transient.study.whip.RunUp`): eccentricity against time with the speed steps
    (left) and the per-speed eccentricity range (filled markers where it settled into a limit cycle, open where
    not) and whirl frequency ratio against the speed in units of the Lund threshold (right)."""
    C = ru.clearance
    eps = np.hypot(ru.x, ru.y) / C
    th = ru.threshold_rpm or 1.0
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.4))
    ax.plot(ru.t, eps, lw=0.5, color="tab:blue")
    tw = ax.twinx()
    tw.plot(ru.t, ru.speed_rpm / th, color="0.4", lw=1.0, ds="steps-post")
    tw.set_ylabel("speed / threshold [-]", color="0.4")
    ax.set(xlabel="time [s]", ylabel="eccentricity ratio e/C [-]", title="run-up through the threshold (speed steps: grey)")
    s = ru.speeds / th
    settled = np.asarray(ru.settled, bool) if np.size(ru.settled) == s.size else np.zeros(s.size, bool)
    bx.fill_between(s, ru.eps_min, ru.eps_max, color="tab:blue", alpha=0.2, lw=0,
                    label="e/C range over the last revolutions")
    bx.plot(s, ru.eps_max, "-", color="tab:blue", lw=0.8)
    bx.plot(s[settled], ru.eps_max[settled], "o", color="tab:blue", ms=5, label="settled (limit cycle)")
    bx.plot(s[~settled], ru.eps_max[~settled], "o", mfc="white", color="tab:blue", ms=5,
            label="NOT settled (envelope still moving)")
    bx.axvline(1.0, color="k", ls=":", lw=0.8)
    bx.set(xlabel="speed / Lund threshold [-]", ylabel="eccentricity ratio e/C [-]", ylim=(0, 1.02),
           title=f"threshold {ru.threshold_rpm:.0f} rpm; {int(settled.sum())} of {s.size} speeds settled")
    cx = bx.twinx()
    cx.plot(s, ru.whirl_ratio, "s--", color="tab:red", ms=4, label="whirl frequency / shaft frequency")
    cx.set(ylabel="whirl frequency / shaft frequency [-]", ylim=(0, 1.2))
    cx.yaxis.label.set_color("tab:red")
    h1, l1 = bx.get_legend_handles_labels()
    h2, l2 = cx.get_legend_handles_labels()
    bx.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
    for a in (ax, bx):
        a.grid(True, lw=0.3)
    return fig


def whirl(result, numbers, outputs_per_revolution, label=""):
    """One long whip run: the eccentricity envelope per revolution (left), the last revolutions of the orbit
    with the Poincare section (centre, once per shaft revolution) and the clearance circle (middle), and the x
    spectrum in shaft orders over the last revolutions (right)."""
    C = result.clearance
    X, Y = per_revolution(result.x, result.y, outputs_per_revolution, C)
    k = int(numbers["last_revolutions"])
    fig, (ax, bx, cx) = figure(1, 3, size=(15, 4.4))
    rev = np.arange(1, X.shape[0] + 1)
    e = np.hypot(X, Y)
    ax.fill_between(rev, e.min(axis=1), e.max(axis=1), color="tab:blue", alpha=0.35, lw=0)
    ax.plot(rev, e.max(axis=1), lw=0.7, color="tab:blue")
    touched = numbers.get("touched_at_s")
    ax.set(xlabel="revolution [-]", ylabel="e/C, min-max per revolution [-]", ylim=(0, 1.02),
           title=f"{label}{result.speed_rpm:.0f} rpm: " + ("no touch" if touched is None else
                                                           f"touches at {touched * result.speed_rpm / 60:.1f} rev"))
    a = np.linspace(0, 2 * np.pi, 400)
    bx.plot(np.sin(a), np.cos(a), color="k", lw=0.8, label="clearance circle")
    bx.plot(Y[-k:].ravel(), X[-k:].ravel(), lw=0.4, color="tab:blue", label=f"last {k} revolutions")
    bx.plot(Y[:, 0], X[:, 0], ".", color="0.6", ms=2, label="Poincare section (every revolution)")
    bx.plot(Y[-k:, 0], X[-k:, 0], "o", color="tab:red", ms=3, label=f"Poincare, last {k}")
    cycle = "limit cycle" if numbers.get("settled") else "NOT settled"
    bx.set(xlabel="y / C [-]", ylabel="x / C (towards the load) [-]",
           title=f"{cycle}: e/C {numbers['eps_min']:.3f}-{numbers['eps_max']:.3f}, envelope "
                 f"{numbers.get('envelope_growth_per_rev', float('nan')):+.1e} C/rev")
    bx.invert_yaxis()
    bx.set_aspect("equal")
    bx.legend(fontsize=7, loc="lower left")
    order, spec, _, _ = revolution_spectrum(X[-k:])
    ac = order > 0.05  # the DC bin (the orbit's mean position) would drag the axis down to its round-off
    cx.semilogy(order[ac], np.maximum(spec[ac], 1e-12), lw=0.8)
    if ac.any():
        cx.set_ylim(max(spec[ac].max() * 1e-6, 1e-12), spec[ac].max() * 2)
    cx.axvline(numbers["whirl_ratio"], color="tab:red", ls=":", lw=0.8)
    cx.set(xlim=(0, 3), xlabel="frequency / shaft frequency [-]", ylabel="x amplitude [C]",
           title=f"whirl frequency ratio {numbers['whirl_ratio']:.3f}")
    for a_ in (ax, bx, cx):
        a_.grid(True, lw=0.3)
    return fig
