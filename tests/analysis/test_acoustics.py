"""Bearing-noise analysis (seed 003 sections 2.3-2.4): exact statistics of synthetic periodic signals,
IEC 61672-1 A-weighting, energy averaging, transmission forms, periodicity detection and a small
end-to-end bearing_noise run."""

import numpy as np
import pytest

from transient import Recording, bearing_noise
from transient.analysis import (NotPeriodicError, a_weighting, energy_average, find_settled,
                                film_transitions, harmonic_amplitudes, mean_and_fluctuation, require_periodic,
                                transmission_coefficient)
from transient.analysis.acoustics import analyse_pressure, spl
from transient.analysis.spectra import amplitude_spectrum

# known signal: mean 3, harmonics 1x (peak 2), 2x (0.5), 5x (0.1) with phases
AMPS = {1: 2.0, 2: 0.5, 5: 0.1}
PHASES = {1: 0.3, 2: -1.1, 5: 2.0}


def synthetic(n_periods, spp, period=1.0, shape=()):
    t = np.arange(n_periods * spp) * period / spp
    s = 3.0 + sum(a * np.cos(2 * np.pi * k * t / period + PHASES[k]) for k, a in AMPS.items())
    return t, s.reshape(-1, *([1] * len(shape))) * np.ones(shape)


def test_mean_rms_harmonics_exact():
    _, s = synthetic(4, 16)
    m, f = mean_and_fluctuation(s)
    assert abs(m - 3.0) < 1e-12
    assert abs(f - np.sqrt(sum(a * a / 2 for a in AMPS.values()))) < 1e-12
    h = harmonic_amplitudes(s, 4, 6)
    expect = np.array([AMPS.get(k, 0.0) for k in range(1, 7)])
    assert np.max(np.abs(h - expect)) < 1e-12
    hr = harmonic_amplitudes(s, 4, 6, kind="rms")
    assert abs(np.sum(hr ** 2) - f ** 2) < 1e-12  # Parseval


@pytest.mark.parametrize("n_periods,spp", [(1, 12), (3, 12), (7, 40), (2, 129)])
def test_independent_of_periods_and_sampling_rate(n_periods, spp):
    _, s = synthetic(n_periods, spp)
    m, f = mean_and_fluctuation(s)
    h = harmonic_amplitudes(s, n_periods, 5)
    assert abs(m - 3.0) < 1e-12 and abs(f - np.sqrt(2.0 + 0.125 + 0.005)) < 1e-12
    assert np.allclose(h, [2.0, 0.5, 0.0, 0.0, 0.1], atol=1e-12, rtol=0)


def test_harmonic_needs_sampling_rate():
    _, s = synthetic(2, 10)
    with pytest.raises(ValueError, match="samples per period"):
        harmonic_amplitudes(s, 2, 5)


def test_amplitude_spectrum_peaks():
    t, s = synthetic(4, 32, period=0.01)
    f, a = amplitude_spectrum(s, t[1] - t[0])
    for k, amp in AMPS.items():
        assert abs(a[np.argmin(np.abs(f - 100.0 * k))] - amp) < 1e-12
    assert abs(a[0] - 3.0) < 1e-12


# IEC 61672-1 table (nominal frequency: dB); the standard computes the tabulated values at the exact
# base-ten mid-band frequencies f_m = 1000 * 10^(n/10) (31.5 Hz nominal = 31.62 Hz exact)
IEC = {31.5: -39.4, 63: -26.2, 125: -16.1, 250: -8.6, 500: -3.2, 1000: 0.0, 2000: 1.2, 4000: 1.0, 8000: -1.1}


def test_a_weighting_iec_table():
    f = 1000.0 * 10.0 ** (np.round(10 * np.log10(np.array(list(IEC)) / 1000.0)) / 10)
    assert np.max(np.abs(a_weighting(f) - np.array(list(IEC.values())))) < 0.1
    assert abs(a_weighting(1000.0)) < 1e-12


def test_energy_average():
    assert abs(energy_average(np.full((5, 7), 73.2)) - 73.2) < 1e-12
    assert abs(energy_average([70.0, -np.inf]) - (70.0 - 10 * np.log10(2))) < 1e-12
    assert abs(energy_average([60.0, 70.0]) - 10 * np.log10((1e6 + 1e7) / 2)) < 1e-12


def test_transmission_forms():
    rs, ra, ro = 7700 * 5050, 1.18 * 344, 870 * 1400
    printed = transmission_coefficient("printed")
    assert abs(printed - 2 / (1 + rs / ra)) < 1e-18
    two = transmission_coefficient("two_interface")
    assert abs(two - 2 / (1 + ro / rs) * 2 / (1 + rs / ra)) < 1e-18
    assert 5.7 < 20 * np.log10(two / printed) < 5.8
    with pytest.raises(ValueError):
        transmission_coefficient("bogus")


def test_analyse_pressure_levels():
    # every node the synthetic signal scaled: N_b = the level of the node
    t, s = synthetic(3, 24, period=0.01, shape=(2, 3))
    n = analyse_pressure(s * 1e4, s[:, 0, 0], s[:, 0, 0], t, 6000.0, 3, 5)
    T = transmission_coefficient("printed")
    pf = 1e4 * np.sqrt(2.0 + 0.125 + 0.005)
    assert abs(n.level_db - 20 * np.log10(T * pf / 20e-6)) < 1e-9
    assert abs(n.level_db_harmonics - n.level_db) < 1e-9  # all content in harmonics 1..5
    assert abs(n.harmonic_levels_db[0] - 20 * np.log10(T * 2e4 / np.sqrt(2) / 20e-6)) < 1e-9
    A = a_weighting(100.0 * np.array([1, 2, 5]))
    ms = sum((1e4 * a) ** 2 / 2 * 10 ** (0.1 * w) for a, w in zip(AMPS.values(), A))
    assert abs(n.level_dba - spl(T * np.sqrt(ms))) < 1e-9


def decaying(n, freq2=None):
    k = np.arange(n)
    if freq2 is None:  # decaying transient onto a periodic orbit: Poincare points converge
        return np.column_stack([0.3 + 0.05 * 0.6 ** k * np.cos(2.0 * k), 0.2 + 0.05 * 0.6 ** k * np.sin(2.0 * k)])
    # quasi-periodic: a second, incommensurate frequency keeps the Poincare points moving on a circle
    return np.column_stack([0.3 + 0.02 * np.cos(2 * np.pi * freq2 * k), 0.2 + 0.02 * np.sin(2 * np.pi * freq2 * k)])


def test_periodicity_detector():
    z = decaying(40)
    k = find_settled(z, 1e-4)
    steps = np.linalg.norm(np.diff(z, axis=0), axis=1)
    assert k is not None and steps[k - 1] < 1e-4 and steps[k - 2] < 1e-4 and steps[k - 3] >= 1e-4
    assert require_periodic(z, 1e-4) == k
    with pytest.raises(NotPeriodicError, match="still decaying"):
        require_periodic(z[:8], 1e-4)
    q = decaying(60, freq2=(np.sqrt(5) - 1) / 2)
    assert find_settled(q, 1e-4) is None
    with pytest.raises(NotPeriodicError, match="not periodic.*not decaying"):
        require_periodic(q, 1e-4, what="the quasi-periodic signal")


@pytest.fixture(scope="module")
def small_noise():
    from transient.models.journal.bearing import JournalBearing
    from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
    from transient.models.journal.orbit import JournalOrbit

    o = JournalOrbit(JournalBearing(**RHO_KIM_BEARING, grid=(24, 4)), **RHO_KIM_ROTOR, speed_rpm=6000)
    return o, bearing_noise(o, revolutions=2, harmonics=3)


def test_bearing_noise_end_to_end(small_noise):
    o, n = small_noise
    assert n.settled_at is not None and n.settle_revolutions <= 20
    assert n.window_closure < 1e-3
    assert n.pressure.shape == (2 * n.samples_per_revolution, 4, 24)  # only the window is recorded
    f, a = n.x_spectrum
    ac = a.copy()
    ac[0] = 0
    assert abs(f[np.argmax(ac)] - 100.0) < 1e-9  # 1x (6000 rpm = 100 Hz) dominates
    assert ac[2] > 10 * max(ac[4], ac[6])
    assert n.harmonic_levels_db[0] > n.harmonic_levels_db[1] > n.harmonic_levels_db[2]
    assert np.isfinite(n.level_db) and n.level_dba < n.level_db  # A(100 Hz) = -19 dB
    assert np.all(n.p_fluct >= 0) and n.p_fluct.shape == (4, 24)
    assert np.all(n.spl[:, 0] == -np.inf)  # groove node: no fluctuation
    tr = film_transitions(o.equilibrium())
    assert tr and tr["cavities"]
    assert 60 < tr["reformation_deg"] < 130 and 200 < tr["rupture_deg"] < 260  # paper: 96 and 240 deg


def test_no_field_when_not_asked():
    from transient.models.journal.bearing import JournalBearing
    from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
    from transient.models.journal.orbit import JournalOrbit

    o = JournalOrbit(JournalBearing(**RHO_KIM_BEARING, grid=(16, 2)), **RHO_KIM_ROTOR, speed_rpm=6000)
    r = o.run(1, recording=Recording(outputs_per_revolution=4))
    assert "pressure" not in r.fields and r.final_state is not None


def test_noise_scenario_tiny(tmp_path, scenario_loader):
    import json


    scenario_loader("journal_noise").main(["--grid", "24", "4", "--speeds", "4000", "6000", "--revolutions", "2", "--out", str(tmp_path)])
    for name in ("fig5_fig6_pfluct.png", "fig4_fig7_spectra.png", "fig9_to_fig12_levels.png", "journal_noise.json"):
        assert (tmp_path / name).stat().st_size > 1000, name
    d = json.loads((tmp_path / "journal_noise.json").read_text())
    a, b = d["points"]
    assert a["level_db"] < b["level_db"] and b["x_1x_over_2x"] > 10
    assert set(d["timings"]) >= {"integration", "recording", "analysis", "total"}
