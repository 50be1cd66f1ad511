"""Hertz elliptical contact and Hamrock–Dowson film formulas (seed 002)."""

import math

import pytest

from transient.physics import film_formulas as hd
from transient.physics.hertz import (displacement, ellipticity_exact, gap_rolling_axis, gap_rolling_axis_slope,
                                  hamrock_brewe, hertz_contact, meniscus_position, reduced_modulus)
from scipy.special import ellipe, ellipk

E_PRIME = 207e9 / (1 - 0.3 ** 2)  # E' = E/(1-nu^2) for two steel bodies [Pa]


def test_reduced_modulus_same_material():
    # hand: 2 / (2 (1 - 0.09) / 207e9) = 207e9 / 0.91 = 2.2747253e11 Pa
    assert reduced_modulus(207e9, 0.3) == pytest.approx(2.2747253e11, rel=1e-7)


def test_circular_limit_matches_classic_hertz():
    # sphere of radius Rs on a flat: Rx = Ry = Rs; classic Hertz (Johnson 4.22) with E* = E'/2:
    # a = (3 W Rs / (4 E*))^(1/3), p0 = 3 W / (2 pi a^2), delta = a^2 / Rs
    Rs, W = 0.01, 100.0
    c = hertz_contact(W, Rs, Rs, E_PRIME)
    a = (3 * W * Rs / (4 * E_PRIME / 2)) ** (1 / 3)
    assert c.k == pytest.approx(1.0, abs=1e-9)
    assert c.a == pytest.approx(a, rel=1e-9) and c.b == pytest.approx(a, rel=1e-9)
    assert c.p_max == pytest.approx(3 * W / (2 * math.pi * a * a), rel=1e-9)
    assert c.delta == pytest.approx(a * a / Rs, rel=1e-9)


@pytest.mark.parametrize("alpha", [1.5, 4.0, 26.0, 80.0])
def test_elliptic_contact_satisfies_johnson_relations(alpha):
    # Johnson (1985) eq. 3.41 with a along the larger radius Ry, e^2 = 1 - b^2/a^2, E* = E'/2:
    #   1/(2 Ry) = (p0/E*) b/(e^2 a^2) (K - E),  1/(2 Rx) = (p0/E*) b/(e^2 a^2) ((a/b)^2 E - K),
    #   delta = (p0/E*) b K
    rx = 1.5e-3
    ry = alpha * rx
    c = hertz_contact(7.0, rx, ry, E_PRIME)
    e2 = 1 - (c.b / c.a) ** 2
    K, E = ellipk(e2), ellipe(e2)
    es = E_PRIME / 2
    f = c.p_max / es * c.b / (e2 * c.a ** 2)
    assert f * (K - E) == pytest.approx(1 / (2 * ry), rel=1e-9)
    assert f * ((c.a / c.b) ** 2 * E - K) == pytest.approx(1 / (2 * rx), rel=1e-9)
    assert c.p_max / es * c.b * K == pytest.approx(c.delta, rel=1e-9)
    # load balance: the integral of the Hertz pressure is 2/3 p0 pi a b
    assert 2 / 3 * c.p_max * math.pi * c.a * c.b == pytest.approx(7.0, rel=1e-12)


def test_hamrock_brewe_approximations_close_to_exact():
    # Hamrock & Brewe (1983) fits; measured accuracy over 5 <= alpha <= 26 (the paper's alpha = 26)
    for alpha in (5.0, 10.0, 26.0):
        k = ellipticity_exact(alpha)
        kb, Eb, Kb = hamrock_brewe(alpha)
        m = 1 - 1 / k ** 2
        assert abs(kb / k - 1) < 0.01
        assert abs(Eb / ellipe(m) - 1) < 0.002
        assert abs(Kb / ellipk(m) - 1) < 0.002


def test_displacement_outside_circular_contact_matches_closed_form():
    # Johnson eq. 3.42b (r > a), combined bodies: u = (p0 / (2 a E*)) [(2a^2 - r^2) asin(a/r) + r a sqrt(1 - a^2/r^2)]
    Rs, W = 0.01, 50.0
    c = hertz_contact(W, Rs, Rs, E_PRIME)
    a, p0, es = c.a, c.p_max, E_PRIME / 2
    for r in (0.0, 0.5 * a, 1.0 * a, 1.3 * a, 3.0 * a, 10.0 * a):
        if r <= a:
            ref = math.pi * p0 / (4 * a * es) * (2 * a * a - r * r)
        else:
            ref = p0 / (2 * a * es) * ((2 * a * a - r * r) * math.asin(a / r) + r * a * math.sqrt(1 - a * a / r / r))
        assert displacement(c, r, 0.0) == pytest.approx(ref, rel=1e-8)
        assert displacement(c, 0.0, r) == pytest.approx(ref, rel=1e-8)


def test_gap_and_meniscus_newton():
    c = hertz_contact(5.0, 1.5e-3, 0.039, E_PRIME)
    # the gap closes at the edge of the contact and its slope is the derivative of the gap
    assert abs(gap_rolling_axis(c, c.b * (1 + 1e-9))) < 1e-6 * c.delta
    x = 3 * c.b
    d = 1e-6 * x
    fd = (gap_rolling_axis(c, x + d) - gap_rolling_axis(c, x - d)) / (2 * d)
    assert gap_rolling_axis_slope(c, x) == pytest.approx(fd, rel=1e-6)
    # far from the contact the gap tends to the rigid parabola minus the approach (u -> 0)
    xf = 200 * c.b
    assert gap_rolling_axis(c, xf) == pytest.approx(xf ** 2 / (2 * c.rx) - c.delta, rel=2e-3)
    for h in (1e-9, 1e-8, 1e-7, 1e-6, 1e-4):
        m = meniscus_position(c, h)
        assert gap_rolling_axis(c, m * c.b) == pytest.approx(h, rel=1e-9)


# worked values for the paper's reference contact, hand-computed:
#   E' = 2.2747253e11 Pa, u = 80 * 2 pi/60 * 0.031/4 = 0.0649262 m/s, w = 30 N / 6 = 5 N, Rx = 1.5 mm,
#   eta = 0.02 Pa s, alpha = 2e-8 1/Pa:
#   U = 0.02 * 0.0649262 / (2.2747253e11 * 1.5e-3) = 3.805661e-12;  G = 4549.451;  W = 9.769189e-6
#   with k = 8:   H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^-5.84) = 1.127890e-5
#                 H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^-5.44)   = 8.929982e-6
#   with b = 20 um: m_c = 1 + 3.06 ((1.5e-3/2e-5)^2 * 1.127890e-5)^0.58 = 1.618169
#   starved, m = 1.3: H_s = 1.127890e-5 * (0.3 / 0.618169)^0.29 = 9.145573e-6

def test_hamrock_dowson_worked_values():
    U, G, W = hd.dimensionless_groups(0.02, 0.0649262, 2e-8, 5.0, 2.2747253e11, 1.5e-3)
    assert U == pytest.approx(3.805661e-12, rel=1e-5)
    assert G == pytest.approx(4549.451, rel=1e-6)
    assert W == pytest.approx(9.769189e-6, rel=1e-6)
    Hc = hd.central_film_flooded(3.805661e-12, 4549.451, 9.769189e-6, 8.0)
    assert Hc == pytest.approx(1.127890e-5, rel=1e-5)
    assert hd.minimum_film_flooded(3.805661e-12, 4549.451, 9.769189e-6, 8.0) == pytest.approx(8.929982e-6, rel=1e-5)
    mc = hd.critical_meniscus_central(1.127890e-5, 1.5e-3, 2e-5)
    assert mc == pytest.approx(1.618169, rel=1e-6)
    assert hd.starved_central_film(1.127890e-5, 1.3, 1.618169) == pytest.approx(9.145573e-6, rel=1e-6)
    assert hd.starved_central_film(1.127890e-5, 2.0, 1.618169) == 1.127890e-5
    assert hd.starved_central_film(1.127890e-5, 1.0, 1.618169) == 0.0
