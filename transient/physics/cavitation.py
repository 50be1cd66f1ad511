"""Mass-conserving (Elrod / JFO) cavitation in a form a stiff BDF integrator can differentiate.

Elrod (1981), Vijayaraghavan & Keith (1989), as in Rho & Kim eqs. (1), (2), (4)::

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
go to zero. In the (P, theta) plane the switch is the rounded corner ``e^(-P/w) + e^(-(1-theta)/w_theta) = 1``
of the sharp "L" (P = 0 for theta < 1, theta = 1 + P / beta_bar for P > 0); the bias it puts on a film is set
by the area it cuts off that corner, ``(pi^2 / 6) w w_theta``: second order in the widths when both shrink
together (docs/journal.md, section 3). Prescribed values (the supply groove, the bearing ends) are not on
the rounded corner but on the sharp one (:func:`sharp_fixed_cells`): a boundary at p = p_c would otherwise
carry P(0) = w ln 2 and bias the load linearly in ``w`` -- that was the +0.14 % of the first versions.

The content formulation of the journal orbit integrates the content ``theta`` (times the film thickness)
itself, so a cell that fills or empties within one time step conserves its mass exactly; the pressure
comes from the universal variable ``u = C^-1(theta)`` (:func:`elrod_inverse`, a monotone scalar Newton).
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


@njit(cache=True)
def sharp_fixed_cells(free, u_fixed, beta_bar, P, dP, C, D, dD):
    """Cells held at a prescribed state (``free[i]`` False) take the *sharp* Elrod values of their prescribed
    ``u_fixed`` (a pressure: ``P = max(u_fixed, 0)``, ``theta = 1 + P / beta_bar``), whatever their current
    ``u``, so the fields and their (zero) derivatives do not depend on it."""
    inv = 1.0 / beta_bar
    for i in range(free.size):
        if not free[i]:
            p = u_fixed[i] if u_fixed[i] > 0.0 else 0.0
            P[i] = p
            C[i] = 1.0 + p * inv
            dP[i] = 0.0
            D[i] = 0.0
            dD[i] = 0.0


@njit(cache=True)
def elrod_inverse(theta, width, content_scale, beta_bar, u):
    """``u = C^-1(theta)`` elementwise for the switch of :func:`elrod_content` (any real ``theta``).

    ``C`` is monotone and concave if ``1/beta_bar < r`` (convex otherwise). At both ends of the sharp curve,
    ``u0 = (theta - 1) / r`` (cavitated) and ``u0 = beta_bar (theta - 1)`` (full film), ``C(u0) - theta`` has the
    sign of ``1/beta_bar - r`` (``P(u0)`` and ``P(u0) - u0`` are positive), so Newton from either converges
    monotonically, from the side the curvature allows; it starts from the one nearer the root on that side (the
    larger if concave, else the smaller): the full film's pressure in one or two steps rather than the 5-12 it takes
    to climb out of the switch from the cavitated end. It stops when the step is below 1e-14 of ``max(1, |u|)``."""
    r = content_scale
    inv = 1.0 / beta_bar
    concave = r > inv
    for i in range(theta.size):
        t = theta[i]
        x = (t - 1.0) / r
        x_full = (t - 1.0) * beta_bar
        x = max(x, x_full) if concave else min(x, x_full)
        for _ in range(200):
            s = x / width
            if s > 30.0:
                e = np.exp(-s)
                P = x + width * np.log1p(e)
                dP = 1.0 / (1.0 + e)
            elif s < -30.0:
                e = np.exp(s)
                P = width * e
                dP = e
            else:
                e = np.exp(s)
                P = width * np.log1p(e)
                dP = e / (1.0 + e)
            f = 1.0 + P * inv + r * (x - P) - t
            dx = -f / (dP * inv + r * (1.0 - dP))
            x += dx
            if abs(dx) <= 1e-14 * max(1.0, abs(x)):
                break
        u[i] = x
