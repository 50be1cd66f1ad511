"""The rotor run on the journal orbit's speed law (``RotorBearingSystem.run(speed_profile=...)``,
models/journal/speed_law.py): a constant law is the constant-speed run, a ramp as a table is the same ramp as a speed
function (whose rate the run differences), the shaft angle is the law's closed form, and the run takes one of
``speed_rpm`` and ``speed_profile``."""

import numpy as np
import pytest

from transient import Integration, JournalBearing, SpeedProfile
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING, ROTOR

M, E = ROTOR["rotor_mass"], ROTOR["unbalance"]
METHODS = ("ida", "bdf2")


@pytest.fixture(scope="module")
def system():
    """Rho & Kim's rotor as a one-node rotor on its bearing (24 x 4), unbalance 0.01 C."""
    b = JournalBearing(**BEARING, grid=(24, 4))
    return RotorBearingSystem(Rotor(mass=M * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: b},
                              unbalance=[(0, M * E, 0.0)], gravity=ROTOR["load"] / M)


@pytest.mark.parametrize("method", METHODS)
def test_a_constant_law_is_the_constant_speed_run(system, method):
    """``speed_profile=((0, n),)`` against ``speed_rpm=n``: the same steps and the same orbit (1e-12 C: both give
    the kernels s = 1, s' = 0; the run's end time, found from the law, agrees to rounding)."""
    ig = Integration(method=method, rtol=1e-7)
    a = system.run(0.3, 3000.0, integration=ig)
    b = system.run(0.3, speed_profile=((0.0, 3000.0),), integration=ig)
    assert a.success and b.success
    assert b.stats.n_steps == a.stats.n_steps
    assert b.final_time == pytest.approx(a.final_time, rel=1e-12)
    assert np.max(np.abs(b.displacement - a.displacement)) < 1e-12 * system.length_scale


def ramp(t):
    """1500 rpm until 5 ms, then 1.5e5 rpm/s to 3000 rpm at 15 ms, 3000 after."""
    return 1500.0 + 1500.0 * min(max((t - 0.005) / 0.01, 0.0), 1.0)


@pytest.mark.parametrize("method", METHODS)
def test_a_ramp_table_is_the_speed_function_and_its_angle_the_closed_form(system, method):
    """The ramp as a table against the same ramp as a speed function (the run differences its rate), 0.6 rev from
    the 1500 rpm equilibrium at rtol 1e-8: the same end time, positions within 1e-6 C; the shaft angle of the table
    run at its end is the law's closed form (``SpeedProfile.angle``) to 1e-7 rad (the angle row phi' = s is
    integrated by the stepper, exactly for BDF of order >= 2 inside a straight piece)."""
    table = ((0.0, 1500.0), (0.005, 1500.0), (0.015, 3000.0))
    ig = Integration(method=method, rtol=1e-8, atol=1e-11)
    old = system.run(0.6, ramp, integration=ig)
    new = system.run(0.6, speed_profile=table, integration=ig)
    assert old.success and new.success
    assert new.final_time == pytest.approx(old.final_time, rel=1e-9)
    assert new.final_time > 0.015  # the ramp is inside the run
    np.testing.assert_allclose(new.speed_rpm, [ramp(t) for t in new.t], rtol=1e-12)
    assert np.max(np.abs(new.displacement - old.displacement)) < 1e-6 * system.length_scale
    dae = system.dae(3000.0)
    assert abs(new.final_state[dae.P0] - SpeedProfile(table).angle(new.final_time)) < 1e-7


def test_the_run_takes_one_speed():
    b = JournalBearing(**BEARING, grid=(8, 2))
    s = RotorBearingSystem(Rotor(mass=M * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: b})
    with pytest.raises(ValueError, match="speed_rpm = 3000.0, speed_profile = .*allowed: one of them"):
        s.run(0.1, 3000.0, speed_profile=((0.0, 3000.0),))
    with pytest.raises(ValueError, match="speed_rpm = None, speed_profile = None.*allowed: one of them"):
        s.run(0.1)
