"""The rotor system's content formulation with thermal films (:mod:`~transient.models.rotor.thermal_films`): the
kernels of :mod:`~transient.models.rotor.content_newton` with the Poiseuille conductances of each thermal film
times its frozen fluidity ``f_i = mu_ref / mu(T_i)`` (:mod:`~transient.models.journal.viscous_film`)::

    k_i = f_i (H_i^3 / 2 + darcy H_i),   dk_i/dX = f_i (3/2 H_i^2 + darcy) cos phi_i  (Y: sin phi_i)

The residual is :func:`~transient.models.rotor.content_newton.rotor_residual`'s, one pass over the films with each
thermal film's conductances scaled before its net outflow (:func:`~transient.models.journal.kernels.stencil_flux`).
The film force depends on the pressures alone and the rotor rows on the force: the Jacobian is
:func:`~transient.models.rotor.content_newton.rotor_jacobian`'s with each thermal film's block written again on its
fields with the fluidity (that of :func:`~transient.models.rotor.kernels.block_jacobian` at the content form's
``u' = X' = Y' = 0``, scattered with its coupling and border again). A fluidity of ones gives the isothermal
system's numbers bit for bit.

``args = ((films, rotor), fluidity, thermal, which)``: the rotor system's kernel arguments, a tuple of fluidity
arrays, the indices of the thermal films among ``films`` and, per film, its index in ``fluidity`` (-1: isothermal).
Untilted blocks only (the thermal rotor refuses ``tilt_coupling``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

import transient.models.rotor.content_newton as rotor_content
import transient.solvers.integrate.bdf2 as stepper
from transient.fv.reynolds import jacobian_kernel
from transient.models.journal.kernels import film_force, position_derivatives, state_fields, stencil_flux
from transient.models.rotor.content_newton import (block_fields, block_gap, node_position, rotor_force,
                                                   rotor_from_state, rotor_jacobian, rotor_norm,
                                                   rotor_rows_residual, rotor_to_state)
from transient.models.rotor.kernels import scatter_block
from transient.solvers.integrate.bdf2 import newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.read_only import as_read_only


@njit(cache=True)
def thermal_block_jacobian(u, X, Y, s, cj, local, switch, geo, fields, extras, fv, sym, fluidity):
    """``dF/dz`` of a thermal film block of the content form into its arrow pattern ``local``: the cell block,
    ``dF_i/dX``, ``dF_i/dY`` (extra columns 0, 1), ``dFx/du_j``, ``dFy/du_j`` (extra rows 2, 3) -- as
    :func:`~transient.models.rotor.kernels.block_jacobian` at ``u' = X' = Y' = 0`` with the conductances and their
    position derivatives times ``fluidity`` and the Couette coefficients times ``s``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    free, u_fixed, pos_c = cells
    state_fields(u, X, Y, switch, geo, fields, fv)
    position_derivatives(H, cosp, sinp, switch.layer_gap, switch.darcy, dk_dq, dc_dq)
    for i in range(free.size):
        k[i] *= fluidity[i]
        c[i] *= s
        for e in range(2):
            dk_dq[e, i] *= fluidity[i]
            dc_dq[e, i] *= s
    jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq[:2], dk_dq[:2], dc_dq[:2], no_dq[:2], True,
                    faces, boundary, cells, face_k, pos_col, local)
    for i in range(free.size):
        if free[i]:
            a = area[i]
            local[pos_c[i]] += a * (cj * H[i] * D[i])
            local[pos_col[i, 0]] += a * cosp[i] * (cj * C[i])
            local[pos_col[i, 1]] += a * sinp[i] * (cj * C[i])
        else:
            local[pos_c[i]] = cj
        g = sym * dP[i] * area[i]
        local[pos_row[2, i]] = g * cosp[i]
        local[pos_row[3, i]] = g * sinp[i]


@njit(cache=True)
def thermal_rotor_residual(t, y, yp, out, args):
    """:func:`~transient.models.rotor.content_newton.rotor_residual` with each thermal film's conductances times its
    fluidity before its net outflow (module docstring): one pass over the films, the rotor rows its :func:`~transient.models.rotor.content_newton.rotor_rows_residual`."""
    base, fluidity, thermal, which = args
    films, rot = base
    s = rot.speed[0]
    rotor_force(y, rot)
    frc = rot.force
    q = y[rot.Q0:rot.V0]
    for b in range(len(films)):
        f = films[b]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)
        block_fields(y, f, X, Y, block_gap(f, q))
        R, k = fields.R, fields.k
        j = which[b]
        if j >= 0:
            flu = fluidity[j]
            for i in range(k.size):
                k[i] *= flu[i]
        sb = s * f.spin
        stencil_flux(as_read_only(work.u), fields, fv, R, sb)
        if sb != 1.0 or j >= 0:
            work.xy[0] = np.nan  # the coefficients are scaled now: not the fields of this state
        fx, fy = film_force(fields.P, geo.cosp, geo.sinp, geo.area, f.sym)
        free, area, o = fv.cells.free, geo.area, f.offset
        for i in range(f.n):
            out[o + i] = area[i] * yp[o + i] + R[i] if free[i] else yp[o + i]
        for i in range(f.support.size):
            frc[f.support[i]] += f.gx[i] * fx + f.gy[i] * fy
    rotor_rows_residual(y, yp, out, rot)


@njit(cache=True)
def thermal_rotor_jacobian(t, y, yp, cj, data, args):
    """:func:`~transient.models.rotor.content_newton.rotor_jacobian` with each thermal film's block on its
    conductances times its fluidity (:func:`thermal_block_jacobian`), scattered again."""
    base, fluidity, thermal, which = args
    films, rot = base
    rotor_jacobian(t, y, yp, cj, data, base)
    if thermal.size == 0:
        return
    s = rot.speed[0]
    full = rot.full
    q = y[rot.Q0:rot.V0]
    for j in range(thermal.size):
        f = films[thermal[j]]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)  # work.u: the film's u at y (rotor_jacobian's block_fields)
        thermal_block_jacobian(as_read_only(work.u), X, Y, s * f.spin, cj, f.local, switch, geo, fields, extras, fv,
                               f.sym, fluidity[j])
        scatter_block(f.local, full, f.maps, f.ax, f.ay, f.gx, f.gy)
        work.xy[0] = np.nan
    for p in range(rot.gather.size):
        data[p] = full[rot.gather[p]]


@njit(cache=True)
def thermal_rotor_norm(z, dz, args):
    return rotor_norm(z, dz, args[0])


@njit(cache=True)
def thermal_rotor_to_state(z, y, args):
    rotor_to_state(z, y, args[0])


@njit(cache=True)
def thermal_rotor_from_state(y, z, args):
    rotor_from_state(y, z, args[0])


@njit(cache=True)  # newton_step is inlined (its kernels are this module's globals): cached on disk like a kernel
def thermal_rotor_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the films (the thermal ones on their fluidity) +
    rotor."""
    return newton_step(thermal_rotor_residual, thermal_rotor_jacobian, thermal_rotor_norm, thermal_rotor_to_state,
                       thermal_rotor_from_state, args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx,
                       err_w, state, counts)


drop_stale_cache(thermal_rotor_newton, stepper.__file__, rotor_content.__file__)
