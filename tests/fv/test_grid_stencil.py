"""Grid, stencil pattern and index maps."""

import numpy as np
import pytest

from transient.fv.grid import Axis, Grid2D, stretched_edges
from transient.fv.stencil import CENTRE, EAST, NORTH, SOUTH, WEST, Stencil


def test_axis_geometry_uniform_centred_and_stretched():
    a = Axis.uniform(8, 2 * np.pi, centred=True, periodic=True)
    assert a.centres[0] == pytest.approx(0.0, abs=1e-15)
    assert np.allclose(a.widths, np.pi / 4) and np.allclose(a.d_lower, np.pi / 4) and np.allclose(a.d_upper, np.pi / 4)
    b = Axis(np.array([0.0, 1.0, 3.0, 6.0]), lower="dirichlet", upper="symmetry")
    assert np.allclose(b.centres, [0.5, 2.0, 4.5])
    assert np.allclose(b.d_lower, [0.5, 1.5, 2.5]) and np.allclose(b.d_upper, [1.5, 2.5, 1.5])
    p = Axis(np.array([0.0, 1.0, 3.0, 6.0]), periodic=True)
    assert p.d_lower[0] == pytest.approx(2.0) and p.d_upper[-1] == pytest.approx(2.0)
    e = stretched_edges(40, 3.0, 0.5, start=1.0, fine_at=0.25)
    assert e[0] == pytest.approx(1.0) and e[-1] == pytest.approx(4.0) and np.all(np.diff(e) > 0)
    w = np.diff(e)
    assert np.argmin(w) in (9, 10) and w.max() / w.min() == pytest.approx(3.0, rel=0.02)


@pytest.mark.parametrize("kwargs, match", [
    (dict(edges=[0.0, 1.0, 1.0]), r"axis.edges must be strictly increasing; edges\[2\] - edges\[1\] = 0.0"),
    (dict(edges=[0.0]), "at least 2 values"),
    (dict(edges=[0.0, 1.0], lower="wall"), r"axis.lower must be one of \('dirichlet', 'symmetry'\), got 'wall'"),
    (dict(edges=[0.0, 1.0, 2.0, 3.0], periodic=True, lower="symmetry"), "periodic axis has no lower/upper"),
    (dict(edges=[0.0, 1.0, 2.0], periodic=True), "periodic axis needs n >= 3 cells, got n=2"),
    (dict(edges=[0.0, np.nan]), "finite"),
])
def test_axis_validation(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Axis(**kwargs)


def test_axis_constructor_validation():
    with pytest.raises(ValueError, match="theta.n must be an integer >= 1, got 0"):
        Axis.uniform(0, 1.0, name="theta")
    with pytest.raises(ValueError, match=r"theta.length must be finite and > 0, got -1.0"):
        Axis.uniform(4, -1.0, name="theta")
    with pytest.raises(ValueError, match=r"delta must be in \[0, 1\)"):
        stretched_edges(4, 1.0, 1.0)


def test_grid_flattening_and_fixed_cells():
    g = Grid2D(Axis.uniform(4, 4.0), Axis.uniform(3, 6.0))
    assert g.n == 12 and g.index(3, 2) == 11
    assert g.xc[g.index(1, 2)] == pytest.approx(1.5) and g.zc[g.index(1, 2)] == pytest.approx(5.0)
    assert np.allclose(g.area, 2.0)
    f = np.arange(12.0)
    assert g.to_2d(f)[2, 1] == f[g.index(1, 2)]
    mask = np.zeros((3, 4), bool)
    mask[1, 2] = True
    g.set_fixed(mask, 7.0)
    assert g.fixed[g.index(2, 1)] and g.fixed.sum() == 1 and g.fixed_values[g.index(2, 1)] == 7.0
    with pytest.raises(ValueError, match=r"fixed must have shape \(3, 4\) or \(12,\), got \(4, 3\)"):
        g.set_fixed(np.zeros((4, 3), bool))
    with pytest.raises(ValueError, match="boolean"):
        g.set_fixed(np.zeros(12))


def _dense_stencil(g, n_extra):
    """Reference pattern by explicit loops over (i, j) (test only)."""
    N = g.n + n_extra
    M = np.zeros((N, N), bool)
    for j in range(g.nz):
        for i in range(g.nx):
            k = i + g.nx * j
            M[k, k] = True
            for di, dj, ax, per in ((-1, 0, g.x, g.x.periodic), (1, 0, g.x, g.x.periodic),
                                    (0, -1, g.z, g.z.periodic), (0, 1, g.z, g.z.periodic)):
                ii, jj = i + di, j + dj
                if per:
                    ii, jj = ii % g.nx, jj % g.nz
                if 0 <= ii < g.nx and 0 <= jj < g.nz:
                    M[k, ii + g.nx * jj] = True
    M[:, g.n:] = True
    M[g.n:, :] = True
    return M


@pytest.mark.parametrize("n_extra", [0, 3])
@pytest.mark.parametrize("px, pz", [(True, False), (False, True), (False, False)])
def test_stencil_pattern_and_maps(n_extra, px, pz):
    x = Axis.uniform(5, 1.0, periodic=px) if px else Axis.uniform(5, 1.0, lower="symmetry")
    z = Axis.uniform(4, 1.0, periodic=pz) if pz else Axis.uniform(4, 1.0, upper="symmetry")
    g = Grid2D(x, z)
    st = Stencil(g, n_extra)
    M = _dense_stencil(g, n_extra)
    assert np.array_equal(st.pattern.toarray() != 0, M)
    assert st.nnz == M.sum()
    # every map points at the right (row, col) in CSC order
    data = np.arange(st.nnz, dtype=float)
    A = st.to_matrix(data).toarray()
    k = np.arange(g.n)
    for col, nbcol in ((CENTRE, None), (WEST, 0), (EAST, 1), (SOUTH, 2), (NORTH, 3)):
        nb = k if nbcol is None else st.nb[:, nbcol]
        ok = nb >= 0
        assert np.all(st.pos[ok, col] == A[k[ok], nb[ok]])
        assert np.all(st.pos[~ok, col] == -1)
    for e in range(n_extra):
        assert np.array_equal(st.pos_col_extra[:, e], A[:, g.n + e])
        assert np.array_equal(st.pos_row_extra[e], A[g.n + e, :])
    assert np.array_equal(st.pos_diag, np.diag(A))
    with pytest.raises(KeyError):
        st.position([0], [g.n - 1 if not px else 2])


def test_stencil_rejects_bad_n_extra():
    g = Grid2D(Axis.uniform(3, 1.0), Axis.uniform(3, 1.0))
    with pytest.raises(ValueError, match="n_extra must be an integer >= 0, got -1"):
        Stencil(g, -1)
