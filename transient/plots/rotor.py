"""Figures of a rotor on journal bearings: the Campbell diagram with the whirl thresholds, the unbalance
response against the speed (linear and from a run), the waterfall of a run-up or coast-down, orbits at nodes.
Inputs are arrays and the rotor results (:mod:`transient.models.rotor.results`); no model is imported."""

from __future__ import annotations

import numpy as np

from transient.analysis.rotor import shaft_angle
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


def response_curve(linear: dict, runs: dict, node_label: str, threshold_rpm=None):
    """1x amplitude [um] at one node against the speed: linear curves ``{label: (speeds [rpm], amplitude [m])}``
    (each its own line style, so curves that agree stay visible; the legend gives the largest difference of two)
    and run-derived points ``{label: (speeds, amplitude[, synchronous])}`` (a run-up is transient: not a settled
    response). Where ``synchronous`` is False the motion there is mostly not at 1x (a whirl) and the
    least-squares 1x amplitude absorbs part of it: those points are drawn open and said so. ``threshold_rpm``: the
    whirl threshold (a vertical line)."""
    fig, ax = figure(size=(8.0, 6.0))
    curves = [(label, np.asarray(s, float), np.asarray(a, float)) for label, (s, a) in linear.items()]
    for (label, s, a), (style, width) in zip(curves, (("-", 2.5), ("--", 1.5), (":", 1.5), ("-.", 1.5))):
        ax.plot(s, a * 1e6, ls=style, lw=width, label=label)
    if len(curves) == 2 and np.array_equal(curves[0][1], curves[1][1]):
        d = np.max(np.abs(curves[1][2] / curves[0][2] - 1.0))
        ax.plot([], [], " ", label=f"(the two linear curves differ by at most {100 * d:.1f} %)")
    for (label, run), marker in zip(runs.items(), ("o", "s", "^", "v")):
        s, a = np.asarray(run[0], float), np.asarray(run[1], float) * 1e6
        sync = np.asarray(run[2], bool) if len(run) > 2 else np.ones(s.size, bool)
        line, = ax.plot(s[sync], a[sync], marker, ms=4, ls="none", label=label)
        if (~sync).any():
            ax.plot(s[~sync], a[~sync], marker, ms=4, ls="none", mfc="none", color=line.get_color(),
                    label=f"{label}, mostly not at 1x (whirl in the 1x fit)")
    if threshold_rpm:
        ax.axvline(threshold_rpm, color="0.4", ls="-.", lw=0.9, label=f"whirl threshold, {threshold_rpm:.0f} rpm")
    ax.set(xlabel="shaft speed [rpm]", ylabel=f"1x amplitude at {node_label} [um]", yscale="log",
           title=f"unbalance response at {node_label}")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)  # below: the points stay visible
    return fig


def fitting_window(result, window_revolutions) -> float:
    """``window_revolutions``, shortened on a short run so that :func:`order_spectra` has at least 3 windows
    (or, on a run of under 4 revolutions, windows of half the run)."""
    total = shaft_angle(np.asarray(result.t, float), np.asarray(result.speed_rpm, float))[-1] / (2 * np.pi)
    return min(window_revolutions, max(total - 2.0, 0.5 * total))


def order_spectra(result, node, window_revolutions=4.0, step_revolutions=1.0, samples_per_revolution=16,
                  padding=8):
    """Order-tracked spectra of x at ``node`` over a run: ``x`` resampled on the shaft angle, windows of
    ``window_revolutions`` sliding by ``step_revolutions``, each with its linear trend removed (the static position
    moves with the speed), Hann-windowed and zero-padded
    ``padding`` times (amplitude-corrected: a sine of amplitude A gives a peak A). Returns the windows' mean speeds
    [rpm], the orders (frequency / shaft frequency) and the amplitudes [m] (windows x orders). The true resolution is
    1 / ``window_revolutions`` orders; the padding only draws the peaks smoothly."""
    t, n = np.asarray(result.t, float), np.asarray(result.speed_rpm, float)
    x = np.asarray(result.position(node)[0], float)
    turns = shaft_angle(t, n) / (2 * np.pi)
    starts = np.arange(0.0, turns[-1] - window_revolutions + 1e-9, step_revolutions)
    if starts.size == 0:
        raise ValueError(f"window_revolutions = {window_revolutions:g} is longer than the run ({turns[-1]:.3g} "
                         "revolutions)")
    m = int(round(window_revolutions * samples_per_revolution))
    hann = np.hanning(m)
    orders = np.fft.rfftfreq(padding * m, 1.0 / samples_per_revolution)
    speeds, amps = [], []
    for a in starts:
        u = a + np.arange(m) / samples_per_revolution
        seg = np.interp(u, turns, x)
        seg = seg - np.polyval(np.polyfit(u, seg, 1), u)  # the drift of the static position with the speed
        amps.append(2.0 * np.abs(np.fft.rfft(seg * hann, padding * m)) / hann.sum())
        speeds.append(float(np.interp(a + 0.5 * window_revolutions, turns, n)))
    return np.array(speeds), orders, np.array(amps)


def waterfall(result, node, title, window_revolutions=4.0, max_order=1.5, critical_hz=None, threshold_rpm=None,
              decades=2.5):
    """Cascade of a run (:class:`~transient.models.rotor.results.RotorRunResult`) at ``node``: the amplitude of x
    [um] (colour, log scale over ``decades`` below the largest) against the order (frequency / shaft frequency,
    left) and against the frequency [Hz] (right), one row per window of ``window_revolutions`` sliding by one
    revolution (:func:`order_spectra`), each row's largest peak marked, with the 1x and 0.5x lines and, if given,
    the frequency ``critical_hz`` [Hz] (the mode that goes unstable, where oil whip locks in) and the whirl
    threshold ``threshold_rpm``."""
    window_revolutions = fitting_window(result, window_revolutions)
    speeds, orders, amp = order_spectra(result, node, window_revolutions)
    order = np.argsort(speeds)  # a coast-down's windows come in falling speed
    speeds, amp = speeds[order], 1e6 * amp[order]
    keep = orders <= max_order
    top = float(amp[:, keep].max()) if amp[:, keep].size else 1.0
    level = np.log10(np.maximum(amp[:, keep], top * 10.0 ** -decades))
    fig, (ax, bx) = figure(1, 2, size=(12.0, 5.0), sharey=True)
    rows = np.arange(speeds.size)
    for a, x in ((ax, np.broadcast_to(orders[keep], level.shape)), (bx, np.outer(speeds / 60.0, orders[keep]))):
        mesh = a.pcolormesh(x, np.broadcast_to(speeds[:, None], level.shape), level, shading="gouraud", cmap="magma",
                            vmin=level.min(), vmax=level.max())
        a.grid(True, lw=0.3, alpha=0.4)
    for k, style in ((1.0, "-"), (0.5, "--")):
        ax.axvline(k, color="w", ls=style, lw=0.9, label=f"{k:g}x")
        bx.plot(k * speeds / 60.0, speeds, color="w", ls=style, lw=0.9, label=f"{k:g}x")
    peak = orders[keep][np.argmax(np.where(orders[keep] >= 0.1, amp[:, keep], 0.0), axis=1)]
    ax.plot(peak, speeds, "o", ms=3, mfc="none", mec="tab:cyan", label="largest peak of each window")
    bx.plot(peak * speeds / 60.0, speeds, "o", ms=3, mfc="none", mec="tab:cyan")
    if threshold_rpm:
        for a in (ax, bx):
            a.axhline(threshold_rpm, color="0.8", ls="-.", lw=0.9)
        ax.plot([], [], color="0.8", ls="-.", lw=0.9, label=f"whirl threshold, {threshold_rpm:.0f} rpm")
    if critical_hz:
        ax.plot(60.0 * critical_hz / speeds, speeds, color="tab:green", ls=":", lw=1.4,
                label=f"least-damped mode, {critical_hz:.0f} Hz")
        bx.axvline(critical_hz, color="tab:green", ls=":", lw=1.4)
    ax.set(xlabel="order: frequency / shaft frequency [-]", ylabel="shaft speed [rpm]", xlim=(0, max_order),
           title=f"{title}: in shaft orders")
    bx.set(xlabel="frequency [Hz]", xlim=(0, max_order * speeds.max() / 60.0), title="the same in Hz")
    if speeds.max() > speeds.min():
        ax.set_ylim(speeds.min(), speeds.max())
    fig.colorbar(mesh, ax=(ax, bx)).set_label(f"log10 amplitude of x [log10 um] ({rows.size} windows of "
                                             f"{window_revolutions:g} rev)")
    ax.legend(fontsize=8, loc="upper right", facecolor="0.2", labelcolor="w", framealpha=0.85)
    return fig


def _period_revolutions(turns, x, end, lookback=6.0) -> float:
    """Revolutions in one period of the largest motion of ``x`` in the ``lookback`` revolutions before index
    ``end`` (1 / the order of its largest peak above 0.1x, rounded up), 2 to 8."""
    u = np.linspace(max(turns[end] - lookback, 0.0), turns[end], 97)
    if u[-1] - u[0] < 1.0:
        return 2.0
    v = np.interp(u, turns, x)
    v = v - np.polyval(np.polyfit(u, v, 1), u)
    orders = np.fft.rfftfreq(8 * u.size, u[1] - u[0])
    spec = np.abs(np.fft.rfft(v * np.hanning(u.size), 8 * u.size))
    peak = orders[np.argmax(np.where(orders >= 0.1, spec, 0.0))]
    return float(np.clip(np.ceil(1.0 / peak - 0.05), 2.0, 8.0))


def orbits(result, nodes: dict, speeds_rpm, revolutions=None):
    """Orbits [um] at ``nodes`` {node: label} ending at each of ``speeds_rpm`` along a run (one panel per node, one
    curve per speed, a dot where it ends). Each covers ``revolutions`` shaft revolutions, by default one period of
    the largest motion there (:func:`_period_revolutions` of the last node's x: a whirl at 0.25x is drawn over 4
    revolutions, not as an open arc), and the drift of the static position over that span (the speed changes
    along a run) is taken out, so the orbit sits at its mean position and closes where the motion is periodic."""
    fig, axes = figure(1, len(nodes), size=(4.6 * len(nodes), 4.6))
    axes = np.atleast_1d(axes)
    t, n = np.asarray(result.t), np.asarray(result.speed_rpm)
    turns = shaft_angle(t, n) / (2 * np.pi)
    lead = np.asarray(result.position(list(nodes)[-1])[0])
    ends = [int(np.argmin(np.abs(n - s))) for s in speeds_rpm]
    spans = [float(revolutions) if revolutions is not None else _period_revolutions(turns, lead, k) for k in ends]
    for ax, (node, label) in zip(axes, nodes.items()):
        x, y = (np.asarray(v) * 1e6 for v in result.position(node))
        for k, span in zip(ends, spans):
            w = (turns >= turns[k] - span) & (turns <= turns[k])
            u = turns[w]
            xs, ys = ((v[w] - np.polyval(np.polyfit(u, v[w], 1), u) + v[w].mean()) if w.sum() > 2 else v[w]
                      for v in (x, y))
            line, = ax.plot(ys, xs, lw=0.8, label=f"{n[k]:.0f} rpm, last {span:g} rev")
            ax.plot(ys[-1:], xs[-1:], "o", ms=3, color=line.get_color())
        ax.set(xlabel="y [um]", ylabel="x (load direction) [um]", title=f"orbit at {label}", aspect="equal")
        ax.invert_yaxis()
        ax.legend(fontsize=7)
    fig.suptitle("orbits along the run (drift of the static position over each span taken out)", fontsize=9)
    return fig
