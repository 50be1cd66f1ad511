"""First run of the journal orbit in a fresh process: what a user waits for before the first half revolution,
IDA against BDF2, with a cold and a warm numba cache.

Each measurement is its own Python process (``python -m transient.bench.first_run METHOD``) so nothing compiled
or imported before counts: it imports :mod:`transient`, builds the Rho & Kim orbit (151 x 21, unbalance 0.01 C,
6000 rpm) and runs half a revolution at the method's settings, reporting the process's CPU seconds for the import,
the build and the run. *Cold*: an empty ``NUMBA_CACHE_DIR`` of its own, so the process compiles every kernel it
calls (and writes them); *warm*: the next process on the same directory, which should compile nothing.
Order: IDA cold, BDF2 cold, then the warm runs alternating (IDA, BDF2, BDF2, IDA), the faster of each kept.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TITLE = "First run: a fresh process's first half revolution, IDA against BDF2, cold and warm numba cache"
REVOLUTIONS = 0.5


def _child(method: str, grid) -> dict:
    """In the fresh process: CPU seconds of the interpreter's start and the imports, the build and the run of
    ``REVOLUTIONS`` (``time.process_time`` counts from the process's start)."""
    from transient.models.journal.bearing import JournalBearing
    from transient.models.journal.orbit import JournalOrbit
    from transient.params.rho_kim import BEARING, ROTOR
    from transient.solvers.settings import Integration, LongRun
    c1 = time.process_time()
    o = JournalOrbit(JournalBearing(**BEARING, grid=tuple(grid)), ROTOR["rotor_mass"], 0.01 * BEARING["clearance"],
                     ROTOR["load"], 6000.0)
    c2 = time.process_time()
    r = o.run(REVOLUTIONS, integration=Integration(method=method), long_run=LongRun(progress=False))
    c3 = time.process_time()
    return dict(method=method, import_cpu=c1, build_cpu=c2 - c1, run_cpu=c3 - c2, total_cpu=c3,
                steps=int(r.stats.n_steps), ok=bool(r.success))


def _spawn(method, cache_dir, grid) -> dict:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache_dir))
    w0 = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "transient.bench.first_run", method, *map(str, grid)], env=env,
                       capture_output=True, text=True, check=True)
    row = json.loads(p.stdout.strip().splitlines()[-1])
    row["wall"] = time.perf_counter() - w0
    return row


def run(quick=False, log=print) -> dict:
    grid = (48, 8) if quick else (151, 21)
    out = dict(grid=grid, revolutions=REVOLUTIONS, quick=quick, cold={}, warm={})
    with tempfile.TemporaryDirectory() as tmp:
        dirs = {m: Path(tmp) / m for m in ("ida", "bdf2")}
        for m in ("ida", "bdf2"):
            out["cold"][m] = _spawn(m, dirs[m], grid)
            log(f"  cold {m}: {out['cold'][m]}")
        for m in ("ida", "bdf2", "bdf2", "ida"):
            row = _spawn(m, dirs[m], grid)
            log(f"  warm {m}: {row}")
            if m not in out["warm"] or row["total_cpu"] < out["warm"][m]["total_cpu"]:
                out["warm"][m] = row
    return out


def markdown(res) -> str:
    g = res["grid"]
    L = [f"Rho & Kim orbit, {g[0]} x {g[1]}, 0.01 C, 6000 rpm, {res['revolutions']} revolution at each method's "
         f"defaults; CPU seconds of one fresh process each (cold: its own empty numba cache; warm: the faster of two "
         f"processes on that cache)" + (" — **quick smoke run**" if res["quick"] else "") + ".", "",
         "| cache | method | import s | build s | run s | total CPU s | steps | wall s |", "|---|---|---|---|---|---|---|---|"]
    for cache in ("cold", "warm"):
        for m in ("ida", "bdf2"):
            r = res[cache][m]
            L.append(f"| {cache} | {m} | {r['import_cpu']:.1f} | {r['build_cpu']:.1f} | {r['run_cpu']:.1f} | "
                     f"{r['total_cpu']:.1f} | {r['steps']} | {r['wall']:.1f} |")
    return "\n".join(L)


def main(out, quick=False) -> str:
    out = Path(out)
    res = run(quick=quick)
    (out / "bench_first_run.json").write_text(json.dumps(res, indent=1))
    return f"## {TITLE}\n\n{markdown(res)}\n"


if __name__ == "__main__":
    print(json.dumps(_child(sys.argv[1], tuple(int(v) for v in sys.argv[2:4]))))
