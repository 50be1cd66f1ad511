"""The point contact's default grid: chosen from M, its film settled, within its stated bound of a finer grid."""

import pytest

from transient.models.point import PointContact
from transient.models.point.point_grid import (
    ERROR_BOUND,
    MIN_NODES,
    RESOLUTION,
    default_grid,
)

#: steel on steel (E' = 220 GPa), Rx = 10 mm, mineral oil (Barus, Dowson-Higginson)
OIL = dict(viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


@pytest.mark.parametrize("M", [5.0, 61.0, 173.0, 518.0, 1726.0])
def test_default_spacing_is_the_coarsest_power_of_two_within_the_resolution(M):
    domain = (-4.5, 1.5, 2.5)
    nx, ny = default_grid(M, domain)
    assert nx == ny and (nx - 1) & (nx - 2) == 0 and nx >= MIN_NODES
    dx = (domain[1] - domain[0]) / (nx - 1)
    assert M ** 0.5 * dx <= RESOLUTION or nx == MIN_NODES
    assert nx == MIN_NODES or M ** 0.5 * 2.0 * dx > RESOLUTION  # half the nodes would be too coarse


def test_default_grid_follows_the_domain_and_the_load():
    light = PointContact(0.01, load=5.0, speed=3.0, **OIL)   # M = 6.7
    heavy = PointContact(0.01, load=10.0, speed=0.1, **OIL)  # M = 173
    assert light.grid == (65, 65) and heavy.grid == (257, 257)
    assert PointContact(0.01, load=10.0, speed=0.1, grid=(129, 129), **OIL).grid == (129, 129)


def settled_within_bound(load, speed):
    """The default contact's films are settled, and within their stated bounds of the Richardson limit of the
    default grid and the grid of twice its nodes per axis (the second-order flux: order 2)."""
    pc = PointContact(0.01, load=load, speed=speed, **OIL)
    s = pc.steady()
    assert s.success and s.grid_settled, s.grid_change["note"]
    nx, ny = pc.grid
    fine = PointContact(0.01, load=load, speed=speed, grid=(2 * nx - 1, 2 * ny - 1), **OIL).steady(check_grid=False)
    for name in ("h_central", "h_min"):
        f1, f2 = getattr(s, name), getattr(fine, name)
        limit = f2 + (f2 - f1) / 3.0
        bound = s.grid_change[f"error_{name}"]
        assert bound <= ERROR_BOUND
        assert abs(f1 - limit) / abs(limit) <= bound, (name, f1, f2, limit, bound)


def test_light_load_default_is_settled_within_its_bound():
    settled_within_bound(5.0, 3.0)  # M = 6.7, 65 x 65


@pytest.mark.slow
@pytest.mark.parametrize("load, speed", [(5.0, 1.0), (20.0, 1.0)])  # M = 15 (65 x 65), 61 (129 x 129)
def test_default_is_settled_within_its_bound(load, speed):
    settled_within_bound(load, speed)
