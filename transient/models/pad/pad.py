"""Parallel rectangular thrust pad in mixed lubrication: squeeze film + asperity contact (Lee & Rhim,
Lee & Rhim).

A rigid pad ``L x B`` (x along the length L, y along the width B) sits parallel to a counter-face at
the nominal separation ``h0(t)`` of the mean planes (positive when the gap is open). Parallel surfaces
generate no wedge pressure (``dh0/dx = 0``), so the film pressure comes from the squeeze term alone.
Average Reynolds equation with the Wu-Zheng contact factor (Lee & Rhim eq. 10 with ``dh0/dx = 0``; the
dimensionless form is their eq. 12), ambient pressure (gauge 0) on all four edges (eq. 13)::

    d/dx(phi_x h0^3/(12 mu) dp/dx) + d/dy(phi_y h0^3/(12 mu) dp/dy) = phi_c dh0/dt           (10, 12)

    phi_x, phi_y = Patir-Cheng pressure flow factors at H = h0/sigma, Peklenik number gamma
    phi_c        = d(h_bar)/d(h0) = P(z < h0)  (Wu-Zheng contact factor, eq. 9)

Force balance on the pad (eq. 14; the paper's F_tot = 0 is the massless limit)::

    M d^2h0/dt^2 = W_hyd + W_asp(h0) - W,     W_hyd = int p dA,
    W_asp = A (4/3) N E' Rp^(1/2) int_{h0}^inf (z - h0)^(3/2) phi(z) dz                     (15)
    A_re  = A pi N Rp int_{h0}^inf (z - h0) phi(z) dz                                        (16)

(:mod:`transient.physics.asperity`; W [N] the applied load pressing the gap closed.)

Two solution paths, which agree (tests):

* ``"full"`` -- 2-D finite volumes (:class:`~transient.fv.reynolds.ReynoldsOperator`, ``nx x ny``
  cells) with the unknowns ``[p_cells, h0, v]``, ``v = dh0/dt``::

      cells: R_i(p; h0) + A_i phi_c(h0) v = 0          (algebraic, R = net Poiseuille outflow)
      h0   : h0' - v = 0                               (differential)
      v    : M v' - (W_hyd + W_asp - W) = 0             (differential if M > 0, algebraic if M = 0)

  With M = 0 the algebraic block ``[[dR/dp, A phi_c], [-A^T, 0]]`` is a non-singular saddle system
  (its Schur complement is ``-phi_c A^T (dR/dp)^-1 A != 0``), so the DAE has index 1 for IDA. The
  analytic sparse Jacobian has the arrow pattern of the operator with two dense trailing unknowns.
  With an ODE method (cvode, bdf, lsoda, rk4) the full path eliminates the pressure instead: every
  right-hand side solves the 2-D problem for the current h0 (a sparse LU), the paper's inner solve.
* ``"separable"`` -- the pad is uniform and parallel and the flow factors do not depend on position,
  so the pressure is ``p = phi_c (dh0/dt) * Pi(x, y; h0)`` with ``Pi`` the solution of one Poisson
  problem, known in closed form. Stretching y by ``sqrt(phi_x/phi_y)`` turns the anisotropic operator
  into a Laplacian; the rectangular series (:func:`transient.verification.reference.squeeze_rect_load`) gives

      W_hyd = -K(h0) dh0/dt,  K(h0) = mu L^3 B phi_c f(B/L sqrt(phi_x/phi_y)) / (phi_x h0^3),
      f(r)  = 1 - 192/(pi^5 r) sum_{n odd} tanh(n pi r/2) / n^5,

  and the transient is a scalar ODE (massless: ``dh0/dt = (W_asp(h0) - W) / K(h0)``; with mass the
  pair ``h0' = v, M v' = -K v + W_asp - W``), integrated by CVODE (or any other method).
  ``path="auto"`` picks it: in this model the flow factors are always uniform over the pad.

Flow factors below their fitted range (``H < H_min(gamma)``, 0.5 ... 1 in Patir & Cheng's Table 1)
are **frozen at H_min** (value and zero derivative): the fits are not valid there and the 1 - C e^-rH
branch would reach zero (an unsolvable Reynolds problem) at H ~ 0.3 ... 0.4. The contact factor and
the asperity integrals are exact for every h0 (Gaussian or the surface's discrete density).
``h0 > 0`` is required: ``K(h0) ~ h0^-3`` keeps a lubricated pad from reaching ``h0 = 0`` in finite
time, so a load above ``W_asp(0+)`` makes the pad creep towards ``h0 = 0`` without equilibrium.

Units: SI at the API (m, Pa, Pa s, N, kg, s). Internally the states are scaled to O(1):
``p/p_ref`` (``p_ref = W/(L B)``), ``h0/h_ref`` (``h_ref = h0_start``) and ``v/v_ref``.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import fields

import numpy as np
import scipy.sparse.linalg as spla
from scipy import special
from scipy.optimize import brentq

from transient.physics.asperity import AsperityContact, DiscreteDensity, steel_asperity_contact
from transient.physics.flow_factors import PRESSURE_FLOW_TABLE, _gamma_bracket, _key
from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import ReynoldsOperator, residual_kernel
from transient.surfaces.roughness import RoughSurface
from transient.results import RunResult, quantity, result_type
from transient.solvers.integrate import Problem, Steps, check_method
from transient.checks import check_instance, check_int, check_positive, check_range
from transient.solvers.model_run import ModelRun, RunParts, check_run_memory, start_point
from transient.solvers.settings import (RK4_INNER_TOLERANCE, Integration, LongRun, check_unused, keyword_table,
                                       requested_method, run_settings)

__all__ = ["ThrustPad", "DescentResult", "pressure_flow_clamped", "rect_shape_factor"]

PATHS = ("auto", "full", "separable")
DESCENT_OWNER = "ThrustPad.descent"
#: The loose keywords of :meth:`ThrustPad.descent` of earlier releases and the settings field each now is.
DESCENT_KEYWORDS = keyword_table("integration", Integration, ("method", "rtol", "atol", "dt", "linear_solver"))
#: The descent's own integration default: CVODE (the separable path is a scalar ODE).
DESCENT_DEFAULTS = {"integration": dict(method="cvode")}
_SQRT2PI = math.sqrt(2.0 * math.pi)


# --------------------------------------------------------------------------------------------------
# scalar helpers
# --------------------------------------------------------------------------------------------------

def rect_shape_factor(r, n_terms: int = 200) -> float:
    """f(r) = 1 - 192/(pi^5 r) sum_{n odd} tanh(n pi r/2)/n^5 (r = B/L, rectangular squeeze series).

    ``W = mu L^3 B f(B/L) V / h^3`` for smooth plates closing at ``V = -dh/dt``; f -> 1 for r -> inf.
    Series error after ``n_terms`` odd terms < 192/(pi^5 r) / (4 (2 n_terms)^4).
    """
    r = float(r)
    n = 2.0 * np.arange(int(n_terms)) + 1.0
    return float(1.0 - 192.0 / (np.pi ** 5 * r) * np.sum(np.tanh(0.5 * n * np.pi * r) / n ** 5))


def pressure_flow_clamped(H: float, gamma: float):
    """Patir-Cheng pressure flow factors with their H-derivatives, frozen below the fit range.

    Returns ``(phi_x, phi_y, dphi_x/dH, dphi_y/dH, H_min)``. Same fits and log-gamma interpolation as
    :func:`transient.physics.flow_factors.pressure_flow_factors` (``phi_x = 1 - C exp(-r H)`` for
    gamma <= 1, ``1 + C H^-r`` for gamma > 1, ``phi_y(gamma) = phi_x(1/gamma)``), evaluated at
    ``max(H, H_min)``; ``H_min`` is the largest lower limit of the tabulated fits involved (for phi_x
    and phi_y), and the derivatives are 0 below it.
    """
    bx = _gamma_bracket(gamma)
    by = _gamma_bracket(1.0 / float(gamma))
    hmin = max(PRESSURE_FLOW_TABLE[_key(g)][2] for g, _ in bx + by)
    He = max(float(H), hmin)
    frozen = float(H) < hmin

    def fit(bracket):
        val = der = 0.0
        for g, w in bracket:
            C, r, _ = PRESSURE_FLOW_TABLE[_key(g)]
            if g <= 1.0:
                e = math.exp(-r * He)
                val += w * (1.0 - C * e)
                der += w * C * r * e
            else:
                val += w * (1.0 + C * He ** (-r))
                der += w * (-r * C * He ** (-r - 1.0))
        return val, (0.0 if frozen else der)

    px, dpx = fit(bx)
    py, dpy = fit(by)
    return px, py, dpx, dpy, hmin


# --------------------------------------------------------------------------------------------------
# result
# --------------------------------------------------------------------------------------------------

@result_type
class DescentResult(RunResult):
    """Squeeze descent of the pad under a constant load.

    ``t`` [s], ``h0`` [m] (mean-plane separation), ``dh0_dt`` [m/s], ``w_hyd`` [N] (film load),
    ``w_asp`` [N] (asperity load), ``contact_area`` [m^2] (real contact area A_re), ``load`` [N],
    ``path`` ("full" | "separable"), ``method``, ``stats`` (:class:`transient.solvers.integrate.Stats`),
    ``success``, ``message``; ``pressure`` [Pa] (ny, nx) at the last output (full IDA path only);
    ``final_state`` ``(h0 [m], dh0/dt [m/s])`` and ``final_time`` [s], from which ``descent(start=result)`` goes on.
    """

    shapes = {"h0": ("t",), "dh0_dt": ("t",), "w_hyd": ("t",), "w_asp": ("t",), "contact_area": ("t",)}

    h0: np.ndarray = quantity("m")
    dh0_dt: np.ndarray = quantity("m/s")
    w_hyd: np.ndarray = quantity("N")
    w_asp: np.ndarray = quantity("N")
    contact_area: np.ndarray = quantity("m^2")
    load: float = quantity("N")
    mass: float = quantity("kg")
    path: str = quantity("")
    method: str = quantity("")
    pressure: np.ndarray | None = quantity("Pa", None, repr=False)

    @property
    def force_residual(self) -> np.ndarray:
        """``W_hyd + W_asp - W`` [N] at the outputs (= M d^2h0/dt^2; 0 for a massless pad)."""
        return self.w_hyd + self.w_asp - self.load


# --------------------------------------------------------------------------------------------------
# the pad
# --------------------------------------------------------------------------------------------------

class ThrustPad:
    """Parallel rectangular thrust pad, smooth or rough (Lee & Rhim). See the module doc.

    Parameters (SI)
    ----------
    length L [m] (x), width B [m] (y), viscosity mu [Pa s].
    surface : None (smooth: phi_x = phi_y = phi_c = 1, no contact), a number (Gaussian heights of RMS
        sigma [m] of the equivalent surface), or a :class:`~transient.surfaces.roughness.RoughSurface`
        (its RMS, its measured Peklenik number gamma and its discrete height density, ``bins`` bins).
    grid : (nx, ny) finite-volume cells of the full path (each 2 ... 2000).
    contact : ``"auto"`` (default: :func:`~transient.physics.asperity.steel_asperity_contact` for a rough
        surface, with the surface's discrete density; none for a smooth one), an
        :class:`~transient.physics.asperity.AsperityContact`, or None (no asperity load).
    gamma : Peklenik number for the flow factors, overriding the surface's ([1/9, 9]).
    """

    def __init__(self, length, width, viscosity, surface=None, grid=(40, 40), contact="auto", gamma=None,
                 bins: int = 256):
        self.length = check_range("length", length, "m", 1e-5, 10.0, why="(a pad, from 10 um to 10 m)")
        self.width = check_range("width", width, "m", 1e-5, 10.0, why="(a pad, from 10 um to 10 m)")
        self.viscosity = check_range("viscosity", viscosity, "Pa s", 0.0, 1e4, low_open=True)
        if isinstance(grid, (str, bytes)) or not hasattr(grid, "__len__") or len(grid) != 2:
            raise ValueError(f"grid = {grid!r} [cells]; allowed: two integers (nx, ny), each 2 ... 2000")
        nx = check_int("grid[0] (nx)", grid[0], "cells", 2, 2000)
        ny = check_int("grid[1] (ny)", grid[1], "cells", 2, 2000)
        self.grid_shape = (nx, ny)
        self.area = self.length * self.width
        self.surface = None
        self.density: DiscreteDensity | None = None
        if surface is None:
            self.sigma = None
            g = 1.0
        elif isinstance(surface, RoughSurface):
            self.surface = surface
            self.sigma = surface.rq
            self.density = surface.height_density(bins=bins)
            g = surface.gamma
        elif isinstance(surface, (int, float, np.floating, np.integer)) and not isinstance(surface, bool):
            self.sigma = check_range("surface (sigma, RMS roughness)", surface, "m", 1e-9, 1e-3,
                                     why="(1 nm to 1 mm)")
            g = 1.0
        else:
            raise ValueError(f"surface must be None, an RMS roughness sigma [m] or a RoughSurface, got "
                             f"{type(surface).__name__}")
        if gamma is not None:
            g = gamma
        self.gamma = check_range("gamma (Peklenik number)", g, "-", 1.0 / 9.0 * (1 - 1e-12), 9.0 * (1 + 1e-12),
                                 why="(Patir-Cheng flow-factor tables)")
        if isinstance(contact, str):
            if contact != "auto":
                raise ValueError(f"contact must be 'auto', an AsperityContact or None, got {contact!r}")
            contact = None if self.sigma is None else steel_asperity_contact(self.sigma, density=self.density)
        elif contact is not None and not isinstance(contact, AsperityContact):
            raise ValueError(f"contact must be 'auto', an AsperityContact or None, got {type(contact).__name__}")
        self.contact = contact
        self._op = None
        self._lap = None

    # ---------------------------------------------------------------------------------------------
    @property
    def rough(self) -> bool:
        return self.sigma is not None

    def __repr__(self):
        s = "smooth" if not self.rough else f"sigma={self.sigma:.4g} m, gamma={self.gamma:.3g}"
        return (f"ThrustPad(L={self.length:g} m, B={self.width:g} m, mu={self.viscosity:g} Pa s, {s}, "
                f"grid={self.grid_shape}, contact={'yes' if self.contact is not None else 'no'})")

    # ---- film factors and contact as functions of h0 --------------------------------------------
    def flow_factors(self, h0):
        """``(phi_x, phi_y, dphi_x/dh0, dphi_y/dh0)`` at h0 [m] (frozen below the fit range; 1 if smooth)."""
        if not self.rough:
            return 1.0, 1.0, 0.0, 0.0
        px, py, dpx, dpy, _ = pressure_flow_clamped(h0 / self.sigma, self.gamma)
        return px, py, dpx / self.sigma, dpy / self.sigma

    def contact_factor(self, h0):
        """``(phi_c, dphi_c/dh0)`` at h0 [m]: P(z < h0) and the height density at h0 (1, 0 if smooth)."""
        if not self.rough:
            return 1.0, 0.0
        if self.density is not None:
            d = self.density
            k = int(np.searchsorted(d.edges, h0, side="right")) - 1
            pdf = d.prob[k] / (d.edges[k + 1] - d.edges[k]) if 0 <= k < d.prob.size else 0.0
            return float(d.contact_factor(h0)), float(pdf)
        H = h0 / self.sigma
        return float(special.ndtr(H)), math.exp(-0.5 * H * H) / (_SQRT2PI * self.sigma)

    def asperity_load(self, h0):
        """W_asp [N] at h0 [m] (eq. 15 times the pad area; 0 without contact). Vectorised."""
        if self.contact is None:
            return np.zeros_like(np.asarray(h0, dtype=float)) + 0.0
        return self.area * self.contact.load(h0)

    def asperity_load_derivative(self, h0):
        """dW_asp/dh0 [N/m]."""
        if self.contact is None:
            return 0.0 * np.asarray(h0, dtype=float)
        return self.area * self.contact.load_derivative(h0)

    def contact_area(self, h0):
        """Real contact area A_re [m^2] at h0 [m] (eq. 16 times the pad area)."""
        if self.contact is None:
            return 0.0 * np.asarray(h0, dtype=float)
        return self.area * self.contact.real_area_fraction(h0)

    # ---- squeeze film -------------------------------------------------------------------------
    def squeeze_coefficient(self, h0, path: str = "separable") -> float:
        """K(h0) [N s/m] with ``W_hyd = -K dh0/dt``: closed-form series (``"separable"``) or the 2-D
        finite-volume solve (``"full"``)."""
        h0 = check_positive("h0", h0, "m")
        if path == "separable":
            return self._K_series(h0)
        if path == "full":
            return self._K_grid(h0)
        raise ValueError(f"path must be 'separable' or 'full', got {path!r}")

    def squeeze_load(self, h0, dh0_dt, path: str = "full") -> float:
        """Film load W_hyd [N] for the pad at h0 [m] moving at dh0_dt [m/s] (> 0 when dh0_dt < 0).

        ``path="full"``: 2-D finite volumes on the pad grid; ``"separable"``: the exact series."""
        v = check_range("dh0_dt", dh0_dt, "m/s")
        return -self.squeeze_coefficient(h0, path) * v

    def pressure(self, h0, dh0_dt) -> np.ndarray:
        """Film pressure [Pa, gauge] on the grid, shape (ny, nx), from the 2-D finite volumes."""
        h0 = check_positive("h0", h0, "m")
        v = check_range("dh0_dt", dh0_dt, "m/s")
        q = self._unit_pressure(h0)
        return (self.contact_factor(h0)[0] * v * q).reshape(self.grid_shape[1], self.grid_shape[0])

    def _K_series(self, h0):
        px, py, _, _ = self.flow_factors(h0)
        pc, _ = self.contact_factor(h0)
        f = rect_shape_factor(self.width / self.length * math.sqrt(px / py))
        return self.viscosity * self.length ** 3 * self.width * pc * f / (px * h0 ** 3)

    def _K_grid(self, h0):
        pc, _ = self.contact_factor(h0)
        q = self._unit_pressure(h0)
        return -pc * float(self._cell_area @ q)

    # ---- finite-volume machinery --------------------------------------------------------------
    def _build_operator(self):
        if self._op is not None:
            return
        nx, ny = self.grid_shape
        g = Grid2D(Axis.uniform(nx, self.length, name="x"), Axis.uniform(ny, self.width, name="y"))
        op = ReynoldsOperator(g, n_extra=2, upwind=False, boundary_P=0.0, boundary_C=1.0)
        n = op.n_cells
        self._op = op
        self._cell_area = np.ascontiguousarray(g.area)
        self._ones = np.ones(n)
        self._zeros = np.zeros(n)
        # dR/dp of the x faces and of the y faces for unit conductance (R is linear in p)
        mats = []
        for kx, kz in ((1.0, 0.0), (0.0, 1.0)):
            d = op.jacobian(self._ones, self._ones, self._ones, self._zeros, self._ones * kx, self._zeros,
                            self._ones * kz, self._zeros, self._zeros, self._zeros)
            mats.append(op.matrix(d)[:n, :n].tocsc())
        self._Dx, self._Dy = mats
        self._lu_cache = {}
        # CSC row / column of every pattern entry (for the state/residual scaling of the Jacobian)
        self._row = op.stencil.indices.copy()
        self._col = np.repeat(np.arange(op.n), np.diff(op.stencil.indptr))

    def _unit_pressure(self, h0):
        """q [Pa s/m] with p = phi_c (dh0/dt) q: solves (kx Dx + ky Dy) q = -A on the grid."""
        self._build_operator()
        px, py, _, _ = self.flow_factors(h0)
        c = h0 ** 3 / (12.0 * self.viscosity)
        key = round(py / px, 12)
        lu = self._lu_cache.get(key)
        if lu is None:
            if len(self._lu_cache) > 8:
                self._lu_cache.clear()
            lu = spla.splu((self._Dx + key * self._Dy).tocsc())
            self._lu_cache[key] = lu
        return lu.solve(-self._cell_area) / (px * c)

    # ---- equilibrium ------------------------------------------------------------------------------
    def equilibrium(self, load) -> float:
        """h0 [m] with W_asp(h0) = load: the steady limit of the rough pad (a parallel pad carries no
        steady film load). Direct root solve (brentq) of the monotone asperity load."""
        W = check_positive("load", load, "N")
        if self.contact is None:
            raise ValueError("equilibrium needs asperity contact: a smooth (or contact=None) parallel pad "
                             "has no steady state under load (its film only delays the approach)")
        f = lambda h: float(self.asperity_load(h)) - W  # noqa: E731
        s = self.sigma
        if self.density is not None:
            lo, hi = float(self.density.edges[0]), float(self.density.edges[-1])
        else:
            lo, hi = -8.0 * s, 40.0 * s
        while f(lo) < 0:
            lo -= 4.0 * s
            if lo < -1e3 * s:
                raise ValueError(f"load = {W:g} N is beyond the elastic contact model (W_asp(-1000 sigma) < load)")
        return float(brentq(f, lo, hi, xtol=1e-15 * s, rtol=1e-13, maxiter=200))

    # ---- transient --------------------------------------------------------------------------------
    def parameters(self) -> dict:
        """Every parameter of the pad that changes a descent (SI; the height density and the contact as digests of
        their numbers), e.g. to key a checkpoint."""
        c = self.contact
        return dict(length=self.length, width=self.width, viscosity=self.viscosity, grid=list(self.grid_shape),
                    sigma=self.sigma, gamma=self.gamma, density=_digest(self.density),
                    contact=None if c is None else dict(
                        {f.name: getattr(c, f.name) for f in fields(c) if f.name != "density"},
                        density=_digest(c.density)))

    def descent(self, load, h0_start=None, t_end=None, mass=0.0, *, path: str = "auto", n_out: int = 201,
                t_eval=None, start=None, integration: Integration | None = None, long_run: LongRun | None = None,
                **legacy) -> DescentResult:
        """Squeeze descent under a constant load W = ``load`` [N] from rest at h0 = ``h0_start`` [m], or from
        ``start`` (a previous :class:`DescentResult`, or ``(time [s], (h0 [m], dh0/dt [m/s]))``: the descent goes
        on from its final gap, speed and time, e.g. under another load), over ``t_end`` [s] from the start.

        ``mass`` [kg] (0: massless force balance, eq. 14 with F_tot = 0; the start's speed is then the balance's);
        ``path`` "auto" (= separable), "full" (2-D film: a DAE with the analytic sparse Jacobian for ida, the
        pressure eliminated by a 2-D solve per right-hand side for ODE methods) or "separable" (scalar ODE);
        outputs at ``t_eval`` [s] (increasing, from 0 to t_end, counted from the start) or ``n_out`` equally spaced
        times.

        The settings that are not physics come as objects: ``integration``
        (:class:`~transient.solvers.settings.Integration`; default ``Integration(method="cvode")``): ``method``
        one of the methods that need no step solve of the model's own (ida, cvode, bdf, radau, lsoda, rk4), ``rtol``
        and ``atol`` on the scaled states (h0/h0_start, v/v_ref, p/p_ref; all O(1)), ``dt`` [s] the fixed step of
        rk4 (required there), ``linear_solver``; ``long_run`` (:class:`~transient.solvers.settings.LongRun`):
        ``checkpoint`` (an ``.npz`` rewritten after each tenth of the outputs; ``resume=True`` continues from it bit
        for bit), ``progress``, ``stop(result_so_far)``, ``time_budget`` [s]. Ctrl-C says where the checkpoint is.
        The loose keywords of earlier releases (``method=``, ``rtol=``, ``atol=``, ``dt=``) are deprecated: they
        still work for one release, with a ``DeprecationWarning`` naming the new spelling.
        """
        check_method(DESCENT_OWNER, requested_method(integration, legacy, "cvode"))
        ig = run_settings(DESCENT_OWNER, legacy, DESCENT_KEYWORDS, DESCENT_DEFAULTS, integration=integration)[
            "integration"]
        lr = LongRun() if long_run is None else check_instance("long_run", long_run, LongRun, "None or LongRun(...)")
        check_method(DESCENT_OWNER, ig.method)
        check_unused(DESCENT_OWNER, "integration", ig, ("formulation", "steps_per_revolution"))
        check_unused(DESCENT_OWNER, "long_run", lr, ("chunk_revolutions",))
        W = check_range("load", load, "N", 0.0, 1e9, low_open=True)
        t_end = check_range("t_end", t_end, "s", 0.0, 1e6, low_open=True)
        M = check_range("mass", mass, "kg", 0.0, 1e6)
        check_range("rtol", ig.rtol, "-", 1e-14, 0.1)
        if path not in PATHS:
            raise ValueError(f"path must be one of {PATHS}, got {path!r}")
        if t_eval is None:
            n_out = check_int("n_out", n_out, "-", 2, 1e7)
            t_eval = np.linspace(0.0, t_end, n_out)
        else:
            t_eval = np.asarray(t_eval, dtype=float)
            if t_eval.ndim != 1 or t_eval.size < 2 or t_eval[0] != 0.0 or abs(t_eval[-1] - t_end) > 1e-12 * t_end \
                    or np.any(np.diff(t_eval) <= 0):
                raise ValueError("t_eval must run from 0 to t_end [s], increasing")
        if ig.method == "rk4" and ig.dt is None:
            raise ValueError("method 'rk4' needs dt [s] (fixed step): integration=Integration(method='rk4', dt=...)")
        if ig.method == "rk4" and ig.inner_tolerance != RK4_INNER_TOLERANCE:
            raise ValueError(f"inner_tolerance = {ig.inner_tolerance!r} [-] is not used by {DESCENT_OWNER} (no inner "
                             "solve per stage); allowed: leave it out")
        path = "separable" if path == "auto" else path
        check_descent_memory(self.grid_shape[0] * self.grid_shape[1], t_eval.size, path)
        t0, h_s, v_s = self._descent_start(start, h0_start)
        # scales: v_ref = the massless rate at the start (or h_s / t_end if the pad starts balanced)
        v0 = (float(self.asperity_load(h_s)) - W) / self._K_series(h_s)
        v_ref = max(abs(v0), h_s / t_end)
        sc = dict(W=W, M=M, h=h_s, v=v_ref, p=W / self.area)
        if path == "full" and ig.method == "ida":
            sysm = _FullDAE(self, sc)
        else:
            sysm = _ReducedODE(self, sc, grid=path == "full")
        run = ModelRun.at_times(t_eval.size - 1, lr)
        key = dict(self.parameters(), load=W, mass=M, path=path, **ig.key(), dt=ig.dt, start_speed=v_s,
                   h0_start=h_s, outputs=_digest(t_eval))
        solver = dict(method=ig.method, rtol=ig.rtol, atol=ig.atol, linear_solver=ig.linear_solver,
                      steps=Steps(dt=ig.dt))
        parts = RunParts(label=f"pad descent {W:g} N", omega=1.0, revolution=1.0, unit="s",
                         problem_at=sysm.problem_at, solver=solver, series=sysm.series, sample=sysm.sample,
                         journals=lambda y: [], eccentricities=lambda r: [], touch_message=None,
                         result=lambda rec, stats, touched, message, t: self._descent_result(
                             sysm, rec, stats, message, ig.method, path),
                         key=key, status=lambda: "")
        return run.go(parts, sysm.state(h_s, v_s), t0, t0 + t_eval)

    def _descent_start(self, start, h0_start) -> tuple:
        """``(t0 [s], h0 [m], dh0/dt [m/s])`` of a descent: from rest at ``h0_start`` or from ``start``."""
        if start is None:
            return 0.0, check_range("h0_start", h0_start, "m", 1e-9, 1e-2, why="(1 nm to 10 mm)"), 0.0
        if h0_start is not None:
            raise ValueError(f"h0_start = {h0_start!r} [m] and start both given; allowed: one of them")
        t0, y = start_point(start, DescentResult)
        if y.shape != (2,):
            raise ValueError(f"start: a state of shape {y.shape}; a descent's state is (h0 [m], dh0/dt [m/s])")
        h = check_range("start h0", y[0], "m", 1e-9, 1e-2, why="(1 nm to 10 mm)")
        return t0, h, check_range("start dh0/dt", y[1], "m/s", -1e3, 1e3)

    def _descent_result(self, sysm, rec, stats, message, method, path) -> DescentResult:
        """The result of a descent from its recorder (:class:`~transient.solvers.model_run.RunParts`)."""
        a = rec.arrays()
        out = sysm.outputs(a)
        pres = sysm.pressure(rec.last_y) if isinstance(sysm, _FullDAE) and rec.last_y is not None else None
        success = True  # the run's own outcome joins it (ModelRun.go)
        if not np.all(np.isfinite(out["h0"]) & (out["h0"] > 0)):
            success, message = False, (f"the gap closed (h0 <= 0 at t = {a['t'][np.argmax(~(out['h0'] > 0))]:.6g} "
                                       "s): the load is not carried by this pad's film and contact")
        final = sysm.public(rec.last_y) if rec.last_y is not None else None
        return DescentResult(t=a["t"], load=sysm.sc["W"], mass=sysm.sc["M"], path=path, method=method,
                             stats=stats, success=success, message=message, pressure=pres, final_state=final,
                             final_time=float(a["t"][-1]) if len(a["t"]) else 0.0, **out)


def _digest(x):
    """A short digest of the numbers in ``x`` (an array, a dataclass of arrays, or None)."""
    if x is None:
        return None
    arrays = [np.asarray(getattr(x, f.name)) for f in fields(x)] if hasattr(x, "__dataclass_fields__") else [x]
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(a, dtype=float).tobytes())
    return h.hexdigest()[:16]


# --------------------------------------------------------------------------------------------------
# the two formulations
# --------------------------------------------------------------------------------------------------

class _ReducedODE:
    """ODE in (h0) (massless) or (h0, v) (mass > 0) with W_hyd = -K(h0) v; K from the series
    (separable path) or from the 2-D grid solve per call (full path with an ODE method)."""

    def __init__(self, pad: ThrustPad, sc, grid: bool):
        self.pad, self.sc, self.grid = pad, sc, grid
        self.K = pad._K_grid if grid else pad._K_series

    def rates(self, h):
        """(K, W_asp) at h."""
        return self.K(h), float(self.pad.asperity_load(h))

    @property
    def series(self) -> tuple:
        """What a run records at each output (:meth:`sample`): the scaled states."""
        return ("h",) if self.sc["M"] == 0.0 else ("h", "v")

    def state(self, h, v) -> np.ndarray:
        """The run's state at the gap ``h`` [m] moving at ``v`` [m/s] (massless: the speed is the balance's)."""
        sc = self.sc
        return np.array([h / sc["h"]]) if sc["M"] == 0.0 else np.array([h / sc["h"], v / sc["v"]])

    def public(self, y) -> np.ndarray:
        """``(h0 [m], dh0/dt [m/s])`` of a run's state (a result's ``final_state``)."""
        h = y[0] * self.sc["h"]
        if self.sc["M"] > 0.0:
            return np.array([h, y[1] * self.sc["v"]])
        K, Wa = self.rates(h)
        return np.array([h, (Wa - self.sc["W"]) / K])

    def sample(self, t, y) -> dict:
        return dict(h=y[0]) if self.sc["M"] == 0.0 else dict(h=y[0], v=y[1])

    def problem_at(self, y, t) -> Problem:
        sc = self.sc
        hr, vr, W, M = sc["h"], sc["v"], sc["W"], sc["M"]
        if M == 0.0:
            def rhs(t, y, out):
                h = y[0] * hr
                K, Wa = self.rates(h)
                out[0] = (Wa - W) / K / hr  # d(h/hr)/dt
            return Problem(y0=np.array(y, dtype=float), rhs=rhs, name="thrust pad (massless, reduced)")

        def rhs(t, y, out):
            h, v = y[0] * hr, y[1] * vr
            K, Wa = self.rates(h)
            out[0] = v / hr
            out[1] = (-K * v + Wa - W) / M / vr
        return Problem(y0=np.array(y, dtype=float), rhs=rhs, name="thrust pad (mass, reduced)")

    def outputs(self, a):
        """The result's series from the recorded arrays ``a``."""
        sc = self.sc
        h = a["h"] * sc["h"]
        pad = self.pad
        K = np.array([self.K(x) for x in h])
        wa = np.asarray(pad.asperity_load(h), dtype=float) * np.ones_like(h)
        if sc["M"] == 0.0:
            v = (wa - sc["W"]) / K
        else:
            v = a["v"] * sc["v"]
        return dict(h0=h, dh0_dt=v, w_hyd=-K * v, w_asp=wa,
                    contact_area=np.asarray(pad.contact_area(h), dtype=float) * np.ones_like(h))


class _FullDAE:
    """The 2-D DAE ``[p_cells, h0, v]`` for IDA, scaled; residual and analytic sparse Jacobian."""

    def __init__(self, pad: ThrustPad, sc):
        pad._build_operator()
        self.pad, self.sc = pad, sc
        op = pad._op
        self.op = op
        self.n = n = op.n_cells
        self.N = N = op.n
        mu = pad.viscosity
        self.c3 = 1.0 / (12.0 * mu)
        # state scales S (y_SI = S * y) and residual row scales Rs (F_scaled = F_SI / Rs)
        S = np.empty(N)
        S[:n], S[n], S[n + 1] = sc["p"], sc["h"], sc["v"]
        Rs = np.empty(N)
        k_ref = sc["h"] ** 3 * self.c3
        Rs[:n] = k_ref * sc["p"]
        Rs[n] = sc["v"]
        Rs[n + 1] = sc["W"]
        self.S, self.Rs = S, Rs
        self.fac = S[pad._col] / Rs[pad._row]
        self.A = pad._cell_area
        self.kx = np.empty(n)
        self.kz = np.empty(n)
        self.dq = (np.zeros((2, n)), np.zeros((2, n)), np.zeros((2, n)), np.zeros((2, n)))
        self.res_args = op.face_tuples + (op.no_face_k,)
        self.st = op.stencil
        # positions of the dense-row entries
        self.pos_hh = int(self.st.pos_row_extra[0, n])
        self.pos_hv = int(self.st.pos_row_extra[0, n + 1])
        self.pos_vp = np.ascontiguousarray(self.st.pos_row_extra[1, :n])
        self.pos_vh = int(self.st.pos_row_extra[1, n])
        self.pos_vv = int(self.st.pos_row_extra[1, n + 1])
        self.pos_ch = np.ascontiguousarray(self.st.pos_col_extra[:n, 0])
        self.pos_cv = np.ascontiguousarray(self.st.pos_col_extra[:n, 1])

    def _fields(self, h):
        pad = self.pad
        px, py, dpx, dpy = pad.flow_factors(h)
        pc, dpc = pad.contact_factor(h)
        Wa = float(pad.asperity_load(h))
        dWa = float(pad.asperity_load_derivative(h))
        return px, py, dpx, dpy, pc, dpc, Wa, dWa

    def residual(self, t, y, yp, out):
        n, S = self.n, self.S
        p = y[:n] * S[0]
        h = y[n] * S[n]
        v = y[n + 1] * S[n + 1]
        px, py, _, _, pc, _, Wa, _ = self._fields(h)
        c = h ** 3 * self.c3
        self.kx.fill(px * c)
        self.kz.fill(py * c)
        z = self.pad._zeros
        residual_kernel(p, p, self.pad._ones, self.kx, self.kz, z, z, False, *self.res_args, out)
        out[:n] += self.A * (pc * v)
        out[:n] /= self.Rs[0]
        out[n] = (yp[n] * S[n] - v) / self.Rs[n]
        w_hyd = float(self.A @ p)
        out[n + 1] = (self.sc["M"] * yp[n + 1] * S[n + 1] - (w_hyd + Wa - self.sc["W"])) / self.Rs[n + 1]

    def jacobian(self, t, y, yp, cj, data):
        n, S = self.n, self.S
        pad = self.pad
        p = y[:n] * S[0]
        h = y[n] * S[n]
        v = y[n + 1] * S[n + 1]
        px, py, dpx, dpy, pc, dpc, Wa, dWa = self._fields(h)
        c = h ** 3 * self.c3
        dc = 3.0 * h ** 2 * self.c3
        self.kx.fill(px * c)
        self.kz.fill(py * c)
        dkx, dkz = self.dq[0], self.dq[1]
        dkx[0].fill(dpx * c + px * dc)
        dkz[0].fill(dpy * c + py * dc)
        o, z = pad._ones, pad._zeros
        self.op.jacobian(p, o, o, z, self.kx, z, self.kz, z, z, z, dq=self.dq, data=data)
        data[self.pos_ch] += self.A * (dpc * v)
        data[self.pos_cv] += self.A * pc
        data[self.pos_vp] = -self.A
        data[self.pos_hh] = cj
        data[self.pos_hv] = -1.0
        data[self.pos_vh] = -dWa
        data[self.pos_vv] = cj * self.sc["M"]
        data *= self.fac  # d(F/Rs)/d(y/S) with y' scaled alike (cj acts on the scaled y')

    series = ("h", "v", "w_hyd")

    def state(self, h, v) -> np.ndarray:
        """The consistent state at the gap ``h`` [m] moving at ``v`` [m/s] (massless: on the force balance, the
        speed its own): the film's pressure ``p = phi_c v q(h)`` of that squeeze."""
        n, S, sc = self.n, self.S, self.sc
        pad = self.pad
        y0 = np.zeros(self.N)
        y0[n] = h / S[n]
        if sc["M"] == 0.0:
            v = (float(pad.asperity_load(h)) - sc["W"]) / pad._K_grid(h)
        y0[:n] = pad.contact_factor(h)[0] * v * pad._unit_pressure(h) / S[0]
        y0[n + 1] = v / S[n + 1]
        return y0

    def public(self, y) -> np.ndarray:
        """``(h0 [m], dh0/dt [m/s])`` of a run's state (a result's ``final_state``)."""
        n, S = self.n, self.S
        return np.array([y[n] * S[n], y[n + 1] * S[n + 1]])

    def pressure(self, y) -> np.ndarray:
        """The film pressure [Pa] (ny, nx) of a run's state."""
        nx, ny = self.pad.grid_shape
        return (y[:self.n] * self.S[0]).reshape(ny, nx)

    def sample(self, t, y) -> dict:
        n = self.n
        return dict(h=y[n], v=y[n + 1], w_hyd=float(self.A @ (y[:n] * self.S[0])))

    def problem_at(self, y, t) -> Problem:
        """The DAE from the consistent state ``y``: ``y'`` from the kinematics and the force balance."""
        n, S, sc = self.n, self.S, self.sc
        y0 = np.array(y, dtype=float)
        yp0 = np.zeros(self.N)
        h, v = y0[n] * S[n], y0[n + 1] * S[n + 1]
        yp0[n] = v / S[n]
        if sc["M"] > 0.0:
            w_hyd = float(self.A @ (y0[:n] * S[0]))
            yp0[n + 1] = (w_hyd + float(self.pad.asperity_load(h)) - sc["W"]) / sc["M"] / S[n + 1]
        alg = np.arange(n) if sc["M"] > 0 else np.concatenate([np.arange(n), [n + 1]])
        return Problem(y0=y0, yp0=yp0, residual=self.residual, jac_pattern=self.op.pattern,
                       jac_residual=self.jacobian, algebraic=alg, name="thrust pad (full 2-D DAE)")

    def outputs(self, a):
        """The result's series from the recorded arrays ``a``."""
        n, S = self.n, self.S
        h = a["h"] * S[n]
        pad = self.pad
        one = np.ones_like(h)
        return dict(h0=h, dh0_dt=a["v"] * S[n + 1], w_hyd=a["w_hyd"],
                    w_asp=np.asarray(pad.asperity_load(h), float) * one,
                    contact_area=np.asarray(pad.contact_area(h), float) * one)


def descent_memory(cells: int, n_out: int, path: str) -> dict:
    """Bytes a :meth:`ThrustPad.descent` will need, by part: ``grid`` (~30 arrays over the cells: film,
    factors, operator), ``jacobian`` (the full path's sparse Jacobian and LU factors, nested-dissection fill
    ~31/8 n log2 n entries of 12 bytes) and ``recordings`` (streamed, never the state: the time and up to three
    recorded numbers per output as Python floats in lists, 32 bytes each, then the result's six series)."""
    n = cells + 2 if path == "full" else 2
    return dict(grid=30.0 * 8 * cells,
                jacobian=12.0 * (5 * n + 31 / 8 * n * np.log2(max(n, 2))) if path == "full" else 0.0,
                recordings=n_out * (4 * 32.0 + 6 * 8.0 * 2))


def check_descent_memory(cells: int, n_out: int, path: str):
    """Refuse (one line) a descent whose :func:`descent_memory` exceeds the stated share of the machine, advising a
    coarser grid when the pad alone does not fit, else fewer outputs."""
    check_run_memory(f"this descent ({n_out} outputs on {cells} cells, {path} path)",
                     descent_memory(cells, n_out, path), "use a coarser grid",
                     "lower n_out (or pass fewer t_eval), or use a coarser grid")
