"""The start-up / coast-down scenario runs end to end (quick settings): the journal lifts off the asperities on the
way up and sinks back onto them on the way down, without a NaN or a stall, the contact pressures bounded."""

import numpy as np


def test_journal_startup_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("journal_startup").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_startup.png").exists() and (tmp_path / "journal_startup.json").exists()
    up, down = data["start-up"], data["coast-down"]
    for run in (up, down):
        assert run["success"] and run["finite"]
        assert run["peak_contact_pressure"] < 100e6  # 20 MPa at rest (the hardness is GPa)
    load = 5000.0
    assert up["contact_load"][0] > 0.99 * load and up["contact_load"][-1] < 1e-3 * load
    assert [w for _, w in up["contact_events"]] == ["begins", "ends"]
    assert down["contact_load"][0] < 1e-3 * load and down["contact_load"][-1] > 0.99 * load
    assert [w for _, w in down["contact_events"]] == ["begins"]
    T = np.asarray(up["friction_torque"])
    assert T[0] > 20 * T[-1]  # boundary friction at rest, the hydrodynamic film's at speed
