"""The package's import rules (docs/architecture.md), read from the import graph of the source files."""

import ast
import functools
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


def _module_imports():
    """The import edges of the package at ``PKG`` (parsed once per package root)."""
    return _imports_under(PKG)


@functools.lru_cache(maxsize=None)
def _imports_under(root):
    """(importing module, imported module) for every ``transient.*`` import, as dotted module names; imports inside
    functions count (``ast.walk`` sees them). ``from transient.a import b`` counts as an import of ``transient.a.b``
    when that is a module, else of ``transient.a``."""
    modules = {".".join(("transient",) + p.relative_to(root).with_suffix("").parts).removesuffix(".__init__")
               for p in root.rglob("*.py")}
    out = []
    for path in root.rglob("*.py"):
        me = ".".join(("transient",) + path.relative_to(root).with_suffix("").parts).removesuffix(".__init__")
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("transient"):
                for a in node.names:
                    sub = f"{node.module}.{a.name}"
                    out.append((me, sub if sub in modules else node.module))
            elif isinstance(node, ast.Import):
                out.extend((me, a.name) for a in node.names if a.name.startswith("transient"))
    return out, modules


def _cycles_in(folder):
    """The import circles among the modules of one package folder (its ``__init__`` re-exports left out)."""
    edges, modules = _module_imports()
    inside = {m for m in modules if m.startswith(folder + ".")}
    graph = {m: set() for m in inside}
    for a, b in edges:
        if a in inside and b in inside and b != a:
            graph[a].add(b)
    cycles, state = [], {}

    def visit(m, path):
        state[m] = 1
        for n in sorted(graph[m]):
            if state.get(n) == 1:
                cycles.append(path[path.index(n):] + [n])
            elif n not in state:
                visit(n, path + [n])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m, [m])
    return cycles


def test_no_import_circle_inside_a_model_folder():
    """A model folder is a set of blocks with arrows one way (imports inside functions count)."""
    folders = sorted({p.parent for p in (PKG / "models").rglob("*.py") if p.parent != PKG / "models"})
    assert len(folders) >= 4
    for folder in folders:
        name = ".".join(("transient",) + folder.relative_to(PKG).parts)
        assert _cycles_in(name) == [], name


def test_ehl_films_share_the_engine_and_never_borrow_sideways():
    """The line/roller and point contacts take what they share (Krylov solvers, the node-wise Schur reduction, the
    limiter, the dry contact, the error types, the complementarity element) from ``models/ehl`` and never import
    each other; ``models/ehl`` imports no model folder."""
    edges, _ = _module_imports()
    folder = lambda m: m.split(".")[2] if m.startswith("transient.models.") and m.count(".") >= 3 else None  # noqa: E731
    sideways = sorted((a, b) for a, b in edges if {folder(a), folder(b)} == {"point", "roller"})
    upward = sorted((a, b) for a, b in edges if folder(a) == "ehl" and folder(b) not in (None, "ehl"))
    assert sideways == [] and upward == []
    assert any(folder(a) == "point" and folder(b) == "ehl" for a, b in edges)


def test_ehl_films_iterate_on_the_engines_one_newton():
    """The point film's and the line/roller films' FBNS Newton is ``models/ehl/newton.py``'s: both facades import
    it, and its Armijo line search (the test ``(1 - 1e-4 s)``) is written nowhere else in the models."""
    edges, _ = _module_imports()
    assert ("transient.models.point.fbns", "transient.models.ehl.newton") in edges
    assert ("transient.models.roller.line_newton", "transient.models.ehl.newton") in edges
    armijo = sorted(str(p.relative_to(PKG)) for p in (PKG / "models").rglob("*.py") if "1e-4 * s)" in p.read_text())
    assert armijo == ["models/ehl/newton.py"]


def test_line_and_roller_films_take_their_rows_and_schur_matrix_from_the_engine():
    """The line's and the roller's films (Reynolds-condition and film-content forms) compute their rows with
    ``models/ehl/rows.py``'s one kernel and build their Schur matrix with ``models/ehl/reduced.py``'s; the rows'
    Poiseuille face conductance is written in that kernel only among the line's and the roller's modules."""
    edges, _ = _module_imports()
    for module in ("roller.ehl_problem", "roller.line_fbns"):
        assert (f"transient.models.{module}", "transient.models.ehl.rows") in edges, module
    for module in ("roller.line_fbns", "roller.roller_fbns"):
        assert (f"transient.models.{module}", "transient.models.ehl.reduced") in edges, module
    face = sorted(str(p.relative_to(PKG)) for p in (PKG / "models").rglob("*.py")
                  if p.parent.name in ("ehl", "roller") and "0.5 * (eps[" in p.read_text())
    assert face == ["models/ehl/rows.py"]


def test_the_circle_finder_finds_a_circle(tmp_path, monkeypatch):
    """The rule above can fail: two modules importing each other (one inside a function) are a circle."""
    pkg = tmp_path / "transient" / "models" / "toy"
    pkg.mkdir(parents=True)
    (pkg / "a.py").write_text("from transient.models.toy.b import g\n")
    (pkg / "b.py").write_text("def g():\n    from transient.models.toy import a\n")
    monkeypatch.setitem(globals(), "PKG", tmp_path / "transient")
    assert _cycles_in("transient.models.toy") != []


def test_results_and_checks_import_nothing_above_them():
    """``results.py`` and ``checks.py`` sit at the bottom: they import only ``_version`` (not the package root, not
    a room); ``results.py`` also takes the memory cap of loaded files from ``checks.py``, which is below it."""
    edges, _ = _module_imports()
    allowed = {"transient.results": ("transient._version", "transient.checks"), "transient.checks": ("transient._version",)}
    bad = sorted((a, b) for a, b in edges if a in allowed and b not in allowed[a])
    assert bad == []


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


# ---- no option grab-bags: at most 12 parameters ------------------------------------------------------------------
MAX_PARAMETERS = 12
#: numba kernels take their data as arguments (grouped in named tuples where they are many); ``intrinsic`` is
#: numba's too.
NUMBA_DECORATORS = {"njit", "jit", "intrinsic", "generated_jit", "vectorize", "guvectorize"}
#: Constructors of physical parameter sets: each parameter is a quantity of the element (its geometry, its
#: lubricant, its load and speed) or of its film's discretisation.
PARAMETER_SETS = {"JournalBearing", "LineContact", "RollerContact", "PointContact", "SqueezeFilmDamper"}


def _decorator_name(d):
    d = d.func if isinstance(d, ast.Call) else d
    return d.attr if isinstance(d, ast.Attribute) else getattr(d, "id", "")


def _parameter_count(f) -> int:
    """Every parameter: positional-only, positional, keyword-only, ``*args`` and ``**kwargs`` (one each)."""
    a = f.args
    return (len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (a.vararg is not None)
            + (a.kwarg is not None))


def _public_functions(tree):
    """``(function, owner class or None)`` for every public function of a module: its top-level functions and the
    methods of its top-level classes whose names do not start with ``_`` (``__init__`` and ``__call__`` are
    public), in public classes."""
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and not node.name.startswith("_"):
            yield node, None
        elif isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            for f in node.body:
                if (isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))
                        and (not f.name.startswith("_") or f.name in ("__init__", "__call__"))):
                    yield f, node.name


def _long_signatures(root):
    """``(file, line, name, parameter count)`` of every public function or method over the limit, ``self`` and
    ``cls`` not counted, the exceptions aside (a method is named ``Class.method``)."""
    out = []
    for path in sorted(root.rglob("*.py")):
        if any(part.startswith("_") and part != "__init__.py" for part in path.relative_to(root).parts):
            continue
        tree = ast.parse(path.read_text())
        for f, cls in _public_functions(tree):
            n = _parameter_count(f)
            if cls is not None and f.args.args and f.args.args[0].arg in ("self", "cls") \
                    and not {_decorator_name(d) for d in f.decorator_list} & {"staticmethod"}:
                n -= 1
            if (n <= MAX_PARAMETERS or {_decorator_name(d) for d in f.decorator_list} & NUMBA_DECORATORS
                    or (f.name == "__init__" and cls in PARAMETER_SETS)):
                continue
            out.append((str(path.relative_to(root)), f.lineno, f.name if cls is None else f"{cls}.{f.name}", n))
    return out


def test_every_model_runs_through_the_one_run_driver():
    """A model's run in the time domain goes through ``solvers/model_run.py`` (start, recorder, checkpoints, stop,
    touch event, wall), never straight to the long-run driver ``run_long`` beneath it."""
    direct = sorted(str(path.relative_to(PKG)) for path in (PKG / "models").rglob("*.py")
                    for node in ast.walk(ast.parse(path.read_text()))
                    if isinstance(node, ast.ImportFrom) and node.module == "transient.solvers.longrun"
                    and any(a.name == "run_long" for a in node.names))
    assert direct == [], f"run_long imported by {direct}; a model's run goes through transient.solvers.model_run"


def test_no_public_function_takes_more_than_12_parameters():
    """Settings travel as objects (``transient.solvers.settings``, ``Steps``, ``NewtonSettings``,
    ``ShootingSettings``, ``TrackSettings``): every parameter counts, keyword-only ones and ``**kwargs`` too; the
    exceptions are numba kernels and constructors of physical parameter sets (``PARAMETER_SETS``)."""
    offenders = _long_signatures(PKG)
    assert offenders == [], "more than 12 parameters: " + "; ".join(f"{name} ({n}, {f}:{line})"
                                                                   for f, line, name, n in offenders)


def test_the_parameter_rule_can_fail(tmp_path):
    """Thirteen parameters are caught in a function and a method, keyword-only ones and ``**kwargs`` included;
    a private function, a nested one, a numba kernel and a parameter set's constructor are not."""
    names = ", ".join(f"a{i}" for i in range(13))
    eleven, twelve = (", ".join(f"a{i}" for i in range(k)) for k in (11, 12))
    (tmp_path / "m.py").write_text(
        f"from numba import njit\n"
        f"def bag({names}):\n    pass\n"
        f"class Model:\n    def run(self, {names}):\n        pass\n"
        f"    def _private(self, {names}):\n        pass\n"
        f"def keywords(a0, *, {names}):\n    pass\n"
        f"def kwargs({twelve}, **legacy):\n    pass\n"
        f"def fine({eleven}, **legacy):\n    def inner({names}):\n        pass\n"
        f"@njit(cache=True)\ndef kernel({names}):\n    pass\n"
        f"class JournalBearing:\n    def __init__(self, {names}):\n        pass\n")
    assert [(name, n) for _, _, name, n in _long_signatures(tmp_path)] == [
        ("bag", 13), ("Model.run", 13), ("keywords", 14), ("kwargs", 13)]


TESTS = Path(__file__).resolve().parent
#: test folders that mirror something outside the package (the scenario scripts)
OUTSIDE_THE_PACKAGE = {"scenarios"}
#: test folders of external reference data (other codes' results, published tables), read by the tests; no tests
REFERENCE_DATA = {"data"}


def _test_folders():
    return sorted(p.relative_to(TESTS) for p in TESTS.rglob("*") if p.is_dir() and p.name != "__pycache__"
                  and not any(part.startswith(".") for part in p.relative_to(TESTS).parts))


def test_the_test_tree_mirrors_the_package():
    """Every test folder names a folder of the package (``tests/models/journal`` -> ``transient/models/journal``),
    and no ``test_*.py`` of a model, a solver or a physical law sits loose at the top of ``tests/``."""
    folders = _test_folders()
    assert folders, "tests/ has no sub-folders"
    for rel in folders:
        if rel.parts[0] in REFERENCE_DATA:
            assert not list((TESTS / rel).glob("test_*.py")), f"tests/{rel} holds reference data, not tests"
        elif rel.parts[0] in OUTSIDE_THE_PACKAGE:
            assert (TESTS.parent / rel).is_dir(), rel
        else:
            assert (PKG / rel).is_dir(), f"tests/{rel} mirrors no folder transient/{rel}"
    loose = {p.stem for p in TESTS.glob("test_*.py") if not p.stem.startswith("test_docs_")}  # the docs site's
    assert loose <= {"test_architecture", "test_api_edges", "test_cli", "test_figures", "test_fuzz_inputs",
                     "test_reliability", "test_result_bases", "test_results"}, loose


#: the entry points of the time domain, by name: every model's run is one of these
RUN_LIKE = {"run", "sequence", "descent", "transient"}


def test_every_run_like_method_is_counted_and_within_the_limit():
    """The time-domain entry points (``run``, ``sequence``, ``descent``, ``transient``) of every model are public
    methods the parameter rule reads -- the journal orbit, the rotor system, the pad, the ball bearing, the point,
    line and roller contacts -- and each takes at most 12 parameters, ``**legacy`` counted."""
    found = {}
    for path in sorted((PKG / "models").rglob("*.py")):
        for f, cls in _public_functions(ast.parse(path.read_text())):
            if cls is not None and f.name in RUN_LIKE:
                found[f"{cls}.{f.name}"] = _parameter_count(f) - 1  # self
    assert {"JournalOrbit.run", "RotorBearingSystem.run", "ThrustPad.descent", "ThrustBallBearing.sequence",
            "PointContact.transient", "LineContact.transient", "RollerContact.transient"} <= set(found), found
    assert {name: n for name, n in found.items() if n > MAX_PARAMETERS} == {}
