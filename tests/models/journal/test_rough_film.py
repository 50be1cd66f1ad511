"""Rough journal bearings (mixed lubrication, steady): the average Reynolds equation in the Elrod film, asperity
contact in the load balance, friction torque, the Stribeck curve."""

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from rough_bearing import check_force_sensitivity, rough_bearing
from transient import JournalBearing, Roughness, steel_asperity_contact, stribeck_curve
from transient.models.journal.film import Film
from transient.models.journal.rough_film import RoughFilm
from transient.params import rho_kim
from transient.physics.flow_factors import (pressure_flow_factor_slopes, pressure_flow_factors, shear_flow_factor,
                                            shear_flow_factor_slope)
from transient.study.stribeck import lift_off_speed

BEARING = dict(rho_kim.BEARING)
GRID = (36, 6)


def rough(sigma, grid=GRID, **kw):
    """The Rho & Kim bearing with steel asperities of composite roughness ``sigma``; ``kw`` to the bearing."""
    return rough_bearing(sigma, grid, kw)


@pytest.mark.parametrize("gamma", [1 / 9, 0.5, 1.0, 2.0, 9.0])
def test_flow_factor_slopes_are_the_fits_derivatives(gamma):
    H = np.array([1.1, 2.0, 3.7, 4.9, 6.0, 12.0])
    d = 1e-6
    up, dn = pressure_flow_factors(H + d, gamma), pressure_flow_factors(H - d, gamma)
    sx, sy = pressure_flow_factor_slopes(H, gamma)
    np.testing.assert_allclose(sx, (up[0] - dn[0]) / (2 * d), rtol=1e-6, atol=1e-10)
    np.testing.assert_allclose(sy, (up[1] - dn[1]) / (2 * d), rtol=1e-6, atol=1e-10)
    fd = (shear_flow_factor(H + d, gamma) - shear_flow_factor(H - d, gamma)) / (2 * d)
    np.testing.assert_allclose(shear_flow_factor_slope(H, gamma), fd, rtol=1e-6, atol=1e-10)


@pytest.mark.parametrize("kw, name", [
    (dict(gamma=10.0), "roughness.gamma"), (dict(boundary_friction=1.5), "roughness.boundary_friction"),
    (dict(boundary_friction=-0.1), "roughness.boundary_friction"),
    (dict(journal_variance_share=2.0), "roughness.journal_variance_share")])
def test_bad_roughness_is_a_named_error(kw, name):
    with pytest.raises(ValueError, match=name.replace(".", r"\.")):
        Roughness(steel_asperity_contact(1e-6), **kw)
    with pytest.raises(ValueError, match="roughness.contact"):
        Roughness(contact=1e-6)


def test_rough_film_refuses_the_films_it_does_not_cover():
    r = Roughness(steel_asperity_contact(1e-6))
    with pytest.raises(ValueError, match="roughness"):
        JournalBearing(**BEARING, grid=GRID, roughness=r, cavitation="reynolds")
    with pytest.raises(ValueError, match="roughness sigma"):
        JournalBearing(**BEARING, grid=GRID, roughness=Roughness(steel_asperity_contact(50e-6)))
    with pytest.raises(TypeError, match="roughness"):
        JournalBearing(**BEARING, grid=GRID, roughness=1e-6)


def test_smooth_bearing_is_the_smooth_film():
    """roughness=None builds the smooth Film (no RoughFilm code on its path); its friction torque is R times the
    film's drag and it has no contact."""
    b = JournalBearing(**BEARING, grid=GRID)
    assert b.roughness is None and type(b.film(3000.0)) is Film
    s = b.steady_state(0.6, 3000.0)
    assert s.contact_load == 0.0 and s.contact_pressure is None
    assert s.friction_torque == pytest.approx(b.radius * s.friction_force, rel=1e-15)
    assert s.power_loss == pytest.approx(s.friction_torque * 3000.0 * math.pi / 30.0, rel=1e-15)


@pytest.mark.parametrize("eps", [0.3, 0.9])
def test_vanishing_roughness_is_the_smooth_film(eps):
    """sigma = 1 nm on C = 80 um: h / sigma >= 8000 everywhere, where 1 - phi_x = 0.9 exp(-0.56 h/sigma), Phi_s ~
    exp(-h / 4 sigma), 1 - Phi(h/sigma) and the Greenwood-Tripp integral all underflow: the rough film is the smooth
    one to rounding (Newton stops at 1e-10 of the state: 1e-9 relative on the force)."""
    smooth = JournalBearing(**BEARING, grid=GRID).steady_state(eps, 3000.0)
    b = rough(1e-9)
    assert type(b.film(3000.0)) is RoughFilm
    s = b.steady_state(eps, 3000.0)
    np.testing.assert_allclose(s.force, smooth.force, rtol=1e-9)
    assert s.friction_torque == pytest.approx(smooth.friction_torque, rel=1e-9)
    assert s.contact_load == 0.0


def test_jacobian_matches_finite_differences(fd_jacobian):
    """dG/du and dG/d(X, Y, VX, VY) of the rough film (pseudo-time rate 0 and 3), with cells above and below the
    flow factors' fit floor (h / sigma from 0.4 to 38) and a squeezing journal."""
    b = rough(4e-6, grid=(16, 4), switch_width=1e4)
    f = b.film(3000.0)
    n = f.n
    X, Y, VX, VY = 0.88, 0.42, 0.02, -0.03  # e/C = 0.975: h_min = 2 um = 0.5 sigma
    u = f.solve(X, Y)[0] + 1e-3 * np.random.default_rng(2).standard_normal(n) * f.op.free
    C_ref = np.full(n, 0.9)
    for rate in (0.0, 3.0):
        M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY, rate=rate)).toarray()
        J_fd = fd_jacobian(lambda v, rate=rate: f.residual(v, X, Y, VX, VY, rate=rate, C_ref=C_ref).copy(), u, n,
                           step=5e-4 * f.width)
        scale = np.max(np.abs(J_fd))
        assert np.max(np.abs(M[:n, :n] - J_fd)) < 1e-6 * scale
    Jq = fd_jacobian(lambda q: f.residual(u, *q).copy(), np.array([X, Y, VX, VY]), n, step=1e-7)
    M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY)).toarray()
    assert np.max(np.abs(M[:n, n:n + 4] - Jq)) < 1e-6 * np.max(np.abs(Jq))


def test_force_sensitivity_with_contact_matches_finite_differences(fd_jacobian):
    """dF/d(X, Y) of film + asperities (the equilibrium's Newton matrix) against central differences of the
    force of steady films solved at neighbouring positions, in contact (h_min = 1.6 sigma)."""
    f = rough(2e-6, grid=(24, 4)).film(200.0)
    check_force_sensitivity(f, np.array([-0.96, 0.0]), fd_jacobian)


def test_contact_force_is_the_greenwood_tripp_integral_of_the_gap():
    """The asperity force at a rigid journal position against the Greenwood-Tripp pressure of the gap
    h = C (1 + X cos phi) integrated by adaptive quadrature: L R int p_a cos phi dphi (the cell sum is the
    midpoint rule on 151 cells, on a smooth periodic integrand: it converges exponentially, 1e-8 is loose)."""
    b = rough(1e-6, grid=(151, 4))
    f = b.film(100.0)
    X = 0.985
    Fx = f.contact_force(X, 0.0)[0] * f.force_scale
    c = b.roughness.contact
    ref = b.length * b.radius * quad(lambda p: c.load(b.clearance * (1 + X * math.cos(p))) * math.cos(p),
                                     0, 2 * math.pi, points=[math.pi], limit=200)[0]
    assert ref < 0 and Fx == pytest.approx(ref, rel=1e-8)


def test_high_speed_rough_bearing_is_the_smooth_one():
    """At 6000 rpm under 5 kN the film's thinnest gap is about 19 sigma (sigma = 1 um): no contact, and the average
    flow coefficients differ from the smooth film's by at most 0.9 exp(-0.56 h_min / sigma) (pressure flow factor,
    2e-5) plus |2 V_j - 1| Phi_s(h_min / sigma) sigma / h_min (shear flow, 3e-4 relative to the Couette flux). The
    eccentricity and attitude agree within that bound."""
    smooth = JournalBearing(**BEARING, grid=GRID).equilibrium(5000.0, 6000.0)
    b = rough(1e-6)
    s = b.equilibrium(5000.0, 6000.0)
    H = s.min_film / 1e-6
    bound = 0.9 * math.exp(-0.56 * H) + abs(2 * b.roughness.journal_variance_share - 1) * shear_flow_factor(H) / H
    assert H > 15 and s.contact_load < 1e-12 * 5000.0
    assert abs(s.eccentricity_ratio - smooth.eccentricity_ratio) < bound * smooth.eccentricity_ratio
    assert abs(s.attitude_angle_deg - smooth.attitude_angle_deg) < bound * smooth.attitude_angle_deg


def test_low_speed_load_is_shared_by_film_and_asperities():
    """At 20 rpm the asperities carry a large part of 5 kN; the film and the contact forces add up to the load
    (equilibrium residual 1e-10 of the load) and the torque adds the boundary friction mu_b R sum p_a dA."""
    b = rough(1e-6)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # the contact pressure is above the isoviscous film's range
        s = b.equilibrium(5000.0, 20.0)
    film = np.subtract(s.force, s.contact_force)
    assert 0.2 * 5000.0 < s.contact_load < 5000.0 and s.film_load > 0.05 * 5000.0
    np.testing.assert_allclose(np.add(film, s.contact_force), (-5000.0, 0.0), atol=1e-7 * 5000.0)
    assert s.contact_normal_load >= s.contact_load
    boundary = 0.12 * b.radius * s.contact_normal_load
    assert s.friction_torque == pytest.approx(b.radius * s.friction_force + boundary, rel=1e-12)
    assert boundary > 0.5 * s.friction_torque  # boundary friction dominates at this speed


def test_light_load_friction_is_petroffs():
    """Petroff: a concentric full film shears ``T0 = 2 pi mu omega R^3 L / C``, the friction coefficient
    ``T0 / (R W) = 4 pi^2 mu N R^2 L / (W C)`` (N in rev/s). A lightly loaded rough bearing whose film is full (fed
    from its ends at 5 bar, no groove) at 6000 rpm: the Couette shear of the eccentric film is T0 / sqrt(1 - eps^2),
    the Poiseuille part of the journal's wall stress adds the pressure's moment e W sin(attitude) / 2 (at most
    e W / 2); no contact."""
    b = JournalBearing(**BEARING, groove=None, ambient_pressure=5e5, grid=GRID,
                       roughness=Roughness(steel_asperity_contact(1e-6), boundary_friction=0.12))
    W = 100.0
    s = b.equilibrium(W, 6000.0)
    eps = s.eccentricity_ratio
    assert np.min(s.film_content) >= 1.0 and eps < 0.05 and s.contact_load == 0.0
    w = 6000.0 * math.pi / 30.0
    T0 = 2 * math.pi * b.viscosity * w * b.radius ** 3 * b.length / b.clearance
    moment = eps * b.clearance * W * math.sin(math.radians(s.attitude_angle_deg)) / 2
    assert s.friction_torque - T0 / math.sqrt(1 - eps ** 2) == pytest.approx(moment, rel=0.05)
    petroff = 4 * math.pi ** 2 * b.viscosity * 100.0 * b.radius ** 2 * b.length / (W * b.clearance)
    assert s.friction_coefficient == pytest.approx(petroff, rel=2e-3)  # 1/sqrt(1 - eps^2) - 1 = 9e-4


def test_stribeck_curve_has_its_minimum_and_lift_off():
    b = rough(1e-6, grid=(24, 4))
    speeds = np.geomspace(10, 6000, 8)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        r = stribeck_curve(b, 5000.0, speeds)
    assert np.all(np.diff(r.speed_rpm) > 0) and r.speed_rpm.size == 8
    k = int(np.argmin(r.friction_torque))
    assert 0 < k < 7  # falling (mixed) then rising (hydrodynamic) branch
    assert np.all(np.diff(r.h_min) > 0)
    assert np.all(np.diff(r.contact_load[r.contact_load > 1e-9]) < 0)
    share = r.contact_load / 5000.0
    i = np.nonzero(share >= 0.01)[0][-1]
    assert speeds[i] < r.lift_off_speed_rpm < speeds[i + 1]
    # each point is the equilibrium from the default start too
    s = b.equilibrium(5000.0, float(r.speed_rpm[-1]))
    assert s.friction_torque == pytest.approx(r.friction_torque[-1], rel=1e-8)


def test_lift_off_speed_interpolates_the_crossing():
    s = np.array([10.0, 100.0, 1000.0])
    assert lift_off_speed(s, [500.0, 50.0, 0.0], 1000.0, 0.025) == pytest.approx(10 ** 2.5)  # share 0.05 -> 0
    assert math.isnan(lift_off_speed(s, [0.0, 0.0, 0.0], 1000.0))
    assert math.isnan(lift_off_speed(s, [500.0, 500.0, 500.0], 1000.0))


@pytest.mark.slow  # 20 equilibria by continuation on 151 cells: 5 s of CPU
def test_at_rest_the_asperities_sit_where_greenwood_tripp_puts_them():
    """At 1e-3 rpm (fed at 1 kPa: the film carries 2 N of 5 kN) the equilibrium, reached by continuation in speed
    when Newton from the default start fails, sits where the Greenwood-Tripp pressure of the rigid gap
    h = C (1 + X cos phi), integrated by adaptive quadrature, carries the same contact load: the gap agrees to 1e-6
    (the midpoint rule of 151 cells, one centred on the thinnest gap, on the smooth periodic contact pressure)."""
    b = JournalBearing(**dict(BEARING, supply_pressure=1e3), grid=(151, 2),
                       roughness=Roughness(steel_asperity_contact(1e-6), boundary_friction=0.12))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        s = b.equilibrium(5000.0, 1e-3)
    assert s.contact_load > 0.99 * 5000.0
    c = b.roughness.contact

    def excess(X):
        return -b.length * b.radius * quad(lambda p: c.load(b.clearance * (1 + X * math.cos(p))) * math.cos(p), 0,
                                           2 * math.pi, points=[math.pi], limit=200)[0] - s.contact_load

    X = brentq(excess, 0.99, 0.99999, xtol=1e-15)
    assert (1 - s.eccentricity_ratio) / (1 - X) == pytest.approx(1.0, abs=1e-6)
    assert s.friction_torque == pytest.approx(b.radius * (s.friction_force + 0.12 * s.contact_normal_load), rel=1e-12)
