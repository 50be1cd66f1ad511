"""The roller scenario and the docs check the same statements of Park's paper: the scenario's list is the table of
docs/ehl.md (section 3), in order, and the count the other pages give is its length."""

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
WORDS = dict(enumerate(("no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")))


def _table_rows():
    text = (DOCS / "ehl.md").read_text()
    section = text[text.index("## 3. What the model reproduces"):text.index("## 4.")]
    return [m.group(1).strip() for m in re.finditer(r"^\| ([^|]+) \|", section, re.M)][1:]  # after the header


def test_the_scenario_checks_the_statements_of_the_docs_table():
    tree = ast.parse((ROOT / "scenarios" / "roller_ehl.py").read_text())  # its list, without importing the model
    node = next(n for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "STATEMENTS")
    statements = list(ast.literal_eval(node.value).values())
    assert statements == _table_rows()


def test_the_pages_count_the_same_statements():
    n = WORDS[len(_table_rows())]
    assert f"the paper's {n}\n  statements" in (DOCS / "validation.md").read_text()
    assert f"of the paper's {n} statements" in (DOCS / "disagreements.md").read_text()
    verdicts = re.findall(r"^\| [^|]+ \| \*\*(yes|partly|no)\*\*", (DOCS / "ehl.md").read_text(), re.M)
    said = re.search(r"(\w+) of the paper's \w+ statements are reproduced on its grid; (\w+) partly",
                     (DOCS / "disagreements.md").read_text())
    assert said and (said[1].lower(), said[2]) == (WORDS[verdicts.count("yes")], WORDS[verdicts.count("partly")])


def test_the_recorded_paper_grid_verdicts_are_the_tables():
    import json

    recorded = json.loads((DOCS / "ehl_94x45" / "roller_ehl.json").read_text())["statements"]
    table = re.findall(r"^\| ([^|]+) \| \*\*(yes|partly|no)\*\*", (DOCS / "ehl.md").read_text(), re.M)
    word = {"reproduced": "yes", "partly": "partly", "NOT reproduced": "no"}
    assert [(v["statement"], word[v["verdict"]]) for v in recorded.values()] == [(s.strip(), v) for s, v in table]
