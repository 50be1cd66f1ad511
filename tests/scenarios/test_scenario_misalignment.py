"""The misaligned-bearing scenario runs end to end (quick settings): the edge film and the moments against the tilt."""

import numpy as np


def test_misalignment_scenario_quick(tmp_path, scenario_loader):
    data = scenario_loader("journal_misalignment").main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "journal_misalignment.png").exists() and (tmp_path / "journal_misalignment.json").exists()
    tilt, moment, h = np.asarray(data["tilt"]), np.asarray(data["moment"]), np.asarray(data["min_film"])
    C, half = 150e-6, 0.04
    assert np.allclose(h, C * (0.5 - tilt * half / C), rtol=1e-12)  # the end film: e/C 0.5 plus the tilt's reach
    assert abs(h[-1] - 0.3 * C) < 1e-12 * C
    assert np.all(moment[0] == 0.0) and np.all(np.diff(moment[:, 1]) < 0)  # a restoring moment growing with the tilt
