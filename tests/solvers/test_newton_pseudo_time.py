"""The one Newton's pseudo-transient phase (Kelley & Keyes): it ends when the residual vanishes."""
import numpy as np
import scipy.sparse as sp

from transient.solvers.newton import NewtonSettings, newton


def _problem():
    a = np.array([[4.0, 1.0], [1.0, 3.0]])
    b = np.array([1.0, 2.0])
    return a, b, np.linalg.solve(a, b)


def test_a_start_that_solves_the_equations_ends_the_pseudo_transient_phase():
    a, b, _ = _problem()
    x0 = np.array([1.0, 0.0])  # F(x0) = 0 exactly for this right-hand side
    b = a @ x0
    converged = lambda x, f, dx: float(np.max(np.abs(f))) <= 1e-12  # noqa: E731
    res = newton(lambda x: a @ x - b, lambda x, shift: sp.csc_matrix(a + shift * np.eye(2)), x0,
                 settings=NewtonSettings(pseudo_time=1e-3, max_iter=20), converged=converged)
    assert res.success and res.iterations <= 2
    assert np.array_equal(res.x, x0)


def test_the_pseudo_transient_phase_still_reaches_the_solution():
    a, b, x_exact = _problem()
    converged = lambda x, f, dx: float(np.max(np.abs(f))) <= 1e-12  # noqa: E731
    res = newton(lambda x: a @ x - b, lambda x, shift: sp.csc_matrix(a + shift * np.eye(2)), np.zeros(2),
                 settings=NewtonSettings(pseudo_time=1e-2, max_iter=100), converged=converged)
    assert res.success
    assert np.allclose(res.x, x_exact, rtol=0, atol=1e-12)
