"""The squeeze-film damper on the journal film at zero spin: circular centred orbits against the short-damper closed
forms (docs/validation.md, "Squeeze-film damper"), the film's own cavitation between starved and full, refusals."""

import numpy as np
import pytest

from transient import CircumferentialGroove, OilHole, SqueezeFilmDamper, load_result

#: a short damper, L/D = 0.05 (the closed forms are its L/D -> 0 limit)
SHORT = dict(diameter=0.1, length=0.005, clearance=100e-6, viscosity=0.01)
WHIRL = 3000.0  # [rpm]
FULL = 5e5  # [Pa] a supply pressure that keeps the film full (uncavitated) at these orbits
GROOVE = dict(feed="groove", groove_width=0.5e-3)


def _ratios(damper, eps, film):
    r = damper.circular_orbit(eps, WHIRL)
    fr, ft = damper.short_damper_forces(eps, WHIRL, film)
    return r, r.radial_force / fr if fr else r.radial_force / ft, r.tangential_force / ft


@pytest.mark.parametrize("eps", [0.3, 0.7])
def test_the_fed_film_at_a_high_supply_pressure_is_the_uncavitated_short_damper(eps):
    """End feed: no cavitation, no radial force, the 2-pi film's tangential force within 1 % at L/D = 0.05."""
    r, radial, tangential = _ratios(SqueezeFilmDamper(**SHORT, supply_pressure=FULL, grid=(96, 20)), eps, "2pi")
    assert r.success and r.cavitated_fraction == 0.0
    assert abs(radial) < 1e-3
    assert tangential == pytest.approx(1.0, abs=0.01)
    assert r.tangential_force < 0.0 and r.damping > 0.0  # the film resists the whirl


@pytest.mark.parametrize("eps", [0.3, 0.7])
def test_the_reynolds_condition_film_at_the_cavitation_pressure_is_the_pi_film(eps):
    d = SqueezeFilmDamper(**SHORT, supply_pressure=0.0, cavitation="reynolds", grid=(96, 20))
    _, radial, tangential = _ratios(d, eps, "pi")
    assert radial == pytest.approx(1.0, abs=0.01) and tangential == pytest.approx(1.0, abs=0.01)


@pytest.mark.parametrize("seals", ["open", "closed"])
def test_a_central_groove_splits_the_damper_into_lands(seals):
    """Open ends: two lands of half the length (a quarter of the force); closed ends: each land is half an open land
    twice as long. Both films, within 1 %."""
    for film, kw in (("2pi", dict(supply_pressure=FULL)), ("pi", dict(supply_pressure=0.0, cavitation="reynolds"))):
        d = SqueezeFilmDamper(**SHORT, **kw, **GROOVE, end_seals=seals, grid=(64, 20))
        assert [closed for _, closed in d.lands()] == [seals == "closed"] * 2
        assert sum(length for length, _ in d.lands()) == pytest.approx(SHORT["length"] - GROOVE["groove_width"])
        for eps in (0.3, 0.7):
            _, radial, tangential = _ratios(d, eps, film)
            assert tangential == pytest.approx(1.0, abs=0.01)
            assert radial == pytest.approx(1.0 if film == "pi" else 0.0, abs=0.01)


def test_sealing_the_ends_of_a_grooved_damper_quadruples_its_force():
    kw = dict(**SHORT, supply_pressure=FULL, **GROOVE, grid=(48, 20))
    open_, closed = (SqueezeFilmDamper(**kw, end_seals=s).circular_orbit(0.5, WHIRL) for s in ("open", "closed"))
    assert closed.tangential_force / open_.tangential_force == pytest.approx(4.0, rel=0.02)


def test_the_axial_grid_converges_at_second_order():
    """The full film's force on 10, 20 and 40 axial cells: successive differences shrink about fourfold."""
    f = [SqueezeFilmDamper(**SHORT, supply_pressure=FULL, grid=(48, n)).circular_orbit(0.5, WHIRL).tangential_force
         for n in (10, 20, 40)]
    assert (f[0] - f[1]) / (f[1] - f[2]) == pytest.approx(4.0, rel=0.1)


def test_the_elrod_film_runs_from_starved_to_full_with_the_supply_pressure():
    """Mass conservation: near the cavitation pressure the film has little oil to fill from and carries less than
    the pi-film; at a few times mu w (L/c)^2 it is full, the 2-pi film. In between its forces pass the pi-film's."""
    ft_pi = SqueezeFilmDamper(**SHORT, supply_pressure=FULL, grid=(64, 10)).short_damper_forces(0.5, WHIRL, "pi")[1]
    p_squeeze = 0.01 * (WHIRL * np.pi / 30) * (0.005 / 100e-6) ** 2  # mu w (L/c)^2 [Pa]
    rows = [SqueezeFilmDamper(**SHORT, supply_pressure=s * p_squeeze, grid=(64, 10)).circular_orbit(0.5, WHIRL)
            for s in (1e-3, 0.03, 0.3, 3.0)]
    share = [r.tangential_force / ft_pi for r in rows]
    cavitated = [r.cavitated_fraction for r in rows]
    assert share[0] < 0.1 and cavitated[0] > 0.9  # starved
    assert np.all(np.diff(share) > 0) and np.all(np.diff(cavitated) < 0)
    assert min(share) < 1.0 < max(share[:3])  # the pi-film lies between starved and full
    assert cavitated[-1] == 0.0 and share[-1] == pytest.approx(2.0, abs=0.02)  # the 2-pi film
    assert rows[-1].radial_force == pytest.approx(0.0, abs=1e-3 * abs(rows[-1].tangential_force))
    assert all(r.radial_force < 0.0 for r in rows[:3])  # the cavitated film pulls towards the centre


def test_the_whirl_direction_of_the_pressure_map():
    """Angles from the minimum film in the whirl direction: the film is squeezed ahead of the journal (0-180 deg),
    so the pressure peak lies there and the cavitated film behind it."""
    r = SqueezeFilmDamper(**SHORT, supply_pressure=1e3, grid=(72, 10)).circular_orbit(0.5, WHIRL)
    assert r.angle_deg[0] == 0.0 and np.all(np.diff(r.angle_deg) > 0)  # cells centred on the minimum film
    peak = r.angle_deg[np.argmax(r.pressure[0])]
    assert 0.0 < peak < 180.0
    assert np.mean(r.film_content[:, r.angle_deg > 180.0]) < np.mean(r.film_content[:, r.angle_deg < 180.0])


def test_the_centring_spring_and_the_saved_result(tmp_path):
    d = SqueezeFilmDamper(**SHORT, supply_pressure=FULL, centring_stiffness=2e6, grid=(32, 6))
    r = d.circular_orbit(0.4, WHIRL)
    assert r.spring_force == pytest.approx(-2e6 * 0.4 * 100e-6)
    assert r.stiffness == pytest.approx(-r.radial_force / r.orbit_radius)
    back = load_result(r.save(tmp_path / "orbit.npz"))
    assert back.tangential_force == r.tangential_force and np.array_equal(back.pressure, r.pressure)
    assert SqueezeFilmDamper(**SHORT, supply_pressure=FULL, grid=(32, 6)).circular_orbit(0.4, WHIRL).spring_force == 0.0


def test_grooves_given_as_objects():
    """Two circumferential grooves: three lands, the middle one between the grooves."""
    grooves = [CircumferentialGroove(width=0.4e-3, axial_position=-1.5e-3),
               CircumferentialGroove(width=0.4e-3, axial_position=1.5e-3)]
    d = SqueezeFilmDamper(**SHORT, supply_pressure=FULL, feed=grooves, grid=(32, 20))
    assert len(d.lands()) == 3
    _, _, tangential = _ratios(d, 0.5, "2pi")
    assert tangential == pytest.approx(1.0, abs=0.02)


@pytest.mark.parametrize("kw, name", [
    (dict(feed=OilHole(0.0, 1e-3)), "feed"),
    (dict(feed="holes"), "feed"),
    (dict(feed=[]), "feed"),
    (dict(end_seals="closed"), "end_seals"),
    (dict(end_seals="tight"), "end_seals"),
    (dict(supply_pressure=0.0), "supply_pressure"),
    (dict(centring_stiffness=-1.0), "centring_stiffness"),
    (dict(feed="groove", groove_width=0.005), "groove_width"),
    (dict(cavitation="gumbel"), "cavitation"),
    (dict(length=0.0), "length"),
])
def test_bad_parameters_are_refused_by_name(kw, name):
    args = dict(SHORT, supply_pressure=FULL, grid=(16, 4))
    args.update(kw)
    with pytest.raises(ValueError, match=name) as e:
        SqueezeFilmDamper(**args)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("eps, whirl, name", [(1.0, WHIRL, "eccentricity_ratio"), (0.0, WHIRL, "eccentricity_ratio"),
                                             (0.5, 0.0, "whirl_speed_rpm"), (0.5, -100.0, "whirl_speed_rpm")])
def test_bad_orbits_are_refused_by_name(eps, whirl, name):
    d = SqueezeFilmDamper(**SHORT, supply_pressure=FULL, grid=(16, 4))
    with pytest.raises(ValueError, match=name):
        d.circular_orbit(eps, whirl)
