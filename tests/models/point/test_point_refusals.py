"""Bad input to the EHL point contact is refused when the contact is built, in one line naming the parameter, its value
and the allowed range, before any film is solved or Newton matrix allocated (each case was an unnamed error, a
problem reported under another parameter's name, or a dense Newton matrix of minutes to hours and up to 16 GB)."""

import time

import pytest

from transient.models.point import PointContact


def one_line(excinfo):
    assert "\n" not in str(excinfo.value).strip()
    return str(excinfo.value)


# --------------------------------------------------------------------------------------------------
# the EHL point contact
# --------------------------------------------------------------------------------------------------

POINT = dict(radius_x=0.01, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


@pytest.mark.parametrize("kw, match", [
    (dict(domain=5), r"domain = 5; allowed: 3 numbers \[b\]"),
    (dict(domain=(-4.5, 1.5)), r"domain = \(-4\.5, 1\.5\) \(2 items\); allowed: 3 numbers"),
    (dict(dh_constants=5), r"dh_constants = 5; allowed: 2 numbers \[1/Pa\]"),
])
def test_point_contact_arguments_of_the_wrong_shape_are_named(kw, match):
    with pytest.raises(ValueError, match=match) as e:
        PointContact(**dict(POINT, grid=(25, 25)) | kw)
    one_line(e)


@pytest.mark.parametrize("grid, nearest, gb", [((128, 129), (129, 129), "0.52"), ((300, 301), (305, 305), "16")])
def test_point_contact_grid_that_does_not_coarsen_is_refused_before_the_dense_matrix(grid, nearest, gb):
    """128 x 129 (nx - 1 = 127 odd) cannot take the two-level Krylov solver, so every Newton step was a dense LU of
    8065^2 numbers (past 240 s); 300 x 301 asked for 16 GB. Refused at construction, naming the nearest grid that
    coarsens, which is accepted."""
    t0 = time.perf_counter()
    with pytest.raises(ValueError, match=rf"grid = \({grid[0]}, {grid[1]}\) nodes does not coarsen by a power of two.*"
                                         rf"dense LU of {gb} GB.*e\.g\. grid = \({nearest[0]}, {nearest[1]}\)") as e:
        PointContact(**POINT, grid=grid)
    one_line(e)
    assert time.perf_counter() - t0 < 5.0
    assert PointContact(**POINT, grid=nearest).grid == nearest


def test_point_contact_unit_slip_names_the_parameters_behind_the_grid():
    """radius_x = 5 (m, meant in mm?) shrinks the Hertz zone under the grid's spacing: the message names radius_x
    with the grid, not the grid alone."""
    with pytest.raises(ValueError, match=r"radius_x = 5 m \(plausible .*grid = \(25, 25\) puts 0\.79 x") as e:
        PointContact(**dict(POINT, radius_x=5), grid=(25, 25))
    one_line(e)
