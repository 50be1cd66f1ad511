"""Craig-Bampton reduction of the example rotor against the full model: statics exact, eigenvalues and the
unbalance response converging as modes are added (the numbers are in docs/validation.md)."""

import math

import numpy as np
import pytest

from transient.models.rotor import linear as lin
from transient.models.rotor.modal import reduce
from transient.models.rotor.shaft import example_matrices

EX = example_matrices()
M, K, G = EX["mass"], EX["stiffness"], EX["gyroscopic"]
KEEP = [0, 1, 48, 49]  # x, y of the bearing nodes 0 and 12
KB = np.array([[2e7, 1e7], [-5e6, 3e7]])  # N/m: anisotropic and cross-coupled, like a film
CB = np.array([[1.5e5, 5e4], [5e4, 8e4]])  # N s/m
FULL_BEARINGS = [(0, 1, KB, CB), (48, 49, KB, CB)]
REDUCED_BEARINGS = [(0, 1, KB, CB), (2, 3, KB, CB)]  # the kept dofs are the first reduced coordinates


def _eigen_error(r, speed):
    """Largest relative error of the four lowest underdamped eigenvalues at ``speed`` [rad/s]."""
    lf = lin.eigenvalues(M, None, G, K, FULL_BEARINGS, speed)
    lr = lin.eigenvalues(r.mass, r.damping, r.gyroscopic, r.stiffness, REDUCED_BEARINGS, speed)
    lf, lr = lf[lf.imag > 0][:4], lr[lr.imag > 0][:4]
    return np.max(np.abs(lr - lf) / np.abs(lf))


def _response_error(r):
    """Largest error of the unbalance response (disk unbalance) at the bearings and the disk, relative to the
    largest full amplitude, over 1500 to 8000 rpm (through the first critical speed)."""
    errors = []
    for rpm in (1500.0, 2500.0, 2900.0, 4000.0, 8000.0):
        w = rpm * math.pi / 30
        F = lin.unbalance_forces(52, 4, [(6, 1e-4, 0.0)], w)
        xf = lin.unbalance_response(M, None, G, K, FULL_BEARINGS, F, w)[[0, 1, 24, 25, 48, 49]]
        q = lin.unbalance_response(r.mass, r.damping, r.gyroscopic, r.stiffness, REDUCED_BEARINGS, r.basis.T @ F, w)
        xr = (r.basis @ q)[[0, 1, 24, 25, 48, 49]]
        errors.append(np.abs(xr - xf).max() / np.abs(xf).max())
    return max(errors)


def test_reduced_model_structure():
    r = reduce(M, K, None, G, KEEP, 6)
    assert r.mass.shape == (10, 10) and r.basis.shape == (52, 10) and r.damping is None
    assert np.array_equal(r.basis[KEEP, :4], np.eye(4)) and not r.basis[KEEP, 4:].any()
    assert np.allclose(r.gyroscopic, -r.gyroscopic.T) and np.all(np.linalg.eigvalsh(r.mass) > 0)
    assert np.allclose(r.mass[4:, 4:], np.eye(6), atol=1e-10)  # fixed-interface modes are M-normalised


def test_statics_under_loads_at_the_kept_dofs_is_exact_for_any_number_of_modes():
    F = np.zeros(52)
    F[[0, 1, 48, 49]] = [400.0, -150.0, 700.0, 90.0]
    Kf = K.copy()
    for ix, iy, kb, _ in FULL_BEARINGS:
        Kf[np.ix_([ix, iy], [ix, iy])] += kb
    x_full = np.linalg.solve(Kf, F)
    for modes in (0, 4):
        r = reduce(M, K, None, G, KEEP, modes)
        Kr = r.stiffness.copy()
        for ix, iy, kb, _ in REDUCED_BEARINGS:
            Kr[np.ix_([ix, iy], [ix, iy])] += kb
        x = r.basis @ np.linalg.solve(Kr, r.basis.T @ F)
        assert np.abs(x - x_full).max() <= 1e-10 * np.abs(x_full).max()


def test_reduction_error_falls_as_modes_grow():
    """Measured (4000 rpm, film-like bearings): eigenvalues 3.9e-3 / 4.5e-5 / 8.5e-7 and unbalance response
    4.1e-3 / 1.7e-4 / 6.1e-6 with 4 / 8 / 16 modes; the static (Guyan) reduction alone is useless dynamically."""
    speed = 4000 * math.pi / 30
    guyan = reduce(M, K, None, G, KEEP, 0)
    assert _response_error(guyan) > 0.5
    eig = {m: _eigen_error(reduce(M, K, None, G, KEEP, m), speed) for m in (4, 8, 16)}
    resp = {m: _response_error(reduce(M, K, None, G, KEEP, m)) for m in (2, 8, 16)}
    assert eig[4] > eig[8] > eig[16] and resp[2] > resp[8] > resp[16]
    assert eig[4] < 5e-3 and eig[8] < 1e-4 and eig[16] < 2e-6
    assert resp[2] < 5e-3 and resp[8] < 3e-4 and resp[16] < 1e-5


def test_keeping_every_dof_is_the_full_model():
    r = reduce(M, K, None, G, np.arange(52), 0)
    assert np.array_equal(r.basis, np.eye(52)) and np.array_equal(r.mass, M) and np.array_equal(r.gyroscopic, G)


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError, match=r"keep = .* \[-\] must hold distinct dof indices in \[0, 51\]"):
        reduce(M, K, None, G, [0, 52], 2)
    with pytest.raises(ValueError, match=r"modes = 49 \[-\] is out of range"):
        reduce(M, K, None, G, KEEP, 49)
    with pytest.raises(ValueError, match="does not hold the rotor statically"):
        reduce(M, K, None, G, [0, 1], 2)  # one bearing node: the rotor can still tilt about it


def test_rotor_reduce_is_the_craig_bampton_reduction_at_its_bearing_nodes():
    from transient.models.rotor import Rotor

    ex = Rotor.example()
    r = ex.reduce(4)
    ref = reduce(ex.mass, ex.stiffness, ex.damping, ex.gyroscopic, KEEP, 4)
    assert r.reduced and r.n == 8 and r.bearing_nodes == ex.bearing_nodes and r.disk_nodes == ex.disk_nodes
    assert np.array_equal(r.basis, ref.basis) and np.array_equal(r.stiffness, ref.stiffness)
    assert np.array_equal(r.translation(12), np.eye(8)[2:4])  # the bearing node's x, y are coordinates 2, 3
    assert np.allclose(r.gravity_load, ex.gravity_load @ ref.basis)
    assert r.total_mass == pytest.approx(ex.total_mass, rel=1e-12)
    with pytest.raises(ValueError, match="already reduced"):
        r.reduce(2)
    with pytest.raises(ValueError, match=r"modes = 49 \[-\] is out of range"):
        ex.reduce(49)
