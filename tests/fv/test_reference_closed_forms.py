"""The closed forms of transient.verification.reference against independent quadrature and series."""

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from transient.verification import reference as ref

EPS, MU, U, R, C, L = 0.6, 0.03, 5.0, 0.02, 1e-4, 0.01


def test_sommerfeld_force_is_the_integral_of_its_pressure():
    p = lambda t: ref.sommerfeld_pressure(t, EPS, MU, U, R, C)
    fy = -quad(lambda t: p(t) * np.sin(t), 0, 2 * np.pi, limit=200)[0] * R * L
    Fx, Fy = ref.sommerfeld_force(EPS, MU, U, R, C, L)
    assert Fy == pytest.approx(fy, rel=1e-10) and Fx == 0.0
    t = np.linspace(0, 2 * np.pi, 4096, endpoint=False)  # periodic trapezoid rule: spectrally accurate
    assert abs(-np.mean(p(t) * np.cos(t)) * 2 * np.pi * R * L) < 1e-12 * abs(fy)
    assert -np.mean(p(t) * np.sin(t)) * 2 * np.pi * R * L == pytest.approx(Fy, rel=1e-12)
    assert p(0.0) == 0.0
    # it satisfies the Reynolds equation: h^3 p' - 6 mu U R h = const
    t = np.linspace(0, 2 * np.pi, 9)
    dp = (p(t + 1e-6) - p(t - 1e-6)) / 2e-6
    h = C * (1 + EPS * np.cos(t))
    q = h**3 * dp - 6 * MU * U * R * h
    assert np.ptp(q) < 1e-6 * np.max(np.abs(q))


@pytest.mark.parametrize("film, hi", [("full", 2 * np.pi), ("half", np.pi)])
def test_short_bearing_force_is_the_integral_of_its_pressure(film, hi):
    p = lambda z, t: ref.short_bearing_pressure(t, z, EPS, MU, U, R, C, L)
    fy = -dblquad(lambda z, t: p(z, t) * np.sin(t) * R, 0, hi, -L / 2, L / 2)[0]
    fx = -dblquad(lambda z, t: p(z, t) * np.cos(t) * R, 0, hi, -L / 2, L / 2)[0]
    Fx, Fy = ref.short_bearing_force(EPS, MU, U, C, L, film)
    assert Fy == pytest.approx(fy, rel=1e-8)
    assert Fx == pytest.approx(fx, rel=1e-8, abs=1e-10 * abs(fy))
    assert ref.short_bearing_pressure(1.0, L / 2, EPS, MU, U, R, C, L) == 0.0


def test_squeeze_series_against_double_sine_series_and_strip_limit():
    a, b, h, dhdt, mu = 0.02, 0.05, 1e-4, -1e-3, 0.1
    G = -12 * mu * dhdt / h**3
    m = 2.0 * np.arange(1500) + 1
    M, N = np.meshgrid(m, m)
    # independent: p = sum_{m,n odd} 16 G sin sin / (pi^4 m n (m^2/a^2 + n^2/b^2)), integrated
    W2 = np.sum(64 * G * a * b / (np.pi**6 * M**2 * N**2 * (M**2 / a**2 + N**2 / b**2)))
    W = ref.squeeze_rect_load(a, b, h, dhdt, mu)
    assert W == pytest.approx(W2, rel=1e-6)
    # symmetric in a, b up to the truncation of the series (< 2e-11 relative with 200 terms for b/a = 2.5)
    assert ref.squeeze_rect_load(b, a, h, dhdt, mu) == pytest.approx(W, rel=1e-9)
    # infinite strip W = mu b a^3 V / h^3, approached as 1 - 0.630 a/b
    strip = lambda bb: mu * bb * a**3 * (-dhdt) / h**3
    for ratio in (10, 100, 1000):
        r = ref.squeeze_rect_load(a, ratio * a, h, dhdt, mu) / strip(ratio * a)
        assert r == pytest.approx(1 - 192 / np.pi**5 * 1.00452376 / ratio, rel=1e-6)
    # the pressure series integrates to the load and vanishes on the edges
    Wp = dblquad(lambda y, x: ref.squeeze_rect_pressure(x, y, a, b, h, dhdt, mu), 0, a, 0, b)[0]
    assert Wp == pytest.approx(W, rel=1e-6)
    assert np.allclose(ref.squeeze_rect_pressure(np.array([0.0, a, a / 3]), np.array([b / 2, b / 3, 0.0]),
                                                 a, b, h, dhdt, mu), 0.0, atol=1e-9 * G * a**2)


def test_reference_validation():
    with pytest.raises(ValueError, match=r"eps \(eccentricity ratio\) must be in \[0, 1\), got 1.2"):
        ref.sommerfeld_force(1.2, MU, U, R, C)
    with pytest.raises(ValueError, match="film must be 'full' or 'half'"):
        ref.short_bearing_force(0.5, MU, U, C, L, film="quarter")
    with pytest.raises(ValueError, match="h must be finite and > 0"):
        ref.squeeze_rect_load(1.0, 1.0, 0.0, -1.0, 1.0)
