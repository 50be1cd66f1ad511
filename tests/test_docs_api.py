"""The API pages read right: every public docstring of the package, rewritten by the docs build's hook
(docs/conf.py, docs/docstrings.py), parses under napoleon into fields whose names are parameter names and whose
types are units, not descriptions. The docs build warns (an error under ``-W``) on the same check."""

import importlib
import importlib.util
import inspect
import pkgutil
from pathlib import Path

import pytest

pytest.importorskip("sphinx.ext.napoleon")

import transient  # noqa: E402

DOCS = Path(__file__).resolve().parents[1] / "docs"


def _load(name):
    spec = importlib.util.spec_from_file_location(f"docs_{name}", DOCS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


docstrings = _load("docstrings")
conf = _load("conf")


def _public():
    """(name, object) of every public class and function defined in the package, and of every public method and
    property of those classes (what autodoc renders)."""
    seen = set()
    for info in pkgutil.walk_packages(transient.__path__, "transient."):
        module = importlib.import_module(info.name)
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module.__name__:
                continue
            if not (inspect.isclass(obj) or inspect.isfunction(obj)):
                continue
            found = [(f"{info.name}.{name}", obj)]
            if inspect.isclass(obj):
                for m, attr in vars(obj).items():
                    f = attr.fget if isinstance(attr, property) else getattr(attr, "__func__", attr)
                    if (not m.startswith("_") or m == "__init__") and (inspect.isfunction(f) or isinstance(attr, property)):
                        found.append((f"{info.name}.{name}.{m}", f))
            for qualname, o in found:
                if id(o) not in seen and inspect.getdoc(o):
                    seen.add(id(o))
                    yield qualname, o


def _rendered(doc: str) -> list[str]:
    lines = inspect.cleandoc(doc).splitlines()
    conf._docstring(None, "class", "x", None, {}, lines)
    return lines


def _fields(lines):
    from sphinx.ext.napoleon import Config, NumpyDocstring

    out = str(NumpyDocstring(lines, Config(napoleon_use_param=True))).splitlines()
    params = [line.split(":")[1][len("param "):] for line in out if line.startswith(":param ")]
    types = {line.split(":")[1][len("type "):]: line.split(": ", 1)[1] for line in out if line.startswith(":type ")}
    return params, types


def test_every_public_docstring_reads_right():
    public = list(_public())
    assert len(public) > 300  # the walk found the package
    bad = []
    for name, obj in public:
        lines = inspect.getdoc(obj).splitlines()
        conf._docstring(None, "class", name, obj, {}, lines)
        bad += [f"{name}: {p}" for p in docstrings.problems(lines, "class", name)]
    assert not bad, "\n".join(bad)


def test_names_with_units_render_as_names_with_units():
    params, types = _fields(_rendered("""Summary.

        Parameters (SI)
        ----------
        diameter, length, clearance [m] : journal diameter D, bearing length L,
            radial clearance C.
        viscosity [Pa s], bulk_modulus [Pa] : mu and beta.
        supply_pressure [Pa, absolute] : pressure in the groove.
        load : total load [N]; speed_rpm [rpm] : shaft speed; grid : cells
            of the film.
        width W [m] (y), height H [m].
        groove : the oil feeds: a :class:`Groove` or None.

        With a closing remark on the whole call.
        """))
    assert params == ["diameter", "length", "clearance", "viscosity", "bulk_modulus", "supply_pressure", "load",
                      "speed_rpm", "grid", "width", "height", "groove"]
    assert types == {"diameter": "[m]", "length": "[m]", "clearance": "[m]", "viscosity": "[Pa s], [Pa]",
                     "bulk_modulus": "[Pa s], [Pa]", "supply_pressure": "[Pa, absolute]", "speed_rpm": "[rpm]",
                     "width": "[m]", "height": "[m]"}


def test_the_journal_bearing_page_names_its_parameters():
    params, types = _fields(_rendered(transient.JournalBearing.__doc__))
    assert {"diameter", "viscosity", "bulk_modulus", "supply_pressure", "cavitation_pressure", "groove"} <= set(params)
    assert types["viscosity"] == "[Pa s], [Pa]" and types["supply_pressure"] == "[Pa, absolute]"


@pytest.mark.parametrize("doc, problem", [
    ("Parameters\n----------\nviscosity [Pa s] : mu.\n", "not a parameter name"),
    ("Parameters\n----------\nrotor : the rotor, carried by its bearings at the nodes given.\n", "is a description"),
    ("Parameters (SI)\n----------\nload : the load.\n", "not one napoleon knows"),
])
def test_the_check_names_what_napoleon_would_garble(doc, problem):
    found = docstrings.problems(doc.splitlines())
    assert len(found) == 1 and problem in found[0]
