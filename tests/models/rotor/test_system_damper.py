"""A rotor on squeeze-film dampers: the damper's film in the system at zero spin, its centring spring in the rotor's
stiffness. The static equilibrium hangs on the springs; the settled synchronous orbit of a balanced-by-symmetry rotor
is a circular centred orbit whose film force is the damper's own steady whirling-frame solve
(``SqueezeFilmDamper.circular_orbit``), to the two discretisations' second-order difference."""

import numpy as np
import pytest

from transient import Integration, LongRun, Recording, Rotor, RotorBearingSystem, SqueezeFilmDamper
from transient.models.journal.bearing import NoEquilibriumError

C = 200e-6
DAMPER = dict(diameter=0.1, length=0.02, clearance=C, viscosity=0.01, supply_pressure=2e5, centring_stiffness=5e6)
ROTOR = dict(shaft_stiffness=1e7, disk_mass=20.0, journal_mass=2.0)
SPEED = 6000.0


def _settled_forces(grid, revolutions, rtol):
    """(e/c, radial, tangential force [N]) of the damper at node 0 over the last revolution of an unbalance run, and
    the damper."""
    d = SqueezeFilmDamper(**DAMPER, grid=grid)
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=0.0)
    r = s.run(revolutions, SPEED, integration=Integration(rtol=rtol), recording=Recording(outputs_per_revolution=16),
              long_run=LongRun(progress=False))
    assert r.success, r.message
    x, y = (v[-17:] for v in r.position(0))
    F = r.bearing_force[-17:, 0, :]
    e = np.hypot(x, y)
    radial, tangential = (F[:, 0] * x + F[:, 1] * y) / e, (F[:, 1] * x - F[:, 0] * y) / e
    assert np.ptp(e) < 5e-3 * e.mean()  # circular and centred (settling to within 1e-5 by 20 revolutions)
    assert np.all(np.diff(np.unwrap(np.arctan2(y, x))) > 0)  # forward whirl, with the shaft
    return e.mean() / C, radial.mean(), tangential.mean(), d


def test_the_equilibrium_hangs_on_the_centring_springs():
    d = SqueezeFilmDamper(**DAMPER, grid=(16, 4))
    eq = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, gravity=9.81).equilibrium(SPEED)
    weight = (ROTOR["disk_mass"] + 2 * ROTOR["journal_mass"]) * 9.81
    sag = 0.5 * weight / (DAMPER["centring_stiffness"] * C)
    assert eq.eccentricity_ratio == pytest.approx(np.full(2, sag), rel=1e-6)
    assert np.max(np.abs(eq.bearing_force)) < 1e-9 * weight  # a film at rest that does not turn carries nothing


def test_the_run_settles_on_the_dampers_circular_orbit():
    eps, radial, tangential, d = _settled_forces((24, 2), 12, 1e-6)
    orbit = d.circular_orbit(eps, SPEED)
    # measured: +1.15 % on 24 cells round, +0.28 % on 48, +0.07 % on 96 (test_..._converge_together)
    assert tangential == pytest.approx(orbit.tangential_force, rel=0.02)
    assert abs(radial) < 1e-3 * abs(tangential) and abs(orbit.radial_force) < 1e-3 * abs(tangential)  # full film


@pytest.mark.slow
def test_the_time_domain_and_the_whirling_frame_films_converge_together():
    """The squeeze term in time (the rotor's film) and as a Couette transport (the whirling frame): their difference
    falls at second order in the circumferential cells."""
    diff = []
    for n in (24, 48, 96):
        eps, _, tangential, d = _settled_forces((n, 4), 20, 1e-7)
        diff.append(tangential / d.circular_orbit(eps, SPEED).tangential_force - 1.0)
    assert diff[0] / diff[1] > 3.0 and diff[1] / diff[2] > 3.0 and abs(diff[2]) < 1e-3


def test_what_a_damper_refuses_in_the_system():
    d = SqueezeFilmDamper(**dict(DAMPER, centring_stiffness=None), grid=(16, 4))
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=9.81)
    with pytest.raises(NoEquilibriumError, match="centring"):
        s.equilibrium(SPEED)
    d = SqueezeFilmDamper(**DAMPER, grid=(16, 4))
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=9.81)
    with pytest.raises(ValueError, match="method"):
        s.run(1, SPEED, integration=Integration(method="bdf2"), long_run=LongRun(progress=False))
    for analysis in (lambda: s.unbalance_response(SPEED), lambda: s.unbalance_response(SPEED, film_states=False),
                     lambda: s.periodic_response(SPEED)):
        with pytest.raises(ValueError, match="quasi-static K and C"):
            analysis()
    assert s.parameters()["bearings"]["0"]["damper"] is True
