"""The tapered roller's transient on the film-content form (BDF2, the default) at the paper's loading on the
paper case's test grid (40 x 25 clustered): its long-time limit is the steady film-content film (``steady(method=
"fbns")``, at this load also ``steady()``'s film), not the penalty form's."""

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.transient import GAMMA
from transient.solvers.settings import Integration

E, RM = 220e9, 0.01
BDF2 = Integration(method="bdf2", rtol=1e-5)
CASE = dict(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E)  # the paper's loading on a shorter roller


@pytest.fixture(scope="module")
def contact():
    ro = TaperedRoller(RM, 10.0, 2 * RM, 0.5 * RM, 0.2 * RM, 0.002)
    return RollerContact.from_dimensionless(**CASE, roller=ro, grid=("clustered", 40, 25))


@pytest.fixture(scope="module")
def steady(contact):
    return contact.steady(method="fbns", tol=1e-10)


@pytest.mark.slow
def test_from_the_penalty_film_the_transient_tends_to_the_content_film(contact, steady):
    penalty = contact.steady(penalty=GAMMA, tol=1e-10)
    assert abs(penalty.h_min / steady.h_min - 1.0) > 1e-6  # the limit tells the two forms apart
    r = contact.transient(t_end=5 * contact.time_scale, start=penalty, n_out=6, integration=BDF2)
    assert r.success
    for key in ("h_central", "h_min"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(steady, key), rel=1e-7)
    # the pressure peak relaxes slowest: measured 2.5e-7 after these 5 transits
    assert r.p_max[-1] == pytest.approx(steady.p_max, rel=1e-6)


def test_a_steady_start_stays_on_the_steady_film(contact, steady):
    r = contact.transient(t_end=5 * contact.time_scale, start=steady, n_out=6, integration=BDF2)
    assert r.success
    assert r.h_central[0] == pytest.approx(steady.h_central, rel=1e-12)  # the start's content is its own
    for key in ("h_central", "h_min", "p_max"):
        assert np.max(np.abs(getattr(r, key) / getattr(steady, key) - 1.0)) < 1e-8


def test_an_unknown_method_is_refused_before_any_work(contact):
    with pytest.raises(ValueError, match="method"):
        contact.transient(t_end=contact.time_scale, integration=Integration(method="rk4", dt=0.1))


@pytest.mark.slow
def test_the_default_transient_from_the_dry_contact_reaches_the_steady_film():
    # the nodes that cross the cavitation boundary leave the step's error test: measured 1,574 steps over 40 c/u
    # (held in the test, the steps stay at 1e-6 - 1e-4 c/u: ~1e5 steps); the limit within 7e-9 of steady()
    ro = TaperedRoller(RM, 10.0, 2 * RM, 0.5 * RM, 0.2 * RM, 0.0)
    c = RollerContact.from_dimensionless(**CASE, roller=ro, grid=("clustered", 32, 25))
    s = c.steady(method="fbns", tol=1e-10)
    r = c.transient(t_end=40 * c.time_scale, start="dry", n_out=11)
    assert r.success and r.n_steps < 3000
    for key in ("h_central", "h_min"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(s, key), rel=1e-7)
