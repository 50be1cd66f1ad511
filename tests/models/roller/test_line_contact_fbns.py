"""The line contact's film-content form and its FBNS Newton: Jacobian against finite differences, the same
discrete film as the Reynolds-condition solver, cold starts at the corners of the Moes chart, the whole chart."""

import math
import warnings

import numpy as np
import pytest

from transient.models.roller.line_contact import FilmResolutionWarning
from transient.models.roller.line_fbns import LineContentFilm, schur_system
from transient.models.roller.line_newton import content_newton
from transient.models.roller.line_sequence import cold_start, solve_sequence
from transient.physics.line_formulas import moes_central
from transient.study.ehl_chart import chart_contact, chart_point


def _state(lf, seed=0):
    rng = np.random.default_rng(seed)
    n = lf.n
    return np.concatenate([np.abs(rng.normal(0.3, 0.2, n)), rng.uniform(0.4, 1.0, n), [0.5]])


@pytest.mark.parametrize("density,law,grid", [("incompressible", "barus", "clustered"),
                                              ("dowson-higginson", "roelands", "uniform")])
def test_schur_matrix_is_the_jacobian_of_the_reynolds_rows(fd_jacobian, density, law, grid):
    c = chart_contact(20.0, 5.0, nodes=81, grid=grid, density=density, viscosity_law=law)
    lf = LineContentFilm(c.film_problem())
    n = lf.n
    u = _state(lf)
    e = lf.equations(u)
    ones, zeros = np.ones(n), np.zeros(n)
    S_p = lf.schur_matrix(e, ones, zeros)  # dR/dp, dR/dh0; the load row
    S_t = lf.schur_matrix(e, zeros, ones)  # dR/dtheta
    J = fd_jacobian(lambda v: np.append(lf.equations(v)["res"], lf.equations(v)["load"]), u, n + 1)
    scale = np.abs(J).max()
    assert np.abs(S_p[:, :n] - J[:, :n]).max() < 1e-7 * scale
    assert np.abs(S_p[:, n] - J[:, -1]).max() < 1e-7 * scale
    assert np.abs(S_t[:n, :n] - J[:n, n: 2 * n]).max() < 1e-7 * scale
    # the right-hand side's products are the same blocks
    v_p, v_t = np.random.default_rng(1).normal(size=(2, n))
    assert np.allclose(lf.jacobian_product(e, v_p, v_t), J[:n, :n] @ v_p + J[:n, n: 2 * n] @ v_t,
                       atol=1e-7 * scale * np.abs(v_p).sum())


def test_schur_step_solves_the_full_newton_system():
    """The node-wise elimination: the step from the Schur system satisfies the unreduced linearisation."""
    c = chart_contact(20.0, 5.0, nodes=81)
    lf = LineContentFilm(c.film_problem())
    n = lf.n
    u = _state(lf, 2)
    u[:n:3] = 0.0  # some nodes at p = 0, some at theta = 1, one at the kink
    u[n + 1: 2 * n: 4] = 1.0
    u[n] = 1.0
    e = lf.equations(u)
    S, r, (a_p, b_p, a_th, b_t) = schur_system(lf, u, e)
    z = np.linalg.solve(S, r)
    dp, dt = a_p + b_p * z[:n], a_th + b_t * z[:n]
    alpha, gamma = lf.fb_derivatives(u, e)
    assert np.allclose(alpha * dp + gamma * dt, -e["fb"], atol=1e-12)
    lin = e["res"] + lf.jacobian_product(e, dp, dt) + lf.schur_matrix(e, np.ones(n), np.zeros(n))[:n, n] * z[n]
    assert np.abs(lin).max() < 1e-8 * np.abs(e["res"]).max()
    assert e["load"] + lf.weight @ dp == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("M,L,nodes", [(10.0, 5.0, 257), (100.0, 10.0, 257), (3.0, 20.0, 257)])
def test_same_discrete_film_as_the_reynolds_condition_solver(M, L, nodes):
    c = chart_contact(M, L, nodes=nodes)
    new = c.steady()
    old = c.steady_reynolds()
    assert "film-content Newton" in new.message
    assert np.abs(new.film / old.film - 1.0).max() < 1e-8
    assert np.abs(new.pressure - old.pressure).max() < 1e-8 * old.p_max
    # the film-content solution satisfies the Reynolds-condition equations as they are
    assert new.residual_norms[-1] <= 1e-9
    assert new.iterations < old.iterations


@pytest.mark.parametrize("M,L", [(1.0, 0.0), (1.0, 25.0), (1000.0, 0.0), (1000.0, 25.0)])
def test_chart_corners_from_cold_starts_on_a_modest_grid(M, L):
    c = chart_contact(M, L, nodes=513)
    seq = solve_sequence(c, tol=1e-10)
    assert seq.success, seq.message
    s = c.steady()
    assert s.success and "film-content Newton" in s.message and s.h_min > 0.0
    assert s.residual_norms[-1] <= 1e-9 and abs(s.load_error) < 1e-9
    # the content is 1 wherever there is pressure, and below 1 only downstream of the contact
    lf, u = seq.content, seq.state
    p, theta = u[: lf.n], u[lf.n: 2 * lf.n]
    x = lf.x[1:-1]
    assert np.all(theta[p > 1e-12] > 1.0 - 1e-9)
    assert np.all(x[theta < 1.0 - 1e-6] > 0.0)


def test_cold_start_has_no_kink_downstream_and_the_inlet_ramp_scaled_by_alpha():
    c = chart_contact(1000.0, 25.0, nodes=257)
    f = c.film_problem()
    u = cold_start(c, f)
    n = f.n
    x = f.grid.x[1:-1]
    p, theta = u[:n], u[n: 2 * n]
    hc = moes_central(c.M, c.L) * math.sqrt(2.0 * c.U) * c.radius / c.film_scale
    assert float(np.interp(0.0, f.grid.x, f.film(p, u[-1]))) == pytest.approx(hc)
    h = f.film(p, u[-1])[1:-1]
    down = x > 1.0
    assert np.all(p[down] == 0.0) and np.all(theta[down] <= 1.0)
    assert np.allclose((theta * h)[down & (h > hc)], hc)  # carried at the central flux, off the kink
    ap = c.lubricant.pressure_viscosity * c.p_h
    assert p[x < -1.0].max() <= 0.5 / ap + 1e-15


def test_failed_newton_reports_its_history():
    c = chart_contact(1000.0, 25.0, nodes=257)
    lf = LineContentFilm(c.film_problem())
    u, ok, st = content_newton(lf, cold_start(c, lf.base), max_iter=2)
    assert not ok and st.iterations <= 2 and len(st.norms) == st.iterations + 1


@pytest.mark.slow
def test_whole_moes_chart_on_1025_nodes_converges_with_the_film_content_newton():
    for M in (1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0):
        for L in (0.0, 2.0, 5.0, 10.0, 20.0, 25.0):
            r = chart_point(M, L, nodes=1025)
            assert r["success"] and "film-content Newton" in r["message"], (M, L, r["message"])
            assert r["residual"] <= 1e-9 and r["H_min"] > 0


def test_overflowed_viscosity_gives_the_vanishing_flow_limit_not_nan():
    """Roelands with the chart's largest alpha (Z = 1.8) overflows exp near 2.5 GPa: eps and its derivatives
    there are 0 (their limit), not inf/inf, and the Jacobian stays finite."""
    c = chart_contact(1000.0, 25.0, nodes=257, viscosity_law="roelands")
    lf = LineContentFilm(c.film_problem())
    u = cold_start(c, lf.base)
    u[: lf.n] *= 1.0 + (u[: lf.n] > 0.5)  # pressures up to 2 p_h = 11.7 GPa: eta/eta0 beyond the double range
    with np.errstate(over="ignore", invalid="ignore"):
        eta = c.lubricant.eta(u[: lf.n].max() * c.p_h)[0]
        e = lf.equations(u)
    assert not np.isfinite(eta)
    for key in ("res", "dp", "dh", "dt"):
        assert np.all(np.isfinite(e[key])), key
    hot = lf.x[1:-1][u[: lf.n] * c.p_h > 3e9]
    assert hot.size and np.all(lf.props[2][1:-1][u[: lf.n] * c.p_h > 3e9] == 0.0)


@pytest.mark.parametrize("law,density,grid", [("roelands", "incompressible", "clustered"),
                                              ("roelands", "dowson-higginson", "clustered"),
                                              ("barus", "dowson-higginson", "clustered"),
                                              ("barus", "incompressible", "uniform"),
                                              ("roelands", "dowson-higginson", "uniform")])
def test_heaviest_chart_corner_converges_for_every_lubricant_and_grid(law, density, grid):
    """M = 1000, L = 25 from a cold start on 1025 nodes (Roelands there reaches eta/eta0 = inf)."""
    r = chart_point(1000.0, 25.0, nodes=1025, grid=grid, density=density, viscosity_law=law)
    assert r["success"] and "film-content Newton" in r["message"], r["message"]
    assert r["residual"] <= 1e-9 and r["H_min"] > 0


@pytest.mark.parametrize("M,L", [(1000.0, 0.0), (1.0, 0.0)])
def test_uniform_grid_chart_corners_converge(M, L):
    """Both converge; at M = 1000 the uniform grid (0.0054 b) is too coarse at the inlet edge: flagged."""
    r = chart_point(M, L, nodes=1025, grid="uniform")
    assert r["success"] and "film-content Newton" in r["message"], r["message"]
    assert r["residual"] <= 1e-9 and r["H_min"] > 0
    assert r["resolved"] is (M < 100.0)


def test_under_resolved_film_warns_and_says_so_in_its_message():
    c = chart_contact(1000.0, 10.0, nodes=1025, grid="uniform")
    with pytest.warns(FilmResolutionWarning, match="inlet edge"):
        s = c.steady()
    assert s.success and "under-resolved" in s.message
    with warnings.catch_warnings():
        warnings.simplefilter("error", FilmResolutionWarning)
        assert "under-resolved" not in chart_contact(1000.0, 10.0, nodes=1025).steady().message


def test_clustered_chart_grid_puts_h_c_near_its_grid_limit_at_m_1000():
    """The chart grid's inlet cluster: H_c on 1025 nodes against 2049 nodes at M = 1000, L = 10 (the
    Richardson limit from 1025/2049/4097 is 3.266, docs/validation.md): within 0.5 %."""
    a = chart_point(1000.0, 10.0, nodes=1025)
    b = chart_point(1000.0, 10.0, nodes=2049)
    assert a["success"] and b["success"]
    assert abs(a["H_c"] / b["H_c"] - 1.0) < 5e-3
