"""Smoke test of the oil-whip benchmark (quick settings: 48 x 8 and 32 x 6 films)."""

import math

import pytest

from transient.bench import whip


@pytest.mark.slow
def test_bench_whip_quick_structure():
    res = whip.run(quick=True, log=lambda *_: None)
    assert [r["grid"] for r in res["rows"]] == [[48, 8], [32, 6]]
    for r in res["rows"]:
        assert r["message"] == "reached the final time"
        assert 0.3 < r["whirl_ratio"] < 0.7  # a whirl near half the shaft speed
        assert r["study"]["cpu_per_rev"] > 0 and r["orbit_size"]["steps_per_rev"] > r["study"]["steps_per_rev"]
    assert res["rows"][0]["amplitude_error"] == 0.0
    assert math.isfinite(res["step_error"]["relative"])
    assert "min per 1000 rev" in whip.markdown(res)
