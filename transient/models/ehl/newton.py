"""The EHL films' one Fischer-Burmeister-Newton-Schur (FBNS) iteration, with pluggable linear solvers.

Newton on ``u = [p, theta, h0]`` of a film-content problem (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.*
58, 2015; Hansen, Kacan, Frohnapfel & Codrignani, *Tribol. Lett.* 70, 2022, with the elastic film and in time):
the Reynolds rows (mass conservation everywhere; in a time step with the storage ``cj (q - q_hat)`` already in
them), the rows ``FB(p, 1 - theta) = 0`` and the load balance. Each FB row ``a dp + g dtheta = -FB`` is diagonal,
so one unknown per node is eliminated (:func:`~transient.models.ehl.reduced.schur`) and the linear solver takes
the reduced ``(N + 1)`` system (one unknown ``z`` per node and ``dh0``); the step is back-substituted
``dp = a_p + b_p z``, ``dtheta = a_theta + b_theta z``.

Globalisation: the step is cut so that no pressure moves by more than ``step_max`` plus half its value, then
halved (at most 30 times) until the film stays positive and the squared scaled residual falls below ``(1 -
1e-4 s)`` times the largest of the last ``memory`` ones (Armijo; ``memory > 1``: the non-monotone rule of
Grippo, Lampariello & Lucidi, *SIAM J. Numer. Anal.* 23, 1986). Converged when the largest scaled residual is
below ``tol``.

The rows (``rows``): ``n``, ``equations(u)`` -> a dict with ``res`` (Reynolds rows), ``scale`` (their row
scales), ``fb``, ``load`` and the film ``H``; ``fb_derivatives(u, e)``. The linear solver (``solver``):
``solve(rows, u, e, elimination, stats)`` -> ``z``, counting in ``stats`` (:class:`NewtonStats`) its
factorisations, Krylov iterations and every Krylov solve that missed its tolerance (``krylov_misses``: such a
step is taken, and :func:`warn_inexact` names it); optionally ``tighten()``, called when a step near the
solution keeps more than :data:`STAGNATION` of the residual's norm (an inexact solver that stalls the Newton).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from transient.models.ehl.errors import InexactStepWarning
from transient.models.ehl.reduced import schur

#: a Newton step near the solution (largest scaled residual below :data:`STAGNATION_NEAR`) that keeps more than
#: this fraction of the residual's norm tightens an inexact linear solver (its ``tighten()``)
STAGNATION = 0.5
STAGNATION_NEAR = 1e-3
#: the Armijo rule's scale of the trial residual: the start iterate's row scales (so that the Newton step is a
#: descent direction of the merit) or the trial's own
ARMIJO_SCALES = ("start", "trial")


@dataclass
class NewtonStats:
    """Counts of one solve: Newton steps tried (the last may have failed its line search), factorisations,
    Krylov iterations (all steps), steps whose Krylov solve missed its tolerance (taken inexactly); ``norms``:
    the largest scaled residual per accepted iterate; ``preconditioner``: what the linear solver keeps for a
    next solve (the line's reused LU)."""

    iterations: int = 0
    factorisations: int = 0
    krylov: int = 0
    krylov_misses: int = 0
    norms: list = field(default_factory=list)
    preconditioner: object = None


def merit(e, scale) -> np.ndarray:
    """The scaled residual: Reynolds rows by ``scale``, Fischer-Burmeister rows, load balance."""
    return np.concatenate([e["res"] / scale, e["fb"], [e["load"]]])


def back_substitute(elimination, z) -> np.ndarray:
    """The full step ``du = [dp, dtheta, dh0]`` from the reduced unknowns ``z`` (module docstring)."""
    a_p, b_p, a_th, b_t = elimination
    n = a_p.size
    du = np.empty(2 * n + 1)
    du[:n] = a_p + b_p * z[:n]
    du[n: 2 * n] = a_th + b_t * z[:n]
    du[-1] = z[n]
    return du


def fbns_newton(rows, u0, solver, tol: float, max_iter: int, step_max: float = 0.5, memory: int = 1,
                armijo: str = "start", stats: NewtonStats | None = None):
    """Newton (module docstring) from ``u0`` until the largest scaled residual is below ``tol``, at most
    ``max_iter`` steps; ``armijo``: the row scales of the line search's trial residual (:data:`ARMIJO_SCALES`).
    Returns ``(u, converged, stats)``."""
    if armijo not in ARMIJO_SCALES:
        raise ValueError(f"armijo = {armijo!r}: allowed {ARMIJO_SCALES}")
    n = rows.n
    u = np.array(u0, float)
    e = rows.equations(u)
    f = merit(e, e["scale"])
    stats = NewtonStats() if stats is None else stats
    stats.norms = [float(np.max(np.abs(f)))]
    squares = [float(f @ f)]
    for _ in range(max_iter):
        if stats.norms[-1] < tol:
            return u, True, stats
        elimination = schur(rows, u, e)
        du = back_substitute(elimination, solver.solve(rows, u, e, elimination, stats))
        big = np.max(np.abs(du[:n]) / (step_max + 0.5 * np.abs(u[:n])))
        s = min(1.0, 1.0 / big) if big > 0 else 1.0
        phi0 = max(squares[-memory:])
        accepted = False
        for _ in range(30):
            ut = u + s * du
            with np.errstate(over="ignore", invalid="ignore"):
                et = rows.equations(ut)
                if np.min(et["H"]) > 0.0:
                    ft = merit(et, e["scale"] if armijo == "start" else et["scale"])
                    if np.all(np.isfinite(ft)) and float(ft @ ft) < (1.0 - 1e-4 * s) * phi0:
                        accepted = True
                        break
            s *= 0.5
        stats.iterations += 1
        if not accepted:
            return u, False, stats
        u, e = ut, et
        f = ft if armijo == "trial" else merit(e, e["scale"])
        stats.norms.append(float(np.max(np.abs(f))))
        squares.append(float(f @ f))
        if (hasattr(solver, "tighten") and stats.norms[-1] < STAGNATION_NEAR
                and np.sqrt(squares[-1]) > STAGNATION * np.sqrt(squares[-2])):
            solver.tighten()  # an inexact linear solve that no longer reduces the residual: solve it tighter
    return u, stats.norms[-1] < tol, stats


def warn_inexact(stats: NewtonStats, converged: bool, stacklevel: int = 3):
    """:class:`~transient.models.ehl.errors.InexactStepWarning` naming the steps taken with a Krylov solve short
    of its tolerance (none: no warning)."""
    if stats.krylov_misses:
        warnings.warn(InexactStepWarning(
            f"{stats.krylov_misses} of {stats.iterations} Newton steps were taken with GMRES short of its tolerance "
            f"(the solve {'converged' if converged else 'did not converge'})"), stacklevel=stacklevel)
