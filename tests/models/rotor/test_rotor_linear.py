"""Linear rotor-bearing analysis against the closed forms of Jeffcott rotors (every expected value below is
written out from the equations of motion, none produced by the code under test)."""

import math

import numpy as np
import pytest

from transient.models.rotor import linear as lin

M_J, K_J, C_J = 10.0, 4e6, 800.0  # kg, N/m, N s/m: w_n = 632.5 rad/s, zeta = 0.0632


def _jeffcott(k=K_J, c=C_J, q=0.0):
    """A point mass on one isotropic support: K = [[k, q], [-q, k]] (q: cross-coupled stiffness)."""
    return np.eye(2) * M_J, [(0, 1, np.array([[k, q], [-q, k]]), c * np.eye(2))]


def test_unbalance_response_of_a_jeffcott_rotor():
    """m x'' + c x' + k x = m_u e W^2 cos(W t): X = m_u e W^2 / (k - m W^2 + i c W), Y = -i X (forward circle)."""
    M, bearings = _jeffcott()
    u = 1e-4  # kg m
    for w in (200.0, math.sqrt(K_J / M_J), 1500.0):
        F = lin.unbalance_forces(2, 2, [(0, u, 30.0)], w)
        Q = lin.unbalance_response(M, None, None, np.zeros((2, 2)), bearings, F, w)
        X = u * w * w * np.exp(1j * math.radians(30.0)) / (K_J - M_J * w * w + 1j * C_J * w)
        assert Q[0] == pytest.approx(X, rel=1e-12) and Q[1] == pytest.approx(-1j * X, rel=1e-12)
    # at the undamped critical speed the amplitude is m_u e W / c
    w = math.sqrt(K_J / M_J)
    Q = lin.unbalance_response(M, None, None, np.zeros((2, 2)), bearings, lin.unbalance_forces(2, 2, [(0, u, 0)], w), w)
    assert abs(Q[0]) == pytest.approx(u * w / C_J, rel=1e-12)


def test_eigenvalues_of_a_damped_anisotropic_two_dof_system():
    """Uncoupled x and y: lambda = -c/(2m) +- i sqrt(k/m - (c/2m)^2) per direction, sorted by |imag|."""
    M = np.eye(2) * M_J
    kx, ky, cx, cy = 4e6, 9e6, 800.0, 300.0
    bearings = [(0, 1, np.diag([kx, ky]), np.diag([cx, cy]))]
    lam = lin.eigenvalues(M, None, None, np.zeros((2, 2)), bearings, 0.0)
    expect = []
    for k, c in ((kx, cx), (ky, cy)):
        s, wd = -c / (2 * M_J), math.sqrt(k / M_J - (c / (2 * M_J)) ** 2)
        expect += [s - 1j * wd, s + 1j * wd]
    assert np.abs(lam.imag) == pytest.approx(np.sort(np.abs(np.imag(expect))), rel=1e-12)  # sorted by |imag|
    assert np.sort_complex(lam) == pytest.approx(np.sort_complex(np.array(expect)), rel=1e-12)


def test_eigenvalues_with_cross_coupling():
    """z = x + i y: m s^2 + c s + k -+ i q = 0 (forward / backward), four roots."""
    q = 3e4
    M, bearings = _jeffcott(q=q)
    lam = lin.eigenvalues(M, None, None, np.zeros((2, 2)), bearings, 0.0)
    expect = []
    for kk in (K_J - 1j * q, K_J + 1j * q):
        disc = np.sqrt(C_J * C_J - 4 * M_J * kk + 0j)
        expect += [(-C_J + disc) / (2 * M_J), (-C_J - disc) / (2 * M_J)]
    assert np.sort_complex(lam) == pytest.approx(np.sort_complex(np.array(expect)), rel=1e-10)


def test_quasi_static_threshold_of_cross_coupling_growing_with_speed():
    """K_xy = -K_yx = a W: unstable when a W > c sqrt(k/m), i.e. above W* = c sqrt(k/m) / a."""
    a = 2000.0  # N s/m
    def bearings_of_speed(w):
        return _jeffcott(q=a * w)[1]
    thr = lin.quasi_static_threshold(np.eye(2) * M_J, None, None, np.zeros((2, 2)), bearings_of_speed, (10.0, 600.0))
    assert thr == pytest.approx(C_J * math.sqrt(K_J / M_J) / a, rel=1e-8)
    assert lin.quasi_static_threshold(np.eye(2) * M_J, None, None, np.zeros((2, 2)), bearings_of_speed,
                                      (10.0, 100.0)) is None


def _disk_node(k=K_J, kt=2e5, c=C_J, ip=0.05, idi=0.03):
    """One node (x, y, tx, ty): a disk of mass m, polar I_p, diametral I_d on translational springs k (damped c)
    and rotational springs k_t."""
    M = np.diag([M_J, M_J, idi, idi])
    G = np.zeros((4, 4))
    G[2, 3], G[3, 2] = ip, -ip
    K = np.diag([0.0, 0.0, kt, kt])
    return M, G, K, [(0, 1, k * np.eye(2), c * np.eye(2))]


def test_campbell_of_a_spinning_disk():
    """Translation: w_d = sqrt(k/m - (c/2m)^2), zeta = c / (2 sqrt(k m)), log dec = 2 pi zeta / sqrt(1 - zeta^2);
    tilt: I_d w^2 -+ I_p W w - k_t = 0 (forward +, backward -), undamped."""
    M, G, K, bearings = _disk_node()
    speeds = np.array([0.0, 1000.0, 5000.0])
    c = lin.campbell(M, None, G, K, lambda w: bearings, speeds, 4, dofs=("x", "y", "tx", "ty"))
    ip, idi, kt = 0.05, 0.03, 2e5
    zeta = C_J / (2 * math.sqrt(K_J * M_J))
    wd = math.sqrt(K_J / M_J) * math.sqrt(1 - zeta ** 2)
    for i, w in enumerate(speeds):
        root = math.sqrt((ip * w) ** 2 + 4 * idi * kt)
        fw, bw = (ip * w + root) / (2 * idi), (-ip * w + root) / (2 * idi)
        f = c.frequencies[i]
        assert np.sort(f) == pytest.approx(np.sort([wd, wd, fw, bw]), rel=1e-9)
        trans = np.isclose(f, wd, rtol=1e-9)
        assert c.damping_ratios[i][trans] == pytest.approx(zeta, rel=1e-9)
        assert c.log_decrements[i][trans] == pytest.approx(2 * math.pi * zeta / math.sqrt(1 - zeta ** 2), rel=1e-9)
        assert np.abs(c.damping_ratios[i][~trans]).max() < 1e-9
        if w > 0:
            assert c.whirl[i][np.isclose(f, fw)] == pytest.approx(1.0) and c.whirl[i][np.isclose(f, bw)] == \
                pytest.approx(-1.0)


def test_critical_speeds_of_a_jeffcott_rotor_and_a_spinning_disk():
    """The forward whirls cross the 1x line at W = w_d (translation) and, for the tilt, at
    I_d W^2 - I_p W^2 - k_t = 0: W = sqrt(k_t / (I_d - I_p)) (I_d > I_p)."""
    M, G, K, bearings = _disk_node(ip=0.02, idi=0.03)
    zeta = C_J / (2 * math.sqrt(K_J * M_J))
    wd = math.sqrt(K_J / M_J) * math.sqrt(1 - zeta ** 2)
    cs = lin.critical_speeds(M, None, G, K, lambda w: bearings, (10.0, 6000.0), 4, dofs=("x", "y", "tx", "ty"))
    assert cs == pytest.approx([wd, math.sqrt(2e5 / (0.03 - 0.02))], rel=1e-9)
    cs = lin.critical_speeds(M, None, G, K, lambda w: bearings, (10.0, 6000.0), 4, dofs=("x", "y", "tx", "ty"),
                             frequency="undamped")
    assert cs == pytest.approx([math.sqrt(K_J / M_J), math.sqrt(2e5 / (0.03 - 0.02))], rel=1e-9)
    # a disk with I_p > I_d (a flat disk) has no forward tilt critical speed
    M, G, K, bearings = _disk_node(ip=0.05, idi=0.03)
    cs = lin.critical_speeds(M, None, G, K, lambda w: bearings, (10.0, 6000.0), 4, dofs=("x", "y", "tx", "ty"))
    assert cs == pytest.approx([wd], rel=1e-9)


def test_bad_input_names_the_parameter():
    M, bearings = _jeffcott()
    with pytest.raises(ValueError, match="mass .* not symmetric"):
        lin.eigenvalues(np.array([[1.0, 0.5], [0.0, 1.0]]), None, None, np.zeros((2, 2)), bearings, 0.0)
    with pytest.raises(ValueError, match="mass .* not positive definite"):
        lin.eigenvalues(np.diag([1.0, 0.0]), None, None, np.zeros((2, 2)), bearings, 0.0)
    with pytest.raises(ValueError, match=r"bearings\[0\] iy = 2 \[-\]"):
        lin.eigenvalues(M, None, None, np.zeros((2, 2)), [(0, 2, np.eye(2), np.eye(2))], 0.0)
    with pytest.raises(ValueError, match=r"stiffness \[N/m\] must be a \(2, 2\)"):
        lin.eigenvalues(M, None, None, np.zeros((3, 3)), bearings, 0.0)
    with pytest.raises(ValueError, match=r"omega = -1.0 \[rad/s\]"):
        lin.eigenvalues(M, None, None, np.zeros((2, 2)), bearings, -1.0)
    with pytest.raises(ValueError, match=r"forces \[N\] must be 2"):
        lin.unbalance_response(M, None, None, np.zeros((2, 2)), bearings, np.zeros(3), 100.0)


@pytest.mark.slow
def test_example_rotor_on_two_film_bearings_has_its_first_critical_below_its_whirl_onset():
    """The built-in example is sized for a run-up through the first critical speed to twice the whirl onset:
    on two of Rho & Kim's bearings (quasi-static K/C, 61 x 11) both fall at a few thousand rpm, the critical
    below the onset and the onset below twice the critical (so that whip can lock in on the way up).
    Measured: 2443 and 4585 rpm (151 x 21: 2452 and 4618 rpm)."""
    from transient.models.journal.bearing import JournalBearing
    from transient.models.rotor.shaft import example_matrices
    from transient.params.rho_kim import BEARING

    ex = example_matrices()
    M, K, G = ex["mass"], ex["stiffness"], ex["gyroscopic"]
    load = 9.81 * M[0::4, 0::4].sum() / len(ex["bearing_nodes"])
    bearing = JournalBearing(**BEARING, grid=(61, 11))

    def bearings_of_speed(w):
        Kb, Cb = bearing.coefficients(load, max(w * 30 / math.pi, 50.0))
        return [(4 * n, 4 * n + 1, Kb, Cb) for n in ex["bearing_nodes"]]

    rpm = 30 / math.pi
    critical = lin.critical_speeds(M, None, G, K, bearings_of_speed, (100.0, 600.0), 2, dofs=ex["dofs"], samples=11,
                                   max_damping_ratio=0.3) * rpm
    onset = lin.quasi_static_threshold(M, None, G, K, bearings_of_speed, (100.0, 1500.0), samples=15) * rpm
    assert critical.size == 1 and 1500 < critical[0] < 4000
    assert critical[0] < onset < 2 * critical[0] and onset < 8000


def test_one_node_rigid_rotor_threshold_equals_the_bearings_own_lund_threshold():
    """Rho & Kim's rigid rotor (100 kg on one bearing, 981 N) as a one-node rotor: quasi_static_threshold with
    the bearing's K/C at each speed equals JournalBearing.stability_threshold (its own Lund eigenvalues; brentq
    rtol 1e-4 there)."""
    from transient.models.journal.bearing import JournalBearing
    from transient.params.rho_kim import BEARING, ROTOR

    bearing = JournalBearing(**BEARING, grid=(41, 6))
    mass, load = ROTOR["rotor_mass"], ROTOR["load"]
    own = bearing.stability_threshold(mass, load)

    def bearings_of_speed(w):
        return [(0, 1, *bearing.coefficients(load, w * 30 / math.pi))]

    ours = lin.quasi_static_threshold(np.eye(2) * mass, None, None, np.zeros((2, 2)), bearings_of_speed,
                                      (own * 0.8 * math.pi / 30, own * 1.2 * math.pi / 30), samples=3)
    assert ours * 30 / math.pi == pytest.approx(own, rel=3e-4)
