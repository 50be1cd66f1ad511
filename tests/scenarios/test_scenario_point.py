"""The point-contact scenario end to end (--quick): the maps, Chevalier's law on the starved films, the ball
bearing's formula against numerical contact."""

import json

import pytest


@pytest.mark.slow
def test_point_contact_scenario_quick(tmp_path, scenario_loader):
    scenario_loader("point_contact").main(["--quick", "--out", str(tmp_path)])
    for name in ("point_maps.png", "point_starved_films.png", "point_ball_films.png", "point_contact.json"):
        assert (tmp_path / name).stat().st_size > 1000, name
    d = json.loads((tmp_path / "point_contact.json").read_text())
    flooded, starved = d["maps"]["flooded"], d["maps"]["starved"]
    assert flooded["m"] > 4.0 and 1.0 < starved["m"] < 1.5  # the starved meniscus moves to the Hertz zone
    assert starved["h_central"] < 0.5 * flooded["h_central"]  # half the flooded film as the layer, less at the centre
    ch = d["starved"]["circular"]
    assert ch["holds"] and ch["max_deviation"] < 0.03 and 1.5 < ch["gamma"] < 4.0
    ball = d["ball"]["80 rpm (M = 2132)"]
    t = ball["table"]
    # thin layers: the law's film is thicker than the numerical contact's (which is the layer / rho_c)
    assert t["formula"][-1] > 2.0 * t["numerical"][-1]
    assert t["numerical_h"][-1] / t["h_in"][-1] == pytest.approx(0.838, abs=0.01)
    seq = ball["sequences"]
    assert "pass 5" in seq["80 rpm, numerical"]["message"] and seq["80 rpm, formula"]["message"] == ""
    assert seq["80 rpm, formula"]["regime"][-1] == "parched"
