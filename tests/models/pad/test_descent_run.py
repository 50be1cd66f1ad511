"""The pad's descent on the one run driver: settings objects, start from a result, checkpoint/resume bit for bit,
stop, time budget, and the old keywords for one release."""

import warnings
from dataclasses import replace

import numpy as np
import pytest

from transient import Integration, LongRun, ThrustPad
from transient.solvers.longrun import CheckpointError
from transient.verification.reference import squeeze_rect_load

L, MU, W, HS = 0.02, 0.03, 200.0, 20e-6
K0 = squeeze_rect_load(L, L, 1.0, -1.0, MU, n_terms=400)  # smooth plates: W = K0 V / h^3


def _law(t):
    """The smooth pad's closed form: h(t) = (1/hs^2 + 2 W t / K0)^(-1/2)."""
    return 1.0 / np.sqrt(1.0 / HS ** 2 + 2.0 * W * np.asarray(t) / K0)


T_END = K0 / (2 * W) * (1 / 5e-6 ** 2 - 1 / HS ** 2)
TIGHT = Integration(method="cvode", rtol=1e-8, atol=1e-10)


def test_the_settings_objects_give_what_the_old_keywords_gave():
    pad = ThrustPad(L, L, MU, grid=(8, 8))
    new = pad.descent(W, HS, T_END, integration=TIGHT, n_out=11)
    with pytest.warns(DeprecationWarning, match=r"rtol= is deprecated.*integration=Integration\(rtol=...\)"):
        old = pad.descent(W, HS, T_END, method="cvode", rtol=1e-8, atol=1e-10, n_out=11)
    assert np.array_equal(new.h0, old.h0) and np.array_equal(new.t, old.t)
    assert np.max(np.abs(new.h0 / _law(new.t) - 1)) < 1e-5
    with pytest.raises(ValueError, match=r"ThrustPad.descent: rtol=1e-08 and integration=Integration\(...\) both"):
        pad.descent(W, HS, T_END, integration=TIGHT, rtol=1e-8)


def test_a_descent_goes_on_from_its_result_on_the_closed_form():
    """Half the descent, then the rest from its result: the time goes on, and the gap follows the law."""
    pad = ThrustPad(L, L, MU, grid=(8, 8))
    first = pad.descent(W, HS, 0.5 * T_END, integration=TIGHT, n_out=11)
    assert first.final_time == pytest.approx(0.5 * T_END, rel=1e-14)
    assert first.final_state[0] == first.h0[-1] and first.final_state[1] == first.dh0_dt[-1]
    rest = pad.descent(W, None, 0.5 * T_END, start=first, integration=TIGHT, n_out=11)
    assert rest.success and rest.t[0] == first.t[-1] and rest.t[-1] == pytest.approx(T_END, rel=1e-12)
    assert np.max(np.abs(rest.h0 / _law(rest.t) - 1)) < 1e-5
    with pytest.raises(ValueError, match=r"h0_start = 2e-05 \[m\] and start both given"):
        pad.descent(W, HS, 0.5 * T_END, start=first)
    with pytest.raises(ValueError, match=r"start: a state of shape \(3,\)"):
        pad.descent(W, None, 0.5 * T_END, start=(0.0, [1e-5, 0.0, 0.0]))


def test_the_full_dae_with_mass_goes_on_from_its_result():
    """The 2-D DAE with mass: the second half from the first's gap and speed lands where one run lands."""
    pad = ThrustPad(L, L, MU, grid=(8, 8))
    ida = Integration(method="ida", rtol=1e-8, atol=1e-10)
    whole = pad.descent(W, HS, T_END, mass=0.05, path="full", integration=ida, n_out=21)
    first = pad.descent(W, HS, 0.5 * T_END, mass=0.05, path="full", integration=ida, n_out=11)
    rest = pad.descent(W, None, 0.5 * T_END, mass=0.05, path="full", integration=ida, n_out=11, start=first)
    assert whole.success and first.success and rest.success
    assert first.final_state[1] < 0  # moving when the second run takes over
    assert rest.h0[-1] == pytest.approx(whole.h0[-1], rel=1e-5)
    assert rest.pressure.shape == (8, 8) and rest.pressure.min() > 0


@pytest.mark.parametrize("path, method", [("separable", "cvode"), ("full", "ida")])
def test_a_checkpointed_descent_resumes_bit_for_bit(tmp_path, path, method):
    pad = ThrustPad(L, L, MU, surface=1e-6, grid=(6, 6))
    kw = dict(path=path, n_out=21, integration=Integration(method=method, rtol=1e-7, atol=1e-9))
    load = 1.5e6 * pad.area
    whole = pad.descent(load, 5e-6, 0.2, long_run=LongRun(checkpoint=tmp_path / "whole.npz"), **kw)
    part = tmp_path / "part.npz"
    cut = pad.descent(load, 5e-6, 0.2, long_run=LongRun(checkpoint=part, stop=lambda r: "cut" if r.t.size > 8
                                                                                        else None), **kw)
    assert cut.message == "cut" and cut.t.size == 9  # the driver's chunks: a tenth of the 20 intervals each
    resumed = pad.descent(load, 5e-6, 0.2, long_run=LongRun(checkpoint=part, resume=True), **kw)
    assert resumed.success and np.array_equal(resumed.t, whole.t)
    for name in ("h0", "dh0_dt", "w_hyd", "w_asp"):
        assert np.array_equal(getattr(resumed, name), getattr(whole, name)), name
    with pytest.raises(CheckpointError, match="load"):
        pad.descent(1.01 * load, 5e-6, 0.2, long_run=LongRun(checkpoint=part, resume=True), **kw)


def test_time_budget_and_refused_settings():
    pad = ThrustPad(L, L, MU, grid=(40, 40))
    r = pad.descent(W, HS, T_END, path="full", integration=Integration(method="cvode"),
                    long_run=LongRun(time_budget=1e-6))
    assert not r.success and "budget" in r.message and r.t.size >= 1
    with pytest.raises(ValueError, match=r"ThrustPad.descent: long_run=LongRun\(chunk_revolutions=2.0\) is not used"):
        pad.descent(W, HS, T_END, long_run=LongRun(chunk_revolutions=2.0))
    with pytest.raises(ValueError, match=r"ThrustPad.descent: integration=Integration\(formulation='content'\)"):
        pad.descent(W, HS, T_END, integration=Integration(method="cvode", formulation="content"))
    with pytest.raises(ValueError, match=r"t_eval must run from 0 to t_end \[s\], increasing"):
        pad.descent(W, HS, 1.0, t_eval=[0.0, 0.7, 0.5, 1.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new spelling warns of nothing
        pad.descent(W, HS, T_END, integration=replace(TIGHT, rtol=1e-6), n_out=3)
