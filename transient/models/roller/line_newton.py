"""Fischer-Burmeister-Newton-Schur iteration of the line contact with a reused factorisation.

Newton on the film-content equations of :class:`~transient.models.roller.line_fbns.LineContentFilm`
(Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.* 58, 2015; Hansen et al., *Tribol. Lett.* 70, 2022):
each Fischer-Burmeister row ``a dp + g dtheta = -FB`` is diagonal, so one unknown per node is eliminated
(theta where ``|g| >= |a|``, the pressure otherwise), leaving the exact ``(n + 1)`` Schur matrix ``S``
(dense: the elastic coupling). ``S`` is assembled every iteration (``O(n^2)``) but factorised only now and
then: the step solves ``S dz = r`` by right-preconditioned GMRES (Saad & Schultz, 1986; the point film's
:func:`~transient.models.ehl.krylov.gmres_solve`) with the LU factors of an earlier ``S`` in single
precision; a new factorisation is made when GMRES needs more than :data:`REFACTOR_ITERS` iterations or does
not reach its tolerance. Near the solution ``S`` changes
little, so most Newton iterations cost a few ``O(n^2)`` products instead of an ``O(n^3)`` LU. On the
DC-FFT film of fine uniform grids (``film.matrix_free``) ``S`` is never formed: its products and the
two-level preconditioner of :mod:`transient.models.roller.line_fft` take the step (``O(n log n)`` per
product).

Globalisation as :func:`transient.models.point.fbns.fbns`: the step is cut so that the film stays
positive and no pressure moves by more than ``step_max`` plus half its value, then halved until the
scaled residual norm decreases (Armijo).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

from transient.models.ehl.errors import InexactStepWarning
from transient.models.ehl.krylov import gmres_solve
from transient.models.ehl.reduced import schur
from transient.models.roller.krylov import DenseLU
from transient.models.roller.line_fbns import schur_rhs, schur_system
from transient.models.roller.line_fft import MatrixFreeStep

#: GMRES iterations above which the preconditioner is refreshed at the next Newton iteration
REFACTOR_ITERS = 12
#: below this many unknowns each step is a direct LAPACK solve (cheaper than GMRES there)
DIRECT_BELOW = 400
#: GMRES relative tolerance of a Newton step
GMRES_RTOL = 1e-8
#: GMRES restart length (a step allows two cycles)
GMRES_RESTART = 40


@dataclass
class ContentNewtonStats:
    """Counts of one solve: Newton iterations, LU factorisations, GMRES iterations (all steps), steps whose GMRES
    missed its tolerance (taken inexactly)."""

    iterations: int = 0
    factorisations: int = 0
    krylov: int = 0
    krylov_misses: int = 0
    norms: list = field(default_factory=list)
    #: the GMRES preconditioner (LU factors of an earlier Schur matrix) at the end: a next solve may start with it
    preconditioner: object = None


def _gmres(S, r, pre):
    """GMRES on ``S z = r`` right-preconditioned by ``pre`` (the point film's
    :func:`~transient.models.ehl.krylov.gmres_solve`: its tolerance is on the true residual):
    ``(z, converged, iterations)``."""
    z, its, ok = gmres_solve(_Dense(S), r, pre, GMRES_RTOL, restart=GMRES_RESTART, max_iter=2 * GMRES_RESTART)
    return z, ok, its


class _Dense:
    """A dense matrix with the ``matvec`` of a linear operator."""

    def __init__(self, S):
        self.S = S

    def matvec(self, v):
        return self.S @ v


def _krylov_step(S, r, pre, stats):
    """``(z, preconditioner, refresh next time)``: GMRES with ``pre``; if it does not converge, with the
    factors of ``S`` itself (and LAPACK's solve if even that fails)."""
    z, ok, its = _gmres(S, r, pre)
    stats.krylov += its
    if not ok:
        pre = DenseLU(S)
        stats.factorisations += 1
        z, ok, its2 = _gmres(S, r, pre)
        stats.krylov += its2
        if not ok:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", sla.LinAlgWarning)
                z = sla.solve(S, r, check_finite=False)
    return z, pre, its > REFACTOR_ITERS


def merit(e, scale):
    """The scaled residual: Reynolds rows by ``scale`` (the row scales of the iterate the step starts from,
    so that the Newton step is a descent direction of the merit), Fischer-Burmeister rows, load balance."""
    return np.concatenate([e["res"] / scale, e["fb"], [e["load"]]])


def content_newton(film, u0, tol: float = 1e-10, max_iter: int = 60, step_max: float = 0.5, preconditioner=None):
    """Newton (module docstring) from ``u0`` until the largest scaled residual is below ``tol``;
    ``preconditioner``: the factors a former solve left (``stats.preconditioner``) for GMRES's first step
    (the dense path above :data:`DIRECT_BELOW` unknowns), e.g. across the steps of a transient.

    Returns ``(u, converged, stats)`` (:class:`ContentNewtonStats`; ``stats.norms`` the infinity norm of
    the scaled residual per iteration). Steps whose GMRES missed its tolerance (matrix-free films) are never
    taken silently: :class:`~transient.models.roller.results.InexactStepWarning` names their number."""
    u, ok, stats = _content_newton(film, u0, tol, max_iter, step_max, preconditioner)
    if stats.krylov_misses:
        warnings.warn(InexactStepWarning(
            f"{stats.krylov_misses} of {stats.iterations} Newton steps were taken with GMRES short of its tolerance "
            f"(the solve {'converged' if ok else 'did not converge'})"), stacklevel=2)
    return u, ok, stats


def _content_newton(film, u0, tol, max_iter, step_max, pre):
    n = film.n
    u = np.array(u0, float)
    e = film.equations(u)
    f = merit(e, e["scale"])
    stats = ContentNewtonStats(norms=[float(np.max(np.abs(f)))], preconditioner=pre)
    m2 = float(f @ f)
    refresh, step = pre is None, None
    for _ in range(max_iter):
        if stats.norms[-1] < tol:
            return u, True, stats
        if film.matrix_free:
            a_p, b_p, a_th, b_t = schur(film, u, e)
            r = schur_rhs(film, e, a_p, a_th)
            if step is None:
                step = MatrixFreeStep(film, tol)
            z = step.solve(film, u, e, b_p, b_t, r, stats)
        elif n < DIRECT_BELOW:
            S, r, (a_p, b_p, a_th, b_t) = schur_system(film, u, e)
            with warnings.catch_warnings():  # an ill-conditioned step is judged by the line search
                warnings.simplefilter("ignore", sla.LinAlgWarning)
                z = sla.solve(S, r, check_finite=False)
            stats.factorisations += 1
        else:
            S, r, (a_p, b_p, a_th, b_t) = schur_system(film, u, e)
            if refresh or pre is None:
                pre = DenseLU(S)
                stats.factorisations += 1
            z, pre, refresh = _krylov_step(S, r, pre, stats)
            stats.preconditioner = pre
        du = np.empty(2 * n + 1)
        du[:n] = a_p + b_p * z[:n]
        du[n: 2 * n] = a_th + b_t * z[:n]
        du[-1] = z[n]
        big = np.max(np.abs(du[:n]) / (step_max + 0.5 * np.abs(u[:n])))
        s = min(1.0, 1.0 / big) if big > 0 else 1.0
        accepted = False
        for _ in range(30):
            ut = u + s * du
            with np.errstate(over="ignore", invalid="ignore"):
                et = film.equations(ut)
                if np.min(et["H"]) > 0.0:
                    ft = merit(et, e["scale"])
                    if np.all(np.isfinite(ft)) and float(ft @ ft) < (1.0 - 1e-4 * s) * m2:
                        accepted = True
                        break
            s *= 0.5
        stats.iterations += 1
        if not accepted:
            return u, False, stats
        u, e = ut, et
        f = merit(e, e["scale"])
        m2 = float(f @ f)
        stats.norms.append(float(np.max(np.abs(f))))
    return u, stats.norms[-1] < tol, stats
