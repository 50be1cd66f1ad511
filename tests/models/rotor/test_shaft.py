"""Shaft finite elements against beam theory, and the gyroscopic split of a spinning rigid rotor against its
closed form."""

import math

import numpy as np
import pytest
import scipy.linalg as sl

from transient.models.rotor.linear import modes_at
from transient.models.rotor.shaft import Disk, disk_from_geometry, example_matrices, shaft_matrices

E, RHO, NU = 211e9, 7850.0, 0.3


def _pinned_frequencies(d, n_elements, length, count, **kw):
    """The lowest ``count`` distinct natural frequencies [rad/s] of a uniform shaft pinned (x = y = 0) at its ends."""
    m = shaft_matrices(np.full(n_elements, length / n_elements), d, density=RHO, young_modulus=E,
                       poisson_ratio=NU, **kw)
    n = m["mass"].shape[0]
    free = [i for i in range(n) if i not in (0, 1, n - 4, n - 3)]
    w2 = sl.eigh(m["stiffness"][np.ix_(free, free)], m["mass"][np.ix_(free, free)], eigvals_only=True)
    w = np.sqrt(np.abs(w2))
    assert np.allclose(w[0::2][:count], w[1::2][:count], rtol=1e-9)  # x and y planes alike
    return w[0::2][:count]


def test_matrices_are_symmetric_and_carry_the_mass():
    d = example_matrices()
    M, K, G = d["mass"], d["stiffness"], d["gyroscopic"]
    assert np.allclose(M, M.T) and np.allclose(K, K.T) and np.allclose(G, -G.T)
    assert d["dofs"] == ("x", "y", "tx", "ty") and d["nodes"] == list(range(13)) and M.shape == (52, 52)
    shaft_mass = RHO * math.pi * 0.04 ** 2 * 1.2
    disk_mass = RHO * math.pi * 0.2 ** 2 * 0.1
    # rigid translation in x: the kinetic energy's mass is the total mass
    ux = np.zeros(52)
    ux[0::4] = 1.0
    assert ux @ M @ ux == pytest.approx(shaft_mass + disk_mass, rel=1e-12)
    assert ux @ K @ ux == pytest.approx(0.0, abs=1e-6 * np.abs(K).max())
    assert d["bearing_nodes"] == (0, 12) and d["disk_nodes"] == (6,)


def test_simply_supported_euler_bernoulli_beam_converges_to_theory():
    """w_n = (n pi / L)^2 sqrt(EI / (rho A)); cubic Hermite elements with consistent mass: error ~ h^4."""
    d, L = 0.05, 1.0
    EI, rhoA = E * math.pi * d ** 4 / 64, RHO * math.pi * d ** 2 / 4
    exact = np.array([(k * math.pi / L) ** 2 * math.sqrt(EI / rhoA) for k in (1, 2, 3)])
    errors = []
    for ne in (4, 8, 16):
        w = _pinned_frequencies(d, ne, L, 3, shear=False, rotary_inertia=False)
        errors.append(np.abs(w / exact - 1))
    errors = np.array(errors)
    assert errors[-1].max() < 1e-4
    assert np.all(errors[0] / errors[1] > 12) and np.all(errors[1] / errors[2] > 12)  # fourth order: 16


def test_free_free_euler_bernoulli_beam():
    """beta L = 4.7300408, 7.8532046, 10.9956078 (free-free beam); four rigid-body modes at zero."""
    d, L, ne = 0.05, 1.0, 48
    m = shaft_matrices(np.full(ne, L / ne), d, density=RHO, young_modulus=E, poisson_ratio=NU, shear=False,
                       rotary_inertia=False)
    w2 = sl.eigh(m["stiffness"], m["mass"], eigvals_only=True)
    EI, rhoA = E * math.pi * d ** 4 / 64, RHO * math.pi * d ** 2 / 4
    exact = np.array([4.7300408, 7.8532046, 10.9956078]) ** 2 / L ** 2 * math.sqrt(EI / rhoA)
    assert np.all(np.abs(w2[:4]) < 1e-8 * w2[4])
    assert np.sqrt(w2[4:10:2]) == pytest.approx(exact, rel=1e-5)


def test_thick_simply_supported_beam_converges_to_timoshenko_theory():
    """L/d = 4: the simply supported Timoshenko beam with rotary inertia, k = n pi / L:
    (rho^2 I / (kappa G)) w^4 - (rho A + rho I k^2 (1 + E / (kappa G))) w^2 + E I k^4 = 0."""
    d, L = 0.1, 0.4
    A, I = math.pi * d ** 2 / 4, math.pi * d ** 4 / 64
    G = E / (2 * (1 + NU))
    kappa = 6 * (1 + NU) / (7 + 6 * NU)
    exact = []
    for n in (1, 2, 3):
        k = n * math.pi / L
        a, b, c = RHO ** 2 * I / (kappa * G), -(RHO * A + RHO * I * k * k * (1 + E / (kappa * G))), E * I * k ** 4
        exact.append(math.sqrt((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)))
    exact = np.array(exact)
    eb = np.array([(n * math.pi / L) ** 2 * math.sqrt(E * I / (RHO * A)) for n in (1, 2, 3)])
    assert np.all(exact < 0.95 * eb)  # shear and rotary inertia matter here
    errors = np.array([np.abs(_pinned_frequencies(d, ne, L, 3) / exact - 1) for ne in (8, 16, 32)])
    # measured: 6.3e-4, 7.2e-3, 2.5e-2 at 8 elements, 3.9e-5, 4.4e-4, 1.6e-3 at 32: second order (the element's
    # shear parameter Phi ~ 1 / h^2 grows as it shrinks, so the cubic terms fade)
    assert errors[-1].max() < 2e-3
    assert np.all(errors[:-1] / errors[1:] > 3.8)


@pytest.mark.parametrize("with_disk", [False, True])
@pytest.mark.parametrize("speed", [0.0, 300.0, 2000.0])
def test_gyroscopic_split_of_a_rigid_rotor(speed, with_disk):
    """A stiff solid shaft (radius r, length L; E 100 x steel) on springs k at its ends, alone or with a disk at
    mid-span, against the rigid body: translation w^2 = 2 k / m; conical modes
    I_d w^2 -+ I_p Omega w - k L^2 / 2 = 0 (forward root rises with speed, backward falls), with
    I_p = m_s r^2 / 2 + I_p,disk and I_d = m_s (3 r^2 + L^2) / 12 + I_d,disk about the centre.
    The shaft's flexibility (k L^3 / (48 E I) = 2e-5) is the only difference from the rigid body."""
    k, L, r = 1e5, 1.0, 0.05
    disks = [disk_from_geometry(2, 0.3, 0.04)] if with_disk else []
    m = shaft_matrices(np.full(4, L / 4), 2 * r, density=RHO, young_modulus=100 * E, disks=disks)
    n = m["mass"].shape[0]
    bearings = [(0, 1, k * np.eye(2), np.zeros((2, 2))), (n - 4, n - 3, k * np.eye(2), np.zeros((2, 2)))]
    ms = RHO * math.pi * r * r * L
    mass = ms + sum(d.mass for d in disks)
    ip = ms * r * r / 2 + sum(d.polar_inertia for d in disks)
    idi = ms * (3 * r * r + L * L) / 12 + sum(d.diametral_inertia for d in disks)
    root = math.sqrt((ip * speed) ** 2 + 4 * idi * k * L * L / 2)
    fw, bw = (ip * speed + root) / (2 * idi), (-ip * speed + root) / (2 * idi)
    tr = math.sqrt(2 * k / mass)
    f, _, _, whirl = modes_at(m["mass"], None, m["gyroscopic"], m["stiffness"], bearings, speed, 4,
                              dofs=m["dofs"])
    assert np.sort(f) == pytest.approx(np.sort([tr, tr, fw, bw]), rel=5e-5)
    if speed > 0:  # the two translational modes are degenerate (any whirl); the conical ones are circular
        assert whirl[np.argmin(np.abs(f - fw))] > 0.999 and whirl[np.argmin(np.abs(f - bw))] < -0.999


def test_disk_adds_its_mass_inertia_and_gyroscopic_coupling_at_its_node():
    bare = shaft_matrices([0.5, 0.5], 0.05)
    disk = Disk(1, 20.0, 0.4, 0.25)
    with_disk = shaft_matrices([0.5, 0.5], 0.05, disks=[disk])
    dM = with_disk["mass"] - bare["mass"]
    dG = with_disk["gyroscopic"] - bare["gyroscopic"]
    assert np.allclose(dM[4:8, 4:8], np.diag([20.0, 20.0, 0.25, 0.25])) and np.count_nonzero(dM) == 4
    assert dG[6, 7] == 0.4 and dG[7, 6] == -0.4 and np.count_nonzero(dG) == 2
    assert np.array_equal(with_disk["stiffness"], bare["stiffness"])


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match=r"element_lengths\[1\] = .*-0.1.* \[m\]"):
        shaft_matrices([0.1, -0.1], 0.05)
    with pytest.raises(ValueError, match=r"inner_diameters\[0\]"):
        shaft_matrices([0.1], 0.05, 0.06)
    with pytest.raises(ValueError, match="disk node"):
        shaft_matrices([0.1], 0.05, disks=[Disk(3, 1.0, 0.1, 0.05)])
