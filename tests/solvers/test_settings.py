"""Run settings as objects (transient.solvers.settings): validated on creation, equivalent to the keywords."""

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Recording, ThrustBallBearing
from transient.params import rho_kim
from transient.solvers.longrun import CheckpointError


def _orbit():
    return JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000, **rho_kim.ROTOR)


@pytest.mark.parametrize("method", ["ida", "bdf2", "rk4"])
def test_objects_and_keywords_give_bitwise_identical_orbits(method):
    o = _orbit()
    steps = dict(steps_per_revolution=200) if method == "rk4" else {}
    by_keywords = o.run(0.5, method=method, rtol=1e-5, atol=1e-8, outputs_per_revolution=8, record=("force",),
                        chunk_revolutions=0.25, progress=False, **steps)
    by_objects = o.run(0.5, integration=Integration(method=method, rtol=1e-5, atol=1e-8, **steps),
                       recording=Recording(outputs_per_revolution=8, record="force"),
                       long_run=LongRun(chunk_revolutions=0.25, progress=False))
    assert by_keywords.success and by_objects.success
    for name in ("t", "x", "y", "force"):
        a, b = getattr(by_keywords, name), getattr(by_objects, name)
        assert a.shape == b.shape and np.array_equal(a, b), name
    # the same keywords beside the object that they agree with are accepted
    again = o.run(0.5, method=method, integration=Integration(method=method, rtol=1e-5, atol=1e-8, **steps),
                  outputs_per_revolution=8, record=("force",), chunk_revolutions=0.25, progress=False)
    assert np.array_equal(again.x, by_keywords.x)


def test_objects_and_keywords_give_identical_ball_sequences():
    b = ThrustBallBearing()
    kw = dict(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=3, stop_at_periodic=False)
    by_keywords = b.sequence(**kw, rtol=1e-5, atol=1e-9, record_profiles=True)
    by_objects = b.sequence(**kw, integration=Integration(method="cvode", rtol=1e-5, atol=1e-9),
                            recording=Recording(record=("profiles",)))
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
    (dict(integration=Integration(rtol=1e-5), rtol=1e-7), ("integration=Integration(rtol=1e-05", "rtol=1e-07")),
    (dict(integration=Integration(method="cvode"), method="ida"), ("method='cvode'", "method='ida'")),
    (dict(recording=Recording(outputs_per_revolution=8), outputs_per_revolution=4),
     ("recording=Recording(outputs_per_revolution=8", "outputs_per_revolution=4")),
    (dict(long_run=LongRun(resume=True), resume=False), ("long_run=LongRun(resume=True", "resume=False")),
])
def test_an_object_and_a_contradicting_keyword_is_an_error_naming_both(keywords, named):
    with pytest.raises(ValueError, match="both given") as e:
        _orbit().run(0.1, **keywords)
    assert all(n in str(e.value) for n in named), str(e.value)


def test_a_wrong_type_for_a_settings_object_is_named():
    with pytest.raises(ValueError, match=r"integration = \{'rtol': 1e-05\}; allowed: None or Integration\(\.\.\.\)"):
        _orbit().run(0.1, integration=dict(rtol=1e-5))


def test_the_checkpoint_key_comes_from_the_objects(tmp_path):
    """A checkpoint written through keywords resumes through the equal objects, and is refused (naming the
    setting) when an object differs."""
    o = _orbit()
    path = tmp_path / "orbit.npz"
    o.run(1.0, outputs_per_revolution=8, chunk_revolutions=0.5, checkpoint=path, progress=False)
    lr = LongRun(chunk_revolutions=0.5, checkpoint=path, resume=True, progress=False)
    r = o.run(1.0, integration=Integration(), recording=Recording(outputs_per_revolution=8), long_run=lr)
    assert r.success and r.t.size == 9
    with pytest.raises(CheckpointError, match="written with rtol = 1e-06, this run has rtol = 1e-07"):
        o.run(1.0, integration=Integration(rtol=1e-7), recording=Recording(outputs_per_revolution=8), long_run=lr)


def test_a_keyword_given_as_none_is_checked_not_taken_as_left_out():
    with pytest.raises(ValueError, match="record_from_revolution = None"):
        _orbit().run(0.1, record_from_revolution=None)
    with pytest.raises(ValueError, match=r"record = 1\.0; allowed: a series name or a tuple of them"):
        _orbit().run(0.1, record=1.0)
    with pytest.raises(ValueError, match="rtol"):
        ThrustBallBearing().sequence(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=2, rtol=None)
