"""Figures of a rotor on journal bearings: the Campbell diagram with the whirl thresholds, the unbalance
response against the speed (linear and from a run), the waterfall of a run-up or coast-down, orbits at nodes.
Inputs are arrays and the rotor results (:mod:`transient.models.rotor.results`); no model is imported."""

from __future__ import annotations

import numpy as np

from transient.analysis.rotor import waterfall as cascade
from transient.plots import figure


def campbell(speeds_rpm, eigenvalues, thresholds: dict):
    """Damped natural frequencies [Hz] of the linearised system against the speed (``eigenvalues`` [1/s],
    one row per speed; colour: damping ratio), the 1x and 0.5x lines and the ``thresholds`` {label: rpm}."""
    fig, ax = figure(size=(7.5, 4.8))
    s = np.asarray(speeds_rpm, dtype=float)
    for k, lam in enumerate(eigenvalues):
        lam = np.asarray(lam)
        lam = lam[lam.imag > 1e-6]
        zeta = -lam.real / np.abs(lam)
        sc = ax.scatter(np.full(lam.size, s[k]), lam.imag / (2 * np.pi), c=np.clip(zeta, 0, 0.5), s=10,
                        cmap="viridis_r", vmin=0, vmax=0.5)
    hz = s / 60.0
    ax.plot(s, hz, "k-", lw=1, label="1x")
    ax.plot(s, 0.5 * hz, "k--", lw=1, label="0.5x")
    for (label, n), style in zip(thresholds.items(), ("-", ":", "-.")):
        ax.axvline(n, color="tab:red", ls=style, label=f"{label}: {n:.0f} rpm")
    ax.set(xlabel="shaft speed [rpm]", ylabel="damped natural frequency [Hz]", ylim=(0, 1.2 * hz.max()),
           title="Campbell diagram (bearings as K, C) and whirl thresholds")
    fig.colorbar(sc, ax=ax).set_label("damping ratio [-]")
    ax.legend(fontsize=8, loc="upper left")
    return fig


def response_curve(linear: dict, runs: dict, node_label: str):
    """1x amplitude [um] at one node against the speed: linear curves ``{label: (speeds [rpm], amplitude [m])}``
    and run-derived points ``{label: (speeds, amplitude)}`` (a run-up is transient: not a settled response)."""
    fig, ax = figure(size=(7.5, 4.5))
    for label, (s, a) in linear.items():
        ax.plot(s, np.asarray(a) * 1e6, lw=1.5, label=label)
    for label, (s, a) in runs.items():
        ax.plot(s, np.asarray(a) * 1e6, ".", ms=4, label=label)
    ax.set(xlabel="shaft speed [rpm]", ylabel=f"1x amplitude at {node_label} [um]", yscale="log",
           title=f"unbalance response at {node_label}")
    ax.legend(fontsize=8)
    return fig


def waterfall(result, node, title, window_revolutions=4.0, max_order=1.5):
    """Cascade of a run (:class:`~transient.models.rotor.results.RotorRunResult`) at ``node``: the amplitude
    spectrum of x [um] per window against frequency [Hz] and speed [rpm], with the 1x, 0.5x lines."""
    x = result.position(node)[0]
    speeds, freqs, amp = cascade(result.t, x, result.speed_rpm, window_revolutions)
    order = np.argsort(speeds)  # a coast-down's windows come in falling speed
    speeds, amp = speeds[order], amp[order]
    fig, ax = figure(size=(7.5, 4.8))
    keep = freqs <= max_order * speeds.max() / 60.0
    a = np.maximum(amp[:, keep] * 1e6, 1e-4)
    mesh = ax.pcolormesh(freqs[keep], speeds, np.log10(a), shading="nearest", cmap="magma")
    ax.plot(speeds / 60.0, speeds, "w-", lw=0.8, label="1x")
    ax.plot(0.5 * speeds / 60.0, speeds, "w--", lw=0.8, label="0.5x")
    ax.set(xlabel="frequency [Hz]", ylabel="shaft speed [rpm]", title=title)
    fig.colorbar(mesh, ax=ax).set_label("log10 amplitude of x [log10 um]")
    ax.legend(fontsize=8, loc="lower right")
    return fig


def orbits(result, nodes: dict, speeds_rpm, revolutions=2.0):
    """Orbits [um] at ``nodes`` {node: label} over ``revolutions`` revolutions ending at each of ``speeds_rpm``
    along a run (one panel per node, one curve per speed)."""
    fig, axes = figure(1, len(nodes), size=(4.2 * len(nodes), 4.2))
    axes = np.atleast_1d(axes)
    t, n = np.asarray(result.t), np.asarray(result.speed_rpm)
    for ax, (node, label) in zip(axes, nodes.items()):
        x, y = (np.asarray(v) * 1e6 for v in result.position(node))
        for s in speeds_rpm:
            k = int(np.argmin(np.abs(n - s)))
            t0 = t[k] - revolutions * 60.0 / max(n[k], 1e-9)
            w = (t >= t0) & (t <= t[k])
            ax.plot(y[w], x[w], lw=0.8, label=f"{n[k]:.0f} rpm")
        ax.set(xlabel="y [um]", ylabel="x (load direction) [um]", title=f"orbit at {label}", aspect="equal")
        ax.invert_yaxis()
        ax.legend(fontsize=7)
    return fig
