"""The rotor-bearing system linearised: the quasi-static (K, C) analyses against the single bearing's, the
linearisation with the film states against the time domain (forced response and growth rate), the stability
thresholds."""

import numpy as np
import pytest

from transient import JournalBearing, Recording, Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING

M_ROTOR, ECC, G = 100.0, 0.8e-6, 9.81


@pytest.fixture(scope="module")
def bearing():
    return JournalBearing(**BEARING, grid=(48, 8))


def harmonic(x, per):
    """The 1x complex amplitude of the last revolution of a series with ``per`` outputs per revolution."""
    seg = np.asarray(x)[-per - 1:-1]
    return 2 * np.mean(seg * np.exp(-2j * np.pi * np.arange(per) / per))


def test_one_node_quasi_static_analyses_are_the_bearings(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    lin = s.unbalance_response(6000, film_states=False)
    assert lin.linearisation == "K and C"
    Z = bearing.unbalance_response(M_ROTOR, ECC, M_ROTOR * G, 6000)
    assert np.allclose(lin.position(0), Z, rtol=1e-7)
    assert s.growth_rate(6000, film_states=False) == pytest.approx(bearing.growth_rate(M_ROTOR, M_ROTOR * G, 6000),
                                                                   rel=1e-7)


def test_film_state_eigenvalue_is_the_time_domain_decay(bearing):
    """A free vibration from the equilibrium decays at the real part of the least stable eigenvalue of the
    linearisation with the film states (not at the quasi-static one)."""
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, gravity=G)
    eq = s.equilibrium(6000)
    lam = s.eigenvalues(6000, equilibrium=eq)[-1]
    qs = np.max(s.quasi_static_eigenvalues(6000, eq).real)
    y = eq.state.copy()
    y[s.dae(6000).Q0] += 0.01
    r = s.run(12, 6000, start=(0.0, y), recording=Recording(outputs_per_revolution=64))
    x, yy = r.position(0)
    e = np.hypot(x - eq.position(0)[0], yy - eq.position(0)[1])[:12 * 64].reshape(12, 64).max(axis=1)
    rate = np.polyfit(r.t[:12 * 64:64][4:], np.log(e[4:]), 1)[0]
    assert rate == pytest.approx(lam.real, rel=0.02)
    assert abs(qs - lam.real) > 0.05 * abs(lam.real)  # the film's own dynamics matter here


def test_small_unbalance_settles_on_the_film_state_linear_response(bearing):
    """A flexible rotor on two bearings started on the linear response with the film states stays on it (its
    slowest mode decays by e^-8 over the run, so a wrong start would have moved): every node within 1e-3."""
    s = RotorBearingSystem(Rotor.jeffcott(2e7, 90.0, 5.0), {0: bearing, 2: bearing}, unbalance=[(1, 2e-5, 0.0)])
    lin = s.unbalance_response(3000, film_states=True)
    slowest = s.eigenvalues(3000)[-1].real
    assert slowest * 7 * 60 / 3000 < -8
    per = 32
    r = s.run(8, 3000, start=(0.0, s.linear_start(3000)), recording=Recording(outputs_per_revolution=per))
    for node in (0, 1, 2):
        for settled, linear in zip(r.position(node), lin.position(node)):
            assert abs(harmonic(settled, per) - linear) < 1e-3 * abs(linear)
    assert abs(lin.position(1)[0]) > 1e-3 * bearing.clearance


def test_two_bearing_quasi_static_growth_is_the_half_rotors(bearing):
    """The symmetric rigid rotor on two identical bearings has the quasi-static growth rates (whose zero is the
    threshold) of half its mass on one bearing, below and above the onset."""
    s = RotorBearingSystem(Rotor.rigid(M_ROTOR, 3.0, 0.5), {0: bearing, 1: bearing}, gravity=G)
    for n in (6000.0, 9000.0):
        half = bearing.growth_rate(M_ROTOR / 2, M_ROTOR * G / 2, n)
        assert s.growth_rate(n, film_states=False) == pytest.approx(half, rel=1e-6)


def free_growth_rate(s, speed, revolutions=16, per=64):
    """Growth rate [1/s] of a free vibration from the equilibrium at ``speed`` [rpm] (time domain): the slope of
    the log of the per-revolution peak distance from the equilibrium over the second half of the run."""
    eq = s.equilibrium(speed)
    y = eq.state.copy()
    y[s.dae(speed).Q0] += 0.01
    r = s.run(revolutions, speed, start=(0.0, y), recording=Recording(outputs_per_revolution=per))
    x, yy = r.position(0)
    n = revolutions * per
    e = np.hypot(x - eq.position(0)[0], yy - eq.position(0)[1])[:n].reshape(revolutions, per).max(axis=1)
    half = revolutions // 2
    return np.polyfit(r.t[:n:per][half:], np.log(e[half:]), 1)[0]


@pytest.mark.slow
def test_time_domain_threshold_is_the_film_state_threshold(bearing):
    """The growth rate of free runs 3 % either side of the linearised threshold (film states) changes sign, and
    its zero (linear interpolation) lies within 1 % of it; the quasi-static threshold is higher."""
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, gravity=G)
    n_film = s.stability_threshold((4000.0, 12000.0))
    n_qs = s.stability_threshold((4000.0, 12000.0), film_states=False)
    lo, hi = 0.97 * n_film, 1.03 * n_film
    g_lo, g_hi = free_growth_rate(s, lo), free_growth_rate(s, hi)
    assert g_lo < 0 < g_hi
    n_time = lo - g_lo * (hi - lo) / (g_hi - g_lo)
    assert n_time == pytest.approx(n_film, rel=0.01)
    assert n_qs > 1.02 * n_film


def test_periodic_response_of_one_node_is_the_orbits(bearing):
    """Shooting on the system's period map gives the single-bearing orbit's periodic response and multipliers."""
    from transient import JournalOrbit

    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    p = s.periodic_response(6000)
    o = JournalOrbit(bearing, M_ROTOR, ECC, M_ROTOR * G, 6000).periodic_response()
    assert p.success and p.error_estimate <= 1e-6
    x, y = p.position(0)
    assert np.max(np.hypot(x - o.x, y - o.y)) < 1e-5 * bearing.clearance
    assert np.ptp(x) > 0.02 * bearing.clearance
    assert np.allclose(np.sort_complex(p.multipliers[:2]), np.sort_complex(o.multipliers[:2]), atol=1e-2)


def test_steady_and_linear_results_save_and_load(bearing, tmp_path):
    from transient.results import load_result

    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    for r in (s.equilibrium(6000), s.unbalance_response(6000)):
        back = load_result(r.save(tmp_path / type(r).__name__))
        assert type(back) is type(r) and back.units()["displacement"] == "m"
        assert np.array_equal(np.asarray(back.position(0)), np.asarray(r.position(0)))
