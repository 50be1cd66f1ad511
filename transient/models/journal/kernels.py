"""The discretised Elrod film of a plain journal bearing coupled to a rigid 2-DOF rotor (Rho & Kim).

Dimensionless groups (``R`` radius, ``C`` radial clearance, ``omega`` shaft speed)::

    H = h / C = 1 + X cos(phi) + Y sin(phi)        (paper eq. 3; X = x / C, Y = y / C)

(a tilted journal: ``gap0 + X cos + Y sin`` with the cells' ``gap0`` of :class:`~.scales.CellGeometry`,
:mod:`transient.models.journal.tilt`)
    tau = omega t,   zbar = z / R,   p = p_c + p0 P,   p0 = 6 mu omega (R / C)^2

``phi`` is measured from the top of the bearing (the oil groove, opposite the static load) in the
direction of rotation; the load acts in +x (towards phi = pi). This is the reading of the paper in
which eq. (3) and the printed signs of eqs. (7)-(10) agree (see docs/journal.md). The Elrod
conservation law (eq. 1 divided by ``C omega``) in each finite volume::

    A_i d(theta H)_i / dtau + R_i(u) = 0,   R_i = net outflow of  q = theta H / 2 e_phi - H^3 / 2 grad P

with one state ``u`` per cell, ``theta = C(u)``, ``D = dC/du`` (:mod:`transient.physics.cavitation`). The rotor
(paper eqs. 7-10; film force on the journal ``F = +int p (cos phi, sin phi) dA``)::

    X'' = kappa Fbar_x + Wbar + (e / C) cos(tau),   Y'' = kappa Fbar_y + (e / C) sin(tau)
    Fbar = sym * sum_i P_i (cos phi_i, sin phi_i) A_i,   kappa = p0 R^2 / (m C omega^2),
    Wbar = W / (m C omega^2),   sym = 2 on a half bearing (axial symmetry plane), else 1.

Two formulations, both with the analytic sparse "arrow" Jacobian (5-point stencil + 4 dense rows and
columns), filled by the numba kernels below into the CSC pattern of the film operator:

* ODE (CVODE, scipy):  ``u_i' = (-R_i / A_i - theta_i H_i') / (H_i D_i)``, ``H' = X' cos + Y' sin``;
* DAE residual (IDA):  ``A_i (H_i D_i u_i' + theta_i (X' cos + Y' sin)) + R_i = 0`` etc.

Groove cells are held at the supply pressure (``u' = 0``).
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.extending import overload

from transient.physics.cavitation import elrod_content, elrod_inverse, sharp_fixed_cells, softplus_pressure
from transient.fv.reynolds import jacobian_kernel, residual_kernel, scale_rows
from transient.solvers.read_only import as_read_only
from transient.models.journal.gecim_film import bulk_jacobian, bulk_residual

N_ROTOR = 4  # X, Y, VX, VY appended after the cells


@njit(cache=True)
def conductances(X, Y, cosp, sinp, gap0, layer_gap, darcy, H, k, c):
    """Film thickness ``H = gap0 + X cos + Y sin`` (``gap0`` = 1 for an aligned journal, :class:`~.scales.CellGeometry`), Poiseuille conductance ``k = (H - gap)^3/2 + darcy H`` and
    Couette coefficient ``c = H/2`` of every cell.

    ``gap = 2 delta / C`` and ``darcy = 3 alpha^2 mu_1 (1/mu_a + 1/mu_b) / C^2`` are the boundary layers of
    Jang with a Newtonian bulk (:func:`transient.physics.layered.newtonian_flow` in the journal's scales,
    p0 = 6 mu omega (R/C)^2): the bulk is ``H - gap`` thick, the layers add their Darcy flow; the Couette flux
    is ``H/2`` whatever the layers (they move with their walls). Without layers (0, 0) ``k = H^3/2``."""
    for i in range(H.size):
        h = gap0[i] + X * cosp[i] + Y * sinp[i]
        H[i] = h
        hb = h - layer_gap if h > layer_gap else 0.0
        k[i] = 0.5 * hb * hb * hb + darcy * h
        c[i] = 0.5 * h


@njit(cache=True)
def film_fields(u, X, Y, cosp, sinp, gap0, beta_bar, width, content_scale, layer_gap, darcy, H, P, dP, C, D, dD, k, c):
    """Cell fields at state ``u`` and journal position (X, Y): H, P(u), P', theta = C(u), D = C', D', k, c
    (:func:`conductances`)."""
    softplus_pressure(u, width, P, dP)
    elrod_content(u, P, dP, width, content_scale, beta_bar, C, D, dD)
    conductances(X, Y, cosp, sinp, gap0, layer_gap, darcy, H, k, c)


@njit(cache=True)
def position_derivatives(H, cosp, sinp, layer_gap, darcy, dk_dq, dc_dq):
    """d k / d(X, Y) = (1.5 (H - gap)^2 + darcy) (cos, sin) and d c / d(X, Y) = (cos, sin) / 2 (rows 0, 1;
    rows 2, 3 = 0)."""
    for i in range(H.size):
        hb = H[i] - layer_gap if H[i] > layer_gap else 0.0
        h2 = 1.5 * hb * hb + darcy
        dk_dq[0, i] = h2 * cosp[i]
        dk_dq[1, i] = h2 * sinp[i]
        dc_dq[0, i] = 0.5 * cosp[i]
        dc_dq[1, i] = 0.5 * sinp[i]


@njit(cache=True)
def film_force(P, cosp, sinp, area, sym):
    """Dimensionless film force on the journal, ``sym * sum P (cos, sin) A``."""
    fx = 0.0
    fy = 0.0
    for i in range(P.size):
        fx += P[i] * cosp[i] * area[i]
        fy += P[i] * sinp[i] * area[i]
    return sym * fx, sym * fy


@njit(cache=True)
def rotor_accelerations(tau, fx, fy, kappa, wbar, ebar):
    """The rotor equations (paper eqs. 7-10, dimensionless): ``(X'', Y'')`` for the film force (fx, fy),
    the static load ``wbar`` in +x and the unbalance ``ebar`` rotating with the shaft."""
    return kappa * fx + wbar + ebar * np.cos(tau), kappa * fy + ebar * np.sin(tau)


@njit(cache=True)
def shaft_accelerations(s, ds, phi, fx, fy, kappa, wbar, ebar):
    """:func:`rotor_accelerations` at a shaft speed that varies (:mod:`~transient.models.journal.speed_law`): speed
    ratio ``s``, its rate ``ds = ds/dtau`` and the shaft angle ``phi``; the unbalance force
    ``ebar (s^2 (cos, sin) + s' (sin, -cos))`` (at s = 1, s' = 0, phi = tau: :func:`rotor_accelerations` bit for bit)."""
    cp, sp = np.cos(phi), np.sin(phi)
    return kappa * fx + wbar + ebar * (s * s * cp + ds * sp), kappa * fy + ebar * (s * s * sp - ds * cp)


# A Newtonian film's ``fv.bulk`` is None: the three helpers below are typed on it, so numba compiles the Gecim
# flux (gecim_film, physics.layered) only into the kernels of a Gecim film.

def gecim_bulk(bulk):
    """True for the faces of a Gecim bulk (``fv.bulk``); False, at compile time, for None (Newtonian bulk)."""
    return bulk is not None and bulk.cells.shape[0] > 0


def add_bulk_residual(P, H, free, bulk, R):
    """:func:`~transient.models.journal.gecim_film.bulk_residual` of a Gecim bulk; nothing for None."""
    if gecim_bulk(bulk):
        bulk_residual(P, H, free, bulk, R)


def add_bulk_jacobian(P, dP, H, cosp, sinp, free, bulk, pos_col, n_extra, data):
    """:func:`~transient.models.journal.gecim_film.bulk_jacobian` of a Gecim bulk; nothing for None."""
    if gecim_bulk(bulk):
        bulk_jacobian(P, dP, H, cosp, sinp, free, bulk, pos_col, n_extra, data)


@overload(gecim_bulk, jit_options={"cache": True})
def _gecim_bulk(bulk):
    if isinstance(bulk, types.NoneType):
        return lambda bulk: False
    return lambda bulk: bulk.cells.shape[0] > 0


@overload(add_bulk_residual, jit_options={"cache": True})
def _add_bulk_residual(P, H, free, bulk, R):
    if isinstance(bulk, types.NoneType):
        return lambda P, H, free, bulk, R: None
    return add_bulk_residual


@overload(add_bulk_jacobian, jit_options={"cache": True})
def _add_bulk_jacobian(P, dP, H, cosp, sinp, free, bulk, pos_col, n_extra, data):
    if isinstance(bulk, types.NoneType):
        return lambda P, dP, H, cosp, sinp, free, bulk, pos_col, n_extra, data: None
    return add_bulk_jacobian


# Kernel arguments travel as named tuples grouped by lifetime (models/journal/scales.py; built once by
# :class:`~transient.models.journal.film.Film` and the orbit): ``switch`` (Switch, per speed), ``rotor`` (Rotor,
# per orbit), ``geo`` (CellGeometry, per grid), ``fields`` (Scratch), ``extras`` (RotorColumns), ``fv`` (Operator:
# the operator's face tables and the Gecim bulk's faces, None for a Newtonian bulk), ``work`` (ContentScratch).

@njit(cache=True)
def state_fields(u, X, Y, switch, geo, fields, fv):
    """:func:`film_fields` of the state, with the prescribed (groove) cells on the sharp Elrod curve."""
    beta_bar, width, content_scale, layer_gap, darcy = switch
    cosp, sinp, area, gap0 = geo
    H, P, dP, C, D, dD, k, c, zero, _ = fields
    film_fields(u, X, Y, cosp, sinp, gap0, beta_bar, width, content_scale, layer_gap, darcy, H, P, dP, C, D, dD, k, c)
    sharp_fixed_cells(fv.cells.free, fv.cells.u_fixed, beta_bar, P, dP, C, D, dD)


@njit(cache=True)
def stencil_residual(u, X, Y, switch, geo, fields, fv, R, speed_ratio):
    """The film's net outflow ``R`` at the position ``(X, Y)``, its Couette part scaled by ``speed_ratio``
    (``Omega / omega_ref``: 1 here, the shaft's speed function in :mod:`transient.models.rotor.kernels`)."""
    state_fields(u, X, Y, switch, geo, fields, fv)
    stencil_flux(u, fields, fv, R, speed_ratio)


@njit(cache=True)
def stencil_flux(u, fields, fv, R, speed_ratio):
    """:func:`stencil_residual` on the cell fields already in ``fields`` (those of ``u``, :func:`state_fields`)."""
    H, P, dP, C, D, dD, k, c, zero, _ = fields
    faces, boundary, cells, face_k, bulk = fv
    if gecim_bulk(bulk):  # the Poiseuille flux is the Gecim bulk's (gecim_film), not k grad P
        k[:] = 0.0
    if speed_ratio != 1.0:
        c *= speed_ratio
    residual_kernel(u, P, C, k, k, c, zero, True, faces, boundary, cells, face_k, R)
    add_bulk_residual(P, H, cells.free, bulk, R)


@njit(cache=True)
def stencil_jacobian(u, X, Y, switch, geo, fields, extras, fv, data, speed_ratio):
    """The Jacobian of :func:`stencil_residual` into the arrow pattern ``data`` (cell block, position columns)."""
    state_fields(u, X, Y, switch, geo, fields, fv)
    stencil_flux_jacobian(switch, geo, fields, extras, fv, data, speed_ratio)


@njit(cache=True)
def stencil_flux_jacobian(switch, geo, fields, extras, fv, data, speed_ratio):
    """:func:`stencil_jacobian` on the cell fields already in ``fields`` (:func:`state_fields`)."""
    layer_gap, darcy = switch.layer_gap, switch.darcy
    cosp, sinp = geo.cosp, geo.sinp
    H, P, dP, C, D, dD, k, c, zero, _ = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    if dk_dq.shape[0] > 0:
        position_derivatives(H, cosp, sinp, layer_gap, darcy, dk_dq, dc_dq)
    if gecim_bulk(bulk):
        k[:] = 0.0
        dk_dq[:] = 0.0
    if speed_ratio != 1.0:
        c *= speed_ratio
        dc_dq *= speed_ratio
    q = min(dk_dq.shape[0], 2)  # the stencil has no velocity terms: extra columns 2, 3 (VX, VY) stay zero
    jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq[:q], dk_dq[:q], dc_dq[:q], no_dq[:q], True,
                    faces, boundary, cells, face_k, pos_col, data)
    add_bulk_jacobian(P, dP, H, cosp, sinp, cells.free, bulk, pos_col, dk_dq.shape[0], data)


@njit(cache=True)
def ode_rhs(tau, y, out, switch, rotor, geo, fields, fv):
    """ODE right-hand side ``y' = f(tau, y)`` of the film + rotor (module docstring)."""
    ode_rhs_at(tau, y, out, switch, rotor, geo, fields, fv, 1.0, 0.0, tau)


@njit(cache=True)
def ode_rhs_at(tau, y, out, switch, rotor, geo, fields, fv, s, ds, phi):
    """:func:`ode_rhs` at the shaft speed ratio ``s``, rate ``ds`` and angle ``phi`` (:func:`shaft_accelerations`;
    the consistent start of the IDA problem of an orbit with a speed law)."""
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    free = fv.cells.free
    n = free.size
    X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
    stencil_residual(y[:n], X, Y, switch, geo, fields, fv, R, s)
    for i in range(n):
        if free[i]:
            out[i] = (-R[i] / area[i] - C[i] * (VX * cosp[i] + VY * sinp[i])) / (H[i] * D[i])
        else:
            out[i] = 0.0
    fx, fy = film_force(P, cosp, sinp, area, sym)
    out[n] = VX
    out[n + 1] = VY
    out[n + 2], out[n + 3] = shaft_accelerations(s, ds, phi, fx, fy, kappa, wbar, ebar)


@njit(cache=True)
def ode_jacobian(tau, y, data, f, switch, rotor, geo, fields, extras, fv):
    """CSC data of ``df/dy`` for :func:`ode_rhs`; ``f`` must hold ``f(tau, y)`` at the same state::

        df_i/du_j = -dR_i/du_j / (H_i D_i A_i) - delta_ij (H'_i / H_i + f_i D'_i / D_i)
        df_i/dX   = -dR_i/dX / (H_i D_i A_i) - f_i cos(phi_i) / H_i
        df_i/dVX  = -theta_i cos(phi_i) / (H_i D_i)                     (likewise Y, VY with sin)
        df_VX/du_j = kappa sym P'(u_j) cos(phi_j) A_j,  df_X/dVX = 1
    """
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    free, u_fixed, pos_c = fv.cells
    n = free.size
    X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
    stencil_jacobian(y[:n], X, Y, switch, geo, fields, extras, fv, data, 1.0)
    for i in range(n):
        scale[i] = -1.0 / (H[i] * D[i] * area[i]) if free[i] else 0.0
    scale_rows(data, indices, scale)  # rotor rows: scale 1 (they are filled below)
    for i in range(n):
        if free[i]:
            hd = VX * cosp[i] + VY * sinp[i]
            data[pos_c[i]] -= hd / H[i] + f[i] * dD[i] / D[i]
            data[pos_col[i, 0]] -= f[i] * cosp[i] / H[i]
            data[pos_col[i, 1]] -= f[i] * sinp[i] / H[i]
            b = C[i] / (H[i] * D[i])
            data[pos_col[i, 2]] = -b * cosp[i]
            data[pos_col[i, 3]] = -b * sinp[i]
        g = kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i]
        data[pos_row[3, i]] = g * sinp[i]
    data[pos_row[0, n + 2]] = 1.0
    data[pos_row[1, n + 3]] = 1.0


@njit(cache=True)
def dae_residual(tau, y, yp, out, switch, rotor, geo, fields, fv):
    """IDA residual ``F(tau, y, y')`` of the film + rotor (module docstring); groove cells: ``u' = 0``."""
    dae_residual_at(tau, y, yp, out, switch, rotor, geo, fields, fv, 1.0, 0.0, tau)


@njit(cache=True)
def dae_residual_at(tau, y, yp, out, switch, rotor, geo, fields, fv, s, ds, phi):
    """:func:`dae_residual` at the shaft speed ratio ``s``, rate ``ds`` and angle ``phi``: the Couette flux times
    ``s``, the unbalance of :func:`shaft_accelerations`."""
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    free = fv.cells.free
    n = free.size
    X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
    Xd, Yd = yp[n], yp[n + 1]
    stencil_residual(y[:n], X, Y, switch, geo, fields, fv, R, s)
    for i in range(n):
        if free[i]:
            out[i] = area[i] * (H[i] * D[i] * yp[i] + C[i] * (Xd * cosp[i] + Yd * sinp[i])) + R[i]
        else:
            out[i] = yp[i]
    fx, fy = film_force(P, cosp, sinp, area, sym)
    ax, ay = shaft_accelerations(s, ds, phi, fx, fy, kappa, wbar, ebar)
    out[n] = Xd - VX
    out[n + 1] = Yd - VY
    out[n + 2] = yp[n + 2] - ax
    out[n + 3] = yp[n + 3] - ay


@njit(cache=True)
def dae_jacobian(tau, y, yp, cj, data, switch, rotor, geo, fields, extras, fv):
    """CSC data of ``dF/dy + cj dF/dy'`` for :func:`dae_residual`::

        dF_i/du_i += A_i (H_i D'_i u_i' + D_i H'_i + cj H_i D_i),   dF_i/dX += A_i cos (D_i u_i' + cj theta_i)
        dF_VX/du_j = -kappa sym P'(u_j) cos(phi_j) A_j,  dF_X/dX = cj,  dF_X/dVX = -1,  dF_VX/dVX = cj
    """
    dae_jacobian_at(tau, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, 1.0)


@njit(cache=True)
def dae_jacobian_at(tau, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, s):
    """:func:`dae_jacobian` of :func:`dae_residual_at` at the speed ratio ``s`` (the unbalance depends on no state)."""
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    free, u_fixed, pos_c = fv.cells
    n = free.size
    X, Y = y[n], y[n + 1]
    Xd, Yd = yp[n], yp[n + 1]
    stencil_jacobian(y[:n], X, Y, switch, geo, fields, extras, fv, data, s)
    for i in range(n):
        if free[i]:
            a = area[i]
            data[pos_c[i]] += a * (H[i] * dD[i] * yp[i] + D[i] * (Xd * cosp[i] + Yd * sinp[i]) + cj * H[i] * D[i])
            data[pos_col[i, 0]] += a * cosp[i] * (D[i] * yp[i] + cj * C[i])
            data[pos_col[i, 1]] += a * sinp[i] * (D[i] * yp[i] + cj * C[i])
        else:
            data[pos_c[i]] = cj
        g = -kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i]
        data[pos_row[3, i]] = g * sinp[i]
    data[pos_row[0, n]] = cj
    data[pos_row[0, n + 2]] = -1.0
    data[pos_row[1, n + 1]] = cj
    data[pos_row[1, n + 3]] = -1.0
    data[pos_row[2, n + 2]] = cj
    data[pos_row[3, n + 3]] = cj


@njit(cache=True)
def film_residual(u, X, Y, VX, VY, rate, C_ref, out, switch, geo, fields, fv):
    """Film equations for a prescribed journal motion (steady solves and the RK4 baseline)::

        G_i = R_i + A_i (theta_i H'_i + rate H_i (theta_i - theta_ref,i)),   H' = VX cos + VY sin

    ``rate = 0``: quasi-steady film (the steady state when VX = VY = 0); ``rate = 1/dtau``: one
    backward-Euler step of length dtau from the content ``theta_ref`` (Elrod's time discretisation,
    used per RK4 stage, and the pseudo-time steps of the steady solver).
    """
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    free = fv.cells.free
    stencil_residual(u, X, Y, switch, geo, fields, fv, out, 1.0)
    for i in range(u.size):
        if free[i]:
            out[i] += area[i] * (C[i] * (VX * cosp[i] + VY * sinp[i]) + rate * H[i] * (C[i] - C_ref[i]))


@njit(cache=True)
def film_jacobian(u, X, Y, VX, VY, rate, data, switch, geo, fields, extras, fv):
    """CSC data of ``dG/du`` for :func:`film_residual`, and -- if the operator has 4 extra unknowns --
    ``dG/dX, dG/dY`` (rate = 0 only) and ``dG/dVX, dG/dVY = A theta (cos, sin)`` in the extra columns."""
    stencil_jacobian(u, X, Y, switch, geo, fields, extras, fv, data, 1.0)
    film_columns(VX, VY, rate, geo, fields, extras, fv, data)


@njit(cache=True)
def film_columns(VX, VY, rate, geo, fields, extras, fv, data):
    """:func:`film_jacobian`'s entries on top of the flux columns: the storage ``A_i (D_i H'_i + rate H_i D_i)`` on
    the free cells' diagonal and, with 4 extra unknowns, ``dG/dVX, dG/dVY = A theta (cos, sin)``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, C, D = fields.H, fields.C, fields.D
    pos_col = extras.pos_col
    free, pos_c = fv.cells.free, fv.cells.pos_c
    ne = extras.dk_dq.shape[0]
    for i in range(free.size):
        if free[i]:
            data[pos_c[i]] += area[i] * (D[i] * (VX * cosp[i] + VY * sinp[i]) + rate * H[i] * D[i])
            if ne > 0:
                data[pos_col[i, 2]] = area[i] * C[i] * cosp[i]
                data[pos_col[i, 3]] = area[i] * C[i] * sinp[i]


# --------------------------------------------------------------------------------------------------
# Content formulation: the film state is the content m_i = H_i theta_i of each cell (conservative)
# --------------------------------------------------------------------------------------------------
#   work = (u, theta, E, ux, uy, indptr): scratch for the universal variable of the cells, theta = m / H,
#          du/dm, du/dX, du/dY, and the CSC column pointers of the pattern.
# The state is [m (cells), X, Y, VX, VY]; fixed (groove) cells keep their prescribed u and a constant m.
# The universal variable u = C^-1(m / H) of the free cells is found cell by cell (physics.cavitation
# .elrod_inverse), so the residual is the conservation law itself, linear in m':
#
#     F_i = A_i m_i' + R_i(u(m, X, Y), X, Y)                     (IDA)
#     m_i' = -R_i / A_i                                         (ODE methods)
#
# A cell that fills or empties inside one step then changes its mass by exactly what flowed in; in the
# universal form ``A H D(u) u'`` the BDF step multiplies the jump of u by the slope D at the step's end
# (which changes by r beta_bar across the switch) and only the error test, holding every crossing to
# the tolerance, kept that mass error small (docs/journal.md, section 5).

H_FLOOR = 1e-9  # film thickness / C below which theta = m / H is not divided further (Newton iterates past a touch)


@njit(cache=True)
def content_universal(y, switch, geo, free, u_fixed, theta, u):
    """theta = m / H and the universal variable u = C^-1(theta) of the free cells (fixed cells: u_fixed)."""
    beta_bar, width, content_scale, layer_gap, darcy = switch
    cosp, sinp, area, gap0 = geo
    n = free.size
    X, Y = y[n], y[n + 1]
    for i in range(n):
        h = gap0[i] + X * cosp[i] + Y * sinp[i]
        theta[i] = y[i] / (h if h > H_FLOOR else H_FLOOR)
    elrod_inverse(theta, width, content_scale, beta_bar, u)
    for i in range(n):
        if not free[i]:
            u[i] = u_fixed[i]


@njit(cache=True)
def _content_film(y, switch, geo, fields, fv, work, sym):
    """The film of a content state: u = C^-1(m / H), the stencil residual R (in ``fields``) and the force."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    P, R = fields.P, fields.R
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    u, theta = work.u, work.theta
    n = free.size
    content_universal(y, switch, geo, free, u_fixed, theta, u)
    stencil_residual(as_read_only(u), y[n], y[n + 1], switch, geo, fields, fv, R, 1.0)
    return film_force(P, cosp, sinp, area, sym)


@njit(cache=True)
def content_residual(tau, y, yp, out, switch, rotor, geo, fields, fv, work):
    """IDA residual of the content formulation (block comment above); groove cells: ``m' = 0``."""
    fx, fy = _content_film(y, switch, geo, fields, fv, work, rotor.sym)
    content_rows(tau, y, yp, out, rotor, geo.area, fields.R, fv.cells.free, fx, fy)


@njit(cache=True)
def content_rows(tau, y, yp, out, rotor, area, R, free, fx, fy):
    """The rows of :func:`content_residual` from the film's net outflow ``R`` and force ``(fx, fy)``."""
    kappa, wbar, ebar, sym = rotor
    ax, ay = rotor_accelerations(tau, fx, fy, kappa, wbar, ebar)
    content_rows_at(y, yp, out, area, R, free, ax, ay)


@njit(cache=True)
def content_rows_at(y, yp, out, area, R, free, ax, ay):
    """The content residual's rows ``A_i m_i' + R_i`` (free cells; ``m_i'`` on groove cells) and the rotor's,
    ``X' - VX``, ``Y' - VY``, ``VX' - ax``, ``VY' - ay``, at the journal's accelerations ``(ax, ay)``."""
    n = free.size
    for i in range(n):
        out[i] = area[i] * yp[i] + R[i] if free[i] else yp[i]
    out[n] = yp[n] - y[n + 2]
    out[n + 1] = yp[n + 1] - y[n + 3]
    out[n + 2] = yp[n + 2] - ax
    out[n + 3] = yp[n + 3] - ay


@njit(cache=True)
def content_rhs(tau, y, out, switch, rotor, geo, fields, fv, work):
    """ODE right-hand side of the content formulation: ``m' = -R / A`` (free cells), 0 (groove), rotor."""
    kappa, wbar, ebar, sym = rotor
    area = geo.area
    R = fields.R
    free = fv.cells.free
    n = free.size
    fx, fy = _content_film(y, switch, geo, fields, fv, work, sym)
    for i in range(n):
        out[i] = -R[i] / area[i] if free[i] else 0.0
    out[n] = y[n + 2]
    out[n + 1] = y[n + 3]
    out[n + 2], out[n + 3] = rotor_accelerations(tau, fx, fy, kappa, wbar, ebar)


@njit(cache=True)
def content_jacobian(tau, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, work):
    """CSC data of ``dF/dy + cj dF/dy'`` for :func:`content_residual`. With ``E_j = du_j/dm_j = 1 / (H_j D_j)``
    and ``du_j/dX = -theta_j cos(phi_j) / D_j`` / H_j (at fixed m)::

        dF_i/dm_j = dR_i/du_j E_j + delta_ij cj A_i,   dF_i/dX = dR_i/dX|_u + sum_j dR_i/du_j du_j/dX
        dF_VX/dm_j = -kappa sym P'_j A_j cos(phi_j) E_j,  dF_VX/dX = -kappa sym sum_j P'_j A_j cos(phi_j) du_j/dX
    """
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    free, u_fixed, pos_c = fv.cells
    u, theta, E, ux, uy, indptr = work.u, work.theta, work.E, work.ux, work.uy, work.indptr
    n = free.size
    content_universal(y, switch, geo, free, u_fixed, theta, u)
    stencil_jacobian(as_read_only(u), y[n], y[n + 1], switch, geo, fields, extras, fv, data, 1.0)
    for j in range(n):
        h = H[j]
        if free[j] and h > H_FLOOR:
            E[j] = 1.0 / (h * D[j])
            ux[j] = -C[j] * cosp[j] * E[j]
            uy[j] = -C[j] * sinp[j] * E[j]
        elif free[j]:
            E[j] = 1.0 / (H_FLOOR * D[j])
            ux[j] = 0.0
            uy[j] = 0.0
        else:
            E[j] = 0.0
            ux[j] = 0.0
            uy[j] = 0.0
    for j in range(n):  # chain rule through u(m, X, Y), column by column of the stencil block
        for p in range(indptr[j], indptr[j + 1]):
            i = indices[p]
            if i < n:
                if free[i]:
                    data[pos_col[i, 0]] += data[p] * ux[j]
                    data[pos_col[i, 1]] += data[p] * uy[j]
                    data[p] *= E[j]
                else:
                    data[p] = 0.0
    gxx = 0.0
    gxy = 0.0
    gyx = 0.0
    gyy = 0.0
    for i in range(n):
        if free[i]:
            data[pos_c[i]] += cj * area[i]
        else:
            data[pos_c[i]] = cj
            data[pos_col[i, 0]] = 0.0
            data[pos_col[i, 1]] = 0.0
        g = -kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i] * E[i]
        data[pos_row[3, i]] = g * sinp[i] * E[i]
        gxx += g * cosp[i] * ux[i]
        gxy += g * cosp[i] * uy[i]
        gyx += g * sinp[i] * ux[i]
        gyy += g * sinp[i] * uy[i]
    data[pos_row[0, n]] = cj
    data[pos_row[0, n + 1]] = 0.0
    data[pos_row[0, n + 2]] = -1.0
    data[pos_row[0, n + 3]] = 0.0
    data[pos_row[1, n]] = 0.0
    data[pos_row[1, n + 1]] = cj
    data[pos_row[1, n + 2]] = 0.0
    data[pos_row[1, n + 3]] = -1.0
    data[pos_row[2, n]] = gxx
    data[pos_row[2, n + 1]] = gxy
    data[pos_row[2, n + 2]] = cj
    data[pos_row[2, n + 3]] = 0.0
    data[pos_row[3, n]] = gyx
    data[pos_row[3, n + 1]] = gyy
    data[pos_row[3, n + 2]] = 0.0
    data[pos_row[3, n + 3]] = cj


@njit(cache=True)
def content_ode_jacobian(tau, y, data, switch, rotor, geo, fields, extras, fv, work):
    """CSC data of ``df/dy`` for :func:`content_rhs`: ``-diag(1/A, 1, 1, 1, 1)`` times the residual Jacobian
    at ``cj = 0`` (groove rows zero)."""
    free = fv.cells.free
    indices, scale = extras.indices, extras.scale
    n = free.size
    content_jacobian(tau, y, y, 0.0, data, switch, rotor, geo, fields, extras, fv, work)
    area = geo.area
    for i in range(n):
        scale[i] = -1.0 / area[i] if free[i] else 0.0
    for i in range(n, scale.size):
        scale[i] = -1.0
    scale_rows(data, indices, scale)
    for i in range(n, scale.size):
        scale[i] = 1.0
