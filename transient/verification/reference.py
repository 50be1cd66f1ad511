"""Closed-form reference solutions of the Reynolds equation (for verification).

Journal conventions (a, b): film ``h = C (1 + eps cos theta)``, theta measured from the *maximum* film
(the minimum film is at theta = pi), the journal surface moves with speed ``U = omega R`` in the +theta
direction, the bearing is stationary. Reynolds (x = R theta)::

    d/dx (h^3/(12 mu) dp/dx) + d/dz (h^3/(12 mu) dp/dz) = (U/2) dh/dx

Force components on the journal in the (theta = 0, theta = pi/2) frame::

    Fx = -int int p cos(theta) R dtheta dz,     Fy = -int int p sin(theta) R dtheta dz

``Fx`` is the component along the line of centres (positive towards the maximum film, theta = 0) and
``Fy`` the component perpendicular to it (positive towards theta = pi/2). Any consistent unit system.
"""

from __future__ import annotations

import numpy as np


def _check_eps(eps):
    if not (0.0 <= eps < 1.0):
        raise ValueError(f"eps (eccentricity ratio) must be in [0, 1), got {eps!r}")


# --------------------------------------------------------------------------------------------------
# (a) infinitely long bearing, full Sommerfeld solution
# --------------------------------------------------------------------------------------------------

def sommerfeld_pressure(theta, eps, mu, U, R, C):
    """Full-Sommerfeld pressure of the infinitely long journal bearing, ``p(0) = 0``::

        p(theta) = 6 mu U R / C^2 * eps sin(theta) (2 + eps cos theta) / ((2 + eps^2) (1 + eps cos theta)^2)

    Solution of ``d/dtheta(h^3 dp/dtheta) = 6 mu U R dh/dtheta`` with periodic p (Sommerfeld 1904;
    e.g. Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*, 2nd ed., ch. 10, with
    ``U = omega R``).
    """
    _check_eps(eps)
    theta = np.asarray(theta, dtype=float)
    c = np.cos(theta)
    return 6.0 * mu * U * R / C**2 * eps * np.sin(theta) * (2.0 + eps * c) / ((2.0 + eps**2) * (1.0 + eps * c) ** 2)


def sommerfeld_force(eps, mu, U, R, C, L=1.0):
    """Force components (Fx, Fy) of the full-Sommerfeld film over an axial length ``L``::

        Fx = 0,    Fy = -12 pi mu U R^2 L eps / (C^2 (2 + eps^2) sqrt(1 - eps^2))

    (Hamrock et al., ch. 10: ``w = 12 pi eta omega r^3 l eps / (c^2 (2 + eps^2)(1 - eps^2)^(1/2))``.)
    """
    _check_eps(eps)
    return 0.0, -12.0 * np.pi * mu * U * R**2 * L * eps / (C**2 * (2.0 + eps**2) * np.sqrt(1.0 - eps**2))


# --------------------------------------------------------------------------------------------------
# (b) short (Ocvirk) bearing
# --------------------------------------------------------------------------------------------------

def short_bearing_pressure(theta, z, eps, mu, U, R, C, L):
    """Short-bearing (Ocvirk, 1952) pressure; ``z`` from the mid-plane, ``p = 0`` at ``z = +-L/2``::

        p = 3 mu U / (R C^2) * (L^2/4 - z^2) * eps sin(theta) / (1 + eps cos theta)^3

    Derivation: dropping the circumferential Poiseuille term, ``h^3/(12 mu) p_zz = (U/2) dh/dx`` with
    ``dh/dx = -C eps sin(theta) / R`` integrates to the parabola above. Negative pressures kept.
    """
    _check_eps(eps)
    theta = np.asarray(theta, dtype=float)
    z = np.asarray(z, dtype=float)
    return 3.0 * mu * U / (R * C**2) * (0.25 * L**2 - z**2) * eps * np.sin(theta) / (1.0 + eps * np.cos(theta)) ** 3


def short_bearing_force(eps, mu, U, C, L, film: str = "full"):
    """Short-bearing force components (Fx, Fy), ``U = omega R`` the journal surface speed.

    With ``int (L^2/4 - z^2) dz = L^3/6`` the forces are ``-(mu U eps L^3 / (2 C^2)) (I_c, I_s)``,
    ``I_c = int sin cos / (1 + eps cos)^3``, ``I_s = int sin^2 / (1 + eps cos)^3``:

    * ``film="full"`` (2 pi film, negative pressures kept): ``I_c = 0``, ``I_s = pi/(1 - eps^2)^(3/2)``::

          Fx = 0,   Fy = -pi mu U L^3 eps / (2 C^2 (1 - eps^2)^(3/2))

    * ``film="half"`` (half-Sommerfeld, pressure kept on 0 < theta < pi only):
      ``I_c = -2 eps/(1 - eps^2)^2``, ``I_s = pi/(2 (1 - eps^2)^(3/2))``::

          Fx = mu U L^3 eps^2 / (C^2 (1 - eps^2)^2),   Fy = -pi mu U L^3 eps / (4 C^2 (1 - eps^2)^(3/2))

    (Ocvirk 1952; Hamrock et al. ch. 11 with ``u_b = omega r``.) The radius cancels.
    """
    _check_eps(eps)
    k = mu * U * L**3 / C**2
    if film == "full":
        return 0.0, -np.pi * k * eps / (2.0 * (1.0 - eps**2) ** 1.5)
    if film == "half":
        return k * eps**2 / (1.0 - eps**2) ** 2, -np.pi * k * eps / (4.0 * (1.0 - eps**2) ** 1.5)
    raise ValueError(f"film must be 'full' or 'half', got {film!r}")


# --------------------------------------------------------------------------------------------------
# (c) squeeze film between parallel rectangular plates
# --------------------------------------------------------------------------------------------------

def squeeze_rect_load(a, b, h, dhdt, mu, n_terms: int = 200):
    """Load ``W = int p dA`` of the squeeze film between parallel plates ``a x b`` (all edges at p = 0).

    Poisson problem ``div(h^3/(12 mu) grad p) = dh/dt``, i.e. ``lap p = -G``, ``G = -12 mu dh/dt / h^3``.
    Writing ``p = (G/2) x (a - x) + psi`` with harmonic ``psi`` cancelling ``p`` on ``y = 0, b``::

        psi = -(G/2) sum_{n odd} 8 a^2/(pi^3 n^3) sin(n pi x/a) cosh(n pi (y - b/2)/a) / cosh(n pi b/(2a))

    and integrating (``int sin = 2a/(n pi)``, ``int cosh = (2a/(n pi)) sinh(n pi b/(2a))``)::

        W = -mu a^3 b dh/dt / h^3 * [1 - 192 a/(pi^5 b) sum_{n=1,3,5,...} tanh(n pi b/(2a)) / n^5]

    This is the rectangular torsion-function integral (Timoshenko & Goodier, *Theory of Elasticity*,
    sec. 109: ``J = (a^3 b/3)[1 - 192 a/(pi^5 b) sum tanh(n pi b/2a)/n^5]``, ``W = G J / 4``). For
    ``b >> a`` it tends to the infinite strip ``W = mu b a^3 V / h^3`` with ``V = -dh/dt``. The series
    error after ``n_terms`` odd terms is below ``(192 a/(pi^5 b)) / (4 (2 n_terms)^4)``.
    """
    for name, v in (("a", a), ("b", b), ("h", h), ("mu", mu)):
        if not (np.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be finite and > 0, got {v!r}")
    n = 2.0 * np.arange(int(n_terms)) + 1.0
    s = np.sum(np.tanh(n * np.pi * b / (2.0 * a)) / n**5)
    return -mu * a**3 * b * dhdt / h**3 * (1.0 - 192.0 * a / (np.pi**5 * b) * s)


def squeeze_rect_pressure(x, y, a, b, h, dhdt, mu, n_terms: int = 200):
    """Pressure of :func:`squeeze_rect_load` at ``(x, y)`` in ``[0, a] x [0, b]`` (same series)."""
    x = np.asarray(x, dtype=float)[..., None]
    y = np.asarray(y, dtype=float)[..., None]
    G = -12.0 * mu * dhdt / h**3
    n = 2.0 * np.arange(int(n_terms)) + 1.0
    arg = n * np.pi / a
    # cosh(arg (y - b/2)) / cosh(arg b/2), written without overflow
    t = np.abs(y - 0.5 * b)
    ratio = np.exp(arg * (t - 0.5 * b)) * (1.0 + np.exp(-2.0 * arg * t)) / (1.0 + np.exp(-arg * b))
    psi = -np.sum(8.0 * a**2 / (np.pi**3 * n**3) * np.sin(arg * x) * ratio, axis=-1)
    return 0.5 * G * (x[..., 0] * (a - x[..., 0]) + psi)
