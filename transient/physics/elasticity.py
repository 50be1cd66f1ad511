"""Elastic surface deformation of two half-spaces: influence coefficients of uniform pressure patches,
dense for non-uniform tensor grids and by FFT convolution (DC-FFT) on uniform grids.

Combined normal displacement of both surfaces, ``E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b)``:

* point (3-D half-space, Boussinesq; Johnson, *Contact Mechanics*, 1985, eq. 3.20)::

      v(x, y) = 2/(pi E') iint p(x', y') / sqrt((x - x')^2 + (y - y')^2) dx' dy'

* line (plane strain; Johnson eq. 2.25b), up to a constant that a rigid approach absorbs::

      v(x) = -4/(pi E') int p(s) ln|x - s| ds

With the pressure uniform on rectangular patches (the control volumes of the nodes) the integrals are
exact (Love, 1929)::

      iint_patch dx' dy' / r = [Phi(xi, eta)] over the patch corners,  xi = x' - x, eta = y' - y,
      Phi(xi, eta) = xi asinh(eta/|xi|) + eta asinh(xi/|eta|)      (Phi = 0 where a factor is 0)
      int_patch ln|x - s| ds = [u ln|u| - u] over the patch ends,   u = s - x

:func:`surface_influence` and :func:`line_influence` return the dense matrices of these raw integrals
(any tensor grid, exact); :class:`SurfaceConvolution` (point) and :class:`LineConvolution` (line) apply the
same coefficients on a uniform grid by one zero-padded FFT product (Liu, Wang & Liu, *Wear* 243, 2000: "DC-FFT"), exact (no periodic
wrap-around error), ``O(N log N)``; :class:`RowConvolution` on a grid uniform in x only (any y nodes): Toeplitz in
x for every pair of rows, so FFT along x and a dense sum over the rows. Models multiply by their own constant (``2/(pi E')`` in SI, or the
scaled factor of their units). Used by the EHL of the tapered roller (Park).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange


@njit(cache=True, inline="always")
def _phi(xi, eta):
    out = 0.0
    if xi != 0.0 and eta != 0.0:
        out = xi * math.asinh(eta / abs(xi)) + eta * math.asinh(xi / abs(eta))
    return out


@njit(cache=True, parallel=True)
def _surface_kernel(xo, yo, xe, ye, out):
    nxo, nyo = xo.size, yo.size
    npx, npy = xe.size - 1, ye.size - 1
    for jo in prange(nyo):
        g = np.empty((npy + 1, npx + 1))
        for io in range(nxo):
            for b in range(npy + 1):
                eta = ye[b] - yo[jo]
                for a in range(npx + 1):
                    g[b, a] = _phi(xe[a] - xo[io], eta)
            row = jo * nxo + io
            for b in range(npy):
                for a in range(npx):
                    out[row, b * npx + a] = g[b + 1, a + 1] - g[b + 1, a] - g[b, a + 1] + g[b, a]


def surface_influence(x_obs, y_obs, x_edges, y_edges) -> np.ndarray:
    """Dense ``K[(j, i), (l, k)] = iint 1/r`` over patch ``[x_edges[k], x_edges[k+1]] x [y_edges[l],
    y_edges[l+1]]`` seen from node ``(x_obs[i], y_obs[j])``; rows and columns are flat with x fastest.

    Shape ``(len(y_obs) * len(x_obs), (len(y_edges) - 1) * (len(x_edges) - 1))``; multiply by
    ``2/(pi E')`` for the displacement [m] under pressures [Pa]."""
    xo, yo = np.ascontiguousarray(x_obs, float), np.ascontiguousarray(y_obs, float)
    xe, ye = np.ascontiguousarray(x_edges, float), np.ascontiguousarray(y_edges, float)
    out = np.empty((xo.size * yo.size, (xe.size - 1) * (ye.size - 1)))
    _surface_kernel(xo, yo, xe, ye, out)
    return out


def line_influence(x_obs, x_edges) -> np.ndarray:
    """Dense ``L[i, k] = int ln|x_obs[i] - s| ds`` over ``[x_edges[k], x_edges[k+1]]``; multiply by
    ``-4/(pi E')`` for the displacement [m] (up to a constant) under pressures [Pa]."""
    xo = np.asarray(x_obs, float)[:, None]
    u = np.asarray(x_edges, float)[None, :] - xo
    au = np.abs(u)
    f = np.where(au > 0.0, u * np.log(np.where(au > 0.0, au, 1.0)), 0.0) - u
    return f[:, 1:] - f[:, :-1]


class SurfaceConvolution:
    """``K p`` for the coefficients of :func:`surface_influence` on a uniform ``ny x nx`` grid (spacings
    ``dx``, ``dy``, patches centred on the nodes), by a zero-padded FFT product (DC-FFT).

    ``apply(p)`` takes ``p`` of shape ``(ny, nx)`` and returns ``scale * K p`` of the same shape."""

    def __init__(self, nx: int, ny: int, dx: float, dy: float, scale: float = 1.0):
        self.nx, self.ny = int(nx), int(ny)
        ix = np.arange(-(self.nx - 1), self.nx) * dx
        iy = np.arange(-(self.ny - 1), self.ny) * dy
        xe = np.array([-0.5 * dx, 0.5 * dx])
        ye = np.array([-0.5 * dy, 0.5 * dy])
        k = surface_influence(ix, iy, xe, ye).reshape(iy.size, ix.size) * scale  # offsets (dy_j, dx_i)
        ext = np.zeros((2 * self.ny, 2 * self.nx))
        # wrap-around order: offset d >= 0 at index d, offset d < 0 at index 2n + d
        ext[: self.ny, : self.nx] = k[self.ny - 1:, self.nx - 1:]
        ext[: self.ny, self.nx + 1:] = k[self.ny - 1:, : self.nx - 1]
        ext[self.ny + 1:, : self.nx] = k[: self.ny - 1, self.nx - 1:]
        ext[self.ny + 1:, self.nx + 1:] = k[: self.ny - 1, : self.nx - 1]
        self.kernel_hat = np.fft.rfft2(ext)
        self.centre = float(k[self.ny - 1, self.nx - 1])  # self-influence K_00
        self._offsets = k

    def coefficient(self, di: int, dj: int) -> float:
        """``scale * K`` between two nodes ``di`` apart in x and ``dj`` apart in y."""
        return float(self._offsets[self.ny - 1 + dj, self.nx - 1 + di])

    def apply(self, p: np.ndarray) -> np.ndarray:
        p = np.asarray(p, float)
        if p.shape != (self.ny, self.nx):
            raise ValueError(f"p must have shape ({self.ny}, {self.nx}), got {p.shape}")
        pad = np.zeros((2 * self.ny, 2 * self.nx))
        pad[: self.ny, : self.nx] = p
        return np.fft.irfft2(np.fft.rfft2(pad) * self.kernel_hat, s=pad.shape)[: self.ny, : self.nx]


class LineConvolution:
    """``K p`` for the coefficients of :func:`line_influence` on ``n`` uniform nodes spaced ``dx`` (patches
    of width ``dx`` centred on the nodes), by a zero-padded FFT product (DC-FFT): ``K[i, k] = c(i - k)``
    (Toeplitz), so the product is a linear convolution, exact, ``O(n log n)``.

    ``apply(p)`` takes ``p`` of length ``n`` and returns ``scale * K p``."""

    def __init__(self, n: int, dx: float, scale: float = 1.0):
        from scipy.fft import next_fast_len

        self.n = int(n)
        c = line_influence(np.arange(-(self.n - 1), self.n) * dx, np.array([-0.5 * dx, 0.5 * dx]))[:, 0] * scale
        self.length = next_fast_len(2 * self.n - 1, real=True)
        ext = np.zeros(self.length)
        # wrap-around order: offset d >= 0 at index d, offset d < 0 at index length + d
        ext[: self.n] = c[self.n - 1:]
        ext[self.length - (self.n - 1):] = c[: self.n - 1]
        self.kernel_hat = np.fft.rfft(ext)
        self._offsets = c

    def coefficient(self, d: int) -> float:
        """``scale * K`` between two nodes ``d`` apart."""
        return float(self._offsets[self.n - 1 + d])

    def apply(self, p: np.ndarray) -> np.ndarray:
        p = np.asarray(p, float)
        if p.shape != (self.n,):
            raise ValueError(f"p must have shape ({self.n},), got {p.shape}")
        return np.fft.irfft(np.fft.rfft(p, self.length) * self.kernel_hat, self.length)[: self.n]


class RowConvolution:
    """``K p`` for the coefficients of :func:`surface_influence` on a tensor grid uniform in x only: ``nx``
    nodes spaced ``dx`` (patches of width ``dx`` centred on them) and any y rows. For every pair of rows
    (observation row ``J``, source row ``j``) the block of ``K`` is Toeplitz in x, ``K[(J, i), (j, k)] =
    c_Jj(i - k)``, so the product is one zero-padded FFT along x of each source row, a dense sum over the source
    rows per wave number, and one inverse FFT per observation row: exact (the same rectangle coefficients, no
    wrap-around), ``O(ny_o ny_s nx)`` instead of the dense ``O(ny_o ny_s nx^2)``.

    ``y_obs``: the observation rows; ``y_edges``: the source patches' edges along y (``ny_s + 1`` values);
    ``apply(p)`` takes ``p`` of shape ``(ny_s, nx)`` and returns ``scale * K p``, shape ``(ny_o, nx)``;
    ``coefficients[J, nx - 1 + d, j]`` is ``scale c_Jj(d)``."""

    def __init__(self, nx: int, dx: float, y_obs, y_edges, scale: float = 1.0):
        from scipy.fft import next_fast_len

        self.nx = int(nx)
        yo, ye = np.asarray(y_obs, float), np.asarray(y_edges, float)
        self.ny_obs, self.ny_src = yo.size, ye.size - 1
        d = np.arange(-(self.nx - 1), self.nx) * dx
        k = surface_influence(d, yo, np.array([-0.5 * dx, 0.5 * dx]), ye) * scale
        self.coefficients = k.reshape(self.ny_obs, d.size, self.ny_src)
        self.length = next_fast_len(2 * self.nx - 1, real=True)
        ext = np.zeros((self.ny_obs, self.length, self.ny_src))
        # wrap-around order: offset d >= 0 at index d, offset d < 0 at index length + d
        ext[:, : self.nx] = self.coefficients[:, self.nx - 1:]
        ext[:, self.length - (self.nx - 1):] = self.coefficients[:, : self.nx - 1]
        # an even kernel (c(d) = c(-d)) has a real spectrum; kept complex-free as (wave number, J, j)
        self.kernel_hat = np.ascontiguousarray(np.fft.rfft(ext, axis=1).real.transpose(1, 0, 2))

    def apply(self, p: np.ndarray) -> np.ndarray:
        p = np.asarray(p, float)
        if p.shape != (self.ny_src, self.nx):
            raise ValueError(f"p must have shape ({self.ny_src}, {self.nx}), got {p.shape}")
        ph = np.fft.rfft(p, self.length, axis=1)  # (ny_s, n_k)
        parts = np.stack([ph.real.T, ph.imag.T], axis=2)  # (n_k, ny_s, 2)
        out = self.kernel_hat @ parts  # (n_k, ny_o, 2)
        return np.fft.irfft((out[..., 0] + 1j * out[..., 1]).T, self.length, axis=1)[:, : self.nx]
