"""What a rotor run reports and refuses: a journal at its bearing wall is never a success (the touch event on by
default, naming the bearing node, the time and e/C; a run with the event off that reaches the wall is flagged);
the linear unbalance response with the film states by default; memory refused before the films, the equilibrium
or the run are built; strict flags; a speed function evaluated only inside the run."""

import time

import numpy as np
import pytest

from transient import JournalBearing, LongRun, Recording
from transient.checks import MemoryLimitError
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING


@pytest.fixture(scope="module")
def bearing():
    return JournalBearing(**BEARING, grid=(16, 4))


def overloaded(speed=300.0):
    """A one-node rotor on a coarse film (8 x 2 cells) under three times the load it carries at ``speed``, started
    at e/C = 0.9 with the film solved there: the journal is driven through the wall within 0.1 revolution."""
    bearing = JournalBearing(**BEARING, grid=(8, 2))
    s = RotorBearingSystem(Rotor(mass=100.0 * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: bearing},
                           gravity=30.0)
    dae = s.dae(speed)
    blk = dae.blocks[0]
    y = np.zeros(dae.n)
    y[blk.offset:blk.offset + blk.n] = blk.film.solve(0.9, 0.0)[0]
    y[dae.Q0] = 0.9 * bearing.clearance / dae.L
    return s, y


def test_a_journal_reaching_its_bearing_is_never_a_success():
    s, y = overloaded()
    r = s.run(0.15, 300.0, start=(0.0, y), recording=Recording(outputs_per_revolution=64),
              long_run=LongRun(progress=False))  # touch detection by default
    assert not r.success and r.touched_at is not None
    assert "bearing node 0" in r.message and f"t = {r.touched_at:.6g} s" in r.message and "e/C = 0.9990" in r.message
    assert r.eccentricity_ratio(0).max() == pytest.approx(0.999, abs=1e-6)
    off = s.run(0.15, 300.0, start=(0.0, y), recording=Recording(outputs_per_revolution=64),
                long_run=LongRun(progress=False), touch_gap=0.0)
    eps = off.eccentricity_ratio(0)
    assert eps.max() > 1.0  # the discrete film lets the journal through the wall: a negative film
    assert not off.success and off.touched_at is None
    assert "bearing node 0 reaches e/C" in off.message and "negative film" in off.message


def test_a_start_outside_the_clearance_is_refused():
    s, y = overloaded()
    y[s.dae(300.0).Q0] = 1.01
    with pytest.raises(ValueError, match=r"journal at bearing node 0 is outside the clearance: e/C = 1\.01"):
        s.run(0.25, 300.0, start=(0.0, y), long_run=LongRun(progress=False))


def test_unbalance_response_defaults_to_the_film_states(bearing):
    s = RotorBearingSystem(Rotor.jeffcott(2e7, 90.0, 5.0), {0: bearing, 2: bearing}, unbalance=[(1, 2e-5, 0.0)])
    default = s.unbalance_response(3000)
    film = s.unbalance_response(3000, film_states=True)
    kc = s.unbalance_response(3000, film_states=False)
    assert default.linearisation == film.linearisation == "film states" and kc.linearisation == "K and C"
    assert np.array_equal(default.displacement, film.displacement)
    assert not np.array_equal(default.displacement, kc.displacement)  # two linearisations, two answers
    with pytest.raises(ValueError, match="film_states = 'no' is not a flag"):
        s.unbalance_response(3000, film_states="no")


def test_memory_is_refused_before_the_films_the_equilibrium_or_the_run(bearing, monkeypatch):
    s = RotorBearingSystem(Rotor.jeffcott(2e7, 90.0, 5.0), {0: bearing, 2: bearing}, unbalance=[(1, 2e-5, 0.0)])

    def no_work(*args, **kwargs):
        raise AssertionError("films or equilibrium built before the memory check")

    monkeypatch.setattr(s, "dae", no_work)
    monkeypatch.setattr(s, "_steady", no_work)
    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", "1e5")  # the estimates: about 0.85 MB, 6.6 kB per film cell
    for call in (lambda: s.run(1, 3000.0, long_run=LongRun(progress=False)), lambda: s.equilibrium(3000.0),
                 lambda: s.unbalance_response(3000.0)):
        t = time.perf_counter()
        with pytest.raises(MemoryLimitError, match=r"16 x 4 \+ 16 x 4.*coarser grid \(JournalBearing\(grid="):
            call()
        assert time.perf_counter() - t < 0.5


def test_run_flags_are_booleans_only(bearing):
    s = RotorBearingSystem(Rotor.jeffcott(2e7, 90.0, 5.0), {0: bearing, 2: bearing})
    with pytest.raises(ValueError, match="resume = 'False' is not a flag; allowed: True, False"):
        s.run(1, 3000.0, long_run=LongRun(resume="False"))
    with pytest.raises(ValueError, match="progress = 'no' is not a flag; allowed: True, False"):
        s.run(1, 3000.0, long_run=LongRun(progress="no"))


def test_a_speed_function_is_evaluated_only_inside_the_run(bearing):
    """A run-up from rest (from a given state) with a speed function defined only on the run's own span: the
    run's end is found without evaluating it later, and the integrator's steps past the end do not reach it."""
    s = RotorBearingSystem(Rotor(mass=100.0 * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: bearing},
                           unbalance=[(0, 1e-5, 0.0)], gravity=9.81)
    span = np.sqrt(120.0 * 0.05 / 6000.0)  # one revolution of n = 6000 rpm t / 0.05 s
    seen = []

    def run_up(t):
        seen.append(t)
        if not 0.0 <= t <= span:
            raise ValueError(f"t = {t!r} s is outside the run-up")
        return 6000.0 * t / 0.05

    eq = s.equilibrium(200.0)
    r = s.run(1, run_up, start=(0.0, eq.state), reference_speed_rpm=6000.0,
              recording=Recording(outputs_per_revolution=8), long_run=LongRun(progress=False))
    assert r.success and r.final_time == pytest.approx(span, rel=1e-9)
    assert min(seen) >= 0.0 and max(seen) <= span
    assert r.speed_rpm[0] == 0.0 and r.speed_rpm[-1] == pytest.approx(6000.0 * span / 0.05, rel=1e-9)


def test_a_rotor_run_stops_where_its_stop_says_with_the_run_so_far(bearing):
    """A rotor run takes ``LongRun(stop=)`` (the settle loops' hook) as the orbit does: asked after every chunk with
    the result so far, a non-empty answer ends the run as a success with that message; the outputs up to there are
    those of the same run without the stop."""
    s = RotorBearingSystem(Rotor.jeffcott(2e7, 90.0, 5.0), {0: bearing, 2: bearing}, unbalance=[(1, 2e-5, 0.0)])
    seen = []

    def stop(partial):
        seen.append((len(partial.t), partial.displacement.shape, partial.final_state.shape))
        return "enough" if len(partial.t) > 8 else None

    rec, lr = Recording(outputs_per_revolution=16), LongRun(chunk_revolutions=0.25, progress=False)
    r = s.run(1.0, 3000, recording=rec, long_run=LongRun(chunk_revolutions=0.25, stop=stop, progress=False))
    whole = s.run(1.0, 3000, recording=rec, long_run=lr)
    assert r.success and r.message == "enough"
    assert [n for n, _, _ in seen] == [5, 9] and len(r.t) == 9 and len(whole.t) == 17
    assert seen[-1][1] == r.displacement.shape and seen[-1][2] == whole.final_state.shape
    np.testing.assert_array_equal(r.displacement, whole.displacement[:9])
    np.testing.assert_array_equal(r.t, whole.t[:9])
