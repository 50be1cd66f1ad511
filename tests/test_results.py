"""Every model's result saves and loads (no pickle), reports units, and refuses foreign or crafted files: regular
files only (a device or FIFO refused by what it is, never read or waited on), every array bounded by its declared
size before it is read (a member larger than its header, a deflate bomb below the memory cap), and every loaded
result checked against its class (crafted files with NaN, short or extra-axis arrays, bad node lists or a
relabelled class refused naming the file and the field)."""

import json
import os
import threading
import time
import tracemalloc
import zipfile

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, Problem, Result, ThrustBallBearing, ThrustPad, load_result, solve
from transient.analysis.acoustics import analyse_pressure
from transient.models.journal import OrbitResult
from transient.models.rotor.results import RotorEquilibrium, RotorRunResult
from transient.params import rho_kim
from transient.results import ResultFileError, SteadyResult, Stats, quantity, result_type
from transient.solvers.newton import newton
from transient import Integration, Recording


def _same(a, b, path=""):
    """Deep equality of two loaded values (arrays exactly, floats exactly)."""
    if isinstance(a, Result) or hasattr(a, "__dataclass_fields__"):
        assert type(a) is type(b), path
        for k in a.__dataclass_fields__:
            _same(getattr(a, k), getattr(b, k), f"{path}.{k}")
    elif isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray) and a.dtype == b.dtype and a.shape == b.shape, path
        np.testing.assert_array_equal(a, b, err_msg=path)
    elif isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            _same(a[k], b[k], f"{path}[{k}]")
    elif isinstance(a, (list, tuple)):
        assert type(a) is type(b) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{i}]")
    else:
        assert a == b or (a != a and b != b), (path, a, b)


def _round_trip(r, tmp_path, name):
    p = r.save(tmp_path / name)
    assert p.suffix == ".npz" and p.exists()
    q = load_result(p)
    _same(r, q, name)
    return q


@pytest.fixture(scope="module")
def orbit():
    return JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000, **rho_kim.ROTOR)


def test_orbit_result_with_fields(orbit, tmp_path):
    r = orbit.run(0.5, recording=Recording(outputs_per_revolution=8, record=("force", "pressure", "mass", "outflow")))
    q = _round_trip(r, tmp_path, "orbit")
    assert q.pressure.dtype == np.float32 and q.pressure.shape == (5, 2, 16)
    assert q.units()["x"] == "m" and q.units()["force"] == "N"
    df = q.to_dataframe()
    assert list(df.columns[:3]) == ["t", "x", "y"] and "force_0" in df and len(df) == 5
    assert df.attrs["units"]["force_1"] == "N"
    assert "x=<float64 5> m" in repr(q) and len(repr(q)) < 1500  # short: shapes, not arrays


def test_continuing_from_a_loaded_result_equals_one_run(orbit, tmp_path):
    """A run continued from a saved and reloaded result keeps the unbalance phase: same as one run."""
    whole = orbit.run(1.0, recording=Recording(outputs_per_revolution=8), integration=Integration(rtol=1e-8))
    first = load_result(orbit.run(0.5, recording=Recording(outputs_per_revolution=8),
                                  integration=Integration(rtol=1e-8)).save(tmp_path / "half"))
    second = orbit.run(0.5, recording=Recording(outputs_per_revolution=8), integration=Integration(rtol=1e-8),
                       start=first)
    np.testing.assert_allclose(second.t, whole.t[4:], rtol=1e-12)
    np.testing.assert_allclose(second.x, whole.x[4:], rtol=0, atol=1e-7 * orbit.bearing.clearance)


def test_film_state_and_solution(orbit, tmp_path):
    _round_trip(orbit.bearing.steady_state(0.5, 6000), tmp_path, "film")

    def rhs(t, y, out):
        out[:] = -y

    _round_trip(solve(Problem(y0=np.ones(3), rhs=rhs), np.linspace(0, 1, 4)), tmp_path, "solution")


def test_noise_ball_pad_newton(tmp_path):
    rng = np.random.default_rng(0)
    n = analyse_pressure(rng.random((32, 2, 8)), rng.random(32), rng.random(32), np.arange(32) * 1e-3, 6000.0, 2, 3)
    _round_trip(n, tmp_path, "noise")
    s = ThrustBallBearing().sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=3)
    q = _round_trip(s, tmp_path, "ball")
    assert q.contact.a == s.contact.a and q.flooded.h_c == s.flooded.h_c
    pad = ThrustPad(0.02, 0.02, 0.03, surface=2e-6, grid=(8, 8))
    _round_trip(pad.descent(load=600.0, h0_start=1e-5, t_end=0.05, n_out=5), tmp_path, "pad")
    res = newton(lambda x: x ** 2 - 2.0, lambda x, s: np.diag(2 * x), np.array([1.0]))
    assert abs(_round_trip(res, tmp_path, "newton").x[0] - np.sqrt(2)) < 1e-10  # xtol 1e-10


def test_a_crafted_pickle_does_not_run(tmp_path):
    marker = tmp_path / "pwned"

    class Evil:
        def __reduce__(self):
            return (open, (str(marker), "w"))

    path = tmp_path / "evil.npz"
    np.savez(path, __meta__=np.array([Evil()], dtype=object))
    with pytest.raises(ResultFileError, match="evil.npz"):
        load_result(path)
    assert not marker.exists()


def test_truncated_foreign_and_unknown_files(tmp_path, orbit):
    p = orbit.run(0.25, recording=Recording(outputs_per_revolution=4)).save(tmp_path / "r")
    bad = tmp_path / "truncated.npz"
    bad.write_bytes(p.read_bytes()[: p.stat().st_size // 2])
    with pytest.raises(ResultFileError, match="truncated.npz"):
        load_result(bad)
    np.savez(tmp_path / "foreign.npz", a=np.zeros(3))
    with pytest.raises(ResultFileError, match="not a transient result"):
        load_result(tmp_path / "foreign.npz")
    np.savez(tmp_path / "unknown.npz", __meta__=np.array('{"format": "transient-result/1", "class": "Nope"}'))
    with pytest.raises(ResultFileError, match="unknown result type 'Nope'"):
        load_result(tmp_path / "unknown.npz")


@result_type
class _Field(SteadyResult):
    p: np.ndarray = quantity("Pa")


def _load_in_thread(path, wait=5.0):
    """``load_result(path)`` in a thread: (finished, the exception or result); a reader blocked on a FIFO is
    released by opening and closing its writing end."""
    out = {}

    def target():
        try:
            out["value"] = load_result(path)
        except BaseException as e:  # noqa: BLE001 - handed to the test
            out["value"] = e

    th = threading.Thread(target=target, daemon=True)
    th.start()
    th.join(wait)
    finished = not th.is_alive()
    if not finished and path.is_fifo():
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
        th.join(wait)
    return finished, out.get("value")


# regular files only ---------------------------------------------------------------------------------------------

def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "r.npz"
    os.mkfifo(fifo)
    finished, value = _load_in_thread(fifo)
    assert finished, "load_result waited on a FIFO"
    assert isinstance(value, ResultFileError), value
    assert str(fifo) in str(value) and "FIFO" in str(value) and "\n" not in str(value)


@pytest.mark.parametrize("path, kind", [("/dev/null", "a character device"), ("/dev/zero", "a character device"),
                                        (".", "a folder")])
def test_a_device_or_folder_is_refused_by_what_it_is(path, kind):
    if not os.path.exists(path):
        pytest.skip(f"{path} does not exist here")
    t0 = time.perf_counter()
    with pytest.raises(ResultFileError, match=f"{path}: not a regular file but {kind}"):
        load_result(path)
    assert time.perf_counter() - t0 < 1.0  # refused before reading, not after


# every array bounded by its declared size ------------------------------------------------------------------------

def test_a_member_larger_than_its_header_is_refused(tmp_path):
    path = _Field(p=np.arange(4.0)).save(tmp_path / "r")
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    with zipfile.ZipFile(path, "w") as zf:
        for name, a in arrays.items():
            with zf.open(name + ".npy", "w") as fh:
                np.lib.format.write_array(fh, a)
                if name == "p":
                    fh.write(b"\0" * 1000)  # a thousand bytes its .npy header does not declare
    with pytest.raises(ResultFileError, match=f"{path}.*'p.npy' expands to 1160 bytes, but its .npy header declares"):
        load_result(path)


def test_a_deflate_bomb_below_the_memory_cap_is_refused_before_reading(tmp_path):
    """The arrays are what the metadata declares (100 MB of zeros, under any cap), but the file is 0.1 MB:
    refused by the expansion limit before anything is inflated."""
    path = _Field(p=np.zeros(3)).save(tmp_path / "r")
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    meta = json.loads(str(arrays["__meta__"]))
    arrays["p"] = np.zeros(12_500_000)
    meta["fields"]["p"]["shape"] = [12_500_000]
    arrays["__meta__"] = np.array(json.dumps(meta))
    np.savez_compressed(path, **arrays)
    assert path.stat().st_size < 0.5e6
    tracemalloc.start()
    try:
        with pytest.raises(ResultFileError, match=f"{path}.*expand to 100 MB, [0-9]+ times the 0.[0-9]+ MB on disk"):
            load_result(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 10e6, f"refusing read {peak / 1e6:.0f} MB"


def test_a_compressed_file_of_ordinary_size_still_loads(tmp_path):
    p = np.random.default_rng(1).random((50, 40))
    path = _Field(p=p).save(tmp_path / "r")
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    np.savez_compressed(path, **arrays)
    np.testing.assert_array_equal(load_result(path).p, p)


def test_a_damaged_member_is_refused_by_its_checksum(tmp_path):
    p = np.arange(1000.0)
    path = _Field(p=p).save(tmp_path / "r")
    data = bytearray(path.read_bytes())
    i = data.index(p.tobytes()[8000 - 16:8000])  # inside the last row of p's data
    data[i] ^= 0xFF
    path.write_bytes(bytes(data))
    with pytest.raises(ResultFileError, match=f"{path}.*(CRC|checksum|Bad)"):
        load_result(path)


# every loaded result checked against its class ---------------------------------------------------------------------

def _orbit():
    t = np.linspace(0.0, 0.01, 5)
    return OrbitResult(t=t, x=1e-6 * np.cos(t), y=1e-6 * np.sin(t), speed_rpm=6000.0, clearance=1e-4,
                       force=np.ones((5, 2)), pressure=np.zeros((2, 2, 16), np.float32), pressure_t=t[-2:],
                       stats=Stats(n_steps=7), final_state=np.zeros(10), final_time=0.01)


def _rotor():
    t = np.linspace(0.0, 0.01, 4)
    return RotorRunResult(t=t, displacement=np.zeros((4, 3, 2)), speed_rpm=np.full(4, 3000.0),
                          bearing_force=np.ones((4, 2, 2)), nodes=[0, 1, 2], bearing_nodes=[0, 2],
                          clearance=np.full(2, 1e-4), final_state=np.zeros(6), final_time=0.01)


def _set(name, value):
    """A change of one field: an array (its declaration follows it) or a JSON value."""
    def change(fields, arrays):
        if isinstance(value, np.ndarray):
            arrays[name] = value
            fields[name] = {"array": name, "dtype": value.dtype.str, "shape": list(value.shape)}
        elif value is None:
            fields[name] = {"value": None}
        else:
            fields[name] = {"list": value} if isinstance(value, list) else {"value": value}
    return change


def _nan_at(name, index):
    def change(fields, arrays):
        arrays[name] = arrays[name].copy()
        arrays[name][index] = np.nan
    return change


def _relabel(cls_name):
    return lambda fields, arrays, meta: meta.update({"class": cls_name})


T = np.linspace(0.0, 0.01, 5)
CRAFTED = [  # (name, result, change, the field the refusal names)
    ("NaN time", _orbit, _nan_at("t", 2), "t"),
    ("time going back", _orbit, _set("t", T[::-1].copy()), "t"),
    ("NaN in a series", _orbit, _nan_at("x", 1), "x"),
    ("infinite force", _orbit, lambda f, a: a.__setitem__("force", np.full((5, 2), np.inf)), "force"),
    ("short series", _orbit, _set("x", np.zeros(4)), "x"),
    ("series with an extra axis", _orbit, _set("y", np.zeros((5, 1))), "y"),
    ("force with three columns", _orbit, _set("force", np.zeros((5, 3))), "force"),
    ("pressure without its times", _orbit, _set("pressure_t", None), "pressure"),
    ("pressure rows not its times", _orbit, _set("pressure", np.zeros((3, 2, 16), np.float32)), "pressure"),
    ("two-dimensional final state", _orbit, _set("final_state", np.zeros((2, 5))), "final_state"),
    ("speed as a word", _orbit, _set("speed_rpm", "fast"), "speed_rpm"),
    ("success as a word", _orbit, _set("success", "yes"), "success"),
    ("a field the class does not have", _orbit, _set("bogus", 1.0), "bogus"),
    ("statistics as words", _orbit, lambda f, a: f["stats"]["fields"].update(n_steps={"value": "many"}), "n_steps"),
    ("node labels as words", _rotor, _set("nodes", ["a", "b", "c"]), "nodes"),
    ("a repeated node", _rotor, _set("nodes", [0, 0, 2]), "nodes"),
    ("a bearing node that is no node", _rotor, _set("bearing_nodes", [0, 7]), "bearing_nodes"),
    ("displacement of two nodes of three", _rotor, _set("displacement", np.zeros((4, 2, 2))), "displacement"),
    ("a clearance per node, not per bearing", _rotor, _set("clearance", np.full(3, 1e-4)), "clearance"),
    ("bearing forces of one bearing of two", _rotor, _set("bearing_force", np.zeros((4, 1, 2))), "bearing_force"),
    ("a run relabelled as an equilibrium", _rotor, _relabel("RotorEquilibrium"), "t"),
    ("an orbit relabelled as a rotor run", _orbit, _relabel("RotorRunResult"), "x"),
]


def _craft(path, make, change):
    path = make().save(path)
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    meta = json.loads(str(arrays["__meta__"]))
    if change.__code__.co_argcount == 3:
        change(meta["fields"], arrays, meta)
    else:
        change(meta["fields"], arrays)
    arrays["__meta__"] = np.array(json.dumps(meta))
    np.savez(path, **arrays)
    return path


@pytest.mark.parametrize("name, make, change, field", CRAFTED, ids=[c[0] for c in CRAFTED])
def test_a_crafted_result_is_refused_naming_the_file_and_the_field(tmp_path, name, make, change, field):
    path = _craft(tmp_path / "r.npz", make, change)
    with pytest.raises(ResultFileError) as e:
        load_result(path)
    text = str(e.value)
    assert text.startswith(f"{path}: ") and f"'{field}'" in text and "\n" not in text, text


@pytest.mark.parametrize("make", [_orbit, _rotor])
def test_the_uncrafted_results_load(tmp_path, make):
    r = make()
    q = load_result(r.save(tmp_path / "r"))
    for f in ("t", "final_state"):
        np.testing.assert_array_equal(getattr(q, f), getattr(r, f))
    assert type(q) is type(r) and q.stats == r.stats


def test_an_equilibrium_still_loads_as_itself(tmp_path):
    r = RotorEquilibrium(displacement=np.zeros((3, 2)), bearing_force=np.ones((2, 2)), bearing_load=np.ones(2),
                         eccentricity_ratio=np.full(2, 0.5), attitude_angle_deg=np.full(2, 40.0), nodes=[0, 1, 2],
                         bearing_nodes=[0, 2], speed_rpm=3000.0, state=np.zeros(6))
    q = load_result(r.save(tmp_path / "e"))
    assert q.nodes == [0, 1, 2] and q.position(2)[0] == 0.0


def test_every_declared_shape_and_label_names_a_field_of_its_class():
    import dataclasses

    import transient.models.rotor.results  # noqa: F401 - registers the rotor's results
    from transient.results import _REGISTRY, _merged

    for cls in _REGISTRY.values():
        names = {f.name for f in dataclasses.fields(cls)} if dataclasses.is_dataclass(cls) else set()
        for what in ("shapes", "labels"):
            for name, spec in _merged(cls, what).items():
                assert name in names, f"{cls.__name__}.{what} names {name!r}, not a field"
                axes = spec if isinstance(spec, tuple) else (spec,)
                assert all(a is None or isinstance(a, (int, str)) for a in axes), (cls.__name__, name, spec)
