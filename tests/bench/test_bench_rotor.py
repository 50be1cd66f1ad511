"""Smoke test of the rotor benchmark (quick settings: 48 x 8 films)."""

import pytest

from transient.bench import rotor


@pytest.mark.slow
def test_bench_rotor_quick_structure(tmp_path):
    res = rotor.run(quick=True)
    assert set(res["rows"]) == {"orbit", "one", "two", "flex"}
    assert all(r["ok"] and r["cpu_per_rev"] > 0 and r["steps_per_rev"] > 0 for r in res["rows"].values())
    assert res["rows"]["two"]["states"] == 2 * res["rows"]["one"]["states"] - 1  # two films, a 4-dof rotor
    assert res["runup"]["ok"] and res["runup"]["final_speed_rpm"] == pytest.approx(9000.0, rel=1e-3)
    assert "Two bearings cost" in rotor.markdown(res)
    for case in ("one", "two", "flex", "runup"):  # the default against IDA, each judged by its error
        rows = res["methods"][case]
        assert rows["IDA rtol 1e-6"]["method"] == "ida" and rows["default"]["method"] == "bdf2"
        assert all(r["ok"] and 0 < r["error"] < 1e-3 for r in rows.values())
    assert "The run's default method against IDA" in rotor.markdown(res)
