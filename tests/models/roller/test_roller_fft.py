"""Matrix-free FBNS steps of the roller on uniform DC-FFT grids: Schur products and the converged film
against the dense Schur path."""

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.models.roller.line_fbns import schur_system
from transient.models.roller.line_fft import SchurOperator
from transient.models.roller.line_newton import content_newton
from transient.models.roller.roller_fbns import RollerContentFilm, content_start
from transient.models.roller.roller_fft import coarse_grid

E, RM = 220e9, 0.01
CASE = dict(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E)  # the paper's loading on a shorter roller


def contact(grid):
    """The tilted short roller at the paper's loading; ``grid`` (uniform, nx x ny) not checked for resolution:
    the tests compare two solvers of the same discrete problem."""
    c = RollerContact.from_dimensionless(**CASE, roller=TaperedRoller(RM, 10.0, 2 * RM, 0.5 * RM, 0.15 * RM, 0.002),
                                         grid=("clustered", 40, 25))
    c.test_grid = c.make_grid("uniform", *grid)
    return c


def films(c, max_coarse=300):
    """The content film of ``c``'s uniform grid: dense Schur path, and matrix-free on a dense coarse film."""
    g = c.test_grid
    dense = RollerContentFilm(c.film_problem(g, "fft"))
    coarse = RollerContentFilm(c.film_problem(coarse_grid(g, max_coarse), "dense"))
    return dense, RollerContentFilm(c.film_problem(g, "fft"), coarse=coarse)


def test_matrix_free_schur_product_equals_the_dense_schur_matrix():
    c = contact((33, 41))
    dense, free = films(c)
    assert free.matrix_free and free.K is None and not dense.matrix_free
    u = content_start(c, dense)
    n = dense.n
    rng = np.random.default_rng(5)
    u[:n] += 0.05 * rng.random(n)
    u[n: 2 * n] = np.where(rng.random(n) < 0.3, 0.3 + 0.7 * rng.random(n), 1.0)
    e = dense.equations(u)
    S, _, (_, b_p, _, b_t) = schur_system(dense, u, e)
    A = SchurOperator(free, free.equations(u), b_p, b_t)
    for v in rng.standard_normal((3, n + 1)):
        ref = S @ v
        assert np.allclose(A.matvec(v), ref, rtol=0.0, atol=1e-10 * np.max(np.abs(ref)))


def test_matrix_free_newton_converges_with_one_coarse_factorisation():
    c = contact((33, 161))
    dense, free = films(c, 500)
    u, ok, st = content_newton(free, content_start(c, dense), tol=1e-9)
    # measured: 13 Newton iterations, 1 coarse factorisation, 262 GMRES iterations
    assert ok and st.factorisations <= 2 and st.krylov < 30 * st.iterations
    assert abs(free.equations(u)["load"]) < 1e-9


@pytest.mark.slow
def test_matrix_free_newton_converges_to_the_dense_paths_film():
    c = contact((33, 161))
    dense, free = films(c, 500)
    u0 = content_start(c, dense)
    ud, okd, _ = content_newton(dense, u0, tol=1e-9)
    uf, okf, st = content_newton(free, u0, tol=1e-9)
    assert okd and okf and st.krylov > 0
    n = dense.n
    assert np.max(np.abs(uf[:n] - ud[:n])) < 1e-7 * np.max(ud[:n])
    assert uf[-1] == pytest.approx(ud[-1], rel=1e-8)
