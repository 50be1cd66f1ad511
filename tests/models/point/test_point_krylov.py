"""Newton-Krylov path of the point contact: the matrix-free reduced Newton matrix against the dense one and
against finite differences, the preconditioner's grid transfer, and the same discrete solution as the dense
LU path (with and without the nested start)."""

import numpy as np
import pytest

from transient.models.point import PointContact
from transient.models.point.fbns import DenseSolver, fbns, linear_solver
from transient.models.ehl.reduced import dense_reduced, schur
from transient.models.ehl.krylov import KrylovSolver, ReducedOperator, prolongation, prolong_state

BASE = dict(load=20.0, speed=0.2, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11)


def perturbed_state(pc, f, seed=3):
    """A state with pressurised and nearly cavitated, partly filled nodes (both eliminations of the
    Fischer-Burmeister rows; pressures kept off zero, where the lubricant laws have a kink)."""
    rng = np.random.default_rng(seed)
    u = pc.hertz_start(f)
    cavitated = rng.random(f.n) < 0.2
    u[: f.n] = np.where(cavitated, 1e-3, np.abs(u[: f.n] + 0.05 * rng.standard_normal(f.n)) + 1e-3)
    u[f.n: 2 * f.n] = np.where(cavitated, 1.0 - 0.4 * rng.random(f.n), 1.0)
    u[-1] += 0.5  # a positive film everywhere
    assert f.equations(u)["H"].min() > 0
    return u


@pytest.mark.parametrize("cj", [0.0, 3.0])
def test_matrix_free_reduced_matrix_equals_dense(cj):
    pc = PointContact(0.01, 0.02, grid=(25, 25), inlet_film=2e-7, **BASE)
    f = pc.film_problem()
    u = perturbed_state(pc, f)
    e = f.equations(u)
    local = f.local_newton(u, e, cj)
    _, b_p, _, b_t = schur(f, u, e)
    A = ReducedOperator(f, local, b_p, b_t)
    D = dense_reduced(f, local, b_p, b_t)
    v = np.random.default_rng(4).standard_normal(f.n + 1)
    assert np.allclose(A.matvec(v), D @ v, rtol=0, atol=1e-10 * np.abs(D @ v).max())


def test_reduced_product_matches_finite_differences(fd_jacobian):
    pc = PointContact(0.01, grid=(25, 25), viscosity_law="roelands", **BASE)
    f = pc.film_problem()
    u = perturbed_state(pc, f, seed=5)
    e = f.equations(u)
    _, b_p, _, b_t = schur(f, u, e)
    A = ReducedOperator(f, f.local_newton(u, e), b_p, b_t)
    z = np.random.default_rng(6).standard_normal(f.n + 1) * 1e-2
    du = np.concatenate([b_p * z[: f.n], b_t * z[: f.n], [z[-1]]])
    # the Reynolds rows and the load row along du, by central differences in the step length
    g = lambda s: np.append(f.equations(u + s[0] * du)["res"], f.equations(u + s[0] * du)["load"])
    fd = fd_jacobian(g, np.zeros(1), f.n + 1, step=1e-6)[:, 0]
    Av = A.matvec(z)
    assert np.allclose(Av, fd, rtol=0, atol=1e-6 * np.abs(fd).max())


def test_prolongation_reproduces_bilinear_fields_and_zero_boundary():
    pc = PointContact(0.01, grid=(33, 33), **BASE)
    f = pc.film_problem()
    c = f.coarsened(2)
    Pm = prolongation(f, c)
    lin = lambda film: (1.0 + 0.3 * film.x[film.i] - 0.2 * film.y[film.j] + 0.1 * film.x[film.i] * film.y[film.j])
    fine = Pm @ lin(c)
    # exact away from the outer boundary (where the coarse field is cut to zero)
    inner = (f.i < f.nx - 3) & (f.i > 1) & (f.j < f.m - 3)
    assert np.allclose(fine[inner], lin(f)[inner], atol=1e-12)
    assert np.allclose(prolong_state(c, f, np.concatenate([np.zeros(c.n), np.ones(c.n), [0.7]]))[f.n:],
                       np.append(np.ones(f.n), 0.7))


def test_krylov_newton_gives_the_dense_solution():
    pc = PointContact(0.01, grid=(33, 33), upwind="first", **BASE)  # the counts below were measured at first order
    f = pc.film_problem()
    u0 = pc.hertz_start(f)
    ud, okd, nd = fbns(f, u0, solver="dense")
    k = KrylovSolver(f)
    uk, okk, nk = fbns(f, u0, solver=k)
    assert okd and okk
    assert np.max(np.abs(uk - ud)) < 1e-8 * np.max(np.abs(ud))
    assert abs(len(nk) - len(nd)) <= 1
    assert k.stats["failures"] == 0 and max(k.stats["gmres_its"]) < 20


def test_auto_choice_with_nested_start_gives_the_dense_solution():
    pc = PointContact(0.01, grid=(49, 49), **BASE)
    f = pc.film_problem()
    u0 = pc.hertz_start(f)
    solver = linear_solver(f)
    assert isinstance(solver, KrylovSolver)
    assert isinstance(linear_solver(PointContact(0.01, grid=(33, 33), **BASE).film_problem()), DenseSolver)
    uk, okk, _ = fbns(f, u0, solver=solver)
    assert solver.stats["coarse_newton"][0][2]  # the nested start on 25 x 25 converged
    ud, okd, _ = fbns(f, u0, solver="dense", nested=False)
    assert okd and okk
    assert np.max(np.abs(uk - ud)) < 1e-8 * np.max(np.abs(ud))
