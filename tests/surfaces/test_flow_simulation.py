"""Numerical Patir-Cheng flow simulation (transient.surfaces.flow_simulation).

Reference values are closed forms (smooth gap, 1-D ridges, small-roughness perturbation theory) or
the Patir-Cheng fits with a tolerance justified by the measured realisation spread; none are
outputs of the code under test.
"""

import math

import numpy as np
import pytest

from transient.physics.flow_factors import pressure_flow_factors
from transient.surfaces.flow_simulation import (FlowFactorResult, patch_flow_factor, peklenik_lengths,
                                            pressure_flow_factor_numerical, ridge_heights)
from transient.surfaces.roughness import RoughSurface

UM = 1e-6


def _gauss_params(gamma, l0=12, n_lengths=8, acf="exponential"):
    lx, ly = peklenik_lengths(gamma, l0 * UM)
    shape = (int(round(n_lengths * ly / UM)), int(round(n_lengths * lx / UM)))
    return dict(shape=shape, spacing=UM, rq=UM, correlation_lengths=(lx, ly), acf=acf)


# ---------------------------------------------------------------------------------------------
# exact cases
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("direction", ["x", "y"])
def test_smooth_gap_gives_one(direction):
    z = np.zeros((17, 23))
    phi, cf, mism = patch_flow_factor(z, (2 * UM, 3 * UM), [0.5, 1.0, 3.0, 10.0], direction, sigma=UM)
    assert np.max(np.abs(phi - 1.0)) < 1e-11
    assert np.all(cf == 0) and np.max(mism) < 1e-11


def _transverse_exact(h, a):
    # <(h + a sin t)^-3> = (2h^2 + a^2) / (2 (h^2 - a^2)^(5/2)); flows in series: phi = 1/(h^3 <h_T^-3>)
    return 2 * (h * h - a * a) ** 2.5 / (h ** 3 * (2 * h * h + a * a))


def _longitudinal_exact(h, a):
    # <(h + a sin t)^3> = h^3 + 3 h a^2 / 2; flows in parallel: phi = <h_T^3>/h^3
    return 1.0 + 1.5 * a * a / (h * h)


def test_transverse_ridges_series_flow_second_order():
    a = 0.6 * UM
    sigma = a / math.sqrt(2)  # RMS of the sinusoid
    H = np.array([1.5, 2.0, 3.0])  # h/a = 1.06 .. 2.1 -> h_T^3 varies up to 40000-fold at H = 1.5
    h = H * sigma
    exact = _transverse_exact(h, a)
    err = []
    for nx in (100, 200, 400):
        z = ridge_heights((6, nx), a, 2, along="y")  # heights vary along x only
        phi, cf, mism = patch_flow_factor(z, UM, H, "x")
        assert np.all(cf == 0) and np.max(mism) < 1e-8  # conductance contrast up to 4e4
        err.append(np.abs(phi / exact - 1))
    err = np.array(err)
    assert np.all(err[-1] < [1e-2, 1.5e-3, 5e-4])  # measured 7.5e-3, 1.0e-3, 3.0e-4 at nx = 400
    ratio = err[:-1] / err[1:]
    assert np.all((ratio > 3.8) & (ratio < 4.2))  # second order in dx (measured 3.98 - 4.07)


def test_longitudinal_ridges_parallel_flow_exact():
    a = 0.8 * UM
    H = np.array([1.5, 2.0, 5.0])  # h > a: no contact
    h = H * a / math.sqrt(2)
    z = ridge_heights((64, 10), a, 3, along="x")  # heights vary along y only
    phi = patch_flow_factor(z, UM, H, "x")[0]
    # midpoint rule is exact for this trigonometric polynomial: solver precision
    assert np.max(np.abs(phi / _longitudinal_exact(h, a) - 1)) < 1e-11
    # the same kind of surface seen with flow along y is transverse (400 cells over 2 periods)
    phiy = patch_flow_factor(ridge_heights((400, 6), a, 2, along="x"), UM, H, "y")[0]
    assert phiy == pytest.approx(_transverse_exact(h, a), rel=1e-2)


def test_direction_y_is_rotated_surface():
    s = RoughSurface.generate((40, 48), UM, UM, correlation_lengths=(6 * UM, 4 * UM), seed=3)
    a = patch_flow_factor(s.heights, (UM, 2 * UM), [1.5, 3.0], "y")[0]
    b = patch_flow_factor(s.heights.T, (2 * UM, UM), [1.5, 3.0], "x")[0]
    assert np.allclose(a, b, rtol=1e-12)


# ---------------------------------------------------------------------------------------------
# random surfaces
# ---------------------------------------------------------------------------------------------
def test_isotropic_small_roughness_perturbation_limit():
    """H >> 1, isotropic Gaussian: second-order theory gives phi_x = 1 - 1.5/H^2 (k_eff = <k>(1 - var/2d),
    d = 2; equal to the geometric-mean (Matheron) value to this order).  The arithmetic face mean of the
    operator biases the deficit low (see docs); with refine=2 at 12 samples per correlation length the
    measured deficit * H^2 is 1.46 +- 0.27 (mean +- s.e.m., 4 patches, this seed; refine=1 gives 1.04)."""
    H = np.array([20.0])
    res = pressure_flow_factor_numerical(_gauss_params(1.0, l0=12, n_lengths=6), H, n_realisations=4, seed=7,
                                         refine=2)
    d = (1 - res.phi_mean[0]) * H[0] ** 2
    assert 1.2 < d < 1.8
    assert np.all(res.phi[:, 0] < 1)


def test_result_unpacks_and_reports():
    res = pressure_flow_factor_numerical(_gauss_params(1.0, l0=6, n_lengths=7), [2.0, 4.0], n_realisations=3,
                                         seed=1)
    assert isinstance(res, FlowFactorResult)
    H, m, s = res
    assert np.array_equal(H, [2.0, 4.0]) and m.shape == s.shape == (2,) and res.phi.shape == (3, 2)
    assert np.all(s > 0) and np.all(np.diff(m) > 0)  # phi_x rises towards 1 for gamma = 1
    assert res.meta["max_flux_mismatch"] < 1e-9
    # same seed -> same surfaces -> same numbers; given surfaces reproduce the generated run
    seeds = np.random.SeedSequence(1).spawn(3)
    surf = [RoughSurface.generate(seed=q, **_gauss_params(1.0, l0=6, n_lengths=7)) for q in seeds]
    again = pressure_flow_factor_numerical(surf, [2.0, 4.0])
    assert np.allclose(again.phi, res.phi, rtol=1e-12)


def test_isotropic_against_patir_cheng_fit():
    """gamma = 1 at H = 2, 3, 6 (12 samples per correlation length, 7 lengths per side, refine 2,
    4 patches) against 1 - 0.90 exp(-0.56 H): within 8 % (measured patch std 0.02-0.08, see docs)."""
    H = np.array([2.0, 3.0, 6.0])
    res = pressure_flow_factor_numerical(_gauss_params(1.0, l0=12, n_lengths=7), H, n_realisations=4, seed=11,
                                         refine=2)
    fit = pressure_flow_factors(H, 1.0)[0]
    assert np.all(np.abs(res.phi_mean / fit - 1) < 0.08)
    assert np.all(res.phi_mean < 1) and np.all(np.diff(res.phi_mean) > 0)


@pytest.mark.slow
@pytest.mark.parametrize("gamma", [1 / 6, 1.0, 6.0])
def test_patir_cheng_fit_scenario_settings(gamma):
    """The settings of scenarios/flow_factors.py (16 samples per correlation length, 8 lengths per side,
    refine 2, 8 patches; ~15 s each): every tabulated fit within 1.5 patch std of the numerical mean at
    H = 1, 2, 3, 6 (measured |diff|/std <= 0.9, table in docs/validation_flow_factors.md)."""
    H = np.array([1.0, 2.0, 3.0, 6.0])
    res = pressure_flow_factor_numerical(_gauss_params(gamma, l0=16, n_lengths=8), H, n_realisations=8, seed=2024,
                                         refine=2)
    fit = pressure_flow_factors(H, gamma)[0]
    assert np.all(np.abs(res.phi_mean - fit) < 1.5 * res.phi_std)


def test_longitudinal_and_transverse_trends():
    H = np.array([1.5, 3.0])
    lon = pressure_flow_factor_numerical(_gauss_params(6.0, l0=10, n_lengths=7), H, n_realisations=3, seed=2)
    tra = pressure_flow_factor_numerical(_gauss_params(1 / 6, l0=10, n_lengths=7), H, n_realisations=3, seed=2)
    assert np.all(lon.phi > 1.0) and np.all(tra.phi < 1.0)
    assert np.all(np.diff(lon.phi_mean) < 0) and np.all(np.diff(tra.phi_mean) > 0)  # both -> 1
    assert abs(np.mean(lon.gamma) - 6) < 1.0 and abs(np.mean(tra.gamma) - 1 / 6) < 0.03
    # phi_y of the longitudinal surface is a transverse flow
    y = pressure_flow_factor_numerical(_gauss_params(6.0, l0=10, n_lengths=7), H, "y", n_realisations=3, seed=2)
    assert np.all(y.phi < 1.0)


# ---------------------------------------------------------------------------------------------
# validation
# ---------------------------------------------------------------------------------------------
def test_validation_messages():
    z = np.zeros((5, 5))
    with pytest.raises(ValueError, match=r"H = h/sigma = -1.0 \[-\]"):
        patch_flow_factor(z + np.arange(5), UM, [-1.0])
    with pytest.raises(ValueError, match="zero RMS"):
        patch_flow_factor(z, UM, [1.0])
    with pytest.raises(ValueError, match="direction"):
        patch_flow_factor(z + np.arange(5), UM, [1.0], "z")
    with pytest.raises(ValueError, match=r"spacing dx = 0"):
        patch_flow_factor(z + np.arange(5), 0.0, [1.0])
    with pytest.raises(ValueError, match="refine"):
        patch_flow_factor(z + np.arange(5), UM, [1.0], refine=0)
    with pytest.raises(ValueError, match="contact_floor"):
        patch_flow_factor(z + np.arange(5), UM, [1.0], contact_floor=0.0)
    with pytest.raises(ValueError, match="2-D"):
        patch_flow_factor(np.zeros(5), UM, [1.0])
    with pytest.raises(ValueError, match="n_realisations"):
        pressure_flow_factor_numerical(_gauss_params(1.0, l0=4), [1.0], n_realisations=0)
    with pytest.raises(ValueError, match="seed"):
        pressure_flow_factor_numerical(dict(_gauss_params(1.0, l0=4), seed=1), [1.0])
    with pytest.raises(TypeError):
        pressure_flow_factor_numerical(3.0, [1.0])


def test_contact_wall_and_refine():
    """A contact wall one sample thick across the flow.  With the operator's arithmetic face mean the
    wall cell conducts k/2 through each face, so at refine=1 it leaks (documented artefact); refine=2
    makes the wall two cells thick, the faces inside it carry only the floor conductance and the flow
    drops to ~ the floor (1e-9 of the smooth gap per unit length)."""
    z = np.zeros((8, 20))
    z[:, 10] = -5.0
    phi1, cf1, _ = patch_flow_factor(z, UM, [1.0], sigma=1.0)
    assert cf1[0] == pytest.approx(8 / 160)
    assert phi1[0] > 1.0  # leak: the open gap is 1.25 after mean removal, the wall does not block
    phi2, cf2, _ = patch_flow_factor(z, UM, [1.0], sigma=1.0, refine=2)
    assert cf2[0] == pytest.approx(0.1) and phi2[0] < 1e-6
