"""Smoke test of the film operator benchmark (tiny grids) and of `transient bench` writing docs."""

from transient.bench.reynolds_operator import markdown, run
from transient.bench import write_section as _write_bench


def test_bench_film_rows_and_table(tmp_path):
    rows = run(grids=((16, 4), (24, 6)))
    assert [r["cells"] for r in rows] == [64, 144]
    assert all(r["residual_us"] > 0 and r["jacobian_us"] > 0 for r in rows)
    text = markdown(rows)
    assert "| 16 x 4 | 64 |" in text and "| 24 x 6 | 144 |" in text
    _write_bench("reynolds_operator", text, tmp_path)
    assert "| 16 x 4 | 64 |" in (tmp_path / "benchmarks.md").read_text()
