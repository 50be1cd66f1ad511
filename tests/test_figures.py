"""Every figure a scenario writes has a title and labelled axes with units (tests/figure_checks.py): each
scenario runs with --quick into a temporary folder with ``transient.plots.save`` recording the figures.
Slow (the scenarios' quick runs); the fast tests check the figure functions on small inputs."""

from pathlib import Path

import numpy as np
import pytest

import transient.plots as tp
from figure_checks import figure_problems

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"

#: scenarios and the arguments of their quickest complete run
QUICK_ARGS = {p.stem: ["--quick"] for p in sorted(SCENARIOS.glob("*.py"))}
QUICK_ARGS["journal_orbit"] = ["--quick", "--grid", "24", "4"]
QUICK_ARGS["journal_long_run"] = ["--quick"]
QUICK_ARGS["rotor_whip"] = ["--quick", "--revolutions", "6"]


@pytest.fixture
def recorded(monkeypatch):
    figs = {}
    original = tp.save

    def save(fig, path, *a, **kw):
        out = original(fig, path, *a, **kw)
        figs[out.name] = fig
        return out

    monkeypatch.setattr(tp, "save", save)
    return figs


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(QUICK_ARGS))
def test_scenario_figures(name, tmp_path, recorded, scenario_loader):
    scenario_loader(name).main([*QUICK_ARGS[name], "--out", str(tmp_path)])
    pngs = sorted(p.name for p in tmp_path.rglob("*.png"))
    assert pngs, f"{name} wrote no figure"
    assert set(pngs) <= set(recorded), f"figures not written through transient.plots.save: {set(pngs) - set(recorded)}"
    problems = [f"{k}: {p}" for k, f in sorted(recorded.items()) for p in figure_problems(f)]
    assert not problems, "\n".join(problems)


def test_the_check_finds_missing_units_and_titles():
    fig, ax = tp.figure()
    ax.plot([0, 1], [0, 1])
    ax.set(xlabel="speed", ylabel="e/C [-]")
    assert any("x label 'speed'" in p for p in figure_problems(fig))
    assert any("no title" in p for p in figure_problems(fig))
    ax.set(xlabel="speed [rpm]", title="t")
    assert figure_problems(fig) == []


def test_sweep_curves_mark_unsettled_points_and_name_units():
    from transient.plots.sweep import scalar_curves

    table = dict(speed_rpm=[1000.0, 4000.0, 7500.0], semi_major_C=[0.01, 0.02, 0.012], eps_max=[0.3, 0.4, 0.5],
                 settled=[True, True, False], status=["ok"] * 3)
    fig = scalar_curves(table, "speed_rpm", ["semi_major_C", "eps_max"])
    assert figure_problems(fig) == []
    ax = fig.axes[0]
    assert ax.get_xlabel() == "speed [rpm]"
    open_ = [ln for ln in ax.get_lines() if ln.get_label() == "NOT settled"]
    assert len(open_) == 1 and list(open_[0].get_xdata()) == [7500.0]


def test_ball_regime_map_is_categorical_over_the_sampled_points():
    from transient.params import jeong
    from transient.plots.ball import regime_map
    from transient.study.ball import RegimeMap

    Z, N, W = np.array([1, 6, 11]), np.array([70.0, 90.0]), np.array([10.0, 60.0])
    reg = np.zeros((3, 2, 2), int)
    reg[2] = 2
    rmap = RegimeMap(n_balls=Z, speed_rpm=N, load=W, ambient_film=100e-6, regime=reg,
                     H_central=np.full((3, 2, 2), 1e-5))
    fig = regime_map(rmap, "n_balls", "load", at=jeong.REFERENCE, paper=jeong.REPORTED)
    assert figure_problems(fig) == []
    ax = fig.axes[0]
    assert ax.get_xlim() == (-0.5, 2.5) and ax.get_ylim() == (-0.5, 1.5)  # no axis stretched past the samples
    assert [t.get_text() for t in ax.get_xticklabels()] == ["1", "6", "11"]
    colours = {tuple(p.get_facecolor()[:3]) for p in ax.patches}
    assert len(colours) == 2  # two regimes sampled, two colours


def test_spectrum_axis_is_not_set_by_the_dc_bin():
    from transient.plots.journal import x_spectrum
    from transient.study.journal import EquilibriumOrbit

    order = np.arange(0, 16) / 4.0
    spec = np.full(order.size, 1e-9)
    spec[0], spec[4], spec[8] = 0.5, 1e-2, 1e-4  # mean position, 1x, 2x
    rec = EquilibriumOrbit(orbit=None, spectrum_order=order, spectrum_amplitude_C=spec,
                           harmonics_C={"1x": 1e-2, "2x": 1e-4}, speed_rpm=6000.0, fft_revolutions=4,
                           spectrum_peak_order=1.0)
    fig = x_spectrum(rec)
    assert figure_problems(fig) == []
    lo, hi = fig.axes[0].get_ylim()
    assert hi < 0.5 and lo >= 1e-2 * 1e-6 * 0.999


def test_plots_reach_their_figure_modules_and_save_says_it_creates_folders(tmp_path, capsys):
    assert callable(tp.journal.orbit_settling) and callable(tp.whip.whirl) and callable(tp.ball.regime_map)
    fig, ax = tp.figure()
    path = tp.save(fig, tmp_path / "new" / "f.png")
    assert path.exists() and "created folder" in capsys.readouterr().err
    with pytest.raises(FileNotFoundError, match="missing"):
        tp.save(fig, tmp_path / "missing" / "f.png", make_folders=False)


def test_rotor_figures_name_units():
    from transient.models.rotor.results import RotorRunResult
    from transient.plots import rotor

    t = np.linspace(0.0, 1.0, 4001)
    n = 1200.0 + 1200.0 * t
    phi = np.concatenate([[0.0], np.cumsum(0.5 * (n[1:] + n[:-1]) * np.pi / 30.0 * np.diff(t))])
    d = np.zeros((t.size, 2, 2))
    d[:, :, 0] = 1e-6 * np.cos(phi)[:, None]
    d[:, :, 1] = 1e-6 * np.sin(phi)[:, None]
    r = RotorRunResult(t=t, displacement=d, speed_rpm=n, nodes=[0, 1], bearing_nodes=[0])
    lam = [np.array([-10 + 2j * np.pi * 30, -5 + 2j * np.pi * 50]) for _ in range(3)]
    figs = [rotor.campbell([1000.0, 2000.0, 3000.0], lam, {"threshold": 2500.0}),
            rotor.response_curve({"linear": ([1000, 2000], [1e-6, 2e-6])}, {"run": ([1500], [1.5e-6])}, "disk"),
            rotor.waterfall(r, 1, "cascade", window_revolutions=2.0), rotor.orbits(r, {0: "bearing", 1: "disk"}, [1800.0])]
    for fig in figs:
        assert figure_problems(fig) == []


def test_feed_pressure_maps_close_the_film_and_name_units():
    from transient import CircumferentialGroove, Groove, JournalBearing

    bearing = dict(diameter=0.1, length=0.08, clearance=150e-6, viscosity=0.01, supply_pressure=70e3,
                   ambient_pressure=0.0, cavitation_pressure=0.0, grid=(24, 4))
    states = {name: JournalBearing(**bearing, groove=feed).equilibrium(load=5000.0, speed_rpm=3000)
              for name, feed in (("groove", Groove(0.0, 15.0)), ("circumferential", CircumferentialGroove(0.02)))}
    fig = tp.feeds.pressure_maps(states)
    assert figure_problems(fig) == []
    mesh = fig.axes[0].collections[0]
    assert mesh.get_array().shape == (2 * 4, 24 + 1)  # mirrored to the whole length, closed at 360 deg
    assert mesh.get_clim() == (0.0, pytest.approx(1e-3 * max(s.pressure.max() for s in states.values())))


def _inside(fig, artist) -> bool:
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig)
    fig.canvas.draw()
    box, page = artist.get_window_extent(), fig.bbox
    return box.x0 >= page.x0 - 0.5 and box.x1 <= page.x1 + 0.5 and box.y1 <= page.y1 + 0.5


def test_a_long_title_on_a_one_panel_critical_film_figure_fits():
    from transient.params import jeong

    lines = {"n_balls": (np.array([1, 11]), [226e-6, 300e-6], {"load": 30.0, "speed_rpm": 80.0})}
    fig = tp.ball.critical_films(lines, 100e-6, jeong.REPORTED)
    assert _inside(fig, fig._suptitle)
    assert figure_problems(fig) == []


def test_order_spectra_track_the_1x_line_and_a_fixed_whirl_frequency():
    from transient.models.rotor.results import RotorRunResult
    from transient.plots.rotor import order_spectra

    t = np.linspace(0.0, 2.0, 20001)
    n = 1500.0 + 1500.0 * t / 2.0  # run-up 1500 -> 3000 rpm
    phi = np.concatenate([[0.0], np.cumsum(0.5 * (n[1:] + n[:-1]) * np.pi / 30.0 * np.diff(t))])
    d = np.zeros((t.size, 1, 2))
    d[:, 0, 0] = 2e-6 * np.cos(phi) + 5e-6 * np.cos(2 * np.pi * 12.0 * t) + 1e-5 * t  # 1x, 12 Hz whirl, a drift
    r = RotorRunResult(t=t, displacement=d, speed_rpm=n, nodes=[0], bearing_nodes=[0])
    speeds, orders, amp = order_spectra(r, 0, window_revolutions=8.0)
    one = np.argmin(np.abs(orders - 1.0))
    assert np.allclose(amp[:, one], 2e-6, rtol=0.1)  # the 1x amplitude, with the drift taken out
    low = orders < 0.9
    whirl_hz = orders[low][np.argmax(amp[:, low], axis=1)] * speeds / 60.0
    assert np.allclose(whirl_hz, 12.0, atol=1.5)  # at its own frequency while the order falls


def test_damper_figures_name_units():
    eps = np.array([0.2, 0.5])
    figs = [tp.damper.orbit_forces({"film": (eps, [-1.0, -3.0], [-2.0, -6.0])}, {"closed": (eps, [-1.1, -3.1], [-2.1, -6.1])},
                                   "damper"),
            tp.damper.supply_sweep(np.array([0.01, 1.0]), [0.5, 0.0], [0.2, 2.0], [0.9, 0.0], "sweep")]
    for fig in figs:
        assert figure_problems(fig) == []
