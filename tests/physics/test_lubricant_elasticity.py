"""Seed 001 building blocks: lubricant laws (viscosity and density against pressure) and elastic influence coefficients against closed forms."""

import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from transient.physics.elasticity import SurfaceConvolution, line_influence, surface_influence
from transient.physics.lubricant import DOWSON_HIGGINSON_CLASSIC, Lubricant

P = np.array([0.0, 1e8, 5e8, 1e9, 2e9])


def test_barus_and_dowson_higginson_closed_forms():
    r = Lubricant(viscosity=0.05, pressure_viscosity=2e-8)
    eta, deta = r.eta(P)
    assert np.allclose(eta, np.exp(2e-8 * P), rtol=1e-14)
    assert np.allclose(deta, 2e-8 * np.exp(2e-8 * P), rtol=1e-14)
    rho, drho = r.rho(P)
    g = P / 1e9  # the paper's eq. (3): 1 + 0.58 p / (1 + 1.68 p), p in GPa
    assert np.allclose(rho, 1 + 0.58 * g / (1 + 1.68 * g), rtol=1e-14)
    assert np.allclose(drho * 1e9, 0.58 / (1 + 1.68 * g) ** 2, rtol=1e-13)
    classic = Lubricant(0.05, 2e-8, dh_constants=DOWSON_HIGGINSON_CLASSIC).rho(np.array([1e9]))[0]
    assert classic[0] == pytest.approx(1 + 0.6 / 2.7, rel=1e-14)


def test_roelands_closed_form_and_low_pressure_slope():
    eta0, alpha = 0.04, 2.2e-8
    r = Lubricant(viscosity=eta0, pressure_viscosity=alpha, viscosity_law="roelands")
    eta, deta = r.eta(P)
    a = math.log(eta0) + 9.67
    z = alpha * 1.96e8 / a
    assert np.allclose(eta, np.exp(a * ((1 + P / 1.96e8) ** z - 1)), rtol=1e-13)
    assert deta[0] == pytest.approx(alpha, rel=1e-12)  # the same slope as Barus at p = 0
    fd = (r.eta(P + 1.0)[0] - r.eta(P - 1.0)[0]) / 2.0
    assert np.allclose(deta, fd, rtol=1e-6)
    assert np.all(eta[1:] < np.exp(alpha * P[1:]))  # Roelands below Barus at high pressure


@pytest.mark.parametrize("bad", [dict(viscosity=0.0), dict(viscosity=-1.0), dict(pressure_viscosity=-1e-9),
                                 dict(viscosity_law="walther"), dict(density="ideal-gas")])
def test_lubricant_rejects_bad_input(bad):
    kw = dict(viscosity=0.05, pressure_viscosity=2e-8) | bad
    with pytest.raises(ValueError, match=next(iter(bad))):
        Lubricant(**kw)


@pytest.mark.parametrize("x0,y0", [(0.3, -0.2), (0.45, 0.2), (-1.0, 2.0), (1.7, 0.1)])
def test_surface_patch_integral_matches_quadrature(x0, y0):
    k = surface_influence([x0], [y0], [0.0, 1.0], [0.0, 0.5])[0, 0]
    ref = dblquad(lambda y, x: 1 / math.hypot(x - x0, y - y0), 0, 1, 0, 0.5, epsabs=1e-12)[0]
    assert k == pytest.approx(ref, rel=1e-7)


def test_uniform_square_centre_deflection_closed_form():
    # iint over a square of side 2a of 1/r seen from its centre = 8 a ln(1 + sqrt 2)
    a = 0.7
    k = surface_influence([0.0], [0.0], [-a, a], [-a, a])[0, 0]
    assert k == pytest.approx(8 * a * math.log(1 + math.sqrt(2)), rel=1e-14)


def test_line_patch_integral_matches_quadrature():
    for x0 in (0.3, 0.0, -2.0):
        ref = quad(lambda s: math.log(abs(x0 - s)), 0.0, 1.0, points=[x0] if 0 < x0 < 1 else None)[0]
        assert line_influence([x0], [0.0, 1.0])[0, 0] == pytest.approx(ref, rel=1e-12)


def test_dc_fft_equals_dense_influence_matrix():
    nx, ny, dx, dy = 23, 11, 0.1, 0.37
    x, y = np.arange(nx) * dx, np.arange(ny) * dy
    K = surface_influence(x, y, np.r_[x - dx / 2, x[-1] + dx / 2], np.r_[y - dy / 2, y[-1] + dy / 2])
    p = np.random.default_rng(1).random((ny, nx))
    conv = SurfaceConvolution(nx, ny, dx, dy, scale=2.5)
    assert np.allclose(conv.apply(p).ravel(), 2.5 * K @ p.ravel(), rtol=1e-12, atol=1e-12)
