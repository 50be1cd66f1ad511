"""The ```python examples of the user guide (docs/guide/*.md) run as written (in a temporary folder), so the
site shows only code that works."""

import re
from pathlib import Path

import pytest

GUIDE = Path(__file__).resolve().parents[1] / "docs" / "guide"
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)
EXAMPLES = [(p.name, k, code) for p in sorted(GUIDE.glob("*.md")) for k, code in enumerate(BLOCK.findall(p.read_text()))]


def test_every_guide_page_has_an_example():
    pages = {p.name for p in GUIDE.glob("*.md")}
    assert pages and pages == {name for name, _, _ in EXAMPLES}


@pytest.mark.parametrize("page, k, code", EXAMPLES, ids=[f"{n}-{k}" for n, k, _ in EXAMPLES])
def test_guide_example_runs(page, k, code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, f"{page}[{k}]", "exec"), {"__name__": f"guide_{k}"})
