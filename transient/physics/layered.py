"""Layered boundary films with a shear-thinning (Gecim) bulk: the pointwise flow law (Jang).

Jang's model (Jang, eqs. 1-18): across the film ``0 <= z <= h`` two porous, solid-like layers of
thickness ``delta`` sit on the walls (layer a on the lower wall moving at ``U1``, layer b on the upper wall
moving at ``U2``); in them the flow obeys Darcy's law relative to the wall (eqs. 4, 5)::

    u_a = U1 - alpha^2 G / mu_a,    u_b = U2 - alpha^2 G / mu_b,    G = dp/ds

(``alpha`` [m] is the square root of the permeability; the paper calls it "porosity"). Between them the
bulk, ``delta <= z <= h - delta``, of thickness ``H = h - 2 delta``, is a Gecim fluid (eq. 6)::

    mu_c = mu_1 (kappa + mu_2 gdot) / (kappa + mu_1 gdot)
         <=>  tau = mu_2 gdot + (mu_1 - mu_2) gdot kappa / (kappa + mu_1 gdot)      (gdot >= 0)

Momentum (eq. 7) makes the bulk shear stress linear: ``tau(zeta) = tau_0 + G zeta``, ``zeta = z - delta``.
The law inverts in closed form (a quadratic; ``s = tau/kappa``, ``x = mu_1 gdot/kappa``,
``r = mu_2/mu_1``)::

    r x^2 + (1 - s) x - s = 0,    x = [(s - 1) + sqrt((s - 1)^2 + 4 r s)] / (2 r)
                                    = 2 s / [(1 - s) + sqrt(...)]        (the form used for s < 1)

odd in ``s``; ``dx/ds = 1 / (r + (1 - r)/(1 + |x|)^2)`` lies in ``[1, 1/r]``. Velocity continuity at
``z = delta`` and ``z = h - delta`` (eq. 13) fixes ``tau_0``::

    int_0^H gdot(tau_0 + G zeta) dzeta = u_b - u_a = (U2 - U1) - (alpha^2/mu_b - alpha^2/mu_a) G

and the flow per unit width (eq. 18, layers + bulk) splits exactly into::

    q = h (U1 + U2)/2  +  q_p,
    q_p = -(h/2) alpha^2 (1/mu_a + 1/mu_b) G  +  int_0^H (H/2 - zeta) gdot(zeta) dzeta

At ``G = 0`` the stress is uniform, the bulk profile linear and the layers move with their walls, so the
flow is ``h (U1 + U2)/2`` whatever the rheology and the layers: that is the Couette part, and ``q_p``
(zero at ``G = 0``) the pressure part. For a Newtonian bulk ``q_p = -k G`` with
``k = (h - 2 delta)^3 / (12 mu) + (h/2) alpha^2 (1/mu_a + 1/mu_b)`` (``newtonian_flow``).

**Cavitation (Elrod).** In the cavitated zone ``G = 0``: only the Couette part acts, carried by the
content, ``theta h (U1 + U2)/2`` upwinded on ``theta``, exactly as for a classical film. The layers
change nothing there: if they stay saturated (content ``2 delta``) they carry ``delta (U1 + U2)``, which
is again ``(U1 + U2)/2`` times their content, so the flux per unit content is ``(U1 + U2)/2`` however the
content is shared between layers and bulk striations. ``q_p`` is switched off there by ``G = 0`` itself.

**Gap thinner than the layers** (``h < 2 delta``, outside the paper): the two layers share the gap, ``h/2``
each, the bulk is empty and ``q_p = -(h/2) alpha^2 (1/mu_a + 1/mu_b) G`` (continuous, with a continuous
``dq_p/dh``, at ``h = 2 delta``). With ``alpha = 0`` no pressure flow is left.

**Scaling inside the kernels.** A reference length ``L`` (e.g. the clearance ``c``) and speed ``V``
(e.g. ``omega R``): lengths ``/ L``, speeds ``/ V``, viscosities ``/ mu_1``, ``G / (mu_1 V / L^2)``,
stresses and ``kappa / (mu_1 V / L)``, ``q / (V L)``, ``dq/dG / (L^3 / mu_1)``, ``dq/dh / V``. The layers
enter as ``delta / L`` and the Darcy mobilities ``lam_a = alpha^2 mu_1 / (mu_a L^2)``,
``lam_b = alpha^2 mu_1 / (mu_b L^2)``. :class:`LayeredFilm` (SI in and out) picks ``L = max h``,
``V = max(|U1|, |U2|, |G| L^2 / mu_1)`` (1 m/s if all vanish) unless given ``scales = (L, V)``.

**Quadrature.** The bulk integrals are Gauss-Legendre sums (``n`` points per panel) over panels whose
ends are where the stress crosses 0 (the law's curvature jumps there: it depends on ``|gdot|``) and
``+-kappa 2^k`` (the inverse law has complex branch points on ``|tau| = kappa``): each panel is then at
least its own half-length away from a singularity and the sums converge geometrically in ``n``
(docs/layered.md).
``tau_0`` is found by Newton's method from the Newtonian (``mu_1``) solution, to rounding (the slope
lies in ``[H, H/r]``; sweeps over the parameters converge everywhere; NaN after 50 iterations);
``dq_p/dG`` and ``dq_p/dh`` are exact (implicit differentiation of the continuity condition).

**Two directions.** For a Gecim bulk the x and y flows are coupled through ``|gdot|`` (eq. 12). The
same derivation with 2-vectors ``G``, ``tau_0``, ``U1``, ``U2`` and ``gdot = phi(|tau|) tau`` (``phi`` the
secant fluidity) gives :func:`gecim_face_2d` (``dq_p/dG`` a 2 x 2 matrix: a small gradient along the
sliding sees the tangent viscosity, one across it the secant viscosity). Along ``zeta`` the stress
``|tau|`` is least at ``zeta*``; the panels end there and where ``|tau| = kappa 2^k``, and grow
geometrically from ``zeta*``, no longer than ``max(|zeta - zeta*|, d0)``, ``d0 = |tau|_min/|G|``
(``|tau|`` has branch points at ``zeta* +- i d0``). The 1-D kernels are its special case (transverse
gradient and speeds zero) and about 4 times cheaper.

Departures from the printed paper (details in docs/layered.md): eq. (19) is replaced by the flow above
(the printed one drops the Darcy flow inside the layers, has ``h^3`` for ``h`` in x-direction alpha terms,
a sign error in a y term and an unnormalised ``f50``); eq. (27)'s ``f2`` is ``int dz / mu``, not a copy of
``f1``; the friction is the wall traction ``tau(0) = tau_0 - G delta``, ``tau(h) = tau_0 + G (H + delta)``
(the stress is linear across the whole film), not the interface stress of eq. (28). The paper's
``f1 .. f5`` (secant-viscosity integrals) are equivalent to the moments of ``gdot`` used here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from transient.checks import check_positive, check_range

RATIO_MIN = 0.05  # smallest mu_2/mu_1 for which the stated quadrature accuracy is measured
GAUSS_POINTS = 12
NEWTON_TOL = 1e-7  # stop of the 2-D continuity Newton, relative to the stress scale (_solve_tau0_2d)


# --------------------------------------------------------------------------------------------------
# numba kernels (dimensionless, see the module docstring)
# --------------------------------------------------------------------------------------------------

@njit(cache=True)
def gecim_rate(s, r):
    """``x = mu_1 gdot / kappa`` and ``dx/ds`` for the stress ``s = tau / kappa`` (signed), ``r = mu_2/mu_1``."""
    m = abs(s)
    b = m - 1.0
    d = math.sqrt(b * b + 4.0 * r * m)
    x = (b + d) / (2.0 * r) if b >= 0.0 else 2.0 * m / (d - b)
    dx = 1.0 / (r + (1.0 - r) / ((1.0 + x) * (1.0 + x)))
    return math.copysign(x, s), dx


@njit(cache=True)
def _next_break(t):
    """Smallest element ``> t`` of ``{0} U {+-2^k, k >= 0}`` (panel ends, stress in units of kappa)."""
    if t >= 1.0:
        return math.ldexp(1.0, math.frexp(t)[1])
    if t >= 0.0:
        return 1.0
    if t >= -1.0:
        return 0.0
    m, e = math.frexp(-t)
    return -math.ldexp(1.0, e - 2 if m == 0.5 else e - 1)


@njit(cache=True)
def _moments(tau0, G, zb, H, kappa, r, xg, wg):
    """Integrals over ``0 <= zeta <= zb`` of gdot, gdot', zeta gdot', (H/2 - zeta) {gdot, gdot', zeta gdot'}
    (``gdot' = d gdot / d tau``), by Gauss-Legendre on the stress panels."""
    s0 = s1 = s2 = s3 = s4 = s5 = 0.0
    sig = 1.0 if G >= 0.0 else -1.0
    t = sig * tau0 / kappa
    t_end = sig * (tau0 + G * zb) / kappa
    one_panel = G == 0.0 or not math.isfinite(t_end - t)  # (NaN/inf input: one panel, no endless walk)
    a = 0.0
    while a < zb:
        tn = _next_break(t)
        b = zb if (one_panel or tn >= t_end) else min(max((sig * tn * kappa - tau0) / G, a), zb)
        half = 0.5 * (b - a)
        mid = 0.5 * (a + b)
        for j in range(xg.size):
            z = mid + half * xg[j]
            w = half * wg[j]
            x, dx = gecim_rate((tau0 + G * z) / kappa, r)
            g = kappa * x
            c = 0.5 * H - z
            s0 += w * g
            s1 += w * dx
            s2 += w * z * dx
            s3 += w * c * g
            s4 += w * c * dx
            s5 += w * c * z * dx
        a = b
        t = tn
    return s0, s1, s2, s3, s4, s5


@njit(cache=True)
def _converged(step, last, scale):
    """Newton stop: the step is at 1e-14 of the stress scale, or it has stopped shrinking below 1e-10 of it
    (the rounding floor of the sums, which grows with the number of panels and with 1/r)."""
    return step <= 1e-14 * scale or (step <= 1e-10 * scale and step >= 0.5 * last)


@njit(cache=True)
def _solve_tau0(du, G, H, kappa, r, xg, wg):
    """Bulk stress at ``zeta = 0`` such that ``int_0^H gdot = du``: Newton from the Newtonian (``mu_1``)
    solution to rounding; NaN if 50 iterations do not converge (never seen: tests sweep the parameters)."""
    scale = abs(du) / H + abs(G) * H
    t = du / H - 0.5 * G * H
    last = math.inf
    for _ in range(50):
        m = _moments(t, G, H, H, kappa, r, xg, wg)
        step = (m[0] - du) / m[1]
        t -= step
        if _converged(abs(step), last, scale):
            return t
        last = abs(step)
    return math.nan


@njit(cache=True)
def gecim_face(h, G, U1, U2, delta, lam_a, lam_b, kappa, ratio, xg, wg):
    """One face: ``(q_p, dq_p/dG, dq_p/dh, tau_0)`` (``tau_0`` = bulk stress at ``z = delta``; NaN if
    ``h <= 2 delta``). Dimensionless; ``xg, wg`` Gauss-Legendre nodes and weights on [-1, 1]."""
    A = lam_a + lam_b
    H = h - 2.0 * delta
    if H <= 0.0:
        return -0.5 * h * A * G, -0.5 * h * A, -0.5 * A * G, math.nan
    du = (U2 - U1) - (lam_b - lam_a) * G
    tau0 = _solve_tau0(du, G, H, kappa, ratio, xg, wg)
    _, Ft, Fz, K, Kt, KG = _moments(tau0, G, H, H, kappa, ratio, xg, wg)
    g1 = kappa * gecim_rate((tau0 + G * H) / kappa, ratio)[0]
    dt_dG = -(Fz + lam_b - lam_a) / Ft
    dt_dH = -g1 / Ft
    qp = -0.5 * h * A * G + K
    dG = -0.5 * h * A + KG + Kt * dt_dG
    dh = -0.5 * A * G - 0.5 * H * g1 + 0.5 * du + Kt * dt_dH
    return qp, dG, dh, tau0


@njit(cache=True)
def gecim_flow(h, G, U1, U2, delta, lam_a, lam_b, kappa, ratio, xg, wg, qp, dqp_dG, dqp_dh, tau0):
    """:func:`gecim_face` over arrays of faces (``h, G, U1, U2`` in, ``qp, dqp_dG, dqp_dh, tau0`` out)."""
    for i in range(h.size):
        qp[i], dqp_dG[i], dqp_dh[i], tau0[i] = gecim_face(h[i], G[i], U1[i], U2[i], delta, lam_a, lam_b,
                                                          kappa, ratio, xg, wg)


@njit(cache=True)
def newtonian_flow(h, G, delta, lam_sum, qp, dqp_dG, dqp_dh):
    """Newtonian bulk (``mu_1`` = 1): ``q_p = -k G``, ``k = H^3/12 + (h/2) lam_sum``, ``H = max(h - 2 delta, 0)``,
    ``lam_sum = lam_a + lam_b``; with ``dq_p/dG = -k`` and ``dq_p/dh = -G (H^2/4 + lam_sum/2)``."""
    for i in range(h.size):
        H = max(h[i] - 2.0 * delta, 0.0)
        k = H * H * H / 12.0 + 0.5 * h[i] * lam_sum
        qp[i] = -k * G[i]
        dqp_dG[i] = -k
        dqp_dh[i] = -G[i] * (0.25 * H * H + 0.5 * lam_sum)


@njit(cache=True)
def gecim_velocity(z, h, G, U1, U2, delta, lam_a, lam_b, kappa, ratio, xg, wg, u):
    """Velocity ``u(z)`` across one film (``0 <= z <= h``): Darcy plugs in the layers, the integrated
    inverse law in the bulk."""
    ua = U1 - lam_a * G
    ub = U2 - lam_b * G
    H = h - 2.0 * delta
    tau0 = _solve_tau0(ub - ua, G, H, kappa, ratio, xg, wg) if H > 0.0 else 0.0
    for i in range(z.size):
        if H <= 0.0:
            u[i] = ua if z[i] < 0.5 * h else ub
        elif z[i] <= delta:
            u[i] = ua
        elif z[i] >= h - delta:
            u[i] = ub
        else:
            u[i] = ua + _moments(tau0, G, z[i] - delta, H, kappa, ratio, xg, wg)[0]


# --------------------------------------------------------------------------------------------------
# the 2-D (vector) law: eq. (12), the shear rate is the magnitude of (u_z, v_z)
# --------------------------------------------------------------------------------------------------

@njit(cache=True)
def _rate_2d(tx, ty, kappa, r):
    """Shear-rate vector ``phi tau`` and its stress Jacobian ``J = phi I + (x' - phi) t t^T`` at the stress
    ``(tx, ty)`` (``phi`` the secant fluidity ``x/s``, ``x'`` the tangent one, ``t`` the stress direction):
    ``gx, gy, Jxx, Jxy, Jyy``."""
    m2 = tx * tx + ty * ty
    m = math.sqrt(m2)
    s = m / kappa
    b = s - 1.0
    d = math.sqrt(b * b + 4.0 * r * s)
    phi = (b + d) / (2.0 * r * s) if b >= 0.0 else 2.0 / (d - b)
    q = (1.0 + phi * s) ** 2
    c = q / (r * q + 1.0 - r) - phi  # x' - phi, x' = 1 / (r + (1 - r)/(1 + x)^2)
    cm = c / m2 if m2 > 0.0 else 0.0
    return phi * tx, phi * ty, phi + cm * tx * tx, cm * tx * ty, phi + cm * ty * ty


@njit(cache=True)
def _panel_2d(a, b, zs, sgn, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full):
    """Add the Gauss sums over ``zeta = zs + sgn d``, ``a <= d <= b``, to ``acc``: int gdot (0, 1), int J
    (2-4: xx, xy, yy) and, if ``full``, int zeta J (5-7), int (H/2 - zeta) gdot (8, 9), int (H/2 - zeta) J
    (10-12), int (H/2 - zeta) zeta J (13-15) (the continuity Newton needs only the first five)."""
    half = 0.5 * (b - a)
    mid = 0.5 * (a + b)
    for j in range(xg.size):
        z = zs + sgn * (mid + half * xg[j])
        w = half * wg[j]
        gx, gy, jxx, jxy, jyy = _rate_2d(t0x + Gx * z, t0y + Gy * z, kappa, r)
        c = 0.5 * H - z
        wz = w * z
        wc = w * c
        wcz = wc * z
        acc[0] += w * gx
        acc[1] += w * gy
        acc[2] += w * jxx
        acc[3] += w * jxy
        acc[4] += w * jyy
        if not full:
            continue
        acc[5] += wz * jxx
        acc[6] += wz * jxy
        acc[7] += wz * jyy
        acc[8] += wc * gx
        acc[9] += wc * gy
        acc[10] += wc * jxx
        acc[11] += wc * jxy
        acc[12] += wc * jyy
        acc[13] += wcz * jxx
        acc[14] += wcz * jxy
        acc[15] += wcz * jyy


@njit(cache=True)
def _side_2d(a, b, zs, sgn, mmin, Gn, d0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full):
    """Panels over ``a <= d <= b`` on one side of the point ``zs`` of least ``|tau|``: they end where
    ``|tau| = kappa 2^k`` and, if ``d0 > 0``, are no longer than ``max(d, d0)`` (the branch points of
    ``|tau|`` lie at ``d = +-i d0``, ``d0 = |tau|_min / |G|``)."""
    tk = math.hypot(mmin, Gn * a) / kappa
    cur = a
    while cur < b:
        mk = _next_break(tk) * kappa
        dk = math.sqrt(max(mk * mk - mmin * mmin, 0.0)) / Gn
        nxt = min(dk, cur + max(3.0 * cur, d0)) if d0 > 0.0 else dk
        if nxt >= dk:
            tk = mk / kappa
        nxt = min(nxt, b)
        _panel_2d(cur, nxt, zs, sgn, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)
        cur = nxt


@njit(cache=True)
def _moments_2d(t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full=True):
    """The sums of :func:`_panel_2d` over the bulk ``0 <= zeta <= H`` (overwrites ``acc``)."""
    acc[:] = 0.0
    g2 = Gx * Gx + Gy * Gy
    zs = -(t0x * Gx + t0y * Gy) / g2 if g2 > 0.0 else 0.0
    Gn = math.sqrt(g2)
    if Gn * H <= 1e-3 * math.hypot(t0x, t0y) or not math.isfinite(t0x + t0y + Gx + Gy):
        # |tau| varies by at most 1e-3 of itself: no kink, singularities far away, one panel is exact to
        # rounding (and the panel ends measured from a far-away zs would cancel); NaN/inf input: one panel
        _panel_2d(0.0, H, 0.0, 1.0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)
        return
    mmin = abs(t0x * Gy - t0y * Gx) / Gn
    d0 = mmin / Gn if mmin >= 1e-9 * Gn * H else 0.0  # below: a kink to 1e-17 relative
    if zs <= 0.0:
        _side_2d(-zs, H - zs, zs, 1.0, mmin, Gn, d0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)
    elif zs >= H:
        _side_2d(zs - H, zs, zs, -1.0, mmin, Gn, d0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)
    else:
        _side_2d(0.0, zs, zs, -1.0, mmin, Gn, d0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)
        _side_2d(0.0, H - zs, zs, 1.0, mmin, Gn, d0, t0x, t0y, Gx, Gy, H, kappa, r, xg, wg, acc, full)


@njit(cache=True)
def _couette_stress(x, r):
    """The law itself, ``s = S(x) = r x + (1 - r) x / (1 + x)`` (stress / kappa at the rate ``x >= 0``)."""
    return r * x + (1.0 - r) * x / (1.0 + x)


@njit(cache=True)
def _continuity_step(acc, dux, duy):
    """Newton step on velocity continuity ``int gdot = du`` from the sums in ``acc``: ``F_tau^-1 (int gdot - du)``."""
    fx = acc[0] - dux
    fy = acc[1] - duy
    det = acc[2] * acc[4] - acc[3] * acc[3]
    return (acc[4] * fx - acc[3] * fy) / det, (acc[2] * fy - acc[3] * fx) / det


@njit(cache=True)
def _newton_tau0_2d(dux, duy, Gx, Gy, H, kappa, r, xg, wg, acc, tx, ty, max_iter, tol):
    """Newton on velocity continuity from ``(tx, ty)`` with the five sums it needs, until a step is below ``tol``
    of the stress scale (the iterate is then ~tol^2 from the root: quadratic convergence) or stops shrinking below
    1e-10 of it; the iterate, or NaN."""
    scale = math.hypot(dux, duy) / H + math.hypot(Gx, Gy) * H
    last = math.inf
    for _ in range(max_iter):
        _moments_2d(tx, ty, Gx, Gy, H, kappa, r, xg, wg, acc, False)
        sx, sy = _continuity_step(acc, dux, duy)
        tx -= sx
        ty -= sy
        step = math.hypot(sx, sy)
        if step <= tol * scale or _converged(step, last, scale):
            return tx, ty
        last = step
    return math.nan, math.nan


@njit(cache=True)
def _solve_tau0_2d(dux, duy, Gx, Gy, H, kappa, r, xg, wg, acc, tol=NEWTON_TOL):
    """Bulk stress vector at ``zeta = 0`` with ``int_0^H gdot = du``: Newton (NaN if 50 iterations do not
    converge) stopped at a step of ``tol`` of the stress scale; leaves all sixteen sums at the root in ``acc``
    (the flow sums corrected by a last step: the flow is then ~tol^4 from the root's, the derivative sums ~tol^2).
    The start's Couette part solves the law exactly (the stress ``S(|du|/H)`` of a pure shear at the rate ``du/H``), its pressure part is the Newtonian ``mu_1``
    one; against the plain Newtonian start it cuts the sums per face from 5.8 to 3.6 at Jang's journal case."""
    m = math.hypot(dux, duy) / H
    c = _couette_stress(m / kappa, r) * kappa / m if m > 0.0 else 1.0
    tx, ty = _newton_tau0_2d(dux, duy, Gx, Gy, H, kappa, r, xg, wg, acc, c * dux / H - 0.5 * Gx * H,
                             c * duy / H - 0.5 * Gy * H, 50, tol)
    if not math.isfinite(tx):
        return tx, ty
    _moments_2d(tx, ty, Gx, Gy, H, kappa, r, xg, wg, acc, True)
    # one more Newton step from these sums, carried into tau_0 and the flow sums to first order (the derivative
    # sums stay at the iterate, ~tol^2 away)
    sx, sy = _continuity_step(acc, dux, duy)
    acc[8] -= acc[10] * sx + acc[11] * sy
    acc[9] -= acc[11] * sx + acc[12] * sy
    return tx - sx, ty - sy


@njit(cache=True)
def gecim_face_2d(h, Gx, Gy, U1x, U1y, U2x, U2y, delta, lam_a, lam_b, kappa, ratio, xg, wg, tol=NEWTON_TOL):
    """One point of a 2-D film: ``(qx, qy, dqx/dGx, dqx/dGy, dqy/dGx, dqy/dGy, dqx/dh, dqy/dh, tau0x, tau0y)``
    of the pressure part ``q_p`` (dimensionless as :func:`gecim_face`; ``tau_0`` NaN if ``h <= 2 delta``);
    ``tol``: the continuity Newton's stop (:func:`_solve_tau0_2d`)."""
    A = lam_a + lam_b
    H = h - 2.0 * delta
    if H <= 0.0:
        k = -0.5 * h * A
        return k * Gx, k * Gy, k, 0.0, 0.0, k, -0.5 * A * Gx, -0.5 * A * Gy, math.nan, math.nan
    dl = lam_b - lam_a
    dux = (U2x - U1x) - dl * Gx
    duy = (U2y - U1y) - dl * Gy
    acc = np.empty(16)
    tx, ty = _solve_tau0_2d(dux, duy, Gx, Gy, H, kappa, ratio, xg, wg, acc, tol)
    if math.isnan(tx):
        n = math.nan
        return n, n, n, n, n, n, n, n, n, n
    det = acc[2] * acc[4] - acc[3] * acc[3]
    ixx, ixy, iyy = acc[4] / det, -acc[3] / det, acc[2] / det  # F_tau^-1
    mxx, mxy, myy = acc[5] + dl, acc[6], acc[7] + dl          # dF/dG
    txx, txy = -(ixx * mxx + ixy * mxy), -(ixx * mxy + ixy * myy)  # d tau_0/dG
    tyx, tyy = -(ixy * mxx + iyy * mxy), -(ixy * mxy + iyy * myy)
    g1x, g1y = _rate_2d(tx + Gx * H, ty + Gy * H, kappa, ratio)[:2]
    sx, sy = -(ixx * g1x + ixy * g1y), -(ixy * g1x + iyy * g1y)    # d tau_0/dH
    kxx, kxy, kyy = acc[10], acc[11], acc[12]
    k0 = -0.5 * h * A
    return (k0 * Gx + acc[8], k0 * Gy + acc[9],
            k0 + acc[13] + kxx * txx + kxy * tyx, acc[14] + kxx * txy + kxy * tyy,
            acc[14] + kxy * txx + kyy * tyx, k0 + acc[15] + kxy * txy + kyy * tyy,
            -0.5 * (A * Gx + H * g1x - dux) + kxx * sx + kxy * sy,
            -0.5 * (A * Gy + H * g1y - duy) + kxy * sx + kyy * sy, tx, ty)


@njit(cache=True)
def gecim_flow_2d(h, G, U1, U2, delta, lam_a, lam_b, kappa, ratio, xg, wg, qp, dqp_dG, dqp_dh, tau0):
    """:func:`gecim_face_2d` over points: ``h (n,)``; ``G, U1, U2, qp, dqp_dh, tau0 (n, 2)``;
    ``dqp_dG (n, 2, 2)`` with ``dqp_dG[i, a, b] = d qp_a / d G_b``."""
    for i in range(h.size):
        o = gecim_face_2d(h[i], G[i, 0], G[i, 1], U1[i, 0], U1[i, 1], U2[i, 0], U2[i, 1], delta, lam_a, lam_b,
                          kappa, ratio, xg, wg)
        qp[i, 0], qp[i, 1] = o[0], o[1]
        dqp_dG[i, 0, 0], dqp_dG[i, 0, 1], dqp_dG[i, 1, 0], dqp_dG[i, 1, 1] = o[2], o[3], o[4], o[5]
        dqp_dh[i, 0], dqp_dh[i, 1] = o[6], o[7]
        tau0[i, 0], tau0[i, 1] = o[8], o[9]


@njit(cache=True)
def gecim_velocity_2d(z, h, Gx, Gy, U1x, U1y, U2x, U2y, delta, lam_a, lam_b, kappa, ratio, xg, wg, u):
    """Velocity vector ``u(z)`` (rows of ``u``, shape (n, 2)) across one film of the 2-D law: Darcy plugs in the
    layers, ``u_a + int_0^zeta gdot`` in the bulk (the sums of :func:`_moments_2d` up to ``zeta``)."""
    uax, uay = U1x - lam_a * Gx, U1y - lam_a * Gy
    ubx, uby = U2x - lam_b * Gx, U2y - lam_b * Gy
    H = h - 2.0 * delta
    acc = np.empty(16)
    tx = ty = 0.0
    if H > 0.0:
        tx, ty = _solve_tau0_2d(ubx - uax, uby - uay, Gx, Gy, H, kappa, ratio, xg, wg, acc)
    for i in range(z.size):
        if H <= 0.0:
            lower = z[i] < 0.5 * h
            u[i, 0], u[i, 1] = (uax, uay) if lower else (ubx, uby)
        elif z[i] <= delta:
            u[i, 0], u[i, 1] = uax, uay
        elif z[i] >= h - delta:
            u[i, 0], u[i, 1] = ubx, uby
        else:
            _moments_2d(tx, ty, Gx, Gy, z[i] - delta, kappa, ratio, xg, wg, acc)
            u[i, 0], u[i, 1] = uax + acc[0], uay + acc[1]


# --------------------------------------------------------------------------------------------------
# rheology and layers (SI)
# --------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Newtonian:
    """Newtonian bulk: ``mu_c = mu_1``."""

    def viscosity(self, shear_rate, mu_1):
        """``mu_1`` at every shear rate [Pa s]."""
        return np.full(np.shape(shear_rate), float(mu_1))

    def shear_rate(self, stress, mu_1):
        """``tau / mu_1`` [1/s]."""
        return np.asarray(stress, dtype=float) / mu_1


@dataclass(frozen=True)
class Gecim:
    """Gecim (1990) shear thinning: ``mu = mu_1 (kappa + mu_2 gdot)/(kappa + mu_1 gdot)``.

    ``kappa`` [Pa] the stress scale of the transition (1e-9 ... 1e12 Pa: the limits are Newtonian ``mu_1`` as
    ``kappa -> inf`` and ``mu_2`` as ``kappa -> 0``); ``viscosity_ratio = mu_2/mu_1`` in
    ``[RATIO_MIN, 1]`` (1 is Newtonian; the stress is strictly increasing in the shear rate for any
    ratio > 0, but the law is a shear-thinning fit and the quadrature accuracy is stated down to 0.05).
    """

    kappa: float
    viscosity_ratio: float

    def __post_init__(self):
        object.__setattr__(self, "kappa", check_range(
            "kappa", self.kappa, "Pa", 1e-9, 1e12,
            why="(the transition stress; below 1e-9 Pa the law is the Newtonian mu_2 fluid to kappa/tau, and the "
            "dimensionless kernels would overflow)"))
        object.__setattr__(self, "viscosity_ratio", check_range(
            "viscosity_ratio mu_2/mu_1", self.viscosity_ratio, "-", RATIO_MIN, 1.0,
            why="(shear thinning: mu_2 <= mu_1; below 0.05 the law approaches a kink at tau = kappa)"))

    def viscosity(self, shear_rate, mu_1):
        """Apparent viscosity [Pa s] at the shear rate [1/s] (its magnitude)."""
        g = np.abs(np.asarray(shear_rate, dtype=float))
        return mu_1 * (self.kappa + self.viscosity_ratio * mu_1 * g) / (self.kappa + mu_1 * g)

    def shear_rate(self, stress, mu_1):
        """Shear rate [1/s] at the shear stress [Pa] (closed-form inverse, signed)."""
        s = np.asarray(stress, dtype=float) / self.kappa
        x = np.vectorize(lambda v: gecim_rate(v, self.viscosity_ratio)[0], otypes=[float])(s)
        return self.kappa / mu_1 * x


@dataclass(frozen=True)
class BoundaryLayers:
    """Porous solid-like layers on both walls (Jang).

    ``thickness`` delta [m] >= 0 (each wall); ``viscosity`` [Pa s] one value or the pair
    ``(mu_a, mu_b)`` (lower, upper wall); ``alpha`` [m] >= 0 the permeability length (0: immobile layers,
    they move with their walls). ``alpha > 0`` needs ``thickness > 0``: the Darcy slip of the model does
    not vanish with the layer thickness.
    """

    thickness: float
    viscosity: float | tuple[float, float]
    alpha: float

    def __post_init__(self):
        d = check_range("thickness delta", self.thickness, "m", 0.0, 1e-3, why="(boundary layers: at most 1 mm)")
        pair = self.viscosity if np.ndim(self.viscosity) else (self.viscosity, self.viscosity)
        if len(pair) != 2:
            raise ValueError(f"viscosity = {self.viscosity!r} [Pa s] must be one value or a pair (mu_a, mu_b)")
        mu = (check_range("viscosity mu_a (lower layer)", pair[0], "Pa s", 1e-6, 1e6),
              check_range("viscosity mu_b (upper layer)", pair[1], "Pa s", 1e-6, 1e6))
        a = check_range("alpha", self.alpha, "m", 0.0, 0.0 if d == 0.0 else 1e-3,
                        why="(the permeability length; alpha > 0 needs layers of thickness > 0)" if d == 0.0
                        else "(the permeability length, at most 1 mm)")
        object.__setattr__(self, "thickness", d)
        object.__setattr__(self, "viscosity", mu)
        object.__setattr__(self, "alpha", a)


NO_LAYERS = BoundaryLayers(0.0, 1.0, 0.0)


class FaceFlow(NamedTuple):
    """Flow per unit width of a film at faces (SI): ``q = q_couette + q_pressure``."""

    q_couette: np.ndarray   # h (U1 + U2)/2 [m^2/s]; upwinded on the content in Elrod's scheme
    q_pressure: np.ndarray  # [m^2/s]; zero at G = 0
    dqp_dG: np.ndarray      # d q_pressure / dG [m^5/(N s)]
    dqp_dh: np.ndarray      # d q_pressure / dh [m/s]


class ShearStresses(NamedTuple):
    """``tau_xz`` [Pa] at ``z = 0, delta, h - delta, h``; the film pushes the lower wall with
    ``+lower_wall`` and the upper wall with ``-upper_wall`` (force per area along the flow)."""

    lower_wall: np.ndarray
    lower_interface: np.ndarray
    upper_interface: np.ndarray
    upper_wall: np.ndarray


@dataclass(frozen=True)
class LayeredFilm:
    """The pointwise flow law of a layered film (SI in and out; dimensionless kernels inside).

    ``viscosity`` mu_1 [Pa s] of the bulk (its low-shear value for Gecim), ``rheology`` of the bulk,
    ``layers`` on the walls, ``gauss_points`` per quadrature panel (Gecim bulk).
    """

    viscosity: float
    rheology: Newtonian | Gecim = Newtonian()
    layers: BoundaryLayers = NO_LAYERS
    gauss_points: int = GAUSS_POINTS

    def __post_init__(self):
        object.__setattr__(self, "viscosity", check_positive("viscosity mu_1", self.viscosity, "Pa s"))
        object.__setattr__(self, "gauss_points", int(check_range("gauss_points", self.gauss_points, "-", 1, 64)))

    def _scaled(self, h, G, U1, U2, scales):
        """Check and scale broadcast face data; return the dimensionless arrays and the reference (L, V)."""
        if not np.all(h >= 1e-12) or not np.all(h <= 1.0):
            bad = float(h[~((h >= 1e-12) & (h <= 1.0))][0])
            raise ValueError(f"film thickness h = {bad!r} [m] is out of range; allowed: [1e-12, 1] m")
        for name, v, unit, top in (("pressure gradient G", G, "Pa/m", 1e18), ("wall speed U1", U1, "m/s", 1e4),
                                   ("wall speed U2", U2, "m/s", 1e4)):
            if not np.all(np.abs(v) <= top):
                bad = float(v[~(np.abs(v) <= top)][0])
                raise ValueError(f"{name} = {bad!r} [{unit}] is out of range; allowed: [-{top:g}, {top:g}] {unit}")
        if scales is None:
            L = float(h.max())
            V = max(np.abs(U1).max(), np.abs(U2).max(), np.abs(G).max() * L * L / self.viscosity) or 1.0
        else:
            L, V = scales
        gs = self.viscosity * V / L**2
        return h / L, G / gs, U1 / V, U2 / V, float(L), float(V)

    @staticmethod
    def _faces(h, G, U1, U2):
        """Broadcast 1-D face data to flat float arrays; also return the broadcast shape."""
        arrays = np.broadcast_arrays(*(_numbers(name, v) for name, v in (("h", h), ("G", G), ("U1", U1), ("U2", U2))))
        return arrays[0].shape, [np.ascontiguousarray(a).ravel() for a in arrays]

    @staticmethod
    def _faces_2d(h, G, U1, U2):
        """Broadcast 2-D face data (``h`` of shape ``S``; ``G, U1, U2`` of shape ``S + (2,)``) to a flat ``h`` and
        ``(n, 2)`` arrays; also return ``S``."""
        G, U1, U2 = (_numbers(name, v) for name, v in (("G", G), ("U1", U1), ("U2", U2)))
        hv, G, U1, U2 = np.broadcast_arrays(_numbers("h", h)[..., None], G, U1, U2)
        return hv.shape[:-1], [np.ascontiguousarray(hv[..., 0]).ravel()] + [
            np.ascontiguousarray(v).reshape(-1, 2) for v in (G, U1, U2)]

    def _parameters(self, L, V):
        """Dimensionless ``delta, lam_a, lam_b, kappa, ratio`` (Newtonian: ``kappa = 1, ratio = 1``)."""
        ly, mu = self.layers, self.viscosity
        lam = [ly.alpha**2 * mu / (m * L * L) for m in ly.viscosity]
        if isinstance(self.rheology, Gecim):
            kappa, ratio = self.rheology.kappa * L / (mu * V), self.rheology.viscosity_ratio
        else:
            kappa, ratio = 1.0, 1.0
        return ly.thickness / L, lam[0], lam[1], kappa, ratio

    def _gauss(self):
        return np.polynomial.legendre.leggauss(self.gauss_points)

    def flow(self, h, G, U1, U2, scales=None):
        """:class:`FaceFlow` at faces of film ``h`` [m], pressure gradient ``G = dp/ds`` [Pa/m] and wall
        speeds ``U1`` (lower), ``U2`` (upper) [m/s] along the face direction (arrays broadcast).
        ``scales = (L [m], V [m/s])`` overrides the kernels' reference length and speed."""
        shape, faces = self._faces(h, G, U1, U2)
        hs, Gs, U1s, U2s, L, V = self._scaled(*faces, scales)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        qp, dG, dh = (np.empty_like(hs) for _ in range(3))
        if isinstance(self.rheology, Gecim):
            xg, wg = self._gauss()
            gecim_flow(hs, Gs, U1s, U2s, delta, lam_a, lam_b, kappa, ratio, xg, wg, qp, dG, dh, np.empty_like(hs))
        else:
            newtonian_flow(hs, Gs, delta, lam_a + lam_b, qp, dG, dh)
        qc = 0.5 * hs * (U1s + U2s) * V * L
        return _finite_flow(FaceFlow(*(a.reshape(shape) for a in (qc, qp * V * L, dG * L**3 / self.viscosity, dh * V))))

    def flow_2d(self, h, G, U1, U2, scales=None):
        """:class:`FaceFlow` of a 2-D film: ``h`` [m] of shape ``S``, the pressure gradient ``G`` [Pa/m] and
        the wall velocities ``U1, U2`` [m/s] of shape ``S + (2,)``. Returns ``q_couette, q_pressure,
        dqp_dh`` of shape ``S + (2,)`` and ``dqp_dG`` of shape ``S + (2, 2)`` (``[..., a, b] = dq_a/dG_b``).
        For a Gecim bulk the two directions are coupled through ``|gdot|`` (eq. 12)."""
        shape, faces = self._faces_2d(h, G, U1, U2)
        hs, Gs, U1s, U2s, L, V = self._scaled(*faces, scales)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        qp, dh = np.empty_like(Gs), np.empty_like(Gs)
        dG = np.zeros((hs.size, 2, 2))
        if isinstance(self.rheology, Gecim):
            xg, wg = self._gauss()
            gecim_flow_2d(hs, Gs, U1s, U2s, delta, lam_a, lam_b, kappa, ratio, xg, wg, qp, dG, dh, np.empty_like(Gs))
        else:  # linear and isotropic: each direction on its own
            for a in range(2):
                newtonian_flow(hs, np.ascontiguousarray(Gs[:, a]), delta, lam_a + lam_b, qp[:, a], dG[:, a, a],
                               dh[:, a])
        qc = 0.5 * hs[:, None] * (U1s + U2s) * V * L
        return FaceFlow(qc.reshape(shape + (2,)), (qp * V * L).reshape(shape + (2,)),
                        (dG * L**3 / self.viscosity).reshape(shape + (2, 2)), (dh * V).reshape(shape + (2,)))

    def stresses(self, h, G, U1, U2):
        """:class:`ShearStresses` [Pa] (NaN at the interfaces where ``h <= 2 delta``)."""
        shape, faces = self._faces(h, G, U1, U2)
        hs, Gs, U1s, U2s, L, V = self._scaled(*faces, None)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        xg, wg = self._gauss()
        out = [np.empty_like(hs) for _ in range(4)]
        gecim_flow(hs, Gs, U1s, U2s, delta, lam_a, lam_b, kappa, ratio, xg, wg, *out)
        t0 = out[3]
        t1 = t0 + Gs * (hs - 2.0 * delta)
        st = self.viscosity * V / L
        return ShearStresses(*((v * st).reshape(shape) for v in (t0 - Gs * delta, t0, t1, t1 + Gs * delta)))

    def stresses_2d(self, h, G, U1, U2):
        """:class:`ShearStresses` of a 2-D film [Pa]: each entry of shape ``S + (2,)`` (the stress vector), for
        ``h`` [m] of shape ``S`` and ``G`` [Pa/m], ``U1, U2`` [m/s] of shape ``S + (2,)``."""
        shape, faces = self._faces_2d(h, G, U1, U2)
        hs, Gs, U1s, U2s, L, V = self._scaled(*faces, None)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        qp, dh, t0 = np.empty_like(Gs), np.empty_like(Gs), np.empty_like(Gs)
        gecim_flow_2d(hs, Gs, U1s, U2s, delta, lam_a, lam_b, kappa, ratio, *self._gauss(), qp,
                      np.empty((hs.size, 2, 2)), dh, t0)
        t1 = t0 + Gs * (hs - 2.0 * delta)[:, None]
        st = self.viscosity * V / L
        return ShearStresses(*((v * st).reshape(shape + (2,)) for v in (t0 - Gs * delta, t0, t1, t1 + Gs * delta)))

    def velocity_2d(self, h, G, U1, U2, z):
        """Velocity vectors [m/s], shape ``(len(z), 2)``, at heights ``z`` [m] across one 2-D film (``h`` scalar,
        ``G, U1, U2`` 2-vectors)."""
        hs, Gs, U1s, U2s, L, V = self._scaled(*self._faces_2d(float(h), G, U1, U2)[1], None)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        zs = np.asarray(z, dtype=float).ravel()
        u = np.empty((zs.size, 2))
        gecim_velocity_2d(zs / L, hs[0], Gs[0, 0], Gs[0, 1], U1s[0, 0], U1s[0, 1], U2s[0, 0], U2s[0, 1], delta,
                          lam_a, lam_b, kappa, ratio, *self._gauss(), u)
        return u * V

    def velocity(self, h, G, U1, U2, z):
        """Velocity [m/s] at heights ``z`` [m] (``0 <= z <= h``) across one film (scalars ``h, G, U1, U2``)."""
        hs, Gs, U1s, U2s, L, V = self._scaled(*self._faces(h, G, U1, U2)[1], None)
        delta, lam_a, lam_b, kappa, ratio = self._parameters(L, V)
        zs = np.asarray(z, dtype=float)
        u = np.empty(zs.size)
        gecim_velocity(zs.ravel() / L, hs[0], Gs[0], U1s[0], U2s[0], delta, lam_a, lam_b, kappa, ratio,
                       *self._gauss(), u)
        return (u * V).reshape(zs.shape)


def _numbers(name, v) -> np.ndarray:
    """Face data as a float array: numbers only (``None``, strings and booleans are named errors)."""
    if v is None or isinstance(v, (str, bytes, bool)):
        raise ValueError(f"{name} = {v!r} is not a number or an array of numbers")
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {v!r} is not a number or an array of numbers") from None
    if a.size == 0:
        raise ValueError(f"{name} = {v!r} is empty; allowed: a number or a non-empty array of numbers")
    return a


def _finite_flow(f):
    """The flow if every entry is finite, else a named error (inputs beyond what the law is evaluated for)."""
    for name in ("q_couette", "q_pressure", "dqp_dG", "dqp_dh"):
        if not np.all(np.isfinite(getattr(f, name))):
            raise ValueError(f"flow: {name} is not finite for these h, G, U1, U2 (film, pressure gradient or wall "
                             "speeds beyond the range the layered law is evaluated for)")
    return f
