"""Sander, Allmaier, Priebsch, Witt & Skiadas, Tribol. Int. 96 (2016) 173-183: the friction rig, SI, as the public
test of MBDyn's plain-bearing module transcribes it (octave-user/mboct-mbdyn-pkg,
inst/mbdyn_post_ehd_load_output_13.tst; values with provenance in tests/data/sander_2016.json).

A shaft on two support bearings turns in the big-end bore of a connecting rod pulled down by the load ``F``; the
drive measures the shaft torque, the test bearing's friction plus the two supports'. Each support carries ``F / 2``.
Oil at 100 C, 6.8 mPa s, isothermal. Surfaces: summit statistics for the Greenwood-Tripp contact
(:class:`~transient.physics.asperity.SummitContact`), RMS heights and Peklenik numbers for the flow factors.

What the rig has and these bearings do not: the journal's per-surface Peklenik numbers (4 and 12: one composite
number, the variance-weighted 9.9, held at the Patir-Cheng fits' 9) and the elastic bodies as finite-element models.
Options of the surfaces (:func:`roughness`): the oil's pressure-viscosity (Barus, alpha = 9.5e-9 1/Pa) and a Winkler
bore whose compliance is Lame's for a thick ring (:mod:`transient.physics.ring`) of the housings the test models: the
aluminium connecting rod's big end (outer diameter 140 mm) and the steel supports (54 mm from the bore's centre to
the nearest outer face: an outer diameter of 108 mm, an assumption of this model).
"""

from __future__ import annotations

import math

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.feeds import Groove, OilHole
from transient.models.journal.roughness import Roughness
from transient.physics import ring
from transient.physics.asperity import SummitContact

#: Test (big-end) bearing: D, L, relative clearance 1e-3 (the test's assumption).
TEST = dict(diameter=47.8e-3, length=17.2e-3, relative_clearance=1e-3)
#: Support bearings: D, L, relative clearance 1e-3 (assumption); a 180-deg groove 5 mm wide on the unloaded side.
SUPPORT = dict(diameter=54e-3, length=25e-3, relative_clearance=1e-3, groove_width=5e-3)
OIL = dict(viscosity=6.8e-3, bulk_modulus=2.4e9, cavitation_pressure=100.0, supply_pressure=1e5)
#: The oil's Barus pressure-viscosity coefficient [1/Pa].
PRESSURE_VISCOSITY = 9.5e-9
#: Housings as thick rings: outer diameter [m], Young's modulus [Pa], Poisson's ratio (the test's conrod: d2, E2, nu2;
#: the supports: twice the test's l7, E3, nu3).
CONROD = dict(outer_diameter=140e-3, youngs_modulus=70e9, poisson_ratio=0.3)
SUPPORT_HOUSING = dict(outer_diameter=2 * 54e-3, youngs_modulus=210e9, poisson_ratio=0.3)
#: Surfaces (journal 1, bush 2): summit standard deviations and mean heights, RMS heights, Peklenik numbers.
SURFACES = dict(summit_sigma=(0.13e-6, 0.28e-6), summit_height=(0.21e-6, 0.39e-6), rq=(0.20e-6, 0.34e-6),
                gamma=(4.0, 12.0))
#: Greenwood-Tripp: K = 16 sqrt(2) pi / 15 (eta beta sigma)^2 sqrt(sigma / beta), eta beta sigma, E', mu_b.
CONTACT = dict(k_factor=1e-3, eta_beta_sigma=0.05, e_prime=53.3e9, boundary_friction=0.02)
#: The loads [N] (about 5 and 10 MPa on the test bearing's projected area).
LOADS = (4000.0, 8000.0)
#: The rig's shaft torque [N m] against speed [rpm] per load [N] (the source's curves).
MEASURED = {4000.0: ((3000, 1000, 500, 400, 300, 250, 150), (0.96, 0.46, 0.297, 0.257, 0.243, 0.34, 0.5)),
            8000.0: ((3000, 1000, 500, 400, 300, 250, 200, 150), (1.06, 0.544, 0.43, 0.46, 0.58, 0.747, 1.076, 1.71))}
#: MBDyn's elastic model of the rig at 8000 N (the test's regression values): speed [rpm], torque [N m].
PEER = {8000.0: ((150, 500, 3000), (2.339165422042972, 0.5112121251382301, 1.120440242176203))}
GAMMA_MAX = 9.0  # the Patir-Cheng fits' largest Peklenik number


def bore_compliance(bearing: dict, housing: dict) -> float:
    """Lame's bore compliance [m/Pa] (:func:`transient.physics.ring.bore_compliance`) of ``bearing`` (:data:`TEST`
    or :data:`SUPPORT`) in ``housing`` (:data:`CONROD` or :data:`SUPPORT_HOUSING`)."""
    return ring.bore_compliance(0.5 * bearing["diameter"], 0.5 * housing["outer_diameter"],
                                housing["youngs_modulus"], housing["poisson_ratio"])


def roughness(summit_height=None, pressure_viscosity=0.0, bore_compliance=0.0) -> Roughness:
    """The composite surface: summit sigma = sqrt(sum sigma_i^2), delta = sum delta_i (or ``summit_height`` [m]);
    beta and eta from K and eta beta sigma as the source defines them; the flow factors on the composite RMS height
    sqrt(sum Rq_i^2), the journal's share of its variance, and the variance-weighted Peklenik number held at 9; the
    oil's Barus coefficient ``pressure_viscosity`` [1/Pa] (0: isoviscous; the oil's: :data:`PRESSURE_VISCOSITY`); a
    Winkler bore of ``bore_compliance`` [m/Pa] (0: rigid; the rig's: :func:`bore_compliance`)."""
    ss = math.hypot(*SURFACES["summit_sigma"])
    k, ebs = CONTACT["k_factor"], CONTACT["eta_beta_sigma"]
    beta = ss / (k / (16.0 * math.sqrt(2.0) * math.pi / 15.0 * ebs ** 2)) ** 2
    eta = ebs / (ss * beta)
    rq1, rq2 = SURFACES["rq"]
    rq2_total = rq1 ** 2 + rq2 ** 2
    g1, g2 = SURFACES["gamma"]
    gamma = min(GAMMA_MAX, (rq1 ** 2 * g1 + rq2 ** 2 * g2) / rq2_total)
    contact = SummitContact(asperity_density=eta, asperity_radius=beta, e_prime=CONTACT["e_prime"], hardness=1e9,
                            sigma=math.sqrt(rq2_total), summit_sigma=ss, summit_height=sum(SURFACES["summit_height"]) if summit_height is None
                            else summit_height)
    return Roughness(contact, gamma=gamma, boundary_friction=CONTACT["boundary_friction"],
                     journal_variance_share=rq1 ** 2 / rq2_total, pressure_viscosity=pressure_viscosity,
                     bore_compliance=bore_compliance)


def test_bearing(grid=(151, 21), surface: Roughness | None = None) -> JournalBearing:
    """The big-end bearing: the oil hole (5 mm) 90 deg upstream of the load line; ``surface`` (default
    :func:`roughness`)."""
    d = TEST["diameter"]
    return JournalBearing(diameter=d, length=TEST["length"], clearance=0.5 * d * TEST["relative_clearance"],
                          groove=OilHole(angle_deg=90.0, diameter=5e-3), grid=grid,
                          roughness=roughness() if surface is None else surface, ambient_pressure=OIL["supply_pressure"], **OIL)


def support_bearing(grid=(151, 21), surface: Roughness | None = None) -> JournalBearing:
    """One support bearing: the 180-deg groove on the unloaded half as two 90-deg grooves side by side; ``surface``
    (default :func:`roughness`)."""
    d, w = SUPPORT["diameter"], SUPPORT["groove_width"]
    eps = 1e-6  # [deg] the second groove starts just past the first (a cell centre at 0 deg is the first's)
    grooves = (Groove(angle_deg=-45.0, width_deg=90.0, length=w),
               Groove(angle_deg=45.0 + 0.5 * eps, width_deg=90.0 - eps, length=w))
    return JournalBearing(diameter=d, length=SUPPORT["length"], clearance=0.5 * d * SUPPORT["relative_clearance"],
                          groove=grooves, grid=grid, roughness=roughness() if surface is None else surface,
                          ambient_pressure=OIL["supply_pressure"], **OIL)
