"""The ball-pass sequence on the one run driver: checkpoint and resume bit for bit, a start from a result, the time
budget, the state's layout and the driver's refusals."""

from __future__ import annotations

import numpy as np
import pytest

from transient.models.ball import ThrustBallBearing
from transient.models.ball.passes import HEADER, PassMap
from transient.models.ball.settings import TrackSettings
from transient.models.ball.track import FrontTrack, UniformTrack
from transient.solvers.longrun import Interrupted
from transient.solvers.settings import Integration, LongRun

CASE = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6, stop_at_periodic=False)
FAST = dict(integration=Integration(method="cvode", rtol=1e-4, atol=1e-8))


def _same(a, b):
    for name in ("h_inlet", "h_central", "h_minimum", "h_outlet", "m", "volume", "final_state"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    assert a.regime == b.regime and a.final_time == b.final_time
    assert a.stats["n_steps"] == b.stats["n_steps"] and a.stats["n_remesh"] == b.stats["n_remesh"]


@pytest.mark.parametrize("track", [TrackSettings(), TrackSettings(grid="uniform", n_cells=60, mobility_film=10e-6)],
                         ids=["front", "uniform"])
def test_a_sequence_killed_after_k_passes_resumes_to_the_uninterrupted_final_state(tmp_path, monkeypatch, track):
    """Ctrl-C during the levelling after pass 3 of 7; resumed from its checkpoint, the sequence ends on the same
    state, rows and step counts, bit for bit, as the same sequence run without interruption (compared here)."""
    kw = dict(CASE, n_passes=7, track=track, **FAST)
    whole = ThrustBallBearing().sequence(**kw, long_run=LongRun(checkpoint=tmp_path / "whole.npz"))
    target = FrontTrack if track.grid == "front" else UniformTrack
    relax = target.relax
    calls = []

    def interrupted(self, *a, **k):
        calls.append(1)
        if len(calls) == 4:
            raise KeyboardInterrupt
        return relax(self, *a, **k)

    path = tmp_path / "killed.npz"
    monkeypatch.setattr(target, "relax", interrupted)
    with pytest.raises(Interrupted, match="holds 3 passes"):
        ThrustBallBearing().sequence(**kw, long_run=LongRun(checkpoint=path))
    monkeypatch.setattr(target, "relax", relax)
    resumed = ThrustBallBearing().sequence(**kw, long_run=LongRun(checkpoint=path, resume=True))
    assert resumed.success and resumed.n_run == 7
    _same(resumed, whole)


def test_the_checkpointed_run_is_the_plain_run(tmp_path):
    """Chunks restart the meniscus from the root held in the state: the checkpointed (chunked, one pass per chunk)
    sequence gives the plain one's films, the same steps and the same final state (a root may differ in the last
    bits where the plain run answers a repeated inlet film from its cache: 1e-12 relative)."""
    kw = dict(CASE, n_passes=6, **FAST)
    plain = ThrustBallBearing().sequence(**kw)
    chunked = ThrustBallBearing().sequence(**kw, long_run=LongRun(checkpoint=tmp_path / "c.npz"))
    assert plain.final_time == chunked.final_time == 5.0 and plain.stats["n_steps"] == chunked.stats["n_steps"]
    for name in ("h_inlet", "h_central", "volume", "final_state"):
        np.testing.assert_allclose(getattr(chunked, name), getattr(plain, name), rtol=1e-12, err_msg=name)


def test_a_sequence_started_from_a_result_continues_it(tmp_path):
    """Six passes, then four more from the result: the continuation's first pass is the result's last, and its rows
    are the ten-pass sequence's (same arithmetic; the meniscus restarts from the root held in the state, so a root
    may differ in the last bits: 1e-12 relative)."""
    b = ThrustBallBearing()
    ten = b.sequence(**CASE, n_passes=10, **FAST)
    six = b.sequence(**CASE, n_passes=6, **FAST)
    more = b.sequence(**CASE, n_passes=5, start=six, **FAST)
    assert more.final_time == 9.0 and more.n_run == 5
    assert more.h_inlet[0] == six.h_inlet[-1]
    np.testing.assert_allclose(more.h_inlet, ten.h_inlet[5:], rtol=1e-12)
    np.testing.assert_allclose(more.volume, ten.volume[5:], rtol=1e-12)
    assert more.regime == ten.regime[5:]


def test_a_start_under_other_scales_or_another_track_is_refused():
    b = ThrustBallBearing()
    two = b.sequence(**CASE, n_passes=2, **FAST)
    with pytest.raises(ValueError, match=r"ambient film 0.0001 m; this one has 0.00012 m"):
        b.sequence(**dict(CASE, ambient_film=120e-6), n_passes=2, start=two, **FAST)
    with pytest.raises(ValueError, match="same track settings"):
        b.sequence(**CASE, n_passes=2, start=two, track=TrackSettings(grid="uniform"), **FAST)
    with pytest.raises(ValueError, match="whole number of passes"):
        b.sequence(**CASE, n_passes=2, start=(0.5, two.final_state), **FAST)


def test_the_time_budget_ends_a_sequence_between_passes():
    s = ThrustBallBearing().sequence(**CASE, n_passes=50, long_run=LongRun(time_budget=1e-3), **FAST)
    assert not s.success and "time budget" in s.message and 1 <= s.n_run < 50


def test_the_state_holds_the_finest_front_mesh_the_precursor_allows():
    """The front track's state has room for the mesh of the thinnest precursor whose faces still increase."""
    b = ThrustBallBearing()
    s = b.sequence(**CASE, n_passes=3, **FAST)
    assert s.final_state.size > len(HEADER) + 4 + 400
    assert PassMap.header(s.final_state, "h_ref") == CASE["ambient_film"]
    assert PassMap.header(s.final_state, "h_in") == s.h_inlet[-1]


def test_a_periodic_sequence_ends_as_a_success_with_its_pass():
    """A sequence that reaches its periodic state ends there (the driver's terminal event, no failure)."""
    s = ThrustBallBearing().sequence(**dict(CASE, stop_at_periodic=True), n_passes=40, **FAST)
    assert s.success and s.periodic and s.n_run == s.n_periodic + 1 < 40 and s.message == ""


def test_long_run_chunks_are_refused_by_name():
    with pytest.raises(ValueError, match="chunk_revolutions"):
        ThrustBallBearing().sequence(**CASE, n_passes=2, long_run=LongRun(chunk_revolutions=2.0))


def test_stop_ends_a_checkpointed_sequence_after_a_chunk(tmp_path):
    """``LongRun(stop=)`` is asked after each chunk (a tenth of the passes with a checkpoint) with the result so
    far."""
    seen = []

    def stop(result):
        seen.append(result.n_run)
        return "enough" if result.n_run >= 3 else None

    s = ThrustBallBearing().sequence(**CASE, n_passes=11, **FAST,
                                     long_run=LongRun(checkpoint=tmp_path / "s.npz", stop=stop))
    assert seen == [2, 3] and s.n_run == 3 and s.message == "enough"
