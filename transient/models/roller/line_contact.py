"""Steady EHL of an infinitely long line contact: the 1-D limit of the roller model (Park).

A cylinder of reduced radius ``R`` on a plane, load ``w`` per unit length, mean entrainment speed
``u``, lubricant ``eta(p)``, ``rho(p)`` (:mod:`transient.physics.lubricant`). Reynolds with the exit
condition, load balance and the plane-strain elastic film (Johnson eq. 2.25b)::

    d/dx(rho h^3/(12 eta) dp/dx) = u d(rho h)/dx,   p(x_in) = 0,  p = dp/dx = 0 at the free exit
    h = h0 + x^2/(2R) - 4/(pi E') int p(s) ln|x - s| ds,           int p dx = w

Scaled by the Hertz half-width ``b`` and pressure ``p_h`` (:func:`transient.physics.line_formulas.hertz_line`):
``x = b X``, ``p = p_h P``, ``h = (b^2/R) H``; then ``H = H0 + X^2/2 - (1/pi) int P ln|X - S| dS``,
``int P dX = pi/2`` and the Reynolds equation has the wedge coefficient ``lam = 12 eta0 u R^2/(b^3 p_h)``.
Domain ``X in [domain[0], domain[1]]`` and grid by default from the contact's regime
(:mod:`transient.models.roller.line_grid`: the paper's -5 ... 2.5 where the contact is elastic, longer where the
rigid inlet wedge ``sqrt(2 R h_c)`` is; clustered nodes from M = 10, else uniform at the resolving spacing);
finite volumes with second-order upwind wedge flux, the complementarity form of the exit condition solved
inside Newton (:mod:`transient.models.ehl.rows`, :mod:`transient.models.roller.kernels`).
``elastic=False`` gives the rigid cylinder (Martin's limit).
"""

from __future__ import annotations

import math
import time
import warnings

import numpy as np

from transient.checks import check_int, check_positive, check_range
from transient.models.ehl.dry import edge_positions, polonsky_keer
from transient.models.ehl.film_run import contact_digest, load_digest, penalty_deprecated, transient_settings
from transient.models.roller.continuation import PathResult, follow
from transient.models.roller.ehl_problem import EHLFilm, interpolate_state, solve_steady
from transient.models.roller.grid import TensorGrid
from transient.models.roller.line_fft import LineFFTFilm, matrix_free
from transient.models.roller.line_fbns import LineContentFilm
from transient.models.roller.line_grid import (ELASTIC_INLET_WARN, INLET_RESOLUTION, RIGID_INLET_WARN, RIGID_WARN,
                                               default_domain, default_grid, hydrodynamic_length, resolving_spacing,
                                               rigid_regime, uniform_nodes)
from transient.models.roller.line_sequence import inlet_spacing, solve_sequence
from transient.models.roller.line_step import consistent_content, run_content_transient
from transient.models.roller.results import EHLConvergenceError, LineDry, LineSteady, LineTransient
from transient.models.roller.transient import load_ratio, run_squeeze
from transient.models.roller.transient_results import content_outputs, squeeze_result
from transient.physics.elasticity import line_influence
from transient.physics.line_formulas import (dowson_toyoda_central, hertz_line, line_groups, martin_min, moes_central,
                                             moes_groups)
from transient.physics.lubricant import DOWSON_HIGGINSON_PARK, Lubricant
from transient.solvers.newton import NewtonError
from transient.solvers.settings import Integration, LongRun

SCHEMES = ("upwind2", "upwind1")
#: The methods :meth:`LineContact.transient` offers: IDA on the penalty form, BDF2 on the film content (its step solve).
TRANSIENT_METHODS = ("ida", "bdf2")
#: the corner of the Moes chart solved directly from the Hertz pressure; beyond it, continuation from it
M_EASY, L_EASY = 10.0, 5.0
#: Newton iterations allowed per continuation step (a step needing more is too long: it is halved)
PATH_MAX_ITER = 25


class FilmResolutionWarning(UserWarning):
    """A converged film on a grid too coarse at the inlet edge for its load (or, in the rigid regime, for the
    inlet wedge): the discrete equations are solved, but the film is not that of the continuous problem to ~1 %
    (:data:`~transient.models.roller.line_grid.INLET_RESOLUTION`, :data:`~transient.models.roller.line_grid.RIGID_WARN`)."""


class StarvedInletWarning(UserWarning):
    """A domain whose inlet lies within a few hydrodynamic lengths ``sqrt(2 R h_c)`` of the contact: the film is
    that of a contact fed from there, thinner than the fully flooded one
    (:mod:`transient.models.roller.line_grid`)."""


class _DenseOperator:
    """``apply(p)``: a dense influence matrix acting on a (1, n) pressure row (for the dry solver)."""

    def __init__(self, K):
        self.K = K

    def apply(self, p):
        return (self.K @ p.ravel()).reshape(p.shape)


def film_extrema(x, h):
    """Minimum of a nodal film refined by the parabola through the lowest node and its neighbours:
    ``(h_min, x_of_h_min)``."""
    k = int(np.argmin(h))
    if 0 < k < h.size - 1:
        x0, x1, x2 = x[k - 1], x[k], x[k + 1]
        y0, y1, y2 = h[k - 1], h[k], h[k + 1]
        d01, d12, d02 = x1 - x0, x2 - x1, x2 - x0
        a = ((y2 - y1) / d12 - (y1 - y0) / d01) / d02
        bcoef = (y1 - y0) / d01 - a * (x0 + x1)
        if a > 0:
            xm = -bcoef / (2 * a)
            if x0 <= xm <= x2:
                return float(y1 + a * (xm - x1) ** 2 + (2 * a * x1 + bcoef) * (xm - x1)), float(xm)
    return float(h[k]), float(x[k])


class LineContact:
    """Steady EHL line contact, SI at the API (module docstring).

    Parameters: ``radius`` R [m] (reduced), ``load_per_length`` w [N/m], ``speed`` u [m/s] (mean
    entrainment), ``viscosity`` eta0 [Pa s], ``pressure_viscosity`` alpha [1/Pa], ``modulus`` E' [Pa];
    ``density`` ``"dowson-higginson"`` (the paper's constants 0.58, 1.68 /GPa unless ``dh_constants``)
    or ``"incompressible"``; ``viscosity_law`` ``"barus"``, ``"roelands"`` or ``"isoviscous"``;
    ``grid``: None (default: the grid that resolves this contact's film, :func:`~transient.models.roller.line_grid.default_grid`:
    clustered nodes for an elastic contact from M = 10, else uniform), a number of nodes (uniform, boundary nodes
    included), the node positions in units of b, or ``"resolved"``: uniform, at least 401 nodes and
    :meth:`resolving_nodes` (uniform grids above 1025 nodes are solved with DC-FFT elasticity,
    :mod:`transient.models.roller.line_fft`); ``domain`` (inlet, outlet) in units of b (None: fully flooded for the
    regime, :func:`~transient.models.roller.line_grid.default_domain`); ``scheme`` ``"upwind2"`` or ``"upwind1"``;
    ``elastic=False`` for a rigid cylinder.
    """

    def __init__(self, radius, load_per_length, speed, viscosity, pressure_viscosity, modulus,
                 density: str = "dowson-higginson", viscosity_law: str = "barus", grid=None, domain=None,
                 scheme: str = "upwind2", elastic: bool = True, dh_constants=DOWSON_HIGGINSON_PARK):
        self.radius = check_range("radius", radius, "m", 1e-5, 10.0)
        self.load_per_length = check_range("load_per_length", load_per_length, "N/m", 1e-3, 1e10)
        self.speed = check_range("speed", speed, "m/s", 1e-9, 1e3, why="(1 nm/s to 1 km/s)")
        self.modulus = check_range("modulus", modulus, "Pa", 1e6, 1e18,
                                    why="(1 MPa to 1e18 Pa: above ~1e14 Pa the body is rigid, the Martin limit)")
        self.lubricant = Lubricant(viscosity=check_positive("viscosity", viscosity, "Pa s"),
                                 pressure_viscosity=pressure_viscosity, viscosity_law=viscosity_law,
                                 density=density, dh_constants=tuple(dh_constants))
        if scheme not in SCHEMES:
            raise ValueError(f"scheme = {scheme!r} is not one of {SCHEMES}")
        self.scheme = scheme
        self.elastic = bool(elastic)
        self.b, self.p_h = hertz_line(self.load_per_length, self.radius, self.modulus)
        self.U, self.G, self.W = line_groups(self.lubricant.viscosity, self.speed, self.lubricant.pressure_viscosity,
                                             self.load_per_length, self.modulus, self.radius)
        self.M, self.L = moes_groups(self.U, self.G, self.W)
        self.explicit_domain = domain is not None
        if domain is None:
            domain = default_domain(self.M, self.L, self.elastic)
            if domain[0] < -1e5:
                raise ValueError(f"the default domain's inlet, {-domain[0]:.3g} b upstream (26 hydrodynamic lengths "
                                 f"sqrt(2 R h_c) at M = {self.M:.3g}), is out of range; allowed: at most 1e5 b: the "
                                 "load is too light for its modulus (check load_per_length, speed, viscosity and "
                                 "modulus and their units)")
        lo = check_range("domain[0] (inlet)", domain[0], "b", -1e5, -1.0)
        hi = check_range("domain[1] (outlet)", domain[1], "b", 1.0, 1e5)
        self.domain = (lo, hi)
        if grid is None:
            grid = default_grid(self.M, self.L, self.elastic, self.domain)
        elif isinstance(grid, str):
            if grid != "resolved":
                raise ValueError(f"grid = {grid!r}: a number of nodes, the node positions (units of b) or 'resolved'")
            grid = max(401, self.resolving_nodes())
        if np.ndim(grid) == 0:
            n = int(check_range("grid", grid, "nodes", 11, 100001))
            nodes = np.linspace(lo, hi, n)
        else:
            try:
                nodes = np.asarray(grid, dtype=float)
            except (TypeError, ValueError):
                raise ValueError(f"grid = {grid!r}: a number of nodes or the node positions (units of b)") from None
            if nodes.ndim != 1 or nodes.size < 11 or not np.all(np.diff(nodes) > 0):
                raise ValueError(f"grid: {nodes.size} node positions; allowed: at least 11, increasing (units of b)")
            if nodes[0] != lo or nodes[-1] != hi:
                raise ValueError(f"grid nodes must start at the inlet {lo} and end at the outlet {hi} (units of b)")
        self.grid = TensorGrid(nodes)
        # the loaded zone: the Hertz contact, or below M = 2.5 the hydrodynamic length ~ sqrt(2 R h) ~ 2.5 b / M
        zone = max(1.0, 2.5 / self.M)
        inside = np.count_nonzero(np.abs(nodes) < zone)
        if inside < 8:
            raise ValueError(f"grid = {nodes.size} nodes puts {inside} nodes inside the Hertz contact (below M = 2.5: "
                             f"the hydrodynamic zone 2.5 b/M) |x| < {zone:.3g} b; allowed: at least 8 (use more nodes)")
        self._options = dict(viscosity=viscosity, modulus=modulus, density=density, viscosity_law=viscosity_law,
                             scheme=scheme, elastic=elastic, dh_constants=tuple(dh_constants))

    def with_load(self, load_per_length: float, pressure_viscosity: float | None = None, nodes=None) -> "LineContact":
        """The same contact (same nodes in units of its own b, or ``nodes``) at another load [N/m] and,
        optionally, another pressure-viscosity coefficient [1/Pa]: the steps of the load continuation."""
        o = self._options
        alpha = self.lubricant.pressure_viscosity if pressure_viscosity is None else pressure_viscosity
        return LineContact(self.radius, load_per_length, self.speed, o["viscosity"], alpha, o["modulus"],
                           density=o["density"], viscosity_law=o["viscosity_law"],
                           grid=self.grid.x if nodes is None else nodes,
                           domain=self.domain, scheme=o["scheme"], elastic=o["elastic"], dh_constants=o["dh_constants"])

    # -- scaled problem ------------------------------------------------------------------------------
    @property
    def lam(self) -> float:
        """Wedge coefficient ``12 eta0 u R^2 / (b^3 p_h)``."""
        return 12.0 * self.lubricant.viscosity * self.speed * self.radius ** 2 / (self.b ** 3 * self.p_h)

    @property
    def film_scale(self) -> float:
        """Film unit ``b^2 / R`` [m]."""
        return self.b * self.b / self.radius

    def film_problem(self, grid: TensorGrid | None = None, lubricant: Lubricant | None = None, kernel=None,
                     matrix_free: bool = False) -> EHLFilm:
        """The scaled discrete problem (:class:`~transient.models.roller.ehl_problem.EHLFilm`) on ``grid``
        (default: the contact's grid); ``kernel``: its influence matrix if already computed.
        ``matrix_free`` (elastic, uniform grid): the DC-FFT film :class:`~transient.models.roller.line_fft.LineFFTFilm`
        instead (``kernel`` then its :class:`~transient.physics.elasticity.LineConvolution`), for the
        film-content iteration only (it has no dense Jacobian)."""
        grid = self.grid if grid is None else grid
        x = grid.x
        if matrix_free and self.elastic:
            return LineFFTFilm(grid, 0.5 * x * x, np.ones(1), self.lam, self.load_per_length / (self.b * self.p_h),
                               lubricant or self.lubricant, self.p_h, -1.0 / math.pi, self.scheme == "upwind2",
                               conv=kernel)
        return EHLFilm(grid, 0.5 * x * x, np.ones(1), self.lam, self.load_per_length / (self.b * self.p_h),
                       lubricant or self.lubricant, self.p_h, elastic="dense" if self.elastic else "rigid",
                       elastic_factor=-1.0 / math.pi, order2=(self.scheme == "upwind2"), kernel=kernel)

    def initial_guess(self, film: EHLFilm) -> np.ndarray:
        """Hertz pressure plus a small inlet ramp and Moes' central film (elastic, M >= 1; Moes covers
        the whole chart, also L = 0 where Dowson-Toyoda gives no film), or an inlet ramp and Martin's
        film (rigid, and elastic below M = 1, where the film is nearly rigid-hydrodynamic)."""
        xi = film.grid.x[1:-1]
        ramp = np.where(xi < -1.0, 0.1 * (xi - xi[0]) / (-1.0 - xi[0]), 0.0)
        if self.elastic and self.M >= 1.0:
            p = np.sqrt(np.clip(1.0 - xi * xi, 0.0, None)) + ramp
            hc = moes_central(self.M, self.L) * math.sqrt(2.0 * self.U) * self.radius / self.film_scale
            h0 = hc - float(np.interp(0.0, film.grid.x, film.deformation(p)))
        else:
            p = ramp
            h0 = martin_min(self.U, self.W) * self.radius / self.film_scale
        return np.append(p, h0)

    def levels(self) -> list[TensorGrid]:
        """Grids of the nested iteration, coarse to fine: every other node of the next finer grid while
        the coarser one keeps >= 20 nodes in the Hertz contact and >= 101 nodes."""
        out = [self.grid]
        while True:
            x = out[0].x
            if (x.size - 1) % 2:
                break
            xc = x[::2]
            if xc.size < 101 or np.count_nonzero(np.abs(xc) < 1.0) < 20:
                break
            out.insert(0, TensorGrid(xc))
        return out

    def dry(self, nodes: int = 401) -> LineDry:
        """Dry contact of the cylinder (the zero-speed limit) on ``nodes`` uniform nodes over
        ``[-1.5 b, 1.5 b]`` with the same plane-strain patches, by Polonsky-Keer CG
        (:func:`transient.models.ehl.dry.polonsky_keer`): compare with Hertz, ``p_h sqrt(1 - x^2/b^2)``."""
        x = np.linspace(-1.5, 1.5, int(check_range("nodes", nodes, "-", 21, 100001)))
        dx = x[1] - x[0]
        edges = np.concatenate(([x[0] - 0.5 * dx], 0.5 * (x[1:] + x[:-1]), [x[-1] + 0.5 * dx]))
        K = -line_influence(x, edges) / math.pi
        p, delta, it, ok = polonsky_keer((0.5 * x * x)[None, :], _DenseOperator(K), dx, math.pi / 2.0)
        e = edge_positions(x, p[0])
        return LineDry(x=x * self.b, pressure=p[0] * self.p_h, p_max=float(p.max() * self.p_h),
                       half_width=0.5 * (e[1] - e[0]) * self.b, hertz_half_width=self.b, hertz_pressure=self.p_h,
                       success=ok, message="converged" if ok else "Polonsky-Keer CG did not reach its tolerance",
                       iterations=it)

    # -- solves --------------------------------------------------------------------------------------
    def steady(self, initial=None, tol: float = 1e-9, max_iter: int = 60, raise_on_failure: bool = True,
               penalty: float | None = None) -> LineSteady:
        """Steady film. By default (exact complementarity, no ``initial``) the film-content form is solved
        by Fischer-Burmeister-Newton-Schur iterations along grid levels and the load path from the Hertz
        pressure (:func:`transient.models.roller.line_sequence.solve_sequence`); its solution is then
        checked against (and, where it is not within ``tol``, finished by Newton on) the Reynolds-condition
        equations of :meth:`film_problem`, so the discrete film is the same. Where that fails, and for
        ``initial`` or ``penalty``, :meth:`steady_reynolds`. Raises :class:`EHLConvergenceError` (its
        ``result`` flagged ``success=False`` with the residual history) if no path reaches the contact,
        unless ``raise_on_failure=False``. A converged film on an explicit grid too coarse for this load
        (:meth:`_check_resolution`) warns :class:`FilmResolutionWarning` and says so in its message, naming the
        uniform node count that resolves it (:meth:`resolving_nodes`; the default grid resolves it); an explicit
        domain that cuts the inlet off warns :class:`StarvedInletWarning`. Uniform grids above 1025 nodes are solved matrix-free
        (DC-FFT elasticity, :mod:`transient.models.roller.line_fft`): there a film-content solution that
        differs from the Reynolds-condition one in the rupture node is returned as it is (with a note), and
        there is no dense fallback."""
        if initial is not None or penalty is not None:
            return self.steady_reynolds(initial, tol, max_iter, raise_on_failure, penalty)
        t0 = time.perf_counter()
        seq = solve_sequence(self, tol=0.1 * tol, max_iter=max_iter)
        if seq.success:
            film = seq.content.base
            n = seq.content.n
            u = np.append(seq.state[:n], seq.state[-1])
            film.set_row_scale(u)
            norms = list(seq.residual_norms) + [float(np.max(np.abs(film.residual(u))))]
            its = seq.iterations
            ok = norms[-1] <= tol
            msg = f"converged (film-content Newton, {seq.factorisations} LU factorisations): {seq.message}"
            if not ok and seq.content.matrix_free:  # no dense Jacobian to finish with: the film-content solution
                ok = True
                msg += (f"; the Reynolds-condition residual of this film-content solution is {norms[-1]:.3g} "
                        "(the two discrete problems differ in the rupture node)")
            if not ok:  # a different rupture node: finish on the Reynolds-condition equations
                nr, k, hist = self._newton(film, u, tol, PATH_MAX_ITER, [None])
                its += k
                norms += list(hist)
                if nr is not None:
                    ok, u = True, nr.x
                    msg += f"; {k} Newton iterations on the Reynolds-condition equations"
            if ok:
                res = self._result(film, u, True, msg, its, norms, time.perf_counter() - t0)
                if res.h_min > 0.0:
                    return self._check_resolution(res)
        if matrix_free(self.grid) and self.elastic:  # the fallback's dense matrices would not fit
            res = self._result(seq.content.base, np.append(seq.state[: seq.content.n], seq.state[-1]), False,
                               f"film-content Newton: {seq.message or 'no physical film'}", seq.iterations,
                               seq.residual_norms, time.perf_counter() - t0)
            if raise_on_failure:
                raise EHLConvergenceError(res.message, res)
            return res
        fallback = self.steady_reynolds(None, tol, max_iter, False, None)
        fallback.message = f"film-content Newton: {seq.message or 'no physical film'}; then {fallback.message}"
        fallback.wall_time = time.perf_counter() - t0
        if not fallback.success and raise_on_failure:
            raise EHLConvergenceError(fallback.message, fallback)
        return self._check_resolution(fallback) if fallback.success else fallback

    def resolving_nodes(self) -> int:
        """The smallest uniform node count ``2^k + 1`` over :attr:`domain` whose spacing resolves the film
        (:func:`~transient.models.roller.line_grid.resolving_spacing`: ``dx <= INLET_RESOLUTION / M`` at the inlet
        edge, and in the rigid regime ``dx <= RIGID_RESOLUTION sqrt(2 R h_c)``; the film to a few tenths of a per
        cent; a power of two for the grid levels)."""
        return uniform_nodes(self.domain, resolving_spacing(self.M, self.L, self.elastic))

    def _check_resolution(self, res: LineSteady) -> LineSteady:
        """``res``, its message noting (and a :class:`FilmResolutionWarning` raised) when the grid's spacing
        at the inlet edge exceeds ``INLET_RESOLUTION / M`` or, in the rigid regime, the largest spacing within
        ``3 s`` of the centre exceeds ``RIGID_WARN s`` (``s = sqrt(2 R h_c)/b``), and (a
        :class:`StarvedInletWarning`) when the inlet lies closer than ``RIGID_INLET_WARN s`` (rigid regime) or
        ``ELASTIC_INLET_WARN s`` (elastic) upstream."""
        s = hydrodynamic_length(self.M, self.L, self.elastic)
        rigid = rigid_regime(self.M, self.elastic)
        notes = []
        dx = inlet_spacing(self.grid)
        if self.elastic and self.M * dx > INLET_RESOLUTION:
            notes.append(f"under-resolved: node spacing {dx:.3g} b at the inlet edge x = -b, above "
                         f"{INLET_RESOLUTION}/M = {INLET_RESOLUTION / self.M:.3g} b")
        if rigid:
            x = self.grid.x
            near = (x[1:] > -3.0 * s) & (x[:-1] < 3.0 * s)
            dx_s = float(np.max(np.diff(x)[near])) if near.any() else float(x[-1] - x[0])
            if dx_s > RIGID_WARN * s:
                notes.append(f"under-resolved: node spacing {dx_s:.3g} b near the contact, above {RIGID_WARN} "
                             f"sqrt(2 R h_c) = {RIGID_WARN * s:.3g} b (the rigid inlet wedge)")
        if notes:
            note = (" and ".join(notes) + ": the film is that of the discrete equations, not within ~1 % of the grid "
                    f"limit: use {self.resolving_nodes()} uniform nodes (grid='resolved') or the default grid")
            res.message += "; " + note
            warnings.warn(f"LineContact.steady at M = {self.M:.3g}: {note}", FilmResolutionWarning, stacklevel=3)
        need = RIGID_INLET_WARN if rigid else ELASTIC_INLET_WARN
        if -self.domain[0] < need * s:
            note = (f"starved inlet: the domain starts {-self.domain[0]:.3g} b upstream, within {need:g} "
                    f"hydrodynamic lengths sqrt(2 R h_c) = {s:.3g} b of the contact: the film is thinner than the "
                    f"fully flooded one (the default domain starts {-default_domain(self.M, self.L, self.elastic)[0]:.3g} b "
                    "upstream)")
            res.message += "; " + note
            warnings.warn(f"LineContact.steady at M = {self.M:.3g}: {note}", StarvedInletWarning, stacklevel=3)
        return res

    def steady_reynolds(self, initial=None, tol: float = 1e-9, max_iter: int = 60, raise_on_failure: bool = True,
                        penalty: float | None = None) -> LineSteady:
        """Steady film on the Reynolds-condition equations alone, by nested iteration: semismooth Newton
        on the complementarity system on :meth:`levels`, each level started from the coarser solution. The
        coarsest level starts from :meth:`initial_guess` where the contact lies in the easy corner of the
        Moes chart (M <= 10, L <= 5); elsewhere, and wherever Newton from the interpolated coarser solution
        fails, the level is solved by load (and pressure-viscosity) continuation from that corner
        (:meth:`continuation`). ``initial``: a previous :class:`LineSteady` on the same grid to start
        from instead. ``penalty``: None for the exact complementarity (Fischer-Burmeister), or the
        penalty factor of the penalty form (the transient's ``GAMMA`` gives its limit)."""
        t0 = time.perf_counter()
        if penalty is not None:
            penalty = check_range("penalty", penalty, "-", 1.0, 1e12)
        levels = [self.grid] if initial is not None else self.levels()
        easy = self.easy
        # the path runs on the coarsest level fine enough for this load (spacing in the contact <= 4/M)
        k_path = 0 if (easy or initial is not None) else next(
            (k for k, g in enumerate(levels) if self._contact_spacing(g) * self.M <= 4.0), len(levels) - 1)
        u, grid_prev, iters, norms, ok, msg, notes = None, None, 0, [], True, "", []
        for k, grid in enumerate(levels[k_path:], start=k_path):
            film = self.film_problem(grid)
            film.penalty = penalty
            nr = None
            if initial is not None or easy or k > k_path:
                if k == 0 and initial is None:
                    u0 = self.initial_guess(film)
                    nr, its, norms = self._newton(film, u0, tol, max_iter, [None, 0.3, 0.03])
                else:  # from a nearby solution Newton converges fast or not at all: then the path
                    u0 = initial.state if initial is not None else interpolate_state(grid_prev, u, grid)
                    nr, its, norms = self._newton(film, u0, tol, min(max_iter, PATH_MAX_ITER), [None])
                iters += its
            if nr is None and easy:
                ok, msg = False, f"level {k + 1}/{len(levels)} ({grid.x.size} nodes): Newton did not converge"
                u = u0
                break
            if nr is None:
                path = self.continuation(grid, tol=tol, max_iter=min(max_iter, PATH_MAX_ITER), penalty=penalty)
                iters += path.iterations
                norms = path.residual_norms
                notes.append(f"{grid.x.size} nodes: {path.message}")
                if not path.success:
                    ok = False
                    msg = f"level {k + 1}/{len(levels)} ({grid.x.size} nodes): Newton did not converge; {path.message}"
                    dx = self._contact_spacing(grid)
                    if dx * self.M > 4.0:
                        msg += (f"; the node spacing in the contact, {dx:.3g} b, exceeds 4/M = {4.0 / self.M:.3g} b: "
                                "refine the grid (or cluster it in |x| < 1.5 b)")
                    u = path.state
                    film = path.film if path.film is not None else film
                    break
                u = path.state
            else:
                u = nr.x
            grid_prev = grid
        if ok:
            msg = f"converged: {iters} Newton iterations over {len(levels) - k_path} grid level(s)"
            if notes:
                msg += "; " + "; ".join(notes)
        res = self._result(film, u, ok, msg, iters, norms, time.perf_counter() - t0)
        if ok and not res.h_min > 0.0:  # converged equations, unphysical film: the grid cannot carry this load
            ok = False
            msg = (f"did not converge to a physical film: the equations converged to one that closes (h_min = "
                   f"{res.h_min:.3g} m <= 0) on {levels[-1].x.size} nodes: "
                   f"the grid is too coarse for M = {self.M:.3g}; refine it (node spacing in the contact <= 4/M b)")
            res = self._result(film, u, ok, msg, iters, norms, time.perf_counter() - t0)
        if not ok and raise_on_failure:
            raise EHLConvergenceError(msg, res)
        return res

    @property
    def easy(self) -> bool:
        """In the corner of the Moes chart solved from the Hertz pressure directly (M <= 10, L <= 5)."""
        return self.M <= M_EASY * (1.0 + 1e-9) and self.L <= L_EASY * (1.0 + 1e-9)

    @staticmethod
    def _contact_spacing(grid: TensorGrid) -> float:
        """Largest node spacing within 1.5 b of the centre (units of b)."""
        x = grid.x
        near = (x[1:] > -1.5) & (x[:-1] < 1.5)
        return float(np.max(np.diff(x)[near]))

    @staticmethod
    def _newton(film, u0, tol, max_iter, attempts):
        """Newton with line search, then with pseudo-transient continuation from each first step in
        ``attempts`` (None: line search): ``(result or None, iterations, residual history)``."""
        its, norms = 0, []
        for pseudo in attempts:
            try:
                nr = solve_steady(film, u0, tol=tol, max_iter=max_iter, pseudo_time=pseudo,
                                  name="LineContact.steady Newton")
                return nr, its + nr.iterations, nr.residual_norms
            except NewtonError as exc:
                its += exc.result.iterations
                norms = exc.result.residual_norms
        return None, its, norms

    def continuation(self, grid: TensorGrid | None = None, tol: float = 1e-9, max_iter: int = PATH_MAX_ITER,
                     penalty: float | None = None):
        """Steady film on ``grid`` by continuation (:func:`transient.models.roller.continuation.follow`)
        from the easy corner of the Moes chart: the load scaled to ``M = min(M, 10)`` and ``alpha`` to
        ``L = min(L, 5)``, solved from the Hertz pressure, then load (geometrically) and ``alpha``
        (linearly) raised together to this contact's. Each step starts Newton from the previous pressure
        (in units of its own p_h) with ``h0`` shifted so that the central film in metres is unchanged.
        Returns the :class:`~transient.models.roller.continuation.PathResult` (state in this contact's
        scaled units at ``s = 1``)."""
        grid = self.grid if grid is None else grid
        w1, a1 = self.load_per_length, self.lubricant.pressure_viscosity
        w0 = w1 * min(1.0, M_EASY / self.M)
        a0 = a1 * min(1.0, L_EASY / self.L) if self.L > 0 else 0.0
        kernel = self.film_problem(grid).K
        cache = {}

        def at(s):
            if s not in cache:
                c = self if s >= 1.0 else self.with_load(w0 * (w1 / w0) ** s, a0 + s * (a1 - a0))
                f = c.film_problem(grid, kernel=kernel)
                f.penalty = penalty
                cache[s] = (c, f)
            return cache[s]

        def central(s, u):
            c, f = at(s)
            h = f.film(u[:-1], u[-1])
            if not np.all(np.isfinite(h)) or h.min() <= 0.0:
                return float("nan")
            return float(np.interp(0.0, grid.x, h)) * c.film_scale

        def predict(s_from, u, s_to):
            hc = central(s_from, u)
            return np.append(u[:-1], u[-1] + hc / at(s_to)[0].film_scale - hc / at(s_from)[0].film_scale)

        def solve(s, u0):
            return solve_steady(at(s)[1], u0, tol=tol, max_iter=max_iter, name="LineContact.continuation Newton")

        c0, f0 = at(0.0)
        start = c0.with_load(c0.load_per_length, nodes=grid.x).steady_reynolds(tol=tol, max_iter=60, raise_on_failure=False,
                                                                      penalty=penalty)
        if not start.success:
            return PathResult(state=start.state, s=0.0, success=False, iterations=start.iterations,
                              residual_norms=start.residual_norms, film=f0,
                              message=f"Newton failed at the start of the path (M = {c0.M:.3g}, L = {c0.L:.3g})")
        path = follow(solve, predict, central, start.state)
        path.iterations += start.iterations
        path.film = at(path.s)[1]
        return path

    # -- transient -----------------------------------------------------------------------------------
    @property
    def time_scale(self) -> float:
        """Time unit of the scaled transient, the transit time ``b/u`` [s]."""
        return self.b / self.speed

    def transient(self, t_end: float, load=None, start="dry", *, n_out: int = 101, initial_film: float | None = None,
                  ramp_time: float | None = None, max_steps: int = 5000, integration: Integration | None = None,
                  long_run: LongRun | None = None, **legacy) -> LineTransient:
        """Transient film over ``[0, t_end]`` [s]: by BDF2 on the film-content form
        (:mod:`transient.models.roller.line_step`) on the one run driver (:mod:`transient.models.ehl.film_run`).

        ``load``: None (constant, the contact's load), a number [N/m] (a step from the starting load,
        smoothed over ``ramp_time``, default one transit time b/u) or a function of t [s] -> N/m.
        ``start``: ``"dry"`` -- the dry (Hertz) pressure with the film lifted to ``initial_film`` [m] at
        x = 0 (default half the Dowson-Toyoda central film) -- or a :class:`LineSteady` on this grid.
        ``integration`` (:class:`~transient.solvers.settings.Integration`): ``method="bdf2"`` (the default) the
        exact complementarity (the film content, cavitation mass-conserving), whose long-time limit is
        ``steady()``; the content starts full where the start has pressure and mass-conserving where it has none
        (:func:`~transient.models.roller.line_step.consistent_content`); ``max_steps`` bounds the run (uniform
        grids up to 1025 nodes: the dense elastic film); ``rtol`` (default 1e-4). ``method="ida"``: the exit
        condition in penalty form (:data:`transient.models.roller.transient.GAMMA`), whose long-time limit is
        ``steady(penalty=GAMMA)`` -- deprecated, removed in the next release. ``long_run``
        (:class:`~transient.solvers.settings.LongRun`): checkpoint and resume, progress bar, ``stop``,
        ``time_budget`` [s of wall clock]. The loose keywords ``rtol=``, ``method=``, ``time_budget=`` of earlier
        releases are deprecated.
        """
        ig, lr = transient_settings("LineContact.transient", TRANSIENT_METHODS, "bdf2", integration, long_run,
                                    legacy)
        t_end = check_positive("t_end", t_end, "s")
        n_out = check_int("n_out", n_out, "-", 2, 10 ** 6)
        if ig.method == "bdf2":
            if matrix_free(self.grid) and self.elastic:
                raise ValueError(f"method = 'bdf2': {self.grid.x.size} uniform nodes need the matrix-free film; the "
                                 "film-content transient takes the dense film (at most 1025 uniform nodes, or "
                                 "clustered)")
            max_steps = check_int("max_steps", max_steps, "-", 1, 10 ** 7)
        else:
            penalty_deprecated("LineContact.transient", lr)
        film = self.film_problem()
        w_start = self.load_per_length
        if start == "dry":
            xi = self.grid.x[1:-1]
            p = np.sqrt(np.clip(1.0 - xi * xi, 0.0, None))
            hc = dowson_toyoda_central(self.U, self.G, self.W) * self.radius
            h_init = 0.5 * hc if initial_film is None else check_positive("initial_film", initial_film, "m")
            h0 = h_init / self.film_scale - float(np.interp(0.0, self.grid.x, film.film(p, 0.0)))
            y0 = np.append(p, h0)
        elif isinstance(start, LineSteady):
            y0 = np.array(start.state, float)
            if y0.size != self.grid.n + 1:
                raise ValueError(f"start has {y0.size - 1} pressure nodes, this grid {self.grid.n}")
            w_start = float(np.trapezoid(start.pressure, start.x))
        else:
            raise ValueError(f"start = {start!r}: use 'dry' or a LineSteady of this contact")
        if ig.method == "bdf2":
            return self._content_transient(film, y0, w_start, t_end, load, n_out, ramp_time, max_steps, (ig, lr))
        return self._transient(film, y0, self.lam, self.time_scale, self.load_per_length, w_start, t_end, load,
                               ig.rtol, n_out, ramp_time)

    def _transient(self, film, y0, kappa, t_ref, w_ref, w_start, t_end, load, rtol, n_out, ramp_time):
        ratio = load_ratio(load, w_ref, w_start, t_ref, ramp_time)
        sol, wall, rows = run_squeeze(film, kappa, ratio, y0, t_end, t_ref, rtol, n_out,
                                      lambda f, y: self._result(f, y, True, "", 0, [], 0.0))
        return squeeze_result(LineTransient, sol, wall, rows, ratio, t_ref, w_ref, self.film_scale)

    def _content_transient(self, film, y0, w_start, t_end, load, n_out, ramp_time, max_steps,
                           settings) -> LineTransient:
        """``method="bdf2"`` of :meth:`transient`: :class:`~transient.models.roller.line_step.LineFilmStep` on the
        one run driver from ``y0 = [p, h0]`` (its content by
        :func:`~transient.models.roller.line_step.consistent_content`)."""
        content = LineContentFilm(film)
        n, t_ref, w_ref = content.n, self.time_scale, self.load_per_length
        ratio = load_ratio(load, w_ref, w_start, t_ref, ramp_time)
        u0 = consistent_content(content, y0[:-1], y0[-1])
        sample, result = content_outputs(LineTransient, lambda y, _: self._result(film, y, True, "", 0, [], 0.0), n,
                                         ratio, t_ref, w_ref, self.film_scale)
        key = dict(contact=contact_digest(self), nodes=int(self.grid.n),
                   load=load_digest(ratio, t_end / t_ref, n_out))
        return run_content_transient(content, self.lam, u0, ratio, t_end / t_ref, n_out, sample, result, settings,
                                     max_steps, key, "line contact (film content, FBNS)")

    def _result(self, film, u, ok, msg, iterations, norms, wall) -> LineSteady:
        p, h0 = u[:-1], u[-1]
        x = film.grid.x * self.b
        pressure = film.grid.full(p).ravel() * self.p_h
        h = film.film(p, h0) * self.film_scale
        h_min, x_min = film_extrema(x, h)
        return LineSteady(x=x, pressure=pressure, film=h, h_central=float(np.interp(0.0, x, h)), h_min=h_min,
                          x_of_h_min=x_min, p_max=float(pressure.max()),
                          load_error=float(film.area_w @ p - 1.0), radius=self.radius, modulus=self.modulus,
                          hertz_half_width=self.b, hertz_pressure=self.p_h, success=ok, message=msg,
                          iterations=int(iterations), wall_time=wall, residual_norms=list(map(float, norms)),
                          state=np.array(u, dtype=float))


def rigid_squeeze(radius, load_per_length, viscosity, h0_start, t_end, grid: int = 401, half_width: float = 10.0,
                  rtol: float = 1e-6, n_out: int = 51) -> LineTransient:
    """Pure squeeze of a rigid cylinder on a plane (no rolling, isoviscous, incompressible) under a
    constant load, from the gap ``h0_start`` [m] at rest, by the same DAE and IDA (the closed form is
    :func:`transient.verification.ehl_reference.squeeze_film_history`). Domain ``|x| <= half_width b``
    with the length unit ``b = sqrt(2 R h0_start)`` (the Hertz half-width of a fictitious modulus
    ``4 w/(pi h0_start)``: lengths, pressure and time are only scaled by it); time unit
    ``12 eta0 R^2 / (b^2 p_h)``."""
    h0_start = check_positive("h0_start", h0_start, "m")
    w = check_positive("load_per_length", load_per_length, "N/m")
    lc = LineContact(radius, w, 1.0, viscosity, 0.0, 4.0 * w / (math.pi * h0_start), density="incompressible",
                     viscosity_law="isoviscous", grid=grid, domain=(-half_width, half_width), elastic=False)
    film = lc.film_problem()
    film.lam = 0.0
    t_ref = 12.0 * viscosity * radius ** 2 / (lc.b ** 2 * lc.p_h)
    y0 = np.append(np.zeros(lc.grid.n), h0_start / lc.film_scale)
    return lc._transient(film, y0, 1.0, t_ref, lc.load_per_length, lc.load_per_length,
                         check_positive("t_end", t_end, "s"), None, rtol, n_out, None)
