"""Viscosity against temperature and the oil's thermal properties (physics/lubricant.py)."""

import math

import numpy as np
import pytest

from transient.physics.lubricant import ExponentialViscosity, ThermalProperties, VogelViscosity


def test_two_point_law_passes_through_both_points():
    law = ExponentialViscosity.two_point((323.0, 0.01902), (353.0, 0.00772))
    assert law.at(323.0) == pytest.approx(0.01902, rel=1e-14)
    assert law.at(353.0) == pytest.approx(0.00772, rel=1e-14)
    assert law.coefficient == pytest.approx(math.log(0.01902 / 0.00772) / 30.0, rel=1e-14)
    T = np.array([300.0, 340.0])
    assert np.allclose(law.at(T), 0.01902 * np.exp(-law.coefficient * (T - 323.0)), rtol=1e-14)


def test_equal_viscosities_give_an_exactly_isoviscous_law():
    law = ExponentialViscosity.two_point((320.0, 0.03), (350.0, 0.03))
    assert law.coefficient == 0.0
    assert np.all(law.at(np.linspace(300.0, 400.0, 7)) == 0.03)


def test_vogel_law_and_pressure_dependence():
    law = VogelViscosity(6.4e-5, 900.0, 140.0)
    assert law.at(313.15) == pytest.approx(6.4e-5 * math.exp(900.0 / (313.15 - 140.0)), rel=1e-14)
    barus = ExponentialViscosity(0.02, 320.0, 0.03, pressure_viscosity=2e-8)
    assert barus.at(320.0, 50e6) == pytest.approx(0.02 * math.exp(1.0), rel=1e-14)


@pytest.mark.parametrize("make, name", [
    (lambda: ExponentialViscosity.two_point((323.0, 0.01), (353.0, 0.02)), "viscosity_at"),
    (lambda: ExponentialViscosity.two_point((323.0, 0.01), (323.0, 0.02)), "viscosity_at[1][0]"),
    (lambda: ExponentialViscosity.two_point((-5.0, 0.01), (323.0, 0.02)), "viscosity_at[0][0]"),
    (lambda: ExponentialViscosity.two_point((300.0,), (323.0, 0.02)), "viscosity_at[0]"),
    (lambda: ExponentialViscosity(0.02, 320.0, -0.01), "coefficient"),
    (lambda: VogelViscosity(1e-4, 900.0, 400.0), "c"),
    (lambda: ThermalProperties(-870.0, 1900.0), "density"),
    (lambda: ThermalProperties(870.0, 1900.0, conductivity=0.0), "conductivity"),
    (lambda: ExponentialViscosity(0.02, 320.0, 0.03).at(5000.0), "temperature"),
])
def test_bad_input_is_named(make, name):
    with pytest.raises(ValueError, match=rf"^{__import__('re').escape(name)}"):
        make()
