"""The Moes chart of the EHL line contact: :class:`~transient.models.roller.LineContact` solved at given
Moes groups (M, L) and compared with Moes' central-film formula and its four asymptotes
(:mod:`transient.physics.line_formulas`).

A chart point fixes ``U`` (default 1e-11, as in Venner & Lubrecht's charts), ``R`` and ``E'``; then
``W = M (2U)^1/2`` and ``G = L (2U)^-1/4`` give the load and ``alpha``. The domain is fully flooded at
every M: inlet ``-max(4, 28/M) b``, outlet ``max(1.5, 14/M) b`` (below M ~ 7 the pressure spreads over
the hydrodynamic length ``sqrt(2 R h) ~ 2.8 b/M``). ``grid="clustered"`` concentrates the nodes in the
Hertz zone, at the inlet edge and at the outlet spike (for M >= 10; :data:`CLUSTERS`), ``"uniform"`` spaces
them evenly (at M >= 300 too coarse at the inlet edge on 1025 nodes: ``resolved`` False).
"""

from __future__ import annotations

import math
import time
import warnings

import numpy as np

from transient.models.roller import LineContact
from transient.models.roller.line_contact import FilmResolutionWarning
from transient.models.roller.grid import clustered_axis
from transient.models.roller.line_grid import LINE_CLUSTERS
from transient.physics.line_formulas import moes_asymptotes, moes_central

RADIUS, MODULUS, VISCOSITY = 0.01, 220e9, 0.02
#: node-density clusters ``(centre, width, weight)``, units of b: the line contact's default clusters
#: (:data:`transient.models.roller.line_grid.LINE_CLUSTERS`)
CLUSTERS = LINE_CLUSTERS


def chart_domain(M: float) -> tuple[float, float]:
    """Fully flooded domain (inlet, outlet) in units of b at Moes load ``M`` (module docstring)."""
    return -max(4.0, 28.0 / M), max(1.5, 14.0 / M)


def chart_nodes(M: float, nodes: int, grid: str = "clustered") -> np.ndarray:
    """Node positions (units of b) of a chart point's grid."""
    lo, hi = chart_domain(M)
    if grid == "uniform" or M < 10.0:
        return np.linspace(lo, hi, nodes)
    if grid != "clustered":
        raise ValueError(f"grid = {grid!r}: use 'clustered' or 'uniform'")
    return clustered_axis(lo, hi, nodes, clusters=CLUSTERS, snap=(0.0,))


def chart_contact(M: float, L: float, nodes: int = 1025, grid: str = "clustered", density: str = "incompressible",
                  viscosity_law: str = "barus", U: float = 1e-11) -> LineContact:
    """The line contact at Moes groups ``(M, L)`` (module docstring), SI inside."""
    W, G = M * math.sqrt(2.0 * U), L / (2.0 * U) ** 0.25
    speed = U * MODULUS * RADIUS / VISCOSITY
    return LineContact(RADIUS, W * MODULUS * RADIUS, speed, VISCOSITY, G / MODULUS, MODULUS, density=density,
                       viscosity_law=viscosity_law, grid=chart_nodes(M, nodes, grid), domain=chart_domain(M))


def chart_point(M: float, L: float, **kw) -> dict:
    """Solve one chart point: Moes-scaled ``H_c = (h_c/R)(2U)^-1/2`` and ``H_min`` against Moes' formula,
    iterations, wall and CPU time [s] (CPU: this process, all its threads); ``resolved``: False where
    ``steady`` warned that the grid is too coarse at the inlet edge for this M (:class:`FilmResolutionWarning`)."""
    c = chart_contact(M, L, **kw)
    t0, c0 = time.perf_counter(), time.process_time()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FilmResolutionWarning)
        s = c.steady(raise_on_failure=False)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    resolved = not any(issubclass(w.category, FilmResolutionWarning) for w in caught)
    unit = c.radius * math.sqrt(2.0 * c.U)
    moes = moes_central(M, L)
    return dict(M=M, L=L, success=bool(s.success), H_c=s.h_central / unit, H_min=s.h_min / unit, moes=moes,
                deviation=s.h_central / unit / moes - 1.0, asymptotes=moes_asymptotes(M, L),
                resolved=resolved, p_max=s.p_max / c.p_h, iterations=s.iterations, wall_s=wall, cpu_s=cpu,
                nodes=int(c.grid.x.size),
                residual=float(s.residual_norms[-1]) if s.residual_norms else float("nan"), message=s.message)


def run_chart(Ms, Ls, **kw) -> list[dict]:
    """:func:`chart_point` over the tensor product of ``Ms`` and ``Ls``."""
    return [chart_point(M, L, **kw) for M in Ms for L in Ls]


def moes_curves(rows: list[dict], n: int = 200) -> dict:
    """Moes' formula per L of ``rows`` and the four asymptotes (RP, EP at the largest L) on ``n``
    loads spanning the rows' M, for :func:`transient.plots.roller.moes_chart`."""
    Ms = np.geomspace(min(r["M"] for r in rows), max(r["M"] for r in rows), n)
    Ls = sorted({r["L"] for r in rows})
    top = max(Ls[-1], 1.0)
    asym = [moes_asymptotes(m, top) for m in Ms]
    return dict(M=Ms, formula={L: np.array([moes_central(m, L) for m in Ms]) for L in Ls},
                asymptotes={k: np.array([a[k] for a in asym]) for k in ("RI", "EI", "RP", "EP")})
