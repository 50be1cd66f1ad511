"""The dry (elastostatic) contact under a load, shared by the EHL films: Polonsky & Keer's conjugate-gradient
solution of the complementarity ``P >= 0, gap >= 0, P gap = 0`` with the load as constraint (Polonsky & Keer, *Wear*
231, 1999), and the edges of a pressure run between nodes."""

from __future__ import annotations

import numpy as np

from transient.physics.elasticity import SurfaceConvolution


def polonsky_keer(g0: np.ndarray, conv: SurfaceConvolution, cell_area: float, load: float, p0=None,
                  tol: float = 1e-10, max_iter: int = 5000):
    """Polonsky-Keer CG for ``P >= 0, g0 + K P - delta >= 0`` complementary, ``cell_area sum P = load``.

    ``g0`` (ny, nx) rigid gap, ``conv.apply`` the deformation ``K P``. Returns ``(P, delta, iterations,
    converged)``; converged when the relative L1 change of ``P`` falls below ``tol`` with no node in
    contact having a negative pressure and no free node a negative gap (up to round-off)."""
    shape = g0.shape
    if p0 is None:
        near = g0 <= g0.min() + 0.1 * (np.ptp(g0) + 1e-300)
        p = np.where(near, 1.0, 0.0)
    else:
        p = np.array(p0, dtype=float)
    p *= load / (cell_area * p.sum())
    t = np.zeros(shape)
    g_old, delta_cg = 1.0, 0.0
    for it in range(1, max_iter + 1):
        g = conv.apply(p) + g0
        ic = p > 0.0
        g_mean = g[ic].mean()
        g -= g_mean
        G = float(np.sum(g[ic] ** 2))
        t = np.where(ic, g + delta_cg * (G / g_old) * t, 0.0)
        g_old = G
        r = conv.apply(t)
        r -= r[ic].mean()
        rt = float(np.sum(r[ic] * t[ic]))
        tau = float(np.sum(g[ic] * t[ic])) / rt if rt != 0.0 else 0.0
        p_prev = p.copy()
        p = np.where(ic, p - tau * t, p)
        p[p < 0.0] = 0.0
        overlap = (p == 0.0) & (g < 0.0)
        if np.any(overlap):
            delta_cg = 0.0
            p[overlap] -= tau * g[overlap]
        else:
            delta_cg = 1.0
        p *= load / (cell_area * p.sum())
        change = float(np.abs(p - p_prev).sum() * cell_area / load)
        if change < tol:
            return p, float(g_mean), it, True
    return p, float(g_mean), max_iter, False


def edge_positions(s: np.ndarray, q: np.ndarray) -> tuple[float, float] | None:
    """Ends of the positive run of ``q(s)`` containing its maximum, between nodes by linear
    extrapolation of ``q^2``; None if ``q`` has no positive value."""
    if not np.any(q > 0.0):
        return None
    k = int(np.argmax(q))
    lo = k
    while lo > 0 and q[lo - 1] > 0.0:
        lo -= 1
    hi = k
    while hi < q.size - 1 and q[hi + 1] > 0.0:
        hi += 1

    def extend(kk, inner, outer):
        if outer < 0 or outer >= q.size:
            return s[kk]
        d = s[outer] - s[kk]
        a2, b2 = q[kk] ** 2, q[inner] ** 2 if inner != kk else 0.0
        frac = a2 / (b2 - a2) if b2 > a2 else 0.5
        return s[kk] + d * min(frac, 1.0)

    return extend(lo, min(lo + 1, hi), lo - 1), extend(hi, max(hi - 1, lo), hi + 1)
