"""Results of the journal bearing models (Rho & Kim; the layered film of Jang): SI fields with
units. :class:`FilmState` is a film solution with the journal held at a position, :class:`OrbitResult` the
time series of an orbit run."""

from __future__ import annotations

from dataclasses import field

import numpy as np

from transient.checks import check_int, check_range
from transient.physics.layered import NO_LAYERS, BoundaryLayers, Gecim, LayeredFilm, Newtonian
from transient.results import RunResult, SteadyResult, quantity, result_type
from transient.units import rpm_to_hz

RECORDED_FIELDS = ("force", "moment", "min_film", "mass", "outflow", "supply_flow", "side_leakage", "pressure", "pressure_t",
                   "film_content", "film_content_t", "max_temperature", "power_loss", "heat_flow", "stored_heat",
                   "shaft_speed", "temperature", "temperature_t", "friction_torque", "contact_load", "contact_pressure")


@result_type
class FilmState(SteadyResult):
    """A film solution with the journal at a fixed position (and, optionally, moving).

    ``pressure`` [Pa, absolute] and ``film_content`` (theta = rho/rho_c) are (n_axial, n_theta) arrays on
    the modelled grid (half bearing when symmetric; row 0 next to the mid-plane); ``angle_deg`` and
    ``z`` [m] are the cell-centre coordinates. ``force`` [N] is the film force on the journal
    (x towards the load, y at +90 deg in the direction of rotation), ``load`` [N] its magnitude (the
    external load it carries) and ``attitude_angle_deg`` the angle from the load line to the line of
    centres, in the direction of rotation. ``friction_force`` [N]: the film's drag on the journal surface;
    ``bearing_friction_force`` [N]: its drag on the bearing surface, along the rotation
    (:func:`~transient.models.journal.film.wall_friction`; boundary layers and the Gecim bulk included).
    ``friction_torque`` [N m]: the torque resisting the journal, ``R friction_force`` plus, on a rough bearing,
    the boundary friction ``mu_b R sum p_a dA`` of the asperity contacts; ``power_loss`` [W] its power.

    Rough bearings (``JournalBearing(roughness=...)``): ``force`` is the film's and the asperities' force together
    (what carries the load), ``contact_force`` [N] the asperities' part and ``contact_load`` [N] its magnitude,
    ``contact_normal_load`` [N] the sum of the asperity pressure over the surface (what the boundary friction
    acts on), ``contact_pressure`` [Pa] the nominal asperity pressure per cell (Greenwood-Tripp). At rest
    (``equilibrium(load, 0)``, :mod:`~transient.models.journal.rest`): ``speed_rpm`` 0, ``friction_torque`` the
    torque that starts the shaft, ``rest_radius`` [m] the journal's radius.

    Flows (:mod:`transient.models.journal.flows`), whole bearing: ``supply_flow`` [m^3/s] the net flow each feed
    delivers, ``feed_inflow`` [m^3/s] the flow each feed sends into the film, ``side_leakage`` [m^3/s] the outflow
    at the ends z = -L/2 and +L/2; the design-chart variables ``flow_variable`` = Q / (R C N L) (Q the feeds' total
    inflow, N [rev/s]) and ``side_flow_ratio`` = Q_s / Q (Q_s the leakage of both ends).

    Tilt (:mod:`transient.models.journal.tilt`): ``tilt`` [rad] the journal's tilt relative to the bush (about x,
    about y), ``moment`` [N m] the film's moment on the journal about the bearing centre (about x, about y; zero on a
    half bearing, whose mirror halves cancel), ``min_film`` the smallest gap over the whole bearing (at an end when
    tilted); ``eccentricity_ratio`` and ``position`` are the journal's at the mid-plane.
    Thermal films (``JournalBearing(thermal=ThermalFilm(...))``, :mod:`transient.models.journal.thd`):
    ``temperature`` [K] and ``viscosity_field`` [Pa s] per cell, ``max_temperature`` [K], ``mixing_temperature``
    [K] of each feed, ``outlet_temperature`` [K] (mixed mean of the side leakage), ``dissipation`` [W] (the film's
    viscous dissipation), ``heat_convected`` [W] (carried away by the oil above the supply temperature: side
    leakage and the discharged recirculated oil), ``heat_conducted`` [W] (to the walls) and ``thermal_iterations``
    (film-temperature alternations); the friction fields and ``power_loss`` at the cells' viscosities. None or NaN
    for an isothermal film.
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
    supply_flow: np.ndarray = quantity("m^3/s", None)
    feed_inflow: np.ndarray = quantity("m^3/s", None)
    side_leakage: np.ndarray = quantity("m^3/s", None)
    flow_variable: float = quantity("-", float("nan"))
    side_flow_ratio: float = quantity("-", float("nan"))
    layers: tuple | None = None  # (delta [m], mu_a [Pa s], mu_b [Pa s], alpha [m]) or None
    gecim: tuple | None = None  # the shear-thinning bulk (kappa [Pa], mu_2/mu_1) or None (Newtonian)
    friction_torque: float = quantity("N m", float("nan"))
    contact_force: tuple[float, float] = quantity("N", (0.0, 0.0))
    contact_load: float = quantity("N", 0.0)
    contact_normal_load: float = quantity("N", 0.0)
    #: the journal's radius [m] where the speed cannot give it (a rough bearing at rest), else NaN
    rest_radius: float = quantity("m", float("nan"))
    contact_pressure: np.ndarray | None = quantity("Pa", None, repr=False)
    moment: tuple[float, float] = quantity("N m", (0.0, 0.0))
    tilt: tuple[float, float] = quantity("rad", (0.0, 0.0))
    temperature: np.ndarray | None = quantity("K", None, repr=False)
    viscosity_field: np.ndarray | None = quantity("Pa s", None, repr=False)
    mixing_temperature: np.ndarray | None = quantity("K", None)
    outlet_temperature: float = quantity("K", float("nan"))
    dissipation: float = quantity("W", float("nan"))
    heat_convected: float = quantity("W", float("nan"))
    heat_conducted: float = quantity("W", float("nan"))
    thermal_iterations: int = 0
    message: str = field(default="converged", kw_only=True)

    @property
    def max_temperature(self) -> float:
        """Highest film temperature [K] (NaN for an isothermal film)."""
        return float("nan") if self.temperature is None else float(self.temperature.max())

    @property
    def max_pressure(self) -> float:
        return float(self.pressure.max())

    @property
    def film_load(self) -> float:
        """Magnitude [N] of the film's share of the force (the force less the asperities')."""
        return float(np.hypot(self.force[0] - self.contact_force[0], self.force[1] - self.contact_force[1]))

    @property
    def power_loss(self) -> float:
        """Friction power [W]: ``friction_torque`` times the shaft's angular speed."""
        return self.friction_torque * self.speed_rpm * np.pi / 30.0

    @property
    def friction_coefficient(self) -> float:
        """``friction_torque / (R load)`` [-] (R from ``sliding_speed`` and the speed; at rest ``rest_radius``)."""
        w = self.speed_rpm * np.pi / 30.0
        radius = self.sliding_speed / w if w != 0.0 else self.rest_radius
        return self.friction_torque / (radius * self.load)

    def _law(self):
        """The film's flow law (:class:`~transient.physics.layered.LayeredFilm`, SI)."""
        ly = NO_LAYERS if self.layers is None else BoundaryLayers(self.layers[0], (self.layers[1], self.layers[2]),
                                                                  self.layers[3])
        return LayeredFilm(self.viscosity, Newtonian() if self.gecim is None else Gecim(*self.gecim), ly)

    def velocity_profile(self, angle_deg: float, axial_index: int = 0, points: int = 41):
        """Circumferential velocity across the film at the cell nearest ``angle_deg`` in axial row
        ``axial_index`` (0: next to the mid-plane): (heights z [m] from the journal surface, velocity [m/s]),
        from the film's flow law (Jang: the journal moves at ``sliding_speed``, the bearing is at rest;
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
        layers (Jang eq. 28; the walls themselves without layers) along the angle in axial row
        ``axial_index``: (lower, upper) arrays over ``angle_deg``, from the film's flow law at each cell."""
        row = check_int("axial_index", axial_index, "-", 0, self.pressure.shape[0] - 1)
        h, G, Gz = self.film_thickness[row], self.pressure_gradient[row], self.axial_pressure_gradient[row]
        s = self._law().stresses_2d(h, np.stack([G, Gz], axis=-1), (self.sliding_speed, 0.0), (0.0, 0.0))
        return s.lower_interface[:, 0], s.upper_interface[:, 0]


@result_type
class OrbitResult(RunResult):
    """Time series of one orbit run (outputs at ``outputs_per_revolution`` per revolution).

    ``t`` [s], ``x``, ``y`` [m] (journal centre; x towards the load); the recorded series (None if not
    asked): ``force`` [N] (film force on the journal, (n, 2)), ``moment`` [N m] (its moment about the bearing
    centre, (n, 2)), ``min_film`` [m] (the smallest gap over the bearing), ``mass`` [m^3],
    ``outflow`` [m^3/s] ((n, 2): ends, groove), ``supply_flow`` [m^3/s] ((n, feeds): the net flow out of each
    feed), ``side_leakage`` [m^3/s] ((n, 2): out of the ends z = -L/2, +L/2; :mod:`~transient.models.journal.flows`),
    ``pressure`` [Pa] ((k, nz, ntheta) at ``pressure_t``
    [s], only over the recorded window), ``film_content`` (at ``film_content_t``); a thermal bearing's
    ``max_temperature`` [K], ``power_loss`` [W], ``heat_flow`` [W], ``stored_heat`` [J], ``shaft_speed`` [rpm] and
    ``temperature`` [K] (at ``temperature_t``), ``final_temperature`` [K] (cells, then feeds) and ``heat_balance``
    (per thermal interval, :meth:`~transient.models.journal.thermal_orbit.ThermalRun.heat_balance`). ``stats`` sums the
    integrator statistics over chunks; ``touched_at`` [s] if the journal reached the wall (the run stopped
    there); ``final_state`` (film + rotor, dimensionless) at ``final_time`` [s]: ``run(..., start=result)``
    continues from it with the unbalance phase where it was. ``success`` is False (and ``message`` says
    why) if the integrator failed; the outputs up to the failure are kept.
    """

    shapes = {"x": ("t",), "y": ("t",), "force": ("t", 2), "moment": ("t", 2), "min_film": ("t",), "mass": ("t",), "outflow": ("t", 2),
              "supply_flow": ("t", None), "side_leakage": ("t", 2), "pressure": ("pressure_t", "nz", "ntheta"),
              "pressure_t": (None,), "film_content": ("film_content_t", "nz", "ntheta"), "film_content_t": (None,),
              "max_temperature": ("t",), "power_loss": ("t",), "heat_flow": ("t",), "stored_heat": ("t",),
              "shaft_speed": ("t",), "temperature": ("temperature_t", "nz", "ntheta"), "temperature_t": (None,),
              "final_temperature": (None,), "friction_torque": ("t",), "contact_load": ("t",),
              "contact_pressure": ("t",)}

    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    method: str = "ida"
    speed_rpm: float = quantity("rpm", 0.0)
    clearance: float = quantity("m", 0.0)
    touched_at: float | None = quantity("s", None)
    force: np.ndarray | None = quantity("N", None)
    moment: np.ndarray | None = quantity("N m", None)
    min_film: np.ndarray | None = quantity("m", None)
    mass: np.ndarray | None = quantity("m^3", None)
    outflow: np.ndarray | None = quantity("m^3/s", None)
    supply_flow: np.ndarray | None = quantity("m^3/s", None)
    side_leakage: np.ndarray | None = quantity("m^3/s", None)
    pressure: np.ndarray | None = quantity("Pa", None)
    pressure_t: np.ndarray | None = quantity("s", None)
    film_content: np.ndarray | None = None
    film_content_t: np.ndarray | None = quantity("s", None)
    max_temperature: np.ndarray | None = quantity("K", None)
    power_loss: np.ndarray | None = quantity("W", None)
    heat_flow: np.ndarray | None = quantity("W", None)
    stored_heat: np.ndarray | None = quantity("J", None)
    shaft_speed: np.ndarray | None = quantity("rpm", None)
    temperature: np.ndarray | None = quantity("K", None)
    temperature_t: np.ndarray | None = quantity("s", None)
    final_temperature: np.ndarray | None = quantity("K", None)
    heat_balance: dict | None = None
    friction_torque: np.ndarray | None = quantity("N m", None)
    contact_load: np.ndarray | None = quantity("N", None)
    contact_pressure: np.ndarray | None = quantity("Pa", None)
    contact_events: list | None = None
    peak_contact_pressure: float | None = quantity("Pa", None)

    @property
    def eccentricity_ratio(self) -> np.ndarray:
        return np.hypot(self.x, self.y) / self.clearance

    @property
    def revolutions(self) -> np.ndarray:
        return self.t * rpm_to_hz(self.speed_rpm)

    @property
    def fields(self) -> dict:
        """The recorded series by name (only those recorded)."""
        return {k: getattr(self, k) for k in RECORDED_FIELDS if getattr(self, k) is not None}
