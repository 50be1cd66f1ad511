"""Surface-tension levelling of an oil layer across a rolling track: nonlinear thin-film equation (MOL) on a
uniform grid (the earlier formulation, with its optional mobility floor; the physical model with re-wetting
fronts is :mod:`transient.models.ball.front`) and Chiu's (1974) linear Fourier solution.

Thin-film (lubrication) equation for the oil layer ``h(x, t)`` on a flat surface, surface tension
``sigma``, viscosity ``eta`` (no gravity, no slip at the wall, free surface)::

    h_t = -(sigma / (3 eta)) d/dx ( h^3 d^3h/dx^3 )                                         (TF)

Scaled with a length ``x_ref``, a film ``h_ref`` and ``T = 3 eta x_ref^4 / (sigma h_ref^3)`` it reads
``H_t = -(H^3 H_xxx)_x``. Conservative finite volumes on cells of width ``dx`` (centres
``x_i = (i + 1/2) dx``): the flux through the face between cells j and j+1 is
``q_j = Hf^3 (H_{j+2} - 3 H_{j+1} + 3 H_j - H_{j-1}) / dx^3`` with ``Hf = (H_j + H_{j+1})/2`` and
``dH_i/dt = -(q_i - q_{i-1}) / dx`` (optionally with the mobility ``Hf^3 + b^3``, see
:class:`LevellingGrid`), so the discrete volume ``sum H_i dx`` changes only through the
boundary faces. Boundaries (ghost cells):

* left ``x = 0``: the track centreline, a symmetry plane (``H_-1 = H_0``, ``H_-2 = H_1``), or periodic;
* right ``x = X``: ``"reservoir"`` -- the ambient film ``H = H_res`` with ``H_xx = 0`` (ghosts odd
  about ``H_res``: the undisturbed ambient oil beyond the ball's reach feeds the track), or
  ``"closed"`` -- no flux (``H_x = H_xxx = 0``, ghosts even), or periodic.

Linearised about a uniform depth ``h0``, a mode ``cos(kappa x)`` decays at
``lambda = sigma h0^3 kappa^4 / (3 eta)`` (the discrete operator gives ``(2 sin(kappa dx/2)/dx)^4``
in place of ``kappa^4``).

Chiu's solution (Y. P. Chiu, "A theory of hydrodynamic friction forces in starved point contacts
considering cavitation", and "A theory of film replenishment in rolling contacts", ASLE Trans. 17,
1974; as written in Jeong et al., Eqs. 6-7) for a depression ``f(x)`` of half width ``a'`` in a layer of
depth ``h_inf``::

    zeta(x, t) = a' int_0^inf F(xi) exp(-xi L g(H)) cos(xi x / a') dxi,   L = t S / (2 eta a')
    g(H) = (1 - 4 H e^{-2H} - e^{-4H}) / (1 + e^{-2H})^2 = (sinh 2H - 2H)/(1 + cosh 2H),  H = xi h_inf / a'
    F(xi) = 2/(pi a'^2) int_0^inf f(x) cos(xi x / a') dx

(S = sigma). ``g(H) = (2/3) H^3 (1 - 4 H^2/5 + ...)`` for small H, so Chiu's decay rate
``xi S g / (2 eta a' t)`` tends to the thin-film rate ``sigma h_inf^3 kappa^4/(3 eta)``,
``kappa = xi/a'``: the thin-film equation is the long-wave limit of Chiu's Stokes-layer kernel, and
Chiu's solution is the small-amplitude limit of (TF) there.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np
import scipy.fft as sfft
import scipy.sparse as sp
from scipy.integrate import quad

from transient.checks import check_choice
from transient.solvers.integrate import Problem

BCS = ("reservoir", "closed", "periodic")


# --------------------------------------------------------------------------------------------------
# numba kernels (dimensionless)
# --------------------------------------------------------------------------------------------------

@nb.njit(cache=True)
def _ext(h, j, idx, coef, const):
    return coef[j + 2] * h[idx[j + 2]] + const[j + 2]


@nb.njit(cache=True)
def _flux(h, j, inv_dx3, idx, coef, const, mob0):
    hm1 = _ext(h, j - 1, idx, coef, const)
    h0 = _ext(h, j, idx, coef, const)
    h1 = _ext(h, j + 1, idx, coef, const)
    h2 = _ext(h, j + 2, idx, coef, const)
    hf = 0.5 * (h0 + h1)
    mob = (hf * hf * hf if hf > 0.0 else 0.0) + mob0
    return mob * (h2 - 3.0 * h1 + 3.0 * h0 - hm1) * inv_dx3


@nb.njit(cache=True)
def thin_film_rhs(h, dx, idx, coef, const, mob0, out):
    """``out_i = -(q_i - q_{i-1})/dx`` for the scaled thin-film equation (module docstring)."""
    n = h.size
    inv_dx3 = 1.0 / (dx * dx * dx)
    q_prev = _flux(h, -1, inv_dx3, idx, coef, const, mob0)
    for i in range(n):
        q = _flux(h, i, inv_dx3, idx, coef, const, mob0)
        out[i] = -(q - q_prev) / dx
        q_prev = q


@nb.njit(cache=True)
def thin_film_jac(h, dx, idx, coef, const, mob0, pos, period, data):
    """Analytic Jacobian ``d out / d h`` into the CSC data array (positions ``pos[row, col-row+2]``)."""
    n = h.size
    inv_dx3 = 1.0 / (dx * dx * dx)
    data[:] = 0.0
    dq = np.empty(4)
    # periodic: face -1 is face n-1, so visit each face once
    for j in range(0 if period > 0 else -1, n):
        hm1 = _ext(h, j - 1, idx, coef, const)
        h0 = _ext(h, j, idx, coef, const)
        h1 = _ext(h, j + 1, idx, coef, const)
        h2 = _ext(h, j + 2, idx, coef, const)
        hf = 0.5 * (h0 + h1)
        if hf > 0.0:
            mob = hf * hf * hf + mob0
            dmob = 1.5 * hf * hf
        else:
            mob = mob0
            dmob = 0.0
        third = (h2 - 3.0 * h1 + 3.0 * h0 - hm1) * inv_dx3
        dq[0] = -mob * inv_dx3                      # d q / d h_{j-1}
        dq[1] = dmob * third + 3.0 * mob * inv_dx3  # d q / d h_j
        dq[2] = dmob * third - 3.0 * mob * inv_dx3  # d q / d h_{j+1}
        dq[3] = mob * inv_dx3                       # d q / d h_{j+2}
        for s in range(4):
            e = j - 1 + s + 2
            col = idx[e]
            c = coef[e] * dq[s]
            if c == 0.0:
                continue
            # face j enters row j with -1/dx and row j+1 with +1/dx
            for side in range(2):
                r = j + side
                fac = (2.0 * side - 1.0) / dx
                if r < 0 or r >= n:
                    if period == 0:
                        continue
                    r = r % n
                d = col - r
                if period > 0:
                    d = (d + n + 2) % n - 2
                data[pos[r, d + 2]] += fac * c


# --------------------------------------------------------------------------------------------------
# grid / problem
# --------------------------------------------------------------------------------------------------

class LevellingGrid:
    """Uniform finite-volume grid across the track for the scaled thin-film equation.

    Parameters (dimensionless: lengths in ``x_ref``, films in ``h_ref``)
    ----------
    n_cells : number of cells (>= 5).
    length : domain length ``X`` (the half width from the centreline, or the period if periodic).
    bc : ``"reservoir"`` (ambient film ``h_res`` at ``x = X``), ``"closed"`` or ``"periodic"``.
    h_res : the reservoir film (only for ``bc="reservoir"``).
    mobility_film : ``b``: the face mobility is ``Hf^3 + b^3`` (a precursor-like regularisation of the
        moving contact line of a ridge spreading onto a nearly dry track; 0 = pure ``Hf^3``). It adds
        no oil, it lets a front move on a grid that cannot resolve a molecularly thin film.
    """

    def __init__(self, n_cells: int, length: float, bc: str = "reservoir", h_res: float = 1.0,
                 mobility_film: float = 0.0):
        if int(n_cells) != n_cells or n_cells < 5:
            raise ValueError(f"n_cells = {n_cells!r} [-] must be an integer >= 5")
        if not (np.isfinite(length) and length > 0):
            raise ValueError(f"length = {length!r} [x_ref] must be finite and > 0")
        check_choice("bc", bc, BCS)
        if bc == "reservoir" and not h_res > 0:
            raise ValueError(f"h_res = {h_res!r} [h_ref] must be > 0")
        if not (np.isfinite(mobility_film) and mobility_film >= 0):
            raise ValueError(f"mobility_film = {mobility_film!r} [h_ref] must be finite and >= 0")
        self.mob0 = float(mobility_film) ** 3
        n = int(n_cells)
        self.n, self.length, self.bc, self.h_res = n, float(length), bc, float(h_res)
        self.dx = self.length / n
        self.x = (np.arange(n) + 0.5) * self.dx
        j = np.arange(-2, n + 2)
        idx = np.clip(j, 0, n - 1).astype(np.int64)
        coef = np.ones(n + 4)
        const = np.zeros(n + 4)
        if bc == "periodic":
            idx = (j % n).astype(np.int64)
        else:
            idx[0], idx[1] = 1, 0                    # symmetry plane at x = 0
            idx[n + 2], idx[n + 3] = n - 1, n - 2    # mirror at x = X
            if bc == "reservoir":                    # odd about h_res: h = h_res, h_xx = 0
                coef[n + 2:] = -1.0
                const[n + 2:] = 2.0 * self.h_res
        self.idx, self.coef, self.const = idx, coef, const
        self.period = n if bc == "periodic" else 0
        rows, cols = [], []
        for d in range(-2, 3):
            r = np.arange(n)
            c = r + d
            if bc == "periodic":
                c = c % n
            else:
                keep = (c >= 0) & (c < n)
                r, c = r[keep], c[keep]
            rows.append(r)
            cols.append(c)
        rows, cols = np.concatenate(rows), np.concatenate(cols)
        pat = sp.csc_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n))
        pat.sum_duplicates()
        pat.sort_indices()
        pat.data[:] = 1.0
        self.pattern = pat
        pos = -np.ones((n, 5), dtype=np.int64)
        for c in range(n):
            for p in range(pat.indptr[c], pat.indptr[c + 1]):
                r = pat.indices[p]
                d = c - r
                if bc == "periodic":
                    d = (d + n + 2) % n - 2
                pos[r, d + 2] = p
        self.pos = pos

    # kernels bound to this grid ------------------------------------------------------------------
    def rhs(self, h: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        out = np.empty_like(h) if out is None else out
        thin_film_rhs(h, self.dx, self.idx, self.coef, self.const, self.mob0, out)
        return out

    def jac_data(self, h: np.ndarray, data: np.ndarray | None = None) -> np.ndarray:
        data = np.empty(self.pattern.nnz) if data is None else data
        thin_film_jac(h, self.dx, self.idx, self.coef, self.const, self.mob0, self.pos, self.period, data)
        return data

    def jac_matrix(self, h: np.ndarray) -> sp.csc_matrix:
        return sp.csc_matrix((self.jac_data(h), self.pattern.indices, self.pattern.indptr), shape=(self.n, self.n))

    def volume(self, h: np.ndarray) -> float:
        """Discrete volume ``sum h_i dx`` (conserved by the interior fluxes)."""
        return float(np.sum(h) * self.dx)

    def problem(self, h0: np.ndarray, name: str = "thin_film") -> Problem:
        """The facade's :class:`Problem` for ``dH/dt = rhs(H)`` from ``H(0) = h0`` (scaled time)."""
        dx, idx, coef, const, pos, period = self.dx, self.idx, self.coef, self.const, self.pos, self.period
        mob0 = self.mob0

        def rhs(t, y, out):
            thin_film_rhs(y, dx, idx, coef, const, mob0, out)

        def jac(t, y, data):
            thin_film_jac(y, dx, idx, coef, const, mob0, pos, period, data)

        return Problem(y0=np.array(h0, dtype=float), rhs=rhs, jac_pattern=self.pattern, jac_rhs=jac,
                       band=None if self.bc == "periodic" else (2, 2), name=name)

    # linear theory -------------------------------------------------------------------------------
    def mode_wavenumbers(self) -> np.ndarray:
        """Wavenumbers of the grid's eigenmodes ``cos(kappa x)`` (cell-centred, matching the BCs)."""
        k = np.arange(self.n)
        if self.bc == "reservoir":
            return (k + 0.5) * math.pi / self.length
        if self.bc == "closed":
            return k * math.pi / self.length
        return 2.0 * math.pi * np.minimum(k, self.n - k) / self.length

    def discrete_rate(self, kappa, h0: float = 1.0):
        """Decay rate of ``cos(kappa x)`` under the linearised discrete operator (scaled time)."""
        return h0 ** 3 * (2.0 * np.sin(0.5 * np.asarray(kappa) * self.dx) / self.dx) ** 4

    def to_modes(self, zeta: np.ndarray) -> np.ndarray:
        """Orthonormal modal coefficients of a deviation field (DCT-IV / DCT-II, cosine modes)."""
        if self.bc == "reservoir":
            return sfft.dct(zeta, type=4, norm="ortho")
        if self.bc == "closed":
            return sfft.dct(zeta, type=2, norm="ortho")
        raise ValueError("modal (Chiu) propagation is implemented for the half-domain BCs only")

    def from_modes(self, c: np.ndarray) -> np.ndarray:
        if self.bc == "reservoir":
            return sfft.idct(c, type=4, norm="ortho")
        return sfft.idct(c, type=2, norm="ortho")


def continuous_rate(kappa, h0: float = 1.0):
    """Thin-film decay rate ``h0^3 kappa^4`` of ``cos(kappa x)`` (scaled units)."""
    return h0 ** 3 * np.asarray(kappa, dtype=float) ** 4


# --------------------------------------------------------------------------------------------------
# Chiu (1974)
# --------------------------------------------------------------------------------------------------

def chiu_kernel(H):
    """``g(H) = (1 - 4H e^{-2H} - e^{-4H}) / (1 + e^{-2H})^2 = (sinh 2H - 2H)/(1 + cosh 2H)`` (Chiu 1974;
    Jeong et al. Eq. 6). For ``H < 0.5`` the numerator is summed as its series to avoid cancellation."""
    H = np.asarray(H, dtype=float)
    out = np.empty_like(H)
    small = H < 0.5
    Hs = H[small]
    z = 2.0 * Hs
    term = z ** 3 / 6.0
    num = term.copy()
    for n in range(2, 12):  # sinh z - z = sum_{n>=1} z^(2n+1)/(2n+1)!
        term = term * z * z / ((2 * n) * (2 * n + 1))
        num = num + term
    out[small] = num / (1.0 + np.cosh(z))
    Hl = H[~small]
    e2 = np.exp(-2.0 * Hl)
    out[~small] = (1.0 - 4.0 * Hl * e2 - e2 * e2) / (1.0 + e2) ** 2
    return out if out.ndim else float(out)


def chiu_rate(kappa, h_inf: float, sigma: float, eta: float, thin: bool = False):
    """SI decay rate [1/s] of ``cos(kappa x)``: Chiu ``sigma kappa g(kappa h_inf) / (2 eta)``.

    (Chiu's exponent ``xi L g(H)`` with ``xi = kappa a'``, ``L = t S/(2 eta a')``.) ``thin=True``
    gives the thin-film limit ``sigma h_inf^3 kappa^4 / (3 eta)``.
    """
    kappa = np.asarray(kappa, dtype=float)
    if thin:
        return sigma * h_inf ** 3 * kappa ** 4 / (3.0 * eta)
    return sigma * kappa * chiu_kernel(kappa * h_inf) / (2.0 * eta)


def chiu_depression(x: float, t: float, F, a_prime: float, h_inf: float, sigma: float, eta: float,
                    thin: bool = False) -> float:
    """Chiu's ``zeta(x, t) = a' int_0^inf F(xi) exp(-xi L g(xi h_inf/a')) cos(xi x/a') dxi`` [m].

    ``F(xi)`` [1/m] is the transform of the initial depression (``F = 2/(pi a'^2) int f cos``).
    """
    L = t * sigma / (2.0 * eta * a_prime)

    def integrand(xi):
        if thin:
            expo = (2.0 / 3.0) * xi * L * (xi * h_inf / a_prime) ** 3
        else:
            expo = xi * L * chiu_kernel(xi * h_inf / a_prime)
        return F(xi) * math.exp(-expo) * math.cos(xi * x / a_prime)

    # the integrand is negligible where the exponent exceeds ~700 or F has decayed; integrate piecewise
    val = 0.0
    edges = np.concatenate([[0.0], np.geomspace(1e-3, 1e3, 61)])
    for lo, hi in zip(edges[:-1], edges[1:]):
        v, _ = quad(integrand, lo, hi, epsabs=1e-16, epsrel=1e-11, limit=200)
        val += v
    return a_prime * val
