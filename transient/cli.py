"""The ``transient`` command.

    transient run SCENARIO.py [args ...]   run a scenario script (``--help`` lists its options; every scenario
                                           takes ``--quick`` and ``--out DIR``)
    transient run SCENE.toml [--out DIR]   run a scene file (one model run: result, scalars, figure)
    transient sweep SCENE.toml --param NAME=a:b:n [--param ...] [--workers N | --scheduler ADDRESS]
                                           [--store DIR]
                                           sweep it (grid of the values; resumable; table + figures in DIR)

Outputs go under one root, ./transient_out (or $TRANSIENT_OUT), never beside the sources: a scenario into
ROOT/NAME/ (its --quick run into ROOT/NAME/quick/), a scene into ROOT/SCENE/, a sweep into ROOT/sweep_KIND/.
    transient bench NAME [--out DIR] [--quick]
                                           run a benchmark; its section, figures and raw numbers go to DIR
                                           (default ./bench_results; ``--out docs`` updates the committed tables)
    transient bench --list                 the benchmarks and what each measures
    transient --version

Mistakes (a missing file, an unknown benchmark, an out-of-range parameter, a full or read-only disk) print
one line naming what is wrong; Ctrl-C stops with one line (long runs say where their checkpoint is: run the
same command again to continue).
"""

from __future__ import annotations

import argparse
import runpy
import sys
from pathlib import Path

import transient


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="transient", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"transient {transient.__version__}")
    parser.add_argument("--traceback", action="store_true", help="show the full traceback of an error")
    sub = parser.add_subparsers(dest="command", required=True)
    p_run = sub.add_parser("run", help="run a scenario script or a scene file")
    p_run.add_argument("scenario", help="a scenario .py file (see scenarios/) or a scene .toml file")
    p_run.add_argument("args", nargs=argparse.REMAINDER, help="arguments passed to the scenario (a scene: --out DIR)")
    p_sweep = sub.add_parser("sweep", help="sweep a scene file over parameter values")
    p_sweep.add_argument("scene", help="a scene .toml file")
    p_sweep.add_argument("--param", action="append", default=[], metavar="NAME=VALUES",
                         help="swept parameter: NAME=a:b:n (n values), NAME=a:b (integers), NAME=a,b,c")
    p_sweep.add_argument("--workers", type=int, help="local worker processes (default: the cores)")
    p_sweep.add_argument("--scheduler", help="address of a Dask scheduler (instead of the local pool); Dask "
                                             "exchanges pickled tasks, so use only a scheduler you trust")
    p_sweep.add_argument("--store", help="folder of the results (default: ./transient_out/sweep_KIND)")
    p_bench = sub.add_parser("bench", help="run a benchmark and write its section, figures and numbers")
    p_bench.add_argument("name", nargs="?", help="benchmark name (see --list)")
    p_bench.add_argument("--list", action="store_true", help="list the benchmarks")
    p_bench.add_argument("--out", default="bench_results", help="output folder (default: ./bench_results)")
    p_bench.add_argument("--quick", action="store_true", help="fast smoke version (few settings)")
    return parser


def _run_scenario(path: Path, args: list[str]) -> int:
    if not path.is_file():
        raise FileNotFoundError(f"scenario file not found: {path}")
    if path.suffix.lower() not in (".py", ".toml"):
        raise ValueError(f"transient run takes a scenario script (.py) or a scene file (.toml), got {path} "
                         "(scenarios/ holds the scripts, scenarios/scenes/ the scenes)")
    if path.suffix.lower() == ".toml":
        from transient.study.scene import load_scene, run_scene

        from transient.study.scenario import default_root

        where = default_root() / path.stem
        ap = argparse.ArgumentParser(prog=f"transient run {path}")
        ap.add_argument("--out", default=str(where), help=f"output folder (default: {where})")
        a = ap.parse_args(args)
        _, scalars = run_scene(load_scene(path), a.out)
        for k, v in scalars.items():
            print(f"{k:24s} {v}")
        print(f"written: {a.out}")
        return 0
    sys.argv = [str(path), *args]
    runpy.run_path(str(path), run_name="__main__")
    return 0


def _sweep(a) -> int:
    from transient.study.scene import load_scene
    from transient.study.sweep import parse_params, sweep

    values = parse_params(a.param)
    res = sweep(load_scene(a.scene), values, store=a.store, workers=a.workers, scheduler=a.scheduler)
    print(res.message)
    for f in res.failures:
        print(f"  failed: {f}")
    print(f"table: {Path(res.store) / 'results.parquet'} and results.csv")
    return 0 if res.success else 1


def _bench(a, parser) -> int:
    from transient import bench

    if a.list or not a.name:
        import importlib

        for n in bench.names():
            print(f"{n:10s} {importlib.import_module(f'transient.bench.{n}').TITLE}")
        return 0
    text, path = bench.run(a.name, a.out, quick=a.quick)
    print(text)
    print(f"\nwritten: {path} and {Path(a.out) / 'benchmarks.md'}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    a = parser.parse_args(argv)
    try:
        if a.command == "run":
            return _run_scenario(Path(a.scenario), a.args)
        if a.command == "sweep":
            return _sweep(a)
        return _bench(a, parser)
    except KeyboardInterrupt as e:  # a long run's Interrupted says where its checkpoint is
        text = getattr(e, "command_line", "") or str(e)
        print(f"transient: {text}" if text else "transient: interrupted", file=sys.stderr)
        return 130
    except (ValueError, TypeError, OSError, RuntimeError, ImportError, MemoryError) as e:
        if a.traceback:
            raise
        shell = getattr(e, "command_line", "")  # an error with advice for the shell (a checkpoint: --fresh)
        print(f"transient: error: {' '.join(shell.split()) if shell else _one_line(e)}", file=sys.stderr)
        return 2


def _one_line(e: BaseException) -> str:
    """The error as one line; an OS error without our wording gets its path and errno's reason."""
    if isinstance(e, MemoryError) and not str(e):
        return "out of memory; use a coarser grid or fewer outputs"
    if isinstance(e, OSError) and e.filename is not None:
        from transient.results import file_error

        text = str(file_error(e, e.filename, "use"))
    else:
        text = str(e) or type(e).__name__
    return " ".join(text.split())


if __name__ == "__main__":
    sys.exit(main())
