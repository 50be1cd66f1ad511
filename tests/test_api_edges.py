"""Small API contracts a new user meets first: a rough surface with its default correlation length, readable
reprs of the bearing and the surface, and the compile notice only on a cold kernel cache."""

import io

import pytest

from transient import JournalBearing, RoughSurface
from transient.params import rho_kim


def test_rough_surface_generates_with_its_default_correlation_length():
    s = RoughSurface.generate((64, 96), 1e-6, 2e-6, seed=3)
    lx, ly = s.correlation_lengths  # measured; the default is isotropic, 1/8 of the shorter side (8 um)
    assert s.rq == pytest.approx(2e-6, rel=0.1)
    assert lx == pytest.approx(8e-6, rel=0.35) and ly == pytest.approx(8e-6, rel=0.35)


def test_reprs_say_what_the_object_is_without_dumping_arrays():
    s = RoughSurface.generate((64, 64), 1e-6, 2e-6, correlation_lengths=8e-6, seed=3)
    r = repr(s)
    assert r.startswith("RoughSurface(shape=(64, 64), spacing=(1e-06, 1e-06) m, rq=") and "array" not in r
    assert f"rq={s.rq:.4g} m" in r
    assert len(r) < 200
    b = JournalBearing(**rho_kim.BEARING, grid=(24, 4))
    r = repr(b)
    assert r.startswith("JournalBearing(diameter=0.08 m, length=0.024 m, clearance=8e-05 m") and "0x" not in r
    assert "grid=(24, 4)" in r and "cavitation='elrod'" in r


def test_compile_notice_only_when_the_cache_is_cold(monkeypatch):
    from transient import compile_notice

    out = io.StringIO()
    monkeypatch.setattr(compile_notice, "is_cold", lambda family: False)
    assert compile_notice.announce("journal", stream=out) is False and out.getvalue() == ""
    monkeypatch.setattr(compile_notice, "is_cold", lambda family: family == "ball")
    assert compile_notice.announce("journal", "ball", stream=out)
    assert out.getvalue().startswith(f"compiling kernels once (~{compile_notice.FAMILIES['ball'][2]} s")

