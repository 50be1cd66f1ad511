"""The thermal run-up scenario runs end to end (quick settings): the film's temperature lags the speed -- below the
steady THD film's at full speed, rising towards it while the speed holds -- with the heat balance closed."""

import json

import numpy as np


def test_journal_thermal_runup_scenario_quick(tmp_path, scenario_loader):
    scenario_loader("journal_thermal_runup").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_thermal_runup.png").exists()
    data = json.loads((tmp_path / "journal_thermal_runup.json").read_text())
    run, steady = data["run"], data["steady"]
    assert run["shaft_speed"][0] == 1500.0 and run["shaft_speed"][-1] == 3000.0
    assert data["lag_at_full_speed_K"] > 2.0  # seconds of wall heat capacity: far behind the speed
    assert 0.0 < data["final_lag_K"] < data["lag_at_full_speed_K"]  # catching up at constant speed
    assert np.all(np.diff(run["max_temperature"]) >= -1e-9)
    assert max(run["max_temperature"]) < steady["max_temperature"][-1]
    assert data["heat_balance_max_error"] < 0.01
