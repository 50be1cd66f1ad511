"""The steady Elrod film by grid sequencing (JournalBearing.film_solve, Film.solve(chord=True)) against the solve
from rest on the same grid: the same discrete film, so the same load, pressure and mass balance to the solver's
tolerance; and the interpolation that carries a coarse film to the fine grid (fv.grid.interpolate_cells).
Timings: transient/bench/steady_film.py."""

import warnings

import numpy as np
import pytest

import transient.models.journal.bearing as bearing_module
from transient.fv.grid import Axis, Grid2D, interpolate_cells
from transient.models.journal import Groove, JournalBearing, OilHole

RPM = 3000.0


def pfeil(grid, groove=Groove(270.0, 15.0, length=0.06), **kw):
    """Pfeil's demonstration bearing (docs/validation.md)."""
    return JournalBearing(0.1, 0.08, 150e-6, 0.01, groove=groove, grid=grid, supply_pressure=70e3,
                          ambient_pressure=0.0, cavitation_pressure=0.0, **kw)


def from_rest(b, X, Y):
    f = b.film(RPM)
    u, its = f.solve(X, Y)
    return f.state(u, X, Y, its)


def mass_balance(s):
    return (np.sum(s.supply_flow) - np.sum(s.side_leakage)) / np.sum(s.side_leakage)


# --------------------------------------------------------------------------------------------------
# the prolongation
# --------------------------------------------------------------------------------------------------

def test_interpolation_reproduces_linear_fields_holds_the_ends_and_wraps_the_periodic_axis():
    x = Axis.uniform(6, 2 * np.pi, centred=True, periodic=True)
    z = Axis.uniform(4, 1.0, lower="symmetry", upper="dirichlet")
    coarse = Grid2D(x, z)
    fine = Grid2D(Axis.uniform(12, 2 * np.pi, centred=True, periodic=True),
                  Axis.uniform(8, 1.0, lower="symmetry", upper="dirichlet"))
    v = 3.0 + 2.0 * coarse.zc  # linear in z
    got = fine.to_2d(interpolate_cells(coarse, v, fine))
    zf = fine.z.centres
    inside = (zf >= z.centres[0]) & (zf <= z.centres[-1])
    assert np.allclose(got[inside], (3.0 + 2.0 * zf[inside])[:, None], rtol=0, atol=1e-14)
    assert np.all(got[zf < z.centres[0]] == 3.0 + 2.0 * z.centres[0])  # held beyond the end centres
    assert np.all(got[zf > z.centres[-1]] == 3.0 + 2.0 * z.centres[-1])
    w = np.arange(6.0)  # along x: the last fine cell (-pi/6) lies half-way between the last coarse one (-pi/3) and 0
    got = interpolate_cells(Grid2D(x, Axis.uniform(1, 1.0)), w, Grid2D(fine.x, Axis.uniform(1, 1.0)))
    assert got[-1] == pytest.approx(2.5, abs=1e-14) and got[1] == pytest.approx(0.5, abs=1e-14)
    assert got[0] == pytest.approx(0.0, abs=1e-14) and got[2] == pytest.approx(1.0, abs=1e-14)
    assert np.array_equal(interpolate_cells(coarse, v, coarse), v)  # the same grid: the values


def test_coarser_halves_the_circumferential_cells_only():
    b = pfeil((101, 12))
    c = b.coarser()
    assert c.grid_shape == (51, 12) and c.grid.n == 51 * 12 and b.grid_shape == (101, 12) and b.grid.n == 101 * 12
    assert np.array_equal(c.grid.z.centres, b.grid.z.centres)
    assert c.feed_cells.size == c.grid.n and b.feed_cells.size == b.grid.n


# --------------------------------------------------------------------------------------------------
# the same answer as the solve from rest
# --------------------------------------------------------------------------------------------------

def test_sequenced_film_is_the_film_from_rest_above_the_threshold():
    """At the module's own thresholds: 200 x 52 = 10,400 cells > SEQUENCE_CELLS, so one coarse level (100 x 52: the
    fewest circumferential cells allowed) solved from rest, interpolated, and the fine level's chord Newton from there;
    below it, the solve from rest."""
    b = pfeil((200, 52))
    assert b.grid.n > bearing_module.SEQUENCE_CELLS >= b.coarser().grid.n
    assert b.coarser().grid_shape[0] == bearing_module.SEQUENCE_MIN_THETA
    small = pfeil((120, 40))  # below SEQUENCE_CELLS: from rest
    assert len(small.film_solve(small.film(RPM), 0.5, 0.0)[2]) == 1
    ref = from_rest(b, 0.5, 0.0)
    f = b.film(RPM)
    u, its, levels = b.film_solve(f, 0.5, 0.0)
    assert [lv[0] for lv in levels] == [(100, 52), (200, 52)]
    s = f.state(u, 0.5, 0.0, its)
    assert s.load == pytest.approx(ref.load, rel=1e-9)
    assert s.attitude_angle_deg == pytest.approx(ref.attitude_angle_deg, abs=1e-7)
    assert np.max(np.abs(s.pressure - ref.pressure)) <= 1e-8 * np.max(ref.pressure)
    assert np.max(np.abs(s.film_content - ref.film_content)) <= 1e-9
    assert abs(mass_balance(s)) <= 1e-12 and abs(mass_balance(ref)) <= 1e-12
    assert levels[-1][2] < levels[-1][1]  # the chord reused factorisations


@pytest.mark.parametrize("case", ["groove", "hole smaller than a coarse cell", "two grooves, whole length"])
def test_sequenced_film_over_several_levels_matches_the_film_from_rest(monkeypatch, case):
    """A lower threshold, so 192 x n is solved on 48, 96 and 192 cells round; feeds that the coarse grids represent
    differently (a hole that covers no coarse cell centre, grooves off the mid-plane) change only the start."""
    monkeypatch.setattr(bearing_module, "SEQUENCE_CELLS", 800)
    monkeypatch.setattr(bearing_module, "SEQUENCE_MIN_THETA", 48)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the coarse grids' feed warnings stay inside film_solve
        b = {"groove": lambda: pfeil((192, 16)),
             "hole smaller than a coarse cell": lambda: pfeil((192, 16), groove=OilHole(270.0, 0.0035)),
             "two grooves, whole length": lambda: pfeil((192, 16), groove=[Groove(270.0, 15.0, length=0.03),
                                                                           Groove(90.0, 10.0, length=0.02)],
                                                         symmetric=False)}[case]()
        f = b.film(RPM)
        u, its, levels = b.film_solve(f, 0.45, 0.15)
    assert [lv[0][0] for lv in levels] == [48, 96, 192]
    ref = from_rest(b, 0.45, 0.15)
    s = b.steady_state(np.hypot(0.45, 0.15), RPM, np.degrees(np.arctan2(0.15, 0.45)))
    assert s.load == pytest.approx(ref.load, rel=1e-9)
    assert np.max(np.abs(s.pressure - ref.pressure)) <= 1e-8 * np.max(ref.pressure)
    assert abs(mass_balance(s)) <= 1e-12


def test_equilibrium_and_coefficients_with_sequencing_equal_those_without(monkeypatch):
    b = pfeil((96, 12))
    W = 1500.0
    e0 = b.equilibrium(W, RPM)
    K0, C0 = b.coefficients(W, RPM)
    monkeypatch.setattr(bearing_module, "SEQUENCE_CELLS", 500)
    monkeypatch.setattr(bearing_module, "SEQUENCE_MIN_THETA", 24)
    e1 = b.equilibrium(W, RPM)
    K1, C1 = b.coefficients(W, RPM)
    assert np.allclose(e1.position, e0.position, rtol=0, atol=1e-9 * b.clearance)
    assert np.allclose(K1, K0, rtol=1e-7, atol=0) and np.allclose(C1, C0, rtol=1e-7, atol=0)


def test_a_bad_prolonged_start_still_reaches_the_film_from_rest():
    """``chord=True`` from a start far from the film (all at the ambient): plain chord Newton, or, should it
    fail, the pseudo-transient solve from the same start -- the same film either way."""
    b = pfeil((96, 12))
    ref = from_rest(b, 0.6, 0.0)
    f = b.film(RPM)
    u, its = f.solve(0.6, 0.0, u0=np.zeros(b.grid.n), chord=True)
    s = f.state(u, 0.6, 0.0, its)
    assert s.load == pytest.approx(ref.load, rel=1e-9)
