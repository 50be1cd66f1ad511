"""Detection of a steady periodic response from once-per-period (Poincare) samples.

A response that has settled onto a motion with the forcing period T returns to the same point every
period, so its Poincare samples ``z_k = z(t0 + k T)`` converge. :func:`find_settled`
(:mod:`transient.solvers.settling`, where models reach it too) returns the first
sample from which ``confirm`` consecutive Poincare steps ``|z_k - z_{k-1}| / scale`` are all below
``tol``; :func:`require_periodic` raises :class:`NotPeriodicError` with a clear message when that does
not happen within the samples given (transient still decaying too slowly, or a motion that is not
periodic with the forcing period: quasi-periodic whirl past the stability threshold, period
doubling, ...). The samples of a quasi-periodic motion lie on a closed curve and keep moving along it,
so their steps do not fall below ``tol`` (and ``confirm`` > 1 guards against an occasional close
return).
"""

from __future__ import annotations

import numpy as np

from transient.solvers.settling import find_settled, poincare_steps  # noqa: F401  (the criterion lives with the solvers)


class NotPeriodicError(RuntimeError):
    """The response did not become periodic with the forcing period within the allowed time."""


def not_periodic_message(samples, tol, scale=1.0, what="the response") -> str:
    d = poincare_steps(samples, scale)
    n = len(d)
    tail = d[-min(n, 5):] if n else d
    trend = ""
    if n >= 6:
        half = n // 2
        a, b = np.median(d[:half]), np.median(d[half:])
        if b > 0.5 * a:
            trend = (" and they are not decaying (no convergence to a periodic orbit: the motion is "
                     "quasi-periodic or chaotic, e.g. an oil whirl past the stability threshold, or "
                     "periodic with a multiple of the forcing period)")
        else:
            trend = (" although they are still decaying (slowly settling: allow more settling periods "
                     "or a looser tol)")
    return (f"{what} is not periodic with the forcing period to tol = {tol:g} after {len(samples)} Poincare "
            f"samples: the last once-per-period steps are "
            f"{np.array2string(np.asarray(tail), formatter={'float_kind': lambda v: f'{v:.2e}'})} "
            f"(in units of {scale:g}){trend}")


def require_periodic(samples, tol, scale=1.0, confirm=2, what="the response") -> int:
    """:func:`find_settled`, raising :class:`NotPeriodicError` with an explanatory message if the
    samples never settle."""
    k = find_settled(samples, tol, scale, confirm)
    if k is None:
        raise NotPeriodicError(not_periodic_message(samples, tol, scale, what))
    return k
