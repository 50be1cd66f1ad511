"""Every benchmark module imports and is listed by ``transient bench --list``: one broken import would make
``transient.bench.names()`` (and with it every ``transient bench`` command) fail."""

import importlib
import pkgutil

import pytest

import transient.bench as bench

MODULES = sorted(m.name for m in pkgutil.iter_modules(bench.__path__) if not m.name.startswith("_"))


@pytest.mark.parametrize("name", MODULES)
def test_bench_module_imports(name):
    module = importlib.import_module(f"transient.bench.{name}")
    if hasattr(module, "main"):
        assert isinstance(module.TITLE, str) and module.TITLE


def test_bench_names_lists_every_bench_module():
    with_main = [n for n in MODULES if hasattr(importlib.import_module(f"transient.bench.{n}"), "main")]
    assert bench.names() == with_main
    assert {"ehl", "ehl_line", "ehl_point", "journal", "orbit_size"} <= set(with_main)
