"""The long-run driver under every model's run (:mod:`~transient.solvers.model_run`): chunks, checkpoints, Ctrl-C.

:func:`run_long` integrates a model's :class:`~transient.solvers.integrate.Problem` from ``t0`` over
``n_outputs`` output intervals of length ``dt_out`` (model time; or at chosen output times: ``dt_out`` the
array of them), in chunks of ``chunk_outputs`` intervals. After every chunk it

* updates a progress bar (tqdm: done / total in the model's display unit, e.g. revolutions, time left),
* rewrites the checkpoint (if asked): the state, its time, the recorder's arrays and the statistics, in
  one ``.npz`` without pickle, keyed on ``key`` -- every parameter and setting that changes the result.
  ``resume=True`` continues from it; a checkpoint written with other parameters is refused with the name
  of the first parameter that differs, a truncated or corrupted one with the file name and how to start
  afresh, a path that is not a regular file (a FIFO, a device) by what it is, without opening it. Before
  resuming, its contents are checked against each other and the code: the format and code version (the
  package version and a hash of its sources: a state layout may change between versions), the state's
  declared size against the run's (before any array is read), each array's declared dtype and shape (read
  from the headers before anything is decompressed, under a size cap), a SHA-256 digest of every array
  (streamed, no copies), a finite state, finite recorded series, the output count and the state's time, and
  the recorder's own consistency (``restore`` raises ``ValueError`` on inconsistent
  arrays; an optional ``times()`` must give the output times ``t0 + k dt_out`` or the chosen ones). An advisory lock
  (``PATH.lock``, removed when the run ends) keeps two runs off one checkpoint. An OS fault while writing
  (full disk, read-only folder) raises :class:`CheckpointWriteError` naming the file and where the last
  complete checkpoint is;
* asks ``stop(recorder)`` whether to end early (e.g. the response has settled).

The model supplies ``problem_at(y, t) -> Problem`` and a recorder with ``observe(t, y)``, ``arrays()``
and ``restore(arrays)``; the recorder keeps only what the user asked for, so memory stays bounded.
Ctrl-C raises :class:`Interrupted`, whose message says where the checkpoint is and how to resume (in
Python: ``resume=True``; its ``command_line`` attribute says the same for the shell: run the same command
again, ``--fresh`` to start over).
"""

from __future__ import annotations

import json
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from transient.checks import check_positive
from transient.results import (FileFault, NotARegularFile, NpzReader, _content_digest, atomic_savez, code_version,
                               read_npz)
from transient.solvers.integrate import Stats, Steps, solve
from transient.solvers.legacy import keyword_table, run_settings
from transient.solvers.progress import FRACTIONAL, progress_bar
from transient.solvers.settings import LongRun

CHECKPOINT_FORMAT = "transient-checkpoint/2"
MAX_CHUNKS = 1_000_000


class Interrupted(KeyboardInterrupt):
    """Ctrl-C during a long run; the message says where the checkpoint is and how to resume from Python,
    ``command_line`` the same for the shell (run the same command again; ``--fresh`` starts over)."""

    def __init__(self, message: str, command_line: str = ""):
        super().__init__(message)
        self.command_line = command_line or message


#: How a refused checkpoint is set aside: from Python (``resume=False``) and from the shell (the scenarios' flag).
FRESH_PYTHON = "run with resume=False to start afresh"
FRESH_SHELL = "run the same command with --fresh to start afresh"


class CheckpointError(ValueError):
    """A checkpoint that cannot be used: other parameters or code, inconsistent, unreadable, or in use by
    another process. The message advises Python's ``resume=False``; ``command_line`` the same for the shell
    (``--fresh``)."""

    def __init__(self, message: str, command_line: str = ""):
        super().__init__(message)
        self.command_line = command_line or message.replace(FRESH_PYTHON, FRESH_SHELL)


class CheckpointWriteError(FileFault):
    """The OS refused to write a checkpoint (full disk, read-only folder); the message names the file and
    what the last complete checkpoint holds."""


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


@dataclass(frozen=True)
class Display:
    """How a long run shows itself: ``label`` names it in the progress bar and messages; ``unit = (name,
    length)`` is the display unit (e.g. ``("rev", 2 pi)`` for a time in radians of shaft rotation); ``status()``
    returns a short string for the bar (e.g. the current eccentricity) or is ``None``."""

    label: str = "run"
    unit: tuple = ("s", 1.0)
    status: Callable | None = None

    def __post_init__(self):
        if not isinstance(self.label, str):
            raise ValueError(f"label = {self.label!r}; allowed: a string")
        if not (isinstance(self.unit, tuple) and len(self.unit) == 2 and isinstance(self.unit[0], str)):
            raise ValueError(f"unit = {self.unit!r}; allowed: (name, length), e.g. ('rev', 2 pi)")
        object.__setattr__(self, "unit", (self.unit[0], check_positive("unit length", self.unit[1], self.unit[0])))
        if self.status is not None and not callable(self.status):
            raise ValueError(f"status = {self.status!r} is not callable; allowed: None or status() -> str")


#: The loose keywords of :func:`run_long` of earlier releases and where each now goes.
RUN_LONG_KEYWORDS = ({name: ("solver", dict, name) for name in ("method", "rtol", "atol", "linear_solver", "options")}
                     | {name: ("steps", Steps, name) for name in ("dt", "max_step", "first_step")}
                     | {name: ("long_run", LongRun, name) for name in ("checkpoint", "resume", "progress", "stop",
                                                                        "time_budget")}
                     | keyword_table("display", Display))


def run_long(problem_at: Callable, y0, t0: float, dt_out, n_outputs: int, recorder, *, solver: dict | None = None,
             long_run: LongRun | None = None, chunk_outputs: int | None = None, key: dict | None = None,
             display: Display | None = None, **legacy) -> Outcome:
    """Integrate ``n_outputs`` output intervals (module docstring).

    ``solver``: the keywords of :func:`~transient.solvers.integrate.solve` for every chunk (``method``,
    ``rtol``, ``atol``, ``steps``, ``linear_solver``, ``options``; ``method`` is required, ``rk4`` needs
    ``steps=Steps(dt=...)``); a model whose run is a map between its output times (the ball-pass sequence) hands
    ``advance(y, times, observer, time_budget) -> Solution`` in it instead (``problem_at`` unused): the chunk from
    ``y`` over ``times``, each output handed to ``observer(t, y)``, a terminal event in ``t_events``/``y_events``. ``long_run`` (:class:`~transient.solvers.settings.LongRun`): the checkpoint and
    ``resume``, the progress bar (``progress``), ``stop(recorder) -> str | None`` and ``time_budget`` [s of wall
    time] for the whole run (all chunks: past it the run ends with ``success=False`` and the outputs so far); its
    ``chunk_revolutions`` is the model's, which hands ``chunk_outputs`` (output intervals per chunk; default:
    the whole run). ``key``: every parameter and setting that changes the result (keys the checkpoint).
    ``dt_out``: the output interval, or the array of the ``n_outputs + 1`` output times from ``t0``
    (:func:`output_times`). ``display`` (:class:`Display`): the label, display unit and status of the bar and
    messages. The loose keywords of earlier releases (``method=``, ``checkpoint=``, ``label=``, ...) are
    deprecated."""
    given = run_settings("run_long", legacy, RUN_LONG_KEYWORDS, solver=solver, long_run=long_run,
                         display=display, steps=None)
    solver, long_run, display = given["solver"], given["long_run"], given["display"]
    if any(RUN_LONG_KEYWORDS[k][0] == "steps" for k in legacy):
        solver = dict(solver, steps=given["steps"])
    if "method" not in solver:
        raise ValueError(f"solver = {solver!r}: the method is required; allowed: solver=dict(method=..., ...)")
    solver = dict(solver)
    advance = solver.pop("advance", None)
    method = solver["method"]
    checkpoint, resume, progress = long_run.checkpoint, long_run.resume, long_run.progress
    stop, time_budget, status = long_run.stop, long_run.time_budget, display.status
    label = display.label
    n_outputs = int(n_outputs)
    if n_outputs < 1:
        raise ValueError(f"the run must span at least one output interval, got {n_outputs}")
    chunk_outputs = n_outputs if chunk_outputs is None else int(chunk_outputs)
    if chunk_outputs < 1:
        raise ValueError(f"chunk = {chunk_outputs} output intervals; allowed: >= 1 (one output interval)")
    if -(-n_outputs // chunk_outputs) > MAX_CHUNKS:
        raise ValueError(f"{n_outputs} outputs in chunks of {chunk_outputs} make more than {MAX_CHUNKS} chunks; "
                         "use longer chunks")
    times = output_times(t0, dt_out, n_outputs)
    uname, ulen = display.unit
    ckpt = _Checkpoint(checkpoint, key or {}, label) if checkpoint else None
    y = np.array(y0, dtype=float)
    k = 0
    stats = Stats()
    if ckpt is not None:
        ckpt.acquire()
    try:
        if ckpt is not None and resume and ckpt.path.exists():
            y, k, saved_stats = ckpt.load(recorder, n_outputs, y, times)
            stats = saved_stats
        resumed_from = k
        n_chunks = -(-(n_outputs - k) // chunk_outputs)
        progress = (n_chunks > 1) if progress is None else bool(progress)
        bar = progress_bar(progress, (times[-1] - t0) / ulen, uname, label, (times[k] - t0) / ulen, FRACTIONAL)
        wall0 = time.perf_counter()
        deadline = math.inf if time_budget is None else wall0 + float(time_budget)
        out = Outcome(y=y, t=times[k], stats=stats, outputs_done=k, resumed_from=resumed_from)
        try:
            while k < n_outputs:
                k_end = min(n_outputs, k + chunk_outputs)
                tau = times[k:k_end + 1]
                remaining = None if time_budget is None else max(deadline - time.perf_counter(), 1e-9)
                if advance is None:
                    res = solve(problem_at(y, tau[0]), tau, **solver, store=False, observer=_Last(recorder, out),
                                time_budget=remaining)
                else:
                    res = advance(y, tau, _Last(recorder, out), remaining)
                _accumulate(stats, res.stats)
                if not res.success:
                    out.success = False
                    out.message = (f"{method} stopped at {out.t / ulen:.6g} {uname}: {res.message}")
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
                    ckpt.save(y, k, out.t, recorder, stats, times, display.unit)
                if bar is not None:
                    bar.update((tau[-1] - tau[0]) / ulen if k < n_outputs else bar.total - bar.n)
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
                held = f"{label} interrupted {where}; checkpoint {ckpt.path} holds {(times[ckpt.saved_outputs] - t0) / ulen:.6g} {uname}"
                raise Interrupted(f"{held}: run again with resume=True (same parameters) to continue",
                                  f"{held}: run the same command again to continue (--fresh starts over)") from None
            raise Interrupted(f"{label} interrupted {where}; no checkpoint was written (pass checkpoint=PATH "
                              "to make a long run resumable)",
                              f"{label} interrupted {where}; no checkpoint was written") from None
        finally:
            if bar is not None:
                bar.close()
        stats.wall_time += time.perf_counter() - wall0
        out.stats, out.outputs_done = stats, k
        return out
    finally:
        if ckpt is not None:
            ckpt.release()


def output_times(t0: float, dt_out, n_outputs: int) -> np.ndarray:
    """The ``n_outputs + 1`` output times of a run from ``t0``: every ``dt_out`` (a number > 0), or ``dt_out``
    itself when it is the array of them (increasing, finite, the first ``t0``); a one-line ``ValueError`` otherwise."""
    if np.ndim(dt_out) == 0:
        return t0 + check_positive("dt_out", dt_out, "-") * np.arange(n_outputs + 1)
    times = np.asarray(dt_out, dtype=float)
    if times.shape != (n_outputs + 1,) or not np.all(np.isfinite(times)) or np.any(np.diff(times) <= 0) \
            or times[0] != t0:
        raise ValueError(f"dt_out: {times.size} output times; allowed: {n_outputs + 1} finite increasing times from "
                         f"t0 = {t0!r}")
    return times


class _Last:
    """Observer that hands each output to the recorder and keeps the last state in the outcome."""

    def __init__(self, recorder, out: Outcome):
        self.recorder, self.out = recorder, out

    def __call__(self, t, y):
        self.out.y = np.array(y)
        self.out.t = float(t)
        self.recorder.observe(t, y)


def _accumulate(total: Stats, part: Stats):
    total.n_steps += part.n_steps
    total.n_rhs += part.n_rhs
    total.n_jac += part.n_jac
    total.callback_time += part.callback_time


class _Checkpoint:
    """A checkpoint file, its advisory lock and its key."""

    #: what to do with a checkpoint that cannot be resumed
    FRESH = f"delete it or {FRESH_PYTHON}"

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

    @property
    def lock_path(self) -> Path:
        return self.path.with_name(self.path.name + ".lock")

    def acquire(self):
        """Take the advisory lock ``PATH.lock`` (refused naming the holder's process id). The lock file is
        removed on release; a lock taken on a file that another run has just removed is taken again."""
        import fcntl

        for _ in range(20):
            try:
                fd = os.open(self.lock_path, os.O_RDWR | os.O_CREAT, 0o644)
            except OSError as e:
                raise CheckpointError(f"checkpoint lock {self.lock_path} cannot be created ({e.strerror}); choose "
                                      "a writable folder for the checkpoint") from None
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                other = os.read(fd, 64).decode(errors="replace").strip() or "?"
                os.close(fd)
                raise CheckpointError(f"checkpoint {self.path} is in use by process {other}; wait for it or use "
                                      "another checkpoint path") from None
            try:
                same = os.fstat(fd).st_ino == os.stat(self.lock_path).st_ino
            except FileNotFoundError:
                same = False
            if same:
                break
            os.close(fd)  # the holder removed this lock file as we opened it: take the new one
        else:
            raise CheckpointError(f"checkpoint lock {self.lock_path} keeps changing; another process is "
                                  "competing for it")
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode())
        self.lock_fd = fd

    def release(self):
        if self.lock_fd is not None:
            import fcntl

            try:
                os.unlink(self.lock_path)  # while still held: nobody can take the old file afterwards
            except OSError:
                pass
            fcntl.flock(self.lock_fd, fcntl.LOCK_UN)
            os.close(self.lock_fd)
            self.lock_fd = None

    def save(self, y, k, t, recorder, stats: Stats, times, unit):
        arrays = {f"rec.{name}": np.asarray(v) for name, v in recorder.arrays().items()}
        arrays["state"] = np.asarray(y, dtype=float)
        meta = dict(format=CHECKPOINT_FORMAT, code_version=code_version(), key=self.key, outputs_done=int(k),
                    time=float(t), digest=_content_digest(arrays),
                    arrays={name: [a.dtype.str, list(a.shape)] for name, a in arrays.items()},
                    stats=dict(n_steps=stats.n_steps, n_rhs=stats.n_rhs, n_jac=stats.n_jac,
                               callback_time=stats.callback_time, wall_time=stats.wall_time))
        arrays["__meta__"] = np.array(json.dumps(meta))
        try:
            atomic_savez(self.path, arrays)
        except OSError as e:
            uname, ulen = unit
            if self.saved_outputs is not None:
                kept = (f"the last complete checkpoint {self.path} holds {(times[self.saved_outputs] - times[0]) / ulen:.6g} "
                        f"{uname}; once fixed, resume from it")
            elif self.path.exists():
                kept = f"the previous checkpoint {self.path} is unchanged"
            else:
                kept = "no checkpoint was written"
            raise CheckpointWriteError(e.errno, f"{e.strerror}; {kept}") from None
        self.saved_outputs = int(k)

    def load(self, recorder, n_outputs, y0, times):
        try:
            z = NpzReader(self.path)
        except NotARegularFile as e:
            raise CheckpointError(f"checkpoint {self.path} is {e.kind}, not a regular file; give the checkpoint "
                                  "a file name of its own") from None
        except Exception as e:
            raise CheckpointError(f"checkpoint {self.path} cannot be read ({type(e).__name__}: {e}); "
                                  f"{self.FRESH}") from None
        with z:
            return self._load(z, recorder, n_outputs, y0, times)

    def _load(self, z, recorder, n_outputs, y0, times):
        fresh = self.FRESH

        def refuse(why):
            return CheckpointError(f"checkpoint {self.path} {why}; {fresh}")

        try:
            heads = z.headers()
            if "__meta__" not in heads or heads["__meta__"][0].kind != "U" or heads["__meta__"][1] != ():
                raise ValueError("no metadata")
            meta = json.loads(str(read_npz(z, wanted=["__meta__"])["__meta__"]))
            if not isinstance(meta, dict):
                raise ValueError("the metadata is not a JSON object")
        except Exception as e:
            raise CheckpointError(f"checkpoint {self.path} cannot be read ({type(e).__name__}: {e}); {fresh}") from None
        if meta.get("format") != CHECKPOINT_FORMAT:
            raise refuse(f"is not a {self.label} checkpoint of this version (format {meta.get('format')!r}, "
                         f"expected {CHECKPOINT_FORMAT})")
        if meta.get("code_version") != code_version():
            raise refuse(f"was written by transient {meta.get('code_version')!r}, this is {code_version()} "
                         "(the state's layout may differ)")
        old = meta.get("key", {})
        if not isinstance(old, dict):
            raise refuse("has no parameter key")
        for name in sorted(set(old) | set(self.key)):
            if old.get(name, "<absent>") != self.key.get(name, "<absent>"):
                raise CheckpointError(
                    f"checkpoint {self.path} was written with {name} = {_show(old.get(name, '<absent>'))}, this "
                    f"run has {name} = {_show(self.key.get(name, '<absent>'))}; {fresh}")
        k = meta.get("outputs_done")
        if not isinstance(k, int) or isinstance(k, bool) or k < 1:
            raise refuse(f"holds outputs_done = {_show(k)}, not a positive count")
        if k > n_outputs:
            raise CheckpointError(f"checkpoint {self.path} already holds {k} output intervals, more than the "
                                  f"{n_outputs} asked for; ask for at least as many or {fresh}")
        t_expected = times[k]
        t = meta.get("time")
        if not isinstance(t, (int, float)) or not abs(t - t_expected) <= 1e-9 * max(1.0, abs(t_expected)):
            raise refuse(f"holds the state at time {_show(t)}, but {k} outputs end at {t_expected:.17g}")
        declared = meta.get("arrays")
        if not isinstance(declared, dict) or "state" not in declared:
            raise refuse("declares no arrays")
        y0 = np.asarray(y0)
        try:
            declared = {name: (np.dtype(d[0]), tuple(d[1])) for name, d in declared.items()}
            extra = sorted(set(heads) - set(declared) - {"__meta__"})
            if extra:
                raise ValueError(f"array {extra[0]!r} is not declared")
        except Exception as e:
            raise refuse(f"has inconsistent arrays ({type(e).__name__}: {e})") from None
        s_dtype, s_shape = declared["state"]
        if s_shape != y0.shape or s_dtype.kind != "f":  # before anything is read
            raise refuse(f"holds a state of {s_dtype.str} {list(s_shape)}, this run has {list(y0.shape)} states")
        try:
            data = read_npz(z, wanted=list(declared), declared=declared)
        except Exception as e:
            raise refuse(f"has inconsistent arrays ({type(e).__name__}: {e})") from None
        if _content_digest(data) != meta.get("digest"):
            raise refuse("does not match its digest (the file was altered or damaged)")
        for name, a in data.items():
            if name.startswith("rec.") and a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
                i = np.unravel_index(int(np.argmin(np.isfinite(a))), a.shape)
                raise refuse(f"holds {a[i]} in its recorded series {name[4:]!r} at index {list(map(int, i))} (a "
                             "checkpoint of a run records finite outputs only: it was altered or damaged)")
        y = data.pop("state")
        if y.shape != y0.shape or y.dtype.kind != "f":
            raise refuse(f"holds a state of {y.dtype.str} {list(y.shape)}, this run has {list(y0.shape)} states")
        if not np.all(np.isfinite(y)):
            raise refuse(f"holds a non-finite state (index {int(np.argmin(np.isfinite(y)))})")
        try:
            recorder.restore({name[4:]: v for name, v in data.items() if name.startswith("rec.")})
            recorded = getattr(recorder, "times", None)
            if recorded is not None:
                held = np.asarray(recorded(), dtype=float)
                want = times[:k + 1]
                gap = float(np.min(np.diff(times)))
                if held.shape != want.shape or not np.allclose(held, want, rtol=1e-12, atol=1e-9 * gap):
                    raise ValueError(f"its recorded outputs ({held.size}) are not the {k + 1} output times of "
                                     f"{k} intervals")
        except (ValueError, KeyError, IndexError, TypeError) as e:
            raise refuse(f"has inconsistent recordings ({type(e).__name__}: {e})") from None
        st = meta.get("stats", {})
        try:
            stats = Stats(n_steps=int(st.get("n_steps", 0)), n_rhs=int(st.get("n_rhs", 0)),
                          n_jac=int(st.get("n_jac", 0)), callback_time=float(st.get("callback_time", 0.0)),
                          wall_time=float(st.get("wall_time", 0.0)))
        except (TypeError, ValueError, AttributeError):
            raise refuse("holds malformed statistics") from None
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
