"""A rotor on thermal bearings (models/rotor/thermal_films.py, thermal_kernels.py): the isothermal limit, the one-node
rotor against the thermal journal orbit, the long-time limit (the rotor's thermal equilibrium), the energy balance
per revolution, checkpoint/resume with the temperatures, refusals."""

from dataclasses import replace

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, ThermalFilm
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.models.rotor.content_form import BDF2_STEPS_PER_REVOLUTION
from transient.models.rotor.thermal_films import ThermalContentSystem
from transient.solvers.longrun import Interrupted
from transient.solvers.settings import Integration, LongRun, Recording

GEOMETRY = dict(diameter=0.1, length=0.05, clearance=1e-4)
OIL = ThermalFilm(supply_temperature=323.15, viscosity_at=((323.0, 0.01902), (353.0, 0.00772)), density=870.0,
                  heat_capacity=1950.0)
GRID = (30, 4)
SPEED, LOAD, MASS, ECC = 3000.0, 2000.0, 10.0, 0.3e-5
C = GEOMETRY["clearance"]


def bearing(thermal=OIL, viscosity=None):
    return JournalBearing(**GEOMETRY, viscosity=viscosity, grid=GRID, thermal=thermal)


def one_node(b, ecc=ECC):
    rotor = Rotor(mass=MASS * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    return RotorBearingSystem(rotor, {0: b}, unbalance=[(0, MASS * ecc, 0.0)], gravity=LOAD / MASS)


def two_bearings(b, unbalance=MASS * ECC):
    """A rigid rotor of 2 MASS (0.3 kg m^2) on two bearings 0.5 m apart, its centre of mass 0.2 m from bearing 0,
    which carries 0.6 of the weight (2.4 kN against 1.6 kN), the unbalance at bearing 0."""
    c, span = np.array([0.6, 0.4]), 0.5  # the centre's position x_c = c . (x_0, x_1)
    t = 2 * MASS * np.outer(c, c) + 0.3 / span ** 2 * np.array([[1.0, -1.0], [-1.0, 1.0]])
    rotor = Rotor(mass=np.kron(t, np.eye(2)), stiffness=np.zeros((4, 4)), nodes=[0, 1])
    return RotorBearingSystem(rotor, {0: b, 1: b}, unbalance=[(0, unbalance, 0.0)], gravity=LOAD / MASS)


@pytest.fixture(scope="module")
def cold_start():
    """The one-node rotor from its thermal equilibrium's position with the oil at the supply temperature, no
    unbalance: the films heat up at constant speed (thermal interval 1 rev)."""
    s = one_node(bearing(), ecc=0.0)
    r = s.run(10, SPEED, thermal_interval=1.0, temperature=OIL.supply_temperature,
              recording=Recording(outputs_per_revolution=20))
    assert r.success, r.message
    return s, r


def test_zero_temperature_coefficient_is_the_isothermal_rotor():
    """A viscosity law with equal viscosities at both points (fluidity exactly 1): the thermal rotor on two
    bearings (0.3 C of unbalance) takes the isothermal rotor's steps (BDF2 in chunks of the thermal interval) and its orbits to 1e-12 C;
    the temperatures are still solved."""
    mu = 0.02
    iso = two_bearings(JournalBearing(**GEOMETRY, viscosity=mu, grid=GRID), unbalance=MASS * 0.3 * C)
    hot = two_bearings(bearing(replace(OIL, viscosity_at=((320.0, mu), (350.0, mu))), viscosity=mu),
                       unbalance=MASS * 0.3 * C)
    y0 = iso.equilibrium(SPEED).state
    rc = Recording(outputs_per_revolution=20)
    a = iso.run(1.5, SPEED, start=(0.0, y0), integration=Integration(method="bdf2"),
                long_run=LongRun(chunk_revolutions=0.5), recording=rc)
    b = hot.run(1.5, SPEED, start=(0.0, y0), thermal_interval=0.5, recording=rc)
    assert a.success and b.success and b.method == "bdf2"
    assert b.stats.n_steps == a.stats.n_steps
    assert np.max(np.abs(b.displacement - a.displacement)) <= 1e-12 * C
    assert np.max(np.abs(a.displacement - a.displacement[0])) > 1e-3 * C  # the orbit moves
    assert np.all(b.max_temperature[-1] > OIL.supply_temperature + 1.0)


def test_one_node_rotor_is_the_thermal_journal_orbit():
    """The same equations and the same temperature coupling (thermal interval 0.5 rev, plain BDF2 at the rotor's
    step cap): the journal to 1e-6 C, the hottest temperature to 1e-6 K at every output."""
    b = bearing()
    kw = dict(thermal_interval=0.5)
    r = one_node(b).run(1, SPEED, integration=Integration(method="bdf2", rtol=1e-7, atol=1e-10),
                        recording=Recording(outputs_per_revolution=20), **kw)
    o = JournalOrbit(b, MASS, ECC, LOAD, SPEED).run(
        1, integration=Integration(method="bdf2", rtol=1e-7, atol=1e-10, max_order=2,
                                   steps_per_revolution=BDF2_STEPS_PER_REVOLUTION),
        recording=Recording(outputs_per_revolution=20, record=("max_temperature", "power_loss")), **kw)
    assert r.success and o.success and np.allclose(r.t, o.t, rtol=1e-12)
    x, y = r.position(0)
    assert np.max(np.hypot(x - o.x, y - o.y)) < 1e-6 * C
    assert np.max(np.abs(r.max_temperature[:, 0] - o.max_temperature)) < 1e-6
    assert np.max(np.abs(r.power_loss[:, 0] - o.power_loss)) < 1e-6 * o.power_loss[0]
    assert np.max(np.hypot(o.x - o.x[0], o.y - o.y[0])) > 1e-4 * C  # the orbit moves (100 times the tolerance)
    assert r.max_temperature[-1, 0] != r.max_temperature[0, 0]  # the temperatures move


def test_long_time_limit_is_the_thermal_equilibrium(cold_start):
    """From the oil at the supply temperature the rotor settles to its thermal static equilibrium: after 10
    revolutions at 1 rev intervals within 1e-4 C and 0.05 K (the thermal orbit's approach, docs/validation.md)."""
    s, r = cold_start
    e = s.equilibrium(SPEED)
    x, y = r.position(0)
    ex, ey = e.displacement[0]
    assert np.hypot(x[-1] - ex, y[-1] - ey) <= 1e-4 * C
    assert r.max_temperature[-1, 0] == pytest.approx(e.max_temperature[0], abs=0.05)
    assert r.power_loss[-1, 0] == pytest.approx(e.power_loss[0], rel=1e-3)
    assert r.max_temperature[0, 0] == OIL.supply_temperature and e.max_temperature[0] - OIL.supply_temperature > 10


def test_energy_balance_per_revolution(cold_start):
    """Heat made = heat carried away and conducted + the change of the heat stored, per thermal interval (1 rev),
    within 1e-3 of the heat made in every interval, the first of the cold start included (measured <= 8.5e-5)."""
    s, r = cold_start
    h = r.heat_balance[0]
    error = h["stored"] - (h["dissipation"] - h["heat_out"])
    assert h["dissipation"].size == 10
    assert np.all(np.abs(error) <= 1e-3 * h["dissipation"])
    assert h["stored"][0] > 0.3 * h["dissipation"][0]  # a transient: the film stores much of its heat at first


def test_checkpoint_resume_carries_the_temperatures(tmp_path, monkeypatch):
    """A thermal two-bearing run killed in its third interval and resumed from its checkpoint ends where the
    uninterrupted run does, bit for bit: orbits, temperatures, heat ledgers."""
    kw = dict(thermal_interval=0.25, recording=Recording(outputs_per_revolution=20),
              temperature=OIL.supply_temperature)
    lr = LongRun(progress=False)
    full = two_bearings(bearing()).run(0.75, SPEED, long_run=lr, **kw)
    path = tmp_path / "thermal.npz"
    set_speed = ThermalContentSystem.set_speed

    def killed(self, tau):
        if tau > 2 * np.pi * 0.6:
            raise KeyboardInterrupt
        set_speed(self, tau)

    monkeypatch.setattr(ThermalContentSystem, "set_speed", killed)
    with pytest.raises(Interrupted, match="run again with resume=True"):
        two_bearings(bearing()).run(0.75, SPEED, long_run=replace(lr, checkpoint=str(path)), **kw)
    monkeypatch.undo()
    resumed = two_bearings(bearing()).run(0.75, SPEED, long_run=replace(lr, checkpoint=str(path), resume=True),
                                          **kw)
    assert resumed.success and resumed.stats.n_steps < 2 * full.stats.n_steps
    for k in ("t", "displacement", "max_temperature", "power_loss", "stored_heat", "final_temperature",
              "final_state"):
        np.testing.assert_array_equal(getattr(resumed, k), getattr(full, k))
    for k in (0, 1):  # per thermal bearing, in the order of thermal_nodes
        for name, v in full.heat_balance[k].items():
            np.testing.assert_array_equal(resumed.heat_balance[k][name], v)
    assert np.all(full.max_temperature[-1] > full.max_temperature[0])


@pytest.mark.parametrize("call, words", [
    (lambda s: s.run(1, SPEED, integration=Integration(method="ida")), "method = 'ida' with thermal bearings"),
    (lambda s: s.run(1, SPEED, thermal_interval=0.001), "thermal_interval"),
    (lambda s: s.run(1, SPEED, long_run=LongRun(chunk_revolutions=0.5)), "chunk_revolutions"),
    (lambda s: s.run(1, SPEED, temperature=[330.0, 331.0]), "temperature"),
    (lambda s: s.linearisation(SPEED), "linearisation with thermal bearings"),
    (lambda s: s.periodic_response(SPEED), "periodic_response with thermal bearings"),
])
def test_bad_input_is_named(call, words):
    with pytest.raises(ValueError, match=words):
        call(one_node(bearing()))


def test_tilt_coupling_and_isothermal_temperature_are_refused():
    r = Rotor(mass=MASS * np.eye(4), stiffness=np.zeros((4, 4)), nodes=[0], dofs=("x", "y", "tx", "ty"))
    with pytest.raises(ValueError, match="tilt_coupling = True with thermal bearings"):
        RotorBearingSystem(r, {0: bearing()}, tilt_coupling=True)
    with pytest.raises(ValueError, match="temperature = 330.0 .* without thermal bearings"):
        one_node(JournalBearing(**GEOMETRY, viscosity=0.02, grid=GRID)).run(1, SPEED, temperature=330.0)
