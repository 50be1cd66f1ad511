"""The Couette flux options of the point film: the face fluxes' order on smooth and extremal contents, and mass
conservation of the second-order fluxes at the discrete level (flux form)."""

import numpy as np
import pytest

from transient.models.point import PointContact
from transient.models.point.kernels import face_flux

#: a steel ball on a steel flat, mineral oil: M = 61, L = 10.8
BASE = dict(load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


@pytest.mark.parametrize("scheme", [1, 2])
def test_second_order_fluxes_are_exact_on_a_linear_content(scheme):
    dx = 0.1
    q = 2.0 + 3.0 * dx * np.arange(3)  # q = 2 + 3 x at x = 0, dx, 2 dx
    f, dm, dc, dp = face_flux(scheme, q[0], q[1], q[2], dx)
    assert f == pytest.approx(2.0 + 3.0 * 1.5 * dx, rel=1e-14)  # the value at the face x = 1.5 dx
    assert dm + dc + dp == pytest.approx(1.0, rel=1e-14)  # a constant content passes unchanged
    first = face_flux(0, q[0], q[1], q[2], dx)
    assert first[0] == q[1]


def test_limited_flux_is_first_order_at_an_extremum():
    dx = 0.1
    assert face_flux(2, 1.0, 0.5, 1.0, dx)[0] == 0.5  # a minimum: the upwind node's content
    assert face_flux(1, 1.0, 0.5, 1.0, dx)[0] == pytest.approx(0.25)  # unlimited: undershoots the minimum


@pytest.mark.parametrize("upwind, grid", [("second", 33), ("limited", 49)])
def test_second_order_fluxes_conserve_mass(upwind, grid):
    s = PointContact(0.01, grid=(grid, grid), upwind=upwind, **BASE).steady(check_grid=False)
    assert s.success
    q = s.inlet_flux
    assert abs(q - s.outlet_flux - s.side_flux) < 1e-7 * q
    assert s.theta.max() <= 1.0 + 1e-8 and s.pressure.min() >= -1e-8 * s.p_max


def test_upwind_names_the_allowed_choices():
    with pytest.raises(ValueError, match="upwind"):
        PointContact(0.01, grid=(33, 33), upwind="central", **BASE)
