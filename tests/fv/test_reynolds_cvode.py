"""The film operator plugs into the integrator facade: CVODE with the analytic sparse Jacobian."""

import numpy as np
from scipy.special import expit

from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import Fields, ReynoldsOperator, integrate, scale_rows
from transient.solvers.newton import solve_steady
from transient.solvers.integrate import Problem, solve


def test_elrod_film_cvode_reaches_the_steady_newton_solution():
    """Fixed-journal Elrod-like film (smooth switch, upwind Couette, groove cells at supply pressure).

    ODE per free cell: ``A_i h_i du_i/dt = -R_i(u)`` (h fixed); groove cells ``du/dt = 0``.
    """
    eps, beta, w = 0.6, 50.0, 0.01
    nt, nz = 24, 4
    x = Axis.uniform(nt, 2 * np.pi, centred=True, periodic=True, name="x")
    z = Axis.uniform(nz, 0.5, lower="symmetry", upper="dirichlet", name="z")  # half bearing
    fixed = np.zeros((nz, nt), bool)
    fixed[:, 0] = True
    g = Grid2D(x, z, fixed=fixed, fixed_values=1.0 + 0.5 / beta)
    op = ReynoldsOperator(g, upwind=True, boundary_P=0.0, boundary_C=1.0)
    h = 1 + eps * np.cos(g.xc)
    k, zero, one = h**3 / 12, np.zeros(g.n), np.ones(g.n)

    def fields(u):
        s = (u - 1) / w
        return Fields(beta * w * np.logaddexp(0, s), beta * expit(s), u, one, k, zero, k, zero, h / 2, zero)

    scale = np.where(g.free, -1.0 / (g.area * h), 0.0)
    indices = op.stencil.indices

    def rhs(t, y, out):
        op.residual_of(y, fields(y), out)
        out *= scale

    def jac(t, y, data):
        op.jacobian_of(fields(y), data=data)
        scale_rows(data, indices, scale)

    y0 = np.ones(g.n)
    y0[g.fixed] = g.fixed_values[g.fixed]
    problem = Problem(y0=y0, rhs=rhs, jac_pattern=op.pattern, jac_rhs=jac, name="elrod-film")
    res = solve(problem, np.array([0.0, 5.0, 60.0]), method="cvode", rtol=1e-8, atol=1e-10)
    assert res.success, res.message
    assert res.stats.n_jac > 0  # the analytic Jacobian was used
    steady = solve_steady(op, fields, np.ones(g.n))
    assert np.max(np.abs(res.y_final - steady.u)) < 1e-6
    assert np.max(np.abs(res.y[1] - steady.u)) > 1e-3  # not trivially there at t = 5
    # load from the film pressure (Fy = -sum p sin(theta) dA) is that of the steady film
    Fy = integrate(fields(res.y_final).P, -np.sin(g.xc), g.area)
    assert np.isclose(Fy, integrate(fields(steady.u).P, -np.sin(g.xc), g.area), rtol=1e-5)
