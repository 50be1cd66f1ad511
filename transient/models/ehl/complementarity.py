"""The Fischer-Burmeister form of the cavitation complementarity in the EHL films' FBNS Newton.

Each node carries ``FB(p, b) = p + b - sqrt(p^2 + b^2)`` with ``b = 1 - theta`` (``p >= 0``, ``b >= 0``, ``p b = 0``:
Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.* 58, 2015). Its gradient is
``dFB/dp = 1 - p / r``, ``dFB/dtheta = -(1 - b / r)`` with ``r = sqrt(p^2 + b^2)``.

At the kink ``p = b = 0`` (a full film at exactly zero pressure, the film's reformation front) FB is not
differentiable; any element of its generalised Jacobian (the convex hull of the one-sided limits) serves the
semismooth Newton. The element taken here is the full film's, ``(0, -1)``: the content is held at 1 and the
pressure left free, as on the side ``p > 0``, so that a node on the front can take up pressure in the next step
(the symmetric element ``(1 - 1/sqrt 2, -(1 - 1/sqrt 2))`` would split the step between the two)."""

from __future__ import annotations

import numpy as np


def fb_residual(p, theta):
    """``(FB(p, 1 - theta), r)`` per node at pressures ``p`` and contents ``theta``, ``r = sqrt(p^2 + (1 -
    theta)^2)`` (kept for :func:`fb_derivatives`)."""
    b = 1.0 - theta
    rad = np.sqrt(p * p + b * b)
    return p + b - rad, rad


def fb_derivatives(p, theta, rad):
    """``(dFB/dp, dFB/dtheta)`` per node at pressures ``p``, contents ``theta`` and ``rad = sqrt(p^2 + (1 -
    theta)^2)`` (the value the residual already holds); the full film's element ``(0, -1)`` at the kink."""
    b = 1.0 - theta
    safe = np.where(rad > 0, rad, 1.0)
    return np.where(rad > 0, 1.0 - p / safe, 0.0), -np.where(rad > 0, 1.0 - b / safe, 1.0)
