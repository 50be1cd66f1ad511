"""The thermal (THD) journal film: isothermal limit, energy balance, monotone temperatures, mixing, refusals
(models/journal/thermal.py, thd.py, viscous_film.py, thermal_settings.py)."""

import re
from dataclasses import replace

import numpy as np
import pytest

from transient import BushConvection, IsothermalShaft, JournalBearing, ThermalFilm
from transient.models.journal import thd
from transient.models.journal.thermal import EnergyEquation, energy_system
from transient.models.journal.viscous_film import ViscousFilm

GEOMETRY = dict(diameter=0.1, length=0.05, clearance=1e-4)
OIL = ThermalFilm(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
                  heat_capacity=1950.0)
GRID = (40, 6)
SPEED = 3000.0


def thermal_bearing(thermal=OIL, grid=GRID, **kw):
    return JournalBearing(**GEOMETRY, viscosity=kw.pop("viscosity", None), grid=grid, thermal=thermal, **kw)


def test_zero_temperature_coefficient_is_the_isothermal_film():
    mu = 0.02
    iso = JournalBearing(**GEOMETRY, viscosity=mu, grid=GRID)
    flat = replace(OIL, viscosity_at=((320.0, mu), (350.0, mu)))
    hot = thermal_bearing(flat, viscosity=mu)
    a, b = iso.steady_state(0.6, SPEED, 10.0), hot.steady_state(0.6, SPEED, 10.0)
    assert np.max(np.abs(b.pressure - a.pressure)) <= 1e-12 * np.max(a.pressure)
    assert np.allclose(b.force, a.force, rtol=1e-12, atol=0)
    assert b.friction_torque == pytest.approx(a.friction_torque, rel=1e-12)
    assert np.all(b.viscosity_field == mu)
    assert b.max_temperature > OIL.supply_temperature  # the temperatures are still solved
    # the equilibrium and its coefficients: both converge to the same force balance (1e-10 of the load)
    Ka, Ca = iso.coefficients(2000.0, SPEED)
    Kb, Cb = hot.coefficients(2000.0, SPEED)
    assert np.allclose(Kb, Ka, rtol=1e-7, atol=1e-7 * np.abs(Ka).max())
    assert np.allclose(Cb, Ca, rtol=1e-7, atol=1e-7 * np.abs(Ca).max())


@pytest.mark.parametrize("boundary", ["adiabatic", BushConvection(2000.0), IsothermalShaft()])
def test_friction_power_leaves_as_heat(boundary):
    """Shaft power plus the supply's flow work = heat carried out by the oil + heat to the walls (1 %); the discrete
    equations conserve the dissipation exactly."""
    b = thermal_bearing(replace(OIL, boundary=boundary), grid=(60, 10))
    s = b.steady_state(0.6, SPEED)
    pump = float(np.sum((b.feed_pressures - b.ambient_pressure) * s.supply_flow))
    heat = s.heat_convected + s.heat_conducted
    assert s.power_loss + pump == pytest.approx(heat, rel=0.01)
    assert s.dissipation == pytest.approx(heat, rel=1e-9)
    assert (s.heat_conducted == 0.0) == (boundary == "adiabatic")


def test_thermal_film_is_hotter_and_carries_less():
    iso = JournalBearing(**GEOMETRY, viscosity=OIL.viscosity(OIL.supply_temperature), grid=GRID)
    s, si = thermal_bearing().steady_state(0.6, SPEED), iso.steady_state(0.6, SPEED)
    Ts = OIL.supply_temperature
    assert s.temperature.min() >= Ts - 1e-9
    assert s.max_temperature > Ts + 5.0
    assert s.load < si.load and s.power_loss < si.power_loss
    assert Ts < s.mixing_temperature[0] < s.max_temperature
    assert Ts < s.outlet_temperature < s.max_temperature
    assert np.allclose(s.viscosity_field, OIL.viscosity(s.temperature), rtol=1e-3)  # at the converged temperatures


def test_no_overshoot_on_a_coarse_grid():
    """Without dissipation, oil at the supply temperature and a bush above it: every temperature lies between the two
    (discrete maximum principle of the upwinded equations), on a 16 x 2 grid."""
    b = thermal_bearing(replace(OIL, boundary=BushConvection(5000.0, temperature=373.15)), grid=(16, 2))
    f = b.film(SPEED)
    u, *_ = thd.steady(b, f, 0.8, 0.0)
    E = EnergyEquation(f, b.thermal)
    E.solve(u, 0.8, 0.0)
    wall, Tw = E.wall_coefficients()
    q_in, q_rec = np.zeros(1), np.zeros(1)
    from transient.models.journal.thermal import feed_totals
    q_in, q_rec = feed_totals(E.free, E.feed, E.n_feeds, E.streams, E.stream_flow)
    carry = np.minimum(b.thermal.mixing, q_in / q_rec)
    m = energy_system(E.free, E.feed, E.n_feeds, E.streams, f.fv.boundary, E.stream_flow, E.qb, np.zeros(f.n),
                      wall / E.heat_unit, Tw, 323.15, carry, q_in, q_rec, E.rows, E.cols, E.vals, E.rhs)
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla
    N = f.n + E.n_feeds
    T = spla.spsolve(sp.csc_matrix((E.vals[:m], (E.rows[:m], E.cols[:m])), shape=(N, N)), E.rhs)
    assert T.min() >= 323.15 - 1e-9 and T.max() <= 373.15 + 1e-9
    assert T.max() > 330.0  # the bush heats the film


def test_mixing_coefficient_sets_the_feed_temperature():
    """No carry-over: the feed's oil is supply oil warmed only by the shear in the groove's own cells,
    ``T_mix = T_supply + Phi_groove / (rho c_p Q_in)``; full carry-over: the recirculated oil warms it further."""
    b = thermal_bearing(replace(OIL, mixing=0.0))
    f = b.film(SPEED)
    u, _, balance, _ = thd.steady(b, f, 0.6, 0.0)
    E = EnergyEquation(f, b.thermal)
    E.solve(u, 0.6, 0.0)
    from transient.models.journal.thermal import feed_totals
    q_in, _ = feed_totals(E.free, E.feed, E.n_feeds, E.streams, E.stream_flow)
    groove_heat = E.power_unit * E.source[~E.free].sum()
    rise = groove_heat / (E.heat_unit * q_in[0])
    assert balance.mixing_temperature[0] == pytest.approx(OIL.supply_temperature + rise, abs=1e-9)
    assert 0.0 < rise < 1.0
    warm = thermal_bearing(replace(OIL, mixing=1.0)).steady_state(0.6, SPEED)
    assert warm.mixing_temperature[0] > balance.mixing_temperature[0] + 1.0


def test_viscous_film_jacobian_matches_finite_differences():
    b = thermal_bearing(grid=(16, 3))
    f = b.film(SPEED)
    assert isinstance(f, ViscousFilm)
    f.fluidity[:] = np.random.default_rng(1).uniform(0.5, 2.0, f.n)
    X, Y = 0.5, 0.2
    u, _ = f.solve(X, Y)
    J = f.op.matrix(f.jacobian_data(u, X, Y)).toarray()[:f.n, :f.n + 2]
    h = 1e-7
    fd = np.empty_like(J)
    for j in range(f.n):
        e = np.zeros(f.n)
        e[j] = h
        fd[:, j] = (f.residual(u + e, X, Y) - f.residual(u - e, X, Y)) / (2 * h)
    fd[:, f.n] = (f.residual(u, X + h, Y) - f.residual(u, X - h, Y)) / (2 * h)
    fd[:, f.n + 1] = (f.residual(u, X, Y + h) - f.residual(u, X, Y - h)) / (2 * h)
    assert np.max(np.abs(J - fd)) <= 1e-6 * np.max(np.abs(fd))


def test_thermal_equilibrium_carries_the_load():
    s = thermal_bearing().equilibrium(2000.0, SPEED)
    assert s.load == pytest.approx(2000.0, rel=1e-9)
    assert s.max_temperature > OIL.supply_temperature
    assert s.dissipation == pytest.approx(s.heat_convected, rel=1e-9)


@pytest.mark.parametrize("make, name", [
    (lambda: replace(OIL, supply_temperature=-10.0), "supply_temperature"),
    (lambda: replace(OIL, mixing=1.5), "mixing"),
    (lambda: replace(OIL, boundary="hot"), "boundary"),
    (lambda: replace(OIL, density=None), "density"),
    (lambda: replace(OIL, viscosity_at=((323.0, 0.01), (353.0, 0.02))), "viscosity_at"),
    (lambda: ThermalFilm(323.15, density=870.0, heat_capacity=1950.0), "viscosity_at"),
    (lambda: BushConvection(-1.0), "boundary.coefficient"),
    (lambda: thermal_bearing(cavitation="reynolds"), "thermal"),
    (lambda: JournalBearing(**GEOMETRY, grid=GRID), "viscosity"),
    (lambda: replace(OIL, wall_heat_capacity=-1.0), "wall_heat_capacity"),
])
def test_bad_input_is_named(make, name):
    with pytest.raises(ValueError, match=rf"^{re.escape(name)}"):
        make()


def test_a_thermal_state_saves_and_loads(tmp_path):
    s = thermal_bearing().steady_state(0.6, SPEED)
    from transient import load_result
    r = load_result(s.save(tmp_path / "thd"))
    assert np.array_equal(r.temperature, s.temperature) and r.max_temperature == s.max_temperature
    assert np.array_equal(r.mixing_temperature, s.mixing_temperature) and r.heat_convected == s.heat_convected


def test_pressure_viscosity_thickens_the_loaded_film():
    """A Barus coefficient raises the viscosity where the pressure is: the film carries more at the same position."""
    piezo = replace(OIL, viscosity_at=None, viscosity_law=replace(OIL.law, pressure_viscosity=2e-8))
    s, s0 = thermal_bearing(piezo).steady_state(0.6, SPEED), thermal_bearing().steady_state(0.6, SPEED)
    assert s.load > s0.load
    p = s.pressure  # above the cavitation pressure, 0 Pa here
    mu_T = OIL.viscosity(s.temperature)
    assert np.allclose(s.viscosity_field, mu_T * np.exp(2e-8 * np.maximum(p, 0.0)), rtol=1e-3)


def test_first_temperatures_follow_their_viscosity():
    """From the film at the supply viscosity (e/C 0.9, 40 x 6) the plain energy solve overshoots the THD film's
    hottest temperature by far (the cold oil's dissipation); the solve whose dissipation follows each cell's new
    viscosity lands near it, and the alternation built on it settles on the same film as the plain alternation."""
    b = thermal_bearing()
    X, Y = 0.9, 0.0
    state = b.steady_state(0.9, SPEED)
    f = b.film(SPEED)
    T0 = thd._start(f, b.thermal, b.viscosity)
    u, *_ = b.film_solve(f, X, Y)
    E = EnergyEquation(f, b.thermal)
    f.residual(u, X, Y)
    rates = E.rates()
    plain = E.solve_rates(rates).temperature
    heated = thd.heated_temperatures(E, rates, T0, OIL.supply_temperature, 800.0)[:f.n]
    hottest = state.max_temperature
    assert plain.max() - hottest > 50.0
    assert abs(heated.max() - hottest) < 0.3 * (hottest - OIL.supply_temperature)
    assert np.all(heated >= OIL.supply_temperature - 1e-9)
    # the same fixed point from the plain alternation (its 40 K step limit: docs/validation.md)
    def plain_alternation(energy, r, T, low, high):
        return energy.solve_rates(r).temperature

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(thd, "heated_temperatures", plain_alternation)
        mp.setattr(thd, "MAX_STEP_K", 40.0)
        old = b.steady_state(0.9, SPEED)
    assert old.thermal_iterations > state.thermal_iterations
    assert np.max(np.abs(old.temperature - state.temperature)) <= 10 * OIL.tolerance
    assert old.load == pytest.approx(state.load, rel=1e-6)
