"""The long-run driver (used by the journal orbit): chunks, a progress bar, checkpoint/resume, clean Ctrl-C.

:func:`run_long` integrates a model's :class:`~transient.solvers.integrate.Problem` from ``t0`` over
``n_outputs`` output intervals of length ``dt_out`` (model time), in chunks of ``chunk_outputs``
intervals. After every chunk it

* updates a progress bar (tqdm: done / total in the model's display unit, e.g. revolutions, time left),
* rewrites the checkpoint (if asked): the state, its time, the recorder's arrays and the statistics, in
  one ``.npz`` without pickle, keyed on ``key`` -- every parameter and setting that changes the result.
  ``resume=True`` continues from it; a checkpoint written with other parameters is refused with the name
  of the first parameter that differs, a truncated or corrupted one with the file name and how to start
  afresh. An advisory lock (``PATH.lock``) keeps two runs off one checkpoint;
* asks ``stop(recorder)`` whether to end early (e.g. the response has settled).

The model supplies ``problem_at(y, t) -> Problem`` and a recorder with ``observe(t, y)``, ``arrays()``
and ``restore(arrays)``; the recorder keeps only what the user asked for, so memory stays bounded.
Ctrl-C raises :class:`Interrupted`, whose message says where the checkpoint is and how to resume.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from transient.results import atomic_savez
from transient.solvers.integrate import Stats, solve

CHECKPOINT_FORMAT = "transient-checkpoint/1"
MAX_CHUNKS = 1_000_000


class Interrupted(KeyboardInterrupt):
    """Ctrl-C during a long run; the message says where the checkpoint is and how to resume."""


class CheckpointError(ValueError):
    """A checkpoint that cannot be used: other parameters, unreadable, or in use by another process."""


@dataclass
class Outcome:
    """What :func:`run_long` hands back to the model: the last state and its time, the summed statistics,
    the terminal event (time, state) if one stopped the run, why it ended, and the outputs done."""

    y: np.ndarray
    t: float
    stats: Stats
    outputs_done: int
    success: bool = True
    message: str = "reached the final time"
    event: tuple | None = None
    resumed_from: int = 0
    extra: dict = field(default_factory=dict)


def run_long(problem_at: Callable, y0, t0: float, dt_out: float, n_outputs: int, recorder, *, method: str,
             rtol: float = 1e-6, atol=1e-8, dt: float | None = None, max_step: float = 0.0, first_step: float = 0.0,
             linear_solver: str = "auto", options: dict | None = None, chunk_outputs: int | None = None, checkpoint=None, resume: bool = False,
             key: dict | None = None, progress: bool | None = None, unit: tuple[str, float] = ("s", 1.0),
             label: str = "run", status: Callable | None = None, stop: Callable | None = None,
             time_budget: float | None = None) -> Outcome:
    """Integrate ``n_outputs`` output intervals (module docstring).

    ``unit = (name, length)``: the display unit of the progress bar and messages (e.g. ``("rev", 2 pi)``
    for a time in radians of shaft rotation). ``status()`` returns a short string for the bar (e.g. the
    current eccentricity). ``method``, ``rtol``, ``atol``, ``dt``, ``max_step``, ``first_step``,
    ``linear_solver`` and ``options`` are :func:`~transient.solvers.integrate.solve`'s (its defaults); ``rk4``
    needs ``dt``. ``time_budget`` [s of wall time] bounds the whole run (all chunks): past
    it the run ends with ``success=False`` and the outputs so far."""
    n_outputs = int(n_outputs)
    if n_outputs < 1:
        raise ValueError(f"the run must span at least one output interval, got {n_outputs}")
    chunk_outputs = n_outputs if chunk_outputs is None else int(chunk_outputs)
    if chunk_outputs < 1:
        raise ValueError(f"chunk = {chunk_outputs} output intervals; allowed: >= 1 (one output interval)")
    if -(-n_outputs // chunk_outputs) > MAX_CHUNKS:
        raise ValueError(f"{n_outputs} outputs in chunks of {chunk_outputs} make more than {MAX_CHUNKS} chunks; "
                         "use longer chunks")
    uname, ulen = unit
    ckpt = _Checkpoint(checkpoint, key or {}, label) if checkpoint else None
    y = np.array(y0, dtype=float)
    k = 0
    stats = Stats()
    if ckpt is not None:
        ckpt.acquire()
    try:
        if ckpt is not None and resume and ckpt.path.exists():
            y, k, saved_stats = ckpt.load(recorder, n_outputs)
            stats = saved_stats
        resumed_from = k
        n_chunks = -(-(n_outputs - k) // chunk_outputs)
        progress = (n_chunks > 1) if progress is None else bool(progress)
        bar = _bar(progress, n_outputs * dt_out / ulen, k * dt_out / ulen, uname, label)
        wall0 = time.perf_counter()
        deadline = math.inf if time_budget is None else wall0 + float(time_budget)
        out = Outcome(y=y, t=t0 + k * dt_out, stats=stats, outputs_done=k, resumed_from=resumed_from)
        try:
            while k < n_outputs:
                k_end = min(n_outputs, k + chunk_outputs)
                tau = t0 + dt_out * np.arange(k, k_end + 1)
                remaining = None if time_budget is None else max(deadline - time.perf_counter(), 1e-9)
                res = solve(problem_at(y, tau[0]), tau, method=method, rtol=rtol, atol=atol, dt=dt, max_step=max_step,
                            first_step=first_step, linear_solver=linear_solver, options=options, store=False,
                            observer=_Last(recorder, out), time_budget=remaining)
                _accumulate(stats, res.stats)
                if not res.success:
                    out.success = False
                    out.message = (f"{method} failed after {tau[0] / ulen:.6g} {uname}: {res.message}")
                    break
                y = out.y
                if res.t_events.size:
                    te, ye = float(res.t_events[0]), np.array(res.y_events[0])
                    out.event = (te, ye)
                    recorder.observe(te, ye)
                    y, out.y, out.t = ye, ye, te
                    out.message = f"terminal event at {te / ulen:.6g} {uname}"
                    k = k_end
                    break
                k = k_end
                out.t = tau[-1]
                if ckpt is not None:
                    ckpt.save(y, k, recorder, stats)
                if bar is not None:
                    bar.update(chunk_outputs * dt_out / ulen if k < n_outputs else bar.total - bar.n)
                    if status is not None:
                        bar.set_postfix_str(status(), refresh=False)
                if stop is not None:
                    why = stop(recorder)
                    if why:
                        out.message = why
                        break
        except KeyboardInterrupt:
            where = f"at {out.t / ulen:.6g} {uname}"
            if ckpt is not None and ckpt.saved_outputs is not None:
                raise Interrupted(f"{label} interrupted {where}; checkpoint {ckpt.path} holds "
                                  f"{ckpt.saved_outputs * dt_out / ulen:.6g} {uname}: run again with resume=True "
                                  f"(same parameters) to continue") from None
            raise Interrupted(f"{label} interrupted {where}; no checkpoint was written (pass checkpoint=PATH "
                              "to make a long run resumable)") from None
        finally:
            if bar is not None:
                bar.close()
        stats.wall_time += time.perf_counter() - wall0
        out.stats, out.outputs_done = stats, k
        return out
    finally:
        if ckpt is not None:
            ckpt.release()


class _Last:
    """Observer that hands each output to the recorder and keeps the last state in the outcome."""

    def __init__(self, recorder, out: Outcome):
        self.recorder, self.out = recorder, out

    def __call__(self, t, y):
        self.out.y = np.array(y)
        self.recorder.observe(t, y)


def _bar(enabled, total, initial, unit, label):
    if not enabled:
        return None
    from tqdm.auto import tqdm

    return tqdm(total=total, initial=initial, unit=unit, desc=label, file=sys.stderr, dynamic_ncols=True,
                bar_format="{desc}: {percentage:3.0f}%|{bar}| {n:.4g}/{total:.4g} {unit} [{elapsed}<{remaining}] {postfix}")


def _accumulate(total: Stats, part: Stats):
    total.n_steps += part.n_steps
    total.n_rhs += part.n_rhs
    total.n_jac += part.n_jac
    total.callback_time += part.callback_time


class _Checkpoint:
    """A checkpoint file, its advisory lock and its key."""

    def __init__(self, path, key: dict, label: str):
        self.path = Path(path)
        if self.path.suffix != ".npz":
            raise ValueError(f"checkpoint = {str(path)!r}: the file name must end in .npz")
        folder = self.path.parent if str(self.path.parent) else Path(".")
        if not folder.is_dir():
            raise ValueError(f"checkpoint folder {folder} does not exist")
        if not os.access(folder, os.W_OK):
            raise ValueError(f"checkpoint folder {folder} is not writable")
        self.key = json.loads(json.dumps(key, default=_jsonable))
        self.label = label
        self.lock_fd = None
        self.saved_outputs = None

    def acquire(self):
        import fcntl

        lock = self.path.with_name(self.path.name + ".lock")
        fd = os.open(lock, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            other = os.read(fd, 64).decode(errors="replace").strip() or "?"
            os.close(fd)
            raise CheckpointError(f"checkpoint {self.path} is in use by process {other}; wait for it or use another "
                                  "checkpoint path") from None
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode())
        self.lock_fd = fd

    def release(self):
        if self.lock_fd is not None:
            import fcntl

            fcntl.flock(self.lock_fd, fcntl.LOCK_UN)
            os.close(self.lock_fd)
            self.lock_fd = None

    def save(self, y, k, recorder, stats: Stats):
        arrays = {f"rec.{name}": np.asarray(v) for name, v in recorder.arrays().items()}
        meta = dict(format=CHECKPOINT_FORMAT, key=self.key, outputs_done=int(k),
                    stats=dict(n_steps=stats.n_steps, n_rhs=stats.n_rhs, n_jac=stats.n_jac,
                               callback_time=stats.callback_time, wall_time=stats.wall_time))
        arrays["state"] = np.asarray(y, dtype=float)
        arrays["__meta__"] = np.array(json.dumps(meta))
        atomic_savez(self.path, arrays)
        self.saved_outputs = int(k)

    def load(self, recorder, n_outputs):
        fresh = "delete it or run with resume=False to start afresh"
        try:
            with np.load(self.path, allow_pickle=False) as z:
                data = {name: z[name] for name in z.files}
            meta = json.loads(str(data.pop("__meta__")))
            y = data.pop("state")
        except Exception as e:
            raise CheckpointError(f"checkpoint {self.path} cannot be read ({type(e).__name__}: {e}); {fresh}") from None
        if meta.get("format") != CHECKPOINT_FORMAT:
            raise CheckpointError(f"checkpoint {self.path} is not a {self.label} checkpoint of this version; {fresh}")
        old = meta.get("key", {})
        for name in sorted(set(old) | set(self.key)):
            if old.get(name, "<absent>") != self.key.get(name, "<absent>"):
                raise CheckpointError(
                    f"checkpoint {self.path} was written with {name} = {_show(old.get(name, '<absent>'))}, this "
                    f"run has {name} = {_show(self.key.get(name, '<absent>'))}; {fresh}")
        k = int(meta["outputs_done"])
        if k > n_outputs:
            raise CheckpointError(f"checkpoint {self.path} already holds {k} output intervals, more than the "
                                  f"{n_outputs} asked for; ask for at least as many or {fresh}")
        recorder.restore({name[4:]: v for name, v in data.items() if name.startswith("rec.")})
        st = meta.get("stats", {})
        stats = Stats(n_steps=st.get("n_steps", 0), n_rhs=st.get("n_rhs", 0), n_jac=st.get("n_jac", 0),
                      callback_time=st.get("callback_time", 0.0), wall_time=st.get("wall_time", 0.0))
        self.saved_outputs = k
        return y, k, stats


def _jsonable(v):
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (np.integer, np.floating)):
        return v.item()
    if isinstance(v, Path):
        return str(v)
    return repr(v)


def _show(v) -> str:
    s = json.dumps(v)
    return s if len(s) <= 80 else s[:77] + "..."
