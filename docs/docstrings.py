"""The package's docstring habits, rewritten into the numpy style that Sphinx's napoleon reads, and a check that
every field section then reads right.

The docstrings are written for reading in the source (and ``help()``). Their field sections (``Parameters``,
``Attributes``, ...) put the unit in brackets after the name and the description after the colon::

    diameter, length, clearance [m] : journal diameter D, bearing length L, radial clearance C.
    viscosity [Pa s], bulk_modulus [Pa] : mu and beta (paper: 1e9; ...).
    load : total axial load [N]; speed_rpm : shaft speed [rpm]; ambient_film : ...
        an indented continuation of the last description.
    length L [m] (x), width B [m] (y), viscosity mu [Pa s].

Napoleon reads ``name : type`` and would take ``viscosity [Pa s]`` for a name and the description for a type
(and Sphinx then reads ``:param viscosity [Pa s]:`` as type ``viscosity [Pa`` of a parameter ``s]``).
:func:`fields` rewrites every entry to ``names : [unit]`` with the description on the indented lines below, splits
several entries written on one line (``a : ...; b : ...``), and moves a paragraph written at the entries'
indentation after a blank line (prose about the whole call) into a ``Notes`` section. A section header with a
qualifier (``Parameters (SI)``) becomes the plain header napoleon knows.

:func:`problems` parses a docstring with napoleon itself and names every field whose name is not a parameter
name or whose type is prose: the docs build turns each into a warning (an error under ``-W``) and
``tests/test_docs_api.py`` runs it over every public docstring.
"""

import re

FIELD_SECTIONS = ("Parameters", "Other Parameters", "Keyword Arguments", "Attributes")
SECTIONS = FIELD_SECTIONS + ("Returns", "Yields", "Raises", "Warns", "Notes", "Examples", "References",
                             "See Also", "Warnings", "Methods", "Failures")
NAME = r"\*{0,2}[A-Za-z_]\w*"
UNIT = r"\[[^\[\]]*\]"
ITEM = rf"{NAME}(?:\s+{UNIT})?"
ITEMS = rf"{ITEM}(?:\s*,\s*{ITEM})*"
ENTRY = re.compile(rf"^(?P<items>{ITEMS})\s+:(?:\s+(?P<text>.*?))?\s*$")
BARE = re.compile(rf"^(?P<items>{ITEMS})\s*$")
NEXT_ENTRY = re.compile(rf";\s+(?={ITEMS}\s+:\s)")
# "length L [m] (x), width B [m] (y), viscosity mu [Pa s]." -- names with a symbol and a unit, no description
SYMBOL = rf"{NAME}(?:\s+[A-Za-z_]\w*)?\s+{UNIT}(?:\s+\([^()]*\))?"
SYMBOL_LIST = re.compile(rf"^{SYMBOL}(?:\s*,\s*{SYMBOL})*\.?\s*$")
SYMBOL_ITEM = re.compile(rf"(?P<name>{NAME})(?:\s+(?P<symbol>[A-Za-z_]\w*))?\s+(?P<unit>{UNIT})"
                         rf"(?:\s+\((?P<note>[^()]*)\))?")
PARAM_NAME = re.compile(rf"^{NAME}$")
HEADER = re.compile(r"^(?P<name>[A-Z][A-Za-z ]*?)(?:\s*\(.*\))?\s*$")


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _is_header(lines: list[str], i: int) -> str | None:
    """The section name if lines[i] is a numpy section header (a known name, optionally with a qualifier in
    parentheses, underlined by dashes), else None."""
    if i + 1 >= len(lines) or not lines[i + 1].strip() or set(lines[i + 1].strip()) != {"-"}:
        return None
    m = HEADER.match(lines[i].strip())
    return m["name"] if m and m["name"] in SECTIONS else None


def _split_items(items: str) -> tuple[list[str], list[str]]:
    names, units = [], []
    for item in re.split(r"\s*,\s*(?![^\[]*\])", items.strip()):
        m = re.match(rf"^({NAME})(?:\s+({UNIT}))?$", item)
        names.append(m[1])
        units.append(m[2] or "")
    return names, units


def _each(units: list[str]) -> list[str]:
    """The unit of every name: ``a, b, c [m]`` gives all three the last name's unit."""
    return [units[-1]] * len(units) if units[-1] and not any(units[:-1]) else units


def _type(units: list[str]) -> str:
    """One unit for the group when all are equal, else the units in the names' order."""
    each = _each(units)
    if not any(each):
        return ""
    return each[0] if len(set(each)) == 1 else ", ".join(u or "[-]" for u in each)


def _entry(names: list[str], units: list[str], text: list[tuple[int, str]], indent: int) -> list[str]:
    head = " " * indent + ", ".join(names)
    kind = _type(units)
    out = [head + (f" : {kind}" if kind else "")]
    out += [" " * (indent + 4 + extra) + t if t else "" for extra, t in text]
    return out


def _symbol_list(line: str, indent: int) -> list[str]:
    out = []
    for m in SYMBOL_ITEM.finditer(line):
        note = " ".join(s for s in (m["symbol"], f"({m['note']})" if m["note"] else None) if s)
        out += _entry([m["name"]], [m["unit"]], [(0, note)] if note else [], indent)
    return out


def _field_section(body: list[str], indent: int, one_name: bool) -> tuple[list[str], list[str]]:
    """The rewritten entries of one field section and its prose (for a Notes section); ``one_name`` writes a
    group ``a, b : text`` as one entry per name (napoleon's attributes take one name each)."""
    entries: list[list] = []  # [names, units, [(extra indent, text)], first line is a symbol list]
    prose: list[str] = []
    blank_before = True
    in_prose = False
    for k, line in enumerate(body):
        if not line.strip():
            blank_before = True
            if in_prose:
                prose.append("")
            elif entries:
                entries[-1][2].append((0, ""))
            continue
        level = _indent(line)
        text = line.strip()
        deeper_next = next((_indent(nx) > indent for nx in body[k + 1:] if nx.strip()), False)
        if level <= indent:
            m = ENTRY.match(text)
            if m is None and BARE.match(text) and (deeper_next or blank_before):
                m = BARE.match(text)
            if m is not None:
                in_prose = False
                names, units = _split_items(m["items"])
                first = m.groupdict().get("text") or ""
                entries.append([names, units, [(0, first)] if first else [], False])
            elif SYMBOL_LIST.match(text):
                in_prose = False
                entries.append([None, None, [(0, text)], True])
            elif in_prose or blank_before or not entries:
                if prose and not in_prose:
                    prose.append("")
                in_prose = True
                prose.append(line)
            else:
                entries[-1][2].append((0, text))
        elif in_prose or not entries:
            in_prose = True
            prose.append(line)
        else:
            entries[-1][2].append((max(0, level - indent - 4), text))
        blank_before = False
    out = []
    for names, units, text, symbols in entries:
        if symbols:
            out += _symbol_list(text[0][1], indent)
            continue
        while text and not text[-1][1]:
            text.pop()
        # "a : ...; b : ..." on the entry's own lines (not in deeper blocks): one entry each
        pieces: list[tuple[list, list, list]] = [(names, units, [])]
        for extra, t in text:
            parts = NEXT_ENTRY.split(t) if extra == 0 else [t]
            pieces[-1][2].append((extra, parts[0].rstrip()))
            for part in parts[1:]:
                m = ENTRY.match(part)
                n, u = _split_items(m["items"])
                pieces.append((n, u, [(0, m["text"] or "")]))
        for n, u, t in pieces:
            while t and not t[0][1]:
                t.pop(0)
            groups = [([a], [b]) for a, b in zip(n, _each(u))] if one_name else [(n, u)]
            for n1, u1 in groups:
                out += _entry(n1, u1, t, indent)
    return out, prose


def fields(lines: list[str]) -> None:
    """Rewrite the field sections of a docstring (a list of lines, in place) into napoleon's numpy style."""
    out: list[str] = []
    i = 0
    while i < len(lines):
        name = _is_header(lines, i)
        if name is None:
            out.append(lines[i])
            i += 1
            continue
        indent = _indent(lines[i])
        out += [" " * indent + name, lines[i + 1]]
        j = i + 2
        while j < len(lines) and not (_indent(lines[j]) <= indent and _is_header(lines, j)):
            j += 1
        body = lines[i + 2: j]
        if name in FIELD_SECTIONS:
            entries, prose = _field_section(body, indent, one_name=name == "Attributes")
            while prose and not prose[-1].strip():
                prose.pop()
            out += entries
            if prose:
                out += ["", " " * indent + "Notes", " " * indent + "-----"] + prose
            if j < len(lines):
                out.append("")
        else:
            out += body
        i = j
    lines[:] = out


def problems(lines: list[str], what: str = "class", name: str = "") -> list[str]:
    """What napoleon would render wrongly in this (rewritten) docstring: a section header it does not know
    (``Parameters (SI)``: the section would be plain text), a field whose name is not a parameter name
    (``viscosity [Pa s]``, a sentence) or whose type is a description (longer than 40 characters)."""
    from sphinx.ext.napoleon import Config, NumpyDocstring

    config = Config(napoleon_use_param=True, napoleon_use_rtype=True, napoleon_google_docstring=False,
                    napoleon_custom_sections=["Failures"])
    found = [f"section header {lines[i].strip()!r} is not one napoleon knows" for i in range(len(lines) - 1)
             if lines[i].strip() and lines[i + 1].strip() and set(lines[i + 1].strip()) == {"-"}
             and lines[i].strip() not in SECTIONS and len(lines[i + 1].strip()) >= 3]
    rendered = str(NumpyDocstring(list(lines), config, what=what, name=name)).splitlines()
    for line in rendered:
        m = re.match(r"^:param (.+?):", line) or re.match(r"^\.\. attribute:: (.+)$", line)
        if m and not PARAM_NAME.match(m[1].replace("\\", "")):
            found.append(f"field name {m[1]!r} is not a parameter name")
        t = re.match(r"^:type (.+?): (.*)$", line) or re.match(r"^\s+:type: (.*)$", line)
        if t and len(t[t.lastindex]) > 40:
            found.append(f"field type {t[t.lastindex]!r} is a description")
    return found
