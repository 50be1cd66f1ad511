"""A rotor whose films take its nodes' tilts (``RotorBearingSystem(tilt_coupling=True)``, models/rotor/kernels.py
tilted blocks): the aligned path bitwise at zero tilt, the analytic Jacobians (IDA and BDF2) against differences, a
free journal following its misaligned bush, moments odd in the misalignment, the one-node rotor's eigenvalues from
the single bearing's 4 x 4 coefficients, those coefficients against differences, a symmetric shaft's opposite tilts."""

import numpy as np
import pytest

from transient import Integration, JournalBearing, Recording, SqueezeFilmDamper
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.models.rotor.shaft import Disk, shaft_matrices
from transient.params.rho_kim import BEARING

from content_jacobian import content_jacobians

M, INERTIA, SPEED = 100.0, 2.0, 6000.0
DOFS = ("x", "y", "tx", "ty")


def bearing(grid=(16, 6), **kw):
    return JournalBearing(**BEARING, grid=grid, symmetric=False, **kw)


def one_node(b, tilt_stiffness=0.0, coupled=True, unbalance=()):
    """One node of mass M and transverse inertia INERTIA on one bearing, a spring on its tilts."""
    rotor = Rotor(mass=np.diag([M, M, INERTIA, INERTIA]), stiffness=np.diag([0, 0, tilt_stiffness, tilt_stiffness]),
                  nodes=[0], dofs=DOFS)
    return RotorBearingSystem(rotor, {0: b}, gravity=9.81, tilt_coupling=coupled, unbalance=unbalance)


def perturbed(s, seed):
    """A state near the start guess with every rotor coordinate and rate moved, and a y' (IDA's form)."""
    dae = s.dae(SPEED, lambda tau: (0.8 + 0.01 * tau, 0.01))
    rng = np.random.default_rng(seed)
    y = s._start_guess(dae, 0.8) + 1e-3 * rng.standard_normal(dae.n)
    y[dae.Q0:dae.P0] += 0.05 * rng.standard_normal(2 * dae.nq)
    y[dae.P0] = 0.7
    return dae, y, 1e-2 * rng.standard_normal(dae.n)


def jacobian(dae, y, yp, cj):
    data = np.empty(dae.pattern.nnz)
    dae.jacobian(0.3, y, yp, cj, data)
    J = dae.pattern.copy()
    J.data = data
    return J.toarray()


def test_zero_tilt_is_the_aligned_film_bitwise():
    """At a state whose tilts and tilt rates are zero the coupled films' rows, their forces on x and y and their
    Jacobian (cell block, position columns, force rows) are the uncoupled system's to the last bit: the tilted
    kernels add exact zeros on the same arithmetic path."""
    b = bearing()
    on, off = one_node(b, 1e5), one_node(b, 1e5, coupled=False)
    dae, y, yp = perturbed(on, 2)
    dae_off = off.dae(SPEED, dae.speed)
    for v in (y, yp):
        v[dae.Q0 + 2:dae.Q0 + 4] = v[dae.V0 + 2:dae.V0 + 4] = 0.0
    r_on, r_off = np.empty(dae.n), np.empty(dae.n)
    dae.residual(0.3, y, yp, r_on)
    dae_off.residual(0.3, y, yp, r_off)
    n = dae.blocks[0].n
    assert np.array_equal(r_on[:n], r_off[:n])
    assert np.array_equal(r_on[dae.V0:dae.V0 + 2], r_off[dae.V0:dae.V0 + 2])
    assert np.abs(r_on[dae.V0 + 2:dae.V0 + 4] - r_off[dae.V0 + 2:dae.V0 + 4]).max() > 0  # the film's moment
    J_on, J_off = jacobian(dae, y, yp, 3.7), jacobian(dae_off, y, yp, 3.7)
    xy = [dae.Q0, dae.Q0 + 1]
    assert np.array_equal(J_on[:n, :n], J_off[:n, :n]) and np.array_equal(J_on[:n, xy], J_off[:n, xy])
    assert np.array_equal(J_on[dae.V0:dae.V0 + 2, :n], J_off[dae.V0:dae.V0 + 2, :n])


def test_tilted_jacobian_matches_finite_differences(fd_jacobian):
    """IDA's ``dF/dy + cj dF/dy'`` with the node tilted and tilting in a misaligned bush (gap, squeeze rates,
    moments on the tilts): central differences agree to 1e-5 of each row's scale (the uncoupled Jacobian test's
    bound), nothing outside the pattern."""
    s = one_node(bearing(misalignment=(1e-4, -2e-4)), 1e4)
    dae, y, yp = perturbed(s, 1)
    cj = 3.7

    def F(y_, yp_):
        out = np.empty(dae.n)
        dae.residual(0.3, y_, yp_, out)
        return out

    J_fd = fd_jacobian(lambda v: F(v, yp), y, dae.n, step=1e-7) + cj * fd_jacobian(lambda v: F(y, v), yp, dae.n,
                                                                                       step=1e-7)
    J = jacobian(dae, y, yp, cj)
    scale = np.max(np.abs(J_fd), axis=1, keepdims=True) + 1e-12
    assert np.max(np.abs(J - J_fd) / scale) < 1e-5  # measured 7e-7
    tilts = [dae.Q0 + 2, dae.Q0 + 3]
    assert np.abs(J[:dae.blocks[0].n, tilts]).max() > 0 and np.abs(J[dae.V0 + 2:dae.V0 + 4, :dae.Q0]).max() > 0
    outside = (J_fd != 0) & (dae.pattern.toarray() == 0)
    assert not np.any(np.abs(J_fd[outside]) > 1e-8 * scale.repeat(dae.n, axis=1)[outside])


def test_tilted_bdf2_jacobian_matches_finite_differences(fd_jacobian):
    """The BDF2 Newton's ``dF/dz`` (content films) with the node tilted: central differences agree to 1e-6 of each
    column's scale (the uncoupled test's bound) on the free cells and the rotor, the tilt columns included."""
    s = one_node(bearing(misalignment=(1e-4, -2e-4)), 1e4)
    form, dae, J, Jfd, cols = content_jacobians(s, SPEED, 3, fd_jacobian)
    scale = np.max(np.abs(J[:, cols]), axis=0)
    rel = np.max(np.abs(J[:, cols] - Jfd[:, cols]), axis=0) / scale
    assert np.max(rel) < 1e-6, (np.max(rel), cols[np.argmax(rel)])
    assert np.abs(J[:dae.Q0, dae.Q0 + 2:dae.Q0 + 4]).max() > 0


def test_free_journal_follows_its_misaligned_bush():
    """A node free to tilt (no tilt stiffness) in a misaligned bush settles with the journal tilted as the bush: no
    moment, and the force and position of the aligned film under the same load."""
    m = (2e-4, -3e-4)
    s = one_node(bearing(misalignment=m))
    eq = s.equilibrium(SPEED)
    dae = s.dae(SPEED)
    q = eq.state[dae.Q0:dae.V0] * dae.L
    assert q[2:] == pytest.approx(m, rel=1e-7)
    assert np.abs(eq.bearing_moment).max() < 1e-9 * M * 9.81 * BEARING["length"]
    aligned = bearing().equilibrium(M * 9.81, SPEED)
    assert np.allclose(q[:2], aligned.position, rtol=1e-6, atol=1e-9 * BEARING["clearance"])


def test_moments_odd_in_the_misalignment():
    """A node held by a tilt spring in a bush misaligned by +m and by -m (the mirror z -> -z): the same force and
    position, opposite tilts and moments; the moment is the spring's."""
    k = 2e4
    m = np.array([1.5e-4, 2.5e-4])
    out = []
    for sign in (1, -1):
        s = one_node(bearing(misalignment=tuple(sign * m)), k)
        eq = s.equilibrium(SPEED)
        dae = s.dae(SPEED)
        out.append((eq, eq.state[dae.Q0:dae.V0] * dae.L))
    (e1, q1), (e2, q2) = out
    M1, M2 = e1.bearing_moment[0], e2.bearing_moment[0]
    assert np.hypot(*M1) > 1e-3 * M * 9.81 * BEARING["length"]
    assert np.allclose(M1, -M2, rtol=1e-7) and np.allclose(q1[2:], -q2[2:], rtol=1e-7)
    assert np.allclose(e1.bearing_force, e2.bearing_force, rtol=1e-8) and np.allclose(q1[:2], q2[:2], rtol=1e-7)
    assert np.allclose(M1, k * q1[2:], rtol=1e-6)  # (M_x, M_y) balance the spring's k (tx, ty)


def test_one_node_eigenvalues_are_the_bearings_4x4():
    """The coupled one-node rotor's quasi-static eigenvalues and 4 x 4 coefficients are those of the single
    bearing's ``coefficients(tilt_dofs=True)`` at the same load: the rotor's linear matrices use the 4 x 4."""
    b = bearing()
    s = one_node(b, 5e4)
    K, C = s.coefficients(SPEED)[0]
    Kb, Cb = b.coefficients(M * 9.81, SPEED, tilt_dofs=True)
    for A, Ab in ((K, Kb), (C, Cb)):
        assert A.shape == (4, 4)
        assert np.abs(A - Ab).max() < 1e-6 * np.abs(Ab).max()
    Mm = np.diag([M, M, INERTIA, INERTIA])
    Kt = Kb + np.diag([0, 0, 5e4, 5e4])
    A = np.block([[np.zeros((4, 4)), np.eye(4)], [-np.linalg.solve(Mm, Kt), -np.linalg.solve(Mm, Cb)]])
    lam, ref = s.quasi_static_eigenvalues(SPEED), np.linalg.eigvals(A)
    for v in ref:
        assert np.min(np.abs(lam - v)) < 1e-6 * abs(v)
    tilt_modes = np.linalg.eigvals(A[np.ix_([2, 3, 6, 7], [2, 3, 6, 7])])
    assert np.min(np.abs(lam[:, None] - tilt_modes[None, :])) < 1e-6 * np.abs(tilt_modes).max()


def test_system_4x4_equals_finite_differences_of_steady_films():
    """The coupled rotor's 4 x 4 K at its equilibrium in a misaligned bush (cross terms between forces and tilts)
    against central differences of the bearing's steady forces and moments (``steady_state`` with the tilt)."""
    b = bearing(grid=(24, 8), misalignment=(1e-4, 2e-4))
    s = one_node(b, 2e4)
    eq = s.equilibrium(SPEED)
    dae = s.dae(SPEED)
    q = eq.state[dae.Q0:dae.V0] * dae.L
    K, _ = s.coefficients(SPEED, eq)[0]
    CL = BEARING["clearance"]

    def gen(dq):
        x, y, tx, ty = q + dq
        st = b.steady_state(np.hypot(x, y) / CL, SPEED, np.degrees(np.arctan2(y, x)), tilt=(tx, ty))
        return np.array([*st.force, *st.moment])

    hx, ht = 1e-5 * CL, 1e-5 * CL / BEARING["length"]  # the differences' own error: 1.2e-7 here, 1.2e-5 at 1e-4
    steps = np.array([hx, hx, ht, ht])
    fd = np.empty((4, 4))
    for k in range(4):
        e = np.eye(4)[k] * steps[k]
        fd[:, k] = -(gen(e) - gen(-e)) / (2 * steps[k])
    assert np.abs(K[2:, :]).max() > 0 and np.abs(K[:2, 2:]).max() > 0
    for i in range(4):  # each row over the steps: forces [N] and moments [N m] on their own scales
        row, ref = K[i] * steps, fd[i] * steps
        assert np.abs(row - ref).max() < 1e-6 * np.abs(ref).max()
    Kb, _ = b.coefficients(M * 9.81, SPEED, tilt=tuple(q[2:]), tilt_dofs=True)  # the bearing's own, same tilt
    assert np.abs(K - Kb).max() < 1e-8 * np.abs(K).max()  # measured 3e-11


def test_symmetric_shaft_tilts_cancel():
    """A symmetric shaft (two elements, a disk at mid-span) on two equal bearings at its ends: its slopes there
    are opposite, and so are the films' moments; the forces and eccentricities are equal; the moments change the
    ends' slopes from the uncoupled shaft's."""
    mats = shaft_matrices([0.2, 0.2], 0.05, disks=[Disk(1, 40.0, 0.2, 0.1)])
    rotor = Rotor(mass=mats["mass"], stiffness=mats["stiffness"], gyroscopic=mats["gyroscopic"], nodes=mats["nodes"],
                  dofs=mats["dofs"])
    b = bearing()
    out = []
    for coupled in (True, False):
        s = RotorBearingSystem(rotor, {0: b, 2: b}, gravity=9.81, tilt_coupling=coupled)
        eq = s.equilibrium(SPEED)
        out.append((eq, eq.state[s.dae(SPEED).Q0:s.dae(SPEED).V0]))
    (eq, q), (eq0, q0) = out
    ty0, ty2 = q[3], q[11]
    assert ty0 == pytest.approx(-ty2, rel=1e-7) and abs(ty0) > 0
    assert eq.eccentricity_ratio[0] == pytest.approx(eq.eccentricity_ratio[1], rel=1e-8)
    assert np.allclose(eq.bearing_force[0], eq.bearing_force[1], rtol=1e-8)
    assert np.allclose(eq.bearing_moment[0], -eq.bearing_moment[1], rtol=1e-6)
    assert abs(eq.bearing_moment[0][1]) > 0 and abs(q[3] - q0[3]) > 1e-6 * abs(q0[3])


def test_ida_and_bdf2_agree_on_a_tilting_node():
    """Half a revolution of an unbalanced node with a tilt spring in a misaligned bush: IDA and BDF2 (each with its
    own tilted kernels) agree to 1e-5 C."""
    s = one_node(bearing(misalignment=(1e-4, -2e-4)), 2e4, unbalance=[(0, 1e-4, 0.0)])
    runs = [s.run(0.5, SPEED, integration=Integration(method=m, rtol=1e-7, atol=1e-10),
                  recording=Recording(outputs_per_revolution=20)) for m in ("ida", "bdf2")]
    assert all(r.success for r in runs)
    x = [np.array(r.position(0)) for r in runs]
    assert np.abs(x[0] - x[1]).max() < 1e-5 * BEARING["clearance"]
    assert np.abs(x[0] - x[0][:, :1]).max() > 1e-3 * BEARING["clearance"]  # it moves


def damper_node(coupled):
    """One node (2 kg, tilt inertia 1e-5 kg m^2 on a tilt spring of 100 N m/rad) in a squeeze-film damper."""
    d = SqueezeFilmDamper(diameter=0.1, length=0.02, clearance=200e-6, viscosity=0.01, supply_pressure=2e5,
                          centring_stiffness=5e6, grid=(24, 6))
    rotor = Rotor(mass=np.diag([2.0, 2.0, 1e-5, 1e-5]), stiffness=np.diag([0, 0, 100.0, 100.0]), nodes=[0], dofs=DOFS)
    return RotorBearingSystem(rotor, {0: d}, gravity=0.0, tilt_coupling=coupled)


def test_damper_film_takes_the_tilt(fd_jacobian):
    """The damper's film (zero spin) feels the tilt the same way: its Jacobian against differences, and its squeeze
    film damps a tilt oscillation the uncoupled film does not see. Released at 2 mrad about y (the ends 0.1 C off
    centre), after 0.25 revolution at 6000 rpm (1.25 periods of the undamped tilt) the tilt's energy is 0.067 of
    the start's with the coupling (measured), 0.99999 without (the undamped oscillator, IDA's error)."""
    s = damper_node(True)
    dae, y, yp = perturbed(s, 4)
    y[dae.Q0:dae.V0] *= 0.2  # inside the damper's clearance at the ends
    cj = 3.7

    def F(y_, yp_):
        out = np.empty(dae.n)
        dae.residual(0.3, y_, yp_, out)
        return out

    J_fd = fd_jacobian(lambda v: F(v, yp), y, dae.n, step=1e-7) + cj * fd_jacobian(lambda v: F(y, v), yp, dae.n,
                                                                                       step=1e-7)
    J = jacobian(dae, y, yp, cj)
    scale = np.max(np.abs(J_fd), axis=1, keepdims=True) + 1e-12
    assert np.max(np.abs(J - J_fd) / scale) < 1e-5
    energy = []
    for coupled in (True, False):
        s = damper_node(coupled)
        dae = s.dae(SPEED)
        y0 = s.equilibrium(SPEED).state.copy()
        y0[dae.Q0 + 3] = 2e-3 / dae.L
        r = s.run(0.25, SPEED, start=(0.0, y0), integration=Integration(rtol=1e-7, atol=1e-10))
        assert r.success
        th, om = r.final_state[dae.Q0 + 3] * dae.L, r.final_state[dae.V0 + 3] * dae.L * dae.omega
        energy.append((1e-5 * om ** 2 + 100.0 * th ** 2) / (100.0 * 4e-6))
    assert energy[0] < 0.2 and energy[1] == pytest.approx(1.0, abs=1e-3)


def test_tilt_coupling_refusals():
    """A rotor without tilts and a Gecim bulk are refused by name; a misaligned bearing is taken either way."""
    from transient.physics.layered import Gecim

    with pytest.raises(ValueError, match=r"tilt_coupling = True with a rotor of dofs = \('x', 'y'\)"):
        RotorBearingSystem(Rotor(mass=M * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: bearing()},
                           tilt_coupling=True)
    with pytest.raises(ValueError, match=r"bearings\[0\] rheology = Gecim"):
        one_node(bearing(rheology=Gecim(1e4, 0.5)))
    with pytest.raises(ValueError, match="tilt_coupling"):
        one_node(bearing(), coupled="yes")
    assert one_node(bearing(misalignment=(0.0, 1e-4)), 1e4, coupled=False).bearings[0].misalignment == (0.0, 1e-4)
