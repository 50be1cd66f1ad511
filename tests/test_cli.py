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


def test_a_checkpoint_mismatch_in_a_scenario_advises_the_command_line_option():
    from transient.solvers.longrun import CheckpointError
    from transient.study.scenario import fresh_advice

    with pytest.raises(CheckpointError, match=r"with --fresh to start afresh$") as err:
        with fresh_advice():
            raise CheckpointError("checkpoint c.npz was written by transient 'a', this is 'b'; delete it or run with "
                                  "resume=False to start afresh")
    assert "resume=False" not in str(err.value)
