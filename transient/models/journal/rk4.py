"""The paper's time scheme for the journal orbit, done well: the users' hand-coded baseline (Rho & Kim).

Classical RK4 on the rotor with N steps per revolution; the film is solved at every stage for the
stage's rotor state, its time derivative by a backward-Euler step from the film of the last completed
step (Elrod 1981), Newton iterations to the paper's criterion ``sum|theta^k - theta^(k-1)| / sum theta^k
< 1e-6`` (eq. 6), reusing one sparse LU across iterations, stages and steps while it contracts (chord).
"""

from __future__ import annotations

import numpy as np

from transient.models.journal.kernels import film_force, rotor_accelerations
from transient.solvers.integrate import Problem
from transient.solvers.newton import Chord, NewtonError, NewtonSettings, newton


class FilmStageSolver:
    """Per-stage film solve of the RK4 baseline (paper: Elrod iteration every time step).

    For the rotor state of a stage at time ``tau_s`` it solves the film equations with the squeeze rate
    of the stage and a backward-Euler time derivative from the film ``u_n`` of the step start::

        A_i (theta_i H'_i + H_i / beta_bar (u_i - u_n,i) / (tau_s - tau_n)) + R_i(u) = 0

    by Newton iterations until the paper's criterion (eq. 6) ``sum|d theta| / sum theta < 1e-6``. The
    LU factorisation is reused across iterations, stages and steps, and refreshed when an iteration
    fails to contract (chord Newton).
    """

    def __init__(self, orbit, criterion=1e-6, max_iter=50):
        self.orbit = orbit
        self.film = orbit.bearing.film(orbit.speed_rpm, n_extra=0)
        self.n = self.film.n
        self.criterion = criterion
        self.max_iter = max_iter
        self.chord = Chord()
        self.n_iterations = 0
        self.t_hist = None
        self.u_hist = None
        self.theta_hist = None
        self.data = np.empty(self.film.op.nnz)

    def problem(self, y0, tau0) -> Problem:
        o, f = self.orbit, self.film
        n = self.n
        w = f

        def rhs(t, y, out):  # rotor only; the cells' entries are ignored (algebraic)
            fx, fy = film_force(w.P, w.cosp, w.sinp, w.area, w.sym)  # P of the film just solved for y
            out[:n] = 0.0
            out[n] = y[n + 2]
            out[n + 1] = y[n + 3]
            out[n + 2], out[n + 3] = rotor_accelerations(t, fx, fy, o.kappa, o.wbar, o.ebar)

        def step_begin(t, y):
            if self.t_hist is None:
                self.u_hist = y[:n].copy()
            elif t > self.t_hist:  # film at the new step start, for the rotor state RK4 produced
                self.u_hist = self._solve(t, y)
            else:
                return
            self.t_hist = t
            f.residual(self.u_hist, y[n], y[n + 1], y[n + 2], y[n + 3])
            self.theta_hist = f.C.copy()

        def algebraic_solve(t, y):
            if self.t_hist is None:  # the initial state: its film is the history
                step_begin(t, y)
            y = y.copy()
            y[:n] = self._solve(t, y) if t > self.t_hist else self.u_hist
            if t <= self.t_hist:  # the fields (P) must correspond to this film for rhs
                f.residual(y[:n], y[n], y[n + 1], y[n + 2], y[n + 3])
            return y

        return Problem(y0=np.asarray(y0, dtype=float), rhs=rhs, algebraic=np.arange(n),
                       algebraic_solve=algebraic_solve, step_begin=step_begin, name="journal orbit (RK4 + film)")

    def _solve(self, t, y):
        """Film at stage time t for the stage's rotor state y: chord Newton (one factorisation kept across
        iterations, stages and steps while it contracts) to the paper's criterion on theta."""
        n, f = self.n, self.film
        X, Y, VX, VY = y[n], y[n + 1], y[n + 2], y[n + 3]
        rate = 1.0 / (t - self.t_hist)
        G = lambda v: f.residual(v, X, Y, VX, VY, rate=rate, C_ref=self.theta_hist)  # noqa: E731
        J = lambda v, shift: f.op.matrix(f.jacobian_data(v, X, Y, VX, VY, rate=rate, data=self.data))  # noqa: E731
        G(self.u_hist)
        theta = [f.C.copy()]

        def converged(v, r, dv):  # paper eq. (6); the scratch fields hold the last iterate's film
            new = f.C.copy()
            done = np.sum(np.abs(new - theta[0])) < self.criterion * np.sum(new)
            theta[0] = new
            return done

        try:
            res = newton(G, J, self.u_hist, chord=self.chord, converged=converged,
                         settings=NewtonSettings(max_iter=self.max_iter), name="RK4 film iteration")
        except NewtonError:
            raise RuntimeError(f"RK4 film iteration did not reach the criterion {self.criterion} in {self.max_iter} "
                               f"iterations at tau = {t:.6g}") from None
        self.n_iterations += res.iterations
        return res.x

    @property
    def n_factorisations(self) -> int:
        return self.chord.n_factorisations
