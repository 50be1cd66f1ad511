"""Seed 001, 1-D limit: the EHL line contact against Hertz, Martin, Dowson-Higginson / Dowson-Toyoda,
grid convergence, load balance, the analytic Jacobian and bad input."""

import math

import numpy as np
import pytest

from transient.models.roller import LineContact
from transient.models.roller.results import EHLConvergenceError
from transient.physics.line_formulas import (dowson_higginson_min, dowson_toyoda_central, hertz_line,
                                             line_groups)
from transient.verification.ehl_reference import martin_film

R, E = 0.01, 220e9


def contact(w=1e5, u=2.0, eta=0.02, alpha=1.2e-8, **kw):
    return LineContact(R, w, u, eta, alpha, E, **kw)


def test_dry_limit_is_hertz():
    c = contact()
    d = c.dry(401)
    b, ph = hertz_line(1e5, R, E)
    assert d.p_max == pytest.approx(ph, rel=1e-4)
    assert d.half_width == pytest.approx(b, rel=2e-3)
    x = d.x / b
    err = np.abs(d.pressure / ph - np.sqrt(np.clip(1 - x * x, 0, None)))
    assert np.max(err[np.abs(x) < 0.9]) < 2e-3
    # at the edges the square-root profile is resolved to O(sqrt(dx)), dx = 0.0075 b
    assert np.max(err) < 0.5 * math.sqrt(0.0075)


@pytest.mark.slow
def test_ehl_pressure_tends_to_dry_as_speed_falls():
    gaps = []
    for u in (2.0, 0.5, 0.125):
        c = contact(u=u, grid=401)
        s = c.steady()
        d = c.dry(401)
        pd = np.interp(s.x, d.x, d.pressure)
        gaps.append(np.abs(s.pressure - pd).sum() / pd.sum())
    assert gaps[0] > gaps[1] > gaps[2]
    assert gaps[2] < 0.1


def test_rigid_isoviscous_matches_martin_with_second_order_convergence():
    w, u, eta = 2e4, 1.0, 0.05
    err = []
    for n in (401, 801):
        c = LineContact(R, w, u, eta, 0.0, E, density="incompressible", viscosity_law="isoviscous", elastic=False,
                        grid=n, domain=(-20.0, 10.0))
        s = c.steady()
        err.append(s.h_min / martin_film(w, R, eta, u, inlet=-20.0 * c.b) - 1.0)
    assert abs(err[1]) < 2e-3 and 3.0 < err[0] / err[1] < 5.0
    U, _, W = line_groups(eta, u, 0.0, w, E, R)
    assert s.H_min == pytest.approx(4.9 * U / W, rel=0.05)  # the infinite-inlet constant, wide inlet


@pytest.mark.parametrize("w,u", [(1e5, 2.0), pytest.param(3e4, 0.5, marks=pytest.mark.slow),
                                 pytest.param(2e5, 8.0, marks=pytest.mark.slow)])
def test_barus_films_against_dowson_formulas(w, u):
    c = contact(w=w, u=u, grid=801, domain=(-8.0, 2.5))
    s = c.steady()
    U, G, W = c.U, c.G, c.W
    assert s.H_min == pytest.approx(dowson_higginson_min(U, G, W), rel=0.05)
    assert s.H_central == pytest.approx(dowson_toyoda_central(U, G, W), rel=0.12)


@pytest.mark.slow
def test_grid_convergence_is_second_order():
    h = [contact(grid=n).steady() for n in (201, 401, 801)]
    for key in ("h_central", "h_min"):
        v = [getattr(s, key) for s in h]
        ratio = (v[1] - v[0]) / (v[2] - v[1])
        assert 3.0 < ratio < 5.5, (key, v, ratio)
        assert abs(v[2] - v[1]) / v[2] < 2e-3


def test_load_balance_and_complementarity():
    s = contact(grid=401).steady()
    assert abs(s.load_error) < 1e-6
    assert s.pressure.min() > -1e-9 * s.p_max
    assert s.film.min() > 0


def test_analytic_jacobian_matches_finite_differences(fd_jacobian):
    c = contact(grid=61, domain=(-5.0, 2.5))
    f = c.film_problem()
    u = c.initial_guess(f)
    u[:-1] += 0.05 * np.random.default_rng(3).random(u.size - 1)
    J = f.reynolds_jacobian_dense(u)

    def F(v):
        return f.reynolds(v[:-1], f.film(v[:-1], v[-1])).copy()

    fd = fd_jacobian(F, u, J.shape[0])
    assert np.max(np.abs(J - fd)) < 1e-6 * np.max(np.abs(fd))


@pytest.mark.parametrize("field,value,unit", [("load_per_length", 0.0, "N/m"), ("speed", -1.0, "m/s"),
                                              ("radius", 0.0, "m"), ("viscosity", -0.01, "Pa s")])
def test_bad_input_names_parameter_value_unit(field, value, unit):
    kw = dict(radius=R, load_per_length=1e5, speed=2.0, viscosity=0.02, pressure_viscosity=1.2e-8, modulus=E)
    kw[field] = value
    with pytest.raises(ValueError) as e:
        LineContact(**kw)
    assert field in str(e.value) and repr(value) in str(e.value) and unit in str(e.value)


def test_too_coarse_grid_is_rejected():
    with pytest.raises(ValueError, match="inside the Hertz contact"):
        contact(grid=21)


def test_newton_failure_raises_with_residual_history():
    with pytest.raises(EHLConvergenceError) as e:
        contact(grid=201).steady(max_iter=2)
    r = e.value.result
    assert r.success is False and len(r.residual_norms) >= 2 and "did not converge" in r.message
