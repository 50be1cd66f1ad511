"""The point-contact film in time on the BDF2 stepper: the solve of one implicit step and the pseudo-transient
continuation to the steady film (:class:`~transient.solvers.integrate.stepper.BDF2`, :class:`~transient.solvers.integrate.stepper.StepSolve`).

The transient Reynolds rows of :mod:`transient.models.point.ehl_problem`, time ``T = t u/b``::

    R(P, theta, H0) - d(rho theta H)/dT = 0,   FB(P, 1 - theta) = 0,   load balance at W(T)/W

are a DAE whose algebraic part switches node by node between the pressure and the content (the
complementarity rows). As Hansen, Kacan, Frohnapfel & Codrignani (*Tribol. Lett.* 70, 2022) do for the
unsteady FBNS, every step solves the full nonsmooth system by Newton (:func:`~transient.models.point.fbns.fbns`)
with the storage ``q = rho theta H`` discretised by the stepper's BDF2: ``dq/dT = cj (q - q_hat)``,
``q_hat = -b / cj`` with ``b`` the stepper's history of ``q``. (SUNDIALS' correctors stall where the
complementarity rows switch, as documented for the roller.)
"""

from __future__ import annotations

import numpy as np

from transient.models.ehl.film_run import ATOL_PER_RTOL
from transient.models.point.fbns import fbns, merit
from transient.solvers.integrate.stepper import BDF2, StepBounds, StepSolve


class FilmStep(StepSolve):
    """FBNS Newton on one BDF2 step of the point film ``film`` (a
    :class:`~transient.models.point.ehl_problem.PointFilm`) under the load ``load_ratio(T)`` (``W(T)/W``), from
    the state ``u0`` at the scaled time ``t0``, to the scaled residual ``tol``. Newton starts from the stepper's predictor
    where its content is non-negative, else (and after a failure from the predictor) from the last state;
    ``last``: the last accepted ``(T, state)``."""

    error_components = None  # the whole state: pressure, content and the rigid approach H0
    test_first_step = False  # the dry start is not on the film's constraints: the first step is the jump onto them

    def __init__(self, film, u0, load_ratio, tol=1e-9, max_iter=30, t0=0.0):
        self.film, self.load_ratio, self.tol, self.max_iter = film, load_ratio, tol, max_iter
        self.qs = [self._storage(t0, u0)]
        self.newton = 0
        self.last = (t0, np.asarray(u0, float))  # the last accepted (T, state)

    def _storage(self, T, u):
        return self.film.storage(self.film.equations(u, self.load_ratio(T)))

    def solve(self, t, cj, history, ts, ys, y_pred):
        film, n = self.film, self.film.n
        q_hat = -history(self.qs) / cj
        u = ys[-1]
        start = y_pred if len(ts) > 1 and np.min(y_pred[n:2 * n]) >= 0.0 else u
        un, ok, norms = fbns(film, start, self.tol, self.max_iter, self.load_ratio(t), cj=cj, q_hat=q_hat)
        self.newton += len(norms) - 1
        if not ok and start is not u:
            un, ok, norms = fbns(film, u, self.tol, self.max_iter, self.load_ratio(t), cj=cj, q_hat=q_hat)
            self.newton += len(norms) - 1
        return (0 if ok else 1), un

    def accepted(self, t, y):
        self.qs = (self.qs + [self._storage(t, y)])[-3:]
        self.last = (t, y)

    def counts(self):
        return 0, self.newton


def steady_by_time_steps(film, u0, tol=1e-8, t_max=1e4, rtol=0.3):
    """Pseudo-transient continuation to the steady state: the physical transient (:class:`FilmStep` on the BDF2
    stepper, driven here step by step) with a loose error control until the steady residual falls below 1e-3,
    then steady Newton; if Newton stalls there (a node cycling on a kink of the complementarity), the transient
    goes on (its steps grow to ~T) until the steady residual is below ``tol``. Returns ``(u, ok, norms, counts)``."""
    def steady_residual(u):
        return float(np.max(np.abs(merit(film, film.equations(u)))))

    counts = dict(steps=0, rejected=0, newton_failures=0, newton=0, T=0.0)

    def march(u, first_step, level):
        step = FilmStep(film, u, lambda T: 1.0)
        stepper = BDF2(step, np.asarray(u, float), 0.0, t_max, rtol=rtol, atol=ATOL_PER_RTOL * rtol,
                       bounds=StepBounds(first_step=first_step), test_first_step=False)
        while stepper.t < t_max and stepper.step() is None and steady_residual(stepper.y) >= level:
            pass
        counts["steps"] += stepper.n_steps
        counts["rejected"] += stepper.n_error_test_failures
        counts["newton_failures"] += stepper.n_nonlinear_failures
        counts["newton"] += step.newton
        counts["T"] += stepper.t
        return stepper.y, stepper.t

    u, T = march(u0, 1e-2, 1e-3)
    us, oks, norms = fbns(film, u, tol, 60)
    if not oks:
        u, _ = march(u, T / 10.0 if T > 0 else 1e-2, tol)
        norms = [steady_residual(u)]
        us, oks = u, norms[-1] < tol
    return us, oks, norms, counts
