"""The short-damper closed forms against a quadrature of the short-damper pressure they come from."""

import numpy as np
import pytest
from scipy.integrate import quad

from transient.models.damper.closed_forms import land_forces, open_land_forces

MU, R, C, W = 0.02, 0.06, 120e-6, 250.0


def _quadrature(eps, length, cavitated):
    """Integrate p = 6 mu e w sin(phi) (l^2/4 - z^2) / h^3 over z (l^3 / 6) and phi (only p > 0 when cavitated)."""
    e = eps * C
    line = lambda phi: MU * e * W * length ** 3 * np.sin(phi) / (C * (1.0 - eps * np.cos(phi))) ** 3  # noqa: E731
    top = np.pi if cavitated else 2.0 * np.pi
    fr = -R * quad(lambda p: line(p) * np.cos(p), 0.0, top, limit=200)[0]
    ft = -R * quad(lambda p: line(p) * np.sin(p), 0.0, top, limit=200)[0]
    return fr, ft


@pytest.mark.parametrize("eps", [0.1, 0.5, 0.9])
def test_the_closed_forms_are_the_integrated_short_damper_pressure(eps):
    L = 0.01
    for film, cavitated in (("pi", True), ("2pi", False)):
        fr, ft = open_land_forces(eps, W, MU, R, L, C, film)
        qr, qt = _quadrature(eps, L, cavitated)
        assert ft == pytest.approx(qt, rel=1e-9)
        assert fr == pytest.approx(qr, rel=1e-9, abs=1e-12 * abs(qt))


def test_a_closed_land_is_half_an_open_land_twice_as_long():
    """A land sealed at one end is the half of an open land about its symmetry plane."""
    fr, ft = land_forces([(0.004, True)], 0.6, W, MU, R, C, "pi")
    gr, gt = open_land_forces(0.6, W, MU, R, 0.008, C, "pi")
    assert (fr, ft) == pytest.approx((0.5 * gr, 0.5 * gt), rel=1e-12)
    # and a grooved damper with open ends has two lands of half the length: a quarter of the ungrooved force
    hr, ht = land_forces([(0.004, False), (0.004, False)], 0.6, W, MU, R, C, "pi")
    assert (hr, ht) == pytest.approx((0.25 * gr, 0.25 * gt), rel=1e-12)


def test_an_unknown_film_is_refused():
    with pytest.raises(ValueError, match="film"):
        open_land_forces(0.5, W, MU, R, 0.01, C, "half")
