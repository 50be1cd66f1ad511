"""Parameter sweeps of a scene on a local process pool or on Dask, resumable point by point.

``sweep(scene, {"speed_rpm": values, ...})`` runs the grid (cartesian product) of the values, one model run
per point (:mod:`transient.study.scene`), and returns a :class:`SweepResult` (the table of scalars, one row
per point). ``transient sweep SCENE.toml --param speed_rpm=1000:7500:27`` is the same from the shell.

* Where: a local process pool (``workers``, default the cores; one thread per process: OpenMP, BLAS and
  numba pinned to 1 thread, SuperLU_MT already runs single-threaded), or an existing Dask cluster
  (``scheduler`` = its address or a ``distributed.Client``): the same point function runs on a laptop and
  on a cluster. numba kernels are compiled (or loaded from its cache) once per worker process. A Dask
  scheduler and its workers exchange tasks and results as pickles, which run code when read: connect only
  to a scheduler you trust, on a network you trust (the local pool and the store use no pickle). An
  unreachable address is one line after :data:`CONNECT_TIMEOUT` seconds. Pool workers exit when the sweep's
  process dies, even killed with -9 (parent-death signal and a watchdog thread).
* Resumable: each point is written by the worker that computed it, as soon as it completes, under
  ``store/points/KEY``: ``KEY.parquet`` (one row: parameters, scalars, status, error, code version) and
  ``KEY.npz`` (the saved Result, if asked). ``KEY`` hashes the kind, every parameter, the run options and
  the code version (the package version and a hash of its sources), so a rerun skips finished points, a
  changed parameter or code recomputes them, a killed sweep loses at most the points in flight, and two
  sweeps on one store never share a file (unique temporary names, atomic renames). A file that cannot be
  read, or whose key or code version is not the one expected, is recomputed, never used.
* A point that fails records its error and the sweep goes on; the summary lists the failures.
* A progress bar across points (done / total, time left); memory bounded whatever the number of points (at
  most two points per worker in flight, only the scalar rows kept). The table is written as
  ``store/results.parquet`` and ``results.csv``; figures of the sweep from :mod:`transient.plots.sweep`.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import sys
import time
import traceback
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from pathlib import Path

import numpy as np

from transient.results import StatusResult, atomic_write, code_version, file_error, quantity, read_npz, result_type
from transient.solvers.progress import progress_bar
from transient.study.scenario import default_root
from transient.study.scene import KINDS, Scene

#: Environment that pins every worker process to one thread
ONE_THREAD = dict(OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1", NUMBA_NUM_THREADS="1",
                  OMP_WAIT_POLICY="PASSIVE")


@result_type
class SweepResult(StatusResult):
    """A finished sweep: ``table`` (column -> values, one row per point in grid order), the swept
    parameters, the store folder, how many points were computed, reused from the store and failed (with their
    errors in ``failures``), and the wall time [s]."""

    time_axis = None
    table: dict = None
    swept: list = None
    store: str = ""
    computed: int = 0
    reused: int = 0
    failed: int = 0
    failures: list = None
    wall_time: float = quantity("s", 0.0)

    def to_dataframe(self):
        import pandas as pd

        return pd.DataFrame(self.table)


# --------------------------------------------------------------------------------------------------
# points and keys
# --------------------------------------------------------------------------------------------------

def parse_values(spec: str, name: str = "") -> list:
    """``a:b:n`` -> n values from a to b; ``a:b`` -> the integers a..b; ``a,b,c`` -> the list; ``a`` -> [a].
    A list-valued parameter (``grid``) takes lists: ``NAME=[151,21];[301,41]``. Finite numbers only; at
    most :data:`MAX_POINTS` values. ``name`` (the parameter) goes into the error messages."""
    s = spec.strip() if isinstance(spec, str) else spec
    what = f"--param {name}={spec!r}" if name else f"values {spec!r}"
    if not isinstance(s, str) or not s:
        raise ValueError(f"{what}: no values; expected a:b:n (n values from a to b), a:b (integers), or a,b,c")
    try:
        if s.startswith("["):
            out = [json.loads(part) for part in s.split(";")]
            if not all(isinstance(v, list) and v and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                         for x in v) for v in out):
                raise ValueError
        elif ":" in s:
            parts = s.split(":")
            if len(parts) == 3:
                a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
                if not (1 <= n <= MAX_POINTS):
                    raise ValueError
                out = [float(v) for v in np.linspace(a, b, n)]
            elif len(parts) == 2:
                a, b = int(parts[0]), int(parts[1])
                if abs(b - a) >= MAX_POINTS:
                    raise ValueError
                out = list(range(a, b + 1)) if b >= a else list(range(a, b - 1, -1))
            else:
                raise ValueError
        else:
            out = [_number(v) for v in s.split(",")]
    except (ValueError, OverflowError):
        raise ValueError(f"{what}: expected a:b:n (n values from a to b, n in [1, {MAX_POINTS}]), a:b (integers), "
                         "a,b,c (numbers) or [..];[..] (lists)") from None
    flat = [x for v in out for x in (v if isinstance(v, list) else [v])]
    if not all(np.isfinite(flat)):
        raise ValueError(f"{what}: values must be finite numbers")
    if len(out) > MAX_POINTS:
        raise ValueError(f"{what}: {len(out)} values, more than {MAX_POINTS}")
    return out


def parse_params(specs: list[str]) -> dict:
    """``["NAME=VALUES", ...]`` (the command line's ``--param``) -> ``{NAME: values}``; a name given twice
    is an error."""
    values = {}
    for spec in specs:
        name, sep, vals = spec.partition("=")
        name = name.strip()
        if not sep or not name:
            raise ValueError(f"--param {spec!r}: expected NAME=VALUES")
        if name in values:
            raise ValueError(f"--param {name} is given twice; give each swept parameter once (a,b,c lists values)")
        values[name] = parse_values(vals, name)
    return values


#: the most values of one swept parameter, and of points in a sweep
MAX_POINTS = 100_000


def _number(v):
    v = v.strip()
    try:
        return int(v)
    except ValueError:
        return float(v)


def grid(values: dict) -> list[dict]:
    """Cartesian product of the swept values, in order (the last name varies fastest)."""
    names = list(values)
    return [dict(zip(names, combo)) for combo in itertools.product(*(values[n] for n in names))]


def point_key(kind: str, params: dict, run: dict) -> str:
    text = json.dumps(dict(kind=kind, params=params, run=run, code=code_version()), sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:24]


# --------------------------------------------------------------------------------------------------
# the store
# --------------------------------------------------------------------------------------------------

def _plain(v):
    if isinstance(v, (list, tuple, dict)):
        return json.dumps(v)
    if isinstance(v, (np.integer, np.floating, np.bool_)):
        return v.item()
    return v


def _write_row(path: Path, row: dict):
    import pyarrow as pa
    import pyarrow.parquet as pq

    table = pa.Table.from_pylist([{k: _plain(v) for k, v in row.items()}])
    atomic_write(path, lambda fh: pq.write_table(table, fh))


def _make_store(store: Path):
    """Create the store's folders; an OS fault is one line naming the folder and what to do."""
    try:
        (store / "points").mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise file_error(e, store, "create the store folder") from None
    if not os.access(store / "points", os.W_OK):
        raise file_error(OSError(13, "Permission denied"), store, "write into the store folder")


def read_row(store: Path, key: str, need_result: bool) -> dict | None:
    """The stored row of ``key`` if it is complete, readable, of this key and code version and succeeded."""
    import pyarrow.parquet as pq

    path = store / "points" / f"{key}.parquet"
    if not path.exists():
        return None
    try:
        rows = pq.read_table(path).to_pylist()
        row = rows[0] if len(rows) == 1 else None
    except Exception:
        return None
    if not row or row.get("key") != key or row.get("code_version") != code_version() or row.get("status") != "ok":
        return None
    if need_result:
        try:
            meta = json.loads(str(read_npz(store / "points" / f"{key}.npz", wanted=["__meta__"])["__meta__"]))
            if meta.get("format", "").split("/")[0] != "transient-result":
                return None
        except Exception:
            return None
    return row


def run_point(kind: str, params: dict, run: dict, key: str, store: str, save_result: bool) -> dict:
    """Compute one point and write its files (runs in a worker). Never raises: a failure is a row."""
    t0 = time.perf_counter()
    row = dict(key=key, code_version=code_version(), kind=kind, **{f"param.{k}": v for k, v in params.items()})
    points = Path(store) / "points"
    try:
        result, scalars = KINDS[kind].point(params, run)
        if save_result:
            result.save(points / f"{key}.npz")
        row.update(status="ok", error="", **scalars)
    except Exception as e:  # the sweep goes on; the row says why
        row.update(status="failed", error=f"{type(e).__name__}: {e}",
                   traceback="".join(traceback.format_exception(e))[-2000:])
    row["point_wall_s"] = time.perf_counter() - t0
    _write_row(points / f"{key}.parquet", row)
    return row


def _worker_init(parent: int | None = None):
    """Each pool worker: one thread, and exit as soon as the process that started it is gone (killed with
    -9, it cannot shut its pool down): on Linux the kernel's parent-death signal, elsewhere (and as a
    second guard) a daemon thread that checks the parent's id every half second."""
    os.environ.update(ONE_THREAD)
    if parent is None:
        return
    if sys.platform.startswith("linux"):
        try:
            import ctypes
            import signal

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)  # PR_SET_PDEATHSIG = 1
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:  # the parent died before the signal was armed
        os._exit(1)

    def watch():
        while True:
            time.sleep(0.5)
            if os.getppid() != parent:
                os._exit(1)

    import threading

    threading.Thread(target=watch, name="transient-parent-watchdog", daemon=True).start()


# --------------------------------------------------------------------------------------------------
# the sweep
# --------------------------------------------------------------------------------------------------

def sweep(scene: Scene, values: dict, *, store=None, workers: int | None = None, scheduler=None,
          progress: bool = True, figures: bool | None = None) -> SweepResult:
    """Run ``scene`` over the grid of ``values`` (name -> list) and return the table (module docstring).

    ``store``: the folder of the per-point files and the table (default ``sweep_<kind>`` under the output
    root, :func:`transient.study.scenario.default_root`). ``workers``: local processes (default: the cores; 1 runs in this process). ``scheduler``: a
    Dask scheduler address or ``distributed.Client`` (then ``workers`` is ignored)."""
    if not values:
        raise ValueError("a sweep needs at least one swept parameter (NAME=values)")
    n_points = int(np.prod([len(v) for v in values.values()], dtype=float))
    if n_points > MAX_POINTS:
        raise ValueError(f"the sweep has {n_points} points, more than {MAX_POINTS}; sweep fewer values")
    points = grid(values)
    for p in points:  # every point's model is built (no solve) before anything is computed
        scene.check_point(scene.with_params(**p))
    store = Path(store or Path(default_root()) / f"sweep_{scene.kind.name}")
    _make_store(store)
    kind, run = scene.kind.name, scene.run
    save_result = bool(scene.outputs.get("save_result", True))
    jobs = []
    for p in points:
        params = scene.with_params(**p)
        jobs.append((kind, params, run, point_key(kind, params, run), str(store), save_result))
    rows = {}
    for j in jobs:
        r = read_row(store, j[3], save_result)
        if r is not None:
            rows[j[3]] = r
    todo = [j for j in jobs if j[3] not in rows]
    reused = len(jobs) - len(todo)
    t0 = time.perf_counter()
    bar = progress_bar(progress, len(jobs), "point", f"sweep {kind}", reused)
    try:
        for row in _execute(todo, workers, scheduler):
            rows[row["key"]] = row
            if bar is not None:
                bar.update(1)
                bar.set_postfix_str(f"failed {sum(r['status'] != 'ok' for r in rows.values())}", refresh=False)
    finally:
        if bar is not None:
            bar.close()
    ordered = [rows[j[3]] for j in jobs]
    table = _table(ordered)
    _write_table(store, ordered)
    failures = [dict(**{k[6:]: r[k] for k in r if k.startswith("param.")}, error=r["error"])
                for r in ordered if r["status"] != "ok"]
    res = SweepResult(table=table, swept=list(values), store=str(store), computed=len(todo), reused=reused,
                      failed=len(failures), failures=failures, wall_time=time.perf_counter() - t0,
                      success=not failures,
                      message=f"{len(jobs)} points: {len(todo)} computed, {reused} reused, {len(failures)} failed")
    if figures if figures is not None else scene.outputs.get("figures", True):
        _figures(scene, res, store)
    return res


def _execute(jobs, workers, scheduler):
    """Yield the rows of ``jobs`` as they complete, at most two per worker in flight."""
    if not jobs:
        return
    if scheduler is not None:
        yield from _execute_dask(jobs, scheduler)
        return
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    if workers < 1:
        raise ValueError(f"workers = {workers}; allowed: >= 1")
    if workers == 1:
        for j in jobs:
            yield run_point(*j)
        return
    pool = _pool(workers)
    pending, queue = set(), iter(jobs)
    for j in itertools.islice(queue, 2 * workers):
        pending.add(pool.submit(run_point, *j))
    while pending:
        done, pending = wait(pending, return_when=FIRST_COMPLETED)
        for f in done:
            yield f.result()
            nxt = next(queue, None)
            if nxt is not None:
                pending.add(pool.submit(run_point, *nxt))


_POOLS: dict = {}


def _pool(workers: int) -> ProcessPoolExecutor:
    """The process pool of ``workers`` single-threaded workers, kept for the life of this process: its
    workers import the package and load the numba kernels once, not per sweep."""
    import atexit
    import multiprocessing as mp

    pool = _POOLS.get(workers)
    if pool is not None and not getattr(pool, "_broken", False):
        return pool
    saved = {k: os.environ.get(k) for k in ONE_THREAD}
    os.environ.update(ONE_THREAD)  # spawned workers inherit it before they import numpy or numba
    try:
        pool = ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("spawn"), initializer=_worker_init,
                                   initargs=(os.getpid(),))
        # start the workers now, while the environment holds
        list(pool.map(_noop, range(workers)))
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    if not _POOLS:
        atexit.register(lambda: [p.shutdown(wait=False, cancel_futures=True) for p in _POOLS.values()])
    _POOLS[workers] = pool
    return pool


def _noop(_):
    return os.getpid()


def _execute_dask(jobs, scheduler):
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise ImportError('a Dask scheduler needs the optional extra: pip install -e ".[distributed]"') from None
    client = scheduler if isinstance(scheduler, Client) else _connect(Client, scheduler)
    try:
        n_workers = max(1, len(client.scheduler_info().get("workers", {})))
        queue = iter(jobs)
        futures = [client.submit(run_point, *j, pure=False) for j in itertools.islice(queue, 2 * n_workers)]
        ac = as_completed(futures)
        for f in ac:
            yield f.result()
            nxt = next(queue, None)
            if nxt is not None:
                ac.add(client.submit(run_point, *nxt, pure=False))
    finally:
        if client is not scheduler:
            client.close()


#: seconds to wait for a Dask scheduler before giving up
CONNECT_TIMEOUT = 10.0


def _connect(Client, address):
    """A ``distributed.Client`` of ``address``, or one line within :data:`CONNECT_TIMEOUT` seconds saying
    it cannot be reached."""
    import logging

    if not isinstance(address, str) or not address.strip():
        raise ValueError(f"scheduler = {address!r}; allowed: the address of a Dask scheduler, e.g. tcp://host:8786")
    quiet = logging.getLogger("distributed")
    level = quiet.level
    quiet.setLevel(logging.CRITICAL)
    try:
        return Client(address, timeout=CONNECT_TIMEOUT)
    except (OSError, TimeoutError, ValueError, TypeError) as e:
        why = " ".join(str(e).split())[:160] or type(e).__name__
        raise ConnectionError(f"cannot reach the Dask scheduler at {address} within {CONNECT_TIMEOUT:g} s ({why}); "
                              "check the address and that the scheduler runs, or leave out --scheduler to use "
                              "local processes") from None
    finally:
        quiet.setLevel(level)


def _table(rows) -> dict:
    cols = []
    for r in rows:
        cols.extend(k for k in r if k not in cols and k != "traceback")
    return {c: [r.get(c) for r in rows] for c in cols}


def _write_table(store: Path, rows):
    import pandas as pd

    df = pd.DataFrame([{k: _plain(v) for k, v in r.items() if k != "traceback"} for r in rows])
    atomic_write(store / "results.parquet", lambda fh: df.to_parquet(fh, index=False))
    atomic_write(store / "results.csv", lambda fh: fh.write(df.to_csv(index=False).encode()))


def _figures(scene, res, store):
    from transient.plots import save

    if scene.kind.figures is None:
        return
    table = {(k[6:] if k.startswith("param.") else k): v for k, v in res.table.items()}
    for name, fig in scene.kind.figures(table, res.swept).items():
        save(fig, store / f"{scene.kind.name}_{name}.png")
