"""The steady-film bench's two methods and its table, on a small grid (grid sequencing forced by lowering its
thresholds); the timings themselves are the bench's, not the tests'."""

import transient.models.journal.bearing as bearing_module
from transient.bench import steady_film


def test_both_methods_give_the_same_film_and_the_table_names_their_levels(monkeypatch):
    monkeypatch.setattr(bearing_module, "SEQUENCE_CELLS", 400)
    monkeypatch.setattr(bearing_module, "SEQUENCE_MIN_THETA", 24)
    b = steady_film.pfeil_bearing((96, 8))
    cases = {}
    for name, method in steady_film.METHODS.items():
        state, levels = method(b)
        cases[name] = steady_film._numbers(state, levels, 1.0)
    rest, seq = cases["from rest"], cases["grid sequencing"]
    assert [lv[0] for lv in seq["levels"]] == [[48, 8], [96, 8]] and len(rest["levels"]) == 1
    assert abs(seq["load"] / rest["load"] - 1) < 1e-9
    assert abs(seq["mass_balance"]) < 1e-12 and abs(rest["mass_balance"]) < 1e-12
    for c in cases.values():
        c["load_rel_diff"], c["speed_up"] = c["load"] / rest["load"] - 1, 1.0
    text = steady_film.markdown(dict(quick=True, cases=[dict(grid=[96, 8], rounds=1, methods=cases)]))
    assert "| 96 x 8 | grid sequencing |" in text and "48 x 8: " in text and "quick smoke run" in text
