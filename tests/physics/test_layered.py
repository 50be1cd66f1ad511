"""Layered boundary films with a Gecim bulk (seed 004, transient.physics.layered): the pointwise flow law.

References derived here, independently of the kernels: the Gecim law inverted by bracketed root finding
(not the kernels' quadratic) and integrated by scipy quad across the film, straight from Jang's eqs. (4),
(5), (14), (18); the slit (plane Poiseuille) flow of a Gecim fluid in closed form; Newtonian closed forms;
the infinitely long slider bearing in closed form.
"""

import math

import numpy as np
import pytest
from scipy import integrate, optimize

from transient.physics.layered import (NO_LAYERS, BoundaryLayers, Gecim, LayeredFilm, Newtonian, _moments,
                                       _moments_2d, gecim_face, gecim_face_2d, gecim_rate)

MU = 0.02        # mu_1 [Pa s]
KAPPA = 2.0e3    # [Pa]
RATIO = 0.57     # mu_2/mu_1 (the paper's)
C = 20e-6        # a length scale [m]
U = 5.0          # a speed [m/s]
G0 = MU * U / C**2  # a pressure-gradient scale [Pa/m]


# --------------------------------------------------------------------------------------------------
# independent references
# --------------------------------------------------------------------------------------------------

def ref_rate(tau, mu1, kappa, r):
    """Shear rate from the forward Gecim law ``tau = mu(gdot) gdot`` by bracketed root finding."""
    t = abs(tau)
    if t == 0.0:
        return 0.0
    f = lambda g: mu1 * (kappa + r * mu1 * g) / (kappa + mu1 * g) * g - t  # noqa: E731
    g = optimize.brentq(f, t / mu1 * (1 - 1e-9), t / (r * mu1) * (1 + 1e-9), xtol=1e-300, rtol=8.9e-16)
    return math.copysign(g, tau)


def ref_flow(h, G, U1, U2, mu1, kappa, r, delta=0.0, mu_a=1.0, mu_b=1.0, alpha=0.0):
    """Flow per unit width and bulk stress at z = delta, by quadrature of eqs. (4), (5), (14), (18)."""
    ua, ub = U1 - alpha**2 * G / mu_a, U2 - alpha**2 * G / mu_b
    H = h - 2 * delta

    def quad(fun, t0, power):  # absolute tolerance too: the velocity jump vanishes in a symmetric slit
        pts = [z for z in (-t0 / G, (kappa - t0) / G, (-kappa - t0) / G) if 0 < z < H] if G else None
        scale = H**power * max(abs(ref_rate(t, mu1, kappa, r)) for t in (t0, t0 + G * H))
        return integrate.quad(fun, 0, H, points=pts, epsabs=1e-13 * scale, epsrel=1e-13, limit=200)[0]

    def jump(t0):
        return quad(lambda z: ref_rate(t0 + G * z, mu1, kappa, r), t0, 1) - (ub - ua)

    t_n = mu1 * (ub - ua) / H - G * H / 2
    w = abs(t_n) + abs(G) * H
    t0 = optimize.brentq(jump, t_n - 3 * w, t_n + 3 * w, xtol=1e-300, rtol=8.9e-16)
    q = delta * (ua + ub) + H * ua + quad(lambda z: (H - z) * ref_rate(t0 + G * z, mu1, kappa, r), t0, 2)
    return q, t0


def slit_flow_gecim(G, H, mu1, kappa, r):
    """Plane Poiseuille flow of a Gecim fluid in closed form: ``q = -(2/G^2) sign(G) int_0^T tau gdot dtau``,
    ``T = |G| H/2``, integrated in the shear-rate variable ``x`` where ``tau/kappa = S(x)`` is rational."""
    s = abs(G) * H / 2 / kappa
    X = (s - 1 + math.sqrt((s - 1) ** 2 + 4 * r * s)) / (2 * r)
    S = r * X + (1 - r) * X / (1 + X)
    L = math.log1p(X)
    int_s2 = (r * r * X**3 / 3 + 2 * r * (1 - r) * (X**2 / 2 - X + L)
              + (1 - r) ** 2 * (X - 2 * L + X / (1 + X)))       # int_0^X S^2 dx
    int_tau_gdot = kappa**3 / mu1 * (X * S * S - int_s2) / 2     # int x S S' dx, by parts
    return -2 * math.copysign(1.0, G) / G**2 * int_tau_gdot


def film(rheology=Newtonian(), layers=NO_LAYERS, mu=MU, n=12):
    return LayeredFilm(mu, rheology, layers, n)


def q_total(f):
    return f.q_couette + f.q_pressure


PAPER_LAYERS = BoundaryLayers(0.2 * C, (10 * MU, 4 * MU), 0.1 * C)


# --------------------------------------------------------------------------------------------------
# the Gecim law
# --------------------------------------------------------------------------------------------------

def test_gecim_law_inverse_and_limits():
    g = Gecim(KAPPA, RATIO)
    rate = np.concatenate([-np.logspace(-4, 8, 49), [0.0], np.logspace(-4, 8, 49)]) * KAPPA / MU
    stress = g.viscosity(rate, MU) * rate
    np.testing.assert_allclose(g.shear_rate(stress, MU), rate, rtol=2e-15, atol=0)
    assert g.viscosity(0.0, MU) == MU
    assert g.viscosity(1e14 * KAPPA / MU, MU) == pytest.approx(RATIO * MU, rel=1e-13, abs=0)
    assert np.all(np.diff(g.viscosity(np.logspace(-3, 6, 50), MU)) < 0)  # shear thinning
    np.testing.assert_allclose(Newtonian().shear_rate(stress, MU) * MU, stress, rtol=1e-15)


@pytest.mark.parametrize("r", [0.05, RATIO, 1.0])
def test_gecim_rate_slope_against_finite_differences(r):
    for s in (-300.0, -1.0, -0.2, 1e-3, 0.7, 1.0, 3.0, 1e4):
        e = 1e-6 * abs(s)
        fd = (gecim_rate(s + e, r)[0] - gecim_rate(s - e, r)[0]) / (2 * e)
        assert gecim_rate(s, r)[1] == pytest.approx(fd, rel=1e-8, abs=0)
        assert 1.0 <= gecim_rate(s, r)[1] <= 1.0 / r * (1 + 1e-15)


# --------------------------------------------------------------------------------------------------
# flow law against closed forms
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("layers", [NO_LAYERS, PAPER_LAYERS])
def test_couette_gecim(layers):
    """G = 0: flow h (U1 + U2)/2 whatever the rheology; the bulk stress is mu(gdot) gdot, gdot = dU/H."""
    f = film(Gecim(KAPPA, RATIO), layers)
    h = np.array([0.5, 1.0, 2.0]) * C
    U1, U2 = -1.0, U
    r = f.flow(h, 0.0, U1, U2)
    np.testing.assert_allclose(q_total(r), h * (U1 + U2) / 2, rtol=1e-15)
    assert np.all(np.abs(r.q_pressure) <= 1e-15 * h * U)
    gdot = (U2 - U1) / (h - 2 * layers.thickness)
    tau = f.rheology.viscosity(gdot, MU) * gdot
    st = f.stresses(h, 0.0, U1, U2)
    for v in st:
        np.testing.assert_allclose(v, tau, rtol=1e-14)


SLIT_ACCURACY = {0.05: 1e-11, RATIO: 1e-14}  # 12 points: measured worst 5.5e-12 and 2e-15 over 0.3..1000 kappa


@pytest.mark.parametrize("r", [0.05, RATIO])
@pytest.mark.parametrize("stress_over_kappa", [0.3, 1.0, 7.0, 300.0, 1e5])
def test_slit_flow_gecim_closed_form(r, stress_over_kappa):
    """Plane Poiseuille flow: kernel against the closed form (wall stress |G| H/2 = given multiple of kappa;
    below ~0.3 kappa the closed form loses digits to cancellation, see the quadrature test)."""
    H = C
    for sign in (1.0, -1.0):
        G = sign * 2 * stress_over_kappa * KAPPA / H
        q = film(Gecim(KAPPA, r)).flow(H, G, 0.0, 0.0).q_pressure
        assert q == pytest.approx(slit_flow_gecim(G, H, MU, KAPPA, r), rel=SLIT_ACCURACY[r], abs=0)


def test_slit_flow_against_quadrature():
    """Closed form and kernel against root finding + scipy quad of the forward law (no shared code)."""
    for s in (1e-3, 0.3, 7.0, 300.0):
        G = -2 * s * KAPPA / C
        ref = ref_flow(C, G, 0.0, 0.0, MU, KAPPA, RATIO)[0]
        assert film(Gecim(KAPPA, RATIO)).flow(C, G, 0.0, 0.0).q_pressure == pytest.approx(ref, rel=1e-14, abs=0)
        if s >= 0.3:
            assert slit_flow_gecim(G, C, MU, KAPPA, RATIO) == pytest.approx(ref, rel=1e-13, abs=0)


CASES = [  # h/C, G/G0, U1/U, U2/U: sliding with and without a stress sign change in the bulk
    (1.0, -3.0, 0.0, 1.0),
    (0.6, 25.0, 0.0, 1.0),
    (1.4, 8.0, -0.5, 0.7),
    (0.8, -0.4, 1.0, 0.0),
]


@pytest.mark.parametrize("case", CASES)
def test_layered_gecim_against_direct_integration(case):
    hc, g, u1, u2 = case
    ly = PAPER_LAYERS
    h, G, U1, U2 = hc * C, g * G0, u1 * U, u2 * U
    f = film(Gecim(KAPPA, RATIO), ly)
    q_ref, t0_ref = ref_flow(h, G, U1, U2, MU, KAPPA, RATIO, ly.thickness, *ly.viscosity, ly.alpha)
    assert q_total(f.flow(h, G, U1, U2)) == pytest.approx(q_ref, rel=1e-12, abs=0)
    assert f.stresses(h, G, U1, U2).lower_interface == pytest.approx(t0_ref, rel=1e-12, abs=0)


def test_corrected_eq19_with_secant_viscosity_integrals():
    """The paper's representation (f1..f5 of the secant viscosity mu_c = tau/gdot, eq. 27 corrected) gives
    the kernel's flow: q = delta(ua+ub) + H ua + G f40 + (ub - ua) f50/f20 with the integrals over the bulk
    f20 = int dz/mu_c, f10 = int z/mu_c dz, f40 = int f3 dz = int (H - z) z/mu_c - (f10/f20) int (H - z)/mu_c,
    f50 = int f2 dz = int (H - z)/mu_c dz."""
    ly = PAPER_LAYERS
    h, G, U1, U2 = 0.7 * C, 6 * G0, 0.0, U
    f = film(Gecim(KAPPA, RATIO), ly)
    t0 = float(f.stresses(h, G, U1, U2).lower_interface)
    H = h - 2 * ly.thickness
    inv_mu = lambda z: ref_rate(t0 + G * z, MU, KAPPA, RATIO) / (t0 + G * z)  # noqa: E731
    pts = [-t0 / G] if 0 < -t0 / G < H else None

    def q(fun):
        return integrate.quad(fun, 0, H, points=pts, epsabs=0, epsrel=1e-13, limit=200)[0]

    f20, f10 = q(inv_mu), q(lambda z: z * inv_mu(z))
    f50 = q(lambda z: (H - z) * inv_mu(z))
    f40 = q(lambda z: (H - z) * z * inv_mu(z)) - f10 / f20 * f50
    ua, ub = U1 - ly.alpha**2 * G / ly.viscosity[0], U2 - ly.alpha**2 * G / ly.viscosity[1]
    q19 = ly.thickness * (ua + ub) + H * ua + G * f40 + (ub - ua) * f50 / f20
    assert q_total(f.flow(h, G, U1, U2)) == pytest.approx(q19, rel=1e-12, abs=0)


def test_newtonian_layered_closed_forms():
    h = np.linspace(0.2, 2.0, 10) * C
    G = np.linspace(-5.0, 7.0, 10) * G0
    U1, U2 = 0.3 * U, U
    # no layers: the classical film
    r = film().flow(h, G, U1, U2)
    np.testing.assert_allclose(r.q_pressure, -G * h**3 / (12 * MU), rtol=1e-14)
    np.testing.assert_allclose(r.q_couette, h * (U1 + U2) / 2, rtol=1e-15)
    # immobile layers (alpha = 0): exactly a classical film of thickness h - 2 delta, plus delta (U1 + U2)
    d = 0.05 * C
    r = film(layers=BoundaryLayers(d, 10 * MU, 0.0)).flow(h, G, U1, U2)
    thin = film().flow(h - 2 * d, G, U1, U2)
    np.testing.assert_allclose(r.q_pressure, thin.q_pressure, rtol=1e-14)
    np.testing.assert_allclose(r.dqp_dG, thin.dqp_dG, rtol=1e-14)
    np.testing.assert_allclose(q_total(r), q_total(thin) + d * (U1 + U2), rtol=1e-14)
    # porous layers: against direct integration of the piecewise profile
    ly = PAPER_LAYERS
    f = film(layers=ly)
    for i in (2, 4, 9):  # h > 2 delta
        q_ref = ref_flow(h[i], G[i], U1, U2, MU, KAPPA, 1.0, ly.thickness, *ly.viscosity, ly.alpha)[0]
        assert q_total(f.flow(h[i], G[i], U1, U2)) == pytest.approx(q_ref, rel=1e-13, abs=0)
    # the Gecim kernel at mu_2 = mu_1 is the Newtonian closed form
    rg = film(Gecim(KAPPA, 1.0), ly).flow(h, G, U1, U2)
    rn = f.flow(h, G, U1, U2)
    for a, b in zip(rg, rn):
        np.testing.assert_allclose(a, b, rtol=1e-13)


@pytest.mark.parametrize("limit", ["mu_1", "mu_2"])
def test_gecim_tends_to_newtonian_limits(limit):
    """kappa -> inf: Newtonian mu_1, error ~ 1/kappa; kappa -> 0: Newtonian mu_2, error ~ kappa."""
    ly = PAPER_LAYERS
    h, G = np.array([0.5, 1.0, 1.7]) * C, np.array([4.0, -2.0, 9.0]) * G0
    mu_n = MU if limit == "mu_1" else RATIO * MU
    ref = film(layers=ly, mu=mu_n).flow(h, G, 0.0, U)  # same layers: alpha^2/mu_a,b are absolute
    stress = MU * U / C
    kappas = [1e6 * stress, 1e7 * stress] if limit == "mu_1" else [1e-6 * stress, 1e-7 * stress]
    errs = [np.max(np.abs(q_total(film(Gecim(k, RATIO), ly).flow(h, G, 0.0, U)) / q_total(ref) - 1))
            for k in kappas]
    assert errs[0] < 1e-5
    assert errs[0] / errs[1] == pytest.approx(10.0, rel=0.02, abs=0)


def test_quadrature_converges_geometrically():
    """Relative error of the slit flow against the closed form vs Gauss points per panel, for the hardest
    allowed law (mu_2/mu_1 = 0.05) at a wall stress of 3 kappa (the transition spans the film): geometric
    decrease (measured: a factor ~8 per added point, rho^2 with rho ~ 2.9 the Bernstein ellipse of the
    panels), down to rounding at 12 points."""
    G, H = -6 * KAPPA / C, C
    exact = slit_flow_gecim(G, H, MU, KAPPA, 0.05)
    ns = [2, 3, 4, 6, 8, 10, 12]
    errs = [abs(film(Gecim(KAPPA, 0.05), n=n).flow(H, G, 0.0, 0.0).q_pressure / exact - 1) for n in ns]
    assert all(b < a / 4 ** (m - n) for a, b, n, m in zip(errs, errs[1:], ns, ns[1:]))
    assert errs[2] / errs[-1] > 6.0**8  # n = 4 -> 12
    assert errs[0] > 1e-4 and errs[-1] < 2e-13


# --------------------------------------------------------------------------------------------------
# derivatives, scales, stresses, profile
# --------------------------------------------------------------------------------------------------

FD_CASES = [  # h/C, G/G0, U1/U, U2/U, delta/C, alpha/C, (mu_a, mu_b)/MU, rheology
    (1.0, -3.0, 0.0, 1.0, 0.2, 0.1, (10, 4), "gecim"),
    (0.6, 25.0, 0.0, 1.0, 0.2, 0.1, (10, 10), "gecim"),
    (1.4, 8.0, -0.5, 0.7, 0.0, 0.0, (1, 1), "gecim"),
    (0.8, 0.0, 0.0, 1.0, 0.1, 0.05, (2, 30), "gecim"),
    (0.9, -4.0, 0.0, 1.0, 0.1, 0.3, (1, 50), "gecim"),     # strongly asymmetric Darcy slip
    (0.3, 2.0, 0.0, 1.0, 0.2, 0.1, (10, 4), "gecim"),      # h < 2 delta: the layers share the gap
    (0.9, -6.0, 0.0, 1.0, 0.15, 0.1, (10, 4), "newtonian"),
]


@pytest.mark.parametrize("case", FD_CASES)
def test_derivatives_against_central_differences(case):
    hc, g, u1, u2, dc, ac, mus, rh = case
    rheo = Gecim(KAPPA, RATIO) if rh == "gecim" else Newtonian()
    f = film(rheo, BoundaryLayers(dc * C, tuple(m * MU for m in mus), ac * C))
    h, G, U1, U2 = hc * C, g * G0, u1 * U, u2 * U
    sc = (C, U)  # fixed scales: the finite differences must not move the kernels' reference scales
    r = f.flow(h, G, U1, U2, scales=sc)
    eG, eh = 1e-5 * max(abs(G), G0), 1e-6 * h
    fd_G = (f.flow(h, G + eG, U1, U2, sc).q_pressure - f.flow(h, G - eG, U1, U2, sc).q_pressure) / (2 * eG)
    fd_h = (f.flow(h + eh, G, U1, U2, sc).q_pressure - f.flow(h - eh, G, U1, U2, sc).q_pressure) / (2 * eh)
    assert float(r.dqp_dG) == pytest.approx(fd_G, rel=1e-6, abs=0)
    assert abs(float(r.dqp_dh) - fd_h) <= 1e-6 * max(abs(fd_h), 1e-3 * U)  # dq_p/dh = 0 at G = 0


def test_results_do_not_depend_on_the_kernel_scales():
    f = film(Gecim(KAPPA, RATIO), PAPER_LAYERS)
    h, G = np.array([0.3, 0.9, 1.8]) * C, np.array([10.0, -4.0, 0.5]) * G0
    a = f.flow(h, G, 0.0, U)
    for sc in [(1e-3, 1e-2), (3 * C, 40.0)]:
        for x, y in zip(a, f.flow(h, G, 0.0, U, scales=sc)):
            np.testing.assert_allclose(y, x, rtol=1e-13, atol=1e-15 * np.max(np.abs(x)))


def test_stresses_momentum_balance_and_newtonian_wall_stress():
    h, G = np.array([0.5, 1.0, 1.6]) * C, np.array([3.0, -1.0, 8.0]) * G0
    st = film(Gecim(KAPPA, RATIO), PAPER_LAYERS).stresses(h, G, 0.0, U)
    # the total shear stress is linear across the whole film (layers carry G delta through their matrix)
    np.testing.assert_allclose(st.upper_wall - st.lower_wall, G * h, rtol=1e-14)
    np.testing.assert_allclose(st.upper_interface - st.lower_interface, G * (h - 2 * PAPER_LAYERS.thickness),
                               rtol=1e-14)
    d = 0.1 * C  # immobile layers, Newtonian: wall stress mu dU/(h - 2 delta) + G h/2 at the upper wall
    st = film(layers=BoundaryLayers(d, 10 * MU, 0.0)).stresses(h, G, 0.0, U)
    np.testing.assert_allclose(st.upper_wall, MU * U / (h - 2 * d) + G * h / 2, rtol=1e-13)


def test_velocity_profile():
    ly = PAPER_LAYERS
    f = film(Gecim(KAPPA, RATIO), ly)
    h, G, U1, U2 = 1.2 * C, -7.0 * G0, 0.0, U
    d = ly.thickness
    ua, ub = U1 - ly.alpha**2 * G / ly.viscosity[0], U2 - ly.alpha**2 * G / ly.viscosity[1]
    np.testing.assert_allclose(f.velocity(h, G, U1, U2, [0.0, d / 2, d]), ua, rtol=1e-14)
    np.testing.assert_allclose(f.velocity(h, G, U1, U2, [h - d, h]), ub, rtol=1e-14)
    # continuous at the upper interface, integrates to the flow
    assert f.velocity(h, G, U1, U2, h - d - 1e-12 * h) == pytest.approx(ub, rel=1e-10, abs=0)
    q = integrate.quad(lambda z: float(f.velocity(h, G, U1, U2, z)), 0, h, points=[d, h - d], epsabs=0,
                       epsrel=1e-12)[0]
    assert q == pytest.approx(q_total(f.flow(h, G, U1, U2)), rel=1e-11, abs=0)
    # the interface stress is the bulk law at the profile's slope there
    e = 1e-6 * h
    u0, u1, u2 = f.velocity(h, G, U1, U2, [d, d + e, d + 2 * e])
    slope = (-3 * u0 + 4 * u1 - u2) / (2 * e)  # one-sided, second order
    tau = f.stresses(h, G, U1, U2).lower_interface
    assert f.rheology.viscosity(slope, MU) * slope == pytest.approx(tau, rel=1e-9, abs=0)


# --------------------------------------------------------------------------------------------------
# validation
# --------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("make, match", [
    (lambda: Gecim(-1.0, 0.5), r"kappa = -1\.0 \[Pa\].*\[1e-09, 1e\+12\] Pa"),
    (lambda: Gecim(float("inf"), 0.5), r"kappa = inf \[Pa\]"),
    (lambda: Gecim(1.0, 1.5), r"viscosity_ratio mu_2/mu_1 = 1\.5 \[-\].*\[0\.05, 1\]"),
    (lambda: Gecim(1.0, 0.0), r"viscosity_ratio mu_2/mu_1 = 0\.0"),
    (lambda: BoundaryLayers(-1e-9, 0.1, 0.0), r"thickness delta = -1e-09 \[m\].*\[0, 0\.001\] m"),
    (lambda: BoundaryLayers(1e-8, (0.1, -2.0), 0.0), r"viscosity mu_b \(upper layer\) = -2\.0 \[Pa s\]"),
    (lambda: BoundaryLayers(1e-8, 0.0, 0.0), r"viscosity mu_a \(lower layer\) = 0\.0 \[Pa s\]"),
    (lambda: BoundaryLayers(1e-8, (0.1, 0.2, 0.3), 0.0), r"viscosity = \(0\.1, 0\.2, 0\.3\) \[Pa s\]"),
    (lambda: BoundaryLayers(1e-8, 0.1, -1e-9), r"alpha = -1e-09 \[m\].*\[0, 0\.001\] m"),
    (lambda: BoundaryLayers(0.0, 0.1, 1e-9), r"alpha = 1e-09 \[m\].*\[0, 0\] m.*thickness > 0"),
    (lambda: LayeredFilm(0.0), r"viscosity mu_1 = 0\.0 \[Pa s\]"),
    (lambda: LayeredFilm(0.1, gauss_points=0), r"gauss_points = 0 \[-\]"),
    (lambda: LayeredFilm(0.1).flow([1e-6, -1e-6], 0.0, 0.0, 1.0), r"film thickness h = -1e-06 \[m\]"),
])
def test_validation_errors_name_the_parameter(make, match):
    with pytest.raises(ValueError, match=match):
        make()


# --------------------------------------------------------------------------------------------------
# the infinitely long slider bearing with layers (1-D modified Reynolds equation)
# --------------------------------------------------------------------------------------------------

def slider_load(f, h_out, K, length, speed, n=64):
    """Load per unit width of an inclined pad ``h = h_out (1 + K (1 - x/L))``, lower wall sliding at
    ``speed``: ``d q / dx = 0`` with ``q(h, dp/dx) = Q`` at Gauss points, ``p(0) = p(L) = 0``."""
    xg, wg = np.polynomial.legendre.leggauss(n)
    x, w = (xg + 1) * length / 2, wg * length / 2
    h = h_out * (1 + K * (1 - x / length))
    sc = (h_out, speed)

    def gradient(Q):
        G = np.zeros_like(h)
        for _ in range(50):  # Newton on q(h, G) = Q at every point
            r = f.flow(h, G, speed, 0.0, sc)
            dG = (q_total(r) - Q) / r.dqp_dG
            G -= dG
            if np.max(np.abs(dG)) <= 1e-15 * np.max(np.abs(G)):
                break
        return G

    Q = optimize.brentq(lambda Q: w @ gradient(Q), speed * h_out / 2, speed * h.max() / 2, xtol=1e-300,
                        rtol=8.9e-16)
    return w @ ((length - x) * gradient(Q))  # int p dx = int (L - x) dp/dx dx


def slider_closed_form(mu, speed, length, h_out, K):
    return 6 * mu * speed * length**2 / (K * h_out) ** 2 * (math.log1p(K) - 2 * K / (2 + K))


def test_slider_with_immobile_layers_is_the_classical_slider_on_the_thinner_film():
    h_out, K, length, d = 10e-6, 1.2, 0.02, 2e-6
    assert slider_load(film(), h_out, K, length, U) == pytest.approx(
        slider_closed_form(MU, U, length, h_out, K), rel=1e-12, abs=0)
    # the bulk film is h - 2 delta = (h_out - 2 delta)(1 + K' (1 - x/L)), K' = K h_out/(h_out - 2 delta)
    w = slider_load(film(layers=BoundaryLayers(d, 10 * MU, 0.0)), h_out, K, length, U)
    assert w == pytest.approx(slider_closed_form(MU, U, length, h_out - 2 * d, K * h_out / (h_out - 2 * d)),
                              rel=1e-12, abs=0)


def test_slider_gecim_load_between_its_newtonian_bounds():
    """Shear thinning lowers the load below the mu_1 film's and keeps it above the mu_2 film's; porous layers
    carry some flow and lower the load below the immobile layers' one."""
    h_out, K, length = 10e-6, 1.2, 0.02
    kappa = 0.65 * MU * U / h_out
    w1 = slider_closed_form(MU, U, length, h_out, K)
    wg = slider_load(film(Gecim(kappa, RATIO), n=8), h_out, K, length, U, n=24)
    assert RATIO * w1 < wg < w1
    d = 0.2 * h_out
    w_imm = slider_load(film(Gecim(kappa, RATIO), BoundaryLayers(d, 10 * MU, 0.0), n=8), h_out, K, length, U, 24)
    w_por = slider_load(film(Gecim(kappa, RATIO), BoundaryLayers(d, 10 * MU, 0.1 * h_out), n=8), h_out, K,
                        length, U, 24)
    assert wg < w_por < w_imm


# --------------------------------------------------------------------------------------------------
# the 2-D (vector) law: eq. (12) couples the directions through |gdot|
# --------------------------------------------------------------------------------------------------

def ref_flow_2d(h, G, U1, U2, mu1, kappa, r, delta=0.0, mu_a=1.0, mu_b=1.0, alpha=0.0):
    """Flow vector per unit width by root finding on the 2-vector tau_0 and scipy quad of the forward law
    (gdot parallel to tau, |gdot| from ``ref_rate``)."""
    G, U1, U2 = (np.asarray(v, dtype=float) for v in (G, U1, U2))
    ua, ub = U1 - alpha**2 * G / mu_a, U2 - alpha**2 * G / mu_b
    H = h - 2 * delta

    def gdot(t0, z):
        t = t0 + G * z
        m = math.hypot(*t)
        return t * (ref_rate(m, mu1, kappa, r) / m if m > 0 else 1 / mu1)

    def quad(fun, t0, power):
        zs = -(t0 @ G) / (G @ G)
        scale = H**power * max(np.abs(gdot(t0, z)).max() for z in (0, H))
        return np.array([integrate.quad(lambda z: fun(z)[a], 0, H, points=[zs] if 0 < zs < H else None,
                                        epsabs=1e-13 * scale, epsrel=1e-13, limit=200)[0] for a in (0, 1)])

    def jump(t0):
        return quad(lambda z: gdot(t0, z), t0, 1) - (ub - ua)

    sol = optimize.root(jump, mu1 * (ub - ua) / H - G * H / 2, method="hybr", tol=1e-15)
    t0 = sol.x
    return delta * (ua + ub) + H * ua + quad(lambda z: (H - z) * gdot(t0, z), t0, 2)


def rotate(v, a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]]) @ v


STATES_2D = [  # h/C, (Gx, Gy)/G0, U1/U, U2/U (vectors), layers, kappa/KAPPA
    (1.0, (-3.0, 2.0), (0.0, 0.0), (1.0, 0.0), PAPER_LAYERS, 1.0),
    (0.6, (25.0, -8.0), (0.0, 0.0), (1.0, 0.0), PAPER_LAYERS, 1.0),
    (1.3, (4.0, 6.0), (-0.3, 0.2), (0.5, 0.4), NO_LAYERS, 1.0),
    # |tau| passes near 0 (d0/H ~ 8e-3): without the grading about its branch points the error is 7e-10
    (1.0, (-6.0, 0.0), (0.0, 0.0), (0.0, 0.05), NO_LAYERS, 10.0),
]


def test_2d_law_reduces_to_the_1d_law():
    f = film(Gecim(KAPPA, RATIO), PAPER_LAYERS)
    for hc, g, u1, u2 in CASES:
        h, G, U1, U2 = hc * C, g * G0, u1 * U, u2 * U
        one = f.flow(h, G, U1, U2)
        two = f.flow_2d(h, [G, 0.0], [U1, 0.0], [U2, 0.0])
        for a, b in zip(one, (two.q_couette[0], two.q_pressure[0], two.dqp_dG[0, 0], two.dqp_dh[0])):
            assert b == pytest.approx(a, rel=1e-13, abs=0)
        assert two.q_pressure[1] == 0.0 and two.dqp_dG[0, 1] == 0.0 and two.dqp_dh[1] == 0.0


def test_2d_newtonian_layered_film_is_the_1d_law_in_each_direction():
    f = film(layers=PAPER_LAYERS)
    h = np.array([0.3, 0.9, 1.6]) * C
    G = np.array([[2.0, -1.0], [0.5, 4.0], [-3.0, 0.0]]) * G0
    U1, U2 = np.array([0.1, -0.2]) * U, np.array([1.0, 0.3]) * U
    r = f.flow_2d(h, G, U1, U2)
    for a in (0, 1):
        one = f.flow(h, G[:, a], U1[a], U2[a])
        for x, y in zip(one, (r.q_couette[:, a], r.q_pressure[:, a], r.dqp_dG[:, a, a], r.dqp_dh[:, a])):
            np.testing.assert_allclose(y, x, rtol=1e-14)
    np.testing.assert_array_equal(r.dqp_dG[:, 0, 1], 0.0)
    np.testing.assert_array_equal(r.dqp_dG[:, 1, 0], 0.0)


def test_2d_law_is_isotropic():
    f = film(Gecim(KAPPA, RATIO), PAPER_LAYERS)
    a = 0.7
    for hc, g, u1, u2, ly, _ in STATES_2D[:3]:
        G, U1, U2 = (np.array(v) * s for v, s in ((g, G0), (u1, U), (u2, U)))
        r0 = f.flow_2d(hc * C, G, U1, U2)
        r1 = f.flow_2d(hc * C, rotate(G, a), rotate(U1, a), rotate(U2, a))
        R = rotate(np.eye(2), a)
        np.testing.assert_allclose(r1.q_pressure, R @ r0.q_pressure, rtol=1e-12)
        np.testing.assert_allclose(r1.dqp_dG, R @ r0.dqp_dG @ R.T, rtol=1e-12, atol=1e-12 * np.abs(r0.dqp_dG).max())
        np.testing.assert_allclose(r1.dqp_dh, R @ r0.dqp_dh, rtol=1e-12)


@pytest.mark.parametrize("layers", [NO_LAYERS, PAPER_LAYERS])
def test_2d_small_gradients_on_a_sheared_film_see_tangent_and_secant_viscosities(layers):
    """Couette flow along x, G = 0: a gradient along the sliding sees the tangent viscosity d tau/d gdot,
    one across it the secant viscosity tau/gdot (closed forms of the Gecim law at gdot = dU/H)."""
    h, dU = 0.8 * C, U
    H = h - 2 * layers.thickness
    g = dU / H
    mu_s = MU * (KAPPA + RATIO * MU * g) / (KAPPA + MU * g)
    mu_t = MU * (KAPPA**2 + 2 * RATIO * MU * KAPPA * g + RATIO * MU**2 * g**2) / (KAPPA + MU * g) ** 2
    darcy = h / 2 * layers.alpha**2 * sum(1 / m for m in layers.viscosity)
    r = film(Gecim(KAPPA, RATIO), layers).flow_2d(h, [0.0, 0.0], [0.0, 0.0], [dU, 0.0])
    assert -r.dqp_dG[0, 0] == pytest.approx(H**3 / (12 * mu_t) + darcy, rel=1e-13, abs=0)
    assert -r.dqp_dG[1, 1] == pytest.approx(H**3 / (12 * mu_s) + darcy, rel=1e-13, abs=0)
    assert abs(r.dqp_dG[0, 1]) < 1e-15 * abs(r.dqp_dG[0, 0]) and abs(r.dqp_dG[1, 0]) < 1e-15 * abs(r.dqp_dG[0, 0])
    assert mu_t < mu_s < MU


@pytest.mark.parametrize("state", STATES_2D)
def test_2d_law_against_direct_integration(state):
    hc, g, u1, u2, ly, km = state
    h, G, U1, U2 = hc * C, np.array(g) * G0, np.array(u1) * U, np.array(u2) * U
    f = film(Gecim(km * KAPPA, RATIO), ly)
    r = f.flow_2d(h, G, U1, U2)
    ref = ref_flow_2d(h, G, U1, U2, MU, km * KAPPA, RATIO, ly.thickness, *ly.viscosity, ly.alpha)
    np.testing.assert_allclose(r.q_couette + r.q_pressure, ref, rtol=1e-12, atol=0)


@pytest.mark.parametrize("state", STATES_2D)
def test_2d_derivatives_against_central_differences(state):
    hc, g, u1, u2, ly, km = state
    h, G, U1, U2 = hc * C, np.array(g) * G0, np.array(u1) * U, np.array(u2) * U
    f = film(Gecim(km * KAPPA, RATIO), ly)
    sc = (C, U)
    r = f.flow_2d(h, G, U1, U2, sc)
    for b in (0, 1):
        e = 1e-5 * G0 * np.eye(2)[b]
        fd = (f.flow_2d(h, G + e, U1, U2, sc).q_pressure - f.flow_2d(h, G - e, U1, U2, sc).q_pressure) / (2e-5 * G0)
        np.testing.assert_allclose(r.dqp_dG[:, b], fd, rtol=1e-6, atol=1e-6 * np.abs(r.dqp_dG).max())
    eh = 1e-6 * h
    fd = (f.flow_2d(h + eh, G, U1, U2, sc).q_pressure - f.flow_2d(h - eh, G, U1, U2, sc).q_pressure) / (2 * eh)
    np.testing.assert_allclose(r.dqp_dh, fd, rtol=1e-6, atol=1e-6 * np.abs(fd).max())


def test_newton_stops_at_the_rounding_floor():
    """A state found by a 20000-point sweep: the Newtonian start is exact (r = 1) and the steps bounce at
    2.5e-14 of the stress scale; Newton must stop there, not run out of iterations (NaN)."""
    xg, wg = np.polynomial.legendre.leggauss(12)
    H, kappa = 0.27902214840656486, float.fromhex("0x1.2406b8966f164p-9")
    G = tuple(float.fromhex(v) for v in ("-0x1.8befa55e08867p-9", "0x1.1e9fb9ff29fccp-11"))
    du = tuple(float.fromhex(v) for v in ("-0x1.c3b4f7f66bacfp-5", "0x1.661036752bcf8p-9"))
    o = gecim_face_2d(H, *G, 0.0, 0.0, *du, 0.0, 0.0, 0.0, kappa, 1.0, xg, wg)
    t_newton = np.array(du) / H - np.array(G) * H / 2
    np.testing.assert_allclose(o[8:], t_newton, rtol=1e-13)


def test_newton_converges_over_a_parameter_sweep():
    """Newton from the Newtonian solution converges (velocity continuity to rounding; measured worst
    3e-16 in 1-D, 1e-14 in 2-D of the bound's scale) for random states: stresses over ~1e-6 .. 1e7 kappa,
    mu_2/mu_1 from 0.05 to 1, sliding and gradients in any direction."""
    rng = np.random.default_rng(4)
    xg, wg = np.polynomial.legendre.leggauss(12)
    for _ in range(400):
        H = rng.uniform(0.05, 2.0)
        G = rng.normal(size=2) * 10 ** rng.uniform(-3, 4)
        dU = rng.normal(size=2) * 10 ** rng.uniform(-3, 4)
        kappa, r = 10 ** rng.uniform(-3, 3), rng.choice([0.05, 0.2, RATIO, 1.0])
        t0 = gecim_face(H, G[0], 0.0, dU[0], 0.0, 0.0, 0.0, kappa, r, xg, wg)[3]
        jump = _moments(t0, G[0], H, H, kappa, r, xg, wg)[0]
        # rounding of the sums: the shear rates reach (|dU|/H + |G| H) / r, r = mu_2/mu_1
        assert abs(jump - dU[0]) <= 1e-13 * (abs(dU[0]) + abs(G[0]) * H * H) / r
        o = gecim_face_2d(H, G[0], G[1], 0.0, 0.0, dU[0], dU[1], 0.0, 0.0, 0.0, kappa, r, xg, wg)
        acc = np.empty(16)
        _moments_2d(o[8], o[9], G[0], G[1], H, kappa, r, xg, wg, acc)
        assert math.hypot(acc[0] - dU[0], acc[1] - dU[1]) <= 1e-13 * (math.hypot(*dU) + math.hypot(*G) * H * H) / r
