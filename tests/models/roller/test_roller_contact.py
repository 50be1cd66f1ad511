"""Seed 001, finite line contact: dry footprint against Hertz, exact symmetries of the steady EHL
solution, the mid-plane against the line contact, load balance, Jacobian, DC-FFT, bad input."""

import numpy as np
import pytest

from transient.models.roller import LineContact, RollerContact, TaperedRoller
from transient.models.roller.dry import dry_contact
from transient.physics.hertz import hertz_contact

E, RM = 220e9, 0.01
CASE = dict(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E)  # the paper's loading on a shorter roller


def roller(theta=10.0, tilt=0.0, start=0.2):
    return TaperedRoller(RM, theta, 2 * RM, 0.5 * RM, start * RM, tilt)


def solve(tilt):
    c = RollerContact.from_dimensionless(**CASE, roller=roller(0.0, tilt), grid=("clustered", 40, 25))
    return c, c.steady()


@pytest.fixture(scope="module")
def untapered():
    """Steady solution of an untapered, untilted roller (40 x 25 clustered grid)."""
    return solve(0.0)


def test_dry_fully_crowned_roller_is_the_hertz_ellipse():
    ro = TaperedRoller(RM, 0.0, 2 * RM, 0.5 * RM, 0.0, 0.0)  # gap X^2/2 + Y^2/(2 * 0.5): an ellipse
    load = 2e-5 * E * RM ** 2
    d = dry_contact(ro, load, E)
    h = hertz_contact(load, rx=0.5 * RM, ry=RM, e_prime=E)  # semi-axis a along the larger radius (x here)
    assert d.half_width == pytest.approx(h.a, rel=5e-3)
    assert 0.5 * d.footprint_length == pytest.approx(h.b, rel=5e-3)
    assert d.p_max == pytest.approx(h.p_max, rel=2e-3)
    assert d.approach == pytest.approx(h.delta, rel=2e-3)


def test_symmetry(untapered):
    c0, s0 = untapered
    assert np.max(np.abs(c0.grid.y + c0.grid.y[::-1])) < 1e-9 * c0.grid.y[-1]
    assert np.max(np.abs(s0.pressure - s0.pressure[::-1])) < 1e-8 * s0.p_max


@pytest.mark.slow
def test_tilt_mirror_and_the_lower_end_carries_more():
    (_, sp), (_, sm) = solve(0.002), solve(-0.002)
    assert np.max(np.abs(sp.pressure - sm.pressure[::-1])) < 1e-8 * sp.p_max
    assert sp.h_min == pytest.approx(sm.h_min, rel=1e-8)
    # positive tilt adds Y tan(phi): the large end (Y > 0) opens, the small end carries more
    assert sp.y_of_p_max < 0 and sp.y_of_h_min < 0


def test_load_balance_and_positive_film(untapered):
    c, s = untapered
    assert s.success and abs(s.load_error) < 1e-6
    w = np.trapezoid(np.trapezoid(s.pressure, s.x, axis=1), s.y)
    assert w == pytest.approx(c.load, rel=0.02)  # trapezoid vs the patch sum of the model
    assert s.film[1:-1, 1:-1].min() > 0 and s.pressure.min() > -1e-9 * s.p_max


def test_result_saves_and_loads_with_units(untapered, tmp_path):
    from transient.results import load_result

    s = untapered[1]
    back = load_result(s.save(tmp_path / "steady"))
    assert np.array_equal(back.pressure, s.pressure) and back.h_min == s.h_min
    assert back.units()["film"] == "m" and back.units()["pressure"] == "Pa"


def test_midplane_equals_line_contact_on_the_same_nodes(untapered):
    c, s = untapered
    x, p, h = s.section_x(0.0)
    w = np.trapezoid(p, x)
    b = LineContact(RM, w, c.speed, c.lubricant.viscosity, c.lubricant.pressure_viscosity, E).b
    nodes = x / b
    lc = LineContact(RM, w, c.speed, c.lubricant.viscosity, c.lubricant.pressure_viscosity, E,
                     grid=nodes, domain=(nodes[0], nodes[-1]))
    assert s.h_central == pytest.approx(lc.steady().h_central, rel=5e-3)


def test_analytic_jacobian_2d_matches_finite_differences(untapered, fd_jacobian):
    c = untapered[0]
    g = c.make_grid("clustered", 14, 12)
    f = c.film_problem(g)
    u = c.initial_guess(f)
    u[:-1] += 0.05 * np.random.default_rng(5).random(u.size - 1)
    J = f.reynolds_jacobian_dense(u)

    def F(v):
        return f.reynolds(v[:-1], f.film(v[:-1], v[-1])).copy()

    fd = fd_jacobian(F, u, J.shape[0])
    assert np.max(np.abs(J - fd)) < 1e-6 * np.max(np.abs(fd))


def test_fft_and_dense_elasticity_give_the_same_residual(untapered):
    c = untapered[0]
    g = c.make_grid("uniform", 24, 20)
    fd, ff = c.film_problem(g, "dense"), c.film_problem(g, "fft")
    u = c.initial_guess(fd)
    assert np.allclose(fd.residual(u), ff.residual(u), rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("field,value,unit", [("load", 0.0, "N"), ("speed", -1.0, "m/s"), ("viscosity", 0.0, "Pa s")])
def test_bad_input_names_parameter_value_unit(field, value, unit):
    kw = dict(roller=roller(), load=100.0, speed=1.0, viscosity=0.02, pressure_viscosity=1e-8, modulus=E)
    kw[field] = value
    with pytest.raises(ValueError) as e:
        RollerContact(**kw)
    assert field in str(e.value) and repr(value) in str(e.value) and unit in str(e.value)


def test_bad_geometry_and_coarse_grid():
    with pytest.raises(ValueError, match="mean_radius"):
        TaperedRoller(-0.01)
    with pytest.raises(ValueError, match="tilt_deg"):
        TaperedRoller(RM, tilt_deg=10.0)
    c = RollerContact.from_dimensionless(**CASE, roller=roller(), grid=(12, 8))
    with pytest.raises(ValueError, match="dry contact width"):
        c.steady()


def test_tilt_that_opens_the_mid_plane_is_rejected_with_its_range():
    c = RollerContact.from_dimensionless(**CASE, roller=roller(tilt=0.5))
    with pytest.raises(ValueError) as e:
        c.dry()
    msg = str(e.value)
    assert "tilt_deg = 0.5 [deg]" in msg and "allowed" in msg and "mid-plane" in msg
