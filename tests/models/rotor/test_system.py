"""A rotor on several journal bearings: the analytic Jacobian against finite differences, the one-node and the
symmetric two-bearing rotor against the single-bearing orbit, the static equilibrium against the shaft's
statics, results with units, bad input."""

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, Recording
from transient.models.rotor import Rotor, RotorBearingSystem, RotorRunResult
from transient.params.rho_kim import BEARING
from transient.results import load_result

M_ROTOR, ECC, G = 100.0, 0.8e-6, 9.81


@pytest.fixture(scope="module")
def bearing():
    return JournalBearing(**BEARING, grid=(48, 8))


def test_one_node_rotor_is_the_journal_orbit(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    r = s.run(2, 6000, integration=Integration(rtol=1e-7, atol=1e-10))
    o = JournalOrbit(bearing, M_ROTOR, ECC, M_ROTOR * G, 6000).run(2, integration=Integration(rtol=1e-7, atol=1e-10))
    assert r.success and np.array_equal(r.t, o.t)
    x, y = r.position(0)
    assert np.max(np.abs(x - o.x)) < 1e-6 * bearing.clearance
    assert np.max(np.abs(y - o.y)) < 1e-6 * bearing.clearance
    assert np.max(np.hypot(o.x - o.x[0], o.y - o.y[0])) > 1e-3 * bearing.clearance  # the orbit moves


def test_symmetric_rotor_on_two_bearings_is_the_half_orbit(bearing):
    rotor = Rotor.rigid(M_ROTOR, 3.0, 0.5)
    s = RotorBearingSystem(rotor, {0: bearing, 1: bearing}, unbalance=[(0, M_ROTOR * ECC / 2, 0.0),
                                                                       (1, M_ROTOR * ECC / 2, 0.0)], gravity=G)
    eq = s.equilibrium(6000)
    assert eq.bearing_load == pytest.approx([M_ROTOR * G / 2] * 2, rel=1e-8)
    half = bearing.equilibrium(M_ROTOR * G / 2, 6000)
    assert np.allclose(eq.position(0), half.position, rtol=1e-6)
    r = s.run(2, 6000, integration=Integration(rtol=1e-7, atol=1e-10))
    o = JournalOrbit(bearing, M_ROTOR / 2, ECC, M_ROTOR * G / 2, 6000).run(
        2, integration=Integration(rtol=1e-7, atol=1e-10))
    for node in (0, 1):
        x, y = r.position(node)
        assert np.max(np.hypot(x - o.x, y - o.y)) < 1e-6 * bearing.clearance


def flexible_system(bearing, reduced=True):
    """Two nodes joined by a shaft spring, each with its own bearing (one offset), gyroscopic coupling,
    structural damping, unbalances at both; ``reduced``: on a non-trivial basis (three coordinates)."""
    k = 2e8
    M_full = np.diag([30.0, 30.0, 20.0, 20.0])
    K_full = k * np.array([[1, 0, -1, 0], [0, 1, 0, -1], [-1, 0, 1, 0], [0, -1, 0, 1.0]])
    basis = np.array([[1.0, 0, 0.2], [0, 1, 0], [0.3, 0, 1], [0, 0.5, 1]]) if reduced else np.eye(4)
    Gf = np.zeros((4, 4))
    Gf[0, 1], Gf[1, 0] = 0.02, -0.02
    rotor = Rotor(mass=basis.T @ M_full @ basis, stiffness=basis.T @ K_full @ basis, damping=basis.T @ (1e-5 * K_full) @ basis,
                  gyroscopic=basis.T @ Gf @ basis, nodes=[0, 1], basis=basis,
                  gravity_load=np.vstack([basis.T @ M_full @ [1, 0, 1, 0], basis.T @ M_full @ [0, 1, 0, 1]]))
    other = JournalBearing(**dict(BEARING, clearance=100e-6), grid=(16, 4))
    return RotorBearingSystem(rotor, {0: bearing, 1: other}, unbalance=[(0, 1e-4, 30.0), (1, 2e-4, -60.0)],
                              gravity=(9.81, 1.0))


def test_system_jacobian_matches_finite_differences(fd_jacobian):
    b = JournalBearing(**BEARING, grid=(16, 4))
    s = flexible_system(b)
    dae = s.dae(6000.0, lambda tau: (0.8 + 0.01 * tau, 0.01))
    eq = s._start_guess(dae, 0.8)
    rng = np.random.default_rng(1)
    y = eq + 1e-3 * rng.standard_normal(dae.n)
    y[dae.Q0:dae.P0] += 0.05 * rng.standard_normal(2 * dae.nq)
    y[dae.P0] = 0.7
    yp = 1e-2 * rng.standard_normal(dae.n)
    cj = 3.7

    def F(y_, yp_):
        out = np.empty(dae.n)
        dae.residual(0.3, y_, yp_, out)
        return out

    J_fd = fd_jacobian(lambda v: F(v, yp), y, dae.n, step=1e-7) + cj * fd_jacobian(lambda v: F(y, v), yp, dae.n,
                                                                                       step=1e-7)
    data = np.empty(dae.pattern.nnz)
    dae.jacobian(0.3, y, yp, cj, data)
    J = dae.pattern.copy()
    J.data = data
    J = J.toarray()
    scale = np.max(np.abs(J_fd), axis=1, keepdims=True) + 1e-12
    assert np.max(np.abs(J - J_fd) / scale) < 1e-5
    outside = (J_fd != 0) & (dae.pattern.toarray() == 0)
    assert not np.any(np.abs(J_fd[outside]) > 1e-8 * scale.repeat(dae.n, axis=1)[outside])


def test_equilibrium_balances_the_weight_of_a_flexible_rotor(bearing):
    s = flexible_system(bearing, reduced=False)
    eq = s.equilibrium(6000)
    assert s.rotor.total_mass == pytest.approx(50.0)
    assert -eq.bearing_force[:, 0].sum() == pytest.approx(9.81 * 50.0, rel=1e-9)
    assert -eq.bearing_force[:, 1].sum() == pytest.approx(1.0 * 50.0, rel=1e-9)
    loads = s.static_loads()  # the shaft on rigid supports: each node carries its own mass
    assert loads[0] == pytest.approx((9.81 * 30, 30.0), rel=1e-5) and loads[1] == pytest.approx((9.81 * 20, 20.0), rel=1e-5)


def test_run_result_units_save_load_and_continuation(bearing, tmp_path):
    s = flexible_system(bearing)
    r = s.run(0.5, 6000, recording=Recording(outputs_per_revolution=40))
    assert r.units()["displacement"] == "m" and r.units()["t"] == "s"
    back = load_result(r.save(tmp_path / "run"))
    assert isinstance(back, RotorRunResult)
    assert np.array_equal(back.position(1)[0], r.position(1)[0])
    whole = s.run(1.0, 6000, recording=Recording(outputs_per_revolution=40))
    more = s.run(0.5, 6000, recording=Recording(outputs_per_revolution=40), start=r)
    joined = r + more
    assert np.allclose(joined.t, whole.t, rtol=1e-12)
    assert np.max(np.abs(joined.displacement - whole.displacement)) < 1e-3 * bearing.clearance


def test_constant_speed_function_is_the_constant_speed(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    a = s.run(1, 6000, integration=Integration(rtol=1e-7, atol=1e-10))
    b = s.run(1, lambda t: 6000.0, integration=Integration(rtol=1e-7, atol=1e-10))
    assert np.allclose(a.t, b.t, rtol=1e-9)
    assert np.max(np.abs(a.displacement - b.displacement)) < 1e-7 * bearing.clearance


def test_run_up_follows_the_speed_and_turns_the_revolutions(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * ECC, 0.0)], gravity=G)
    ramp = lambda t: 3000.0 + 60000.0 * t  # noqa: E731 -- 1000 rpm/s ... 60000 rpm/s: 3000 -> ~4100 rpm
    r = s.run(2, ramp, recording=Recording(outputs_per_revolution=20))
    assert r.success
    assert np.allclose(r.speed_rpm, ramp(r.t))
    assert r.revolutions[-1] == pytest.approx(2.0, rel=1e-3)


def test_bad_input_names_the_parameter(bearing):
    with pytest.raises(ValueError, match="mass is not symmetric"):
        Rotor(mass=[[1.0, 0.1], [0.0, 1.0]], stiffness=np.zeros((2, 2)))
    with pytest.raises(ValueError, match="mass is singular"):
        Rotor(mass=[[1.0, 1.0], [1.0, 1.0]], stiffness=np.zeros((2, 2)))
    with pytest.raises(ValueError, match=r"stiffness has shape \(3, 3\)"):
        Rotor(mass=np.eye(2), stiffness=np.zeros((3, 3)))
    with pytest.raises(ValueError, match="dofs"):
        Rotor(mass=np.eye(2), stiffness=np.zeros((2, 2)), dofs=("x", "z"))
    with pytest.raises(ValueError, match="nodes has 2 labels"):
        Rotor(mass=np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0, 1])
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    with pytest.raises(ValueError, match=r"bearings: node = 3 is not a node"):
        RotorBearingSystem(rotor, {3: bearing})
    with pytest.raises(ValueError, match=r"unbalance\[0\]: node = 5"):
        RotorBearingSystem(rotor, {0: bearing}, unbalance=[(5, 1e-4, 0.0)])
    with pytest.raises(ValueError, match=r"unbalance\[0\] m e = -1 \[kg m\]"):
        RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, -1, 0.0)])
    with pytest.raises(ValueError, match=r"cavitation = 'reynolds'"):
        RotorBearingSystem(rotor, {0: JournalBearing(**BEARING, grid=(16, 4), cavitation="reynolds")})
    with pytest.raises(ValueError, match=r"gravity = .* \[m/s\^2\]"):
        RotorBearingSystem(rotor, {0: bearing}, gravity=(1.0, 2.0, 3.0))
    soft = Rotor(mass=M_ROTOR * np.eye(4), stiffness=1e3 * np.array([[1, 0, -1, 0], [0, 1, 0, -1], [-1, 0, 1, 0],
                                                                     [0, -1, 0, 1.0]]), nodes=[0, 1])
    with pytest.raises(ValueError, match="more than 1000 bearing clearances"):  # a rotor in N/mm, not N/m
        RotorBearingSystem(Rotor(mass=M_ROTOR * np.eye(4), stiffness=1e-3 * soft.stiffness, nodes=[0, 1]),
                           {0: bearing}, gravity=G)
    heavy = RotorBearingSystem(Rotor(mass=1e6 * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: bearing})
    with pytest.raises(ValueError, match="cannot carry its static load"):
        heavy.equilibrium(6000)
    s = RotorBearingSystem(rotor, {0: bearing}, gravity=G)
    with pytest.raises(ValueError, match=r"speed_rpm\(t = 0 s\) = 0 \[rpm\]"):
        s.run(1, lambda t: 1000.0 * t)
    with pytest.raises(ValueError, match="method"):
        s.run(1, 6000, integration=Integration(method="rk45"))


def test_rigid_and_jeffcott_builders():
    r = Rotor.rigid(10.0, 2.0, 0.4)
    assert r.total_mass == pytest.approx(10.0)
    tilt = np.array([-0.2, 0, 0.2, 0])  # a unit tilt about the centre: kinetic energy I / 2
    assert tilt @ r.mass @ tilt == pytest.approx(2.0)
    j = Rotor.jeffcott(1e6, 8.0, 1.0)
    assert j.total_mass == pytest.approx(10.0)
    assert np.allclose(j.stiffness @ np.tile([1.0, 0.0], 3), 0.0)  # a free rigid translation


def test_touch_event_stops_the_run_at_the_bearing(bearing):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    s = RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, M_ROTOR * 0.6 * bearing.clearance, 0.0)], gravity=G)
    r = s.run(3, 6000, touch_gap=0.4, recording=Recording(outputs_per_revolution=32))
    assert r.touched_at is not None and r.t[-1] < 3 * 0.01
    assert "touches its bearing" in r.message
    assert r.eccentricity_ratio(0).max() <= 0.6 + 1e-3


def test_equilibrium_by_bordered_band_lu_equals_the_sparse_lu(bearing, monkeypatch):
    """The equilibrium's Newton solves on the bordered band LU (a band block per film, the rotor the border); the
    same Newton on SuperLU of the whole system, in the same run, reaches the same state (to the Newton's xtol)."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    from transient.models.rotor import system

    s = flexible_system(bearing, reduced=False)
    band = s.equilibrium(6000).state

    class SparseLU:
        def __init__(self, pattern, n_border):
            self.pattern = pattern

        def factor(self, data):
            self.lu = spla.splu(sp.csc_matrix((data.copy(), self.pattern.indices, self.pattern.indptr),
                                              shape=self.pattern.shape))
            return 0

        def solve(self, rhs):
            return self.lu.solve(rhs)

    monkeypatch.setattr(system, "BorderedBandLU", SparseLU)
    sparse = s.equilibrium(6000).state
    assert np.max(np.abs(band - sparse)) <= 1e-9 * max(1.0, np.max(np.abs(sparse)))
