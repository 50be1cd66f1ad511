"""Verification of the journal-bearing model (seed 003): Jacobians, closed-form and published limits,
convergence in grid / switch width / time step, conservation, validation and restart.

Conventions (see ``transient.models.journal.kernels``): ``phi`` from the top (groove) in the direction of
rotation, load in +x (towards phi = pi), ``H = 1 + X cos(phi) + Y sin(phi)``, film force on the journal
``F = +int p (cos phi, sin phi) dA``. A journal displaced by ``eps`` along +x puts the maximum film at
phi = 0 and the minimum film at phi = pi, so the closed forms of :mod:`transient.verification.reference`
(theta from the maximum film, ``F_ref = -int p (cos theta, sin theta) dA``) apply with ``theta = phi``
and ``F_model = -F_ref`` component by component.

All numbers quoted in the docstrings were measured on the grids used here (docs/validation.md).
"""

import os
from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse as sp

from transient.verification.reference import short_bearing_force
from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import Groove, JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit
from transient.physics.layered import BoundaryLayers, Gecim
from transient import Integration, LongRun, Recording

D, L, CL, MU = (RHO_KIM_BEARING[k] for k in ("diameter", "length", "clearance", "viscosity"))
W, MASS, RPM = RHO_KIM_ROTOR["load"], RHO_KIM_ROTOR["rotor_mass"], 6000.0


def paper_bearing(grid=(48, 8), **kw):
    return JournalBearing(D, L, CL, MU, grid=grid, **kw)


# --------------------------------------------------------------------------------------------------
# analytic Jacobians vs central finite differences
# --------------------------------------------------------------------------------------------------

def _compare(J_an, J_fd, mask):
    """Relative difference (max entry / max |J| per column, worst column) and the largest FD entry
    outside the sparsity pattern."""
    scale = np.maximum(np.abs(J_an).max(axis=0), 1e-300)
    rel = float((np.abs(J_fd - J_an).max(axis=0) / scale).max())
    outside = float(np.abs(J_fd[~mask]).max()) if (~mask).any() else 0.0
    return rel, outside


#: boundary layers of seed 004 (Newtonian bulk) for the Jacobian checks: thick, mobile, unequal
LAYERS = BoundaryLayers(thickness=0.1 * CL, viscosity=(10 * MU, 20 * MU), alpha=0.05 * CL)


#: seed 004's shear-thinning bulk at the paper's kappa* = kappa C / (mu omega R) = 0.65, mu_2/mu_1 = 0.57
GECIM = Gecim(kappa=0.65 * MU * omega(RPM) * 0.5 * D / CL, viscosity_ratio=0.57)
#: the film variants of the Jacobian checks: (layers, rheology)
FILMS = {"classical": (None, None), "layers": (LAYERS, None), "gecim": (LAYERS, GECIM)}
#: (switch width [Pa], film) of the Jacobian checks. The Gecim bulk runs with the wide switch only: its face flux
#: has rounding-level jumps where the quadrature panels change (~1e-15 of R), which the ODE right-hand side
#: divides by D = 1/beta_bar; with the narrow switch's finite-difference step (5e-4 w = 2e-8) they reach 3e-6 of
#: the column scale, which is FD noise (it grows as 1/step), not a Jacobian error. The narrow switch's own
#: derivatives are the Newtonian films' (same switch code).
CASES = [(1e5, f) for f in FILMS] + [(1e3, "classical"), (1e3, "layers")]


def _orbit_state(switch_width, film="classical"):
    """A small orbit problem at a state with cavitated, full-film and switch-band cells, the journal
    off equilibrium and moving."""
    layers, rheology = FILMS[film]
    b = paper_bearing(grid=(16, 4), switch_width=switch_width, layers=layers, rheology=rheology)
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    prob = o.problem()
    nf = o.film.n
    y = prob.y0.copy()
    rng = np.random.default_rng(1)
    y[:nf] += 1e-3 * rng.standard_normal(nf) * o.film.op.free
    y[nf:] = [0.5, 0.3, 0.05, -0.04]
    return o, prob, y


TAU = 0.3  # the time at which the Jacobians are checked


def _rhs_jacobians(fd_jacobian, prob, y, step):
    """The analytic ``df/dy`` of an ODE problem at ``y`` (dense) and its central differences."""
    n = y.size
    pat = prob.jac_pattern.tocsc()
    data = np.empty(pat.nnz)
    prob.jac_rhs(TAU, y, data)

    def f(v):
        out = np.empty(n)
        prob.rhs(TAU, v, out)
        return out

    return sp.csc_matrix((data, pat.indices, pat.indptr), shape=(n, n)).toarray(), fd_jacobian(f, y, n, step=step)


def _residual_jacobians(fd_jacobian, prob, y, yp, cj, step):
    """The analytic ``dF/dy + cj dF/dy'`` of an IDA problem at ``(y, y')`` (dense) and its central differences."""
    n = y.size
    pat = prob.jac_pattern.tocsc()
    data = np.empty(pat.nnz)
    prob.jac_residual(TAU, y, yp, cj, data)

    def F(v, vp):
        out = np.empty(n)
        prob.residual(TAU, v, vp, out)
        return out

    J_fd = fd_jacobian(lambda v: F(v, yp), y, n, step=step) + cj * fd_jacobian(lambda v: F(y, v), yp, n,
                                                                                          step=step)
    return sp.csc_matrix((data, pat.indices, pat.indptr), shape=(n, n)).toarray(), J_fd


def _inconsistent_yp(prob, y):
    """``y'`` off the solution on purpose (1.3 times the rhs): the residual Jacobian must hold anywhere."""
    yp = np.empty(y.size)
    prob.rhs(TAU, y, yp)
    return 1.3 * yp


@pytest.mark.parametrize("switch_width, film", CASES)
def test_ode_jacobian_matches_finite_differences(switch_width, film, fd_jacobian):
    o, prob, y = _orbit_state(switch_width, film)
    J_an, J_fd = _rhs_jacobians(fd_jacobian, prob, y, 5e-4 * o.film.width)
    rel, outside = _compare(J_an, J_fd, prob.jac_pattern.toarray() != 0)
    assert rel < 1e-6, rel
    assert outside == 0.0
    # the rotor columns / rows are really there (not trivially zero)
    nf = o.film.n
    assert np.abs(J_an[:nf, nf:]).max() > 0 and np.abs(J_an[nf + 2:, :nf]).max() > 0


@pytest.mark.parametrize("switch_width, film", CASES)
def test_dae_jacobian_matches_finite_differences(switch_width, film, fd_jacobian):
    o, prob, y = _orbit_state(switch_width, film)
    J_an, J_fd = _residual_jacobians(fd_jacobian, prob, y, _inconsistent_yp(prob, y), 7.5, 5e-4 * o.film.width)
    mask = (prob.jac_pattern.toarray() != 0) | np.eye(o.n, dtype=bool)  # IDA's pattern always has the diagonal
    rel, outside = _compare(J_an, J_fd, mask)
    assert rel < 1e-6, rel
    assert outside == 0.0


@pytest.mark.parametrize("switch_width, film", CASES)
def test_content_jacobians_match_finite_differences(switch_width, film, fd_jacobian):
    """The content formulation (state m = H theta): the IDA residual Jacobian dF/dy + cj dF/dy' and the ODE
    Jacobian, with the chain rule through u = C^-1(m / H) (du/dm and du/dX at fixed m) in the film rows and
    in the rotor rows (the force depends on X through u at fixed content)."""
    o, _, y_u = _orbit_state(switch_width, film)
    prob = o.problem(y_u, formulation="content")
    y = prob.y0.copy()
    np.testing.assert_allclose(o.universal_state(y), y_u, rtol=1e-9, atol=1e-12)  # the layouts map back
    mask = (prob.jac_pattern.toarray() != 0) | np.eye(o.n, dtype=bool)
    h = 5e-5 * o.film.width  # the content bends on the scale w_theta + w / beta_bar: a finer step than in u
    J_an, J_fd = _residual_jacobians(fd_jacobian, prob, y, _inconsistent_yp(prob, y), 7.5, h)
    rel, outside = _compare(J_an, J_fd, mask)
    assert rel < 1e-6, rel
    assert outside == 0.0
    nf = o.film.n
    assert np.abs(J_an[nf + 2:, nf:nf + 2]).max() > 0  # dF_V/dX through u(m, X): really there
    rel, outside = _compare(*_rhs_jacobians(fd_jacobian, prob, y, h), mask)
    assert rel < 1e-6, rel
    assert outside == 0.0


def test_content_inverse_and_conservation():
    """u = C^-1(theta) inverts the switch to rounding error on both sides, in the switch band and for
    beta = 1e7 (convex C) and 1e12 (concave); the content residual is the conservation law: the film rows of
    F sum (times sym) to d/dt of the film content plus the net outflow (Film.mass_flows)."""
    from transient.physics.cavitation import elrod_content, elrod_inverse, softplus_pressure

    for beta_bar, w, r in ((0.37, 2e-3, 0.25), (37.0, 2e-3, 0.25), (3.7e4, 2e-3, 0.25), (37.0, 1e-4, 100.0)):
        u = np.concatenate([np.linspace(-1.0 / r, 0.3, 200), np.linspace(-20 * w, 20 * w, 200)])
        P, dP, C, D, dD = (np.empty_like(u) for _ in range(5))
        softplus_pressure(u, w, P, dP)
        elrod_content(u, P, dP, w, r, beta_bar, C, D, dD)
        back = np.empty_like(u)
        elrod_inverse(C, w, r, beta_bar, back)
        # |du| <= a few ulps of theta divided by the slope D
        assert np.all(np.abs(back - u) <= 1e-13 * np.maximum(1.0, np.abs(u)) + 8e-16 / D), (beta_bar, w, r)
    o, _, y_u = _orbit_state(1e4)
    prob = o.problem(y_u, formulation="content")
    nf, f = o.film.n, o.film
    y = prob.y0.copy()
    yp = np.zeros(o.n)
    out = np.empty(o.n)
    prob.residual(0.3, y, yp, out)  # m' = 0: the film rows are the net outflows R_i
    M, q_ends, q_groove = f.mass_flows(o.universal_state(y)[:nf], y[nf], y[nf + 1])
    assert M == pytest.approx(f.sym * np.sum((f.area * y[:nf])[f.op.free]), rel=1e-12)
    assert f.sym * np.sum(out[:nf][f.op.free]) == pytest.approx(q_ends + q_groove, rel=1e-9)


@pytest.mark.parametrize("rate", [0.0, 3.0])
def test_film_jacobian_matches_finite_differences(rate, fd_jacobian):
    """dG/du, and at rate = 0 the rotor columns dG/dX, dG/dY, dG/dVX, dG/dVY (the columns the
    equilibrium Newton and the K/C sensitivities use)."""
    b = paper_bearing(grid=(16, 4), switch_width=1e4)
    f = b.film(RPM)
    n = f.n
    X, Y, VX, VY = 0.45, 0.35, 0.02, -0.03
    u = f.solve(X, Y)[0] + 1e-3 * np.random.default_rng(2).standard_normal(n) * f.op.free
    C_ref = np.full(n, 0.9)
    data = f.jacobian_data(u, X, Y, VX, VY, rate=rate)
    M = f.op.matrix(data).toarray()
    pat = f.op.pattern.toarray() != 0

    def G(v):
        return f.residual(v, X, Y, VX, VY, rate=rate, C_ref=C_ref).copy()

    J_fd = fd_jacobian(G, u, n, step=5e-4 * f.width)
    rel, outside = _compare(M[:n, :n], J_fd, pat[:n, :n])
    assert rel < 1e-6, rel
    assert outside == 0.0
    if rate == 0.0:
        q = np.array([X, Y, VX, VY])

        def Gq(v):
            return f.residual(u, *v, rate=rate, C_ref=C_ref).copy()

        Jq = fd_jacobian(Gq, q, n)
        rel_q, _ = _compare(M[:n, n:n + 4], Jq, pat[:n, n:n + 4])
        assert rel_q < 1e-6, rel_q


# --------------------------------------------------------------------------------------------------
# closed-form limit: short (Ocvirk) bearing, half-Sommerfeld film
# --------------------------------------------------------------------------------------------------

def _short_bearing_error(LD, eps, rpm=RPM):
    """Elrod film force vs the short-bearing half (pi) film, grid-extrapolated.

    Physical set-up: a groove of negligible width (one cell) at the maximum film, supply = ambient =
    cavitation pressure = 0, so the film enters the converging half full at zero gauge pressure and
    ruptures where the pressure would go negative -- the pi film's assumptions. Without a groove the
    comparison would NOT be apt: with p_ambient = p_cav nothing drives oil in through the ends, the
    mass-conserving film starves and carries 50-98 % less than the flooded pi film (measured).

    The switch's pressure width is scaled with the mean film pressure (1e-4) and its content width is
    1e-4, so the smoothing is equally small at every L/D. 480 cells around (120 -> 240 -> 480 changes the
    force by <= 0.09 % and <= 0.03 %), and two axial grids (Richardson, p = 2) remove the axial
    discretisation error, which is otherwise ~0.4 % at 12 cells and would hide the model difference at
    small L/D.
    """
    Lb = LD * D
    U = omega(rpm) * 0.5 * D
    ref = np.array(short_bearing_force(eps, MU, U, CL, Lb, film="half"))
    p_mean = abs(ref[1]) / (Lb * D / 2)
    F = {}
    for nz in (6, 12):
        b = JournalBearing(D, Lb, CL, MU, supply_pressure=0.0, groove=Groove(0.0, 0.1), grid=(480, nz),
                           switch_width=1e-4 * p_mean, switch_content_width=1e-4)
        F[nz] = -np.array(b.steady_state(eps, rpm).force)  # F_model = -F_ref
    F_ext = (4 * F[12] - F[6]) / 3
    return F_ext / ref - 1.0, F[12] / ref - 1.0


def test_short_bearing_limit_half_sommerfeld():
    """Measured (eps = 0.6; relative errors of the radial / tangential force, axially extrapolated):
    L/D = 0.2: -5.09 % / -4.28 %;  0.1: -1.36 % / -1.16 %;  0.05: -0.35 % / -0.29 %  -- they fall like
    (L/D)^2, the order of the circumferential Poiseuille flow the short-bearing theory drops.
    The mass-conserving film differs from the pi film only through that term here: the rupture of the
    short-bearing film is at the minimum film where both put it, and the groove refills the film at
    the maximum film as the pi film assumes."""
    errs = {LD: _short_bearing_error(LD, 0.6)[0] for LD in (0.2, 0.1, 0.05)}
    e = {LD: np.abs(v) for LD, v in errs.items()}
    assert np.all(e[0.05] < 0.006), errs
    assert np.all(e[0.1] < 0.02), errs
    # quadratic in L/D: halving L/D divides the error by about 4
    for a, b in ((0.2, 0.1), (0.1, 0.05)):
        ratio = e[a] / e[b]
        assert np.all((ratio > 3.0) & (ratio < 5.5)), (a, b, ratio)


# --------------------------------------------------------------------------------------------------
# published finite-bearing design data: Raimondi & Boyd (1958), full 360 deg bearing, L/D = 1
# --------------------------------------------------------------------------------------------------

RAIMONDI_BOYD_LD1 = {  # eps: (Sommerfeld number S = (R/C)^2 mu N / P, attitude angle [deg])
    0.6: (0.121, 50.58),
    0.8: (0.0446, 36.24),
}


def _raimondi_boyd_point(eps, grid):
    Lb = D  # L/D = 1
    b = JournalBearing(D, Lb, CL, MU, supply_pressure=0.0, groove=Groove(0.0, 0.1), grid=grid)
    s = b.steady_state(eps, RPM)  # journal along +x: maximum film at the groove (phi = 0)
    S = (0.5 * D / CL) ** 2 * MU * (RPM / 60.0) * Lb * D / s.load
    return S, s.attitude_angle_deg


@pytest.mark.parametrize("eps", sorted(RAIMONDI_BOYD_LD1))
def test_raimondi_boyd_full_bearing_LD1(eps):
    """Raimondi & Boyd solved the Reynolds equation with the film starting at the maximum film at zero
    pressure and the Swift-Stieber (Reynolds) condition at rupture. The mass-conserving film reproduces
    that with a line groove (one cell) at the maximum film at zero supply pressure: the film enters the
    converging part full, ruptures with p = dp/dn = 0 (JFO), and the cavitated film never reforms before
    the groove (its content falls while the film opens), so both models describe the same film.

    Measured (120x10 / 240x20 / 480x40): eps = 0.6: S = 0.11901 / 0.11933 / 0.11939 (-1.3 %), attitude
    49.95 / 49.94 / 49.93 deg (-0.65 deg); eps = 0.8: S = 0.04277 / 0.04278 / 0.04276 (-4.1 %), attitude
    35.04 / 34.98 / 34.96 deg (-1.3 deg). The table's 1958 finite differences are the likely larger error
    at eps = 0.8 (steep pressure peak). Tolerance: 5 % on S, 2 deg on the attitude.
    A bearing fed only through its ends (groove=None, p_amb = p_c) starves: S 120x too large at eps 0.6.
    """
    S_ref, att_ref = RAIMONDI_BOYD_LD1[eps]
    S1, a1 = _raimondi_boyd_point(eps, (120, 10))
    S2, a2 = _raimondi_boyd_point(eps, (240, 20))
    assert abs(S2 / S_ref - 1.0) < 0.05, (S2, S_ref)
    assert abs(a2 - att_ref) < 2.0, (a2, att_ref)
    # converged on these grids: doubling them changes S by < 0.5 % and the attitude by < 0.1 deg
    assert abs(S2 / S1 - 1.0) < 5e-3 and abs(a2 - a1) < 0.1, (S1, S2, a1, a2)


# --------------------------------------------------------------------------------------------------
# convergence: grid and switch width
# --------------------------------------------------------------------------------------------------

def _observed_order(values, ratio=2.0):
    d1, d2 = abs(values[1] - values[0]), abs(values[2] - values[1])
    return np.log(d1 / d2) / np.log(ratio)


def test_grid_convergence_flooded_second_order():
    """A flooded bearing (no groove, ends at 20 MPa = supply, eps = 0.3: no cell cavitates) isolates the
    discretisation of the full film. Grids 40x4 / 80x8 / 160x16: load 837.10 / 820.78 / 816.68 N at
    beta = 1e12, observed order 1.99 (second order: Couette flux with the film thickness at the face).
    A full incompressible film is antisymmetric, so the attitude is 90 deg: 89.99991 on every grid.
    The cell-upwinded thickness used before (flux (theta h)_upwind / 2) shifted the Couette flow by half
    a cell: attitude 86.94 / 88.46 / 89.23 / 89.61 deg on 76x11 / 151x21 / 301x41 / 601x81, first order."""
    loads, atts = [], []
    for grid in ((40, 4), (80, 8), (160, 16)):
        b = paper_bearing(grid=grid, groove=None, supply_pressure=20e6, ambient_pressure=20e6, bulk_modulus=1e12)
        s = b.steady_state(0.3, RPM)
        assert s.film_content.min() > 1.0  # full film everywhere
        loads.append(s.load)
        atts.append(s.attitude_angle_deg)
    assert 1.8 < _observed_order(loads) < 2.2, loads
    assert np.all(np.abs(np.array(atts) - 90.0) < 1e-3), atts


def test_grid_convergence_cavitating():
    """Paper bearing, eps = 0.6 at 50 deg from the load line, 6000 rpm, grids 40x4 / 80x8 / 160x16 /
    320x32: load 1852.55 / 1821.76 / 1807.87 / 1806.96 N, attitude 46.370 / 46.363 / 46.427 / 46.418 deg.
    The content is upwinded (monotone across the cavitation fronts), the thickness taken at the face:
    the change from 80x8 to 160x16 is 0.8 % in load and 0.06 deg (4.3 % and 1.2 deg with the cell-upwinded
    thickness used before). The 6 deg groove is 1, 1, 3 and 5 cells wide, which makes the order irregular."""
    loads, atts = [], []
    for grid in ((40, 4), (80, 8), (160, 16)):
        s = paper_bearing(grid=grid).steady_state(0.6, RPM, 50.0)
        loads.append(s.load)
        atts.append(s.attitude_angle_deg)
    assert abs(loads[2] - loads[1]) < 0.6 * abs(loads[1] - loads[0]), loads
    assert abs(loads[2] / loads[1] - 1.0) < 0.01, loads
    assert abs(atts[2] - atts[1]) < 0.2, atts


def test_switch_width_convergence():
    """The switch biases the film by the area it rounds off the sharp Elrod corner, ~(pi^2/6) w w_theta
    (physics.cavitation), and the prescribed pressures (groove, ends) are on the sharp curve: the bias is
    second order in the widths. 48x8, eps = 0.6 at 50 deg, against w = 10 Pa, w_theta = 1e-5 (1814.5905 N,
    46.1754 deg); both widths times 1, sqrt(10), 10 (measured): attitude -0.0066, -0.054, -0.41 deg (x8.2,
    x7.6 per sqrt(10); first order would be x3.2), load -0.0024 %, -0.0012 %, +0.075 %. The first version
    (ends at P(0) = w ln 2) was linear in w: +0.14 % / +0.10 deg at its default."""
    ref = paper_bearing(switch_width=10.0, switch_content_width=1e-5).steady_state(0.6, RPM, 50.0)
    p0 = paper_bearing().pressure_scale(RPM)
    dl, da = [], []
    for k in (1.0, np.sqrt(10.0), 10.0):
        s = paper_bearing(switch_width=2e-3 * p0 * k, switch_content_width=5e-4 * k).steady_state(0.6, RPM, 50.0)
        dl.append(s.load / ref.load - 1.0)
        da.append(s.attitude_angle_deg - ref.attitude_angle_deg)
    da = np.abs(da)
    assert da[1] > 5.0 * da[0] and da[2] > 5.0 * da[1], da
    assert abs(dl[0]) < 1e-4 and da[0] < 0.01, (dl, da)
    assert abs(dl[2]) < 2e-3, dl


def test_prescribed_pressures_are_on_the_sharp_curve():
    """The ends (p_amb = p_c) and the groove (p_s) carry exactly their pressure and theta = 1 + p / beta, not
    the rounded switch's P(u_amb) = w ln 2 (which biased the load linearly in w)."""
    b = paper_bearing(switch_width=1e5)  # a wide switch would show any rounding at once
    f = b.film(RPM)
    assert np.all(f.op.bP == 0.0) and np.all(f.op.bC == 1.0)
    f.residual(np.zeros(f.n), 0.3, 0.2)
    g = ~f.op.free
    u_s = b.supply_pressure / f.p0
    np.testing.assert_array_equal(f.P[g], u_s)
    np.testing.assert_allclose(f.C[g], 1.0 + u_s / f.beta_bar, rtol=1e-15)


# --------------------------------------------------------------------------------------------------
# transient: equilibrium, integrator agreement, RK4 baseline, mass conservation
# --------------------------------------------------------------------------------------------------

def test_unbalance_free_transient_settles_at_equilibrium():
    """No unbalance, 3000 rpm (growth rate -0.47 omega on 48x8), journal started at rest 0.11 C away
    from the equilibrium with its steady film: the distance falls 0.11 -> 1e-2 -> 5e-4 -> 2e-5 -> 6e-7 C
    per revolution (measured, rtol 1e-6) onto the position :meth:`equilibrium` finds."""
    rpm = 3000.0
    b = paper_bearing()
    o = JournalOrbit(b, MASS, 0.0, W, rpm)
    e = o.equilibrium()
    X0, Y0 = e.position[0] / CL + 0.1, e.position[1] / CL - 0.05
    s = b.steady_state(np.hypot(X0, Y0), rpm, np.degrees(np.arctan2(Y0, X0)))
    y0 = np.zeros(o.n)
    y0[: o.film.n] = s.u
    y0[o.film.n:o.film.n + 2] = X0, Y0
    r = o.run(4, integration=Integration(rtol=1e-6, atol=1e-9), recording=Recording(outputs_per_revolution=1), y0=y0)
    d = np.hypot(r.x - e.position[0], r.y - e.position[1]) / CL
    assert d[0] > 0.1
    assert np.all(np.diff(d) < 0)
    assert d[-1] < 1e-5, d


@pytest.fixture(scope="module")
def reference_orbit():
    b = paper_bearing()
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    o.initial_state()
    ref = o.run(1, integration=Integration(method="cvode", rtol=1e-10, atol=1e-13),
                recording=Recording(outputs_per_revolution=20))
    amp = np.max(np.hypot(ref.x - ref.x[0], ref.y - ref.y[0]))
    return o, ref, amp


def _orbit_error(r, ref, amp):
    return float(np.max(np.hypot(r.x - ref.x, r.y - ref.y)) / amp)


def test_cvode_and_ida_agree(reference_orbit):
    """One revolution from equilibrium (paper case, 48x8; orbit excursion 0.018 C). Error relative to
    the excursion vs CVODE rtol 1e-10 (IDA at 1e-10 differs by 1.3e-8), atol = rtol / 1000, measured at
    rtol 1e-4 / 1e-5 / 1e-6 / 1e-7 / 1e-8:
    CVODE 2.3e-3 / 8.3e-5 / 8.6e-5 / 2.2e-6 / 6.2e-7,  IDA 5.9e-4 / 2.5e-5 / 1.7e-5 / 9.4e-7 / 1.3e-7.
    The error falls with rtol but not in proportion at every step (rupture / reformation crossings)."""
    o, ref, amp = reference_orbit
    for method in ("cvode", "ida"):
        err = {rt: _orbit_error(o.run(1, integration=Integration(method=method, rtol=rt, atol=rt * 1e-3),
                                      recording=Recording(outputs_per_revolution=20)), ref, amp)
               for rt in (1e-4, 1e-7)}
        assert err[1e-4] < 5e-3 and err[1e-7] < 1e-5, (method, err)
        assert err[1e-7] < 0.01 * err[1e-4], (method, err)


def test_mass_conservation_improves_with_rtol():
    """Global balance M(t1) - M(t0) + int (end outflow + groove outflow) dt per revolution, relative to
    the end leakage (the throughput). It is exactly zero for the semi-discrete model, so it measures the
    integrator. Measured (48x8, paper case, 800 outputs per revolution, atol = rtol / 100, rtol 1e-3 ...
    1e-8): IDA 8.0e-5, 4.2e-6, 2.8e-6, 1.4e-7, 2.2e-9, 8.7e-9; CVODE 5.4e-5, 3.0e-5, 2.0e-6, 5.7e-7,
    5.7e-8, 1.9e-8 (Simpson quadrature error 5e-8: the last two are not resolved). The single-width
    switch lost 6.1e-2 of the leakage at rtol 1e-3."""
    b = paper_bearing()
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    o.initial_state()
    rel = []
    for rtol in (1e-3, 1e-5, 1e-7):
        r = o.run(1, integration=Integration(rtol=rtol, atol=rtol * 1e-2),
                  recording=Recording(outputs_per_revolution=800, record=("mass", "outflow")))
        mb = o.mass_balance(r)
        assert mb["quadrature_relative"][0] < 1e-6
        rel.append(mb["relative"][0])
        # the end leakage is an outflow and the groove supplies it
        assert np.all(r.outflow[:, 0] > 0) and np.all(r.outflow[:, 1] < 0)
    assert rel[0] < 1e-3, rel
    assert rel[1] < 0.1 * rel[0] and rel[2] < 0.1 * rel[1], rel
    assert rel[2] < 1e-7, rel


def test_recorded_film_content_is_theta_in_cavitation():
    """Regression: the recorded film content is theta = C(u) (it was 1 + u / beta_bar, i.e. ~1 in the
    cavitated zone where u = theta - 1)."""
    b = paper_bearing()
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    r = o.run(0.02, recording=Recording(outputs_per_revolution=100, record=("film_content",)))
    theta0 = r.film_content[0]
    np.testing.assert_allclose(theta0, o.equilibrium().film_content, atol=1e-6)
    assert theta0.min() < 0.9


# --------------------------------------------------------------------------------------------------
# parameter validation
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, name", [
    (dict(clearance=-1e-5), "clearance"),
    (dict(clearance=0.0), "clearance"),
    (dict(clearance=0.02), "clearance"),
    (dict(viscosity=0.0), "viscosity"),
    (dict(diameter=-0.08), "diameter"),
    (dict(length=0.0), "length"),
    (dict(bulk_modulus=-1.0), "bulk_modulus"),
    (dict(switch_width=0.0), "switch_width"),
    (dict(switch_content_width=0.0), "switch_content_width"),
    (dict(switch_content_width=0.5), "switch_content_width"),
    (dict(supply_pressure=-5.0), "supply_pressure"),
    (dict(ambient_pressure=-5.0), "ambient_pressure"),
    (dict(grid=(4, 4)), "n_theta"),
    (dict(grid=(32, 0)), "n_axial"),
    (dict(grid="fine"), "grid"),
])
def test_bad_bearing_parameters_raise(kwargs, name):
    args = dict(diameter=D, length=L, clearance=CL, viscosity=MU)
    args.update(kwargs)
    with pytest.raises(ValueError, match=name):
        JournalBearing(**args)


def test_default_switch_width_follows_p0_and_tolerances_are_on_theta_and_pressure():
    """The default pressure width is 1e-4 p0 at every speed; in the universal layout the cells' atol is
    atol min(1, 1/r) because a cavitated cell's unknown is its content deficit divided by r = w_theta / w
    (p/p0 in the full film); in the content layout it is atol."""
    b = paper_bearing()
    for rpm in (1000.0, 6000.0):
        f = b.film(rpm)
        assert f.width == pytest.approx(1e-4)
        assert f.content_scale == pytest.approx(0.01 / 1e-4)
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    tol = o.absolute_tolerance(1e-6)
    nf = o.film.n
    assert np.allclose(tol[:nf], 1e-6 / 100.0) and np.allclose(tol[nf:], 1e-6)
    assert np.allclose(o.absolute_tolerance(1e-6, "content"), 1e-6)
    wide = JournalOrbit(paper_bearing(switch_width=1e4, switch_content_width=1e-4), MASS, 0.01 * CL, W, RPM)
    assert wide.film.content_scale < 1 and np.allclose(wide.absolute_tolerance(1e-6), 1e-6)
    # the content deficit of a cavitated cell (10 switch widths below 0) is r times its unknown, up to the
    # softplus tail r w ln(1 + e^-10) = 4.5e-7
    f = o.film
    u = np.full(nf, -1e-3)
    f.residual(u, 0.3, 0.2)
    np.testing.assert_allclose(f.C[f.op.free], 1.0 - f.content_scale * 1e-3, rtol=0.0, atol=1e-6)
    with pytest.raises(ValueError, match="atol"):
        o.absolute_tolerance(0.0)
    with pytest.raises(ValueError, match="formulation"):
        o.absolute_tolerance(1e-6, "theta")


def test_bad_groove_and_operating_parameters_raise():
    with pytest.raises(ValueError, match="width_deg"):
        Groove(0.0, 0.0)
    b = paper_bearing(grid=(16, 4))
    for eps in (1.0, 1.2, -0.1):
        with pytest.raises(ValueError, match="eccentricity_ratio"):
            b.steady_state(eps, RPM)
    with pytest.raises(ValueError, match="speed_rpm"):
        b.steady_state(0.5, 0.0)
    with pytest.raises(ValueError, match="load"):
        b.equilibrium(-1.0, RPM)
    with pytest.raises(ValueError, match="rotor_mass"):
        JournalOrbit(b, 0.0, 0.0, W, RPM)
    with pytest.raises(ValueError, match="unbalance"):
        JournalOrbit(b, MASS, CL, W, RPM)
    with pytest.raises(ValueError, match="load"):
        JournalOrbit(b, MASS, 0.0, -W, RPM)
    o = JournalOrbit(b, MASS, 0.0, W, RPM)
    with pytest.raises(ValueError, match="revolutions"):
        o.run(0.0)
    with pytest.raises(ValueError, match="record"):
        o.run(1.0, recording=Recording(record=("temperature",)))
    with pytest.raises(ValueError, match="steps_per_revolution"):
        o.run(0.1, integration=Integration(method="rk4", steps_per_revolution=1))
    with pytest.raises(ValueError, match="mass_balance"):
        o.mass_balance(o.run(0.05))


# --------------------------------------------------------------------------------------------------
# checkpoint / resume
# --------------------------------------------------------------------------------------------------

def test_checkpoint_resume_equals_uninterrupted_run(tmp_path):
    b = paper_bearing(grid=(32, 6))
    o = JournalOrbit(b, MASS, 0.01 * CL, W, RPM)
    kw = dict(integration=Integration(rtol=1e-6, atol=1e-9),
              recording=Recording(outputs_per_revolution=20, record=("force", "mass")))
    lr = LongRun(chunk_revolutions=1.0, progress=False)
    full = o.run(2.0, long_run=lr, **kw)
    path = str(tmp_path / "orbit.npz")
    o.run(1.0, long_run=replace(lr, checkpoint=path), **kw)  # "crashes" after the first chunk
    assert os.path.exists(path)
    resumed = JournalOrbit(b, MASS, 0.01 * CL, W, RPM).run(2.0, long_run=replace(lr, checkpoint=path, resume=True),
                                                           **kw)
    assert resumed.t.shape == full.t.shape
    for k in ("t", "x", "y"):
        np.testing.assert_allclose(getattr(resumed, k), getattr(full, k), rtol=1e-12, atol=0)
    assert resumed.force.dtype == float and resumed.mass.dtype == float
    np.testing.assert_allclose(resumed.force, full.force, rtol=1e-12)
    np.testing.assert_allclose(resumed.mass, full.mass, rtol=1e-12)
    # a checkpoint of another orbit is refused
    other = JournalOrbit(b, MASS, 0.02 * CL, W, RPM)
    with pytest.raises(ValueError, match="checkpoint"):
        other.run(2.0, long_run=replace(lr, checkpoint=path, resume=True), **kw)


# ---- issue 17: inputs that used to pass silently or fail deep inside -------------------------------------------
@pytest.mark.parametrize("make, name", [
    (lambda: Groove(angle_deg=float("nan")), "angle_deg"),
    (lambda: Groove(angle_deg="90"), "angle_deg"),
    (lambda: JournalBearing(D, L, CL, MU, symmetric="False", grid=(24, 4)), "symmetric"),
    (lambda: JournalBearing(D, L, CL, MU, grid=(41.5, 6)), "n_theta"),
    (lambda: JournalBearing(D, L, CL, MU, grid=(41, "6")), "n_axial"),
    (lambda: JournalBearing(D, L, CL, MU, cavitation_pressure=float("nan"), grid=(24, 4)), "cavitation_pressure"),
    (lambda: JournalBearing(D, L, CL, MU, cavitation_pressure="0", grid=(24, 4)), "cavitation_pressure"),
    (lambda: JournalBearing(D, L, CL, MU, grid=(24, 4)).steady_state(0.5, 1e300), "speed_rpm"),
])
def test_bad_journal_inputs_are_named(make, name):
    with pytest.raises(ValueError, match=name):
        make()


def test_orbit_rejects_a_start_outside_the_clearance_and_non_numeric_states():
    o = JournalOrbit(JournalBearing(D, L, CL, MU, grid=(24, 4)), MASS, 0.01 * CL, W, RPM)
    y = o.initial_state()
    y[o.film.n] = 1.2
    with pytest.raises(ValueError, match="outside the clearance"):
        o.run(0.1, y0=y, long_run=LongRun(progress=False))
    for bad in ("5", 1.0, [None] * o.n):
        with pytest.raises(ValueError, match="initial state"):
            o.run(0.1, y0=bad, long_run=LongRun(progress=False))
    with pytest.raises(ValueError, match="revolutions"):
        o.run("5", long_run=LongRun(progress=False))


def test_an_unreachable_equilibrium_is_a_named_value_error():
    b = JournalBearing(D, L, CL, MU, grid=(24, 4))
    with pytest.raises(ValueError, match=r"load=1000000\.0 N, speed_rpm=6000"):
        b.equilibrium(1e6, 6000.0)


def test_pressures_beyond_the_isoviscous_rigid_model_warn():
    b = JournalBearing(D, L, CL, MU, grid=(48, 8))
    with pytest.warns(UserWarning, match="outside its validity"):
        b.steady_state(0.98, RPM)


def test_flooded_film_matches_ross_fluid_flow():
    """Matched physics against an independent code: ROSS 2.3.0 (petrobras/ross) ``FluidFlow``, finite differences
    of the full-Sommerfeld Reynolds equation (its pressure before the clipping at zero), on the Rho & Kim bearing
    at eps = 0.6, 6000 rpm, both ends at 200 MPa (nothing cavitates). ROSS's load on 21x151, 41x301, 81x601 nodes:
    2616.05, 2619.31, 2620.12 N (Richardson: 2620.4 N); its largest pressure rise 2.754 MPa on the finest grid
    (first order in its grid: 2.821, 2.777, 2.754), the mean of rise and drop 2.7312 MPa. Here: flooded,
    incompressible (beta = 1e14), no groove, 151x21 half grid (docs/validation.md: 0.19 % apart after both
    grids are extrapolated)."""
    p_amb = 2e8
    b = JournalBearing(**(RHO_KIM_BEARING | dict(grid=(151, 21), bulk_modulus=1e14, ambient_pressure=p_amb,
                                                 supply_pressure=p_amb, groove=None)))
    s = b.steady_state(0.6, RPM)
    assert s.pressure.min() > p_amb - 3e6  # flooded: no cell near cavitation
    assert s.load == pytest.approx(2620.4, rel=5e-3)
    rise = s.pressure.max() - p_amb
    assert rise == pytest.approx(2.7312e6, rel=3e-3)
