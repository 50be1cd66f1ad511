"""The journal orbit's content formulation in the form the BDF2 stepper takes (:class:`~transient.solvers.integrate.bdf2.Bdf2Model`).

The state is ``y = [m, X, Y, VX, VY]`` (``m = H theta``, :mod:`~transient.models.journal.kernels`), the residual the
conservation law ``F = A m' + R(u(m))`` and the rotor equations; the Newton variables are ``z = [u, X, Y, VX, VY]``,
the universal variable of the free cells, smooth across the cavitation switch where ``u(m)`` has a corner (Newton on m
cycles over it). The argument tuple ``args`` = (switch, rotor, geo, fields, extras, fv, work, (p_tol, m_tol),
regime) is built by :meth:`~transient.models.journal.orbit.JournalOrbit.bdf2_model`.
"""

from __future__ import annotations

from numba import njit

from transient.models.journal.kernels import content_jacobian, content_residual, content_universal, state_fields
from transient.solvers.integrate.bdf2 import newton_step


@njit  # not cacheable: numba counts the kernels handed to newton_step as dynamic globals (compiled once per process)
def bdf2_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the content film + rotor, iterating on ``[u, X, Y, VX, VY]``."""
    return newton_step(bdf2_residual, bdf2_jacobian, film_newton_norm, bdf2_to_state, bdf2_from_state, args, t,
                       cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts)


@njit(cache=True)
def bdf2_residual(t, y, yp, out, args):
    """:func:`~transient.models.journal.kernels.content_residual` with the arguments of :meth:`~transient.models.journal.orbit.JournalOrbit.bdf2_model`."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    content_residual(t, y, yp, out, switch, rotor, geo, fields, fv, work)


@njit(cache=True)
def bdf2_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` for the content residual in the Newton variables ``z = [u, X, Y, VX,
    VY]`` (:func:`bdf2_to_state`): :func:`~transient.models.journal.kernels.content_jacobian` (columns d/dm at fixed
    X, Y), then with ``m_j = H_j C(u_j)``: ``d/du_j = H_j D_j d/dm_j`` and ``d/dX|u = d/dX|m + sum_j C_j cos(phi_j)
    d/dm_j`` (free cells; the groove cells keep m). Keeps the cells' regimes (:func:`cell_regime`) at this
    Jacobian."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    content_jacobian(t, y, yp, cj, data, switch, rotor, geo, fields, extras, fv, work)
    cosp, sinp = geo.cosp, geo.sinp
    H, C, D = fields.H, fields.C, fields.D
    pos_col, indices = extras.pos_col, extras.indices
    free = fv.cells.free
    u, indptr = work.u, work.indptr
    width = switch.width
    for j in range(free.size):
        if free[j]:
            s = H[j] * D[j]
            cx, cy = C[j] * cosp[j], C[j] * sinp[j]
            for p in range(indptr[j], indptr[j + 1]):
                i = indices[p]
                data[pos_col[i, 0]] += data[p] * cx
                data[pos_col[i, 1]] += data[p] * cy
                data[p] *= s
        regime[j] = cell_regime(u[j], width)


@njit(cache=True)
def bdf2_to_state(z, y, args):
    """The content state ``y = [m, X, Y, VX, VY]`` of the Newton variables ``z = [u, X, Y, VX, VY]``: ``m = H C(u)``
    on the free cells (groove cells: ``z`` holds m)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    free = fv.cells.free
    n = free.size
    state_fields(z[:n], z[n], z[n + 1], switch, geo, fields, fv)
    H, C = fields.H, fields.C
    for i in range(n):
        y[i] = H[i] * C[i] if free[i] else z[i]
    for i in range(n, y.size):
        y[i] = z[i]


@njit(cache=True)
def bdf2_from_state(y, z, args):
    """The inverse of :func:`bdf2_to_state` (:func:`~transient.models.journal.kernels.content_universal`)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    content_universal(y, switch, geo, free, u_fixed, work.theta, work.u)
    for i in range(n):
        z[i] = work.u[i] if free[i] else y[i]
    for i in range(n, y.size):
        z[i] = y[i]


@njit(cache=True)
def cell_regime(u, width):
    """1 full film, -1 cavitated, 0 inside the switch (|u| <= its pressure width)."""
    return 1 if u > width else (-1 if u < -width else 0)


@njit(cache=True)
def film_newton_norm(z, dz, args):
    """A Newton update ``du`` of the film in units of its tolerances ``(p_tol, m_tol)``: the largest over the free
    cells of ``|P'(u) du| / p_tol`` (pressure) and ``|H D du| / m_tol`` (content), at the fields of the last
    residual evaluation; and the number of cells whose regime (:func:`cell_regime`) differs from the one at the
    last Jacobian. Limits the update first: a cell outside the switch whose update would carry it across stops at
    u = 0 (the next iteration, on a fresh Jacobian, goes on from there)."""
    switch, rotor, geo, fields, extras, fv, work, (p_tol, m_tol), regime = args
    free = fv.cells.free
    H, dP, D = fields.H, fields.dP, fields.D
    width = switch.width
    size = 0.0
    switched = 0
    for i in range(free.size):
        if free[i]:
            if cell_regime(z[i], width) != regime[i]:
                switched += 1
            new = z[i] - dz[i]
            if (z[i] > width and new < 0.0) or (z[i] < -width and new > 0.0):
                dz[i] = z[i]  # a cell jumping across the switch stops at its centre (Newton cycles over the kink)
            a = abs(dz[i])
            v = max(a * dP[i] / p_tol, a * H[i] * D[i] / m_tol)
            if v > size:
                size = v
    return size, switched

