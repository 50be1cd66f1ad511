"""The classical Reynolds-condition film of ``JournalBearing(cavitation="reynolds")`` (issue 17).

Conventions as in tests/models/journal/test_journal_model.py: ``phi`` from the groove (top) in the direction of rotation,
``H = 1 + X cos(phi) + Y sin(phi)``, film force on the journal ``F = +int p (cos, sin) dA``; a journal
displaced along +x puts the maximum film at phi = 0, so the closed forms of
:mod:`transient.verification.reference` apply with ``theta = phi`` and ``F_model = -F_ref``.

Expected values are published data or independent closed forms / quadratures, never the code's own
output. Numbers quoted in the docstrings were measured on the grids used here (docs/validation.md).
"""

import warnings

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from transient.fv.grid import Axis, Grid2D
from transient.models.journal.bearing import Groove, JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.verification.reference import short_bearing_force

D, L, CL, MU = (RHO_KIM_BEARING[k] for k in ("diameter", "length", "clearance", "viscosity"))
W, MASS, RPM = RHO_KIM_ROTOR["load"], RHO_KIM_ROTOR["rotor_mass"], 6000.0


def reynolds_bearing(length=L, grid=(48, 8), **kw):
    return JournalBearing(D, length, CL, MU, grid=grid, cavitation="reynolds", **kw)


# --------------------------------------------------------------------------------------------------
# the parameter
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bad", ["Reynolds", "jfo", "", None, 1])
def test_bad_cavitation_value_names_the_parameter(bad):
    with pytest.raises(ValueError, match=r"cavitation must be one of \('elrod', 'reynolds'\)") as e:
        JournalBearing(D, L, CL, MU, cavitation=bad)
    assert repr(bad) in str(e.value)


def test_parameters_carry_the_mode():
    assert JournalBearing(D, L, CL, MU).parameters()["cavitation"] == "elrod"
    assert reynolds_bearing().parameters()["cavitation"] == "reynolds"


def test_orbit_refuses_a_reynolds_bearing():
    with pytest.raises(ValueError, match="JournalOrbit: cavitation = 'reynolds'; allowed: 'elrod'"):
        JournalOrbit(reynolds_bearing(), MASS, 0.01 * CL, W, RPM)


def test_elrod_film_without_supply_warns():
    with pytest.warns(UserWarning, match="no oil supply.*cavitation=\"reynolds\""):
        JournalBearing(D, L, CL, MU, groove=None)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        reynolds_bearing(groove=None)  # the classical 360 deg bearing: no warning
        JournalBearing(D, L, CL, MU, groove=None, ambient_pressure=2e5)  # fed through its ends


# --------------------------------------------------------------------------------------------------
# analytic Jacobian vs finite differences; complementarity
# --------------------------------------------------------------------------------------------------

def test_jacobian_matches_finite_differences(fd_jacobian):
    """dG/dP (affine: exact up to rounding) and the journal columns dG/d(X, Y, VX, VY) on a 16x4 grid with a
    groove, at a moving, off-centre journal and a pressure with cavitated cells; the finite-difference
    entries outside the sparsity pattern are exactly zero."""
    b = reynolds_bearing(grid=(16, 4))
    f = b.film(RPM)
    n = f.n
    q = np.array([0.5, 0.3, 0.05, -0.04])
    P, _ = f.solve(*q)
    assert np.any(P[f.free] == 0.0) and np.any(P[f.free] > 0.0)
    M = f.op.matrix(f.jacobian_data(P, *q)).toarray()
    pattern = f.op.matrix(np.ones(f.op.nnz)).toarray() != 0
    Ju = fd_jacobian(lambda v: f.residual(v, *q).copy(), P + 0.1, n, 1e-3, relative=False)
    Jq = fd_jacobian(lambda v: f.residual(P, *v).copy(), q, n, 1e-6, relative=False)
    for an, fd, pat in ((M[:n, :n], Ju, pattern[:n, :n]), (M[:n, n:n + 4], Jq, pattern[:n, n:n + 4])):
        scale = np.abs(an).max(axis=0)
        assert float((np.abs(fd - an).max(axis=0) / scale).max()) < 1e-7
        assert np.all(fd[~pat] == 0.0)


@pytest.mark.parametrize("groove", [Groove(), None])
def test_complementarity_holds(groove):
    """p >= p_c everywhere; the flow residual G (net outflow + squeeze) vanishes where p > p_c and is >= 0
    (the film loses Couette flow) where p = p_c; both zones are present."""
    b = reynolds_bearing(grid=(96, 12), groove=groove, supply_pressure=101325.0 if groove else 0.0)
    f = b.film(RPM)
    for q in ((0.8, 0.0, 0.0, 0.0), (0.4, 0.5, 0.1, -0.2)):
        P, _ = f.solve(*q)
        G = f.residual(P, *q)
        free = f.free
        flow = np.abs(G[free]).max()  # the scale of the net cell flows
        full, cav = free & (P > 0), free & (P == 0)
        assert P.min() >= 0.0
        assert full.sum() > 10 and cav.sum() > 10
        assert np.abs(G[full]).max() < 1e-10 * flow
        assert G[cav].min() > -1e-10 * flow
        assert np.abs(f.complementarity(P, *q)).max() < 1e-12 * max(1.0, P.max())
        s = b.steady_state(np.hypot(q[0], q[1]), RPM, np.degrees(np.arctan2(q[1], q[0])))
        assert s.pressure.min() >= b.cavitation_pressure


# --------------------------------------------------------------------------------------------------
# published design data: Raimondi & Boyd (1958), full 360 deg bearing, L/D = 1
# --------------------------------------------------------------------------------------------------

RAIMONDI_BOYD_LD1 = {  # eps: (Sommerfeld number S = (R/C)^2 mu N / P, attitude angle [deg]); as in
    0.6: (0.121, 50.58),  # tests/models/journal/test_journal_model.py (Raimondi & Boyd 1958, ASLE Trans. 1; Shigley's
    0.8: (0.0446, 36.24),  # table for the full journal bearing, L/D = 1)
}


def _raimondi_boyd_point(eps, grid, groove):
    b = JournalBearing(D, D, CL, MU, supply_pressure=0.0, groove=groove, grid=grid, cavitation="reynolds")
    s = b.steady_state(eps, RPM)  # journal along +x: maximum film at phi = 0
    return (0.5 * D / CL) ** 2 * MU * (RPM / 60.0) * D * D / s.load, s.attitude_angle_deg


@pytest.mark.parametrize("eps", sorted(RAIMONDI_BOYD_LD1))
def test_raimondi_boyd_full_bearing_LD1(eps):
    """Raimondi & Boyd: Reynolds equation, film starting at the maximum film at p = 0, Swift-Stieber
    rupture. Line groove (one cell) at the maximum film at zero supply pressure, measured
    (120x10 / 240x20 / 480x40): eps 0.6: S = 0.12044 / 0.12081 / 0.12091 (-0.15 % on 240x20), attitude
    50.53 deg (-0.05); eps 0.8: S = 0.04443 / 0.04453 / 0.04455 (-0.16 %), attitude 36.23 (-0.01); second
    order (differences 0.0037 -> 0.0010). Asserted: 1 % on S, 0.3 deg, 120x10 -> 240x20 within 0.5 %.

    Without a groove (the film re-forms where the complementarity puts it, slightly before the maximum
    film): S +0.24 / +0.20 %, attitude +1.40 / +0.56 deg on 240x20. Asserted: 2 % and 2 deg."""
    S_ref, att_ref = RAIMONDI_BOYD_LD1[eps]
    S1, a1 = _raimondi_boyd_point(eps, (120, 10), Groove(0.0, 0.1))
    S2, a2 = _raimondi_boyd_point(eps, (240, 20), Groove(0.0, 0.1))
    assert abs(S2 / S_ref - 1.0) < 0.01, (S2, S_ref)
    assert abs(a2 - att_ref) < 0.3, (a2, att_ref)
    assert abs(S2 / S1 - 1.0) < 5e-3 and abs(a2 - a1) < 0.05, (S1, S2, a1, a2)
    S3, a3 = _raimondi_boyd_point(eps, (240, 20), None)
    assert abs(S3 / S_ref - 1.0) < 0.02 and abs(a3 - att_ref) < 2.0, (S3, a3)


# --------------------------------------------------------------------------------------------------
# closed forms: short (Ocvirk) and long (Swift-Stieber / Gumbel) bearings
# --------------------------------------------------------------------------------------------------

def _short_error(LD, eps):
    """Reynolds film (no groove) vs the short-bearing pi film, axially Richardson-extrapolated (6/12 cells,
    480 around)."""
    Lb = LD * D
    ref = np.array(short_bearing_force(eps, MU, omega(RPM) * 0.5 * D, CL, Lb, film="half"))
    F = {nz: -np.array(reynolds_bearing(Lb, (480, nz), groove=None).steady_state(eps, RPM).force) for nz in (6, 12)}
    return (4 * F[12] - F[6]) / 3 / ref - 1.0


def test_short_bearing_limit():
    """As L/D -> 0 the circumferential Poiseuille flow vanishes, every axial line is independent and the
    complementarity keeps the pressure exactly where the short-bearing pressure is positive (0 < phi < pi):
    the Reynolds and the half-Sommerfeld (Gumbel) conditions coincide, Ocvirk's pi film. Measured (eps 0.6,
    radial / tangential): L/D 0.2: -5.45 / -4.31 %; 0.1: -1.46 / -1.18 %; 0.05: -0.38 / -0.31 % -- (L/D)^2."""
    e = {LD: np.abs(_short_error(LD, 0.6)) for LD in (0.1, 0.05)}
    assert np.all(e[0.05] < 0.005) and np.all(e[0.1] < 0.02), e
    ratio = e[0.1] / e[0.05]
    assert np.all((ratio > 3.0) & (ratio < 5.0)), ratio


def _long_swift_stieber(eps):
    """Infinitely long bearing, film from the maximum film (theta = 0, p = 0) to the Swift-Stieber rupture
    theta_2 (p = dp/dtheta = 0), by quadrature: ``dP/dtheta = 1/H^2 - H_2/H^3``, ``H_2 = H(theta_2)``, theta_2
    from ``P(theta_2) = 0``; force per unit length in units p0 R L, ``int P (cos, sin) dtheta``."""
    H = lambda t: 1.0 + eps * np.cos(t)  # noqa: E731
    P_at = lambda t, H2: quad(lambda s: 1.0 / H(s) ** 2 - H2 / H(s) ** 3, 0.0, t)[0]  # noqa: E731
    t2 = brentq(lambda t: P_at(t, H(t)), np.pi + 1e-9, 2 * np.pi - 1e-9, xtol=1e-14)
    H2 = H(t2)
    return t2, np.array([quad(lambda t: P_at(t, H2) * w(t), 0.0, t2, limit=200)[0] for w in (np.cos, np.sin)])


def _long_model(eps, n):
    """The model's film on one axial cell with symmetry (no-flux) faces at both ends: no end leakage."""
    b = reynolds_bearing(D, (n, 1), supply_pressure=0.0, groove=Groove(0.0, 0.1))
    z = Axis.uniform(1, 1.0, lower="symmetry", upper="symmetry", name="z")  # half length L/(2R) = 1
    b.grid = Grid2D(b.grid.x, z, fixed=b.grid.fixed, fixed_values=0.0)
    f = b.film(RPM)
    P, _ = f.solve(eps, 0.0)
    return np.array(f.force(P, eps, 0.0)) / 2.0  # per unit length L/R = 2


@pytest.mark.parametrize("eps", [0.6, 0.8])
def test_long_bearing_swift_stieber(eps):
    """Measured: eps 0.6 (rupture at 213.08 deg): 120 / 240 / 480 cells -0.09 / -0.02 / -0.006 % on the
    radial force; eps 0.8 (200.17 deg): -0.34 / -0.10 / -0.02 %: second order. Asserted on 240 cells:
    0.2 %. The half-Sommerfeld (Gumbel) closed form ``(-2 eps^2 / ((2 + eps^2)(1 - eps^2)),
    pi eps / ((2 + eps^2) sqrt(1 - eps^2)))`` carries less: the Reynolds condition adds 23 % (eps 0.6)
    and 26 % (0.8) to the load of the long bearing (the positive pressure runs past the minimum film)."""
    _, ref = _long_swift_stieber(eps)
    F = _long_model(eps, 240)
    assert np.all(np.abs(F / ref - 1.0) < 2e-3), (F, ref)
    gumbel = np.array([-2 * eps**2 / ((2 + eps**2) * (1 - eps**2)), np.pi * eps / ((2 + eps**2) * np.sqrt(1 - eps**2))])
    assert np.hypot(*ref) > 1.15 * np.hypot(*gumbel)


# --------------------------------------------------------------------------------------------------
# stiffness and damping, equilibrium, stability threshold
# --------------------------------------------------------------------------------------------------

def test_force_sensitivity_matches_finite_differences_of_the_solve(fd_jacobian):
    """The active-set sensitivities (position: stiffness; journal velocity through the squeeze term:
    damping) against central differences of the whole complementarity solve (step 1e-6): the rupture
    boundary's motion adds nothing to first order (p = dp/dn = 0 there). Measured 2e-10 / 8e-11."""
    b = reynolds_bearing(grid=(96, 12))
    f = b.film(RPM)
    X, Y = 0.3, 0.4

    def F(v):
        P, _ = f.solve(*v)
        return np.array(f.force(P, v[0], v[1]))

    P, _ = f.solve(X, Y)
    _, dq, dv = f.force_sensitivity(P, X, Y)
    fd = fd_jacobian(F, np.array([X, Y, 0.0, 0.0]), 2, 1e-6, relative=False)
    assert np.abs(fd[:, :2] - dq).max() < 1e-6 * np.abs(dq).max()
    assert np.abs(fd[:, 2:] - dv).max() < 1e-6 * np.abs(dv).max()
    assert abs(dv[0, 1] - dv[1, 0]) < 1e-9 * np.abs(dv).max()  # fixed-boundary damping is symmetric


def _short_force(q, zb):
    """Short-bearing film force (dimensionless, model frame) with the pressure kept where it is positive:
    ``H^3/2 P_zz = s``, ``s = d(H/2)/dphi + H'``, ``P = s (z^2 - zb^2) / H^3`` where ``s < 0``;
    ``F = 4 zb^3 / 3 int max(-s, 0) / H^3 (cos, sin) dphi``."""
    X, Y, VX, VY = q
    a, c = 0.5 * Y + VX, -0.5 * X + VY  # s = a cos + c sin
    d = np.arctan2(c, a)
    pts = sorted(np.mod([d + 0.5 * np.pi, d - 0.5 * np.pi], 2 * np.pi))

    def g(t, w):
        s = a * np.cos(t) + c * np.sin(t)
        return max(-s, 0.0) / (1.0 + X * np.cos(t) + Y * np.sin(t)) ** 3 * w(t)

    return np.array([4 * zb**3 / 3 * quad(g, 0.0, 2 * np.pi, args=(w,), points=pts, epsabs=1e-13, epsrel=1e-12,
                                          limit=200)[0] for w in (np.cos, np.sin)])


def _short_coefficient_error(fd_jacobian, LD, X=0.55, Y=0.25):
    """Worst relative error (per column, against its largest entry) of dF/d(X, Y) and dF/d(VX, VY) of the
    Reynolds film (no groove, 480 around, axially Richardson-extrapolated from 6/12 cells) against the
    derivatives of the short-bearing pi-film force (quadrature + central differences)."""
    zb = 0.5 * LD * D / (0.5 * D)
    ref = fd_jacobian(lambda v: _short_force(v, zb), np.array([X, Y, 0.0, 0.0]), 2, 1e-5, relative=False)
    S = {}
    for nz in (6, 12):
        f = reynolds_bearing(LD * D, (480, nz), groove=None).film(RPM)
        P, _ = f.solve(X, Y)
        _, dq, dv = f.force_sensitivity(P, X, Y)
        S[nz] = np.hstack([dq, dv])
    err = np.abs((4 * S[12] - S[6]) / 3 - ref) / np.abs(ref).max(axis=0)
    return err[:, :2].max(), err[:, 2:].max()


def test_short_bearing_stiffness_and_damping(fd_jacobian):
    """Stiffness (position) and damping (squeeze) sensitivities of a short bearing against the short-bearing
    pi-film force's derivatives. Measured (stiffness / damping): L/D 0.2: 7.9 / 5.4 %; 0.1: 2.2 / 1.4 %;
    0.05: 0.62 / 0.45 % -- the (L/D)^2 term of the short-bearing theory, as for the force."""
    e1, e2 = np.array(_short_coefficient_error(fd_jacobian, 0.1)), np.array(_short_coefficient_error(fd_jacobian, 0.05))
    assert np.all(e1 < 0.03) and np.all(e2 < 0.01), (e1, e2)
    assert np.all(e1 / e2 > 2.5), (e1, e2)


def test_equilibrium_coefficients_and_threshold():
    """Paper bearing (Rho & Kim), 48x8, Reynolds film: the equilibrium carries the load, K and C are the
    force sensitivities in SI, and Lund's threshold lies near the paper's ~7800 rpm (measured 8573 rpm;
    the Elrod film gives 8305 rpm on this grid)."""
    b = reynolds_bearing()
    e = b.equilibrium(W, RPM)
    assert abs(e.load / W - 1.0) < 1e-8 and abs(e.force[1]) < 1e-8 * W
    assert 0.3 < e.eccentricity_ratio < 0.7
    K, C = b.coefficients(W, RPM)
    assert np.all(np.isfinite(K)) and K[0, 0] > 0 and K[1, 1] > 0 and C[0, 0] > 0 and C[1, 1] > 0
    assert abs(C[0, 1] - C[1, 0]) < 1e-8 * abs(C).max()
    n_th = b.stability_threshold(MASS, W)
    assert 0.85 * 7800 < n_th < 1.15 * 7800, n_th


def test_friction_variable_against_raimondi_boyd():
    """Raimondi & Boyd's friction variable (R/C) f, f = friction force / load, L/D = 1 (Shigley's table: 3.22 at
    eps 0.6, 1.70 at 0.8; it counts the full-film shear over the whole circumference, as the Reynolds film's
    content of 1 does). Measured on 240x20 without a groove: 3.2289 (+0.28 %), 1.7098 (+0.58 %); 120x10:
    3.2195, 1.7065."""
    for eps, ref in ((0.6, 3.22), (0.8, 1.70)):
        b = JournalBearing(D, D, CL, MU, supply_pressure=0.0, groove=None, grid=(240, 20), cavitation="reynolds")
        s = b.steady_state(eps, RPM)
        rcf = 0.5 * D / CL * s.friction_force / s.load
        assert abs(rcf / ref - 1.0) < 0.01, (eps, rcf)
