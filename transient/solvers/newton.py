"""Direct steady solver: Newton on the discrete film equations ``R(u) + s = 0`` with a sparse LU.

``R`` is the net volume outflow of :class:`~transient.fv.reynolds.ReynoldsOperator` and ``s`` a
per-cell source (e.g. the squeeze term ``A_i d(C h)_i/dt`` for a prescribed ``dh/dt``). Each iteration
solves ``J du = -(R + s)`` with ``scipy.sparse.linalg.splu`` on the cell block of the operator's
pattern, then backtracks (halving) until ``||R + s||_2`` decreases. Converged when

    ||du||_inf <= xtol * ||u||_inf     or     ||R + s||_inf <= ftol * max(||R(u0) + s||_inf, ||s||_inf)

A linear problem (``P = u``, ``C, k`` independent of ``u``) therefore stops after one or two
iterations. Fixed (prescribed) cells are held at their values; their source is ignored.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.sparse.linalg as spla

from transient.fv.reynolds import Fields, ReynoldsOperator


class SteadyConvergenceError(RuntimeError):
    """Newton did not converge; ``result`` holds the last iterate and the history."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result


@dataclass
class SteadyResult:
    u: np.ndarray
    iterations: int
    residual_norm: float
    converged: bool
    step_norms: list = field(default_factory=list)
    residual_norms: list = field(default_factory=list)


def solve_steady(op: ReynoldsOperator, fields: Callable[[np.ndarray], Fields], u0, source=None, *,
                 xtol: float = 1e-10, ftol: float = 1e-10, max_iter: int = 50,
                 line_search: bool = True) -> SteadyResult:
    """Solve ``R(u) + source = 0`` for the cell unknowns by Newton's method.

    Parameters
    ----------
    op : the operator (extra unknowns, if any, are not solved for here).
    fields : ``fields(u) -> Fields`` -- the model's P, C, k, c and derivatives at ``u``.
    u0 : initial guess, length ``op.n_cells`` (fixed cells are reset to their prescribed values).
    source : per-cell source (length ``n_cells``) or None.
    xtol, ftol, max_iter : see the module docstring; raises :class:`SteadyConvergenceError` if not met.
    """
    n = op.n_cells
    if not (xtol > 0 and ftol > 0):
        raise ValueError(f"xtol and ftol must be > 0, got xtol={xtol!r}, ftol={ftol!r}")
    if isinstance(max_iter, bool) or int(max_iter) != max_iter or max_iter < 1:
        raise ValueError(f"max_iter must be an integer >= 1, got {max_iter!r}")
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

    r = F(u)
    r_norm = float(np.max(np.abs(r)))
    f_scale = max(r_norm, float(np.max(np.abs(s))), np.finfo(float).tiny)
    res = SteadyResult(u=u, iterations=0, residual_norm=r_norm, converged=False, residual_norms=[r_norm])
    if r_norm == 0.0:
        res.converged = True
        return res
    for it in range(1, int(max_iter) + 1):
        op.jacobian_of(fields(u), data=data)
        J = op.matrix(data)[:n, :n].tocsc()
        try:
            du = -spla.splu(J).solve(r)
        except RuntimeError as exc:  # singular factor
            res.u, res.iterations = u, it
            raise SteadyConvergenceError(f"steady Newton: singular Jacobian at iteration {it} ({exc})", res) from exc
        lam, r2 = 1.0, float(np.dot(r, r))
        while True:
            u_new = u + lam * du
            r_new = F(u_new)
            ok = np.all(np.isfinite(r_new)) and float(np.dot(r_new, r_new)) <= (1 - 1e-4 * lam) ** 2 * r2
            if ok or not line_search or lam < 1.0 / 256:
                break
            lam *= 0.5
        step = lam * float(np.max(np.abs(du)))
        u, r = u_new, r_new
        r_norm = float(np.max(np.abs(r)))
        res.step_norms.append(step)
        res.residual_norms.append(r_norm)
        res.u, res.iterations, res.residual_norm = u, it, r_norm
        if not np.isfinite(r_norm):
            break
        if step <= xtol * float(np.max(np.abs(u))) or r_norm <= ftol * f_scale:
            res.converged = True
            return res
    raise SteadyConvergenceError(
        f"steady Newton did not converge in {res.iterations} iterations (max_iter={max_iter}): "
        f"last step {res.step_norms[-1] if res.step_norms else float('nan'):.3e} > xtol*|u| = "
        f"{xtol * float(np.max(np.abs(u))):.3e} and residual {r_norm:.3e} > ftol*scale = {ftol * f_scale:.3e}",
        res)
