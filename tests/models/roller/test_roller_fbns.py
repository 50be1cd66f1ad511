"""The tapered roller's mass-conserving film (FBNS): the Jacobian pieces against finite differences, the
Schur reduction against the full Newton matrix, the same film as the Reynolds-condition form at the paper's
load, exact symmetry of an untilted symmetric roller, heavy loads."""

import numpy as np
import pytest

from transient.models.ehl.reduced import schur
from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.contact import M_EASY_2D
from transient.models.roller.results import EHLConvergenceError, UnderResolvedGridError
from transient.models.roller.roller_fbns import RollerContentFilm, content_start
from transient.params import park

E, RM = 220e9, 0.01
CASE = dict(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E)  # the paper's loading on a shorter roller


def roller(theta=10.0, tilt=0.0, start=0.2):
    return TaperedRoller(RM, theta, 2 * RM, 0.5 * RM, start * RM, tilt)


def paper(factor, grid="paper", tilt=0.002):
    return RollerContact.from_dimensionless(**dict(park.DIMENSIONLESS, W=park.DIMENSIONLESS["W"] * factor),
                                            roller=TaperedRoller(**dict(park.ROLLER, tilt_deg=tilt)),
                                            speed=park.SPEED, grid=grid)


def perturbed_state(c, scheme):
    """A state with a cavitated region (theta in (0.3, 1)) and pressure everywhere else, on a 14 x 12 grid."""
    g = c.make_grid("clustered", 14, 12)
    c.scheme = scheme
    cf = RollerContentFilm(c.film_problem(g))
    u = content_start(c, cf)
    n = cf.n
    rng = np.random.default_rng(3)
    u[:n] += 0.05 * rng.random(n)
    u[n: 2 * n] = np.where(rng.random(n) < 0.4, 0.3 + 0.7 * rng.random(n), 1.0)
    return cf, u


@pytest.mark.parametrize("scheme", ["upwind2", "limited", "upwind1"])
def test_content_jacobian_matches_finite_differences(scheme, fd_jacobian):
    c = RollerContact.from_dimensionless(**CASE, roller=roller(tilt=0.002), grid=("clustered", 40, 25))
    cf, u = perturbed_state(c, scheme)
    n = cf.n
    J = cf.jacobian_dense(u)
    fd = fd_jacobian(lambda v: cf.residual(v)[:n].copy(), u, n)
    assert np.max(np.abs(J[:n] - fd)) < 1e-6 * np.max(np.abs(fd))


def test_schur_matrix_is_the_newton_matrix_after_the_node_wise_substitution():
    c = RollerContact.from_dimensionless(**CASE, roller=roller(tilt=0.002), grid=("clustered", 40, 25))
    cf, u = perturbed_state(c, "upwind2")
    n = cf.n
    e = cf.equations(u)
    _, b_p, _, b_t = schur(cf, u, e)
    z = np.random.default_rng(4).standard_normal(n + 1)
    J = cf.jacobian_dense(u)
    du = np.concatenate([b_p * z[:n], b_t * z[:n], [z[n]]])
    full = J @ du
    S = cf.schur_matrix(e, b_p, b_t)
    assert np.allclose(S[:n] @ z, full[:n], rtol=0.0, atol=1e-10 * np.max(np.abs(full[:n])))
    assert S[n] @ z == pytest.approx(full[-1], rel=1e-12)


@pytest.fixture(scope="module")
def both_forms():
    """The tilted roller at the paper's loading by both forms (40 x 25 clustered grid)."""
    c = RollerContact.from_dimensionless(**CASE, roller=roller(tilt=0.002), grid=("clustered", 40, 25))
    return c.steady(method="reynolds", tol=1e-10), c.steady(method="fbns", tol=1e-10)


def test_content_form_gives_the_reynolds_condition_film_at_the_paper_load(both_forms):
    a, b = both_forms
    assert b.success and b.solver_info["method"] == "fbns"
    assert np.max(np.abs(a.pressure - b.pressure)) < 1e-8 * a.p_max
    assert np.max(np.abs(a.film - b.film)) < 1e-8 * a.h_central
    # the outlet cavitates: the content drops below 1 there, and only where the pressure is zero
    assert b.content.min() < 0.5
    assert np.all(b.pressure[b.content < 1.0 - 1e-9] <= 1e-9 * b.p_max)


def test_auto_takes_the_reynolds_condition_form_up_to_the_paper_load_and_fbns_above(both_forms):
    c = RollerContact.from_dimensionless(**CASE, roller=roller(tilt=0.002), grid=("clustered", 40, 25))
    assert c.mid_plane_M <= M_EASY_2D
    s = c.steady(tol=1e-10)
    assert s.solver_info["method"] == "reynolds"
    assert np.max(np.abs(s.pressure - both_forms[1].pressure)) < 1e-8 * s.p_max
    heavy = paper(5.0)
    assert heavy.mid_plane_M > M_EASY_2D
    info = {}
    heavy.steady_content = lambda *a: info.setdefault("method", "fbns")
    heavy.steady_reynolds = lambda *a: info.setdefault("method", "reynolds")
    heavy.steady()
    assert info["method"] == "fbns"


def test_untilted_symmetric_roller_gives_a_symmetric_film():
    c = RollerContact.from_dimensionless(**CASE, roller=roller(0.0, 0.0), grid=("clustered", 40, 25))
    s = c.steady(method="fbns", tol=1e-10)
    assert np.max(np.abs(c.grid.y + c.grid.y[::-1])) < 1e-9 * c.grid.y[-1]
    assert np.max(np.abs(s.pressure - s.pressure[::-1])) < 1e-8 * s.p_max
    assert np.max(np.abs(s.content - s.content[::-1])) < 1e-7


def test_method_is_validated():
    c = RollerContact.from_dimensionless(**CASE, roller=roller(), grid=("clustered", 40, 25))
    with pytest.raises(ValueError, match="method"):
        c.steady(method="newton")


def test_fifty_times_the_paper_load_is_refused_on_the_paper_grid_before_newton():
    c = paper(50.0)
    with pytest.raises(UnderResolvedGridError, match="4 b/M") as err:
        c.steady()
    r = err.value.resolution
    # the worst row is the loaded (small) end's, near its profile start, its x spacing ~13x the rule
    assert r["worst_ratio"] > 10.0 and r["worst_y"] < -0.6 * c.roller.mean_radius
    assert "nx >=" in str(err.value)


def _checks(c, s):
    assert s.success and abs(s.load_error) < 1e-6
    assert s.film[1:-1, 1:-1].min() > 0 and s.pressure.min() > -1e-9 * s.p_max
    assert s.content.min() >= 0.0 and s.content.max() <= 1.0 + 1e-9
    w = np.trapezoid(np.trapezoid(s.pressure, s.x, axis=1), s.y)
    assert w == pytest.approx(c.load, rel=0.02)
    assert s.y_of_h_min < -c.roller.profile_start and s.h_min < 0.5 * s.h_central


@pytest.mark.slow
def test_five_times_the_paper_load_on_the_paper_grid_from_the_dry_pressure():
    c = paper(5.0)
    s = c.steady()
    _checks(c, s)
    assert s.solver_info["levels"][-1]["grid"] == [94, 45]
    assert s.p_max == pytest.approx(c.dry().p_max, rel=0.25)


@pytest.mark.slow
def test_ten_times_the_paper_load_needs_the_loaded_ends_y_resolution():
    # 94 x 45: Newton from the dry pressure and the load path both stop, the film closing at the small end's
    # profiled part; doubling the y nodes (0.02 c there instead of 0.15 c) converges from the dry pressure
    c = paper(10.0, ("clustered", 94, 89))
    s = c.steady()
    _checks(c, s)
    coarse = paper(10.0)
    with pytest.raises(EHLConvergenceError, match="y nodes there"):
        coarse.steady()


def test_default_grid_doubles_the_y_nodes_above_the_papers_load():
    """Without ``grid``: the paper's 94 x 45 at its load, above it 111 y nodes (the clustered 89-node law plus the
    side lobes'; x uniform, as many nodes as the most loaded row needs), kept along the load path."""
    assert paper(1.0, None).grid_spec == ("clustered", 94, 45)
    heavy = paper(2.0, None)
    assert heavy.grid_spec == ("hybrid", 128, 111)
    assert heavy.with_load(0.5 * heavy.load).grid_spec == ("hybrid", 128, 111)
    assert paper(2.0).grid_spec == ("clustered", 94, 45)  # grid="paper" stays the paper's
