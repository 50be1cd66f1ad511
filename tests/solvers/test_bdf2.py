"""The variable-step BDF2 stepper (solvers/integrate/bdf2.py) on the journal orbit's content formulation: its Newton Jacobian
against finite differences, second-order convergence at fixed steps against a tight IDA reference, the discrete
mass balance of every step, bulk moduli 1e7 and 1e12, dense output between steps, checkpoint/resume, the touch
event. These tests share orbits; the long ones are marked slow."""

import os
from dataclasses import replace

import numpy as np
import pytest

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.content_newton import bdf2_jacobian, bdf2_residual, bdf2_to_state
from transient.models.journal.orbit import BDF2_FILM_TOL, JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.integrate import bdf2, solve
from transient import Integration, LongRun, Recording

CL, W, MASS, RPM = BEARING["clearance"], ROTOR["load"], ROTOR["rotor_mass"], 6000.0
TWO_PI = 2 * np.pi


def orbit(grid=(48, 8), unbalance=0.3, **kw):
    return JournalOrbit(JournalBearing(**dict(BEARING, **kw), grid=grid), MASS, unbalance * CL, W, RPM)


def fixed_step_run(o, steps_per_rev, tau, y0=None, counts=None):
    """The content problem from the equilibrium (or y0, universal layout) by BDF2 with a fixed step (its Newton's
    cost by operation added to ``counts`` if given)."""
    p = o.problem(y0, formulation="content")
    return solve(p, tau, method="bdf2", rtol=1e-3, atol=1e-9,
                 options={"bdf2": o.bdf2_model(), "fixed_step": TWO_PI / steps_per_rev, "newton_counts": counts})


def journal_error(o, s, ref):
    n = o.film.n
    return float(np.max(np.hypot(s.y[:, n] * CL - ref.x, s.y[:, n + 1] * CL - ref.y)) / CL)


def test_newton_jacobian_matches_finite_differences():
    """dF/dz of the content residual in the Newton variables z = [u, X, Y, VX, VY] (chain rule through
    m = H C(u)), with y' = cj y + b as in a BDF2 step, against central differences, at a state with cavitated,
    full-film and switching cells."""
    o = orbit(grid=(16, 4))
    n = o.film.n
    yu = o.initial_state()
    yu[n + 2], yu[n + 3] = 0.3, -0.2
    m = o.bdf2_model()
    args = m.args
    z = yu.copy()
    y = np.empty_like(z)
    cj, rng = 37.0, np.random.default_rng(0)
    b = -cj * o.content_state(yu) + 0.01 * rng.standard_normal(z.size)

    def F(zz):
        bdf2_to_state(zz, y, args)
        out = np.empty_like(zz)
        bdf2_residual(0.3, y, cj * y + b, out, args)
        return out

    bdf2_to_state(z, y, args)
    data = np.zeros(o.film.op.nnz)
    bdf2_jacobian(0.3, y, cj * y + b, cj, data, args)
    J = o.film.op.matrix(data).toarray()
    free = np.concatenate([o.film.op.free, np.ones(4, bool)])
    Jfd = np.zeros_like(J)
    for j in np.flatnonzero(free):
        h = 1e-7 * max(1.0, abs(z[j]))
        zp, zm = z.copy(), z.copy()
        zp[j] += h
        zm[j] -= h
        Jfd[:, j] = (F(zp) - F(zm)) / (2 * h)
    cols = np.flatnonzero(free)
    scale = np.max(np.abs(Jfd[:, cols]), axis=0) + 1e-30
    rel = np.max(np.abs(J[:, cols] - Jfd[:, cols]), axis=0) / scale
    assert np.max(rel) < 1e-5, (np.max(rel), cols[np.argmax(rel)])


def test_every_step_conserves_mass_to_the_newton_tolerance():
    """At fixed steps the outputs at the step points are the steps themselves: the BDF2 conservation law of each
    free cell, A (3 m_(k+2) - 4 m_(k+1) + m_k) / (2 h) + R(m_(k+2)) = 0, holds to the Newton tolerance (its residual
    divided by the cell's A 3 / (2 h) is a content error below BDF2_FILM_TOL), and so does the whole film's
    balance (the sum over the cells: content change + outflow). The Newton's counts: one residual per iteration
    (a refreshed Jacobian solves the residual at hand again), every Jacobian accounted for by its reason, one
    solve per step."""
    o = orbit(grid=(24, 6))
    spr = 400
    h = TWO_PI / spr
    tau = np.arange(0, 41) * h
    c = np.zeros(bdf2.N_COUNTS, dtype=np.int64)
    s = fixed_step_run(o, spr, tau, counts=c)
    assert s.success, s.message
    assert c[bdf2.RESIDUALS] == c[bdf2.ITERATIONS] == s.stats.n_rhs
    assert c[bdf2.J_EVALS] == c[bdf2.J_SWITCH] + c[bdf2.J_RATE] + c[bdf2.J_START] == s.stats.n_jac
    assert c[bdf2.SOLVES] == s.stats.n_steps == 40
    args, n = o.bdf2_model().args, o.film.n
    free, area = o.film.op.free, o.film.area
    worst, flux = 0.0, 0.0
    for k in range(1, 39):
        ym, y0, y1 = s.y[k - 1], s.y[k], s.y[k + 1]
        yp = (3 * y1 - 4 * y0 + ym) / (2 * h)
        out = np.empty(o.n)
        bdf2_residual(tau[k + 1], y1, yp, out, args)
        R = o.film.R
        worst = max(worst, float(np.max(np.abs(out[:n][free]) / (area[free] * 1.5 / h))))
        flux = max(flux, float(np.max(np.abs(R[free]))))
        assert abs(np.sum(out[:n][free])) <= 1e-6 * np.sum(np.abs(R[free]))
    assert worst <= BDF2_FILM_TOL, (worst, flux)


@pytest.fixture(scope="module")
def large_48():
    o = orbit()
    ref = o.run(1, integration=Integration(rtol=1e-8, atol=1e-11), recording=Recording(outputs_per_revolution=20),
                long_run=LongRun(progress=False))
    return o, ref


@pytest.mark.slow
def test_second_order_at_fixed_steps(large_48):
    """48 x 8, 0.3 C, one revolution from the equilibrium: errors at 250 and 500 fixed steps per revolution
    (measured 3.2e-4 and 8.2e-5 C) fall like h^2 (ratio 3.9), and 500 steps are within 1e-4 C."""
    o, ref = large_48
    tau = np.linspace(0, TWO_PI, 21)
    e = [journal_error(o, fixed_step_run(o, spr, tau), ref) for spr in (250, 500)]
    order = np.log2(e[0] / e[1])
    assert 1.7 < order < 2.3, e
    assert e[1] < 1e-4, e


@pytest.mark.slow
def test_dense_output_between_steps(large_48):
    """Outputs half-way between fixed steps (the quadratic interpolant of the last three steps) are as accurate as
    the steps themselves, against a cubic spline through 2000 outputs per revolution of the IDA reference."""
    from scipy.interpolate import CubicSpline

    o, _ = large_48
    spr = 500
    h = TWO_PI / spr
    tau = np.r_[0.0, np.arange(1, 21) / 20 * TWO_PI - 0.5 * h]
    off = fixed_step_run(o, spr, tau)
    assert off.success, off.message
    fine = o.run(1, integration=Integration(rtol=1e-8, atol=1e-11), recording=Recording(outputs_per_revolution=2000),
                 long_run=LongRun(progress=False))
    t = tau / o.film.omega
    xr, yr = CubicSpline(fine.t, fine.x)(t), CubicSpline(fine.t, fine.y)(t)
    n = o.film.n
    err = float(np.max(np.hypot(off.y[:, n] * CL - xr, off.y[:, n + 1] * CL - yr)) / CL)
    assert err < 1.5e-4, err


@pytest.mark.slow
def test_adaptive_run_and_stats(large_48):
    """run(method="bdf2"): the default step cap (500 per revolution) and rtol 1e-4 on the rotor stay within
    2e-4 C of the reference; the statistics are the facade's."""
    o, ref = large_48
    r = o.run(1, integration=Integration(method="bdf2", rtol=1e-4), recording=Recording(outputs_per_revolution=20),
              long_run=LongRun(progress=False))
    assert r.success and r.method == "bdf2"
    e = float(np.max(np.hypot(r.x - ref.x, r.y - ref.y)) / CL)
    assert e < 2e-4, e
    assert 500 <= r.stats.n_steps < 1500 and r.stats.n_jac > 0 and r.stats.n_rhs > r.stats.n_steps


@pytest.mark.slow
@pytest.mark.parametrize("bulk", [1e7, 1e12])
def test_bulk_modulus_extremes(bulk):
    """A soft (1e7 Pa) and a nearly incompressible (1e12 Pa) liquid: the fixed-step orbit over 0.3 revolution
    agrees with IDA (rtol 1e-8) to the accuracy of 500 steps per revolution."""
    o = orbit(grid=(24, 6), bulk_modulus=bulk)
    ref = o.run(0.3, integration=Integration(rtol=1e-8, atol=1e-11), recording=Recording(outputs_per_revolution=20),
                long_run=LongRun(progress=False))
    tau = np.linspace(0, 0.3 * TWO_PI, 7)
    s = fixed_step_run(o, 500, tau)
    assert s.success, s.message
    assert journal_error(o, s, ref) < 2e-4


@pytest.mark.slow
def test_checkpoint_resume_is_bitwise(tmp_path):
    o = orbit(grid=(24, 6), unbalance=0.1)
    kw = dict(integration=Integration(method="bdf2", rtol=1e-4),
              recording=Recording(outputs_per_revolution=20, record=("force", "mass")))
    lr = LongRun(chunk_revolutions=0.25, progress=False)
    full = o.run(0.5, long_run=lr, **kw)
    path = str(tmp_path / "orbit.npz")
    o.run(0.25, long_run=replace(lr, checkpoint=path), **kw)  # "crashes" after the first chunk
    assert os.path.exists(path)
    resumed = orbit(grid=(24, 6), unbalance=0.1).run(0.5, long_run=replace(lr, checkpoint=path, resume=True), **kw)
    for k in ("t", "x", "y", "force", "mass"):
        np.testing.assert_array_equal(getattr(resumed, k), getattr(full, k))


@pytest.mark.slow
def test_touch_event():
    """A journal thrown outwards reaches the touch limit (here a wide gap, e/C = 0.7): the run stops there, the
    event located on the step's interpolant, with the named message."""
    o = orbit(grid=(24, 6), unbalance=0.01)
    y = o.perturbed_start(0.3)
    y[o.film.n + 2] = 10.0
    r = o.run(0.5, integration=Integration(method="bdf2", rtol=1e-5), long_run=LongRun(progress=False), y0=y,
              touch_gap=0.3)
    assert r.touched_at is not None and "journal touches the bearing" in r.message, r.message
    assert np.hypot(r.x[-1], r.y[-1]) / CL == pytest.approx(0.7, abs=1e-9)
    assert r.t[-1] == pytest.approx(r.touched_at, rel=1e-12)


def test_bdf2_needs_the_content_formulation():
    with pytest.raises(ValueError, match="content"):
        orbit(grid=(16, 4)).run(0.1, integration=Integration(method="bdf2", formulation="universal"))


@pytest.mark.slow
def test_layers_and_gecim_bulk():
    """Boundary layers with a Gecim shear-thinning bulk (the kernels evaluate its faces themselves): the fixed-step
    orbit over 0.2 revolution agrees with IDA (rtol 1e-8)."""
    from transient.physics.layered import BoundaryLayers, Gecim

    o = orbit(grid=(24, 6), layers=BoundaryLayers(0.1 * CL, 10 * BEARING["viscosity"], 0.05 * CL),
              rheology=Gecim(kappa=0.65 * BEARING["viscosity"] * RPM * np.pi / 30 * BEARING["diameter"] / 2 / CL,
                             viscosity_ratio=0.57))  # Gecim's kappa* = kappa C / (mu omega R) = 0.65
    ref = o.run(0.2, integration=Integration(rtol=1e-8, atol=1e-11), recording=Recording(outputs_per_revolution=20),
                long_run=LongRun(progress=False))
    s = fixed_step_run(o, 500, np.linspace(0, 0.2 * TWO_PI, 5))
    assert s.success, s.message
    assert journal_error(o, s, ref) < 2e-4


def test_bdf2_without_a_model_is_refused():
    from transient.solvers.integrate import Problem

    p = Problem(y0=np.ones(2), residual=lambda t, y, yp, out: None, name="two states")
    with pytest.raises(ValueError, match="Bdf2Model"):
        solve(p, [0.0, 1.0], method="bdf2")


def test_switch_refresh_weighs_the_iterations_it_saves():
    """A refresh for switched cells: always for many cells or at no cost; else only when the chord iterations it
    saves (``log(size max(0.3, r / (1 - r))) / -log r`` left, one after a refresh) exceed its cost."""
    pays = bdf2._switch_pays
    assert pays(2.0, 0.05, 1, 0.0)  # no cost given: every switch refreshes
    assert pays(2.0, 0.05, bdf2.SWITCH_ALWAYS + 1, 6.0)  # many switched cells: always
    assert not pays(2.0, 0.05, 1, 6.0)  # fast chord: converges in about one iteration
    # r = 0.5, size 1e3: log(1e3) / log(2) = 9.97 iterations left, 8.97 saved
    assert pays(1e3, 0.5, 1, 8.9) and not pays(1e3, 0.5, 1, 9.0)
