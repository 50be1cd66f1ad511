"""The numba kernels of one film block of a rotor-bearing system: the Elrod film of a journal bearing
(:mod:`transient.models.journal.kernels`, its dimensionless groups) driven by the motion of its rotor node,
and the scatter of its Jacobian into the system's block-arrow matrix.

The film block of bearing ``b`` in the IDA residual form, at the node's dimensionless position ``(X, Y)`` and
velocity ``(X', Y')`` (clearance ``C_b``, time ``tau = omega_ref t``)::

    A_i (H_i D_i u_i' + theta_i (X' cos phi_i + Y' sin phi_i)) + R_i(u; s) = 0,      groove cells: u_i' = 0

with the Couette part of the net outflow ``R_i`` scaled by the speed ratio ``s = Omega(t) / omega_ref`` (the
pressure stays in the reference unit ``p0 = 6 mu omega_ref (R/C)^2``): at ``s = 1`` this is the residual of
:func:`~transient.models.journal.kernels.dae_residual`, term by term. The film force on the journal is
``Fbar = sym sum_i P_i (cos phi_i, sin phi_i) A_i`` (force unit ``p0 R^2``).
"""

from __future__ import annotations

from numba import njit

from transient.fv.reynolds import jacobian_kernel
from transient.models.journal.kernels import film_force, state_fields, stencil_jacobian, stencil_residual


@njit(cache=True)
def block_residual(u, up, X, Y, Xd, Yd, s, out, switch, geo, fields, fv, sym):
    """The film block's residual (module docstring) into ``out``; returns the film force ``(Fx, Fy)``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    free = fv.cells.free
    stencil_residual(u, X, Y, switch, geo, fields, fv, R, s)
    for i in range(free.size):
        if free[i]:
            out[i] = area[i] * (H[i] * D[i] * up[i] + C[i] * (Xd * cosp[i] + Yd * sinp[i])) + R[i]
        else:
            out[i] = up[i]
    return film_force(P, cosp, sinp, area, sym)


@njit(cache=True)
def block_jacobian(u, up, X, Y, Xd, Yd, s, cj, local, switch, geo, fields, extras, fv, sym):
    """``dF/du + cj dF/du'`` of :func:`block_residual` in the film's own arrow pattern (``local``): the cell
    block, ``dF_i/dX`` and ``dF_i/dY`` (``cj`` terms of ``X'``, ``Y'`` included) in extra columns 0 and 1, and
    the force derivatives ``dFx/du_j``, ``dFy/du_j`` in extra rows 2 and 3."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    pos_row, pos_col = extras.pos_row, extras.pos_col
    free, u_fixed, pos_c = fv.cells
    stencil_jacobian(u, X, Y, switch, geo, fields, extras, fv, local, s)
    for i in range(free.size):
        if free[i]:
            a = area[i]
            local[pos_c[i]] += a * (H[i] * dD[i] * up[i] + D[i] * (Xd * cosp[i] + Yd * sinp[i]) + cj * H[i] * D[i])
            local[pos_col[i, 0]] += a * cosp[i] * (D[i] * up[i] + cj * C[i])
            local[pos_col[i, 1]] += a * sinp[i] * (D[i] * up[i] + cj * C[i])
        else:
            local[pos_c[i]] = cj
        g = sym * dP[i] * area[i]
        local[pos_row[2, i]] = g * cosp[i]
        local[pos_row[3, i]] = g * sinp[i]


@njit(cache=True)
def scatter_block(local, data, maps, ax, ay, gx, gy):
    """The film block's ``local`` Jacobian into the system's CSC ``data`` (positions in ``maps``, a
    :class:`~transient.models.rotor.model.BlockMaps`): the cell block as it is, the coupling of the free cells to the rotor
    coordinates ``dF_i/dq_j = dF_i/dX ax_j + dF_i/dY ay_j`` (``X = ax . q``), and the border
    ``dF_r/du_i = -(gx_r dFx/du_i + gy_r dFy/du_i)`` (the force enters rotor row ``r`` as ``gx_r Fx + gy_r Fy``)."""
    src, dst, col_x, col_y, coupling, row_fx, row_fy, border = maps[:8]
    for p in range(src.size):
        data[dst[p]] = local[src[p]]
    for i in range(col_x.size):
        lx = local[col_x[i]]
        ly = local[col_y[i]]
        for j in range(ax.size):
            data[coupling[i, j]] = lx * ax[j] + ly * ay[j]
    for i in range(row_fx.size):
        fx = local[row_fx[i]]
        fy = local[row_fy[i]]
        for r in range(gx.size):
            data[border[i, r]] = -(gx[r] * fx + gy[r] * fy)


# --------------------------------------------------------------------------------------------------
# A film block that feels its node's tilts (RotorBearingSystem(tilt_coupling=True); transient.models.journal.tilt)
# --------------------------------------------------------------------------------------------------
#   The node's tilts enter the gap as the tilt groups (A, B) = (t_y, -t_x) R / C on top of the bush's static ones
#   (in ``gap_static``): H_i = gap_static_i + A zcos_i + B zsin_i + X cos_i + Y sin_i with zcos = zbar cos phi,
#   zsin = zbar sin phi, so the film sees four "positions" (X, Y, A, B) with the geometry rows (cos, sin, zcos,
#   zsin): their rates in the squeeze term, their forces (Fx, Fy, Fa, Fb) = sym sum P (cos, sin, zcos, zsin) A
#   (Fa, Fb: the forces conjugate to A, B; the moments M_x = -p0 R^3 Fb, M_y = p0 R^3 Fa). ``tilt`` = (gap_static,
#   zcos, zsin, zbar, held): ``held`` the (A, B) the film's ``gap0`` is of.


@njit(cache=True)
def tilt_gap(gap0, tilt, A, B):
    """The gap of the centred journal at the tilt groups (A, B) into ``gap0`` (``gap_static`` itself, bitwise, at
    A = B = 0), and (A, B) into ``held``."""
    gap_static, zcos, zsin, zbar, held = tilt
    for i in range(gap0.size):
        gap0[i] = gap_static[i] + (A * zcos[i] + B * zsin[i])
    held[0] = A
    held[1] = B


@njit(cache=True)
def tilted_block_residual(u, up, X, Y, A, B, Xd, Yd, Ad, Bd, s, out, switch, geo, fields, fv, sym, tilt):
    """:func:`block_residual` of a block at the tilt groups (A, B) with their rates (Ad, Bd) in the squeeze term
    (block comment above); returns ``(Fx, Fy, Fa, Fb)``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    zcos, zsin = tilt[1], tilt[2]
    free = fv.cells.free
    tilt_gap(geo.gap0, tilt, A, B)
    stencil_residual(u, X, Y, switch, geo, fields, fv, R, s)
    for i in range(free.size):
        if free[i]:
            out[i] = area[i] * (H[i] * D[i] * up[i] + C[i] * ((Xd * cosp[i] + Yd * sinp[i])
                                                             + (Ad * zcos[i] + Bd * zsin[i]))) + R[i]
        else:
            out[i] = up[i]
    fx, fy = film_force(P, cosp, sinp, area, sym)
    fa, fb = film_force(P, zcos, zsin, area, sym)
    return fx, fy, fa, fb


@njit(cache=True)
def tilted_block_jacobian(u, up, X, Y, A, B, Xd, Yd, Ad, Bd, s, cj, local, switch, geo, fields, extras, fv, sym,
                          tilt):
    """``dF/du + cj dF/du'`` of :func:`tilted_block_residual` in the film's arrow pattern (``local``): the cell
    block, ``dF_i/d(X, Y, A, B)`` (their rates' ``cj`` terms included) in extra columns 0 to 3, the force
    derivatives ``dFx/du_j``, ``dFy/du_j`` in extra rows 2, 3 and ``dFa/du_j``, ``dFb/du_j`` in rows 0, 1 (the
    Newtonian flux: a Gecim bulk's tilt columns are not written)."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    free, u_fixed, pos_c = cells
    layer_gap, darcy = switch.layer_gap, switch.darcy
    zcos, zsin = tilt[1], tilt[2]
    tilt_gap(geo.gap0, tilt, A, B)
    state_fields(u, X, Y, switch, geo, fields, fv)
    for i in range(free.size):  # d k / d(X, Y, A, B), d c / d(...) (kernels.position_derivatives, four rows)
        hb = H[i] - layer_gap if H[i] > layer_gap else 0.0
        h2 = 1.5 * hb * hb + darcy
        dk_dq[0, i] = h2 * cosp[i]
        dk_dq[1, i] = h2 * sinp[i]
        dk_dq[2, i] = h2 * zcos[i]
        dk_dq[3, i] = h2 * zsin[i]
        dc_dq[0, i] = 0.5 * cosp[i]
        dc_dq[1, i] = 0.5 * sinp[i]
        dc_dq[2, i] = 0.5 * zcos[i]
        dc_dq[3, i] = 0.5 * zsin[i]
    if s != 1.0:  # as stencil_flux_jacobian: the same rounding as the untilted block
        c *= s
        dc_dq *= s
    jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq, dk_dq, dc_dq, no_dq, True, faces, boundary, cells,
                    face_k, pos_col, local)
    for i in range(free.size):
        if free[i]:
            a = area[i]
            local[pos_c[i]] += a * (H[i] * dD[i] * up[i] + D[i] * ((Xd * cosp[i] + Yd * sinp[i])
                                                                  + (Ad * zcos[i] + Bd * zsin[i])) + cj * H[i] * D[i])
            w = D[i] * up[i] + cj * C[i]  # in block_jacobian's order of operations
            local[pos_col[i, 0]] += a * cosp[i] * w
            local[pos_col[i, 1]] += a * sinp[i] * w
            local[pos_col[i, 2]] += a * zcos[i] * w
            local[pos_col[i, 3]] += a * zsin[i] * w
        else:
            local[pos_c[i]] = cj
        g = sym * dP[i] * area[i]
        local[pos_row[2, i]] = g * cosp[i]
        local[pos_row[3, i]] = g * sinp[i]
        local[pos_row[0, i]] = g * zcos[i]
        local[pos_row[1, i]] = g * zsin[i]


@njit(cache=True)
def scatter_tilted_block(local, data, maps, ax, ay, aa, ab, gx, gy, ga, gb):
    """:func:`scatter_block` of a tilted block: the coupling ``dF_i/dq_j = sum_k dF_i/dp_k a_k,j`` over the four
    positions ``p = (X, Y, A, B) = (ax, ay, aa, ab) . q``, the border ``-(gx Fx + gy Fy + ga Fa + gb Fb)_u``."""
    src, dst, col_x, col_y, coupling, row_fx, row_fy, border, col_a, col_b, row_fa, row_fb = maps
    for p in range(src.size):
        data[dst[p]] = local[src[p]]
    for i in range(col_x.size):
        lx = local[col_x[i]]
        ly = local[col_y[i]]
        la = local[col_a[i]]
        lb = local[col_b[i]]
        for j in range(ax.size):
            data[coupling[i, j]] = lx * ax[j] + ly * ay[j] + la * aa[j] + lb * ab[j]
    for i in range(row_fx.size):
        fx = local[row_fx[i]]
        fy = local[row_fy[i]]
        fa = local[row_fa[i]]
        fb = local[row_fb[i]]
        for r in range(gx.size):
            data[border[i, r]] = -(gx[r] * fx + gy[r] * fy + ga[r] * fa + gb[r] * fb)
