"""The rough journal film with a pressure-dependent viscosity (Barus): its limits, its Jacobian and the reduced
pressure of a full film."""

import math

import numpy as np
import pytest

from rough_bearing import rough_bearing
from transient import Roughness, steel_asperity_contact


def rough(sigma, alpha, grid, **kw):
    """The Rho & Kim bearing with steel asperities of composite roughness ``sigma`` and Barus coefficient ``alpha``."""
    return rough_bearing(sigma, grid, kw, pressure_viscosity=alpha)


@pytest.mark.parametrize("alpha", [-1e-9, 2e-7, float("nan")])
def test_bad_pressure_viscosity_is_a_named_error(alpha):
    with pytest.raises(ValueError, match="pressure_viscosity"):
        Roughness(steel_asperity_contact(1e-6), pressure_viscosity=alpha)


def test_vanishing_pressure_viscosity_is_the_isoviscous_film():
    """alpha -> 0 through the Barus code path (1e-18 /Pa: alpha p below 1e-10): the equilibrium in contact and its
    friction torque equal the isoviscous film's to 1e-9."""
    iso = rough(2e-6, 0.0, (24, 4)).equilibrium(3000.0, 200.0)
    bar = rough(2e-6, 1e-18, (24, 4)).equilibrium(3000.0, 200.0)
    assert iso.contact_load > 0.05 * 3000.0
    np.testing.assert_allclose(bar.position, iso.position, rtol=1e-9)
    assert bar.friction_torque == pytest.approx(iso.friction_torque, rel=1e-9)
    assert bar.contact_load == pytest.approx(iso.contact_load, rel=1e-9)


def test_jacobian_matches_finite_differences(fd_jacobian):
    """dG/du (pseudo-time rate 0 and 3) and dG/d(X, Y, VX, VY) of the Barus film with alpha p up to 5, cells above
    and below the flow factors' fit floor, a squeezing journal."""
    f = rough(4e-6, 3e-8, (16, 4), switch_width=1e4).film(3000.0)
    n = f.n
    X, Y, VX, VY = 0.88, 0.42, 0.02, -0.03
    u = f.solve(X, Y)[0]
    f.residual(u, X, Y)
    assert f.alpha_p0 * np.max(f.P) > 3.0
    u = u + 1e-3 * np.random.default_rng(2).standard_normal(n) * f.op.free
    C_ref = np.full(n, 0.9)
    for rate in (0.0, 3.0):
        M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY, rate=rate)).toarray()
        J_fd = fd_jacobian(lambda v, rate=rate: f.residual(v, X, Y, VX, VY, rate=rate, C_ref=C_ref).copy(), u, n,
                           step=5e-4 * f.width)
        assert np.max(np.abs(M[:n, :n] - J_fd)) < 1e-6 * np.max(np.abs(J_fd))
    Jq = fd_jacobian(lambda q: f.residual(u, *q).copy(), np.array([X, Y, VX, VY]), n, step=1e-7)
    M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY)).toarray()
    assert np.max(np.abs(M[:n, n:n + 4] - Jq)) < 1e-6 * np.max(np.abs(Jq))


def film_pressure(alpha, ambient, grid, X=0.5, Y=0.2):
    """Film pressure above cavitation [Pa] of a full film (fed from its ends, no groove, nearly incompressible)."""
    f = rough(0.2e-6, alpha, grid, bulk_modulus=1e12, groove=None, ambient_pressure=ambient).film(3000.0)
    u = f.solve(X, Y)[0]
    f.residual(u, X, Y)
    assert np.min(f.C) >= 1.0  # full film
    return f.p0 * f.P.copy(), f.scales.cavitation_pressure


def test_full_film_reduced_pressure_is_the_isoviscous_pressure():
    """Barus's reduced pressure ``q = (1 - exp(-alpha p)) / alpha`` turns the Reynolds equation with
    ``mu0 exp(alpha p)`` into the isoviscous one (the Couette flow does not see the viscosity): a full film with
    alpha p up to 0.43, its ends at p_a, has q equal to the pressure of the isoviscous film with its ends at q(p_a).
    The discrete films differ by the face averages of the conductance: second order in the cell size (0.091 % and
    0.023 % of the pressure range on 36 x 6 and 72 x 12 cells)."""
    alpha, ambient = 1e-7, 3e6
    errors = []
    for grid in ((36, 6), (72, 12)):
        pB, pc = film_pressure(alpha, ambient, grid)
        assert alpha * np.max(pB) > 0.4
        q_end = pc + (1.0 - math.exp(-alpha * (ambient - pc))) / alpha
        pI, _ = film_pressure(0.0, q_end, grid)
        qB = (1.0 - np.exp(-alpha * pB)) / alpha
        errors.append(np.max(np.abs(qB - pI)) / np.ptp(pI))
    assert errors[0] < 2e-3
    assert errors[1] < 0.3 * errors[0]  # converging at second order (ratio 1/4)


def test_friction_shears_at_the_cells_viscosity():
    """The journal's friction force of the Barus film is ``sum (mu(p) U / h + h G / 2) theta dA``: the Couette stress
    at each cell's viscosity ``mu0 exp(alpha p)`` (up to 1.2 mu0 here), the Poiseuille stress unchanged."""
    b = rough(0.2e-6, 4e-8, (36, 6))
    f = b.film(3000.0)
    X, Y = 0.7, 0.3
    u = f.solve(X, Y)[0]
    s = f.state(u, X, Y)
    f.residual(u, X, Y)
    mu = np.exp(4e-8 * (s.pressure - f.scales.cavitation_pressure)).ravel()
    assert np.max(mu) > 1.2
    U = f.scales.omega * f.scales.radius
    h = s.film_thickness
    theta = np.minimum(s.film_content, 1.0)
    area = f.grid.to_2d(f.area) * f.scales.radius ** 2 * f.scales.sym
    couette = np.sum(f.grid.to_2d(mu) * b.viscosity * U / h * theta * area)
    poiseuille = np.sum(0.5 * h * s.pressure_gradient * theta * area)
    assert s.friction_force == pytest.approx(couette + poiseuille, rel=1e-10)
