"""The discrete mass-conserving EHL point-contact film: unknowns, residual and Newton matrix.

Scaled as Venner & Lubrecht (*Multilevel Methods in Lubrication*, 2000) with the Hertz semi-axis ``b``
along the rolling direction: ``X = x/b``, ``Y = y/b``, ``P = p/p_h``, ``H = h Rx/b^2``, time by ``b/u``::

    H = H0 + X^2/2 + (Rx/Ry) Y^2/2 + c_el iint P(X', Y')/R dX'dY',   c_el = 2 p_h Rx/(pi E' b)
    d/dX(eps dP/dX) + d/dY(eps dP/dY) - d(rho theta H)/dX [- d(rho theta H)/dT] = 0,
    eps = rho H^3/(eta lam),   lam = 12 eta0 u Rx^2/(b^3 p_h)
    P >= 0,  1 - theta >= 0,  P (1 - theta) = 0       (Fischer-Burmeister: FB(P, 1 - theta) = 0)
    iint P dX dY = 2 pi k/3 (W(t)/W)                    (load balance, the unknown H0)

the fractional-film (Jakobsson-Floberg-Olsson / Elrod) form as solved by the Fischer-Burmeister-Newton-Schur
method (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.* 58, 2015; extended to EHL by Hansen, Kacan,
Frohnapfel & Codrignani, *Tribol. Lett.* 70, 2022). A starved inlet enters as the flux of the oil layer
``H_oil`` through the inlet boundary; the meniscus (where theta reaches 1) is a result.

The problem is symmetric about ``Y = 0``: the unknowns live on the half grid ``Y >= 0`` (the symmetry row
included), the elastic film takes the mirrored pressure. The film uses the DC-FFT product
(:class:`~transient.physics.elasticity.SurfaceConvolution`); Newton uses the same coefficients as a dense
matrix (the elastic coupling is dense), reduced node by node to the pressure-or-content unknown that the
Fischer-Burmeister row leaves free (the Schur step of FBNS), and factorised by LAPACK.
"""

from __future__ import annotations


import numpy as np
import scipy.fft as sfft
import scipy.sparse as sp

from transient.models.point.kernels import node_properties, reynolds
from transient.physics.elasticity import SurfaceConvolution, surface_influence
from transient.models.ehl.complementarity import CavitationRows, fb_residual


class MirroredConvolution:
    """``K p`` on the half grid for a pressure mirrored about ``Y = 0``: the DC-FFT product of
    :class:`~transient.physics.elasticity.SurfaceConvolution` (same coefficients), zero-padded to the next
    fast FFT length at least ``2 n - 1`` per axis (exact linear convolution; ``2 n`` of a prime ``n`` would
    make the FFT several times slower)."""

    def __init__(self, conv: SurfaceConvolution, m: int):
        self.conv, self.m = conv, m
        ny, nx = conv.ny, conv.nx
        self.shape = (sfft.next_fast_len(2 * ny - 1, real=True), sfft.next_fast_len(2 * nx - 1, real=True))
        k = conv._offsets
        ext = np.zeros(self.shape)
        ly, lx = self.shape
        ext[:ny, :nx] = k[ny - 1:, nx - 1:]
        ext[:ny, lx - nx + 1:] = k[ny - 1:, : nx - 1]
        ext[ly - ny + 1:, :nx] = k[: ny - 1, nx - 1:]
        ext[ly - ny + 1:, lx - nx + 1:] = k[: ny - 1, : nx - 1]
        self.kernel_hat = sfft.rfft2(ext)

    def apply(self, half: np.ndarray) -> np.ndarray:
        """Half-grid deformation ``(m, nx)`` for the half-grid pressure ``half`` ``(m, nx)``."""
        full = np.vstack([half[:0:-1], half])
        out = sfft.irfft2(sfft.rfft2(full, s=self.shape) * self.kernel_hat, s=self.shape)
        return out[self.m - 1: self.conv.ny, : self.conv.nx]


class PointFilm(CavitationRows):
    """The discrete film on the half grid (module docstring).

    ``x`` (nx nodes) and ``y`` (n nodes, symmetric, odd count) in units of b; ``ratio`` = Rx/Ry;
    ``lam``, ``c_el``, ``p_h`` [Pa]; ``lub`` the lubricant's kernel arguments; ``h_oil`` the scaled
    inlet layer (``inf``: flooded); ``load`` = iint P dX dY at the reference load (2 pi k/3); ``scheme`` the
    Couette flux (0 first-order upwind, 1 second-order linear upwind, 2 van Albada limited)."""

    def __init__(self, x, y, ratio, lam, c_el, p_h, lub, h_oil, load, scheme=1):
        self.x = np.asarray(x, float)
        self.y_full = np.asarray(y, float)
        ny = self.y_full.size
        self.m = (ny + 1) // 2
        self.y = self.y_full[self.m - 1:]
        self.nx = self.x.size
        self.ratio = float(ratio)
        self.dx = float(self.x[1] - self.x[0])
        self.dy = float(self.y[1] - self.y[0])
        self.lam, self.c_el, self.p_h = float(lam), float(c_el), float(p_h)
        self.lub = tuple(float(v) for v in lub)
        self.h_oil = float(h_oil)
        self.load = float(load)
        self.scheme = int(scheme)
        m, nx = self.m, self.nx
        self.n = (m - 1) * (nx - 2)
        yy, xx = np.meshgrid(self.y, self.x, indexing="ij")
        self.rigid = 0.5 * xx ** 2 + 0.5 * ratio * yy ** 2
        jj, ii = np.meshgrid(np.arange(m - 1), np.arange(1, nx - 1), indexing="ij")
        self.j, self.i = jj.ravel(), ii.ravel()
        self.flat = self.j * nx + self.i  # unknown -> half-grid node
        self.weight = np.where(self.j == 0, 1.0, 2.0) * self.dx * self.dy  # load quadrature (both halves)
        self.conv = SurfaceConvolution(nx, ny, self.dx, self.dy, scale=self.c_el)
        self.mirrored = MirroredConvolution(self.conv, m)
        self._kernel = None
        self._coarse = {}
        self._pattern()

    # -- fields ---------------------------------------------------------------------------------------
    def split(self, u):
        """``(P, T, H0)`` half-grid pressure and content arrays ``(m, nx)`` from the unknown vector."""
        P = np.zeros((self.m, self.nx))
        T = np.ones((self.m, self.nx))
        P.ravel()[self.flat] = u[: self.n]
        T.ravel()[self.flat] = u[self.n: 2 * self.n]
        return P, T, float(u[-1])

    def full(self, half):
        """The field on the whole grid ``(ny, nx)`` from its half (mirrored about Y = 0)."""
        return np.vstack([half[:0:-1], half])

    def film(self, P, h0):
        """Half-grid film ``H`` for the half-grid pressure ``P`` (DC-FFT of the mirrored pressure)."""
        return h0 + self.rigid + self.mirrored.apply(P)

    def deformation(self, dp):
        """``K dp``: the half-grid film change (flat) for pressure changes ``dp`` at the unknowns (DC-FFT)."""
        field = np.zeros(self.m * self.nx)
        field[self.flat] = dp
        return self.mirrored.apply(field.reshape(self.m, self.nx)).ravel()

    def kernel(self):
        """Dense ``dH/dP``: rows every half-grid node, columns the unknowns (mirror images added)."""
        if self._kernel is None:
            m, nx, ny = self.m, self.nx, self.y_full.size
            ix = np.arange(-(nx - 1), nx) * self.dx
            iy = np.arange(-(ny - 1), ny) * self.dy
            off = surface_influence(ix, iy, np.array([-0.5, 0.5]) * self.dx,
                                    np.array([-0.5, 0.5]) * self.dy).reshape(iy.size, ix.size) * self.c_el
            jo, io = np.divmod(np.arange(m * nx), nx)
            js, is_ = self.j, self.i
            di = io[:, None] - is_[None, :] + nx - 1
            k = off[jo[:, None] - js[None, :] + ny - 1, di]
            k += np.where(js[None, :] > 0, off[jo[:, None] + js[None, :] + ny - 1, di], 0.0)
            self._kernel = k
        return self._kernel

    # -- equations ------------------------------------------------------------------------------------
    def _pattern(self):
        m, nx = self.m, self.nx
        j, i = self.j, self.i
        unknown = -np.ones(m * nx, dtype=np.int64)
        unknown[self.flat] = np.arange(self.n)
        js = np.where(j == 0, j + 1, j - 1)
        nodes = np.stack([j * nx + i, j * nx + i - 1, j * nx + i + 1, js * nx + i, (j + 1) * nx + i,
                          j * nx + np.maximum(i - 2, 0)], axis=1)
        nodes[j == 0, 3] = nodes[j == 0, 4]  # the south slot is unused on the symmetry row (zeros)
        self.col_h = nodes  # centre, west, east, south, north, west-west (unused, zero, at column 1)
        self.col_p = unknown[nodes]

    def equations(self, u, load_ratio=1.0):
        """Residual pieces at ``u``: dict with the scaled fields and the kernel's local derivatives."""
        P, T, h0 = self.split(u)
        H = self.film(P, h0)
        rho, drho, eps, deps, depsh = node_properties(P, H, self.lam, self.p_h, self.lub)
        n = self.n
        res, scale = np.empty(n), np.empty(n)
        dp, dh, dt = np.empty((n, 6)), np.empty((n, 6)), np.empty((n, 6))
        reynolds(P, T, H, rho, drho, eps, deps, depsh, self.dx, self.dy, self.h_oil, self.scheme, res, scale,
                 dp, dh, dt)
        p = u[:n]
        fb, rad = fb_residual(p, u[n: 2 * n])
        load = self.weight @ p / self.load - load_ratio
        return dict(P=P, T=T, H=H, rho=rho, drho=drho, res=res, scale=scale, dp=dp, dh=dh, dt=dt, fb=fb,
                    rad=rad, load=load)

    def flow_balance(self, e):
        """Scaled flow rates through the boundary (both halves, units ``u b^3/Rx``): ``inlet`` (into the
        domain at ``X_in``: the carried layer plus the Poiseuille flow), ``outlet`` (out at ``X_out``) and
        ``sides`` (out at ``|Y| = Y_max``). Their balance is the sum of the Reynolds rows times the areas."""
        P, T, H, rho = e["P"], e["T"], e["H"], e["rho"]
        _, _, eps, _, _ = node_properties(P, H, self.lam, self.p_h, self.lub)
        wy = np.where(np.arange(self.m - 1) == 0, 1.0, 2.0) * self.dy
        ew = 0.5 * (eps[:-1, 0] + eps[:-1, 1])
        inlet = np.minimum(self.h_oil, H[:-1, 0]) - ew * (P[:-1, 1] - P[:-1, 0]) / self.dx
        ee = 0.5 * (eps[:-1, -2] + eps[:-1, -1])
        q = rho[:-1] * T[:-1] * H[:-1]
        carried = q[:, -2] if self.scheme == 0 else 1.5 * q[:, -2] - 0.5 * q[:, -3]  # the kernel's outlet face
        outlet = carried - ee * (P[:-1, -1] - P[:-1, -2]) / self.dx
        en = 0.5 * (eps[-2, 1:-1] + eps[-1, 1:-1])
        sides = -en * (P[-1, 1:-1] - P[-2, 1:-1]) / self.dy
        return dict(inlet=float(inlet @ wy), outlet=float(outlet @ wy), sides=2.0 * float(sides.sum()) * self.dx)

    def local_matrices(self, e):
        """Sparse ``(dR/dP local, dR/dH on the half-grid nodes, dR/dtheta)`` from the kernel's slots."""
        n, nn = self.n, self.m * self.nx
        rows = np.repeat(np.arange(n), self.col_p.shape[1])
        cp = self.col_p.ravel()
        keep = cp >= 0
        a_p = sp.csr_matrix((e["dp"].ravel()[keep], (rows[keep], cp[keep])), shape=(n, n))
        d_h = sp.csr_matrix((e["dh"].ravel(), (rows, self.col_h.ravel())), shape=(n, nn))
        a_t = sp.csr_matrix((e["dt"].ravel()[keep], (rows[keep], cp[keep])), shape=(n, n))
        return a_p, d_h, a_t

    def storage(self, e):
        """The film content ``q = rho theta H`` at the unknowns (the transient's stored mass)."""
        return (e["rho"] * e["T"] * e["H"]).ravel()[self.flat]

    def coarsened(self, factor: int = 2, scheme: int | None = None) -> "PointFilm":
        """The same problem on every ``factor``-th node (``nx - 1`` and ``(ny - 1)/2`` divisible by it; cached),
        with this film's Couette flux or ``scheme``."""
        if (self.nx - 1) % factor or (self.m - 1) % factor:
            raise ValueError(f"factor = {factor}: the grid {self.nx} x {self.y_full.size} does not coarsen by it")
        scheme = self.scheme if scheme is None else int(scheme)
        if (factor, scheme) not in self._coarse:
            self._coarse[factor, scheme] = PointFilm(self.x[::factor], self.y_full[::factor], self.ratio, self.lam,
                                                     self.c_el, self.p_h, self.lub, self.h_oil, self.load, scheme)
        return self._coarse[factor, scheme]

    def local_newton(self, u, e, cj=0.0):
        """The sparse pieces of the Jacobian of the Reynolds rows ``R - cj q`` (``cj = 0``: steady):
        ``(dR/dP at fixed film, dR/dH on the half-grid nodes, dR/dtheta)``; the full pressure block is
        ``dR/dP + (dR/dH) K`` with ``K`` the elastic influence of the unknowns on the half-grid films, and
        ``dR/dH0`` the row sums of ``dR/dH``."""
        if cj:  # the storage's derivatives enter the centre slot (the unknown's own node, no other slot's)
            f = self.flat
            rho, drho, T, H = (e[k].ravel()[f] for k in ("rho", "drho", "T", "H"))
            e = dict(e, dp=e["dp"].copy(), dh=e["dh"].copy(), dt=e["dt"].copy())
            e["dh"][:, 0] -= cj * rho * T
            e["dp"][:, 0] -= cj * drho * T * H
            e["dt"][:, 0] -= cj * rho * H
        return self.local_matrices(e)

    def newton_matrix(self, u, e, cj=0.0):
        """Blocks of the Jacobian of the Reynolds rows ``R - cj q`` (:meth:`local_newton`): ``(J_P dense,
        J_theta sparse, dR/dH0, load row)``."""
        a_p, d_h, a_t = self.local_newton(u, e, cj)
        j_pp = np.asarray(d_h @ self.kernel())
        j_pp += a_p.toarray()
        j_h0 = np.asarray(d_h.sum(axis=1)).ravel()
        return j_pp, a_t, j_h0, self.weight / self.load
