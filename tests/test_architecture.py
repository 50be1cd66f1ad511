"""The package's import rules (docs/architecture.md), read from the import graph of the source files."""

import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "transient"


def _imports():
    """(importing module's room, imported module) for every ``transient.*`` import in the package."""
    out = []
    for path in PKG.rglob("*.py"):
        rel = path.relative_to(PKG)
        room = rel.parts[0] if len(rel.parts) > 1 else rel.stem
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("transient"):
                names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names if a.name.startswith("transient")]
            else:
                continue
            for n in names:
                parts = n.split(".")
                if len(parts) > 1:
                    out.append((room, str(rel), parts[1]))
    return out


IMPORTS = _imports()


def _violations(rooms_from, rooms_to):
    return sorted({(f, to) for room, f, to in IMPORTS if room in rooms_from and to in rooms_to})


def test_the_graph_was_read():
    assert len(IMPORTS) > 100
    assert {"fv", "physics", "models", "solvers", "study", "plots", "analysis"} <= {r for r, _, _ in IMPORTS}


def test_fv_and_physics_never_import_each_other():
    assert _violations({"fv"}, {"physics"}) == []
    assert _violations({"physics"}, {"fv"}) == []


def test_models_never_import_analysis_study_plots():
    assert _violations({"models"}, {"analysis", "study", "plots"}) == []


def test_analysis_never_imports_models_study_plots():
    assert _violations({"analysis"}, {"models", "study", "plots"}) == []


def test_plots_import_results_and_analysis_only():
    allowed = {"results", "analysis", "plots"}
    bad = sorted({(f, to) for room, f, to in IMPORTS if room == "plots" and to not in allowed})
    assert bad == []


def test_only_the_cli_benches_and_the_package_root_import_study():
    """Scenarios (outside the package) may; inside it only the runners (CLI, benches) and the public
    re-exports of __init__."""
    bad = sorted({(f, to) for room, f, to in IMPORTS if to == "study" and room not in ("study", "cli", "bench", "__init__")})
    assert bad == []


def test_solvers_and_results_know_no_model():
    assert _violations({"solvers", "results", "checks"}, {"models", "study", "plots", "analysis"}) == []


def test_every_scenario_answers_help_without_running(capsys):
    """--help prints the options and exits at once (argparse), for every scenario script."""
    import runpy
    import sys

    import pytest

    for path in sorted((PKG.parent / "scenarios").glob("*.py")):
        argv = sys.argv
        sys.argv = [str(path), "--help"]
        try:
            with pytest.raises(SystemExit) as e:
                runpy.run_path(str(path), run_name="__main__")
        finally:
            sys.argv = argv
        assert e.value.code == 0, path.name
        text = capsys.readouterr().out
        assert "--quick" in text and "--out" in text, path.name
