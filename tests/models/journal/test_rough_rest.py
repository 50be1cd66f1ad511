"""A rough journal bearing at rest (models/journal/rest.py): the static contact equilibrium at 0 rpm against the
Greenwood-Tripp integral of the rigid gap, the bore's and the feeds' cases, and the start-ups from 0 rpm (the journal
orbit and the rotor system) through contact to lift-off."""

import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from transient import (
    Integration,
    JournalBearing,
    JournalOrbit,
    Recording,
    Roughness,
    steel_asperity_contact,
)
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.params import rho_kim, sander

LOAD = 8000.0  # [N] the Sander rig's larger load


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # contact pressures above the isoviscous film's range
        return f(*a, **kw)


def greenwood_tripp_load(bearing, eps):
    """The asperities' force [N] along the line of centres of a rigid aligned journal at e/C = ``eps``:
    ``L R int p_a(C (1 - eps cos t)) cos t dt`` over the circumference, by adaptive quadrature of the exact
    Greenwood-Tripp pressure (``AsperityContact.load``), not the film's table."""
    c, C = bearing.roughness.contact, bearing.clearance
    f = lambda t: float(c.load(C * (1.0 - eps * np.cos(t)))) * np.cos(t)
    return bearing.length * bearing.radius * quad(f, -np.pi, np.pi, points=[0.0], limit=400, epsrel=1e-12)[0]


def test_rest_equilibrium_is_the_greenwood_tripp_balance():
    """0 rpm, the Sander big end (feeds and ends at 1 bar: the film at rest is uniform and carries nothing): the
    asperities carry the load (to 1e-9), along the load line, and the equilibrium's eccentricity puts the exact
    Greenwood-Tripp integral of the rigid gap at the load (to the grid's and the table's error: 1e-3); the torque
    that starts the shaft is the boundary friction ``mu_b R sum p_a dA``."""
    b = sander.test_bearing((48, 8))
    s = quiet(b.equilibrium, LOAD, 0.0)
    assert s.speed_rpm == 0.0 and s.success
    assert s.contact_force[0] == pytest.approx(-LOAD, rel=1e-9) and abs(s.contact_force[1]) < 1e-9 * LOAD
    assert np.hypot(s.force[0] - s.contact_force[0], s.force[1] - s.contact_force[1]) < 1e-9 * LOAD
    assert abs(s.attitude_angle_deg) < 1e-6
    assert greenwood_tripp_load(b, s.eccentricity_ratio) == pytest.approx(LOAD, rel=1e-3)
    assert s.friction_torque == pytest.approx(0.02 * b.radius * s.contact_normal_load, rel=1e-12)
    assert s.friction_coefficient == pytest.approx(s.friction_torque / (b.radius * LOAD), rel=1e-12)
    assert s.power_loss == 0.0
    assert s.contact_normal_load >= LOAD


def test_rest_equilibrium_with_a_winkler_bore_and_barus_oil():
    """The same with the rig's options: the bore gives way (the journal passes the rigid circle), pressure-viscosity
    changes nothing at rest; the asperities still carry the load to 1e-9."""
    k = sander.bore_compliance(sander.TEST, sander.CONROD)
    b = sander.test_bearing((48, 8), sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY,
                                                      bore_compliance=k))
    s = quiet(b.equilibrium, LOAD, 0.0)
    assert s.contact_force[0] == pytest.approx(-LOAD, rel=1e-9)
    rigid = quiet(sander.test_bearing((48, 8)).equilibrium, LOAD, 0.0)
    assert s.eccentricity_ratio > rigid.eccentricity_ratio and s.min_film > rigid.min_film


def test_rest_equilibrium_with_a_supply_above_ambient():
    """A groove at 1 atm and the ends at 0 (Rho & Kim's bearing): the film at rest is the Poiseuille field between
    them and pushes the journal away from the groove; the film and the asperities together carry the load."""
    r = Roughness(steel_asperity_contact(1e-6), gamma=3.0, boundary_friction=0.12, journal_variance_share=0.8)
    b = JournalBearing(**rho_kim.BEARING, grid=(24, 4), roughness=r)
    s = quiet(b.equilibrium, 5000.0, 0.0)
    assert s.force[0] == pytest.approx(-5000.0, rel=1e-9) and abs(s.force[1]) < 1e-9 * 5000.0
    film = np.hypot(s.force[0] - s.contact_force[0], s.force[1] - s.contact_force[1])
    assert 0.0 < film < 0.1 * 5000.0  # the feed's field: small beside the load
    assert np.min(s.pressure) >= 0.0 and np.max(s.pressure) <= rho_kim.BEARING["supply_pressure"] * (1 + 1e-9)


def test_smooth_bearing_at_rest_is_refused():
    b = JournalBearing(**rho_kim.BEARING, grid=(24, 4))
    with pytest.raises(ValueError, match="speed_rpm"):
        b.equilibrium(1000.0, 0.0)


def rho_kim_rough():
    r = Roughness(steel_asperity_contact(1e-6), gamma=3.0, boundary_friction=0.12, journal_variance_share=0.8)
    return JournalBearing(**rho_kim.BEARING, grid=(24, 4), roughness=r)


RUN_UP = ((0.0, 0.0), (0.5, 600.0))  # [s, rpm] from rest to 600 rpm in 0.5 s
RECORD = ("shaft_speed", "friction_torque", "min_film", "contact_load")


@pytest.mark.slow  # about 10 s of CPU on an idle machine (30 s on a busy one)
def test_orbit_run_up_from_rest():
    """A 500 kg rotor under 5 kN on the rough Rho & Kim bearing, its speed law from 0 rpm and no start given: the
    run starts at the static contact equilibrium (the asperities carry the load, the torque is the boundary
    friction), passes through contact and lifts off (contact begins at rest and ends), with no NaN."""
    b = rho_kim_rough()
    o = JournalOrbit(b, 500.0, 0.0, 5000.0, 600.0, speed_profile=RUN_UP)
    rest = quiet(b.equilibrium, 5000.0, 0.0)
    r = quiet(o.run, 6.5, integration=Integration(method="bdf2"),  # 0.65 s: revolutions at the reference speed
              recording=Recording(outputs_per_revolution=10, record=RECORD))
    assert r.success and np.all(np.isfinite(r.x)) and np.all(np.isfinite(r.friction_torque))
    assert r.shaft_speed[0] == 0.0 and r.shaft_speed[-1] == pytest.approx(600.0)
    assert r.contact_load[0] == pytest.approx(rest.contact_load, rel=1e-9)
    assert r.friction_torque[0] == pytest.approx(rest.friction_torque, rel=1e-9)
    assert [w for _, w in r.contact_events] == ["begins", "ends"] and r.contact_events[0][0] == 0.0
    assert r.contact_load[-1] < 1e-3 * 5000.0 and r.friction_torque[-1] < 0.05 * r.friction_torque[0]


@pytest.mark.slow  # about 8 s of CPU on an idle machine (25 s on a busy one)
def test_rotor_run_up_from_rest():
    """The same rotor as a one-node rotor system (IDA): the run from 0 rpm starts at the static contact
    equilibrium, the bearing's at rest, and lifts off; a rotor on a smooth bearing at 0 rpm is refused."""
    b = rho_kim_rough()
    rotor = Rotor(mass=500.0 * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: b}, unbalance=[(0, 0.0, 0.0)], gravity=10.0)
    rest = quiet(b.equilibrium, 5000.0, 0.0)
    r = quiet(s.run, 4.0, speed_profile=RUN_UP, integration=Integration(method="ida"),
              recording=Recording(outputs_per_revolution=10))
    assert r.success
    x, y = r.position(0)
    assert np.hypot(x[0] - rest.position[0], y[0] - rest.position[1]) < 1e-9 * b.clearance
    load = np.ravel(r.contact_load)
    assert load[0] == pytest.approx(rest.contact_load, rel=1e-9) and load[-1] < 1e-3 * 5000.0
    assert [w for _, _, w in r.contact_events] == ["begins", "ends"]
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(np.ravel(r.friction_torque)))
    smooth = RotorBearingSystem(rotor, {0: JournalBearing(**rho_kim.BEARING, grid=(24, 4))},
                                unbalance=[(0, 0.0, 0.0)], gravity=10.0)
    with pytest.raises(ValueError, match="rest"):
        smooth.run(1.0, speed_profile=RUN_UP)
