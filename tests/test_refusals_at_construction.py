"""Bad input to the rotor, the rotor on bearings, the oil feeds, the journal bearing's switch and the EHL point contact
is refused when the object is built, in one line naming the parameter, its value and the allowed range -- before any
film is solved or matrix allocated (each case was an unnamed error, a non-convergence after the work, or silently
accepted)."""

import time
import warnings

import numpy as np
import pytest

from transient.models.journal import CircumferentialGroove, Groove, JournalBearing, OilHole
from transient.models.point import PointContact
from transient.models.rotor import Rotor, RotorBearingSystem


def one_line(excinfo):
    assert "\n" not in str(excinfo.value).strip()
    return str(excinfo.value)


# --------------------------------------------------------------------------------------------------
# the rotor and the rotor on bearings
# --------------------------------------------------------------------------------------------------

def rigid():
    return Rotor.rigid(20.0, 0.5, 0.3)


@pytest.mark.parametrize("key, value, match", [
    ("nodes", 5, r"nodes = 5; allowed: a list of integer node labels"),
    ("dofs", 5, r"dofs = 5; allowed: \('x', 'y'\) or \('x', 'y', 'tx', 'ty'\)"),
    ("gravity_load", 5, r"gravity_load has shape \(\); allowed: a finite \(2, 4\) matrix"),
    ("basis", {}, r"basis = \{\} \(dict\); allowed: a finite \(n_full, 4\) matrix"),
])
def test_rotor_arguments_of_the_wrong_shape_are_named(key, value, match):
    r = rigid()
    with pytest.raises(ValueError, match=match) as e:
        Rotor(**dict(mass=r.mass, stiffness=r.stiffness, nodes=[0, 1]) | {key: value})
    one_line(e)


def bearing(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return JournalBearing(**dict(dict(diameter=0.08, length=0.04, clearance=8e-5, viscosity=0.03, grid=(24, 4)),
                                     **kw))


@pytest.mark.parametrize("kw, match", [
    (dict(unbalance=5), r"unbalance = 5; allowed: a list of \(node, m e \[kg m\], phase \[deg\]\)"),
    (dict(rotor=5), r"rotor = 5 \(int\); allowed: a transient Rotor"),
])
def test_system_arguments_of_the_wrong_kind_are_named(kw, match):
    b = bearing()
    with pytest.raises(ValueError, match=match) as e:
        RotorBearingSystem(**dict(dict(rotor=rigid(), bearings={0: b, 1: b}), **kw))
    one_line(e)


def test_implausible_unbalance_is_refused_with_its_range():
    """20 kg m on the 146 kg example rotor puts its mass centre 0.14 m off the axis of bearings with a 80 um
    clearance; allowed: up to 10 x mass x clearance (0.117 kg m), which the 1e-4 kg m of the whirl scenario is far
    below."""
    b = bearing()
    rotor = Rotor.example()
    with pytest.raises(ValueError, match=r"unbalance: sum of m e = 20 \[kg m\] is out of range; allowed: \[0, 0\.117\] "
                                         r"kg m \(10 x rotor mass 146 kg x smallest clearance 8e-05 m") as e:
        RotorBearingSystem(rotor, {n: b for n in rotor.bearing_nodes}, unbalance=[(6, 20.0, 0.0)])
    one_line(e)
    RotorBearingSystem(rotor, {n: b for n in rotor.bearing_nodes}, unbalance=[(6, 0.1, 0.0)])  # inside the range


# --------------------------------------------------------------------------------------------------
# the journal bearing: its switch and its oil feeds on its grid
# --------------------------------------------------------------------------------------------------

def test_switch_width_beyond_any_film_pressure_is_refused_at_construction():
    """1e300 Pa used to be accepted and to end in "film solve did not converge"; 1e9 Pa (the largest pressure a
    bearing takes) still solves (measured: the load 3 % below the default switch's at 3000 rpm)."""
    with pytest.raises(ValueError, match=r"switch_width = 1e\+300 \[Pa\] is out of range; allowed: \[1e-06, 1e\+09\] "
                                         r"Pa") as e:
        bearing(switch_width=1e300)
    one_line(e)
    with pytest.raises(ValueError, match=r"switch_width = 1e-300 \[Pa\] is out of range"):
        bearing(switch_width=1e-300)
    assert np.isfinite(bearing(switch_width=1e9).steady_state(0.6, 3000.0).load)


def test_groove_width_in_radians_warns_naming_the_grid():
    """30 deg typed as 0.52 (its radians): less than a quarter of a 2.38-deg cell of the default 151 cells round, it was
    silently modelled as one column. Warned, not refused: a groove of one column is also how a single cell is pinned
    at the supply pressure (the Raimondi-Boyd and short-bearing validations)."""
    with pytest.warns(UserWarning, match=r"groove\.width_deg = 0\.52 deg is less than 0\.25 cell of the grid of 151 x "
                                         r"21 cells \(2\.38 deg .*modelled as one column 2\.38 deg wide \(a width in "
                                         r"radians\? .*resolved by a finer grid, n_theta >= 174\)"):
        JournalBearing(0.08, 0.04, 8e-5, 0.03, groove=Groove(0.0, 0.52))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        JournalBearing(0.08, 0.04, 8e-5, 0.03, groove=Groove(0.0, 30.0))  # the intended groove


def test_partial_groove_shorter_than_a_quarter_cell_is_refused():
    with pytest.raises(ValueError, match=r"groove\.length = 0\.0001 \[m\] is less than 0\.25 cell of the grid of "
                                         r"24 x 4 cells"):
        bearing(groove=Groove(0.0, 20.0, length=1e-4))


def test_oil_hole_smaller_than_a_cell_warns_and_one_far_smaller_is_refused():
    """The 24 x 4 grid's cells are 10.5 mm round and 5 mm along: a 4 mm hole off the mid-plane (the whole length then,
    24 x 8 cells) at a cell centre covers that centre (it was silently one whole cell); a 1 mm hole is less than a
    quarter cell."""
    with pytest.warns(UserWarning, match=r"groove\.diameter = 0\.004 m is smaller than a cell of the grid of 24 x 8 "
                                         r"cells.*modelled as 1 whole cell"):
        JournalBearing(0.08, 0.04, 8e-5, 0.03, grid=(24, 4), groove=OilHole(0.0, 4e-3, axial_position=0.0025))
    with pytest.raises(ValueError, match=r"groove\.diameter = 0\.001 \[m\] is less than 0\.25 cell"):
        bearing(groove=OilHole(7.5, 1e-3))


def test_circumferential_groove_covering_every_row_is_refused_at_construction():
    """39 mm of a 40 mm bearing covers all 4 rows of the half grid: no land is left (it used to end in "film solve did
    not converge ... residual 0"). 20 mm leaves two rows."""
    with pytest.raises(ValueError, match=r"groove\.width = 0\.039 \[m\] at axial_position = 0\.0 m "
                                         r"covers cell rows 0 to 3 of the grid of 24 x 4 cells.*leaving no land row"
                       ) as e:
        bearing(groove=CircumferentialGroove(0.039))
    one_line(e)
    assert np.isfinite(bearing(groove=CircumferentialGroove(0.02)).steady_state(0.5, 3000.0).load)


def test_circumferential_groove_at_the_cavitation_pressure_is_refused_at_construction():
    """A ring groove at p_c with the ends at p_c drives no oil into the Elrod film (it used to end in "film solve did
    not converge ... residual 1e-17"); 1 bar above, the film is fed."""
    with pytest.raises(ValueError, match=r"groove\.pressure = 0\.0 \[Pa\] with ambient_pressure = 0\.0 Pa: a "
                                         r"circumferential groove at the cavitation pressure feeds no oil") as e:
        bearing(groove=CircumferentialGroove(5e-3, pressure=0.0))
    one_line(e)
    with pytest.raises(ValueError, match=r"supply_pressure = 0\.0 \[Pa\]"):
        bearing(groove=CircumferentialGroove(5e-3), supply_pressure=0.0)
    assert np.isfinite(bearing(groove=CircumferentialGroove(5e-3, pressure=1e5)).steady_state(0.5, 3000.0).load)


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
    with pytest.raises(ValueError, match=r"grid = \(25, 25\) puts 0\.79 x .* from radius_x = 5\.0 m, .*load = 20\.0 N.*"
                                         r"check their units") as e:
        PointContact(**dict(POINT, radius_x=5), grid=(25, 25))
    one_line(e)
