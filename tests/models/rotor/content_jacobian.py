"""The rotor system's BDF2 Newton Jacobian and its finite-difference counterpart at a perturbed, off-centre state,
shared by the rotor's Jacobian tests."""

import numpy as np

from transient.models.rotor.content_form import ContentSystem
from transient.models.rotor.content_newton import rotor_jacobian, rotor_residual, rotor_to_state


def content_jacobians(system, speed_rpm, seed, fd_jacobian):
    """(form, dae, J, Jfd, cols): dF/dz of the content residual with y' = cj y + b (as in a BDF2 step) on a speed ramp
    (s, s' = 0.8 + 0.01 tau, 0.01), analytic and by differences, at a state with the journals moved off their start
    guess; ``cols`` the columns of the free cells and the rotor."""
    dae = system.dae(speed_rpm, lambda tau: (0.8 + 0.01 * tau, 0.01))
    form = ContentSystem(dae)
    rng = np.random.default_rng(seed)
    z = system._start_guess(dae, 0.8)
    z[dae.Q0:dae.P0] += 0.05 * rng.standard_normal(2 * dae.nq)
    z[dae.P0] = 0.7
    tau, cj = 0.3, 37.0
    form.set_speed(tau)
    args = form.args
    y = np.empty(dae.n)
    rotor_to_state(z, y, args)
    b = -cj * y + 0.01 * rng.standard_normal(dae.n)

    def F(zz):
        yy = np.empty(dae.n)
        rotor_to_state(zz, yy, args)
        out = np.empty(dae.n)
        rotor_residual(tau, yy, cj * yy + b, out, args)
        return out

    data = np.zeros(form.pattern.nnz)
    rotor_to_state(z, y, args)
    rotor_jacobian(tau, y, cj * y + b, cj, data, args)
    J = form.pattern.copy()
    J.data = data
    J = J.toarray()
    free = np.ones(dae.n, dtype=bool)
    for blk in dae.blocks:
        free[blk.offset:blk.offset + blk.n] = blk.film.op.free
    width = min(blk.film.width for blk in dae.blocks)
    Jfd = fd_jacobian(F, z, dae.n, step=5e-4 * width)
    return form, dae, J, Jfd, np.flatnonzero(free)
