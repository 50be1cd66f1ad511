"""The oil-feed design scenario runs end to end (quick settings) and its mass balance holds at every point."""

import numpy as np


def test_feeds_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("journal_feeds").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_feeds.png").exists() and (tmp_path / "journal_feeds.json").exists()
    names = ("full groove", "3/4-length groove", "two grooves at +-90 deg", "oil hole")
    for name in names:
        r = data[name]
        assert np.all(np.isfinite(r["eccentricity_ratio"]))
        assert np.max(np.abs(r["balance"])) < 1e-8
        assert np.all(np.diff(r["eccentricity_ratio"]) > 0)  # heavier load, larger eccentricity
    # sealing the groove's ends cuts the supply at every load
    assert np.all(np.array(data["3/4-length groove"]["supply_flow"]) < np.array(data["full groove"]["supply_flow"]))


def test_feeds_bench_quick():
    from transient.bench import feeds

    r = feeds.run(quick=True)
    assert set(r["cases"]) == set(feeds.feeds(0.08))
    for c in r["cases"].values():
        assert all(np.isfinite(c[k]) and c[k] > 0 for k in ("rhs_us", "jac_us", "flows_us", "orbit_s"))
    assert "| 3/4-length groove + hole |" in feeds.markdown(r)
