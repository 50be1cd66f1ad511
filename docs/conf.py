"""Sphinx configuration of the transient documentation site: ``sphinx-build -W -b html docs docs/_build/html``.

The Markdown pages are read by MyST; the API reference is generated from the docstrings (autodoc, autosummary,
numpy-style sections by napoleon)."""

import os
import sys

sys.path.insert(0, os.path.abspath(".."))
os.environ.setdefault("NUMBA_DISABLE_JIT", "0")

project = "transient"
author = "the transient developers"
copyright = "the transient developers"
release = version = "0.1.0"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
exclude_patterns = ["_build", "bench", "**/*.json"]
myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3
autosummary_generate = True
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": False}
autodoc_typehints = "none"
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_param = False  # grouped names ("diameter, length, clearance [m]") stay one entry
napoleon_custom_sections = ["Failures"]
templates_path = ["_templates"]
nitpicky = False

html_theme = "furo"
html_title = "transient"

# -- docstrings --------------------------------------------------------------------------------------------------
# The package's docstrings are written for reading in the source (and help()): numpy-style sections with units in
# brackets after the names ("viscosity [Pa s] : text"), units in the header ("Parameters (SI)") and |x| for
# magnitudes. docstrings.fields rewrites the field sections into napoleon's numpy style (docstrings.py says how);
# two more rewrites make them valid reStructuredText; then docstrings.problems checks the result (a warning, so an
# error under -W, for every field napoleon would still render garbled).
import re  # noqa: E402

from sphinx.util import logging  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import docstrings  # noqa: E402

_LITERAL = re.compile(r"(``.*?``)")
_logger = logging.getLogger("transient.docs")


def _escape_bars(line: str) -> str:
    """|x| is a magnitude in the docstrings, a substitution in reST: escape the bars outside ``literals``."""
    parts = _LITERAL.split(line)
    return "".join(p if p.startswith("``") else re.sub(r"(?<!\\)\|", r"\\|", p) for p in parts)


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _docstring(app, what, name, obj, options, lines):
    docstrings.fields(lines)
    i = 0
    while i + 1 < len(lines):  # "text:" followed directly by a more indented block: a literal block in reST
        a, b = lines[i], lines[i + 1]
        if a.rstrip().endswith(":") and not a.rstrip().endswith("::") and b.strip() and _indent(b) > _indent(a) \
                and not re.search(r"\s:\s|^\s*\w+ :", a):
            lines[i] = a.rstrip() + ":"
            lines.insert(i + 1, "")
            j = i + 2
            while j < len(lines) and (not lines[j].strip() or _indent(lines[j]) > _indent(a)):
                j += 1
            if j < len(lines) and lines[j - 1].strip():
                lines.insert(j, "")  # the block ends with a blank line
            i += 1
        i += 1
    for i, line in enumerate(lines):
        if "|" in line and not line.lstrip().startswith(("+", "|")):
            lines[i] = _escape_bars(lines[i])


def _check(app, what, name, obj, options, lines):
    for problem in docstrings.problems(lines, what, name):
        _logger.warning(f"docstring of {name}: {problem}", type="transient", subtype="docstring")


def setup(app):
    app.connect("autodoc-process-docstring", _docstring, priority=400)
    app.connect("autodoc-process-docstring", _check, priority=450)  # napoleon's own rewrite runs at 500
