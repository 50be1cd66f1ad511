"""Grid and load sequencing of the line contact's film-content Newton (:mod:`transient.models.roller.line_newton`).

The line contact (:class:`~transient.models.roller.line_contact.LineContact`) is solved on the grid levels
of :meth:`LineContact.levels` (every other node of the next finer one), coarse to fine, along the load
path of :meth:`LineContact.continuation`: ``s = 0`` is the contact with the load scaled to
``M0 = min(M, 10)`` and ``alpha`` to ``L0 = min(L, 5)``, solved from the Hertz pressure (:func:`cold_start`);
``s = 1`` is the contact itself (``w = w0 (w1/w0)^s``, ``alpha = a0 + s (a1 - a0)``). Level ``k`` carries
the load up to ``M_k = min(M, RESOLVED / dx_k, RESOLVED_INLET / dx_in)`` (``dx_k`` its node spacing in the
Hertz zone, ``dx_in`` at the inlet edge: a grid resolves the inlet build-up and the outlet constriction,
both narrowing with M, only so far; where its path stops earlier, the next
level continues from there), by continuation steps
(:func:`transient.models.roller.continuation.follow`) started from the previous step's solution; the
next, finer level starts from it interpolated (nested iteration). On the coarse levels a Newton
iteration costs little; on the finest one, a few iterations with a reused factorisation. Uniform levels
finer than :data:`~transient.models.roller.line_fft.MATRIX_FREE_ABOVE` nodes take the matrix-free DC-FFT
path of :mod:`transient.models.roller.line_fft`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from threadpoolctl import threadpool_limits

from transient.models.roller.continuation import follow
from transient.models.roller.grid import TensorGrid
from transient.models.roller.line_fbns import LineContentFilm
from transient.models.roller.line_fft import matrix_free
from transient.models.roller.line_newton import content_newton
from transient.physics.line_formulas import moes_central
from transient.solvers.newton import NewtonError, NewtonResult

#: the corner of the Moes chart solved from the Hertz pressure
M_START, L_START = 10.0, 5.0
#: a level carries the load up to M = RESOLVED / (its node spacing in the Hertz zone, units of b) ...
RESOLVED = 8.0
#: ... and up to M = RESOLVED_INLET / (its node spacing at the inlet edge x = -b, where the film is set)
RESOLVED_INLET = 3.5
#: amplitude (units of p_h, at most; 0.5/(alpha p_h) when smaller) of the inlet pressure ramp of the start
INLET_RAMP = 0.05
#: the coarsest level keeps at least this many nodes, this many of them in the loaded zone
MIN_NODES, MIN_ZONE = 129, 10
#: Newton iterations allowed per continuation step
STEP_ITERS = 25


@dataclass
class SequenceResult:
    """Outcome of :func:`solve_sequence`: the film-content state on the finest grid and its film problem."""

    state: np.ndarray
    content: LineContentFilm
    success: bool
    message: str
    iterations: int = 0
    factorisations: int = 0
    residual_norms: list = field(default_factory=list)
    log: list = field(default_factory=list)


def cold_start(contact, film) -> np.ndarray:
    """``[p, theta, h0]``: the Hertz pressure with an inlet ramp (amplitude ``INLET_RAMP``, at most
    ``0.5/(alpha p_h)``: the inlet pressure is of the order of ``1/alpha``), ``h0`` putting the central film at
    Moes' formula, and downstream of the contact the content ``theta = h_c/h`` of a film carried at the
    central flux (so that no node starts at the kink ``p = 1 - theta = 0`` of the Fischer-Burmeister pair
    except upstream, where the film is full)."""
    xi = film.grid.x[1:-1]
    p = np.sqrt(np.clip(1.0 - xi * xi, 0.0, None))
    ap = contact.lubricant.pressure_viscosity * contact.p_h
    amp = min(INLET_RAMP, 0.5 / ap) if ap > 0.0 else INLET_RAMP
    p = np.maximum(p, np.where(xi < -1.0, amp * (xi - xi[0]) / (-1.0 - xi[0]), 0.0))
    hc = moes_central(contact.M, contact.L) * math.sqrt(2.0 * contact.U) * contact.radius / contact.film_scale
    h0 = hc - float(np.interp(0.0, film.grid.x, film.film(p, 0.0)))
    h = film.film(p, h0)[1:-1]
    theta = np.where((xi > 0.0) & (p <= 0.0), np.clip(hc / np.where(h > 0.0, h, np.inf), 0.0, 1.0), 1.0)
    return np.concatenate([p, theta, [h0]])


def carry(grid_from: TensorGrid, u, grid_to: TensorGrid) -> np.ndarray:
    """``[p, theta, h0]`` of one grid on another (linear interpolation; ``p = 0``, ``theta = 1`` on the
    boundary)."""
    m = grid_from.x.size - 2
    p = np.interp(grid_to.x[1:-1], grid_from.x, np.concatenate([[0.0], u[:m], [0.0]]))
    t = np.interp(grid_to.x[1:-1], grid_from.x, np.concatenate([[1.0], u[m: 2 * m], [1.0]]))
    return np.concatenate([p, t, u[-1:]])


def grid_levels(contact) -> list[TensorGrid]:
    """Grids coarse to fine: every other node of the next finer one while the coarser keeps at least
    ``MIN_NODES`` nodes and ``MIN_ZONE`` of them in the loaded zone ``|x| < max(1, 2.5/M)`` b."""
    out = [contact.grid]
    zone = max(1.0, 2.5 / contact.M)
    while (out[0].x.size - 1) % 2 == 0:
        xc = out[0].x[::2]
        if xc.size < MIN_NODES or np.count_nonzero(np.abs(xc) < zone) < MIN_ZONE:
            break
        out.insert(0, TensorGrid(xc))
    return out


def inlet_spacing(grid: TensorGrid) -> float:
    """Node spacing (units of b) of the interval that contains the inlet edge ``x = -1``."""
    x = grid.x
    k = int(np.clip(np.searchsorted(x, -1.0), 1, x.size - 1))
    return float(x[k] - x[k - 1])


def resolved_load(contact, grid: TensorGrid) -> float:
    """The largest Moes load M a level carries (module docstring): ``RESOLVED`` over the largest spacing
    in the Hertz zone, ``RESOLVED_INLET`` over the spacing at the inlet edge (measured: on uniform grids the
    load path stalls near ``M dx = 4-6`` at the inlet edge, each stalled path costing its rejected steps)."""
    return min(contact.M, RESOLVED / contact._contact_spacing(grid), RESOLVED_INLET / inlet_spacing(grid))


def solve_sequence(contact, tol: float = 1e-10, max_iter: int = 60) -> SequenceResult:
    """The film-content solution of ``contact`` (module docstring) on its finest grid. BLAS runs on one
    thread (``transient`` sets ``OPENBLAS_NUM_THREADS=1`` at import, too late when numpy was imported
    first): the matrices (n <~ 4000) are too small for threads to pay, and on a shared machine BLAS threads
    waiting for a core made a chart point 4x slower (measured)."""
    with threadpool_limits(limits=1, user_api="blas"):
        return _solve_sequence(contact, tol, max_iter)


def _solve_sequence(contact, tol, max_iter) -> SequenceResult:
    levels = grid_levels(contact)
    w1, a1 = contact.load_per_length, contact.lubricant.pressure_viscosity
    m0 = min(contact.M, M_START)
    w0 = w1 * m0 / contact.M
    a0 = a1 * min(1.0, L_START / contact.L) if contact.L > 0 else 0.0
    out = SequenceResult(state=np.zeros(1), content=None, success=False, message="")

    def s_of(M):
        return 1.0 if contact.M <= m0 * (1.0 + 1e-12) else min(1.0, math.log(M / m0) / math.log(contact.M / m0))

    u, s, grid_prev = None, 0.0, None
    for k, grid in enumerate(levels):
        mf = contact.elastic and matrix_free(grid)  # DC-FFT elasticity (line_fft), else the dense matrix
        first = contact.film_problem(grid, matrix_free=mf)
        kernel = first.conv if mf else first.K
        cache = {}

        def at(t, grid=grid, kernel=kernel, cache=cache, mf=mf):
            if t not in cache:
                c = contact if t >= 1.0 else contact.with_load(w0 * (w1 / w0) ** t, a0 + t * (a1 - a0), nodes=grid.x)
                cache[t] = (c, LineContentFilm(c.film_problem(grid, kernel=kernel, matrix_free=mf)))
            return cache[t]

        def newton_at(t, u_start, iters):
            u_new, ok, st = content_newton(at(t)[1], u_start, tol=tol, max_iter=iters)
            out.iterations += st.iterations
            out.factorisations += st.factorisations
            out.residual_norms = st.norms
            return u_new, ok, st

        def central(t, v, at=at, grid=grid):
            c, f = at(t)
            h = f.base.film(v[: f.n], v[-1])
            return float(np.interp(0.0, grid.x, h)) * c.film_scale if h.min() > 0.0 else float("nan")

        def shift(t0, v, t1, at=at, central=central):
            """``v`` at ``t0`` carried to ``t1``: ``h0`` moved so that the central film in metres stays."""
            hc = central(t0, v)
            w = v.copy()
            w[-1] += hc / at(t1)[0].film_scale - hc / at(t0)[0].film_scale
            return w

        last = k == len(levels) - 1
        s_target = 1.0 if last else max(s, s_of(resolved_load(contact, grid)))
        if k == 0:
            u0 = cold_start(at(0.0)[0], at(0.0)[1].base)
            u, ok, st = newton_at(0.0, u0, max_iter)
            out.log.append(f"{grid.x.size} nodes: cold start M = {at(0.0)[0].M:.3g}, L = {at(0.0)[0].L:.3g}: "
                           f"{st.iterations} iterations")
        else:
            start = carry(grid_prev, u, grid)
            ok = False
            if s_target > s:  # first the whole way at once, from the coarser solution
                u_j, ok, st = newton_at(s_target, shift(s, start, s_target), STEP_ITERS)
                if ok:
                    u, s = u_j, s_target
                    out.log.append(f"{grid.x.size} nodes: {st.iterations} iterations from {grid_prev.x.size} "
                                   f"nodes to s = {s:.3g}")
            if not ok:
                u, ok, st = newton_at(s, start, max_iter)
                out.log.append(f"{grid.x.size} nodes: {st.iterations} iterations from {grid_prev.x.size} nodes")
        if not ok:
            out.message = f"{grid.x.size} nodes: Newton did not converge at s = {s:.3g} of the load path"
            break
        if s_target > s:
            def param(tp, lo=s, hi=s_target):  # follow's parameter [0, 1] on [s, s_target]
                return 1.0 if tp >= 1.0 and hi >= 1.0 else lo + tp * (hi - lo)

            def central_p(tp, v, central=central, param=param):
                return central(param(tp), v)

            def predict(t0, v, t1, shift=shift, param=param):
                return shift(param(t0), v, param(t1))

            def solve(tp, v, param=param):
                u_new, ok, st = newton_at(param(tp), v, STEP_ITERS)
                res = NewtonResult(x=u_new, iterations=st.iterations, residual_norm=st.norms[-1], success=ok,
                                   message="", residual_norms=st.norms)
                if not ok:
                    raise NewtonError("film-content Newton did not converge", res)
                return res

            path = follow(solve, predict, central_p, u, first_step=0.5)
            out.log.append(f"{grid.x.size} nodes: load path s = {s:.3g} -> {s_target:.3g}: {path.message}")
            u, s = path.state, param(path.s)
            if not path.success and last:
                out.message = f"{grid.x.size} nodes: {path.message}"
                m_res = resolved_load(contact, grid)
                if m_res < contact.M:
                    out.message += (f"; this grid resolves the inlet and the contact up to M ~ {m_res:.3g} (node "
                                    f"spacing {inlet_spacing(grid):.3g} b at the inlet edge x = -b, "
                                    f"{contact._contact_spacing(grid):.3g} b in the contact): refine it there")
                ok = False
                break
            # a coarse level that cannot carry the load further hands over to the finer one where it stopped
        grid_prev = grid
    out.state = u
    out.content = at(s)[1]
    out.success = bool(ok and s >= 1.0)
    if out.success:
        out.message = "; ".join(out.log)
    return out
