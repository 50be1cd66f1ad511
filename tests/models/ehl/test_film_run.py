"""The EHL contacts' transients on the one run driver: settings objects, the old keywords warning and giving the
same run, the default method (the film-content BDF2, whose limit is ``steady()``), checkpoint/resume bit for bit,
the time budget, and the settings a film does not use refused by name."""

import math
import warnings

import numpy as np
import pytest

from transient.models.point import PointContact
from transient.models.roller import LineContact
from transient.solvers.longrun import CheckpointError
from transient.solvers.settings import Integration, LongRun

POINT = dict(load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)
R, E, W = 0.01, 220e9, 3.1e4
BDF2 = Integration(method="bdf2", rtol=1e-3)
#: the paper's short inlet is starved at this load (the film is that of this domain, on purpose)
pytestmark = pytest.mark.filterwarnings("ignore::transient.models.roller.line_contact.StarvedInletWarning")


@pytest.fixture(scope="module")
def point():
    return PointContact(0.01, grid=(25, 25), domain=(-3.0, 1.5, 1.5), **POINT)


@pytest.fixture(scope="module")
def line():
    return LineContact(R, W, 1.0, 0.022, 2500 / E, E, grid=61, domain=(-5.0, 2.5))


def _same(a, b, names=("t", "h_central", "h_min", "p_max", "h0", "load", "final_state")):
    for name in names:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_old_keywords_warn_and_run_the_same_as_the_settings_objects(point):
    t_end = 2 * point.time_scale
    new = point.transient(t_end, n_out=3, integration=BDF2)
    with pytest.warns(DeprecationWarning, match=r"rtol= is deprecated.*integration=Integration\(rtol=\.\.\.\)"):
        old = point.transient(t_end, n_out=3, rtol=1e-3)
    assert new.success and old.success
    _same(new, old)


def test_the_line_contact_runs_the_film_content_by_default(line):
    t_end = 3 * line.time_scale
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # the default warns of nothing
        default = line.transient(t_end, n_out=4)
        bdf2 = line.transient(t_end, n_out=4, integration=Integration(method="bdf2", rtol=1e-4))
    _same(default, bdf2)
    with pytest.warns(DeprecationWarning, match="penalty form"):
        ida = line.transient(t_end, n_out=4, integration=Integration(method="ida", rtol=1e-4))
    assert ida.success and not np.array_equal(ida.h_central, default.h_central)


@pytest.mark.parametrize("which", ["point", "line"])
def test_a_checkpointed_transient_resumes_bit_for_bit(tmp_path, request, which):
    contact = request.getfixturevalue(which)
    kw = dict(n_out=21, integration=Integration(method="bdf2", rtol=1e-3 if which == "point" else 1e-5))
    t_end = 4 * contact.time_scale
    whole = contact.transient(t_end, long_run=LongRun(checkpoint=tmp_path / "whole.npz"), **kw)
    part = tmp_path / "part.npz"
    cut = contact.transient(t_end, long_run=LongRun(checkpoint=part, stop=lambda r: "cut" if r.t.size > 8 else None),
                            **kw)
    assert cut.message == "cut" and cut.t.size == 9  # chunks of a tenth of the 20 intervals
    resumed = contact.transient(t_end, long_run=LongRun(checkpoint=part, resume=True), **kw)
    assert whole.success and resumed.success
    _same(resumed, whole)
    assert np.array_equal(resumed.pressure, whole.pressure)
    with pytest.raises(CheckpointError, match="load"):
        contact.transient(t_end, load=_more_load(contact), long_run=LongRun(checkpoint=part, resume=True), **kw)


def _more_load(contact):
    return 1.01 * (contact.load if hasattr(contact, "hertz") else contact.load_per_length)


def test_time_budget_and_settings_a_film_does_not_use_are_refused(point, line):
    r = point.transient(50 * point.time_scale, integration=BDF2, long_run=LongRun(time_budget=1e-6))
    assert not r.success and "budget" in r.message
    with pytest.raises(ValueError, match=r"PointContact.transient cannot .*'ida'|PointContact.transient.*'ida'"):
        point.transient(point.time_scale, integration=Integration(method="ida"))
    with pytest.raises(ValueError, match=r"integration=Integration\(atol=1e-06\) is not used"):
        point.transient(point.time_scale, integration=Integration(method="bdf2", atol=1e-6))
    with pytest.raises(ValueError, match=r"long_run=LongRun\(chunk_revolutions=2.0\) is not used"):
        line.transient(line.time_scale, long_run=LongRun(chunk_revolutions=2.0))
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match=r"long_run=LongRun\(progress=True\)"):
        line.transient(line.time_scale, integration=Integration(method="ida"), long_run=LongRun(progress=True))
    assert math.isfinite(point.time_scale)
