"""The journal case of Jang, "Study on boundary lubrication in the sliding bearing system under high load and speed"
with boundary layers: how much the layers raise the film and why, with a Newtonian and with the paper's shear-
thinning (Gecim) bulk.

Jang's bearing (R/B = 1, eps = 0.9, h_min = 0.1 C; the paper's example D = 25 mm, C = 10 um) with layers of
thickness delta = 0, 0.1, 0.2, 0.3 h_min on both walls, layer viscosity mu_ab = 10 mu (2 ... 100 explored)
and permeability length alpha = 0.1 h_min, on the classical Reynolds-condition film (the paper's cavitation
condition is likely p >= 0). For each case the steady film at the fixed position; the rise of the load over the
layer-free film splits exactly into

* the thinner bulk: the immobile layers (alpha = 0) are a bearing of clearance C - 2 delta
  (tests/models/journal/test_layers.py), and
* the Darcy flow through mobile layers (alpha > 0), which gives part of it back.

Pressures are reported as p* = p / p0, p0 = 6 mu omega (R/C)^2 (the layer-free bearing's scale).

:func:`gecim_cases` repeats the thickness and viscosity cases with the Gecim bulk (kappa* = kappa C / (mu_1 omega R)
= 0.65, mu_2/mu_1 = 0.57), adds the friction, and for the layers' immobility (Figs. 9-11: alpha from 0.1 h_min to 0,
mu_ab from 2 to 100 mu) the velocity profile across the film at the peak pressure and the interface shear stress
along the mid-plane.
"""

from __future__ import annotations


import numpy as np

from transient.models.journal.bearing import JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit
from transient.params import rho_kim
from transient.physics.layered import BoundaryLayers, Gecim
from transient.results import StatusResult, quantity, result_type

#: Jang's example bearing (D = 25 mm, c = 10 um, R/B = 1); viscosity and speed set only the scale
BEARING = dict(diameter=0.025, length=0.0125, clearance=10e-6, viscosity=0.01, groove=None,
               cavitation="reynolds")
SPEED_RPM = 300.0  # keeps the thickest layers' peak (~19 p0) below the 100 MPa validity warning
ECCENTRICITY = 0.9
H_MIN = 1.0 - ECCENTRICITY  # h_min / C
THICKNESS = (0.0, 0.1, 0.2, 0.3)  # delta / h_min
LAYER_VISCOSITY = (2.0, 10.0, 100.0)  # mu_ab / mu
ALPHA = 0.1  # alpha / h_min
KAPPA_STAR = 0.65  # kappa C / (mu_1 omega R)
RATIO = 0.57  # mu_2 / mu_1
#: (alpha / h_min, mu_ab / mu) from mobile to immobile layers at delta = 0.2 h_min (Figs. 9-11)
IMMOBILITY = ((0.1, 2.0), (0.1, 10.0), (0.1, 100.0), (0.05, 10.0), (0.0, 10.0))
IMMOBILITY_DELTA = 0.2


def _empty():
    return np.zeros(0)


@result_type
class LayeredCases(StatusResult):
    """:func:`layered_cases`: the grid, the pressure scale p0 [Pa], the mid-plane angle [deg]; ``base`` (no layers)
    and one row per layer thickness (``thickness``: immobile and mobile layers, the rise from the thinner bulk and
    the Darcy share) and per layer viscosity (``viscosity``), each with load [N], peak p* and profile p*(angle)."""

    time_axis = None
    grid: tuple = (0, 0)
    p0_Pa: float = quantity("Pa", 0.0)
    angle_deg: np.ndarray = quantity("deg", default_factory=_empty)
    base: dict = quantity("-", default_factory=dict)
    thickness: list = quantity("-", default_factory=list)
    viscosity: list = quantity("-", default_factory=list)
    record_skip = ("angle_deg",)


@result_type
class GecimCases(LayeredCases):
    """:func:`gecim_cases`: :class:`LayeredCases` with the Gecim bulk next to the Newtonian one (``base`` and each
    row by bulk, friction [N] added), the axial coordinate z/B of the fields, the bulk's kappa [Pa] and the
    immobility cases (``immobility``: velocity across the film, interface shear [Pa])."""

    z_over_B: np.ndarray = quantity("-", default_factory=_empty)
    kappa_Pa: float = quantity("Pa", 0.0)
    immobility: list = quantity("-", default_factory=list)
    record_skip = ("angle_deg", "z_over_B")


@result_type
class ShearThinningDynamics(StatusResult):
    """:func:`shear_thinning_dynamics`: per bulk (``newtonian``, ``gecim``) the equilibrium, K [N/m], C [N s/m],
    the threshold [rpm] and the periodic orbit [C] with its convergence; the grid, speed [rpm], kappa [Pa], rtol."""

    time_axis = None
    grid: tuple = (0, 0)
    speed_rpm: float = quantity("rpm", 0.0)
    kappa_Pa: float = quantity("Pa", 0.0)
    rtol: float = 0.0
    newtonian: dict = quantity("-", default_factory=dict)
    gecim: dict = quantity("-", default_factory=dict)


def gecim_bulk(bearing=BEARING, speed_rpm=SPEED_RPM):
    """The paper's Gecim bulk for a bearing (a dict of :class:`JournalBearing` arguments, SI) at ``speed_rpm``:
    kappa [Pa] = kappa* mu_1 omega R / C, mu_2/mu_1 = :data:`RATIO`."""
    C, mu, R = bearing["clearance"], bearing["viscosity"], 0.5 * bearing["diameter"]
    return Gecim(kappa=KAPPA_STAR * mu * omega(speed_rpm) * R / C, viscosity_ratio=RATIO)


def _state(grid, thickness, viscosity_ratio, alpha, rheology=None):
    C = BEARING["clearance"]
    layers = None if thickness == 0 else BoundaryLayers(thickness * H_MIN * C, viscosity_ratio * BEARING["viscosity"],
                                                        alpha * H_MIN * C)
    b = JournalBearing(**BEARING, grid=grid, layers=layers, rheology=rheology)
    return b, b.steady_state(ECCENTRICITY, SPEED_RPM)


def layered_cases(grid=(121, 20)) -> LayeredCases:
    """The cases of the module docstring: per layer thickness (alpha = 0 and alpha = 0.1 h_min) and per layer
    viscosity (delta = 0.1 h_min); loads [N], peak p*, and the mid-plane p*(angle) profiles."""
    b0, s0 = _state(grid, 0.0, 1.0, 0.0)
    p0 = b0.pressure_scale(SPEED_RPM)
    out = LayeredCases(grid=tuple(grid), p0_Pa=p0, angle_deg=s0.angle_deg, base=dict(load_N=s0.load,
                       peak=s0.max_pressure / p0, profile=s0.pressure[0] / p0))
    for d in THICKNESS[1:]:
        row = dict(delta_over_hmin=d)
        for tag, a in (("immobile", 0.0), ("mobile", ALPHA)):
            _, s = _state(grid, d, 10.0, a)
            row[tag] = dict(load_N=s.load, peak=s.max_pressure / p0, profile=s.pressure[0] / p0)
        row["rise_thinner_bulk"] = row["immobile"]["load_N"] / s0.load - 1.0
        row["darcy_share"] = (row["mobile"]["load_N"] - row["immobile"]["load_N"]) / s0.load
        out.thickness.append(row)
    for v in LAYER_VISCOSITY:
        _, s = _state(grid, 0.1, v, ALPHA)
        out.viscosity.append(dict(mu_ab_over_mu=v, load_N=s.load, peak=s.max_pressure / p0,
                                     profile=s.pressure[0] / p0))
    return out


def _summary(s, p0, field=False):
    out = dict(load_N=s.load, peak=s.max_pressure / p0, profile=s.pressure[0] / p0, friction_N=s.friction_force,
               bearing_friction_N=s.bearing_friction_force, friction_coefficient=s.friction_force / s.load)
    if field:
        out["field"] = s.pressure / p0
    return out


def gecim_cases(grid=(121, 20)) -> GecimCases:
    """The thickness and viscosity cases with the Gecim bulk next to the Newtonian one, and the immobility cases
    (:data:`IMMOBILITY`): load [N], peak p*, mid-plane profile, friction on journal and bearing [N] and the
    coefficient (the Gecim cases with the pressure field p/p0 over (axial row, angle)); per immobility case
    the velocity across the film at the mid-plane peak (z/h, u/U) and the interface shear [Pa] along the angle."""
    rh = gecim_bulk()
    b0, n0 = _state(grid, 0.0, 1.0, 0.0)
    p0 = b0.pressure_scale(SPEED_RPM)
    _, g0 = _state(grid, 0.0, 1.0, 0.0, rh)
    out = GecimCases(grid=tuple(grid), p0_Pa=p0, angle_deg=g0.angle_deg, z_over_B=g0.z / (0.5 * BEARING["length"]),
                     kappa_Pa=rh.kappa, base=dict(newtonian=_summary(n0, p0), gecim=_summary(g0, p0, field=True)))
    for d in THICKNESS[1:]:
        row = dict(delta_over_hmin=d)
        for tag, a, law in (("newtonian", ALPHA, None), ("gecim", ALPHA, rh), ("gecim_immobile", 0.0, rh)):
            row[tag] = _summary(_state(grid, d, 10.0, a, law)[1], p0, field=tag == "gecim")
        row["thinning_load_ratio"] = row["gecim"]["load_N"] / row["newtonian"]["load_N"]
        row["rise_thinner_bulk"] = row["gecim_immobile"]["load_N"] / g0.load - 1.0
        row["darcy_share"] = (row["gecim"]["load_N"] - row["gecim_immobile"]["load_N"]) / g0.load
        out.thickness.append(row)
    for v in LAYER_VISCOSITY:
        out.viscosity.append(dict(mu_ab_over_mu=v, **_summary(_state(grid, 0.1, v, ALPHA, rh)[1], p0)))
    U = omega(SPEED_RPM) * 0.5 * BEARING["diameter"]
    for a, v in IMMOBILITY:
        s = _state(grid, IMMOBILITY_DELTA, v, a, rh)[1]
        peak = float(s.angle_deg[int(np.argmax(s.pressure[0]))])
        z, u = s.velocity_profile(peak, 0, 101)
        lower, upper = s.interface_shear(0)
        out.immobility.append(dict(alpha_over_hmin=a, mu_ab_over_mu=v, peak_angle_deg=peak, load_N=s.load,
                                      z_over_h=z / z[-1], u_over_U=u / U, interface_lower_Pa=lower,
                                      interface_upper_Pa=upper, friction_N=s.friction_force))
    return out


def shear_thinning_dynamics(grid=(151, 21), rtol=1e-5, speed_rpm=6000.0) -> ShearThinningDynamics:
    """The Gecim bulk in the rotor computations (the bearing and rotor of Rho & Kim, Elrod film): with the
    Newtonian bulk and with a Gecim bulk of kappa* = 0.65 at ``speed_rpm`` (kappa fixed in Pa), mu_2/mu_1 = 0.57:
    the static equilibrium, K and C, the Lund threshold, and the periodic unbalance orbit (0.01 C) by shooting
    (:meth:`~transient.models.journal.JournalOrbit.periodic_response`: one closed revolution, x, y in units of C,
    with its convergence, error estimate and dominant Floquet multiplier)."""
    B, rotor = rho_kim.BEARING, rho_kim.ROTOR
    gecim = gecim_bulk(B, speed_rpm)
    out = ShearThinningDynamics(grid=tuple(grid), speed_rpm=speed_rpm, kappa_Pa=gecim.kappa, rtol=rtol)
    for name, rh in (("newtonian", None), ("gecim", gecim)):
        b = JournalBearing(**B, grid=tuple(grid), rheology=rh)
        eq = b.equilibrium(rotor["load"], speed_rpm)
        K, C = b.coefficients(rotor["load"], speed_rpm)
        o = JournalOrbit(b, rotor["rotor_mass"], 0.01 * B["clearance"], rotor["load"], speed_rpm)
        p = o.periodic_response(rtol=rtol, outputs_per_revolution=100)
        x, y = p.x / B["clearance"], p.y / B["clearance"]
        setattr(out, name, dict(
            eccentricity=eq.eccentricity_ratio, attitude_deg=eq.attitude_angle_deg, friction_N=eq.friction_force,
            K=K, C=C, threshold_rpm=b.stability_threshold(rotor["rotor_mass"], rotor["load"]), x_C=x, y_C=y,
            equilibrium_C=(float(eq.position[0] / B["clearance"]), float(eq.position[1] / B["clearance"])),
            orbit_span_C=(float(np.ptp(x)), float(np.ptp(y))), converged=bool(p.converged),
            error_estimate_C=float(p.error_estimate / B["clearance"]), max_multiplier=p.max_multiplier,
            periods=int(p.revolutions_integrated), message=p.message))
    return out
