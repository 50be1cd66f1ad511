"""Starvation laws of EHL point contacts, to compare computed starved films with.

Chevalier, Lubrecht, Cann, Colin & Dalmaz ("Film thickness in starved EHL point contacts", *J. Tribol.* 120,
1998): the central film of a contact fed by a uniform layer ``h_oil`` is a function of one ratio,

    h_c / h_c,ff = r / (1 + r^gamma)^(1/gamma),   r = h_oil / (rho_c h_c,ff)

(``rho_c`` the density at the centre relative to the layer's: all the oil of a thin layer passes through the
Hertz zone, ``rho_c h_c -> h_oil``; a thick one floods it, ``h_c -> h_c,ff``), ``gamma`` the one parameter of the
contact (:func:`fit_gamma`). Hamrock & Dowson (*J. Lubr. Technol.* 99, 1977) relate the film to the meniscus
distance ``m`` instead: ``h_c = h_c,ff ((m - 1)/(m_c - 1))^0.29`` below ``m_c``.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import minimize_scalar

from transient.physics import film_formulas as hd


def chevalier(r, gamma: float):
    """Chevalier et al.'s starved central film ``h_c/h_c,ff = r/(1 + r^gamma)^(1/gamma)`` at ``r``."""
    r = np.asarray(r, float)
    return r / (1.0 + r ** gamma) ** (1.0 / gamma)


def fit_gamma(r, film_ratio) -> tuple[float, float]:
    """``(gamma, largest |relative deviation|)`` of Chevalier's law fitted to the films ``h_c/h_c,ff`` at
    ``r`` by least squares on the logarithm."""
    r, y = np.asarray(r, float), np.asarray(film_ratio, float)
    cost = lambda g: float(np.sum(np.log(chevalier(r, g) / y) ** 2))
    g = float(minimize_scalar(cost, bounds=(0.3, 20.0), method="bounded", options=dict(xatol=1e-6)).x)
    return g, float(np.max(np.abs(chevalier(r, g) / y - 1.0)))


def hd_meniscus_law(m, m_c: float):
    """Hamrock & Dowson's ``((m - 1)/(m_c - 1))^0.29`` (0 at m <= 1, 1 at m >= m_c)."""
    return np.array([hd.starved_central_film(1.0, float(v), m_c) for v in np.atleast_1d(m)])
