"""``RotorBearingSystem.periodic_response`` and ``response_curve`` on both period maps (models/rotor/periodic.py):
the conservative BDF2 (content films) gives the journal orbit's BDF2 periodic orbit on a one-node rotor and IDA's
within BDF2's time-discretisation error; the response curve's continuation and Floquet verdicts."""

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING
from transient.solvers.shooting import ShootingSettings

M_ROTOR, ECC, G = 100.0, 0.8e-6, 9.81
C = BEARING["clearance"]


@pytest.fixture(scope="module")
def bearing():
    return JournalBearing(**BEARING, grid=(24, 4))


@pytest.fixture(scope="module")
def one_node(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    return RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)


@pytest.fixture(scope="module")
def orbits(one_node):
    return {m: one_node.periodic_response(6000, rtol=1e-6, tol=1e-7, integrator=m) for m in ("ida", "bdf2")}


def test_bdf2_periodic_response_of_one_node_is_the_journal_orbits(bearing, orbits):
    """The same equations as the journal orbit's (tests/models/rotor/test_system_bdf2.py runs both on the same
    steps); the journal's period map integrates them by its variable-order BDF, the rotor's by plain BDF2 at its
    550-step cap, whose own error on an orbit of this size is ~2e-6 C per revolution (docs/periodic.md): the fixed
    points agree within that (5e-6 C, as BDF2 against IDA below), each found to tol = 1e-7 C."""
    p = orbits["bdf2"]
    o = JournalOrbit(bearing, M_ROTOR, ECC, M_ROTOR * G, 6000).periodic_response(rtol=1e-6, tol=1e-7,
                                                                                 integrator="bdf2")
    assert p.success and p.converged and p.stable and p.integrator == "bdf2", p.message
    assert p.error_estimate <= 1e-7 and o.success
    x, y = p.position(0)
    assert np.max(np.hypot(x - o.x, y - o.y)) < 5e-6 * C  # measured 2.4e-6 C (3.4e-8 C with both on plain BDF2)
    assert np.ptp(x) > 0.02 * C  # the orbit moves
    assert np.allclose(np.sort_complex(p.multipliers[:2]), np.sort_complex(o.multipliers[:2]), atol=1e-2)


def test_bdf2_and_ida_periodic_orbits_agree_within_bdf2s_error(orbits):
    """IDA (variable order, rtol 1e-6) and BDF2 (second order at its 550-step cap: ~2e-6 C per revolution on an
    orbit of this size, docs/periodic.md) integrate the same semi-discrete model."""
    a, b = orbits["ida"], orbits["bdf2"]
    assert a.success and a.integrator == "ida"
    xa, ya = a.position(0)
    xb, yb = b.position(0)
    assert np.max(np.hypot(xa - xb, ya - yb)) < 5e-6 * C  # measured 1.8e-6 C
    assert abs(a.max_multiplier - b.max_multiplier) < 1e-2
    nf = a.state.size - 5  # the film states, in the universal layout for both
    assert np.max(np.abs(a.state[:nf] - b.state[:nf])) < 1e-4 * np.max(np.abs(a.state[:nf]))  # measured 2.3e-6


@pytest.mark.slow
def test_response_curve_continues_on_bdf2_and_flags_the_unstable_orbit(one_node, bearing):
    """Continuation in speed across the whirl onset of the one-node rotor (the journal's, ~7800 rpm on the paper's
    grid): stable below, unstable (|mu| > 1) above, the onset between; the same rotor's linearised threshold with
    the film states lies in the same bracket."""
    speeds = [7000.0, 7500.0, 8000.0, 8500.0]
    c = one_node.response_curve(speeds, rtol=1e-5, integrator="bdf2", shooting=ShootingSettings(max_iter=15, relax=1))
    assert np.all(c.converged), c.message
    assert c.stable[0] and not c.stable[-1] and c.integrator == "bdf2"
    assert speeds[0] < c.onset_rpm < speeds[-1]
    threshold = one_node.stability_threshold((6000.0, 9000.0))
    lo = max(n for n in speeds if n < c.onset_rpm)
    assert lo < threshold < lo + 500.0 or abs(threshold - c.onset_rpm) < 0.02 * threshold
    ax, ay = c.amplitudes(0)
    assert np.all(ax > 0) and np.all(ay > 0)
    assert c.orbits[0].position(0)[0].size == 65


def test_response_curve_warm_starts_and_saves(one_node, tmp_path):
    """Two speeds by continuation on IDA: the second, started from the first's orbit on its refined basis, converges
    to the orbit of a cold start (each fixed point to tol = 1e-5 C); the curve saves and loads with its orbits."""
    from transient.results import load_result

    c = one_node.response_curve([6000.0, 6200.0], rtol=1e-5)
    cold = one_node.periodic_response(6200.0, rtol=1e-5)
    assert np.all(c.converged) and np.all(c.stable) and np.isnan(c.onset_rpm), c.message
    x, y = c.orbits[1].position(0)
    xc, yc = cold.position(0)
    assert np.max(np.hypot(x - xc, y - yc)) < 2e-5 * C
    assert abs(c.amplitudes(0)[0][1] - cold.amplitude(0)[0]) < 2e-5 * C
    back = load_result(c.save(tmp_path / "curve"))
    assert np.array_equal(back.amplitude, c.amplitude) and len(back.orbits) == 2
    assert back.units()["amplitude"] == "m" and back.orbits[1].stable


def test_periodic_response_refusals(one_node):
    with pytest.raises(ValueError, match="integrator"):
        one_node.periodic_response(6000, integrator="rk4")
    with pytest.raises(ValueError, match="max_iter"):
        one_node.periodic_response(6000, max_iter=3, shooting=ShootingSettings())
    with pytest.raises(ValueError, match="strictly monotone"):
        one_node.response_curve([3000.0, 2000.0, 2500.0])
    with pytest.raises(ValueError, match="start has shape"):
        one_node.periodic_response(6000, start=np.zeros(3))
