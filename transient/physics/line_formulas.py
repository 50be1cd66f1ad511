"""Line (infinitely long) contacts: Hertz, and the published EHL film-thickness formulas.

Dimensionless groups per unit length (Dowson & Higginson, *Elasto-Hydrodynamic Lubrication*, 1966/77;
Hamrock, *Fundamentals of Fluid Film Lubrication*, ch. 21), with ``u`` the mean entrainment speed
``(u_a + u_b)/2``, ``w`` the load per unit length, ``E' = 2/((1-nu_a^2)/E_a + (1-nu_b^2)/E_b)``::

    U = eta0 u / (E' R),   G = alpha E',   W = w / (E' R),   H = h / R

Hertz (Johnson, *Contact Mechanics*, eq. 4.45 with E* = E'/2)::

    b = sqrt(8 w R / (pi E')),   p_h = sqrt(w E' / (2 pi R)) = E' b / (4 R),   p = p_h sqrt(1 - x^2/b^2)

Film formulas::

    Dowson & Higginson (1966), minimum:   H_min = 2.65 U^0.70 G^0.54 W^-0.13
    Dowson & Toyoda (1979), central:       H_c   = 3.06 U^0.69 G^0.56 W^-0.10
    Pan & Hamrock (1989), minimum/central: H_min = 1.714 U^0.694 G^0.568 W^-0.128
                                           H_c   = 2.922 U^0.692 G^0.470 W^-0.166
    Martin (1916), rigid, isoviscous:      H_min = 4.9 U / W     (Reynolds exit condition)
"""

from __future__ import annotations

import math


def line_groups(viscosity: float, speed: float, pressure_viscosity: float, load_per_length: float,
                modulus: float, radius: float) -> tuple[float, float, float]:
    """``(U, G, W)`` of a line contact (module docstring), SI inputs."""
    return (viscosity * speed / (modulus * radius), pressure_viscosity * modulus, load_per_length / (modulus * radius))


def hertz_line(load_per_length: float, radius: float, modulus: float) -> tuple[float, float]:
    """Hertz half-width ``b`` [m] and maximum pressure ``p_h`` [Pa] of a cylinder on a plane
    (``radius`` the reduced radius, ``modulus`` E')."""
    b = math.sqrt(8.0 * load_per_length * radius / (math.pi * modulus))
    return b, modulus * b / (4.0 * radius)


def dowson_higginson_min(U: float, G: float, W: float) -> float:
    """Dowson & Higginson (1966) minimum film ``H_min = h_min / R``."""
    return 2.65 * U ** 0.70 * G ** 0.54 * W ** -0.13


def dowson_toyoda_central(U: float, G: float, W: float) -> float:
    """Dowson & Toyoda (1979) central film ``H_c = h_c / R``."""
    return 3.06 * U ** 0.69 * G ** 0.56 * W ** -0.10


def pan_hamrock_min(U: float, G: float, W: float) -> float:
    """Pan & Hamrock (1989) minimum film ``H_min``."""
    return 1.714 * U ** 0.694 * G ** 0.568 * W ** -0.128


def pan_hamrock_central(U: float, G: float, W: float) -> float:
    """Pan & Hamrock (1989) central film ``H_c``."""
    return 2.922 * U ** 0.692 * G ** 0.470 * W ** -0.166


def martin_min(U: float, W: float) -> float:
    """Martin (1916) rigid-isoviscous minimum film ``H_min = 4.9 U / W`` (Reynolds exit condition)."""
    return 4.9 * U / W
