"""Oil feeds of the journal bearing (partial and multiple axial grooves, oil holes, a circumferential groove) and the
flows they set (transient/models/journal/feeds.py, flows.py).

Expected values are closed forms, the recipe of the code before the feeds existed (computed in the same run), or
equalities between two different set-ups of the same physics -- never the code's own output. Numbers measured on these grids: docs/validation.md.
"""

import warnings

import numpy as np
import pytest

from transient.fv.grid import Grid2D
from transient.models.journal import CircumferentialGroove, Groove, JournalBearing, JournalOrbit, OilHole
from transient.models.journal.film import Film
from transient.models.journal.reynolds_film import ReynoldsFilm
from transient.models.journal.scales import film_scales
from transient.physics.layered import BoundaryLayers, Gecim
from transient import Integration, Recording

D, L, C, MU, RPM = 0.1, 0.08, 150e-6, 0.01, 3000.0  # Pfeil's demonstration bearing
R = 0.5 * D


def bearing(groove, grid=(48, 8), **kw):
    kw = dict(dict(supply_pressure=1.7e5, ambient_pressure=1e5, cavitation_pressure=0.0), **kw)
    return JournalBearing(D, kw.pop("length", L), C, MU, groove=groove, grid=grid, **kw)


# --------------------------------------------------------------------------------------------------
# the full-length groove, bitwise the single groove the bearing had before the feeds
# --------------------------------------------------------------------------------------------------

def single_groove_film(b, speed_rpm):
    """The film of ``b`` (one full-length axial groove) as the bearing built it before the feeds existed, computed in
    this run: the groove's cells by the old recipe (cell centres within half the width of the groove's angle, the
    nearest one if none; every row) and one scalar supply value (p_s - p_c) / p0 for all of them."""
    g, x, z = b.groove, b.grid.x, b.grid.z
    dphi = np.angle(np.exp(1j * (x.centres - np.radians(g.angle_deg))))
    in_groove = np.abs(dphi) <= 0.5 * np.radians(g.width_deg) + 1e-12
    if not in_groove.any():
        in_groove[np.argmin(np.abs(dphi))] = True
    fixed = np.tile(in_groove, z.n)
    grid = Grid2D(x, z, fixed=fixed, fixed_values=0.0)
    scales = film_scales(b, speed_rpm)
    u_supply = (b.supply_pressure - b.cavitation_pressure) / scales.p0
    scales = scales._replace(u_supply=np.full(int(fixed.sum()), u_supply), feed_cells=np.where(fixed, 0, -1),
                             feed_edges=np.array([False]))
    kind = ReynoldsFilm if b.cavitation == "reynolds" else Film
    return kind(grid, scales, b.flow_law), fixed


@pytest.mark.parametrize("cavitation", ["elrod", "reynolds"])
@pytest.mark.parametrize("symmetric", [True, False])
def test_full_length_groove_is_bitwise_the_single_groove_of_before(cavitation, symmetric):
    """A full-length groove, however it is spelt, is the single groove of the bearing before the feeds existed: the
    same cells and, on this CPU, bitwise the same film. The old recipe is computed in the same run
    (:func:`single_groove_film`), so the comparison holds on any CPU (numba compiles for the host, whose rounding
    differs in the last bit between CPUs)."""
    kw = dict(grid=(60, 8), symmetric=symmetric, cavitation=cavitation, supply_pressure=2e5)
    spellings = [Groove(30.0, 12.0), Groove(30.0, 12.0, length=None), [Groove(30.0, 12.0, None)]]
    states = [JournalBearing(0.1, 0.05, 100e-6, 0.01, groove=g, **kw).steady_state(0.6, 3000.0, 10.0)
              for g in spellings]
    b = JournalBearing(0.1, 0.05, 100e-6, 0.01, groove=spellings[0], **kw)
    film, fixed = single_groove_film(b, 3000.0)
    assert np.array_equal(b.feed_cells >= 0, fixed) and fixed.sum() == 3 * b.grid.z.n  # centres at 24, 30, 36 deg
    a = np.radians(10.0)
    X, Y = 0.6 * np.cos(a), 0.6 * np.sin(a)
    u, its = film.solve(X, Y)
    old = film.state(u, X, Y, its)
    for s in states:
        assert np.array_equal(np.asarray(s.force), np.asarray(old.force))
        assert np.array_equal(s.pressure, old.pressure)


# --------------------------------------------------------------------------------------------------
# circumferential groove: two bearings, and the grooved short bearing's flow
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("cavitation", ["elrod", "reynolds"])
def test_circumferential_groove_at_ambient_is_two_land_bearings(cavitation):
    """Groove of 2 rows per half at the ambient pressure == one land of length (L - w)/2 with both ends at ambient,
    on the same cells: the grooved bearing carries twice the land's force and feeds what the land draws in."""
    n, m = 12, 2
    dz = 0.5 * L / n
    w, land_length = 2 * m * dz, 0.5 * L - m * dz
    kw = dict(supply_pressure=1e5, ambient_pressure=1e5, cavitation=cavitation)
    g = bearing(CircumferentialGroove(w), grid=(60, n), **kw).steady_state(0.6, RPM, 20.0)
    land = bearing(None, grid=(60, n - m), length=land_length, symmetric=False, **kw).steady_state(0.6, RPM, 20.0)
    np.testing.assert_allclose(g.force, 2.0 * np.array(land.force), rtol=1e-9)
    np.testing.assert_allclose(g.pressure[m:], land.pressure, rtol=1e-9, atol=1e-9 * g.max_pressure)
    scale = max(abs(land.side_leakage[1]), 1e-3 * np.pi * R * C * L * RPM / 60)
    np.testing.assert_allclose(g.supply_flow[0], -2.0 * land.side_leakage[0], atol=1e-9 * scale)
    np.testing.assert_allclose(g.side_leakage, land.side_leakage[1], atol=1e-9 * scale)


@pytest.mark.parametrize("cavitation", ["elrod", "reynolds"])
@pytest.mark.parametrize("eps", [0.0, 0.3, 0.6])
def test_circumferential_groove_flow_is_the_grooved_short_bearing_closed_form(eps, cavitation):
    """Full film fed by a central groove at p_s into two lands of length l: Q = pi R C^3 (p_s - p_a)(1 + 1.5 eps^2) /
    (3 mu l) (e.g. Hamrock, Schmid & Jacobson, "Fundamentals of Fluid Film Lubrication", pressure-fed bearings). The
    feed's linear axial pressure solves the 2-D film exactly and the hydrodynamic part carries no net flow out of a
    full 360 deg film, so the closed form holds at any L/D (incompressible film; bulk modulus 1e12 for Elrod)."""
    n, m = 12, 2
    w = 2 * m * 0.5 * L / n
    ps, pa = 2e6, 1e5
    s = bearing(CircumferentialGroove(w), grid=(60, n), supply_pressure=ps, ambient_pressure=pa, bulk_modulus=1e12,
                cavitation=cavitation).steady_state(eps, RPM)
    assert s.pressure.min() > 0.0  # the full film the closed form assumes
    Q = np.pi * R * C ** 3 * (ps - pa) * (1 + 1.5 * eps ** 2) / (3 * MU * (0.5 * (L - w)))
    assert s.supply_flow[0] == pytest.approx(Q, rel=1e-9)
    assert s.side_leakage.sum() == pytest.approx(Q, rel=1e-9)


# --------------------------------------------------------------------------------------------------
# flows: mass balance, half grid, orbit records
# --------------------------------------------------------------------------------------------------

FEED_SETS = {"partial groove": Groove(0.0, 15.0, length=0.06),
             "two grooves": [Groove(90.0, 15.0, length=0.06), Groove(-90.0, 15.0, length=0.06, pressure=2.5e5)],
             "hole": OilHole(0.0, 8e-3),
             "hole off the mid-plane": OilHole(0.0, 8e-3, axial_position=0.015),
             "circumferential groove": CircumferentialGroove(6e-3),
             "groove and hole": [Groove(0.0, 15.0, length=0.04), OilHole(180.0, 6e-3, axial_position=-0.02)]}


@pytest.mark.parametrize("name", list(FEED_SETS))
def test_steady_elrod_supply_equals_side_leakage(name):
    s = bearing(FEED_SETS[name], grid=(48, 12), ambient_pressure=0.0).steady_state(0.7, RPM, 15.0)
    assert np.all(np.isfinite(s.supply_flow)) and s.supply_flow.size == len(np.atleast_1d(FEED_SETS[name]))
    assert s.supply_flow.sum() == pytest.approx(s.side_leakage.sum(), rel=1e-8)
    assert s.supply_flow.sum() > 0.0  # ambient at the cavitation pressure: the feeds supply the film
    assert s.flow_variable > 0.0 and s.side_flow_ratio > 0.0


def test_half_grid_only_for_feeds_symmetric_about_the_mid_plane():
    assert bearing(Groove(0.0, 15.0, length=0.06)).symmetric
    assert bearing(OilHole(0.0, 8e-3)).symmetric
    off = bearing(OilHole(0.0, 8e-3, axial_position=0.015), grid=(48, 8))
    assert not off.symmetric and off.grid_shape == (48, 16)
    assert not bearing([Groove(0.0, 10.0, length=0.04), CircumferentialGroove(4e-3, axial_position=0.03)]).symmetric


@pytest.mark.parametrize("name", ["partial groove", "two grooves", "circumferential groove"])
def test_half_grid_equals_the_whole_length(name):
    half = bearing(FEED_SETS[name], grid=(48, 12)).steady_state(0.6, RPM, 15.0)
    full = bearing(FEED_SETS[name], grid=(48, 24), symmetric=False).steady_state(0.6, RPM, 15.0)
    np.testing.assert_allclose(half.force, full.force, rtol=1e-9)
    np.testing.assert_allclose(half.supply_flow, full.supply_flow, rtol=1e-8)
    np.testing.assert_allclose(half.side_leakage, full.side_leakage, rtol=1e-8)


def test_a_hole_off_the_mid_plane_mirrors():
    up = bearing(OilHole(0.0, 8e-3, axial_position=0.015), grid=(48, 12)).steady_state(0.6, RPM, 15.0)
    down = bearing(OilHole(0.0, 8e-3, axial_position=-0.015), grid=(48, 12)).steady_state(0.6, RPM, 15.0)
    np.testing.assert_allclose(up.force, down.force, rtol=1e-9)
    np.testing.assert_allclose(up.side_leakage, down.side_leakage[::-1], rtol=1e-8)
    assert abs(up.side_leakage[0] - up.side_leakage[1]) > 0.05 * abs(up.side_leakage).max()


@pytest.mark.parametrize("method", ["ida", "rk4"])
def test_orbit_records_flows_consistent_with_the_mass_balance(method):
    """The orbit's supply and leakage (face fluxes, flows.py) against its global mass balance terms (the kernels'
    residual, Film.mass_flows): the same flows, computed two ways."""
    b = bearing([Groove(0.0, 15.0, length=0.06), OilHole(90.0, 8e-3, axial_position=0.01)], grid=(40, 6),
                ambient_pressure=0.0)
    o = JournalOrbit(b, 5.0, 0.01 * C, 400.0, RPM)
    steps = dict(steps_per_revolution=400) if method == "rk4" else {}  # the fixed steps of rk4 (ida takes none)
    r = o.run(0.05, integration=Integration(method=method, **steps),
              recording=Recording(outputs_per_revolution=100, record=("supply_flow", "side_leakage", "outflow")))
    assert r.supply_flow.shape == (r.t.size, 2) and r.side_leakage.shape == (r.t.size, 2)
    np.testing.assert_allclose(r.supply_flow.sum(axis=1), -r.outflow[:, 1], rtol=1e-9)
    np.testing.assert_allclose(r.side_leakage.sum(axis=1), r.outflow[:, 0], rtol=1e-9)


# --------------------------------------------------------------------------------------------------
# every computation takes the feeds
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("cavitation", ["elrod", "reynolds"])
def test_coefficients_of_an_asymmetric_feed_set_match_finite_differences(cavitation):
    """K = -dF/dx of the bearing with a groove and an off-centre hole (whole-length grid) against central
    differences of the steady force."""
    b = bearing([Groove(0.0, 15.0, length=0.05), OilHole(200.0, 12e-3, axial_position=0.02)], grid=(40, 6),
                ambient_pressure=0.0, cavitation=cavitation)
    load = 2000.0
    st = b.equilibrium(load, RPM)
    K, _ = b.coefficients(load, RPM)
    x, y = st.position
    h = 1e-6 * C
    for j, (dx, dy) in enumerate(((h, 0.0), (0.0, h))):
        fp = np.array(b.steady_state(np.hypot(x + dx, y + dy) / C, RPM, np.degrees(np.arctan2(y + dy, x + dx))).force)
        fm = np.array(b.steady_state(np.hypot(x - dx, y - dy) / C, RPM, np.degrees(np.arctan2(y - dy, x - dx))).force)
        np.testing.assert_allclose(-(fp - fm) / (2 * h), K[:, j], rtol=1e-6, atol=1e-6 * np.abs(K).max())


@pytest.mark.parametrize("kw", [dict(rheology=Gecim(kappa=2e4, viscosity_ratio=0.5)),
                                dict(layers=BoundaryLayers(0.05 * C, (10 * MU, 20 * MU), 0.02 * C)),
                                dict(rheology=Gecim(kappa=2e4, viscosity_ratio=0.5), cavitation="reynolds")])
def test_layers_and_gecim_bulk_take_the_feeds_and_balance(kw):
    s = bearing([Groove(0.0, 15.0, length=0.05), OilHole(120.0, 12e-3, axial_position=0.015)], grid=(40, 6),
                ambient_pressure=0.0, **kw).steady_state(0.6, RPM, 15.0)
    assert s.load > 0 and np.all(np.isfinite(s.supply_flow))
    if kw.get("cavitation") != "reynolds":
        assert s.supply_flow.sum() == pytest.approx(s.side_leakage.sum(), rel=1e-8)


def test_stability_threshold_with_two_grooves():
    b = bearing([Groove(90.0, 15.0, length=0.06), Groove(-90.0, 15.0, length=0.06)], grid=(40, 6),
                ambient_pressure=0.0)
    n = b.stability_threshold(20.0, 2000.0, speed_range_rpm=(300.0, 60000.0), rtol=1e-3)
    assert b.growth_rate(20.0, 2000.0, 0.97 * n) < 0.0 < b.growth_rate(20.0, 2000.0, 1.03 * n)


# --------------------------------------------------------------------------------------------------
# holes: to zero, and to a groove of the same area
# --------------------------------------------------------------------------------------------------

def test_hole_shrinking_to_zero_tends_to_the_ungrooved_film():
    """The load change a hole makes falls with its diameter (ends at ambient feed the film without it). A pressure
    hole in a 2-D film acts like a point source, whose influence vanishes only like 1 / ln(1 / d)."""
    grid = (144, 24)
    none = bearing(None, grid=grid).steady_state(0.5, RPM)
    dW = [abs(bearing(OilHole(90.0, d), grid=grid).steady_state(0.5, RPM).load / none.load - 1)
          for d in (16e-3, 8e-3, 4e-3)]
    assert dW[0] > dW[1] > dW[2]
    assert dW[1] / dW[0] < 0.8 and dW[2] / dW[1] < 0.8


def test_hole_smaller_than_a_cell_warns():
    """48 x 8 cells of 6.54 x 5 mm: a 3 mm hole is modelled as whole cells (warned); a 0.5 mm hole, less than a
    quarter of a cell, is refused (it would be modelled 13 times too wide)."""
    with pytest.warns(UserWarning, match=r"groove\.diameter = 0\.003 m is smaller than a cell of the grid of 48 x 8 "
                                         r"cells .*modelled as 1 whole cell"):
        bearing(OilHole(90.0, 3e-3))
    with pytest.raises(ValueError, match=r"groove\.diameter = 0\.0005 \[m\] is less than 0\.25 cell of the grid of "
                                         r"48 x 8 cells .*allowed on this grid: \[0\.00164, 0\.08\] m"):
        bearing(OilHole(90.0, 5e-4))


def test_hole_of_the_groove_area_approaches_the_groove():
    grid = (144, 24)
    g = Groove(90.0, 15.0, length=0.02)
    d = np.sqrt(4 * g.area(L, R) / np.pi)
    none = bearing(None, grid=grid).steady_state(0.5, RPM)
    sg = bearing(g, grid=grid).steady_state(0.5, RPM)
    sh = bearing(OilHole(90.0, d), grid=grid).steady_state(0.5, RPM)
    assert abs(sh.load - sg.load) < 0.05 * abs(sg.load - none.load)
    assert sh.supply_flow[0] == pytest.approx(sg.supply_flow[0], rel=0.06)


#: Pfeil's fvm_elrod (github.com/simonpfeil/SBFEM-and-numerical-solutions-of-the-Reynolds-equation,
#: Matlab/demonstration_fvm_elrod), run with GNU Octave 7 on its demonstration script's inputs and grid (n_x = 100
#: nodes round, n_y = 26 on the whole length, symmetric BC; shaft displaced by C/2 horizontally, X_att = 0), only
#: the groove's centre X_os changed for the second case: load |(F_h, F_v)| [N] and attitude atan2(-F_v, F_h) [deg].
#: Peer's X is measured from the minimum film in the direction of rotation, this code's angle from the maximum film,
#: so the peer's X_os = 90 deg (its demonstration) is Groove(270) here and X_os = 270 deg is Groove(90).
PFEIL_DEMO = {270.0: (1739.932426, 52.658),   # X_os = 90 deg: F_h 1055.388563, F_v -1383.300339 N
              90.0: (1294.476996, 39.209)}    # X_os = 270 deg: F_h 1003.015204, F_v -818.309962 N


@pytest.mark.parametrize("angle", list(PFEIL_DEMO))
def test_pfeil_demonstration_groove_against_fvm_elrod_at_its_grid(angle):
    """Pfeil's demonstration (15-deg groove, 60 mm long, 70 kPa above an ambient at the cavitation pressure,
    e/C 0.5, 3000 rpm) on the grid nearest the peer's (100 x 13 cells on the half; the groove takes the same 5
    columns as the peer's nodes). Measured differences at this grid: load +0.70 % / +0.39 %, attitude -0.05 / -0.13
    deg. On finer grids both codes converge to the same load (docs/validation.md), from opposite sides; for the
    demonstration each is ~0.3 % off at this grid (the groove's axial ends: the peer holds nodes to +-30.4 mm, this
    code cells to +-29.2 mm with the edge on the face at +-30.8 mm; the cavitation boundaries and bearing ends).
    Tolerance 1 % / 0.2 deg covers that; the mirrored groove is 25-35 % / 13 deg off and an ambient 1 bar above the
    cavitation pressure +6.9 % / +15 deg, so the angle convention and the pressure reference are pinned (not the
    groove's length: a full-length groove is 0.9 % from the 60 mm one)."""
    W, attitude = PFEIL_DEMO[angle]
    s = bearing(Groove(angle, 15.0, length=0.06), grid=(100, 13), supply_pressure=70e3, ambient_pressure=0.0,
                cavitation_pressure=0.0).steady_state(0.5, RPM)
    assert s.load == pytest.approx(W, rel=0.01)
    assert s.attitude_angle_deg == pytest.approx(attitude, abs=0.2)


# --------------------------------------------------------------------------------------------------
# flow variables: the limits of the design charts
# --------------------------------------------------------------------------------------------------

def test_flow_variable_is_pi_in_the_concentric_bearing():
    """Concentric journal, groove at the cavitation pressure: the film carries the Couette flow U C L / 2, i.e.
    Q / (R C N L) = pi, the eps -> 0 end of Raimondi & Boyd's flow-variable chart."""
    s = bearing(Groove(0.0, 6.0), grid=(60, 8), supply_pressure=0.0, ambient_pressure=0.0,
                cavitation="reynolds").steady_state(0.0, RPM)
    assert s.flow_variable == pytest.approx(np.pi, rel=1e-12)


def test_flow_variables_approach_the_short_bearing_limit():
    """Groove at the maximum film and at the ambient = cavitation pressure (Raimondi & Boyd's set-up), Reynolds
    condition: as L/D -> 0 the circumferential flow is Couette, Q / (R C N L) -> pi (1 + eps), and the side flow is
    what the film loses from maximum to minimum film, Q_s / Q -> 2 eps / (1 + eps) (Ocvirk's short bearing)."""
    eps = 0.5
    err = []
    for ld in (0.5, 0.25, 0.125):
        s = JournalBearing(D, ld * D, C, MU, groove=Groove(0.0, 3.0), grid=(240, 8), supply_pressure=0.0,
                           cavitation="reynolds").steady_state(eps, RPM, 0.0)
        err.append((abs(s.flow_variable / (np.pi * (1 + eps)) - 1), abs(s.side_flow_ratio / (2 * eps / (1 + eps)) - 1)))
    err = np.array(err)
    assert np.all(np.diff(err, axis=0) < 0)  # both converge as L/D falls
    assert np.all(err[-1] < 0.05)


# --------------------------------------------------------------------------------------------------
# bad input: one line naming the parameter, its value, unit and allowed range
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("feed, match", [
    (lambda: Groove(0.0, 10.0, length=0.1), r"groove\.length = 0\.1 \[m\] is out of range; allowed: \(0, 0\.08\] m"),
    (lambda: OilHole(0.0, 0.09), r"groove\.diameter = 0\.09 \[m\] is out of range; allowed: \(0, 0\.08\] m"),
    (lambda: OilHole(0.0, 0.01, axial_position=0.038), r"groove\.axial_position = 0\.038 \[m\] is out of range"),
    (lambda: CircumferentialGroove(0.08), r"groove\.width = 0\.08 \[m\] is out of range; allowed: \(0, 0\.08\) m"),
    (lambda: Groove(0.0, 10.0, pressure=-1.0), r"groove\.pressure = -1\.0 \[Pa\] is out of range"),
    (lambda: Groove(0.0, 10.0, pressure=5e3), r"groove\.pressure = 5000\.0 \[Pa\] is out of range; allowed: \[10000, 1e\+09\] Pa"),
    (lambda: [Groove(0.0, 20.0), Groove(10.0, 10.0)], r"groove\[1\] = Groove\(.*overlaps groove\[0\]"),
    (lambda: [OilHole(0.0, 0.01), CircumferentialGroove(0.004)], r"groove\[1\] = Circ.*overlaps groove\[0\]"),
])
def test_bad_feeds_are_one_line_errors(feed, match):
    with pytest.raises(ValueError, match=match) as e:
        bearing(feed(), grid=(72, 12), cavitation_pressure=1e4, ambient_pressure=1e4)
    assert "\n" not in str(e.value)


def test_not_a_feed_is_a_type_error():
    with pytest.raises(TypeError, match=r"groove\[1\] must be a Groove, OilHole or CircumferentialGroove"):
        bearing([Groove(), "hole"])


HOSTILE = [float("nan"), float("inf"), -float("inf"), 0.0, -1.0, 1e300, -1e-300, "1", True, None, [1.0], 1e-9]
FIELDS = [(Groove, "angle_deg"), (Groove, "width_deg"), (Groove, "length"), (Groove, "pressure"),
          (OilHole, "angle_deg"), (OilHole, "diameter"), (OilHole, "axial_position"), (OilHole, "pressure"),
          (CircumferentialGroove, "width"), (CircumferentialGroove, "axial_position"), (CircumferentialGroove, "pressure")]


@pytest.mark.parametrize("kind, key", FIELDS, ids=[f"{k.__name__}.{f}" for k, f in FIELDS])
def test_hostile_feed_fields_give_a_named_error_or_a_finite_film(kind, key):
    """NaN, infinities, zero, negatives, huge and tiny numbers, strings, booleans, None, containers in every field of
    every feed: a one-line ValueError/TypeError naming the field, or a film with finite force and flows."""
    named = finite = 0
    for value in HOSTILE:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # a hole smaller than a cell warns
                s = bearing(kind(**{key: value}), grid=(24, 4)).steady_state(0.5, RPM)
        except (ValueError, TypeError) as e:
            msg = str(e)
            assert "\n" not in msg and (key in msg or "groove" in msg), msg
            named += 1
            continue
        assert np.all(np.isfinite(s.force)) and np.all(np.isfinite(s.supply_flow)), (key, value)
        finite += 1
    assert named + finite == len(HOSTILE)


def test_feeds_off_the_mid_plane_in_the_bdf2_orbit_agree_with_ida():
    """A partial groove and an off-centre hole (whole-length grid) in one revolution of the orbit: the BDF2 stepper on
    the content film against a tight IDA run, positions and each feed's supply flow."""
    b = JournalBearing(diameter=0.08, length=0.024, clearance=80e-6, viscosity=0.029, grid=(36, 6),
                       groove=[Groove(0.0, 10.0, length=0.012), OilHole(180.0, 4e-3, axial_position=0.004)])
    assert not b.symmetric
    o = JournalOrbit(bearing=b, rotor_mass=100.0, unbalance=0.1 * 80e-6, load=981.0, speed_rpm=6000)
    ida = o.run(revolutions=1, integration=Integration(method="ida", rtol=1e-7),
                recording=Recording(record=("supply_flow",)))
    bdf2 = o.run(revolutions=1, integration=Integration(method="bdf2", rtol=1e-5),
                 recording=Recording(record=("supply_flow",)))
    assert ida.success and bdf2.success
    assert np.max(np.hypot(bdf2.x - ida.x, bdf2.y - ida.y)) < 2e-4 * 80e-6
    np.testing.assert_allclose(bdf2.supply_flow[-1], ida.supply_flow[-1], rtol=1e-3)
