"""Matrix-free Newton steps of the roller's film-content (FBNS) iteration on uniform DC-FFT grids.

On a uniform grid the influence matrix of :class:`~transient.models.roller.ehl_problem.EHLFilm` is
block-Toeplitz, so ``K p`` is one zero-padded 2-D FFT product (DC-FFT, Liu, Wang & Liu, *Wear* 243, 2000;
:class:`transient.physics.elasticity.SurfaceConvolution`) and no ``N x N`` matrix is stored. The Schur system
of :func:`~transient.models.roller.line_newton.content_newton` (the node-wise elimination of the
Fischer-Burmeister rows) is then solved by GMRES with the products of
:class:`~transient.models.roller.line_fft.SchurOperator` (one FFT product each) and :class:`RollerTwoLevel`,
the line contact's two-level preconditioner (:class:`~transient.models.roller.line_fft.TwoLevel`) on the
roller's tensor grid:

* a coarse-grid correction: the dense Schur matrix of the same problem on a coarser grid over the same domain
  (``RollerContact`` takes its clustered 47 x 45 grid, which resolves the profiled ends; :func:`coarse_grid`, a
  uniform one) at the interpolated state (:func:`~transient.models.roller.roller_fbns.carry_content`),
  LU-factorised in single precision; residuals restricted by the transposed bilinear interpolation (rows
  averaged, Reynolds rows unscaled to the fine and scaled to the coarse rows), steps interpolated back;
* then a near-field correction: the Schur matrix with ``K`` cut to its self-influence (the 5-point stencil
  of the Reynolds rows), bordered by the ``h0`` column and the load row, by sparse LU
  (:class:`~transient.models.roller.line_fft.NearField`'s bordered solve).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from transient.models.roller.grid import TensorGrid
from transient.models.roller.line_fft import CoarseCorrection, NearField, SchurOperator, prolongation

#: :func:`coarse_grid` keeps at most this many interior nodes (dense Schur matrix, float32 LU)
COARSE_MAX_UNKNOWNS = 2500


def near_matrix(A: SchurOperator) -> sp.csc_matrix:
    """``S`` (Reynolds rows by their scales) with ``K`` cut to the self-influence ``K_00``: per slot ``s`` of row
    ``r`` at interior node ``q``: ``(Sp + Sh K_00) b_p[q] + St b_t[q]``."""
    c, e = A.c, A.e
    k00 = c.base.conv.centre
    rows = np.repeat(np.arange(c.n), c.colp.shape[1])
    cols = c.colp.ravel()
    q = np.where(cols >= 0, cols, 0)
    vals = (e["dp"].ravel() + e["dh"].ravel() * k00) * A.b_p[q] + e["dt"].ravel() * A.b_t[q]
    keep = (cols >= 0) & (vals != 0.0)
    B = sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape=(c.n, c.n))
    return (sp.diags(A.inv_scale) @ B).tocsc()


def coarse_grid(grid: TensorGrid, max_unknowns: int = COARSE_MAX_UNKNOWNS) -> TensorGrid:
    """A uniform grid over ``grid``'s domain: the axis with more nodes halved (``n -> (n - 1) // 2 + 1``) until at
    most ``max_unknowns`` interior nodes remain."""
    nx, ny = grid.x.size, grid.y.size
    while (nx - 2) * (ny - 2) > max_unknowns:
        if ny >= nx:
            ny = (ny - 1) // 2 + 1
        else:
            nx = (nx - 1) // 2 + 1
    return TensorGrid(np.linspace(grid.x[0], grid.x[-1], nx), np.linspace(grid.y[0], grid.y[-1], ny))


class RollerTwoLevel(CoarseCorrection):
    """The two-level preconditioner (module docstring) of the Schur operator ``A``; ``coarse``: the roller's dense
    content film on the coarse grid (:class:`~transient.models.roller.roller_fbns.RollerContentFilm`), ``uc``: the
    fine state on it."""

    def __init__(self, A: SchurOperator, uc, coarse):
        gf, gc = A.c.grid, coarse.grid
        self._set_coarse(coarse, uc, sp.kron(prolongation(gf.y, gc.y), prolongation(gf.x, gc.x), format="csr"))
        self.set_operator(A)

    def set_operator(self, A: SchurOperator):
        """Keep the coarse factors, take the near field and the row scales of a new operator."""
        self._set_scales(A)
        self.near = NearField.of_matrix(near_matrix(A), A, "COLAMD")
