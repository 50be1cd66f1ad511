"""Central film of elliptic EHL contacts by Nijenbanning, Venner & Moes (*Wear* 176, 217-229, 1994: "Film
thickness in elastohydrodynamically lubricated elliptic contacts"), the reference the numerical point
contact is checked against over Moes' chart.

Moes' groups with the mean entraining speed ``u`` (``2U`` = the sum-speed group), ``D = Rx/Ry``::

    M = W (2U)^-3/4,   L = G (2U)^1/4,   H = (h_c/Rx) (2U)^-1/2,   U = eta0 u/(E' Rx), W = w/(E' Rx^2), G = alpha E'

The four asymptotes (rigid-isoviscous, elastic-isoviscous, rigid-piezoviscous, elastic-piezoviscous)::

    H_RI = 145 (1 + 0.796 D^(14/15))^(-15/7) D^-1 M^-2
    H_EI = 3.18 (1 + 0.006 ln D + 0.63 D^(4/7))^(-14/25) D^(-1/15) M^(-2/15)
    H_RP = 1.29 (1 + 0.691 D)^(-2/3) L^(2/3)
    H_EP = 1.48 (1 + 0.006 ln D + 0.63 D^(4/7))^(-7/20) D^(-1/24) M^(-1/12) L^(3/4)

blended as::

    H = { [H_RI^(3/2) + (H_EI^-4 + H_00^-4)^(-3/8)]^(2s/3) + (H_RP^-8 + H_EP^-8)^(-s/8) }^(1/s)
    s = 1.5 (1 + exp(-1.2 H_EI/H_RI)),   H_00 = 1.8 D^-1

Transcribed from a secondary rendering of the paper (the paper itself was not at hand, so neither the
constants nor the formula's stated accuracy were checked against it). The term ``H_00`` bounds the
elastic-isoviscous asymptote; it lowers ``H`` by 0.1-4 % for ``M >= 20``, ``L >= 5`` (most at small M and L).
"""

from __future__ import annotations

import math


def nvm_asymptotes(M: float, L: float, D: float = 1.0) -> dict:
    """The four asymptotes ``{"RI", "EI", "RP", "EP"}`` of the dimensionless central film (module docstring)."""
    c = 1.0 + 0.006 * math.log(D) + 0.63 * D ** (4.0 / 7.0)
    return dict(RI=145.0 * (1.0 + 0.796 * D ** (14.0 / 15.0)) ** (-15.0 / 7.0) / D * M ** -2.0,
                EI=3.18 * c ** (-14.0 / 25.0) * D ** (-1.0 / 15.0) * M ** (-2.0 / 15.0),
                RP=1.29 * (1.0 + 0.691 * D) ** (-2.0 / 3.0) * L ** (2.0 / 3.0),
                EP=1.48 * c ** (-7.0 / 20.0) * D ** (-1.0 / 24.0) * M ** (-1.0 / 12.0) * L ** 0.75)


def nvm_central(M: float, L: float, D: float = 1.0, bound_ei: bool = True) -> float:
    """Nijenbanning-Venner-Moes central film ``H = (h_c/Rx) (2U)^-1/2`` (module docstring); ``bound_ei``:
    with the term ``H_00`` (False: without it, to measure its weight)."""
    a = nvm_asymptotes(M, L, D)
    s = 1.5 * (1.0 + math.exp(-1.2 * a["EI"] / a["RI"]))
    ei = (a["EI"] ** -4 + (1.8 / D) ** -4) ** -0.25 if bound_ei else a["EI"]
    iso = (a["RI"] ** 1.5 + ei ** 1.5) ** (2.0 * s / 3.0)
    piezo = (a["RP"] ** -8 + a["EP"] ** -8) ** (-s / 8.0) if L > 0 else 0.0
    return (iso + piezo) ** (1.0 / s)


def nvm_central_film(load: float, speed: float, viscosity: float, pressure_viscosity: float, modulus: float,
                     radius_x: float, radius_y: float | None = None) -> float:
    """The central film [m] of :func:`nvm_central` in SI (``speed`` the mean entraining speed)."""
    ry = radius_x if radius_y is None else radius_y
    two_u = 2.0 * viscosity * speed / (modulus * radius_x)
    M = load / (modulus * radius_x ** 2) * two_u ** -0.75
    L = pressure_viscosity * modulus * two_u ** 0.25
    return nvm_central(M, L, radius_x / ry) * radius_x * math.sqrt(two_u)
