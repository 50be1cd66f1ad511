"""Seed 001, transient EHL on the penalty form (IDA, deprecated beside the default film-content BDF2): pure squeeze
against its closed form, long-time limits equal to the penalty form's steady solution, and the penalty form of the
exit condition converging to the exact complementarity."""

import numpy as np
import pytest

from transient.models.roller import LineContact, RollerContact, TaperedRoller
from transient.models.roller.line_contact import rigid_squeeze
from transient.models.roller.transient import GAMMA
from transient.solvers.settings import Integration
from transient.verification.ehl_reference import squeeze_film_history

R, E = 0.01, 220e9
pytestmark = pytest.mark.filterwarnings("ignore:.*penalty form.*:DeprecationWarning")


def ida(rtol):
    return Integration(method="ida", rtol=rtol)


def paperlike(n):
    return LineContact(R, 3.1e4, 1.0, 0.022, 2500 / E, E, grid=n, domain=(-5.0, 2.5))  # the paper's extent


def test_rigid_pure_squeeze_matches_closed_form_second_order():
    err = []
    for n in (101, 201):
        r = rigid_squeeze(R, 1e4, 0.05, 1e-5, 5e-5, grid=n, rtol=1e-8, half_width=5.0)
        assert r.success
        ref = squeeze_film_history(r.t, 1e-5, 1e4, R, 0.05, r.x[0], r.x[-1])
        assert r.h0[-1] < 0.25 * r.h0[0]  # the film closes fourfold over the run
        err.append(np.max(np.abs(r.h0 / ref - 1)))
    assert err[1] < 1e-2 and 3.0 < err[0] / err[1] < 5.0


def test_dry_start_tends_to_the_steady_film():
    c = paperlike(101)
    s = c.steady(penalty=GAMMA)
    r = c.transient(t_end=40 * c.time_scale, start="dry", n_out=21, integration=ida(1e-6))
    assert r.success
    assert r.h_central[0] < 0.6 * s.h_central  # starts from half the Dowson-Toyoda film
    for key in ("h_central", "h_min", "p_max"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(s, key), rel=1e-6)


def test_load_pulse_returns_to_the_steady_film():
    c = paperlike(101)
    s = c.steady(penalty=GAMMA)
    w = c.load_per_length
    r = c.transient(t_end=40 * c.time_scale, start=s, n_out=41, integration=ida(1e-6),
                    load=lambda t: w * (1 + 0.5 * np.sin(np.pi * min(t / (10 * c.time_scale), 1.0)) ** 2))
    assert r.success and r.load.max() == pytest.approx(1.5 * w, rel=1e-3)
    assert r.h_min.min() < 0.97 * s.h_min  # the pulse thins the film
    assert r.h_central[-1] == pytest.approx(s.h_central, rel=1e-6)


def test_penalty_form_converges_to_the_exact_complementarity_as_one_over_gamma():
    c = paperlike(201)
    exact = c.steady()
    err = [abs(c.steady(penalty=g).h_min / exact.h_min - 1) for g in (1e3, 1e4, 1e5)]
    assert 7 < err[0] / err[1] < 13 and 7 < err[1] / err[2] < 13
    assert err[1] < 1e-4  # the transient's gamma


@pytest.mark.slow
def test_roller_transient_from_dry_tends_to_steady():
    ro = TaperedRoller(R, 10.0, 2 * R, 0.5 * R, 0.2 * R, 0.0)
    c = RollerContact.from_dimensionless(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E, roller=ro,
                                         grid=("clustered", 32, 25))
    s = c.steady(penalty=GAMMA)
    r = c.transient(t_end=40 * c.time_scale, start="dry", n_out=11, integration=ida(1e-5))
    assert r.success
    for key in ("h_central", "h_min", "p_max"):
        assert getattr(r, key)[-1] == pytest.approx(getattr(s, key), rel=1e-6)
