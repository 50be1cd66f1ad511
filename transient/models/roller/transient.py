"""Transient EHL (Park, extended in time): the squeeze-film DAE integrated by IDA.

Reynolds with the squeeze term, in the scaled units of :mod:`transient.models.roller.ehl_problem` (time
``tau`` in units of ``t_ref``; rolling: ``t_ref = b/u`` and ``kappa = lam``)::

    G = F(p, h) - kappa [rho'(p) h dp/dtau + rho(p) dh/dtau],   dh/dtau = dh0/dtau + k_el K dp/dtau
    -G/d + gamma min(p, 0) = 0     (penalty form of the Reynolds exit condition, gamma = 1e4, smoothed)
    sum_i A_i p_i / W_ref - W(t)/W_ref = 0                        (load balance, algebraic)

Unknowns ``y = [p, h0]``. The pressure derivative enters through the elastic film and the density;
``h0`` is fixed by the load constraint, whose gradient is transverse to the null space of
``dF/dy'`` -- an index-1 DAE. IDA (through :func:`transient.solvers.integrate.solve`, dense Jacobian
``dR/dy + cj dR/dy'`` filled analytically: the storage terms enter the local Jacobian's centre slot,
:func:`~transient.models.roller.kernels.assemble_dense`).

Consistent start: from a state ``y0`` (the dry pressure with a lifted film, or a steady solution) one
backward-Euler step of length ``dt0`` is solved by Newton; ``(y1, (y1 - y0)/dt0)`` satisfies the
DAE residual exactly at ``t0 + dt0`` and starts IDA.
"""

from __future__ import annotations

import time

import numpy as np

from transient.checks import check_positive, check_range
from transient.models.roller.ehl_problem import EHLFilm
from transient.models.roller.kernels import assemble_dense
from transient.solvers.integrate import Problem, solve
from transient.solvers.newton import NewtonSettings, newton

#: penalty factor of the transient's complementarity form (kernels.penalty): IDA's corrector fails where
#: Fischer-Burmeister rows switch between differential and algebraic; the penalty keeps every row a
#: Reynolds row. Its steady state is steady(penalty=GAMMA), which differs from the exact one by O(1/GAMMA)
#: (docs/ehl.md gives the convergence study).
GAMMA = 1e4
#: IDA options: a semismooth corrector needs more than the default 4 Newton iterations near switches
IDA_OPTIONS = {"max_nonlin_iters": 10, "max_conv_fails": 50}


class SqueezeDAE:
    """Residual and dense Jacobian of the transient film (module docstring). ``load_ratio(tau)``:
    ``W(t)/W_ref`` at scaled time ``tau``."""

    def __init__(self, film: EHLFilm, kappa: float, load_ratio, gamma: float = GAMMA):
        self.film = film
        film.penalty = gamma
        self.kappa = float(kappa)
        self.load_ratio = load_ratio
        self.n = film.n
        self.error = None

    def _terms(self, y, yp, jac):
        f = self.film
        p, h0 = y[:-1], y[-1]
        h = f.film(p, h0)
        F = f.reynolds(p, h, jac=jac)
        c = f.colh[:, 0]
        rho, drho = f.props[0][c], f.props[1][c]
        hdot = (yp[-1] + f.deformation(yp[:-1]))[c]
        G = F - self.kappa * (drho * h[c] * yp[:-1] + rho * hdot)
        return p, G, rho, drho, h[c], hdot

    def residual(self, t, y, yp, out):
        f = self.film
        p, G, *_ = self._terms(y, yp, False)
        f.complementarity(p, -G * f.row_scale, out[:-1])
        out[-1] = f.area_w @ p - self.load_ratio(t)

    def jacobian(self, t, y, yp, cj, J):
        try:
            f = self.film
            p, G, rho, drho, hc, hdot = self._terms(y, yp, True)
            f.complementarity(p, -G * f.row_scale, f.phi)
            k = self.kappa
            f.Sp[:, 0] -= k * drho * (hdot + cj * hc)
            f.Sh[:, 0] -= k * (drho * yp[:-1] + cj * rho)
            K = f.K if f.elastic == "dense" else np.zeros((1, 1))
            assemble_dense(f.Sp, f.Sh, f.colp, f.colh, K, f.elastic == "dense", f.fb_a, f.fb_b * f.row_scale,
                           f.area_w, J)
        except Exception as exc:  # noqa: BLE001 -- an exception inside a SUNDIALS callback can crash the process
            self.error = exc
            J[:] = np.eye(J.shape[0])

    def consistent_start(self, t0, y0, dt0):
        """One backward-Euler step from ``y0``: ``(t1, y1, yp1)`` with ``R(t1, y1, yp1) = 0``."""
        t1 = t0 + dt0
        buf = np.empty(self.n + 1)
        J = np.empty((self.n + 1, self.n + 1))

        def res(y):
            self.residual(t1, y, (y - y0) / dt0, buf)
            return buf.copy()

        def jac(y, shift):
            self.jacobian(t1, y, (y - y0) / dt0, 1.0 / dt0, J)
            return J.copy()

        def converged(y, r, dy):
            scale = max(1.0, float(np.max(np.abs(y))))
            return float(np.max(np.abs(r))) <= 1e-10 and float(np.max(np.abs(dy))) <= 1e-10 * scale

        guess = y0.copy()  # off the Fischer-Burmeister kink (p = 0 and F = 0) where y0 has no pressure
        guess[:-1] = np.maximum(guess[:-1], 1e-3 * max(1.0, float(np.max(y0[:-1]))))
        nr = newton(res, jac, guess, converged=converged, settings=NewtonSettings(max_iter=50),
                    max_step=self.film.step_limit, name="transient EHL start (backward-Euler step)")
        return t1, nr.x, (nr.x - y0) / dt0


def integrate(dae: SqueezeDAE, y0, tau_eval, rtol: float, dt0: float):
    """IDA from ``y0`` at ``tau_eval[0]`` (consistent start by one backward-Euler step of ``dt0``);
    returns the facade's Solution (outputs at ``tau_eval``; the first is ``y0`` itself) and the wall
    time."""
    t0 = time.perf_counter()
    dae.film.set_row_scale(y0)
    t1, y1, yp1 = dae.consistent_start(tau_eval[0], np.asarray(y0, float), dt0)
    if not tau_eval[1] > t1:
        raise ValueError(f"the first output after the start must come after the start step (tau > {t1:g})")
    prob = Problem(y0=y1, yp0=yp1, residual=dae.residual, jac_residual=dae.jacobian, name="transient EHL")
    sol = solve(prob, np.concatenate(([t1], tau_eval[1:])), method="ida", rtol=rtol, atol=rtol * 1e-2,
                options=IDA_OPTIONS)
    if dae.error is not None:
        raise dae.error
    sol.y[0] = y0
    sol.t[0] = tau_eval[0]
    return sol, time.perf_counter() - t0


def load_ratio(load, w_ref, w_start, t_ref, ramp_time):
    """``W(t)/W_ref`` as a function of scaled time: constant, a smoothed step, or the user's function."""
    if load is None:
        return lambda tau: w_start / w_ref
    if callable(load):
        return lambda tau: float(load(tau * t_ref)) / w_ref
    w_end = check_positive("load", load, "N/m or N")
    t_ramp = (1.0 if ramp_time is None else check_positive("ramp_time", ramp_time, "s") / t_ref)

    def ratio(tau):
        s = min(max(tau / t_ramp, 0.0), 1.0)
        return (w_start + (w_end - w_start) * s * s * (3.0 - 2.0 * s)) / w_ref

    return ratio


def run_squeeze(film: EHLFilm, kappa: float, ratio, y0, t_end: float, t_ref: float, rtol: float, n_out, row):
    """The squeeze DAE of ``film`` from ``y0`` over ``t_end`` [s] (time unit ``t_ref`` [s]) with ``n_out``
    outputs and the load ratio ``ratio(tau)``; returns (Solution, wall time, ``[row(film, y)]`` per output)."""
    dae = SqueezeDAE(film, kappa, ratio)
    tau = np.linspace(0.0, t_end / t_ref, int(check_range("n_out", n_out, "-", 2, 1e6)))
    sol, wall = integrate(dae, y0, tau, rtol, dt0=1e-3 * tau[1])
    return sol, wall, [row(film, y) for y in sol.y]
