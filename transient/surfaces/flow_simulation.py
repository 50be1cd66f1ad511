"""Numerical flow simulation for the Patir-Cheng pressure flow factors (an independent check of the fits).

N. Patir & H. S. Cheng, "An average flow model for determining effects of three-dimensional roughness
on partial hydrodynamic lubrication", ASME J. Lubr. Technol. 100 (1978) 12-17, obtain phi_x by
solving the *local* (deterministic) Reynolds equation on a small rough patch ("model bearing"):

    div( h_T^3 grad p ) = 0   on  0 < x < Lx, 0 < y < Ly,
    p = p_A at x = 0,  p = p_B at x = Lx,  dp/dy = 0 at y = 0, Ly,

with the local gap h_T = h + delta(x, y) (h: nominal separation of the mean planes, delta: composite
roughness heights -- one rough surface against a smooth one).  The pressure flow factor is the mean
flow through the patch over the flow of the smooth gap h under the same pressure drop:

    phi_x = [ (1/Ly) int_0^Ly  -h_T^3/(12 mu) dp/dx dy ] / [ h^3/(12 mu) (p_A - p_B)/Lx ].

Here (mu and the pressures cancel; the problem is linear) the equation is discretised with
:class:`~transient.fv.reynolds.ReynoldsOperator` on a cell-centred grid whose cells are the surface
samples (``P = u``, ``C = 1``, ``kx = kz = k``, no Couette term): one assembly (numba kernel), one
``splu`` solve per H.  The flow Q is taken on the inlet Dirichlet faces (half a cell from the first
cell centre, the cell's own k, exactly as the operator); the discrete outlet flow equals it to solver
precision (checked, reported as ``flux_mismatch``).  Heights are used about their mean plane and
H = h / sigma with sigma the RMS of *that* realisation (so H is exact per patch).

Contact: where h_T <= 0 there is no flow: k = max(h_T, 0)^3, with a floor k >= (floor h)^3
(``contact_floor``, default 1e-3, i.e. 1e-9 of the smooth-gap conductance) only so the matrix is
never singular (a cell in contact surrounded by contact has an empty row otherwise).  The operator's
face conductance is the arithmetic mean of the two cells, so a face between an open cell and a
contact cell still carries half the open cell's conductance: a contact spot "leaks" over half a cell
at its rim.  More generally the arithmetic face mean over-estimates the conductance between two
cells of very different gap, so phi is biased *high* by an amount of order (dx / correlation
length) x (variance of ln h_T^3); for the exponential ACF (non-differentiable surface) the decay
with resolution is slow.  ``refine`` (integer) samples the periodic surface on an r-times finer
grid by bilinear interpolation (renormalised to the sample RMS), which removes most of the bias
(measured in ``docs/validation_flow_factors.md``: for an isotropic log-normal conductivity, whose
exact effective value is the geometric mean, the relative error of the second-order deficit falls
from ~18 % (refine 1) to ~3 % (refine 2) at 8 samples per correlation length).

phi_y: the same computation on the surface rotated by 90 degrees (flow along y).

Public API
----------
* :func:`patch_flow_factor` -- phi for one height array and several H (the core solve);
* :func:`pressure_flow_factor_numerical` -- averages over realisations (generated from parameters or
  given surfaces), returns :class:`FlowFactorResult` (iterates as ``(H, phi_mean, phi_std)``);
* :func:`peklenik_lengths` -- correlation lengths (lx, ly) for a Peklenik number gamma.
"""

from __future__ import annotations

import math
from dataclasses import field

import numpy as np
import scipy.sparse.linalg as spla

from transient.checks import check_choice
from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import ReynoldsOperator
from transient.surfaces.roughness import RoughSurface
from transient.results import StatusResult, quantity, result_type
from transient.checks import check_positive, check_range

__all__ = [
    "FlowFactorResult",
    "patch_flow_factor",
    "pressure_flow_factor_numerical",
    "peklenik_lengths",
    "ridge_heights",
]

DIRECTIONS = ("x", "y")


@result_type
class FlowFactorResult(StatusResult):
    """Result of :func:`pressure_flow_factor_numerical`.

    ``H`` (n_H,), ``phi_mean`` and ``phi_std`` (sample standard deviation over realisations, ddof=1;
    0 for one realisation), ``phi`` (n_real, n_H) every realisation, ``sigma`` [m] and ``gamma``
    (measured Peklenik number, in the flow frame) per realisation, ``contact_fraction`` (n_real, n_H),
    ``meta`` (grid, direction, floor, refine, max flux mismatch).  Unpacks as ``H, mean, std = result``.
    """

    time_axis = None
    H: np.ndarray = quantity("-")
    phi_mean: np.ndarray = quantity("-")
    phi_std: np.ndarray = quantity("-")
    phi: np.ndarray = quantity("-")
    sigma: np.ndarray = quantity("m")
    gamma: np.ndarray = quantity("-")
    contact_fraction: np.ndarray = quantity("-")
    meta: dict = field(default_factory=dict)

    def __iter__(self):
        return iter((self.H, self.phi_mean, self.phi_std))

    @property
    def phi_sem(self) -> np.ndarray:
        """Standard error of the mean, phi_std / sqrt(n_realisations)."""
        return self.phi_std / math.sqrt(max(self.phi.shape[0], 1))


# --------------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------------
def _check_H(H_values) -> np.ndarray:
    H = np.atleast_1d(np.asarray(H_values, dtype=float))
    if H.ndim != 1 or H.size == 0:
        raise ValueError(f"H_values must be a non-empty 1-D list of h/sigma values [-], got shape {H.shape}")
    for v in H:
        check_range("H = h/sigma", float(v), "-", 0.0, math.inf, low_open=True, high_open=True)
    return H


def _spacing(spacing):
    sp = (spacing, spacing) if np.isscalar(spacing) else tuple(spacing)
    if len(sp) != 2:
        raise ValueError(f"spacing must be a number or (dx, dy) [m], got {spacing!r}")
    return check_positive("spacing dx", sp[0], "m"), check_positive("spacing dy", sp[1], "m")


def _refine_periodic(z: np.ndarray, r: int) -> np.ndarray:
    """Bilinear interpolation of a periodic sampled field onto an r-times finer cell-centred grid."""
    if r == 1:
        return z
    ny, nx = z.shape
    # fine cell centres in units of coarse spacing, coarse samples at integer positions (cell centres)
    sx = (np.arange(nx * r) + 0.5) / r - 0.5
    sy = (np.arange(ny * r) + 0.5) / r - 0.5
    ix0 = np.floor(sx).astype(int)
    iy0 = np.floor(sy).astype(int)
    wx = sx - ix0
    wy = sy - iy0
    ix0 %= nx
    iy0 %= ny
    ix1, iy1 = (ix0 + 1) % nx, (iy0 + 1) % ny
    a = z[np.ix_(iy0, ix0)] * (1 - wx)[None, :] + z[np.ix_(iy0, ix1)] * wx[None, :]
    b = z[np.ix_(iy1, ix0)] * (1 - wx)[None, :] + z[np.ix_(iy1, ix1)] * wx[None, :]
    return a * (1 - wy)[:, None] + b * wy[:, None]


class _Patch:
    """Operator, pattern and boundary data of one rectangular patch (reused for every H)."""

    def __init__(self, nx: int, ny: int, dx: float, dy: float):
        ax = Axis.uniform(nx, nx * dx, lower="dirichlet", upper="dirichlet", name="x")
        ay = Axis.uniform(ny, ny * dy, lower="symmetry", upper="symmetry", name="y")
        self.op = ReynoldsOperator(Grid2D(ax, ay), upwind=False, boundary_P=0.0, boundary_C=1.0)
        self.op.set_boundary("x-", P=1.0)  # p_A = 1, p_B = 0 (the problem is linear)
        self.op.set_boundary("x+", P=0.0)
        self.nx, self.ny, self.dx, self.dy = nx, ny, dx, dy
        n = self.op.n_cells
        self.zeros = np.zeros(n)
        self.ones = np.ones(n)

    def solve(self, k: np.ndarray):
        """Pressure (ny, nx) and (Q_in, Q_out) per unit p_A - p_B for the flat conductance field k."""
        op, z, o = self.op, self.zeros, self.ones
        # residual is affine in u: R(u) = J u + R(0)  (P = u, dP = 1, C = 1, dC = 0, k fixed, c = 0)
        r0 = op.residual(z, z, o, k, k, z, z)
        J = op.matrix(op.jacobian(z, o, o, z, k, z, k, z, z, z))
        u = spla.splu(J.tocsc()).solve(-r0)
        p = u.reshape(self.ny, self.nx)
        kk = k.reshape(self.ny, self.nx)
        half = 0.5 * self.dx
        q_in = float(np.sum(kk[:, 0] * (1.0 - p[:, 0]) / half) * self.dy)
        q_out = float(np.sum(kk[:, -1] * (p[:, -1] - 0.0) / half) * self.dy)
        return p, q_in, q_out


def patch_flow_factor(heights, spacing, H_values, direction: str = "x", sigma=None,
                      contact_floor: float = 1e-3, refine: int = 1, return_pressure: bool = False):
    """Pressure flow factor of one rough patch for each H = h/sigma (see module docstring).

    Parameters
    ----------
    heights : (ny, nx) composite roughness heights delta [m] (rows along y, columns along x), e.g.
        ``RoughSurface.heights``; used about their mean.
    spacing : dx or (dx, dy) [m].
    H_values : h / sigma values (> 0).
    direction : "x" (flow along the columns, phi_x) or "y" (phi_y: the patch rotated by 90 degrees).
    sigma : RMS roughness [m] defining H; default the RMS of the (mean-removed) heights actually
        used (after ``refine``: bilinear interpolation lowers the variance between samples, so the
        interpolated field is renormalised to the same RMS -- H stays h / RMS of the gap).  A smooth
        surface (all heights equal) needs an explicit sigma > 0 (H then only sets h = H sigma).
    contact_floor : k >= (contact_floor h)^3 in contact (h_T <= 0), 0 < floor < 1.
    refine : integer >= 1; cells per sample per direction (bilinear, periodic interpolation).

    Returns ``(phi, contact_fraction, flux_mismatch)`` arrays over H (flux mismatch = max
    |Q_in - Q_out|/Q_in), plus the last pressure field (ny, nx) if ``return_pressure``.
    """
    z = np.asarray(heights, dtype=float)
    if z.ndim != 2 or min(z.shape) < 2:
        raise ValueError(f"heights must be a 2-D array of at least 2x2 samples [m], got shape {z.shape}")
    if not np.all(np.isfinite(z)):
        raise ValueError("heights must be finite [m]")
    dx, dy = _spacing(spacing)
    check_choice("direction", direction, DIRECTIONS)
    H = _check_H(H_values)
    floor = check_range("contact_floor", contact_floor, "-", 0.0, 1.0, low_open=True, high_open=True)
    if isinstance(refine, bool) or int(refine) != refine or refine < 1:
        raise ValueError(f"refine = {refine!r} [-] is out of range; allowed: integers >= 1")
    refine = int(refine)
    if direction == "y":
        z, dx, dy = z.T, dy, dx
    z = _refine_periodic(z, refine)
    z = z - z.mean()
    s = float(np.sqrt(np.mean(z * z))) if sigma is None else check_positive("sigma", sigma, "m")
    if s <= 0.0:
        raise ValueError("heights have zero RMS: give sigma [m] > 0 explicitly to define H = h/sigma")
    z = z / s  # dimensionless heights delta / sigma
    patch = _Patch(z.shape[1], z.shape[0], dx / refine, dy / refine)
    Lx, Ly = patch.nx * patch.dx, patch.ny * patch.dy
    zf = z.ravel()
    phi = np.empty(H.size)
    cfrac = np.empty(H.size)
    mism = np.empty(H.size)
    p = None
    for m, Hm in enumerate(H):  # one linear sparse solve per H
        hT = Hm + zf
        k = np.maximum(hT, floor * Hm) ** 3
        p, q_in, q_out = patch.solve(k)
        phi[m] = q_in / (Ly * Hm ** 3 / Lx)
        cfrac[m] = float(np.mean(hT <= 0.0))
        mism[m] = abs(q_in - q_out) / abs(q_in)
    if return_pressure:
        return phi, cfrac, mism, p
    return phi, cfrac, mism


def peklenik_lengths(gamma: float, length: float):
    """Correlation lengths (lx, ly) [m] with lx/ly = gamma and the same correlation area lx ly = length^2."""
    g = check_positive("gamma", gamma, "-")
    length = check_positive("length", length, "m")
    return length * math.sqrt(g), length / math.sqrt(g)


def ridge_heights(shape, amplitude: float, periods: int, along: str):
    """Sinusoidal 1-D ridges on a (ny, nx) cell-centred grid: heights a sin(2 pi n (i + 1/2)/N).

    ``along="y"``: heights vary with x only (ridges across an x flow, "transverse");
    ``along="x"``: heights vary with y only (ridges along an x flow, "longitudinal").
    """
    ny, nx = (int(v) for v in shape)
    if along == "y":
        t = (np.arange(nx) + 0.5) / nx
        return np.broadcast_to(amplitude * np.sin(2 * np.pi * periods * t)[None, :], (ny, nx)).copy()
    if along == "x":
        t = (np.arange(ny) + 0.5) / ny
        return np.broadcast_to(amplitude * np.sin(2 * np.pi * periods * t)[:, None], (ny, nx)).copy()
    raise ValueError(f"along must be 'x' or 'y', got {along!r}")


def pressure_flow_factor_numerical(surface_or_params, H_values, direction: str = "x",
                                   n_realisations: int = 8, seed=0, *, contact_floor: float = 1e-3,
                                   refine: int = 1) -> FlowFactorResult:
    """Patir-Cheng flow simulation averaged over surface realisations.

    ``surface_or_params`` is one of

    * a :class:`RoughSurface` or a list of them (each one realisation; ``n_realisations`` and ``seed``
      are ignored), or
    * a dict of :meth:`RoughSurface.generate` keyword arguments (SI: ``shape=(ny, nx)``, ``spacing``
      [m], ``rq`` [m], ``correlation_lengths=(lx, ly)`` [m], ``acf``, ``method`` ...; no ``seed``):
      ``n_realisations`` surfaces are generated with independent seeds spawned from ``seed``.

    H_values: h/sigma (> 0), sigma the RMS of each realisation.  direction "x" -> phi_x, "y" -> phi_y.
    Returns a :class:`FlowFactorResult` (``H, phi_mean, phi_std = result``).
    """
    H = _check_H(H_values)
    check_choice("direction", direction, DIRECTIONS)
    if isinstance(surface_or_params, RoughSurface):
        surfaces = [surface_or_params]
    elif isinstance(surface_or_params, dict):
        if "seed" in surface_or_params:
            raise ValueError("give the seed as the 'seed' argument, not inside the generation parameters")
        if isinstance(n_realisations, bool) or int(n_realisations) != n_realisations or n_realisations < 1:
            raise ValueError(f"n_realisations = {n_realisations!r} [-] is out of range; allowed: integers >= 1")
        seeds = np.random.SeedSequence(seed).spawn(int(n_realisations))
        surfaces = (RoughSurface.generate(seed=sq, **surface_or_params) for sq in seeds)
    else:
        try:
            surfaces = list(surface_or_params)
        except TypeError:
            raise TypeError("surface_or_params must be a RoughSurface, a list of them, or a dict of "
                            "RoughSurface.generate parameters") from None
        if not surfaces or not all(isinstance(s, RoughSurface) for s in surfaces):
            raise TypeError("surface_or_params must be a non-empty list of RoughSurface objects")
    phis, cfs, sig, gam, mism = [], [], [], [], 0.0
    shape = None
    for s in surfaces:
        phi, cf, mm = patch_flow_factor(s.heights, s.spacing, H, direction, contact_floor=contact_floor,
                                        refine=refine)
        phis.append(phi)
        cfs.append(cf)
        sig.append(s.rq)
        try:
            g = s.gamma
        except Exception:  # noqa: BLE001 - a surface without a measurable ACF crossing
            g = math.nan
        gam.append(g if direction == "x" else 1.0 / g)
        mism = max(mism, float(np.max(mm)))
        shape = s.shape
    phi = np.array(phis)
    n = phi.shape[0]
    meta = dict(direction=direction, n_realisations=n, shape=shape, refine=refine,
                contact_floor=contact_floor, max_flux_mismatch=mism)
    return FlowFactorResult(H=H, phi_mean=phi.mean(axis=0),
                            phi_std=phi.std(axis=0, ddof=1) if n > 1 else np.zeros(H.size),
                            phi=phi, sigma=np.array(sig), gamma=np.array(gam), contact_fraction=np.array(cfs),
                            meta=meta)
