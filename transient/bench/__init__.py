"""Benchmarks behind ``transient bench NAME``: one protocol for all.

A bench is a module ``transient.bench.NAME`` with

* ``TITLE``: one line saying what it measures;
* ``main(out: Path, quick: bool = False) -> str``: runs every method side by side in one run, writes its
  figures and raw numbers into ``out`` and returns its markdown section (figures linked by file name).

:func:`write_section` files the section as ``out/bench/NAME.md`` and rebuilds ``out/benchmarks.md`` from
all sections there. ``transient bench`` writes to ``./bench_results`` unless told ``--out DIR`` (``--out
docs`` updates the committed tables).
"""

from __future__ import annotations

import importlib
import json
import pkgutil
import time
from pathlib import Path


def timed(fn):
    """``(fn(), wall [s], CPU [s] of this process)``: on a shared machine the CPU time is the fair measure."""
    t0, c0 = time.perf_counter(), time.process_time()
    r = fn()
    return r, time.perf_counter() - t0, time.process_time() - c0


def best_of(fn, repeats):
    """``(shortest wall time [s] of `repeats` calls of fn(), the last call's result)``."""
    best, out = float("inf"), None
    for _ in range(repeats):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def table(columns, rows) -> list[str]:
    """A markdown table's lines: the header of ``columns`` (cell texts), its rule, then ``rows`` (table lines)."""
    return ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns), *rows]


def save_raw(out, name: str, res: dict) -> None:
    """Write bench ``name``'s raw numbers ``res`` to ``out/bench_NAME.json`` (numpy numbers as floats)."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / f"bench_{name}.json").write_text(json.dumps(res, indent=1, default=float))


def names() -> list[str]:
    """The available benches (modules of this package that define ``main``)."""
    out = []
    for m in pkgutil.iter_modules(__path__):
        if not m.name.startswith("_") and hasattr(importlib.import_module(f"{__name__}.{m.name}"), "main"):
            out.append(m.name)
    return sorted(out)


def run(name: str, out, quick: bool = False) -> tuple[str, Path]:
    """Run bench ``name`` (``orbit-size`` and ``orbit_size`` are the same), write its section under ``out``;
    returns (markdown, path of the section)."""
    name = str(name).replace("-", "_")
    if name not in names():
        raise ValueError(f"bench = {name!r} is not a benchmark; available: {', '.join(names())}")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    text = importlib.import_module(f"{__name__}.{name}").main(out, quick=quick)
    return text, write_section(name, text, out)


def write_section(name: str, text: str, out) -> Path:
    """Write ``out/bench/NAME.md`` and rebuild ``out/benchmarks.md`` from all bench sections."""
    out = Path(out)
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
