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
