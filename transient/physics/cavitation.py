"""Mass-conserving (Elrod / JFO) cavitation in a form a stiff BDF integrator can differentiate.

Elrod (1981), Vijayaraghavan & Keith (1989), as in Rho & Kim (seed 003) eqs. (1), (2), (4)::

    theta = rho / rho_c,    p = p_c + beta g(theta) (theta - 1),    g = 1 full film, 0 cavitated

The unknown per cell is a *universal variable* ``u`` scaled differently on the two sides of the
switch (``beta_bar = beta / p0``, ``r`` the content scale below)::

    full film   (u > 0):  u = beta_bar (theta - 1)   -- the dimensionless pressure above p_c
    cavitation  (u < 0):  u = (theta - 1) / r        -- minus the missing content, in units of r

With ``u`` (not ``theta``) as the state the pressure is resolved to the integrator's relative tolerance
whatever the bulk modulus (``theta`` itself sits at ``1 + p/beta`` and loses every digit of ``p`` when
``beta`` = 1e12), and in the cavitated zone ``u`` moves as slowly as the content does (a single
``beta_bar (theta - 1)`` scaling would make ``u`` race through the switch ``beta_bar`` times faster
and force tiny time steps at every rupture and reformation).

The discontinuous switch ``g`` is replaced by a softplus of *two* widths: ``w`` in pressure (units of
p0) and ``w_theta = r w`` in content. The pressure and the content are::

    P(u) = w ln(1 + exp(u / w))                 -> max(u, 0) as w -> 0,   P' = 1 / (1 + exp(-u / w))
    C(u) = theta = 1 + P(u) / beta_bar + r (u - P(u))                      (u - P = -w ln(1 + e^(-u/w)))
    D(u) = dC/du = P' / beta_bar + r (1 - P'),   dD/du = P'' (1/beta_bar - r),   P'' = P' (1 - P') / w

so ``P`` and ``C`` are smooth and monotone and the model tends to the sharp Elrod model as both widths
go to zero. The two widths do different jobs (docs/journal.md, section 3): the pressure width biases the
load (linearly in ``w``), the content width -- over which a cell fills or empties -- hardly does, but
sets how abruptly a cell's state turns at rupture and reformation, and so the time steps a BDF
integrator needs there. ``r = 1`` is the single-width switch.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def softplus_pressure(u, width, P, dP):
    """``P = w ln(1 + e^(u/w))`` and ``dP/du`` (overflow-safe), elementwise."""
    for i in range(u.size):
        s = u[i] / width
        if s > 30.0:
            P[i] = u[i] + width * np.log1p(np.exp(-s))
            dP[i] = 1.0 / (1.0 + np.exp(-s))
        elif s < -30.0:
            e = np.exp(s)
            P[i] = width * e
            dP[i] = e
        else:
            e = np.exp(s)
            P[i] = width * np.log1p(e)
            dP[i] = e / (1.0 + e)


def softplus(u, width):
    """NumPy convenience wrapper of :func:`softplus_pressure` (returns ``P, dP/du``)."""
    u = np.ascontiguousarray(u, dtype=float)
    P, dP = np.empty_like(u), np.empty_like(u)
    softplus_pressure(u.ravel(), float(width), P.ravel(), dP.ravel())
    return P, dP


@njit(cache=True)
def elrod_content(u, P, dP, width, content_scale, beta_bar, C, D, dD):
    """Content ``C = theta``, ``D = dC/du`` and ``dD/du`` from ``u`` and the switch ``P, P'`` (see above;
    ``content_scale`` is ``r``)."""
    r = content_scale
    inv = 1.0 / beta_bar
    for i in range(u.size):
        C[i] = 1.0 + P[i] * inv + r * (u[i] - P[i])
        D[i] = dP[i] * inv + r * (1.0 - dP[i])
        dD[i] = dP[i] * (1.0 - dP[i]) / width * (inv - r)
