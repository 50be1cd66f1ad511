"""The x-line preconditioner of the roller's matrix-free film-content steps on grids uniform in x.

On a grid uniform in x and clustered in y the film is ``h = h0 + g + K p`` with ``K`` Toeplitz in x for every
pair of rows (:class:`~transient.physics.elasticity.RowConvolution`): the Schur system of the Newton step
(:class:`~transient.models.roller.line_fft.SchurOperator`, the node-wise elimination of the Fischer-Burmeister
rows) is solved by GMRES with its FFT products, right-preconditioned by :class:`LineBlocks`: the Schur matrix
kept on each x-line (every node of a row coupled with every node of the same row, the elastic coupling exact)
plus the y stencil (each node with the same x node of the rows above and below), a banded matrix of half-width
``nx`` factorised by LAPACK's banded LU (``sgbtrf``, single precision: :data:`BAND_DTYPE`) and bordered by the ``h0`` column and the load row. It is
Venner & Lubrecht's line relaxation along x (*Multilevel Methods in Lubrication*, Elsevier 2000, ch. 11) used
as a preconditioner: the heavily loaded rows' Couette-elastic coupling along the flow is kept whole, which the
coarse-grid correction of :mod:`transient.models.roller.roller_fft` misses (its coarse Schur matrix is
ill-conditioned at service loads and one coarse correction multiplies the residual, docs/validation.md).
The factors are kept across Newton iterations while GMRES stays within :data:`REFRESH_ITERS`; the Newton steps
take Eisenstat-Walker forcing terms (:data:`FORCING`).
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy.linalg import lapack

from transient.checks import check_memory

#: GMRES iterations above which the line factors are rebuilt at the next Newton iteration
REFRESH_ITERS = 60
#: precision of the band's factors: single (half the memory and ~1.5x faster solves than double, measured at 10x,
#: docs/validation.md; a preconditioner, so GMRES still reaches its tolerance on the double products)
BAND_DTYPE = np.float32
#: Eisenstat-Walker forcing terms for the Newton steps this preconditioner serves
#: (:func:`~transient.models.roller.line_fft.forcing_term`; False: every step to GMRES's ``RTOL``)
FORCING = True
_BAND_LAPACK = {np.dtype(np.float64): (lapack.dgbtrf, lapack.dgbtrs), np.dtype(np.float32): (lapack.sgbtrf, lapack.sgbtrs)}


@njit(cache=True)
def line_band(sp_, sh, st, colp, colh, coef, inv_scale, b_p, b_t, nx, nxf, ab):
    """Fill the LAPACK band storage ``ab`` (``kl = ku = nx``) with the x-line blocks and the y stencil of the
    Schur matrix: per row ``r`` (node ``(j, i)``) the columns of its own x-line and the columns ``r -+ nx``;
    ``coef[J, nxf - 1 + d, j]``: the film at full row ``J`` from unit pressure on source row ``j``, ``d`` x
    nodes apart."""
    n = sp_.shape[0]
    ny = n // nx
    kl = nx
    ku = nx
    for r in range(n):
        j = r // nx
        i = r - j * nx
        base = j * nx
        for s in range(sp_.shape[1]):
            h = colh[r, s]
            if h >= 0:
                a = sh[r, s] * inv_scale[r]
                if a != 0.0:
                    Js = h // nxf
                    Is = h - Js * nxf
                    for k in range(nx):
                        q = base + k
                        ab[kl + ku + r - q, q] += a * coef[Js, nxf - 1 + Is - (k + 1), j] * b_p[q]
                    if j >= 1:
                        q = r - nx
                        ab[kl + ku + r - q, q] += a * coef[Js, nxf - 1 + Is - (i + 1), j - 1] * b_p[q]
                    if j <= ny - 2:
                        q = r + nx
                        ab[kl + ku + r - q, q] += a * coef[Js, nxf - 1 + Is - (i + 1), j + 1] * b_p[q]
            q = colp[r, s]
            if q >= 0:
                ab[kl + ku + r - q, q] += (sp_[r, s] * b_p[q] + st[r, s] * b_t[q]) * inv_scale[r]


class LineBlocks:
    """The preconditioner (module docstring) of the Schur operator ``A`` (its film: a
    :class:`~transient.models.roller.roller_fbns.RollerContentFilm` on an ``"xfft"`` film): ``solve(b)``
    returns ``M^-1 b`` for the bordered banded matrix ``M``."""

    refresh_iters = REFRESH_ITERS
    forcing = FORCING

    def __init__(self, A, dtype=None):
        c, e = A.c, A.e
        g = c.grid
        nx, n = g.nx, c.n
        self.dtype = np.dtype(BAND_DTYPE if dtype is None else dtype)
        factor, self._trs = _BAND_LAPACK[self.dtype]
        check_memory(f"the x-line preconditioner of this {g.x.size} x {g.y.size} grid",
                     dict(band=self.dtype.itemsize * (3 * nx + 1) * n), "use fewer x nodes")
        ab = np.zeros((3 * nx + 1, n), dtype=self.dtype, order="F")
        line_band(e["dp"], e["dh"], e["dt"], c.colp, c.colh, c.base.conv.coefficients, A.inv_scale, A.b_p, A.b_t,
                  nx, g.x.size, ab)
        self.lu, self.piv, info = factor(ab, nx, nx, overwrite_ab=True)
        if info < 0:
            raise ValueError(f"LAPACK ?gbtrf: illegal argument {-info}")
        # info > 0: an exactly singular band (no such step measured); its solves are not finite, so GMRES misses
        # its tolerance and the step is flagged (line_newton.content_newton)
        self.nx, self.n = nx, n
        self.cvec = self._band_solve(A.j_h0 * A.inv_scale)
        self.w = c.weight * A.b_p
        wc = float(self.w @ self.cvec)
        self.wc = wc if wc != 0.0 else 1.0

    def _band_solve(self, b):
        x, _ = self._trs(self.lu, self.nx, self.nx, np.asarray(b, self.dtype), self.piv)
        return x.astype(float)

    def set_operator(self, A):
        """Keep the factors (reused while GMRES stays cheap)."""

    def solve(self, b):
        x = self._band_solve(np.ascontiguousarray(b[: self.n]))
        s = (self.w @ x - b[self.n]) / self.wc
        return np.append(x - s * self.cvec, s)
