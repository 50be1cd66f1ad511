"""Thrust ball bearing starvation sequence (seed 002)."""

import math

import numpy as np
import pytest

from transient.models.ball.bearing import FLOODED, PARCHED, STARVED, ThrustBallBearing
from transient import Integration, TrackSettings


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
        b.hertz(load=-3.0)
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
    c = b.hertz(load=30.0)
    assert c.load_per_ball == pytest.approx(5.0)
    assert c.a > c.b and c.k == pytest.approx(c.a / c.b)
    assert 2 / 3 * c.p_max * math.pi * c.a * c.b == pytest.approx(5.0, rel=1e-12)


def test_flooded_sequence_with_chiu_recovers_and_is_periodic():
    b = ThrustBallBearing()
    s = b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=200, track=TrackSettings(replenishment="chiu"))
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
    s = b.sequence(load=30, speed_rpm=80, ambient_film=20e-9, n_passes=30, track=TrackSettings(replenishment="chiu"))
    assert s.m[0] < s.m_c  # starved from the first ball
    assert s.regime[0] == STARVED  # first ball: the whole ambient film is 'replenishment'
    assert s.final_regime == PARCHED
    assert s.h_central[-1] < 0.7 * s.flooded.h_c


def test_closed_groove_conserves_oil_through_events_and_reflow():
    b = ThrustBallBearing()
    for grid in ("front", "uniform"):
        s = b.sequence(load=30, speed_rpm=80, ambient_film=50e-6, n_passes=4,
                       track=TrackSettings(bc="closed", ridge_fraction=1.0, n_cells=100, grid=grid),
                       integration=Integration(method="cvode", rtol=1e-8 if grid == "uniform" else 1e-5,
                                               atol=1e-12 if grid == "uniform" else 1e-9),
                       stop_at_periodic=False)
        assert np.max(np.abs(s.volume - s.volume[0])) < 1e-9 * s.volume[0]


def test_bad_input_names_parameter_value_unit_and_range():
    b = ThrustBallBearing()
    hc = b.flooded_film(30, 80).h_c  # 16.9 nm
    with pytest.raises(ValueError, match=r"ambient_film = 1e-08 \[m\] is out of range; allowed: \[1\.69.*e-08.*flooded central"):
        b.sequence(load=30, speed_rpm=80, ambient_film=1e-8, n_passes=3)
    assert hc > 1e-8
    with pytest.raises(ValueError, match=r"surface_tension = 0\.0 \[N/m\] is out of range; allowed: \(0, 1\) N/m"):
        ThrustBallBearing(surface_tension=0.0)
    with pytest.raises(ValueError, match=r"precursor_film = 0\.0002 \[m\] is out of range; allowed: \(0, 0\.0001\) m"):
        b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=3, track=TrackSettings(precursor_film=2e-4))
    with pytest.raises(ValueError, match=r"mobility_film = 0\.001 \[m\]"):
        b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=3, track=TrackSettings(mobility_film=1e-3))
    with pytest.raises(ValueError, match="grid = 'fine'"):
        b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=3, track=TrackSettings(grid="fine"))


def test_physical_precursor_reference_bearing_parches_and_the_verdict_does_not_move():
    # the physical model (no mobility floor, the outlet film h_c/2 as precursor, front-following mesh): the
    # first ball's ridge re-wets the centreline, the second's does not reach it; the ball then runs on its own
    # outlet film (the parched fixed point h_in = h_c(h_in)/2). The same on a refined mesh and with the
    # precursor 3x the physical one.
    b = ThrustBallBearing()
    runs = [b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=4, stop_at_periodic=False,
                       integration=Integration(method="cvode", rtol=1e-4, atol=1e-8), track=TrackSettings(**kw))
            for kw in ({}, dict(refine=1.5), dict(precursor_film=3 * 8.46e-9))]
    for s in runs:
        assert s.regime[:2] == [FLOODED, FLOODED] and s.regime[2:] == [PARCHED, PARCHED]
        assert s.h_inlet[2] < 0.05e-6              # the second ball's ridge never reached the centre
    for s in runs[:2]:
        assert 28e-6 < s.h_inlet[1] < 36e-6        # the first ball's ridge refilled the centre to ~1/3
    assert abs(runs[1].h_inlet[1] - runs[0].h_inlet[1]) < 0.05 * runs[0].h_inlet[1]
    assert runs[2].h_inlet[1] > runs[0].h_inlet[1]  # a thicker precursor lets the front run faster


def test_old_formulation_verdict_moves_with_its_mobility_floor():
    # the reason for the front mesh: with the floor b the uniform-grid model's verdict is b's
    b = ThrustBallBearing()
    run = lambda bm: b.sequence(load=30, speed_rpm=80, ambient_film=100e-6, n_passes=12,
                                track=TrackSettings(grid="uniform", n_cells=100, mobility_film=bm),
                                integration=Integration(method="cvode", rtol=1e-4, atol=1e-8), stop_at_periodic=False)
    hi, lo = run(10e-6), run(3e-6)
    assert hi.regime[-1] == FLOODED and hi.h_inlet[-1] > 5e-6
    assert lo.h_inlet[-1] < 0.2 * hi.h_inlet[-1]


def test_regime_map_loops_over_points_and_round_trips(tmp_path):
    from transient.results import load_result
    from transient.study.ball import RegimeMap, regime_map

    b = ThrustBallBearing()
    calls = []
    m = regime_map(b, [6], [80.0], [20.0, 30.0], 100e-6, n_passes=20, progress=lambda k, n, p, s: calls.append(k))
    assert calls == [1, 2] and m.regime.shape == (1, 1, 2)
    assert list(m.names()[0, 0]) == [PARCHED, PARCHED]
    vals, names = m.line("load", n_balls=6, speed_rpm=80.0)
    assert list(vals) == [20.0, 30.0] and list(names) == [PARCHED, PARCHED]
    q = load_result(m.save(tmp_path / "map"))
    assert isinstance(q, RegimeMap) and np.array_equal(q.regime, m.regime) and q.regimes == m.regimes


def test_regime_figures_show_regimes_values_and_the_papers_boundaries():
    from transient.params import jeong
    from transient.plots import ball as plots
    from transient.study.ball import RegimeMap

    Z, N, W = np.arange(1, 12), np.arange(70.0, 91.0, 5.0), np.arange(10.0, 61.0, 10.0)
    reg = np.where(Z[:, None, None] <= 5, 0, np.where(Z[:, None, None] == 6, 1, 2)) + 0 * N[None, :, None] + 0 * W
    m = RegimeMap(n_balls=Z, speed_rpm=N, load=W, ambient_film=100e-6, regime=reg, H_central=np.full(reg.shape, 1e-5))
    fig = plots.regime_map(m, "n_balls", "speed_rpm", at=jeong.REFERENCE, paper=jeong.REPORTED)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "number of balls" and "30 N" in ax.get_title() and "100 um" in ax.get_title()
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert {"fully flooded", "starved", "parched"} <= set(labels)
    assert "paper, number of balls: flooded up to 5 balls" in labels
    assert "paper, shaft speed: starved up to 82 rpm" in labels
    assert sum(1 for t in ax.texts) == Z.size * N.size            # H_c written in every cell
    fig = plots.critical_films({"n_balls": (Z, 1e-6 * (220 + 8 * Z), dict(load=30, speed_rpm=80))}, 100e-6,
                               jeong.REPORTED)
    assert "critical ambient film" in fig.axes[0].get_ylabel()


def test_an_isoviscous_oil_is_outside_the_flooded_film_fit():
    """pressure_viscosity = 0 used to give a zero flooded film (h ~ G^0.49) without a word (issue 17)."""
    with pytest.raises(ValueError, match="pressure_viscosity"):
        ThrustBallBearing(pressure_viscosity=0.0)
    with pytest.raises(ValueError, match="n_balls"):
        ThrustBallBearing(n_balls="6")


def test_the_papers_boundaries_as_a_verdict():
    """The paper: flooded to 5 balls, starved at 6, parched beyond; the verdict names the points that differ."""
    from transient.study.ball import paper_regime, paper_verdict

    assert [paper_regime("n_balls", z) for z in (5, 6, 7)] == ["fully flooded", "starved", "parched"]
    assert paper_verdict("n_balls", [1, 6, 11], ["fully flooded", "starved", "parched"]).startswith("reproduced")
    v = paper_verdict("n_balls", [1, 6, 11], ["parched", "parched", "parched"])
    assert v.startswith("NOT reproduced at 2 of 3") and "1: parched (paper fully flooded)" in v
