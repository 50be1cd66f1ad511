"""The line contact's transient on the film-content form (BDF2 on the stepper contract, the default): its
long-time limit is ``steady()`` (the exact complementarity), not the penalty form's ``steady(penalty=GAMMA)``;
load changes against the penalty form's (deprecated) IDA transient and the steady film at the new load."""

import math

import numpy as np
import pytest

from transient.models.roller import LineContact
from transient.models.roller.transient import GAMMA
from transient.solvers.settings import Integration

R, E, W = 0.01, 220e9, 3.1e4
DOMAIN = (-5.0, 2.5)
BDF2 = Integration(method="bdf2", rtol=1e-5)
#: the paper's short inlet is starved at this load (the film is that of this domain, on purpose)
pytestmark = pytest.mark.filterwarnings("ignore::transient.models.roller.line_contact.StarvedInletWarning")


def paperlike(load=W, n=101):
    """The paper's extent in units of the Hertz half-width at ``W``: the same SI nodes at any ``load``."""
    f = math.sqrt(W / load)  # b grows as sqrt(load)
    return LineContact(R, load, 1.0, 0.022, 2500 / E, E, grid=n, domain=(DOMAIN[0] * f, DOMAIN[1] * f))


@pytest.fixture(scope="module")
def contact():
    return paperlike()


@pytest.fixture(scope="module")
def steady(contact):
    return contact.steady()


def test_dry_start_tends_to_steady_not_to_the_penalty_film(contact, steady):
    r = contact.transient(t_end=40 * contact.time_scale, start="dry", n_out=11, integration=BDF2)
    assert r.success and r.n_steps > 10
    assert r.h_central[0] < 0.6 * steady.h_central  # starts from half the Dowson-Toyoda film
    # measured 3e-10: the steady solve's tolerance; the penalty film is 7e-6 (h_c) to 1.7e-5 (h_min) away
    for key in ("h_central", "h_min", "p_max"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(steady, key), rel=1e-7)
    penalty = contact.steady(penalty=GAMMA)
    assert abs(penalty.h_min / steady.h_min - 1.0) > 1e-6  # the limit tells the two forms apart


def test_load_pulse_follows_the_penalty_transient_and_returns_to_steady(contact, steady):
    w, ts = contact.load_per_length, contact.time_scale
    pulse = lambda t: w * (1 + 0.5 * np.sin(np.pi * min(t / (10 * ts), 1.0)) ** 2)
    rb = contact.transient(t_end=40 * ts, start=steady, n_out=41, load=pulse, integration=BDF2)
    with pytest.warns(DeprecationWarning, match="penalty form"):
        ri = contact.transient(t_end=40 * ts, start=steady, n_out=41, load=pulse,
                               integration=Integration(method="ida", rtol=1e-5))
    assert rb.success and ri.success
    assert rb.load.max() == pytest.approx(1.5 * w, rel=1e-3)
    assert rb.h_central[0] == pytest.approx(steady.h_central, rel=1e-12)  # the start's content is consistent
    assert rb.h_min.min() < 0.97 * steady.h_min  # the pulse thins the film
    # the same history as the penalty form's up to its O(1/GAMMA) difference (measured 1.1e-5)
    assert np.max(np.abs(rb.h_central / ri.h_central - 1.0)) < 1e-4
    assert rb.h_central[-1] == pytest.approx(steady.h_central, rel=1e-7)


@pytest.mark.slow
def test_load_step_ends_on_the_steady_film_at_the_new_load(contact, steady):
    r = contact.transient(t_end=30 * contact.time_scale, start=steady, n_out=16, load=2 * W, integration=BDF2)
    assert r.success and r.load[-1] == pytest.approx(2 * W)
    twice = paperlike(2 * W)
    assert np.allclose(twice.grid.x * twice.b, contact.grid.x * contact.b, rtol=1e-12, atol=1e-15)
    s2 = twice.steady()
    assert r.h_central[-1] < 0.97 * steady.h_central
    for key in ("h_central", "h_min", "p_max"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(s2, key), rel=1e-6)


def test_an_unknown_method_and_a_matrix_free_grid_are_refused_before_any_work(contact):
    with pytest.raises(ValueError, match="method"):
        contact.transient(t_end=contact.time_scale, integration=Integration(method="rk4", dt=0.1))
    fine = paperlike(n=2049)
    with pytest.raises(ValueError, match="2049 uniform nodes"):
        fine.transient(t_end=fine.time_scale)
