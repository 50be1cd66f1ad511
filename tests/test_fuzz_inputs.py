"""Property-based fuzzing of the public constructors and run methods (hypothesis): every input gets a named
error (the parameter's name in a one-line ValueError/TypeError; for the rotor, the rotor on bearings, the oil feeds
and the point contact a ValueError) or a correct, finite result; no hang, no crash.

Each case replaces ONE argument of a valid call by a hostile value (NaN, +-inf, zero, negative, huge, tiny,
strings, booleans, None, containers, non-integers); the counts of named errors and finite results are
gathered in ``COUNTS`` and printed at the end of the run (docs/validation.md quotes them).
"""

import os
import warnings
from collections import Counter

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from transient import (AsperityContact, DiscreteDensity, Integration, LongRun, Recording, RoughSurface, ThrustPad,
                       TrackSettings, steel_asperity_contact)
from transient.models.ball import ThrustBallBearing
from transient.models.journal import CircumferentialGroove, Groove, JournalBearing, JournalOrbit, OilHole
from transient.models.point import PointContact
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.physics.layered import BoundaryLayers, Gecim, LayeredFilm

COUNTS = Counter()
VALID = Counter()  # valid inputs whose results a target checked, by target

hostile = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**6, 10**6),
    st.sampled_from([0, 0.0, -1.0, 1e-300, 1e300, -1e-9, float("nan"), float("inf"), -float("inf")]),
    st.text(max_size=5), st.sampled_from(["0.08", "1e-3", "", "nan", "True"]), st.booleans(), st.none(),
    st.lists(st.floats(-1e3, 1e3), max_size=3), st.tuples(st.floats(-10, 10), st.floats(-10, 10)))


def _outcome(name, call, check=None, errors=(ValueError, TypeError)):
    """Run ``call``; an error of ``errors`` must name ``name``; a result must pass ``check`` (finite)."""
    try:
        r = call()
    except errors as e:
        msg = str(e)
        assert name.split(".")[-1].split("[")[0] in msg, f"error does not name {name!r}: {msg}"
        assert "\n" not in msg.strip(), f"multi-line error for {name!r}: {msg}"
        COUNTS["named error"] += 1
        return None
    if check is not None:
        check(r)
    COUNTS["finite result"] += 1
    return r


def _finite(*values):
    for v in values:
        assert np.all(np.isfinite(np.asarray(v, dtype=float))), v


# deterministic in the fast suite (the same examples every run: a red CI is reproducible); FUZZ_EXAMPLES=N runs
# N fresh random examples per test instead, for exploring
_EXPLORE = int(os.environ.get("FUZZ_EXAMPLES", "0"))
SETTINGS = settings(max_examples=_EXPLORE or 60, deadline=None, derandomize=not _EXPLORE,
                    suppress_health_check=[HealthCheck.too_slow])

PAD = dict(length=0.02, width=0.02, viscosity=0.03, surface=2e-6, grid=(6, 6))


@SETTINGS
@given(key=st.sampled_from(sorted(PAD)), value=hostile)
def test_thrust_pad(key, value):
    kw = dict(PAD, **{key: value})

    def run():
        pad = ThrustPad(**kw)
        r = pad.descent(load=600.0, h0_start=1e-5, t_end=0.02, n_out=4)
        return pad, r

    def check(res):
        pad, r = res
        if r.success:
            _finite(r.h0, r.w_hyd, r.w_asp)
            assert np.all(r.h0 > 0), "a successful descent has a positive gap"

    _outcome({"surface": "surface", "grid": "grid"}.get(key, key), run, check)


@SETTINGS
@given(key=st.sampled_from(["load", "h0_start", "t_end", "mass", "rtol", "n_out"]), value=hostile)
def test_pad_descent(key, value):
    pad = ThrustPad(**PAD)
    kw = dict(load=600.0, h0_start=1e-5, t_end=0.02, n_out=4, rtol=1e-6)
    kw[key] = value

    def check(r):
        if r.success:
            _finite(r.h0)
            assert np.all(r.h0 > 0)

    _outcome(key, lambda: pad.descent(**kw), check)


SURF = dict(shape=(16, 16), spacing=1e-6, rq=1e-6, correlation_lengths=(4e-6, 4e-6), seed=1)


@SETTINGS
@given(key=st.sampled_from(["shape", "spacing", "rq", "correlation_lengths", "skewness"]), value=hostile)
def test_rough_surface(key, value):
    kw = dict(SURF, **{key: value})
    name = {"spacing": "spacing", "correlation_lengths": "correlation", "shape": "shape"}.get(key, key)
    _outcome(name, lambda: RoughSurface.generate(**kw), lambda s: _finite(s.heights))


CONTACT = dict(asperity_density=1e9, asperity_radius=1e-3, e_prime=1e11, hardness=4e9, sigma=1e-6)  # psi = 0.79


@SETTINGS
@given(key=st.sampled_from(sorted(CONTACT)), value=hostile)
def test_asperity_contact(key, value):
    kw = dict(CONTACT, **{key: value})
    _outcome(key, lambda: AsperityContact(**kw), lambda c: _finite(c.load(2e-6), c.real_area_fraction(2e-6)))


@SETTINGS
@given(value=hostile)
def test_steel_contact_and_density(value):
    _outcome("rq", lambda: steel_asperity_contact(value), lambda c: _finite(c.load(2e-6)))
    _outcome("sigma", lambda: DiscreteDensity.gaussian(value), lambda d: _finite(d.integral(1.5, 0.5)))


@SETTINGS
@given(key=st.sampled_from(["kappa", "viscosity_ratio"]), value=hostile)
def test_gecim(key, value):
    kw = dict(kappa=1e5, viscosity_ratio=0.57)
    kw[key] = value
    _outcome(key, lambda: Gecim(**kw), lambda g: _finite(g.viscosity(1e4, 0.03)))


@SETTINGS
@given(key=st.sampled_from(["thickness", "viscosity", "alpha"]), value=hostile)
def test_boundary_layers(key, value):
    kw = dict(thickness=1e-6, viscosity=0.3, alpha=1e-7)
    kw[key] = value

    def check(layers):
        f = LayeredFilm(0.03, Gecim(1e5, 0.57), layers)
        _finite(f.flow(20e-6, -1e9, 1.0, 0.0))

    _outcome(key, lambda: BoundaryLayers(**kw), check)


JOURNAL = dict(diameter=0.08, length=0.04, clearance=8e-5, viscosity=0.03, bulk_modulus=1e9, supply_pressure=101325.0,
               cavitation_pressure=0.0, ambient_pressure=0.0, switch_content_width=1e-2, grid=(24, 4), symmetric=True,
               groove=Groove(), cavitation="elrod", switch_width=None)


@SETTINGS
@given(key=st.sampled_from(sorted(JOURNAL)), value=hostile)
def test_journal_bearing(key, value):
    kw = dict(JOURNAL, **{key: value})

    def run():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return JournalBearing(**kw).steady_state(0.6, 6000.0)

    _outcome(key, run, lambda st_: _finite(st_.pressure, st_.force, st_.film_content))


@SETTINGS
@given(key=st.sampled_from(["kappa", "viscosity_ratio", "rheology"]), value=hostile)
def test_journal_with_a_gecim_bulk(key, value):
    """The Gecim bulk inside the journal film: a hostile kappa or ratio, or a hostile ``rheology`` argument."""
    def run():
        rh = value if key == "rheology" else Gecim(**dict(dict(kappa=1e3, viscosity_ratio=0.57), **{key: value}))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return JournalBearing(**dict(JOURNAL, grid=(16, 3)), rheology=rh).steady_state(0.6, 6000.0)

    _outcome(key, run, lambda st_: _finite(st_.pressure, st_.force, st_.friction_force, st_.bearing_friction_force))


@SETTINGS
@given(key=st.sampled_from(["angle_deg", "width_deg"]), value=hostile)
def test_groove(key, value):
    _outcome(key, lambda: Groove(**{key: value}), lambda g: _finite(JournalBearing(**dict(JOURNAL, groove=g))
                                                                     .steady_state(0.5, 3000.0).force))


_ORBIT = None


def _orbit():
    global _ORBIT
    if _ORBIT is None:
        _ORBIT = JournalOrbit(JournalBearing(**JOURNAL), 50.0, 1e-6, 500.0, 6000.0)
    return _ORBIT


@SETTINGS
@given(key=st.sampled_from(["revolutions", "rtol", "atol", "outputs_per_revolution", "touch_gap", "y0",
                            "chunk_revolutions"]), value=hostile)
def test_journal_orbit_run(key, value):
    assume(not (key == "revolutions" and isinstance(value, (int, float)) and value > 0.5))  # valid, but long
    kw = dict(revolutions=0.05, rtol=1e-4, atol=1e-8, outputs_per_revolution=20) | {key: value}
    name = {"y0": "initial state"}.get(key, key)

    def run():  # the settings objects are made inside: their refusals count as the run's
        chunk = {"chunk_revolutions": kw["chunk_revolutions"]} if "chunk_revolutions" in kw else {}
        return _orbit().run(kw["revolutions"], integration=Integration(rtol=kw["rtol"], atol=kw["atol"]),
                            recording=Recording(outputs_per_revolution=kw["outputs_per_revolution"]),
                            long_run=LongRun(progress=False, **chunk), **{k: kw[k] for k in ("touch_gap", "y0") if k in kw})

    _outcome(name, run, lambda r: _finite(r.x, r.y))


@SETTINGS
@given(key=st.sampled_from(["rotor_mass", "unbalance", "load", "speed_rpm"]), value=hostile)
def test_journal_orbit(key, value):
    kw = dict(rotor_mass=50.0, unbalance=1e-6, load=500.0, speed_rpm=6000.0) | {key: value}
    _outcome(key, lambda: JournalOrbit(_orbit().bearing, **kw).initial_state(), _finite)


BALL = dict(pitch_diameter=0.031, ball_diameter=0.003, n_balls=6, conformity=0.52, youngs_modulus=207e9,
            poisson_ratio=0.3, viscosity=0.02, pressure_viscosity=2e-8, surface_tension=0.036)


@SETTINGS
@given(key=st.sampled_from(sorted(BALL)), value=hostile)
def test_thrust_ball_bearing(key, value):
    def check(b):
        f = b.flooded_film(100.0, 1000.0)
        _finite(f.h_c, f.h_min, f.m_star)
        assert f.h_c > 0 and f.h_min > 0, "a flooded film is positive"

    _outcome(key, lambda: ThrustBallBearing(**dict(BALL, **{key: value})), check)


# --------------------------------------------------------------------------------------------------
# the roller family, the layered flow law, the ball sequence, the scene loader, the sweep's --param parser and
# load_result: a smaller fixed budget each (FUZZ_EXAMPLES=N explores N per test)
# --------------------------------------------------------------------------------------------------

FAST = settings(max_examples=_EXPLORE or 25, deadline=None, derandomize=not _EXPLORE,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])

LINE = dict(radius=0.01, load_per_length=1e5, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11,
            grid=129)


@FAST
@given(key=st.sampled_from(sorted(LINE)), value=hostile)
def test_line_contact(key, value):
    from transient import LineContact

    assume(not (key == "grid" and isinstance(value, (int, float)) and not isinstance(value, bool) and value > 400))  # valid, slow

    def check(s):
        if s.success:
            _finite(s.h_min, s.h_central, s.p_max, s.film, s.pressure)
            assert s.h_min > 0

    from transient.models.roller.results import EHLConvergenceError

    def run():
        c = LineContact(**dict(LINE, **{key: value}))
        try:
            return c.steady()
        except EHLConvergenceError as e:  # a valid contact the solver does not converge on: named, counted apart
            assert "did not converge" in str(e)
            COUNTS["named non-convergence"] += 1
            return None

    def checked(s):
        if s is None:  # counted as a named non-convergence above, not as a finite result
            COUNTS["finite result"] -= 1
        else:
            check(s)

    _outcome(key, run, checked)


@FAST
@given(key=st.sampled_from(["mean_radius", "half_angle_deg", "length", "dub_off_radius", "profile_start", "tilt_deg"]),
       value=hostile)
def test_tapered_roller(key, value):
    from transient import TaperedRoller
    from transient.params import park

    _outcome(key, lambda: TaperedRoller(**dict(park.ROLLER, **{key: value})),
             lambda r: _finite(r.half_length, r.length, r.profile_start))


ROLLER_CONTACT = dict(U=1e-11, G=2500.0, W=2e-5, modulus=220e9, speed=1.0, grid=("clustered", 24, 24))


@FAST
@given(key=st.sampled_from(["U", "G", "W", "modulus", "speed", "grid"]), value=hostile)
@example(key="U", value=2e-11)  # valid inputs: the check below runs on a built contact every time
@example(key="W", value=5e-5)
@example(key="speed", value=2.0)
def test_roller_contact(key, value):
    from transient import RollerContact, TaperedRoller
    from transient.params import park

    kw = dict(ROLLER_CONTACT, roller=TaperedRoller(**park.ROLLER)) | {key: value}

    def check(c):
        """The contact carries the groups it was built from (load W E' R_m^2, viscosity U E' R_m / speed)."""
        _finite(c.load, c.lubricant.viscosity, c.lubricant.pressure_viscosity)
        assert c.U == pytest.approx(kw["U"], rel=1e-12) and c.W == pytest.approx(kw["W"], rel=1e-12)
        assert c.lubricant.pressure_viscosity * c.modulus == pytest.approx(kw["G"], rel=1e-12)
        VALID["roller contact"] += 1

    _outcome(key, lambda: RollerContact.from_dimensionless(**kw), check)


def test_roller_target_checks_a_valid_contact():
    """The explicit examples above build valid contacts, so the roller target's check runs (and can fail)."""
    before = VALID["roller contact"]
    test_roller_contact()
    assert VALID["roller contact"] >= before + 3


# --------------------------------------------------------------------------------------------------
# the rotor, the rotor on bearings, the oil feeds and the EHL point contact: every bad input a named ValueError
# --------------------------------------------------------------------------------------------------

def _named_value_error(name, call, check=None):
    """As :func:`_outcome`, but the error must be a ``ValueError`` (naming ``name``): these constructors check every
    argument with the vocabulary of transient.checks."""
    return _outcome(name, call, check, errors=(ValueError,))


def _rigid_rotor():
    return Rotor.rigid(20.0, 0.5, 0.3)


ROTOR_KEYS = ["mass", "stiffness", "damping", "gyroscopic", "nodes", "dofs", "basis", "gravity_load"]


@FAST
@given(key=st.sampled_from(ROTOR_KEYS), value=hostile)
@example(key="damping", value=None)  # valid
@example(key="nodes", value=[3, 7])
def test_rotor(key, value):
    r = _rigid_rotor()
    kw = dict(mass=r.mass, stiffness=r.stiffness, nodes=[0, 1]) | {key: value}

    def check(rotor):
        assert rotor.total_mass == pytest.approx(20.0, rel=1e-12)  # the rigid rotor's mass, whatever the labels

    _named_value_error(key, lambda: Rotor(**kw), check)


def _bearing():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return JournalBearing(**JOURNAL)


@FAST
@given(key=st.sampled_from(["rotor", "bearings", "unbalance", "gravity"]), value=hostile)
@example(key="gravity", value=(0.0, 9.81))  # valid
@example(key="unbalance", value=5)  # was "'int' object is not iterable"
def test_rotor_bearing_system(key, value):
    b = _bearing()
    kw = dict(rotor=_rigid_rotor(), bearings={0: b, 1: b}, unbalance=[(0, 1e-4, 0.0)], gravity=9.81) | {key: value}

    def check(s):
        """The shaft on rigid supports: the bearing loads carry the weight."""
        W = np.array(list(s.static_loads().values())).sum(axis=0)
        np.testing.assert_allclose(W, 20.0 * s.gravity_vector, rtol=1e-9, atol=1e-9 * 20.0 * 9.81)

    _named_value_error(key, lambda: RotorBearingSystem(**kw), check)


@FAST
@given(index=st.sampled_from([0, 1, 2]), value=hostile)
@example(index=1, value=20.0)  # 20 kg m on a 20 kg rotor: refused as implausible
def test_rotor_unbalance_items(index, value):
    b = _bearing()
    item = [0, 1e-4, 0.0]
    item[index] = value
    _named_value_error("unbalance", lambda: RotorBearingSystem(_rigid_rotor(), {0: b, 1: b}, unbalance=[tuple(item)]))


FEED_FIELDS = [(Groove, "angle_deg"), (Groove, "width_deg"), (Groove, "length"), (Groove, "pressure"),
               (OilHole, "angle_deg"), (OilHole, "diameter"), (OilHole, "axial_position"), (OilHole, "pressure"),
               (CircumferentialGroove, "width"), (CircumferentialGroove, "axial_position"),
               (CircumferentialGroove, "pressure")]
FEED_VALID = {OilHole: dict(diameter=0.012), Groove: {}, CircumferentialGroove: {}}  # a hole of at least a cell


@FAST
@given(field=st.sampled_from(FEED_FIELDS), value=hostile)
@example(field=(Groove, "width_deg"), value=0.52)  # a width in radians: warned (one column of a 15-deg cell)
@example(field=(CircumferentialGroove, "width"), value=0.039)  # covers every row of the 40 mm bearing's half
@example(field=(CircumferentialGroove, "pressure"), value=0.0)  # at the cavitation pressure: supplies nothing
@example(field=(Groove, "length"), value=0.02)  # valid
def test_oil_feeds(field, value):
    kind, key = field

    def run():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a hole smaller than a cell warns
            feed = kind(**(FEED_VALID[kind] | {key: value}))
            return JournalBearing(**dict(JOURNAL, groove=feed)).steady_state(0.5, 3000.0)

    _named_value_error(key, run, lambda s: _finite(s.force, s.supply_flow, s.side_leakage, s.pressure))


@FAST
@given(value=hostile)
def test_groove_argument(value):
    _named_value_error("groove", lambda: JournalBearing(**dict(JOURNAL, groove=value)))


POINT = dict(radius_x=0.01, radius_y=None, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8,
             modulus=2.2e11, density="dowson-higginson", viscosity_law="barus", inlet_film=None, grid=(25, 25),
             domain=None, dh_constants=(0.58e-9, 1.68e-9), upwind="first")


@FAST
@given(key=st.sampled_from(sorted(POINT)), value=hostile)
@example(key="domain", value=5)  # was "'int' object is not subscriptable"
@example(key="grid", value=(128, 129))  # an even node count: the dense Newton matrix
@example(key="radius_y", value=0.03)  # valid
def test_point_contact(key, value):
    def check(c):
        _finite(c.hd_central, c.hd_minimum, c.x_nodes, c.y_nodes)
        assert c.hd_central >= 0 and c.x_nodes.size == c.grid[0]  # 0 for an isoviscous oil (valid: alpha = 0)
        assert np.min(np.abs(c.x_nodes)) == 0.0  # a node at the centre

    _named_value_error(key, lambda: PointContact(**(POINT | {key: value})), check)


@FAST
@given(key=st.sampled_from(["h", "G", "U1", "U2"]), value=hostile)
def test_layered_flow(key, value):
    film = LayeredFilm(0.03, Gecim(1e5, 0.57), BoundaryLayers(1e-6, 0.3, 1e-7))
    kw = dict(h=20e-6, G=-1e9, U1=1.0, U2=0.0) | {key: value}

    def check(f):
        _finite(f.q_couette, f.q_pressure, f.dqp_dG, f.dqp_dh)

    _outcome(key, lambda: film.flow(**kw), check)


@FAST
@given(key=st.sampled_from(["n_passes", "ambient_film", "load", "speed_rpm", "replenishment"]), value=hostile)
def test_ball_sequence(key, value):
    b = ThrustBallBearing(**BALL)
    kw = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6, n_passes=2) | {key: value}
    assume(not (key == "n_passes" and isinstance(value, int) and not isinstance(value, bool) and value > 3))  # valid, long

    def run():
        try:
            if "replenishment" in kw:  # a setting of the track between passes
                return b.sequence(**{k: v for k, v in kw.items() if k != "replenishment"},
                                  track=TrackSettings(replenishment=kw["replenishment"]))
            return b.sequence(**kw)
        except RuntimeError as e:  # a valid bearing whose levelling the solver cannot finish: named, counted apart
            assert "levelling failed" in str(e), str(e)
            COUNTS["named non-convergence"] += 1
            return None

    def check(s):
        if s is None:
            COUNTS["finite result"] -= 1
        else:
            _finite(s.H_central, s.h_inlet)

    _outcome(key, run, check)


SCENE_KEYS = [("overrides", "load"), ("overrides", "n_balls"), ("overrides", "speed_rpm"), ("run", "n_passes"),
              ("run", "replenishment"), ("outputs", "figures"), ("parameters", None), ("kind", None),
              ("overrides", None), ("run", None), ("outputs", None), ("title", None)]


@FAST
@given(where=st.sampled_from(SCENE_KEYS), value=hostile)
def test_scene_loader(where, value):
    from transient.study.scene import scene_from_dict

    section, key = where
    doc = dict(kind="ball_sequence", parameters="jeong", run=dict(n_passes=2), outputs=dict(figures=False))
    if key is None:
        doc[section] = value
    else:
        doc[section] = dict(doc.get(section, {}), **{key: value})
    _outcome(key or section, lambda: scene_from_dict(doc))


@FAST
@given(key=st.sampled_from(["overrides", "run"]), value=st.dictionaries(st.text(max_size=4), hostile, max_size=3))
def test_scene_loader_tables(key, value):
    from transient.study.scene import scene_from_dict

    doc = dict(kind="pad_descent", outputs=dict(figures=False), **{key: value})

    def run():
        try:
            return scene_from_dict(doc)
        except ValueError as e:  # an unknown key names itself; a known one names itself too
            assert any(k in str(e) for k in value) or key in str(e), str(e)
            COUNTS["named error"] += 1
            return "named"

    r = run()
    if r != "named":
        COUNTS["finite result"] += 1


@FAST
@given(text=st.one_of(st.text(max_size=20), st.from_regex(r"-?[0-9.e]{1,6}:-?[0-9.e]{1,6}(:[0-9-]{1,6})?", fullmatch=True),
                      st.from_regex(r"\[[0-9., -]{0,10}\](;\[[0-9., -]{0,10}\])?", fullmatch=True)))
def test_sweep_param_parser(text):
    from transient.study.sweep import MAX_POINTS, parse_params

    def check(values):
        v = values["load"]
        assert 1 <= len(v) <= MAX_POINTS
        _finite(*[x for item in v for x in (item if isinstance(item, list) else [item])])

    _outcome("param", lambda: parse_params([f"load={text}"]), check)


_SAVED = {}


def _saved_result(tmp):
    if "bytes" not in _SAVED:
        r = ThrustPad(**PAD).descent(load=600.0, h0_start=1e-5, t_end=0.02, n_out=4)
        path = r.save(os.path.join(tmp, "r.npz"))
        _SAVED["bytes"] = path.read_bytes()
    return _SAVED["bytes"]


@FAST
@given(how=st.sampled_from(["flip", "truncate", "meta"]), where=st.floats(0, 1), value=hostile,
       field=st.sampled_from(["format", "class", "fields", "t", "h0", "success", "version", "units"]))
def test_load_result(tmp_path_factory, how, where, value, field):
    import json
    import zipfile

    from transient import load_result
    from transient.results import ResultFileError

    tmp = tmp_path_factory.mktemp("fuzz")
    data = bytearray(_saved_result(str(tmp)))
    path = tmp / "f.npz"
    if how == "flip":
        i = int(where * (len(data) - 1))
        data[i] ^= 0xFF
        path.write_bytes(bytes(data))
    elif how == "truncate":
        path.write_bytes(bytes(data[: int(where * len(data))]))
    else:
        src = tmp / "src.npz"
        src.write_bytes(bytes(data))
        with np.load(src) as z:
            arrays = {k: z[k] for k in z.files}
        meta = json.loads(str(arrays["__meta__"]))
        if field in meta:
            meta[field] = value
        else:
            meta["fields"][field] = value
        arrays["__meta__"] = np.array(json.dumps(meta))
        np.savez(path, **arrays)
    try:
        r = load_result(path)
    except ResultFileError as e:
        assert str(path) in str(e) and "\n" not in str(e).strip(), str(e)
        COUNTS["named error"] += 1
        return
    except zipfile.BadZipFile as e:  # pragma: no cover - must not happen
        raise AssertionError(f"unnamed: {e!r}")
    COUNTS["finite result"] += 1
    assert r.ok in (True, False)


@pytest.fixture(scope="module", autouse=True)
def report_counts():
    """After this module's tests (on this worker; ``-s`` shows it): the counts quoted in docs/validation.md (a failure
    above is a test failure, so no failures means 100 % named errors or finite results)."""
    yield
    total = sum(COUNTS.values())
    print(f"\nfuzzed inputs: {total}, named errors {COUNTS['named error']}, finite results {COUNTS['finite result']}, "
          f"named non-convergence {COUNTS['named non-convergence']}")
