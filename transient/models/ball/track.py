"""The oil layer across the race track between two balls: what a ball pass does to it and how it levels.

Two discretisations of the same scaled problem (lengths in ``a'``, films in ``h_inf``, time in the
levelling time ``T``; :mod:`transient.models.ball.levelling`), both on the half track ``[0, X]``
(symmetry at the centreline, the ambient film or a wall at ``X``):

* :class:`FrontTrack` -- the physical model: no floor on the mobility, the swept band keeps the film
  the contact left behind (the precursor the re-wetting front advances over), finite volumes on a mesh
  that follows the front (:mod:`transient.models.ball.front`), rebuilt at every pass for that pass's
  precursor and remapped conservatively.
* :class:`UniformTrack` -- the earlier formulation: a uniform grid, optionally with the mobility floor
  ``h^3 + b^3``; or Chiu's linear kernel / its thin-film limit propagated mode by mode.

A pass (both): inside the band ``0 <= x < 1`` (the Hertz semi-axis across the track) the film becomes
``min(h, h_out)``; a share ``ridge_fraction`` of the oil removed goes into a side ridge
``sin(pi (x - 1)/w_r)`` on ``[1, 1 + w_r]`` (exact cell integrals: the volume is kept to round-off).
"""

from __future__ import annotations

import numpy as np

from transient.models.ball.front import FrontLevelling, FrontMesh, remap, sine_hump_share
from transient.models.ball.levelling import LevellingGrid, chiu_rate
from transient.solvers.integrate import solve
from transient.solvers.integrate import Steps


class FrontTrack:
    """Front-following finite volumes (the default ``grid="front"`` of the ball-pass sequence).

    Parameters (scaled)
    ----------
    length : ``X``; bc : ``"reservoir"`` or ``"closed"``; refine : grid refinement factor (1 = default
    mesh: ``dx_min = eps/2`` at the front, growth 1.12 behind it); level : the mesh follows ``H = level eps``;
    tau : relaxation time of that level; mobility_film : optional floor ``b`` (0 = none);
    edge : width of the wall of the depression left by the ball (the film rises from ``H*`` at the band
    edge to the old film with a C2 quintic over ``edge``; 0 = a step, the paper's rectangular
    depression, which is the limit ``edge -> 0``).
    """

    kind = "front"

    def __init__(self, length: float, bc: str = "reservoir", *, refine: float = 1.0, level: float = 3.0,
                 tau: float = 1e-3, mobility_film: float = 0.0, edge: float = 0.02, mesh_options: dict | None = None):
        self.X, self.bc, self.refine, self.edge = float(length), bc, float(refine), float(edge)
        self.level, self.tau, self.mobility_film = float(level), float(tau), float(mobility_film)
        self.mesh_options = dict(mesh_options or {})
        self._mesh_for(1e-3)  # validates the layout now (one-line errors before any integration)
        self.mesh = None
        self.c = None
        self.s = 1.0
        self.lev = None
        self.front = False

    def _mesh_for(self, eps: float) -> FrontMesh:
        """The mesh for a precursor ``eps`` (cached: a parched sequence repeats the same precursor)."""
        key = float(eps)
        cache = self.__dict__.setdefault("_meshes", {})
        if key not in cache:
            if len(cache) > 64:
                cache.clear()
            cache[key] = FrontMesh(self.X, min(0.5 * eps, 0.05), refine=self.refine, **self.mesh_options)
        return cache[key]

    def start(self, h0: float = 1.0):
        """Uniform film ``h0`` before the first ball (mesh designed for a precursor of 1e-3)."""
        self.mesh = self._mesh_for(1e-3)
        self.c = h0 * self.mesh.widths(1.0)
        self.s = 1.0

    # what the next ball meets -----------------------------------------------------------------------
    def inlet(self) -> float:
        """The film on the centreline (first cell) [h_inf]."""
        return float(self.c[0] / (self.mesh.faces(self.s)[1]))

    def volume(self) -> float:
        return float(np.sum(self.c))

    def profile(self, x: np.ndarray) -> np.ndarray:
        xc = self.mesh.centres(self.s)
        h = self.c / self.mesh.widths(self.s)
        return np.interp(x, xc, h)

    # the pass ---------------------------------------------------------------------------------------
    def ball_pass(self, h_out: float, ridge_fraction: float, ridge_width: float):
        """The ball leaves ``h_out`` on the band and moves the rest into the side ridge (share ``ridge_fraction``);
        the mesh is rebuilt for this precursor with its front where the film first exceeds ``H*`` behind the
        band edge (no front if the film there is thinner: the mesh then stays put)."""
        old_faces = self.mesh.faces(self.s)
        mesh = self._mesh_for(h_out)
        faces = mesh.faces(1.0)
        c = remap(old_faces, self.c, faces)
        w = np.diff(faces)
        xc = 0.5 * (faces[:-1] + faces[1:])
        band = np.arange(mesh.n) < mesh.jc          # face jc sits at x = 1
        keep = np.where(band, np.minimum(c, h_out * w), c)
        if self.edge > 0:
            # the wall of the depression: from the band film at x = 1 to the old film over `edge` (C2 quintic)
            xi = np.clip((xc - 1.0) / self.edge, 0.0, 1.0)
            S = xi ** 3 * (10.0 - 15.0 * xi + 6.0 * xi * xi)
            h = keep / w
            wall = (xc > 1.0) & (xc < 1.0 + self.edge) & (h > h_out)
            keep = np.where(wall, (h_out + (h - h_out) * S) * w, keep)
        removed = float(np.sum(c - keep))
        c = keep
        if ridge_fraction > 0 and removed > 0:
            c = c + ridge_fraction * removed * sine_hump_share(faces, 1.0, ridge_width)
        hstar = self.level * h_out
        lev = FrontLevelling(mesh, self.bc, hstar=hstar, tau=self.tau, mobility_film=self.mobility_film)
        h = c / w
        jc = mesh.jc
        reach = np.flatnonzero(xc[jc:] < 1.0 + 0.5 * mesh.d_behind)
        wet = np.flatnonzero(h[jc:jc + reach.size] > hstar)
        s = 1.0
        self.front = wet.size > 0
        if self.front:
            i = jc + int(wet[0])
            if i > jc:   # crossing between the centres i-1 and i; cell jc [s, s + dx] then holds about H*
                x0 = xc[i - 1] + (hstar - h[i - 1]) / (h[i] - h[i - 1]) * (xc[i] - xc[i - 1])
                s = max(1.0, x0 - 0.5 * mesh.dx_min)
                c = remap(faces, c, mesh.faces(s))
            c = lev.seed_front(c, s)
        self.mesh, self.s, self.c, self.lev = mesh, s, c, lev

    # between balls ----------------------------------------------------------------------------------
    def relax(self, t: float, stats: dict, *, method="cvode", rtol=1e-6, atol=1e-10, linear_solver="auto", dt=None):
        """Level for the scaled time ``t``: follow the front if there is one at the band edge."""
        self.lev, self.c, self.s, _ = self.lev.advance(self.c, self.s, t, moving=self.front, method=method, rtol=rtol,
                                                       atol=atol, linear_solver=linear_solver, stats=stats)
        self.mesh = self.lev.mesh


class UniformTrack:
    """Uniform cells: the nonlinear levelling (``replenishment="thin_film"``, optional mobility floor) or
    Chiu's linear modes (``"chiu"``, ``"chiu_thin"``)."""

    kind = "uniform"

    def __init__(self, n_cells: int, length: float, bc: str = "reservoir", *, replenishment: str = "thin_film",
                 mobility_film: float = 0.0, chiu_decay=None):
        self.grid = LevellingGrid(n_cells, length, bc, h_res=1.0, mobility_film=mobility_film)
        self.replenishment = replenishment
        self.bc = bc
        self.chiu_decay = chiu_decay
        g = self.grid
        self.band = np.clip((1.0 - (g.x - 0.5 * g.dx)) / g.dx, 0.0, 1.0)
        if not self.band.any():
            raise ValueError(f"n_cells = {n_cells} leaves no cell inside the depression half width a'")
        self.h = None

    def start(self, h0: float = 1.0):
        self.h = np.full(self.grid.n, float(h0))

    def inlet(self) -> float:
        return max(float(self.h[0]), 0.0)

    def volume(self) -> float:
        return self.grid.volume(self.h)

    def profile(self, x: np.ndarray) -> np.ndarray:
        return np.interp(x, self.grid.x, self.h)

    def ridge_shape(self, ridge_width: float) -> np.ndarray:
        g = self.grid
        xs = g.x
        rmask = (xs >= 1.0) & (xs < 1.0 + ridge_width)
        shape = np.where(rmask, np.sin(np.pi * (xs - 1.0) / ridge_width), 0.0)
        if shape.sum() <= 0:
            raise ValueError(f"ridge_width = {ridge_width:.3g} a' is narrower than one cell ({g.dx:.3g} a')")
        return shape / (shape.sum() * g.dx)

    def ball_pass(self, h_out: float, ridge_fraction: float, ridge_width: float):
        excess = self.band * np.maximum(self.h - h_out, 0.0)
        self.h = self.h - excess
        if ridge_fraction > 0:
            self.h = self.h + ridge_fraction * excess.sum() * self.grid.dx * self.ridge_shape(ridge_width)

    def relax(self, t: float, stats: dict, *, method="cvode", rtol=1e-6, atol=1e-10, linear_solver="auto", dt=None):
        if self.replenishment == "thin_film":
            res = solve(self.grid.problem(self.h, name="ball_levelling"), np.array([0.0, t]), method=method, rtol=rtol,
                        atol=atol, steps=Steps(dt=dt), linear_solver=linear_solver)
            if not res.success:
                raise RuntimeError(f"levelling failed ({method}): {res.message}")
            self.h = np.array(res.y[-1])
            for k in ("n_steps", "n_rhs", "n_jac"):
                stats[k] = stats.get(k, 0) + getattr(res.stats, k)
        else:
            ref = 1.0 if self.bc == "reservoir" else 0.0
            self.h = ref + self.grid.from_modes(self.grid.to_modes(self.h - ref) * self.chiu_decay)

    @staticmethod
    def chiu_decay_factors(grid: LevellingGrid, a_prime, h_ref, sigma, eta, t_b, thin):
        kap = grid.mode_wavenumbers() / a_prime
        return np.exp(-chiu_rate(kap, h_ref, sigma, eta, thin=thin) * t_b)
