"""The orbit of a rough journal bearing (mixed lubrication in the time domain): the average Reynolds equation of
Patir & Cheng in the orbit's Elrod film, the Greenwood-Tripp asperity contact in the rotor's equations, and a shaft
speed that may vary in time (start-up, coast-down), as numba kernels for IDA (universal variable) and the BDF2
content Newton.

Per cell the coefficients are those of :func:`~transient.models.journal.roughness.rough_coefficients` (the same
fits, evaluated here in numba; the asperity pressure ``p_a(h)`` is a cubic Hermite table of
:meth:`~transient.physics.asperity.AsperityContact.load` and its slope in ``h / sigma``, 0.005 apart). With the mean
gap ``h_T / C`` and the contact factor ``phi_c = d h_T / d h`` the film content of a cell is ``m = (h_T / C) theta``
and the conservation law, in ``tau = omega_ref t``::

    A_i (h_T,i D_i u_i' + theta_i phi_c,i H_i') + R_i(k_x, k_z, s c_x) = 0      (universal, IDA)
    A_i m_i' + R_i = 0,   theta_i = m_i / h_T(H_i)                              (content, BDF2)

``s(tau) = Omega / omega_ref`` is the shaft speed ratio (the orbit's speed law, :mod:`~transient.models.journal.speed_law`;
1 at constant speed): the Couette and shear flows scale with it, the pressure unit ``p0`` is the reference speed's.
The rotor::

    X'' = kappa (Fbar_x + Fa_x) + Wbar + ebar (s^2 cos phi + s' sin phi),   phi = int s dtau
    Y'' = kappa (Fbar_y + Fa_y) + ebar (s^2 sin phi - s' cos phi)
    Fa = sym sum_i (p_a,i / p0) (cos, sin) A_i                                  (asperity force)

with the contact stiffness ``sym sum (dp_a/dH / p0) (cos, sin)(cos, sin) A`` in its Jacobian rows.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from transient.fv.reynolds import jacobian_kernel, residual_kernel
from transient.models.journal.kernels import N_ROTOR, content_rows_at, film_force, shaft_accelerations, state_fields
from transient.models.journal.content_newton import (cell_regime, content_newton_norm, gather_pattern, keep_prescribed,
                                                     pattern_target, store_content)
from transient.models.journal.film import read_only
from transient.models.journal.speed_law import CONSTANT, shaft_speed
from transient.physics.cavitation import elrod_inverse
from transient.physics.flow_factors import PRESSURE_FLOW_TABLE, SHEAR_FLOW_TABLE, gamma_bracket
import transient.solvers.integrate.bdf2 as stepper
from transient.solvers.integrate.bdf2 import BandNewton, newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.read_only import as_read_only

#: The asperity pressure table: ``h / sigma`` from ``CONTACT_TABLE_LOW`` (linear below) to the top (0 above: the
#: Gaussian F_3/2(8) is 4e-17 of F_3/2(0)) in steps of ``CONTACT_TABLE_STEP`` (Hermite error ~1e-12 relative).
CONTACT_TABLE_LOW = -6.0
CONTACT_TABLE_TOP = 8.0
CONTACT_TABLE_STEP = 0.005
#: The film parameter ``h_min / sigma`` below which an orbit's journal is in contact (its records' contact events):
#: 3, the customary onset of mixed lubrication (asperity load below 1e-4 of the peak Greenwood-Tripp pressure).
CONTACT_LAMBDA = 3.0
_SQRT2 = math.sqrt(2.0)
_SQRT2PI = math.sqrt(2.0 * math.pi)


class RoughCells(NamedTuple):
    """The kernel data of a rough film (built by :func:`rough_cells`): the fits' coefficients, the asperity table,
    the speed law and the per-cell scratch the kernels fill."""

    sig: float            # sigma / C
    floor: float          # h / sigma below which the flow factors are held (Roughness.fit_floor)
    px: np.ndarray        # (2, 4) pressure flow fit along x per bracketing gamma: C, r, power law (1) or exp (0), weight
    pz: np.ndarray        # (2, 4) the same across (1 / gamma)
    ps: np.ndarray        # (2, 6) shear flow fit: A1, a1, a2, a3, A2, weight (2 V_j - 1) w_gamma
    table: np.ndarray     # (2, m) p_a / p0 and d(p_a / p0)/d(h / sigma) at h / sigma = low + k step
    low: float
    step: float
    knots: np.ndarray     # (3, K) the shaft's speed law (speed_law.speed_knots): tau_k, s_k, angle phi(tau_k)
    kz: np.ndarray        # per cell: k_z, and d/dH of k_x, k_z, c_x (at speed 1)
    dkx: np.ndarray
    dkz: np.ndarray
    dcx: np.ndarray
    mean_gap: np.ndarray  # h_T / C
    phi_c: np.ndarray
    dphi_c: np.ndarray
    pa: np.ndarray        # p_a / p0 and d(p_a / p0)/dH
    dpa: np.ndarray
    dkz_dq: np.ndarray    # (2, n) d k_z / d(X, Y)
    cs: np.ndarray        # s c_x: the Couette and shear coefficient at the shaft's speed


def _pressure_fit(gamma):
    out = np.zeros((2, 4))
    for b, (g, w) in enumerate(gamma_bracket(gamma)):
        C, r, _ = PRESSURE_FLOW_TABLE[[k for k in PRESSURE_FLOW_TABLE if abs(k - g) <= 1e-12 * k][0]]
        out[b] = C, r, 0.0 if g <= 1.0 else 1.0, w
    return out


def rough_cells(roughness, clearance, p0, n, knots=CONSTANT) -> RoughCells:
    """:class:`RoughCells` of a film of ``n`` cells with ``roughness`` (:class:`~.roughness.Roughness`), clearance
    [m] and pressure unit ``p0`` [Pa], shaft speed law ``knots`` (:mod:`~transient.models.journal.speed_law`)."""
    if roughness.pressure_viscosity != 0.0:
        raise ValueError(f"roughness.pressure_viscosity = {roughness.pressure_viscosity!r} [1/Pa] in a rough orbit; "
                         "allowed: 0 (the orbit's film is isoviscous; the steady states take the Barus film)")
    if roughness.bore_compliance != 0.0:
        raise ValueError(f"roughness.bore_compliance = {roughness.bore_compliance!r} [m/Pa] in a rough orbit; "
                         "allowed: 0 (the orbit's bore is rigid; the steady states take the Winkler bore)")
    sig = roughness.sigma / clearance
    ps = np.zeros((2, 6))
    w = 2.0 * roughness.journal_variance_share - 1.0
    for b, (g, wg) in enumerate(gamma_bracket(roughness.gamma)):
        A1, a1, a2, a3, A2 = SHEAR_FLOW_TABLE[[k for k in SHEAR_FLOW_TABLE if abs(k - g) <= 1e-12 * k][0]]
        ps[b] = A1, a1, a2, a3, A2, w * wg
    c = roughness.contact
    top = CONTACT_TABLE_TOP
    if c.density is not None:
        top = max(top, float(np.max(c.density.edges)) / roughness.sigma)
    hs = np.arange(CONTACT_TABLE_LOW, top + CONTACT_TABLE_STEP, CONTACT_TABLE_STEP)
    h = hs * roughness.sigma
    table = np.vstack([np.asarray(c.load(h), float) / p0, np.asarray(c.load_derivative(h), float) * roughness.sigma / p0])
    z = lambda: np.zeros(n)  # noqa: E731
    return RoughCells(sig, roughness.fit_floor, _pressure_fit(roughness.gamma), _pressure_fit(1.0 / roughness.gamma),
                      ps, np.ascontiguousarray(table), CONTACT_TABLE_LOW, CONTACT_TABLE_STEP, knots,
                      z(), z(), z(), z(), z(), z(), z(), z(), z(), np.zeros((2, n)), z())


# ------------------------------------------------------------------------------------------------- per cell
@njit(cache=True)
def _pressure_factor(hs, fit):
    """Patir-Cheng pressure flow factor and its slope at ``h / sigma = hs`` (bracketing gammas weighted)."""
    v = 0.0
    d = 0.0
    for b in range(2):
        C, r, power, w = fit[b, 0], fit[b, 1], fit[b, 2], fit[b, 3]
        if w == 0.0:
            continue
        if power == 0.0:
            e = math.exp(-r * hs)
            f = 1.0 - C * e
            if f > 0.0:
                v += w * f
                d += w * C * r * e
        else:
            v += w * (1.0 + C * hs ** -r)
            d -= w * r * C * hs ** (-r - 1.0)
    return v, d


@njit(cache=True)
def _shear_factor(hs, fit):
    """The weighted shear flow factor ``(2 V_j - 1) Phi_s`` and its slope at ``h / sigma = hs`` (hs > 0)."""
    v = 0.0
    d = 0.0
    for b in range(2):
        A1, a1, a2, a3, A2, w = fit[b, 0], fit[b, 1], fit[b, 2], fit[b, 3], fit[b, 4], fit[b, 5]
        if w == 0.0:
            continue
        if hs <= 5.0:
            f = A1 * hs ** a1 * math.exp(-a2 * hs + a3 * hs * hs)
            v += w * f
            d += w * f * (a1 / hs - a2 + 2.0 * a3 * hs)
        else:
            f = A2 * math.exp(-0.25 * hs)
            v += w * f
            d -= 0.25 * w * f
    return v, d


@njit(cache=True)
def _asperity(hs, table, low, step):
    """Asperity pressure / p0 and its slope by ``h / sigma`` (cubic Hermite in the table; linear below, 0 above)."""
    m = table.shape[1]
    x = (hs - low) / step
    if x <= 0.0:
        return table[0, 0] + table[1, 0] * (hs - low), table[1, 0]
    k = int(x)
    if k >= m - 1:
        return 0.0, 0.0
    t = x - k
    y0, y1 = table[0, k], table[0, k + 1]
    d0, d1 = table[1, k] * step, table[1, k + 1] * step
    t2 = t * t
    t3 = t2 * t
    v = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * d1
    dv = (6 * t2 - 6 * t) * y0 + (3 * t2 - 4 * t + 1) * d0 + (-6 * t2 + 6 * t) * y1 + (3 * t2 - 2 * t) * d1
    return v, dv / step


@njit(cache=True)
def mean_gap(H, sig):
    """Mean gap ``h_T / C`` of Gaussian heights at the nominal film ``H`` (Wu & Zheng): ``sig (Hs Phi + phi)``."""
    hr = H / sig
    return sig * (hr * 0.5 * math.erfc(-hr / _SQRT2) + math.exp(-0.5 * hr * hr) / _SQRT2PI)


@njit(cache=True)
def rough_cell_fields(H, rough, k, c):
    """The average-flow coefficients of every cell at its film ``H`` (module docstring of
    :mod:`~transient.models.journal.roughness`): ``k`` <- k_x, ``c`` <- c_x (speed 1), and the rough scratch."""
    sig, floor = rough.sig, rough.floor
    for i in range(H.size):
        h = H[i]
        hr = h / sig
        active = hr > floor
        hs = hr if active else floor
        phx, dphx = _pressure_factor(hs, rough.px)
        phz, dphz = _pressure_factor(hs, rough.pz)
        phs, dphs = _shear_factor(hs, rough.ps)
        if not active:
            dphx = 0.0
            dphz = 0.0
            dphs = 0.0
        pdf = math.exp(-0.5 * hr * hr) / _SQRT2PI
        cdf = 0.5 * math.erfc(-hr / _SQRT2)
        hT = mean_gap(h, sig)
        h3 = 0.5 * h * h * h
        k[i] = h3 * phx
        rough.kz[i] = h3 * phz
        c[i] = 0.5 * (hT + sig * phs)
        rough.dkx[i] = 1.5 * h * h * phx + h3 * dphx / sig
        rough.dkz[i] = 1.5 * h * h * phz + h3 * dphz / sig
        rough.dcx[i] = 0.5 * (cdf + dphs)
        rough.mean_gap[i] = hT
        rough.phi_c[i] = cdf
        rough.dphi_c[i] = pdf / sig
        pa, dpa = _asperity(hr, rough.table, rough.low, rough.step)
        rough.pa[i] = pa
        rough.dpa[i] = dpa / sig


@njit(cache=True)
def peak_asperity_pressure(X, Y, geo, rough):
    """The largest asperity pressure / p0 of the cells at the journal position (X, Y)."""
    cosp, sinp, area, gap0 = geo
    top = 0.0
    for i in range(cosp.size):
        p = _asperity((gap0[i] + X * cosp[i] + Y * sinp[i]) / rough.sig, rough.table, rough.low, rough.step)[0]
        if p > top:
            top = p
    return top


@njit(cache=True)
def rough_accelerations(tau, fx, fy, rotor, knots):
    """``(X'', Y'')`` of the module docstring for the film + asperity force (fx, fy)."""
    kappa, wbar, ebar, sym = rotor
    s, ds, phi = shaft_speed(tau, knots)
    return shaft_accelerations(s, ds, phi, fx, fy, kappa, wbar, ebar)


@njit(cache=True)
def rough_state_fields(u, X, Y, switch, geo, fields, fv, rough):
    """The cell fields of ``u`` at (X, Y) with the rough coefficients in ``fields.k`` (k_x), ``fields.c`` (c_x at
    speed 1) and ``rough``."""
    state_fields(u, X, Y, switch, geo, fields, fv)
    rough_cell_fields(fields.H, rough, fields.k, fields.c)


@njit(cache=True)
def rough_flux(s, u, fields, fv, rough, R):
    """The net outflow ``R`` of every cell at speed ratio ``s`` on the fields of :func:`rough_state_fields`."""
    faces, boundary, cells, face_k, bulk = fv
    for i in range(R.size):
        rough.cs[i] = s * fields.c[i]
    residual_kernel(u, fields.P, fields.C, fields.k, rough.kz, rough.cs, fields.zero, True, faces, boundary, cells,
                    face_k, R)


@njit(cache=True)
def rough_flux_jacobian(s, geo, fields, extras, fv, rough, data):
    """dR/du and dR/d(X, Y) at speed ratio ``s`` into ``data`` (zeroed first) on the fields of
    :func:`rough_state_fields`."""
    cosp, sinp = geo.cosp, geo.sinp
    dk, dc = extras.dk_dq, extras.dc_dq
    n = cosp.size
    for i in range(n):
        rough.cs[i] = s * fields.c[i]
    q = min(dk.shape[0], 2)
    for i in range(n):
        for e in range(q):
            trig = cosp[i] if e == 0 else sinp[i]
            dk[e, i] = rough.dkx[i] * trig
            rough.dkz_dq[e, i] = rough.dkz[i] * trig
            dc[e, i] = s * rough.dcx[i] * trig
    faces, boundary, cells, face_k, bulk = fv
    jacobian_kernel(fields.P, fields.dP, fields.C, fields.D, fields.k, fields.zero, rough.kz, fields.zero, rough.cs,
                    fields.zero, dk[:q], rough.dkz_dq[:q], dc[:q], extras.no_dq[:q], True, faces, boundary, cells,
                    face_k, extras.pos_col, data)


@njit(cache=True)
def rough_force(P, geo, rough, sym):
    """Film + asperity force on the journal (dimensionless)."""
    fx, fy = film_force(P, geo.cosp, geo.sinp, geo.area, sym)
    ax, ay = film_force(rough.pa, geo.cosp, geo.sinp, geo.area, sym)
    return fx + ax, fy + ay


@njit(cache=True)
def _rotor_block(data, pos_row, n, cj, rotor, geo, rough):
    """The rotor rows' own 4 x 4 block of ``dF/dy + cj dF/dy'`` with the contact stiffness in dF_V/d(X, Y)."""
    kappa, sym = rotor.force_group, rotor.sym
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    kxx = 0.0
    kxy = 0.0
    kyy = 0.0
    for i in range(n):
        g = kappa * sym * rough.dpa[i] * area[i]
        kxx += g * cosp[i] * cosp[i]
        kxy += g * cosp[i] * sinp[i]
        kyy += g * sinp[i] * sinp[i]
    for r in range(N_ROTOR):
        for e in range(N_ROTOR):
            data[pos_row[r, n + e]] = cj if r == e else (-1.0 if e == r + 2 else 0.0)
    data[pos_row[2, n]] = -kxx
    data[pos_row[2, n + 1]] = -kxy
    data[pos_row[3, n]] = -kxy
    data[pos_row[3, n + 1]] = -kyy


# ------------------------------------------------------------------------------------------------- IDA, universal
@njit(cache=True)
def rough_dae_residual(tau, y, yp, out, switch, rotor, geo, fields, fv, rough):
    """IDA residual of the rough film + rotor (module docstring); groove cells ``u' = 0``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    free = fv.cells.free
    n = free.size
    X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
    Xd, Yd = yp[n], yp[n + 1]
    rough_state_fields(y[:n], X, Y, switch, geo, fields, fv, rough)
    R = fields.R
    rough_flux(shaft_speed(tau, rough.knots)[0], y[:n], fields, fv, rough, R)
    C, D, hT, pc = fields.C, fields.D, rough.mean_gap, rough.phi_c
    for i in range(n):
        if free[i]:
            out[i] = area[i] * (hT[i] * D[i] * yp[i] + C[i] * pc[i] * (Xd * cosp[i] + Yd * sinp[i])) + R[i]
        else:
            out[i] = yp[i]
    fx, fy = rough_force(fields.P, geo, rough, rotor.sym)
    ax, ay = rough_accelerations(tau, fx, fy, rotor, rough.knots)
    out[n] = Xd - VX
    out[n + 1] = Yd - VY
    out[n + 2] = yp[n + 2] - ax
    out[n + 3] = yp[n + 3] - ay


@njit(cache=True)
def rough_dae_jacobian(tau, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, rough):
    """CSC data of ``dF/dy + cj dF/dy'`` for :func:`rough_dae_residual`::

        dF_i/du_i += A_i (h_T D'_i u_i' + D_i phi_c H'_i + cj h_T D_i)
        dF_i/dX   += A_i cos (phi_c D_i u_i' + theta_i phi_c' H'_i + cj theta_i phi_c)
        dF_VX/du_j = -kappa sym P'_j cos A_j,   dF_VX/dX = -kappa sym sum p_a' cos^2 A (contact stiffness)
    """
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    pos_row, pos_col = extras.pos_row, extras.pos_col
    free, pos_c = fv.cells.free, fv.cells.pos_c
    kappa, sym = rotor.force_group, rotor.sym
    n = free.size
    X, Y = y[n], y[n + 1]
    Xd, Yd = yp[n], yp[n + 1]
    rough_state_fields(y[:n], X, Y, switch, geo, fields, fv, rough)
    rough_flux_jacobian(shaft_speed(tau, rough.knots)[0], geo, fields, extras, fv, rough, data)
    C, D, dD, dP = fields.C, fields.D, fields.dD, fields.dP
    hT, pc, dpc = rough.mean_gap, rough.phi_c, rough.dphi_c
    for i in range(n):
        if free[i]:
            a = area[i]
            hd = Xd * cosp[i] + Yd * sinp[i]
            data[pos_c[i]] += a * (hT[i] * dD[i] * yp[i] + D[i] * pc[i] * hd + cj * hT[i] * D[i])
            b = a * (pc[i] * D[i] * yp[i] + C[i] * dpc[i] * hd + cj * C[i] * pc[i])
            data[pos_col[i, 0]] += b * cosp[i]
            data[pos_col[i, 1]] += b * sinp[i]
        else:
            data[pos_c[i]] = cj
        g = -kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i]
        data[pos_row[3, i]] = g * sinp[i]
    _rotor_block(data, pos_row, n, cj, rotor, geo, rough)


@njit(cache=True)
def rough_ode_rhs(tau, y, out, switch, rotor, geo, fields, fv, rough):
    """``y'`` of the universal state (the consistent start of IDA): ``u' = (-R / A - theta phi_c H') / (h_T D)``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    free = fv.cells.free
    n = free.size
    X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
    rough_state_fields(y[:n], X, Y, switch, geo, fields, fv, rough)
    R = fields.R
    rough_flux(shaft_speed(tau, rough.knots)[0], y[:n], fields, fv, rough, R)
    C, D = fields.C, fields.D
    for i in range(n):
        if free[i]:
            hd = VX * cosp[i] + VY * sinp[i]
            out[i] = (-R[i] / area[i] - C[i] * rough.phi_c[i] * hd) / (rough.mean_gap[i] * D[i])
        else:
            out[i] = 0.0
    fx, fy = rough_force(fields.P, geo, rough, rotor.sym)
    out[n] = VX
    out[n + 1] = VY
    out[n + 2], out[n + 3] = rough_accelerations(tau, fx, fy, rotor, rough.knots)


# ------------------------------------------------------------------------------------------------- content, BDF2
@njit(cache=True)
def rough_content_rhs(tau, y, out, switch, rotor, geo, fields, fv, work, rough):
    """``y'`` of the content state: ``m' = -R / A`` (free cells), 0 (groove), the rotor's."""
    area = geo.area
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    rough_content_universal(y, switch, geo, free, u_fixed, rough.sig, work.theta, work.u)
    rough_state_fields(as_read_only(work.u), y[n], y[n + 1], switch, geo, fields, fv, rough)
    R = fields.R
    rough_flux(shaft_speed(tau, rough.knots)[0], as_read_only(work.u), fields, fv, rough, R)
    for i in range(n):
        out[i] = -R[i] / area[i] if free[i] else 0.0
    fx, fy = rough_force(fields.P, geo, rough, rotor.sym)
    out[n] = y[n + 2]
    out[n + 1] = y[n + 3]
    out[n + 2], out[n + 3] = rough_accelerations(tau, fx, fy, rotor, rough.knots)
    work.xy[0] = np.nan  # the fields are this state's, not the Newton's last


def orbit_tribology(film, bearing, u, X, Y, speed_rpm) -> dict:
    """The friction torque on the journal [N m] (film shear at the shaft speed ``speed_rpm`` plus the boundary
    friction ``mu_b sum p_a dA``, as :meth:`RoughFilm.state <transient.models.journal.rough_film.RoughFilm.state>`),
    the asperity load [N] and the largest asperity pressure [Pa] of the film ``u`` at (X, Y)."""
    from transient.models.journal.film import film_geometry

    sc = film.scales
    film.residual(u, X, Y)
    h, G, _ = film_geometry(film, X, Y, film.P)
    theta = film.grid.to_2d(np.asarray(film.C, dtype=float))
    U = speed_rpm * math.pi / 30.0 * sc.radius
    lower = film.law.stresses(h, G, U, 0.0).lower_wall
    shear = float(-np.sum(lower * sc.sym * np.minimum(theta, 1.0) * film.grid.to_2d(film.area))) * sc.radius ** 2
    out = dict(friction_torque=sc.radius * shear, contact_load=0.0, contact_pressure=0.0)
    if getattr(film, "roughness", None) is not None:
        pa, _ = film.contact(X, Y)
        normal = sc.sym * float(pa @ film.area) * sc.radius ** 2
        Fc = film.contact_force(X, Y) * film.force_scale
        out.update(friction_torque=out["friction_torque"] + sc.radius * film.roughness.boundary_friction * normal,
                   contact_load=float(np.hypot(*Fc)), contact_pressure=float(np.max(pa)))
    return out
@njit(cache=True)
def rough_content_universal(y, switch, geo, free, u_fixed, sig, theta, u):
    """``theta = m / h_T(H)`` and ``u = C^-1(theta)`` of the free cells of the content state ``y`` (fixed cells:
    ``u_fixed``); ``sig = sigma / C``."""
    beta_bar, width, content_scale, layer_gap, darcy = switch
    cosp, sinp, area, gap0 = geo
    n = free.size
    X, Y = y[n], y[n + 1]
    for i in range(n):
        theta[i] = y[i] / mean_gap(gap0[i] + X * cosp[i] + Y * sinp[i], sig)
    elrod_inverse(theta, width, content_scale, beta_bar, u)
    for i in range(n):
        if not free[i]:
            u[i] = u_fixed[i]


@njit(cache=True)
def rough_bdf2_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the rough content film + rotor, iterating on
    ``[u, X, Y, VX, VY]`` (args: those of :mod:`~transient.models.journal.content_newton` and ``rough``)."""
    return newton_step(rough_bdf2_residual, rough_newton_jacobian, rough_newton_norm, rough_to_state,
                       rough_from_state, args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w,
                       state, counts)


drop_stale_cache(rough_bdf2_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined


@njit(cache=True)
def rough_fields_of(y, args):
    """The cell fields of the content state ``y`` (:func:`~transient.models.journal.content_newton.fields_of` with
    the content ``h_T C(u)``)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    C = fields.C
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    held = y[n] == work.xy[0] and y[n + 1] == work.xy[1]
    if held:
        for i in range(n):
            if free[i] and rough.mean_gap[i] * C[i] != y[i]:
                held = False
                break
    if not held:
        rough_content_universal(as_read_only(y), switch, geo, free, u_fixed, rough.sig, work.theta, work.u)
        rough_state_fields(as_read_only(work.u), y[n], y[n + 1], switch, geo, fields, fv, rough)
        work.xy[0] = y[n]
        work.xy[1] = y[n + 1]


@njit(cache=True)
def rough_bdf2_residual(t, y, yp, out, args):
    """``F = A m' + R(u(m))`` and the rotor rows (module docstring) at the content state ``y``."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    rough_fields_of(y, args)
    rough_flux(shaft_speed(t, rough.knots)[0], as_read_only(work.u), fields, fv, rough, fields.R)
    fx, fy = rough_force(fields.P, geo, rough, rotor.sym)
    ax, ay = rough_accelerations(t, fx, fy, rotor, rough.knots)
    content_rows_at(y, yp, out, geo.area, fields.R, fv.cells.free, ax, ay)


@njit(cache=True)
def rough_bdf2_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` in the Newton variables ``z = [u, X, Y, VX, VY]``
    (``m_j = h_T,j C(u_j)``)::

        dF_i/du_j = dR_i/du_j + delta_ij cj A_i h_T,i D_i,   dF_i/dX = dR_i/dX|_u + cj A_i theta_i phi_c,i cos
    and the rotor rows of :func:`rough_dae_jacobian`. Keeps the cells' regimes at this Jacobian."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    pos_row, pos_col = extras.pos_row, extras.pos_col
    free, pos_c = fv.cells.free, fv.cells.pos_c
    kappa, sym = rotor.force_group, rotor.sym
    n = free.size
    rough_fields_of(y, args)
    rough_flux_jacobian(shaft_speed(t, rough.knots)[0], geo, fields, extras, fv, rough, data)
    C, D, dP = fields.C, fields.D, fields.dP
    hT, pc = rough.mean_gap, rough.phi_c
    for i in range(n):
        if free[i]:
            a = cj * area[i]
            data[pos_c[i]] += a * hT[i] * D[i]
            data[pos_col[i, 0]] += a * C[i] * pc[i] * cosp[i]
            data[pos_col[i, 1]] += a * C[i] * pc[i] * sinp[i]
        else:
            data[pos_c[i]] = cj
        g = -kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i]
        data[pos_row[3, i]] = g * sinp[i]
        regime[i] = cell_regime(work.u[i], switch.width)
    _rotor_block(data, pos_row, n, cj, rotor, geo, rough)


@njit(cache=True)
def rough_newton_jacobian(t, y, yp, cj, data, args):
    """:func:`rough_bdf2_jacobian` in the problem's pattern (the operator's, or the decoupled one gathered from it:
    :func:`~transient.models.journal.content_newton.newton_jacobian`)."""
    work = args[6]
    rough_bdf2_jacobian(t, y, yp, cj, pattern_target(data, work), args)
    gather_pattern(data, work)


@njit(cache=True)
def rough_to_state(z, y, args):
    """The content state ``y`` of the Newton variables ``z``: ``m = h_T C(u)`` on the free cells."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    rough_state_fields(as_read_only(z[:n]), z[n], z[n + 1], switch, geo, fields, fv, rough)
    store_content(z, y, rough.mean_gap, fields.C, free, u_fixed, work)


@njit(cache=True)
def rough_from_state(y, z, args):
    """The inverse of :func:`rough_to_state`."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    rough_content_universal(as_read_only(y), switch, geo, free, u_fixed, rough.sig, work.theta, z[:n])
    keep_prescribed(y, z, free)


@njit(cache=True)
def rough_newton_norm(z, dz, args):
    """:func:`~transient.models.journal.content_newton.film_newton_norm` with the content ``h_T C(u)``."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime, rough = args
    return content_newton_norm(z, dz, rough.mean_gap, switch.width, fv.cells.free, fields.dP, fields.D, tol, regime)


class _StepLedger(BandNewton):
    """The BDF2 step solve of a rough orbit that, on every accepted step, evaluates the film's conservation law
    ``F_i = A_i m_i' + R_i`` at the step's state and content rate (:func:`step_mass_balance`)."""

    def __init__(self, model, pattern, n, rtol, atol, area, free):
        super().__init__(model, pattern, n, rtol, atol)
        self.area, self.free = area[free], free
        self.rows = []
        self.t_last = None

    def accepted(self, t, y):
        super().accepted(t, y)
        F = np.empty(y.size)
        rough_bdf2_residual(t, read_only(y), read_only(self.yp), F, self.model.args)
        if self.t_last is not None:
            h = t - self.t_last
            m = self.free.size
            cells = F[:m][self.free]
            rate = self.area * self.yp[:m][self.free]
            self.rows.append((t, h, h * abs(float(np.sum(cells))) / float(np.sum(self.area)),
                              h * float(np.max(np.abs(cells) / self.area)), h * float(np.sum(np.abs(rate)))
                              / float(np.sum(self.area))))
        self.t_last = t


def step_mass_balance(orbit, revolutions, y0=None, rtol=1e-6) -> dict:
    """The rough film's mass balance on every BDF2 step of ``revolutions`` of ``orbit`` (a rough
    :class:`~transient.models.journal.orbit.JournalOrbit`, from ``y0`` in the universal layout, default its initial
    state; its default BDF2 settings at ``rtol``).

    The step solves the conservation law of every free cell ``A_i m_i' + R_i = 0`` (module docstring: content
    ``m = (h_T / C) theta`` with the flow factors in the face fluxes ``R``) with ``m'`` the BDF formula's content rate,
    so ``h sum_i A_i m_i'`` is the step's content change (``sum A (m_n+1 - m_n)`` at first order) and ``h sum_i R_i``
    the net flux through the film's ends and feeds times the step (the faces between cells cancel in the sum).
    Returns per step: ``t`` [tau], ``h`` [tau], ``imbalance`` = ``h |sum_i F_i| / sum_i A_i`` (content change plus
    net outflow, per unit of film area, in the content's unit: compare with the Newton's content tolerance
    ``BDF2_FILM_TOL``), ``worst_cell`` = ``h max_i |F_i| / A_i`` and ``change`` = ``h sum_i |A_i m_i'| / sum_i A_i``
    (how much content moved in the step)."""
    from dataclasses import replace as _replace

    from transient.solvers.integrate import Steps, solve
    from transient.solvers.settings import Integration

    if orbit.rough is None:
        raise ValueError("step_mass_balance with roughness = None; allowed: a JournalOrbit of a rough bearing")
    f = orbit.film
    if orbit.speed_profile is not None:  # a function's knots over this run
        orbit._set_knots(orbit.speed_profile.knots(f.omega, orbit.speed_rpm, revolutions * 60.0 / orbit.speed_rpm))
    step = orbit._stepper(Integration(method="bdf2", rtol=rtol), "content", 0.0)  # the run's BDF2 settings
    y = orbit.content_state(orbit.initial_state() if y0 is None else np.asarray(y0, dtype=float))
    problem = step.problem_at(y, 0.0)
    model = step.options.pop("bdf2")
    ledger = _StepLedger(model, problem.jac_pattern, orbit.n, step.rtol, step.atol, f.area, f.op.free)
    sol = solve(_replace(problem, step_solve=ledger), np.array([0.0, 2 * np.pi * revolutions]), "bdf2", step.rtol,
                step.atol, steps=Steps(max_step=step.max_step, first_step=step.first_step), options=step.options)
    if not sol.success:
        raise RuntimeError(f"step_mass_balance: the run failed: {sol.message}")
    a = np.array(ledger.rows, dtype=float).reshape(-1, 5)
    return dict(t=a[:, 0], h=a[:, 1], imbalance=a[:, 2], worst_cell=a[:, 3], change=a[:, 4])
