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

Viscosity against temperature ``T`` [K] (absolute viscosity [Pa s]; the thermal films), each optionally times
Barus' ``exp(alpha p)``::

    exponential  mu = mu_r exp(-beta (T - T_r))                  (Reynolds' law; ExponentialViscosity)
    two-point    the exponential law through (T1, mu1), (T2, mu2): beta = ln(mu1 / mu2) / (T2 - T1)
    Vogel        mu = a exp(b / (T - c))                          (Vogel 1921; VogelViscosity)

and the oil's thermal properties (:class:`ThermalProperties`: density, specific heat, conductivity).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from transient.checks import check_items, check_positive, check_range

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


# --------------------------------------------------------------------------------------------------
# Viscosity against temperature (thermal films)
# --------------------------------------------------------------------------------------------------

#: Law codes of :func:`temperature_viscosity_point`.
EXPONENTIAL, VOGEL = 0, 1
#: The temperatures [K] a law is asked about (an oil film between its freezing and its flash point, with margin).
TEMPERATURE_RANGE_K = (150.0, 800.0)


@njit(cache=True, error_model="numpy")
def temperature_viscosity_point(law, T, a, b, c):
    """Viscosity [Pa s] at ``T`` [K]: ``a exp(-b (T - c))`` (:data:`EXPONENTIAL`: a = mu_r, b = beta [1/K], c = T_r)
    or ``a exp(b / (T - c))`` (:data:`VOGEL`: a [Pa s], b [K], c [K])."""
    if law == VOGEL:
        return a * math.exp(b / (T - c))
    return a * math.exp(-b * (T - c))


@njit(cache=True, error_model="numpy")
def temperature_viscosity_array(law, T, a, b, c, out):
    """:func:`temperature_viscosity_point` of every entry of ``T`` into ``out``."""
    for i in range(T.size):
        out[i] = temperature_viscosity_point(law, T[i], a, b, c)


def _check_temperature(name, value):
    return check_range(name, value, "K", *TEMPERATURE_RANGE_K, why="(absolute temperature of an oil film)")


class _TemperatureLaw:
    """What the temperature laws share: ``at(T, p)`` [Pa s] and the kernel arguments."""

    code = EXPONENTIAL
    pressure_viscosity = 0.0

    def kernel_args(self) -> tuple:
        """``(law code, a, b, c)`` of :func:`temperature_viscosity_point`."""
        raise NotImplementedError

    def at(self, temperature, pressure=0.0):
        """Viscosity [Pa s] at temperatures ``temperature`` [K] (array or number) and gauge pressure ``pressure``
        [Pa] (Barus ``exp(alpha p)`` with ``pressure_viscosity`` alpha; 1 when alpha = 0)."""
        T = np.atleast_1d(np.asarray(temperature, dtype=float))
        lo, hi = TEMPERATURE_RANGE_K
        if not np.all((T >= lo) & (T <= hi)):
            bad = T[~((T >= lo) & (T <= hi))][0]
            raise ValueError(f"temperature = {bad!r} [K] is out of range; allowed: [{lo:g}, {hi:g}] K")
        out = np.empty(T.size)
        law, a, b, c = self.kernel_args()
        temperature_viscosity_array(law, np.ascontiguousarray(T.ravel()), a, b, c, out)
        mu = out.reshape(T.shape)
        if self.pressure_viscosity != 0.0:
            mu = mu * np.exp(self.pressure_viscosity * np.asarray(pressure, dtype=float))
        return mu if np.ndim(temperature) else float(mu[0])


@dataclass(frozen=True)
class ExponentialViscosity(_TemperatureLaw):
    """``mu = viscosity exp(-coefficient (T - temperature))`` [Pa s]: ``viscosity`` [Pa s] at ``temperature`` [K],
    temperature-viscosity ``coefficient`` beta [1/K] (0: isoviscous; mineral oils 0.02-0.05),
    ``pressure_viscosity`` alpha [1/Pa] (Barus; 0: none)."""

    viscosity: float
    temperature: float
    coefficient: float
    pressure_viscosity: float = 0.0

    def __post_init__(self):
        check_range("viscosity", self.viscosity, "Pa s", 1e-6, 1e4)
        _check_temperature("temperature", self.temperature)
        check_range("coefficient", self.coefficient, "1/K", 0.0, 1.0,
                    why="(an oil's viscosity falls with temperature: beta >= 0)")
        check_range("pressure_viscosity", self.pressure_viscosity, "1/Pa", 0.0, 1e-6)

    def kernel_args(self) -> tuple:
        return (EXPONENTIAL, self.viscosity, self.coefficient, self.temperature)

    @classmethod
    def two_point(cls, first, second, pressure_viscosity=0.0) -> "ExponentialViscosity":
        """The exponential law through two points ``(T1 [K], mu1 [Pa s])``, ``(T2, mu2)`` (T1 != T2; the
        viscosity must not rise with temperature); equal viscosities give beta = 0 exactly."""
        (T1, mu1), (T2, mu2) = (check_items(f"viscosity_at[{k}]", v, "(temperature [K], viscosity [Pa s])", 2)
                                for k, v in enumerate(check_items("viscosity_at", (first, second),
                                                                  "two (temperature [K], viscosity [Pa s]) pairs", 2)))
        T1, T2 = _check_temperature("viscosity_at[0][0]", T1), _check_temperature("viscosity_at[1][0]", T2)
        mu1 = check_range("viscosity_at[0][1]", mu1, "Pa s", 1e-6, 1e4)
        mu2 = check_range("viscosity_at[1][1]", mu2, "Pa s", 1e-6, 1e4)
        if T1 == T2:
            raise ValueError(f"viscosity_at[1][0] = {T2!r} [K] equals viscosity_at[0][0]; allowed: two different "
                             "temperatures")
        beta = math.log(mu1 / mu2) / (T2 - T1)
        if beta < 0.0:
            raise ValueError(f"viscosity_at = (({T1:g} K, {mu1:g} Pa s), ({T2:g} K, {mu2:g} Pa s)): the viscosity "
                             "rises with temperature; allowed: mu at the higher temperature at most mu at the lower")
        return cls(mu1, T1, beta, pressure_viscosity)


@dataclass(frozen=True)
class VogelViscosity(_TemperatureLaw):
    """Vogel's law ``mu = a exp(b / (T - c))``: ``a`` [Pa s], ``b`` [K], ``c`` [K] (below every temperature it
    is asked about), ``pressure_viscosity`` alpha [1/Pa] (Barus; 0: none)."""

    a: float
    b: float
    c: float
    pressure_viscosity: float = 0.0

    code = VOGEL

    def __post_init__(self):
        check_range("a", self.a, "Pa s", 1e-12, 1e4, low_open=True)
        check_range("b", self.b, "K", 0.0, 1e5)
        check_range("c", self.c, "K", 0.0, TEMPERATURE_RANGE_K[0], high_open=True,
                    why=f"(below the lowest temperature a law is asked about, {TEMPERATURE_RANGE_K[0]:g} K)")
        check_range("pressure_viscosity", self.pressure_viscosity, "1/Pa", 0.0, 1e-6)

    def kernel_args(self) -> tuple:
        return (VOGEL, self.a, self.b, self.c)


@dataclass(frozen=True)
class ThermalProperties:
    """An oil's ``density`` [kg/m^3], specific ``heat_capacity`` [J/(kg K)] and thermal ``conductivity``
    [W/(m K)] (mineral oils: about 870, 1900-2100, 0.13), taken constant over the film's temperatures."""

    density: float
    heat_capacity: float
    conductivity: float = 0.13

    def __post_init__(self):
        check_range("density", self.density, "kg/m^3", 100.0, 3000.0)
        check_range("heat_capacity", self.heat_capacity, "J/(kg K)", 100.0, 10000.0)
        check_range("conductivity", self.conductivity, "W/(m K)", 1e-3, 10.0)

    @property
    def volumetric_heat(self) -> float:
        """``density * heat_capacity`` [J/(m^3 K)]."""
        return self.density * self.heat_capacity
