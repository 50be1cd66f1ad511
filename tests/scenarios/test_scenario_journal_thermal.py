"""The thermal journal scenario runs end to end (quick settings): the hotter film runs more eccentric and loses less
power than the isothermal film at the supply viscosity, above its supply temperature, with its energy balance
closed."""

import json

import numpy as np


def test_journal_thermal_scenario_quick(tmp_path, scenario_loader):
    scenario_loader("journal_thermal").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_thermal.png").exists()
    data = json.loads((tmp_path / "journal_thermal.json").read_text())
    thd, iso, meta = data["thd"], data["iso"], data["meta"]
    supply = meta["oil"]["supply_temperature"]
    assert len(data["speed_rpm"]) == 5
    # thinner oil carries the same load at a larger eccentricity, with less shear loss
    assert np.all(np.asarray(thd["eccentricity_ratio"]) > np.asarray(iso["eccentricity_ratio"]))
    assert np.all(np.asarray(thd["power_loss"]) < np.asarray(iso["power_loss"]))
    assert np.all(np.asarray(thd["max_temperature"]) > supply)
    assert np.all(np.diff(thd["max_temperature"]) > 0)  # faster is hotter
    assert np.all(np.asarray(thd["min_viscosity"]) < meta["supply_viscosity"])
    # dissipation = heat carried out by the oil + heat to the walls (adiabatic: none), to rounding
    d, q = np.asarray(thd["dissipation"]), np.asarray(thd["heat_convected"]) + np.asarray(thd["heat_conducted"])
    assert np.all(np.abs(d - q) <= 1e-9 * d) and np.all(np.asarray(thd["heat_conducted"]) == 0.0)
