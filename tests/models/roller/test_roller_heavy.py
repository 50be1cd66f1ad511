"""The tilted tapered roller above the paper's load: the clustered grid resolves the ends of the
footprint, and the steady film converges with positive film, balanced load and a Hertzian pressure."""

import math

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.contact import END_WIDTH
from transient.params import park


def contact(factor, grid="paper", tilt=0.002):
    kw = dict(park.DIMENSIONLESS, W=park.DIMENSIONLESS["W"] * factor)
    return RollerContact.from_dimensionless(**kw, roller=TaperedRoller(**dict(park.ROLLER, tilt_deg=tilt)),
                                            speed=park.SPEED, grid=grid)


@pytest.mark.parametrize("factor", [1.0, 10.0])
def test_clustered_grid_puts_nodes_on_both_ends_of_the_footprint(factor):
    c = contact(factor)
    s = c.scales
    for end in (s["y_lo"], s["y_hi"]):
        near = np.count_nonzero(np.abs(c.grid.y - end) < END_WIDTH)
        assert near >= 4
        spacing = np.diff(c.grid.y)[int(np.argmin(np.abs(c.grid.y[:-1] - end)))]
        assert spacing < 0.15  # units of c: the side lobes of the film are ~0.3 c wide


def _checks(c, s):
    assert s.success and abs(s.load_error) < 1e-6
    w = np.trapezoid(np.trapezoid(s.pressure, s.x, axis=1), s.y)
    assert w == pytest.approx(c.load, rel=0.02)
    assert s.film[1:-1, 1:-1].min() > 0 and s.pressure.min() > -1e-9 * s.p_max
    # the minimum film at the small end (positive tilt loads it), below the central film
    assert s.y_of_h_min < -c.roller.profile_start and s.h_min < 0.5 * s.h_central


@pytest.mark.slow
def test_ten_times_the_paper_load_on_the_paper_grid():
    c = contact(10.0)
    s = c.steady()
    _checks(c, s)
    assert s.solver_info["continuation"]["loads"][-1] == pytest.approx(c.load)
    # heavily loaded: the pressure is nearly the dry (Hertzian) one, the film a few per cent of c^2/R
    assert s.p_max == pytest.approx(c.dry().p_max, rel=0.15)
    base = contact(1.0).steady()
    assert s.h_central < base.h_central  # the central film thins as the load grows
    assert math.log(s.h_central / base.h_central) / math.log(10.0) == pytest.approx(-0.1, abs=0.06)
