"""Shared test helpers as fixtures: central finite-difference Jacobians and loading scenario scripts.

The test tree mirrors the package: ``fv/``, ``physics/``, ``surfaces/``, ``solvers/``, ``models/<element>/``,
``analysis/``, ``study/``, ``scenarios/`` (the scripts under ``scenarios/``), ``bench/``; tests of the
package as a whole (import rules, results, fuzzing, figures, documentation) sit at the top.
"""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
SCENARIOS = ROOT / "scenarios"


def central_jacobian(f, y, rows, step=1e-6, relative=True):
    """``(rows, y.size)`` central differences of ``f(y) -> array``. Column ``j`` steps by ``step max(1, |y_j|)``
    (``relative``) or by ``step``; the step must be well below the scale on which ``f`` bends."""
    y = np.asarray(y, dtype=float)
    J = np.zeros((rows, y.size))
    for j in range(y.size):
        hj = step * max(1.0, abs(y[j])) if relative else step
        yp, ym = y.copy(), y.copy()
        yp[j] += hj
        ym[j] -= hj
        J[:, j] = (f(yp) - f(ym)) / (2 * hj)
    return J


def load_scenario(name):
    """The module of ``scenarios/<name>.py``, executed once per call, so tests call its ``main(argv)``."""
    spec = importlib.util.spec_from_file_location(f"scenario_{name}", SCENARIOS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="session")
def fd_jacobian():
    """:func:`central_jacobian`: the reference of the tests that check analytic Jacobians."""
    return central_jacobian


@pytest.fixture(scope="session")
def scenario_loader():
    """:func:`load_scenario`: ``scenario_loader("journal_orbit").main([...])``."""
    return load_scenario

