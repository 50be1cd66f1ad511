"""The Stribeck scenario runs end to end (quick settings): a falling mixed branch, a rising hydrodynamic one, the
lift-off between them."""

import numpy as np


def test_stribeck_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("stribeck").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "stribeck.png").exists() and (tmp_path / "stribeck.json").exists()
    c = data["curve"]
    T, s = np.asarray(c["friction_torque"]), np.asarray(c["speed_rpm"])
    k = int(np.argmin(T))
    assert 0 < k < T.size - 1 and np.all(np.diff(T[:k + 1]) < 0) and np.all(np.diff(T[k:]) > 0)
    assert s[0] < c["lift_off_speed_rpm"] < s[k + 1]
    assert np.asarray(c["contact_load"])[-1] < 1e-12 * c["load"]  # h_min = 19 sigma at 6000 rpm
