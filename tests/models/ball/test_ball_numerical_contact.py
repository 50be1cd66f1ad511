"""ThrustBallBearing(contact="numerical"): each pass's film from the starved point contact at its inlet film."""

import pytest

from transient.models.ball import ThrustBallBearing
from transient.models.ball.settings import TrackSettings
from transient.models.point import PointContact

#: 2000 rpm: Moes M ~ 190 for the paper's bearing at 30 N (the paper's 80 rpm gives M ~ 2100, which the
#: point-contact solver does not resolve on coarse grids)
RUN = dict(load=30.0, speed_rpm=2000.0, track=TrackSettings(grid="uniform", n_cells=64))


def _contact(b, h_in=None):
    c = b.hertz(RUN["load"])
    return PointContact(b.rx, b.ry, load=c.load_per_ball, speed=b.entrainment_speed(RUN["speed_rpm"]),
                        viscosity=b.viscosity, pressure_viscosity=b.pressure_viscosity, modulus=c.e_prime,
                        inlet_film=h_in, grid=b.contact_grid)


def test_formula_is_the_default_and_the_choice_is_checked():
    assert ThrustBallBearing().contact == "formula"
    with pytest.raises(ValueError, match="contact"):
        ThrustBallBearing(contact="fem")


def test_flooded_pass_takes_the_numerical_flooded_film():
    b = ThrustBallBearing(contact="numerical")
    seq = b.sequence(ambient_film=100e-6, n_passes=1, **RUN)
    flooded = _contact(b).steady()
    assert seq.h_central[0] == pytest.approx(flooded.h_central, rel=1e-12)
    assert seq.h_minimum[0] == pytest.approx(flooded.h_min, rel=1e-12)
    formula = ThrustBallBearing().sequence(ambient_film=100e-6, n_passes=1, **RUN)
    assert seq.h_central[0] == pytest.approx(formula.h_central[0], rel=0.3)  # Hamrock-Dowson, coarse grid


@pytest.mark.slow
def test_starved_pass_takes_the_starved_point_contact_film():
    b = ThrustBallBearing(contact="numerical")
    h_in = 0.15e-6  # about the flooded central film (0.146 um, Hamrock-Dowson): starved, the meniscus inside
    seq = b.sequence(ambient_film=h_in, n_passes=1, **RUN)
    s = _contact(b, h_in).steady()
    assert not s.flooded_inlet
    assert seq.h_central[0] == pytest.approx(s.h_central, rel=1e-12)


@pytest.mark.slow
def test_reference_sequence_with_the_numerical_contact_runs_dry_flagged():
    """Jeong et al.'s reference point (80 rpm): the mass-conserving contact passes on h_in/rho_c, the track keeps
    half of it, so the inlet film falls ~2.4x per pass until it is below what the contact accepts; the formula's
    periodic parched film has a central film twice its inlet film."""
    ref = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6, n_passes=10, stop_at_periodic=False)
    num = ThrustBallBearing(contact="numerical").sequence(**ref)
    assert not num.success and num.final_regime == "parched"
    assert "pass 5" in num.message and "inlet_film" in num.message
    assert num.n_run == 5
    starved = slice(2, 5)
    assert num.h_central[starved] / num.h_inlet[starved] == pytest.approx(0.838, abs=0.01)
    assert num.h_inlet[3] / num.h_inlet[2] == pytest.approx(0.5 * num.h_central[2] / num.h_inlet[2], rel=0.01)
    formula = ThrustBallBearing().sequence(**ref)
    assert formula.success and formula.h_central[-1] / formula.h_inlet[-1] == pytest.approx(2.0, rel=0.01)
