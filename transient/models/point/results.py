"""Results of the EHL point contact: SI fields with units, the dimensionless views as properties."""

from __future__ import annotations

from dataclasses import field

import numpy as np

from transient.results import RunResult, SteadyResult, quantity, result_type


@result_type
class PointSteady(SteadyResult):
    """Steady EHL point contact (:class:`~transient.models.point.contact.PointContact`).

    ``x`` (rolling direction) and ``y`` node positions [m] (boundary nodes included), ``pressure``,
    ``film`` and the film content ``theta`` (1 where the gap is full, below 1 in the starved inlet and the
    cavitated outlet) of shape ``(y.size, x.size)``. ``h_central`` the film at the origin, ``h_min`` its
    minimum (at ``x_of_h_min``, ``y_of_h_min``), ``p_max`` the largest pressure, ``meniscus_x`` where the
    film content reaches 1 on the centreline (the inlet meniscus; the domain's inlet when flooded there),
    ``b`` and ``hertz_pressure`` the Hertz semi-axis along the rolling direction and maximum pressure,
    ``inlet_flux``, ``outlet_flux`` and ``side_flux`` the oil flow rates into the domain at its inlet and out of
    it at its outlet and sides [m^3/s] (volume at ambient density), ``inlet_film`` the prescribed inlet layer
    (``inf``: fully flooded). ``grid_change`` the films on every second and fourth node and the
    error of each film they bound, ``grid_settled`` whether both errors are at most 5 % (:meth:`PointContact.grid_check`;
    False when not checked)."""

    time_axis = None
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    theta: np.ndarray = quantity("-")
    h_central: float = quantity("m")
    h_min: float = quantity("m")
    x_of_h_min: float = quantity("m")
    y_of_h_min: float = quantity("m")
    p_max: float = quantity("Pa")
    meniscus_x: float = quantity("m")
    load_error: float = quantity("-")
    radius_x: float = quantity("m")
    b: float = quantity("m")
    hertz_pressure: float = quantity("Pa")
    flooded_inlet: bool = True
    inlet_film: float = quantity("m", float("inf"))
    inlet_flux: float = quantity("m^3/s", 0.0)
    outlet_flux: float = quantity("m^3/s", 0.0)
    side_flux: float = quantity("m^3/s", 0.0)
    wall_time: float = quantity("s", 0.0)
    state: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    solver_info: dict = field(default_factory=dict)
    grid_change: dict = field(default_factory=dict)
    grid_settled: bool = False

    @property
    def m(self) -> float:
        """Meniscus distance ``-meniscus_x / b`` (Hamrock & Dowson's m)."""
        return -self.meniscus_x / self.b

    @property
    def H_central(self) -> float:
        """``h_central / Rx`` (Hamrock-Dowson's H)."""
        return self.h_central / self.radius_x

    @property
    def H_min(self) -> float:
        return self.h_min / self.radius_x

    def centreline(self):
        """``(x, pressure, film, theta)`` along ``y = 0``."""
        j = self.y.size // 2
        return self.x, self.pressure[j], self.film[j], self.theta[j]


@result_type
class PointDry(SteadyResult):
    """Dry (elastostatic) point contact on the EHL grid (:meth:`PointContact.dry`): pressure, its maximum,
    the contact semi-axes along (``half_width_x``) and across (``half_width_y``) the rolling direction, and
    Hertz's values."""

    time_axis = None
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    p_max: float = quantity("Pa")
    half_width_x: float = quantity("m")
    half_width_y: float = quantity("m")
    hertz_pressure: float = quantity("Pa")
    hertz_b: float = quantity("m")
    hertz_a: float = quantity("m")
    wall_time: float = quantity("s", 0.0)


@result_type
class PointTransient(RunResult):
    """Transient of the point contact: series at the output times ``t``, final fields."""

    snapshot_fields = ("x", "y", "pressure", "film", "theta")
    shapes = {"h_central": ("t",), "h_min": ("t",), "p_max": ("t",), "h0": ("t",), "load": ("t",)}
    h_central: np.ndarray = quantity("m")
    h_min: np.ndarray = quantity("m")
    p_max: np.ndarray = quantity("Pa")
    h0: np.ndarray = quantity("m")
    load: np.ndarray = quantity("N")
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    theta: np.ndarray = quantity("-")
    wall_time: float = quantity("s", 0.0)
