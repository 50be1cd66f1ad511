"""The orbit of a journal in a misaligned bush (transient/models/journal/orbit.py with JournalBearing(misalignment=)):
the tilted gap in the time domain, the moment and the smallest gap in the records, the touch at the worse end."""

import numpy as np
import pytest

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.solvers.settings import Recording

D, L, CL, MU = 0.1, 0.08, 150e-6, 0.01  # Pfeil's demonstration bearing (D, L, C), a light oil
SPEED, LOAD, MASS = 3000.0, 2000.0, 20.0
TILT = (0.0, 4e-4)  # the bush tilted across the load line: the journal's ends at +-0.1 C about its centre


def bearing(**kw):
    return JournalBearing(D, L, CL, MU, grid=(40, 10), **kw)  # misaligned: the whole length, 40 x 20


def test_misaligned_orbit_rests_at_the_tilted_equilibrium_with_its_moment():
    """Started at the static equilibrium without unbalance the journal stays there; the recorded moment and smallest
    gap are the steady state's (:meth:`JournalBearing.equilibrium` in the same bush), and the smallest gap is at an
    end: below the mid-plane's C (1 - e/C)."""
    o = JournalOrbit(bearing(misalignment=TILT), MASS, 0.0, LOAD, SPEED)
    eq = o.equilibrium()
    r = o.run(0.1, recording=Recording(record=("force", "moment", "min_film"), outputs_per_revolution=20))
    assert r.success
    M0 = np.hypot(*eq.moment)
    assert M0 > 1e-3 * LOAD * L  # the misaligned film has a moment
    assert np.abs(r.moment - np.array(eq.moment)).max() < 1e-6 * M0
    assert np.abs(r.min_film - eq.min_film).max() < 1e-9 * CL
    assert eq.min_film < CL * (1.0 - eq.eccentricity_ratio) - 0.05 * CL
    assert np.abs(r.x - r.x[0]).max() < 1e-6 * CL and np.abs(r.force[:, 0] + LOAD).max() < 1e-5 * LOAD


def test_the_aligned_orbit_records_no_moment_and_its_mid_plane_gap():
    """An aligned bearing: the moment recorded is zero (mid-plane symmetry, a half bearing) and the smallest gap the
    mid-plane's, as before."""
    o = JournalOrbit(bearing(), MASS, 0.0, LOAD, SPEED)
    r = o.run(0.05, recording=Recording(record=("moment", "min_film"), outputs_per_revolution=20))
    assert np.all(r.moment == 0.0)
    assert np.array_equal(r.min_film, CL * (1.0 - np.hypot(r.x, r.y) / CL))


@pytest.mark.parametrize("misaligned", [True, False])
def test_touch_is_detected_at_the_worse_end(misaligned):
    """The journal thrown towards the load from its equilibrium: in the misaligned bush the run stops where the
    eccentricity at an end (not at the mid-plane, well clear) reaches ``max_eccentricity_ratio - touch_gap``; the
    same throw in the aligned bush (the same grid) stays clear of that limit and runs to its end."""
    tilted = JournalOrbit(bearing(misalignment=TILT), MASS, 0.0, LOAD, SPEED)
    o = tilted if misaligned else JournalOrbit(bearing().whole_length(), MASS, 0.0, LOAD, SPEED)
    n = o.film.n
    y0 = tilted.initial_state()
    limit = float(tilted.reach(y0[n], y0[n + 1])) + 0.005  # the misaligned start's edge: 0.600 (mid-plane 0.537)
    y0 = o.initial_state()
    y0[n + 2] = 1.0  # X' [C per radian of shaft angle], towards the load
    r = o.run(0.25, y0=y0, touch_gap=o.bearing.max_eccentricity_ratio - limit,
              recording=Recording(record=("min_film",), outputs_per_revolution=200))
    if misaligned:  # measured without the limit: the edge reaches 0.612, the mid-plane 0.545
        assert not r.success and r.touched_at is not None
        X, Y = r.final_state[n], r.final_state[n + 1]
        assert o.reach(X, Y) == pytest.approx(limit, abs=1e-6)
        assert np.hypot(X, Y) < limit - 0.05
        assert r.min_film.min() >= CL * (1.0 - limit) - 1e-9 * CL
    else:  # measured: 0.547
        assert r.success and np.hypot(r.x, r.y).max() / CL < limit
