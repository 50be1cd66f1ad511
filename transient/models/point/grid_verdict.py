"""The grid verdict of a point-contact film: an error bound from the same film on coarser grids.

With ``f1, f2, f4`` the film on the grid, on every second and on every fourth node, ``d1 = f1 - f2`` and
``d2 = f2 - f4``, Richardson's estimate of the fine film's error is ``|d1| / (2^p - 1)`` (Roache, *Verification
and Validation in Computational Science and Engineering*, 1998, ch. 5). The order ``p``: observed,
``log2(d2/d1)``, where the three films converge monotonically, and never above the scheme's formal order (an
observed order above it is taken as luck, not as accuracy); below ``MIN_ORDER`` or non-monotone the films are
not in the asymptotic range and no error is bounded. With two grids only, the scheme's order. The last change
``|d1|`` alone is no bound: at first order and an observed order 0.3-0.8 the error is 1.3-3 times it.
The estimate is multiplied by Roache's factor of safety (his grid convergence index): 1.25 from three grids, 3
from two. Measured: the bare estimate from 33-65-129 at M = 61 put h_min's error at 1.70 %, its error against
the Richardson limit of 129 and 257 nodes is 1.84 % (docs/validation.md).
"""

from __future__ import annotations

import math

#: an observed order below this: the films are not converging at a rate that bounds their error
MIN_ORDER = 0.5
#: the formal order of each Couette flux (:data:`transient.models.point.contact.UPWIND`)
FORMAL_ORDER = {"first": 1.0, "second": 2.0, "limited": 2.0}
#: Roache's factor of safety on Richardson's estimate from three grids, and from two (the scheme's order assumed)
SAFETY_THREE, SAFETY_TWO = 1.25, 3.0


def error_estimate(fine: float, half: float, quarter: float | None, formal_order: float) -> tuple[float, str]:
    """``(error, basis)``: the estimated relative error of ``fine`` (``inf`` when not bounded; Richardson's
    estimate times :data:`SAFETY_THREE` or :data:`SAFETY_TWO`) and how it was obtained, in words (the order
    used, or why there is none)."""
    d1 = fine - half
    if quarter is None:
        return (SAFETY_TWO * abs(d1) / (2.0 ** formal_order - 1.0) / abs(fine),
                f"two grids, the scheme's order {formal_order:g}")
    d2 = half - quarter
    if d1 == 0.0 and d2 == 0.0:
        return 0.0, "no change over three grids"
    if d1 * d2 <= 0.0 or abs(d2) <= abs(d1):
        return math.inf, "the films do not converge monotonically over three grids"
    p = math.log2(d2 / d1)
    if p < MIN_ORDER:
        return math.inf, f"observed order {p:.2f} < {MIN_ORDER}"
    p_used = min(p, formal_order)
    return SAFETY_THREE * abs(d1) / (2.0 ** p_used - 1.0) / abs(fine), f"observed order {p:.2f}" + (
        f", taken as the scheme's {formal_order:g}" if p > formal_order else "")


def describe(error: float, basis: str) -> str:
    """``"error <= x % (basis)"``, or ``"error not bounded (reason)"``."""
    if math.isfinite(error):
        return f"error <= {error:.1%} ({basis})"
    return f"error not bounded ({basis})"
