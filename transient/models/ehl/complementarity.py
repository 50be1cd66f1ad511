"""The Fischer-Burmeister form of the complementarity conditions of the EHL films' semismooth Newton.

``FB(a, b) = a + b - sqrt(a^2 + b^2)`` vanishes exactly where ``a >= 0``, ``b >= 0``, ``a b = 0`` (Woloszynski,
Podsiadlo & Stachowiak, *Tribol. Lett.* 58, 2015). Its gradient is ``(1 - a/r, 1 - b/r)`` with ``r = sqrt(a^2 +
b^2)``; at the kink ``a = b = 0`` FB is not differentiable, and any element of its generalised Jacobian (the
convex hull of the one-sided limits, here the pairs ``(1 - cos t, 1 - sin t)``, ``t`` in ``[0, pi/2]``) serves the
semismooth Newton. Two pairs, two elements (:func:`fb_gradient`'s ``kink``):

- the cavitation of the film-content form (point, line, roller): ``a = p``, ``b = 1 - theta``, both unknowns.
  The element taken is the full film's, ``(0, 1)`` (``dFB/dtheta = -1``): the content is held at 1 and the
  pressure left free, as on the side ``p > 0``, so that a node on the reformation front (a full film at exactly
  zero pressure) can take up pressure in the next step (the symmetric element would split the step between the
  two).
- the exit condition of the Reynolds-condition form (line, roller): ``a = p``, ``b = -F``, the pressure and the
  node's Reynolds residual (:data:`SYMMETRIC_KINK`). Neither side is preferred: at a node where both vanish the
  row weighs the pressure and the Reynolds row alike, so the Newton matrix keeps both the node's pressure and its
  flow balance (the element ``(1, 0)`` would drop the flow balance, ``(0, 1)`` the pressure).
"""

from __future__ import annotations

import numpy as np

#: the symmetric element of the generalised Jacobian at the kink, ``(1 - 1/sqrt 2, 1 - 1/sqrt 2)``
SYMMETRIC_KINK = (1.0 - 1.0 / np.sqrt(2.0), 1.0 - 1.0 / np.sqrt(2.0))
#: the full film's element at the kink of the cavitation pair ``(p, 1 - theta)``
FULL_FILM_KINK = (0.0, 1.0)


def fb_value(a, b):
    """``(FB(a, b), r)`` per entry, ``r = sqrt(a^2 + b^2)`` (kept for :func:`fb_gradient`)."""
    rad = np.sqrt(a * a + b * b)
    return a + b - rad, rad


def fb_gradient(a, b, rad, kink):
    """``(dFB/da, dFB/db)`` per entry at ``rad = sqrt(a^2 + b^2)`` (the value :func:`fb_value` holds); the element
    ``kink`` (module docstring) where ``rad = 0``."""
    safe = np.where(rad > 0, rad, 1.0)
    return np.where(rad > 0, 1.0 - a / safe, kink[0]), np.where(rad > 0, 1.0 - b / safe, kink[1])


def fb_residual(p, theta):
    """``(FB(p, 1 - theta), r)`` per node at pressures ``p`` and contents ``theta``, ``r = sqrt(p^2 + (1 -
    theta)^2)`` (kept for :func:`fb_derivatives`)."""
    return fb_value(p, 1.0 - theta)


def fb_derivatives(p, theta, rad):
    """``(dFB/dp, dFB/dtheta)`` per node at pressures ``p``, contents ``theta`` and ``rad = sqrt(p^2 + (1 -
    theta)^2)`` (the value the residual already holds); the full film's element ``(0, -1)`` at the kink."""
    d_p, d_b = fb_gradient(p, 1.0 - theta, rad, FULL_FILM_KINK)
    return d_p, -d_b


class CavitationRows:
    """The Fischer-Burmeister rows' gradient of a film-content film (the point's, the line's and the roller's), for
    :func:`~transient.models.ehl.newton.fbns_newton`: unknowns ``u = [p (n), theta (n), h0]``, ``e["rad"]`` from
    :func:`fb_residual` in the film's ``equations``."""

    n: int

    def fb_derivatives(self, u, e):
        """``(dFB/dp, dFB/dtheta)`` per node (:func:`fb_derivatives`)."""
        return fb_derivatives(u[: self.n], u[self.n: 2 * self.n], e["rad"])
