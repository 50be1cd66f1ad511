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
