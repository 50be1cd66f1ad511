"""Steady thermohydrodynamic (THD) journal film: the Elrod film with a per-cell viscosity
(:mod:`transient.models.journal.viscous_film`) and the energy equation (:mod:`transient.models.journal.thermal`),
solved alternately (Picard): the film at the viscosities of the last temperatures, the temperatures from that film's
flows and dissipation (each cell's dissipation following the viscosity of its new temperature:
:func:`heated_temperatures`), until the plain energy solve's temperatures change by less than
``ThermalFilm.tolerance`` [K]. The equilibrium
interleaves the same alternation with the Newton step on the journal position (its force sensitivities at frozen
temperatures), and stops when both the force balance and the temperatures have converged.

Also the thermal :class:`~transient.models.journal.results.FilmState`: the friction of the film at the cells'
viscosities, the temperatures, viscosities and heat flows.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.models.journal.film import film_geometry
from transient.models.journal.thermal import ENERGY_ORDERING, EnergyEquation
from transient.physics.lubricant import TEMPERATURE_RANGE_K, VOGEL

#: Alternations :func:`anderson` combines (measured in docs/validation.md, "Thermal films").
ANDERSON_DEPTH = 4
#: Largest change of a cell's temperature from one alternation to the next [K], a guard on Anderson's extrapolation:
#: a film solved at viscosities far off takes the chord Newton out of its range. (With the plain energy solve the
#: first temperatures overshot by 157 K at e/C = 0.9 and a 40 K limit was needed; :func:`heated_temperatures` does
#: not overshoot and a 40 K limit then costs two alternations there: docs/validation.md.)
MAX_STEP_K = 100.0
#: Newton iterations of :func:`heated_temperatures` at most (it stops at ``ThermalFilm.tolerance``).
HEATED_NEWTON_ITERATIONS = 8
#: ... or once its step is below this fraction of the largest change from the film's temperatures (an alternation
#: far from the fixed point needs no more).
HEATED_RELATIVE_TOLERANCE = 1e-2
#: Weight of the journal position against the temperatures in the equilibrium's mixing [K per unit of C].
POSITION_KELVIN = 100.0


class ThermalConvergenceError(RuntimeError):
    """The film and its temperatures did not settle in ``ThermalFilm.max_iterations`` alternations."""


def fluidity(film, thermal, temperature, reference_viscosity, pressure=True):
    """``mu_ref / mu(T_i, p_i)`` per cell: the cells' viscosities at their temperatures and, for a law with a
    pressure-viscosity coefficient and ``pressure=True``, at the film's last pressures above the cavitation
    pressure (``film.P``)."""
    law = thermal.law
    p = film.p0 * np.maximum(film.P, 0.0) if pressure and law.pressure_viscosity > 0.0 else 0.0
    return reference_viscosity / thermal.viscosity(temperature, p)


def update_fluidity(film, thermal, temperature, reference_viscosity) -> bool:
    """Set the film's fluidity from the temperatures (and pressures); True if it changed."""
    new = fluidity(film, thermal, temperature, reference_viscosity)
    changed = not np.array_equal(new, film.fluidity)
    film.fluidity[:] = new
    return changed


def _start(film, thermal, reference_viscosity):
    """Supply temperature everywhere, its viscosity in the film (at zero pressure: no film solved yet)."""
    T = np.full(film.n, thermal.supply_temperature)
    film.fluidity[:] = fluidity(film, thermal, T, reference_viscosity, pressure=False)
    return T


def anderson(inputs, outputs, low, high):
    """The next input of the fixed-point iteration ``T -> G(T)`` by Anderson mixing (Walker & Ni, SIAM J. Numer.
    Anal. 49, 2011) over the iterates kept in ``inputs``, ``outputs`` (oldest first): the combination of the
    outputs whose residuals ``G(T) - T`` combine to the least-squares smallest, clipped to [low, high] (the
    temperatures a viscosity law may be asked about); plain Picard (the last output) with one iterate."""
    g = outputs[-1]
    if len(inputs) < 2:
        return g
    F = np.array([o - i for i, o in zip(inputs, outputs)])
    dF = np.diff(F, axis=0).T
    dG = np.diff(np.array(outputs), axis=0).T
    gamma = np.linalg.lstsq(dF, F[-1], rcond=None)[0]
    return np.clip(g - dG @ gamma, low, high)


def viscosity_slope(law, temperature):
    """``d ln mu / dT`` [1/K] of a temperature law at ``temperature`` [K] (the Barus factor does not depend on T)."""
    code, _, b, c = law.kernel_args()
    if code == VOGEL:
        return -b / (temperature - c) ** 2
    return np.full(np.shape(temperature), -b)


def heated_temperatures(energy, r, temperature, low, high):
    """The temperatures of the film's rates ``r`` (solved at the cells' ``temperature`` [K]) with each cell's
    dissipation following the viscosity of its new temperature, ``Phi_i mu(T'_i) / mu(T_i)``: at a fixed film shape
    the Couette shear goes like mu, and the film's pressures, so the Poiseuille dissipation, do too. Newton on the
    energy equations with the dissipation's slope ``-Phi_i d ln mu / dT >= 0`` added to the free cells' diagonal
    (still an M-matrix), from ``temperature``, to ``ThermalFilm.tolerance`` or ``HEATED_RELATIVE_TOLERANCE`` of the
    change, every iterate clipped to [low, high].
    Where ``T' = T`` the equations are the plain ones: the alternation's fixed point is the same THD film, but the
    alternation's strongest feedback -- hotter oil, thinner oil, less heat -- is taken inside each temperature solve
    (the first temperatures from the film at the supply viscosity no longer overshoot: docs/validation.md).
    Returns the cells' and the feeds' temperatures."""
    th, film = energy.thermal, energy.film
    n, free = film.n, energy.free
    law = th.law
    mu = law.at(temperature)
    scale = energy.power_unit / energy.heat_unit
    x = np.concatenate([temperature, np.full(energy.n_feeds, th.supply_temperature)])
    tol = th.tolerance
    for _ in range(HEATED_NEWTON_ITERATIONS):
        T = x[:n]
        source = r.source * law.at(T) / mu
        A, rhs = energy.system(r._replace(source=source))
        slope = np.where(free, -scale * source * viscosity_slope(law, T), 0.0)
        J = A + sp.diags(np.concatenate([slope, np.zeros(energy.n_feeds)]), format="csc")
        dx = spla.splu(J, permc_spec=ENERGY_ORDERING).solve(rhs - A @ x)
        x = np.clip(x + dx, low, high)
        step = np.max(np.abs(dx[:n]))
        tol = max(tol, HEATED_RELATIVE_TOLERANCE * float(np.max(np.abs(x[:n] - temperature))))
        if step <= tol:
            break
    return x


def steady(bearing, film, X, Y):
    """The steady THD film at (X, Y): ``(u, newton iterations, EnergyBalance, alternations)``. Each alternation
    solves the film at the last temperatures' viscosities (chord Newton from the last film), then the temperatures
    (:func:`heated_temperatures`);
    the next temperatures by :func:`anderson` over the last ``ANDERSON_DEPTH`` alternations."""
    th = bearing.thermal
    energy = EnergyEquation(film, th)
    T = _start(film, th, bearing.viscosity)
    low = min(th.supply_temperature, th.wall()[2])
    u, its, _ = bearing.film_solve(film, X, Y)
    inputs, outputs = [], []
    for k in range(th.max_iterations):
        film.residual(u, X, Y)  # the cell fields of the state
        r = energy.rates()
        balance = energy.solve_rates(r)
        change = float(np.max(np.abs(balance.temperature - T)))
        if change <= th.tolerance:
            return u, its, balance, k + 1
        heated = heated_temperatures(energy, r, T, low, TEMPERATURE_RANGE_K[1])[:film.n]
        inputs, outputs = (inputs + [T])[-ANDERSON_DEPTH:], (outputs + [heated])[-ANDERSON_DEPTH:]
        T = np.clip(anderson(inputs, outputs, low, TEMPERATURE_RANGE_K[1]), T - MAX_STEP_K, T + MAX_STEP_K)
        if not update_fluidity(film, th, T, bearing.viscosity):  # an isoviscous oil: the film is the same
            return u, its, energy.solve(u, X, Y), k + 1
        u, n = film.solve(X, Y, u0=u, chord=True)
        its += n
    raise ThermalConvergenceError(f"the THD film at X={X:.4g}, Y={Y:.4g} did not settle in {th.max_iterations} "
                                  f"alternations (last temperature change {change:.3g} K)")


def equilibrium(bearing, film, wbar, tol, max_iter, start):
    """The THD equilibrium under the dimensionless load ``wbar``: ``(u, (X, Y), iterations, (dF/dq, dF/dv),
    EnergyBalance)``, or None if it did not converge. One fixed-point map of position and temperatures: the film at
    the position and the temperatures' viscosities, then the Newton step on the position (force sensitivities at
    frozen temperatures) and the temperatures of that film; :func:`anderson` over both (the position in units of
    ``POSITION_KELVIN`` [K per C], so that both weigh alike), ``max_iter`` plus ``ThermalFilm.max_iterations`` film
    solves at most."""
    th = bearing.thermal
    energy = EnergyEquation(film, th)
    T = _start(film, th, bearing.viscosity)
    q = np.array([0.3, 0.3] if start is None else start, dtype=float)
    reach = bearing._reach * bearing.max_eccentricity_ratio
    low = np.concatenate([[-np.inf, -np.inf], np.full(film.n, min(th.supply_temperature, th.wall()[2]))])
    high = np.concatenate([[np.inf, np.inf], np.full(film.n, TEMPERATURE_RANGE_K[1])])
    inputs, outputs = [], []
    u = None
    for it in range(max_iter + th.max_iterations):
        u = bearing.film_solve(film, q[0], q[1])[0] if u is None else film.solve(q[0], q[1], u0=u, chord=True)[0]
        F, dF_dq, dF_dv = film.force_sensitivity(u, q[0], q[1])
        film.residual(u, q[0], q[1])  # the cell fields of the state
        rates = energy.rates()
        balance = energy.solve_rates(rates)
        change = float(np.max(np.abs(balance.temperature - T)))
        r = np.array([F[0] + wbar, F[1]])
        if np.max(np.abs(r)) <= tol * max(wbar, 1e-300) and change <= th.tolerance:
            return u, q, it, (dF_dq, dF_dv), balance
        dq = -np.linalg.solve(dF_dq, r)
        lam = 1.0  # keep the journal inside the clearance
        while np.hypot(*(q + lam * dq)) >= reach:
            lam *= 0.5
        x = np.concatenate([q * POSITION_KELVIN, T])
        heated = heated_temperatures(energy, rates, T, low[2], high[2])[:film.n]
        g = np.concatenate([(q + lam * dq) * POSITION_KELVIN, heated])
        inputs, outputs = (inputs + [x])[-ANDERSON_DEPTH:], (outputs + [g])[-ANDERSON_DEPTH:]
        nxt = anderson(inputs, outputs, low, high)
        q_next = nxt[:2] / POSITION_KELVIN
        if np.hypot(*q_next) >= reach:  # mixing left the clearance: the plain step, and start the mixing afresh
            nxt, inputs, outputs = g, [], []
            q_next = nxt[:2] / POSITION_KELVIN
        q, T = q_next, nxt[2:]
        update_fluidity(film, th, T, bearing.viscosity)
    return None


def thermal_state(bearing, film, u, X, Y, iterations, balance, alternations):
    """The :class:`~transient.models.journal.results.FilmState` of a THD film: the isothermal state's fields with
    the friction at the cells' viscosities ``mu_i = mu_ref / f_i`` (``tau(0) = -mu_i U / h - (h/2) dp/ds``, a
    cavitated cell shearing its content fraction), the temperatures and the heat flows."""
    state = film.state(u, X, Y, iterations)
    s, grid = film.scales, film.grid
    mu = grid.to_2d(bearing.viscosity / film.fluidity)
    h, G, _ = film_geometry(film, X, Y, film.P)
    U = s.omega * s.radius
    lower = -mu * U / h - 0.5 * h * G
    upper = lower + G * h
    weight = s.sym * np.minimum(grid.to_2d(film.C), 1.0) * grid.to_2d(film.area) * s.radius ** 2
    friction, bearing_friction = float(-np.sum(lower * weight)), float(-np.sum(upper * weight))
    return dataclasses.replace(
        state, friction_force=friction, bearing_friction_force=bearing_friction,
        friction_torque=s.radius * friction, temperature=grid.to_2d(balance.temperature).copy(),
        viscosity_field=mu.copy(), mixing_temperature=balance.mixing_temperature,
        outlet_temperature=balance.outlet_temperature, dissipation=balance.dissipation,
        heat_convected=balance.convected, heat_conducted=balance.conducted, thermal_iterations=alternations)
