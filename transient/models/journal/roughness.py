"""Rough journal bearing surfaces: the average Reynolds equation's coefficients and the asperity contact pressure of
every film cell, in the journal film's dimensionless units (:mod:`transient.models.journal.kernels`: ``H = h / C``,
pressure in ``p0``, flux in ``C R^2 omega``).

Average flow model (N. Patir & H. S. Cheng, ASME J. Lubr. Technol. 100 (1978) 12-17 and 101 (1979) 220-230) with the
mean film thickness of Gaussian heights (C. Wu & L. Zheng, ASME J. Tribol. 111 (1989) 188-191), journal speed
``U = omega R``, bush at rest, ``Sigma = sigma / C``, ``Hs = h / sigma`` (the factors of
:mod:`transient.physics.flow_factors`)::

    k_x = phi_x(Hs) H^3 / 2,   k_z = phi_z(Hs) H^3 / 2                   (Poiseuille conductances)
    c_x = (h_T / C + Sigma phi_s) / 2,   phi_s = (2 V_j - 1) Phi_s(Hs)    (Couette + shear flow, per unit content)
    h_T / C = Sigma (Hs Phi(Hs) + phi(Hs)),   d(h_T)/dh = phi_c(Hs) = Phi(Hs)   (mean gap, contact factor)

``V_j = sigma_journal^2 / sigma^2`` is the journal's share of the roughness variance (the moving surface; Patir &
Cheng 1979: ``phi_s = V_r1 Phi_s - V_r2 Phi_s`` with surface 1 moving). Below the fits' range (``Hs`` under 0.5 to 1,
depending on gamma) the pressure and shear flow factors are held at the range's edge (their slopes are 0 there): the
fits are not data below it, and the held value keeps the conductance positive through contact.

Asperity contact (Greenwood & Tripp; :class:`~transient.physics.asperity.AsperityContact`): the nominal pressure
``p_a(h)`` of each cell at its nominal gap ``h = C H``, carried by the asperities beside the film pressure.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from transient.checks import check_instance, check_range
from transient.physics.asperity import AsperityContact
from transient.physics.flow_factors import (PRESSURE_FLOW_TABLE, contact_factor, gamma_bracket, mean_film_thickness,
                                            pressure_flow_factor_slopes, pressure_flow_factors, shear_flow_factor,
                                            shear_flow_factor_slope)

__all__ = ["RoughCoefficients", "Roughness", "contact_pressure", "rough_coefficients"]

SHEAR_FIT_H_MIN = 0.5  # [-] lower end of the Patir-Cheng (1979) shear flow fit


@dataclass(frozen=True)
class Roughness:
    """The combined rough surface of a journal bearing (journal + bush).

    Parameters
    ----------
    contact : :class:`~transient.physics.asperity.AsperityContact` -- Greenwood-Tripp asperities: composite RMS
        roughness ``sigma`` [m], asperity density and radius, composite modulus E', hardness.
    gamma [-] : Peklenik number (1 isotropic; > 1 streaks along the rotation, < 1 across it), in [1/9, 9].
    boundary_friction [-] : boundary friction coefficient mu_b of the asperity contacts, in [0, 1].
    journal_variance_share [-] : the journal's share of the roughness variance, ``sigma_journal^2 / sigma^2``, in
        [0, 1] (0.5, default: both surfaces alike, and the shear flow factor cancels).
    pressure_viscosity [1/Pa] : Barus coefficient alpha of the oil in the film, ``mu = mu0 exp(alpha p)`` with p the
        film pressure above cavitation, in [0, 1e-7] (0, default: isoviscous). Steady states only (the Stribeck
        curve, the equilibrium); the transient rough orbit refuses it.
    bore_compliance [m/Pa] : radial compliance K of a Winkler bore, which each cell's film and asperity pressures
        push out by ``K (p + p_a)``, in [0, 1e-11] (0, default: rigid). Steady states only, as ``pressure_viscosity``.
    """

    contact: AsperityContact
    gamma: float = 1.0
    boundary_friction: float = 0.1
    journal_variance_share: float = 0.5
    pressure_viscosity: float = 0.0
    bore_compliance: float = 0.0

    def __post_init__(self):
        check_instance("roughness.contact", self.contact, AsperityContact, "an AsperityContact")
        set_ = lambda k, v: object.__setattr__(self, k, v)
        set_("gamma", check_range("roughness.gamma", self.gamma, "-", 1.0 / 9.0 * (1 - 1e-12), 9.0 * (1 + 1e-12),
                                  why="(the Patir-Cheng fits' Peklenik numbers)"))
        set_("boundary_friction", check_range("roughness.boundary_friction", self.boundary_friction, "-", 0.0, 1.0))
        set_("journal_variance_share", check_range("roughness.journal_variance_share", self.journal_variance_share,
                                                   "-", 0.0, 1.0))
        set_("pressure_viscosity", check_range("roughness.pressure_viscosity", self.pressure_viscosity, "1/Pa", 0.0,
                                               1e-7, why="(Barus coefficients of oils: 1e-8 to 3e-8)"))
        set_("bore_compliance", check_range("roughness.bore_compliance", self.bore_compliance, "m/Pa", 0.0, 1e-11))

    @property
    def sigma(self) -> float:
        """Composite RMS roughness [m]."""
        return float(self.contact.sigma)

    @property
    def fit_floor(self) -> float:
        """Smallest ``h / sigma`` at which the flow factors are evaluated (the fits' lower end at this gamma)."""
        gs = [g for g, _ in gamma_bracket(self.gamma) + gamma_bracket(1.0 / self.gamma)]
        return max([SHEAR_FIT_H_MIN] + [PRESSURE_FLOW_TABLE[g][2] for g in gs])

    def parameters(self) -> dict:
        c = self.contact
        return dict(sigma=self.sigma, gamma=self.gamma, boundary_friction=self.boundary_friction,
                    journal_variance_share=self.journal_variance_share,
                    pressure_viscosity=self.pressure_viscosity, bore_compliance=self.bore_compliance,
                    asperity_density=c.asperity_density,
                    asperity_radius=c.asperity_radius, e_prime=c.e_prime, hardness=c.hardness)


class RoughCoefficients(NamedTuple):
    """Per-cell coefficients of the average Reynolds equation and their slopes d/dH (module docstring)."""

    kx: np.ndarray
    kz: np.ndarray
    cx: np.ndarray
    dkx: np.ndarray
    dkz: np.ndarray
    dcx: np.ndarray
    mean_gap: np.ndarray   # h_T / C
    phi_c: np.ndarray      # contact factor d(h_T)/dh
    dphi_c: np.ndarray     # d(phi_c)/dH


def rough_coefficients(H, roughness: Roughness, clearance: float) -> RoughCoefficients:
    """The coefficients of the average Reynolds equation at the film thickness ``H = h / C`` of every cell."""
    sig = roughness.sigma / clearance
    H = np.asarray(H, dtype=float)
    hr = H / sig
    floor = roughness.fit_floor
    active = hr > floor
    hs = np.where(active, hr, floor)
    phx, phz = pressure_flow_factors(hs, roughness.gamma, extrapolate=True)
    dphx, dphz = pressure_flow_factor_slopes(hs, roughness.gamma)
    w = 2.0 * roughness.journal_variance_share - 1.0
    phs = w * shear_flow_factor(hs, roughness.gamma, extrapolate=True) if w != 0.0 else np.zeros_like(H)
    dphs = w * shear_flow_factor_slope(hs, roughness.gamma) if w != 0.0 else np.zeros_like(H)
    h3 = 0.5 * H ** 3
    phi_c = contact_factor(hr)
    mean_gap = sig * mean_film_thickness(hr)
    return RoughCoefficients(
        kx=h3 * phx, kz=h3 * phz, cx=0.5 * (mean_gap + sig * phs),
        dkx=1.5 * H * H * phx + h3 * np.where(active, dphx, 0.0) / sig,
        dkz=1.5 * H * H * phz + h3 * np.where(active, dphz, 0.0) / sig,
        dcx=0.5 * (phi_c + np.where(active, dphs, 0.0)), mean_gap=mean_gap, phi_c=phi_c,
        dphi_c=np.exp(-0.5 * hr * hr) / np.sqrt(2.0 * np.pi) / sig)


def contact_pressure(H, roughness: Roughness, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """Asperity contact pressure ``p_a`` [Pa] of every cell at its nominal gap ``h = C H`` and ``dp_a/dH`` [Pa]
    (Greenwood-Tripp, :meth:`~transient.physics.asperity.AsperityContact.load`)."""
    h = clearance * np.asarray(H, dtype=float)
    c = roughness.contact
    return np.asarray(c.load(h), dtype=float), clearance * np.asarray(c.load_derivative(h), dtype=float)
