"""Greenwood-Tripp integrals and asperity contact (transient.physics.asperity).

Reference values are computed in the tests from the standard normal closed forms (scipy.stats.norm)
or by scipy.integrate.quad at 1e-13 relative tolerance -- never by the code under test.
"""

import math

import numpy as np
import pytest
from scipy import integrate, stats

from transient.physics.asperity import (STEEL_CONTACT, AsperityContact, DiscreteDensity, greenwood_tripp,
                                     greenwood_tripp_derivative, steel_asperity_contact)
from transient.surfaces.roughness import RoughSurface

H = np.array([-6.0, -3.0, -1.5, -0.5, 0.0, 0.3, 1.0, 2.0, 3.0, 4.0, 5.0])


def quad_F(n, h):
    f = lambda s: (s - h) ** n * stats.norm.pdf(s)  # noqa: E731
    return integrate.quad(f, h, max(h, 0.0) + 40.0, epsabs=0.0, epsrel=1e-13, limit=400)[0]


def test_F0_F1_F2_closed_forms():
    Q, pdf = stats.norm.sf(H), stats.norm.pdf(H)
    np.testing.assert_allclose(greenwood_tripp(0, H), Q, rtol=1e-12)
    np.testing.assert_allclose(greenwood_tripp(1, H), pdf - H * Q, rtol=1e-10)
    np.testing.assert_allclose(greenwood_tripp(2, H), (1 + H ** 2) * Q - H * pdf, rtol=1e-9)


@pytest.mark.parametrize("n", [0, 1, 1.5, 2, 2.5])
def test_F_against_quadrature(n):
    hs = np.concatenate([H, [6.0, 8.0, 12.0]])  # includes the far tail, where the closed forms cancel
    ref = np.array([quad_F(n, h) for h in hs])
    np.testing.assert_allclose(greenwood_tripp(n, hs), ref, rtol=1e-8)


def test_F_at_zero_exact_values():
    # F_n(0) = Gamma(n+1)/sqrt(2 pi) * D_{-n-1}(0),  D_v(0) = 2^(v/2) sqrt(pi) / Gamma((1-v)/2)
    for n in (1.5, 2.5):
        v = -n - 1
        exact = math.gamma(n + 1) / math.sqrt(2 * math.pi) * 2 ** (v / 2) * math.sqrt(math.pi) / math.gamma((1 - v) / 2)
        assert greenwood_tripp(n, 0.0) == pytest.approx(exact, rel=1e-12)
    # published Greenwood-Tripp values to 4 digits
    assert round(greenwood_tripp(1.5, 0.0), 4) == 0.4300
    assert round(greenwood_tripp(2.5, 0.0), 4) == 0.6166


def test_F_vectorised_and_derivative():
    h = np.linspace(-2, 4, 12).reshape(3, 4)
    assert greenwood_tripp(1.5, h).shape == (3, 4)
    assert isinstance(greenwood_tripp(1.5, 0.5), float)
    for n in (1.5, 2.5, 1.0):
        d = (greenwood_tripp(n, h + 1e-6) - greenwood_tripp(n, h - 1e-6)) / 2e-6
        np.testing.assert_allclose(greenwood_tripp_derivative(n, h), d, rtol=1e-6)
    assert greenwood_tripp(2.5, 50.0) == 0.0
    with pytest.raises(ValueError, match="n = -1"):
        greenwood_tripp(-1, 0.0)


def test_discrete_gaussian_density_matches_gt():
    sig = 2e-6
    d = DiscreteDensity.gaussian(sig, bins=800)
    h = np.array([-2.0, -1.0, 0.0, 1.0, 2.0, 3.0])
    for n in (0, 1, 1.5, 2.5):
        np.testing.assert_allclose(d.integral(n, h * sig), sig ** n * np.array([quad_F(n, x) for x in h]),
                                   rtol=2e-3)
    assert d.sigma == pytest.approx(sig, rel=1e-3)


def test_discrete_density_of_generated_surface_matches_gaussian():
    """A 1024^2 Gaussian surface (l = 4 samples, ~65 000 independent patches): the histogram
    integrals for h0/sigma in [-1, 1.5] agree with the Gaussian ones within 3 % (the upper tail beyond
    1.5 sigma holds < 7 % of the samples, so relative sampling noise grows there: 8 % allowed at 2)."""
    s = RoughSurface.generate((1024, 1024), 1e-6, 5e-6, correlation_lengths=(4e-6, 4e-6), seed=31)
    dens = s.height_density(bins=256)
    sig = s.rq
    disc = steel_asperity_contact(5e-6, density=dens)
    gaus = AsperityContact(disc.asperity_density, disc.asperity_radius, disc.e_prime, disc.hardness, sigma=sig)
    h = np.array([-1.0, 0.0, 0.5, 1.0, 1.5]) * sig
    np.testing.assert_allclose(disc.load(h), gaus.load(h), rtol=0.03)
    np.testing.assert_allclose(disc.real_area_fraction(h), gaus.real_area_fraction(h), rtol=0.03)
    assert disc.load(2 * sig) == pytest.approx(gaus.load(2 * sig), rel=0.08)
    # contact factor and mean gap of the discrete density (Lee & Rhim eqs. 7, 9)
    assert dens.contact_factor(0.0) == pytest.approx(0.5, abs=0.01)
    hb = dens.mean_gap(np.array([0.0, 3 * sig]))
    assert hb[0] == pytest.approx(sig / math.sqrt(2 * math.pi), rel=0.03)
    assert hb[1] == pytest.approx(3 * sig * stats.norm.cdf(3) + sig * stats.norm.pdf(3), rel=1e-3)


def test_gaussian_contact_formulas():
    N, E, Hd, sig = 2e5, 1.154e11, 4e9, 3e-6
    Rp = sig / 0.01 ** 2
    c = AsperityContact(N, Rp, E, Hd, sigma=sig)
    h0 = np.array([0.0, 1.0, 2.0]) * sig
    F15 = np.array([quad_F(1.5, x) for x in (0.0, 1.0, 2.0)])
    F1 = np.array([quad_F(1.0, x) for x in (0.0, 1.0, 2.0)])
    W = 4 / 3 * N * E * math.sqrt(Rp) * sig ** 1.5 * F15         # Lee & Rhim eq. (15)
    A = math.pi * N * Rp * sig * F1                                # eq. (16)
    np.testing.assert_allclose(c.load(h0), W, rtol=1e-8)
    np.testing.assert_allclose(c.real_area_fraction(h0), A, rtol=1e-8)
    np.testing.assert_allclose(c.mean_contact_pressure(h0), W / A, rtol=1e-8)
    np.testing.assert_allclose(c.contact_count(h0), N * stats.norm.sf([0.0, 1.0, 2.0]), rtol=1e-10)
    dW = (c.load(h0 + 1e-12) - c.load(h0 - 1e-12)) / 2e-12
    np.testing.assert_allclose(c.load_derivative(h0), dW, rtol=1e-5)
    assert c.plasticity_index == pytest.approx(E / Hd * math.sqrt(sig / Rp))
    assert np.isnan(c.mean_contact_pressure(60 * sig))


def test_load_and_area_monotone_in_h0():
    c = steel_asperity_contact(2.07e-6)
    h = np.linspace(-1, 4, 60) * 2.07e-6
    assert np.all(np.diff(c.load(h)) < 0) and np.all(np.diff(c.real_area_fraction(h)) < 0)


def test_steel_defaults_documented_values():
    c = steel_asperity_contact(5e-6)
    assert c.asperity_radius == pytest.approx(5e-6 / STEEL_CONTACT["sqrt_rq_rp"] ** 2)
    assert c.asperity_density * 5e-6 * c.asperity_radius == pytest.approx(STEEL_CONTACT["n_rq_rp"])
    assert c.plasticity_index == pytest.approx(1.154e11 / 4e9 * 0.01)
    assert c.plasticity_index < 1


def test_plasticity_index_error():
    with pytest.raises(ValueError) as e:
        AsperityContact(1e9, 1e-5, 1.154e11, 4e9, sigma=1e-6)   # psi = 28.85 * 0.316 = 9.1
    msg = str(e.value)
    assert "plasticity index psi" in msg and "9.12" in msg and "psi < 1" in msg
    c = AsperityContact(1e9, 1e-5, 1.154e11, 4e9, sigma=1e-6, elastic_only=False)
    assert c.plasticity_index == pytest.approx(1.154e11 / 4e9 * math.sqrt(0.1))
    with pytest.raises(ValueError, match="psi"):
        steel_asperity_contact(1e-6, sqrt_rq_rp=0.05)               # psi = 1.44


@pytest.mark.parametrize("args,words", [
    (dict(asperity_density=-1.0), ["asperity_density N", "-1", "1/m^2", "[1000, 1e+16]"]),
    (dict(asperity_radius=0.0), ["asperity_radius Rp", "m"]),
    (dict(e_prime=float("nan")), ["e_prime E'", "Pa"]),
    (dict(hardness=-4e9), ["hardness H", "Pa"]),
    (dict(sigma=-1e-6), ["sigma (Rq)", "m"]),
    (dict(sigma=None), ["height density"]),
])
def test_contact_validation_messages(args, words):
    base = dict(asperity_density=1e5, asperity_radius=0.05, e_prime=1.154e11, hardness=4e9, sigma=5e-6)
    base.update(args)
    with pytest.raises(ValueError) as e:
        AsperityContact(**base)
    for w in words:
        assert w in str(e.value)


def test_density_validation():
    with pytest.raises(ValueError, match="sum to 1"):
        DiscreteDensity(np.array([0.0, 1.0, 2.0]), np.array([0.5, 0.6]))
    with pytest.raises(ValueError, match="increasing"):
        DiscreteDensity(np.array([0.0, 0.0, 2.0]), np.array([0.5, 0.5]))
    with pytest.raises(ValueError, match="unknown steel"):
        steel_asperity_contact(1e-6, modulus=1.0)
