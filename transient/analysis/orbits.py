"""Journal orbits sampled at a fixed rate per revolution: per-revolution arrays, ellipse shape, spectrum,
growth rate, peak of a response curve. Takes arrays and Results, never models."""

from __future__ import annotations

import numpy as np


def per_revolution(x, y, outputs_per_revolution: int, scale: float = 1.0):
    """Orbit samples x, y (start sample first) reshaped to (revolution, sample) and divided by ``scale``
    (e.g. the clearance), the start sample dropped."""
    opr = int(outputs_per_revolution)
    n = (len(x) - 1) // opr
    X = (np.asarray(x)[1:1 + n * opr] / scale).reshape(n, opr)
    Y = (np.asarray(y)[1:1 + n * opr] / scale).reshape(n, opr)
    return X, Y


def orbit_shape(X, Y) -> dict:
    """Centre, semi-axes (from the covariance of a uniformly sampled ellipse: a = sqrt(2 lambda)) and the
    half peak-to-peak amplitudes of one revolution of samples (same units as X, Y)."""
    X, Y = np.asarray(X, float), np.asarray(Y, float)
    xc, yc = X.mean(), Y.mean()
    lam = np.linalg.eigvalsh(np.cov(np.vstack([X - xc, Y - yc]), bias=True))
    return dict(centre=(float(xc), float(yc)), semi_major=float(np.sqrt(2 * max(lam[1], 0.0))),
                semi_minor=float(np.sqrt(2 * max(lam[0], 0.0))), amp_x=float(0.5 * np.ptp(X)),
                amp_y=float(0.5 * np.ptp(Y)), radius_max=float(np.max(np.hypot(X - xc, Y - yc))))


def ellipse_semi_major(Z) -> float:
    """Semi-major axis of the ellipse (Re(Z_x e^{it}), Re(Z_y e^{it})) of complex amplitudes Z."""
    M = np.array([[Z[0].real, -Z[0].imag], [Z[1].real, -Z[1].imag]])
    return float(np.linalg.svd(M, compute_uv=False)[0])


def revolution_spectrum(signal_per_rev, orders=(0.5, 1, 2, 3, 4)):
    """Peak-amplitude spectrum of a signal sampled uniformly over an integer number of revolutions,
    ``signal_per_rev`` (revolution, sample): (order [multiples of the shaft speed], amplitude, the
    amplitude at each of ``orders`` by name "1x", ..., the order of the largest non-zero peak)."""
    s = np.asarray(signal_per_rev, float)
    xs = s.ravel()
    spec = np.abs(np.fft.rfft(xs - xs.mean())) * 2 / xs.size
    order = np.fft.rfftfreq(xs.size, d=1.0 / s.shape[1])
    harm = {f"{h:g}x": float(spec[int(np.argmin(np.abs(order - h)))]) for h in orders}
    return order, spec, harm, float(order[1 + int(np.argmax(spec[1:]))])


def growth_per_revolution(distance, revolutions, skip_fraction=0.25) -> tuple[float, np.ndarray]:
    """Growth rate per revolution of an oscillation's envelope: the slope of log r at the local maxima of
    r(t) past the first ``skip_fraction`` of the run. Returns (slope, indices of the maxima used)."""
    r, rev = np.asarray(distance, float), np.asarray(revolutions, float)
    pk = np.flatnonzero((r[1:-1] > r[:-2]) & (r[1:-1] >= r[2:])) + 1
    sel = pk[rev[pk] > skip_fraction * rev[-1]]
    if sel.size < 2:
        sel = pk[-2:] if pk.size >= 2 else np.array([0, r.size - 1])
    return float(np.polyfit(rev[sel], np.log(r[sel]), 1)[0]), sel


def peak_abscissa(x, y) -> float:
    """Abscissa of the maximum of y(x), refined by a parabola through it and its neighbours."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    i = int(np.argmax(y))
    if 0 < i < len(y) - 1:
        A = np.vstack([x[i - 1:i + 2] ** 2, x[i - 1:i + 2], np.ones(3)]).T
        a, b, _ = np.linalg.solve(A, y[i - 1:i + 2])
        if a < 0:
            return float(np.clip(-b / (2 * a), x[i - 1], x[i + 1]))
    return float(x[i])
