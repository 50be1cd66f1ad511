"""The seed-003 journal orbit scenario runs end to end (quick settings, tiny grid)."""

import json



def test_journal_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("journal_orbit").main(["--quick", "--grid", "24", "4", "--out", str(tmp_path)])
    for name in ("journal_fig3_orbit.png", "journal_fig4_spectrum.png", "journal_fig8_response.png",
                 "journal_stability.png", "journal_orbit.json", "orbit_6000rpm.npz"):
        assert (tmp_path / name).stat().st_size > 1000, name
    saved = json.loads((tmp_path / "journal_orbit.json").read_text())
    f3 = saved["fig3_fig4"]
    assert f3["spectrum_peak_order"] == 1.0  # the x spectrum's largest peak is at 1x
    assert f3["harmonics_C"]["1x"] > 10 * f3["harmonics_C"]["2x"]
    assert 0 < f3["settled_orbit"]["semi_minor"] <= f3["settled_orbit"]["semi_major"] < 0.1
    pts = saved["fig8"]["points"]
    assert [p["speed_rpm"] for p in pts] == [1000, 3000, 5000, 6000, 7500]
    for p in pts:  # small unbalance: the nonlinear orbit is close to the linear response
        assert abs(p["semi_major"] / p["linear_semi_major"] - 1) < 0.1, p
    st = saved["stability"]
    assert [r["verdict"] for r in st["runs"]] == ["decays", "grows"]
    assert data["stability"]["threshold_rpm"] == st["threshold_rpm"]
    assert not list(tmp_path.glob("*checkpoint*"))
