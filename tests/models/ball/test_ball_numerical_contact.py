"""ThrustBallBearing(contact="numerical"): each pass's film from the starved point contact at its inlet film."""

import pytest

from transient.models.ball import ThrustBallBearing
from transient.models.point import PointContact

#: 2000 rpm: Moes M ~ 190 for the paper's bearing at 30 N (the paper's 80 rpm gives M ~ 2100, which the
#: point-contact solver does not resolve on coarse grids)
RUN = dict(load=30.0, speed_rpm=2000.0, grid="uniform", n_cells=64)


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
