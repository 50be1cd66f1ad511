"""The line-contact film in time on the BDF2 stepper, in the film-content (complementarity) form that
:meth:`~transient.models.roller.line_contact.LineContact.steady` solves, so that the transient's long-time limit
is that steady film (:class:`~transient.solvers.integrate.stepper.BDF2`, :class:`~transient.solvers.integrate.stepper.StepSolve`).

The rows of :class:`~transient.models.roller.line_fbns.LineContentFilm` with the storage of the transient
Reynolds equation, time ``tau = t u/b`` (scaled units of :mod:`transient.models.roller.ehl_problem`)::

    R_I(p, theta, h0) - kappa d(rho theta h)_I/dtau = 0,   FB(p_I, 1 - theta_I) = 0,   sum_I dx_I p_I / w_bar = W(tau)/W

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
from scipy import sparse as sp
from scipy.sparse import linalg as spla

from transient.models.roller.line_fbns import OFFSETS, LineContentFilm
from transient.models.roller.line_newton import content_newton
from transient.solvers.integrate.stepper import StepSolve

#: the error test's absolute tolerance as a fraction of rtol: a scaled pressure or content below 1e-2 counts as 1e-2
ATOL_PER_RTOL = 1e-2


class StepRows:
    """The film-content rows of one implicit step (module docstring) of ``content`` (a
    :class:`LineContentFilm`): ``R - kappa cj (q - q_hat)`` with the derivatives of the storage in the local
    slots' centre, under the load ratio ``load_ratio``; everything else is ``content``'s."""

    def __init__(self, content: LineContentFilm, kappa: float, cj: float, q_hat, load_ratio: float):
        self.content, self.kappa, self.cj, self.q_hat, self.load_ratio = content, kappa, cj, q_hat, load_ratio

    def __getattr__(self, name):
        return getattr(self.content, name)

    def equations(self, u, load_ratio=None):
        c = self.content
        e = c.equations(u, self.load_ratio)
        n = c.n
        rho, rh, drh = c.props[0, 1:-1], c.props[5, 1:-1], c.props[6, 1:-1]
        theta = u[n: 2 * n]
        k = self.kappa * self.cj
        e["res"] = e["res"] - k * (rh * theta - self.q_hat)
        e["scale"] = e["scale"] + k * rh
        e["dp"][:, 0] -= k * drh * theta
        e["dh"][:, 0] -= k * rho * theta
        e["dt"][:, 0] -= k * rh
        return e


def storage(content: LineContentFilm, u) -> np.ndarray:
    """``q = rho theta h`` at the interior nodes of the state ``u = [p, theta, h0]``."""
    content.equations(u)
    return content.props[5, 1:-1] * u[content.n: 2 * content.n]


def consistent_content(content: LineContentFilm, p, h0) -> np.ndarray:
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
        rows, cols, vals = [], [], []
        for s, off in enumerate(OFFSETS):
            col = np.arange(n) + off
            ok = (col >= 0) & (col < n)
            rows.append(np.arange(n)[ok])
            cols.append(col[ok])
            vals.append(e["dt"][ok, s])
        J = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))
        Jd = J[dry][:, dry].tocsc()
        u[n + dry] = np.clip(1.0 + spla.spsolve(Jd, -e["res"][dry]), 0.0, 1.0)
    return u


class LineFilmStep(StepSolve):
    """FBNS Newton on one BDF2 step of the line film ``content`` (a :class:`LineContentFilm`) with the storage
    coefficient ``kappa`` under the load ratio ``load_ratio(tau)`` (``W/W_ref``), from the state ``u0`` at
    ``tau = 0``, to the scaled residual ``tol``. Newton starts from the stepper's predictor where its content
    is non-negative, else (and after a failure from the predictor) from the
    last state; ``last``: the last accepted ``(tau, state)``."""

    error_components = None  # the whole state: pressure, content and the rigid approach h0
    test_first_step = False  # a start off the complementarity (dry, or a full outlet): the first step is the jump onto it

    def __init__(self, content: LineContentFilm, kappa: float, u0, load_ratio, tol: float = 1e-10, max_iter: int = 30):
        self.content, self.kappa, self.load_ratio = content, float(kappa), load_ratio
        self.tol, self.max_iter = tol, max_iter
        self.qs = [storage(content, u0)]
        self.newton = 0
        self.factorisations = 0
        self.last = (0.0, np.asarray(u0, float))

    def solve(self, t, cj, history, ts, ys, y_pred):
        n = self.content.n
        rows = StepRows(self.content, self.kappa, cj, -history(self.qs) / cj, self.load_ratio(t))
        u = ys[-1]
        start = y_pred if len(ts) > 1 and np.min(y_pred[n:2 * n]) >= 0.0 else u
        un, ok = self._newton(rows, start, self.tol, self.max_iter)
        if not ok and start is not u:
            un, ok = self._newton(rows, u, self.tol, self.max_iter)
        return (0 if ok else 1), un

    def _newton(self, rows, start, tol, max_iter):
        """:func:`content_newton` from ``start``; where ``start`` already meets ``tol`` one Newton step is taken
        all the same (a corrector of zero would zero the stepper's error estimate, whose step controller then
        remembers a vanishing error and cuts the next step fivefold)."""
        un, ok, stats = content_newton(rows, start, tol, max_iter)
        self.newton += stats.iterations
        self.factorisations += stats.factorisations
        if ok and stats.iterations == 0:
            un, _, stats = content_newton(rows, un, 0.0, 1)
            self.newton += stats.iterations
            self.factorisations += stats.factorisations
        return un, ok

    def accepted(self, t, y):
        self.qs = (self.qs + [storage(self.content, y)])[-3:]
        self.last = (t, y)

    def counts(self):
        return self.newton, self.factorisations
