"""Hertz elliptical point contact: exact (complete elliptic integrals) and Hamrock–Brewe approximations.

Notation (Hamrock & Dowson, *Ball Bearing Lubrication*, Wiley 1981; Hamrock, *Fundamentals of Fluid
Film Lubrication*): ``x`` is the rolling (entraining) direction, ``y`` the transverse one.
``Rx``, ``Ry`` are the reduced radii of curvature, ``alpha_r = Ry / Rx >= 1``,
``R = 1 / (1/Rx + 1/Ry)``, ``E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b)``.
The ellipse has the semi-major axis ``a`` across the rolling direction (along ``y``) and the
semi-minor axis ``b`` along the rolling direction; the ellipticity is ``k = a / b``.
(The 2017 paper of Jeong, Lee, Yoo & Cho, names the transverse direction x and the rolling
direction y, so its ``a_x`` is our ``a`` and its ``a_y`` our ``b``.)

Exact relations (Johnson, *Contact Mechanics*, 1985, eqs. 3.40-3.41; Hamrock & Brewe 1983), with
the eccentricity ``e^2 = 1 - 1/k^2`` and the complete elliptic integrals ``K(e)``, ``E(e)``::

    alpha_r = Ry/Rx = (k^2 E - K) / (K - E)                    (solved for k)
    a = (6 k^2 E w R / (pi E'))^(1/3),  b = (6 E w R / (pi k E'))^(1/3)
    p_max = 3 w / (2 pi a b),  delta = K (9 / (2 E R) (w / (pi k E'))^2)^(1/3)

Hamrock–Brewe (1983) approximations: ``k = 1.0339 alpha_r^0.6360``,
``E = 1.0003 + 0.5968/alpha_r``, ``K = 1.5277 + 0.6023 ln(alpha_r)``.

Outside the ellipse the combined surface displacement of the Hertz pressure
``p = p_max sqrt(1 - x^2/b^2 - y^2/a^2)`` is (Love 1929; Johnson 1985, sec. 3.6)::

    u(x, y) = (p_max a b / E') * int_lambda^inf [1 - x^2/(b^2+s) - y^2/(a^2+s)] ds / sqrt((a^2+s)(b^2+s)s)

with ``lambda = 0`` inside the contact and ``x^2/(b^2+lambda) + y^2/(a^2+lambda) = 1`` outside,
so the gap of the dry contact along the rolling centreline (``y = 0``) is
``g(x) = x^2/(2 Rx) - delta + u(x, 0)``; this is the ``h_Y(m)`` of the paper's Eq. (3), ``m = x/b``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from transient.results import record_type


def reduced_modulus(youngs_modulus: float, poisson_ratio: float,
                    youngs_modulus_b: float | None = None, poisson_ratio_b: float | None = None) -> float:
    """Hamrock's effective modulus ``E' = 2 / ((1-nu_a^2)/E_a + (1-nu_b^2)/E_b)`` [Pa]."""
    eb = youngs_modulus if youngs_modulus_b is None else youngs_modulus_b
    nb = poisson_ratio if poisson_ratio_b is None else poisson_ratio_b
    return 2.0 / ((1.0 - poisson_ratio ** 2) / youngs_modulus + (1.0 - nb ** 2) / eb)


def _ratio_exact(k: float) -> float:
    """``(k^2 E - K)/(K - E)`` at ``e^2 = 1 - 1/k^2`` (the radius ratio giving ellipticity k)."""
    m = 1.0 - 1.0 / (k * k)
    K, E = ellipk(m), ellipe(m)
    return (k * k * E - K) / (K - E)


def ellipticity_exact(alpha_r: float) -> float:
    """Exact ellipticity ``k = a/b`` for the radius ratio ``alpha_r = Ry/Rx >= 1`` (root of Johnson 3.41)."""
    if not alpha_r >= 1.0:
        raise ValueError(f"alpha_r = Ry/Rx must be >= 1, got {alpha_r}")
    if alpha_r - 1.0 < 1e-12:
        return 1.0
    lo, hi = 1.0 + 1e-9, 2.0
    while _ratio_exact(hi) < alpha_r:
        hi *= 2.0
    return brentq(lambda k: _ratio_exact(k) - alpha_r, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=200)


def hamrock_brewe(alpha_r: float) -> tuple[float, float, float]:
    """Hamrock–Brewe (1983) curve fits ``(k, E, K)`` for ``alpha_r = Ry/Rx``."""
    return 1.0339 * alpha_r ** 0.6360, 1.0003 + 0.5968 / alpha_r, 1.5277 + 0.6023 * math.log(alpha_r)


@record_type
@dataclass(frozen=True)
class HertzContact:
    """One elliptical Hertz contact (per ball). Lengths [m], pressure [Pa], load [N].

    ``a`` semi-axis across the rolling direction, ``b`` along it, ``k = a/b``; ``rx`` (rolling) and
    ``ry`` (transverse) reduced radii; ``e_int``/``k_int`` the complete elliptic integrals E and K
    used; ``delta`` the mutual approach; ``load_per_ball`` the normal load on this contact.
    """

    load_per_ball: float
    rx: float
    ry: float
    e_prime: float
    k: float
    a: float
    b: float
    p_max: float
    delta: float
    e_int: float
    k_int: float
    exact: bool

    @property
    def alpha_r(self) -> float:
        return self.ry / self.rx

    @property
    def r_eff(self) -> float:
        """``R = 1/(1/Rx + 1/Ry)`` [m]."""
        return 1.0 / (1.0 / self.rx + 1.0 / self.ry)

    def gap_outside(self, x: float) -> float:
        """Dry-contact gap [m] on the rolling centreline at ``|x| >= b`` (elastic displacement included)."""
        return gap_rolling_axis(self, x)


def hertz_contact(load_per_ball: float, rx: float, ry: float, e_prime: float, exact: bool = True) -> HertzContact:
    """Hertz elliptical contact for a normal load [N], reduced radii [m] (``ry >= rx``) and ``E'`` [Pa].

    ``exact=True`` solves Johnson's transcendental relation for k with scipy's ``ellipk``/``ellipe``;
    ``exact=False`` uses the Hamrock–Brewe (1983) fits (module docstring).
    """
    for name, val, unit in (("load_per_ball", load_per_ball, "N"), ("rx", rx, "m"), ("ry", ry, "m"),
                            ("e_prime", e_prime, "Pa")):
        if not (np.isfinite(val) and val > 0):
            raise ValueError(f"{name} = {val!r} {unit} must be finite and > 0")
    if ry < rx:
        raise ValueError(f"ry = {ry} m must be >= rx = {rx} m (y is the direction of the larger radius)")
    alpha = ry / rx
    if exact:
        k = ellipticity_exact(alpha)
        m = 1.0 - 1.0 / (k * k)
        e_int, k_int = float(ellipe(m)), float(ellipk(m))
    else:
        k, e_int, k_int = hamrock_brewe(alpha)
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    w = load_per_ball
    a = (6.0 * k * k * e_int * w * r / (math.pi * e_prime)) ** (1.0 / 3.0)
    b = (6.0 * e_int * w * r / (math.pi * k * e_prime)) ** (1.0 / 3.0)
    p_max = 3.0 * w / (2.0 * math.pi * a * b)
    delta = k_int * (9.0 / (2.0 * e_int * r) * (w / (math.pi * k * e_prime)) ** 2) ** (1.0 / 3.0)
    return HertzContact(load_per_ball=w, rx=rx, ry=ry, e_prime=e_prime, k=k, a=a, b=b, p_max=p_max,
                        delta=delta, e_int=e_int, k_int=k_int, exact=exact)


def displacement(c: HertzContact, x: float, y: float) -> float:
    """Combined normal surface displacement [m] of both bodies under the Hertz pressure at (x, y).

    ``x`` along the rolling direction (semi-axis b), ``y`` across it (semi-axis a); Love's integral
    (module docstring), evaluated by adaptive quadrature after the substitution ``s = lambda + t^2``.
    """
    a2, b2 = c.a * c.a, c.b * c.b
    q = x * x / b2 + y * y / a2
    if q <= 1.0:
        lam = 0.0
    else:  # positive root of x^2/(b^2+l) + y^2/(a^2+l) = 1
        lam = brentq(lambda l: x * x / (b2 + l) + y * y / (a2 + l) - 1.0, 0.0, x * x + y * y, xtol=1e-30,
                     rtol=1e-15)

    def integrand(t):
        s = lam + t * t
        return 2.0 * (1.0 - x * x / (b2 + s) - y * y / (a2 + s)) / math.sqrt((a2 + s) * (b2 + s)) * \
            (t / math.sqrt(s) if s > 0 else 1.0)

    return c.p_max * c.a * c.b / c.e_prime * _quad_split(integrand, math.sqrt(a2 + lam))


def _quad_split(f, t_split: float) -> float:
    """``int_0^inf f(t) dt`` as two adaptive pieces split where the kernel changes scale."""
    v1, _ = quad(f, 0.0, t_split, epsabs=0.0, epsrel=1e-11, limit=200)
    v2, _ = quad(f, t_split, np.inf, epsabs=0.0, epsrel=1e-11, limit=200)
    return v1 + v2


def gap_rolling_axis(c: HertzContact, x: float) -> float:
    """Dry gap ``g(x) = x^2/(2 Rx) - delta + u(x, 0)`` [m] on the rolling centreline, ``|x| >= b``."""
    x = abs(x)
    if x < c.b:
        return 0.0
    return x * x / (2.0 * c.rx) - c.delta + displacement(c, x, 0.0)


def gap_rolling_axis_slope(c: HertzContact, x: float) -> float:
    """``dg/dx`` [-] on the rolling centreline for ``x > b`` (the boundary term of Love's integral vanishes)."""
    a2, b2 = c.a * c.a, c.b * c.b
    lam = x * x - b2

    def integrand(t):
        s = lam + t * t
        return -4.0 * x / (b2 + s) / math.sqrt((a2 + s) * (b2 + s)) * (t / math.sqrt(s) if s > 0 else 1.0)

    return x / c.rx + c.p_max * c.a * c.b / c.e_prime * _quad_split(integrand, math.sqrt(a2 + lam))


def meniscus_position(c: HertzContact, h_inlet: float, m_max: float = 1e6, tol: float = 1e-12) -> float:
    """Meniscus position ``m = x_in / b`` where the dry gap equals the inlet film, ``g(m b) = h_inlet``.

    Newton–Raphson on ``g(m b) - h_inlet`` (the paper's Eq. 3), safeguarded by bisection; ``h_inlet``
    [m] is the oil layer the ball meets. Returns 1 for ``h_inlet <= 0``.
    """
    if h_inlet <= 0.0:
        return 1.0
    # start from the rigid estimate x^2/(2 Rx) ~ h_inlet + delta, bracket [b, x_hi]
    lo, hi = c.b, max(c.b * 1.0001, math.sqrt(2.0 * c.rx * (h_inlet + c.delta)) * 1.5)
    while gap_rolling_axis(c, hi) < h_inlet:
        hi *= 2.0
        if hi > m_max * c.b:
            return m_max
    x = min(max(math.sqrt(2.0 * c.rx * (h_inlet + c.delta)), lo * (1 + 1e-9)), hi)
    for _ in range(100):
        g = gap_rolling_axis(c, x) - h_inlet
        if g > 0:
            hi = x
        else:
            lo = x
        if abs(g) <= tol * h_inlet or (hi - lo) <= 1e-15 * hi:
            break
        dg = gap_rolling_axis_slope(c, x)
        xn = x - g / dg if dg > 0 else 0.5 * (lo + hi)
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        x = xn
    return x / c.b
