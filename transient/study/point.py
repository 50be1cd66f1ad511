"""Studies of the starved EHL point contact: the central film against the inlet layer (continuation in the layer
from the flooded solution), Chevalier et al.'s law fitted to it and Hamrock & Dowson's meniscus law at the computed
meniscus (:mod:`transient.analysis.starvation`), and the thrust ball bearing's films from the formula and from the
numerical contact.
"""

from __future__ import annotations

import math

import numpy as np

from transient.analysis.starvation import chevalier, fit_gamma, hd_meniscus_law
from transient.models.point import PointContact
from transient.physics import film_formulas as hd


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
            cols[k].append(v if ok or k in ("success", "newton") else (False if k == "flooded" else math.nan))
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
