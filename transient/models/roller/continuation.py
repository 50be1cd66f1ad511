"""Parameter continuation for the steady EHL Newton: from an easily solved contact to the requested one.

Semismooth Newton on the complementarity system converges from the Hertz pressure only near the
middle of the Moes chart; heavily loaded (large M) and strongly piezoviscous (large L) contacts need
a start close to the answer. The path ``s in [0, 1]`` joins an easy contact (``s = 0``, solved from
its cold start) to the requested one (``s = 1``); each accepted step starts Newton from the previous
solution carried to the new parameters (``predict``). Step control (Allgower & Georg, *Introduction
to Numerical Continuation Methods*, 2003, ch. 6): a step is accepted when Newton converges, the film
stays positive and the central film changes by at most the factor ``exp(max_change)`` -- a larger
jump means Newton left the solution branch (coarse-grid EHL problems have spurious thin-film
solutions at high load) -- then the step grows 1.5x; otherwise it is halved, down to ``min_step``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from transient.solvers.newton import NewtonError


@dataclass
class PathResult:
    """Outcome of :func:`follow`: the last state, its parameter ``s`` and the histories."""

    state: np.ndarray
    s: float
    success: bool
    message: str
    iterations: int = 0
    steps: int = 0
    rejected: int = 0
    residual_norms: list = field(default_factory=list)
    path: list = field(default_factory=list)
    #: every attempted step: (s, accepted, Newton iterations)
    attempts: list = field(default_factory=list)
    #: the discrete problem at ``s`` and the contact it belongs to (set by the caller)
    film: object = None
    contact: object = None


def follow(solve, predict, central_film, u0, *, first_step: float = 0.25, max_change: float = 0.4,
           min_step: float = 1.0 / 512, max_steps: int = 200) -> PathResult:
    """Continue ``u0`` (a solution at ``s = 0``) to ``s = 1``.

    ``solve(s, u_start)`` returns a Newton result (``x``, ``iterations``, ``residual_norms``) or raises
    :class:`~transient.solvers.newton.NewtonError`; ``predict(s_from, u, s_to)`` carries a state to new
    parameters; ``central_film(s, u)`` is the central film in a unit that does not change along the
    path (its minimum film must be positive too: return ``nan`` otherwise)."""
    u, s, ds = np.array(u0, float), 0.0, first_step
    hc = central_film(0.0, u)
    out = PathResult(state=u, s=0.0, success=False, message="")
    out.path.append((0.0, hc))
    while s < 1.0 and out.steps + out.rejected < max_steps:
        s_new = min(1.0, s + ds)
        start = predict(s, u, s_new)
        try:
            with np.errstate(over="ignore", invalid="ignore"):  # a too long step may overflow exp(alpha p): rejected
                nr = solve(s_new, start)
            hc_new = central_film(s_new, nr.x)
            ok = bool(np.isfinite(hc_new) and hc_new > 0 and abs(math.log(hc_new / hc)) <= max_change)
            its = nr.iterations
            out.residual_norms = list(nr.residual_norms)
        except NewtonError as exc:
            ok = False
            its = exc.result.iterations
            out.residual_norms = list(exc.result.residual_norms)
        out.iterations += its
        out.attempts.append((s_new, ok, int(its)))
        if ok:
            u, s, hc = nr.x, s_new, hc_new
            out.steps += 1
            out.path.append((s, hc))
            ds = min(1.5 * ds, 1.0)
        else:
            out.rejected += 1
            ds *= 0.5
            if ds < min_step:
                break
    out.state, out.s = u, s
    out.success = s >= 1.0
    out.message = (f"continuation reached the requested contact in {out.steps} steps ({out.rejected} rejected)"
                   if out.success else
                   f"continuation stopped at s = {s:.4f} of the path after {out.steps} steps, {out.rejected} "
                   f"rejected (step below {min_step:.1e})")
    return out
