"""Statistics and spectra of periodic signals sampled uniformly over an integer number of periods.

With ``N = n_periods * samples_per_period`` uniform samples covering exactly ``n_periods`` periods
(the end point excluded), the rectangle rule is exact for every harmonic below the Nyquist
frequency, so

* :func:`mean_and_fluctuation` gives eqs. (11)-(12) (p_m, p_f) exactly for band-limited signals;
* :func:`harmonic_amplitudes` reads harmonic k of the period from FFT bin ``k * n_periods`` (no
  leakage): peak amplitude ``2 |X| / N`` (RMS = peak / sqrt 2). Parseval: ``p_f^2 = sum_k rms_k^2``
  over the harmonics up to Nyquist.
"""

from __future__ import annotations

import numpy as np


def mean_and_fluctuation(signal, axis=0):
    """Time mean p_m and RMS fluctuation p_f = sqrt(mean((p - p_m)^2)) along ``axis`` (eqs. 11, 12).

    The samples must cover an integer number of periods, end point excluded."""
    s = np.asarray(signal, dtype=float)
    m = s.mean(axis=axis)
    f = np.sqrt(np.mean((s - np.expand_dims(m, axis)) ** 2, axis=axis))
    return m, f


def harmonic_amplitudes(signal, n_periods, harmonics, axis=0, kind="peak"):
    """Amplitudes of harmonics 1..``harmonics`` of the period, shape (harmonics, ...rest).

    ``kind``: ``"peak"`` (amplitude a of a cos(k w t + phi)) or ``"rms"`` (a / sqrt 2); ``"complex"``
    gives the complex peak amplitude (a e^{i phi}). Requires harmonic < Nyquist."""
    s = np.moveaxis(np.asarray(signal, dtype=float), axis, 0)
    N = s.shape[0]
    n_periods = int(n_periods)
    if N % n_periods:
        raise ValueError(f"{N} samples do not cover {n_periods} periods with an integer number of samples each")
    spp = N // n_periods
    if harmonics >= spp / 2:
        raise ValueError(f"harmonic {harmonics} needs more than {2 * harmonics} samples per period, got {spp}")
    X = np.fft.rfft(s, axis=0)
    bins = n_periods * np.arange(1, harmonics + 1)
    c = 2.0 * X[bins] / N
    if kind == "complex":
        return c
    a = np.abs(c)
    if kind == "rms":
        return a / np.sqrt(2.0)
    if kind == "peak":
        return a
    raise ValueError(f"kind must be 'peak', 'rms' or 'complex', got {kind!r}")


def amplitude_spectrum(signal, dt, axis=0):
    """Single-sided peak-amplitude spectrum: (frequency [Hz], amplitude) of a uniformly sampled
    signal (mean at f = 0 as |mean|; a component a cos(2 pi f t) on a bin shows as a)."""
    s = np.moveaxis(np.asarray(signal, dtype=float), axis, 0)
    N = s.shape[0]
    X = np.fft.rfft(s, axis=0)
    a = 2.0 * np.abs(X) / N
    a[0] *= 0.5
    if N % 2 == 0:
        a[-1] *= 0.5
    return np.fft.rfftfreq(N, dt), a
