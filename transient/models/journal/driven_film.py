"""The content film + rotor of a smooth journal orbit at a shaft speed that varies in time, with a per-cell fluidity,
in the form the BDF2 stepper takes: the orbit with a speed law (:mod:`~transient.models.journal.speed_law`) and the
thermal orbit (:mod:`~transient.models.journal.thermal_orbit`, its fluidity frozen over each thermal interval).

The kernels are the content formulation's (:mod:`~transient.models.journal.content_newton`) with the Poiseuille
conductances times the fluidity ``f = mu_ref / mu`` of each cell (1: the isothermal film), the Couette flux times the
speed ratio ``s(tau)`` and the unbalance force at the shaft angle ``phi(tau)``
(:func:`~transient.models.journal.kernels.shaft_accelerations`), both from the law's knots
(:func:`~transient.models.journal.speed_law.shaft_speed`). ``args = (content args, fluidity, knots)``; at f = 1 and a
constant law they are the content kernels' arithmetic, bit for bit.
"""

from __future__ import annotations

from numba import njit

import transient.solvers.integrate.bdf2 as stepper
from transient.models.journal.content_newton import (_bdf2_from_state as bdf2_from_state,
                                                     _bdf2_to_state as bdf2_to_state, content_columns, fields_of,
                                                     film_newton_norm, gather_pattern, pattern_target)
from transient.models.journal.kernels import (content_rows_at, film_force, shaft_accelerations, state_fields,
                                              stencil_flux)
from transient.models.journal.speed_law import shaft_speed
from transient.models.journal.viscous_film import fluidity_flux_jacobian
from transient.solvers.integrate.bdf2 import newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.read_only import as_read_only


@njit(cache=True)
def scale_fields(fields, fluidity, s, switch):
    """The conductances of the cells' fields (from their H, idempotent): ``k = f (H - gap)^3 / 2 + darcy H`` times
    the fluidity ``f``, ``c = s H / 2``."""
    layer_gap, darcy = switch.layer_gap, switch.darcy
    H, k, c = fields.H, fields.k, fields.c
    for i in range(H.size):
        h = H[i]
        hb = h - layer_gap if h > layer_gap else 0.0
        k[i] = fluidity[i] * (0.5 * hb * hb * hb + darcy * h)
        c[i] = s * (0.5 * h)


@njit(cache=True)
def driven_fields(u, X, Y, s, fluidity, switch, geo, fields, fv):
    """The cell fields of the universal state ``u`` at ``(X, Y)`` with the fluidity and speed ratio ``s``."""
    state_fields(u, X, Y, switch, geo, fields, fv)
    scale_fields(fields, fluidity, s, switch)


@njit(cache=True)
def driven_residual(t, y, yp, out, args):
    """The content residual (:func:`~transient.models.journal.content_newton.bdf2_residual`) on the fluidity, the
    Couette flux at the shaft's speed and the unbalance at its angle (module docstring)."""
    base, flu, knots = args
    switch, rotor, geo, fields, extras, fv, work, tol, regime = base
    kappa, wbar, ebar, sym = rotor
    fields_of(y, base)
    s, ds, phi = shaft_speed(t, knots)
    scale_fields(fields, flu, s, switch)
    stencil_flux(as_read_only(work.u), fields, fv, fields.R, 1.0)
    fx, fy = film_force(fields.P, geo.cosp, geo.sinp, geo.area, sym)
    ax, ay = shaft_accelerations(s, ds, phi, fx, fy, kappa, wbar, ebar)
    content_rows_at(y, yp, out, geo.area, fields.R, fv.cells.free, ax, ay)


@njit(cache=True)
def driven_jacobian(t, y, yp, cj, data, args):
    """:func:`~transient.models.journal.content_newton.bdf2_jacobian` (operator pattern) with the conductances of
    :func:`scale_fields` and their position derivatives times the fluidity (Poiseuille) and ``s`` (Couette)."""
    base, flu, knots = args
    switch, rotor, geo, fields, extras, fv, work, tol, regime = base
    fields_of(y, base)
    s = shaft_speed(t, knots)[0]
    scale_fields(fields, flu, s, switch)
    fluidity_flux_jacobian(flu, s, switch, geo, fields, extras, fv, data)
    content_columns(cj, rotor, geo, fields, extras, fv, work.u, switch.width, regime, data)


@njit(cache=True)
def driven_newton_jacobian(t, y, yp, cj, data, args):
    """:func:`driven_jacobian` in the problem's pattern (the operator's, or the decoupled one gathered from it)."""
    work = args[0][6]
    driven_jacobian(t, y, yp, cj, pattern_target(data, work), args)
    gather_pattern(data, work)


@njit(cache=True)
def driven_norm(z, dz, args):
    return film_newton_norm(z, dz, args[0])


@njit(cache=True)
def driven_to_state(z, y, args):
    bdf2_to_state(z, y, args[0])


@njit(cache=True)
def driven_from_state(y, z, args):
    bdf2_from_state(y, z, args[0])


@njit(cache=True)  # newton_step is inlined (its kernels are this module's globals): cached on disk like a kernel
def driven_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the driven content film + rotor."""
    return newton_step(driven_residual, driven_newton_jacobian, driven_norm, driven_to_state, driven_from_state,
                       args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts)


drop_stale_cache(driven_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined
