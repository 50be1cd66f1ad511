"""One speed law for every journal orbit (models/journal/speed_law.py): the law against closed forms, a constant law
equal to the constant-speed run (smooth, rough, thermal), the smooth orbit with a law against the rough orbit's smooth
limit, IDA against BDF2 through a run-up, a run-up that settles on the final speed's equilibrium, the deprecated
``run(speed=)``, refusals; the rough film's mass balance on every BDF2 step."""

import math
import warnings

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, Roughness, ThermalFilm, steel_asperity_contact
from transient.models.journal.kernels import shaft_accelerations
from transient.models.journal.orbit import BDF2_FILM_TOL
from transient.models.journal.rough_orbit import step_mass_balance
from transient.models.journal.speed_law import FUNCTION_KNOTS, SpeedProfile, shaft_speed, speed_knots
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, Recording

GRID = (24, 4)
SPEED = 3000.0
PERIOD = 60.0 / SPEED  # [s] one revolution at the reference speed
ROTOR_KW = dict(rotor_mass=ROTOR["rotor_mass"], unbalance=ROTOR["unbalance"], load=ROTOR["load"], speed_rpm=SPEED)
RUN_UP = ((0.0, 0.5 * SPEED), (PERIOD, SPEED))  # 0.5x -> 1x in one reference revolution
REC = Recording(outputs_per_revolution=20, record=("shaft_speed",))


def smooth(grid=GRID):
    return JournalBearing(**BEARING, grid=grid)


def rough(sigma, grid=GRID):
    r = Roughness(steel_asperity_contact(sigma), gamma=3.0, boundary_friction=0.12, journal_variance_share=0.8)
    return JournalBearing(**BEARING, grid=grid, roughness=r)


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # a rough film's contact pressure beyond the isoviscous range
        return f(*a, **kw)


# ------------------------------------------------------------------------------------------------- the law itself
def test_a_ramp_turns_the_shaft_through_the_closed_form_angle():
    """A ramp from n0 at t1 > 0 to n1 at t2 (constant before and after): speed, rate and the shaft angle
    theta(t) = int_0^t Omega dt in SI (SpeedProfile) and in the kernels' units (knots, shaft_speed) against the
    closed forms, before, inside and after the ramp."""
    t1, t2, n0, n1 = 0.5, 1.5, 600.0, 1800.0
    law = SpeedProfile(((t1, n0), (t2, n1)))
    w0, a = n0 * math.pi / 30.0, (n1 - n0) * math.pi / 30.0 / (t2 - t1)

    def theta(t):
        if t <= t1:
            return w0 * t
        if t <= t2:
            return w0 * t + 0.5 * a * (t - t1) ** 2
        return theta(t2) + n1 * math.pi / 30.0 * (t - t2)

    omega_ref, rpm_ref = 1200.0 * math.pi / 30.0, 1200.0
    knots = law.knots(omega_ref, rpm_ref, 3.0)
    for t in (0.0, 0.2, 0.9, 1.2, 2.7):
        n = n0 if t <= t1 else (n1 if t >= t2 else n0 + (n1 - n0) * (t - t1) / (t2 - t1))
        assert math.isclose(law.value(t), n, rel_tol=1e-14)
        assert math.isclose(law.angle(t), theta(t), rel_tol=1e-13, abs_tol=1e-15)
        s, ds, phi = shaft_speed(omega_ref * t, knots)
        assert math.isclose(s, n / rpm_ref, rel_tol=1e-14)
        assert math.isclose(phi, theta(t), rel_tol=1e-13, abs_tol=1e-15)  # phi = int s dtau = int Omega dt
        inside = t1 <= t < t2
        assert math.isclose(ds, a / omega_ref ** 2 if inside else 0.0,
                            rel_tol=1e-13, abs_tol=1e-18)
        assert math.isclose(law.derivative(t), (n1 - n0) / (t2 - t1) if inside else 0.0, rel_tol=1e-13)


def test_a_function_is_taken_on_its_knots():
    """A function n(t): its knots every 1/FUNCTION_KNOTS reference revolution from t = 0 past the run's end; a
    linear function is its own straight lines (speed and angle to rounding), a parabola's speed is within the
    lines' error (dt^2 |n''| / 8)."""
    omega_ref = SPEED * math.pi / 30.0
    line = SpeedProfile(lambda t: 1500.0 + 3e4 * t)
    k = line.knots(omega_ref, SPEED, 2.5 * PERIOD)
    assert k.shape[1] == int(math.ceil(2.5 * FUNCTION_KNOTS)) + 2 and k[0, 0] == 0.0 and k[0, -1] >= 2.5 * 2 * math.pi
    for t in (0.0, 0.3 * PERIOD, 2.2 * PERIOD):
        s, ds, phi = shaft_speed(omega_ref * t, k)
        assert math.isclose(s * SPEED, 1500.0 + 3e4 * t, rel_tol=1e-13)
        assert math.isclose(phi, (1500.0 * t + 1.5e4 * t * t) * math.pi / 30.0, rel_tol=1e-12)
    curve = SpeedProfile(lambda t: 1500.0 + 1e7 * t * t)
    kc = curve.knots(omega_ref, SPEED, PERIOD)
    dt = PERIOD / FUNCTION_KNOTS
    t = np.linspace(0.0, PERIOD, 97)
    s = np.array([shaft_speed(omega_ref * x, kc)[0] for x in t]) * SPEED
    assert np.max(np.abs(s - curve.value(t))) <= 2e7 * dt * dt / 8 * (1 + 1e-9)


def test_the_unbalance_force_follows_the_law():
    """The rotor's unbalance term of an orbit with a run-up: ``m e (Omega^2 (cos, sin) + dOmega/dt (sin, -cos))``
    at theta(t) (SI, closed form) against the kernels' (shaft_accelerations on the orbit's law, no film)."""
    o = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=RUN_UP)
    m, e, C, w = o.rotor_mass, o.unbalance, o.bearing.clearance, o.film.omega
    a = 0.5 * SPEED * math.pi / 30.0 / PERIOD
    for t in (0.1 * PERIOD, 0.7 * PERIOD):
        W, th = 0.5 * w + a * t, 0.5 * w * t + 0.5 * a * t * t
        ax, ay = shaft_accelerations(*shaft_speed(w * t, o.knots), 0.0, 0.0, o.kappa, 0.0, o.ebar)
        unit = m * C * w * w  # the rotor equations' force unit
        assert math.isclose(ax * unit, m * e * (W * W * math.cos(th) + a * math.sin(th)), rel_tol=1e-12)
        assert math.isclose(ay * unit, m * e * (W * W * math.sin(th) - a * math.cos(th)), rel_tol=1e-12)


@pytest.mark.parametrize("bad, match", [(((0.0, 10.0), (0.0, 20.0)), "ascending"),
                                        (((0.0, -1.0),), "speed_profile speed"), (((-1.0, 1.0),), "speed_profile time"),
                                        ((1.0, 2.0, 3.0), "speed_profile"), ("fast", "speed_profile")])
def test_a_bad_table_is_named(bad, match):
    with pytest.raises(ValueError, match=match):
        JournalOrbit(smooth(), **ROTOR_KW, speed_profile=bad)


# ------------------------------------------------------------------------------------------------- constant law
@pytest.mark.parametrize("method", ["bdf2", "ida"])
def test_a_constant_law_is_the_constant_speed_run(method):
    """speed_profile=((0, speed_rpm),) on the smooth orbit: the same steps and the same orbit (to 1e-12 C) as no
    profile, on the law's kernels (driven_film for BDF2, the kernels' *_at for IDA)."""
    ig = Integration(method=method)
    a = JournalOrbit(smooth(), **ROTOR_KW).run(0.3, integration=ig, recording=REC)
    b = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=((0.0, SPEED),)).run(0.3, integration=ig, recording=REC)
    assert a.success and b.success and a.stats.n_steps == b.stats.n_steps
    C = a.clearance
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) <= 1e-12 * C
    assert np.all(b.shaft_speed == SPEED)


@pytest.mark.parametrize("method", ["bdf2", "ida"])
def test_a_constant_law_on_a_rough_bearing(method):
    b = rough(1e-6)
    kw = dict(rotor_mass=500.0, unbalance=20e-6, load=5000.0, speed_rpm=60.0)
    ig = Integration(method=method)
    r0 = quiet(JournalOrbit(b, **kw).run, 0.05, integration=ig, recording=REC)
    r1 = quiet(JournalOrbit(b, **kw, speed_profile=((0.0, 60.0),)).run, 0.05, integration=ig, recording=REC)
    assert r0.success and r1.success and r0.stats.n_steps == r1.stats.n_steps
    assert np.max(np.hypot(r0.x - r1.x, r0.y - r1.y)) <= 1e-12 * r0.clearance


OIL = ThermalFilm(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
                  heat_capacity=1950.0)


def thermal_orbit(speed_profile=None):
    b = JournalBearing(diameter=0.1, length=0.05, clearance=1e-4, viscosity=None, grid=(30, 4), thermal=OIL)
    return JournalOrbit(b, 10.0, 2e-6, 2000.0, 1500.0, speed_profile=speed_profile)


THERMAL_REC = Recording(outputs_per_revolution=8, record=("shaft_speed", "max_temperature", "power_loss"))


def test_a_constant_law_on_a_thermal_bearing():
    a = thermal_orbit().run(1, thermal_interval=0.5, recording=THERMAL_REC)
    b = thermal_orbit(((0.0, 1500.0),)).run(1, thermal_interval=0.5, recording=THERMAL_REC)
    assert a.success and b.success and a.stats.n_steps == b.stats.n_steps
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) <= 1e-12 * a.clearance
    np.testing.assert_allclose(b.max_temperature, a.max_temperature, rtol=1e-12)


def test_the_deprecated_speed_keyword_is_the_same_law():
    """run(speed=f) on a thermal bearing: a DeprecationWarning, and the run of JournalOrbit(..., speed_profile=f)."""
    def f(t):
        return 1500.0 + 1500.0 * min(t / 0.04, 1.0)

    with pytest.warns(DeprecationWarning, match="speed_profile"):
        a = thermal_orbit().run(1, speed=f, thermal_interval=0.5, recording=THERMAL_REC)
    b = thermal_orbit(f).run(1, thermal_interval=0.5, recording=THERMAL_REC)
    assert a.success and b.success and a.stats.n_steps == b.stats.n_steps
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) <= 1e-12 * a.clearance
    np.testing.assert_allclose(a.shaft_speed, [f(t) for t in a.t], rtol=1e-12)
    assert a.power_loss[-1] > 1.5 * a.power_loss[0]


# ------------------------------------------------------------------------------------------------- a run-up
def test_the_smooth_orbit_is_the_rough_orbits_smooth_limit_through_a_run_up():
    """The same run-up (0.5x -> 1x in a revolution) on the smooth film and on the rough film with sigma = 1 nm
    (h / sigma >= 1000: flow factors 1, no contact), IDA at the same tolerances: the journal paths agree to the
    steppers' tolerance (rtol 1e-8; measured 1.1e-9 C, the same 649 steps)."""
    ig = Integration(method="ida", rtol=1e-8, atol=1e-10)
    a = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=RUN_UP).run(0.5, integration=ig, recording=REC)
    b = quiet(JournalOrbit(rough(1e-9), **ROTOR_KW, speed_profile=RUN_UP).run, 0.5, integration=ig, recording=REC)
    assert a.success and b.success
    np.testing.assert_array_equal(a.shaft_speed, b.shaft_speed)
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) < 1e-8 * a.clearance


@pytest.fixture(scope="module")
def run_ups():
    """The smooth run-up 0.5x -> 1x (one revolution) held to three revolutions, from the 0.5x equilibrium, no
    unbalance, by BDF2 and by IDA."""
    o = JournalOrbit(smooth(), **dict(ROTOR_KW, unbalance=0.0), speed_profile=RUN_UP)
    return o, {m: o.run(3.0, integration=Integration(method=m), recording=REC) for m in ("bdf2", "ida")}


def test_ida_and_bdf2_agree_through_a_run_up(run_ups):
    o, r = run_ups
    a, b = r["ida"], r["bdf2"]
    assert a.success and b.success
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) < 1e-6 * o.bearing.clearance  # rtol 1e-6 both (measured 8.7e-8)
    np.testing.assert_allclose(a.shaft_speed[[0, 10, 20, -1]], [0.5 * SPEED, 0.75 * SPEED, SPEED, SPEED])


def test_a_run_up_settles_on_the_final_speeds_equilibrium(run_ups):
    """From the 0.5x equilibrium (the orbit's start with a law) the journal ends at the 1x equilibrium: its distance,
    relative to the distance between the two equilibria, falls revolution by revolution at full speed, to below
    2e-3 after two (measured 5.0e-4)."""
    o, r = run_ups
    C = o.bearing.clearance
    slow = np.array(o.bearing.equilibrium(o.load, 0.5 * SPEED).position)
    fast = np.array(o.bearing.equilibrium(o.load, SPEED).position)
    np.testing.assert_allclose([r["bdf2"].x[0], r["bdf2"].y[0]], slow, atol=1e-12 * C)
    shift = np.hypot(*(fast - slow))
    for run in r.values():
        d = np.hypot(run.x - fast[0], run.y - fast[1]) / shift
        assert np.all(np.diff(d[[20, 30, 40, 50, 60]]) < 0) and d[-1] < 2e-3


def test_a_run_up_reaches_the_periodic_orbit_in_the_shafts_phase():
    """With the unbalance: after the run-up (0.5x -> 1x in a revolution: the shaft turns 3/4 of a revolution in the
    first reference revolution, so at full speed theta = tau - pi/2) and seven revolutions at full speed, the last
    revolution is the periodic orbit at the final speed a quarter revolution later, within 1e-3 of the orbit's
    size; at any other shift of whole outputs it is more than 0.1 of it away."""
    ramp = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=RUN_UP).run(8.0, integration=Integration(method="bdf2"),
                                                                         recording=REC)
    p = JournalOrbit(smooth(), **ROTOR_KW).periodic_response(rtol=1e-6, outputs_per_revolution=20)
    assert ramp.success and p.converged
    size = np.ptp(p.x[:20])
    last = np.column_stack([ramp.x[-21:-1], ramp.y[-21:-1]])
    err = [np.max(np.hypot(*(last - np.roll(np.column_stack([p.x[:20], p.y[:20]]), k, axis=0)).T)) for k in range(20)]
    assert int(np.argmin(err)) == 5 and err[5] < 1e-3 * size  # a quarter revolution: 5 of 20 outputs
    assert min(err[:5] + err[6:]) > 0.1 * size


# ------------------------------------------------------------------------------------------------- refusals
@pytest.mark.parametrize("call, match", [
    (lambda o: o.run(0.1, integration=Integration(method="cvode")), "^method = 'cvode'.*speed_profile"),
    (lambda o: o.run(0.1, integration=Integration(method="rk4")), "^method = 'rk4'.*speed_profile"),
    (lambda o: o.run(0.1, integration=Integration(method="ida", formulation="content")), "^method = 'ida'"),
    (lambda o: o.run(0.1, recording=Recording(record=("outflow",))), "^record"),
    (lambda o: o.periodic_response(), "^periodic_response with a speed_profile"),
])
def test_what_a_law_does_not_take_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call(JournalOrbit(smooth(), **ROTOR_KW, speed_profile=RUN_UP))


def test_a_smooth_run_from_rest_is_refused():
    o = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=((0.0, 0.0), (1.0, SPEED)))
    with pytest.raises(ValueError, match="^speed_profile starts at 0"):
        o.initial_state()


# ------------------------------------------------------------------------------------------------- mass per step
def test_the_rough_film_conserves_mass_on_every_bdf2_step():
    """The rough film (flow factors, contact factor on the content) whirling in contact (5 kN at 60 rpm, 20 um
    unbalance), and through a speed ramp: on every BDF2 step the content change plus the net outflow times the step
    is within the Newton's content tolerance, per cell and summed over the film."""
    b = rough(1e-6)
    for profile in (None, ((0.0, 30.0), (0.5, 60.0))):
        o = quiet(JournalOrbit, b, 500.0, 20e-6, 5000.0, 60.0, speed_profile=profile)
        mb = quiet(step_mass_balance, o, 0.25)
        assert mb["t"].size > 50 and np.max(mb["change"]) > 10 * BDF2_FILM_TOL  # content moves in the steps
        assert np.max(mb["worst_cell"]) < BDF2_FILM_TOL
        assert np.max(mb["imbalance"]) < 1e-2 * BDF2_FILM_TOL


def test_speed_knots_start_after_zero():
    """A law whose first knot is after t = 0 turns the shaft at its first speed before it: phi(tau_0) = s_0 tau_0."""
    k = speed_knots(((2.0, 0.5), (3.0, 1.0)))
    np.testing.assert_allclose(shaft_speed(1.0, k), (0.5, 0.0, 0.5), atol=1e-15)
    np.testing.assert_allclose(shaft_speed(2.5, k), (0.75, 0.5, 1.0 + 0.5 * 0.5 + 0.25 * 0.25), atol=1e-15)


def test_a_scene_gives_the_profile():
    """A journal_orbit scene's ``speed_profile`` override reaches the orbit (checked when the scene is read)."""
    from transient.study.scene import scene_from_dict

    scene = scene_from_dict(dict(kind="journal_orbit", overrides=dict(grid=[24, 4], speed_rpm=SPEED,
                                                                      speed_profile=[[0.0, 1500.0], [0.02, 3000.0]])))
    o = scene.kind.build(scene.params)
    assert o.speed_profile.table == ((0.0, 1500.0), (0.02, 3000.0))
    with pytest.raises(ValueError, match="speed_profile times"):
        scene_from_dict(dict(kind="journal_orbit", overrides=dict(grid=[24, 4],
                                                                  speed_profile=[[0.0, 1.0], [0.0, 2.0]])))


def test_a_checkpoint_is_keyed_on_the_law(tmp_path):
    """A run with a law resumes from its checkpoint; another law is refused by name."""
    from transient.solvers.settings import LongRun

    ck = str(tmp_path / "orbit.npz")
    o = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=RUN_UP)
    a = o.run(0.2, recording=REC, long_run=LongRun(checkpoint=ck, chunk_revolutions=0.1, progress=False))
    b = o.run(0.2, recording=REC, long_run=LongRun(checkpoint=ck, chunk_revolutions=0.1, resume=True, progress=False))
    np.testing.assert_array_equal(a.x, b.x)
    other = JournalOrbit(smooth(), **ROTOR_KW, speed_profile=lambda t: 0.5 * SPEED + 0.5 * SPEED * min(t / PERIOD, 1))
    with pytest.raises(ValueError, match="speed_profile"):
        other.run(0.2, recording=REC, long_run=LongRun(checkpoint=ck, chunk_revolutions=0.1, resume=True,
                                                       progress=False))
