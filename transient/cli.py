"""The ``transient`` command.

    transient run SCENARIO.py [args ...]   run a scenario script (figures and files go where it says)
    transient bench NAME [--out DIR] [--quick]
                                           run a benchmark, write its table/plot under DIR (docs/);
                                           --quick: a fast smoke version (where the benchmark has one)
    transient --version
"""

from __future__ import annotations

import argparse
import runpy
import sys
from pathlib import Path

import transient


def _bench_film(out: Path, quick: bool = False) -> str:
    from transient.bench import callbacks, film
    rows = film.run()
    text = "## Film operator: residual and Jacobian evaluation time against grid size\n\n" + film.markdown(rows)
    text += ("\n\n## Integrator callback overhead\n\n"
             "Wall time per right-hand-side call of a CVODE run (linear decay, 1000 states, sparse diagonal "
             "Jacobian): the numba kernel alone, scikit-sundae called directly, and through `transient.solve`.\n\n"
             + callbacks.markdown(callbacks.run()))
    return text


def _bench_journal(out: Path, quick: bool = False) -> str:
    from transient.bench import journal
    result = journal.run(quick=quick)
    journal.write(result, out)
    return "## Journal orbit (seed 003): work-precision at 6000 rpm\n\n" + journal.markdown(result)  # has the figure


def _bench_ball(out: Path, quick: bool = False) -> str:
    from transient.bench import ball
    res = ball.run(out_dir=str(out))
    return ("## Thrust ball bearing: 200-ball-pass sequence, work-precision (seed 002)\n"
            + res["markdown"] + "\n\n![work-precision](bench_ball.png)")


def _bench_roughness(out: Path, quick: bool = False) -> str:
    from transient.bench import roughness
    return "## Rough-surface generation (seed 000)\n" + roughness.bench_surface()


def _bench_pad(out: Path, quick: bool = False) -> str:
    from transient.bench import thrust_pad
    return thrust_pad.run()  # has its own section heading


BENCHES = {"film": _bench_film, "journal": _bench_journal, "ball": _bench_ball, "roughness": _bench_roughness,
           "pad": _bench_pad}


def _write_bench(name: str, text: str, out: Path) -> Path:
    """Write docs/bench/NAME.md and rebuild docs/benchmarks.md from all bench sections."""
    sections = out / "bench"
    sections.mkdir(parents=True, exist_ok=True)
    path = sections / f"{name}.md"
    path.write_text(f"<!-- written by `transient bench {name}`; do not edit by hand -->\n{text}\n")
    parts = ["# Benchmarks\n",
             "Every section below is written by `transient bench NAME` on this project's 2-core machine. "
             "Ratios between methods measured in one run are the meaningful numbers; absolute seconds depend "
             "on the machine.\n"]
    for sec in sorted(sections.glob("*.md")):
        parts.append(f"\n<!-- section: {sec.name} -->\n" + sec.read_text().split("\n", 1)[1])
    (out / "benchmarks.md").write_text("\n".join(parts))
    return path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="transient", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"transient {transient.__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p_run = sub.add_parser("run", help="run a scenario script")
    p_run.add_argument("scenario", help="path to a scenario .py file (see scenarios/)")
    p_run.add_argument("args", nargs=argparse.REMAINDER, help="arguments passed to the scenario")
    p_bench = sub.add_parser("bench", help="run a benchmark and write its results under docs/")
    p_bench.add_argument("name", choices=sorted(BENCHES))
    p_bench.add_argument("--out", default="docs", help="output folder (default: docs)")
    p_bench.add_argument("--quick", action="store_true", help="fast smoke version (few settings)")
    a = parser.parse_args(argv)

    if a.command == "run":
        path = Path(a.scenario)
        if not path.is_file():
            parser.error(f"scenario file not found: {path}")
        sys.argv = [str(path), *a.args]
        runpy.run_path(str(path), run_name="__main__")
        return 0
    out = Path(a.out)
    text = BENCHES[a.name](out, quick=a.quick)
    path = _write_bench(a.name, text, out)
    print(text)
    print(f"\nwritten: {path} and {out / 'benchmarks.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
