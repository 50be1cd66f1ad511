"""A unit slip in a point contact's inputs (a radius in mm, a viscosity in mPa s, a load in kN, a speed in mm/s)
is named as such, not only as a grid too coarse for the contact; a plausible contact on a coarse grid still gets
the grid advice alone."""

import pytest

from transient import PointContact
from transient.models.point.plausibility import implausible

BASE = dict(radius_x=0.01, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


@pytest.mark.parametrize("name, value, words", [
    ("radius_x", 10.0, "radius_x = 10 m"),           # 10 mm given as 10
    ("viscosity", 40.0, "viscosity = 40 Pa s"),      # 40 mPa s given as 40
    ("load", 0.02, "load = 0.02 N"),                 # 20 N given in kN
    ("speed", 1000.0, "speed = 1000 m/s"),           # 1 m/s given in mm/s
])
def test_a_unit_slip_is_named_before_the_grid(name, value, words):
    with pytest.raises(ValueError) as err:
        PointContact(**dict(BASE, **{name: value}))
    text = str(err.value)
    assert text.startswith("implausible for an EHL point contact: " + words) and "\n" not in text
    assert "the default grid would be" in text  # and what it does to the grid
    with pytest.raises(ValueError, match="nodes per Hertz semi-axes"):  # an explicit coarse grid: the same slip named
        PointContact(**dict(BASE, **{name: value}), grid=(65, 65))


def test_a_plausible_contact_on_a_coarse_grid_gets_the_grid_advice_alone():
    with pytest.raises(ValueError, match=r"^grid = \(17, 17\) puts .* \(more nodes or a smaller domain\)$"):
        PointContact(**BASE, grid=(17, 17))


def test_the_load_is_judged_by_its_pressure_only_when_the_geometry_is_plausible():
    assert implausible(0.01, 0.04, 1.0, 20.0, 0.78e9) == []
    assert [s.split(" =")[0] for s in implausible(0.01, 0.04, 1.0, 0.02, 0.078e9)] == ["load"]
    assert [s.split(" =")[0] for s in implausible(10.0, 0.04, 1.0, 20.0, 0.0078e9)] == ["radius_x"]
