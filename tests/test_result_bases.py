"""The result vocabulary: StatusResult / RunResult / SteadyResult, Stats totals, concatenation of run chunks,
and the stopping rule every settle loop shares (solvers/settling)."""

import numpy as np
import pytest

from transient.results import RunResult, Stats, StatusResult, SteadyResult, load_result, quantity, result_type
from transient.solvers.settling import find_settled, settled_stop, settles


@result_type
class _Chunk(RunResult):
    x: np.ndarray = quantity("m")
    grid: np.ndarray = quantity("m")
    snapshot_fields = ("grid",)


def test_every_model_result_declares_status_once():
    from transient.models.ball.bearing import BallSequence
    from transient.models.journal import FilmState, OrbitResult
    from transient.models.pad.pad import DescentResult
    from transient.models.roller.results import LineSteady, RollerTransient

    for cls in (OrbitResult, DescentResult, RollerTransient):
        assert issubclass(cls, RunResult)
    for cls in (FilmState, LineSteady):
        assert issubclass(cls, SteadyResult)
    assert issubclass(BallSequence, StatusResult)
    for cls in (OrbitResult, FilmState, BallSequence):
        assert "success" not in cls.__dict__.get("__annotations__", {})
    assert FilmState.__dataclass_fields__["message"].default == "converged"


def test_stats_add_and_unknown_counts_stay_unknown():
    a = Stats(n_steps=3, n_rhs=5, n_jac=1, n_error_test_failures=2, wall_time=0.5)
    b = Stats(n_steps=4, n_rhs=6, n_jac=2, n_error_test_failures=None, wall_time=0.25)
    c = a + b
    assert (c.n_steps, c.n_rhs, c.n_jac, c.wall_time) == (7, 11, 3, 0.75)
    assert c.n_error_test_failures is None


def test_run_chunks_concatenate_like_one_run(tmp_path):
    g = np.linspace(0.0, 1.0, 3)  # as long as the chunks: a snapshot, not a series
    a = _Chunk(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 4.0]), g, stats=Stats(n_steps=2),
               final_state=np.array([4.0]), final_time=2.0)
    b = _Chunk(np.array([2.0, 3.0, 4.0]), np.array([4.0, 9.0, 16.0]), 2 * g, stats=Stats(n_steps=5),
               final_state=np.array([16.0]), final_time=4.0, success=False, message="stopped")
    c = a + b
    np.testing.assert_array_equal(c.t, [0.0, 1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(c.x, [0.0, 1.0, 4.0, 9.0, 16.0])
    np.testing.assert_array_equal(c.grid, 2 * g)
    assert c.stats.n_steps == 7 and c.final_time == 4.0 and c.final_state[0] == 16.0
    assert not c.success and c.message == "stopped"
    d = load_result(c.save(tmp_path / "c"))
    np.testing.assert_array_equal(d.x, c.x)
    assert d.stats.n_steps == 7 and d.message == "stopped"


def test_steady_result_status_is_keyword_only():
    with pytest.raises(TypeError):
        SteadyResult(False)
    r = SteadyResult(success=False, message="no convergence", iterations=7, residual_norms=[1.0, 0.1])
    assert not r.ok and r.iterations == 7


def test_settle_criteria():
    z = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.6], [1.0, 0.6 + 1e-6], [1.0, 0.6 + 2e-6]])
    assert find_settled(z, 1e-5) == 4  # steps 3 and 4 below tol
    steps = np.array([[0.0, 0.0], [3e-5, 4e-5], [3e-5 + 3e-5, 8e-5]])  # Euclidean 5e-5, largest component 4e-5
    assert find_settled(steps, 4.5e-5, confirm=1) is None
    assert find_settled(steps, 4.5e-5, confirm=1, norm="max") == 1
    with pytest.raises(ValueError, match="norm"):
        find_settled(z, 1e-5, norm="l1")

    class R:
        x = z[:, 0]
        y = z[:, 1]

    stop = settled_stop(lambda r: np.column_stack([r.x, r.y]), settles(1e-5))
    assert stop(R()) == "settled after 4 periods"
    R.x, R.y = z[:3, 0], z[:3, 1]
    assert stop(R()) is None
