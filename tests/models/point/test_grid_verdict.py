"""The grid verdict's error estimate on film sequences of known order: Richardson's bound where the films converge,
no bound where they do not."""

import math

import pytest

from transient.models.point.grid_verdict import SAFETY_THREE, SAFETY_TWO, describe, error_estimate


def films(limit, c, p, dx=1.0):
    """The films on spacings dx, 2 dx, 4 dx of a scheme with error c dx^p."""
    return [limit + c * (k * dx) ** p for k in (1, 2, 4)]


@pytest.mark.parametrize("p", [1.0, 1.5, 2.0])
def test_richardson_bound_is_the_error_at_the_observed_order_times_roaches_factor(p):
    f1, f2, f4 = films(100.0, 3.0, p)
    err, basis = error_estimate(f1, f2, f4, formal_order=2.0)
    assert err == pytest.approx(SAFETY_THREE * 3.0 / f1, rel=1e-12) and f"{p:.2f}" in basis


def test_an_order_above_the_schemes_is_taken_as_the_schemes():
    """Observed order 3 on a second-order scheme: bounded at order 2, i.e. by more than the true error."""
    f1, f2, f4 = films(100.0, 1.0, 3.0)
    err, basis = error_estimate(f1, f2, f4, formal_order=2.0)
    assert err == pytest.approx(SAFETY_THREE * abs(f1 - f2) / 3.0 / f1) and err > 1.0 / f1
    assert "taken as the scheme's 2" in basis


@pytest.mark.parametrize("f1, f2, f4", [(220.7, 226.6, 233.9),   # first order, observed order 0.31
                                        (271.0, 278.0, 272.7),   # non-monotone
                                        (100.0, 101.0, 101.5)])  # diverging differences
def test_no_bound_where_the_films_do_not_converge(f1, f2, f4):
    err, basis = error_estimate(f1, f2, f4, formal_order=1.0)
    assert math.isinf(err) and describe(err, basis).startswith("error not bounded")


def test_two_grids_use_the_schemes_order():
    err, basis = error_estimate(101.0, 104.0, None, formal_order=2.0)
    assert err == pytest.approx(SAFETY_TWO * 1.0 / 101.0) and "two grids" in basis
