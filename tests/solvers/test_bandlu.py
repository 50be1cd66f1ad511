"""The bordered band LU (reverse Cuthill-McKee band + LAPACK gbtrf/gbtrs + Schur border) against SuperLU on the
journal orbit's own arrow Jacobian (content formulation) and on a random arrow that needs row pivoting."""

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.bandlu import BorderedBandLU


def _orbit_jacobian(grid):
    b = JournalBearing(**BEARING, grid=grid)
    o = JournalOrbit(b, ROTOR["rotor_mass"], 0.3 * BEARING["clearance"], ROTOR["load"], 6000.0)
    p = o.problem(formulation="content")
    y = p.y0.copy()
    y[o.film.n + 2] = 0.05  # a moving journal: squeeze terms in the film rows
    data = np.empty(p.jac_pattern.nnz)
    p.jac_residual(0.0, y, p.yp0, 2 * 500 / (2 * np.pi) * 1.5, data)  # cj of a BDF2 step at 500 steps/rev
    return p.jac_pattern, data


@pytest.mark.parametrize("grid", [(48, 8), (76, 11)])
def test_orbit_jacobian_solution_equals_superlu(grid):
    pattern, data = _orbit_jacobian(grid)
    lu = BorderedBandLU(pattern, 4)
    assert lu.ku < 3 * grid[1] and lu.kl < 3 * grid[1]  # RCM: about twice the axial width (periodic wrap)
    assert lu.factor(data) == 0
    M = sp.csc_matrix((data, pattern.indices, pattern.indptr), shape=pattern.shape)
    ref = spla.splu(M)
    rng = np.random.default_rng(3)
    for _ in range(3):
        rhs = rng.standard_normal(pattern.shape[0])
        x, xs = lu.solve(rhs), ref.solve(rhs)
        assert np.max(np.abs(x - xs)) <= 1e-12 * np.max(np.abs(xs))


def test_random_arrow_needing_pivoting():
    n, nb = 300, 3
    rng = np.random.default_rng(0)
    A = sp.diags([rng.standard_normal(n - abs(k)) for k in (-2, -1, 0, 1, 2)], [-2, -1, 0, 1, 2]).tolil()
    A[0, n - 1] = A[n - 1, 0] = 1.0  # a periodic wrap
    A.setdiag(1e-14 * rng.standard_normal(n))  # tiny diagonal: no LU without pivoting
    M = sp.bmat([[A, rng.standard_normal((n, nb))], [rng.standard_normal((nb, n)), np.eye(nb)]]).tocsc()
    M.sort_indices()
    lu = BorderedBandLU(M, nb)
    assert lu.factor(M.data) == 0
    rhs = rng.standard_normal(n + nb)
    x = lu.solve(rhs)
    assert np.max(np.abs(M @ x - rhs)) <= 1e-10 * np.max(np.abs(rhs)) * np.max(np.abs(x))
    assert np.allclose(x, spla.spsolve(M, rhs), rtol=1e-8, atol=1e-10)


def test_bad_border_is_refused():
    with pytest.raises(ValueError, match="n_border"):
        BorderedBandLU(sp.identity(5, format="csc"), 5)


def test_border_partly_outside_the_block():
    """A wide border of which only a few columns and rows reach the block (a rotor whose films see only its
    bearing nodes): the same solution as SuperLU, the Schur complement formed on those few."""
    n, nb = 200, 12
    rng = np.random.default_rng(1)
    A = sp.diags([rng.standard_normal(n - abs(k)) for k in (-1, 0, 1)], [-1, 0, 1]) + 4 * sp.identity(n)
    B, C = np.zeros((n, nb)), np.zeros((nb, n))
    B[:, [2, 7]] = rng.standard_normal((n, 2))
    C[[3, 7, 9], :] = rng.standard_normal((3, n))
    M = sp.bmat([[A, B], [C, rng.standard_normal((nb, nb)) + 5 * np.eye(nb)]]).tocsc()
    M.eliminate_zeros()
    M.sort_indices()
    lu = BorderedBandLU(M, nb)
    assert lu.arrays.cols.tolist() == [2, 7] and lu.arrays.rows.tolist() == [3, 7, 9]
    assert lu.factor(M.data) == 0
    rhs = rng.standard_normal(n + nb)
    assert np.allclose(lu.solve(rhs), spla.spsolve(M, rhs), rtol=1e-10, atol=1e-12)


def _two_blocks(rng):
    """An arrow of two independent pivoting bands (and a few unconnected cells) on a border that reaches each block
    through its own columns and rows (a rotor on two films)."""
    def band(n):
        A = sp.diags([rng.standard_normal(n - abs(k)) for k in (-3, -1, 0, 1, 3)], [-3, -1, 0, 1, 3]).tolil()
        A[0, n - 1] = A[n - 1, 0] = 1.0
        A.setdiag(1e-14 * rng.standard_normal(n))
        return A
    n1, n2, nb = 150, 120, 5
    A = sp.block_diag([band(n1), sp.identity(3), band(n2), sp.identity(2)]).tocsc()
    n = A.shape[0]
    B, C = np.zeros((n, nb)), np.zeros((nb, n))
    B[:n1, 0], B[n1 + 3:n1 + 3 + n2, 1] = rng.standard_normal(n1), rng.standard_normal(n2)
    C[2, :n1], C[3, n1 + 3:n1 + 3 + n2] = rng.standard_normal(n1), rng.standard_normal(n2)
    M = sp.bmat([[A, B], [C, rng.standard_normal((nb, nb)) + 5 * np.eye(nb)]]).tocsc()
    M.sort_indices()
    return M, nb, (n1 + 3, n1 + 3 + n2)


def test_a_refactorisation_refactors_only_the_blocks_that_changed():
    """Two independent band blocks are two segments; entries changed in one of them refactor that one only (the
    other's band LU and its part of Z kept), a change of the corner none: each time SuperLU's solution."""
    rng = np.random.default_rng(2)
    M, nb, (a, b) = _two_blocks(rng)
    lu = BorderedBandLU(M, nb)
    assert lu.segments.size == 3  # the unconnected cells joined to their neighbours
    rhs = rng.standard_normal(M.shape[0])
    assert lu.factor(M.data) == 0 and lu.arrays.dirty.all()
    rows = M.indices
    cols = np.repeat(np.arange(M.shape[0]), np.diff(M.indptr))
    second = (rows >= a) & (rows < b) | (cols >= a) & (cols < b)  # its band and its border entries
    corner = (rows >= M.shape[0] - nb) & (cols >= M.shape[0] - nb)
    for changed, dirty in ((second, 1), (corner, 0)):
        M.data[changed] *= 1.3
        assert lu.factor(M.data) == 0
        assert lu.arrays.dirty.sum() == dirty
        x = lu.solve(rhs)
        assert np.max(np.abs(M @ x - rhs)) <= 1e-10 * np.max(np.abs(rhs)) * np.max(np.abs(x))
        assert np.allclose(x, spla.spsolve(M, rhs), rtol=1e-8, atol=1e-10)
