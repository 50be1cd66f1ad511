"""numba kernels of the Reynolds-condition form of the line contact's and the tapered roller's EHL film (the rows:
:mod:`transient.models.ehl.rows`): the exit condition as a complementarity and the dense Newton matrix.

Reynolds exit condition (P = dP/dn = 0 at the free boundary) as the complementarity problem
``p >= 0, -F >= 0, p F = 0``, written as the Fischer-Burmeister equation
``phi(p, -F) = p - F - sqrt(p^2 + F^2) = 0`` (:mod:`transient.models.ehl.complementarity`) and solved by a
semismooth Newton, or (the transient) in penalty form ``-F + gamma min(p, 0) = 0`` (smoothed, :func:`penalty`),
whose error is O(1/gamma).
"""

from __future__ import annotations

import math

from numba import njit

from transient.models.ehl.reduced import reynolds_row


@njit(cache=True, error_model="numpy")
def penalty(a, b, phi, da, db, gamma):
    """Penalty form of the complementarity ``a >= 0, b >= 0, a b = 0``: ``phi = b + gamma q(a)`` with
    ``q(a) = (a - sqrt(a^2 + d^2))/2`` (``min(a, 0)`` rounded over ``|a| < d = 1e-10``; a larger ``d``
    puts a spurious source ``gamma d^2 / (4 a)`` into the low-pressure inlet): where ``b > 0`` the
    solution has ``a ~ -b/gamma`` (slightly negative), where ``a > 0`` it has ``b ~ 0``."""
    d2 = 1e-20
    for k in range(a.size):
        r = math.sqrt(a[k] * a[k] + d2)
        phi[k] = b[k] + 0.5 * gamma * (a[k] - r)
        da[k] = 0.5 * gamma * (1.0 - a[k] / r)
        db[k] = 1.0


@njit(cache=True, error_model="numpy")
def assemble_dense(Sp, Sh, colp, colh, K, elastic, fb_a, fb_b, area_w, J):
    """Dense Newton matrix of ``[phi(p, -F); (sum A p - W)/W]`` in the unknowns ``[p, h0]``.

    ``K`` (n_full, n): film change per unit interior pressure (``dh/dp``; not read for a rigid body,
    ``elastic=False``); ``colp`` / ``colh`` map the slots to interior / full node indices (-1: none)."""
    n = Sp.shape[0]
    for r in range(n):
        row = J[r]
        row[n] = reynolds_row(Sp, Sh, colp, colh, K, elastic, r, row)
        b = -fb_b[r]
        for q in range(n + 1):
            row[q] *= b
        row[r] += fb_a[r]
    for q in range(n):
        J[n, q] = area_w[q]
    J[n, n] = 0.0
