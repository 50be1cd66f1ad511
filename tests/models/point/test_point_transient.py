"""Transient EHL point contact: its long-time limit is the steady film; a load step squeezes the film."""

import numpy as np
import pytest

from transient.models.point import PointContact
from transient.solvers.settings import Integration

BASE = dict(load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)
GRID = (33, 33)
BDF2 = Integration(method="bdf2", rtol=1e-3)


@pytest.fixture(scope="module")
def contact():
    return PointContact(0.01, grid=GRID, domain=(-4.5, 2.0, 2.5), **BASE)


def test_start_from_dry_contact_settles_on_the_steady_film(contact):
    s = contact.steady()
    r = contact.transient(t_end=60 * contact.time_scale, start="dry", integration=BDF2)
    assert r.success
    assert r.h_central[-1] == pytest.approx(s.h_central, rel=1e-4)
    assert r.h_min[-1] == pytest.approx(s.h_min, rel=1e-3)
    assert np.max(np.abs(r.pressure - s.pressure)) < 1e-3 * s.p_max


@pytest.mark.slow
def test_load_step_squeezes_to_the_steady_film_at_the_new_load(contact):
    s1 = contact.steady()
    r = contact.transient(t_end=60 * contact.time_scale, load=2 * BASE["load"], start=s1, integration=BDF2)
    assert r.success
    # the film thins to the new level (undershooting it by less than 0.1 % on the way)
    assert r.h_central[-1] < 0.96 * r.h_central[0] and r.h_central.min() > 0.999 * r.h_central[-1]
    # the same SI grid at the doubled load: its steady film is the transient's limit
    b1 = contact.b
    twice = PointContact(0.01, grid=GRID, **dict(BASE, load=2 * BASE["load"]))
    f = b1 / twice.b
    twice = PointContact(0.01, grid=GRID, domain=tuple(v * f for v in contact.domain), **dict(BASE, load=2 * BASE["load"]))
    assert np.allclose(twice.x_nodes * twice.b, contact.x_nodes * b1, rtol=1e-12, atol=1e-15)
    s2 = twice.steady()
    assert r.h_central[-1] == pytest.approx(s2.h_central, rel=1e-4)
    assert r.load[-1] == pytest.approx(2 * BASE["load"])


@pytest.mark.slow
def test_load_ramp_given_as_a_function_of_time_ends_on_the_steady_film(contact):
    # 20 -> 40 N over 10 b/u, held to 60 b/u: measured 3.2e-8 (h_c) and 1.9e-8 (h_min) from the steady film
    s1 = contact.steady()
    ramp = lambda t: BASE["load"] * (1.0 + min(t / (10 * contact.time_scale), 1.0))
    r = contact.transient(t_end=60 * contact.time_scale, load=ramp, start=s1, integration=BDF2)
    assert r.success
    assert np.allclose(r.load, [ramp(t) for t in r.t], rtol=1e-12)
    assert np.all(np.diff(r.load) >= 0.0) and r.load[-1] == pytest.approx(2 * BASE["load"])
    f = contact.b / PointContact(0.01, grid=GRID, **dict(BASE, load=2 * BASE["load"])).b
    twice = PointContact(0.01, grid=GRID, domain=tuple(v * f for v in contact.domain),
                         **dict(BASE, load=2 * BASE["load"]))
    s2 = twice.steady()
    assert r.h_central[-1] == pytest.approx(s2.h_central, rel=1e-6)
    assert r.h_min[-1] == pytest.approx(s2.h_min, rel=1e-6)
