"""The jump of a rigid rotor on a squeeze-film damper (``scenarios/damper_jump.py``'s system): the circular orbits
against the rigid rotor's own scalar equation, their continuation through both folds, the whole system's shooting on
each branch (Floquet multipliers: both outer branches stable, the one between the folds a saddle) and a speed ramp
that jumps past the fold."""

import numpy as np
import pytest

from transient import JournalBearing, LongRun, Recording, Rotor, RotorBearingSystem, SqueezeFilmDamper
from transient.models.rotor.circular_orbits import CircularOrbits, first_orbit, orbits_at_speed
from transient.units import rpm_to_rad_s

C, MASS, K = 100e-6, 20.0, 2e6
DAMPER = dict(diameter=0.1, length=0.01, clearance=C, viscosity=0.01, supply_pressure=5e3, centring_stiffness=K)
UNBALANCE = 0.3 * MASS * C


def _system(grid=(16, 2), **kw):
    d = SqueezeFilmDamper(**DAMPER, grid=grid)
    return RotorBearingSystem(Rotor(mass=MASS * np.eye(2), stiffness=np.zeros((2, 2))), {0: d},
                              unbalance=[(0, UNBALANCE, 0.0)], **dict(dict(gravity=0.0), **kw))


def _scalar_residual(d, z, speed_rpm):
    """The rigid rotor's circular orbit written out: (k - m w^2 - f / e) Z = m e w^2 with the film force
    f = F_r + i F_t along and across the line of centres (relative to the unbalance force)."""
    w = rpm_to_rad_s(speed_rpm)
    eps = abs(z)
    o = d.circular_orbit(eps, speed_rpm)
    f = complex(o.radial_force, o.tangential_force)
    return abs((K - MASS * w * w - f / (eps * C)) * z * C - UNBALANCE * w * w) / (UNBALANCE * w * w)


def test_a_circular_orbit_solves_the_rigid_rotors_equation():
    s = _system()
    for speed in (3000.0, 7000.0):
        x = first_orbit(CircularOrbits(s, speed), speed)
        assert x[-1] == pytest.approx(1.0)
        z = complex(x[0], x[1])
        assert _scalar_residual(s.dampers[0], z, speed) < 1e-8


def test_what_circular_orbits_refuse():
    with pytest.raises(ValueError, match="gravity"):
        _system(gravity=9.81).circular_orbits((3000, 6000))
    d = SqueezeFilmDamper(**DAMPER, grid=(16, 2))
    b = JournalBearing(0.1, 0.02, 100e-6, 0.01, grid=(16, 2))
    two = RotorBearingSystem(Rotor.jeffcott(1e7, 20.0, 2.0), {0: d, 2: b}, unbalance=[(1, 1e-4, 0.0)], gravity=0.0)
    with pytest.raises(ValueError, match="every film"):
        two.circular_orbits((3000, 6000))
    lopsided = Rotor(mass=MASS * np.eye(2), stiffness=np.diag([0.0, 1e6]))
    s = RotorBearingSystem(lopsided, {0: d}, unbalance=[(0, UNBALANCE, 0.0)], gravity=0.0)
    with pytest.raises(ValueError, match="axisymmetric"):
        s.circular_orbits((3000, 6000))


def _jeffcott_on_dampers(gravity):
    """test_system_damper.py's Jeffcott rotor in two end-fed dampers with centring springs (full film)."""
    d = SqueezeFilmDamper(diameter=0.1, length=0.02, clearance=200e-6, viscosity=0.01, supply_pressure=2e5,
                          centring_stiffness=5e6, grid=(24, 2))
    return RotorBearingSystem(Rotor.jeffcott(1e7, 20.0, 2.0), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)],
                              gravity=gravity)


@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_shooting_on_dampers_converges_from_its_default_start(gravity):
    """Without gravity the shooting starts on the circular orbit, with it on the linear response with the film
    states; either way on the rotor's own states as the basis. Its orbit is the one a run from the static
    equilibrium settles on: 30 revolutions (IDA; the slowest multiplier 0.63 leaves 1e-6 of the start), sampled at
    the same shaft angles (measured: 2e-5 of the orbit radius apart without gravity)."""
    s = _jeffcott_on_dampers(gravity)
    p = s.periodic_response(6000.0)
    assert p.success and p.stable, p.message
    r = s.run(30, 6000.0, recording=Recording(outputs_per_revolution=64), long_run=LongRun(progress=False))
    assert r.success, r.message
    for node in (0, 1, 2):
        shot, run = np.array(p.position(node)), np.array([v[-65:] for v in r.position(node)])
        assert np.max(np.abs(shot - run)) < 1e-3 * np.max(np.hypot(*run))
    e = np.hypot(*p.position(0)) / 200e-6
    if gravity == 0.0:
        assert np.ptp(e) < 1e-4 * e.mean()  # circular and centred
    else:
        assert np.ptp(e) > 0.01  # the orbit about the static sag is not centred


@pytest.mark.slow
def test_the_jump_both_branches_their_floquet_multipliers_and_a_ramp_that_jumps_at_the_fold():
    """scenarios/damper_jump.py's rotor on 24 x 4 cells. The path of circular orbits folds twice; between the folds
    the speed has three orbits: the outer two stable, the middle one a saddle (a real multiplier above 1), each within
    2 % of its circular orbit (the whirling frame's film against the time-domain film); outside them one orbit. A
    run-down from the lower branch (BDF2, 80 revolutions) jumps up past the lower fold, within 2 % of it. Measured:
    folds 6683.7 and 4944.5 rpm; at 6000 rpm e/c 0.8358 / 0.7962 / 0.4394 against 0.8356 / 0.8082 / 0.4385, |mu|
    0.321 / 1.961 / 0.636; the run-down 5640 -> 4300 rpm jumps at 4902 rpm (-0.86 %)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parents[3] / "scenarios"))
    import damper_jump as scenario

    s = scenario.system()
    curve = s.circular_orbits((4000.0, 7500.0))
    assert curve.success and curve.folds_rpm.size == 2, curve.message
    low, high = sorted(curve.folds_rpm)
    assert np.all(curve.backward[curve.fold_index[0] + 1:curve.fold_index[1] + 1])
    assert len(orbits_at_speed(s, curve, 0.95 * low)) == 1 and len(orbits_at_speed(s, curve, 1.05 * high)) == 1
    speed = 0.5 * (low + high)
    found = orbits_at_speed(s, curve, speed)
    assert len(found) == 3
    for k, z in enumerate(found):
        p = s.periodic_response(speed, start=s.circular_orbit_state(speed, z), integrator="bdf2")
        assert p.converged, p.message
        e = np.hypot(*p.position(0)) / C
        assert e.mean() == pytest.approx(abs(z[0]), rel=0.02)
        mu = np.asarray(p.multipliers)
        if k == 1:
            assert not p.stable and abs(mu[0].imag) < 1e-6 and mu[0].real > 1.0
        else:
            assert p.stable
    n0 = low + 0.4 * (high - low)
    found = orbits_at_speed(s, curve, n0)
    p = s.periodic_response(n0, start=s.circular_orbit_state(n0, found[-1]), integrator="bdf2")
    r, eps, jump, _ = scenario.ramp(s, n0, low - 650.0, p.state, abs(found[0][0]), 80)
    assert r.success, r.message
    assert eps[0] < 0.5 and eps[-1] > 0.7
    assert 0.98 * low < jump < low


def test_the_jump_figure_names_units():
    import sys
    from pathlib import Path

    import transient.plots as tp
    from transient.models.rotor.circular_orbits import CircularOrbitCurve

    sys.path.insert(0, str(Path(__file__).parents[2]))
    from figure_checks import figure_problems

    n = np.array([4000.0, 5000.0, 6000.0, 5500.0, 6500.0])
    eps = np.array([[0.5], [0.8], [0.85], [0.6], [0.4]])
    curve = CircularOrbitCurve(speed_rpm=n, eccentricity_ratio=eps, amplitude=eps + 0j, radial_force=-eps,
                               tangential_force=-eps, transmitted_force=100 * eps, arclength=np.arange(5.0),
                               speed_slope=np.array([1.0, 1.0, 0.1, -1.0, 1.0]), folds_rpm=np.array([6100.0, 5400.0]),
                               fold_eccentricity=np.array([0.85, 0.55]), fold_index=np.array([2, 3]), damper_nodes=[0])
    fig = tp.damper.jump(curve, {"ramp": (n, eps[:, 0], 100 * eps[:, 0])}, [(6000.0, 0.85, 85.0, True)], "jump")
    assert figure_problems(fig) == []
