"""Smoke test of the journal-orbit work-precision benchmark (tiny grid, quick settings)."""

import math

from transient.bench import journal
from transient.bench import write_section as _write_bench


def test_bench_journal_quick_structure_and_convergence(tmp_path):
    res = journal.run(grid=(24, 4), quick=True, time_budget_s=60.0, progress=False)
    rows = res["rows"]
    lines = {r["line"] for r in rows}
    assert lines == {"cvode", "ida", "bdf", "lsoda", "rk4", "rk4_tight"}
    assert all(r["status"] == "ok" for r in rows), [r["status"] for r in rows]
    for r in rows:
        assert r["wall"] > 0 and r["n_steps"] > 0
        assert 0 < r["error_max"] < 1e-2 and r["error_final"] <= r["error_max"] * (1 + 1e-12)
    # tighter tolerance -> smaller error (1e-3 vs 1e-6) for both SUNDIALS methods
    for line in ("cvode", "ida"):
        e = {r["setting"]: r["error_max"] for r in rows if r["line"] == line}
        assert e["1e-06"] < 0.1 * e["1e-03"], (line, e)
    # the reference is resolved far below the errors measured (its own error contaminates them < 1 %)
    assert res["reference"]["check_error_max"] < 1e-2 * min(r["error_max"] for r in rows)
    m = res["matched"]["paper"]
    assert m["target"] > 0 and math.isfinite(m["lines"]["cvode"]["wall"])
    assert m["lines"]["cvode"]["ratio_to_cvode"] == 1.0
    assert res["long"]["revolutions"] == 2 and res["long"]["wall"] > 0
    text = journal.markdown(res)
    assert text.count("| CVODE | 1e-0") == 2 and "quick smoke run" in text and "RK4, inner 1e-06 (paper) | 3000" in text
    png = journal.write(res, tmp_path)
    assert png.exists() and png.stat().st_size > 10_000 and (tmp_path / "bench_journal.json").exists()
    _write_bench("journal", text, tmp_path)
    assert "| IDA | 1e-06 |" in (tmp_path / "benchmarks.md").read_text()


def test_cost_at_interpolates_on_the_pareto_front():
    rows = [dict(line="x", status="ok", error_max=e, wall=w) for e, w in
            ((1e-2, 1.0), (1e-4, 10.0), (1e-3, 20.0))]  # the 20 s point is dominated
    w, how = journal.cost_at(rows, "x", 1e-3)
    assert how == "interpolated" and abs(w - math.sqrt(10.0)) < 1e-9
    assert journal.cost_at(rows, "x", 1e-5) == (math.nan, "not reached") or \
        journal.cost_at(rows, "x", 1e-5)[1] == "not reached"
    assert journal.cost_at(rows, "x", 1.0) == (1.0, "upper bound")
