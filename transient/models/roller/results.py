"""Results of the EHL models (Park, seed 001): SI fields with units, dimensionless views as properties.

Every result says ``success`` / ``message``; a steady solve also keeps its Newton residual history
(``residual_norms``, the infinity norm of the scaled equations per iteration), so a failed solve can be
inspected (:class:`EHLConvergenceError` carries the result).
"""

from __future__ import annotations

from dataclasses import field

import numpy as np

from transient.results import Result, quantity, result_type


class EHLConvergenceError(RuntimeError):
    """A steady EHL solve did not converge; ``result`` is the last iterate, flagged ``success=False``."""

    def __init__(self, message: str, result):
        super().__init__(message)
        self.result = result


@result_type
class LineSteady(Result):
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
    success: bool = True
    message: str = ""
    iterations: int = 0
    wall_time: float = quantity("s", 0.0)
    residual_norms: list = field(default_factory=list)
    state: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))

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
class LineTransient(Result):
    """Transient of the line contact (IDA): series at the output times ``t``, final fields."""

    t: np.ndarray = quantity("s")
    h_central: np.ndarray = quantity("m")
    h_min: np.ndarray = quantity("m")
    p_max: np.ndarray = quantity("Pa")
    h0: np.ndarray = quantity("m")
    load: np.ndarray = quantity("N/m")
    x: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    film: np.ndarray = quantity("m")
    success: bool = True
    message: str = ""
    n_steps: int = 0
    n_jacobians: int = 0
    wall_time: float = quantity("s", 0.0)
    final_state: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    final_time: float = quantity("s", 0.0)
