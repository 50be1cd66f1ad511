"""Fischer-Burmeister-Newton-Schur (FBNS) iteration of the point-contact film.

Woloszynski, Podsiadlo & Stachowiak (*Tribol. Lett.* 58, 2015) for the mass-conserving cavitation problem;
Hansen, Kacan, Frohnapfel & Codrignani (*Tribol. Lett.* 70, 2022) with the elastic film. Newton on
``[P, theta, H0]``: Reynolds rows (mass conservation everywhere), ``FB(P, 1 - theta) = 0`` rows, and the
load balance. Each FB row ``a dP + g dtheta = -FB`` is diagonal, so one unknown per node is eliminated
(theta where ``|g| >= |a|``, the pressure otherwise): the reduced ``(N + 1)`` system is dense (elasticity)
and solved by LU (Hansen et al. keep only five diagonals of the elastic block and iterate more; the exact
block is affordable up to ~10^4 unknowns and converges quadratically). The iteration and its globalisation
(backtracking on the scaled residual norm with the film kept positive) are the EHL engine's
(:func:`~transient.models.ehl.newton.fbns_newton`); this module gives it the point film's rows
(:class:`StepRows`), its reduced system (:class:`ReducedSolve`: dense LU or Newton-Krylov) and the nested start.
"""

from __future__ import annotations

import time

import numpy as np
import scipy.linalg as sla

from transient.models.ehl.krylov import KrylovSolver, coarsening_factor, inject, prolong_state
from transient.models.ehl.newton import back_substitute, fbns_newton, warn_inexact
from transient.models.ehl.reduced import dense_reduced, schur

#: the largest nodal unknown count (half grid) solved by the dense LU; above it, Newton-Krylov
DENSE_MAX_UNKNOWNS = 600


class DenseSolver:
    """The reduced system by LAPACK LU (``O(N^3)``, exact)."""

    name = "dense LU"

    def __init__(self, film):
        self.stats = dict(newton=0)

    def solve(self, film, u, e, local, b_p, b_t, r, cj):
        self.stats["newton"] += 1
        A = dense_reduced(film, local, b_p, b_t)
        return sla.solve(A, r, overwrite_a=True, overwrite_b=True, check_finite=False)


def linear_solver(film, method="auto"):
    """The reduced system's solver: ``"dense"`` (:class:`DenseSolver`), ``"krylov"``
    (:class:`~transient.models.ehl.krylov.KrylovSolver`), or ``"auto"``: dense up to
    :data:`DENSE_MAX_UNKNOWNS` nodal unknowns, Krylov above (and where the grid coarsens)."""
    if method == "auto":
        method = "krylov" if film.n > DENSE_MAX_UNKNOWNS and coarsening_factor(film) > 1 else "dense"
    return KrylovSolver(film) if method == "krylov" else DenseSolver(film)


class StepRows:
    """The rows :func:`~transient.models.ehl.newton.fbns_newton` iterates on: the point film's ``film`` under the
    load ratio ``load_ratio``, steady or (``cj > 0``) one implicit time step ``R - cj (q - q_hat)`` with the row
    scales of :func:`rows`."""

    def __init__(self, film, load_ratio=1.0, cj=0.0, q_hat=None):
        self.film, self.load_ratio, self.cj, self.q_hat = film, load_ratio, cj, q_hat
        self.n = film.n

    def equations(self, u):
        e = self.film.equations(u, self.load_ratio)
        if not self.cj:
            return e
        res, scale = rows(self.film, e, self.cj, self.q_hat)
        return dict(e, res=res, scale=scale)

    def fb_derivatives(self, u, e):
        return self.film.fb_derivatives(u, e)


class ReducedSolve:
    """The engine's linear solver (:mod:`transient.models.ehl.newton`) on the point film: the reduced system's
    right-hand side from the film's sparse local blocks, solved by ``inner`` (:class:`DenseSolver` or
    :class:`~transient.models.ehl.krylov.KrylovSolver`), whose misses of its GMRES tolerance are counted."""

    def __init__(self, film, inner, cj=0.0):
        self.film, self.inner, self.cj = film, inner, cj
        if hasattr(inner, "tighten"):
            self.tighten = inner.tighten

    def solve(self, rows, u, e, elimination, stats):
        before = dict(self.inner.stats)
        z = reduced_solve(self.film, u, e, e["res"], self.cj, self.inner, elimination)
        after = self.inner.stats
        stats.krylov += after.get("gmres", 0) - before.get("gmres", 0)
        stats.krylov_misses += after.get("failures", 0) - before.get("failures", 0)
        stats.factorisations += after.get("setups", after["newton"]) - before.get("setups", before["newton"])
        return z


def reduced_solve(film, u, e, res, cj, solver, elimination):
    """The reduced unknowns ``z`` of the Newton step at ``u`` (``e = film.equations(u)``, ``res`` its Reynolds
    rows, ``cj`` their storage coefficient; ``elimination`` from :func:`~transient.models.ehl.reduced.schur`)."""
    n = film.n
    local = film.local_newton(u, e, cj)
    a_pd, d_h, a_t = local
    a_p, b_p, a_th, b_t = elimination
    r = np.empty(n + 1)
    r[:n] = -res - a_pd @ a_p - a_t @ a_th
    if np.any(a_p):
        r[:n] -= d_h @ film.deformation(a_p)
    r[n] = -e["load"] - film.weight / film.load @ a_p
    return solver.solve(film, u, e, local, b_p, b_t, r, cj)


def newton_step(film, u, e, res=None, cj=0.0, solver=None):
    """The full Newton step ``du`` at ``u`` (``e = film.equations(u)``), by the node-wise Schur reduction.

    ``res``, ``cj``: the Reynolds rows of a time step, ``R - cj (q - q_hat)``, and their storage coefficient
    (default: the steady rows ``e["res"]``, ``cj = 0``); ``solver``: the reduced system's solver
    (:func:`linear_solver`; default dense)."""
    elimination = schur(film, u, e)
    res = e["res"] if res is None else res
    solver = DenseSolver(film) if solver is None else solver
    return back_substitute(elimination, reduced_solve(film, u, e, res, cj, solver, elimination))


def rows(film, e, cj=0.0, q_hat=None):
    """``(Reynolds rows, their scales)``: steady ``R``, or a time step's ``R - cj (q - q_hat)``."""
    if not cj:
        return e["res"], e["scale"]
    q = film.storage(e)
    rho_h = (e["rho"] * e["H"]).ravel()[film.flat]
    return e["res"] - cj * (q - q_hat), e["scale"] + cj * rho_h


def merit(film, e, cj=0.0, q_hat=None):
    """The scaled residual vector: Reynolds rows by their scale, Fischer-Burmeister rows, load balance."""
    r, s = rows(film, e, cj, q_hat)
    return np.concatenate([r / s, e["fb"], [e["load"]]])


def nested_start(film, u0, tol, max_iter, load_ratio, step_max, memory, solver):
    """Nested iteration (Venner & Lubrecht, *Multilevel Methods in Lubrication*, 2000, the FMG start): the
    steady problem on every second node from ``u0`` injected there (itself nested while the grid is large),
    its solution interpolated bilinearly back (a second-order Couette flux that fails there: the first-order one);
    None when the coarse Newton fails."""
    t0 = time.perf_counter()
    coarse = film.coarsened(2)
    uc, ok, norms = fbns(coarse, inject(film, coarse, 2, u0), tol, max_iter, load_ratio, step_max, memory=memory)
    if not ok and coarse.scheme != 0:
        coarse = film.coarsened(2, scheme=0)
        uc, ok, norms = fbns(coarse, inject(film, coarse, 2, u0), tol, max_iter, load_ratio, step_max, memory=memory)
    solver.stats.setdefault("coarse_newton", []).append((coarse.nx, len(norms) - 1, ok))
    solver.stats["coarse_s"] = solver.stats.get("coarse_s", 0.0) + time.perf_counter() - t0
    return prolong_state(coarse, film, uc) if ok else None


def fbns(film, u0, tol=1e-8, max_iter=60, load_ratio=1.0, step_max=0.5, cj=0.0, q_hat=None, memory=1,
         solver="auto", nested=True):
    """Newton from ``u0`` until the largest scaled residual is below ``tol`` (steady, or one implicit time
    step ``R - cj (q - q_hat) = 0`` when ``cj > 0``).

    Returns ``(u, converged, norms)``; ``norms`` the infinity norm of the scaled residual per iteration.
    The step is cut so that the film stays positive and no pressure moves by more than ``step_max`` (of
    p_h) plus half its value in one step, then halved until the residual norm decreases below the largest of
    the last ``memory`` norms (1: monotone; more: the non-monotone rule of Grippo, Lampariello & Lucidi, 1986).
    ``solver``: ``"auto"``, ``"dense"``, ``"krylov"`` (:func:`linear_solver`) or a solver object; its ``stats``
    count the Newton steps (and for Krylov the GMRES iterations and times); steps taken with GMRES short of
    its tolerance are warned (:class:`~transient.models.ehl.errors.InexactStepWarning`). ``nested``: a steady solve on a
    grid above the dense size that starts far from the solution (scaled residual above 1e-2) starts from
    the solution on every second node (:func:`nested_start`) when that converges."""
    u = np.array(u0, float)
    if isinstance(solver, str):
        solver = linear_solver(film, solver)
    step_rows = StepRows(film, load_ratio, cj, q_hat)
    if (nested and not cj and film.n > DENSE_MAX_UNKNOWNS and (film.nx - 1) % 2 == 0 and (film.m - 1) % 2 == 0
            and float(np.max(np.abs(merit(film, film.equations(u, load_ratio))))) > 1e-2):
        start = nested_start(film, u, tol, max_iter, load_ratio, step_max, memory, solver)
        if start is not None:
            u = start
    u, ok, stats = fbns_newton(step_rows, u, ReducedSolve(film, solver, cj), tol, max_iter, step_max, memory,
                               armijo="trial")
    warn_inexact(stats, ok)
    return u, ok, stats.norms
