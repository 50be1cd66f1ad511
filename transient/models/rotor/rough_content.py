"""The content BDF of a rotor on rough bearings (``RotorBearingSystem.run(method="bdf2")``, every bearing rough): the
Newton of :mod:`transient.models.rotor.content_newton` with each film block the rough one of
:mod:`transient.models.rotor.rough_films` (module docstring there: the content ``m = (h_T / C) theta``, the flux with
the flow factors, the asperity force and its stiffness on the momentum rows).

``args = (films, roughs, rotor)``: the system's :class:`~transient.models.rotor.content_newton.FilmArgs`, per film
``(cells, contact, contact_pos)`` and the rotor rows (:class:`~transient.models.rotor.content_newton.RotorArgs`),
built by :func:`content_args`. A mix of rough and smooth bearings: ``args = (smooth films, rough films, roughs,
rotor)``, the smooth blocks through :mod:`~transient.models.rotor.content_newton`'s kernels, the rough ones through
this module's (:func:`mixed_rotor_newton`).
"""

from __future__ import annotations

from numba import njit

from transient.models.journal.content_newton import cell_regime
from transient.models.journal.rough_orbit import (rough_content_universal, rough_flux, rough_force, rough_newton_norm,
                                                  rough_state_fields)
from transient.models.rotor.content_newton import (node_position, rotor_force, rotor_from_state, rotor_jacobian,
                                                  rotor_norm, rotor_residual, rotor_rows_jacobian,
                                                  rotor_rows_residual, rotor_to_state)
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
    rotor_force(y, rot)
    rough_blocks_residual(y, yp, out, films, roughs, rot)
    rotor_rows_residual(y, yp, out, rot)


@njit(cache=True)
def rough_blocks_residual(y, yp, out, films, roughs, rot):
    """The rough film blocks' rows of the residual; their forces added to ``rot.force``."""
    s = rot.speed[0]
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


@njit(cache=True)
def rough_rotor_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` in the Newton pattern: each rough block by
    :func:`rough_block_jacobian` at ``u' = X' = Y' = 0`` (``dF_i/du_j = dR_i/du_j + delta_ij cj A h_T D``,
    ``dF_i/dX = dR_i/dX|_u + cj A theta phi_c cos``) scattered with its coupling and border, the rotor rows, then
    each block's contact stiffness on its momentum rows. Keeps each film's cell regimes at this Jacobian."""
    films, roughs, rot = args
    rough_blocks_jacobian(y, cj, films, roughs, rot)
    rotor_rows_jacobian(y, cj, rot)
    rough_contact_stiffness(films, roughs, rot)
    for p in range(rot.gather.size):
        data[p] = rot.full[rot.gather[p]]


@njit(cache=True)
def rough_blocks_jacobian(y, cj, films, roughs, rot):
    """The rough film blocks' entries of the Jacobian in ``rot.full`` (:func:`rough_rotor_jacobian`); keeps each
    film's cell regimes."""
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


@njit(cache=True)
def rough_contact_stiffness(films, roughs, rot):
    """Each rough block's asperity stiffness added to its momentum rows in ``rot.full`` (after the rotor rows)."""
    for k in range(len(films)):
        f = films[k]
        add_contact_stiffness(rot.full, roughs[k][2], roughs[k][1], f.ax, f.ay, f.gx, f.gy)


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


# ------------------------------------------------------------------------------------------------------------------
# A mix of rough and smooth bearings: args = (smooth films, rough films, roughs, rotor); each group through its own
# block kernels (the smooth ones those of content_newton on (smooth films, rotor)), the rotor rows once more on the
# forces of both.


@njit(cache=True)
def mixed_rotor_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on smooth and rough films + rotor."""
    return newton_step(mixed_rotor_residual, mixed_rotor_jacobian, mixed_rotor_norm, mixed_rotor_to_state,
                       mixed_rotor_from_state, args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx,
                       err_w, state, counts)


drop_stale_cache(mixed_rotor_newton, stepper.__file__)


@njit(cache=True)
def mixed_rotor_residual(t, y, yp, out, args):
    """``F(t, y, y')``: the smooth blocks and the rotor's forces by
    :func:`~transient.models.rotor.content_newton.rotor_residual`, the rough blocks' rows and forces, the rotor
    rows again on the forces of all."""
    smooth, films, roughs, rot = args
    rotor_residual(t, y, yp, out, (smooth, rot))
    rough_blocks_residual(y, yp, out, films, roughs, rot)
    rotor_rows_residual(y, yp, out, rot)


@njit(cache=True)
def mixed_rotor_jacobian(t, y, yp, cj, data, args):
    """The Newton matrix: the smooth blocks and the rotor rows
    (:func:`~transient.models.rotor.content_newton.rotor_jacobian`), the rough blocks and their contact stiffness."""
    smooth, films, roughs, rot = args
    rotor_jacobian(t, y, yp, cj, data, (smooth, rot))
    rough_blocks_jacobian(y, cj, films, roughs, rot)
    rough_contact_stiffness(films, roughs, rot)
    for p in range(rot.gather.size):
        data[p] = rot.full[rot.gather[p]]


@njit(cache=True)
def mixed_rotor_norm(z, dz, args):
    """The larger of the smooth and the rough films' Newton norms (and switched cells)."""
    smooth, films, roughs, rot = args
    v, w = rotor_norm(z, dz, (smooth, rot))
    vr, wr = rough_rotor_norm(z, dz, (films, roughs, rot))
    return max(v, vr), max(w, wr)


@njit(cache=True)
def mixed_rotor_to_state(z, y, args):
    """:func:`~transient.models.rotor.content_newton.rotor_to_state` and :func:`rough_rotor_to_state`, each on its
    films."""
    smooth, films, roughs, rot = args
    rotor_to_state(z, y, (smooth, rot))
    rough_rotor_to_state(z, y, (films, roughs, rot))


@njit(cache=True)
def mixed_rotor_from_state(y, z, args):
    """The inverse of :func:`mixed_rotor_to_state`."""
    smooth, films, roughs, rot = args
    rotor_from_state(y, z, (smooth, rot))
    rough_rotor_from_state(y, z, (films, roughs, rot))


def content_args(form) -> tuple:
    """``(args, newton, residual)`` of the rough films for the
    :class:`~transient.models.rotor.content_form.ContentSystem` ``form``: every bearing rough ``(films, roughs,
    rotor)``, :func:`rough_rotor_newton` and :func:`rough_rotor_residual`; a mix of rough and smooth bearings
    ``(smooth films, rough films, roughs, rotor)``, :func:`mixed_rotor_newton` and :func:`mixed_rotor_residual`."""
    blocks = form.dae.blocks
    films, rotor = form.args
    rough = [k for k, b in enumerate(blocks) if b.rough is not None]
    roughs = tuple((blocks[k].rough, blocks[k].contact, blocks[k].contact_pos) for k in rough)
    if len(rough) == len(blocks):
        return (films, roughs, rotor), rough_rotor_newton, rough_rotor_residual
    smooth = tuple(f for k, f in enumerate(films) if k not in rough)
    return ((smooth, tuple(films[k] for k in rough), roughs, rotor), mixed_rotor_newton,
            mixed_rotor_residual)
