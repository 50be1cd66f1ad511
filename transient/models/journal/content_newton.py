"""The journal orbit's content formulation in the form the BDF2 stepper takes (:class:`~transient.solvers.integrate.bdf2.Bdf2Model`).

The state is ``y = [m, X, Y, VX, VY]`` (``m = H theta``, :mod:`~transient.models.journal.kernels`), the residual the
conservation law ``F = A m' + R(u(m))`` and the rotor equations; the Newton variables are ``z = [u, X, Y, VX, VY]``,
the universal variable of the free cells, smooth across the cavitation switch where ``u(m)`` has a corner (Newton on m
cycles over it). The argument tuple ``args`` = (switch, rotor, geo, fields, extras, fv, work, (p_tol, m_tol),
regime) is built by :meth:`~transient.models.journal.orbit.JournalOrbit.bdf2_model`.

Only :func:`bdf2_newton` and :func:`bdf2_residual` (also the start's slope) are called from Python in a run; the
Newton's other kernels are :func:`~transient.solvers.inner_kernel.inner_kernel` s (no entry points for Python: a
first run compiles about half as much for each), ``newton_jacobian``, ``bdf2_jacobian``, ``bdf2_to_state`` and
``bdf2_from_state`` the same functions as Python calls them.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from numba import njit

from transient.models.journal.kernels import (N_ROTOR, content_rows, content_universal, film_force, state_fields,
                                              stencil_flux, stencil_flux_jacobian)
import transient.solvers.integrate.bdf2 as stepper
from transient.solvers.integrate.bdf2 import newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.inner_kernel import entry_point, inner_kernel
from transient.solvers.read_only import as_read_only


@njit(cache=True)  # newton_step is inlined (its kernels are this module's globals): cached on disk like a kernel
def bdf2_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the content film + rotor, iterating on ``[u, X, Y, VX, VY]``."""
    return newton_step(bdf2_residual, _newton_jacobian, film_newton_norm, _bdf2_to_state, _bdf2_from_state, args,
                       t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts)


drop_stale_cache(bdf2_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined


def decoupled_pattern(pattern, free):
    """The arrow ``pattern`` (CSC) without the entries that couple a prescribed cell (``free`` False) to another
    unknown, and the position in ``pattern``'s data of each entry kept (``gather``, CSC order).

    A prescribed (groove) cell's fields are its sharp prescribed values whatever its state
    (:func:`~transient.physics.cavitation.sharp_fixed_cells`: P' = D = 0), so its column holds only the diagonal;
    its row is ``m' = cj m + b``: so those entries are exactly zero in every Jacobian of :func:`bdf2_jacobian`. An
    axial groove over the whole length then cuts the film's periodic wrap in phi: on the paper's 151 x 21 grid the
    reverse Cuthill-McKee band of the film block narrows from 43 to 21 and LAPACK's band LU is 2.3x faster."""
    pat = sp.csc_matrix(pattern)
    pat.sort_indices()
    N = pat.shape[0]
    is_free = np.ones(N, dtype=bool)
    is_free[:free.size] = free
    rows = pat.indices
    cols = np.repeat(np.arange(N), np.diff(pat.indptr))
    keep = (rows == cols) | (is_free[rows] & is_free[cols])
    gather = np.flatnonzero(keep).astype(np.int64)
    indptr = np.concatenate([[0], np.cumsum(np.bincount(cols[keep], minlength=N))])
    kept = sp.csc_matrix((np.ones(gather.size), rows[keep], indptr), shape=pat.shape)
    return kept, gather


@njit(cache=True)
def pattern_target(data, work):
    """Where a content Jacobian in the problem's pattern is written: ``data`` in the operator's pattern, else (``data``
    of the decoupled pattern of :func:`decoupled_pattern`) the operator pattern's ``work.jac``, gathered into
    ``data`` after (:func:`gather_pattern`)."""
    if data.size == work.gather.size and data.size != work.jac.size:
        return work.jac
    return data


@njit(cache=True)
def gather_pattern(data, work):
    """``data`` of the decoupled pattern from the operator pattern's ``work.jac`` by ``work.gather`` (nothing in the
    operator's pattern: :func:`pattern_target` wrote ``data`` itself)."""
    full, gather = work.jac, work.gather
    if data.size == gather.size and data.size != full.size:
        for k in range(gather.size):
            data[k] = full[gather[k]]


@inner_kernel
def _newton_jacobian(t, y, yp, cj, data, args):
    """:func:`bdf2_jacobian` in the pattern of the problem: the operator's (``data`` of its size) or the decoupled
    one of :func:`decoupled_pattern` (gathered from the operator's, ``work.jac``, by ``work.gather``)."""
    work = args[6]
    _bdf2_jacobian(t, y, yp, cj, pattern_target(data, work), args)  # one call site: a smaller kernel to compile
    gather_pattern(data, work)


@njit(cache=True)
def bdf2_residual(t, y, yp, out, args):
    """:func:`~transient.models.journal.kernels.content_residual` with the arguments of
    :meth:`~transient.models.journal.orbit.JournalOrbit.bdf2_model`, on the cell fields of :func:`fields_of`."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    fields_of(y, args)
    stencil_flux(as_read_only(work.u), fields, fv, fields.R, 1.0)
    fx, fy = film_force(fields.P, geo.cosp, geo.sinp, geo.area, rotor.sym)
    content_rows(t, y, yp, out, rotor, geo.area, fields.R, fv.cells.free, fx, fy)


@inner_kernel
def _bdf2_jacobian(t, y, yp, cj, data, args):
    """CSC data of ``(dF/dy + cj dF/dy') dy/dz`` for the content residual ``F = A m' + R(u) = 0`` with ``m' = cj m +
    b`` in the Newton variables ``z = [u, X, Y, VX, VY]`` (:func:`bdf2_to_state`: ``m_j = H_j C(u_j)``), at the cell
    fields of :func:`fields_of`. The film's outflow is a function of u and the position, so its columns are those
    of the universal form (:func:`~transient.models.journal.kernels.stencil_jacobian`)::

        dF_i/du_j = dR_i/du_j + delta_ij cj A_i H_i D_i,   dF_i/dX = dR_i/dX|_u + cj A_i theta_i cos(phi_i)
        dF_VX/du_j = -kappa sym P'_j A_j cos(phi_j),  dF_VX/dX = 0,  dF_X/dX = cj,  dF_X/dVX = -1,  dF_VX/dVX = cj

    (likewise Y, VY with sin); groove cells (``z`` holds m): ``dF_i/dm_i = cj``. Keeps the cells' regimes
    (:func:`cell_regime`) at this Jacobian."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    fields_of(y, args)
    stencil_flux_jacobian(switch, geo, fields, extras, fv, data, 1.0)
    content_columns(cj, rotor, geo, fields, extras, fv, work.u, switch.width, regime, data)


@inner_kernel
def content_columns(cj, rotor, geo, fields, extras, fv, u, width, regime, data):
    """The content form's own Jacobian entries on top of the film's flux columns (:func:`bdf2_jacobian`, and the
    thermal orbit's): the storage ``cj A_i (H_i D_i, C_i cos, C_i sin)`` of the free cells (``cj`` on groove cells),
    the film force's pressure columns in the rotor rows, the rotor's own block; keeps each cell's regime."""
    kappa, wbar, ebar, sym = rotor
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, dP, C, D = fields.H, fields.dP, fields.C, fields.D
    pos_row, pos_col = extras.pos_row, extras.pos_col
    free, pos_c = fv.cells.free, fv.cells.pos_c
    n = free.size
    for i in range(n):
        if free[i]:
            a = cj * area[i]
            data[pos_c[i]] += a * H[i] * D[i]
            data[pos_col[i, 0]] += a * C[i] * cosp[i]
            data[pos_col[i, 1]] += a * C[i] * sinp[i]
        else:
            data[pos_c[i]] = cj
        g = -kappa * sym * dP[i] * area[i]
        data[pos_row[2, i]] = g * cosp[i]
        data[pos_row[3, i]] = g * sinp[i]
        regime[i] = cell_regime(u[i], width)
    for r in range(N_ROTOR):
        for e in range(N_ROTOR):
            data[pos_row[r, n + e]] = cj if r == e else (-1.0 if e == r + 2 else 0.0)


@inner_kernel
def fields_of(y, args):
    """The cell fields of the content state ``y`` in ``fields`` and its universal variable in ``work.u``: those
    :func:`bdf2_to_state` left if they are ``y``'s (the same journal position, ``work.xy``, and every free cell's
    content ``H C(u)`` bitwise equal to ``y``; the stepper evaluates the residual and the Jacobian right after
    mapping its Newton variables), else from the inversion ``u = C^-1(m / H)``
    (:func:`~transient.models.journal.kernels.content_universal`)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    H, C = fields.H, fields.C
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    held = y[n] == work.xy[0] and y[n + 1] == work.xy[1]
    if held:
        for i in range(n):
            if free[i] and H[i] * C[i] != y[i]:
                held = False
                break
    if not held:
        content_universal(as_read_only(y), switch, geo, free, u_fixed, work.theta, work.u)
        state_fields(as_read_only(work.u), y[n], y[n + 1], switch, geo, fields, fv)
        work.xy[0] = y[n]
        work.xy[1] = y[n + 1]


def forget_fields(args):
    """Make the next :func:`fields_of` on ``args`` invert its state (``u = C^-1(m / H)``) rather than take the
    fields the last Newton or a Python caller left in its ``work``: a start's slope is then a function of the start
    state alone, the same bits in a run resumed from a checkpoint as in the uninterrupted one."""
    args[6].xy[0] = np.nan


@inner_kernel
def _bdf2_to_state(z, y, args):
    """The content state ``y = [m, X, Y, VX, VY]`` of the Newton variables ``z = [u, X, Y, VX, VY]``: ``m = H C(u)``
    on the free cells (groove cells: ``z`` holds m). Leaves the cell fields of ``u`` in ``fields``, ``u`` in
    ``work.u`` and the position in ``work.xy`` for the residual and the Jacobian at ``y`` (:func:`fields_of`)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    state_fields(as_read_only(z[:n]), z[n], z[n + 1], switch, geo, fields, fv)
    store_content(z, y, fields.H, fields.C, free, u_fixed, work)


@njit(cache=True)
def store_content(z, y, gap, C, free, u_fixed, work):
    """:func:`bdf2_to_state`'s state from the cell fields of ``z``: the content ``y_i = gap_i C_i`` (``gap``: H, or a
    rough film's mean gap) and ``work.u_i = z_i`` on the free cells, ``y_i = z_i`` and the prescribed u elsewhere;
    the rotor's entries; the position in ``work.xy``."""
    n = free.size
    u = work.u
    for i in range(n):
        if free[i]:
            y[i] = gap[i] * C[i]
            u[i] = z[i]
        else:
            y[i] = z[i]
            u[i] = u_fixed[i]
    for i in range(n, y.size):
        y[i] = z[i]
    work.xy[0] = z[n]
    work.xy[1] = z[n + 1]


@inner_kernel
def _bdf2_from_state(y, z, args):
    """The inverse of :func:`bdf2_to_state` (:func:`~transient.models.journal.kernels.content_universal`, into ``z``:
    the fields and ``work.u`` stay those of the last :func:`bdf2_to_state`)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    free, u_fixed = fv.cells.free, fv.cells.u_fixed
    n = free.size
    content_universal(as_read_only(y), switch, geo, free, u_fixed, work.theta, z[:n])
    keep_prescribed(y, z, free)


@njit(cache=True)
def keep_prescribed(y, z, free):
    """:func:`bdf2_from_state`'s entries of ``z`` that are ``y``'s: the prescribed (groove) cells' contents and the
    rotor's."""
    n = free.size
    for i in range(n):
        if not free[i]:
            z[i] = y[i]
    for i in range(n, y.size):
        z[i] = y[i]


@inner_kernel
def cell_regime(u, width):
    """1 full film, -1 cavitated, 0 inside the switch (|u| <= its pressure width)."""
    return 1 if u > width else (-1 if u < -width else 0)


@inner_kernel
def film_newton_norm(z, dz, args):
    """A Newton update ``du`` of the film in units of its tolerances ``(p_tol, m_tol)``: the largest over the free
    cells of ``|P'(u) du| / p_tol`` (pressure) and ``|H D du| / m_tol`` (content), at the fields of the last
    residual evaluation; and the number of cells whose regime (:func:`cell_regime`) differs from the one at the
    last Jacobian. Limits the update first: a cell outside the switch whose update would carry it across stops at
    u = 0 (the next iteration, on a fresh Jacobian, goes on from there)."""
    switch, rotor, geo, fields, extras, fv, work, tol, regime = args
    return content_newton_norm(z, dz, fields.H, switch.width, fv.cells.free, fields.dP, fields.D, tol, regime)


@njit(cache=True)
def content_newton_norm(z, dz, gap, width, free, dP, D, tol, regime):
    """:func:`film_newton_norm` of a film whose content is ``gap C(u)`` (``gap``: H, or a rough film's mean gap),
    switch width ``width``, cells ``free``, fields ``dP`` and ``D``, tolerances ``tol = (p_tol, m_tol)``."""
    p_tol, m_tol = tol
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
            v = max(a * dP[i] / p_tol, a * gap[i] * D[i] / m_tol)
            if v > size:
                size = v
    return size, switched


# the Newton's kernels as Python calls them (tests, diagnostics): the same functions, cached with entry points
newton_jacobian = entry_point(_newton_jacobian)
bdf2_jacobian = entry_point(_bdf2_jacobian)
bdf2_to_state = entry_point(_bdf2_to_state)
bdf2_from_state = entry_point(_bdf2_from_state)
