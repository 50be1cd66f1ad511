"""What an orbit run reports and refuses: a journal at its bearing wall is never a success (the touch event, and a
run with the event off that reaches the wall); memory refused before the grid, the film or the run are built,
naming the grid; a fixed step the orbit does not take refused."""

import time

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Recording
from transient.checks import MemoryLimitError
from transient.params.rho_kim import BEARING


def overloaded():
    """A rotor on a coarse film (8 x 2 cells) under three times the load the film carries at 300 rpm, started at
    e/C = 0.9 with the film solved there: the journal is driven through the wall within 0.1 revolution."""
    o = JournalOrbit(JournalBearing(**BEARING, grid=(8, 2)), 100.0, 0.0, 3000.0, 300.0)
    y = np.zeros(o.n)
    y[o.film.n] = 0.9
    y[:o.film.n] = o.film.solve(0.9, 0.0)[0]
    return o, y


def test_a_journal_reaching_its_bearing_is_never_a_success():
    o, y = overloaded()
    r = o.run(0.15, y0=y, recording=Recording(outputs_per_revolution=64), long_run=LongRun(progress=False))  # touch detection by default
    assert not r.success and r.touched_at is not None and "journal touches the bearing" in r.message
    off = o.run(0.15, y0=y, recording=Recording(outputs_per_revolution=64), long_run=LongRun(progress=False),
                touch_gap=0.0)
    eps = np.hypot(off.x, off.y) / o.bearing.clearance
    assert eps.max() > 1.0  # the discrete film lets the journal through the wall: a negative film
    assert not off.success and off.touched_at is None
    assert f"reaches e/C = {eps.max():.4f}" in off.message and "negative film" in off.message


def test_a_grid_too_large_is_refused_before_it_is_built(monkeypatch):
    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", "1e6")
    t = time.perf_counter()
    with pytest.raises(MemoryLimitError, match=r"grid = \(2000, 500\) \(1000000 cells\).*coarser grid"):
        JournalBearing(**BEARING, grid=(2000, 500))
    assert time.perf_counter() - t < 0.5


def test_an_orbit_too_large_is_refused_before_its_film_is_built(monkeypatch):
    b = JournalBearing(**BEARING, grid=(16, 4))

    def no_film(*args, **kwargs):
        raise AssertionError("the film was built before the memory check")

    o = JournalOrbit(b, 100.0, 1e-6, 981.0, 6000.0)
    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", "1e5")  # the film and its solver alone: 6.6 kB per cell
    with pytest.raises(MemoryLimitError, match=r"coarser grid \(JournalBearing\(grid=") as e:
        o.run(1.0, long_run=LongRun(progress=False))
    assert "lower revolutions" not in str(e.value)  # the grid is what must change, not the run's length
    monkeypatch.setattr(b, "film", no_film)
    with pytest.raises(MemoryLimitError, match=r"an orbit on 64 film cells.*coarser grid \(JournalBearing\(grid="):
        JournalOrbit(b, 100.0, 1e-6, 981.0, 6000.0)


def test_a_fixed_step_the_orbit_does_not_take_is_refused():
    o = JournalOrbit(JournalBearing(**BEARING, grid=(8, 2)), 100.0, 1e-6, 981.0, 6000.0)
    with pytest.raises(ValueError, match=r"dt = 0\.01 \[-\] is not used by the orbit; allowed: steps_per_revolution"):
        o.run(0.1, integration=Integration(method="rk4", dt=0.01), long_run=LongRun(progress=False))


def test_the_bdf2_band_lu_counts_and_is_refused_before_it_is_built(monkeypatch):
    """The bordered band LU of method "bdf2" stores about 6 min(n_theta, n_axial) rows per cell: on a square grid it
    outgrows what IDA needs, and a run it does not fit is refused naming the grid before anything is built."""
    o = JournalOrbit(JournalBearing(**BEARING, grid=(48, 48)), 100.0, 1e-6, 981.0, 6000.0)
    ida, bdf2 = o.memory_estimate(1.0), o.memory_estimate(1.0, method="bdf2")
    assert bdf2["band LU"] == pytest.approx(8.0 * (6.2 * 48 + 1) * o.film.n)
    monkeypatch.setenv("TRANSIENT_MEMORY_BYTES", str(2 * sum(ida.values()) + 1e4))  # IDA's run fits, bdf2's not

    def no_work(*args, **kwargs):
        raise AssertionError("the run was built before the memory check")

    monkeypatch.setattr(o, "bdf2_model", no_work)
    monkeypatch.setattr(o, "initial_state", no_work)
    with pytest.raises(MemoryLimitError, match=r"band LU .*coarser grid \(JournalBearing\(grid="):
        o.run(1.0, integration=Integration(method="bdf2"), long_run=LongRun(progress=False))
