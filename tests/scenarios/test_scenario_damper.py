"""The squeeze-film damper scenario runs end to end (quick settings) and its films meet the closed forms."""

import numpy as np
import pytest


@pytest.mark.slow
def test_damper_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("squeeze_film_damper").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "squeeze_film_damper.png").exists() and (tmp_path / "squeeze_film_damper_supply.png").exists()
    full, pi = (next(v for k, v in data.items() if k.startswith(s)) for s in ("Elrod film, supply 300", "Reynolds"))
    # L/D = 0.1: the finite length takes up to ~3 % off the short-damper forms at e/c 0.8
    assert np.all(np.abs(full["tangential_deviation"]) < 0.04) and np.all(np.abs(full["radial_deviation"]) < 1e-3)
    assert np.all(np.abs(pi["tangential_deviation"]) < 0.04) and np.all(np.abs(pi["radial_deviation"]) < 0.04)
    sweep = data["supply_sweep"]
    assert sweep["cavitated"][0] > 0.9 and sweep["cavitated"][-1] == 0.0
    assert abs(sweep["tangential_share"][-1] - 2.0) < 0.02  # the full film is the 2-pi film
