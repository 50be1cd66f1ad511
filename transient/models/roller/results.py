"""Results of the EHL models (Park): SI fields with units, dimensionless views as properties.

Every result says ``success`` / ``message``; a steady solve also keeps its Newton residual history
(``residual_norms``, the infinity norm of the scaled equations per iteration), so a failed solve can be
inspected (:class:`EHLConvergenceError` carries the result).
"""

from __future__ import annotations

from dataclasses import field

import numpy as np

from transient.models.ehl.errors import EHLConvergenceError, InexactStepWarning  # noqa: F401 (raised by the roller's solves)
from transient.results import RunResult, SteadyResult, quantity, result_type


class UnderResolvedGridError(ValueError):
    """The grid's x spacing cannot carry the load of its most loaded row (no Newton iteration was made):
    ``resolution`` is :meth:`RollerContact.dry_resolution`'s answer."""

    def __init__(self, message: str, resolution: dict):
        super().__init__(message)
        self.resolution = resolution


@result_type
class LineSteady(SteadyResult):
    """Steady EHL line contact (:class:`~transient.models.roller.line_contact.LineContact`).

    ``x`` node positions (boundary nodes included), ``pressure`` and ``film`` at the nodes; the film at
    ``x = 0`` (``h_central``), its minimum (``h_min``, at ``x_of_h_min``), the maximum pressure; the
    contact's radius and modulus give the dimensionless views ``X, P, H, H_central, H_min, P_max``."""

    time_axis = None
    x: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    h_central: float = quantity("m")
    h_min: float = quantity("m")
    x_of_h_min: float = quantity("m")
    p_max: float = quantity("Pa")
    load_error: float = quantity("-")
    radius: float = quantity("m")
    modulus: float = quantity("Pa")
    hertz_half_width: float = quantity("m")
    hertz_pressure: float = quantity("Pa")
    wall_time: float = quantity("s", 0.0)
    state: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))

    def to_dataframe(self):
        """The steady fields as a ``pandas.DataFrame``, one row per node: ``x, pressure, film`` with their
        units in ``df.attrs["units"]``."""
        return _node_table(dict(x=self.x, pressure=self.pressure, film=self.film), self.units())

    @property
    def X(self):
        return self.x / self.radius

    @property
    def P(self):
        return self.pressure / self.modulus

    @property
    def H(self):
        return self.film / self.radius

    @property
    def H_central(self):
        return self.h_central / self.radius

    @property
    def H_min(self):
        return self.h_min / self.radius

    @property
    def P_max(self):
        return self.p_max / self.modulus


@result_type
class LineDry(SteadyResult):
    """Dry contact of the cylinder (:meth:`LineContact.dry`): pressure, maximum, half-width, and the Hertz
    values for comparison."""

    time_axis = None
    x: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    p_max: float = quantity("Pa")
    half_width: float = quantity("m")
    hertz_half_width: float = quantity("m")
    hertz_pressure: float = quantity("Pa")


@result_type
class LineTransient(RunResult):
    """Transient of the line contact (IDA on the penalty form, or BDF2 on the film-content form): series at the
    output times ``t``, final fields; ``final_state`` ``[p, h0]`` (scaled) in both."""

    snapshot_fields = ("x", "pressure", "film")
    shapes = {"h_central": ("t",), "h_min": ("t",), "p_max": ("t",), "h0": ("t",), "load": ("t",)}
    h_central: np.ndarray = quantity("m")
    h_min: np.ndarray = quantity("m")
    p_max: np.ndarray = quantity("Pa")
    h0: np.ndarray = quantity("m")
    load: np.ndarray = quantity("N/m")
    x: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    n_steps: int = 0
    n_jacobians: int = 0
    wall_time: float = quantity("s", 0.0)


@result_type
class RollerSteady(SteadyResult):
    """Steady EHL of the tapered roller (:class:`~transient.models.roller.contact.RollerContact`).

    ``x`` (rolling direction) and ``y`` (along the roller, from the mid-plane, negative at the small
    end) node positions including the boundary nodes; ``pressure`` and ``film`` of shape
    ``(y.size, x.size)``. ``h_central`` is the film at ``x = 0`` on the mid-plane; ``h_min``,
    ``p_max`` the extrema with their positions. Dimensionless views (the paper's): ``X, Y`` (by R_m),
    ``P`` (by E'), ``H`` (by R_m)."""

    time_axis = None
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    h_central: float = quantity("m")
    h_min: float = quantity("m")
    x_of_h_min: float = quantity("m")
    y_of_h_min: float = quantity("m")
    p_max: float = quantity("Pa")
    x_of_p_max: float = quantity("m")
    y_of_p_max: float = quantity("m")
    load_error: float = quantity("-")
    mean_radius: float = quantity("m")
    modulus: float = quantity("Pa")
    half_width: float = quantity("m")
    footprint_length: float = quantity("m")
    profile_start: float = quantity("m", 0.0)
    wall_time: float = quantity("s", 0.0)
    state: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    solver_info: dict = field(default_factory=dict)
    #: film content theta (1: full film; < 1: cavitated, the fraction of the gap filled), shaped like ``film``
    content: np.ndarray = quantity("-", default_factory=lambda: np.zeros((0, 0)))

    @property
    def X(self):
        return self.x / self.mean_radius

    @property
    def Y(self):
        return self.y / self.mean_radius

    @property
    def P(self):
        return self.pressure / self.modulus

    @property
    def H(self):
        return self.film / self.mean_radius

    def to_dataframe(self):
        """The steady fields as a ``pandas.DataFrame``, one row per node (x fastest): ``x, y, pressure,
        film`` with their units in ``df.attrs["units"]`` (a steady result has no time axis)."""
        yy, xx = np.meshgrid(self.y, self.x, indexing="ij")
        return _node_table(dict(x=xx, y=yy, pressure=self.pressure, film=self.film), self.units())

    def section_x(self, y: float):
        """``(x, pressure, film)`` along the rolling direction at ``y`` [m] (linear in y between rows)."""
        p, h = _row(self.y, self.pressure, y), _row(self.y, self.film, y)
        return self.x, p, h

    def section_y(self, x: float = 0.0):
        """``(y, pressure, film)`` along the roller at ``x`` [m] (linear in x between columns)."""
        p, h = _row(self.x, self.pressure.T, x), _row(self.x, self.film.T, x)
        return self.y, p, h


def _node_table(fields: dict, units: dict):
    import pandas as pd

    df = pd.DataFrame({k: np.asarray(v).ravel() for k, v in fields.items()})
    df.attrs["units"] = {k: units.get(k, "") for k in fields}
    return df


def _row(coord, field2d, at):
    j = int(np.clip(np.searchsorted(coord, at), 1, coord.size - 1))
    w = (at - coord[j - 1]) / (coord[j] - coord[j - 1])
    return (1.0 - w) * field2d[j - 1] + w * field2d[j]


@result_type
class RollerTransient(RunResult):
    """Transient of the roller contact (IDA): series at the output times ``t``, final fields."""

    snapshot_fields = ("x", "y", "pressure", "film")
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
    n_steps: int = 0
    n_jacobians: int = 0
    wall_time: float = quantity("s", 0.0)
