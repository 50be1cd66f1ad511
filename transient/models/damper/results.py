"""The result of a squeeze-film damper's circular centred orbit (SI fields with units)."""

from __future__ import annotations

import numpy as np

from transient.results import SteadyResult, quantity, result_type
from transient.units import rpm_to_rad_s


@result_type
class CircularOrbit(SteadyResult):
    """The film of a damper whose journal whirls on a circular centred orbit, steady in the whirling frame.

    ``radial_force`` [N] is the film force on the journal along the line of centres (+ outwards, away from the
    damper's centre), ``tangential_force`` [N] across it (+ in the whirl direction; a damping film gives a negative
    one). ``spring_force`` [N]: the centring spring's radial force ``-k e`` (0 without a spring). ``pressure`` [Pa,
    absolute] and ``film_content`` (theta = rho / rho_c, 1 in the full film) are (n_axial, n_theta) arrays on the
    modelled grid (half the damper when it is symmetric about its mid-plane; row 0 next to it), at ``angle_deg``
    measured from the minimum film in the whirl direction and at the axial positions ``z`` [m].
    """

    eccentricity_ratio: float = quantity("-")
    whirl_speed_rpm: float = quantity("rpm")
    clearance: float = quantity("m")
    radial_force: float = quantity("N")
    tangential_force: float = quantity("N")
    spring_force: float = quantity("N")
    pressure: np.ndarray = quantity("Pa")
    film_content: np.ndarray = quantity("-")
    angle_deg: np.ndarray = quantity("deg")
    z: np.ndarray = quantity("m")

    @property
    def orbit_radius(self) -> float:
        """e = eps c [m]."""
        return self.eccentricity_ratio * self.clearance

    @property
    def damping(self) -> float:
        """The film's equivalent damping ``-F_t / (e omega)`` [N s/m] on this orbit."""
        return -self.tangential_force / (self.orbit_radius * rpm_to_rad_s(self.whirl_speed_rpm))

    @property
    def stiffness(self) -> float:
        """The film's equivalent direct stiffness ``-F_r / e`` [N/m] on this orbit (positive where the cavitated film
        pulls the journal towards the centre; zero for the uncavitated film)."""
        return -self.radial_force / self.orbit_radius

    @property
    def max_pressure(self) -> float:
        return float(self.pressure.max())

    @property
    def cavitated_fraction(self) -> float:
        """The share of the film's cells that are not full (content below 1 - 1e-3)."""
        return float(np.mean(self.film_content < 1.0 - 1e-3))
