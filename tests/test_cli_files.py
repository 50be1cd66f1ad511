"""``transient run`` refuses a file that is neither a scenario script nor a scene in one line, before reading it."""

from pathlib import Path

import pytest

from transient.cli import main

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("name", ["README.md", "notes.txt", "orbit.npz"])
def test_run_refuses_a_file_that_is_not_a_script_or_a_scene(name, tmp_path, capsys):
    path = tmp_path / name
    path.write_text("# Title\n\nprose, not Python\n")
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "(.py)" in err and "(.toml)" in err and name in err


def test_run_refuses_the_readme_in_one_line(capsys):
    assert main(["run", str(ROOT / "README.md")]) == 2
    assert capsys.readouterr().err.count("\n") == 1
