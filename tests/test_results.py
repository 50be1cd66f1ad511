"""Every model's result saves and loads (no pickle), reports units, and refuses foreign or crafted files."""

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, Problem, Result, ThrustBallBearing, ThrustPad, load_result, solve
from transient.analysis.acoustics import analyse_pressure
from transient.params import rho_kim
from transient.results import ResultFileError
from transient.solvers.newton import newton


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
    r = orbit.run(0.5, outputs_per_revolution=8, record=("force", "pressure", "mass", "outflow"))
    q = _round_trip(r, tmp_path, "orbit")
    assert q.pressure.dtype == np.float32 and q.pressure.shape == (5, 2, 16)
    assert q.units()["x"] == "m" and q.units()["force"] == "N"
    df = q.to_dataframe()
    assert list(df.columns[:3]) == ["t", "x", "y"] and "force_0" in df and len(df) == 5
    assert df.attrs["units"]["force_1"] == "N"
    assert "x=<float64 5> m" in repr(q) and len(repr(q)) < 1500  # short: shapes, not arrays


def test_continuing_from_a_loaded_result_equals_one_run(orbit, tmp_path):
    """A run continued from a saved and reloaded result keeps the unbalance phase: same as one run."""
    whole = orbit.run(1.0, outputs_per_revolution=8, rtol=1e-8)
    first = load_result(orbit.run(0.5, outputs_per_revolution=8, rtol=1e-8).save(tmp_path / "half"))
    second = orbit.run(0.5, outputs_per_revolution=8, rtol=1e-8, start=first)
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
    p = orbit.run(0.25, outputs_per_revolution=4).save(tmp_path / "r")
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
