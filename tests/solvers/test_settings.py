"""Run settings as objects (transient.solvers.settings): validated on creation; the deprecated loose keywords still
work for one release, warn naming the new spelling, and give the same arrays."""

import warnings

import numpy as np
import pytest

from transient import (Integration, JournalBearing, JournalOrbit, LongRun, Problem, Recording, Steps, ThrustBallBearing,
                       TrackSettings, solve)
from transient.params import rho_kim
from transient.solvers.longrun import CheckpointError


def _orbit():
    return JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000, **rho_kim.ROTOR)


@pytest.mark.parametrize("method", ["ida", "bdf2", "rk4"])
def test_objects_and_the_deprecated_keywords_give_bitwise_identical_orbits(method):
    o = _orbit()
    steps = dict(steps_per_revolution=200) if method == "rk4" else {}
    with pytest.warns(DeprecationWarning) as caught:
        by_keywords = o.run(0.5, method=method, rtol=1e-5, atol=1e-8, outputs_per_revolution=8, record=("force",),
                            chunk_revolutions=0.25, progress=False, **steps)
    assert any("pass integration=Integration(rtol=...)" in str(w.message) for w in caught)
    by_objects = o.run(0.5, integration=Integration(method=method, rtol=1e-5, atol=1e-8, **steps),
                       recording=Recording(outputs_per_revolution=8, record="force"),
                       long_run=LongRun(chunk_revolutions=0.25, progress=False))
    assert by_keywords.success and by_objects.success
    for name in ("t", "x", "y", "force"):
        a, b = getattr(by_keywords, name), getattr(by_objects, name)
        assert a.shape == b.shape and np.array_equal(a, b), name


def test_objects_and_the_deprecated_keywords_give_identical_ball_sequences():
    b = ThrustBallBearing()
    kw = dict(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=3, stop_at_periodic=False)
    with pytest.warns(DeprecationWarning) as caught:
        by_keywords = b.sequence(**kw, rtol=1e-5, atol=1e-9, record_profiles=True, refine=1.5)
    assert any("record_profiles= is deprecated" in str(w.message) and "recording=Recording(record=...)"
               in str(w.message) for w in caught)
    by_objects = b.sequence(**kw, integration=Integration(method="cvode", rtol=1e-5, atol=1e-9),
                            recording=Recording(record=("profiles",)), track=TrackSettings(refine=1.5))
    for name in ("h_inlet", "h_central", "profiles", "volume"):
        assert np.array_equal(getattr(by_keywords, name), getattr(by_objects, name)), name
    with pytest.raises(ValueError, match=r"record: unknown series \['force'\]"):
        b.sequence(**kw, recording=Recording(record="force"))


@pytest.mark.parametrize("make, text", [
    (lambda: Integration(rtol=2.0), "rtol must be a finite number in (0, 1), got 2.0"),
    (lambda: Integration(atol=1e-40), "atol = 1e-40 [-] is out of range; allowed: [1e-30, 1] -"),
    (lambda: Integration(method="euler"), "method must be one of"),
    (lambda: Integration(formulation="theta"), "formulation must be one of ('content', 'universal'), got "
                                               "formulation = 'theta'"),
    (lambda: Integration(steps_per_revolution=2), "steps_per_revolution = 2 [1/rev] is out of range; allowed: "
                                                  "[4, 1e+07] 1/rev"),
    (lambda: Integration(inner_tolerance=0.0), "inner_tolerance = 0.0 [-] is out of range; allowed: (0, inf) -"),
    (lambda: Integration(dt=-1.0), "dt = -1.0 [-] is out of range"),
    (lambda: Integration(linear_solver="gmres"), "linear_solver must be one of"),
    (lambda: Recording(outputs_per_revolution=0), "outputs_per_revolution = 0 [1/rev] is out of range; allowed: "
                                                  "[1, 1e+06] 1/rev"),
    (lambda: Recording(outputs_per_revolution=2.5), "outputs_per_revolution = 2.5 [1/rev] is not a whole number"),
    (lambda: Recording(record_from_revolution=-1), "record_from_revolution = -1 [rev] is out of range"),
    (lambda: Recording(record=(1,)), "record = (1,): series are named by strings"),
    (lambda: LongRun(chunk_revolutions=0), "chunk_revolutions = 0 [rev] is out of range; allowed: (0, inf) rev"),
    (lambda: LongRun(time_budget=-5), "time_budget = -5 [s] is out of range; allowed: (0, inf) s"),
    (lambda: LongRun(checkpoint="run.pkl"), "checkpoint = 'run.pkl': the file name must end in .npz"),
    (lambda: LongRun(resume="yes"), "resume = 'yes' is not a flag"),
    (lambda: LongRun(stop=3), "stop = 3 is not callable"),
])
def test_invalid_settings_are_one_line_errors_naming_the_parameter(make, text):
    with pytest.raises(ValueError) as e:
        make()
    message = str(e.value)
    assert text in message and "\n" not in message


def test_settings_are_frozen_and_normalised():
    ig = Integration(rtol=1e-5)
    with pytest.raises(AttributeError):
        ig.rtol = 1e-3
    assert Recording(record="force").record == ("force",)
    assert Recording(outputs_per_revolution=8.0).outputs_per_revolution == 8


@pytest.mark.parametrize("keywords, named", [
    (dict(integration=Integration(rtol=1e-5), rtol=1e-7), ("rtol=1e-07", "integration=Integration(rtol=...)")),
    (dict(integration=Integration(method="cvode"), method="cvode"), ("method='cvode'", "integration=Integration(")),
    (dict(recording=Recording(outputs_per_revolution=8), outputs_per_revolution=8),
     ("outputs_per_revolution=8", "recording=Recording(outputs_per_revolution=...)")),
    (dict(long_run=LongRun(resume=True), resume=False), ("resume=False", "long_run=LongRun(resume=...)")),
])
def test_an_object_and_an_old_keyword_for_the_same_setting_is_an_error_naming_both(keywords, named):
    """Even when they agree: a setting is passed once."""
    with pytest.raises(ValueError, match="both given") as e:
        _orbit().run(0.1, **keywords)
    assert all(n in str(e.value) for n in named), str(e.value)


def test_an_unknown_keyword_is_a_type_error_naming_it():
    with pytest.raises(TypeError, match=r"JournalOrbit\.run\(\) got an unexpected keyword argument 'rtoll'"):
        _orbit().run(0.1, rtoll=1e-6)
    with pytest.raises(TypeError, match=r"ThrustBallBearing\.sequence\(\) got an unexpected keyword argument 'cells'"):
        ThrustBallBearing().sequence(30, 80, 50e-6, cells=10)
    with pytest.raises(TypeError, match=r"solve\(\) got an unexpected keyword argument 'step'"):
        solve(Problem(y0=np.ones(1), rhs=_decay), [0.0, 1.0], step=0.1)


def test_a_wrong_type_for_a_settings_object_is_named():
    with pytest.raises(ValueError, match=r"integration = \{'rtol': 1e-05\}; allowed: None or Integration\(\.\.\.\)"):
        _orbit().run(0.1, integration=dict(rtol=1e-5))


def test_the_checkpoint_key_comes_from_the_objects(tmp_path):
    """A checkpoint written through the old keywords resumes through the equal objects, and is refused (naming the
    setting) when an object differs."""
    o = _orbit()
    path = tmp_path / "orbit.npz"
    with pytest.warns(DeprecationWarning):
        o.run(1.0, outputs_per_revolution=8, chunk_revolutions=0.5, checkpoint=path, progress=False)
    lr = LongRun(chunk_revolutions=0.5, checkpoint=path, resume=True, progress=False)
    r = o.run(1.0, integration=Integration(method="bdf2"), recording=Recording(outputs_per_revolution=8),
              long_run=lr)  # the orbit's default method
    assert r.success and r.t.size == 9
    with pytest.raises(CheckpointError, match="written with rtol = 1e-06, this run has rtol = 1e-07"):
        o.run(1.0, integration=Integration(method="bdf2", rtol=1e-7), recording=Recording(outputs_per_revolution=8),
              long_run=lr)
    with pytest.raises(CheckpointError, match='this run has formulation = "universal"'):
        o.run(1.0, integration=Integration(), recording=Recording(outputs_per_revolution=8), long_run=lr)


def test_an_old_keyword_given_as_none_is_checked_not_taken_as_left_out():
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="record_from_revolution = None"):
        _orbit().run(0.1, record_from_revolution=None)
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match=r"record = 1\.0; allowed: a series name"):
        _orbit().run(0.1, record=1.0)
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="rtol"):
        ThrustBallBearing().sequence(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=2, rtol=None)


def _decay(t, y, out):
    out[0] = -y[0]


def _warned(call, old, new):
    """``call()`` under a DeprecationWarning naming ``old=`` and the new spelling ``new``, raised at the caller's
    line (this file), not inside the package."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = call()
    ours = [w for w in caught if issubclass(w.category, DeprecationWarning)
            and f"the keyword {old}= is deprecated" in str(w.message)]
    assert ours, f"no DeprecationWarning for {old}=: {[str(w.message) for w in caught]}"
    assert f"pass {new}" in str(ours[0].message), str(ours[0].message)
    assert ours[0].filename == __file__, ours[0].filename
    return out


def _field(spelling):
    """``"rtol"`` of ``"integration=Integration(rtol=...)"``."""
    return spelling.split("(")[1].split("=")[0]


#: every old keyword of JournalOrbit.run: (keywords, the new spelling of the same run, the warning's new spelling)
ORBIT_KEYWORDS = [
    (dict(method="cvode"), dict(integration=Integration(method="cvode")), "integration=Integration(method=...)"),
    (dict(rtol=1e-5), dict(integration=Integration(rtol=1e-5)), "integration=Integration(rtol=...)"),
    (dict(atol=1e-7), dict(integration=Integration(atol=1e-7)), "integration=Integration(atol=...)"),
    (dict(formulation="content"), dict(integration=Integration(formulation="content")),
     "integration=Integration(formulation=...)"),
    (dict(method="rk4", steps_per_revolution=100), dict(integration=Integration(method="rk4", steps_per_revolution=100)),
     "integration=Integration(steps_per_revolution=...)"),
    (dict(method="rk4", steps_per_revolution=100, inner_tolerance=1e-5),
     dict(integration=Integration(method="rk4", steps_per_revolution=100, inner_tolerance=1e-5)),
     "integration=Integration(inner_tolerance=...)"),
    (dict(outputs_per_revolution=40), dict(recording=Recording(outputs_per_revolution=40)),
     "recording=Recording(outputs_per_revolution=...)"),
    (dict(record=("force", "min_film")), dict(recording=Recording(record=("force", "min_film"))),
     "recording=Recording(record=...)"),
    (dict(record="pressure", record_from_revolution=0.1),
     dict(recording=Recording(record="pressure", record_from_revolution=0.1)),
     "recording=Recording(record_from_revolution=...)"),
    (dict(chunk_revolutions=0.1), dict(long_run=LongRun(chunk_revolutions=0.1)),
     "long_run=LongRun(chunk_revolutions=...)"),
    (dict(progress=False), dict(long_run=LongRun(progress=False)), "long_run=LongRun(progress=...)"),
    (dict(stop=lambda r: None), dict(long_run=LongRun(stop=lambda r: None)), "long_run=LongRun(stop=...)"),
    (dict(time_budget=1e4), dict(long_run=LongRun(time_budget=1e4)), "long_run=LongRun(time_budget=...)"),
]


@pytest.mark.parametrize("old, new, spelling", ORBIT_KEYWORDS, ids=[_field(s) for _, _, s in ORBIT_KEYWORDS])
def test_every_old_keyword_of_the_orbit_run_still_works_and_warns(old, new, spelling):
    """The same arrays as the new spelling, on a 16 x 2 grid over 0.2 revolution."""
    o = _orbit()
    a = _warned(lambda: o.run(0.2, **old), _field(spelling), spelling)
    b = o.run(0.2, **new)
    assert a.success and b.success and a.method == b.method
    for name in ("t", "x", "y") + tuple(a.fields):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_the_checkpoint_and_resume_keywords_still_work_and_warn(tmp_path):
    o = _orbit()
    kw = dict(chunk_revolutions=0.1, progress=False)
    a = _warned(lambda: o.run(0.2, checkpoint=tmp_path / "a.npz", **kw), "checkpoint", "long_run=LongRun(checkpoint=...)")
    b = o.run(0.2, long_run=LongRun(checkpoint=tmp_path / "b.npz", **kw))
    assert np.array_equal(a.x, b.x) and (tmp_path / "a.npz").exists()
    again = _warned(lambda: o.run(0.2, checkpoint=tmp_path / "a.npz", resume=True, **kw), "resume",
                    "long_run=LongRun(resume=...)")
    assert np.array_equal(again.x, a.x)


def test_the_old_step_keywords_of_solve_still_work_and_warn():
    p = Problem(y0=np.ones(1), rhs=_decay)
    t = np.linspace(0.0, 1.0, 5)
    for name, value, method in (("dt", 0.01, "rk4"), ("max_step", 0.05, "bdf"), ("first_step", 1e-4, "bdf"),
                                ("max_steps", 10_000, "bdf")):
        a = _warned(lambda: solve(p, t, method, **{name: value}), name, f"steps=Steps({name}=...)")
        b = solve(p, t, method, steps=Steps(**{name: value}))
        assert a.success and np.array_equal(a.y, b.y), name
    with pytest.raises(ValueError, match=r"solve: dt=0\.01 and steps=Steps\(\.\.\.\) both given"):
        solve(p, t, "rk4", dt=0.01, steps=Steps(dt=0.01))
    with pytest.raises(ValueError, match=r"method 'rk4' needs a fixed step dt > 0"):
        solve(p, t, "rk4")


@pytest.mark.parametrize("old, spelling", [
    (dict(replenishment="chiu"), "track=TrackSettings(replenishment=...)"),
    (dict(grid="uniform", n_cells=40), "track=TrackSettings(grid=...)"),
    (dict(bc="closed"), "track=TrackSettings(bc=...)"),
    (dict(ridge_fraction=0.5, ridge_width=1e-4), "track=TrackSettings(ridge_fraction=...)"),
    (dict(reservoir_distance=1e-3), "track=TrackSettings(reservoir_distance=...)"),
    (dict(precursor_film=1e-8), "track=TrackSettings(precursor_film=...)"),
    (dict(grid="uniform", n_cells=40, mobility_film=5e-6), "track=TrackSettings(mobility_film=...)"),
    (dict(front_level=4.0, front_tau=2e-3, edge_width=1e-6), "track=TrackSettings(front_level=...)"),
    (dict(method="bdf", rtol=1e-4), "integration=Integration(method=...)"),
    (dict(atol=1e-8), "integration=Integration(atol=...)"),
    (dict(grid="uniform", n_cells=40, linear_solver="band"), "integration=Integration(linear_solver=...)"),
])
def test_every_old_keyword_of_the_ball_sequence_still_works_and_warns(old, spelling):
    """The same inlet films as the new spelling over 2 passes."""
    from transient.models.ball.bearing import sequence_settings

    b = ThrustBallBearing()
    kw = dict(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=2, stop_at_periodic=False)
    a = _warned(lambda: b.sequence(**kw, **old), _field(spelling), spelling)
    new = sequence_settings(**old)
    assert set(new) == {"track", "integration", "recording"}
    c = b.sequence(**kw, **new)
    assert np.array_equal(a.h_inlet, c.h_inlet) and np.array_equal(a.h_central, c.h_central)


def test_the_old_dt_keyword_of_the_sequence_reaches_the_levelling():
    """An explicit rk4 step of 0.05 levelling times is unstable on this track: the old and the new spelling fail
    alike, at the first step (t = 0.05: the step was taken)."""
    b = ThrustBallBearing()
    kw = dict(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=2, track=TrackSettings(grid="uniform", n_cells=40))
    with pytest.warns(DeprecationWarning) as caught:
        with pytest.raises(RuntimeError) as old:
            b.sequence(**kw, method="rk4", dt=0.05)
    assert any("pass integration=Integration(dt=...)" in str(w.message) for w in caught)
    with pytest.raises(RuntimeError) as new:
        b.sequence(**kw, integration=Integration(method="rk4", dt=0.05))
    assert str(old.value) == str(new.value) and "at t=0.05" in str(new.value)


def test_the_sequence_keeps_its_own_integration_defaults():
    from transient.models.ball.bearing import sequence_settings

    assert sequence_settings()["integration"] == Integration(method="cvode", atol=1e-10)
    assert sequence_settings(rtol=1e-4)["integration"] == Integration(method="cvode", rtol=1e-4, atol=1e-10)
    with pytest.raises(ValueError, match="'rtoll' is not a setting"):
        sequence_settings(rtoll=1e-4)


def test_track_settings_are_validated_on_creation():
    for make, text in ((lambda: TrackSettings(grid="fine"), "grid must be one of"),
                       (lambda: TrackSettings(n_cells=4), "n_cells = 4 [-] is out of range"),
                       (lambda: TrackSettings(ridge_fraction=1.5), "ridge_fraction = 1.5 [-] is out of range"),
                       (lambda: TrackSettings(precursor_film=-1e-9), "precursor_film = -1e-09 [m] is out of range"),
                       (lambda: TrackSettings(front_tau=0.0), "front_tau = 0.0 [-] is out of range")):
        with pytest.raises(ValueError) as e:
            make()
        assert text in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_the_old_keywords_of_run_long_still_work_and_warn(tmp_path):
    from transient.solvers.longrun import Display, run_long

    class Rec:
        def __init__(self):
            self.t = []

        def observe(self, t, y):
            self.t.append(float(y[0]))

        def arrays(self):
            return dict(t=np.array(self.t))

        def restore(self, a):
            self.t = list(a["t"])

    def go(**kw):
        rec = Rec()
        run_long(lambda y, t: Problem(y0=y, rhs=_decay), np.array([1.0]), 0.0, 0.25, 4, rec, chunk_outputs=2,
                 key=dict(rate=1.0), **kw)
        return np.array(rec.t)

    new = go(solver=dict(method="rk4", steps=Steps(dt=0.01)), long_run=LongRun(progress=False),
             display=Display(label="decay"))
    old = _warned(lambda: go(method="rk4", dt=0.01, progress=False, label="decay"), "method", "solver=dict(method=...)")
    assert np.array_equal(old, new)
    for name, value, spelling in (("rtol", 1e-7, "solver=dict(rtol=...)"), ("max_step", 0.1, "steps=Steps(max_step=...)"),
                                  ("checkpoint", tmp_path / "d.npz", "long_run=LongRun(checkpoint=...)"),
                                  ("unit", ("s", 1.0), "display=Display(unit=...)")):
        _warned(lambda: go(method="bdf", **{name: value}), name, spelling)
    with pytest.raises(TypeError, match=r"run_long\(\) got an unexpected keyword argument 'chunks'"):
        go(solver=dict(method="bdf"), chunks=2)


def _rotor():
    from transient.models.rotor import Rotor, RotorBearingSystem

    return RotorBearingSystem(Rotor(mass=100.0 * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]),
                              {0: JournalBearing(**rho_kim.BEARING, grid=(8, 2))}, gravity=9.81)


@pytest.mark.parametrize("old, new, spelling", [
    (dict(rtol=1e-5), dict(integration=Integration(rtol=1e-5)), "integration=Integration(rtol=...)"),
    (dict(atol=1e-7), dict(integration=Integration(atol=1e-7)), "integration=Integration(atol=...)"),
    (dict(method="ida"), dict(integration=Integration(method="ida")), "integration=Integration(method=...)"),
    (dict(outputs_per_revolution=20), dict(recording=Recording(outputs_per_revolution=20)),
     "recording=Recording(outputs_per_revolution=...)"),
    (dict(chunk_revolutions=0.05), dict(long_run=LongRun(chunk_revolutions=0.05)),
     "long_run=LongRun(chunk_revolutions=...)"),
    (dict(progress=False), dict(long_run=LongRun(progress=False)), "long_run=LongRun(progress=...)"),
    (dict(time_budget=1e4), dict(long_run=LongRun(time_budget=1e4)), "long_run=LongRun(time_budget=...)"),
])
def test_every_old_keyword_of_the_rotor_run_still_works_and_warns(old, new, spelling):
    s = _rotor()
    a = _warned(lambda: s.run(0.1, 3000.0, **old), _field(spelling), spelling)
    b = s.run(0.1, 3000.0, **new)
    assert a.success and b.success and np.array_equal(a.t, b.t) and np.array_equal(a.displacement, b.displacement)
    assert np.array_equal(a.final_state, b.final_state)


def test_the_rotor_refuses_a_setting_it_does_not_use():
    with pytest.raises(ValueError, match=r"RotorBearingSystem\.run: recording=Recording\(record=\('force',\)\) is not "
                                         r"used by this model; allowed: leave record out"):
        _rotor().run(0.1, 3000.0, recording=Recording(record="force"))


def test_the_old_keywords_of_settle_and_bearing_noise_still_work_and_warn():
    from transient.study.noise import bearing_noise
    from transient.study.settle import Settling, settle

    o = _orbit()
    a = _warned(lambda: settle(o, max_periods=2, require=False, chunk_periods=1), "chunk_periods",
                "long_run=LongRun(chunk_revolutions=...)")
    b = settle(o, max_periods=2, require=False, long_run=LongRun(chunk_revolutions=1))
    assert np.array_equal(a.result.x, b.result.x)
    n_old = _warned(lambda: bearing_noise(o, revolutions=1, harmonics=2, periodic=False, settle_revolutions=1,
                                          rtol=1e-5), "settle_revolutions", "settling=Settling(periods=...)")
    n_new = bearing_noise(o, revolutions=1, harmonics=2, periodic=False, settling=Settling(periods=1),
                          integration=Integration(rtol=1e-5))
    assert np.array_equal(n_old.pressure, n_new.pressure) and n_old.level_db == n_new.level_db


def test_the_package_itself_raises_no_deprecation_warning():
    """A short orbit, a rotor run, a ball sequence and a settle: none of them goes through an old keyword."""
    from transient.study.settle import settle

    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        o = _orbit()
        assert o.run(0.2, integration=Integration(method="bdf2"), recording=Recording(record="force")).success
        settle(o, max_periods=2, require=False, integration=Integration(rtol=1e-5))
        assert _rotor().run(0.1, 3000.0, recording=Recording(outputs_per_revolution=20)).success
        ThrustBallBearing().sequence(30, 80, 50e-6, n_passes=2)


def test_the_old_keywords_of_newton_and_the_shootings_still_work_and_warn():
    from transient.solvers.newton import NewtonSettings, newton
    from transient.solvers.shooting import ShootingSettings, newton_krylov, newton_picard

    F, J = (lambda x: x ** 2 - 2.0), (lambda x, s: np.diag(2 * x))
    a = _warned(lambda: newton(F, J, np.array([1.0]), xtol=1e-12, max_iter=20), "xtol",
                "settings=NewtonSettings(xtol=...)")
    b = newton(F, J, np.array([1.0]), settings=NewtonSettings(xtol=1e-12, max_iter=20))
    assert np.array_equal(a.x, b.x) and a.iterations == b.iterations
    with pytest.raises(ValueError, match=r"newton: ftol=1e-08 and settings=NewtonSettings\(\.\.\.\) both given"):
        newton(F, J, np.array([1.0]), ftol=1e-8, settings=NewtonSettings())
    M = np.diag([0.5, 0.2, 0.1])  # an affine period map y -> M y + c: its fixed point is (I - M)^-1 c
    c = np.array([1.0, 2.0, 3.0])

    def flow(y, t0, T, rtol):
        return M @ y + c

    a = _warned(lambda: newton_picard(flow, np.zeros(3), 1.0, np.eye(3)[:, :1], tol=1e-12), "tol",
                "settings=ShootingSettings(tol=...)")
    b = newton_picard(flow, np.zeros(3), 1.0, np.eye(3)[:, :1], settings=ShootingSettings(tol=1e-12))
    assert a.success and np.array_equal(a.state, b.state)
    assert np.allclose(b.state, np.linalg.solve(np.eye(3) - M, c), rtol=1e-10)
    k = _warned(lambda: newton_krylov(flow, np.zeros(3), 1.0, tol=1e-12, krylov_tol=1e-6), "tol",
                "settings=ShootingSettings(tol=...)")
    assert k.success and np.array_equal(k.state, newton_krylov(
        flow, np.zeros(3), 1.0, settings=ShootingSettings(tol=1e-12, krylov_tol=1e-6)).state)
    with pytest.raises(TypeError, match=r"newton_krylov\(\) got an unexpected keyword argument 'refresh'"):
        newton_krylov(flow, np.zeros(3), 1.0, refresh=0.5)
    with pytest.raises(ValueError, match=r"newton_krylov: settings=ShootingSettings\(refresh=0\.5\) is not used"):
        newton_krylov(flow, np.zeros(3), 1.0, settings=ShootingSettings(refresh=0.5))


def test_the_reynolds_operator_jacobian_takes_its_ten_fields_positionally():
    from transient.fv.reynolds import ReynoldsOperator

    with pytest.raises(TypeError, match="takes the 10 fields P, dP, C, dC, kx, dkx, kz, dkz, cx, cz; got 9"):
        ReynoldsOperator.jacobian(None, *([np.zeros(1)] * 9))


def test_the_old_iteration_keywords_of_periodic_response_still_work_and_warn():
    """``max_iter=``, ``fd_step=``, ``relax=`` of ``periodic_response`` are ``shooting=ShootingSettings(...)``
    fields: the old spelling warns and gives the same orbit; tolerances in ``shooting`` are refused (they are
    ``rtol`` and ``tol``)."""
    from transient.models.journal.periodic import periodic_response
    from transient.solvers.shooting import ShootingSettings

    o = JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000.0, **rho_kim.ROTOR)
    a = _warned(lambda: periodic_response(o, rtol=1e-6, max_iter=2), "max_iter", "shooting=ShootingSettings(max_iter=...)")
    b = periodic_response(o, rtol=1e-6, shooting=ShootingSettings(max_iter=2, relax=1))
    assert np.array_equal(a.state, b.state) and a.iterations == b.iterations
    with pytest.raises(ValueError, match=r"periodic_response: shooting=ShootingSettings\(tol=0\.001\) is not used"):
        periodic_response(o, shooting=ShootingSettings(tol=1e-3))
