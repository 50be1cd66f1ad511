"""The rough journal film in a Winkler bore (the bore gives way by K (p + p_a) cell by cell) and the thick ring's
compliance that parametrises it."""

import numpy as np
import pytest
from scipy.integrate import solve_bvp

from rough_bearing import check_force_sensitivity, rough_bearing
from transient import Roughness, steel_asperity_contact
from transient.models.journal.rough_orbit import rough_cells
from transient.physics.ring import bore_compliance


def rough(sigma, K, grid, alpha=0.0, **kw):
    """The Rho & Kim bearing with steel asperities of composite roughness ``sigma`` in a bore of compliance ``K``."""
    return rough_bearing(sigma, grid, kw, bore_compliance=K, pressure_viscosity=alpha)


@pytest.mark.parametrize("K", [-1e-13, 1e-10, float("inf")])
def test_bad_bore_compliance_is_a_named_error(K):
    with pytest.raises(ValueError, match="bore_compliance"):
        Roughness(steel_asperity_contact(1e-6), bore_compliance=K)


def test_orbits_refuse_the_options_of_the_steady_film():
    for kw, name in ((dict(bore_compliance=1e-13), "bore_compliance"), (dict(pressure_viscosity=1e-8),
                                                                       "pressure_viscosity")):
        with pytest.raises(ValueError, match=name):
            rough_cells(Roughness(steel_asperity_contact(1e-6), **kw), 80e-6, 1e5, 10)


def test_vanishing_compliance_is_the_rigid_bore():
    """K -> 0 through the Winkler code path (1e-24 m/Pa: a give of 1e-16 m): the equilibrium in contact equals the
    rigid bore's to 1e-9."""
    rigid = rough(2e-6, 0.0, (24, 4)).equilibrium(3000.0, 200.0)
    soft = rough(2e-6, 1e-24, (24, 4)).equilibrium(3000.0, 200.0)
    assert rigid.contact_load > 0.05 * 3000.0
    np.testing.assert_allclose(soft.position, rigid.position, rtol=1e-9)
    assert soft.friction_torque == pytest.approx(rigid.friction_torque, rel=1e-9)
    assert soft.contact_load == pytest.approx(rigid.contact_load, rel=1e-9)
    assert soft.min_film == pytest.approx(np.min(rigid.film_thickness), rel=1e-9)  # the least cell gap


def elastic_film(alpha=0.0):
    """A film in contact whose bore gives several sigma: K = 2e-12 m/Pa, e/C = 0.99 (rigid gap 0.8 um = 0.4 sigma)."""
    return rough(2e-6, 2e-12, (16, 4), alpha=alpha, switch_width=1e4).film(3000.0)


@pytest.mark.parametrize("alpha", [0.0, 2e-8])
def test_jacobian_matches_finite_differences(fd_jacobian, alpha):
    """dG/du (pseudo-time rate 0 and 3) and dG/d(X, Y, VX, VY) of the film in the Winkler bore (with and without
    Barus), at a steady state with asperity contact, perturbed."""
    f = elastic_film(alpha)
    n = f.n
    X, Y, VX, VY = 0.93, 0.35, 0.0, 0.0
    u = f.solve(X, Y)[0]
    f.residual(u, X, Y)
    pa, _ = f.contact(X, Y)
    give = f.H - (f.gap0 + X * f.cosp + Y * f.sinp)
    assert np.max(pa) > 0 and np.max(give) * f.scales.clearance > 3 * f.roughness.sigma
    u = u + 1e-3 * np.random.default_rng(3).standard_normal(n) * f.op.free
    for rate in (0.0, 3.0):  # the pseudo-time storage: d(h_T theta)/du through the bore's give too
        M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY, rate=rate)).toarray()
        J_fd = fd_jacobian(lambda v, rate=rate: f.residual(v, X, Y, VX, VY, rate=rate).copy(), u, n,
                           step=5e-4 * f.width)
        assert np.max(np.abs(M[:n, :n] - J_fd)) < 1e-6 * np.max(np.abs(J_fd))
    M = f.op.matrix(f.jacobian_data(u, X, Y, VX, VY)).toarray()
    Jq = fd_jacobian(lambda q: f.residual(u, *q).copy(), np.array([X, Y, VX, VY]), n, step=1e-7)
    assert np.max(np.abs(M[:n, n:n + 4] - Jq)) < 1e-6 * np.max(np.abs(Jq))


def test_gap_is_the_rigid_gap_plus_the_bores_give():
    """Every cell's film thickness is the rigid journal's plus ``K (p + p_a)`` at its own film and asperity
    pressures (the per-cell solve, checked on the SI state)."""
    f = elastic_film()
    X, Y = 0.93, 0.35
    u = f.solve(X, Y)[0]
    s = f.state(u, X, Y)
    C, K = f.scales.clearance, 2e-12
    rigid = C * f.grid.to_2d(f.gap0 + X * f.cosp + Y * f.sinp)
    p = s.pressure - f.scales.cavitation_pressure
    np.testing.assert_allclose(s.film_thickness, rigid + K * (p + s.contact_pressure), rtol=1e-10, atol=1e-12 * C)
    assert s.min_film == pytest.approx(np.min(s.film_thickness), rel=1e-12)


def test_force_sensitivity_matches_finite_differences(fd_jacobian):
    """dF/d(X, Y) of film + asperities in the Winkler bore (the equilibrium's Newton matrix) against central
    differences of the force of steady films at neighbouring positions."""
    f = rough(2e-6, 1e-12, (24, 4)).film(200.0)
    q = np.array([-1.0, 0.05])  # past the rigid bore's circle: the bore's give carries the journal
    check_force_sensitivity(f, q, fd_jacobian)


def test_ring_compliance_is_lames():
    """The bore's give of a thick ring under internal pressure against the plane-stress equilibrium
    ``u'' + u'/r - u/r^2 = 0`` with ``sigma_r(a) = -p``, ``sigma_r(b) = 0`` solved numerically."""
    a, b, E, nu, p = 0.0239, 0.07, 70e9, 0.3, 1e6
    c = E / (1 - nu * nu)

    def rhs(r, y):
        return np.vstack([y[1], -y[1] / r + y[0] / r ** 2])

    def bc(ya, yb):
        return np.array([c * (ya[1] + nu * ya[0] / a) + p, c * (yb[1] + nu * yb[0] / b)])

    r = np.linspace(a, b, 50)
    sol = solve_bvp(rhs, bc, r, np.zeros((2, r.size)), tol=1e-10)
    assert sol.success
    assert bore_compliance(a, b, E, nu) * p == pytest.approx(sol.sol(a)[0], rel=1e-8)
    with pytest.raises(ValueError, match="outer_radius"):
        bore_compliance(a, a, E, nu)
