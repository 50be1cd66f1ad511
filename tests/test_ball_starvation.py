"""Thrust ball bearing starvation sequence (seed 002)."""

import math

import numpy as np
import pytest

from transient.models.ball.bearing import FLOODED, PARCHED, STARVED, ThrustBallBearing


def test_parameter_validation_names_parameter_and_unit():
    with pytest.raises(ValueError, match=r"n_balls = 0 \[-\]"):
        ThrustBallBearing(n_balls=0)
    with pytest.raises(ValueError, match="conformity = 0.45"):
        ThrustBallBearing(conformity=0.45)
    with pytest.raises(ValueError, match="viscosity = -1.*Pa s"):
        ThrustBallBearing(viscosity=-1.0)
    with pytest.raises(ValueError, match="n_balls = 40"):  # more balls than fit on the pitch circle
        ThrustBallBearing(n_balls=40)
    b = ThrustBallBearing()
    with pytest.raises(ValueError, match="load = -3.*N"):
        b.contact(load=-3.0)
    with pytest.raises(ValueError, match="ambient_film"):
        b.sequence(load=30, speed_rpm=80, ambient_film=-1e-6, n_passes=3)


def test_geometry_and_kinematics_hand_values():
    b = ThrustBallBearing()
    # Rx = d/2 = 1.5 mm; Ry = f d / (2f - 1) = 0.52 * 3 mm / 0.04 = 39 mm
    assert b.rx == pytest.approx(1.5e-3, rel=1e-12)
    assert b.ry == pytest.approx(0.039, rel=1e-12)
    # u = omega d_e / 4 = (80 * 2 pi / 60) * 0.031 / 4 = 0.0649262 m/s; t_b = 4 pi / (6 omega) = 0.25 s
    assert b.entrainment_speed(80) == pytest.approx(0.0649262, rel=1e-6)
    assert b.pass_interval(80) == pytest.approx(0.25, rel=1e-12)
    c = b.contact(load=30.0)
    assert c.load_per_ball == pytest.approx(5.0)
    assert c.a > c.b and c.k == pytest.approx(c.a / c.b)
    assert 2 / 3 * c.p_max * math.pi * c.a * c.b == pytest.approx(5.0, rel=1e-12)


def test_flooded_sequence_with_chiu_recovers_and_is_periodic():
    b = ThrustBallBearing()
    s = b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=200, replenishment="chiu")
    assert s.h_inlet[0] == 100e-6
    assert s.periodic and s.final_regime == FLOODED
    assert np.all(s.m >= s.m_c)
    assert np.all(s.h_central == s.flooded.h_c)
    # the track never recovers beyond the ambient film
    assert np.all(s.h_inlet <= 100e-6 * (1 + 1e-12))


def test_thin_ambient_film_is_parched():
    # an ambient film of 20 nm is about the film the contact takes (h_c ~ 17 nm): the contact leaves
    # h_c/2 and the levelling brings back less than h_c before the next ball
    b = ThrustBallBearing()
    s = b.sequence(load=30, speed_rpm=80, ambient_film=20e-9, n_passes=30, replenishment="chiu")
    assert s.m[0] < s.m_c  # starved from the first ball
    assert s.regime[0] == STARVED  # first ball: the whole ambient film is 'replenishment'
    assert s.final_regime == PARCHED
    assert s.h_central[-1] < 0.7 * s.flooded.h_c


def test_closed_groove_conserves_oil_through_events_and_reflow():
    b = ThrustBallBearing()
    s = b.sequence(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=6, bc="closed", ridge_fraction=1.0,
                   stop_at_periodic=False, rtol=1e-8, atol=1e-12, n_cells=100)
    assert np.max(np.abs(s.volume - s.volume[0])) < 1e-9 * s.volume[0]


def test_thin_film_sequence_converges_in_grid_and_tolerance():
    b = ThrustBallBearing()
    run = lambda n, rtol: b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=3, n_cells=n,
                                     rtol=rtol, stop_at_periodic=False).h_inlet[1:]
    h100, h200, h400 = run(100, 1e-7), run(200, 1e-7), run(400, 1e-7)
    e1 = np.max(np.abs(h100 - h400))
    e2 = np.max(np.abs(h200 - h400))
    assert e2 < 0.6 * e1          # the grid error falls when the grid is refined
    assert e2 < 0.02 * 100e-6     # and is below 2 % of the ambient film at 200 cells
    t4, t6 = run(200, 1e-4), run(200, 1e-6)
    assert np.max(np.abs(t6 - h200)) < np.max(np.abs(t4 - h200))
    assert np.max(np.abs(t6 - h200)) < 1e-4 * 100e-6
