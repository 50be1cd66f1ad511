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

from transient.models.journal.kernels import film_force, stencil_jacobian, stencil_residual


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
    src, dst, col_x, col_y, coupling, row_fx, row_fy, border = maps
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
