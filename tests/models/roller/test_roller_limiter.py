"""The limited Couette flux (van Albada) of the roller's film: exact Jacobian against finite differences,
the unlimited second-order flux where the film is smooth, first order at its extrema."""

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.ehl.limiter import van_albada
from transient.params import park


def contact(scheme, factor=1.0):
    kw = dict(park.DIMENSIONLESS, W=park.DIMENSIONLESS["W"] * factor)
    return RollerContact.from_dimensionless(**kw, roller=TaperedRoller(**dict(park.ROLLER, tilt_deg=0.002)),
                                            speed=park.SPEED, grid=("clustered", 40, 25), scheme=scheme)


def test_van_albada_slope_and_derivatives(fd_jacobian):
    assert van_albada(1.0, 1.0)[0] == 1.0  # equal slopes: the unlimited extrapolation
    assert van_albada(-1.0, 2.0) == (0.0, 0.0, 0.0) and van_albada(0.0, 2.0)[0] == 0.0  # extremum: first order
    a, b = 0.3, 1.7
    s, sa, sb = van_albada(a, b)
    assert s == pytest.approx(a * b * (a + b) / (a * a + b * b), rel=1e-15)
    fd = fd_jacobian(lambda v: np.array([van_albada(v[0], v[1])[0]]), np.array([a, b]), 1)
    assert np.allclose([sa, sb], fd[0], rtol=1e-7)


def test_limited_jacobian_matches_finite_differences(fd_jacobian):
    c = contact("limited")
    f = c.film_problem(c.make_grid("clustered", 16, 12))
    assert f.scheme_code == 2
    u = c.initial_guess(f)
    u[:-1] += 0.05 * np.random.default_rng(7).random(u.size - 1)
    J = f.reynolds_jacobian_dense(u)

    def F(v):
        return f.reynolds(v[:-1], f.film(v[:-1], v[-1])).copy()

    fd = fd_jacobian(F, u, J.shape[0])
    assert np.max(np.abs(J - fd)) < 1e-6 * np.max(np.abs(fd))


def test_limited_flux_is_the_second_order_one_on_a_smooth_film_and_first_order_at_an_extremum():
    films = {s: contact(s).film_problem(contact(s).make_grid("clustered", 16, 12)) for s in ("limited", "upwind2", "upwind1")}
    g = films["limited"].grid
    p = np.zeros(g.n)
    smooth = np.tile(1.0 + g.x, g.y.size)  # rho h linear in x (p = 0: rho = 1): slopes equal everywhere
    F = {s: f.reynolds(p, smooth.copy()).copy() for s, f in films.items()}
    assert np.allclose(F["limited"], F["upwind2"], rtol=1e-12, atol=1e-12)
    vee = np.tile(np.abs(g.x), g.y.size)  # a minimum at x = 0
    F = {s: f.reynolds(p, vee.copy()).copy() for s, f in films.items()}
    I = int(np.argmin(np.abs(g.x)))  # the minimum's node (full index along x), row J = 1
    i0 = I - 1  # its interior index in row 0
    # its outflow face takes the first-order value m_I, its inflow face the second-order one
    f = films["upwind2"]
    dxL, dxR = g.x[I] - g.x[I - 1], g.x[I + 1] - g.x[I]
    extrapolation = 0.5 * dxR / dxL * (vee[I] - vee[I - 1])
    expected = F["upwind2"][i0] + f.lam * f.rs[1] * extrapolation / (0.5 * (dxL + dxR))
    assert F["limited"][i0] == pytest.approx(expected, rel=1e-12)
    assert F["limited"][i0] != pytest.approx(F["upwind2"][i0], rel=1e-3)
