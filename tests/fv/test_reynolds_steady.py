"""Direct steady Newton solver on the finite-volume Reynolds equations."""

import numpy as np
import pytest
from scipy.special import expit

from transient.verification import reference as ref
from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import Fields, ReynoldsOperator
from transient.solvers.newton import SteadyConvergenceError, solve_steady

A, H, DHDT, MU = 0.01, 2e-5, -1e-3, 0.05


def _squeeze(alpha, n=24):
    """Squeeze film on an A x 2A plate, Barus-like k = h^3 exp(-alpha p)/(12 mu), P = u."""
    g = Grid2D(Axis.uniform(n, A, name="x"), Axis.uniform(2 * n, 2 * A, name="z"))
    k0 = H**3 / (12 * MU)
    one, zero = np.ones(g.n), np.zeros(g.n)

    def fields(u):
        k = k0 * np.exp(-alpha * u)
        return Fields(u, one, one, zero, k, -alpha * k, k, -alpha * k, zero, zero)

    return g, ReynoldsOperator(g), fields


def test_linear_converges_in_one_or_two_iterations():
    g, op, fields = _squeeze(0.0)
    src = g.area * DHDT
    res = solve_steady(op, fields, np.zeros(g.n), source=src)
    assert res.converged and res.iterations <= 2
    r = op.residual_of(res.u, fields(res.u)) + src
    assert np.max(np.abs(r)) < 1e-10 * np.max(np.abs(src))
    # and it is the squeeze solution (64 cells across would give 0.5 % - here a coarse sanity bound)
    assert res.u @ g.area == pytest.approx(ref.squeeze_rect_load(A, 2 * A, H, DHDT, MU), rel=1e-2)


def test_nonlinear_barus_converges_quadratically():
    g, op, fields = _squeeze(0.0)
    u_lin = solve_steady(op, fields, np.zeros(g.n), source=g.area * DHDT).u
    # Barus k = k0 exp(-alpha p): the reduced pressure q = (1 - exp(-alpha p))/alpha solves the linear
    # problem, so p = -ln(1 - alpha q_lin)/alpha (bounded only while alpha q_lin < 1); alpha q_max = 1/2
    alpha = 0.5 / np.max(u_lin)
    g, op, fields = _squeeze(alpha)
    src = g.area * DHDT
    res = solve_steady(op, fields, u_lin, source=src, ftol=1e-13)  # start from the isoviscous solution
    r = np.array(res.residual_norms) / res.residual_norms[0]
    assert res.converged and res.iterations <= 8, r
    # quadratic: once in the basin, the normalised residual roughly squares each iteration
    tail = r[r < 1e-2]
    assert tail.size >= 2
    assert np.all(tail[1:] <= 10.0 * tail[:-1] ** 2), r
    assert np.max(np.abs(op.residual_of(res.u, fields(res.u)) + src)) < 1e-12 * np.max(np.abs(src))
    p_exact = -np.log(1.0 - alpha * u_lin) / alpha  # continuous transform of the linear solution
    assert np.max(np.abs(res.u - p_exact)) < 5e-3 * np.max(p_exact)
    assert np.max(res.u) > 1.3 * np.max(u_lin)


def test_elrod_steady_converges():
    """Smooth-switch Elrod film (upwind Couette, groove of prescribed cells) converges to R = 0."""
    eps, beta, w = 0.6, 50.0, 0.01
    x = Axis.uniform(24, 2 * np.pi, centred=True, periodic=True, name="x")
    z = Axis.uniform(4, 0.5, lower="symmetry", upper="dirichlet", name="z")
    fixed = np.zeros((4, 24), bool)
    fixed[:, 0] = True
    g = Grid2D(x, z, fixed=fixed, fixed_values=1.0 + 0.5 / beta)
    op = ReynoldsOperator(g, upwind=True, boundary_P=0.0, boundary_C=1.0)
    h = 1 + eps * np.cos(g.xc)
    k, zero = h**3 / 12, np.zeros(g.n)

    def fields(u):
        s = (u - 1) / w
        return Fields(beta * w * np.logaddexp(0, s), beta * expit(s), u, np.ones(g.n), k, zero, k, zero, h / 2, zero)

    res = solve_steady(op, fields, np.ones(g.n))
    assert res.converged
    assert np.max(np.abs(op.residual_of(res.u, fields(res.u)))) < 1e-10
    assert np.min(res.u) < 0.5  # a cavitated zone exists (film content well below 1)
    assert np.allclose(res.u[g.fixed], 1.0 + 0.5 / beta)


def test_non_convergence_raises_clear_error():
    g, op, fields = _squeeze(2e-5)
    with pytest.raises(SteadyConvergenceError, match="did not converge in 1 iterations"):
        solve_steady(op, fields, np.zeros(g.n), source=g.area * DHDT, max_iter=1)
    with pytest.raises(ValueError, match="max_iter"):
        solve_steady(op, fields, np.zeros(g.n), max_iter=0)
    with pytest.raises(ValueError, match=r"u0 must have shape \(1152,\)"):
        solve_steady(op, fields, np.zeros(3))
