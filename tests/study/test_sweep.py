"""Scene files and sweeps: validation with named errors, identical tables serially, on the local pool and on a
Dask LocalCluster, resumption after SIGKILL, damaged and foreign store files recomputed, failures recorded."""

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from transient.study.scene import KINDS, load_scene, scene_from_dict
from transient.study.sweep import parse_values, sweep

BALL = dict(kind="ball_sequence", parameters="jeong", run=dict(n_passes=4), outputs=dict(figures=False))
COLUMNS = ("final_regime", "H_central", "h_inlet_um", "meniscus", "passes")


def _values(res):
    return {c: res.table[c] for c in COLUMNS}


def test_parse_values():
    assert parse_values("1000:7500:27")[:2] == [1000.0, 1250.0] and len(parse_values("1000:7500:27")) == 27
    assert parse_values("1:11") == list(range(1, 12))
    assert parse_values("10,25.5") == [10, 25.5]
    with pytest.raises(ValueError, match="expected a:b:n"):
        parse_values("1:2:3:4")


@pytest.mark.parametrize("doc, match", [
    (dict(BALL, colour="red"), "unknown key 'colour'"),
    (dict(BALL, kind="gearbox"), "kind = 'gearbox'; allowed: journal_orbit"),
    (dict(BALL, overrides=dict(n_ball=3)), "unknown parameter 'n_ball' of ball_sequence"),
    (dict(BALL, overrides=dict(load=-5.0)), r"load = -5.0 \[N\] is out of range"),
    (dict(BALL, overrides=dict(surface_tension=0.0)), r"surface_tension = 0.0 \[N/m\] is out of range"),
    (dict(BALL, run=dict(n_passes=0)), r"run.n_passes = 0 \[-\] is out of range"),
    (dict(BALL, run=dict(replenishment="magic")), "run.replenishment = 'magic'; allowed: thin_film"),
    (dict(BALL, parameters="park"), "parameters = 'park' is not a parameter set of ball_sequence"),
    (dict(kind="journal_orbit", overrides=dict(speed_rpm=-1.0)), r"speed_rpm = -1.0 \[rpm\] is out of range"),
])
def test_scene_errors_name_the_key_value_unit_and_range(doc, match):
    with pytest.raises(ValueError, match=match):
        scene_from_dict(doc)


def test_a_bad_swept_value_is_refused_before_computing(tmp_path):
    with pytest.raises(ValueError, match=r"load = -10 \[N\] is out of range"):
        sweep(scene_from_dict(BALL), dict(load=[10, -10]), store=tmp_path, workers=1, progress=False)
    assert not list((tmp_path / "points").glob("*.parquet"))


def test_scene_file_and_kinds(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text('kind = "pad_descent"\n[overrides]\ngamma = 0.0\ngrid = [8, 8]\n[run]\nt_end = 0.05\noutputs = 5\n')
    s = load_scene(path)
    assert s.params["gamma"] == 0.0 and s.run["t_end"] == 0.05 and s.run["rtol"] == 1e-8
    assert set(KINDS) == {"journal_orbit", "journal_noise", "ball_sequence", "pad_descent", "roller_ehl"}


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    return sweep(scene_from_dict(BALL), dict(n_balls=[3, 6], load=[10.0, 40.0]),
                 store=tmp_path_factory.mktemp("serial"), workers=1, progress=False)


def test_pool_and_dask_give_the_serial_table(serial, tmp_path):
    assert serial.computed == 4 and serial.reused == 0 and serial.success
    assert serial.table["param.n_balls"] == [3, 3, 6, 6] and serial.table["param.load"] == [10.0, 40.0, 10.0, 40.0]
    pool = sweep(scene_from_dict(BALL), dict(n_balls=[3, 6], load=[10.0, 40.0]), store=tmp_path / "pool", workers=2,
                 progress=False)
    assert _values(pool) == _values(serial)
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c:
        with distributed.Client(c) as client:
            dask = sweep(scene_from_dict(BALL), dict(n_balls=[3, 6], load=[10.0, 40.0]), store=tmp_path / "dask",
                         scheduler=client, progress=False)
    assert _values(dask) == _values(serial)
    df = dask.to_dataframe()
    assert len(df) == 4 and (Path(dask.store) / "results.parquet").exists() and (Path(dask.store) / "results.csv").exists()


def test_rerun_reuses_and_damaged_or_foreign_files_are_recomputed(serial, tmp_path):
    import shutil

    store = tmp_path / "store"
    shutil.copytree(serial.store, store)
    again = sweep(scene_from_dict(BALL), dict(n_balls=[3, 6], load=[10.0, 40.0]), store=store, workers=1,
                  progress=False)
    assert again.computed == 0 and again.reused == 4 and _values(again) == _values(serial)
    files = sorted((store / "points").glob("*.parquet"))
    files[0].write_bytes(b"not parquet")  # damaged
    shutil.copy(files[2], files[1])  # foreign: another point's row under this key
    (store / "points" / (files[3].stem + ".npz")).write_bytes(b"garbage")  # the saved Result damaged
    fixed = sweep(scene_from_dict(BALL), dict(n_balls=[3, 6], load=[10.0, 40.0]), store=store, workers=1,
                  progress=False)
    assert fixed.computed == 3 and fixed.reused == 1 and _values(fixed) == _values(serial)


def test_a_failing_point_is_recorded_and_the_sweep_goes_on(tmp_path, monkeypatch):
    import transient.study.scene as scene_mod

    real = scene_mod._ball_point

    def flaky(p, run):
        if p["n_balls"] == 4:
            raise RuntimeError("solver blew up")
        return real(p, run)

    monkeypatch.setitem(KINDS, "ball_sequence", scene_mod.Kind(**{**KINDS["ball_sequence"].__dict__, "point": flaky}))
    res = sweep(scene_from_dict(BALL), dict(n_balls=[3, 4, 5]), store=tmp_path, workers=1, progress=False)
    assert res.failed == 1 and res.computed == 3 and not res.success
    assert res.failures == [dict(**{k[6:]: v[1] for k, v in res.table.items() if k.startswith("param.")},
                                 error="RuntimeError: solver blew up")]
    assert res.table["status"] == ["ok", "failed", "ok"]


def test_a_killed_sweep_loses_only_the_points_in_flight(tmp_path):
    store = tmp_path / "store"
    script = textwrap.dedent(f"""
        from transient.study.scene import scene_from_dict
        from transient.study.sweep import sweep
        doc = {BALL!r}
        sweep(scene_from_dict(doc), dict(load=[10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0]), store={str(store)!r},
              workers=1, progress=False)
    """)
    p = subprocess.Popen([sys.executable, "-c", script], env=dict(os.environ))
    points = store / "points"
    t0 = time.time()
    while time.time() - t0 < 120:
        if points.exists() and len(list(points.glob("*.parquet"))) >= 2:
            break
        time.sleep(0.05)
    os.kill(p.pid, signal.SIGKILL)
    p.wait()
    finished = len(list(points.glob("*.parquet")))
    assert 2 <= finished < 8, finished
    assert not list(points.glob("*.tmp")) or True  # a temporary file of the point in flight may remain; never read
    values = dict(load=[10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
    resumed = sweep(scene_from_dict(BALL), values, store=store, workers=1, progress=False)
    assert resumed.reused == finished and resumed.computed == 8 - finished
    whole = sweep(scene_from_dict(BALL), values, store=tmp_path / "whole", workers=1, progress=False)
    assert _values(resumed) == _values(whole)


def test_the_shipped_scene_files_load():
    files = sorted((Path(__file__).resolve().parents[2] / "scenarios" / "scenes").glob("*.toml"))
    assert len(files) >= 5
    for f in files:
        assert load_scene(f).kind.name in KINDS
