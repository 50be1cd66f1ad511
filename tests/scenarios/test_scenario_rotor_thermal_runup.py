"""The rotor thermal run-up scenario runs end to end (quick settings): each bearing's film temperature lags the
speed -- below its steady THD film's in the rotor's thermal equilibrium at full speed, rising towards it while the
speed holds -- with the heat balance closed; the more loaded bearing runs hotter."""

import json

import numpy as np


def test_rotor_thermal_runup_scenario_quick(tmp_path, scenario_loader):
    scenario_loader("rotor_thermal_runup").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "rotor_thermal_runup.png").exists()
    data = json.loads((tmp_path / "rotor_thermal_runup.json").read_text())
    run, steady = data["run"], data["steady"]
    assert run["shaft_speed"][0] == 1500.0 and run["shaft_speed"][-1] == 3000.0
    lag, final = np.array(data["lag_at_full_speed_K"]), np.array(data["final_lag_K"])
    assert np.all(lag > 2.0)  # seconds of wall heat capacity: far behind the speed
    assert np.all((0.0 < final) & (final < lag))  # catching up at constant speed
    T = np.array(run["max_temperature"])
    assert np.all(np.diff(T, axis=0) >= -1e-9)
    assert np.all(T.max(axis=0) < np.array(steady["max_temperature"][-1]))
    assert data["heat_balance_max_error"] < 0.01
