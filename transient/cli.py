"""The ``transient`` command.

    transient run SCENARIO.py [args ...]   run a scenario script (``--help`` lists its options; every scenario
                                           takes ``--quick`` and ``--out DIR``)
    transient bench NAME [--out DIR] [--quick]
                                           run a benchmark; its section, figures and raw numbers go to DIR
                                           (default ./bench_results; ``--out docs`` updates the committed tables)
    transient bench --list                 the benchmarks and what each measures
    transient --version

Mistakes (a missing file, an unknown benchmark, an out-of-range parameter) print one line naming what is
wrong; Ctrl-C stops with one line (long runs say where their checkpoint is).
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
    p_run = sub.add_parser("run", help="run a scenario script")
    p_run.add_argument("scenario", help="path to a scenario .py file (see scenarios/)")
    p_run.add_argument("args", nargs=argparse.REMAINDER, help="arguments passed to the scenario")
    p_bench = sub.add_parser("bench", help="run a benchmark and write its section, figures and numbers")
    p_bench.add_argument("name", nargs="?", help="benchmark name (see --list)")
    p_bench.add_argument("--list", action="store_true", help="list the benchmarks")
    p_bench.add_argument("--out", default="bench_results", help="output folder (default: ./bench_results)")
    p_bench.add_argument("--quick", action="store_true", help="fast smoke version (few settings)")
    return parser


def _run_scenario(path: Path, args: list[str]) -> int:
    if not path.is_file():
        raise FileNotFoundError(f"scenario file not found: {path}")
    sys.argv = [str(path), *args]
    runpy.run_path(str(path), run_name="__main__")
    return 0


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
        return _bench(a, parser)
    except KeyboardInterrupt as e:  # a long run's Interrupted says where its checkpoint is
        print(f"transient: {e}" if str(e) else "transient: interrupted", file=sys.stderr)
        return 130
    except (ValueError, TypeError, FileNotFoundError, RuntimeError) as e:
        if a.traceback:
            raise
        print(f"transient: error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
