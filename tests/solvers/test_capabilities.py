"""Capabilities checked at the door: a model asked for a method it cannot be integrated by is refused before any
work, naming the entry point, the method and the methods it takes; a model that hands BDF2 its step solve takes
it everywhere a method is chosen (scene files included)."""

import time

import pytest

from transient import Integration, JournalBearing, JournalOrbit, ThrustBallBearing, ThrustPad
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.integrate import METHODS, check_method, methods_for
from transient.study.scene import KINDS


def test_methods_for_a_model_without_step_solve_leave_out_bdf2():
    assert "bdf2" in METHODS and "bdf2" in methods_for(step_solve=True)
    assert "bdf2" not in methods_for(step_solve=False)
    assert set(methods_for(step_solve=False)) == set(METHODS) - {"bdf2"}


@pytest.mark.parametrize("method", ["bdf2", "rk45", 3, None])
def test_check_method_names_owner_method_and_offered(method):
    with pytest.raises(ValueError) as e:
        check_method("Thing.run", method)
    text = str(e.value)
    assert "Thing.run" in text and repr(method) in text and "cvode" in text and "bdf2, " not in text
    if method == "bdf2":
        assert "step solve" in text


def test_thrust_pad_descent_refuses_bdf2_before_any_work():
    pad = ThrustPad(0.02, 0.02, 0.01, grid=(200, 200))
    t0 = time.process_time()
    with pytest.raises(ValueError, match=r"ThrustPad.descent: method = 'bdf2' is not available"):
        pad.descent(100.0, 10e-6, 1e-3, method="bdf2", path="full")
    assert time.process_time() - t0 < 5.0  # refused at the check, not inside the integrator


def test_ball_sequence_refuses_bdf2_before_any_work():
    with pytest.raises(ValueError, match=r"ThrustBallBearing.sequence: method = 'bdf2' is not available"):
        ThrustBallBearing().sequence(100.0, 1000.0, 1e-6, n_passes=3,
                                     integration=Integration(method="bdf2", atol=1e-10))


def test_journal_orbit_takes_bdf2_and_the_scene_offers_it():
    assert "bdf2" in KINDS["journal_orbit"].run["method"].choices
    b = JournalBearing(**BEARING, grid=(12, 4))
    r = JournalOrbit(b, ROTOR["rotor_mass"], 0.3 * BEARING["clearance"], ROTOR["load"], 6000.0).run(
        0.05, integration=Integration(method="bdf2"))
    assert r.success and r.method == "bdf2"


def _refused(call, owner, method, offered, why=""):
    """``call`` is refused before any work (under a second of CPU), naming ``owner``, ``method`` and exactly the
    methods ``offered``."""
    t0 = time.process_time()
    with pytest.raises(ValueError) as e:
        call()
    assert time.process_time() - t0 < 1.0
    assert str(e.value) == (f"{owner}: method = {method!r} is not available{why}; it takes one of "
                            f"{', '.join(offered)}")


def test_every_model_refuses_an_impossible_method_at_its_door():
    """Pad, ball, point, line, roller, orbit and rotor: each names itself and the methods it takes."""
    from transient import Rotor, RotorBearingSystem
    from transient.models.point import PointContact
    from transient.models.roller import LineContact, RollerContact, TaperedRoller

    no_step_solve = tuple(m for m in METHODS if m != "bdf2")
    why = " ('bdf2' integrates only models that hand it their own step solve; {} has none)"
    _refused(lambda: ThrustPad(0.02, 0.02, 0.01, grid=(4, 4)).descent(100.0, 1e-5, 1e-3,
                                                                        integration=Integration(method="bdf2")),
             "ThrustPad.descent", "bdf2", no_step_solve, why.format("ThrustPad.descent"))
    _refused(lambda: ThrustBallBearing().sequence(100.0, 1000.0, 1e-6, integration=Integration(method="bdf2")),
             "ThrustBallBearing.sequence", "bdf2", no_step_solve, why.format("ThrustBallBearing.sequence"))
    point = PointContact(0.01, grid=(25, 25), load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8,
                         modulus=2.2e11)
    _refused(lambda: point.transient(1e-4, integration=Integration(method="ida")), "PointContact.transient", "ida",
             ("bdf2",))
    line = LineContact(0.01, 3.1e4, 1.0, 0.022, 2500 / 220e9, 220e9, grid=101, domain=(-5.0, 2.5))
    _refused(lambda: line.transient(1e-6, integration=Integration(method="rk4", dt=0.1)), "LineContact.transient",
             "rk4", ("ida", "bdf2"))
    roller = RollerContact.from_dimensionless(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=2.2e11,
                                              roller=TaperedRoller(0.01, 10.0, 0.02, 0.005, 0.002, 0.0),
                                              grid=(12, 8))
    _refused(lambda: roller.transient(1e-6, integration=Integration(method="rk4", dt=0.1)),
             "RollerContact.transient", "rk4", ("ida", "bdf2"))
    b = JournalBearing(**BEARING, grid=(12, 4))
    orbit = JournalOrbit(b, ROTOR["rotor_mass"], 0.0, ROTOR["load"], 3000.0)
    _refused(lambda: orbit.run(1.0, method="euler"), "JournalOrbit.run", "euler", METHODS)  # the old keyword too
    rotor = Rotor.example()
    system = RotorBearingSystem(rotor, {n: JournalBearing(**BEARING, grid=(12, 4)) for n in rotor.bearing_nodes})
    _refused(lambda: system.run(1.0, 3000.0, integration=Integration(method="cvode")), "RotorBearingSystem.run",
             "cvode", ("ida", "bdf2"))
