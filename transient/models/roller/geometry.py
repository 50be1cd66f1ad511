"""Tapered roller with dub-off (profiled) ends, possibly tilted: the rigid gap of Park, eq. (4).

Dimensionless, lengths by the mean radius ``R_m`` (radius at the mid-plane ``Y = 0``); ``X`` rolling
direction, ``Y`` along the contact line (the generator), negative towards the small end::

    H_rigid(X, Y) = X^2 / (2 Rs(Y)) + (|Y| - Y_d)^2 / (2 R_d*) [|Y| > Y_d only] + Y tan(phi)
    Rs(Y) = R(Y)/R_m = 1 + Y sin(theta)

``theta`` is the roller half angle, ``Y_d`` the profile start, ``R_d* = R_d/R_m`` the dub-off radius,
``phi`` the tilt (positive: counter-clockwise in the paper's Fig. 1, opening the large end). ``Rs`` is
taken along the generator (the contact line), ``1 + Y sin(theta)``; along the axis it would be
``1 + Y tan(theta)``, 1.5 % different at ``|Y| = 0.7`` for theta = 10 deg (docs/ehl.md). The local
entrainment speed follows the radius, ``U = U_m Rs(Y)``. The race is taken flat (the paper's reduced
geometry): ``Rs`` is also the reduced radius of curvature in the rolling direction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from transient.checks import check_positive, check_range


@dataclass(frozen=True)
class TaperedRoller:
    """Geometry of the roller, SI: ``mean_radius`` R_m [m], ``half_angle_deg`` theta [deg],
    ``length`` [m] along the generator, ``dub_off_radius`` R_d [m], ``profile_start`` y_d [m] (distance
    of the start of the dub-off from the mid-plane, both ends), ``tilt_deg`` phi [deg]."""

    mean_radius: float
    half_angle_deg: float = 0.0
    length: float | None = None
    dub_off_radius: float = math.inf
    profile_start: float | None = None
    tilt_deg: float = 0.0

    def __post_init__(self):
        check_positive("mean_radius", self.mean_radius, "m")
        check_range("half_angle_deg", self.half_angle_deg, "deg", 0.0, 30.0)
        length = 2.0 * self.mean_radius if self.length is None else self.length
        check_positive("length", length, "m")
        object.__setattr__(self, "length", float(length))
        if self.dub_off_radius != math.inf:  # math.inf: no dub-off (a straight roller)
            check_range("dub_off_radius", self.dub_off_radius, "m", 1e-6, math.inf, high_open=True,
                        why="(or math.inf: no dub-off)")
        start = 0.5 * length if self.profile_start is None else self.profile_start
        check_range("profile_start", start, "m", 0.0, 0.5 * length, why=f"(at most half the length = {length!r} m)")
        object.__setattr__(self, "profile_start", float(start))
        check_range("tilt_deg", self.tilt_deg, "deg", -5.0, 5.0)
        if math.sin(math.radians(self.half_angle_deg)) * 0.5 * length >= self.mean_radius:
            raise ValueError(f"half_angle_deg = {self.half_angle_deg!r} [deg] with length = {length!r} [m] gives a "
                             f"non-positive radius at the small end for mean_radius = {self.mean_radius!r} [m]")

    # dimensionless geometry (units of R_m) -----------------------------------------------------------
    @property
    def half_length(self) -> float:
        """``L / (2 R_m)``."""
        return 0.5 * self.length / self.mean_radius

    @property
    def y_d(self) -> float:
        """Profile start ``Y_d = y_d / R_m``."""
        return self.profile_start / self.mean_radius

    @property
    def r_d(self) -> float:
        """Dub-off radius ``R_d* = R_d / R_m``."""
        return self.dub_off_radius / self.mean_radius

    def radius_ratio(self, Y):
        """``Rs(Y) = 1 + Y sin(theta)``."""
        return 1.0 + np.asarray(Y, float) * math.sin(math.radians(self.half_angle_deg))

    def profile(self, Y):
        """Dub-off drop ``(|Y| - Y_d)^2 / (2 R_d*)`` beyond the profile start, 0 inside."""
        excess = np.clip(np.abs(np.asarray(Y, float)) - self.y_d, 0.0, None)
        return excess * excess / (2.0 * self.r_d)

    def tilt(self, Y):
        """``Y tan(phi)``."""
        return np.asarray(Y, float) * math.tan(math.radians(self.tilt_deg))

    def gap(self, X, Y):
        """Rigid gap ``H_rigid(X, Y)`` (module docstring), broadcasting X and Y."""
        X, Y = np.asarray(X, float), np.asarray(Y, float)
        return X * X / (2.0 * self.radius_ratio(Y)) + self.profile(Y) + self.tilt(Y)

    def with_tilt(self, tilt_deg: float) -> "TaperedRoller":
        return TaperedRoller(self.mean_radius, self.half_angle_deg, self.length, self.dub_off_radius,
                             self.profile_start, tilt_deg)
