"""Pressure-dependent viscosity and density of a lubricant: Barus, Roelands, Dowson-Higginson.

Every law is a numba kernel returning the value relative to its ambient value and its derivative with
respect to the pressure ``p`` [Pa] (gauge), pointwise (``*_point``, callable from other kernels) and
vectorised over arrays (``*_array``). Used by the EHL models (Park) and available to the
journal and layered films.

Viscosity, ``eta / eta0``::

    Barus      eta/eta0 = exp(alpha p)                                              (Park eq. 2)
    Roelands   eta/eta0 = exp( (ln eta0 + 9.67) [ (1 + p/p_r)^Z - 1 ] ),
               p_r = 1.96e8 Pa, Z = alpha p_r / (ln eta0 + 9.67)   (eta0 in Pa s)

(Z chosen so that Roelands and Barus share the slope ``alpha`` at ``p = 0``; Roelands, 1966; Houpert,
1985). Density, ``rho / rho0`` (Dowson & Higginson, 1966)::

    rho/rho0 = 1 + c1 p / (1 + c2 p)

with the paper's constants ``c1 = 0.58 /GPa, c2 = 1.68 /GPa`` (Park eq. 3; the classic values are 0.6
and 1.7 /GPa, :data:`DOWSON_HIGGINSON_CLASSIC`), or incompressible (``rho/rho0 = 1``).

Law codes (for kernels that take the law as an argument): :data:`BARUS`, :data:`ROELANDS`,
:data:`ISOVISCOUS`; :data:`DOWSON_HIGGINSON`, :data:`INCOMPRESSIBLE`. :class:`Lubricant` bundles a
viscosity law and a density law with their constants, validated, and evaluates both on arrays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from transient.checks import check_positive, check_range

ISOVISCOUS, BARUS, ROELANDS = 0, 1, 2
INCOMPRESSIBLE, DOWSON_HIGGINSON = 0, 1
VISCOSITY_LAWS = {"isoviscous": ISOVISCOUS, "barus": BARUS, "roelands": ROELANDS}
DENSITY_LAWS = {"incompressible": INCOMPRESSIBLE, "dowson-higginson": DOWSON_HIGGINSON}

#: Roelands' reference pressure [Pa] and the constant 9.67 (= -ln(6.31e-5 Pa s))
ROELANDS_P_R = 1.96e8
ROELANDS_LN_ETA_INF = 9.67
#: Dowson-Higginson constants [1/Pa]: the paper's (Park eq. 3) and the classic ones
DOWSON_HIGGINSON_PARK = (0.58e-9, 1.68e-9)
DOWSON_HIGGINSON_CLASSIC = (0.6e-9, 1.7e-9)


@njit(cache=True, error_model="numpy")
def barus_point(p, alpha):
    """``(exp(alpha p), alpha exp(alpha p))``."""
    e = math.exp(alpha * p)
    return e, alpha * e


@njit(cache=True, error_model="numpy")
def roelands_point(p, alpha, ln_eta0):
    """Roelands ``eta/eta0`` and its p-derivative; ``ln_eta0`` = ln(eta0 / 1 Pa s)."""
    a = ln_eta0 + ROELANDS_LN_ETA_INF
    z = alpha * ROELANDS_P_R / a
    base = 1.0 + p / ROELANDS_P_R
    if base <= 0.0:  # far below ambient (never at a solution): continue with the Barus slope
        e = math.exp(alpha * p)
        return e, alpha * e
    bz = base ** z
    e = math.exp(a * (bz - 1.0))
    return e, e * a * z * bz / base / ROELANDS_P_R


@njit(cache=True, error_model="numpy")
def viscosity_point(law, p, alpha, ln_eta0):
    """``eta/eta0`` and ``d(eta/eta0)/dp`` [1/Pa] for the law code ``law``."""
    if law == BARUS:
        return barus_point(p, alpha)
    if law == ROELANDS:
        return roelands_point(p, alpha, ln_eta0)
    return 1.0, 0.0


@njit(cache=True, error_model="numpy")
def density_point(law, p, c1, c2):
    """``rho/rho0`` and ``d(rho/rho0)/dp`` [1/Pa] for the law code ``law`` (Dowson-Higginson c1, c2)."""
    if law == DOWSON_HIGGINSON:
        d = 1.0 + c2 * p
        return 1.0 + c1 * p / d, c1 / (d * d)
    return 1.0, 0.0


@njit(cache=True, error_model="numpy")
def viscosity_array(law, p, alpha, ln_eta0):
    """Vectorised :func:`viscosity_point`: returns two arrays shaped like ``p``."""
    v = np.empty_like(p)
    dv = np.empty_like(p)
    fv, fd = v.ravel(), dv.ravel()
    fp = p.ravel()
    for k in range(fp.size):
        fv[k], fd[k] = viscosity_point(law, fp[k], alpha, ln_eta0)
    return v, dv


@njit(cache=True, error_model="numpy")
def density_array(law, p, c1, c2):
    """Vectorised :func:`density_point`: returns two arrays shaped like ``p``."""
    v = np.empty_like(p)
    dv = np.empty_like(p)
    fv, fd = v.ravel(), dv.ravel()
    fp = p.ravel()
    for k in range(fp.size):
        fv[k], fd[k] = density_point(law, fp[k], c1, c2)
    return v, dv


@dataclass(frozen=True)
class Lubricant:
    """A viscosity law and a density law with their constants (SI).

    ``viscosity`` eta0 [Pa s] (needed by Roelands; Barus and isoviscous use only ratios),
    ``pressure_viscosity`` alpha [1/Pa], ``viscosity_law`` in :data:`VISCOSITY_LAWS`, ``density`` in
    :data:`DENSITY_LAWS`, ``dh_constants`` (c1, c2) [1/Pa] of Dowson-Higginson.
    """

    viscosity: float
    pressure_viscosity: float
    viscosity_law: str = "barus"
    density: str = "dowson-higginson"
    dh_constants: tuple = DOWSON_HIGGINSON_PARK

    def __post_init__(self):
        check_positive("viscosity", self.viscosity, "Pa s")
        check_range("pressure_viscosity", self.pressure_viscosity, "1/Pa", 0.0, 1e-6)
        if self.viscosity_law not in VISCOSITY_LAWS:
            raise ValueError(f"viscosity_law = {self.viscosity_law!r} is not one of {sorted(VISCOSITY_LAWS)}")
        if self.density not in DENSITY_LAWS:
            raise ValueError(f"density = {self.density!r} is not one of {sorted(DENSITY_LAWS)}")
        c1, c2 = self.dh_constants
        check_range("dh_constants[0]", c1, "1/Pa", 0.0, 1e-8)
        check_range("dh_constants[1]", c2, "1/Pa", 0.0, 1e-8)

    @property
    def viscosity_code(self) -> int:
        return VISCOSITY_LAWS[self.viscosity_law]

    @property
    def density_code(self) -> int:
        return DENSITY_LAWS[self.density]

    @property
    def ln_eta0(self) -> float:
        return math.log(self.viscosity)

    def kernel_args(self) -> tuple:
        """Constants for the pointwise kernels, SI: ``(viscosity code, alpha, ln eta0, density code, c1, c2)``."""
        c1, c2 = self.dh_constants
        return (self.viscosity_code, self.pressure_viscosity, self.ln_eta0, self.density_code, c1, c2)

    def eta(self, p):
        """``(eta/eta0, d(eta/eta0)/dp)`` at pressures ``p`` [Pa]."""
        return viscosity_array(self.viscosity_code, np.asarray(p, dtype=float), self.pressure_viscosity, self.ln_eta0)

    def rho(self, p):
        """``(rho/rho0, d(rho/rho0)/dp)`` at pressures ``p`` [Pa]."""
        c1, c2 = self.dh_constants
        return density_array(self.density_code, np.asarray(p, dtype=float), c1, c2)
