"""Periodic responses by shooting (transient.solvers.shooting, transient.models.journal.periodic; issue 14).

Expected values come from independent computations: closed forms (a forced linear system), brute-force time
integration until the orbit has settled, the eigenvalues of the linearised film + rotor model (a dense
eigenproblem of the analytic Jacobian at the static equilibrium), and the growth or decay of perturbed
transients. The journal cases run on a 24 x 4 half grid (periods of ~0.05 s); numbers in docs/validation.md.
"""

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.integrate import solve_ivp

from transient.analysis.periodic import NotPeriodicError
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.models.journal.periodic import (PeriodicOrbit, ResponseCurve, floquet_check, periodic_response,
                                               quasi_periodic_response, response_curve, stability_onset)
from transient.params import rho_kim
from transient.results import load_result
from transient.solvers.shooting import ShootingSettings, floquet_multipliers, newton_krylov, newton_picard
from transient import Integration, Recording

GRID = (24, 4)
ROTOR = rho_kim.ROTOR


# --------------------------------------------------------------------------------------------------
# the generic solver on systems with a closed form or an independent integration
# --------------------------------------------------------------------------------------------------

def _linear_system():
    """y' = A y + b cos t: a lightly damped pair (whirl-like), a strongly damped pair and 6 fast modes."""
    rng = np.random.default_rng(3)
    lam = np.array([-0.05 + 0.8j, -0.05 - 0.8j, -0.9 + 0.5j, -0.9 - 0.5j, -3, -4, -5, -6, -7, -8])
    X = np.eye(10) + 0.3 * rng.standard_normal((10, 10))
    D = sla.block_diag([[lam[0].real, lam[0].imag], [-lam[0].imag, lam[0].real]],
                       [[lam[2].real, lam[2].imag], [-lam[2].imag, lam[2].real]], np.diag(lam[4:].real))
    A = X @ D @ np.linalg.inv(X)
    b = rng.standard_normal(10)
    c = np.linalg.solve(1j * np.eye(10) - A, b)  # periodic solution Re(c e^{it})
    T = 2 * np.pi
    E = sla.expm(A * T)

    def flow(y, t0, period, rtol):
        yp0 = (c * np.exp(1j * t0)).real
        return yp0 + E @ (np.asarray(y) - yp0)  # exact: the periodic solution recurs after 2 pi

    return flow, (c * 1.0).real, np.exp(lam * T), X[:, :2]


def test_newton_picard_and_krylov_on_a_forced_linear_system():
    flow, y_star, mu, _ = _linear_system()
    V0 = np.eye(10)[:, :2]  # a poor basis: the true whirl subspace is X[:, :2]
    r = newton_picard(flow, np.zeros(10), 2 * np.pi, V0, settings=ShootingSettings(tol=1e-10, rtol=1e-8, second_ritz=True))
    assert r.success, r.message
    assert np.max(np.abs(r.state - y_star)) < 1e-9
    assert np.allclose(np.sort_complex(r.multipliers), np.sort_complex(mu[:2]), atol=1e-6)
    k = newton_krylov(flow, np.zeros(10), 2 * np.pi, settings=ShootingSettings(tol=1e-10, rtol=1e-8))
    assert k.success and np.max(np.abs(k.state - y_star)) < 1e-9
    vals, _, periods = floquet_multipliers(flow, y_star, 2 * np.pi, k=4, fd_step=1e-6)
    assert np.allclose(np.sort_complex(vals), np.sort_complex(mu[:4]), atol=1e-7)


def test_newton_picard_converges_on_a_forced_duffing_oscillator():
    """x'' + 0.2 x' + x + 0.5 x^3 = 0.6 cos t: the settled orbit of a long integration is the fixed point, and
    the decay of the settling run's Poincare distance is the dominant multiplier."""

    def rhs(t, y):
        return [y[1], -0.2 * y[1] - y[0] - 0.5 * y[0] ** 3 + 0.6 * np.cos(t)]

    def flow(y, t0, T, rtol):
        return solve_ivp(rhs, (t0, t0 + T), y, rtol=rtol, atol=1e-3 * rtol, method="DOP853").y[:, -1]

    long = solve_ivp(rhs, (0, 80 * np.pi), [0.0, 0.0], rtol=1e-12, atol=1e-14, method="DOP853",
                     t_eval=2 * np.pi * np.arange(41))
    r = newton_picard(flow, [0.0, 0.0], 2 * np.pi, np.eye(2), settings=ShootingSettings(tol=1e-9, rtol=1e-11, rtol_max=1e-6))
    assert r.success, r.message
    assert np.max(np.abs(r.state - long.y[:, -1])) < 1e-8
    d = np.linalg.norm(long.y[:, :-1].T - r.state, axis=1)
    k = np.flatnonzero((d < 1e-2) & (d > 1e-8))
    rate = np.exp(np.polyfit(k, np.log(d[k]), 1)[0])
    assert abs(rate - np.abs(r.multipliers).max()) < 0.02 * rate
    assert r.residual_norms[-1] < 1e-3 * r.residual_norms[0]


def test_a_shooting_that_cannot_converge_says_so():
    flow, *_ = _linear_system()
    r = newton_picard(flow, np.zeros(10), 2 * np.pi, np.eye(10)[:, :2],
                      settings=ShootingSettings(tol=1e-12, rtol=1e-8, max_iter=1))
    assert not r.success and "did not converge in 1 iterations" in r.message and len(r.residual_norms) == 1
    with pytest.raises(ValueError, match="rtol <= rtol_max"):
        ShootingSettings(rtol=1e-3, rtol_max=1e-4)


# --------------------------------------------------------------------------------------------------
# the journal orbit on a small grid
# --------------------------------------------------------------------------------------------------

def _orbit(speed, unbalance=ROTOR["unbalance"]):
    b = JournalBearing(**rho_kim.BEARING, grid=GRID)
    return JournalOrbit(b, ROTOR["rotor_mass"], unbalance, ROTOR["load"], speed)


def _linearised_multipliers(speed):
    """exp(2 pi lambda) of the eigenvalues of the film + rotor ODE Jacobian at the static equilibrium
    (groove cells left out), largest modulus first."""
    o = _orbit(speed, unbalance=0.0)
    prob = o.problem()
    pat = prob.jac_pattern
    data = np.empty(pat.nnz)
    prob.jac_rhs(0.0, prob.y0, data)
    J = sp.csc_matrix((data, pat.indices, pat.indptr), shape=pat.shape)
    keep = np.concatenate([np.flatnonzero(o.film.op.free), o.film.n + np.arange(4)])
    mu = np.exp(2 * np.pi * np.linalg.eigvals(J[keep][:, keep].toarray()))
    return mu[np.argsort(-np.abs(mu))]


@pytest.fixture(scope="module")
def settled():
    """Brute force from the linear start at rtol 1e-9, settled to ~1e-11 C: 12 revolutions at 3000 rpm
    (|mu| = 0.06), 36 at 6000 rpm (|mu| = 0.62), 64 outputs per revolution."""
    out = {}
    for speed, revs in ((3000.0, 12), (6000.0, 36)):
        o = _orbit(speed)
        r = o.run(revs, y0=o.linear_start(), integration=Integration(rtol=1e-9, atol=1e-12),
                  recording=Recording(outputs_per_revolution=64))
        out[speed] = (o, r)
    return out


@pytest.mark.parametrize("speed", [3000.0, 6000.0])
def test_periodic_orbit_is_the_settled_orbit(settled, speed):
    o, r = settled[speed]
    C = o.bearing.clearance
    p = periodic_response(o, rtol=1e-9, tol=1e-8)
    assert p.success and p.stable, p.message
    assert p.error_estimate < 1e-8 * C
    assert np.max(np.hypot(p.x - r.x[-65:], p.y - r.y[-65:])) < 2e-8 * C
    assert p.revolutions_integrated <= 12  # against ~25 (3000 rpm: 6) for settling to 1e-8 C


def test_dominant_multiplier_is_the_decay_rate_of_the_settling_transient(settled):
    o, r = settled[6000.0]
    C = o.bearing.clearance
    p = periodic_response(o, rtol=1e-9, tol=1e-8)
    n = o.film.n
    d = np.hypot(r.x[::64] / C - p.state[n], r.y[::64] / C - p.state[n + 1])
    k = np.flatnonzero((d < 1e-4) & (d > 1e-7))  # above the ~2e-9 C between the two maps' fixed points
    rate = np.exp(np.polyfit(k, np.log(d[k]), 1)[0])
    assert abs(rate - p.max_multiplier) < 0.03 * p.max_multiplier, (rate, p.max_multiplier)


def test_multipliers_are_the_linearised_model_eigenvalues_at_small_unbalance():
    """At e = 0.001 C the orbit hugs the equilibrium: its whirl pair is exp(2 pi lambda) of the linearised
    film + rotor model (not the quasi-steady K, C model, which misses the film's own dynamics)."""
    p = periodic_response(_orbit(6000.0, unbalance=1e-3 * rho_kim.BEARING["clearance"]), rtol=1e-8)
    lin = _linearised_multipliers(6000.0)[:2]
    assert np.abs(np.sort_complex(p.multipliers) - np.sort_complex(lin)).max() < 2e-3, (p.multipliers, lin)


def test_arnoldi_on_the_full_monodromy_confirms_the_ritz_values():
    o = _orbit(6000.0)
    p = periodic_response(o, rtol=1e-8)
    mu, share, _ = floquet_check(o, p, k=4)
    assert np.abs(np.sort_complex(mu[:2]) - np.sort_complex(p.multipliers)).max() < 3e-3
    assert np.all(np.abs(mu[2:]) < 1e-2)  # everything else (the second rotor pair, the film) is wiped out
    assert np.all(share[:2] > 0.9)  # the dominant pair is the rotor's


def test_stability_changes_across_the_onset():
    """Bracket the crossing of the linearised model (independent), then: below it the periodic orbit is
    stable and a perturbed transient decays onto it; above it the dominant multiplier is outside the unit
    circle, the result says so, and the perturbed transient grows (quasi-periodic whirl)."""
    g = lambda s: np.abs(_linearised_multipliers(s)[0]) - 1.0  # noqa: E731
    lo, hi = 7000.0, 9500.0
    assert g(lo) < 0 < g(hi)
    for _ in range(6):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) < 0 else (lo, mid)
    onset = 0.5 * (lo + hi)
    curve = response_curve(_orbit(0.96 * onset), [0.96 * onset, 0.98 * onset, 1.02 * onset, 1.04 * onset], rtol=1e-6)
    assert list(curve.unstable) == [False, False, True, True]
    assert abs(curve.onset_rpm - onset) < 0.02 * onset, (curve.onset_rpm, onset)
    below, above = curve.orbits[1], curve.orbits[2]
    assert below.success and not above.success and above.converged
    refined = stability_onset(_orbit(below.speed_rpm), below, above, rtol=1e-6, tol_rpm=5.0)
    assert abs(refined.onset_rpm - onset) < 0.02 * onset and refined.speed_rpm.size >= 3
    assert f"no stable periodic orbit at {above.speed_rpm:g} rpm (dominant multiplier |mu| = " in above.message
    for p, grows in ((below, False), (above, True)):
        o = _orbit(p.speed_rpm)
        w = quasi_periodic_response(o, 24, start=p, perturbation=1e-3, rtol=1e-6)
        n = o.film.n
        C = o.bearing.clearance
        d = np.hypot(w.poincare_x / C - p.state[n], w.poincare_y / C - p.state[n + 1])
        assert (d[-1] > d[1]) == grows, d
    assert 0.3 < w.whirl_frequency_ratio < 0.7


def test_response_curve_follows_the_linear_response_and_saves(tmp_path):
    o = _orbit(2000.0)
    c = response_curve(o, [2000.0, 2500.0, 3000.0], rtol=1e-6)
    assert c.success and c.converged.all() and not c.unstable.any()
    for s, a in zip(c.speed_rpm, c.semi_major):  # small orbits: the linearised K, C response
        Z = o.bearing.unbalance_response(o.rotor_mass, o.unbalance, o.load, s)
        lin = np.linalg.svd(np.array([[Z[0].real, -Z[0].imag], [Z[1].real, -Z[1].imag]]), compute_uv=False)[0]
        assert abs(a - lin) < 0.03 * lin
    assert c.revolutions_integrated.max() <= 8  # relax, 2-3 iterations, 2 derivatives (+2 on a fresh basis)
    back = load_result(c.save(tmp_path / "curve"))
    assert isinstance(back, ResponseCurve) and isinstance(back.orbits[0], PeriodicOrbit)
    assert np.array_equal(back.multipliers, c.multipliers) and back.orbits[2].state.shape == (o.n,)


def test_nonconvergence_reports_the_history_and_falls_back_to_integration():
    o = _orbit(5000.0)
    p = periodic_response(o, rtol=1e-7, shooting=ShootingSettings(max_iter=1, relax=1))
    assert not p.success and not p.converged and "residual history [C]" in p.message
    q = periodic_response(o, rtol=1e-7, shooting=ShootingSettings(max_iter=1), fallback=True)
    ref = periodic_response(o, rtol=1e-7)
    assert q.converged and "settled by time integration" in q.message
    assert np.max(np.abs(q.state[o.film.n:] - ref.state[o.film.n:])) < 1e-5
    with pytest.raises(ValueError, match="method"):
        periodic_response(o, method="harmonic balance")
    with pytest.raises(ValueError, match="monotone"):
        response_curve(o, [3000.0, 2000.0, 2500.0])


def test_noise_from_the_periodic_state_equals_the_settled_noise():
    from transient.study.noise import bearing_noise

    o = _orbit(4000.0)
    a = bearing_noise(o, revolutions=2, harmonics=3, periodic=True, tol=1e-6, integration=Integration(rtol=1e-7))
    b = bearing_noise(o, revolutions=2, harmonics=3, periodic=False, tol=1e-6, integration=Integration(rtol=1e-7))
    assert abs(a.level_db - b.level_db) < 1e-3 and np.allclose(a.harmonic_levels_db, b.harmonic_levels_db, atol=0.02)
    with pytest.raises(NotPeriodicError, match="no stable periodic orbit"):
        bearing_noise(_orbit(9500.0), revolutions=1, harmonics=2, integration=Integration(rtol=1e-5))


# --------------------------------------------------------------------------------------------------
# the period map on BDF2, the residual behind the verdict
# --------------------------------------------------------------------------------------------------

def test_bdf2_period_map_gives_the_ida_orbit_and_the_settled_one(settled):
    """The conservative BDF2 (content film) and IDA (universal film) integrate the same semi-discrete model: their
    periodic orbits agree within BDF2's own time-discretisation error (second order at its 550-step cap: ~1e-6 C
    per revolution at this orbit size), and both with the brute-force settled orbit."""
    o, r = settled[6000.0]
    C = o.bearing.clearance
    a = periodic_response(o, rtol=1e-8, tol=1e-8)
    b = periodic_response(o, rtol=1e-8, tol=1e-8, integrator="bdf2")
    assert a.success and b.success and b.integrator == "bdf2", b.message
    assert np.max(np.hypot(a.x - r.x[-65:], a.y - r.y[-65:])) < 2e-8 * C
    assert np.max(np.hypot(b.x - r.x[-65:], b.y - r.y[-65:])) < 1e-6 * C  # measured 1.1e-7 C
    assert abs(b.max_multiplier - a.max_multiplier) < 1e-2
    with pytest.raises(ValueError, match="integrator"):
        periodic_response(o, integrator="rk4")


def test_the_converged_verdict_is_backed_by_a_measured_residual():
    """An independent run of one revolution from the accepted state returns to it within tol."""
    o = _orbit(5000.0)
    C, n, tol = o.bearing.clearance, o.film.n, 1e-6
    p = periodic_response(o, rtol=1e-7, tol=tol)
    assert p.converged and p.residual <= tol * C and p.error_estimate <= tol * C
    run = o.run(1, y0=p.state, integration=Integration(rtol=1e-9, atol=1e-12),
                recording=Recording(outputs_per_revolution=8))
    assert np.max(np.abs(run.final_state[n:] - p.state[n:])) < 2 * tol


def test_the_period_maps_cost_levers_leave_the_orbit_unchanged(monkeypatch):
    """IDA's first step in each period (``IDA_FIRST_STEP``) and the periods integrated to their end only (the
    derivatives, the loose iterations) change the cost, not the result: the periodic orbit is IDA's own-first-step
    orbit to the fixed-point tolerance (each within tol of the fixed point, the map's noise ~0.2 rtol), and a period
    integrated without its intermediate outputs ends where the sampled one does."""
    import transient.models.journal.periodic as periodic

    o = _orbit(6000.0)
    n = o.film.n
    p = periodic_response(o, rtol=1e-7, tol=1e-7)
    monkeypatch.setattr(periodic, "IDA_FIRST_STEP", 0.0)
    q = periodic_response(o, rtol=1e-7, tol=1e-7)
    assert p.converged and q.converged
    assert np.max(np.abs(p.state[n:] - q.state[n:])) < 3e-7
    assert abs(p.max_multiplier - q.max_multiplier) < 5e-3
    F = periodic._Flow(o, 16, accept_rtol=1e-6, first_step=0.01)
    z = F.reduce(p.state)
    sampled = F(z, 0.0, 2 * np.pi, 1e-6)
    end_only = F(z + 0.0, 0.0, 2 * np.pi, 1e-6, sample=False)
    assert F.samples[z.tobytes()][1].size == 17 and len(F.samples) == 1
    assert np.max(np.abs(sampled[-4:] - end_only[-4:])) < 1e-7
