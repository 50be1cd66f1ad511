"""Thin-film levelling MOL (transient.models.ball.levelling) and Chiu's linear solution."""

import math

import numpy as np
import pytest

from transient.models.ball.levelling import BCS, LevellingGrid, chiu_depression, chiu_kernel, chiu_rate
from transient.solvers.integrate import solve


@pytest.mark.parametrize("bc", BCS)
@pytest.mark.parametrize("mob", [0.0, 0.1])
def test_jacobian_matches_finite_differences(bc, mob):
    rng = np.random.default_rng(1)
    n = 14
    g = LevellingGrid(n, 2.5, bc, h_res=1.0, mobility_film=mob)
    h = 1.0 + 0.4 * rng.standard_normal(n)
    h[3] = 0.01  # include a nearly dry cell
    J = g.jac_matrix(h).toarray()
    Jfd = np.zeros((n, n))
    for j in range(n):
        d = 1e-7 * max(1.0, abs(h[j]))
        e = np.zeros(n)
        e[j] = d
        Jfd[:, j] = (g.rhs(h + e) - g.rhs(h - e)) / (2 * d)
    assert np.abs(J - Jfd).max() / np.abs(J).max() < 1e-6
    # the pattern holds every nonzero of the finite-difference Jacobian
    assert np.all((np.abs(Jfd) > 1e-9 * np.abs(J).max()) <= (g.pattern.toarray() > 0))


@pytest.mark.parametrize("mode, n", [(0, 50), (3, 100)])
def test_single_mode_decays_at_exact_thin_film_rate(mode, n):
    # linearised about h0: cos(kappa x) decays at h0^3 kappa^4 (scaled units); reservoir BC modes are
    # kappa = (k + 1/2) pi / X. Small amplitude, nonlinear MOL integrated by CVODE.
    X, h0, eps = 1.0, 1.0, 1e-4
    g = LevellingGrid(n, X, "reservoir", h_res=h0)
    kappa = (mode + 0.5) * math.pi / X
    rate = h0 ** 3 * kappa ** 4
    t_end = 1.0 / rate
    shape = np.cos(kappa * g.x)
    res = solve(g.problem(h0 + eps * shape), [0.0, t_end], method="cvode", rtol=1e-11, atol=1e-15)
    amp = np.dot(res.y[-1] - h0, shape) / np.dot(shape, shape)
    measured = -math.log(amp / eps) / t_end
    assert measured == pytest.approx(rate, rel=1e-2)
    # the discrete rate is closer still (same operator; the mobility perturbation biases the rate by
    # O(eps) ~ 1e-4 with this BC): checks the integration and the boundary ghosts, not the grid
    assert measured == pytest.approx(float(g.discrete_rate(kappa, h0)), rel=1e-3)


@pytest.mark.parametrize("bc", ["closed", "periodic"])
def test_volume_conserved_nonlinear(bc):
    # a deep depression with side ridges (large amplitude): the interior fluxes cancel pairwise
    n = 120
    g = LevellingGrid(n, 6.0, bc)
    x = g.x
    h = 1.0 - 0.95 * np.exp(-(x / 0.5) ** 2) + 0.8 * np.exp(-((x - 1.2) / 0.3) ** 2)
    v0 = g.volume(h)
    res = solve(g.problem(h), np.linspace(0.0, 5.0, 6), method="cvode", rtol=1e-8, atol=1e-12)
    assert res.success
    for y in res.y:
        assert abs(g.volume(y) - v0) < 1e-10 * v0
    # and it levels: the final profile is flatter than the initial one
    assert np.ptp(res.y[-1]) < 0.5 * np.ptp(h)


def test_chiu_kernel_thin_limit_and_formula():
    # g(H) = (1 - 4H e^{-2H} - e^{-4H})/(1 + e^{-2H})^2 = (2/3) H^3 (1 - 4/5 H^2 + O(H^4))
    for H in (1e-4, 1e-3, 0.01, 0.05, 0.1):
        g = chiu_kernel(H)
        assert abs(g / (2 / 3 * H ** 3) - (1 - 0.8 * H * H)) < 2 * H ** 4 + 1e-9
    # large H: g -> 1 (deep layer: rate sigma kappa / (2 eta), Chiu's capillary-wave limit)
    assert chiu_kernel(20.0) == pytest.approx(1.0, abs=1e-12)
    # the SI rate tends to the thin-film rate sigma h^3 kappa^4 / (3 eta)
    kap, h, s, e = 100.0, 1e-6, 0.036, 0.02
    assert chiu_rate(kap, h, s, e) == pytest.approx(chiu_rate(kap, h, s, e, thin=True), rel=1e-7)


def test_chiu_integral_reproduces_initial_gaussian():
    # F(xi) of f = D exp(-x^2/a^2) is D exp(-xi^2/4) / (a sqrt(pi)); zeta(x, 0) must give f back
    a, D = 1e-4, 1e-7
    F = lambda xi: D * math.exp(-xi * xi / 4) / (a * math.sqrt(math.pi))
    for x in (0.0, 0.5 * a, 1.5 * a):
        z = chiu_depression(x, 0.0, F, a, 1e-6, 0.036, 0.02)
        assert z == pytest.approx(D * math.exp(-(x / a) ** 2), rel=1e-8)


def test_nonlinear_mol_reproduces_chiu_in_linear_limit():
    # thin layer (h_inf/a' = 0.01) and small depression (1e-3 h_inf): the nonlinear MOL (reservoir far
    # away, X = 12 a') must agree with Chiu's Fourier integral (full Stokes kernel) at the centreline.
    a, hinf, sig, eta = 1e-4, 1e-6, 0.036, 0.02
    T = 3 * eta * a ** 4 / (sig * hinf ** 3)
    D = 1e-3 * hinf
    F = lambda xi: D * math.exp(-xi * xi / 4) / (a * math.sqrt(math.pi))
    g = LevellingGrid(240, 12.0, "reservoir")
    h0 = 1.0 - (D / hinf) * np.exp(-g.x ** 2)
    t_hat = np.array([0.0, 0.05, 0.5, 2.0])
    res = solve(g.problem(h0), t_hat, method="cvode", rtol=1e-9, atol=1e-14)
    for k in range(1, t_hat.size):
        for xa in (0.0, 1.0):
            i = int(np.argmin(np.abs(g.x - xa - 0.5 * g.dx)))  # cell centre next to xa
            z_mol = (1.0 - res.y[k][i]) * hinf
            z_chiu = chiu_depression(g.x[i] * a, t_hat[k] * T, F, a, hinf, sig, eta)
            assert abs(z_mol - z_chiu) < 1e-2 * abs(chiu_depression(0.0, t_hat[k] * T, F, a, hinf, sig, eta))


def test_grid_validation_messages():
    with pytest.raises(ValueError, match="n_cells"):
        LevellingGrid(3, 1.0)
    with pytest.raises(ValueError, match="bc"):
        LevellingGrid(10, 1.0, "open")
    with pytest.raises(ValueError, match="length"):
        LevellingGrid(10, -1.0)
