"""Run options validated or refused, never misread: flags are booleans only (the string 'False' is not false),
a setting the chosen method does not use is an error naming the setting and the method, and a refused checkpoint
advises resume=False in Python and --fresh on the command line."""

import numpy as np
import pytest

from transient import Integration, LongRun, Problem
from transient.cli import main
from transient.solvers.longrun import CheckpointError, run_long


class Recorder:
    def __init__(self):
        self.t = []

    def observe(self, t, y):
        self.t.append(t)

    def arrays(self):
        return dict(t=np.array(self.t))

    def restore(self, a):
        self.t = list(a["t"])


def decay(checkpoint=None, key=None, **long_run):
    def rhs(t, y, out):
        out[0] = -y[0]

    return run_long(lambda y, t: Problem(y0=y, rhs=rhs), np.array([1.0]), 0.0, 0.5, 4, Recorder(),
                    solver=dict(method="bdf"), long_run=LongRun(checkpoint=checkpoint, **long_run), chunk_outputs=2,
                    key=key or dict(rate=1.0))


@pytest.mark.parametrize("name, value", [("resume", "False"), ("resume", 0), ("progress", "no"), ("progress", 1)])
def test_long_run_flags_are_booleans_only(name, value):
    with pytest.raises(ValueError, match=f"{name} = {value!r} is not a flag; allowed: True, False"):
        decay(**{name: value})


@pytest.mark.parametrize("settings, name, shown, users", [
    (dict(method="bdf2", dt=0.5), "dt", "0.5 [-]", "'rk4'"),
    (dict(method="bdf2", linear_solver="dense"), "linear_solver", "'dense'", "'cvode' or 'ida'"),
    (dict(method="bdf2", inner_tolerance=1e-8), "inner_tolerance", "1e-08 [-]", "'rk4'"),
    (dict(method="ida", steps_per_revolution=600), "steps_per_revolution", "600.0 [1/rev]", "'rk4' or 'bdf2'"),
    (dict(method="radau", linear_solver="band"), "linear_solver", "'band'", "'cvode' or 'ida'"),
])
def test_a_setting_the_method_does_not_use_is_refused(settings, name, shown, users):
    with pytest.raises(ValueError) as e:
        Integration(**settings)
    text = str(e.value)
    assert f"{name} = {shown} is not used by method {settings['method']!r}" in text, text
    assert f"allowed: {name} with method {users}" in text and "\n" not in text


def test_the_settings_a_method_uses_are_kept():
    assert Integration(method="rk4").inner_tolerance == 1e-6  # the paper's criterion when left out
    assert Integration(method="rk4", dt=0.5, inner_tolerance=1e-8, steps_per_revolution=100).dt == 0.5
    assert Integration(method="ida", linear_solver="dense").linear_solver == "dense"
    assert Integration(method="bdf2", steps_per_revolution=600).inner_tolerance is None


def test_a_refused_checkpoint_advises_python_and_the_shell_each_their_way(tmp_path, capsys):
    path = tmp_path / "ck.npz"
    decay(path)
    with pytest.raises(CheckpointError) as e:
        decay(path, key=dict(rate=2.0), resume=True)
    assert "rate = 1.0" in str(e.value) and "run with resume=False" in str(e.value)
    assert "--fresh" in e.value.command_line and "resume=False" not in e.value.command_line
    script = tmp_path / "scenario.py"
    script.write_text("import numpy as np\n"
                      "from transient import LongRun, Problem\n"
                      "from transient.solvers.longrun import run_long\n"
                      "class R:\n"
                      "    t = []\n"
                      "    def observe(self, t, y): pass\n"
                      "    def arrays(self): return {}\n"
                      "    def restore(self, a): pass\n"
                      "def rhs(t, y, out): out[0] = -y[0]\n"
                      f"run_long(lambda y, t: Problem(y0=y, rhs=rhs), np.array([1.0]), 0.0, 0.5, 4, R(),"
                      f" solver=dict(method='bdf'), chunk_outputs=2, key=dict(rate=3.0),"
                      f" long_run=LongRun(checkpoint={str(path)!r}, resume=True))\n")
    assert main(["run", str(script)]) == 2
    err = capsys.readouterr().err
    assert "rate = 1.0" in err and "--fresh" in err and "resume=False" not in err, err
