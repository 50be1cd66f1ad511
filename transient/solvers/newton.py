"""One Newton solver for every steady problem of the package: ``F(x) = 0`` with an analytic Jacobian.

:func:`newton` iterates ``(J(x) + shift M) dx = -F(x)``, ``x <- x + lam dx`` with

* a direct factorisation of whatever the model's ``jacobian(x, shift)`` returns: a scipy sparse matrix
  (SuperLU), a dense array (LAPACK LU), or any object with ``.solve(b)`` (the model's own solver, e.g. a
  preconditioned Krylov method);
* backtracking (``line_search``): ``lam`` halves until ``||F||_2`` decreases by the Armijo factor;
* pseudo-transient continuation (``pseudo_time = dtau0``, Kelley & Keyes 1998): the model adds its
  storage term ``shift M`` (``shift = 1/dtau``) to the Jacobian, i.e. each step is a backward-Euler step
  of the model's own dynamics from the current iterate (the storage term of the residual vanishes there);
  ``dtau`` grows as the residual falls (switched evolution relaxation) and becomes infinite (plain
  Newton) once it exceeds 1e12; a step that raises the residual in the plain phase is rejected and
  ``dtau`` cut tenfold;
* chord iterations (``chord=True``, or a :class:`Chord` that keeps the factorisation across calls, e.g.
  across the time steps of a scheme): the factorisation is kept while it still gives descent and the
  residual contracts at least twofold per iteration, and refreshed otherwise;
* ``max_step(x, dx)``: the largest admissible fraction of a step (e.g. keep a journal inside its
  clearance).

Convergence (unless the model passes its own ``converged(x, F, dx)``)::

    step:      lam ||dx||_inf <= xtol * max(x_floor, ||x||_inf)
    residual:  ||F||_inf      <= ftol * f_scale     (f_scale: given, else ||F(x0)||_inf)

``test="either"`` stops on either, ``"both"`` needs both. :class:`NewtonError` carries the last iterate
and the histories when the iteration does not converge.
"""

from __future__ import annotations

from dataclasses import astuple, dataclass, field, fields
from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.checks import check_bool, check_choice, check_positive, check_range
from transient.fv.reynolds import Fields, ReynoldsOperator
from transient.results import SteadyResult, result_type
from transient.solvers.legacy import run_settings

_TINY = np.finfo(float).tiny


@result_type
class NewtonResult(SteadyResult):
    """Outcome of :func:`newton`: the solution ``x``, iterations, residual norms per iteration."""

    time_axis = None
    x: np.ndarray
    residual_norm: float
    n_factorisations: int = 0
    step_norms: list = field(default_factory=list)

    @property
    def u(self) -> np.ndarray:
        """The solution (the film solvers call their unknown ``u``)."""
        return self.x

    @property
    def converged(self) -> bool:
        return self.success


class NewtonError(RuntimeError):
    """Newton did not converge; ``result`` holds the last iterate and the histories."""

    def __init__(self, message, result: NewtonResult):
        super().__init__(message)
        self.result = result


#: the name the steady film solver's callers know
SteadyConvergenceError = NewtonError


class Chord:
    """A factorisation kept across calls of :func:`newton` (``chord=Chord()``), with a count of them."""

    def __init__(self):
        self.lu = None
        self.n_factorisations = 0


def factorise(matrix):
    """An object with ``.solve(b)`` for a sparse matrix, a dense array, or an object that already has one."""
    if hasattr(matrix, "solve"):
        return matrix
    if sp.issparse(matrix):
        return spla.splu(sp.csc_matrix(matrix))
    lu = sla.lu_factor(np.asarray(matrix), check_finite=False)

    class _Dense:
        def solve(self, b):
            return sla.lu_solve(lu, b, check_finite=False)

    return _Dense()


@dataclass(frozen=True)
class NewtonSettings:
    """How :func:`newton` iterates and when it stops (module docstring), validated on creation: ``xtol``,
    ``ftol`` [-] > 0, the step and residual tests; ``f_scale`` ``None`` (``||F(x0)||_inf``) or the residual's
    scale [the residual's unit]; ``x_floor`` >= 0, the least ``||x||_inf`` of the step test [the unknown's unit];
    ``test`` ``"either"`` or ``"both"``; ``max_iter`` an integer >= 1; ``line_search`` a flag (backtracking);
    ``pseudo_time`` ``None`` or the first pseudo-time step ``dtau0`` > 0 [the model's time unit]."""

    xtol: float = 1e-10
    ftol: float = 1e-10
    f_scale: float | None = None
    x_floor: float = 0.0
    test: str = "either"
    max_iter: int = 50
    line_search: bool = True
    pseudo_time: float | None = None

    def __post_init__(self):
        if not (self.xtol > 0 and self.ftol > 0):
            raise ValueError(f"xtol and ftol must be > 0, got xtol={self.xtol!r}, ftol={self.ftol!r}")
        if isinstance(self.max_iter, bool) or int(self.max_iter) != self.max_iter or self.max_iter < 1:
            raise ValueError(f"max_iter must be an integer >= 1, got {self.max_iter!r}")
        check_choice("test", self.test, ("either", "both"))
        check_bool("line_search", self.line_search)
        check_range("x_floor", self.x_floor, "-", 0.0)
        if self.pseudo_time is not None:
            check_positive("pseudo_time", self.pseudo_time, "-")


#: The loose keywords of :func:`newton` of earlier releases, now fields of ``settings=NewtonSettings(...)``.
NEWTON_KEYWORDS = {f.name: ("settings", NewtonSettings, f.name) for f in fields(NewtonSettings)}


def newton(residual: Callable, jacobian: Callable, x0, *, settings: NewtonSettings | None = None,
           chord: bool | Chord = False, converged: Callable | None = None, max_step: Callable | None = None,
           name: str = "Newton", **legacy) -> NewtonResult:
    """Solve ``residual(x) = 0``; ``jacobian(x, shift)`` returns ``dF/dx + shift M`` (module docstring).

    ``settings`` (:class:`NewtonSettings`, default ``NewtonSettings()``): the tolerances, the iteration limit,
    the line search and pseudo-time; the loose keywords ``xtol=``, ``ftol=``, ``f_scale=``, ``x_floor=``,
    ``test=``, ``max_iter=``, ``line_search=``, ``pseudo_time=`` are deprecated (they still work for one
    release, with a ``DeprecationWarning``). Raises :class:`NewtonError` if not converged within ``max_iter``
    iterations."""
    settings = run_settings("newton", legacy, NEWTON_KEYWORDS, settings=settings)["settings"]
    xtol, ftol, f_scale, x_floor, test, max_iter, line_search, pseudo_time = astuple(settings)
    x = np.array(x0, dtype=float, copy=True)
    r = np.asarray(residual(x), dtype=float).copy()
    r_inf = float(np.max(np.abs(r)))
    r2 = float(r @ r)
    scale_f = max(r_inf, _TINY) if f_scale is None else max(float(f_scale), _TINY)
    res = NewtonResult(x=x, iterations=0, residual_norm=r_inf, success=False, message="", residual_norms=[r_inf])
    if r_inf == 0.0 and converged is None:
        res.success, res.message = True, "the initial guess solves the equations"
        return res
    dtau = pseudo_time
    keep = chord if isinstance(chord, Chord) else Chord()
    chord = bool(chord)

    def refactorise():
        try:
            keep.lu = factorise(jacobian(x, shift))
        except RuntimeError as exc:  # SuperLU: "Factor is exactly singular"
            res.x, res.iterations = x, it
            raise NewtonError(f"{name}: singular Jacobian at iteration {it} ({exc})", res) from exc
        keep.n_factorisations += 1
        res.n_factorisations += 1

    fresh = False
    it = 0
    while it < int(max_iter):
        it += 1
        shift = 0.0 if (dtau is None or dtau > 1e12) else 1.0 / dtau
        if keep.lu is None or not chord or shift != 0.0:
            refactorise()
            fresh = True
        dx = -keep.lu.solve(r)
        lam = 1.0 if max_step is None else float(max_step(x, dx))
        while True:
            x_new = x + lam * dx
            r_new = np.asarray(residual(x_new), dtype=float).copy()
            r2_new = float(r_new @ r_new)
            descent = np.isfinite(r2_new) and r2_new <= (1.0 - 1e-4 * lam) ** 2 * r2
            if descent or r2_new == 0.0:
                break
            if chord and not fresh:  # an old factorisation no longer gives descent: refresh it here
                refactorise()
                fresh = True
                dx = -keep.lu.solve(r)
                continue
            if dtau is not None or not line_search or lam < 1.0 / 256:
                break
            lam *= 0.5
        if dtau is not None:  # pseudo-transient: accept unless it failed in the plain-Newton phase
            if not np.isfinite(r2_new) or (shift == 0.0 and r2_new > r2):
                dtau = max(dtau * 0.1, 1e-3)
                continue
            # SER growth of the pseudo-time step; a zero residual ends the pseudo-transient phase at once (its growth
            # factor 0/0 would hold dtau and skip the convergence test forever)
            dtau = 1e15 if r2_new == 0.0 else min(dtau * max(np.sqrt(r2 / max(r2_new, _TINY)), 0.5) * 2.0, 1e15)
        if chord and not fresh and r2_new > 0.25 * r2:  # contracting slower than 2x in ||F||: refresh
            keep.lu = None
        fresh = False
        step = lam * float(np.max(np.abs(dx)))
        x, r, r2 = x_new, r_new, r2_new
        r_inf = float(np.max(np.abs(r)))
        res.x, res.iterations, res.residual_norm = x, it, r_inf
        res.step_norms.append(step)
        res.residual_norms.append(r_inf)
        if not np.isfinite(r_inf):
            break
        if dtau is not None and shift != 0.0:
            continue  # still in the pseudo-transient phase
        if converged is not None:
            done = bool(converged(x, r, lam * dx))
        else:
            ok_x = step <= xtol * max(x_floor, float(np.max(np.abs(x))))
            ok_f = r_inf <= ftol * scale_f
            done = (ok_x and ok_f) if test == "both" else (ok_x or ok_f)
        if done:
            res.success, res.message = True, f"converged in {it} iterations"
            return res
    last = res.step_norms[-1] if res.step_norms else float("nan")
    res.message = (f"{name} did not converge in {res.iterations} iterations (max_iter={max_iter}): last step "
                   f"{last:.3e} (xtol*|x| = {xtol * max(x_floor, float(np.max(np.abs(x)))):.3e}), residual "
                   f"{res.residual_norm:.3e} (ftol*scale = {ftol * scale_f:.3e})")
    raise NewtonError(res.message, res)


def solve_steady(op: ReynoldsOperator, fields: Callable[[np.ndarray], Fields], u0, source=None, *,
                 xtol: float = 1e-10, ftol: float = 1e-10, max_iter: int = 50,
                 line_search: bool = True) -> NewtonResult:
    """Steady film ``R(u) + source = 0`` of a :class:`~transient.fv.reynolds.ReynoldsOperator` by
    :func:`newton` on the cell unknowns with a sparse LU.

    ``fields(u) -> Fields``: the model's P, C, k, c and derivatives at ``u``; ``u0`` the initial guess
    (fixed cells are reset to their prescribed values and their source ignored); ``source`` a per-cell
    source (e.g. the squeeze term ``A_i d(C h)_i/dt``). Converged when the step falls below ``xtol |u|``
    or the residual below ``ftol max(|R(u0) + s|, |s|)``; a linear problem stops after one or two
    iterations. Raises :class:`NewtonError` (alias ``SteadyConvergenceError``) otherwise.
    """
    n = op.n_cells
    u = np.array(u0, dtype=float, copy=True)
    if u.shape != (n,):
        raise ValueError(f"u0 must have shape ({n},), got {u.shape}")
    u[~op.free] = op.u_fixed[~op.free]
    s = np.zeros(n) if source is None else np.array(source, dtype=float, copy=True)
    if s.shape != (n,):
        raise ValueError(f"source must have shape ({n},), got {s.shape}")
    s[~op.free] = 0.0
    data = np.empty(op.nnz)

    def F(v):
        return op.residual_of(v, fields(v)) + s

    def J(v, shift):
        op.jacobian_of(fields(v), data=data)
        return op.matrix(data)[:n, :n]

    r0 = float(np.max(np.abs(F(u))))
    return newton(F, J, u, settings=NewtonSettings(xtol=xtol, ftol=ftol, f_scale=max(r0, float(np.max(np.abs(s)))),
                                                   max_iter=max_iter, line_search=line_search), name="steady Newton")
