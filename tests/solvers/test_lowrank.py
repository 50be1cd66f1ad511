"""The column update of a factored arrow matrix (Woodbury on the bordered band LU) against SuperLU on the matrix
with the columns replaced: the journal orbit's content Jacobian with film cells' columns scaled as by a crossing
of the cavitation switch, and a random arrow."""

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.solvers.bandlu import BorderedBandLU, band_factor
from transient.solvers.lowrank import column_update, lu_solve, reset, updated_lu

from tests.solvers.test_bandlu import _orbit_jacobian


def _check(pattern, data, new, ulu, rng):
    M = sp.csc_matrix((new, pattern.indices, pattern.indptr), shape=pattern.shape)
    ref = spla.splu(M)
    for _ in range(3):
        rhs = rng.standard_normal(pattern.shape[0])
        x = np.empty_like(rhs)
        lu_solve(ulu, rhs, x)
        xs = ref.solve(rhs)
        assert np.max(np.abs(x - xs)) <= 1e-12 * np.max(np.abs(xs))


def _factored(pattern, data, kmax):
    band = BorderedBandLU(pattern, 4)
    ulu = updated_lu(band, pattern, kmax)
    assert band_factor(data, ulu.band) == 0
    reset(ulu, data)
    return ulu


@pytest.mark.parametrize("grid", [(48, 8), (151, 21)])
def test_replaced_columns_solve_like_superlu(grid):
    pattern, data = _orbit_jacobian(grid)
    pattern = sp.csc_matrix(pattern)
    rng = np.random.default_rng(5)
    ulu = _factored(pattern, data, 8)
    new = data.copy()
    cols = rng.choice(pattern.shape[0] - 4, 5, replace=False)
    for c in cols[:3]:  # three cells switch: their columns change by orders of magnitude
        new[pattern.indptr[c]:pattern.indptr[c + 1]] *= 50.0
    new *= 1.0 + 1e-3 * rng.standard_normal(new.size)  # the rest drifts below the threshold
    assert column_update(ulu, new, 0.3) == 3
    assert sorted(ulu.cols[:3]) == sorted(cols[:3])
    eff = data.copy()
    for c in cols[:3]:
        eff[pattern.indptr[c]:pattern.indptr[c + 1]] = new[pattern.indptr[c]:pattern.indptr[c + 1]]
    _check(pattern, data, eff, ulu, rng)
    # two more switch later: the first three stay replaced (with their newest values), five in all
    newer = new.copy()
    for c in cols[3:]:
        newer[pattern.indptr[c]:pattern.indptr[c + 1]] *= 0.02
    assert column_update(ulu, newer, 0.3) == 5
    for c in cols:
        eff[pattern.indptr[c]:pattern.indptr[c + 1]] = newer[pattern.indptr[c]:pattern.indptr[c + 1]]
    _check(pattern, data, eff, ulu, rng)
    assert column_update(ulu, newer, 0.3) == 0  # nothing moved: nothing to do
    too_many = newer.copy()
    too_many[: pattern.indptr[20]] *= 10.0  # 20 columns: more than kmax, refused
    assert column_update(ulu, too_many, 0.3) == -1


def test_random_arrow_column_update():
    n, nb = 300, 3
    rng = np.random.default_rng(1)
    A = sp.diags([rng.standard_normal(n - abs(k)) for k in (-2, -1, 0, 1, 2)], [-2, -1, 0, 1, 2]).tolil()
    A[0, n - 1] = A[n - 1, 0] = 1.0
    A.setdiag(4.0 + rng.standard_normal(n))
    M = sp.bmat([[A, rng.standard_normal((n, nb))], [rng.standard_normal((nb, n)), np.eye(nb)]]).tocsc()
    M.sort_indices()
    band = BorderedBandLU(M, nb)
    ulu = updated_lu(band, M, 4)
    assert band_factor(M.data, ulu.band) == 0
    reset(ulu, M.data)
    new = M.data.copy()
    for c in (7, 150, n + 1):  # two block columns and a border column
        new[M.indptr[c]:M.indptr[c + 1]] = rng.standard_normal(M.indptr[c + 1] - M.indptr[c])
    assert column_update(ulu, new, 0.3) == 3
    _check(M, M.data, new, ulu, rng)
