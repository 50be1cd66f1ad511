"""Short-damper closed forms for a circular centred orbit (CCO) of a squeeze-film damper.

The journal (held against spin by an anti-rotation pin) whirls at ``omega`` on an orbit of radius ``e = eps c``. With
``L / D -> 0`` the Reynolds equation of one land loses its circumferential flow, ``d/dz(h^3 dp/dz) = 12 mu dh/dt``
with ``h = c (1 - eps cos phi)`` (phi from the minimum film, in the whirl direction) and ``dh/dt = -e omega sin phi``;
with the pressure equal at both ends of a land of length ``l``,
``p = 6 mu e omega sin(phi) (l^2/4 - z^2) / h^3`` (above the end pressure), and integrating ``-p (cos, sin)`` over
the journal gives the film force along the line of centres (radial, + outwards) and across it (tangential, + in the
whirl direction) [Vance, *Rotordynamics of Turbomachinery*, Wiley 1988, ch. 6; San Andres, *Modern Lubrication
Theory*, Notes 13 "Squeeze film dampers", Texas A&M 2010]:

* uncavitated (2-pi) film: ``F_r = 0``, ``F_t = -pi mu R l^3 omega eps / (c^2 (1 - eps^2)^(3/2))``;
* pi-film (Guembel: the half of negative pressure set to the ambient):
  ``F_r = -2 mu R l^3 omega eps^2 / (c^2 (1 - eps^2)^2)``, ``F_t = -pi mu R l^3 omega eps / (2 c^2 (1 - eps^2)^(3/2))``.

A land closed at one end (an end seal that lets nothing through) and held at the supply pressure at the other is
half of an open land twice as long (the symmetry plane of that land): its forces are half those of length ``2 l``.
ROSS's ``SqueezeFilmDamper`` uses the same forms as damping ``-F_t / (e omega)`` and stiffness ``-F_r / e``
(docs/disagreements.md records where its variants differ).
"""

from __future__ import annotations

import numpy as np

#: The films of the closed forms: ``"pi"`` (Guembel's half film) and ``"2pi"`` (uncavitated).
FILMS = ("pi", "2pi")


def open_land_forces(eccentricity_ratio, whirl_speed, viscosity, radius, land_length, clearance, film="2pi"):
    """Radial and tangential film force [N] of one open land of length ``land_length`` [m] (both ends at the same
    pressure) on a circular centred orbit at ``whirl_speed`` [rad/s] (module docstring)."""
    eps = np.asarray(eccentricity_ratio, dtype=float)
    unit = viscosity * radius * land_length ** 3 * whirl_speed / clearance ** 2
    tangential = -np.pi * unit * eps / (1.0 - eps ** 2) ** 1.5
    if film == "2pi":
        return np.zeros_like(eps), tangential
    if film == "pi":
        return -2.0 * unit * eps ** 2 / (1.0 - eps ** 2) ** 2, 0.5 * tangential
    raise ValueError(f"film must be one of {FILMS!r}, got film = {film!r}")


def land_forces(lands, eccentricity_ratio, whirl_speed, viscosity, radius, clearance, film="2pi"):
    """The short-damper forces [N] summed over ``lands``: pairs (length [m], closed: True when one end is sealed shut),
    a closed land being half of an open land of twice its length."""
    radial = tangential = 0.0
    for length, closed in lands:
        span = 2.0 * length if closed else length
        fr, ft = open_land_forces(eccentricity_ratio, whirl_speed, viscosity, radius, span, clearance, film)
        share = 0.5 if closed else 1.0
        radial, tangential = radial + share * fr, tangential + share * ft
    return radial, tangential
