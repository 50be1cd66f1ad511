"""DC-FFT elasticity and matrix-free Newton steps of the line contact on fine uniform grids."""

import warnings

import numpy as np
import pytest

from transient.models.ehl.krylov import gmres_solve
from transient.models.roller.line_contact import FilmResolutionWarning
from transient.models.roller.line_fbns import LineContentFilm, schur_system
from transient.models.roller.line_fft import SchurOperator, TwoLevel
from transient.models.roller.line_newton import content_newton
from transient.models.roller.line_sequence import carry, solve_sequence
from transient.physics.elasticity import LineConvolution, line_influence
from transient.study.ehl_chart import chart_contact


@pytest.mark.parametrize("n", [11, 64, 1025])
def test_line_convolution_equals_dense_product(n):
    x = np.linspace(-4.0, 1.5, n)
    dx = x[1] - x[0]
    edges = np.concatenate(([x[0] - 0.5 * dx], 0.5 * (x[1:] + x[:-1]), [x[-1] + 0.5 * dx]))
    K = line_influence(x, edges)
    p = np.random.default_rng(n).random(n)
    ref = -0.7 * (K @ p)
    out = LineConvolution(n, dx, scale=-0.7).apply(p)
    assert np.max(np.abs(out - ref)) <= 1e-12 * np.max(np.abs(ref))


def _state(M, L, n):
    """A film-content state on ``n`` uniform nodes: the converged half-grid solution carried over."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FilmResolutionWarning)
        seq = solve_sequence(chart_contact(M, L, nodes=(n - 1) // 2 + 1, grid="uniform"))
    c = chart_contact(M, L, nodes=n, grid="uniform")
    dense = LineContentFilm(c.film_problem())
    fft = LineContentFilm(c.film_problem(matrix_free=True))
    return dense, fft, carry(seq.content.base.grid, seq.state, dense.base.grid)


def test_fft_film_and_schur_operator_equal_the_dense_ones():
    dense, fft, u = _state(100.0, 10.0, 257)
    assert fft.matrix_free and not dense.matrix_free
    ed, ef = dense.equations(u), fft.equations(u)
    assert np.max(np.abs(ef["H"] - ed["H"])) <= 1e-12 * np.max(np.abs(ed["H"]))
    assert np.max(np.abs(ef["res"] - ed["res"])) <= 1e-9 * np.max(np.abs(ed["res"]))
    S, r, (_, b_p, _, b_t) = schur_system(dense, u, ed)
    A = SchurOperator(fft, ef, b_p, b_t)
    v = np.random.default_rng(0).standard_normal(dense.n + 1)
    assert np.max(np.abs(A.matvec(v) - S @ v)) <= 1e-9 * np.max(np.abs(S @ v))
    # the two-level preconditioner: GMRES on the Newton step converges in at most 30 iterations (measured 24);
    # without it, not in 60
    z, its, ok = gmres_solve(A, r, TwoLevel(A, u, factor=2), 1e-8, restart=60, max_iter=60)
    _, _, ok_none = gmres_solve(A, r, _Identity(), 1e-8, restart=60, max_iter=60)
    assert ok and its <= 30 and not ok_none
    assert np.linalg.norm(S @ z - r) <= 1e-7 * np.linalg.norm(r)


class _Identity:
    def solve(self, b):
        return b


def test_matrix_free_newton_reaches_the_dense_solution():
    dense, fft, u0 = _state(300.0, 10.0, 513)
    ud, okd, _ = content_newton(dense, u0, tol=1e-10)
    uf, okf, st = content_newton(fft, u0, tol=1e-10)
    assert okd and okf and st.krylov > 0
    n = dense.n
    assert np.max(np.abs(uf[:n] - ud[:n])) < 1e-7
    assert abs(uf[-1] - ud[-1]) < 1e-7 * abs(ud[-1])


def test_coarse_uniform_grid_warns_with_the_resolving_node_count():
    c = chart_contact(1000.0, 10.0, nodes=1025, grid="uniform")
    assert c.resolving_nodes() == 16385  # 5.5 b * 1000 / 0.6 = 9167 intervals -> 2^14
    with pytest.warns(FilmResolutionWarning, match="use 16385 uniform nodes"):
        c.steady()


def test_resolved_grid_option():
    c = chart_contact(300.0, 10.0, nodes=1025, grid="uniform")
    r = c.with_load(c.load_per_length)  # same nodes
    assert r.grid.x.size == 1025
    from transient.models.roller import LineContact
    lc = LineContact(c.radius, c.load_per_length, c.speed, c.lubricant.viscosity, c.lubricant.pressure_viscosity,
                     c.modulus, density="incompressible", grid="resolved", domain=c.domain)
    assert lc.grid.x.size == 4097 and (lc.grid.x[1] - lc.grid.x[0]) * lc.M <= 0.6
    with pytest.raises(ValueError, match="'resolved'"):
        LineContact(c.radius, c.load_per_length, c.speed, 0.02, 1e-8, c.modulus, grid="fine")


@pytest.mark.slow
@pytest.mark.parametrize("L", [0.0, 10.0])
def test_uniform_resolving_grid_matches_clustered_limit_at_m1000(L):
    """16385 uniform nodes (M dx = 0.34) against the Richardson limit of the clustered grids 1025 / 2049 / 4097
    (measured differences: H_c +0.3 % at L = 0, docs/validation.md; asserted 1 % on H_c, 2 % on H_min)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", FilmResolutionWarning)
        u = chart_contact(1000.0, L, nodes=16385, grid="uniform").steady()
    hc, hm = [], []
    for n in (1025, 2049, 4097):
        s = chart_contact(1000.0, L, nodes=n).steady()
        hc.append(s.h_central)
        hm.append(s.h_min)

    def limit(v):
        a, b, d = v
        ratio = (b - a) / (d - b)
        assert ratio > 1.0  # the clustered sequence is in its asymptotic range
        return d + (d - b) / (ratio - 1.0)

    assert u.h_central / limit(hc) - 1.0 == pytest.approx(0.0, abs=0.01)
    assert u.h_min / limit(hm) - 1.0 == pytest.approx(0.0, abs=0.02)
