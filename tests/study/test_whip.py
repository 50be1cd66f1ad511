"""Oil whip (seed 003): the whip scenario end to end on a tiny grid, the run-up's state hand-over between
speeds, and the whirl numbers on a synthetic orbit."""

import json
from dataclasses import replace

import numpy as np
import pytest

from transient.models.journal import JournalBearing, JournalOrbit, OrbitResult
from transient.solvers.settings import Integration
from transient.params.rho_kim import BEARING, ROTOR
from transient.study.whip import METHOD, carry_state, long_whip, run_up, whirl_numbers


def test_whip_scenario_quick_and_resumed(tmp_path, scenario_loader):
    """32x4 grid, 5 speeds x 5 revolutions, 16 revolutions at 1.2x and 1.5x: below the threshold the orbit is
    synchronous (whirl ratio ~1), above it the whirl is at about half the shaft speed and grows (measured
    0.96, 0.51, 0.45, 0.47, 0.50 over the run-up; 1.5x: e/C up to 0.93 within 16 revolutions). A second
    call with the same settings resumes from the checkpoints and gives the same numbers."""
    mod = scenario_loader("journal_whip")
    args = ["--quick", "--grid", "32", "4", "--revolutions", "16", "--out", str(tmp_path)]
    data = mod.main(args)
    for name in ("run_up.png", "whirl_1.2x.png", "whirl_1.5x.png", "whip.json", "run_up.npz", "whirl_1.5x.npz"):
        assert (tmp_path / name).stat().st_size > 1000, name
    ru = data["run_up"]
    assert ru["speed_over_threshold"][0] == pytest.approx(0.8) and ru["speed_over_threshold"][-1] == pytest.approx(1.6)
    assert 0.8 < ru["whirl_ratio"][0] < 1.2
    assert 0.4 < ru["whirl_ratio"][-1] < 0.6
    assert ru["eps_max"][-1] > ru["eps_max"][0] + 0.3  # the whirl above the threshold is far larger
    w = data["whirl_1.5x"]
    assert 0.4 < w["whirl_ratio"] < 0.6 and w["eps_max"] > 0.8
    assert len(w["poincare_x"]) == 16 and w["touched_at_s"] is None and w["min_film_m"] > 0
    again = mod.main(args)  # resumed from the finished checkpoints: nothing recomputed, same numbers
    for tag in ("whirl_1.2x", "whirl_1.5x"):
        a, b = dict(again[tag]), dict(data[tag])
        a.pop("wall_s"), b.pop("wall_s")
        assert a == b, tag
    assert json.loads((tmp_path / "whip.json").read_text())["threshold_rpm"] == data["threshold_rpm"]


def test_carry_state_keeps_content_position_and_velocity():
    """Between two speeds the film keeps H theta, the journal its position and its velocity in m/s."""
    b = JournalBearing(**BEARING, grid=(24, 4))
    slow, fast = JournalOrbit(b, speed_rpm=5000.0, **ROTOR), JournalOrbit(b, speed_rpm=9000.0, **ROTOR)
    y = slow.initial_state()
    n = slow.film.n
    y[n:] = [0.3, 0.25, 0.05, -0.02]
    z = carry_state(slow, fast, y)
    np.testing.assert_allclose(fast.content_state(z)[:n], slow.content_state(y)[:n], rtol=1e-12)
    np.testing.assert_allclose(z[n:n + 2], y[n:n + 2])
    np.testing.assert_allclose(z[n + 2:] * fast.film.omega, y[n + 2:] * slow.film.omega, rtol=1e-14)
    # full-film pressures follow the speed: p = p0 P with the same theta (P scales with 1 / p0 ... exactly
    # where theta - 1 = P / beta_bar is what is kept)
    assert np.max(fast.film.universal(fast.content_state(z)[:n], 0.3, 0.25)) > 0


def test_whirl_numbers_of_a_synthetic_whirl():
    """A circular whirl at 0.47 of the shaft speed around the centre plus a small synchronous orbit: the whirl
    ratio is 0.47, the amplitude its radius, the Poincare section one point per revolution."""
    C, opr, revs, rpm = 1e-4, 64, 20, 6000.0
    t = np.arange(revs * opr + 1) / opr * 60.0 / rpm
    ph = 2 * np.pi * rpm / 60.0 * t
    x = C * (0.6 * np.cos(0.47 * ph) + 0.01 * np.cos(ph))
    y = C * (0.6 * np.sin(0.47 * ph) + 0.01 * np.sin(ph))
    r = OrbitResult(t=t, x=x, y=y, speed_rpm=rpm, clearance=C)
    w = whirl_numbers(r, opr, last_revolutions=10)
    assert w["whirl_ratio"] == pytest.approx(0.47, abs=2e-3)
    assert w["amp_x"] == pytest.approx(0.61, abs=0.01) and w["eps_max"] == pytest.approx(0.61, abs=1e-3)
    assert len(w["poincare_x"]) == revs and w["revolutions"] == revs
    with pytest.raises(ValueError, match="revolution"):
        whirl_numbers(OrbitResult(t=t[:10], x=x[:10], y=y[:10], speed_rpm=rpm, clearance=C), opr)


def _whirl(radius_of_revolution, revs=24, opr=64, rpm=6000.0, C=1e-4):
    t = np.arange(revs * opr + 1) / opr * 60.0 / rpm
    ph = 2 * np.pi * rpm / 60.0 * t
    rad = radius_of_revolution(ph / (2 * np.pi))
    return OrbitResult(t=t, x=C * rad * np.cos(0.47 * ph), y=C * rad * np.sin(0.47 * ph), speed_rpm=rpm, clearance=C)


def test_a_whirl_is_a_limit_cycle_only_when_its_envelope_stops_moving():
    """A whirl of constant radius 0.6 C is a limit cycle (envelope growth 0); one whose radius still grows by
    0.01 C per revolution is not settled, and the measured growth is that rate."""
    from transient.study.whip import ENVELOPE_TOL, settled_text

    steady = whirl_numbers(_whirl(lambda rev: 0.6 + 0 * rev), 64, last_revolutions=10)
    assert steady["settled"] and abs(steady["envelope_growth_per_rev"]) < 1e-6
    assert settled_text(steady).startswith("limit cycle")
    growing = whirl_numbers(_whirl(lambda rev: 0.3 + 0.01 * rev), 64, last_revolutions=10)
    assert not growing["settled"] and growing["envelope_growth_per_rev"] == pytest.approx(0.01, rel=0.05)
    assert growing["envelope_growth_per_rev"] > ENVELOPE_TOL
    assert settled_text(growing).startswith("NOT settled")


@pytest.mark.parametrize("method", ["bdf2", "ida"])
def test_the_whip_method_reaches_the_orbit_run(monkeypatch, method):
    """run_up and long_whip hand their ``method`` to every JournalOrbit.run; without one they use METHOD.
    (The spied runs themselves go by IDA: this checks the hand-over, not the integrator.)"""
    seen = []
    real = JournalOrbit.run

    def spy(self, *args, integration=None, **kwargs):
        seen.append(None if integration is None else integration.method)
        return real(self, *args, integration=replace(integration or Integration(), method="ida"), **kwargs)

    monkeypatch.setattr(JournalOrbit, "run", spy)
    b = JournalBearing(**BEARING, grid=(16, 4))
    make = lambda rpm: JournalOrbit(b, speed_rpm=rpm, **ROTOR)  # noqa: E731
    run_up(make, [4000.0, 5000.0], 1.0, outputs_per_revolution=16, method=method)
    long_whip(make(4000.0), 1.0, outputs_per_revolution=16, method=method, progress=False)
    run_up(make, [4000.0], 1.0, outputs_per_revolution=16)
    assert seen == [method, method, method, METHOD]


def test_bdf2_and_ida_give_the_same_whip():
    """12700 rpm (about 1.5x the threshold of the 32 x 4 grid), 8 revolutions from the equilibrium at rtol 1e-4:
    BDF2 on the content film and IDA give the same whirl -- ratio near 0.5, amplitudes and e/C range within
    0.005 C, the same envelope growth within 0.005 C/rev and the same verdict (measured: agreement to ~1e-4 C)."""
    b = JournalBearing(**BEARING, grid=(32, 4))
    w = {m: long_whip(JournalOrbit(b, speed_rpm=12700.0, **ROTOR), 8.0, method=m, progress=False,
                      last_revolutions=8)[1] for m in ("bdf2", "ida")}
    assert 0.4 < w["ida"]["whirl_ratio"] < 0.6 and w["ida"]["eps_max"] > 0.5  # oil whip, large orbit
    assert w["bdf2"]["whirl_ratio"] == pytest.approx(w["ida"]["whirl_ratio"], abs=0.005)
    for k in ("amp_x", "amp_y", "eps_min", "eps_max", "envelope_growth_per_rev"):
        assert w["bdf2"][k] == pytest.approx(w["ida"][k], abs=0.005), k
    assert w["bdf2"]["settled"] == w["ida"]["settled"] and w["bdf2"]["touched_at_s"] is None
