"""The friction rig of Sander et al. (Tribol. Int. 96 (2016)): the transcribed data, the summits' Greenwood-Tripp
contact, and the computed shaft torque against the measured one (tests/data/sander_2016.json)."""

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from figure_checks import figure_problems
from scipy.integrate import quad
from scipy.stats import norm

from transient.params import sander
from transient.physics.asperity import SummitContact
from transient.plots import mixed
from transient.study.sander import RigCurve, deviations, measured_minimum, rig_curve, torque_minimum
from transient.study.stribeck import StribeckCurve

DATA = json.loads((Path(__file__).resolve().parents[2] / "data" / "sander_2016.json").read_text())


def test_parameters_are_the_transcribed_ones():
    rig, rough = DATA["rig"], DATA["roughness"]
    assert sander.TEST["diameter"] == rig["test_bearing"]["diameter_m"]
    assert sander.TEST["length"] == rig["test_bearing"]["length_m"]
    assert sander.SUPPORT["diameter"] == rig["support_bearings"]["diameter_m"]
    assert sander.SUPPORT["length"] == rig["support_bearings"]["length_m"]
    assert sander.OIL["viscosity"] == DATA["oil"]["viscosity_pa_s"]
    assert sander.PRESSURE_VISCOSITY == DATA["oil"]["pressure_viscosity_pa_inv"]
    assert sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY).pressure_viscosity == 9.5e-9
    assert sander.roughness().pressure_viscosity == 0.0
    assert sander.SURFACES["summit_sigma"] == tuple(rough["summit_sigma_m"].values())
    assert sander.SURFACES["summit_height"] == tuple(rough["summit_mean_height_m"].values())
    assert sander.SURFACES["rq"] == tuple(rough["rq_m"].values())
    assert sander.CONTACT["e_prime"] == rough["greenwood_tripp"]["composite_modulus_pa"]
    assert sander.CONTACT["boundary_friction"] == rough["boundary_friction"]
    assert list(sander.LOADS) == rig["loads_n"]
    for load in sander.LOADS:
        m = DATA["measured"][f"load_{load:.0f}N"]
        assert sander.MEASURED[load] == (tuple(m["speed_rpm"]), tuple(m["torque_nm"]))
    p = DATA["peer_code"]["load_8000N"]
    assert sander.PEER[8000.0] == (tuple(p["speed_rpm"]), tuple(p["torque_nm"]))


def test_summit_contact_is_the_greenwood_tripp_integral():
    """The source's K = 0.001 from its eta beta sigma and beta (its own check), and the pressure K E' F_5/2 at the
    summits' separation (h - delta) / sigma_s against adaptive quadrature; the slope against central differences."""
    c = sander.roughness().contact
    assert isinstance(c, SummitContact)
    assert c.k_factor == pytest.approx(1e-3, rel=1e-12)
    assert c.summit_sigma == pytest.approx(math.hypot(0.13e-6, 0.28e-6), rel=1e-15)
    for h in (0.3e-6, 0.6e-6, 0.9e-6, 1.4e-6):
        lam = (h - 0.6e-6) / c.summit_sigma
        f52 = quad(lambda s, lam=lam: (s - lam) ** 2.5 * norm.pdf(s), lam, 40.0, epsabs=0, epsrel=1e-12)[0]
        assert c.load(h) == pytest.approx(1e-3 * 53.3e9 * f52, rel=1e-8)
        dh = 1e-6 * c.summit_sigma
        assert c.load_derivative(h) == pytest.approx((c.load(h + dh) - c.load(h - dh)) / (2 * dh), rel=1e-6)


@pytest.mark.parametrize("kw, name", [(dict(summit_sigma=None), "summit_sigma"), (dict(summit_sigma=-1e-7), "summit_sigma"),
                                      (dict(summit_sigma=3e-7, summit_height=-1e-7), "summit_height")])
def test_bad_summit_contact_is_a_named_error(kw, name):
    with pytest.raises(ValueError, match=name):
        SummitContact(asperity_density=3.7e9, asperity_radius=4.3e-5, e_prime=53.3e9, hardness=1e9, sigma=4e-7, **kw)


def test_torque_minimum_is_the_vertex_in_log_speed():
    s = np.array([100.0, 200.0, 400.0, 800.0])
    t = (np.log(s) - np.log(300.0)) ** 2 + 1.0
    assert torque_minimum(s, t) == pytest.approx(300.0, rel=1e-12)
    assert torque_minimum(s[:2], t[:2]) == 200.0  # least at an end: that sample
    assert measured_minimum(8000.0) == pytest.approx(550, rel=0.01)  # least measured point: 500 rpm


def synthetic(load, s, torque, share):
    n = len(s)
    return StribeckCurve(load=load, speed_rpm=np.asarray(s, float), friction_torque=np.asarray(torque, float),
                         friction_coefficient=np.zeros(n), h_min=np.full(n, 1e-6), eccentricity_ratio=np.full(n, 0.9),
                         contact_load=load * np.asarray(share, float), power_loss=np.zeros(n))


def test_rig_figure_names_units_and_adds_the_supports():
    s = [150.0, 500.0, 3000.0]
    curve = RigCurve(8000.0, synthetic(8000.0, s, [2.0, 0.3, 0.3], [0.5, 0.01, 0.0]),
                     synthetic(4000.0, s, [0.1, 0.1, 0.4], [0.0, 0.0, 0.0]))
    assert curve.torque == pytest.approx([2.2, 0.5, 1.1])
    assert curve.at(500.0) == pytest.approx([0.5])
    assert deviations(curve) == {150.0: (1.71, pytest.approx(2.2), pytest.approx(2.2 / 1.71 - 1)),
                                 500.0: (0.43, pytest.approx(0.5), pytest.approx(0.5 / 0.43 - 1)),
                                 3000.0: (1.06, pytest.approx(1.1), pytest.approx(1.1 / 1.06 - 1))}
    fig = mixed.rig_torque([curve], sander.MEASURED, sander.PEER, {8000.0: ((150, 3000), (0.7e-6, 2e-6))}, "rig")
    assert figure_problems(fig) == []


def rig(load, speeds, grid, surface=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return rig_curve(load, speeds, grid, surface)


BARUS = sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY)


@pytest.mark.parametrize("surface", [None, BARUS], ids=["isoviscous", "barus"])
def test_hydrodynamic_branch_on_a_coarse_grid(surface):
    """48 x 8 cells, 8 kN: above lift-off the shaft torque (test bearing + two supports) is within 10 % of the
    measured one at 1000 and 3000 rpm (isoviscous +6 % and -2 %; with the oil's Barus coefficient +2 % and +1 %), and
    the supports carry more than half of it."""
    curve = rig(8000.0, [1000.0, 3000.0], (48, 8), surface)
    for n, (m, c, d) in deviations(curve).items():
        assert abs(d) < 0.10, (n, m, c)
    assert np.all(2 * curve.support.friction_torque > 0.5 * curve.torque)


def test_pressure_viscosity_lowers_the_mixed_branch_on_a_coarse_grid():
    """48 x 8 cells, 8 kN, 500 rpm: the film at exp(alpha p) viscosity (peak film pressure near 60 MPa, mu up to
    1.8 mu0) carries more of the load, the test bearing's asperity load and the shaft torque fall (1.17 to 1.00 N m),
    but stay more than 40 % above the measured 0.43 N m."""
    iso, bar = rig(8000.0, [500.0], (48, 8)), rig(8000.0, [500.0], (48, 8), BARUS)
    assert bar.test.contact_load[0] < 0.9 * iso.test.contact_load[0]
    assert bar.torque[0] < 0.9 * iso.torque[0]
    assert deviations(bar)[500.0][2] > 0.4


ELASTIC = (sander.roughness(bore_compliance=sander.bore_compliance(sander.TEST, sander.CONROD)),
           sander.roughness(bore_compliance=sander.bore_compliance(sander.SUPPORT, sander.SUPPORT_HOUSING)))


def test_housing_compliances_are_lames():
    """The Winkler bores' compliances from the transcribed housings: the aluminium big end (bore 47.8 mm, outer
    140 mm, E 70 GPa) and the steel supports (bore 54 mm, outer 108 mm, E 210 GPa), Lame in plane stress."""
    rig = DATA["rig"]
    assert sander.CONROD["outer_diameter"] == rig["conrod_outer_diameter_m"]
    assert sander.CONROD["youngs_modulus"] == rig["conrod_youngs_modulus_pa"]
    assert sander.SUPPORT_HOUSING["outer_diameter"] == 2 * rig["support_centre_to_top_m"]
    assert sander.SUPPORT_HOUSING["youngs_modulus"] == rig["support_youngs_modulus_pa"]
    a, b = 23.9e-3, 70e-3
    assert sander.bore_compliance(sander.TEST, sander.CONROD) == pytest.approx(
        a / 70e9 * ((b * b + a * a) / (b * b - a * a) + 0.3), rel=1e-12)
    assert ELASTIC[0].bore_compliance == pytest.approx(5.34e-13, rel=1e-3)
    assert ELASTIC[1].bore_compliance == pytest.approx(2.53e-13, rel=1e-3)


def test_elastic_rig_meets_the_goals_on_a_coarse_grid():
    """48 x 8 cells, 8 kN, Winkler bores of Lame's compliance (isoviscous): the hydrodynamic branch within 10 % at
    1000 and 3000 rpm (-4 %, -4 %), the mixed branch within 40 % at 150, 300 and 500 rpm (-10 %, +9 %, +13 %; the
    rigid bores: +126 % to +238 %), the least torque within 20 % of the measured speed (630 against 550 rpm on these
    six speeds) and the test bearing's thinnest film at 150 rpm within 10 % of the source's 0.7 um (0.73 um)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        curve = rig_curve(8000.0, [150.0, 300.0, 500.0, 700.0, 1000.0, 3000.0], (48, 8), *ELASTIC)
    dev = deviations(curve)
    for n in (1000.0, 3000.0):
        assert abs(dev[n][2]) < 0.10, (n, dev[n])
    for n in (150.0, 300.0, 500.0):
        assert abs(dev[n][2]) < 0.40, (n, dev[n])
    assert curve.minimum_speed_rpm == pytest.approx(measured_minimum(8000.0), rel=0.2)
    assert curve.test.h_min[0] == pytest.approx(0.7e-6, rel=0.1)


BARUS_ELASTIC = tuple(sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY,
                                       bore_compliance=e.bore_compliance) for e in ELASTIC)


@pytest.mark.slow  # 2 x 2 Stribeck curves of 2 speeds on 48 x 8 cells in Winkler bores: about 10 s of CPU
def test_pressure_viscosity_and_elastic_bore_together_on_a_coarse_grid():
    """48 x 8 cells, 8 kN, the hydrodynamic branch with Barus oil in Winkler bores: both options in one film (the
    Jacobian of each is checked in test_rough_bore.py); within 10 % of the measured torque (-2 %, -3 %), and above
    the isoviscous bores' (the viscosity rises with the film pressure: +2 % at 3000 rpm, +1 % at 1000)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        both = rig_curve(8000.0, [1000.0, 3000.0], (48, 8), *BARUS_ELASTIC)
        bore = rig_curve(8000.0, [1000.0, 3000.0], (48, 8), *ELASTIC)
    dev = deviations(both)
    for n in (1000.0, 3000.0):
        assert abs(dev[n][2]) < 0.10, (n, dev[n])
    assert np.all(both.torque > bore.torque)


@pytest.mark.slow  # 4 Stribeck curves of 13 speeds on 151 x 21 cells: about 2 min of CPU
def test_sander_rig_on_the_fine_grid():
    """151 x 21 cells, summits as transcribed (docs/validation.md): the hydrodynamic branch (1000 and 3000 rpm)
    within the 10 % goal at 8 kN (computed +2 %, -2 %); at 4 kN the goal is not met (-12 %, -9 %), checked at 15 %
    so that a change is seen. The mixed branch (150 to 300 rpm) more than 40 % above the measured torque and the
    least torque at a higher speed than measured: the rigid bore's disagreement (docs/disagreements.md)."""
    speeds = np.unique(np.concatenate([sander.MEASURED[8000.0][0], [700.0, 850.0, 1200.0, 1500.0, 2000.0]]))
    for load, tol in ((8000.0, 0.10), (4000.0, 0.15)):
        curve = rig(load, speeds, (151, 21))
        dev = deviations(curve)
        for n in (1000.0, 3000.0):
            assert abs(dev[n][2]) < tol, (load, n, dev[n])
        for n in (150.0, 250.0, 300.0):
            assert dev[n][2] > 0.4, (load, n, dev[n])
        assert curve.minimum_speed_rpm > measured_minimum(load)


@pytest.mark.slow  # 4 Stribeck curves of 11 speeds: about 2 min of CPU on 75 x 11, 8 min on 151 x 21
@pytest.mark.parametrize("grid", [(75, 11), (151, 21)], ids=["75x11", "151x21"])
def test_elastic_rig(grid):
    """Winkler bores of Lame's compliance (docs/validation.md, "The Sander rig's hydrodynamic branch"), on 75 x 11
    and 151 x 21 cells: the least torque within 10 % of the measured speed (333 / 315 against 340 rpm, 567 / 535
    against 550 rpm); the mixed branch (150 to 500 rpm) within 40 % at both loads (-24 % to +7 % / -28 % to +3 %);
    the hydrodynamic branch within 10 % at 8 kN (-5 %, -5 %); at 4 kN the goal is not met (-15 %, -11 % / -10 %,
    -15 %), checked at 20 % so that a change is seen."""
    speeds = [150.0, 200.0, 250.0, 300.0, 400.0, 500.0, 700.0, 1000.0, 1500.0, 2000.0, 3000.0]
    for load, tol in ((8000.0, 0.10), (4000.0, 0.20)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            curve = rig_curve(load, speeds, grid, *ELASTIC)
        dev = deviations(curve)
        for n in (1000.0, 3000.0):
            assert abs(dev[n][2]) < tol, (load, n, dev[n])
        for n in (150.0, 250.0, 300.0, 400.0, 500.0):
            assert abs(dev[n][2]) < 0.40, (load, n, dev[n])
        assert curve.minimum_speed_rpm == pytest.approx(measured_minimum(load), rel=0.1)
