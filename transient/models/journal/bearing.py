"""Finite plain journal bearing with a mass-conserving Elrod film (default) or the classical
incompressible film with the Reynolds (Swift-Stieber) condition: steady film, static equilibrium,
linearised stiffness/damping and the Lund stability threshold (Rho & Kim, seed 003; issue 17).

All public arguments and results are SI (m, Pa, Pa s, N, rpm). The discretisation and the
dimensionless groups are in :mod:`transient.models.journal.kernels`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
from scipy.optimize import brentq

from transient.checks import check_bool, check_int, check_positive, check_range
from transient.fv.grid import Axis, Grid2D
from transient.models.journal.film import Film, omega
from transient.physics.layered import NO_LAYERS, BoundaryLayers, Gecim, LayeredFilm, Newtonian
from transient.models.journal.kernels import N_ROTOR
from transient.models.journal.reynolds_film import ReynoldsFilm

#: The cavitation models of :class:`JournalBearing` (``cavitation=``).
CAVITATION_MODES = ("elrod", "reynolds")
from transient.results import Result, quantity, result_type






SPEED_RANGE_RPM = (1e-3, 1e6)


def check_speed(speed_rpm) -> float:
    """A shaft speed [rpm] in ``SPEED_RANGE_RPM``."""
    return check_range("speed_rpm", speed_rpm, "rpm", *SPEED_RANGE_RPM)


class NoEquilibriumError(RuntimeError, ValueError):
    """The film cannot carry the load at this speed inside the clearance (names ``load`` and ``speed_rpm``)."""


VALIDITY_PRESSURE = 100e6  # [Pa]: exp(alpha p) = 7.4 for a mineral oil's alpha = 2e-8 1/Pa


def _warn_validity(state: "FilmState") -> "FilmState":
    """Warn when the film pressure leaves the isoviscous rigid model's range: above ``VALIDITY_PRESSURE`` a
    mineral oil's viscosity has grown sevenfold (Barus, alpha ~ 2e-8 1/Pa) and the bearing surfaces deform
    by a sizeable part of the film -- an EHL regime this model does not represent."""
    p = state.max_pressure
    if p > VALIDITY_PRESSURE:
        warnings.warn(f"the film pressure reaches {p / 1e6:.0f} MPa (e/C = {state.eccentricity_ratio:.3f}): above "
                      f"{VALIDITY_PRESSURE / 1e6:.0f} MPa the isoviscous rigid film is outside its validity "
                      f"(piezoviscosity and elastic deformation matter)", UserWarning, stacklevel=3)
    return state


@dataclass(frozen=True)
class Groove:
    """Axial oil-supply groove: centre angle from the top of the bearing (opposite the load) in the
    direction of rotation [deg], angular width [deg]. It spans the whole length; its cells are held
    at the bearing's supply pressure."""

    angle_deg: float = 0.0
    width_deg: float = 6.0

    def __post_init__(self):
        check_range("groove.angle_deg", self.angle_deg, "deg", -360.0, 360.0)
        check_range("groove.width_deg", self.width_deg, "deg", 0.0, 90.0, low_open=True)


@result_type
class FilmState(Result):
    """A film solution with the journal at a fixed position (and, optionally, moving).

    ``pressure`` [Pa, absolute] and ``film_content`` (theta = rho/rho_c) are (n_axial, n_theta) arrays on
    the modelled grid (half bearing when symmetric; row 0 next to the mid-plane); ``angle_deg`` and
    ``z`` [m] are the cell-centre coordinates. ``force`` [N] is the film force on the journal
    (x towards the load, y at +90 deg in the direction of rotation), ``load`` [N] its magnitude (the
    external load it carries) and ``attitude_angle_deg`` the angle from the load line to the line of
    centres, in the direction of rotation. ``friction_force`` [N]: the film's drag on the journal surface;
    ``bearing_friction_force`` [N]: its drag on the bearing surface, along the rotation
    (:func:`~transient.models.journal.film.wall_friction`; boundary layers and the Gecim bulk included).
    """

    time_axis = None
    eccentricity_ratio: float = quantity("-")
    attitude_angle_deg: float = quantity("deg")
    position: tuple[float, float] = quantity("m")
    force: tuple[float, float] = quantity("N")
    load: float = quantity("N")
    min_film: float = quantity("m")
    speed_rpm: float = quantity("rpm")
    pressure: np.ndarray = quantity("Pa")
    film_content: np.ndarray = quantity("-")
    angle_deg: np.ndarray = quantity("deg")
    z: np.ndarray = quantity("m")
    u: np.ndarray = quantity("-", repr=False)
    newton_iterations: int = 0
    friction_force: float = quantity("N", float("nan"))
    bearing_friction_force: float = quantity("N", float("nan"))
    film_thickness: np.ndarray = quantity("m", None, repr=False)
    pressure_gradient: np.ndarray = quantity("Pa/m", None, repr=False)
    axial_pressure_gradient: np.ndarray = quantity("Pa/m", None, repr=False)
    viscosity: float = quantity("Pa s", float("nan"))
    sliding_speed: float = quantity("m/s", float("nan"))
    layers: tuple | None = None  # (delta [m], mu_a [Pa s], mu_b [Pa s], alpha [m]) or None
    gecim: tuple | None = None  # the shear-thinning bulk (kappa [Pa], mu_2/mu_1) or None (Newtonian)
    success: bool = True
    message: str = "converged"

    @property
    def max_pressure(self) -> float:
        return float(self.pressure.max())

    def _law(self):
        """The film's flow law (:class:`~transient.physics.layered.LayeredFilm`, SI)."""
        ly = NO_LAYERS if self.layers is None else BoundaryLayers(self.layers[0], (self.layers[1], self.layers[2]),
                                                                  self.layers[3])
        return LayeredFilm(self.viscosity, Newtonian() if self.gecim is None else Gecim(*self.gecim), ly)

    def velocity_profile(self, angle_deg: float, axial_index: int = 0, points: int = 41):
        """Circumferential velocity across the film at the cell nearest ``angle_deg`` in axial row
        ``axial_index`` (0: next to the mid-plane): (heights z [m] from the journal surface, velocity [m/s]),
        from the film's flow law (seed 004: the journal moves at ``sliding_speed``, the bearing is at rest;
        boundary layers, if any, move with their walls plus their Darcy slip; a Gecim bulk through the 2-D law
        at the cell's circumferential and axial pressure gradients)."""
        ang = check_range("angle_deg", angle_deg, "deg", -360.0, 720.0)
        row = check_int("axial_index", axial_index, "-", 0, self.pressure.shape[0] - 1)
        n = check_int("points", points, "-", 2, 100000)
        col = int(np.argmin(np.abs(np.angle(np.exp(1j * np.radians(self.angle_deg - ang))))))
        h, G = float(self.film_thickness[row, col]), float(self.pressure_gradient[row, col])
        z = np.linspace(0.0, h, n)
        if self.gecim is None:
            return z, self._law().velocity(h, G, self.sliding_speed, 0.0, z)
        Gz = float(self.axial_pressure_gradient[row, col])
        return z, self._law().velocity_2d(h, (G, Gz), (self.sliding_speed, 0.0), (0.0, 0.0), z)[:, 0]

    def interface_shear(self, axial_index: int = 0):
        """Circumferential shear stress [Pa] at the journal-side and the bearing-side interface of the boundary
        layers (seed 004 eq. 28; the walls themselves without layers) along the angle in axial row
        ``axial_index``: (lower, upper) arrays over ``angle_deg``, from the film's flow law at each cell."""
        row = check_int("axial_index", axial_index, "-", 0, self.pressure.shape[0] - 1)
        h, G, Gz = self.film_thickness[row], self.pressure_gradient[row], self.axial_pressure_gradient[row]
        s = self._law().stresses_2d(h, np.stack([G, Gz], axis=-1), (self.sliding_speed, 0.0), (0.0, 0.0))
        return s.lower_interface[:, 0], s.upper_interface[:, 0]


class JournalBearing:
    """Plain journal bearing, Elrod (JFO) mass-conserving film or classical Reynolds-condition film,
    rigid journal.

    Parameters (SI)
    ----------
    diameter, length, clearance [m] : journal diameter D, bearing length L, radial clearance C.
    viscosity [Pa s], bulk_modulus [Pa] : mu and beta (paper: 1e9; 1e12 is the incompressible limit).
    supply_pressure [Pa, absolute] : pressure in the groove (paper: 1 atm).
    groove : :class:`Groove` or None (no groove: the film is fed only through its ends).
    grid : (n_theta, n_axial) cells; n_axial covers the half length when ``symmetric`` (paper 151 x 21).
    cavitation_pressure, ambient_pressure [Pa, absolute] : p_c and the pressure at the bearing ends
        (paper: both 0).
    switch_width [Pa] : pressure width of the smooth Elrod switch; it biases the load linearly
        (convergence study in docs/journal.md). Default ``None``: ``SWITCH_WIDTH_P0`` p0 at each speed
        (p0 = 6 mu omega (R/C)^2; 2.7 kPa for the paper's bearing at 6000 rpm), which keeps the bias
        the same at every speed (about +0.15 % on the load).
    switch_content_width [-] : content width of the switch (the film-content deficit over which a cell
        fills or empties); it hardly biases the film but sets how abruptly a cell turns at rupture and
        reformation, so a wider one saves the orbit integrator time steps (docs/journal.md, section 3).
    symmetric : model half the length with a symmetry plane at the mid-plane (exact for this model).
    cavitation : ``"elrod"`` (default) -- the mass-conserving, compressible Elrod film above; or
        ``"reynolds"`` -- the classical incompressible film with the Reynolds (Swift-Stieber) condition,
        ``p >= p_c`` solved as a complementarity problem on the same finite-volume stencil
        (:mod:`transient.models.journal.reynolds_film`; ``bulk_modulus`` and the switch widths are then
        unused). Both serve ``steady_state``, ``equilibrium``, ``coefficients`` and
        ``stability_threshold``; the time-domain orbit needs ``"elrod"``. The classical full 360 deg bearing
        of the design charts (Raimondi & Boyd) is ``cavitation="reynolds"`` with ``groove=None``.
    rheology : the bulk: ``None`` or :class:`~transient.physics.layered.Newtonian` (default, viscosity mu), or
        :class:`~transient.physics.layered.Gecim` (seed 004's shear-thinning bulk, low-shear viscosity mu =
        ``viscosity``): its Poiseuille flux is the 2-D layered flow law at every face
        (:mod:`transient.models.journal.gecim_film`, 9-point Jacobian), in every journal computation and
        both films.
    layers : :class:`~transient.physics.layered.BoundaryLayers` on journal and bearing (seed 004): the bulk is
        ``h - 2 delta`` thick and the layers add their Darcy flow (Newtonian bulk: a Poiseuille conductance,
        :func:`~transient.models.journal.kernels.conductances`); the film closes at ``e/C = 1 - 2 delta / C``
        (the orbit stops there: "boundary layers touch"). Default: none.
    """

    def __init__(self, diameter, length, clearance, viscosity, bulk_modulus=1e9, supply_pressure=101325.0,
                 groove: Groove | None = Groove(), grid=(151, 21), cavitation_pressure=0.0, ambient_pressure=0.0,
                 switch_width=None, switch_content_width=1e-2, symmetric=True, cavitation="elrod", rheology=None,
                 layers: BoundaryLayers | None = None):
        if not isinstance(cavitation, str) or cavitation not in CAVITATION_MODES:
            raise ValueError(f"cavitation must be one of {CAVITATION_MODES}, got cavitation={cavitation!r}")
        self.cavitation = cavitation
        self.diameter = check_range("diameter", diameter, "m", 0.0, 10.0, low_open=True)
        self.length = check_range("length", length, "m", 1e-3 * self.diameter, 10.0 * self.diameter,
                                  why=f"(L/D 0.001 to 10 with diameter = {self.diameter:g} m: longer is a long-bearing "
                                  "limit, not a journal bearing)")
        self.clearance = check_range("clearance", clearance, "m", 1e-5 * self.diameter, 0.1 * self.diameter,
                                     why="(C/D from 1e-5 to 0.1: a journal bearing's radial clearance)")
        self.viscosity = check_range("viscosity", viscosity, "Pa s", 1e-6, 1e4)
        self.bulk_modulus = check_range("bulk_modulus", bulk_modulus, "Pa", 1e6, 1e15,
                                        why="(oils ~1e9; 1e12 and above is the incompressible limit)")
        if rheology is not None and not isinstance(rheology, (Newtonian, Gecim)):
            raise TypeError(f"rheology must be None, Newtonian() or Gecim(kappa=..., viscosity_ratio=...), got "
                            f"{type(rheology).__name__}")
        self.rheology = Newtonian() if rheology is None else rheology
        self.shear_thinning = isinstance(self.rheology, Gecim)
        if layers is not None and not isinstance(layers, BoundaryLayers):
            raise TypeError(f"layers must be a BoundaryLayers or None, got {type(layers).__name__}")
        if layers is not None:
            check_range("layers.thickness", layers.thickness, "m", 0.0, 0.5 * self.clearance, high_open=True,
                        why="(two layers thinner than the clearance: the bulk must not vanish)")
        self.layers = layers
        self.cavitation_pressure = check_range("cavitation_pressure", cavitation_pressure, "Pa", 0.0, 1e9,
                                               why="(absolute pressure)")
        self.ambient_pressure = check_range("ambient_pressure", ambient_pressure, "Pa", cavitation_pressure, 1e9,
                                            why="(absolute; at least cavitation_pressure)")
        self.supply_pressure = check_range("supply_pressure", supply_pressure, "Pa", cavitation_pressure, 1e9,
                                           why="(absolute; at least cavitation_pressure)")
        self.switch_width = None if switch_width is None else check_positive("switch_width", switch_width, "Pa")
        self.switch_content_width = check_range("switch_content_width", switch_content_width, "-", 0.0, 0.1,
                                                low_open=True, why="(a content deficit; above 0.1 the switch "
                                                "smears the cavitated zone)")
        if groove is not None and not isinstance(groove, Groove):
            raise TypeError(f"groove must be a Groove or None, got {type(groove).__name__}")
        self.groove = groove
        self.unsupplied = cavitation == "elrod" and groove is None and self.ambient_pressure <= self.cavitation_pressure
        if self.unsupplied:
            warnings.warn("JournalBearing: the Elrod film has no oil supply (groove=None and ambient_pressure <= "
                          "cavitation_pressure: nothing drives oil into the film, which starves); add a Groove, "
                          "raise the ambient pressure, or use cavitation=\"reynolds\" for the classical 360-deg "
                          "bearing", UserWarning, stacklevel=2)
        if isinstance(grid, (str, bytes)) or not hasattr(grid, "__len__") or len(grid) != 2:
            raise ValueError(f"grid must be (n_theta, n_axial) cells, got {grid!r}")
        n_theta = check_int("grid[0] (n_theta)", grid[0], "cells", 8, 20000)
        n_axial = check_int("grid[1] (n_axial)", grid[1], "cells", 1, 5000)
        self.grid_shape = (n_theta, n_axial)
        self.symmetric = check_bool("symmetric", symmetric)
        self.radius = 0.5 * self.diameter
        self._build_grid()

    # ---------------------------------------------------------------------------------------------
    def _build_grid(self):
        n_theta, n_axial = self.grid_shape
        R = self.radius
        half = 0.5 * self.length / R
        x = Axis.uniform(n_theta, 2 * np.pi, start=0.0, centred=True, periodic=True, name="theta")
        if self.symmetric:
            z = Axis.uniform(n_axial, half, start=0.0, lower="symmetry", upper="dirichlet", name="z")
        else:
            z = Axis.uniform(n_axial, 2 * half, start=-half, lower="dirichlet", upper="dirichlet", name="z")
        fixed = None
        if self.groove is not None:
            phi = x.centres
            dphi = np.angle(np.exp(1j * (phi - np.radians(self.groove.angle_deg))))
            in_groove = np.abs(dphi) <= 0.5 * np.radians(self.groove.width_deg) + 1e-12
            if not in_groove.any():
                in_groove[np.argmin(np.abs(dphi))] = True  # a groove narrower than a cell takes the nearest cell
            fixed = np.tile(in_groove, z.n)
        self.grid = Grid2D(x, z, fixed=fixed, fixed_values=0.0)
        self.phi = self.grid.xc.copy()
        self.n_cells = self.grid.n

    def parameters(self) -> dict:
        """Every parameter that changes the film (SI; the groove as its angle and width [deg])."""
        g = self.groove
        return dict(diameter=self.diameter, length=self.length, clearance=self.clearance, viscosity=self.viscosity,
                    bulk_modulus=self.bulk_modulus, supply_pressure=self.supply_pressure,
                    groove=None if g is None else [g.angle_deg, g.width_deg], grid=list(self.grid_shape),
                    cavitation_pressure=self.cavitation_pressure, ambient_pressure=self.ambient_pressure,
                    switch_width=self.switch_width, switch_content_width=self.switch_content_width,
                    symmetric=self.symmetric, cavitation=self.cavitation,
                    layers=None if self.layers is None else dict(thickness=self.layers.thickness,
                                                                 viscosity=list(self.layers.viscosity),
                                                                 alpha=self.layers.alpha),
                    rheology=None if not self.shear_thinning else dict(
                        kappa=self.rheology.kappa, viscosity_ratio=self.rheology.viscosity_ratio))

    def layer_groups(self) -> tuple[float, float]:
        """The boundary layers in the film's scales: ``(2 delta / C, 3 alpha^2 mu (1/mu_a + 1/mu_b) / C^2)``
        (:func:`~transient.models.journal.kernels.conductances`); ``(0, 0)`` without layers."""
        ly = self.layers
        if ly is None:
            return 0.0, 0.0
        darcy = 3.0 * ly.alpha ** 2 * self.viscosity * (1.0 / ly.viscosity[0] + 1.0 / ly.viscosity[1])
        return 2.0 * ly.thickness / self.clearance, darcy / self.clearance ** 2

    @property
    def max_eccentricity_ratio(self) -> float:
        """Largest e/C with a film: 1, less the two boundary layers (2 delta / C)."""
        return 1.0 - self.layer_groups()[0]

    def pressure_scale(self, speed_rpm) -> float:
        """p0 = 6 mu omega (R/C)^2 [Pa], the dimensionless pressure unit at this speed."""
        return 6.0 * self.viscosity * omega(speed_rpm) * (self.radius / self.clearance) ** 2

    def film(self, speed_rpm, n_extra=N_ROTOR) -> "Film | ReynoldsFilm":
        """The discretised film at a shaft speed (scales, operator, scratch arrays): a :class:`Film`
        (Elrod) or a :class:`~transient.models.journal.reynolds_film.ReynoldsFilm` (``cavitation="reynolds"``)."""
        if self.cavitation == "reynolds":
            return ReynoldsFilm(self, speed_rpm, n_extra)
        return Film(self, speed_rpm, n_extra)

    def _check_supplied(self):
        """A steady Elrod film needs a supply: without one every starved content field is a steady state."""
        if self.unsupplied:
            raise ValueError("groove = None with ambient_pressure <= cavitation_pressure: the Elrod film has no oil "
                             "supply and no unique steady state; add a Groove, raise the ambient pressure, or use "
                             "cavitation=\"reynolds\" (the classical 360-deg bearing)")

    # ---------------------------------------------------------------------------------------------
    def steady_state(self, eccentricity_ratio, speed_rpm, position_angle_deg=0.0) -> FilmState:
        """Film with the journal held at eccentricity ratio ``eps`` in the direction ``position_angle_deg``
        (from the load line +x, in the direction of rotation); a direct Newton solve (Elrod) or the
        active-set solve of the complementarity problem (Reynolds)."""
        eps = check_range("eccentricity_ratio", eccentricity_ratio, "-", 0.0, self.max_eccentricity_ratio,
                          high_open=True, why="(the film, less its boundary layers, must be open everywhere)"
                          if self.layers is not None else "")
        check_speed(speed_rpm)
        a = np.radians(position_angle_deg)
        self._check_supplied()
        f = self.film(speed_rpm)
        u, its = f.solve(eps * np.cos(a), eps * np.sin(a))
        return _warn_validity(f.state(u, eps * np.cos(a), eps * np.sin(a), its))

    def equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40) -> FilmState:
        """Static equilibrium under ``load`` [N] (in +x): 2-D Newton on the journal position with the
        exact derivative of the discrete film force (implicit differentiation of the film equations)."""
        f, u, q, it, _ = self._equilibrium(load, speed_rpm, tol, max_iter)
        return _warn_validity(f.state(u, q[0], q[1], it))

    def coefficients(self, load, speed_rpm) -> tuple[np.ndarray, np.ndarray]:
        """Linearised stiffness K [N/m] and damping C [N s/m] (2x2, x towards the load) at the static
        equilibrium, from the same discrete film: ``K = -dF/dx``, ``C = -dF/d(dx/dt)``."""
        f, _, _, _, (dF_dq, dF_dv) = self._equilibrium(load, speed_rpm)
        K = -dF_dq * f.force_scale / self.clearance
        Cmat = -dF_dv * f.force_scale / (self.clearance * omega(speed_rpm))
        return K, Cmat

    def _equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40):
        """Newton on the journal position (either film: both give the force and its exact sensitivities; the
        Reynolds film's on its converged active set); returns (film, u, (X, Y), iterations, (dF/dq, dF/dv)) with the
        force sensitivities at the converged state (they are the Newton matrix and the damping)."""
        W = check_positive("load", load, "N")
        check_speed(speed_rpm)
        self._check_supplied()
        f = self.film(speed_rpm)
        wbar = W / f.force_scale
        q = np.array([0.3, 0.3])  # eccentric start in the loaded quadrant
        u = None
        for it in range(max_iter):
            u, _ = f.solve(q[0], q[1], u0=u)
            F, dF_dq, dF_dv = f.force_sensitivity(u, q[0], q[1])
            r = np.array([F[0] + wbar, F[1]])
            if np.max(np.abs(r)) <= tol * max(wbar, 1e-300):
                return f, u, q, it, (dF_dq, dF_dv)
            dq = -np.linalg.solve(dF_dq, r)
            lam = 1.0  # keep the journal inside the clearance
            while np.hypot(*(q + lam * dq)) >= 0.995 * self.max_eccentricity_ratio:
                lam *= 0.5
            q = q + lam * dq
        raise NoEquilibriumError(f"equilibrium(load={W} N, speed_rpm={speed_rpm}) did not converge in {max_iter} "
                           f"iterations; last eccentricity ratio {np.hypot(*q):.4f}, force residual "
                           f"{np.max(np.abs(r)) * f.force_scale:.3e} N")

    def unbalance_response(self, rotor_mass, unbalance, load, speed_rpm) -> np.ndarray:
        """Steady unbalance response of the linearised rotor ``m x'' + C x' + K x = m e W^2 (cos, sin)``:
        complex amplitudes Z [m] with ``x(t) = Re(Z_x e^{i W t})``, ``y(t) = Re(Z_y e^{i W t})``."""
        K, Cm = self.coefficients(load, speed_rpm)
        w = omega(speed_rpm)
        A = K + 1j * w * Cm - rotor_mass * w * w * np.eye(2)
        return np.linalg.solve(A, rotor_mass * unbalance * w * w * np.array([1.0, -1j]))

    def growth_rate(self, rotor_mass, load, speed_rpm) -> float:
        """Largest real part [1/s] of the eigenvalues of the linearised rotor (m x'' + C x' + K x = 0)."""
        K, Cm = self.coefficients(load, speed_rpm)
        m = rotor_mass
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K / m, -Cm / m]])
        return float(np.max(sla.eigvals(A).real))

    def stability_threshold(self, rotor_mass, load, speed_range_rpm=(500.0, 30000.0), rtol=1e-4) -> float:
        """Onset speed of oil whirl [rpm] of a rigid rotor of mass ``rotor_mass`` [kg] carried by this
        bearing under ``load`` [N]: the speed at which the linearised system (Lund's method, with K and C
        from the same discrete film) first has an eigenvalue with zero real part."""
        m = check_positive("rotor_mass", rotor_mass, "kg")
        check_positive("load", load, "N")
        lo, hi = speed_range_rpm
        g = lambda n: self.growth_rate(m, load, n)
        speeds = np.geomspace(lo, hi, 9)
        vals = [g(n) for n in speeds]
        for k in range(len(speeds) - 1):
            if vals[k] < 0 <= vals[k + 1]:
                return float(brentq(g, speeds[k], speeds[k + 1], rtol=rtol))
        raise ValueError(f"no stability threshold between {lo} and {hi} rpm for rotor_mass={m} kg, load={load} N "
                         f"(largest growth rates {vals[0]:.3g} ... {vals[-1]:.3g} 1/s)")


