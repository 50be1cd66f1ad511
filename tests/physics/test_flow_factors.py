"""Patir-Cheng flow factors and the Wu-Zheng contact factor (transient.physics.flow_factors)."""

import math

import numpy as np
import pytest
from scipy import stats

from transient.physics.asperity import DiscreteDensity
from transient.physics.flow_factors import (PRESSURE_FLOW_TABLE, SHEAR_FLOW_TABLE, combined_shear_flow_factor,
                                         contact_factor, contact_factor_wu_zheng_fit, mean_film_thickness,
                                         pressure_flow_factors, shear_flow_factor)

GAMMAS = [1 / 9, 1 / 6, 1 / 3, 1.0, 3.0, 6.0, 9.0]


@pytest.mark.parametrize("g", GAMMAS)
def test_pressure_flow_factor_tends_to_one(g):
    px, py = pressure_flow_factors(np.array([1e3, 1e4]), g)
    assert np.all(np.abs(px - 1) < 1e-3) and np.all(np.abs(py - 1) < 1e-3)
    assert abs(px[1] - 1) < abs(px[0] - 1) or abs(px[0] - 1) < 1e-12


def test_pressure_flow_factor_published_points():
    # Patir & Cheng (1978) eq. (20) with Table 1 (C, r): isotropic 1 - 0.90 exp(-0.56 H)
    assert pressure_flow_factors(1.0, 1.0)[0] == pytest.approx(1 - 0.90 * math.exp(-0.56), rel=1e-12)
    assert pressure_flow_factors(3.0, 1 / 9)[0] == pytest.approx(1 - 1.48 * math.exp(-0.42 * 3), rel=1e-12)
    assert pressure_flow_factors(2.0, 6.0)[0] == pytest.approx(1 + 0.520 * 2.0 ** -1.5, rel=1e-12)
    assert pressure_flow_factors(1.0, 3.0)[0] == pytest.approx(1 + 0.225, rel=1e-12)
    with pytest.raises(ValueError, match="gamma = 0.3333"):  # phi_y(gamma=3) uses the 1/3 fit: H >= 0.75
        pressure_flow_factors(0.5, 3.0)
    # isotropic: phi_x = phi_y; transverse (gamma < 1) blocks x flow, longitudinal enhances it
    px, py = pressure_flow_factors(np.linspace(0.5, 6, 12), 1.0)
    assert np.array_equal(px, py)
    assert np.all(pressure_flow_factors(np.linspace(1, 6, 12), 1 / 3)[0] < 1)
    assert np.all(pressure_flow_factors(np.linspace(1, 6, 12), 3.0)[0] > 1)


@pytest.mark.parametrize("g", GAMMAS)
def test_phi_y_is_phi_x_of_reciprocal_gamma(g):
    h = np.linspace(1.0, 6.0, 11)
    assert np.allclose(pressure_flow_factors(h, g)[1], pressure_flow_factors(h, 1 / g)[0], rtol=1e-12)


def test_pressure_flow_factor_continuous_in_gamma_and_H():
    h = np.linspace(1.0, 6.0, 26)
    for g in GAMMAS:
        for eps in (1e-7, -1e-7):
            gg = g * (1 + eps)
            if 1 / 9 <= gg <= 9:
                np.testing.assert_allclose(pressure_flow_factors(h, gg)[0], pressure_flow_factors(h, g)[0],
                                           atol=1e-6)
    # interpolated gamma lies between its neighbours
    a, b, m = (pressure_flow_factors(h, g)[0] for g in (1.0, 3.0, math.sqrt(3.0)))
    assert np.all((m - a) * (m - b) <= 1e-15)
    assert np.max(np.abs(np.diff(pressure_flow_factors(np.linspace(1, 6, 501), 2.0)[0]))) < 0.01


def test_shear_flow_factor_branches_continuous_at_H5():
    # the two branches of Patir & Cheng (1979) Table A1 are fitted separately: they meet within 0.2 %
    for g, (A1, a1, a2, a3, A2) in SHEAR_FLOW_TABLE.items():
        low = A1 * 5 ** a1 * math.exp(-a2 * 5 + a3 * 25)
        assert shear_flow_factor(5.0, g) == pytest.approx(low, rel=1e-12)
        assert shear_flow_factor(5.0 + 1e-9, g) == pytest.approx(A2 * math.exp(-1.25), rel=1e-9)
        assert abs(low / (A2 * math.exp(-1.25)) - 1) < 2e-3


def test_shear_flow_factor_values_and_limits():
    assert shear_flow_factor(1.0, 1.0) == pytest.approx(1.899 * math.exp(-0.92 + 0.05), rel=1e-12)
    assert shear_flow_factor(30.0, 1.0) < 1e-3
    h = np.linspace(0.5, 4, 8)
    # transverse roughness carries more shear flow than longitudinal
    assert np.all(shear_flow_factor(h, 1 / 9) > shear_flow_factor(h, 1.0))
    assert np.all(shear_flow_factor(h, 1.0) > shear_flow_factor(h, 9.0))
    # phi_s for two equal surfaces vanishes; for surface 1 alone it is Phi_s
    assert np.allclose(combined_shear_flow_factor(h, 1e-6, 1e-6), 0.0)
    assert np.allclose(combined_shear_flow_factor(h, 1e-6, 0.0, gamma1=3.0), shear_flow_factor(h, 3.0))


def test_fit_range_errors():
    with pytest.raises(ValueError) as e:
        pressure_flow_factors(np.array([0.8, 2.0]), 1 / 9)
    assert "H = h/sigma = 0.8" in str(e.value) and "H >= 1" in str(e.value)
    assert pressure_flow_factors(0.2, 1 / 9, extrapolate=True)[0] == 0.0   # clipped at zero
    with pytest.raises(ValueError, match="gamma = 12"):
        pressure_flow_factors(2.0, 12.0)
    with pytest.raises(ValueError, match="H = h/sigma = 0.3"):
        shear_flow_factor(0.3, 1.0)


def test_contact_factor_gaussian_limits_and_derivative():
    assert contact_factor(0.0) == 0.5
    assert contact_factor(8.0) == pytest.approx(1.0, abs=1e-14)
    assert contact_factor(-8.0) == pytest.approx(0.0, abs=1e-14)
    H = np.linspace(-3, 4, 15)
    np.testing.assert_allclose(contact_factor(H), stats.norm.cdf(H), rtol=1e-13)
    # phi_c = d(h_bar)/d(h0) (Lee & Rhim eq. 9), h_bar -> h0 for large h0, -> 0 deep in contact
    d = (mean_film_thickness(H + 1e-6) - mean_film_thickness(H - 1e-6)) / 2e-6
    np.testing.assert_allclose(d, contact_factor(H), rtol=1e-7)
    assert mean_film_thickness(10.0) == pytest.approx(10.0, rel=1e-12)
    assert mean_film_thickness(-10.0) < 1e-20


def test_wu_zheng_fit_close_to_gaussian():
    H = np.linspace(0, 2.999, 300)
    assert np.max(np.abs(contact_factor_wu_zheng_fit(H) - stats.norm.cdf(H))) < 0.005
    assert contact_factor_wu_zheng_fit(4.0) == 1.0
    with pytest.raises(ValueError, match="H = -1"):
        contact_factor_wu_zheng_fit(-1.0)


def test_discrete_contact_factor_matches_gaussian():
    d = DiscreteDensity.gaussian(1e-6, bins=800)
    H = np.linspace(-3, 3, 13)
    np.testing.assert_allclose(d.contact_factor(H * 1e-6), stats.norm.cdf(H), atol=1e-4)
    np.testing.assert_allclose(d.mean_gap(H * 1e-6) / 1e-6, mean_film_thickness(H), atol=1e-3)


def test_tables_complete():
    assert sorted(PRESSURE_FLOW_TABLE) == sorted(SHEAR_FLOW_TABLE)
    assert len(PRESSURE_FLOW_TABLE) == 7
