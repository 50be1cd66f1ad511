"""The long-run driver: resume equals an uninterrupted run, checkpoints keyed on every setting, locks, damaged
files, Ctrl-C that says where the checkpoint is; and the journal orbit's use of it."""

import multiprocessing as mp
import os

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Problem, Recording
from transient.params import rho_kim
from transient.solvers.longrun import CheckpointError, Interrupted, run_long


class Recorder:
    def __init__(self):
        self.t, self.y = [], []

    def observe(self, t, y):
        if not self.t or t > self.t[-1]:
            self.t.append(t)
            self.y.append(y.copy())

    def arrays(self):
        return dict(t=np.array(self.t), y=np.array(self.y))

    def restore(self, a):
        self.t, self.y = list(a["t"]), list(a["y"])


def oscillator(y, t0, stop_after=None, calls=None):
    calls = [0] if calls is None else calls

    def rhs(t, y, out):
        calls[0] += 1
        if stop_after is not None and calls[0] > stop_after:
            raise KeyboardInterrupt
        out[0] = y[1]
        out[1] = -y[0] - 0.1 * y[1] + np.cos(t)

    return Problem(y0=y, rhs=rhs)


def drive(path=None, resume=False, n=40, key=None, chunk=10, stop_after=None, method="bdf"):
    rec = Recorder()
    calls = [0]  # right-hand-side calls over the whole run (all chunks)
    out = run_long(lambda y, t: oscillator(y, t, stop_after, calls), np.array([1.0, 0.0]), 0.0, 0.25, n, rec,
                   solver=dict(method=method, rtol=1e-9, atol=1e-12), chunk_outputs=chunk,
                   long_run=LongRun(checkpoint=path, resume=resume, progress=False), key=key or dict(damping=0.1))
    return rec, out


def test_resume_after_interruption_equals_an_uninterrupted_run(tmp_path):
    full, _ = drive()
    path = tmp_path / "ck.npz"
    drive(path, n=20)  # "crashes" after two chunks
    resumed, out = drive(path, resume=True)
    assert out.resumed_from == 20
    np.testing.assert_array_equal(np.array(resumed.t), np.array(full.t))
    np.testing.assert_array_equal(np.array(resumed.y), np.array(full.y))


def test_changed_setting_is_named(tmp_path):
    path = tmp_path / "ck.npz"
    drive(path, n=20)
    with pytest.raises(CheckpointError, match=r"damping = 0\.1, this run has damping = 0\.2"):
        drive(path, resume=True, key=dict(damping=0.2))
    with pytest.raises(CheckpointError, match="already holds 20 output intervals, more than the 10"):
        drive(path, resume=True, n=10)


def test_damaged_checkpoint_names_the_file_and_how_to_start_afresh(tmp_path):
    path = tmp_path / "ck.npz"
    drive(path, n=20)
    path.write_bytes(path.read_bytes()[:100])
    with pytest.raises(CheckpointError, match=r"ck\.npz cannot be read .*resume=False to start afresh"):
        drive(path, resume=True)


def test_bad_checkpoint_folder_is_refused_before_computing(tmp_path):
    with pytest.raises(ValueError, match="does not exist"):
        drive(tmp_path / "nowhere" / "ck.npz")


def _hold_lock(path, ready, release):
    from transient.solvers.longrun import _Checkpoint

    c = _Checkpoint(path, {}, "holder")
    c.acquire()
    ready.set()
    release.wait(10)
    c.release()


def test_a_checkpoint_in_use_is_refused_with_the_process(tmp_path):
    path = tmp_path / "ck.npz"
    ctx = mp.get_context("fork")
    ready, release = ctx.Event(), ctx.Event()
    p = ctx.Process(target=_hold_lock, args=(path, ready, release))
    p.start()
    try:
        assert ready.wait(10)
        with pytest.raises(CheckpointError, match=f"in use by process {p.pid}"):
            drive(path)
    finally:
        release.set()
        p.join(10)
    drive(path)  # free again


def test_ctrl_c_says_where_the_checkpoint_is(tmp_path):
    path = tmp_path / "ck.npz"
    with pytest.raises(Interrupted, match=r"checkpoint .*ck\.npz holds [1-9][0-9.]* s: run again with resume=True"):
        drive(path, stop_after=400, chunk=4)  # 4 outputs of 0.25 s per chunk; interrupted after a few chunks
    rec, out = drive(path, resume=True, chunk=4)
    assert out.resumed_from > 0 and len(rec.t) == 41
    with pytest.raises(Interrupted, match="no checkpoint was written"):
        drive(None, stop_after=50)


def test_orbit_checkpoint_names_a_changed_run_setting(tmp_path):
    o = JournalOrbit(JournalBearing(**rho_kim.BEARING, grid=(16, 2)), speed_rpm=6000, **rho_kim.ROTOR)
    path = tmp_path / "orbit.npz"
    o.run(1.0, recording=Recording(outputs_per_revolution=8), long_run=LongRun(chunk_revolutions=0.5, checkpoint=path))
    lr = LongRun(chunk_revolutions=0.5, checkpoint=path, resume=True)
    for change, name in ((dict(integration=Integration(method="bdf2", rtol=1e-7)), "rtol"),
                         (dict(recording=Recording(outputs_per_revolution=4)), "outputs_per_revolution"),
                         (dict(recording=Recording(outputs_per_revolution=8, record=("force",))), "record"),
                         (dict(touch_gap=1e-2), "touch_gap")):
        kw = dict(dict(recording=Recording(outputs_per_revolution=8), long_run=lr), **change)
        with pytest.raises(CheckpointError, match=f"written with {name} = "):
            o.run(1.0, **kw)
    other = JournalOrbit(o.bearing, speed_rpm=6000, **dict(rho_kim.ROTOR, unbalance=1e-6))
    with pytest.raises(CheckpointError, match="unbalance"):
        other.run(1.0, recording=Recording(outputs_per_revolution=8),
                  long_run=LongRun(chunk_revolutions=0.5, checkpoint=path, resume=True))
    assert not any(f.name.endswith(".tmp") for f in tmp_path.iterdir())
    assert not os.path.exists(str(path) + ".lock")  # a finished run removes its lock file


# checkpoint files read safely -------------------------------------------------------------------------------------

def _rewrite(path, change):
    """Rewrite a checkpoint with ``change(arrays, meta)`` applied and its digest and declarations recomputed
    (a consistently crafted file: only the content checks can refuse it)."""
    import json

    from transient.results import _content_digest

    with np.load(path, allow_pickle=False) as z:
        data = {k: z[k] for k in z.files}
    meta = json.loads(str(data.pop("__meta__")))
    keep_digest = change(data, meta)
    if not keep_digest:
        meta["digest"] = _content_digest(data)
    meta["arrays"] = {k: [v.dtype.str, list(v.shape)] for k, v in data.items()}
    data["__meta__"] = np.array(json.dumps(meta))
    np.savez(path, **data)


def test_a_fifo_checkpoint_is_refused_without_blocking(tmp_path):
    import threading

    path = tmp_path / "ck.npz"
    os.mkfifo(path)
    out = {}

    def target():
        try:
            drive(path, resume=True)
        except BaseException as e:  # noqa: BLE001 - handed to the test
            out["error"] = e

    th = threading.Thread(target=target, daemon=True)
    th.start()
    th.join(5)
    blocked = th.is_alive()
    if blocked:  # release the reader: open and close the writing end
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
        th.join(5)
    assert not blocked, "resuming waited on a FIFO"
    assert isinstance(out.get("error"), CheckpointError), out
    assert f"checkpoint {path} is a FIFO (named pipe), not a regular file" in str(out["error"])


@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_a_non_finite_recorded_series_is_refused_on_resume(tmp_path, value):
    path = tmp_path / "ck.npz"
    drive(path, n=20)
    _rewrite(path, lambda d, m: d["rec.y"].__setitem__((3, 1), value))
    with pytest.raises(CheckpointError, match=rf"checkpoint {path} holds {value} in its recorded series 'y' at "
                                              r"index \[3, 1\] .*resume=False to start afresh"):
        drive(path, resume=True)


def test_a_state_of_another_size_is_refused_before_the_arrays_are_read(tmp_path, monkeypatch):
    from transient.results import NpzReader

    path = tmp_path / "ck.npz"
    drive(path, n=20)
    _rewrite(path, lambda d, m: d.update(state=np.zeros(3)))
    read = NpzReader.read

    def only_the_metadata(self, name):
        if name != "__meta__":
            pytest.fail(f"array {name!r} read before the state's declaration was checked")
        return read(self, name)

    monkeypatch.setattr(NpzReader, "read", only_the_metadata)
    with pytest.raises(CheckpointError, match=r"holds a state of <f8 \[3\], this run has \[2\] states"):
        drive(path, resume=True)


def test_the_digest_of_a_large_checkpoint_is_streamed(tmp_path):
    """A checkpoint whose recorder holds 80 MB and whose digest does not match is refused having read the
    80 MB once: the digest is computed over the arrays in place, without a copy of each."""
    import tracemalloc

    path = tmp_path / "ck.npz"
    drive(path, n=20)
    big = 10_000_000
    _rewrite(path, lambda d, m: d.update({"rec.big": np.ones(big)}) or True)  # declared, digest left as it was
    tracemalloc.start()
    try:
        with pytest.raises(CheckpointError, match="does not match its digest"):
            drive(path, resume=True)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1.4 * 8 * big, f"refusing took {peak / 1e6:.0f} MB for {8 * big / 1e6:.0f} MB of arrays"
