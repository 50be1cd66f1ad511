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
napoleon_custom_sections = ["Failures"]
templates_path = ["_templates"]
nitpicky = False

html_theme = "furo"
html_title = "transient"

# -- docstrings --------------------------------------------------------------------------------------------------
# The package's docstrings are written for reading in the source (and help()): numpy-style sections with units in
# the header ("Parameters (SI)") and |x| for magnitudes. Two rewrites make them valid reStructuredText for the site.
import re  # noqa: E402

_LITERAL = re.compile(r"(``.*?``)")


def _escape_bars(line: str) -> str:
    """|x| is a magnitude in the docstrings, a substitution in reST: escape the bars outside ``literals``."""
    parts = _LITERAL.split(line)
    return "".join(p if p.startswith("``") else re.sub(r"(?<!\\)\|", r"\\|", p) for p in parts)


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _docstring(app, what, name, obj, options, lines):
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
        if re.fullmatch(r"\s*Parameters \(.*\)\s*", line) and i + 1 < len(lines) and set(lines[i + 1].strip()) == {"-"}:
            lines[i] = line[: len(line) - len(line.lstrip())] + "Parameters"
        if "|" in line and not line.lstrip().startswith(("+", "|")):
            lines[i] = _escape_bars(lines[i])


def setup(app):
    app.connect("autodoc-process-docstring", _docstring, priority=400)
