"""Reference solutions for the EHL line contact (Park verification), SI, by quadrature of closed forms.

Rigid cylinder (reduced radius R) on a plane, isoviscous and incompressible, gap ``h = h0 + x^2/(2R)``,
domain ``[a, b]`` with ``p(a) = 0``.

Rolling with the Reynolds exit condition (Martin 1916; finite inlet): integrating
``d/dx(h^3 dp/dx) = 12 eta u dh/dx`` once with ``dp/dx = 0`` where ``h = h_e``::

    p(x) = 12 eta u int_a^x (h - h_e)/h^3 ds,   p(x_e) = 0 fixes the exit x_e (h_e = h(x_e)),
    w    = 12 eta u int_a^{x_e} (x_e - s)(h(s) - h_e)/h(s)^3 ds

which tends to ``h0 = 4.9 eta u R / w`` for ``a -> -inf`` (:func:`transient.physics.line_formulas.martin_min`).

Pure squeeze (no rolling, ``dh/dt = dh0/dt < 0``, full film, ``p(a) = p(b) = 0``)::

    h^3 dp/dx = 12 eta dh0/dt (x - x*),  x* = int s/h^3 / int 1/h^3,
    w = -12 eta dh0/dt C(h0),  C(h0) = int_a^b (b - s)(s - x*)/h(s)^3 ds

so at constant load ``dh0/dt = -w / (12 eta C(h0))``; on the infinite domain ``C = pi sqrt(2) R^1.5 /
(4 h0^1.5)`` and ``h0(t)^-1/2 = h0(0)^-1/2 + w t / (6 sqrt(2) pi eta R^1.5)``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq


def _q(f, a, b):
    return quad(f, a, b, epsabs=0.0, epsrel=1e-9, limit=400)[0]


# Integrals are taken in gamma, x = s0 tan(gamma), s0 = sqrt(2 R h0): h = h0 sec^2(gamma) and
# dx / h^3 = (s0 / h0^3) cos^4(gamma) d(gamma), smooth on the whole (finite or infinite) domain.

def _gamma(x, s0):
    return math.atan(x / s0)


def martin_exit(h0: float, radius: float, inlet: float) -> float:
    """Exit position x_e [m] of the rigid-isoviscous rolling film with inlet at ``inlet`` [m] (< 0)."""
    s0 = math.sqrt(2.0 * radius * h0)
    ga = _gamma(inlet, s0)

    def flux_gap(ge):
        te2 = math.tan(ge) ** 2
        return _q(lambda g: (math.tan(g) ** 2 - te2) * math.cos(g) ** 4, ga, ge)

    return s0 * math.tan(brentq(flux_gap, 1e-9, 0.5 * math.pi - 1e-9, xtol=1e-15, rtol=1e-14))


def martin_load(h0: float, radius: float, viscosity: float, speed: float, inlet: float) -> float:
    """Load per unit length [N/m] carried by the rigid-isoviscous rolling film of minimum gap ``h0``."""
    s0 = math.sqrt(2.0 * radius * h0)
    te = martin_exit(h0, radius, inlet) / s0
    integral = _q(lambda g: (te - math.tan(g)) * (math.tan(g) ** 2 - te * te) * math.cos(g) ** 4,
                  _gamma(inlet, s0), math.atan(te))
    return 12.0 * viscosity * speed * s0 * s0 / (h0 * h0) * integral


def martin_film(load_per_length: float, radius: float, viscosity: float, speed: float, inlet: float) -> float:
    """Minimum film h0 [m] of the rigid-isoviscous rolling cylinder with the inlet at ``inlet`` [m]."""
    h_inf = 4.9 * viscosity * speed * radius / load_per_length
    f = lambda h0: martin_load(h0, radius, viscosity, speed, inlet) - load_per_length  # noqa: E731
    return brentq(f, 0.2 * h_inf, 1.5 * h_inf, xtol=1e-14 * h_inf, rtol=1e-13)


def squeeze_coefficient(h0: float, radius: float, a: float, b: float) -> float:
    """``C(h0)`` [1/m] of the rigid pure-squeeze film on ``[a, b]`` (module docstring)."""
    s0 = math.sqrt(2.0 * radius * h0)
    ga, gb = _gamma(a, s0), _gamma(b, s0)
    tb = b / s0
    c4 = lambda g: math.cos(g) ** 4  # noqa: E731
    ts = _q(lambda g: math.tan(g) * c4(g), ga, gb) / _q(c4, ga, gb)
    return -s0 ** 3 / h0 ** 3 * _q(lambda g: (tb - math.tan(g)) * (math.tan(g) - ts) * c4(g), ga, gb)


def squeeze_film_history(t, h0_start: float, load_per_length: float, radius: float, viscosity: float,
                         a: float, b: float) -> np.ndarray:
    """``h0(t)`` [m] of the rigid cylinder under constant load on ``[a, b]`` (solve_ivp, rtol 1e-11)."""
    t = np.asarray(t, float)
    rhs = lambda _t, h: [-load_per_length / (12.0 * viscosity * squeeze_coefficient(h[0], radius, a, b))]  # noqa: E731
    sol = solve_ivp(rhs, (t[0], t[-1]), [h0_start], t_eval=t, rtol=1e-11, atol=1e-20 + 1e-13 * h0_start,
                    method="DOP853")
    return sol.y[0]


def squeeze_film_infinite(t, h0_start: float, load_per_length: float, radius: float, viscosity: float) -> np.ndarray:
    """Closed form ``h0(t)`` [m] of the pure squeeze on the infinite domain (module docstring)."""
    t = np.asarray(t, float)
    s = h0_start ** -0.5 + load_per_length * t / (6.0 * math.sqrt(2.0) * math.pi * viscosity * radius ** 1.5)
    return s ** -2.0
