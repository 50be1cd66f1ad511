"""Bad input to the journal bearing's switch and to its oil feeds on its grid is refused (or, where the model is valid
but coarse, warned) when the bearing is built, in one line naming the parameter, its value, the allowed range and the
grid, before any film is solved (each case was a non-convergence after the work or silently accepted)."""

import warnings

import numpy as np
import pytest

from transient.models.journal import CircumferentialGroove, Groove, JournalBearing, OilHole


def one_line(excinfo):
    assert "\n" not in str(excinfo.value).strip()
    return str(excinfo.value)


def bearing(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return JournalBearing(**dict(dict(diameter=0.08, length=0.04, clearance=8e-5, viscosity=0.03, grid=(24, 4)),
                                     **kw))


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
