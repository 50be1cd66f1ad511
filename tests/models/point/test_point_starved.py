"""The starved point contact: Chevalier's law and the flooded limit over the inlet layer, mass conservation at a
heavily loaded contact, continuation in the layer, and a layer thinner than the grid carries."""

import numpy as np
import pytest

from transient.models.ball import ThrustBallBearing
from transient.models.point import PointContact
from transient.params import jeong
from transient.models.ehl.errors import EHLConvergenceError
from transient.analysis.starvation import chevalier, fit_gamma
from transient.study.point import layer_sweep

#: a steel ball on a steel flat, mineral oil: M = 61, L = 10.8
#: the starved law was measured with the first-order flux on 33 x 33 nodes, where the second-order one is far off
#: (flooded h_c 176 nm against 273 nm: docs/validation.md)
BASE = dict(radius_x=0.01, load=20.0, speed=1.0, viscosity=0.04, pressure_viscosity=2e-8, modulus=2.2e11,
            upwind="first")
#: Jeong et al.'s thrust ball bearing at 30 N / 6 balls and 80 rpm, per ball (k = 8.1, M = 2130, L = 7.6)
_B = ThrustBallBearing(**jeong.BEARING)
BALL = dict(radius_x=_B.rx, radius_y=_B.ry, load=30.0 / _B.n_balls, speed=_B.entrainment_speed(80.0),
            viscosity=_B.viscosity, pressure_viscosity=_B.pressure_viscosity, modulus=_B.e_prime)


@pytest.fixture(scope="module")
def sweep():
    return layer_sweep([10.0, 3.0, 1.0, 0.5, 0.2], **BASE, grid=(33, 33))


def test_chevalier_law_over_the_inlet_layer(sweep):
    assert sweep["success"].all() and not sweep["flooded"].any()
    r = sweep["ratio"] / sweep["rho_c"]
    film = sweep["h_central"] / sweep["h_c_ff"]
    gamma, dev = fit_gamma(r, film)
    assert dev < 0.03  # measured 1.6 % over 0.1 <= h_oil/h_c,ff <= 10 (docs/validation.md)
    assert 1.5 < gamma < 4.0
    assert np.all(np.diff(film) < 0)  # thinner layers, thinner films (ratios are thickest first)
    # the fitted law is not the identity: it is off by > 10 % from min(r, 1) around r = 1
    assert abs(chevalier(1.0, gamma) - 1.0) > 0.1


def test_thin_layer_passes_through_the_hertz_zone_and_thick_one_floods(sweep):
    # the thinnest layer: all of it passes the centre, at the centre's density (no side flow in the Hertz zone)
    thin = sweep["h_central"][-1] * sweep["rho_c"] / (sweep["ratio"][-1] * sweep["h_c_ff"])
    assert thin == pytest.approx(1.0, abs=0.01)
    assert sweep["m"][-1] < 1.05  # the meniscus reaches the Hertz zone
    # ten times the flooded film: the flooded film to 1 %, the meniscus beyond Hamrock-Dowson's critical one
    assert sweep["h_central"][0] / sweep["h_c_ff"] == pytest.approx(1.0, abs=0.01)
    assert sweep["m"][0] > sweep["m_c"]


def test_continuation_in_the_layer_reaches_the_same_film(sweep):
    s_cont = sweep["results"][2]  # h_oil = h_c,ff, reached from the layer 3 h_c,ff
    pc = PointContact(**BASE, grid=(33, 33), inlet_film=s_cont.inlet_film)
    cold = pc.steady()
    assert cold.h_central == pytest.approx(s_cont.h_central, rel=1e-6)
    assert cold.meniscus_x == pytest.approx(s_cont.meniscus_x, rel=1e-6)


def test_heavily_loaded_starved_contact_conserves_the_layer():
    """M = 2130: the inlet's mass balance is in the convergence test (the Poiseuille coefficient there is 10^5
    times the Couette one, so a row scale containing it accepts a film without its inflow)."""
    flooded = PointContact(**BALL, grid=(65, 33)).steady()
    s = PointContact(**BALL, grid=(65, 33), inlet_film=5e-9).steady(initial=flooded)
    width = s.y[-1] - s.y[0] - (s.y[1] - s.y[0])
    assert s.inlet_flux == pytest.approx(5e-9 * BALL["speed"] * width, rel=1e-6)
    assert abs(s.inlet_flux - s.outlet_flux - s.side_flux) < 1e-6 * s.inlet_flux
    assert 0.75 < s.h_central / 5e-9 < 0.9  # the layer at the centre's density (rho_c ~ 1.2), little side flow
    assert s.h_min > 0.5 * s.h_central
    thinner = PointContact(**BALL, grid=(65, 33), inlet_film=2.64e-9).steady(initial=s)
    assert thinner.h_central / 2.64e-9 == pytest.approx(s.h_central / 5e-9, rel=0.05)


@pytest.mark.slow
def test_layer_thinner_than_the_grid_carries_names_the_inlet_film():
    """On 33 x 33 (dx = 0.19 b) the outlet constriction of the heavily loaded contact collapses below a ~4 nm
    layer; the same layer converges on 65 x 33 (the test above)."""
    with pytest.raises(EHLConvergenceError, match=r"inlet_film = 2\.64e-09 m .* 33 x 33 nodes") as e:
        PointContact(**BALL, grid=(33, 33), inlet_film=2.64e-9).steady()
    assert not e.value.result.success
    with pytest.raises(ValueError, match="inlet_film"):
        PointContact(**BALL, grid=(65, 33), inlet_film=0.6e-9)  # below 5 % of the flooded film
