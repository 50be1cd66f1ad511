"""EHL of a tilted tapered roller: the finite line contact of Park, steady.

Dimensionless as in the paper (X, Y by R_m, ``P = p/E'``, ``H = h/R_m``, ``U_m = eta0 u/(E' R_m)``,
``G = alpha E'``, ``W = w/(E' R_m^2)`` with w the total load), eqs. (1)-(6)::

    d/dX(rho H^3/eta dP/dX) + d/dY(rho H^3/eta dP/dY) = 12 U_m Rs(Y) d(rho H)/dX            (1)
    eta = exp(G P) (Barus) or Roelands; rho = 1 + 0.58 p/(1 + 1.68 p), p in GPa        (2), (3)
    H = H0 + H_rigid(X, Y) + (2/pi) iint P/r dX'dY'   (geometry: TaperedRoller)          (4)
    W = iint P dX dY                                                                     (5)
    P = 0 on the boundary, P = dP/dn = 0 at the free exit boundary (complementarity)     (6)

Domain (Park's Fig. 2): ``X`` from ``-5c`` to ``2.5c``, ``Y`` over ``+-0.55 d`` (widened to the dry
footprint's ends plus 5 % of ``d`` if it is off-centre), with ``c`` (mid-plane half-width) and ``d``
(length) of the dry elastostatic footprint (:mod:`transient.models.roller.dry`). Internally lengths are
scaled by ``c``, pressure by ``p_h = E' c/(4 R_m)`` and the film by ``c^2/R_m``
(:mod:`transient.models.roller.ehl_problem`).

Grids: ``"paper"`` -- 94 x 45 nodes (the paper's maximum), non-uniform: 60 % of the X nodes clustered on
the inlet side of the contact (sech^2 density centred at -0.5 c, width 1.8 c: on the line contact this
gives the central film within 0.7 % of its grid-converged value, the uniform 94-node grid 1.2 %), and in
Y at each end 25 % of the nodes on the profiled part of the footprint and 15 % on the footprint's end
(where the film's side lobes close under load: ``END_WIDTH``); nodes on ``X = 0`` and ``Y = 0, +-Y_d``;
elasticity by the dense influence matrix. ``("clustered", nx, ny)``: the same law with other node counts. ``(nx, ny)``:
uniform, elasticity by DC-FFT and Newton-Krylov (:mod:`transient.models.roller.krylov`). ``("hybrid", nx, ny)``:
x uniform, y clustered as the clustered grids plus a cluster on each end's side lobe, as wide as the end's 4 b/M
(``LOBE_FRACTION``, :meth:`RollerContact.end_lobes`: at service loads the minimum film lies in the valley the
side lobe closes across the footprint's end); the elastic film by FFT along x and densely along y
(:class:`~transient.physics.elasticity.RowConvolution`), the film-content Newton steps by GMRES with x-line
blocks (:mod:`transient.models.roller.roller_lines`); the default above the paper case's load, with 111 y nodes
and as many x nodes as the most loaded row needs (:attr:`RollerContact.grid_spec`). Above the paper case's
load (mid-plane M > 3.2) the clustered x axes put 75 % of their nodes on the contact and 10 % on its outlet
(``X_HEAVY``), and the default ``scheme="auto"`` limits the Couette flux (van Albada): the loaded end of the
tilted roller carries ~2.5x the mid-plane's load per length, and where a row's x spacing exceeds 4 b/M of its
own load the outlet constriction collapses onto one node and closes (:meth:`RollerContact.local_resolution`;
docs/ehl.md, section 8). This moves 5x the paper's load on 47 x 45 from failing to converging; on the paper
grid the 10x path still stops near 7x.

Steady solve (``method="auto"``): on clustered grids above the paper case's mid-plane M the mass-conserving film-content form by
Fischer-Burmeister-Newton-Schur (:mod:`transient.models.roller.roller_fbns`; Woloszynski et al. 2015, Hansen et
al. 2022), Newton from the dry pressure on nested grids, a grid whose loaded rows are too coarse in x refused
first (:meth:`RollerContact.check_resolution`); at and below the paper case's load (the same film, faster), on
uniform grids and for the transient's penalty form the Reynolds-condition form: nested iteration from the dry pressure on coarse grids to the requested one (above the paper
case's load: load continuation on the coarsest level whose x spacing resolves the load); Newton on the
Fischer-Burmeister system with the dense matrix (small grids) or GMRES with a single-precision LU
preconditioner kept across iterations (the paper grid) or a two-level preconditioner (uniform grids).
"""

from __future__ import annotations

import math
import time
from contextlib import nullcontext
from functools import cached_property, partial
from types import SimpleNamespace

import numpy as np
from scipy.interpolate import RegularGridInterpolator
from threadpoolctl import threadpool_limits

from transient.checks import check_int, check_memory, check_positive, check_range
from transient.models.ehl.film_run import contact_digest, load_digest, penalty_deprecated, transient_settings
from transient.models.roller.continuation import PathResult, follow
from transient.models.roller.dry import DryContact, DrySolver, dry_contact
from transient.models.roller.ehl_problem import EHLFilm, interpolate_state, solve_steady
from transient.models.roller.geometry import TaperedRoller
from transient.models.roller.grid import TensorGrid, clustered_axis
from transient.models.roller.krylov import DenseLU, NewtonKrylov, NewtonMatrix, TwoLevel
from transient.models.roller.results import EHLConvergenceError, RollerSteady, RollerTransient, UnderResolvedGridError
from transient.models.roller.roller_fbns import RollerContentFilm, carry_content, content_start, solve_content
from transient.models.roller.line_step import consistent_content, run_content_transient
from transient.models.roller.transient import load_ratio, run_squeeze
from transient.models.roller.transient_results import content_outputs, squeeze_result
from transient.physics.line_formulas import dowson_toyoda_central
from transient.physics.lubricant import DOWSON_HIGGINSON_PARK, Lubricant
from transient.solvers.newton import NewtonError
from transient.solvers.settings import Integration, LongRun

PAPER_GRID = (94, 45)
#: The methods :meth:`RollerContact.transient` offers: IDA on the penalty form, BDF2 on the film-content form.
TRANSIENT_METHODS = ("ida", "bdf2")
#: x node counts of the default x-uniform, y-clustered grid above the paper's load (:attr:`RollerContact.grid_spec`):
#: the fewest whose worst row's x spacing is at most ``HYBRID_RATIO`` times 4 b/M of its own load
#: (:meth:`RollerContact.dry_resolution`)
HYBRID_NX = (128, 256, 512, 1024, 2048)
#: measured on the tilted paper case at 10x its load (docs/validation.md): 256 x nodes (ratio 0.40) give H_c within
#: ~3 % of the Richardson limit (34 s CPU on 89 y nodes, 45 s on the default's 111), 128 (ratio 0.81) 12 % below it
HYBRID_RATIO = 0.5
#: the most x nodes of a default grid: the largest on which the default is verified to converge (10x the paper's
#: load); a load that needs more is refused without an explicit grid (50x: 512 x 89 does not converge, 1024 x 89
#: needs ~2.2 GB for its band LU)
HYBRID_NX_VERIFIED = 512
#: the nested iteration on hybrid grids starts from the coarsest level whose worst row's x spacing is at most this
#: times 4 b/M (10x: 128 x nodes, ratio 0.81, converge from the dry pressure; 50x: 128, ratio 3.6, do not); a
#: coarse level that fails hands the dry pressure to the next
HYBRID_START_RATIO = 1.0
#: share of a hybrid grid's y nodes on each end's side lobe: a sech^2 cluster centred on the footprint's end, as
#: wide as the end's 4 b/M (:meth:`RollerContact.end_lobes`); the other clusters keep their shares of the rest.
#: Measured at 10x the paper's load, 128 x nodes: the minimum film lies in the valley the side lobe closes across
#: the small end (~0.08 c wide); against the Richardson limit in y (111, 221, 441 y nodes, observed order 2.05)
#: the clustered law's 89 y nodes (0.018 c there) give H_min 34 % low, with the lobes 111 (0.0076 c) 7.4 % low; 221
#: and 441 take every Newton step with GMRES at its cap (docs/validation.md)
LOBE_FRACTION = 0.1
#: y nodes of the default hybrid grid: the 89 of the clustered 94 x 89 law and ``LOBE_FRACTION`` of the nodes on
#: each end's side lobe (``88 / (1 - 2 LOBE_FRACTION)`` intervals)
HYBRID_NY = 111
#: Couette flux of the Reynolds equation (:mod:`transient.models.ehl.rows`)
SCHEMES = ("auto", "upwind2", "upwind1", "limited")
#: steady forms: the mass-conserving film content (FBNS) and the Reynolds condition
METHODS = ("auto", "fbns", "reynolds")
#: largest worst-row ratio of x spacing to 4 b/M (:meth:`RollerContact.dry_resolution`) that the film-content
#: solve attempts. Measured on the tilted paper case (Newton from the dry pressure): 47 x 45 converges at 5x the
#: paper's load (ratio 3.3) and fails at 6x (4.0); 94 x 89 converges at 10x (2.9). A necessary condition only:
#: 94 x 45 and 188 x 45 fail at 10x (2.9 and 1.5) where the film closes at the loaded end's profiled part,
#: 0.15 c between y nodes there (94 x 89: 0.02 c)
RESOLUTION_LIMIT = 4.0
#: above this mid-plane Moes load the coarsest level is reached by load continuation
M_EASY_2D = 3.2


def _dense_lu(film, u, shift):
    return DenseLU(film.jacobian(u, shift))


def _two_level(coarse, film, u, shift):
    return TwoLevel(film, coarse, u, shift, NewtonMatrix(film, u, shift))

#: y clusters of the clustered grids at the two ends of the dry footprint: sech^2 width [c] and share of the
#: nodes each. The film's end constriction (the side lobes of the horseshoe) lies within ~0.3 c of the
#: footprint's end and narrows as the load grows (docs/ehl.md, section 6)
END_WIDTH, END_FRACTION = 0.15, 0.15
#: x clusters (centre [c], sech^2 width [c], share of the nodes) of the clustered grids: the paper's load
#: (inlet side of the contact) and above it (mid-plane M > M_EASY_2D), where the contact and its outlet need
#: the nodes: the loaded end of a tilted roller carries ~2.5x the mid-plane's load per length, and its outlet
#: constriction collapses onto one node when the x spacing exceeds 4 b/M of that row (local_resolution)
X_PAPER = [(-0.5, 1.8, 0.6)]
X_HEAVY = [(-0.2, 1.3, 0.75), (1.1, 0.25, 0.1)]
#: Newton iterations allowed per continuation step (accepted steps took 7-19 on 40 x 25 and 47 x 45 and 26-29 on
#: the paper grid; a step that needs more is halved rather than iterated to the 60 of a cold start)
STEP_ITERATIONS = 40
#: above this many unknowns the dense path solves its linear systems by GMRES + a reused LU
KRYLOV_ABOVE = 600
#: first level (and two-level coarse grid) of the uniform-grid solves
COARSE = ("clustered", 47, 45)


def _weights(length, clusters):
    """sech^2 cluster weights giving each cluster ``(centre, width, fraction)`` that fraction of the nodes."""
    total = sum(f for _, _, f in clusters)
    return [(c, d, f * length / ((1.0 - total) * 2.0 * d)) for c, d, f in clusters]


class RollerContact:
    """Steady EHL of a tapered roller on a flat race, SI at the API (module docstring).

    ``roller`` (:class:`TaperedRoller`), ``load`` [N] (total), ``speed`` [m/s] (mean entrainment speed at
    the mid-plane), ``viscosity`` eta0 [Pa s], ``pressure_viscosity`` alpha [1/Pa], ``modulus`` E' [Pa],
    ``density``, ``viscosity_law``, ``dh_constants`` as in :class:`~transient.physics.lubricant.Lubricant`;
    ``grid``: ``"paper"``, ``("clustered", nx, ny)``, ``("hybrid", nx, ny)`` (x uniform, y clustered) or ``(nx, ny)``
    (uniform), default None: the paper's grid up to the paper case's load, a hybrid grid above it (:attr:`grid_spec`); ``domain``: (inlet,
    outlet) in units of c and the half-length of the domain in units of d; ``scheme``: the Couette flux,
    ``"upwind2"``, ``"upwind1"``, ``"limited"`` (second order, van Albada's limiter) or ``"auto"``
    (:attr:`flux_scheme`).
    """

    def __init__(self, roller: TaperedRoller, load, speed, viscosity, pressure_viscosity, modulus,
                 density: str = "dowson-higginson", viscosity_law: str = "barus", grid=None,
                 domain=(-5.0, 2.5, 0.55), scheme: str = "auto", dh_constants=DOWSON_HIGGINSON_PARK):
        if not isinstance(roller, TaperedRoller):
            raise TypeError(f"roller must be a TaperedRoller, got {type(roller).__name__}")
        self.roller = roller
        self.load = check_positive("load", load, "N")
        self.speed = check_positive("speed", speed, "m/s")
        self.modulus = check_positive("modulus", modulus, "Pa")
        self.lubricant = Lubricant(viscosity=check_positive("viscosity", viscosity, "Pa s"),
                                 pressure_viscosity=pressure_viscosity, viscosity_law=viscosity_law, density=density,
                                 dh_constants=tuple(dh_constants))
        self.domain = (check_range("domain[0] (inlet)", domain[0], "c", -50.0, -1.5),
                       check_range("domain[1] (outlet)", domain[1], "c", 1.2, 50.0),
                       check_range("domain[2] (half-length)", domain[2], "d", 0.5, 2.0, low_open=True))
        if scheme not in SCHEMES:
            raise ValueError(f"scheme = {scheme!r} is not one of {SCHEMES}")
        self.scheme = scheme
        if grid is not None:
            self.grid_spec = self._parse_grid(grid)
        self._options = dict(speed=speed, viscosity=viscosity, pressure_viscosity=pressure_viscosity, modulus=modulus,
                             density=density, viscosity_law=viscosity_law, grid=grid, domain=domain, scheme=scheme,
                             dh_constants=tuple(dh_constants))

    def with_load(self, load: float) -> "RollerContact":
        """The same roller, lubricant and grid specification at another total load [N] (its own dry
        footprint and scaled grid): the steps of the load continuation, which keep this contact's grid
        law, node counts (:attr:`grid_spec`) and Couette flux (:attr:`heavy`)."""
        c = RollerContact(self.roller, load, **self._options)
        c.__dict__["heavy"] = self.heavy  # the cached properties, fixed to the path's target
        c.__dict__["grid_spec"] = self.grid_spec
        return c

    @cached_property
    def grid_spec(self) -> tuple:
        """``(kind, nx, ny)``; without ``grid``: the paper's grid up to the paper case's load, and above it
        (:attr:`heavy`) the x-uniform, y-clustered grid ``("hybrid", nx, HYBRID_NY)``: the clustered 94 x 89's y law
        (twice the paper's y nodes: at 5x the paper's load H_min on 94 x 45 is 42 % below 94 x 89's; at 7x and 10x
        94 x 45 does not converge, 94 x 89 does) plus the side lobes' clusters (``LOBE_FRACTION``: the minimum film's
        valley at the loaded end; docs/validation.md) and the fewest x nodes of
        ``HYBRID_NX`` that resolve the most loaded row (``HYBRID_RATIO``), the elastic film by FFT along x
        (:mod:`transient.models.roller.roller_lines`)."""
        if not self.heavy:
            return ("clustered",) + PAPER_GRID
        ny = HYBRID_NY
        for nx in HYBRID_NX:
            if self.dry_resolution(self.make_grid("hybrid", nx, ny))["worst_ratio"] <= HYBRID_RATIO:
                break
        if nx > HYBRID_NX_VERIFIED:
            raise ValueError(f"load = {self.load:g} N (mid-plane M = {self.mid_plane_M:.3g}): the default grid would "
                             f"need {nx} x {ny} nodes, more than the {HYBRID_NX_VERIFIED} x {ny} verified to converge "
                             "(at 10x the paper's load; at 50x, 512 x 89 does not converge: docs/validation.md); "
                             "allowed: a load whose default grid has at most "
                             f"{HYBRID_NX_VERIFIED} x nodes, or an explicit grid=('hybrid', nx, ny)")
        return ("hybrid", nx, ny)

    @cached_property
    def heavy(self) -> bool:
        """Above the paper case's mid-plane load (M > M_EASY_2D): the clustered grids put their x nodes on the
        contact and its outlet (``X_HEAVY``) and ``scheme="auto"`` limits the Couette flux."""
        return self.mid_plane_M > M_EASY_2D

    @property
    def flux_scheme(self) -> str:
        """The Couette flux used: ``scheme``, with ``"auto"`` read as ``"upwind2"`` up to the paper case's
        load and ``"limited"`` above it (:attr:`heavy`)."""
        if self.scheme == "auto":
            return "limited" if self.heavy else "upwind2"
        return self.scheme

    @classmethod
    def from_dimensionless(cls, U: float, G: float, W: float, modulus: float, roller: TaperedRoller,
                           speed: float = 1.0, **kw) -> "RollerContact":
        """The paper's dimensionless case: ``U = eta0 u/(E' R_m)``, ``G = alpha E'``, ``W = w/(E' R_m^2)``
        (total load) with ``E' = modulus`` [Pa] and R_m from ``roller``; ``speed`` [m/s] fixes the SI
        viscosity ``eta0 = U E' R_m / speed`` (only the product matters with Barus)."""
        U = check_range("U", U, "-", 0.0, 1e-4, low_open=True)
        G = check_range("G", G, "-", 0.0, 1e5)
        W = check_range("W", W, "-", 0.0, 1e-2, low_open=True)
        modulus = check_range("modulus", modulus, "Pa", 1e6, 1e13, why="(1 MPa to 10 TPa)")
        speed = check_positive("speed", speed, "m/s")
        if G / modulus > 1e-6:
            raise ValueError(f"G = {G!r} [-] with modulus = {modulus!r} [Pa] gives a pressure-viscosity coefficient "
                             f"G / modulus = {G / modulus:.4g} 1/Pa; allowed: at most 1e-06 1/Pa")
        rm = roller.mean_radius
        return cls(roller, load=W * modulus * rm * rm, speed=speed, viscosity=U * modulus * rm / speed,
                   pressure_viscosity=G / modulus, modulus=modulus, **kw)

    @staticmethod
    def _parse_grid(grid):
        if isinstance(grid, str):
            if grid != "paper":
                raise ValueError(f"grid = {grid!r}: use 'paper', ('clustered', nx, ny), ('hybrid', nx, ny) or (nx, ny)")
            return ("clustered",) + PAPER_GRID
        if not isinstance(grid, (tuple, list)):
            raise ValueError(f"grid = {grid!r}: use 'paper', ('clustered', nx, ny), ('hybrid', nx, ny) or (nx, ny)")
        grid = tuple(grid)
        if len(grid) == 3 and grid[0] in ("clustered", "hybrid"):
            kind, nx, ny = grid
        elif len(grid) == 2:
            kind, (nx, ny) = "uniform", grid
        else:
            raise ValueError(f"grid = {grid!r}: use 'paper', ('clustered', nx, ny), ('hybrid', nx, ny) or (nx, ny)")
        nx = int(check_range("grid nx", nx, "nodes", 12, 4097))
        ny = int(check_range("grid ny", ny, "nodes", 8, 4097))
        return (kind, nx, ny)

    # -- dimensionless groups and scales --------------------------------------------------------------
    @property
    def U(self) -> float:
        return self.lubricant.viscosity * self.speed / (self.modulus * self.roller.mean_radius)

    @property
    def G(self) -> float:
        return self.lubricant.pressure_viscosity * self.modulus

    @property
    def W(self) -> float:
        return self.load / (self.modulus * self.roller.mean_radius ** 2)

    def dry(self) -> DryContact:
        """The dry (elastostatic) contact at the same load (cached): footprint c, d, pressure."""
        return self._dry

    @cached_property
    def _dry(self) -> DryContact:
        d = dry_contact(self.roller, self.load, self.modulus)
        if d.half_width <= 0.0:
            self._raise_open()
        return d

    def _raise_open(self):
        """The tilt opens the contact at the mid-plane: raise naming the tilt and its allowed range."""
        ro = self.roller

        def closed(tilt):
            solver = DrySolver(ro.with_tilt(tilt), self.W, coarse=(32, 192))
            x, y, p, *_ = solver._solve_on(4.0 * math.sqrt(8.0 * self.W / (2 * max(ro.y_d, 0.05)) / math.pi),
                                           -ro.half_length, ro.half_length, 32, 192)
            return solver.footprint(x, y, p)["c"] > 0.0

        lo, hi = 0.0, abs(ro.tilt_deg)
        for _ in range(12):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if closed(math.copysign(mid, ro.tilt_deg)) else (lo, mid)
        check_range("tilt_deg", ro.tilt_deg, "deg", -lo, lo,
                    why=f"(at load = {self.load:g} N a larger tilt opens the contact at the mid-plane, c = 0, "
                        "and the paper's domain is built on c)")

    @cached_property
    def scales(self) -> dict:
        """Scaled-unit constants: ``B = c/R_m``, ``P_h = B/4`` (p_h/E'), wedge ``lam``, load ``w_bar``."""
        d = self.dry()
        rm = self.roller.mean_radius
        B = d.half_width / rm
        Ph = B / 4.0
        return {"B": B, "Ph": Ph, "p_scale": Ph * self.modulus, "lam": 48.0 * self.U / B ** 4,
                "w_bar": self.W / (B * B * Ph), "film": B * B * rm,
                "y_lo": d.footprint_start / rm / B, "y_hi": d.footprint_end / rm / B,
                "d": d.footprint_length / rm / B}

    # -- grids ------------------------------------------------------------------------------------------
    def y_range(self) -> tuple[float, float]:
        """Domain along Y in units of c."""
        s = self.scales
        half = self.domain[2] * s["d"]
        return min(-half, s["y_lo"] - 0.05 * s["d"]), max(half, s["y_hi"] + 0.05 * s["d"])

    def make_grid(self, kind: str, nx: int, ny: int) -> TensorGrid:
        """A grid of the domain in units of c (module docstring)."""
        x0, x1 = self.domain[:2]
        y0, y1 = self.y_range()
        if kind == "uniform":
            return TensorGrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
        s = self.scales
        if kind == "hybrid":
            x = np.linspace(x0, x1, nx)
        else:
            x = clustered_axis(x0, x1, nx, _weights(x1 - x0, X_HEAVY if self.heavy else X_PAPER), snap=[0.0])
        yd = self.roller.y_d / s["B"]
        cl = []
        lobes = self.end_lobes() if kind == "hybrid" else None
        share = 1.0 if lobes is None else 1.0 - 2.0 * LOBE_FRACTION  # the other clusters and the rest alike
        for k, (start, end) in enumerate(((-yd, s["y_lo"]), (yd, s["y_hi"]))):
            cl += [(0.5 * (start + end), max(1.0, abs(end - start)), 0.25 * share),
                   (end, END_WIDTH, END_FRACTION * share), (start, 8.0, 0.05 * share)]
            if lobes is not None:
                cl.append((end, lobes[k], LOBE_FRACTION))
        y = clustered_axis(y0, y1, ny, _weights(y1 - y0, cl), snap=[0.0, -yd, yd])
        return TensorGrid(x, y)

    def end_lobes(self) -> tuple[float, float]:
        """The widths [c] of the film's side lobes at the small and the large end of the footprint: ``4 b/M`` of
        each end's most heavily loaded row read as a line contact (:meth:`local_resolution` on the dry pressure),
        the x rule's length. At service loads the minimum film lies in the valley the side lobe closes across the
        footprint's end, about that wide (docs/validation.md)."""
        d = self.dry()
        r = self._row_resolution(d.x, d.y, d.pressure)
        mid = 0.5 * (d.footprint_start + d.footprint_end)
        out = []
        for side in (d.y < mid, d.y >= mid):
            j = int(np.argmax(np.where(side, r["M"], 0.0)))
            out.append(4.0 * r["b"][j] / r["M"][j] / d.half_width)
        return out[0], out[1]

    @cached_property
    def grid(self) -> TensorGrid:
        g = self.make_grid(*self.grid_spec)
        self._check_grid(g)
        return g

    def _check_grid(self, g: TensorGrid):
        s = self.scales
        across = np.count_nonzero(np.abs(g.x) < 1.0)
        along = np.count_nonzero((g.y > s["y_lo"]) & (g.y < s["y_hi"]))
        if across < 8:
            raise ValueError(f"grid nx = {g.x.size} puts {across} nodes across the dry contact width 2c; allowed: >= 8")
        if along < 16:
            raise ValueError(f"grid ny = {g.y.size} puts {along} nodes along the dry footprint length d; "
                             "allowed: >= 16")
        yd = self.roller.y_d / s["B"]
        for name, side, end in (("small", -1.0, -s["y_lo"]), ("large", 1.0, s["y_hi"])):
            ys = side * g.y
            n_end = np.count_nonzero((ys >= yd) & (ys <= end))
            if end > yd and n_end < 2:
                dy = np.diff(g.y)[min(int(np.argmin(np.abs(ys - yd))), g.y.size - 2)]
                raise ValueError(f"grid ny = {g.y.size} puts {n_end} node(s) on the profiled part of the footprint "
                                 f"at the {name} end ({end - yd:.2f} c long; node spacing there {dy:.2f} c); "
                                 "allowed: >= 2 (refine y or use a clustered grid)")

    def levels(self) -> list[tuple[str, int, int]]:
        """Grid specifications of the nested iteration, coarse to fine. Clustered grids: the x node count
        halved while it stays >= 40 (y is kept: coarser y grids do not resolve the profiled ends).
        Uniform grids: the clustered 47 x 45 grid first (also the coarse grid of the two-level
        preconditioner), then uniform grids with the x node count halved while it stays >= 64. Hybrid grids: the
        x node count halved while it stays >= ``HYBRID_NX[0]``."""
        kind, nx, ny = self.grid_spec
        out = [(kind, nx, ny)]
        if kind == "hybrid":
            while nx // 2 >= HYBRID_NX[0]:
                nx //= 2
                out.insert(0, ("hybrid", nx, ny))
            return out
        if kind == "uniform":
            while nx // 2 >= 64:
                nx //= 2
                out.insert(0, ("uniform", nx, ny))
            return [COARSE] + out
        while (nx + 1) // 2 >= 40:
            nx = (nx + 1) // 2
            out.insert(0, ("clustered", nx, ny))
        return out

    # -- the discrete problem ---------------------------------------------------------------------------
    def film_problem(self, grid: TensorGrid, elastic: str = "dense") -> EHLFilm:
        s = self.scales
        ro = self.roller
        B = s["B"]
        X, Y = grid.x * B, grid.y * B
        rigid = ro.gap(X[None, :], Y[:, None]) / (B * B)
        return EHLFilm(grid, rigid, ro.radius_ratio(Y), s["lam"], s["w_bar"], self.lubricant, s["p_scale"],
                       elastic=elastic, elastic_factor=1.0 / (2.0 * math.pi), order2=(self.flux_scheme == "upwind2"),
                       limiter=(self.flux_scheme == "limited"))

    def initial_guess(self, film: EHLFilm) -> np.ndarray:
        """The dry pressure on ``film``'s grid (plus a small inlet ramp) and ``h0`` giving the
        Dowson-Toyoda central film of a line contact carrying W/d per unit length at the mid-plane."""
        d = self.dry()
        s = self.scales
        rm = self.roller.mean_radius
        f = RegularGridInterpolator((d.y / rm / s["B"], d.x / rm / s["B"]), d.pressure / self.modulus / s["Ph"],
                                    bounds_error=False, fill_value=0.0)
        g = film.grid
        yy, xx = np.meshgrid(g.y[1:-1], g.x[1:-1], indexing="ij")
        p = f(np.stack([yy.ravel(), xx.ravel()], axis=1))
        ramp = np.where(xx.ravel() < -1.0, 0.1 * (xx.ravel() - g.x[0]) / (-1.0 - g.x[0]), 0.0)
        inside = (yy.ravel() > s["y_lo"]) & (yy.ravel() < s["y_hi"])
        p = p + ramp * inside
        w_len = self.W / (d.footprint_length / rm)
        hc = dowson_toyoda_central(self.U, self.G, w_len) / (s["B"] ** 2)
        h_here = film.film(p, 0.0).reshape(g.shape_full)
        j0, i0 = int(np.argmin(np.abs(g.y))), int(np.argmin(np.abs(g.x)))
        # the dry pressure interpolated to a coarse grid need not give a flat gap: keep the film >= hc/2
        return np.append(p, max(hc - h_here[j0, i0], 0.5 * hc - h_here.min()))

    # -- steady ---------------------------------------------------------------------------------------
    def steady(self, tol: float = 1e-8, max_iter: int = 60, raise_on_failure: bool = True,
               penalty: float | None = None, method: str = "auto") -> RollerSteady:
        """Steady EHL film. ``method="fbns"``: the mass-conserving film-content form by
        Fischer-Burmeister-Newton-Schur (:meth:`steady_content`; dense elasticity); ``"reynolds"``: the
        Reynolds-condition form (:meth:`steady_reynolds`), which ``penalty`` (the transient's limit) and the
        uniform DC-FFT grids (Newton-Krylov) use; ``"auto"``: FBNS on clustered grids above the paper case's
        mid-plane M (:data:`M_EASY_2D`), else Reynolds. At and below it both forms give the same pressure and film
        (paper grid: within 1.3e-9 of P_max, H_c to 13 digits) and the Reynolds-condition form is the faster one
        there (docs/validation.md); its result carries no film content (``content`` is 1 everywhere): ask for
        ``method="fbns"`` to get the cavitated zone's content."""
        if method not in METHODS:
            raise ValueError(f"method = {method!r} is not one of {METHODS}")
        if method == "auto":
            easy = self.grid_spec[0] == "uniform" or self.mid_plane_M <= M_EASY_2D
            method = "reynolds" if easy else "fbns"
        if penalty is not None or method == "reynolds":
            return self.steady_reynolds(tol, max_iter, raise_on_failure, penalty)
        return self.steady_content(tol, max_iter, raise_on_failure)

    def steady_content(self, tol: float = 1e-8, max_iter: int = 60, raise_on_failure: bool = True) -> RollerSteady:
        """Steady film of the mass-conserving form (:mod:`transient.models.roller.roller_fbns`) by FBNS Newton
        with a reused single-precision factorisation. Nested iteration over :meth:`levels` (above the paper case's
        mid-plane M, 3.2, from the coarsest level that passes :meth:`check_resolution`'s rule; on hybrid grids the
        coarsest whose worst row's ratio is <= ``HYBRID_START_RATIO``, a coarse level that fails handing the dry
        pressure on to the next): the coarsest level starts
        from the dry pressure (:func:`content_start`; no pseudo-time and no load continuation: on the paper grid
        Newton converges from it up to 6x the paper's load, and a load path from the paper's load stopped at
        6.7x, docs/ehl.md section 8), finer levels from the coarser solution interpolated. The grid is checked
        first (:meth:`check_resolution`). ``tol``: the largest scaled residual (Reynolds
        rows by their diagonal, Fischer-Burmeister rows, load balance). Raises :class:`EHLConvergenceError`
        (with the last iterate) unless ``raise_on_failure=False``; a failure above the paper load names the
        row whose x spacing does not resolve its own load (:meth:`local_resolution`)."""
        t0, c0 = time.perf_counter(), time.process_time()
        self.check_resolution()
        specs = self.levels()
        if self.mid_plane_M > M_EASY_2D:  # from the coarsest level that resolves the loaded rows
            limit = HYBRID_START_RATIO if specs[0][0] == "hybrid" else RESOLUTION_LIMIT
            fine = [self.dry_resolution(self.make_grid(*sp))["worst_ratio"] <= limit for sp in specs[:-1]]
            specs = specs[fine.index(True) if any(fine) else -1:]
        info = {"method": "fbns", "levels": []}
        u, g_prev, iters, ok, msg, norms = None, None, 0, True, "", []
        for k, spec in enumerate(specs):
            last = k == len(specs) - 1
            g = self.grid if last else self.make_grid(*spec)
            tol_k = tol if last else math.sqrt(tol)
            cf = self.content_film(g, spec[0])
            level = {"grid": [int(g.x.size), int(g.y.size)]}
            cold = u is None
            u0 = content_start(self, cf) if cold else carry_content(g_prev, u, g)
            try:
                # the x-line factors and the FFT products are too small for BLAS threads to pay; on a shared
                # machine threads waiting for a core cost 3-5x the CPU time (measured at 10x, 256 x 89)
                with threadpool_limits(limits=1, user_api="blas") if spec[0] == "hybrid" else nullcontext():
                    nr = solve_content(cf, u0, tol_k, max_iter if cold else STEP_ITERATIONS,
                                       f"RollerContact.steady FBNS Newton ({g.x.size} x {g.y.size})")
                ok = True
            except NewtonError as exc:
                nr, ok = exc.result, False
                msg = f"level {k + 1}/{len(specs)} ({g.x.size} x {g.y.size} nodes): {exc}"
            u, its, norms = nr.x, nr.iterations, nr.residual_norms
            level.update(factorisations=int(nr.factorisations), gmres_iterations=int(nr.krylov))
            level["iterations"] = int(its)
            info["levels"].append(level)
            iters += its
            g_prev = g
            if not ok and spec[0] == "hybrid" and not last:  # the next level from the dry pressure
                u, ok = None, True
                level["failed"] = msg
            if not ok:
                break
        info["cpu_s"] = time.process_time() - c0
        if ok:
            msg = f"converged: {iters} Newton iterations over {len(specs)} grid level(s)"
        return self._finish(cf, u, ok, msg, iters, norms, t0, info, raise_on_failure)

    def content_film(self, g: TensorGrid, kind: str) -> RollerContentFilm:
        """The film-content form on ``g`` of grid ``kind``: ``"clustered"``, dense elasticity; ``"hybrid"``, FFT-in-x
        products with matrix-free Newton steps preconditioned by x-line blocks
        (:mod:`transient.models.roller.roller_lines`); ``"uniform"``, DC-FFT products with matrix-free Newton
        steps preconditioned on the clustered ``COARSE`` grid (:mod:`transient.models.roller.roller_fft`),
        which resolves the profiled ends."""
        kind = {True: "uniform", False: "clustered"}.get(kind, kind)  # the former flag ``uniform``
        if kind == "hybrid":
            return RollerContentFilm(self.film_problem(g, "xfft"))
        if kind != "uniform":
            return RollerContentFilm(self.film_problem(g, "dense"))
        coarse = RollerContentFilm(self.film_problem(self.make_grid(*COARSE), "dense"))
        return RollerContentFilm(self.film_problem(g, "fft"), coarse=coarse)

    def check_resolution(self) -> dict:
        """:meth:`dry_resolution` of this contact's grid; raises :class:`UnderResolvedGridError` when its worst
        row's ratio exceeds :data:`RESOLUTION_LIMIT` (no discrete film there: the outlet constriction of that
        row would collapse onto one node), naming the row, its local M and the x node count that would do."""
        r = self.dry_resolution()
        if r["worst_ratio"] > RESOLUTION_LIMIT:
            k = int(np.nanargmax(r["ratio"]))
            kind, nx, ny = self.grid_spec
            need = int(math.ceil(nx * r["worst_ratio"] / RESOLUTION_LIMIT))
            raise UnderResolvedGridError(
                f"grid {kind} {nx} x {ny} is too coarse in x for load = {self.load:g} N: the row at y = "
                f"{1e3 * r['worst_y']:.3f} mm carries a local M = {r['M'][k]:.3g} and its x spacing is "
                f"{r['worst_ratio']:.2f} times 4 b/M there (allowed: <= {RESOLUTION_LIMIT:g}); the x spacing alone needs "
                f"about nx >= {need} (grid=('clustered', {need}, {ny})), and the loaded end's profiled part may need "
                "more y nodes too", r)
        return r

    def _level_specs(self):
        """:meth:`levels`, above the paper case's load from the coarsest one whose x spacing resolves the
        mid-plane's load (``contact_spacing M <= 4``)."""
        specs = self.levels()
        if self.mid_plane_M > M_EASY_2D and specs[0][0] == "clustered":
            fine_enough = [self.contact_spacing(self.make_grid(*sp)) * self.mid_plane_M <= 4.0 for sp in specs]
            specs = specs[fine_enough.index(True) if any(fine_enough) else -1:]
        return specs

    def _finish(self, cf, u, ok, msg, iters, norms, t0, info, raise_on_failure):
        """The :class:`RollerSteady` of a film-content state; a failure names an under-resolved row."""
        n = cf.n
        state = np.append(u[:n], u[-1])
        res = self.result(cf.base, state, ok, msg, iters, norms, time.perf_counter() - t0, info, content=u[n: 2 * n])
        if not ok and np.any(res.pressure > 0.0):
            r = self.local_resolution(res)
            info["local_resolution"] = dict(worst_y=r["worst_y"], worst_ratio=r["worst_ratio"])
            k = int(np.nanargmax(r["ratio"]))
            j = int(np.argmin(np.abs(res.y - res.y_of_h_min)))
            dy = np.diff(res.y)[min(j, res.y.size - 2)] / (self.scales["B"] * self.roller.mean_radius)
            res.message = msg + (f"; the row at y = {1e3 * r['worst_y']:.3f} mm carries a local M = {r['M'][k]:.3g}, "
                                 f"its x spacing {r['worst_ratio']:.2f} times 4 b/M there; the film closes at "
                                 f"y = {1e3 * res.y_of_h_min:.3f} mm, {dy:.3f} c between y nodes there (under-resolved: "
                                 "refine x where the ratio exceeds ~3, y at the loaded end)")
        if not ok and raise_on_failure:
            raise EHLConvergenceError(res.message, res)
        return res

    def steady_reynolds(self, tol: float = 1e-8, max_iter: int = 60, raise_on_failure: bool = True,
                        penalty: float | None = None) -> RollerSteady:
        """Steady film of the Reynolds-condition form (module docstring). The coarsest level starts from the dry pressure with
        pseudo-transient continuation (backward-Euler steps of the squeeze-film transient, first step
        0.3 c/u) and is solved to ``sqrt(tol)`` -- above the paper case's mid-plane M (3.2) it is reached by
        load continuation instead (:meth:`continuation`; ``solver_info["continuation"]``); finer levels
        start from the interpolated coarser solution with plain Newton (pseudo-transient if that fails). ``penalty``: None for the exact
        complementarity (Fischer-Burmeister), or the penalty factor (the transient's ``GAMMA`` gives its limit). Raises
        :class:`EHLConvergenceError` with the non-converged result (``success=False``, residual history)
        unless ``raise_on_failure=False``."""
        t0 = time.perf_counter()
        grid = self.grid
        u, g_prev, iters, ok, msg, info = None, None, 0, True, "", {"method": "reynolds", "levels": []}
        owner = self  # the contact whose scales the state is in (a failed path's last converged load)
        specs = self._level_specs()
        for k, spec in enumerate(specs):
            last = k == len(specs) - 1
            g = grid if last else self.make_grid(*spec)
            film = self.film_problem(g, "fft" if spec[0] == "uniform" else "dense")
            film.penalty = None if penalty is None else check_range("penalty", penalty, "-", 1.0, 1e12)
            if k == 0:
                coarse = film
            u0 = self.initial_guess(film) if k == 0 else interpolate_state(g_prev, u, g)
            attempts = [0.3] if k == 0 else [None, 0.3]
            if k == 0 and self.mid_plane_M > M_EASY_2D:
                attempts = []
                path = self.continuation(spec, tol=math.sqrt(tol) if not last else tol, max_iter=max_iter,
                                         penalty=penalty)
                info["continuation"] = dict(message=path.message, steps=path.steps, rejected=path.rejected,
                                            loads=[p[0] for p in path.path], attempts=path.attempts)
                iters += path.iterations
                jac = None
                nr = SimpleNamespace(x=path.state, iterations=0, residual_norms=path.residual_norms)
                ok, pseudo = path.success, None
                if not ok:
                    msg = (f"level 1/{len(specs)} ({g.x.size} x {g.y.size} nodes): Newton did not converge; "
                           f"{path.message}")
                    if path.path:
                        msg += f" (last converged load {path.path[-1][0]:.4g} N of {self.load:.4g} N)"
                    dx, m = self.contact_spacing(g), self.mid_plane_M
                    if dx * m > 4.0:
                        msg += (f"; the x node spacing in the contact, {dx:.3g} c, exceeds 4/M = {4.0 / m:.3g} c "
                                f"(mid-plane M = {m:.3g}): the grid is too coarse for this load, refine x")
                    film, owner = path.film, path.contact
            for pseudo in attempts:
                if spec[0] == "uniform":
                    jac = NewtonKrylov(film, partial(_two_level, coarse), restart=80, max_iter=400, refresh_after=60)
                else:
                    jac = NewtonKrylov(film, _dense_lu) if film.n > KRYLOV_ABOVE else None
                try:
                    nr = solve_steady(film, u0, tol=tol if last else math.sqrt(tol), max_iter=max_iter,
                                      jacobian=jac, pseudo_time=pseudo,
                                      name=f"RollerContact.steady Newton ({g.x.size} x {g.y.size})")
                    ok = True
                    break
                except NewtonError as exc:
                    nr, ok = exc.result, False
                    msg = f"level {k + 1}/{len(specs)} ({g.x.size} x {g.y.size} nodes): {exc}"
            u, g_prev = nr.x, g
            iters += nr.iterations
            level = {"grid": [int(g.x.size), int(g.y.size)], "iterations": int(nr.iterations),
                     "pseudo_time": pseudo}
            if jac is not None:
                level.update(gmres_iterations=list(jac.gmres_iterations), preconditioners=jac.n_preconditioners)
            info["levels"].append(level)
            if not ok:
                break
        if ok:
            msg = f"converged: {iters} Newton iterations over {len(specs)} grid level(s)"
        res = owner.result(film, u, ok, msg, iters, nr.residual_norms, time.perf_counter() - t0, info)
        if not ok and np.any(res.pressure > 0.0):
            r = owner.local_resolution(res)
            info["local_resolution"] = dict(worst_y=r["worst_y"], worst_ratio=r["worst_ratio"])
            if r["worst_ratio"] > 1.0:
                k = int(np.nanargmax(r["ratio"]))
                msg += (f"; the row at y = {1e3 * r['worst_y']:.3f} mm carries a local M = {r['M'][k]:.3g}: its x spacing "
                        f"is {r['worst_ratio']:.2f} times 4 b/M there (under-resolved, refine x)")
                res = owner.result(film, u, ok, msg, iters, nr.residual_norms, time.perf_counter() - t0, info)
        if not ok and raise_on_failure:
            raise EHLConvergenceError(msg, res)
        return res

    @staticmethod
    def contact_spacing(grid: TensorGrid) -> float:
        """Largest x node spacing within 1.5 c of the centre line (units of c). A heavily loaded line
        contact has discrete solutions only while it is <= 4/M (docs/ehl.md, section 7)."""
        x = grid.x
        near = (x[1:] > -1.5) & (x[:-1] < 1.5)
        return float(np.max(np.diff(x)[near]))

    def local_resolution(self, steady: RollerSteady) -> dict:
        """The x resolution of ``steady``'s grid row by row against the load each row carries.

        Every y row is read as a line contact carrying its own load per length ``w'(y) = int p dx`` on the
        local radius ``R(y) = R_m Rs(y)`` (Moes' ``M(y) = w'/(E' R) (2 U_m)^-1/2``, Hertz half-width
        ``b(y) = (8 w' R/(pi E'))^1/2``); the line contact has discrete solutions while the x spacing within
        1.5 b(y) of the centre line is <= 4 b(y)/M(y) (docs/ehl.md, section 7). Returns the arrays ``y`` [m],
        ``M``, ``spacing`` (in units of b(y)) and ``ratio = spacing M/4`` (> 1: under-resolved; nan where
        the row carries no load), and the worst row's ``worst_y`` [m] and ``worst_ratio``."""
        return self._row_resolution(steady.x, steady.y, steady.pressure)

    def dry_resolution(self, grid: TensorGrid | None = None) -> dict:
        """:meth:`local_resolution` of ``grid`` (default: this contact's) with the dry pressure for the
        EHL one (the rows carry nearly the same loads): known before any Newton iteration."""
        g = self.grid if grid is None else grid
        d, B = self.dry(), self.scales["B"] * self.roller.mean_radius
        f = RegularGridInterpolator((d.y, d.x), d.pressure, bounds_error=False, fill_value=0.0)
        yy, xx = np.meshgrid(g.y * B, g.x * B, indexing="ij")
        return self._row_resolution(g.x * B, g.y * B, f(np.stack([yy.ravel(), xx.ravel()], axis=1)).reshape(yy.shape))

    def _row_resolution(self, x, y, p) -> dict:
        w = np.trapezoid(p, x, axis=1)
        R = self.roller.mean_radius * self.roller.radius_ratio(y / self.roller.mean_radius)
        loaded = w > 0.0
        M = np.where(loaded, w / (self.modulus * R) / math.sqrt(2.0 * self.U), 0.0)
        b = np.sqrt(8.0 * np.maximum(w, 0.0) * R / (math.pi * self.modulus))
        dx, mid = np.diff(x), 0.5 * (x[1:] + x[:-1])
        spacing = np.full(y.size, np.nan)
        for j in np.flatnonzero(loaded):
            near = np.abs(mid) < 1.5 * b[j] + 0.5 * dx
            spacing[j] = dx[near].max() / b[j]
        ratio = spacing * M / 4.0
        k = int(np.nanargmax(ratio))
        return dict(y=y, M=M, b=b, spacing=spacing, ratio=ratio, worst_y=float(y[k]), worst_ratio=float(ratio[k]))

    @property
    def mid_plane_M(self) -> float:
        """Moes' load group of the mid-plane as a line contact carrying W/d per unit length:
        ``M = (W R_m / d) (2U)^-1/2``."""
        return self.W * self.roller.mean_radius / (self.dry().footprint_length) / math.sqrt(2.0 * self.U)

    def continuation(self, spec, tol: float = 1e-8, max_iter: int = 40, penalty: float | None = None):
        """Steady film on the grid ``spec`` by load continuation
        (:func:`transient.models.roller.continuation.follow`) from the load whose mid-plane M is 3.2
        (the paper case; solved from its dry pressure by pseudo-transient Newton) up to this contact's.
        Each contact on the path has its own dry footprint and scaled grid: a step carries the pressure
        in pascals and the central film in metres to the next grid. Returns the
        :class:`~transient.models.roller.continuation.PathResult` (state on this contact's grid)."""
        w1 = self.load
        w0 = w1 * min(1.0, M_EASY_2D / self.mid_plane_M)
        cache = {}

        def at(s):
            if s not in cache:
                c = self if s >= 1.0 else self.with_load(w0 * (w1 / w0) ** s)
                g = c.make_grid(*spec)
                f = c.film_problem(g, "fft" if spec[0] == "uniform" else "dense")
                f.penalty = penalty
                cache[s] = (c, f)
            return cache[s]

        def centre_value(f, u):
            h = f.film(u[:-1], u[-1]).reshape(f.grid.shape_full)
            return h, h[int(np.argmin(np.abs(f.grid.y))), int(np.argmin(np.abs(f.grid.x)))]

        def central(s, u):
            c, f = at(s)
            h, hc = centre_value(f, u)
            return float(hc * c.scales["film"]) if np.all(np.isfinite(h)) and h[1:-1, 1:-1].min() > 0 else float("nan")

        def predict(s_from, u, s_to):
            (c0, f0), (c1, f1) = at(s_from), at(s_to)
            k = c0.scales["B"] / c1.scales["B"]
            g0 = TensorGrid(f0.grid.x * k, f0.grid.y * k)
            v = interpolate_state(g0, np.append(u[:-1] * c0.scales["p_scale"] / c1.scales["p_scale"], 0.0), f1.grid)
            hc = central(s_from, u)
            return np.append(v[:-1], hc / c1.scales["film"] - centre_value(f1, np.append(v[:-1], 0.0))[1])

        def solve(s, u0):
            f = at(s)[1]
            jac = NewtonKrylov(f, _dense_lu) if f.n > KRYLOV_ABOVE else None
            return solve_steady(f, u0, tol=tol, max_iter=min(max_iter, STEP_ITERATIONS), jacobian=jac,
                                name="RollerContact continuation")

        c0, f0 = at(0.0)
        try:
            nr = solve_steady(f0, c0.initial_guess(f0), tol=tol, max_iter=max_iter, pseudo_time=0.3,
                              jacobian=NewtonKrylov(f0, _dense_lu) if f0.n > KRYLOV_ABOVE else None,
                              name="RollerContact continuation start")
        except NewtonError as exc:
            return PathResult(state=exc.result.x, s=0.0, success=False, iterations=exc.result.iterations,
                              residual_norms=list(exc.result.residual_norms), film=f0, contact=c0,
                              message=f"Newton failed at the start of the path (load {w0:.4g} N)")
        path = follow(solve, predict, central, nr.x)
        path.iterations += nr.iterations
        path.contact, path.film = at(path.s)
        path.path = [(at(s)[0].load, hc) for s, hc in path.path]
        return path

    # -- transient --------------------------------------------------------------------------------------
    @property
    def time_scale(self) -> float:
        """Time unit of the scaled transient, the transit time ``c/u`` [s]."""
        return self.dry().half_width / self.speed

    def transient(self, t_end: float, load=None, start="dry", *, n_out: int = 51, initial_film: float | None = None,
                  ramp_time: float | None = None, max_steps: int = 5000, integration: Integration | None = None,
                  long_run: LongRun | None = None, **legacy) -> RollerTransient:
        """Transient EHL over ``[0, t_end]`` [s] on this contact's grid (dense elasticity: use a coarse clustered
        grid, docs/ehl.md gives the cost): by BDF2 on the film-content form (:mod:`transient.models.roller.line_step`)
        on the one run driver (:mod:`transient.models.ehl.film_run`).

        ``load``: None (constant), a number [N] (a step from the starting load smoothed over
        ``ramp_time``, default one transit time c/u) or a function of t [s] -> N. ``start``: ``"dry"``
        -- the dry pressure with the film at the mid-plane centre lifted to ``initial_film`` [m] (default
        half the Dowson-Toyoda central film of the mid-plane) -- or a :class:`RollerSteady` of this
        contact. ``integration`` (:class:`~transient.solvers.settings.Integration`, ``rtol`` default 1e-4):
        ``method="bdf2"`` (the default): the exact complementarity (the film content, cavitation mass-conserving),
        whose long-time limit is ``steady(method="fbns")`` (at and below the paper case's load the same film as
        ``steady()``); the content starts full where the start has pressure and mass-conserving where it has none
        (:func:`~transient.models.roller.line_step.consistent_content`, or a film-content ``start``'s own); the
        nodes crossing the cavitation boundary in a step leave its error test (``LineFilmStep.switched``);
        ``max_steps`` bounds the run. ``method="ida"``: the exit condition in penalty form, whose long-time limit
        is ``steady(penalty=GAMMA)`` (:data:`transient.models.roller.transient.GAMMA`) -- deprecated, removed in
        the next release. ``long_run`` (:class:`~transient.solvers.settings.LongRun`): checkpoint and resume,
        progress bar, ``stop``, ``time_budget`` [s of wall clock]. The loose keywords ``rtol=``, ``method=``,
        ``time_budget=`` of earlier releases are deprecated.
        """
        ig, lr = transient_settings("RollerContact.transient", TRANSIENT_METHODS, "bdf2", integration, long_run,
                                    legacy)
        method = ig.method
        t_end = check_positive("t_end", t_end, "s")
        if self.grid_spec[0] == "uniform":
            raise ValueError("transient needs a clustered grid (dense elasticity for IDA's dense Jacobian)")
        n_out = int(check_range("n_out", n_out, "-", 2, 1e6))
        if method == "bdf2":
            max_steps = check_int("max_steps", max_steps, "-", 1, 10 ** 7)
        else:
            penalty_deprecated("RollerContact.transient", lr)
        nodes = self.grid.nx * self.grid.ny
        n = nodes + 1
        need = dict(elasticity=8.0 * nodes * nodes, outputs=3 * 8.0 * n_out * n)
        need.update(jacobian=3 * 8.0 * n * n if method == "ida" else 12.0 * n * n)
        check_memory(f"this transient ({n_out} outputs on {nodes} nodes)", need,
                     "use a coarser clustered grid (dense elasticity and Jacobian grow as the nodes squared) or "
                     "lower n_out")
        film = self.film_problem(self.grid)
        s = self.scales
        w_start = self.load
        theta0 = None
        if isinstance(start, RollerSteady):
            y0 = np.array(start.state, float)
            if y0.size != film.n + 1:
                raise ValueError(f"start has {y0.size - 1} pressure nodes, this grid {film.n}")
            w_start = float(film.area_w @ y0[:-1]) * self.load
            if start.solver_info.get("method") == "fbns":
                theta0 = film.grid.interior(start.content)
        elif start == "dry":
            y0 = self.initial_guess(film)
            g = film.grid
            h = film.film(y0[:-1], 0.0).reshape(g.shape_full)
            j0, i0 = int(np.argmin(np.abs(g.y))), int(np.argmin(np.abs(g.x)))
            d = self.dry()
            w_len = self.W / (d.footprint_length / self.roller.mean_radius)
            hc = dowson_toyoda_central(self.U, self.G, w_len) * self.roller.mean_radius
            h_init = 0.5 * hc if initial_film is None else check_positive("initial_film", initial_film, "m")
            y0[-1] = h_init / s["film"] - h[j0, i0]
        else:
            raise ValueError(f"start = {start!r}: use 'dry' or a RollerSteady of this contact")
        t_ref = self.time_scale
        ratio = load_ratio(load, self.load, w_start, t_ref, ramp_time)
        if method == "bdf2":
            return self._content_transient(film, y0, theta0, ratio, t_end, n_out, max_steps, (ig, lr))
        sol, wall, rows = run_squeeze(film, s["lam"], ratio, y0, t_end, t_ref, ig.rtol, n_out,
                                      lambda f, y: self.result(f, y, True, "", 0, [], 0.0))
        return squeeze_result(RollerTransient, sol, wall, rows, ratio, t_ref, self.load, s["film"])

    def _content_transient(self, film, y0, theta0, ratio, t_end, n_out, max_steps, settings):
        """``method="bdf2"`` of :meth:`transient`: :class:`~transient.models.roller.line_step.LineFilmStep` on the
        film-content form (:class:`~transient.models.roller.roller_fbns.RollerContentFilm`) from ``y0 = [p, h0]``
        with the content ``theta0`` (None: :func:`~transient.models.roller.line_step.consistent_content`), on the
        one run driver."""
        content = RollerContentFilm(film)
        n, t_ref = content.n, self.time_scale
        if theta0 is None:
            u0 = consistent_content(content, y0[:-1], y0[-1])
        else:
            u0 = np.concatenate([y0[:-1], theta0, [y0[-1]]])
        sample, result = content_outputs(
            RollerTransient, lambda y, theta: self.result(film, y, True, "", 0, [], 0.0, content=theta), n, ratio,
            t_ref, self.load, self.scales["film"])
        key = dict(contact=contact_digest(self), nodes=[int(film.grid.nx), int(film.grid.ny)],
                   load=load_digest(ratio, t_end / t_ref, n_out))
        return run_content_transient(content, self.scales["lam"], u0, ratio, t_end / t_ref, n_out, sample, result,
                                     settings, max_steps, key, "roller contact (film content, FBNS)")

    def result(self, film: EHLFilm, u, ok, msg, iters, norms, wall, info=None, content=None) -> RollerSteady:
        s = self.scales
        g = film.grid
        rm = self.roller.mean_radius
        p, h0 = u[:-1], u[-1]
        P = g.full(p) * s["p_scale"]
        H = film.film(p, h0).reshape(g.shape_full) * s["film"]
        x, y = g.x * s["B"] * rm, g.y * s["B"] * rm
        jp, ip = np.unravel_index(int(np.argmax(P)), P.shape)
        inner = H[1:-1, 1:-1]
        jh, ih = np.unravel_index(int(np.argmin(inner)), inner.shape)
        j0, i0 = int(np.argmin(np.abs(y))), int(np.argmin(np.abs(x)))
        return RollerSteady(x=x, y=y, pressure=P, film=H, h_central=float(H[j0, i0]), h_min=float(inner[jh, ih]),
                            x_of_h_min=float(x[ih + 1]), y_of_h_min=float(y[jh + 1]), p_max=float(P[jp, ip]),
                            x_of_p_max=float(x[ip]), y_of_p_max=float(y[jp]), load_error=float(film.area_w @ p - 1.0),
                            mean_radius=rm, modulus=self.modulus, half_width=s["B"] * rm,
                            footprint_length=s["d"] * s["B"] * rm, profile_start=self.roller.profile_start,
                            success=ok, message=msg, iterations=int(iters),
                            wall_time=wall, residual_norms=list(map(float, norms)), state=np.array(u, float),
                            solver_info=info or {},
                            content=np.ones(g.shape_full) if content is None else g.full(content, boundary=1.0))
