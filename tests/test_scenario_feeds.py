"""The oil-feed design scenario runs end to end (quick settings) and its mass balance holds at every point."""

import numpy as np
from scenario_loader import load_scenario


def test_feeds_scenario_quick(tmp_path):
    data = load_scenario("journal_feeds").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_feeds.png").exists() and (tmp_path / "journal_feeds.json").exists()
    names = ("full groove", "3/4-length groove", "two grooves at +-90 deg", "oil hole")
    for name in names:
        r = data[name]
        assert np.all(np.isfinite(r["eccentricity_ratio"]))
        assert np.max(np.abs(r["balance"])) < 1e-8
        assert np.all(np.diff(r["eccentricity_ratio"]) > 0)  # heavier load, larger eccentricity
    # sealing the groove's ends cuts the supply at every load
    assert np.all(np.array(data["3/4-length groove"]["supply_flow"]) < np.array(data["full groove"]["supply_flow"]))
