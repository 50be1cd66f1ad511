"""Reliability: no silent wrong state, no unbounded memory, no orphaned workers, every file and OS fault named.

Each test reproduces one failure found by attacking the package (resumed finished checkpoints, crafted
checkpoints and result files, huge runs, kill -9 of a sweep, full and read-only disks, bad scene files) and
checks that it is now refused or handled by name. The full-disk and read-only cases use a file-system shim
(the OS call raises ENOSPC / EROFS), since mounting a small tmpfs needs privileges a test cannot assume.
"""

import errno
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
import tracemalloc
import zipfile
from pathlib import Path

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Recording, load_result
from transient.checks import MemoryLimitError
from transient.params import rho_kim
from transient.results import ResultFileError, atomic_savez
from transient.solvers.longrun import CheckpointError, CheckpointWriteError

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def orbit():
    return JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000, **rho_kim.ROTOR)


def _run(o, path, revs=1.0, **kw):
    return o.run(revs, recording=Recording(outputs_per_revolution=8),
                 long_run=LongRun(chunk_revolutions=0.25, checkpoint=path, resume=True, progress=False), **kw)


# 1. a finished checkpoint resumed -------------------------------------------------------------------------------

def test_resuming_a_finished_checkpoint_returns_the_final_state(orbit, tmp_path):
    path = tmp_path / "c.npz"
    first = _run(orbit, path)
    again = _run(orbit, path)  # nothing left to run: the checkpoint's state is the final one
    assert again.final_time == first.final_time
    np.testing.assert_array_equal(again.final_state, first.final_state)
    assert np.hypot(*again.final_state[-2:]) > 0  # the rotor moves (the start state has zero velocity)
    onward = orbit.run(0.5, recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False),
                       start=again)
    whole = orbit.run(1.5, recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False))
    np.testing.assert_allclose(onward.x[-1], whole.x[-1], rtol=1e-3)


# 2. checkpoint contents checked against each other and the code -------------------------------------------------

def _rewrite(path, change):
    with np.load(path, allow_pickle=False) as z:
        data = {k: z[k] for k in z.files}
    meta = json.loads(str(data["__meta__"]))
    change(data, meta)
    data["__meta__"] = np.array(json.dumps(meta))
    np.savez(path, **data)


@pytest.mark.parametrize("name, change", [
    ("t shorter than x", lambda d, m: d.update({"rec.t": d["rec.t"][:3]})),
    ("outputs_done smaller", lambda d, m: m.update(outputs_done=m["outputs_done"] - 2)),
    ("corrupted last time", lambda d, m: d["rec.t"].__setitem__(-1, d["rec.t"][-1] * 1.5)),
    ("state reversed", lambda d, m: d.update(state=d["state"][::-1].copy())),
    ("missing array", lambda d, m: d.pop("rec.x")),
    ("other code version", lambda d, m: m.update(code_version="0.0.1+000000000000")),
    ("non-finite state", lambda d, m: d["state"].__setitem__(0, np.nan)),
])
def test_a_crafted_checkpoint_is_refused_by_name(orbit, tmp_path, name, change):
    path = tmp_path / "c.npz"
    _run(orbit, path, revs=0.5)
    _rewrite(path, change)
    with pytest.raises(CheckpointError, match=f"checkpoint {path}"):
        _run(orbit, path)


def test_consistent_crafted_metadata_is_still_checked(orbit, tmp_path):
    """Even with the digest recomputed, the recorder's rows and the output count must agree."""
    from transient.results import _content_digest

    path = tmp_path / "c.npz"
    _run(orbit, path, revs=0.5)

    def shorten(d, m):
        d["rec.t"], d["rec.x"], d["rec.y"] = d["rec.t"][:3], d["rec.x"][:3], d["rec.y"][:3]
        d["rec.last_tau"] = np.array(d["rec.t"][-1] * orbit.film.omega)
        arrays = {k: v for k, v in d.items() if k != "__meta__"}
        m["digest"] = _content_digest(arrays)
        m["arrays"] = {k: [v.dtype.str, list(v.shape)] for k, v in arrays.items()}

    _rewrite(path, shorten)
    with pytest.raises(CheckpointError, match="recorded outputs"):
        _run(orbit, path)


# 3. memory estimated before a run --------------------------------------------------------------------------------

def test_a_run_too_large_for_the_machine_is_refused_before_allocating(orbit, monkeypatch):
    with pytest.raises(MemoryLimitError, match="revolutions or outputs_per_revolution"):
        orbit.run(1e12, long_run=LongRun(progress=False))
    with pytest.raises(MemoryLimitError, match="record fewer series"):
        orbit.run(2000, recording=Recording(outputs_per_revolution=100000), long_run=LongRun(progress=False))
    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", str(2e8))  # plan for a 200 MB machine
    with pytest.raises(MemoryLimitError, match="of this machine's 0.2 GB"):
        orbit.run(2000, recording=Recording(outputs_per_revolution=1000, record=("pressure",)),
                  long_run=LongRun(progress=False))


def test_pad_ball_roller_and_scene_memory_checks(monkeypatch):
    from transient import RollerContact, TaperedRoller, ThrustPad
    from transient.models.ball import ThrustBallBearing
    from transient.params import jeong, park
    from transient.study.scene import scene_from_dict

    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", str(1e8))  # plan for a 100 MB machine
    with pytest.raises(MemoryLimitError, match="lower n_out"):
        ThrustPad(0.02, 0.02, 0.03, surface=2e-6, grid=(6, 6)).descent(load=600.0, h0_start=1e-5, t_end=0.02, n_out=10**6)
    b = ThrustBallBearing(**jeong.BEARING)
    with pytest.raises(MemoryLimitError, match="lower n_passes"):
        b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=10**7)
    c = RollerContact.from_dimensionless(**park.DIMENSIONLESS, roller=TaperedRoller(**park.ROLLER), grid="paper")
    with pytest.raises(MemoryLimitError, match="coarser clustered grid"):
        c.transient(1e-4, n_out=11)
    for doc in (dict(kind="journal_orbit", overrides=dict(grid=[2000, 2000])),
                dict(kind="pad_descent", overrides=dict(grid=[2000, 2000]), run=dict(outputs=10**6))):
        with pytest.raises(MemoryLimitError, match="coarser grid"):
            scene_from_dict(doc)


# 4. size cap and declared shapes when loading -------------------------------------------------------------------

def test_an_undeclared_huge_array_is_not_read(orbit, tmp_path):
    r = orbit.run(0.25, recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False))
    path = r.save(tmp_path / "r.npz")
    with zipfile.ZipFile(path, "a", compression=zipfile.ZIP_DEFLATED) as zf:
        with zf.open("bomb.npy", "w", force_zip64=True) as fh:
            np.lib.format.write_array(fh, np.zeros(50_000_000))  # 400 MB expanded, ~400 kB on disk
    assert path.stat().st_size < 5e6
    tracemalloc.start()
    try:
        q = load_result(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 50e6, f"loading read {peak / 1e6:.0f} MB"
    np.testing.assert_array_equal(q.x, r.x)


def test_declared_shapes_and_the_cap_are_checked_before_reading(orbit, tmp_path):
    r = orbit.run(0.25, recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False))
    path = r.save(tmp_path / "r.npz")
    with pytest.raises(ResultFileError, match=f"{path}.*cap of"):
        load_result(path, max_bytes=100)
    with np.load(path) as z:
        data = {k: z[k] for k in z.files}
    data["x"] = np.zeros(10**6)  # swapped for a larger array than its metadata declares
    np.savez(path, **data)
    with pytest.raises(ResultFileError, match=f"{path}.*array 'x' is <f8 \\[1000000\\] but declared <f8 \\[3\\]"):
        load_result(path)


def test_a_checkpoint_with_an_undeclared_array_is_refused(orbit, tmp_path):
    path = tmp_path / "c.npz"
    _run(orbit, path, revs=0.5)
    _rewrite(path, lambda d, m: d.update(extra=np.zeros(1000)))
    with pytest.raises(CheckpointError, match="'extra' is not declared"):
        _run(orbit, path)


# 5. pool workers exit when the sweep's process dies ---------------------------------------------------------------

def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:  # a zombie is dead
        return Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0] != "Z"
    except OSError:
        return True


def test_pool_workers_exit_after_kill_9_of_the_parent(tmp_path):
    script = tmp_path / "parent.py"
    script.write_text(textwrap.dedent("""
        import time
        from transient.study.sweep import _pool
        if __name__ == "__main__":
            pool = _pool(2)
            print(" ".join(str(p.pid) for p in pool._processes.values()), flush=True)
            time.sleep(600)
    """))
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    parent = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=env)
    try:
        workers = [int(p) for p in parent.stdout.readline().split()]
        assert len(workers) == 2 and all(_alive(p) for p in workers)
        parent.send_signal(signal.SIGKILL)
        parent.wait(10)
        deadline = time.monotonic() + 15
        while time.monotonic() < deadline and any(_alive(p) for p in workers):
            time.sleep(0.2)
        left = [p for p in workers if _alive(p)]
        assert not left, f"workers {left} outlived their parent"
    finally:
        if parent.poll() is None:
            parent.kill()
        for p in workers if "workers" in dir() else []:
            if _alive(p):
                os.kill(p, signal.SIGKILL)


# 6. OS faults as one line naming the path ------------------------------------------------------------------------

def _cli(args, capsys):
    from transient.cli import main

    rc = main(args)
    err = capsys.readouterr().err.strip()
    return rc, err


SCENE = 'kind = "ball_sequence"\nparameters = "jeong"\n[run]\nn_passes = 2\n[outputs]\nfigures = false\n'


def test_out_or_store_that_is_a_file_is_one_line(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE)
    blocker = tmp_path / "afile"
    blocker.write_text("x")
    rc, err = _cli(["run", str(scene), "--out", str(blocker)], capsys)
    assert rc == 2 and err.count("\n") == 0 and str(blocker) in err and "choose" in err, err
    rc, err = _cli(["sweep", str(scene), "--param", "load=20,30", "--store", str(blocker), "--workers", "1"], capsys)
    assert rc == 2 and err.count("\n") == 0 and str(blocker) in err and "choose" in err, err


def _fault(monkeypatch, code, where):
    """Make every ``os.replace`` / ``mkdir`` into ``where`` fail with ``code`` (the shim of a full or read-only
    file system)."""
    real_replace, real_mkdir, real_mkstemp = os.replace, Path.mkdir, __import__("tempfile").mkstemp

    def replace(src, dst, *a, **k):
        if str(dst).startswith(str(where)):
            raise OSError(code, os.strerror(code))
        return real_replace(src, dst, *a, **k)

    def mkdir(self, *a, **k):
        if str(self).startswith(str(where)) and not self.exists():
            raise OSError(code, os.strerror(code), str(self))
        return real_mkdir(self, *a, **k)

    def mkstemp(*a, dir=None, **k):
        if dir is not None and str(dir).startswith(str(where)):
            raise OSError(code, os.strerror(code), str(dir))
        return real_mkstemp(*a, dir=dir, **k)

    monkeypatch.setattr(os, "replace", replace)
    monkeypatch.setattr(Path, "mkdir", mkdir)
    monkeypatch.setattr("tempfile.mkstemp", mkstemp)


@pytest.mark.parametrize("code, words", [(errno.EROFS, "read-only"), (errno.ENOSPC, "disk is full")])
def test_read_only_or_full_out_and_store_are_one_line(tmp_path, capsys, monkeypatch, code, words):
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE)
    target = tmp_path / "disk"
    target.mkdir()
    _fault(monkeypatch, code, target)
    rc, err = _cli(["run", str(scene), "--out", str(target / "out")], capsys)
    assert rc == 2 and err.count("\n") == 0 and str(target / "out") in err and words in err, err
    rc, err = _cli(["sweep", str(scene), "--param", "load=20,30", "--store", str(target / "st"), "--workers", "1"],
                   capsys)
    assert rc == 2 and err.count("\n") == 0 and str(target / "st") in err and words in err, err


def test_checkpoint_on_a_full_disk_names_it_and_keeps_the_last_one(orbit, tmp_path, monkeypatch):
    path = tmp_path / "c.npz"
    calls = [0]
    real = np.savez

    def savez(fh, **arrays):
        calls[0] += 1
        if calls[0] > 2:  # the third checkpoint finds the disk full
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real(fh, **arrays)

    monkeypatch.setattr(np, "savez", savez)
    with pytest.raises(CheckpointWriteError, match=f"cannot write {path}: No space left.*disk is full.*"
                                                   f"last complete checkpoint {path} holds 0.5 rev"):
        _run(orbit, path)
    monkeypatch.setattr(np, "savez", real)
    assert not [f for f in tmp_path.iterdir() if f.name.endswith(".tmp")]
    resumed = _run(orbit, path)
    whole = orbit.run(1.0, recording=Recording(outputs_per_revolution=8),
                      long_run=LongRun(chunk_revolutions=0.25, progress=False))
    np.testing.assert_array_equal(resumed.x, whole.x)


def test_result_save_on_a_read_only_folder_names_the_file(orbit, tmp_path, monkeypatch):
    r = orbit.run(0.25, recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False))
    _fault(monkeypatch, errno.EROFS, tmp_path)
    with pytest.raises(OSError, match=f"cannot write {tmp_path / 'r.npz'}: .*read-only"):
        r.save(tmp_path / "r.npz")


# 7. scene and sweep validation -----------------------------------------------------------------------------------

BALL = dict(kind="ball_sequence", parameters="jeong", run=dict(n_passes=2), outputs=dict(figures=False))


@pytest.mark.parametrize("doc, match", [
    (dict(BALL, overrides=5), "overrides = 5 must be a table"),
    (dict(BALL, run=5), "run = 5 must be a table"),
    (dict(BALL, outputs="x"), "outputs = 'x' must be a table"),
    (dict(BALL, parameters=dict(load=3)), "parameters = .* must be the name of a parameter set"),
    (dict(kind="journal_orbit", overrides=dict(grid="abc")), "grid = 'abc'"),
    (dict(kind="journal_orbit", overrides=dict(grid=[24.5, 4.2])), r"grid\[0\] = 24.5 \[cells\] is not a whole number"),
    (dict(BALL, overrides=dict(n_balls=True)), "n_balls = True"),
    (dict(kind="journal_orbit", run=dict(revolutions=0.01)), "revolutions = 0.01 .* less than one output interval"),
])
def test_scene_mistakes_are_named(doc, match):
    from transient.study.scene import scene_from_dict

    if isinstance(doc.get("run"), dict) and doc["run"].get("revolutions") == 0.01:  # found when the point runs: the orbit names revolutions
        from transient.study.scene import KINDS

        with pytest.raises(ValueError, match=match):
            KINDS["journal_orbit"].point(scene_from_dict(doc).params, scene_from_dict(doc).run)
        return
    with pytest.raises(ValueError, match=match):
        scene_from_dict(doc)


def test_sweep_param_mistakes_are_named(tmp_path):
    from transient.study.scene import scene_from_dict
    from transient.study.sweep import parse_params, sweep

    with pytest.raises(ValueError, match="--param load is given twice"):
        parse_params(["load=1,2", "load=3"])
    scene = scene_from_dict(dict(kind="journal_orbit"))
    with pytest.raises(ValueError, match=r"grid = 10 \[cells\]; allowed: two whole numbers"):
        sweep(scene, parse_params(["grid=10:12"]), store=tmp_path / "s", workers=1, progress=False)
    assert parse_params(["grid=[40,4];[60,6]"]) == {"grid": [[40, 4], [60, 6]]}
    with pytest.raises(ValueError, match="finite"):
        parse_params(["load=1,nan"])


def test_a_binary_scene_file_is_named(tmp_path):
    from transient.study.scene import load_scene

    path = tmp_path / "bin.toml"
    path.write_bytes(bytes(range(256)))
    with pytest.raises(ValueError, match=f"{path}: not a valid TOML text file"):
        load_scene(path)


# 8. result files validated on load, the file named ---------------------------------------------------------------

def _craft(path, meta, arrays=None):
    np.savez(path, __meta__=np.array(meta if isinstance(meta, str) else json.dumps(meta)), **(arrays or {}))
    return path


GOOD = {"format": "transient-result/1", "class": "OrbitResult", "version": "0.1.0", "units": {}}


@pytest.mark.parametrize("name, meta, arrays", [
    ("meta a list", [1, 2], None),
    ("no fields", GOOD, None),
    ("numeric encoding", dict(GOOD, fields={"t": 5}), None),
    ("required fields missing", dict(GOOD, fields={"t": {"array": "t"}}), {"t": np.zeros(3)}),
    ("deeply nested", '{"format": "transient-result/1", "class": "OrbitResult", "fields": ' + "[" * 100000 + "]" * 100000 + "}",
     None),
    ("string series", dict(GOOD, fields={k: {"array": k} for k in ("t", "x", "y")}),
     {"t": np.zeros(3), "x": np.array(["a", "b", "c"]), "y": np.zeros(3)}),
    ("2-D time", dict(GOOD, fields={k: {"array": k} for k in ("t", "x", "y")}),
     {"t": np.zeros((3, 2)), "x": np.zeros(3), "y": np.zeros(3)}),
])
def test_a_crafted_result_file_is_refused_naming_it(tmp_path, name, meta, arrays):
    path = _craft(tmp_path / "r.npz", meta, arrays)
    with pytest.raises(ResultFileError, match=str(path)):
        load_result(path)


# 9. the smaller ones ---------------------------------------------------------------------------------------------

def test_stale_temporaries_of_killed_writers_are_removed(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = tmp_path / f".x.npz.{dead.pid}.abc123.tmp"
    stale.write_bytes(b"half")
    live = tmp_path / f".x.npz.{os.getppid()}.def456.tmp"  # a live writer's file is left alone
    live.write_bytes(b"busy")
    atomic_savez(tmp_path / "x.npz", dict(a=np.zeros(3)))
    assert not stale.exists() and live.exists()


def test_killed_during_a_write_leaves_no_temporary_after_the_next(tmp_path):
    """A writer killed with -9 in the middle of a large write leaves a .tmp; the next write removes it."""
    code = (f"import numpy as np; from transient.results import atomic_savez; "
            f"atomic_savez({str(tmp_path / 'x.npz')!r}, dict(a=np.random.rand(40_000_000)))")
    p = subprocess.Popen([sys.executable, "-c", code], env=dict(os.environ, PYTHONPATH=str(ROOT)))
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and not list(tmp_path.glob(".x.npz.*.tmp")):
        time.sleep(0.05)
    p.kill()
    p.wait()
    left = list(tmp_path.glob(".x.npz.*.tmp"))
    assert left, "the writer was not caught mid-write"
    atomic_savez(tmp_path / "x.npz", dict(a=np.zeros(3)))
    assert not list(tmp_path.glob(".x.npz.*.tmp"))


def test_time_budget_message_gives_the_time_reached(orbit):
    r = orbit.run(20000, recording=Recording(outputs_per_revolution=8),
                  long_run=LongRun(time_budget=1.5, progress=False), integration=Integration(rtol=1e-8))
    assert not r.success
    reached = float(r.message.split(" stopped at ")[1].split()[0])
    assert reached > 0 and abs(reached - r.t[-1] * 100) < 0.2 + 1 / 8, r.message


@pytest.mark.parametrize("call, name", [
    (lambda o: o.run(0.5, recording=Recording(record=1.0), long_run=LongRun(progress=False)), "record"),
    (lambda o: o.run(0.5, recording=Recording(record_from_revolution=None), long_run=LongRun(progress=False)), "record_from_revolution"),
    (lambda o: o.run(1e12, long_run=LongRun(progress=False)), "revolutions"),
])
def test_unnamed_run_errors_are_named(orbit, call, name):
    with pytest.raises(ValueError, match=name):
        call(orbit)


def test_unnamed_model_errors_are_named():
    from transient import RollerContact, TaperedRoller
    from transient.models.ball import ThrustBallBearing
    from transient.params import jeong, park

    with pytest.raises(ValueError, match="grid = 1.0"):
        RollerContact.from_dimensionless(**park.DIMENSIONLESS, roller=TaperedRoller(**park.ROLLER), grid=1.0)
    with pytest.raises(ValueError, match="youngs_modulus = 2.2e-171"):
        ThrustBallBearing(**dict(jeong.BEARING, youngs_modulus=2.2e-171))
    with pytest.raises(ValueError, match="dub_off_radius = 2.9e-283"):
        TaperedRoller(**dict(park.ROLLER, dub_off_radius=2.9e-283))


@pytest.mark.parametrize("args, name", [
    ((float("nan"), -1e9, 1.0, 0.0), "h = nan"), ((None, -1e9, 1.0, 0.0), "h = None"),
    ((20e-6, 1e300, 1.0, 0.0), "pressure gradient G = 1e[+]300"), ((20e-6, float("inf"), 1.0, 0.0), "G = inf"),
    ((20e-6, -1e9, 1e300, 0.0), "U1 = 1e[+]300"), ((20e-6, -1e9, 1.0, None), "U2 = None"),
])
def test_layered_flow_refuses_nan_and_inf_inputs(args, name):
    from transient.physics.layered import BoundaryLayers, Gecim, LayeredFilm

    f = LayeredFilm(0.03, Gecim(1e5, 0.57), BoundaryLayers(1e-6, 0.3, 1e-7))
    with pytest.raises(ValueError, match=name):
        f.flow(*args)


def test_a_finished_run_leaves_no_lock_file(orbit, tmp_path):
    path = tmp_path / "c.npz"
    _run(orbit, path, revs=0.5)
    assert path.exists() and not (tmp_path / "c.npz.lock").exists()


def test_ctrl_c_advice_on_the_command_line_is_the_same_command(tmp_path, capsys, monkeypatch):
    from transient.solvers.longrun import Interrupted

    def interrupted(*a, **k):
        raise Interrupted("orbit interrupted; checkpoint c.npz holds 3 rev: run again with resume=True",
                          "orbit interrupted; checkpoint c.npz holds 3 rev: run the same command again to continue "
                          "(--fresh starts over)")

    monkeypatch.setattr("transient.cli._run_scenario", interrupted)
    rc, err = _cli(["run", "x.py"], capsys)
    assert rc == 130 and "run the same command again" in err and "--fresh" in err and "resume=True" not in err


def test_a_wrong_dask_address_is_one_line_within_the_timeout(tmp_path, monkeypatch):
    pytest.importorskip("distributed")
    from transient.study import sweep as sw
    from transient.study.scene import scene_from_dict

    monkeypatch.setattr(sw, "CONNECT_TIMEOUT", 3.0)
    t0 = time.monotonic()
    with pytest.raises(ConnectionError, match="cannot reach the Dask scheduler at tcp://127.0.0.1:9 within 3 s"):
        sw.sweep(scene_from_dict(BALL), {"load": [20, 30]}, store=tmp_path / "s", scheduler="tcp://127.0.0.1:9",
                 progress=False)
    assert time.monotonic() - t0 < 30


def test_outputs_go_under_one_root_and_quick_runs_into_their_own_folder(tmp_path, monkeypatch):
    from transient.study.scenario import parser

    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("TRANSIENT_OUT", raising=False)
    ap = parser("doc", ROOT / "scenarios" / "out" / "journal")
    assert Path(ap.parse_args([]).out) == Path("transient_out/journal")
    assert Path(ap.parse_args(["--quick"]).out) == Path("transient_out/journal/quick")
    assert ap.parse_args(["--quick", "--out", "x"]).out == "x"
    monkeypatch.setenv("TRANSIENT_OUT", str(tmp_path / "elsewhere"))
    assert Path(ap.parse_args([]).out) == tmp_path / "elsewhere" / "journal"
    ignored = subprocess.run(["git", "check-ignore", "transient_out/x.png", "scenarios/out/x.png", "c.npz.lock",
                              ".x.npz.123.abc.tmp"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    assert len(ignored) == 4, ignored
