"""The film validation scenario (scenarios/film_validation.py) runs on coarse grids and reports
second-order convergence; it writes its figure and numbers."""

import csv
import json

import numpy as np
import pytest


@pytest.fixture(scope="module")
def scenario(scenario_loader):
    return scenario_loader("film_validation")


def test_quick_run_writes_files_and_second_order(scenario, tmp_path, capsys):
    assert scenario.main(["--out", str(tmp_path / "out"), "--quick"]) == 0
    printed = capsys.readouterr().out
    out = tmp_path / "out"
    png, js, cs = out / "film_validation.png", out / "film_validation.json", out / "film_validation.csv"
    for f in (png, js, cs):
        assert f.is_file() and f.stat().st_size > 0, f
        assert str(f) in printed
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    res = json.loads(js.read_text())
    # the orders read back from the file, not recomputed here
    for kind in ("uniform", "stretched"):
        orders = np.array(res["sommerfeld"][kind]["orders"])
        assert orders.size == 2 and np.all(np.abs(orders - 2.0) < 0.1), (kind, orders)
        assert res["sommerfeld"][kind]["p_err"][-1] < 2e-3
        assert all(it <= 2 for it in res["sommerfeld"][kind]["iterations"])  # linear: one Newton step
    for label, s in res["squeeze"].items():
        orders = np.array(s["orders"])
        assert orders.size == 2 and np.all(np.abs(orders - 2.0) < 0.1), (label, orders)
    assert set(res["squeeze"]) == {"b/a=1", "b/a=2", "b/a=4", "b/a=2 stretched"}
    sb = np.array(res["short_bearing"]["fy_err"])
    assert sb[0] < 1.5e-2 and np.all(sb[1:] < sb[:-1] / 3.0), sb  # the (L/D)^2 short-bearing trend
    with open(cs) as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 2 * 3 + 3 + 4 * 3
    assert {r["check"] for r in rows} == {"sommerfeld", "short_bearing", "squeeze"}


def test_orders_reflect_the_numbers(scenario, tmp_path, monkeypatch):
    """The reported orders come from the measured errors: a first-order error model must show order 1."""
    from transient.study import film_validation
    from transient.verification import cases

    real = cases.squeeze_plate_case

    def first_order(ratio, n=64, delta=0.0, **kw):
        r = real(ratio, n=n, delta=delta, **kw)
        r.err = 1.0 / n
        return r

    monkeypatch.setattr(film_validation, "squeeze_plate_case", first_order)
    res = scenario.run_validation(tmp_path, make_plot=False, **{**scenario.QUICK, "sommerfeld_grids": (8, 16),
                                                                 "short_grid": (24, 8)})
    assert np.allclose(res["squeeze"]["b/a=1"]["orders"], 1.0)


@pytest.mark.parametrize("argv, match", [
    (["--bogus"], "unrecognized arguments"),
    (["--out", " "], "--out must be a non-empty directory path"),
])
def test_bad_cli_arguments(scenario, argv, match, capsys):
    with pytest.raises(SystemExit):
        scenario.main(argv)
    assert match in capsys.readouterr().err


def test_out_must_be_a_directory(scenario, tmp_path, capsys):
    f = tmp_path / "file.txt"
    f.write_text("x")
    with pytest.raises(SystemExit):
        scenario.main(["--out", str(f), "--quick"])
    assert "must be a directory" in capsys.readouterr().err


def test_bad_settings_raise(scenario, tmp_path):
    with pytest.raises(ValueError, match="sommerfeld_grids must be strictly increasing"):
        scenario.run_validation(tmp_path, **{**scenario.QUICK, "sommerfeld_grids": (64, 32)})
    with pytest.raises(ValueError, match="short_LD"):
        scenario.run_validation(tmp_path, **{**scenario.QUICK, "short_LD": (0.1,)})
