"""The thermal bench's table from its own numbers on a small grid (the timings themselves are the bench's)."""

from transient.bench import thermal


def test_the_table_shows_each_eccentricity_and_the_ratio():
    hot, iso = thermal.bearings((24, 4))
    s, si = hot.steady_state(0.6, thermal.RPM), iso.steady_state(0.6, thermal.RPM)
    assert s.max_temperature > thermal.OIL.supply_temperature and s.load < si.load
    case = dict(eccentricity_ratio=0.6, thermal_s=2.0, isothermal_s=1.0, ratio=2.0, alternations=s.thermal_iterations,
                newton=s.newton_iterations, max_temperature_C=s.max_temperature - 273.15, load_ratio=s.load / si.load,
                power_ratio=s.power_loss / si.power_loss)
    text = thermal.markdown(dict(quick=True, grid=[24, 4], rounds=1, rpm=thermal.RPM, cases=[case]))
    assert "| 0.6 | 2.000 | 1.000 | 2.00 |" in text and "quick smoke run" in text
