"""numba kernel of the mass-conserving point-contact film: Reynolds residual with the film content and its
local (five-point) derivatives.

Half grid ``(m, nx)`` (row 0 on the symmetry line ``Y = 0``, row ``m - 1`` and columns ``0``, ``nx - 1``
on the outer boundary, where ``P = 0``), scaled units of :mod:`transient.models.point.ehl_problem`. At every
interior node, per unit area (first-order upwind Couette flux, the flow entering at ``X = X_in``)::

    R = [eps_e (P_E - P) - eps_w (P - P_W)]/dx^2 + [eps_n (P_N - P) - eps_s (P - P_S)]/dy^2
        - (q - q_W)/dx,        eps = rho H^3 / (eta lam),  q = rho theta H,  faces: arithmetic means

with the mirror ``P_S = P_N``, ``eps_s = eps_n`` on the symmetry row and, at the first interior column,
``q_W = min(H_oil, H_W)`` (the oil layer carried in; ``H_oil = inf`` for a flooded inlet).

Outputs, per unknown ``r`` (interior nodes, x fastest): ``res[r]``, the row scale ``scale[r]`` (the
Couette coefficient ``rho H/dx``, the row's derivative with respect to the content: the residual over it is the
control volume's mass error relative to the flux through it; a Poiseuille diagonal in it would hide the mass
balance of a starved inlet, where it is ~10^5 times larger), ``dp[r, 5]`` and ``dh[r, 5]`` (derivatives with respect to P and H
at the centre, west, east, south, north node; on the symmetry row the north slot carries both mirror
terms) and ``dt[r, 2]`` (with respect to theta at the centre and west node).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.physics.lubricant import density_point, viscosity_point


@njit(cache=True, error_model="numpy")
def node_properties(P, H, lam, p_h, lub):
    """``(rho, drho/dP, eps, deps/dP, deps/dH)`` at every node of the half grid (arrays shaped like P);
    ``lub`` = (viscosity code, alpha, ln eta0, density code, c1, c2) in SI."""
    vlaw, alpha, ln_eta0, dlaw, c1, c2 = lub
    m, nx = P.shape
    rho = np.empty((m, nx))
    drho = np.empty((m, nx))
    eps = np.empty((m, nx))
    deps = np.empty((m, nx))
    depsh = np.empty((m, nx))
    for j in range(m):
        for i in range(nx):
            p = P[j, i] * p_h
            e, de = viscosity_point(int(vlaw), p, alpha, ln_eta0)
            r, dr = density_point(int(dlaw), p, c1, c2)
            h = H[j, i]
            ep = r * h * h * h / (e * lam)
            rho[j, i] = r
            drho[j, i] = dr * p_h
            eps[j, i] = ep
            deps[j, i] = ep * (dr / r - de / e) * p_h
            depsh[j, i] = 3.0 * ep / h if h > 0.0 else 0.0
    return rho, drho, eps, deps, depsh


@njit(cache=True, error_model="numpy")
def reynolds(P, T, H, rho, drho, eps, deps, depsh, dx, dy, h_oil, res, scale, dp, dh, dt):
    """Fill ``res``, ``scale``, ``dp``, ``dh``, ``dt`` (module docstring) for the half-grid fields
    ``P`` (pressure), ``T`` (film content theta), ``H`` (film) and the node properties."""
    m, nx = P.shape
    ax = 1.0 / (dx * dx)
    ay = 1.0 / (dy * dy)
    r = 0
    for j in range(m - 1):
        for i in range(1, nx - 1):
            jn = j + 1
            js = j + 1 if j == 0 else j - 1
            p, pw, pe, pn, ps = P[j, i], P[j, i - 1], P[j, i + 1], P[jn, i], P[js, i]
            ec = eps[j, i]
            ee = 0.5 * (ec + eps[j, i + 1])
            ew = 0.5 * (ec + eps[j, i - 1])
            en = 0.5 * (ec + eps[jn, i])
            es = 0.5 * (ec + eps[js, i])
            gx = (pe - p) - (p - pw)
            pois = ax * (ee * (pe - p) - ew * (p - pw)) + ay * (en * (pn - p) - es * (p - ps))
            q = rho[j, i] * T[j, i] * H[j, i]
            if i == 1:
                hw = H[j, 0]
                if h_oil < hw:
                    qw, dqw_h = h_oil, 0.0
                else:
                    qw, dqw_h = hw, 1.0
            else:
                qw = rho[j, i - 1] * T[j, i - 1] * H[j, i - 1]
                dqw_h = rho[j, i - 1] * T[j, i - 1]
            res[r] = pois - (q - qw) / dx
            scale[r] = rho[j, i] * H[j, i] / dx
            # d/d(eps at the centre): half of every face
            dface = 0.5 * (ax * gx + ay * ((pn - p) - (p - ps)))
            dp[r, 0] = -ax * (ee + ew) - ay * (en + es) + deps[j, i] * dface - drho[j, i] * T[j, i] * H[j, i] / dx
            dh[r, 0] = depsh[j, i] * dface - rho[j, i] * T[j, i] / dx
            # west
            if i == 1:
                dp[r, 1] = ax * ew - 0.5 * ax * deps[j, i - 1] * (p - pw)
                dh[r, 1] = -0.5 * ax * depsh[j, i - 1] * (p - pw) + dqw_h / dx
            else:
                dp[r, 1] = ax * ew - 0.5 * ax * deps[j, i - 1] * (p - pw) + drho[j, i - 1] * T[j, i - 1] * H[j, i - 1] / dx
                dh[r, 1] = -0.5 * ax * depsh[j, i - 1] * (p - pw) + dqw_h / dx
            # east
            dp[r, 2] = ax * ee + 0.5 * ax * deps[j, i + 1] * (pe - p)
            dh[r, 2] = 0.5 * ax * depsh[j, i + 1] * (pe - p)
            # north (and its mirror on the symmetry row)
            dp[r, 4] = ay * en + 0.5 * ay * deps[jn, i] * (pn - p)
            dh[r, 4] = 0.5 * ay * depsh[jn, i] * (pn - p)
            if j == 0:
                dp[r, 4] += ay * es - 0.5 * ay * deps[js, i] * (p - ps)
                dh[r, 4] += -0.5 * ay * depsh[js, i] * (p - ps)
                dp[r, 3] = 0.0
                dh[r, 3] = 0.0
            else:
                dp[r, 3] = ay * es - 0.5 * ay * deps[js, i] * (p - ps)
                dh[r, 3] = -0.5 * ay * depsh[js, i] * (p - ps)
            dt[r, 0] = -rho[j, i] * H[j, i] / dx
            dt[r, 1] = rho[j, i - 1] * H[j, i - 1] / dx if i > 1 else 0.0
            r += 1
