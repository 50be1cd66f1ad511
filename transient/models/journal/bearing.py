"""Finite plain journal bearing with a mass-conserving Elrod film (default) or the classical
incompressible film with the Reynolds (Swift-Stieber) condition: steady film, static equilibrium,
linearised stiffness/damping and the Lund stability threshold (Rho & Kim).

All public arguments and results are SI (m, Pa, Pa s, N, rpm). The discretisation and the
dimensionless groups are in :mod:`transient.models.journal.kernels`.
"""

from __future__ import annotations

import copy
import warnings
from dataclasses import asdict

import numpy as np
import scipy.linalg as sla
from scipy.optimize import brentq

from transient.checks import check_bool, check_int, check_memory, check_positive, check_range
from transient.fv.grid import Axis, Grid2D, interpolate_cells
from transient.models.journal.feeds import (CircumferentialGroove, Groove, as_feeds, check_feeds, check_resolution,
                                            feed_labels, feed_name)
from transient.models.journal.film import Film
from transient.models.journal.gecim_film import flow_law
from transient.physics.layered import BoundaryLayers, Gecim, Newtonian
from transient.models.journal.kernels import N_ROTOR
from transient.models.journal.reynolds_film import ReynoldsFilm
from transient.models.journal.rough_film import RoughFilm
from transient.models.journal.roughness import Roughness
from transient.models.journal.scales import film_scales
from transient.models.journal.tilt import (check_open, check_tilt, edge_eccentricities, half_length, sensitivity,
                                           si_coefficients, tilt_groups)
from transient.models.journal import rest, thd
from transient.models.journal.errors import NoEquilibriumError
from transient.models.journal.thermal_settings import ThermalFilm
from transient.models.journal.viscous_film import ViscousFilm
from transient.units import rpm_to_rad_s as omega  # the journal's name for it (public: models.journal.omega)

#: The cavitation models of :class:`JournalBearing` (``cavitation=``).
CAVITATION_MODES = ("elrod", "reynolds")
from transient.models.journal.results import FilmState  # noqa: F401 (its home was here)






SPEED_RANGE_RPM = (1e-3, 1e6)
#: Largest e/C an equilibrium iterate of a rough bearing with a Winkler bore may take (the bore's give included).
ELASTIC_REACH = 1.5
REST_UNIT_RPM = 1.0  # [rpm] the pressure unit of a rough film at rest (its journal does not turn)
ELASTIC_STEP = 0.05  # [C] the longest equilibrium step of a rough bearing with a Winkler bore
#: A rough bearing's equilibrium by continuation in speed (:meth:`JournalBearing._continued_equilibrium`) starts at
#: this multiple of the speed, and at least at ``CONTINUATION_START_RPM`` [rpm].
CONTINUATION_SPEED_RATIO = 1000.0
CONTINUATION_START_RPM = 1000.0

#: Grid sequencing of the steady Elrod film (:meth:`JournalBearing.film_solve`; measured in docs/validation.md, "The
#: steady film on fine grids"): a grid of more cells than ``SEQUENCE_CELLS`` starts from the film of the grid with half
#: its circumferential cells, interpolated, as long as that keeps at least ``SEQUENCE_MIN_THETA`` of them (a coarser
#: film puts the fronts too far from the finer one's: 50 x 102 -> 100 x 102 took 36 Newton iterations, 15 from rest).
SEQUENCE_CELLS = 10_000
SEQUENCE_MIN_THETA = 100


#: Memory per film cell [bytes], peak resident memory measured on the 200 x 50 and 400 x 100 grids
#: (docs/validation.md, "Memory before a run"): the grid's arrays (what the constructor builds: 60-75), the film at one
#: speed (operator tables and scratch arrays: 1020-1030) and a steady solve or equilibrium with it (Jacobian of
#: 13 entries per cell, SuperLU's factors, Newton's work: 6.3-6.5 kB in all).
GRID_BYTES_PER_CELL = 100.0
FILM_BYTES_PER_CELL = 1100.0
STEADY_BYTES_PER_CELL = 6500.0
#: The advice of every refusal for the size of a bearing's grid.
GRID_ADVICE = "use a coarser grid (JournalBearing(grid=(n_theta, n_axial)) with fewer cells)"


def bearing_memory(n_cells) -> dict:
    """Bytes a bearing of ``n_cells`` film cells needs to be built and have its film solved once (a steady state, an
    equilibrium), by part: ``grid``, ``film`` and ``steady solve`` (the per-cell costs above)."""
    return {"grid": GRID_BYTES_PER_CELL * n_cells, "film": FILM_BYTES_PER_CELL * n_cells,
            "steady solve": (STEADY_BYTES_PER_CELL - FILM_BYTES_PER_CELL) * n_cells}


def check_bearing_memory(grid_shape) -> float:
    """Refuse, before any array is allocated, a grid whose film this machine cannot build and solve
    (:func:`~transient.checks.check_memory`, :func:`bearing_memory`), naming the grid."""
    n = int(grid_shape[0]) * int(grid_shape[1])
    return check_memory(f"a journal bearing on grid = ({grid_shape[0]}, {grid_shape[1]}) ({n} cells)",
                        bearing_memory(n), GRID_ADVICE)


def check_speed(speed_rpm) -> float:
    """A shaft speed [rpm] in ``SPEED_RANGE_RPM``."""
    return check_range("speed_rpm", speed_rpm, "rpm", *SPEED_RANGE_RPM)


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


class JournalBearing:
    """Plain journal bearing, Elrod (JFO) mass-conserving film or classical Reynolds-condition film,
    rigid journal.

    Parameters (SI)
    ----------
    diameter, length, clearance [m] : journal diameter D, bearing length L, radial clearance C.
    viscosity [Pa s], bulk_modulus [Pa] : mu and beta (paper: 1e9; 1e12 is the incompressible limit).
    supply_pressure [Pa, absolute] : pressure in the groove (paper: 1 atm).
    groove : the oil feeds (:mod:`transient.models.journal.feeds`): a :class:`Groove` (axial, full or partial
        length), an :class:`~transient.models.journal.feeds.OilHole`, a
        :class:`~transient.models.journal.feeds.CircumferentialGroove`, a sequence of them, or None (no feed: the
        film is fed only through its ends). Each feed is held at its own pressure (default ``supply_pressure``).
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
    symmetric : model half the length with a symmetry plane at the mid-plane (exact for this model) -- only when
        every feed is symmetric about the mid-plane; otherwise the whole length is modelled with ``2 n_axial``
        cells (``self.symmetric`` is then False).
    cavitation : ``"elrod"`` (default) -- the mass-conserving, compressible Elrod film above; or
        ``"reynolds"`` -- the classical incompressible film with the Reynolds (Swift-Stieber) condition,
        ``p >= p_c`` solved as a complementarity problem on the same finite-volume stencil
        (:mod:`transient.models.journal.reynolds_film`; ``bulk_modulus`` and the switch widths are then
        unused). Both serve ``steady_state``, ``equilibrium``, ``coefficients`` and
        ``stability_threshold``; the time-domain orbit needs ``"elrod"``. The classical full 360 deg bearing
        of the design charts (Raimondi & Boyd) is ``cavitation="reynolds"`` with ``groove=None``.
    rheology : the bulk: ``None`` or :class:`~transient.physics.layered.Newtonian` (default, viscosity mu), or
        :class:`~transient.physics.layered.Gecim` (Jang's shear-thinning bulk, low-shear viscosity mu =
        ``viscosity``): its Poiseuille flux is the 2-D layered flow law at every face
        (:mod:`transient.models.journal.gecim_film`, 9-point Jacobian), in every journal computation and
        both films.
    layers : :class:`~transient.physics.layered.BoundaryLayers` on journal and bearing (Jang): the bulk is
        ``h - 2 delta`` thick and the layers add their Darcy flow (Newtonian bulk: a Poiseuille conductance,
        :func:`~transient.models.journal.kernels.conductances`); the film closes at ``e/C = 1 - 2 delta / C``
        (the orbit stops there: "boundary layers touch"). Default: none.
    roughness : :class:`~transient.models.journal.roughness.Roughness` -- rough surfaces (mixed lubrication): the
        average Reynolds equation of Patir & Cheng in the Elrod film and Greenwood-Tripp asperity contact beside the
        film pressure (:mod:`transient.models.journal.rough_film`) in ``steady_state``, ``equilibrium`` and
        ``coefficients``; the friction torque adds the boundary friction of the contacts. Newtonian bulk without
        boundary layers, ``cavitation="elrod"``. Default None: smooth surfaces.
    misalignment : (tilt about x, tilt about y) [rad] of the bush (the bearing's static misalignment; axes and signs
        in :mod:`transient.models.journal.tilt`): the film feels the journal's tilt relative to it
        (``steady_state(..., tilt=)``, ``equilibrium``, ``coefficients``), and the whole length is modelled. Smooth
        films; the time-domain orbit and the rotor system take aligned bearings. Default (0, 0).
    thermal : :class:`~transient.models.journal.thermal_settings.ThermalFilm` -- a thermal (THD) film: the viscosity
        of every cell at its temperature, the temperatures from the film-averaged energy equation
        (:mod:`transient.models.journal.thd`) in ``steady_state``, ``equilibrium``, ``coefficients`` (at frozen
        temperatures) and ``stability_threshold``; the result carries the temperatures and heat flows. ``viscosity``
        may then be None: the oil's viscosity at the supply temperature (it is only the pressure unit's reference).
        Elrod film, Newtonian bulk without boundary layers, smooth surfaces; steady computations only (the orbit and
        the rotor system refuse it). Default None: the isothermal film of viscosity ``viscosity``.
    """

    def __init__(self, diameter, length, clearance, viscosity=None, bulk_modulus=1e9, supply_pressure=101325.0,
                 groove: Groove | None = Groove(), grid=(151, 21), cavitation_pressure=0.0, ambient_pressure=0.0,
                 switch_width=None, switch_content_width=1e-2, symmetric=True, cavitation="elrod", rheology=None,
                 layers: BoundaryLayers | None = None, roughness: Roughness | None = None, misalignment=(0.0, 0.0),
                 thermal: ThermalFilm | None = None):
        if not isinstance(cavitation, str) or cavitation not in CAVITATION_MODES:
            raise ValueError(f"cavitation must be one of {CAVITATION_MODES}, got cavitation={cavitation!r}")
        self.cavitation = cavitation
        self.diameter = check_range("diameter", diameter, "m", 0.0, 10.0, low_open=True)
        self.length = check_range("length", length, "m", 1e-3 * self.diameter, 10.0 * self.diameter,
                                  why=f"(L/D 0.001 to 10 with diameter = {self.diameter:g} m: longer is a long-bearing "
                                  "limit, not a journal bearing)")
        self.clearance = check_range("clearance", clearance, "m", 1e-5 * self.diameter, 0.1 * self.diameter,
                                     why="(C/D from 1e-5 to 0.1: a journal bearing's radial clearance)")
        if thermal is not None and not isinstance(thermal, ThermalFilm):
            raise TypeError(f"thermal must be a ThermalFilm or None, got {type(thermal).__name__}")
        self.thermal = thermal
        if viscosity is None and thermal is None:
            raise ValueError("viscosity = None [Pa s]; allowed: a viscosity in [1e-06, 10000] Pa s (None only with "
                             "thermal=ThermalFilm(...): then its viscosity at the supply temperature)")
        self.viscosity = check_range("viscosity", thermal.viscosity(thermal.supply_temperature) if viscosity is None
                                     else viscosity, "Pa s", 1e-6, 1e4)
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
        self.roughness = self._check_roughness(roughness)
        self._check_thermal()
        self.flow_law = flow_law(self.viscosity, self.rheology, layers)  # the one LayeredFilm of this bearing
        self.cavitation_pressure = check_range("cavitation_pressure", cavitation_pressure, "Pa", 0.0, 1e9,
                                               why="(absolute pressure)")
        self.ambient_pressure = check_range("ambient_pressure", ambient_pressure, "Pa", cavitation_pressure, 1e9,
                                            why="(absolute; at least cavitation_pressure)")
        self.supply_pressure = check_range("supply_pressure", supply_pressure, "Pa", cavitation_pressure, 1e9,
                                           why="(absolute; at least cavitation_pressure)")
        self.switch_width = None if switch_width is None else check_range(
            "switch_width", switch_width, "Pa", 1e-6, 1e9, why="(narrower, the switch is the sharp Elrod switch to "
            "rounding; wider than the largest pressure a bearing takes, it smears the cavitated zone away)")
        self.switch_content_width = check_range("switch_content_width", switch_content_width, "-", 0.0, 0.1,
                                                low_open=True, why="(a content deficit; above 0.1 the switch "
                                                "smears the cavitated zone)")
        self.groove = groove
        self.feeds = as_feeds(groove)
        self.feed_pressures = check_feeds(self.feeds, self.length, 0.5 * self.diameter, self.supply_pressure,
                                          self.cavitation_pressure)
        self.unsupplied = cavitation == "elrod" and not self.feeds and self.ambient_pressure <= self.cavitation_pressure
        self._check_ring_supply()
        if self.unsupplied:
            warnings.warn("JournalBearing: the Elrod film has no oil supply (groove=None and ambient_pressure <= "
                          "cavitation_pressure: nothing drives oil into the film, which starves); add a Groove, "
                          "raise the ambient pressure, or use cavitation=\"reynolds\" for the classical 360-deg "
                          "bearing", UserWarning, stacklevel=2)
        if isinstance(grid, (str, bytes)) or not hasattr(grid, "__len__") or len(grid) != 2:
            raise ValueError(f"grid must be (n_theta, n_axial) cells, got {grid!r}")
        n_theta = check_int("grid[0] (n_theta)", grid[0], "cells", 8, 20000)
        n_axial = check_int("grid[1] (n_axial)", grid[1], "cells", 1, 5000)
        self.misalignment = check_tilt("misalignment", misalignment)
        if self.thermal is not None and self.misalignment != (0.0, 0.0):
            raise ValueError(f"misalignment = {self.misalignment} [rad] with thermal = ThermalFilm(...); allowed: "
                             "(0, 0) (the thermal film is aligned)")
        if self.roughness is not None and self.misalignment != (0.0, 0.0):
            raise ValueError(f"misalignment = {self.misalignment} [rad] with roughness = Roughness(...); allowed: "
                             "(0, 0) (the rough film is aligned)")
        self.symmetric = (check_bool("symmetric", symmetric) and all(f.symmetric for f in self.feeds)
                          and self.misalignment == (0.0, 0.0))
        if check_bool("symmetric", symmetric) and not self.symmetric:
            n_axial *= 2  # feeds off the mid-plane: the whole length, at the same resolution
        self.grid_shape = (n_theta, n_axial)
        self.radius = 0.5 * self.diameter
        self._build_grid()
        check_resolution(self.feeds, self.feed_cells, self.grid_shape, self.length, self.radius, self.symmetric)

    def _check_roughness(self, roughness):
        """A :class:`Roughness` (or None) for an Elrod film with a Newtonian bulk and no boundary layers."""
        if roughness is None:
            return None
        if not isinstance(roughness, Roughness):
            raise TypeError(f"roughness must be a Roughness or None, got {type(roughness).__name__}")
        if self.cavitation != "elrod" or self.shear_thinning or self.layers is not None:
            raise ValueError(f"roughness = Roughness(...) with cavitation = {self.cavitation!r}, rheology = "
                             f"{type(self.rheology).__name__}, layers = {self.layers!r}: the rough film is the Elrod "
                             "film of a Newtonian bulk; allowed: cavitation=\"elrod\", rheology=None, layers=None")
        check_range("roughness sigma", roughness.sigma, "m", 0.0, 0.5 * self.clearance, low_open=True,
                    why="(the composite roughness must be well below the clearance)")
        return roughness

    def _check_thermal(self):
        """A thermal film is the Elrod film of a smooth Newtonian bulk without boundary layers."""
        if self.thermal is not None and (self.cavitation != "elrod" or self.shear_thinning or self.layers is not None
                                         or self.roughness is not None):
            raise ValueError(f"thermal = ThermalFilm(...) with cavitation = {self.cavitation!r}, rheology = "
                             f"{type(self.rheology).__name__}, layers = {self.layers!r}, roughness = "
                             f"{self.roughness!r}: the thermal film is the Elrod film of a smooth Newtonian bulk; "
                             "allowed: cavitation=\"elrod\", rheology=None, layers=None, roughness=None")

    def _check_ring_supply(self):
        """Circumferential grooves alone at the cavitation pressure (within 1 Pa), with the ends there too, supply no
        oil to an Elrod film (no pressure drives oil out of a groove that runs all round): refused, as the steady film
        of a bearing without feeds is (it has no unique steady state; the Newton iteration stalls)."""
        if (self.cavitation == "elrod" and self.feeds and self.ambient_pressure <= self.cavitation_pressure
                and all(isinstance(f, CircumferentialGroove) for f in self.feeds)
                and np.all(self.feed_pressures <= self.cavitation_pressure + 1.0)):
            name = feed_name(self.feeds, 0) + ".pressure" if self.feeds[0].pressure is not None else "supply_pressure"
            raise ValueError(f"{name} = {float(self.feed_pressures[0])!r} [Pa] with ambient_pressure = "
                             f"{self.ambient_pressure!r} Pa: a circumferential groove at the cavitation pressure "
                             "feeds no oil into an Elrod film whose ends are at it too; allowed: a feed pressure more "
                             f"than 1 Pa above cavitation_pressure = {self.cavitation_pressure:g} Pa, an ambient "
                             "pressure above it, or an axial groove or hole")

    def __repr__(self):
        return (f"JournalBearing(diameter={self.diameter:g} m, length={self.length:g} m, clearance={self.clearance:g} m, "
                f"viscosity={self.viscosity:g} Pa s, bulk_modulus={self.bulk_modulus:g} Pa, grid={self.grid_shape}, "
                f"cavitation={self.cavitation!r}, rheology={type(self.rheology).__name__}"
                f"{'' if self.layers is None else ', layers'})")

    # ---------------------------------------------------------------------------------------------
    #: The axial ends of the film: ``"dirichlet"`` (open, held at ``ambient_pressure``) or ``"symmetry"`` (closed: no
    #: flow through them; :class:`~transient.models.damper.damper.SqueezeFilmDamper` with ``end_seals="closed"``).
    end_kind = "dirichlet"

    def _build_grid(self):
        check_bearing_memory(self.grid_shape)
        n_theta, n_axial = self.grid_shape
        R = self.radius
        half = 0.5 * self.length / R
        x = Axis.uniform(n_theta, 2 * np.pi, start=0.0, centred=True, periodic=True, name="theta")
        if self.symmetric:
            z = Axis.uniform(n_axial, half, start=0.0, lower="symmetry", upper=self.end_kind, name="z")
        else:
            z = Axis.uniform(n_axial, 2 * half, start=-half, lower=self.end_kind, upper=self.end_kind, name="z")
        phi, zc = np.tile(x.centres, z.n), np.repeat(z.centres, x.n) * R
        self.feed_cells = feed_labels(self.feeds, phi, zc, R)  # feed index per cell, -1 in the film
        self.grid = Grid2D(x, z, fixed=self.feed_cells >= 0 if self.feeds else None, fixed_values=0.0)
        self.phi = self.grid.xc.copy()
        self.n_cells = self.grid.n

    def parameters(self) -> dict:
        """Every parameter that changes the film (SI; a single full-length groove at the supply pressure as its angle
        and width [deg], other feeds as a list of their fields with their type; roughness and misalignment only when
        there are some)."""
        g = self.groove
        if g is not None and not (isinstance(g, Groove) and g.length is None and g.pressure is None):
            g = [dict(type=type(f).__name__, **asdict(f)) for f in self.feeds]
        elif g is not None:
            g = [g.angle_deg, g.width_deg]
        return dict(diameter=self.diameter, length=self.length, clearance=self.clearance, viscosity=self.viscosity,
                    bulk_modulus=self.bulk_modulus, supply_pressure=self.supply_pressure,
                    groove=g, grid=list(self.grid_shape),
                    cavitation_pressure=self.cavitation_pressure, ambient_pressure=self.ambient_pressure,
                    switch_width=self.switch_width, switch_content_width=self.switch_content_width,
                    symmetric=self.symmetric, cavitation=self.cavitation,
                    layers=None if self.layers is None else dict(thickness=self.layers.thickness,
                                                                 viscosity=list(self.layers.viscosity),
                                                                 alpha=self.layers.alpha),
                    rheology=None if not self.shear_thinning else dict(
                        kappa=self.rheology.kappa, viscosity_ratio=self.rheology.viscosity_ratio),
                    **({} if self.roughness is None else dict(roughness=self.roughness.parameters())),
                    **({} if self.misalignment == (0.0, 0.0) else dict(misalignment=list(self.misalignment))),
                    **({} if self.thermal is None else dict(thermal=self.thermal.parameters())))

    def layer_groups(self) -> tuple[float, float]:
        """The boundary layers in the film's scales: ``(2 delta / C, 3 alpha^2 mu (1/mu_a + 1/mu_b) / C^2)``
        (:func:`~transient.models.journal.kernels.conductances`); ``(0, 0)`` without layers."""
        ly = self.layers
        if ly is None:
            return 0.0, 0.0
        darcy = 3.0 * ly.alpha ** 2 * self.viscosity * (1.0 / ly.viscosity[0] + 1.0 / ly.viscosity[1])
        return 2.0 * ly.thickness / self.clearance, darcy / self.clearance ** 2

    @property
    def _reach(self) -> float:
        """Largest fraction of ``max_eccentricity_ratio`` an equilibrium iterate may take: 0.995; a rough bearing's
        asperities carry the load at smaller gaps, 0.9999 (a film of 1e-4 C); a Winkler bore gives way, so the
        journal may pass the rigid bore's circle: ``ELASTIC_REACH``."""
        if self.roughness is None:
            return 0.995
        return ELASTIC_REACH if self.roughness.bore_compliance > 0.0 else 0.9999

    @property
    def max_eccentricity_ratio(self) -> float:
        """Largest e/C with a film: 1, less the two boundary layers (2 delta / C)."""
        return 1.0 - self.layer_groups()[0]

    def pressure_scale(self, speed_rpm) -> float:
        """p0 = 6 mu omega (R/C)^2 [Pa], the dimensionless pressure unit at this speed."""
        return 6.0 * self.viscosity * omega(speed_rpm) * (self.radius / self.clearance) ** 2

    def film(self, speed_rpm, n_extra=N_ROTOR, tilt=(0.0, 0.0)) -> "Film | ReynoldsFilm":
        """The discretised film at a shaft speed (scales, operator, scratch arrays): a :class:`Film`
        (Elrod) or a :class:`~transient.models.journal.reynolds_film.ReynoldsFilm` (``cavitation="reynolds"``), its
        gap that of a journal tilted by ``tilt`` [rad] in this bearing's (misaligned) bush."""
        if self.roughness is not None:
            return RoughFilm(self.grid, film_scales(self, speed_rpm), self.flow_law, self.roughness, n_extra)
        if self.thermal is not None:
            return ViscousFilm(self.grid, film_scales(self, speed_rpm), self.flow_law, n_extra)
        kind = ReynoldsFilm if self.cavitation == "reynolds" else Film
        f = kind(self.grid, film_scales(self, speed_rpm), self.flow_law, n_extra)
        relative = (tilt[0] - self.misalignment[0], tilt[1] - self.misalignment[1])
        if relative != (0.0, 0.0):
            f.set_tilt(relative)
        return f

    def tilted(self, tilt) -> "JournalBearing":
        """This bearing for a journal tilted by ``tilt`` [rad]: itself if the film of its grid can take the tilt (an
        aligned journal, or the whole length modelled), else :meth:`whole_length`."""
        return self if tuple(tilt) == (0.0, 0.0) else self.whole_length()

    def whole_length(self) -> "JournalBearing":
        """This bearing with the whole length modelled: itself if it is, else a copy without the symmetry plane
        (twice the axial cells of the half bearing: the same resolution)."""
        if not self.symmetric:
            return self
        c = copy.copy(self)
        c.symmetric = False
        c.grid_shape = (self.grid_shape[0], 2 * self.grid_shape[1])
        c._build_grid()
        return c

    def _check_tilt(self, tilt, X, Y):
        """The journal tilt ``tilt`` [rad], refused if its gap closes at a bearing end with the journal at (X, Y)."""
        tilt = check_tilt("tilt", tilt)
        if self.roughness is not None and tilt != (0.0, 0.0):
            raise ValueError(f"tilt = {tilt} [rad] with roughness = Roughness(...); allowed: (0, 0) (the rough film "
                             "is aligned)")
        if self.thermal is not None and tilt != (0.0, 0.0):
            raise ValueError(f"tilt = {tilt} [rad] with thermal = ThermalFilm(...); allowed: (0, 0) (the thermal film "
                             "is aligned)")
        rel = (tilt[0] - self.misalignment[0], tilt[1] - self.misalignment[1])
        a, b = tilt_groups(rel, self.radius, self.clearance)
        check_open(X, Y, a, b, 0.5 * self.length / self.radius, self.max_eccentricity_ratio, tilt)
        return tilt

    def _check_supplied(self):
        """A steady Elrod film needs a supply: without one every starved content field is a steady state."""
        if self.unsupplied:
            raise ValueError("groove = None with ambient_pressure <= cavitation_pressure: the Elrod film has no oil "
                             "supply and no unique steady state; add a Groove, raise the ambient pressure, or use "
                             "cavitation=\"reynolds\" (the classical 360-deg bearing)")

    # ---------------------------------------------------------------------------------------------
    def steady_state(self, eccentricity_ratio, speed_rpm, position_angle_deg=0.0, tilt=(0.0, 0.0)) -> FilmState:
        """Film with the journal held at eccentricity ratio ``eps`` (at the mid-plane) in the direction
        ``position_angle_deg`` (from the load line +x, in the direction of rotation) and tilted by ``tilt`` = (about x,
        about y) [rad] (:mod:`~transient.models.journal.tilt`; a tilt whose gap closes at an end is refused); a direct
        Newton solve (Elrod) or the active-set solve of the complementarity problem (Reynolds)."""
        eps = check_range("eccentricity_ratio", eccentricity_ratio, "-", 0.0, self.max_eccentricity_ratio,
                          high_open=True, why="(the film, less its boundary layers, must be open everywhere)"
                          if self.layers is not None else "")
        check_speed(speed_rpm)
        a = np.radians(position_angle_deg)
        tilt = self._check_tilt(tilt, eps * np.cos(a), eps * np.sin(a))
        self._check_supplied()
        b = self.tilted(tilt)
        f = b.film(speed_rpm, tilt=tilt)
        X, Y = eps * np.cos(a), eps * np.sin(a)
        if self.thermal is not None:
            u, its, balance, alternations = thd.steady(b, f, X, Y)
            return _warn_validity(thd.thermal_state(b, f, u, X, Y, its, balance, alternations))
        u, its, _ = b.film_solve(f, X, Y)
        return _warn_validity(f.state(u, X, Y, its))

    def coarser(self) -> "JournalBearing":
        """This bearing on a grid of half the circumferential cells (rounded up) and the same axial cells: the
        coarse level of :meth:`film_solve` (the axial rows stay where they are, so do the films at the ends)."""
        c = copy.copy(self)
        c.grid_shape = ((self.grid_shape[0] + 1) // 2, self.grid_shape[1])
        with warnings.catch_warnings():  # a feed narrower than a coarse cell: only the start is coarse
            warnings.simplefilter("ignore", UserWarning)
            c._build_grid()
        return c

    def film_solve(self, film, X, Y) -> tuple[np.ndarray, int, list]:
        """The steady film ``u`` of ``film`` (this bearing's, any speed) at (X, Y) and its Newton iterations, by grid
        sequencing above ``SEQUENCE_CELLS`` cells: the same film on :meth:`coarser` grids, down to one of at most that
        size or with fewer than twice ``SEQUENCE_MIN_THETA`` circumferential cells, solved from rest
        (:meth:`Film.solve <transient.models.journal.film.Film.solve>`), each interpolated to the next finer grid
        (:func:`~transient.fv.grid.interpolate_cells`) as the start of its Newton iteration (``chord=True``). The
        fronts of the film then start next to where they end, instead of crossing the grid one cell per iteration.
        Also returns the levels, coarsest first: (grid shape, iterations, factorisations). The Reynolds-condition
        film and the small grids: one solve from rest."""
        if isinstance(film, ReynoldsFilm) or film.n <= SEQUENCE_CELLS or self.grid_shape[0] < 2 * SEQUENCE_MIN_THETA:
            u, its = film.solve(X, Y)
            return u, its, [(self.grid_shape, its, getattr(film, "factorisations", 0))]
        coarse = self.coarser()
        cf = coarse.film(film.speed_rpm)
        cf.set_tilt(film.tilt_rad)  # the same gap on the coarse grid
        uc, _, levels = coarse.film_solve(cf, X, Y)
        u, its = film.solve(X, Y, u0=interpolate_cells(coarse.grid, uc, self.grid), chord=True)
        return u, its, levels + [(self.grid_shape, its, film.factorisations)]

    def equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40, tilt=(0.0, 0.0)) -> FilmState:
        """Static equilibrium under ``load`` [N] (in +x): 2-D Newton on the journal position with the
        exact derivative of the discrete film force (implicit differentiation of the film equations). ``tilt``
        [rad]: the journal held at this tilt (the force balances the load; the moment is what it is). A rough
        bearing at ``speed_rpm = 0``: the static contact equilibrium at rest (:mod:`~transient.models.journal.rest`:
        the asperities and the feeds' pressure field carry the load)."""
        if self.roughness is not None and speed_rpm == 0:
            W = check_positive("load", load, "N")
            self._check_tilt(tilt, 0.0, 0.0)
            self._check_supplied()
            f, u, q, it = rest.rest_equilibrium(self, W, REST_UNIT_RPM)
            return rest.rest_state(f, u, q[0], q[1], it)
        b = self.tilted(check_tilt("tilt", tilt))
        f, u, q, it, _ = b._equilibrium(load, speed_rpm, tol, max_iter, tilt=tilt)
        if self.thermal is not None:
            return _warn_validity(thd.thermal_state(b, f, u, q[0], q[1], it, f.energy_balance, f.alternations))
        return _warn_validity(f.state(u, q[0], q[1], it))

    def coefficients(self, load, speed_rpm, tilt=(0.0, 0.0), tilt_dofs=False) -> tuple[np.ndarray, np.ndarray]:
        """Linearised stiffness K and damping C at the static equilibrium, from the same discrete film:
        ``K = -dF/dq``, ``C = -dF/d(dq/dt)``. Default: 2x2 [N/m, N s/m] in (x, y), x towards the load.
        ``tilt_dofs=True``: 4x4 in ``q = (x [m], y [m], tx [rad], ty [rad])`` with the rows ``(F_x [N], F_y [N],
        M_x [N m], M_y [N m])`` (the film's moments about the bearing centre; the tilt rates in the squeeze term;
        axes in :mod:`~transient.models.journal.tilt`), at the equilibrium with the journal tilted by ``tilt``
        [rad]."""
        tilt = check_tilt("tilt", tilt)
        if self.thermal is not None and tilt_dofs:
            raise ValueError("tilt_dofs = True with thermal = ThermalFilm(...); allowed: False (the thermal film's "
                             "coefficients are the 2 x 2 of an aligned journal)")
        if not check_bool("tilt_dofs", tilt_dofs) and tilt == (0.0, 0.0) and self.misalignment == (0.0, 0.0):
            f, _, _, _, (dF_dq, dF_dv) = self._equilibrium(load, speed_rpm)
            K = -dF_dq * f.force_scale / self.clearance
            Cmat = -dF_dv * f.force_scale / (self.clearance * omega(speed_rpm))
            return K, Cmat
        b = self.whole_length()  # a moment needs both halves
        f, u, q, _, _ = b._equilibrium(load, speed_rpm, tilt=tilt)
        _, dF_dq, dF_dv = sensitivity(f, u, q[0], q[1])
        K, Cmat = si_coefficients(dF_dq, dF_dv, f.force_scale, self.radius, self.clearance, omega(speed_rpm))
        return (K, Cmat) if tilt_dofs else (K[:2, :2], Cmat[:2, :2])

    def _equilibrium(self, load, speed_rpm, tol=1e-10, max_iter=40, start=None, tilt=(0.0, 0.0)):
        """Newton on the journal position (either film: both give the force and its exact sensitivities; the
        Reynolds film's on its converged active set); returns (film, u, (X, Y), iterations, (dF/dq, dF/dv)) with the
        force sensitivities at the converged state (they are the Newton matrix and the damping). ``start``: the
        first journal position (X, Y) [C] (default (0.3, 0.3))."""
        W = check_positive("load", load, "N")
        check_speed(speed_rpm)
        tilt = self._check_tilt(tilt, 0.0, 0.0)
        self._check_supplied()
        f = self.film(speed_rpm, tilt=tilt)
        wbar = W / f.force_scale
        if self.thermal is not None:
            return self._thermal_equilibrium(f, W, speed_rpm, tol, max_iter, start)
        q = np.array([0.3, 0.3] if start is None else start, dtype=float)  # eccentric start in the loaded quadrant
        a, b = f.tilt
        half = half_length(self.grid)
        reach = lambda p: max(edge_eccentricities(p[0], p[1], a, b, half))  # noqa: E731 (|e| at the worse end)
        if reach(q) >= self._reach * self.max_eccentricity_ratio:
            q[:] = 0.0
        u = None
        for it in range(max_iter):
            u = self.film_solve(f, q[0], q[1])[0] if u is None else f.solve(q[0], q[1], u0=u)[0]
            F, dF_dq, dF_dv = f.force_sensitivity(u, q[0], q[1])
            r = np.array([F[0] + wbar, F[1]])
            if np.max(np.abs(r)) <= tol * max(wbar, 1e-300):
                return f, u, q, it, (dF_dq, dF_dv)
            dq = -np.linalg.solve(dF_dq, r)
            if self._reach == ELASTIC_REACH:  # a Winkler bore: steps of at most ELASTIC_STEP (its film is stiff)
                dq *= min(1.0, ELASTIC_STEP / max(float(np.hypot(*dq)), 1e-300))
            lam = 1.0  # keep the journal inside the clearance
            while reach(q + lam * dq) >= self._reach * self.max_eccentricity_ratio:
                lam *= 0.5
            q = q + lam * dq
        if self.roughness is not None and start is None:
            return self._continued_equilibrium(W, speed_rpm, tol, max_iter)
        raise NoEquilibriumError(f"equilibrium(load={W} N, speed_rpm={speed_rpm}) did not converge in {max_iter} "
                           f"iterations; last eccentricity ratio {np.hypot(*q):.4f}, force residual "
                           f"{np.max(np.abs(r)) * f.force_scale:.3e} N")

    def _thermal_equilibrium(self, f, load, speed_rpm, tol, max_iter, start):
        """:meth:`_equilibrium` of a thermal film (:func:`transient.models.journal.thd.equilibrium`); the film keeps
        its energy balance and the number of film solves (``f.energy_balance``, ``f.alternations``)."""
        out = thd.equilibrium(self, f, load / f.force_scale, tol, max_iter, start)
        if out is None:
            raise NoEquilibriumError(f"equilibrium(load={load} N, speed_rpm={speed_rpm}) of the thermal film did not "
                                     f"converge in {max_iter + self.thermal.max_iterations} film solves")
        u, q, it, sens, f.energy_balance = out
        f.alternations = it + 1
        return f, u, q, it, sens

    def _continued_equilibrium(self, load, speed_rpm, tol, max_iter):
        """The equilibrium of a rough bearing by continuation in speed, when Newton from the default start fails
        (at low speed the asperities carry the load and their force grows exponentially as the gap closes: a Newton
        step from the centre lands far off): from ``CONTINUATION_SPEED_RATIO`` times the speed (at least
        ``CONTINUATION_START_RPM``) down to it in steps of a factor of 2, each equilibrium started from the one above."""
        top = min(max(CONTINUATION_SPEED_RATIO * speed_rpm, CONTINUATION_START_RPM), SPEED_RANGE_RPM[1])
        speeds = np.geomspace(top, speed_rpm, max(2, int(np.ceil(np.log2(top / speed_rpm))) + 1))
        q = None
        for s in speeds:
            out = self._equilibrium(load, s, tol, max_iter, start=q)
            q = out[2]
        return out

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


