"""The 1x amplitude on the shaft angle and the waterfall of a run-up, on synthetic signals with known answers."""

import numpy as np
import pytest

from transient.analysis.rotor import shaft_angle, synchronous_amplitude, waterfall


def run_up_signal(n0=1000.0, n1=4000.0, duration=2.0, samples=40000, whirl_hz=None):
    t = np.linspace(0.0, duration, samples)
    speed = n0 + (n1 - n0) * t / duration
    phi = shaft_angle(t, speed)
    amp = 1e-6 * (1.0 + speed / n1)  # grows with the speed
    x = amp * np.cos(phi + 0.3) + 5e-6
    if whirl_hz is not None:
        x = x + 2e-6 * np.cos(2 * np.pi * whirl_hz * t)
    return t, speed, x, amp


def test_shaft_angle_integrates_the_speed():
    t = np.linspace(0.0, 1.0, 1001)
    assert shaft_angle(t, np.full(t.size, 600.0))[-1] == pytest.approx(20 * np.pi)


def test_synchronous_amplitude_follows_a_run_up():
    t, speed, x, amp = run_up_signal()
    speeds, a = synchronous_amplitude(t, x, speed, window_revolutions=2.0)
    expected = 1e-6 * (1.0 + speeds / 4000.0)
    assert len(speeds) > 20
    assert np.max(np.abs(a - expected) / expected) < 2e-3


def test_waterfall_finds_the_1x_line_and_a_fixed_whirl():
    t, speed, x, _ = run_up_signal(whirl_hz=30.0)
    speeds, freqs, amp = waterfall(t, x, speed, window_revolutions=8.0)
    df = freqs[1] - freqs[0]
    for k, n in enumerate(speeds):
        top = freqs[np.argsort(amp[k])[-6:]]
        assert np.min(np.abs(top - 30.0)) <= df  # the whirl line, fixed in frequency
        assert np.min(np.abs(top - n / 60.0)) <= 2 * df  # the 1x line, moving with the speed
