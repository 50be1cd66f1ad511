"""The line contact's and the tapered roller's film in time on the BDF2 stepper, in the film-content
(complementarity) form that their ``steady()`` solves (:meth:`~transient.models.roller.line_contact.LineContact.steady`,
:meth:`~transient.models.roller.contact.RollerContact.steady_content`), so that the transient's long-time limit
is that steady film (:class:`~transient.solvers.integrate.stepper.BDF2`, :class:`~transient.solvers.integrate.stepper.StepSolve`).

The rows of :class:`~transient.models.roller.line_fbns.LineContentFilm` (or, in 2-D, of
:class:`~transient.models.roller.roller_fbns.RollerContentFilm`: the same kind of rows, one more direction) with
the storage of the transient Reynolds equation, time ``tau = t u/b`` (roller: ``t u/c``; scaled units of
:mod:`transient.models.roller.ehl_problem`)::

    R_I(p, theta, h0) - kappa d(rho theta h)_I/dtau = 0,   FB(p_I, 1 - theta_I) = 0,   sum_I A_I p_I / w_bar = W(tau)/W

``kappa = lam`` (the wedge coefficient: the squeeze term of Reynolds scaled as the wedge term). Every step
solves the full nonsmooth system by the line's Fischer-Burmeister-Newton-Schur iteration
(:func:`~transient.models.roller.line_newton.content_newton`; Hansen, Kacan, Frohnapfel & Codrignani, *Tribol.
Lett.* 70, 2022, for the unsteady FBNS) with the storage ``q = rho theta h`` discretised by the stepper's BDF2,
``dq/dtau = cj (q - q_hat)``, ``q_hat = -b / cj``; as the point contact's
:mod:`~transient.models.point.step_solve` does. Where the film is full the rows are those of the penalty-free
Reynolds-condition problem; at steady state (``cj (q - q_hat) = 0``) they are the steady film-content rows.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from scipy import sparse as sp
from scipy.sparse import linalg as spla
from threadpoolctl import threadpool_limits

from transient.checks import check_choice
from transient.models.ehl.film_run import TRANSIENT_SERIES, run_film
from transient.models.ehl.newton import back_substitute, merit
from transient.models.ehl.reduced import Elimination
from transient.models.roller.line_newton import content_newton
from transient.solvers.integrate.stepper import StepSolve

#: simplified Newton (:class:`FrozenSchur`): the factors are reused while the BDF2 coefficient ``cj`` stays within
#: this relative change of the one they were built with (IDA's rule, 25 %), the corrections shrink the residual by
#: ``SIMPLIFIED_RATE`` at least and converge within ``SIMPLIFIED_ITERS``; else full Newton from the same start
CJ_CHANGE = 0.25
#: what :class:`LineFilmStep` keeps from one step to the next: nothing (a full Newton solve, its factorisations
#: new), the GMRES preconditioner of the Newton steps (above ``line_newton.DIRECT_BELOW`` unknowns: the LU of an
#: earlier Schur matrix, refreshed when GMRES slows), or the Schur matrix's LU for simplified Newton
REUSE = ("none", "preconditioner", "simplified")
SIMPLIFIED_RATE = 0.3
SIMPLIFIED_ITERS = 8


class StepRows:
    """The film-content rows of one implicit step (module docstring) of ``content`` (a line's
    :class:`~transient.models.roller.line_fbns.LineContentFilm` or a roller's content film): ``R - kappa cj (q - q_hat)`` with the derivatives of the storage in the local
    slots' centre, under the load ratio ``load_ratio``; everything else is ``content``'s."""

    def __init__(self, content, kappa: float, cj: float, q_hat, load_ratio: float):
        self.content, self.kappa, self.cj, self.q_hat, self.load_ratio = content, kappa, cj, q_hat, load_ratio

    def __getattr__(self, name):
        return getattr(self.content, name)

    def equations(self, u, load_ratio=None):
        c = self.content
        e = c.equations(u, self.load_ratio)
        n = c.n
        rho, rh, drh = c.storage_terms()
        theta = u[n: 2 * n]
        k = self.kappa * self.cj
        e["res"] = e["res"] - k * (rh * theta - self.q_hat)
        e["scale"] = e["scale"] + k * rh
        e["dp"][:, 0] -= k * drh * theta
        e["dh"][:, 0] -= k * rho * theta
        e["dt"][:, 0] -= k * rh
        return e


def storage(content, u) -> np.ndarray:
    """``q = rho theta h`` at the interior nodes of the state ``u = [p, theta, h0]`` of ``content`` (a line's
    or a roller's content film)."""
    content.equations(u)
    return content.storage_terms()[1] * u[content.n: 2 * content.n]


def consistent_content(content, p, h0) -> np.ndarray:
    """The state ``[p, theta, h0]`` of a pressure and rigid approach from the Reynolds-condition form (or a
    dry start): ``p`` clipped at 0; ``theta = 1`` where ``p > 0``, and where ``p = 0`` the content that
    conserves the mass flux (the Reynolds rows there solved for ``theta``, linear in it, then clipped to
    ``[0, 1]``)."""
    n = content.n
    p = np.maximum(np.asarray(p, float), 0.0)
    u = np.concatenate([p, np.ones(n), [float(h0)]])
    dry = np.nonzero(p <= 0.0)[0]
    if dry.size:
        e = content.equations(u)
        columns = content.local_columns()
        rows, cols, vals = [], [], []
        for s in range(columns.shape[1]):
            col = columns[:, s]
            ok = col >= 0
            rows.append(np.arange(n)[ok])
            cols.append(col[ok])
            vals.append(e["dt"][ok, s])
        J = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))
        Jd = J[dry][:, dry].tocsc()
        u[n + dry] = np.clip(1.0 + spla.spsolve(Jd, -e["res"][dry]), 0.0, 1.0)
    return u


class FrozenSchur:
    """Simplified Newton's matrix for the step rows ``rows`` at ``u`` (residual pieces ``e``): the node-wise
    elimination of the Fischer-Burmeister rows (:class:`~transient.models.ehl.reduced.Elimination`) and the Schur
    matrix of that iterate, LU-factorised once (LAPACK) and kept across iterations and steps
    (:meth:`LineFilmStep.solve`); ``cj``: the BDF2 coefficient it was built with."""

    def __init__(self, rows, u, e, cj: float):
        self.elimination = Elimination(*rows.fb_derivatives(u, e))
        S = rows.schur_matrix(e, self.elimination.b_p, self.elimination.b_t)
        S[:-1] /= e["scale"][:, None]
        self.lu = sla.lu_factor(S, check_finite=False)
        self.local = {k: e[k] for k in ("dp", "dh", "dt", "scale")}
        self.cj = float(cj)

    def step(self, rows, e) -> np.ndarray:
        """The simplified Newton correction ``du`` for the residual pieces ``e`` of the current iterate."""
        n = rows.n
        a_p, a_th = self.elimination.offsets(e["fb"])
        r = np.empty(n + 1)
        r[:-1] = (-e["res"] - rows.jacobian_product(self.local, a_p, a_th)) / self.local["scale"]
        r[-1] = -e["load"] - rows.weight @ a_p
        z = sla.lu_solve(self.lu, r, check_finite=False)
        return back_substitute((a_p, self.elimination.b_p, a_th, self.elimination.b_t), z)


class LineFilmStep(StepSolve):
    """FBNS Newton on one BDF2 step of the film ``content`` (a :class:`~transient.models.roller.line_fbns.LineContentFilm` or a
    :class:`~transient.models.roller.roller_fbns.RollerContentFilm`) with the storage
    coefficient ``kappa`` under the load ratio ``load_ratio(tau)`` (``W/W_ref``), from the state ``u0`` at
    ``tau = t0``, to the scaled residual ``tol``. Newton starts from the stepper's predictor where its content
    is non-negative, else (and after a failure from the predictor) from the
    last state; ``last``: the last accepted ``(tau, state)``."""

    error_components = None  # the whole state: pressure, content and the rigid approach h0
    test_first_step = False  # a start off the complementarity (dry, or a full outlet): the first step is the jump onto it

    def __init__(self, content, kappa: float, u0, load_ratio, tol: float = 1e-10, max_iter: int = 30,
                 reuse: str = "preconditioner", t0: float = 0.0):
        self.content, self.kappa, self.load_ratio = content, float(kappa), load_ratio
        self.tol, self.max_iter = tol, max_iter
        self.reuse = check_choice("reuse", reuse, REUSE)
        self.preconditioner = None
        self.qs = [storage(content, u0)]
        self.newton = 0
        self.factorisations = 0
        self.simplified = 0
        self.frozen = None
        self.last = (t0, np.asarray(u0, float))

    def solve(self, t, cj, history, ts, ys, y_pred):
        n = self.content.n
        rows = StepRows(self.content, self.kappa, cj, -history(self.qs) / cj, self.load_ratio(t))
        u = ys[-1]
        start = y_pred if len(ts) > 1 and np.min(y_pred[n:2 * n]) >= 0.0 else u
        if self.frozen is not None and abs(cj / self.frozen.cj - 1.0) <= CJ_CHANGE:
            un, ok = self._simplified(rows, start)
            if ok:
                return 0, un
        un, ok = self._newton(rows, start, self.tol, self.max_iter)
        if not ok and start is not u:
            un, ok = self._newton(rows, u, self.tol, self.max_iter)
        if ok and self.reuse == "simplified":
            self.frozen = FrozenSchur(rows, un, rows.equations(un), cj)
            self.factorisations += 1
        return (0 if ok else 1), un

    def _simplified(self, rows, u):
        """Simplified Newton from ``u`` with :attr:`frozen`'s factors: at least one correction (as
        :meth:`_newton`), at most ``SIMPLIFIED_ITERS``, each reducing the scaled residual by ``SIMPLIFIED_RATE``
        at least, the film positive and the content non-negative; ``(u, converged)``."""
        e = rows.equations(u)
        norm = float(np.max(np.abs(merit(e, e["scale"]))))
        n = rows.n
        for k in range(SIMPLIFIED_ITERS):
            if k and norm < self.tol:
                return u, True
            u = u + self.frozen.step(rows, e)
            self.simplified += 1
            with np.errstate(over="ignore", invalid="ignore"):
                e = rows.equations(u)
                new = float(np.max(np.abs(merit(e, e["scale"]))))
            if not (np.min(e["H"]) > 0.0 and np.min(u[n: 2 * n]) >= -self.tol and new <= SIMPLIFIED_RATE * norm):
                return u, False
            norm = new
        return u, norm < self.tol

    def _newton(self, rows, start, tol, max_iter):
        """:func:`content_newton` from ``start``; where ``start`` already meets ``tol`` one Newton step is taken
        all the same (a corrector of zero would zero the stepper's error estimate, whose step controller then
        remembers a vanishing error and cuts the next step fivefold)."""
        keep = self.reuse == "preconditioner"
        un, ok, stats = content_newton(rows, start, tol, max_iter, preconditioner=self.preconditioner if keep else None)
        self.newton += stats.iterations
        self.factorisations += stats.factorisations
        if ok and stats.iterations == 0:
            un, _, stats = content_newton(rows, un, 0.0, 1, preconditioner=stats.preconditioner if keep else None)
            self.newton += stats.iterations
            self.factorisations += stats.factorisations
        if keep:
            self.preconditioner = stats.preconditioner
        return un, ok

    def accepted(self, t, y):
        self.qs = (self.qs + [storage(self.content, y)])[-3:]
        self.last = (t, y)

    def counts(self):
        return self.newton + self.simplified, self.factorisations

    def switched(self, y_new, ys):
        """The pressure and content of every node on the other side of the cavitation boundary (pressure
        positive at one, zero at the other) at the step's end than at one of the predictor's points ``ys``: their
        corner in time is the complementarity's, not a truncation error, so the stepper's error test leaves them
        out."""
        n = self.content.n
        full = y_new[:n] > 0.0
        out = np.zeros(y_new.size, dtype=bool)
        for y in ys:
            out[:n] |= full != (y[:n] > 0.0)
        out[n:2 * n] = out[:n]
        return out


def run_content_transient(content, kappa: float, u0, ratio, tau_end: float, n_out: int, sample, result, settings,
                          max_steps: int, key: dict, label: str):
    """Integrate the film ``content`` from ``u0`` to the scaled time ``tau_end`` by BDF2 on :class:`LineFilmStep`
    under the load ratio ``ratio(tau)`` on the one run driver (:func:`~transient.models.ehl.film_run.run_film`:
    ``n_out`` outputs ``sample(tau, u)`` of :data:`~transient.models.ehl.film_run.TRANSIENT_SERIES`,
    ``result(arrays, last_state, stats, message)``,
    ``settings`` the run's ``(Integration, LongRun)``); the line contact's and the roller's
    ``transient(method="bdf2")``."""
    ig, lr = settings
    # one BLAS thread: the step's dense solves are too small for threads to pay (measured on a 401-node
    # line: LAPACK's solve of one Schur matrix 4 ms CPU on one thread, 74 ms on two busy cores)
    with threadpool_limits(limits=1, user_api="blas"):
        return run_film(label, lambda u, tau: LineFilmStep(content, kappa, u, ratio, t0=tau), u0, tau_end, n_out,
                        sample, TRANSIENT_SERIES, result, ig, lr, max_steps, dict(key, kappa=kappa))
