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

Moes' groups and his central-film formula for line contacts (Moes, *Optimum similarity analysis with
applications to elastohydrodynamic lubrication*, Wear 159, 1992; as quoted by Venner & Lubrecht,
*Multilevel Methods in Lubrication*, Elsevier 2000), with ``U`` of the mean speed as above::

    M = W (2U)^-1/2,   L = G (2U)^1/4,   H_M = (h/R) (2U)^-1/2
    H_RI = 3 M^-1 (rigid-isoviscous),           H_EI = 2.621 M^-1/5 (elastic-isoviscous)
    H_RP = 1.287 L^2/3 (rigid-piezoviscous),    H_EP = 1.311 M^-1/8 L^3/4 (elastic-piezoviscous)
    H_c = [ (H_RI^7/3 + H_EI^7/3)^(3s/7) + (H_RP^-7/2 + H_EP^-7/2)^(-2s/7) ]^(1/s),
    s = (7 + 8 exp(-2 H_EI / H_RI)) / 5

(a curve fit through the four asymptotes and numerical solutions, stated to a few per cent). In these
groups H_EP is the Dowson-Toyoda central film exactly at G = 5000, U = 1e-11, W = 1e-4 (2.33e-5 both).
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


def moes_groups(U: float, G: float, W: float) -> tuple[float, float]:
    """Moes' line-contact groups ``(M, L) = (W (2U)^-1/2, G (2U)^1/4)`` (module docstring)."""
    return W / math.sqrt(2.0 * U), G * (2.0 * U) ** 0.25


def moes_asymptotes(M: float, L: float) -> dict:
    """The four asymptotes of the central film ``H_M = (h_c/R) (2U)^-1/2`` (module docstring)."""
    return dict(RI=3.0 / M, EI=2.621 * M ** -0.2, RP=1.287 * L ** (2.0 / 3.0), EP=1.311 * M ** -0.125 * L ** 0.75)


def moes_central(M: float, L: float) -> float:
    """Moes' central film ``H_M = (h_c/R) (2U)^-1/2`` of a line contact (module docstring)."""
    a = moes_asymptotes(M, L)
    s = (7.0 + 8.0 * math.exp(-2.0 * a["EI"] / a["RI"])) / 5.0
    iso = (a["RI"] ** (7.0 / 3.0) + a["EI"] ** (7.0 / 3.0)) ** (3.0 * s / 7.0)
    piezo = 0.0
    if L > 0:  # (RP^-3.5 + EP^-3.5)^(-2s/7) through logarithms: it tends to 0 as L -> 0 instead of overflowing
        l1, l2 = -3.5 * math.log(a["RP"]), -3.5 * math.log(a["EP"])
        top = max(l1, l2)
        piezo = math.exp(-2.0 * s / 7.0 * (top + math.log(math.exp(l1 - top) + math.exp(l2 - top))))
    return (iso + piezo) ** (1.0 / s)
