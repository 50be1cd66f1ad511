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

The iteration and its globalisation (the step cut so that the film stays positive and no pressure moves by
more than ``step_max`` plus half its value, then halved until the scaled residual norm decreases: Armijo) are
the EHL engine's :func:`~transient.models.ehl.newton.fbns_newton`, as for the point film; this module gives it
the line's and the roller's linear solvers (:func:`linear_solver`).
"""

from __future__ import annotations

import warnings

import scipy.linalg as sla

from transient.models.ehl.krylov import gmres_solve
from transient.models.ehl.newton import NewtonStats, fbns_newton, warn_inexact
from transient.models.roller.krylov import DenseLU
from transient.models.roller.line_fbns import schur_rhs, scaled_schur
from transient.models.roller.line_fft import MatrixFreeStep

#: GMRES iterations above which the preconditioner is refreshed at the next Newton iteration
REFACTOR_ITERS = 12
#: below this many unknowns each step is a direct LAPACK solve (cheaper than GMRES there)
DIRECT_BELOW = 400
#: GMRES relative tolerance of a Newton step
GMRES_RTOL = 1e-8
#: GMRES restart length (a step allows two cycles)
GMRES_RESTART = 40


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


class DirectSolve:
    """The Schur system (rows by their scales) by LAPACK's LU at every Newton step."""

    def solve(self, rows, u, e, elimination, stats):
        S, r = scaled_schur(rows, e, elimination)
        with warnings.catch_warnings():  # an ill-conditioned step is judged by the line search
            warnings.simplefilter("ignore", sla.LinAlgWarning)
            z = sla.solve(S, r, check_finite=False)
        stats.factorisations += 1
        return z


class ReusedLU:
    """The Schur system by GMRES right-preconditioned with the LU factors of an earlier Schur matrix
    (``preconditioner``, or made at the first step), refactorised after a step that needed more than
    :data:`REFACTOR_ITERS` iterations; the factors in ``stats.preconditioner`` for a next solve."""

    def __init__(self, preconditioner=None):
        self.pre = preconditioner
        self.refresh = preconditioner is None

    def solve(self, rows, u, e, elimination, stats):
        S, r = scaled_schur(rows, e, elimination)
        if self.refresh or self.pre is None:
            self.pre = DenseLU(S)
            stats.factorisations += 1
        z, self.pre, self.refresh = _krylov_step(S, r, self.pre, stats)
        stats.preconditioner = self.pre
        return z


class MatrixFree:
    """The Schur system of a DC-FFT film (``film.matrix_free``) by :class:`~transient.models.roller.line_fft.MatrixFreeStep`
    (made at the first step; ``tol`` the Newton's tolerance, toward which its forcing terms tighten GMRES)."""

    def __init__(self, tol: float = 0.0):
        self.step, self.tol = None, tol

    def solve(self, rows, u, e, elimination, stats):
        a_p, b_p, a_th, b_t = elimination
        if self.step is None:
            self.step = MatrixFreeStep(rows, self.tol)
        return self.step.solve(rows, u, e, b_p, b_t, schur_rhs(rows, e, a_p, a_th), stats)


def linear_solver(film, preconditioner=None, tol: float = 0.0):
    """The Newton steps' solver of the content film ``film``: matrix-free on a DC-FFT film (``tol`` the Newton's
    tolerance), by LAPACK below :data:`DIRECT_BELOW` unknowns, else GMRES with a reused LU (``preconditioner``:
    factors to start with)."""
    if film.matrix_free:
        return MatrixFree(tol)
    return DirectSolve() if film.n < DIRECT_BELOW else ReusedLU(preconditioner)


def content_newton(film, u0, tol: float = 1e-10, max_iter: int = 60, step_max: float = 0.5, preconditioner=None):
    """Newton (module docstring) from ``u0`` until the largest scaled residual is below ``tol``;
    ``preconditioner``: the factors a former solve left (``stats.preconditioner``) for GMRES's first step
    (the dense path above :data:`DIRECT_BELOW` unknowns), e.g. across the steps of a transient.

    Returns ``(u, converged, stats)`` (:class:`~transient.models.ehl.newton.NewtonStats`; ``stats.norms`` the
    infinity norm of the scaled residual per iteration). Steps whose GMRES missed its tolerance (matrix-free
    films) are never taken silently: :class:`~transient.models.ehl.errors.InexactStepWarning` names their number."""
    u, ok, stats = fbns_newton(film, u0, linear_solver(film, preconditioner, tol), tol, max_iter, step_max,
                               stats=NewtonStats(preconditioner=preconditioner))
    warn_inexact(stats, ok)
    return u, ok, stats
