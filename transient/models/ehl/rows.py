"""The rows kernel of the EHL films of the line contact and the tapered roller: node properties and the
finite-volume Reynolds rows with their local derivatives, on a tensor grid with one row (the line, 1-D) or many
(the roller, 2-D), in the Reynolds-condition form (film content 1) or the film-content form.

Scaled variables (see :mod:`transient.models.roller.ehl_problem`): lengths ``x, y`` in units of the contact
half-width, pressure ``p`` in units of ``p_h``, film ``h`` in units of ``b^2/R``. Per interior node
``I`` with control volume ``A = dx dy`` the residual is the net inflow per unit area::

    F_I = { dy [e_{I+1/2} (p_{I+1} - p_I)/(x_{I+1} - x_I) - e_{I-1/2} (p_I - p_{I-1})/(x_I - x_{I-1})]
          + dx [same along y]
          - lam Rs(y) dy (q_{I+1/2} - q_{I-1/2}) } / A  [ - kappa d(rho h)_I/dt  in the transient ]

    e = rho h^3 / eta (face value: arithmetic mean of the two nodes),  q = m at the face, upwind
    (U > 0): q_{I+1/2} = m_I + (x_{I+1} - x_I)/(2 (x_I - x_{I-1})) (m_I - m_{I-1}),  m = rho theta h
    (theta the film content: 1 in the Reynolds-condition form, an unknown in the mass-conserving one)
    (second-order linear upwind extrapolation, ``scheme = 1``; ``scheme = 0``: first-order q = m_I;
    ``scheme = 2``: the extrapolation's slope limited by van Albada's limiter (van Albada, van Leer &
    Roberts, *Astron. Astrophys.* 108, 1982), ``q_{I+1/2} = m_I + (x_{I+1} - x_I)/2 s(a, b)`` with
    ``b = (m_I - m_{I-1})/(x_I - x_{I-1})`` the upwind and ``a = (m_{I+1} - m_I)/(x_{I+1} - x_I)`` the
    downwind slope, ``s = a b (a + b)/(a^2 + b^2)`` where ``a b > 0``, else 0: second order where ``m``
    is smooth, first order at its extrema -- the outlet constriction, where the unlimited extrapolation
    leaves a coarse grid without a discrete solution of positive film under heavy load).

which is eq. (1) of Park's paper, ``div(rho H^3/eta grad P) = 12 U d(rho H)/dX``, in these units
(``lam = 12 eta0 u_m R^2 / (b^3 p_h)``). Boundary nodes carry ``p = 0``. On one row (``two_d`` false: the line)
``dy = 1``, ``Rs = 1`` and the y fluxes are absent.

The local Jacobian has six slots -- centre, I-1, I+1, J-1, J+1, I-2 -- (``Sp``: derivative with respect to the
node pressures at fixed film; ``Sh``: to the node films; ``St``: to the node contents); the full Jacobian is
``Sp + Sh dh/dp`` with ``dh/dp`` the elastic influence matrix. A film stores the slots its stencil has
(``slot_of``: :data:`ALL_SLOTS` in 2-D, :data:`LINE_SLOTS` on a line, whose rows have no J-1, J+1 slots).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from transient.models.ehl.limiter import van_albada
from transient.physics.lubricant import density_point, viscosity_point

#: slots of the local Jacobian
C, W, E, S, N, WW = 0, 1, 2, 3, 4, 5
N_SLOTS = 6
#: the stored column of each slot: all six (a 2-D film)
ALL_SLOTS = np.arange(N_SLOTS)
#: the stored column of each slot on a line: centre, west, east, west-west (-1: the slot is not stored)
LINE_SLOTS = np.array([0, 1, 2, -1, -1, 3])


@njit(cache=True, error_model="numpy")
def node_properties(p_full, h_full, vcode, alpha, ln_eta0, dcode, c1, c2, p_scale, out):
    """Per full node: rho, drho/dp, eps = rho h^3/eta, deps/dp, deps/dh, m = rho h, dm/dp (scaled p).

    ``out`` has shape (7, n_full). Where ``eta`` overflowed (Roelands with ``Z > 1`` passes ``exp(709)`` near
    2.5 GPa at the Moes chart's largest ``alpha``) ``eps`` underflows to 0 and ``deps/dp`` would be
    ``inf/inf``: a non-finite ``eps``, ``deps/dp`` or ``deps/dh`` takes its limit 0 there."""
    pf, hf = p_full.ravel(), h_full.ravel()
    for k in range(pf.size):
        pp = pf[k] * p_scale
        eta, deta = viscosity_point(vcode, pp, alpha, ln_eta0)
        rho, drho = density_point(dcode, pp, c1, c2)
        deta *= p_scale
        drho *= p_scale
        h = hf[k]
        h3 = h * h * h
        out[0, k] = rho
        out[1, k] = drho
        eps = rho * h3 / eta
        deps_p = h3 * (drho * eta - rho * deta) / (eta * eta)
        deps_h = 3.0 * rho * h * h / eta
        out[2, k] = eps if math.isfinite(eps) else 0.0
        out[3, k] = deps_p if math.isfinite(deps_p) else 0.0
        out[4, k] = deps_h if math.isfinite(deps_h) else 0.0
        out[5, k] = rho * h
        out[6, k] = drho * h


@njit(cache=True, error_model="numpy")
def rows_kernel(p_full, h_full, t_full, x, y, rs, lam, two_d, scheme, vcode, alpha, ln_eta0, dcode, c1, c2, p_scale,
                jac, F, Sp, Sh, St, scale, props, slot_of):
    """Residual ``F`` (interior nodes, flat), the row scales ``scale`` (Poiseuille diagonal plus the Couette
    coefficient ``lam Rs rho h/dx``, per unit area) and, if ``jac``, the local Jacobian ``Sp``, ``Sh``,
    ``St`` (with respect to the pressure, film and film content of the slot's node; slot ``s`` in column
    ``slot_of[s]``, not stored where that is -1). ``t_full``: the film content theta at every full node
    (ones: the Reynolds-condition form, the Couette flux carries ``m = rho h``; else ``m = rho theta h``, the
    mass-conserving form of :mod:`transient.models.roller.line_fbns` and
    :mod:`transient.models.roller.roller_fbns`). ``props`` (7, full nodes): :func:`node_properties`, filled
    here."""
    nyf, nxf = p_full.shape
    node_properties(p_full, h_full, vcode, alpha, ln_eta0, dcode, c1, c2, p_scale, props)
    rho, eps, deps_p, deps_h, rh, dm_p = props[0], props[2], props[3], props[4], props[5], props[6]
    tf = t_full.ravel()
    m = rh * tf
    pf = p_full.ravel()
    nx = nxf - 2
    j0, j1 = (1, nyf - 1) if two_d else (0, 1)
    dE = np.zeros(N_SLOTS)
    dM = np.zeros(N_SLOTS)
    dP = np.zeros(N_SLOTS)
    nb = np.zeros(N_SLOTS, np.int64)
    for J in range(j0, j1):
        if two_d:
            dy = 0.5 * (y[J + 1] - y[J - 1])
        else:
            dy = 1.0
        coef = lam * rs[J] * dy
        for I in range(1, nxf - 1):
            r = (J - j0) * nx + (I - 1)
            c = J * nxf + I
            w = c - 1
            e = c + 1
            dxR = x[I + 1] - x[I]
            dxL = x[I] - x[I - 1]
            dx = 0.5 * (dxR + dxL)
            A = dx * dy
            eR = 0.5 * (eps[c] + eps[e])
            eL = 0.5 * (eps[w] + eps[c])
            gR = (pf[e] - pf[c]) / dxR
            gL = (pf[c] - pf[w]) / dxL
            fx = dy * (eR * gR - eL * gL)
            order2 = scheme == 1
            fR = 0.5 * dxR / dxL if order2 else 0.0
            fL = 0.0
            qL = m[w]
            if scheme == 2:
                sR, sRa, sRb = van_albada((m[e] - m[c]) / dxR, (m[c] - m[w]) / dxL)
                qR = m[c] + 0.5 * dxR * sR
                sL, sLa, sLb, dxLL = 0.0, 0.0, 0.0, 1.0
                if I >= 2:
                    dxLL = x[I - 1] - x[I - 2]
                    sL, sLa, sLb = van_albada((m[c] - m[w]) / dxL, (m[w] - m[c - 2]) / dxLL)
                    qL = m[w] + 0.5 * dxL * sL
            else:
                if I >= 2:
                    if order2:
                        fL = 0.5 * dxL / (x[I - 1] - x[I - 2])
                    qL = m[w] + fL * (m[w] - m[c - 2])
                qR = m[c] + fR * (m[c] - m[w])
            fc = -coef * (qR - qL)
            fy = 0.0
            if two_d:
                s_ = c - nxf
                n_ = c + nxf
                dyN = y[J + 1] - y[J]
                dyS = y[J] - y[J - 1]
                eN = 0.5 * (eps[c] + eps[n_])
                eS = 0.5 * (eps[s_] + eps[c])
                gN = (pf[n_] - pf[c]) / dyN
                gS = (pf[c] - pf[s_]) / dyS
                fy = dx * (eN * gN - eS * gS)
            F[r] = (fx + fy + fc) / A
            scale[r] = (dy * (eR / dxR + eL / dxL) + coef * rh[c]) / A
            if two_d:
                scale[r] += dx * (eN / dyN + eS / dyS) / A
            if not jac:
                continue
            for s in range(N_SLOTS):
                dE[s] = 0.0
                dM[s] = 0.0
                dP[s] = 0.0
                nb[s] = -1
            nb[C], nb[W], nb[E] = c, w, e
            dE[E] += 0.5 * dy * gR
            dE[C] += 0.5 * dy * (gR - gL)
            dE[W] -= 0.5 * dy * gL
            dP[E] += dy * eR / dxR
            dP[C] -= dy * (eR / dxR + eL / dxL)
            dP[W] += dy * eL / dxL
            if scheme == 2:
                # q_R(m_W, m_C, m_E) and q_L(m_WW, m_W, m_C) through the limited slopes
                dM[E] -= coef * 0.5 * sRa
                dM[C] -= coef * (1.0 - 0.5 * sRa + 0.5 * dxR / dxL * sRb - 0.5 * sLa)
                dM[W] -= coef * (-0.5 * dxR / dxL * sRb - 1.0 + 0.5 * sLa - 0.5 * dxL / dxLL * sLb)
                if I >= 2:
                    nb[WW] = c - 2
                    dM[WW] -= coef * 0.5 * dxL / dxLL * sLb
            else:
                dM[C] -= coef * (1.0 + fR)
                dM[W] += coef * (1.0 + fR + fL)
                if I >= 2:
                    nb[WW] = c - 2
                    dM[WW] -= coef * fL
            if two_d:
                nb[S], nb[N] = c - nxf, c + nxf
                dE[N] += 0.5 * dx * gN
                dE[C] += 0.5 * dx * (gN - gS)
                dE[S] -= 0.5 * dx * gS
                dP[N] += dx * eN / dyN
                dP[C] -= dx * (eN / dyN + eS / dyS)
                dP[S] += dx * eS / dyS
            for s in range(N_SLOTS):
                o = slot_of[s]
                if o < 0:
                    continue
                k = nb[s]
                if k < 0:
                    Sp[r, o] = 0.0
                    Sh[r, o] = 0.0
                    St[r, o] = 0.0
                    continue
                Sh[r, o] = (dE[s] * deps_h[k] + dM[s] * rho[k] * tf[k]) / A
                Sp[r, o] = (dP[s] + dE[s] * deps_p[k] + dM[s] * dm_p[k] * tf[k]) / A
                St[r, o] = dM[s] * rh[k] / A
