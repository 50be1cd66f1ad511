"""The content BDF of a rotor on rough bearings (``RotorBearingSystem.run(method="bdf2")``, every bearing rough): the
Newton of :mod:`transient.models.rotor.content_newton` with each film block the rough one of
:mod:`transient.models.rotor.rough_films` (module docstring there: the content ``m = (h_T / C) theta``, the flux with
the flow factors, the asperity force and its stiffness on the momentum rows).

``args = (films, roughs, rotor)``: the system's :class:`~transient.models.rotor.content_newton.FilmArgs`, per film
``(cells, contact, contact_pos)`` and the rotor rows (:class:`~transient.models.rotor.content_newton.RotorArgs`),
built by :func:`content_args`.
"""

from __future__ import annotations

from numba import njit

from transient.models.journal.content_newton import cell_regime
from transient.models.journal.rough_orbit import (rough_content_universal, rough_flux, rough_force, rough_newton_norm,
                                                  rough_state_fields)
from transient.models.rotor.content_newton import (node_position, rotor_force, rotor_rows_jacobian,
                                                  rotor_rows_residual)
from transient.models.rotor.kernels import scatter_block
from transient.models.rotor.rough_films import add_contact_stiffness, rough_block_jacobian
import transient.solvers.integrate.bdf2 as stepper
from transient.solvers.integrate.bdf2 import newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.read_only import as_read_only


@njit(cache=True)
def rough_rotor_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the rough films + rotor, iterating on
    ``z = [u_1, ..., u_k, q~, v, phi]``."""
    return newton_step(rough_rotor_residual, rough_rotor_jacobian, rough_rotor_norm, rough_rotor_to_state,
                       rough_rotor_from_state, args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx,
                       err_w, state, counts)


drop_stale_cache(rough_rotor_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined


@njit(cache=True)
def rough_block_fields(y, f, rough, X, Y):
    """The cell fields of rough block ``f``'s content ``y[offset:offset + n]`` at ``(X, Y)`` (and its universal
    variable in ``work.u``): those :func:`rough_rotor_to_state` left if they are this state's (the same position and
    every free cell's ``h_T C(u)`` bitwise ``y``'s), else from the inversion ``u = C^-1(m / h_T)``."""
    switch, _, geo, fields, extras, fv, work, tol, regime = f.film
    C = fields.C
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    o, n = f.offset, f.n
    held = X == work.xy[0] and Y == work.xy[1]
    if held:
        for i in range(n):
            if free[i] and rough.mean_gap[i] * C[i] != y[o + i]:
                held = False
                break
    if not held:
        ym = f.ym
        for i in range(n):
            ym[i] = y[o + i]
        ym[n] = X
        ym[n + 1] = Y
        rough_content_universal(as_read_only(ym), switch, geo, free, u_fixed, rough.sig, work.theta, work.u)
        rough_state_fields(as_read_only(work.u), X, Y, switch, geo, fields, fv, rough)
        work.xy[0] = X
        work.xy[1] = Y


@njit(cache=True)
def rough_rotor_residual(t, y, yp, out, args):
    """``F(t, y, y')`` of the content form (module docstring; the rotor rows of
    :mod:`~transient.models.rotor.content_newton`)."""
    films, roughs, rot = args
    s = rot.speed[0]
    rotor_force(y, rot)
    frc = rot.force
    q = y[rot.Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        rough = roughs[k][0]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)
        rough_block_fields(y, f, rough, X, Y)
        R = fields.R
        rough_flux(s * f.spin, as_read_only(work.u), fields, fv, rough, R)
        fx, fy = rough_force(fields.P, geo, rough, f.sym)
        free, area, o = fv.cells.free, geo.area, f.offset
        for i in range(f.n):
            out[o + i] = area[i] * yp[o + i] + R[i] if free[i] else yp[o + i]
        for j in range(f.support.size):
            frc[f.support[j]] += f.gx[j] * fx + f.gy[j] * fy
    rotor_rows_residual(y, yp, out, rot)


@njit(cache=True)
def rough_rotor_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` in the Newton pattern: each rough block by
    :func:`rough_block_jacobian` at ``u' = X' = Y' = 0`` (``dF_i/du_j = dR_i/du_j + delta_ij cj A h_T D``,
    ``dF_i/dX = dR_i/dX|_u + cj A theta phi_c cos``) scattered with its coupling and border, the rotor rows, then
    each block's contact stiffness on its momentum rows. Keeps each film's cell regimes at this Jacobian."""
    films, roughs, rot = args
    s = rot.speed[0]
    full = rot.full
    q = y[rot.Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        rough, contact = roughs[k][0], roughs[k][1]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)
        rough_block_fields(y, f, rough, X, Y)
        u = work.u
        rough_block_jacobian(as_read_only(u), as_read_only(f.up), X, Y, 0.0, 0.0, s * f.spin, cj, f.local, switch,
                             geo, fields, extras, fv, f.sym, rough, contact)
        scatter_block(f.local, full, f.maps, f.ax, f.ay, f.gx, f.gy)
        for i in range(f.n):
            regime[i] = cell_regime(u[i], switch.width)
    rotor_rows_jacobian(y, cj, rot)
    for k in range(len(films)):
        f = films[k]
        add_contact_stiffness(full, roughs[k][2], roughs[k][1], f.ax, f.ay, f.gx, f.gy)
    for p in range(rot.gather.size):
        data[p] = full[rot.gather[p]]


@njit(cache=True)
def rough_rotor_norm(z, dz, args):
    """:func:`~transient.models.rotor.content_newton.rotor_norm` with each film's content ``h_T C(u)``
    (:func:`~transient.models.journal.rough_orbit.rough_newton_norm`)."""
    films, roughs, rot = args
    size = abs(dz[rot.P0]) / rot.phi_tol
    switched = 0
    for k in range(len(films)):
        f = films[k]
        o, n = f.offset, f.n
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        v, w = rough_newton_norm(z[o:o + n], dz[o:o + n], (switch, None, geo, fields, extras, fv, work, tol, regime,
                                                           roughs[k][0]))
        if v > size:
            size = v
        if w > switched:
            switched = w
    return size, switched


@njit(cache=True)
def rough_rotor_to_state(z, y, args):
    """The content state ``y`` of the Newton variables ``z``: ``m_b = h_T,b C(u_b)`` on the free cells (groove
    cells: ``z`` holds m); leaves each film's fields in its scratch (:func:`rough_block_fields`)."""
    films, roughs, rot = args
    Q0 = rot.Q0
    q = z[Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        rough = roughs[k][0]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        o, n = f.offset, f.n
        X, Y = node_position(f, q)
        rough_state_fields(as_read_only(z[o:o + n]), X, Y, switch, geo, fields, fv, rough)
        C, u = fields.C, work.u
        free, u_fixed = fv.cells.free, fv.cells.u_fixed
        for i in range(n):
            if free[i]:
                y[o + i] = rough.mean_gap[i] * C[i]
                u[i] = z[o + i]
            else:
                y[o + i] = z[o + i]
                u[i] = u_fixed[i]
        work.xy[0] = X
        work.xy[1] = Y
    for i in range(Q0, y.size):
        y[i] = z[i]


@njit(cache=True)
def rough_rotor_from_state(y, z, args):
    """The inverse of :func:`rough_rotor_to_state` (each film by
    :func:`~transient.models.journal.rough_orbit.rough_content_universal`)."""
    films, roughs, rot = args
    Q0 = rot.Q0
    q = y[Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        o, n = f.offset, f.n
        X, Y = node_position(f, q)
        ym = f.ym
        for i in range(n):
            ym[i] = y[o + i]
        ym[n] = X
        ym[n + 1] = Y
        free = fv.cells.free
        rough_content_universal(as_read_only(ym), switch, geo, free, fv.cells.u_fixed, roughs[k][0].sig, work.theta,
                                z[o:o + n])
        for i in range(n):
            if not free[i]:
                z[o + i] = y[o + i]
    for i in range(Q0, y.size):
        z[i] = y[i]


def content_args(form) -> tuple:
    """``(args, newton, residual)`` of the rough films for the
    :class:`~transient.models.rotor.content_form.ContentSystem` ``form`` (every bearing rough): ``(films, roughs,
    rotor)``, :func:`rough_rotor_newton` and :func:`rough_rotor_residual`."""
    blocks = form.dae.blocks
    if any(b.rough is None for b in blocks):
        raise ValueError("bearings: method \"bdf2\" takes bearings all rough or all smooth (one film kind); allowed: "
                         "method=\"ida\" for a mix of rough and smooth bearings")
    films, rotor = form.args
    roughs = tuple((b.rough, b.contact, b.contact_pos) for b in blocks)
    return (films, roughs, rotor), rough_rotor_newton, rough_rotor_residual
