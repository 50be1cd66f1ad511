"""The tilted tapered roller above the paper's load: the clustered grid resolves the ends of the
footprint, and the steady film converges with positive film, balanced load and a Hertzian pressure."""


from types import SimpleNamespace

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.contact import END_WIDTH
from transient.models.roller.results import EHLConvergenceError
from transient.params import park
from transient.physics.line_formulas import moes_central


def contact(factor, grid="paper", tilt=0.002, scheme="auto"):
    kw = dict(park.DIMENSIONLESS, W=park.DIMENSIONLESS["W"] * factor)
    return RollerContact.from_dimensionless(**kw, roller=TaperedRoller(**dict(park.ROLLER, tilt_deg=tilt)),
                                            speed=park.SPEED, grid=grid, scheme=scheme)


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
    s = c.steady(method="reynolds")
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


def test_auto_scheme_and_grid_above_the_paper_load():
    light, heavy = contact(1.0), contact(10.0)
    assert (light.heavy, light.flux_scheme) == (False, "upwind2")
    assert (heavy.heavy, heavy.flux_scheme) == (True, "limited")
    assert heavy.with_load(light.load).heavy  # the path keeps its target's grid law and flux
    assert heavy.film_problem(heavy.make_grid("clustered", 16, 12)).scheme_code == 2

    def spacing(c, lo, hi):
        x = c.grid.x
        mid = 0.5 * (x[1:] + x[:-1])
        return np.diff(x)[(mid > lo) & (mid < hi)].max()

    # the 94 x nodes move from the inlet onto the contact and its outlet (units of c)
    assert spacing(heavy, -1.2, 1.4) < 0.065 < spacing(light, -1.2, 1.4)
    assert spacing(heavy, 0.8, 1.4) < 0.065


def test_local_resolution_reads_each_row_as_a_hertzian_line_contact():
    c = contact(10.0)
    E, U = c.modulus, c.U
    x = np.linspace(-4e-4, 2e-4, 3001)
    y = np.array([-2e-3, 0.0, 3e-3])
    R = c.roller.mean_radius * c.roller.radius_ratio(y / c.roller.mean_radius)
    b0 = np.array([1e-4, 1.5e-4, 0.0])
    ph = E * b0 / (4.0 * R)  # Hertz: p_h = E' b/(4 R)
    p = ph[:, None] * np.sqrt(np.clip(1.0 - (x[None, :] / np.where(b0 > 0, b0, 1.0)[:, None]) ** 2, 0.0, None))
    r = c.local_resolution(SimpleNamespace(x=x, y=y, pressure=p))
    w = np.pi * b0 * ph / 2.0
    assert r["M"][:2] == pytest.approx(w[:2] / (E * R[:2]) / np.sqrt(2.0 * U), rel=1e-4)
    dx = x[1] - x[0]
    assert r["spacing"][:2] == pytest.approx(dx / b0[:2], rel=1e-3)
    assert np.isnan(r["ratio"][2]) and r["M"][2] == 0.0  # an unloaded row
    assert r["worst_y"] == y[1] and r["worst_ratio"] == pytest.approx(r["spacing"][1] * r["M"][1] / 4.0, rel=1e-12)


@pytest.mark.slow
def test_five_times_the_paper_load_stops_at_the_loaded_ends_outlet_when_x_is_too_coarse_there():
    c = contact(5.0, ("clustered", 40, 25))
    with pytest.raises(EHLConvergenceError) as err:
        c.steady(method="reynolds")
    s = err.value.result
    # the path stops with one node closed at the small end's outlet, in a row beyond 4 b/M of its own load
    assert s.h_min < 1e-2 * s.h_central and s.y_of_h_min < -c.roller.profile_start and s.x_of_h_min > 0
    assert "4 b/M" in str(err.value) and s.solver_info["local_resolution"]["worst_ratio"] > 1.0
    assert s.solver_info["local_resolution"]["worst_y"] < -c.roller.profile_start


@pytest.mark.slow
def test_five_times_the_paper_load_converges_on_47_by_45():
    c = contact(5.0, ("clustered", 47, 45))
    assert c.flux_scheme == "limited"
    s = c.steady(method="reynolds")
    _checks(c, s)
    assert s.solver_info["continuation"]["loads"][-1] == pytest.approx(c.load)
    assert s.p_max == pytest.approx(c.dry().p_max, rel=0.1)
