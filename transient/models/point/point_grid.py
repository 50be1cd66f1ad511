"""The point contact's default grid, chosen from Moes' M so that the default film's grid verdict is settled.

With the second-order Couette flux the films converge at order ~2, and the error Richardson's estimate bounds
(:mod:`transient.models.point.grid_verdict`) grows about as ``M dx^2`` (dx the node spacing along the rolling
direction, units of the Hertz semi-axis b): the inlet's pressure build-up and the outlet spike narrow as the load
rises. Measured on circular contacts (second order, Barus, Dowson-Higginson, default domain; docs/validation.md),
Richardson's estimate without the verdict's factor of safety is ~19-23 % of ``M dx^2``: M = 6.7 on 65 x 65:
1.8 %; 15 on 65: 2.6 %; 61 on 129: 2.4 %; 173 on 129: 7.2 %, on 257: 2.0 %; 518 on 257: 6.6 %. The default
spacing is at most ``RESOLUTION / sqrt(M)`` b, where the verdict's bound (factor of safety 1.25 included) is
at most about ``ERROR_BOUND``, and at most ``1 / MIN_NODES_PER_B`` (light loads); on the fewest ``2^k + 1``
nodes (a power of two for the grid check and the Krylov levels), at least ``MIN_NODES``. The cross-track axis
takes as many nodes (its half width ``1 + 1.5 k`` b; at M = 61 on 129 x 129 settled for k = 2, 4, 8).
"""

from __future__ import annotations

import math

#: largest ``sqrt(M) dx`` [b] of the default grid: the bound, ~19-23 % M dx^2 times the verdict's factor of
#: safety 1.25, is then at most ~``ERROR_BOUND`` (at the top of each grid's M range; 1/4 of it at the bottom)
RESOLUTION = 0.4
#: the error bound the default grid aims at
ERROR_BOUND = 0.04
#: nodes required inside the Hertz semi-axis b along the rolling direction (any grid)
MIN_NODES_PER_B = 4
#: the default grid has at least this many nodes per axis (its grid check solves on 33 and 17)
MIN_NODES = 65
#: ... and at most this many (the largest grid :class:`~transient.models.point.contact.PointContact` takes)
MAX_NODES = 2049


def default_spacing(M: float) -> float:
    """The largest node spacing [b] along the rolling direction at which the film is settled to ~3 %:
    ``RESOLUTION / sqrt(M)``, and at most ``1 / MIN_NODES_PER_B`` (light loads)."""
    return min(RESOLUTION / math.sqrt(M), 1.0 / MIN_NODES_PER_B)


def default_grid(M: float, domain) -> tuple[int, int]:
    """``(nx, ny)``: the fewest ``2^k + 1`` nodes (``MIN_NODES`` ... ``MAX_NODES``) spacing ``domain``'s rolling
    extent ``domain[1] - domain[0]`` [b] at most :func:`default_spacing`; as many across."""
    intervals = (domain[1] - domain[0]) / default_spacing(M)
    n = 2 ** max(math.ceil(math.log2(intervals)), round(math.log2(MIN_NODES - 1))) + 1
    n = min(n, MAX_NODES)
    return n, n
