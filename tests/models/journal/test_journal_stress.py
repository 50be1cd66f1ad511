"""Stress tests of the journal-bearing model (seed 003): extreme eccentricity, oil whip, bulk modulus
range, the paper grid and finer. All slow (run with ``pytest -m slow``); timings and results are
recorded in docs/validation.md."""

import time

import numpy as np
import pytest

from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient import Integration, LongRun, Recording

pytestmark = pytest.mark.slow

D, L, CL, MU = (RHO_KIM_BEARING[k] for k in ("diameter", "length", "clearance", "viscosity"))
W, MASS, RPM = RHO_KIM_ROTOR["load"], RHO_KIM_ROTOR["rotor_mass"], 6000.0


def paper_bearing(grid=(151, 21), **kw):
    return JournalBearing(D, L, CL, MU, grid=grid, **kw)


@pytest.mark.parametrize("eps", [0.9, 0.95])
def test_equilibrium_at_high_eccentricity(eps):
    """High load / low speed: the load that a journal at ``eps`` carries at 1000 rpm (from the film at
    that position) is handed to :meth:`equilibrium`, which must find that eccentricity again."""
    b = paper_bearing()
    rpm = 1000.0
    att_guess = 20.0
    s = b.steady_state(eps, rpm, att_guess)
    load = s.load
    t0 = time.perf_counter()
    e = b.equilibrium(load, rpm)
    wall = time.perf_counter() - t0
    print(f"eps={eps}: load {load:.1f} N, equilibrium eps {e.eccentricity_ratio:.6f}, attitude "
          f"{e.attitude_angle_deg:.3f} deg, min film {e.min_film * 1e6:.3f} um, p_max {e.max_pressure / 1e6:.1f} MPa, "
          f"{wall:.2f} s")
    # the groove is fixed at the top, so the equilibrium under this load in +x sits at a slightly different
    # position than the one the load was taken from (measured: eps 0.900041 / 0.949989)
    assert abs(e.eccentricity_ratio - eps) < 1e-3
    np.testing.assert_allclose(e.force, (-load, 0.0), atol=1e-9 * load)


def test_oil_whip_above_stability_threshold():
    """1.5x the Lund threshold (75x11 grid, to keep the run near a minute): the linearised system is
    unstable and the whirl grows to a large limit cycle (measured: threshold 8684 rpm; at 13026 rpm eps
    0.29 -> 0.60 by revolution 8 -> 0.778 at 30 revolutions, a nearly circular whirl, no touch at a 1e-2
    gap). The run either continues or stops at a clear touch event -- it never fails silently.
    Cost: the whirl needs ~14000 CVODE steps per revolution at rtol 1e-4 (7 s/rev on 75x11)."""
    b = paper_bearing(grid=(75, 11))
    t0 = time.perf_counter()
    n_th = b.stability_threshold(MASS, W)
    print(f"threshold {n_th:.1f} rpm ({time.perf_counter() - t0:.1f} s)")
    rpm = 1.5 * n_th
    o = JournalOrbit(b, MASS, 0.01 * CL, W, rpm)
    assert b.growth_rate(MASS, W, rpm) > 0
    t0 = time.perf_counter()
    r = o.run(12, integration=Integration(rtol=1e-4, atol=1e-7), recording=Recording(outputs_per_revolution=50),
              long_run=LongRun(chunk_revolutions=2, progress=True), touch_gap=1e-2)
    wall = time.perf_counter() - t0
    eps = r.eccentricity_ratio
    print(f"{rpm:.0f} rpm: {r.message}; eps start {eps[0]:.4f}, max {eps.max():.4f}, "
          f"last-revolution range {eps[-50:].min():.4f}..{eps[-50:].max():.4f}, {wall:.1f} s, "
          f"{r.stats.n_steps} steps")
    if r.touched_at is not None:
        assert "touches the bearing" in r.message and eps[-1] >= 0.99 - 1e-9
    else:
        assert r.message == "reached the final time"
        assert eps[-50:].mean() > eps[0] + 0.2  # the whirl has grown far beyond the unbalance response


@pytest.mark.parametrize("beta", [1e7, 1e8, 1e9, 1e10, 1e12])
def test_bulk_modulus_range(beta):
    """Steady film and one revolution of the paper orbit for beta = 1e7 ... 1e12 (1e12: the
    incompressible limit, where theta - 1 = p / beta ~ 1e-5 and only the universal variable keeps p)."""
    b = paper_bearing(bulk_modulus=beta)
    s = b.steady_state(0.6, RPM, 50.0)
    e = b.equilibrium(W, RPM)
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    t0 = time.perf_counter()
    r = o.run(1, integration=Integration(rtol=1e-4, atol=1e-8))
    wall = time.perf_counter() - t0
    print(f"beta={beta:.0e}: load(eps 0.6) {s.load:.3f} N, equilibrium eps {e.eccentricity_ratio:.5f} "
          f"att {e.attitude_angle_deg:.3f}, 1 rev {wall:.2f} s ({r.stats.n_steps} steps), "
          f"eps after 1 rev {r.eccentricity_ratio[-1]:.5f}")
    assert r.message == "reached the final time"
    ref = paper_bearing(bulk_modulus=1e12).steady_state(0.6, RPM, 50.0)
    # compressibility raises the load by about p_max / beta (measured: +18.6 % at 1e7, where
    # p_max / beta = 0.32; +3.0 %, +0.30 %, +0.030 % at 1e8, 1e9, 1e10)
    rel = s.load / ref.load - 1
    if beta < 1e12:
        assert 0 < rel < 1.2 * s.max_pressure / beta, rel


def test_grid_sequence_151_301_601():
    """The paper grid and two refinements (steady film, eps = 0.6 at 50 deg, 6000 rpm); the 601x81 solve
    must work (timing reported). Measured: 1805.67 / 1805.99 / 1804.11 N, 46.434 / 46.425 / 46.448 deg.
    The changes (<= 0.1 %) are at the level of the groove's snapping to cells (7.2, 6.0, 6.6 deg wide on
    these grids) and of the first-order cavitation fronts, so they need not shrink monotonically; the
    spread is asserted instead (it was 3 % with the cell-upwinded Couette thickness before session 3)."""
    loads, atts = [], []
    for grid in ((151, 21), (301, 41), (601, 81)):
        t0 = time.perf_counter()
        s = paper_bearing(grid=grid).steady_state(0.6, RPM, 50.0)
        wall = time.perf_counter() - t0
        loads.append(s.load)
        atts.append(s.attitude_angle_deg)
        print(f"{grid}: load {s.load:.3f} N, attitude {s.attitude_angle_deg:.4f} deg, "
              f"{s.newton_iterations} iterations, {wall:.1f} s")
    r = 600.0 / 300.0
    p_load = np.log(abs(loads[1] - loads[0]) / abs(loads[2] - loads[1])) / np.log(r)
    p_att = np.log(abs(atts[1] - atts[0]) / abs(atts[2] - atts[1])) / np.log(r)
    print(f"observed order: load {p_load:.2f}, attitude {p_att:.2f}; 601x81 vs 301x41: "
          f"{abs(loads[2] / loads[1] - 1) * 100:.3f} %, {abs(atts[2] - atts[1]):.4f} deg")
    assert max(loads) / min(loads) - 1 < 2e-3, loads
    assert max(atts) - min(atts) < 0.05, atts
