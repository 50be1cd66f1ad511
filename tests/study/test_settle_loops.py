"""The settle loop of the unbalance orbit (study/journal over study/settle): its verdict is the measured
criterion, and its revolutions are the settling run's."""

import numpy as np

from transient.analysis.orbits import per_revolution
from transient.models.journal import JournalBearing, JournalOrbit
from transient.params import rho_kim
from transient.study.journal import settle_estimate, settled_unbalance_orbit


def _orbit(speed):
    R = rho_kim.ROTOR
    b = JournalBearing(**dict(rho_kim.BEARING, grid=(41, 6)))
    return JournalOrbit(b, rotor_mass=R["rotor_mass"], unbalance=R["unbalance"], load=R["load"], speed_rpm=speed)


def test_settled_unbalance_orbit_says_settled_only_when_the_estimate_is_below_the_fraction():
    u = settled_unbalance_orbit(_orbit(3000.0), 1e-6, 64, 4, 8)
    X, Y = per_revolution(u.orbit.x, u.orbit.y, 64, u.orbit.clearance)
    assert u.revolutions == X.shape[0] == 4
    assert u.settle_estimate == settle_estimate(X, Y) <= 1e-2
    assert u.success and u.message.startswith("settled")
    w = settled_unbalance_orbit(_orbit(7500.0), 1e-6, 64, 4, 6)  # whirl past the threshold: never settles
    assert w.revolutions == 6 and w.settle_estimate > 1e-2
    assert not w.success and w.message.startswith("NOT settled")
    assert w.n_steps == w.orbit.stats.n_steps > 0 and np.isfinite(w.shape["semi_major"])
