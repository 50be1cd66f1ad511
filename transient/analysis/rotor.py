"""Response of a rotor over a run-up or coast-down, from the series of a run (arrays, no model): the synchronous
(1x) amplitude per window by least squares on the shaft angle, and the waterfall (cascade) of amplitude spectra
against the speed."""

from __future__ import annotations

import numpy as np


def shaft_angle(t, speed_rpm) -> np.ndarray:
    """The shaft angle [rad] at the times ``t`` [s] (trapezoidal integral of the speed, 0 at ``t[0]``)."""
    w = np.asarray(speed_rpm, dtype=float) * np.pi / 30.0
    return np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])


def windows(t, speed_rpm, window_revolutions) -> list[slice]:
    """Consecutive windows of about ``window_revolutions`` revolutions each over the run."""
    turns = shaft_angle(t, speed_rpm) / (2 * np.pi)
    edges = np.searchsorted(turns, np.arange(0.0, turns[-1] + 1e-9, window_revolutions))
    return [slice(a, b) for a, b in zip(edges[:-1], edges[1:]) if b - a >= 8]


def synchronous_amplitude(t, x, speed_rpm, window_revolutions=2.0):
    """Per window: the mean speed [rpm] and the 1x amplitude of ``x`` (its unit): the least-squares fit
    ``x = a cos(phi) + b sin(phi) + c`` on the shaft angle phi, amplitude ``hypot(a, b)``."""
    t, x, n = (np.asarray(v, dtype=float) for v in (t, x, speed_rpm))
    phi = shaft_angle(t, n)
    speeds, amps = [], []
    for w in windows(t, n, window_revolutions):
        A = np.column_stack([np.cos(phi[w]), np.sin(phi[w]), np.ones(w.stop - w.start)])
        (a, b, _), *_ = np.linalg.lstsq(A, x[w], rcond=None)
        speeds.append(n[w].mean())
        amps.append(np.hypot(a, b))
    return np.array(speeds), np.array(amps)


def waterfall(t, x, speed_rpm, window_revolutions=4.0):
    """The cascade of a run: per window its mean speed [rpm], and the one-sided amplitude spectrum of ``x``
    (mean removed, Hann window, amplitude-corrected) on common frequencies [Hz] (the shortest window's):
    ``(speeds (k,), frequencies (m,), amplitudes (k, m))``."""
    t, x, n = (np.asarray(v, dtype=float) for v in (t, x, speed_rpm))
    ws = windows(t, n, window_revolutions)
    if not ws:
        raise ValueError("the run is shorter than one window; lower window_revolutions")
    dt = float(np.median(np.diff(t)))
    m = min(w.stop - w.start for w in ws)
    freqs = np.fft.rfftfreq(m, dt)
    hann = np.hanning(m)
    spectra = []
    for w in ws:
        seg = x[w][:m] - x[w][:m].mean()
        spectra.append(2.0 * np.abs(np.fft.rfft(seg * hann)) / hann.sum())
    return np.array([n[w].mean() for w in ws]), freqs, np.array(spectra)
