"""The one Fischer-Burmeister value and gradient of the EHL films (``models/ehl/complementarity.py``): zero exactly
on the complementarity set, the gradient against finite differences, and each element taken at the kink a limit
of gradients beside it (so an element of the generalised Jacobian)."""

import numpy as np

from transient.models.ehl.complementarity import (FULL_FILM_KINK, SYMMETRIC_KINK, fb_derivatives, fb_gradient,
                                                  fb_residual, fb_value)


def test_fb_vanishes_on_the_complementarity_set_only():
    a = np.array([0.0, 0.0, 2.5, 0.0, 1.0, -0.5])
    b = np.array([0.0, 3.0, 0.0, 1e-3, 1.0, 0.5])
    phi, rad = fb_value(a, b)
    assert np.all(phi[:4] == 0.0) and np.all(phi[4:] != 0.0)
    assert np.allclose(rad, np.hypot(a, b), rtol=1e-15)


def test_gradient_away_from_the_kink_is_the_finite_difference():
    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(2, 50))
    _, rad = fb_value(a, b)
    da, db = fb_gradient(a, b, rad, SYMMETRIC_KINK)
    d = 1e-7
    fd_a = (fb_value(a + d, b)[0] - fb_value(a - d, b)[0]) / (2 * d)
    fd_b = (fb_value(a, b + d)[0] - fb_value(a, b - d)[0]) / (2 * d)
    assert np.allclose(da, fd_a, atol=1e-7) and np.allclose(db, fd_b, atol=1e-7)


def test_each_kink_element_is_the_limit_of_gradients_beside_the_kink():
    t = np.array([1e-6, 1e-9, 1e-12])
    zeros = np.zeros(1)
    for kink, (a, b) in ((SYMMETRIC_KINK, (t, t)), (FULL_FILM_KINK, (t, 0.0 * t))):  # along a = b; along b = 0, a > 0
        da, db = fb_gradient(a, b, fb_value(a, b)[1], kink)
        ka, kb = fb_gradient(zeros, zeros, zeros, kink)
        assert np.allclose(da, ka[0], atol=1e-12) and np.allclose(db, kb[0], atol=1e-12)


def test_cavitation_rows_take_the_full_films_element_at_the_kink():
    p, theta = np.array([0.0, 0.2]), np.array([1.0, 1.0])
    fb, rad = fb_residual(p, theta)
    d_p, d_theta = fb_derivatives(p, theta, rad)
    assert fb[0] == 0.0 and (d_p[0], d_theta[0]) == (0.0, -1.0)
    assert (d_p[1], d_theta[1]) == (0.0, -1.0)  # p > 0, theta = 1: the same element as the side p > 0
