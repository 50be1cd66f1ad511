"""Hamrock–Dowson film formulas for elliptical EHL contacts, fully flooded and starved.

Dimensionless groups (Hamrock & Dowson 1977, *J. Lubr. Technol.* 99, 264-276; Hamrock & Dowson,
*Ball Bearing Lubrication*, 1981), with ``u`` the mean entraining speed, ``eta0`` the ambient
viscosity, ``alpha`` the pressure–viscosity coefficient, ``w`` the load per contact::

    U = eta0 u / (E' Rx),   G = alpha E',   W = w / (E' Rx^2),   H = h / Rx

Fully flooded (high elastic modulus, "hard EHL"), used by the paper (Jeong et al., Eq. 5)::

    H_c   = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k))       central
    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k))            minimum

Starvation (Hamrock & Dowson 1977, *J. Lubr. Technol.* 99, 15-23; Jeong et al. Eqs. 1, 4), with the
inlet meniscus at ``m = x_in / b`` (b the semi-axis along the rolling direction)::

    m_c   = 1 + 3.06 ((Rx/b)^2 H_c)^0.58          critical meniscus, central film
    m_min = 1 + 3.34 ((Rx/b)^2 H_min)^0.56        critical meniscus, minimum film
    H_c,s   = H_c   ((m - 1)/(m_c - 1))^0.29      for m < m_c
    H_min,s = H_min ((m - 1)/(m_min - 1))^0.25    for m < m_min
"""

from __future__ import annotations

import math


def dimensionless_groups(viscosity: float, speed: float, pressure_viscosity: float, load: float,
                         e_prime: float, rx: float) -> tuple[float, float, float]:
    """``(U, G, W)`` for viscosity [Pa s], entraining speed [m/s], alpha [1/Pa], load [N], E' [Pa], Rx [m]."""
    return (viscosity * speed / (e_prime * rx), pressure_viscosity * e_prime, load / (e_prime * rx * rx))


def central_film_flooded(U: float, G: float, W: float, k: float) -> float:
    """Hamrock–Dowson fully flooded dimensionless central film ``H_c = h_c / Rx``."""
    return 2.69 * U ** 0.67 * G ** 0.53 * W ** -0.067 * (1.0 - 0.61 * math.exp(-0.73 * k))


def minimum_film_flooded(U: float, G: float, W: float, k: float) -> float:
    """Hamrock–Dowson fully flooded dimensionless minimum film ``H_min = h_min / Rx``."""
    return 3.63 * U ** 0.68 * G ** 0.49 * W ** -0.073 * (1.0 - math.exp(-0.68 * k))


def critical_meniscus_central(H_c: float, rx: float, b: float) -> float:
    """Critical inlet meniscus ``m_c = 1 + 3.06 ((Rx/b)^2 H_c)^0.58`` for the central film."""
    return 1.0 + 3.06 * ((rx / b) ** 2 * H_c) ** 0.58


def critical_meniscus_minimum(H_min: float, rx: float, b: float) -> float:
    """Critical inlet meniscus ``m* = 1 + 3.34 ((Rx/b)^2 H_min)^0.56`` for the minimum film."""
    return 1.0 + 3.34 * ((rx / b) ** 2 * H_min) ** 0.56


def _starved(H_flooded: float, m: float, m_limit: float, exponent: float) -> float:
    """``H_flooded ((m-1)/(m_limit-1))^exponent`` for 1 < m < m_limit, ``H_flooded`` above, 0 at m <= 1."""
    if m >= m_limit:
        return H_flooded
    if m <= 1.0:
        return 0.0
    return H_flooded * ((m - 1.0) / (m_limit - 1.0)) ** exponent


def starved_central_film(H_flooded: float, m: float, m_c: float) -> float:
    """Starved central film ``H_F ((m-1)/(m_c-1))^0.29`` for ``m < m_c`` (``H_F`` otherwise; 0 at m <= 1)."""
    return _starved(H_flooded, m, m_c, 0.29)


def starved_minimum_film(H_flooded: float, m: float, m_star: float) -> float:
    """Starved minimum film ``H_min ((m-1)/(m*-1))^0.25`` for ``m < m*``."""
    return _starved(H_flooded, m, m_star, 0.25)
