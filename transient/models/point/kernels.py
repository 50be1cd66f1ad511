"""numba kernel of the mass-conserving point-contact film: Reynolds residual with the film content and its
local derivatives.

Half grid ``(m, nx)`` (row 0 on the symmetry line ``Y = 0``, row ``m - 1`` and columns ``0``, ``nx - 1``
on the outer boundary, where ``P = 0``), scaled units of :mod:`transient.models.point.ehl_problem`. At every
interior node, per unit area (the flow entering at ``X = X_in``), in flux form::

    R = [eps_e (P_E - P) - eps_w (P - P_W)]/dx^2 + [eps_n (P_N - P) - eps_s (P - P_S)]/dy^2
        - (F_e - F_w)/dx,        eps = rho H^3 / (eta lam),  faces: arithmetic means

with the mirror ``P_S = P_N``, ``eps_s = eps_n`` on the symmetry row. ``F`` is the upwind Couette flux of the
content ``q = rho theta H`` through a face (:func:`face_flux`, the same value for the two control volumes it
separates, so mass is conserved exactly): first order ``F_{i+1/2} = q_i``; second-order linear upwind
``F_{i+1/2} = q_i + (q_i - q_{i-1})/2``; or that slope limited by van Albada's limiter (van Albada, van Leer &
Roberts, *Astron. Astrophys.* 108, 1982), ``F = q_i + dx/2 s(a, b)``, ``b`` the upwind and ``a`` the downwind
slope, ``s = a b (a + b)/(a^2 + b^2)`` where ``a b > 0``, else 0 (the roller's option,
:mod:`transient.models.ehl.rows`). The inlet face carries ``min(H_oil, H_W)`` (the oil layer carried in;
``H_oil = inf`` for a flooded inlet), the face between the first two interior columns is first order, the
outlet face linear.

Outputs, per unknown ``r`` (interior nodes, x fastest): ``res[r]``, the row scale ``scale[r]`` (the first-order
Couette coefficient ``rho H/dx``: the residual over it is the control volume's mass error relative to the flux
through it; a Poiseuille diagonal in it would hide the mass balance of a starved inlet, where it is ~10^5 times
larger), ``dp[r, 6]``, ``dh[r, 6]`` and ``dt[r, 6]`` (derivatives with respect to P, H and theta at the centre,
west, east, south, north and west-west node; on the symmetry row the north slot carries both mirror terms, the
south slot is zero; ``dt`` has no south and north terms).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.models.ehl.limiter import van_albada
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
def face_flux(scheme, qm, qc, qp, dx):
    """Couette flux ``F`` at the face downstream of the node with content ``qc`` (upstream ``qm``, downstream
    ``qp``) and ``(dF/dqm, dF/dqc, dF/dqp)``: ``scheme`` 0 first order ``F = qc``; 1 linear upwind
    ``F = qc + (qc - qm)/2``; 2 the slope limited by van Albada's limiter (module docstring; the roller's
    :func:`~transient.models.ehl.limiter.van_albada`)."""
    if scheme == 0:
        return qc, 0.0, 1.0, 0.0
    if scheme == 1:
        return 1.5 * qc - 0.5 * qm, -0.5, 1.5, 0.0
    s, sa, sb = van_albada((qp - qc) / dx, (qc - qm) / dx)
    return qc + 0.5 * dx * s, -0.5 * sb, 1.0 + 0.5 * (sb - sa), 0.5 * sa


@njit(cache=True, error_model="numpy")
def row_faces(q, i, nx, scheme, dx):
    """Fluxes through the west and east faces of interior column ``i`` and their derivatives with respect to
    the contents at the columns ``i - 2 .. i + 1`` (``dw[4]``, ``de[4]``; index 0 is ``i - 2``). Column 0's
    content ``q[0]`` is the inlet layer (first-order flux into column 1); the face between columns 1 and 2 is
    first order (no second upstream node), the outlet face ``nx - 3/2`` the linear extrapolation (no
    downstream node inside)."""
    dw = np.zeros(4)
    de = np.zeros(4)
    # west face (i - 1/2): downstream of column i - 1
    if i == 1 or i == 2:
        fw = q[i - 1]
        dw[1] = 1.0
    else:
        k = scheme if i - 1 < nx - 2 else min(scheme, 1)
        fw, a, b, c = face_flux(k, q[i - 2], q[i - 1], q[i], dx)
        dw[0], dw[1], dw[2] = a, b, c
    # east face (i + 1/2): downstream of column i
    if i == 1:
        fe = q[i]
        de[2] = 1.0
    else:
        k = scheme if i < nx - 2 else min(scheme, 1)
        fe, a, b, c = face_flux(k, q[i - 1], q[i], q[i + 1], dx)
        de[1], de[2], de[3] = a, b, c
    return fw, fe, dw, de


@njit(cache=True, error_model="numpy")
def reynolds(P, T, H, rho, drho, eps, deps, depsh, dx, dy, h_oil, scheme, res, scale, dp, dh, dt):
    """Fill ``res``, ``scale``, ``dp``, ``dh``, ``dt`` (module docstring) for the half-grid fields
    ``P`` (pressure), ``T`` (film content theta), ``H`` (film) and the node properties; ``scheme`` the
    Couette flux (:func:`face_flux`)."""
    m, nx = P.shape
    ax = 1.0 / (dx * dx)
    ay = 1.0 / (dy * dy)
    q = np.empty(nx)
    slot = (5, 1, 0, 2)  # columns i - 2, i - 1, i, i + 1
    r = 0
    for j in range(m - 1):
        for i in range(nx):
            q[i] = rho[j, i] * T[j, i] * H[j, i]
        hw = H[j, 0]
        if h_oil < hw:
            q[0], dq0_h = h_oil, 0.0
        else:
            q[0], dq0_h = hw, 1.0
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
            fw, fe, dw, de = row_faces(q, i, nx, scheme, dx)
            res[r] = pois - (fe - fw) / dx
            scale[r] = rho[j, i] * H[j, i] / dx
            # Poiseuille part; d/d(eps at the centre): half of every face
            dface = 0.5 * (ax * gx + ay * ((pn - p) - (p - ps)))
            dp[r, 0] = -ax * (ee + ew) - ay * (en + es) + deps[j, i] * dface
            dh[r, 0] = depsh[j, i] * dface
            dp[r, 1] = ax * ew - 0.5 * ax * deps[j, i - 1] * (p - pw)
            dh[r, 1] = -0.5 * ax * depsh[j, i - 1] * (p - pw)
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
            dp[r, 5] = 0.0
            dh[r, 5] = 0.0
            for s in range(6):
                dt[r, s] = 0.0
            # Couette part, -(F_e - F_w)/dx, through the contents q = rho theta H of columns i - 2 .. i + 1
            for o in range(4):
                c = i - 2 + o
                g = (dw[o] - de[o]) / dx
                if g == 0.0:
                    continue
                sl = slot[o]
                if c == 0:
                    dh[r, sl] += g * dq0_h
                else:
                    dp[r, sl] += g * drho[j, c] * T[j, c] * H[j, c]
                    dh[r, sl] += g * rho[j, c] * T[j, c]
                    dt[r, sl] += g * rho[j, c] * H[j, c]
            r += 1
