"""The rotor system's content formulation in the form the BDF2 stepper takes
(:class:`~transient.solvers.integrate.bdf2.Bdf2Model`): one film block per bearing, the rotor as the border.

State and Newton variables (``tau = omega_ref t``, ``m = H theta`` the content of a cell, ``u`` its universal
variable, :mod:`transient.models.journal.content_newton`)::

    y = [m_1, ..., m_k, q~, v, phi],   z = [u_1, ..., u_k, q~, v, phi],   m_b = H_b(X_b, Y_b) C(u_b)

with ``X_b = ax_b . q~``, ``Y_b = ay_b . q~`` the position of bearing ``b``'s node and ``k_b`` its spin (1: a journal
bearing's journal turns with the shaft; 0: a squeeze-film damper's is pinned, its film has no Couette flow;
:class:`~transient.models.rotor.model.BearingBlock`).
Residual (:mod:`transient.models.rotor.model`, the film rows as the conservation law itself)::

    film b:     A m_b' + R(u_b; X_b, Y_b, k_b s) = 0    (groove cells: m' = 0)
    kinematics: q~' - v = 0
    momentum:   M v' + (C / omega_ref + s G) v + K / omega_ref^2 q~ - f(phi, s, s') - sum_b (gx_b Fx_b + gy_b Fy_b) = 0
    angle:      phi' - s = 0

The film kernels are the journal's (:func:`~transient.models.journal.kernels.state_fields`, ``stencil_flux``,
``content_universal``, ``film_force``; the block Jacobian :func:`~transient.models.rotor.kernels.block_jacobian`
with ``u' = 0`` and ``X' = Y' = 0`` is the content form's ``dF/dz``: ``dR/du + cj A H D`` on the diagonal, ``dR/dX|_u
+ cj A theta cos`` in the position columns; the Newton norm of each film
:func:`~transient.models.journal.content_newton.film_newton_norm`). The shaft speed ``s, s'`` of the step's time is
in ``rotor.speed`` (set by the caller before each Newton solve: a user's speed function is Python).

A film block that takes its node's tilts (``RotorBearingSystem(tilt_coupling=True)``) sets its gap at the tilts of
the state first (:func:`block_gap`): ``m_b = H_b(X_b, Y_b, A_b, B_b) C(u_b)``, its tilt forces on the tilt rows and
its block Jacobian by :func:`~transient.models.rotor.kernels.tilted_block_jacobian` (the tilt rates enter through
``m_b'`` as the position rates do).

``args = (films, rotor)``: ``films`` a tuple of :class:`FilmArgs` (one per bearing, all of one numba type),
``rotor`` a :class:`RotorArgs`; built by :class:`~transient.models.rotor.content_form.ContentSystem`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from transient.models.journal.content_newton import cell_regime, film_newton_norm
from transient.models.journal.kernels import content_universal, film_force, state_fields, stencil_flux
from transient.models.rotor.kernels import (block_jacobian, scatter_block, scatter_tilted_block, tilt_gap,
                                           tilted_block_jacobian)
from transient.models.rotor.model import BlockMaps
import transient.solvers.integrate.bdf2 as stepper
from transient.solvers.integrate.bdf2 import newton_step
from transient.solvers.read_only import as_read_only
from transient.solvers.integrate.cache_guard import drop_stale_cache


class FilmArgs(NamedTuple):
    """One bearing's film block: ``film`` the journal's Newton-norm tuple (switch, None, geo, fields, extras, fv,
    work, (p_tol, m_tol), regime), its ``offset`` and size ``n`` in the state, ``sym``, ``spin`` (its Couette flow
    per unit of the shaft's speed ratio: 1 a journal bearing, 0 a squeeze-film damper), the rotor coordinates
    its node moves with (``support``) and their weights ``ax``, ``ay`` (position), ``gx``, ``gy`` (force), the
    scatter ``maps`` into the system pattern, the film's own Jacobian ``local``, zeros ``up`` (its u') and
    ``ym`` (n + 2: a block's content and position in the journal's layout, for the inversion); a block that takes
    its node's tilts (``tilted``): their weights ``aa``, ``ab`` (tilt groups) and ``ga``, ``gb`` (tilt forces) and
    its ``tilt`` geometry (:mod:`transient.models.rotor.kernels`, with the tilt groups its gap is of)."""

    film: tuple
    offset: int
    n: int
    sym: float
    spin: float
    support: np.ndarray
    ax: np.ndarray
    ay: np.ndarray
    gx: np.ndarray
    gy: np.ndarray
    maps: BlockMaps
    local: np.ndarray
    up: np.ndarray
    ym: np.ndarray
    tilted: bool
    aa: np.ndarray
    ab: np.ndarray
    ga: np.ndarray
    gb: np.ndarray
    tilt: tuple


class RotorArgs(NamedTuple):
    """The rotor rows: offsets ``Q0``, ``V0``, ``P0``; ``M``, ``Cw = C / omega``, ``G``, ``Kw = K / omega^2``;
    the static force ``f_static``; the unbalances (``ub_x``, ``ub_y``: (count, nq) rows of ``T m e / L``,
    ``ub_a``: phases); the positions in the system pattern (:func:`~transient.models.rotor.model.system_pattern`)
    of the kinematic, momentum (``mom_q`` with values ``k_vals``, ``mom_v`` at ``(v_rows, v_cols)``), angle-column
    (rows ``phi_rows``) and angle-row entries; ``full`` (the Jacobian in that pattern) and ``gather`` (the
    Newton pattern's entries in it); ``speed`` = (s, s') of the step; ``force`` scratch; ``phi_tol`` the angle's
    Newton tolerance [rad]; ``block_cj``: the cj of each film's block in ``full`` (NaN: none yet); ``per_film``: a
    Jacobian refreshes only the films that need it (:func:`rotor_jacobian`), else every film."""

    Q0: int
    V0: int
    P0: int
    M: np.ndarray
    Cw: np.ndarray
    G: np.ndarray
    Kw: np.ndarray
    f_static: np.ndarray
    ub_x: np.ndarray
    ub_y: np.ndarray
    ub_a: np.ndarray
    kin_q: np.ndarray
    kin_v: np.ndarray
    mom_q: np.ndarray
    k_vals: np.ndarray
    mom_v: np.ndarray
    v_rows: np.ndarray
    v_cols: np.ndarray
    mom_phi: np.ndarray
    phi_rows: np.ndarray
    phi_phi: np.ndarray
    full: np.ndarray
    gather: np.ndarray
    speed: np.ndarray
    force: np.ndarray
    phi_tol: float
    block_cj: np.ndarray
    per_film: bool


@njit(cache=True)
def rotor_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the films + rotor, iterating on ``z``."""
    return newton_step(rotor_residual, rotor_jacobian, rotor_norm, rotor_to_state, rotor_from_state, args, t, cj, b,
                       y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts)


drop_stale_cache(rotor_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined


@njit(cache=True)
def node_position(f, q):
    """(X, Y) of the film block's journal [its clearance] for the rotor coordinates ``q``."""
    X = 0.0
    Y = 0.0
    for j in range(f.support.size):
        X += f.ax[j] * q[f.support[j]]
        Y += f.ay[j] * q[f.support[j]]
    return X, Y


@njit(cache=True)
def node_tilt(f, q):
    """The tilt groups (A, B) of the film block's node for the rotor coordinates ``q``: (0, 0) untilted."""
    A = 0.0
    B = 0.0
    if f.tilted:
        for j in range(f.support.size):
            A += f.aa[j] * q[f.support[j]]
            B += f.ab[j] * q[f.support[j]]
    return A, B


@njit(cache=True)
def block_gap(f, q):
    """A tilted block's gap at its node's tilts of ``q`` (its geometry's ``gap0``, :func:`tilt_gap`). Returns
    whether the gap changed (nothing for an untilted block)."""
    if not f.tilted:
        return False
    A, B = node_tilt(f, q)
    held = f.tilt[4]
    if A == held[0] and B == held[1]:
        return False
    tilt_gap(f.film[2].gap0, f.tilt, A, B)
    return True


@njit(cache=True)
def block_fields(y, f, X, Y, moved):
    """The cell fields of block ``f``'s content ``y[offset:offset + n]`` at ``(X, Y)`` in its ``fields`` and its
    universal variable in ``work.u``: those :func:`rotor_to_state` left if they are this state's (the same position
    and tilt, ``moved`` False, and every free cell's ``H C(u)`` bitwise ``y``'s), else from the inversion
    ``u = C^-1(m / H)``."""
    switch, _, geo, fields, extras, fv, work, tol, regime = f.film
    H, C = fields.H, fields.C
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    o, n = f.offset, f.n
    held = X == work.xy[0] and Y == work.xy[1] and not moved
    if held:
        for i in range(n):
            if free[i] and H[i] * C[i] != y[o + i]:
                held = False
                break
    if not held:
        ym = f.ym
        for i in range(n):
            ym[i] = y[o + i]
        ym[n] = X
        ym[n + 1] = Y
        content_universal(as_read_only(ym), switch, geo, free, u_fixed, work.theta, work.u)
        state_fields(as_read_only(work.u), X, Y, switch, geo, fields, fv)
        work.xy[0] = X
        work.xy[1] = Y


@njit(cache=True)
def rotor_force(y, rot):
    """The static and unbalance forces on the rotor coordinates (module docstring) into ``rot.force``."""
    s, ds = rot.speed[0], rot.speed[1]
    frc = rot.force
    frc[:] = rot.f_static
    phi = y[rot.P0]
    for k in range(rot.ub_a.size):
        c = np.cos(phi + rot.ub_a[k])
        sn = np.sin(phi + rot.ub_a[k])
        a = s * s * c + ds * sn
        b = s * s * sn - ds * c
        for r in range(frc.size):
            frc[r] += rot.ub_x[k, r] * a + rot.ub_y[k, r] * b


@njit(cache=True)
def rotor_rows_residual(y, yp, out, rot):
    """The kinematic, momentum and angle rows of the residual (module docstring), the bearings' forces already in
    ``rot.force`` with the static and unbalance forces."""
    s = rot.speed[0]
    Q0, V0, P0 = rot.Q0, rot.V0, rot.P0
    frc = rot.force
    nq = V0 - Q0
    for r in range(nq):
        out[Q0 + r] = yp[Q0 + r] - y[V0 + r]
        acc = -frc[r]
        for c in range(nq):
            acc += rot.M[r, c] * yp[V0 + c] + (rot.Cw[r, c] + s * rot.G[r, c]) * y[V0 + c] + rot.Kw[r, c] * y[Q0 + c]
        out[V0 + r] = acc
    out[P0] = yp[P0] - s


@njit(cache=True)
def rotor_rows_jacobian(y, cj, rot):
    """The rotor rows' entries of the Jacobian into ``rot.full`` (:func:`rotor_jacobian`'s docstring)."""
    s, ds = rot.speed[0], rot.speed[1]
    full = rot.full
    for j in range(rot.kin_q.size):
        full[rot.kin_q[j]] = cj
        full[rot.kin_v[j]] = -1.0
    for p in range(rot.mom_q.size):
        full[rot.mom_q[p]] = rot.k_vals[p]
    for p in range(rot.mom_v.size):
        r, c = rot.v_rows[p], rot.v_cols[p]
        full[rot.mom_v[p]] = rot.Cw[r, c] + s * rot.G[r, c] + cj * rot.M[r, c]
    phi = y[rot.P0]
    for p in range(rot.phi_rows.size):
        r = rot.phi_rows[p]
        d = 0.0
        for k in range(rot.ub_a.size):
            c = np.cos(phi + rot.ub_a[k])
            sn = np.sin(phi + rot.ub_a[k])
            d -= rot.ub_x[k, r] * (-s * s * sn + ds * c) + rot.ub_y[k, r] * (s * s * c + ds * sn)
        full[rot.mom_phi[p]] = d
    full[rot.phi_phi[0]] = cj


@njit(cache=True)
def rotor_residual(t, y, yp, out, args):
    """``F(t, y, y')`` of the module docstring."""
    films, rot = args
    s = rot.speed[0]
    rotor_force(y, rot)
    frc = rot.force
    q = y[rot.Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)
        block_fields(y, f, X, Y, block_gap(f, q))
        R = fields.R
        sb = s * f.spin
        stencil_flux(as_read_only(work.u), fields, fv, R, sb)
        if sb != 1.0:
            work.xy[0] = np.nan  # the Couette coefficients c are scaled now: not the fields of this state
        fx, fy = film_force(fields.P, geo.cosp, geo.sinp, geo.area, f.sym)
        free, area, o = fv.cells.free, geo.area, f.offset
        for i in range(f.n):
            out[o + i] = area[i] * yp[o + i] + R[i] if free[i] else yp[o + i]
        for j in range(f.support.size):
            frc[f.support[j]] += f.gx[j] * fx + f.gy[j] * fy
        if f.tilted:
            fa, fb = film_force(fields.P, f.tilt[1], f.tilt[2], geo.area, f.sym)
            for j in range(f.support.size):
                frc[f.support[j]] += f.ga[j] * fa + f.gb[j] * fb
    rotor_rows_residual(y, yp, out, rot)


@njit(cache=True)
def block_switched(f):
    """Whether a cell of film block ``f`` is in another regime (:func:`cell_regime`) than at its last Jacobian (its
    ``u`` in ``work.u``)."""
    switch, _, geo, fields, extras, fv, work, tol, regime = f.film
    free, u = fv.cells.free, work.u
    for i in range(f.n):
        if free[i] and cell_regime(u[i], switch.width) != regime[i]:
            return True
    return False


@njit(cache=True)
def rotor_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` in the Newton pattern (``rot.gather`` of the system pattern):
    each film's block (:func:`~transient.models.rotor.kernels.block_jacobian` at ``u' = X' = Y' = 0``, module
    docstring) scattered with its coupling and border (:func:`~transient.models.rotor.kernels.scatter_block`),
    the rotor rows ``dF_q/dq = cj``, ``dF_q/dv = -1``, ``dF_v/dq = K / omega^2``, ``dF_v/dv = C / omega + s G +
    cj M``, ``dF_v/dphi = -df/dphi``, ``dF_phi/dphi = cj``. Keeps each film's cell regimes at this Jacobian.

    With ``rot.per_film`` only the films that need it are evaluated again: a new cj, or cells that changed regime
    since the film's last Jacobian (the chord of the others still holds: a film's switches degrade its own block);
    every film when none does (a refresh for a slow contraction). The others keep their entries in ``rot.full``,
    so the bordered band LU refactors only the refreshed films' bands
    (:func:`~transient.solvers.bandlu.band_factor`)."""
    films, rot = args
    s = rot.speed[0]
    full = rot.full
    q = y[rot.Q0:rot.V0]
    held = rot.block_cj
    fresh = np.zeros(len(films), dtype=np.bool_)
    some = False
    for k in range(len(films)):
        f = films[k]
        X, Y = node_position(f, q)
        block_fields(y, f, X, Y, block_gap(f, q))
        fresh[k] = not rot.per_film or held[k] != cj or block_switched(f)
        some = some or fresh[k]
    for k in range(len(films)):
        if some and not fresh[k]:
            continue
        f = films[k]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        X, Y = node_position(f, q)
        u = work.u
        sb = s * f.spin
        if f.tilted:
            tilted_block_jacobian(as_read_only(u), as_read_only(f.up), X, Y, f.tilt[4][0], f.tilt[4][1], 0.0, 0.0, 0.0, 0.0,
                                  sb, cj, f.local, switch, geo, fields, extras, fv, f.sym, f.tilt)
            scatter_tilted_block(f.local, full, f.maps, f.ax, f.ay, f.aa, f.ab, f.gx, f.gy, f.ga, f.gb)
        else:
            block_jacobian(as_read_only(u), as_read_only(f.up), X, Y, 0.0, 0.0, sb, cj, f.local, switch, geo, fields,
                           extras, fv, f.sym)
            scatter_block(f.local, full, f.maps, f.ax, f.ay, f.gx, f.gy)
        if sb != 1.0:
            work.xy[0] = np.nan
        for i in range(f.n):
            regime[i] = cell_regime(u[i], switch.width)
        held[k] = cj
    rotor_rows_jacobian(y, cj, rot)
    for p in range(rot.gather.size):
        data[p] = full[rot.gather[p]]


@njit(cache=True)
def rotor_norm(z, dz, args):
    """A Newton update of the films (each by :func:`~transient.models.journal.content_newton.film_newton_norm`, which
    may first stop a cell at the switch) and of the angle (``rot.phi_tol``) in units of their tolerances, and the
    cells that switched regime since the last Jacobian in the film with the most: each film's chord degrades with its
    own switches (the stepper's rule for a refresh counts them as one film's, as the journal orbit's)."""
    films, rot = args
    size = abs(dz[rot.P0]) / rot.phi_tol
    switched = 0
    for k in range(len(films)):
        f = films[k]
        o, n = f.offset, f.n
        v, w = film_newton_norm(z[o:o + n], dz[o:o + n], f.film)
        if v > size:
            size = v
        if w > switched:
            switched = w
    return size, switched


@njit(cache=True)
def rotor_to_state(z, y, args):
    """The content state ``y`` of the Newton variables ``z`` (module docstring; groove cells: ``z`` holds m).
    Leaves each film's fields of its ``u`` and position in its scratch for the residual and the Jacobian at ``y``
    (:func:`block_fields`)."""
    films, rot = args
    Q0 = rot.Q0
    q = z[Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        o, n = f.offset, f.n
        X, Y = node_position(f, q)
        block_gap(f, q)
        state_fields(as_read_only(z[o:o + n]), X, Y, switch, geo, fields, fv)
        H, C, u = fields.H, fields.C, work.u
        free, u_fixed = fv.cells.free, fv.cells.u_fixed
        for i in range(n):
            if free[i]:
                y[o + i] = H[i] * C[i]
                u[i] = z[o + i]
            else:
                y[o + i] = z[o + i]
                u[i] = u_fixed[i]
        work.xy[0] = X
        work.xy[1] = Y
    for i in range(Q0, y.size):
        y[i] = z[i]


@njit(cache=True)
def rotor_from_state(y, z, args):
    """The inverse of :func:`rotor_to_state` (each film by
    :func:`~transient.models.journal.kernels.content_universal`; the fields stay those of the last
    :func:`rotor_to_state`)."""
    films, rot = args
    Q0 = rot.Q0
    q = y[Q0:rot.V0]
    for k in range(len(films)):
        f = films[k]
        switch, _, geo, fields, extras, fv, work, tol, regime = f.film
        o, n = f.offset, f.n
        X, Y = node_position(f, q)
        if block_gap(f, q):
            work.xy[0] = np.nan  # the fields are of the last rotor_to_state's tilt, not of this gap
        ym = f.ym
        for i in range(n):
            ym[i] = y[o + i]
        ym[n] = X
        ym[n + 1] = Y
        content_universal(as_read_only(ym), switch, geo, fv.cells.free, fv.cells.u_fixed, work.theta, z[o:o + n])
        free = fv.cells.free
        for i in range(n):
            if not free[i]:
                z[o + i] = y[o + i]
    for i in range(Q0, y.size):
        z[i] = y[i]
