"""EHL point contact, circular or elliptical, fully flooded or starved by a prescribed inlet layer.

Equations and scaling: :mod:`transient.models.point.ehl_problem` (mass-conserving fractional film, Fischer-Burmeister
complementarity, DC-FFT elasticity, load balance by ``h0``); steady solve:
:mod:`transient.models.point.fbns`; transient: :mod:`transient.models.point.step_solve`. SI at the API::

    pc = PointContact(radius_x=0.01, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8,
                      modulus=2.2e11, inlet_film=None)  # grid: chosen from M (point_grid.py)
    s = pc.steady()        # s.h_central, s.h_min, s.p_max, s.meniscus_x, s.pressure, s.film [SI]

``x`` is the rolling (entraining) direction, ``speed`` the mean entraining speed ``(u_a + u_b)/2``,
``modulus`` the reduced modulus ``E' = 2/((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b)``, ``inlet_film`` the
thickness [m] of the oil layer the contact meets (both surfaces together); ``None``: fully flooded.
"""

from __future__ import annotations

import math
import time
import warnings
from types import SimpleNamespace

import numpy as np

from transient.checks import check_choice, check_int, check_items, check_positive, check_range, check_vector
from transient.models.ehl.dry import edge_positions, polonsky_keer
from transient.models.ehl.errors import EHLConvergenceError
from transient.models.ehl.film_run import contact_digest, load_digest, run_film, transient_settings
from transient.models.ehl.krylov import coarsening_factor, inject
from transient.models.point.fbns import DENSE_MAX_UNKNOWNS, fbns
from transient.models.point.ehl_problem import PointFilm
from transient.models.point.grid_verdict import FORMAL_ORDER, describe, error_estimate
from transient.models.point.plausibility import default_grid_message, grid_message, implausible
from transient.models.point.point_grid import MIN_NODES_PER_B, default_grid
from transient.models.point.results import PointDry, PointSteady, PointTransient
from transient.models.point.step_solve import FilmStep, steady_by_time_steps
from transient.physics import film_formulas as hd
from transient.physics.hertz import hertz_contact
from transient.physics.lubricant import DOWSON_HIGGINSON_PARK, Lubricant
from transient.solvers.settings import Integration, LongRun

#: the Couette flux of the Reynolds rows (:func:`~transient.models.point.kernels.face_flux`): first-order upwind,
#: second-order linear upwind (the default), or second order with van Albada's limiter. Measured
#: (docs/validation.md): the second-order fluxes converge at order ~2 (M = 31 ... 518), so that their error is
#: bounded from three grids (:meth:`PointContact.grid_check`); first order converges at an observed order 0.3-0.8
#: over 65-513 nodes, non-monotonically at M >= 173, so that no grid sequence bounds its error. On coarse grids
#: at high M the second-order films are the further off (M = 518: h_c 22 % below the grid limit on 129 x 129, first
#: order 9 % above it) -- the grid verdict says so -- and Newton fails with them at M = 205 on 25 x 25 and 33 x 33
UPWIND = {"first": 0, "second": 1, "limited": 2}
#: The methods :meth:`PointContact.transient` offers: BDF2 on its FBNS step solve (the film's complementarity has
#: no residual form for the other methods).
TRANSIENT_METHODS = ("bdf2",)

#: the largest estimated relative error of h_central and h_min (:meth:`PointContact.grid_check`) for which
#: :meth:`PointContact.steady` calls its films grid-settled
GRID_SETTLED_ERROR = 0.05
#: the former name of :data:`GRID_SETTLED_ERROR`
GRID_SETTLED_CHANGE = GRID_SETTLED_ERROR


def check_fast_path(nx, ny):
    """Refuse a grid whose Newton steps would take the dense LU of the reduced system above its size: the iterative
    solver (:class:`~transient.models.ehl.krylov.KrylovSolver`) needs a grid that coarsens by a power of two
    (``nx - 1`` and ``(ny - 1)/2`` divisible by it) to at most
    :data:`~transient.models.ehl.krylov.COARSE_MAX_UNKNOWNS` unknowns; otherwise every Newton step is an
    O(N^3) dense LU of (N + 1)^2 numbers. The message names the nearest grids that do coarsen."""
    grid = SimpleNamespace(nx=nx, m=(ny + 1) // 2)
    n = (grid.m - 1) * (nx - 2)  # nodal unknowns of the half grid (PointFilm.n)
    if n <= DENSE_MAX_UNKNOWNS or coarsening_factor(grid) > 1:
        return
    nearest = _coarsening_grid(nx, ny)
    raise ValueError(f"grid = ({nx}, {ny}) nodes does not coarsen by a power of two (nx - 1 = {nx - 1} and (ny - 1)/2 "
                     f"= {(ny - 1) // 2} must share one), so its {n} unknowns would take a dense LU of "
                     f"{8 * (n + 1) ** 2 / 1e9:.3g} GB and O(N^3) work per Newton step; allowed: a grid that coarsens "
                     f"(nodes 2^k j + 1), e.g. grid = {nearest} (or at most {DENSE_MAX_UNKNOWNS} unknowns)")


def _coarsening_grid(nx, ny):
    """The grid of fewest extra nodes at or above (nx, ny) that :func:`check_fast_path` accepts."""
    for k in range(1, 12):
        f = 2 ** k
        gx = -(-(nx - 1) // f) * f + 1
        gm = -(-((ny + 1) // 2 - 1) // f) * f + 1
        if coarsening_factor(SimpleNamespace(nx=gx, m=gm)) > 1:
            return gx, 2 * gm - 1
    return (2 ** 7 + 1, 2 ** 7 + 1)


class PointContact:
    """Steady and transient EHL point contact (module docstring).

    Parameters (SI): ``radius_x`` Rx [m] (reduced radius along the rolling direction), ``radius_y`` Ry [m]
    (>= Rx; None: circular), ``load`` [N], ``speed`` [m/s], ``viscosity`` eta0 [Pa s],
    ``pressure_viscosity`` alpha [1/Pa], ``modulus`` E' [Pa], ``density`` ``"dowson-higginson"`` or
    ``"incompressible"``, ``viscosity_law`` ``"barus"`` or ``"roelands"``, ``inlet_film`` [m] or None,
    ``grid`` (nx, ny) nodes (boundary included, ny odd; default None: the fewest 2^k + 1 per axis, at least 65,
    at which the second-order film's error bound is about 4 % or less, chosen from M:
    :func:`~transient.models.point.point_grid.default_grid`), ``upwind`` the Couette flux (:data:`UPWIND`:
    ``"second"`` (default), ``"limited"``, ``"first"``), ``domain`` (x_in, x_out, y_half) in units of b
    (default (-4.5, 1.5, 1 + 1.5 k), the inlet moved upstream of Hamrock-Dowson's critical meniscus when that
    lies further out), ``dh_constants`` Dowson-Higginson's (c1, c2) [1/Pa].
    """

    def __init__(self, radius_x, radius_y=None, *, load, speed, viscosity, pressure_viscosity, modulus,
                 density: str = "dowson-higginson", viscosity_law: str = "barus", inlet_film=None,
                 grid=None, domain=None, dh_constants=DOWSON_HIGGINSON_PARK, upwind: str = "second"):
        check_choice("upwind", upwind, tuple(UPWIND))
        self.upwind = upwind
        self.radius_x = check_range("radius_x", radius_x, "m", 1e-5, 10.0)
        ry = self.radius_x if radius_y is None else radius_y
        self.radius_y = check_range("radius_y", ry, "m", self.radius_x, 1e4,
                                    why=f"(at least radius_x = {self.radius_x:g} m: x is the rolling direction "
                                        "with the smaller radius)")
        self.load = check_range("load", load, "N", 0.0, 1e8, low_open=True)
        self.speed = check_range("speed", speed, "m/s", 1e-9, 1e3, why="(1 nm/s to 1 km/s)")
        self.modulus = check_range("modulus", modulus, "Pa", 1e6, 1e14)
        check_choice("viscosity_law", viscosity_law, ("barus", "roelands"))
        check_choice("density", density, ("dowson-higginson", "incompressible"))
        self.lubricant = Lubricant(viscosity=check_positive("viscosity", viscosity, "Pa s"),
                                   pressure_viscosity=pressure_viscosity, viscosity_law=viscosity_law,
                                   density=density, dh_constants=check_vector("dh_constants", dh_constants, "1/Pa", 2,
                                                                              why="(Dowson-Higginson's c1, c2)"))
        self.hertz = hertz_contact(self.load, self.radius_x, self.radius_y, self.modulus)
        c = self.hertz
        self.U, self.G, self.W = hd.dimensionless_groups(viscosity, self.speed, pressure_viscosity, self.load,
                                                         self.modulus, self.radius_x)
        #: Hamrock-Dowson's fully flooded films [m] and critical meniscus (central film)
        self.hd_central = hd.central_film_flooded(self.U, self.G, self.W, c.k) * self.radius_x
        self.hd_minimum = hd.minimum_film_flooded(self.U, self.G, self.W, c.k) * self.radius_x
        self.m_c = hd.critical_meniscus_central(self.hd_central / self.radius_x, self.radius_x, c.b)
        if inlet_film is not None:
            check_range("inlet_film", inlet_film, "m", 0.05 * self.hd_central, 1.0,
                        why=f"(at least 5 % of the flooded central film {self.hd_central:.3g} m (Hamrock-Dowson): "
                            "a thinner layer cannot carry the load as a film)")
        self.inlet_film = inlet_film
        if domain is None:
            domain = (-max(4.5, 1.25 * self.m_c), 1.5, 1.0 + 1.5 * c.k)
            if not domain[0] >= -1e4:
                raise ValueError(f"the default domain's inlet, 1.25 x Hamrock-Dowson's critical meniscus = "
                                 f"{-domain[0]:.3g} b upstream, is out of range; allowed: at most 1e4 b (set by load = "
                                 f"{self.load!r} N, speed = {self.speed!r} m/s, viscosity = {viscosity!r} Pa s, "
                                 f"pressure_viscosity = {pressure_viscosity!r} 1/Pa, radius_x = {self.radius_x!r} m, "
                                 f"modulus = {self.modulus!r} Pa: check their units)")
        domain = check_vector("domain", domain, "b", 3, why="(x_in, x_out, y_half)")
        x_in = check_range("domain[0] (inlet)", domain[0], "b", -1e4, -1.5)
        x_out = check_range("domain[1] (outlet)", domain[1], "b", 1.2, 1e4)
        y_half = check_range("domain[2] (half width)", domain[2], "b", 1.2 * c.k, 1e4,
                             why=f"(beyond the Hertz semi-axis a = {c.k:.3g} b)")
        self.domain = (x_in, x_out, y_half)
        if grid is None:
            grid = default_grid(self.moes[0], self.domain)
            found = implausible(self.radius_x, viscosity, self.speed, self.load, c.p_max)
            if found:
                raise ValueError(default_grid_message(grid, -x_in, found))
        nx, ny = check_items("grid", grid, "(nx, ny) node counts", 2)
        nx = check_int("grid[0]", nx, "nodes", 17, 2049)
        ny = check_int("grid[1]", ny, "nodes", 17, 2049)
        if ny % 2 == 0:
            raise ValueError(f"grid[1] = {ny} nodes must be odd (a node row on the symmetry line y = 0)")
        dx = (x_out - x_in) / (nx - 1)
        i0 = round(-x_in / dx)
        self.x_nodes = (np.arange(nx) - i0) * dx  # a node at x = 0 (the film's centre)
        self.y_nodes = np.linspace(-y_half, y_half, ny)
        per_b = 1.0 / dx
        if per_b < MIN_NODES_PER_B or c.k / (self.y_nodes[1] - self.y_nodes[0]) < MIN_NODES_PER_B:
            found = implausible(self.radius_x, viscosity, self.speed, self.load, c.p_max)
            raise ValueError(grid_message(grid, per_b, c.k / (self.y_nodes[1] - self.y_nodes[0]), MIN_NODES_PER_B,
                                          -x_in, found))
        check_fast_path(nx, ny)
        self.grid = (nx, ny)

    # -- scales ------------------------------------------------------------------------------------------
    @property
    def b(self) -> float:
        """Hertz semi-axis along the rolling direction [m]."""
        return self.hertz.b

    @property
    def film_scale(self) -> float:
        """Film unit ``b^2/Rx`` [m]."""
        return self.hertz.b ** 2 / self.radius_x

    @property
    def lam(self) -> float:
        """``12 eta0 u Rx^2 / (b^3 p_h)``."""
        c = self.hertz
        return 12.0 * self.lubricant.viscosity * self.speed * self.radius_x ** 2 / (c.b ** 3 * c.p_max)

    @property
    def moes(self) -> tuple[float, float]:
        """Moes' point-contact groups ``(M, L)`` = ``(W (2U)^-3/4, G (2U)^1/4)`` (Rx as the radius)."""
        return self.W * (2.0 * self.U) ** -0.75, self.G * (2.0 * self.U) ** 0.25

    def film_problem(self, inlet_film="same") -> PointFilm:
        """The scaled discrete problem (:class:`~transient.models.point.ehl_problem.PointFilm`)."""
        c = self.hertz
        h_in = self.inlet_film if inlet_film == "same" else inlet_film
        h_oil = math.inf if h_in is None else h_in / self.film_scale
        return PointFilm(self.x_nodes, self.y_nodes, self.radius_x / self.radius_y, self.lam,
                         2.0 * c.p_max * self.radius_x / (math.pi * self.modulus * c.b), c.p_max,
                         self.lubricant.kernel_args(), h_oil, 2.0 * math.pi * c.k / 3.0, UPWIND[self.upwind])

    def hertz_start(self, film: PointFilm) -> np.ndarray:
        """The dry Hertz pressure, ``h0`` putting the central film at Hamrock-Dowson's, full content (starved:
        the content ``H_oil/H`` upstream of the Hertz zone, where the layer does not fill the gap)."""
        k = self.hertz.k
        yy, xx = np.meshgrid(film.y, film.x, indexing="ij")
        P = np.sqrt(np.clip(1.0 - xx ** 2 - (yy / k) ** 2, 0.0, None))
        u = np.concatenate([P.ravel()[film.flat], np.ones(film.n), [0.0]])
        H = film.film(P, 0.0)
        u[-1] = self.hd_central / self.film_scale - H[0, np.argmin(np.abs(film.x))]
        if math.isfinite(film.h_oil):  # starved: the layer carried at constant flux up to where it fills the gap
            H = (H + u[-1]).ravel()[film.flat]
            thin = (film.x[film.i] < 0.0) & (H > film.h_oil) & (u[: film.n] == 0.0)
            u[film.n: 2 * film.n][thin] = film.h_oil / H[thin]
        return u

    # -- dry ---------------------------------------------------------------------------------------------
    def dry(self, tol: float = 1e-12) -> PointDry:
        """Dry contact on the EHL grid by Polonsky & Keer's conjugate gradient on the same DC-FFT
        coefficients (:func:`transient.models.ehl.dry.polonsky_keer`): the zero-speed limit, checked
        against Hertz. Semi-axes between nodes from ``p^2`` extrapolated linearly."""
        t0 = time.perf_counter()
        f = self.film_problem(inlet_film=None)
        yy, xx = np.meshgrid(f.y_full, f.x, indexing="ij")
        g0 = 0.5 * xx ** 2 + 0.5 * (self.radius_x / self.radius_y) * yy ** 2
        P, _, it, ok = polonsky_keer(g0, f.conv, f.dx * f.dy, f.load, tol=tol)
        c = self.hertz
        jc, ic = f.y_full.size // 2, int(np.argmin(np.abs(f.x)))
        ex, ey = edge_positions(f.x, P[jc]), edge_positions(f.y_full, P[:, ic])
        return PointDry(x=f.x * c.b, y=f.y_full * c.b, pressure=P * c.p_max, p_max=float(P.max() * c.p_max),
                        half_width_x=0.5 * (ex[1] - ex[0]) * c.b, half_width_y=0.5 * (ey[1] - ey[0]) * c.b,
                        hertz_pressure=c.p_max, hertz_b=c.b, hertz_a=c.a, success=bool(ok), iterations=it,
                        message="converged" if ok else "Polonsky-Keer CG did not converge",
                        wall_time=time.perf_counter() - t0)

    # -- steady ------------------------------------------------------------------------------------------
    def layer_start(self, film: PointFilm, initial: PointSteady) -> np.ndarray:
        """Start for this contact's inlet layer from ``initial``, a solution for another layer on the same grid
        (continuation in the layer). Upstream of the meniscus the flux is the layer's, carried at zero pressure
        (``theta H = H_oil``): a starved start scales the content there by the ratio of the layers; a flooded
        start gets zero pressure and the content ``H_oil/H`` wherever upstream of the centre the gap is thicker
        than the layer, or, for a layer thinner than its central film (the meniscus then near the Hertz zone,
        where the flooded pressure is far from the starved one), :meth:`hertz_start`."""
        u = np.array(initial.state, float)
        h_old = initial.inlet_film / self.film_scale
        if not math.isfinite(film.h_oil) or h_old == film.h_oil:
            return u
        n = film.n
        upstream = film.x[film.i] < 0.0
        if math.isfinite(h_old):
            starved = upstream & (u[n: 2 * n] < 1.0)
            u[n: 2 * n][starved] = np.minimum(u[n: 2 * n][starved] * film.h_oil / h_old, 1.0)
            return u
        if film.h_oil < initial.h_central / self.film_scale:
            return self.hertz_start(film)
        P, _, h0 = film.split(u)
        H = film.film(P, h0).ravel()[film.flat]
        dry = upstream & (H > film.h_oil)
        u[:n][dry] = 0.0
        u[n: 2 * n][dry] = film.h_oil / H[dry]
        return u

    def steady(self, initial=None, tol: float = 1e-8, max_iter: int = 150, raise_on_failure: bool = True,
               check_grid: bool | None = None) -> PointSteady:
        """Steady film by FBNS Newton from the dry Hertz pressure (or ``initial``: a :class:`PointSteady`
        of the same grid, for this or another inlet layer: :meth:`layer_start`); when Newton fails from there
        (starved inlets), by pseudo-transient continuation
        (:func:`~transient.models.point.step_solve.steady_by_time_steps`) from the same start; when both fail from
        ``initial``, both again from the Hertz start. Raises
        :class:`EHLConvergenceError` (``raise_on_failure``) with the last iterate flagged ``success=False``; for
        a starved inlet whose film collapses (``h_min`` below 1 % of ``h_central``: the layer is thinner than
        the contact carries on this grid) the message names ``inlet_film``.

        ``check_grid`` (default: for a solve from the Hertz start, ``initial`` None; continuation in a parameter
        from ``initial`` is not checked again): the converged films are solved again on every second and every
        fourth node (:meth:`grid_check`); the result's ``grid_change`` holds the coarse grids' ``h_central`` and
        ``h_min`` and the error each film's estimate bounds, ``grid_settled`` whether both errors are at most
        :data:`GRID_SETTLED_ERROR`; when not, a ``UserWarning`` names the grid and the next finer one."""
        check_range("tol", tol, "-", 1e-14, 1e-2)
        max_iter = check_int("max_iter", max_iter, "-", 1, 10000)
        t0 = time.perf_counter()
        film = self.film_problem()
        starts = [self.hertz_start(film)]
        if initial is not None:
            if np.size(initial.state) != 2 * film.n + 1:
                raise ValueError(f"initial: a state of {np.size(initial.state)} unknowns; this grid has {2 * film.n + 1}")
            starts.insert(0, self.layer_start(film, initial))
        for k, u0 in enumerate(starts):
            u, ok, norms = fbns(film, u0, tol, max_iter)
            info = dict(newton=len(norms) - 1, start="initial" if k < len(starts) - 1 else "hertz")
            if not ok:  # pseudo-transient continuation: the physical transient until nearly steady
                u, ok, norms, counts = steady_by_time_steps(film, u0, tol)
                info.update(time_steps=counts)
            if ok:
                break
        res = self._result(film, u, ok, norms, time.perf_counter() - t0, info)
        if not ok and raise_on_failure:
            raise EHLConvergenceError(self.failure_message(res), res)
        if check_grid is None:
            check_grid = initial is None
        if ok and check_grid:
            res.grid_change = self.grid_check(film, res, tol, max_iter)
            res.grid_settled = bool(res.grid_change.get("settled", False))
            if not res.grid_settled:
                warnings.warn(res.grid_change["note"], UserWarning, stacklevel=2)
            res.wall_time = time.perf_counter() - t0
        return res

    def grid_check(self, film: PointFilm, res: PointSteady, tol: float = 1e-8, max_iter: int = 150) -> dict:
        """The error of ``res``'s films bounded from the same problem on every second and every fourth node (Newton
        from the converged state injected there, else from the Hertz pressure; the same Couette flux):
        :func:`~transient.models.point.grid_verdict.error_estimate` per film, Richardson's estimate at the observed
        order (at most the scheme's), at the scheme's order where only two grids are available, unbounded where the
        three films do not converge monotonically at order >= 0.5. Returns ``{"coarse_grid", "h_central_coarse",
        "h_min_coarse", "change_h_central", "change_h_min", "quarter_grid", "h_central_quarter", "h_min_quarter",
        "error_h_central", "error_h_min", "basis_h_central", "basis_h_min", "settled", "note"}``; ``settled`` when
        both errors are at most :data:`GRID_SETTLED_ERROR`; ``note`` says "settled (error <= x %)" or "not
        settled" with the reason and the next finer grid. Unmeasured (``settled`` False, said in ``note``) when
        the grid does not halve or Newton fails on every second node."""
        nx, ny = self.grid
        if (film.nx - 1) % 2 or (film.m - 1) % 2:
            return dict(settled=False, note=f"point contact: grid {nx} x {ny} is not grid-checked (nx - 1 and "
                                            f"(ny - 1)/2 must be even to halve it)")
        coarse = film.coarsened(2)
        uc, ok, _ = fbns(coarse, inject(film, coarse, 2, res.state), tol, max_iter)
        if not ok:
            uc, ok, _ = fbns(coarse, self.hertz_start(coarse), tol, max_iter)
        cgrid = ((nx + 1) // 2, (ny + 1) // 2)
        if not ok:
            return dict(coarse_grid=cgrid, settled=False,
                        note=f"point contact: grid {nx} x {ny} NOT grid-checked (Newton failed on every second "
                             f"node, {cgrid[0]} x {cgrid[1]}): refine to check h_min")
        hc, hm = self._films(coarse, uc)
        out = dict(coarse_grid=cgrid, h_central_coarse=hc, h_min_coarse=hm,
                   change_h_central=abs(res.h_central - hc) / res.h_central, change_h_min=abs(res.h_min - hm) / res.h_min)
        quarter = None
        if (film.nx - 1) % 4 == 0 and (film.m - 1) % 4 == 0 and film.nx >= 33 and film.m >= 17:
            q = film.coarsened(4)
            uq, ok_q, _ = fbns(q, inject(coarse, q, 2, uc), tol, max_iter)
            if not ok_q:
                uq, ok_q, _ = fbns(q, self.hertz_start(q), tol, max_iter)
            if ok_q:
                quarter = self._films(q, uq)
                out.update(quarter_grid=((nx + 3) // 4, (ny + 3) // 4), h_central_quarter=quarter[0],
                           h_min_quarter=quarter[1])
        order = FORMAL_ORDER[self.upwind]
        for key, fine, half, k in (("h_central", res.h_central, hc, 0), ("h_min", res.h_min, hm, 1)):
            out[f"error_{key}"], out[f"basis_{key}"] = error_estimate(fine, half, None if quarter is None else
                                                                      quarter[k], order)
        worst = max(out["error_h_central"], out["error_h_min"])
        out["settled"] = settled = worst <= GRID_SETTLED_ERROR
        grids = f"{cgrid[0]} x {cgrid[1]}" + ("" if quarter is None else " and {} x {}".format(*out["quarter_grid"]))
        errors = (f"h_central {describe(out['error_h_central'], out['basis_h_central'])}, "
                  f"h_min {describe(out['error_h_min'], out['basis_h_min'])} (from {grids})")
        if settled:
            out["note"] = f"point contact: grid {nx} x {ny} settled (error <= {worst:.1%}): {errors}"
        else:
            out["note"] = (f"point contact: h_min = {res.h_min:.4g} m not settled on {nx} x {ny} nodes (dx = "
                           f"{film.dx:.3g} b): {errors}; allowed: {GRID_SETTLED_ERROR:.0%}; refine (grid = "
                           f"{(2 * nx - 1, 2 * ny - 1)}) or take a smaller domain around the contact with the same "
                           f"nodes, and check again")
        return out

    def _films(self, film: PointFilm, u) -> tuple[float, float]:
        """``(h_central, h_min)`` [m] of the state ``u`` of ``film``."""
        P, _, h0 = film.split(u)
        H = film.film(P, h0) * self.film_scale
        return float(H[0, int(np.argmin(np.abs(film.x)))]), float(H.min())

    def failure_message(self, res: PointSteady) -> str:
        """Why ``res`` did not converge, in one line: the residual history, and for a starved inlet whose film
        collapsed (``h_min < 0.01 h_central``) the inlet layer named with the grid's spacing."""
        norms = res.residual_norms
        msg = (f"point contact: Newton did not converge (residual {norms[-1]:.3g} after {len(norms) - 1} "
               f"iterations; history {[f'{v:.2g}' for v in norms]})")
        if self.inlet_film is not None and res.h_min < 0.01 * res.h_central:
            dx = self.x_nodes[1] - self.x_nodes[0]
            msg = (f"inlet_film = {self.inlet_film:.4g} m is thinner than this contact carries on a grid of "
                   f"{self.grid[0]} x {self.grid[1]} nodes (dx = {dx:.3g} b): the film collapses to "
                   f"{res.h_min:.3g} m at x = {res.x_of_h_min / self.b:.3g} b, y = {res.y_of_h_min / self.b:.3g} b; "
                   f"allowed: a thicker layer or a finer grid. ") + msg
        return msg

    # -- transient ---------------------------------------------------------------------------------------
    @property
    def time_scale(self) -> float:
        """``b/u`` [s], the unit of the scaled time."""
        return self.hertz.b / self.speed

    def transient(self, t_end: float, load=None, start="dry", *, n_out: int = 201, max_steps: int = 5000,
                  integration: Integration | None = None, long_run: LongRun | None = None,
                  **legacy) -> PointTransient:
        """The film in time: BDF2 with FBNS Newton per step (:mod:`transient.models.point.step_solve`) on the one
        run driver (:mod:`transient.models.ehl.film_run`).

        ``t_end`` [s]; ``load`` [N]: a number or a function of ``t`` [s] (default: the contact's load);
        ``start``: ``"dry"`` (the dry Hertz pressure with the film lifted to Hamrock-Dowson's central film,
        the content full, or for a starved inlet the layer where it does not fill the gap) or a
        :class:`PointSteady` / :class:`PointTransient` of this contact's grid (its final film; the time starts at
        0 again); ``n_out`` outputs equally spaced on [0, t_end]; ``max_steps`` the most steps of the run.
        ``integration`` (:class:`~transient.solvers.settings.Integration`): ``method`` one of
        :data:`TRANSIENT_METHODS` (the film is a complementarity problem, solved by the FBNS step solve it hands
        BDF2), ``rtol`` the relative local error per step (default 1e-4), ``atol`` on the scaled states (default
        1e-2 rtol); ``long_run`` (:class:`~transient.solvers.settings.LongRun`): checkpoint and resume, progress
        bar, ``stop``, ``time_budget`` [s of wall clock]. The loose keywords ``rtol=``, ``method=``,
        ``time_budget=`` of earlier releases are deprecated. Series at the outputs; the final fields and state
        (``start=`` of a next run)."""
        ig, lr = transient_settings("PointContact.transient", TRANSIENT_METHODS, "bdf2", integration, long_run,
                                    legacy)
        t_end = check_range("t_end", t_end, "s", 0.0, 1e6, low_open=True)
        max_steps = check_int("max_steps", max_steps, "-", 1, 10 ** 7)
        n_out = check_int("n_out", n_out, "-", 2, 10 ** 7)
        if load is None:
            load = self.load
        if callable(load):
            f_load = load
            check_range("load(0)", float(f_load(0.0)), "N", 0.0, 1e8, low_open=True)
        else:
            value = check_range("load", load, "N", 0.0, 1e8, low_open=True)
            f_load = lambda t: value
        film = self.film_problem()
        if isinstance(start, str):
            check_choice("start", start, ("dry",))
            u0 = self.hertz_start(film)
        else:
            u0 = np.asarray(start.final_state if isinstance(start, PointTransient) else start.state, float)
            if u0.size != 2 * film.n + 1:
                raise ValueError(f"start: a state of {u0.size} unknowns; this grid has {2 * film.n + 1}")
        ts = self.time_scale
        ratio = lambda T: float(f_load(T * ts)) / self.load
        c, hs = self.hertz, self.film_scale
        jc, ic = 0, int(np.argmin(np.abs(film.x)))
        tau_end = t_end / ts

        def sample(T, u):
            P, _, h0 = film.split(u)
            H = film.film(P, h0)
            return dict(h_central=H[jc, ic] * hs, h_min=H.min() * hs, p_max=P.max() * c.p_max, h0=h0 * hs,
                        load=ratio(T) * self.load)

        def result(a, u, stats, message):
            P, Th, h0 = film.split(u)
            H = film.film(P, h0)
            return PointTransient(t=a["t"] * ts, h_central=a["h_central"], h_min=a["h_min"], p_max=a["p_max"],
                                  h0=a["h0"], load=a["load"], x=film.x * c.b, y=film.y_full * c.b,
                                  pressure=film.full(P) * c.p_max, film=film.full(H) * hs, theta=film.full(Th),
                                  wall_time=stats.wall_time, stats=stats, final_state=np.array(u),
                                  final_time=float(a["t"][-1]) * ts if len(a["t"]) else 0.0, success=True,
                                  message=message or "completed")

        return run_film("point contact (FBNS)", lambda u, T: FilmStep(film, u, ratio, t0=T), u0, tau_end, n_out,
                        sample, ("h_central", "h_min", "p_max", "h0", "load"), result, ig, lr, max_steps,
                        dict(contact=contact_digest(self), grid=list(self.grid),
                             load=load_digest(ratio, tau_end, n_out)))

    def _result(self, film: PointFilm, u, ok, norms, wall, info) -> PointSteady:
        P, T, h0 = film.split(u)
        H = film.film(P, h0)
        Pf, Tf, Hf = film.full(P), film.full(T), film.full(H)
        c, hs = self.hertz, self.film_scale
        x, y = film.x * c.b, film.y_full * c.b
        jc, ic = y.size // 2, int(np.argmin(np.abs(film.x)))
        jm, im = np.unravel_index(np.argmin(Hf), Hf.shape)
        meniscus, flooded = self._meniscus(film, T[0], H[0])
        e = film.equations(u)
        q_unit = self.speed * hs * c.b  # scaled flow rate -> m^3/s
        flows = {k: v * q_unit for k, v in film.flow_balance(e).items()}
        return PointSteady(x=x, y=y, pressure=Pf * c.p_max, film=Hf * hs, theta=Tf, h_central=float(Hf[jc, ic] * hs),
                           h_min=float(Hf[jm, im] * hs), x_of_h_min=float(x[im]), y_of_h_min=float(abs(y[jm])),
                           p_max=float(Pf.max() * c.p_max), meniscus_x=meniscus * c.b, flooded_inlet=flooded,
                           inlet_film=math.inf if self.inlet_film is None else float(self.inlet_film),
                           load_error=float(e["load"]), radius_x=self.radius_x, b=c.b, hertz_pressure=c.p_max,
                           inlet_flux=flows["inlet"], outlet_flux=flows["outlet"], side_flux=flows["sides"], wall_time=wall, state=np.asarray(u),
                           solver_info=info, success=bool(ok), iterations=len(norms) - 1,
                           residual_norms=[float(v) for v in norms],
                           message="converged" if ok else f"not converged: residual {norms[-1]:.3g}")

    @staticmethod
    def _meniscus(film: PointFilm, theta, h):
        """Inlet meniscus on the centreline [units of b]: where the content reaches 1, extrapolated from the
        two nodes upstream; the domain's inlet (and ``flooded=True``) when the first node is full."""
        x = film.x
        full = np.nonzero(theta[1:-1] >= 1.0 - 1e-9)[0]
        if full.size == 0:
            return float(x[-1]), False
        i = int(full[0]) + 1
        if i <= 1:
            return float(x[0]), True
        t1, t0 = theta[i - 1], theta[i - 2] if i >= 3 else film.h_oil / h[0]
        slope = (t1 - t0) / film.dx
        xm = x[i - 1] + (1.0 - t1) / slope if slope > 0 else x[i - 1]
        return float(min(max(xm, x[i - 1]), x[i])), False
