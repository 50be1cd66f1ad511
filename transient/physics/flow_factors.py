"""Average-flow-model factors: Patir-Cheng pressure and shear flow factors, Wu-Zheng contact factor.

All functions take the film parameter H = h / sigma (nominal film thickness over the composite RMS
roughness) and the Peklenik number gamma = lambda_0.5x / lambda_0.5y (gamma > 1: streaks along x,
"longitudinal"; gamma < 1: "transverse").  Arrays are vectorised.

Pressure flow factor (N. Patir & H. S. Cheng, ASME J. Lubr. Technol. 100 (1978) 12-17, eq. (20)
and Table 1; Lee & Rhim Appendix 1):

    phi_x = 1 - C exp(-r H)    gamma <= 1
    phi_x = 1 + C H^(-r)       gamma > 1
    phi_y(H, gamma) = phi_x(H, 1/gamma)

    gamma   1/9   1/6   1/3    1     3     6     9
    C       1.48  1.38  1.18  0.90  0.225 0.520 0.870
    r       0.42  0.42  0.42  0.56  1.5   1.5   1.5
    range   H>1   H>1   H>0.75 H>0.5 H>0.5 H>0.5 H>0.5

Shear flow factor (Patir & Cheng, ASME J. Lubr. Technol. 101 (1979) 220-230, eqs. (A3)-(A4),
Table A1; Lee & Rhim Appendix 2):

    Phi_s = A1 H^alpha1 exp(-alpha2 H + alpha3 H^2)   H <= 5
    Phi_s = A2 exp(-0.25 H)                             H > 5
    phi_s = Vr1 Phi_s(H, gamma1) - Vr2 Phi_s(H, gamma2),   Vr_i = (sigma_i/sigma)^2

    gamma   A1     alpha1 alpha2 alpha3  A2
    1/9     2.046  1.12   0.78   0.03    1.856
    1/6     1.962  1.08   0.77   0.03    1.754
    1/3     1.858  1.01   0.76   0.03    1.561
    1       1.899  0.98   0.92   0.05    1.126
    3       1.560  0.85   1.13   0.08    0.556
    6       1.290  0.62   1.09   0.08    0.388
    9       1.011  0.54   1.07   0.08    0.295
    (fitted for H > 0.5)

These coefficients are transcribed from the cited tables (not re-derived here).  Between tabulated
gamma the factor is interpolated linearly in log(gamma) between the two neighbouring tabulated
fits (this reproduces the table exactly and is continuous in gamma); gamma outside [1/9, 9] is an
error.  Below the fitted range of H an error is raised unless ``extrapolate=True`` (the fit is then
evaluated as written and, for phi_x, clipped at 0).

Contact factor (C. Wu & L. Zheng, ASME J. Tribol. 111 (1989) 188-191; Lee & Rhim eq. (9)):

    phi_c = d(h_bar)/d(h0) = P(local gap > 0) = int_{-h0}^{inf} phi(z) dz,

for Gaussian heights phi_c = Phi(H) (standard normal CDF): 1/2 at H = 0, -> 1 for H >> 1, -> 0 for
H << 0.  The mean film thickness is h_bar/sigma = H Phi(H) + phi(H).  Wu & Zheng's exponential-
polynomial fit is :func:`contact_factor_wu_zheng_fit`.
For a generated surface use ``DiscreteDensity.contact_factor`` (asperity module).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

__all__ = [
    "PRESSURE_FLOW_TABLE",
    "SHEAR_FLOW_TABLE",
    "pressure_flow_factors",
    "shear_flow_factor",
    "pressure_flow_factor_slopes",
    "shear_flow_factor_slope",
    "combined_shear_flow_factor",
    "contact_factor",
    "mean_film_thickness",
    "contact_factor_wu_zheng_fit",
]

# gamma: (C, r, H_min)
PRESSURE_FLOW_TABLE = {
    1 / 9: (1.48, 0.42, 1.0),
    1 / 6: (1.38, 0.42, 1.0),
    1 / 3: (1.18, 0.42, 0.75),
    1.0: (0.90, 0.56, 0.5),
    3.0: (0.225, 1.5, 0.5),
    6.0: (0.520, 1.5, 0.5),
    9.0: (0.870, 1.5, 0.5),
}
# gamma: (A1, alpha1, alpha2, alpha3, A2)
SHEAR_FLOW_TABLE = {
    1 / 9: (2.046, 1.12, 0.78, 0.03, 1.856),
    1 / 6: (1.962, 1.08, 0.77, 0.03, 1.754),
    1 / 3: (1.858, 1.01, 0.76, 0.03, 1.561),
    1.0: (1.899, 0.98, 0.92, 0.05, 1.126),
    3.0: (1.560, 0.85, 1.13, 0.08, 0.556),
    6.0: (1.290, 0.62, 1.09, 0.08, 0.388),
    9.0: (1.011, 0.54, 1.07, 0.08, 0.295),
}
_GAMMAS = np.array(sorted(PRESSURE_FLOW_TABLE))
_SHEAR_H_MIN = 0.5


def _gamma_bracket(gamma: float):
    """The tabulated gammas around ``gamma`` and their weights (linear in log gamma)."""
    g = float(gamma)
    if not (_GAMMAS[0] * (1 - 1e-12) <= g <= _GAMMAS[-1] * (1 + 1e-12)):
        raise ValueError(f"parameter gamma = {g:g} [-] out of range: the Patir-Cheng fits cover [1/9, 9]")
    i = int(np.searchsorted(_GAMMAS, g * (1 - 1e-12)))
    i = min(max(i, 0), len(_GAMMAS) - 1)
    if abs(_GAMMAS[i] - g) <= 1e-12 * g or i == 0:
        return [(float(_GAMMAS[i]), 1.0)]
    g0, g1 = float(_GAMMAS[i - 1]), float(_GAMMAS[i])
    w1 = math.log(g / g0) / math.log(g1 / g0)
    return [(g0, 1.0 - w1), (g1, w1)]


def _key(g):
    for k in PRESSURE_FLOW_TABLE:
        if abs(k - g) <= 1e-12 * k:
            return k
    raise KeyError(g)


def _phi_x_tab(H, g, extrapolate):
    C, r, hmin = PRESSURE_FLOW_TABLE[_key(g)]
    if not extrapolate and np.any(H < hmin):
        raise ValueError(f"parameter H = h/sigma = {float(np.min(H)):g} [-] out of range for the Patir-Cheng "
                         f"pressure flow fit at gamma = {g:.4g}: allowed H >= {hmin:g} (or extrapolate=True)")
    with np.errstate(divide="ignore"):
        if g <= 1.0:
            return np.clip(1.0 - C * np.exp(-r * H), 0.0, None)
        return 1.0 + C * np.power(np.clip(H, 1e-300, None), -r)


def pressure_flow_factors(H, gamma: float = 1.0, extrapolate: bool = False):
    """Patir-Cheng pressure flow factors (phi_x, phi_y) at H = h/sigma for surface pattern gamma.

    See module docstring for the fit and table.  phi_y(H, gamma) = phi_x(H, 1/gamma).
    """
    H = np.asarray(H, dtype=float)
    phix = sum(w * _phi_x_tab(H, g, extrapolate) for g, w in _gamma_bracket(gamma))
    phiy = sum(w * _phi_x_tab(H, g, extrapolate) for g, w in _gamma_bracket(1.0 / float(gamma)))
    if H.ndim == 0:
        return float(phix), float(phiy)
    return phix, phiy


def _phi_x_slope_tab(H, g):
    C, r, _ = PRESSURE_FLOW_TABLE[_key(g)]
    if g <= 1.0:
        return np.where(1.0 - C * np.exp(-r * H) > 0.0, C * r * np.exp(-r * H), 0.0)
    return -r * C * np.power(np.clip(H, 1e-300, None), -r - 1.0)


def pressure_flow_factor_slopes(H, gamma: float = 1.0):
    """d(phi_x)/dH and d(phi_y)/dH of :func:`pressure_flow_factors` (the fits differentiated as written, no range
    check: the caller keeps H in the fitted range)."""
    H = np.asarray(H, dtype=float)
    dx = sum(w * _phi_x_slope_tab(H, g) for g, w in _gamma_bracket(gamma))
    dy = sum(w * _phi_x_slope_tab(H, g) for g, w in _gamma_bracket(1.0 / float(gamma)))
    return dx, dy


def _phi_s_slope_tab(H, g):
    A1, a1, a2, a3, A2 = SHEAR_FLOW_TABLE[_key(g)]
    Hc = np.clip(H, 1e-300, 5.0)
    low = A1 * np.power(Hc, a1) * np.exp(-a2 * Hc + a3 * Hc * Hc) * (a1 / Hc - a2 + 2.0 * a3 * Hc)
    return np.where(H <= 5.0, low, -0.25 * A2 * np.exp(-0.25 * H))


def shear_flow_factor_slope(H, gamma: float = 1.0):
    """d(Phi_s)/dH of :func:`shear_flow_factor` (H > 0; no range check)."""
    H = np.asarray(H, dtype=float)
    return sum(w * _phi_s_slope_tab(H, g) for g, w in _gamma_bracket(gamma))


def _phi_s_tab(H, g):
    A1, a1, a2, a3, A2 = SHEAR_FLOW_TABLE[_key(g)]
    Hc = np.clip(H, 0.0, 5.0)
    low = A1 * np.power(Hc, a1) * np.exp(-a2 * Hc + a3 * Hc * Hc)
    return np.where(H <= 5.0, low, A2 * np.exp(-0.25 * H))


def shear_flow_factor(H, gamma: float = 1.0, extrapolate: bool = False):
    """Patir-Cheng (1979) shear flow factor Phi_s(H, gamma) of one rough surface (module docstring)."""
    H = np.asarray(H, dtype=float)
    if not extrapolate and np.any(H < _SHEAR_H_MIN):
        raise ValueError(f"parameter H = h/sigma = {float(np.min(H)):g} [-] out of range for the Patir-Cheng "
                         f"shear flow fit: allowed H >= {_SHEAR_H_MIN:g} (or extrapolate=True)")
    if extrapolate and np.any(H < 0):
        raise ValueError(f"parameter H = {float(np.min(H)):g} [-] out of range: Phi_s needs H >= 0")
    out = sum(w * _phi_s_tab(H, g) for g, w in _gamma_bracket(gamma))
    return out if out.ndim else float(out)


def combined_shear_flow_factor(H, sigma1: float, sigma2: float, gamma1: float = 1.0,
                               gamma2: float = 1.0, extrapolate: bool = False):
    """phi_s = Vr1 Phi_s(H, gamma1) - Vr2 Phi_s(H, gamma2), Vr_i = sigma_i^2/(sigma1^2 + sigma2^2).

    Surface 1 moves with U1, surface 2 with U2; the Reynolds shear term is
    (U1 - U2)/2 * sigma * d(phi_s)/dx (Patir & Cheng 1979; Lee & Rhim Appendix 2).
    """
    s1, s2 = float(sigma1), float(sigma2)
    if s1 < 0 or s2 < 0 or s1 + s2 == 0:
        raise ValueError(f"parameters sigma1 = {s1:g} m, sigma2 = {s2:g} m out of range: need >= 0, not both 0")
    v1 = s1 * s1 / (s1 * s1 + s2 * s2)
    return v1 * shear_flow_factor(H, gamma1, extrapolate) - (1.0 - v1) * shear_flow_factor(H, gamma2, extrapolate)


def contact_factor(H):
    """Wu-Zheng contact factor for Gaussian heights: phi_c(H) = Phi(H), H = h0/sigma (any real H)."""
    out = special.ndtr(np.asarray(H, dtype=float))
    return out if np.ndim(out) else float(out)


def mean_film_thickness(H):
    """Gaussian average film thickness h_bar/sigma = int_{-H}^inf (H + z) phi(z) dz = H Phi(H) + phi(H).

    d(h_bar)/d(h0) = phi_c(H) (Lee & Rhim eq. 9).
    """
    H = np.asarray(H, dtype=float)
    out = H * special.ndtr(H) + np.exp(-0.5 * H * H) / math.sqrt(2 * math.pi)
    return out if out.ndim else float(out)


def contact_factor_wu_zheng_fit(H):
    """Wu & Zheng's (1989) closed-form fit of the contact factor, as widely quoted:

        phi_c = exp(-0.6912 + 0.782 H - 0.304 H^2 + 0.0401 H^3)   0 <= H < 3
        phi_c = 1                                               H >= 3
    It agrees with the exact Gaussian phi_c = Phi(H) to within 0.004 on [0, 3) (tested); note it
    slightly exceeds 1 just below H = 3.  (H < 0 is outside the fit: error.)
    """
    H = np.asarray(H, dtype=float)
    if np.any(H < 0):
        raise ValueError(f"parameter H = {float(np.min(H)):g} [-] out of range for the Wu-Zheng fit: allowed [0, inf)")
    Hc = np.clip(H, 0.0, 3.0)
    out = np.where(H < 3.0, np.exp(-0.6912 + 0.782 * Hc - 0.304 * Hc ** 2 + 0.0401 * Hc ** 3), 1.0)
    return out if out.ndim else float(out)


gamma_bracket = _gamma_bracket  # the tabulated gammas a factor at ``gamma`` is interpolated between
