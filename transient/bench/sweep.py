"""Benchmark of the sweep machinery (``transient bench sweep``): parallel speed-up, per-point overhead, memory.

1. 16 points of about one second each (journal orbit, 41 x 6 grid, 20 revolutions, speeds 1000-7500 rpm),
   side by side in one run: 1 worker (in process), a local pool of 2 workers, and a Dask LocalCluster of
   2 single-threaded worker processes, each warmed first (workers started, kernels loaded: what a long sweep
   amortises). Speed-up = wall(1 worker) / wall(2 workers).
2. Per-point overhead of the pool: (wall x workers - sum of the points' own compute times) / points, as a
   fraction of the mean point time (scheduling, process start amortised, writing the Parquet row and the
   saved Result).
3. Memory of the sweeping process over many cheap points (pad descent, 4 x 4 grid): tracemalloc peak for
   100 and for 1000 points (quick: 50 and 200); flat means the peak does not grow with the point count
   beyond the table rows themselves.
"""

from __future__ import annotations

import shutil
import tempfile
import time
import tracemalloc
from pathlib import Path

import numpy as np

from transient.study.scene import scene_from_dict
from transient.study.sweep import sweep

TITLE = "sweeps: 2-worker speed-up on the local pool and Dask, per-point overhead, memory over 1000 points"

ORBIT = dict(kind="journal_orbit", overrides=dict(grid=[41, 6]), run=dict(revolutions=20.0, outputs_per_revolution=16),
             outputs=dict(figures=False))
CHEAP = dict(kind="pad_descent", overrides=dict(gamma=0.0, grid=[4, 4]), run=dict(outputs=5, t_end=0.05),
             outputs=dict(figures=False, save_result=False))


def _timed(values, doc, tmp, name, **kw):
    store = Path(tmp) / name
    t0 = time.perf_counter()
    res = sweep(scene_from_dict(doc), values, store=store, progress=False, **kw)
    wall = time.perf_counter() - t0
    point = float(np.sum(res.table["point_wall_s"]))
    return res, wall, point


def main(out, quick: bool = False) -> str:
    from distributed import Client, LocalCluster

    n = 8 if quick else 16
    values = dict(speed_rpm=[float(v) for v in np.linspace(1000.0, 7500.0, n)])
    warm = dict(speed_rpm=[6100.0, 6200.0, 6300.0, 6400.0])  # two points per worker
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        sweep(scene_from_dict(ORBIT), warm, store=Path(tmp) / "warm1", workers=1, progress=False)
        serial, w1, p1 = _timed(values, ORBIT, tmp, "serial", workers=1)
        sweep(scene_from_dict(ORBIT), warm, store=Path(tmp) / "warm2", workers=2, progress=False)
        pool, w2, p2 = _timed(values, ORBIT, tmp, "pool", workers=2)
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            with Client(cluster) as client:
                sweep(scene_from_dict(ORBIT), warm, store=Path(tmp) / "warmd", scheduler=client, progress=False)
                dask, wd, pd_ = _timed(values, ORBIT, tmp, "dask", scheduler=client)
        same = all(serial.table[c] == t.table[c] for t in (pool, dask) for c in ("semi_major_C", "eps_max"))
        for label, wall, point, workers in (("1 worker (in process)", w1, p1, 1), ("local pool, 2 workers", w2, p2, 2),
                                            ("Dask LocalCluster, 2 workers", wd, pd_, 2)):
            over = (wall * workers - point) / n
            rows.append((label, wall, w1 / wall, point / n, over, over / (point / n)))
        mem = []
        for m in ((50, 200) if quick else (100, 1000)):
            tracemalloc.start()
            res, wall, point = _timed(dict(load=[float(v) for v in np.linspace(100.0, 2000.0, m)]), CHEAP, tmp,
                                      f"cheap{m}", workers=2)
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            mem.append((m, wall, peak / 1e6, res.failed))
            shutil.rmtree(Path(tmp) / f"cheap{m}")
    lines = ["## Sweeps: local pool and Dask (Rho & Kim orbits as the work)", "",
             f"{n} points: journal orbit on 41 x 6 cells, 20 revolutions, speeds 1000-7500 rpm; all three tables "
             f"identical: {same}. Per-point overhead = (wall x workers - sum of point times) / points.", "",
             "| executor | wall [s] | speed-up vs 1 worker | mean point [s] | overhead per point [s] | overhead / point |",
             "|---|---:|---:|---:|---:|---:|"]
    lines += [f"| {a} | {w:.2f} | {s:.2f}x | {p:.3f} | {o:.3f} | {100 * r:.1f} % |" for a, w, s, p, o, r in rows]
    lines += ["", "Memory of the sweeping process (tracemalloc peak; cheap points: pad descent on 4 x 4 cells, 2 workers):",
              "", "| points | wall [s] | peak [MB] | failed |", "|---:|---:|---:|---:|"]
    lines += [f"| {m} | {w:.1f} | {p:.2f} | {f} |" for m, w, p, f in mem]
    lines += ["", "Machine: 2 cores (shared with other work when measured); the speed-up is bounded by 2 and by "
              "the slowest points at the end of the grid."]
    return "\n".join(lines)
