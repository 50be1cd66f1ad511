"""Studies of the starved EHL point contact: the central film against the inlet layer (continuation in the layer
from the flooded solution), Chevalier's law fitted to it, Hamrock & Dowson's meniscus law at the computed
meniscus, and the thrust ball bearing's films from the formula and from the numerical contact.

Chevalier, Lubrecht, Cann, Colin & Dalmaz ("Film thickness in starved EHL point contacts", *J. Tribol.* 120,
1998): the central film of a contact fed by a uniform layer ``h_oil`` is a function of one ratio,

    h_c / h_c,ff = r / (1 + r^gamma)^(1/gamma),   r = h_oil / (rho_c h_c,ff)

(``rho_c`` the density at the centre relative to the layer's: all the oil of a thin layer passes through the
Hertz zone, ``rho_c h_c -> h_oil``; a thick one floods it, ``h_c -> h_c,ff``), ``gamma`` the one parameter of the
contact (fitted here, :func:`fit_gamma`). Hamrock & Dowson (*J. Lubr. Technol.* 99, 1977) instead relate the film
to the meniscus distance ``m``: ``h_c = h_c,ff ((m - 1)/(m_c - 1))^0.29`` below ``m_c``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import minimize_scalar

from transient.models.point import PointContact
from transient.physics import film_formulas as hd


def chevalier(r, gamma: float):
    """Chevalier et al.'s starved central film ``h_c/h_c,ff = r/(1 + r^gamma)^(1/gamma)`` at ``r`` (module
    docstring)."""
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


def layer_sweep(ratios, **contact) -> dict:
    """The starved point contact ``PointContact(**contact)`` at inlet layers ``ratio x`` its flooded central
    film, thickest first, each from the previous solution (:meth:`PointContact.steady` with ``initial``).

    Returns a dict of arrays over ``ratio`` (``h_oil/h_c,ff``): ``h_central``, ``h_min``, ``m`` (the computed
    meniscus distance), ``success``, ``flooded`` (meniscus at the domain's inlet), ``newton`` (iterations) and
    the flooded ``h_c_ff``, ``h_min_ff``, ``rho_c`` (density at the flooded centre), ``m_c`` (Hamrock-Dowson's
    critical meniscus), ``moes`` (M, L), ``contact`` (the flooded :class:`PointContact`), ``flooded_result``,
    ``results`` (the starved solutions, None where not converged)."""
    pc = PointContact(**contact)
    f = pc.steady()
    jc, ic = f.y.size // 2, int(np.argmin(np.abs(f.x)))
    rho_c = float(pc.lubricant.rho(f.pressure[jc, ic])[0])
    ratios = np.sort(np.asarray(ratios, float))[::-1]
    cols = {k: [] for k in ("h_central", "h_min", "m", "success", "flooded", "newton")}
    results, prev = [], f
    for R in ratios:
        s = PointContact(**dict(contact, inlet_film=float(R * f.h_central))).steady(initial=prev,
                                                                                   raise_on_failure=False)
        ok = bool(s.success)
        for k, v in (("h_central", s.h_central), ("h_min", s.h_min), ("m", s.m), ("success", ok),
                     ("flooded", bool(s.flooded_inlet)), ("newton", s.iterations)):
            cols[k].append(v if ok or k in ("success", "newton") else math.nan)
        results.append(s if ok else None)
        prev = s if ok else prev
    out = {k: np.array(v) for k, v in cols.items()}
    out.update(ratio=ratios, h_c_ff=f.h_central, h_min_ff=f.h_min, rho_c=rho_c, m_c=pc.m_c, moes=pc.moes,
               contact=pc, flooded_result=f, results=results)
    return out


def chevalier_check(sweep: dict) -> dict:
    """Chevalier's law fitted to a :func:`layer_sweep` (its converged, starved points): ``gamma``, the largest
    relative deviation, ``r`` and the computed and fitted ``h_c/h_c,ff``; Hamrock & Dowson's law at the computed
    meniscus beside it (``hd_law``, with ``m`` and ``m_c``)."""
    ok = sweep["success"] & ~sweep["flooded"]
    r = sweep["ratio"][ok] / sweep["rho_c"]
    y = sweep["h_central"][ok] / sweep["h_c_ff"]
    g, dev = fit_gamma(r, y)
    return dict(gamma=g, max_deviation=dev, r=r, film=y, law=chevalier(r, g), m=sweep["m"][ok], m_c=sweep["m_c"],
                hd_law=hd_meniscus_law(sweep["m"][ok], sweep["m_c"]))


def ball_films(bearing, load: float, speed_rpm: float, inlet_films) -> dict:
    """One ball pass of ``bearing`` at the inlet films ``inlet_films`` [m] (thickest first), its central film by
    the formula (Hamrock-Dowson with the 0.29 law at the dry-gap meniscus, the paper's) and by the numerical
    starved point contact (on ``bearing.contact_grid``), each relative to its own flooded film.

    Returns a dict of arrays: ``h_in``, ``m`` (the dry-gap meniscus), ``formula``, ``numerical`` (``h_c/h_c,ff``),
    ``numerical_h`` [m] and ``formula_h`` [m], the flooded films ``hd_central`` and ``numerical_ff`` [m], Moes'
    ``M`` and Hamrock-Dowson's ``m_c``."""
    from transient.models.ball.numerical_film import NumericalFilms
    from transient.physics.hertz import meniscus_position

    c = bearing.hertz(load)
    ff = bearing.flooded_film(load, speed_rpm)
    films = NumericalFilms(bearing, c, ff.speed, bearing.contact_grid)
    h_in = np.sort(np.asarray(inlet_films, float))[::-1]
    m = np.array([meniscus_position(c, h) for h in h_in])
    formula = np.array([hd.starved_central_film(ff.H_c, v, ff.m_c) * c.rx for v in m])
    numerical = np.array([films(h, i)[0] for i, h in enumerate(h_in)])
    return dict(h_in=h_in, m=m, formula_h=formula, numerical_h=numerical, formula=formula / ff.h_c,
                numerical=numerical / films.flooded.h_central, hd_central=ff.h_c,
                numerical_ff=films.flooded.h_central, M=ff.W * (2.0 * ff.U) ** -0.75, m_c=ff.m_c)
