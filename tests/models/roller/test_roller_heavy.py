"""The tilted tapered roller above the paper's load: the clustered grid resolves the ends of the
footprint, and the steady film converges with positive film, balanced load and a Hertzian pressure."""


import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.contact import END_WIDTH
from transient.params import park
from transient.physics.line_formulas import moes_central


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
def test_twice_the_paper_load_on_the_paper_grid():
    c = contact(2.0)
    s = c.steady()
    _checks(c, s)
    assert s.solver_info["continuation"]["loads"][-1] == pytest.approx(c.load)
    # the pressure stays near the dry (Hertzian) one; the central film thins as Moes' line-contact
    # formula at the mid-plane groups says (its own accuracy is a few per cent)
    base = contact(1.0).steady()
    ratio = s.h_central / base.h_central
    L = c.G * (2.0 * c.U) ** 0.25
    moes = moes_central(c.mid_plane_M, L) / moes_central(contact(1.0).mid_plane_M, L)
    print(f"p_max / dry p_max = {s.p_max / c.dry().p_max:.3f}; h_c(2x) / h_c(1x) = {ratio:.4f}, Moes {moes:.4f}; "
          f"h_min = {s.h_min:.3e} m at y = {s.y_of_h_min:.4e} m; wall {s.wall_time:.0f} s")
    assert s.p_max == pytest.approx(c.dry().p_max, rel=0.25)
    assert ratio == pytest.approx(moes, rel=0.08)
