"""The shear-thinning (Gecim) bulk of seed 004 inside the journal film (issue 13; models/journal/gecim_film.py).

Checked against: the classical film in the Newtonian limit (second-order convergence of the difference, which
is the face-film discretisation), the exact mapping of immobile layers onto a bearing of clearance C - 2 delta
(which also checks every scale: kappa*, p0, the gradient factor 6), the bounds set by the two viscosities, the
analytic Jacobian of the Reynolds-condition film (the Elrod film's ODE, DAE and content Jacobians are in
tests/models/journal/test_journal_model.py, ``gecim`` case), the orbit's mass balance and bad input.
"""

import numpy as np
import pytest

from transient import BoundaryLayers, Gecim, Integration, JournalBearing, JournalOrbit, LongRun, Recording
from transient.models.journal.bearing import Groove, omega
from transient.params.rho_kim import BEARING, ROTOR

CL, MU, RPM = BEARING["clearance"], BEARING["viscosity"], 6000.0
R = 0.5 * BEARING["diameter"]
KAPPA = 0.65 * MU * omega(RPM) * R / CL  # the paper's kappa* = kappa C / (mu_1 omega R) = 0.65
GECIM = Gecim(kappa=KAPPA, viscosity_ratio=0.57)
FLOODED = dict(bulk_modulus=1e13, supply_pressure=3e7, ambient_pressure=3e7)


def bearing(grid=(48, 8), **kw):
    return JournalBearing(**(BEARING | dict(grid=grid) | kw))


@pytest.mark.parametrize("cavitation, kw", [("reynolds", dict(groove=None)), ("elrod", FLOODED)])
def test_newtonian_limit_converges_to_the_classical_film_at_second_order(cavitation, kw):
    """mu_2 = mu_1 (and kappa far above every stress) is a Newtonian bulk; the Gecim path evaluates the law at
    the face film (H_L + H_R)/2 where the classical film averages the conductances, so the two differ by
    O(dphi^2): measured 6.0e-4, 1.5e-4, 3.8e-5 (Reynolds) on 24x4, 48x8, 96x16."""
    diffs = []
    for grid in ((24, 4), (48, 8), (96, 16)):
        a = bearing(grid, cavitation=cavitation, **kw).steady_state(0.5, RPM, 30.0)
        b = bearing(grid, cavitation=cavitation, rheology=Gecim(kappa=1e12, viscosity_ratio=1.0),
                    **kw).steady_state(0.5, RPM, 30.0)
        diffs.append(abs(b.load / a.load - 1.0))
    assert diffs[0] < 1e-3
    for coarse, fine in zip(diffs[:-1], diffs[1:]):
        assert 3.5 < coarse / fine < 4.5, diffs


@pytest.mark.parametrize("cavitation", ["reynolds", "elrod"])
def test_immobile_layers_on_a_gecim_bulk_are_a_bearing_of_clearance_c_minus_two_delta(cavitation):
    """alpha = 0: whatever the bulk's rheology the layers move with their walls, so the film is the layer-free
    Gecim film of clearance C - 2 delta at the same absolute eccentricity (same kappa in Pa; p0, kappa* and
    the face gradients all change with C). Exact in the Reynolds film; O(p/beta) in the flooded Elrod film."""
    delta = 0.15 * CL
    kw = dict(cavitation=cavitation, rheology=GECIM)
    e = 0.5 * CL
    tol = 1e-7
    if cavitation == "elrod":
        kw |= dict(bulk_modulus=1e14, supply_pressure=3e7, ambient_pressure=3e7)
        e = 0.3 * CL
        tol = 1e-6
    lay = bearing(layers=BoundaryLayers(delta, MU, 0.0), **kw).steady_state(e / CL, RPM, 30.0)
    cla = bearing(**(kw | dict(clearance=CL - 2 * delta))).steady_state(e / (CL - 2 * delta), RPM, 30.0)
    scale = np.abs(cla.pressure).max()
    assert np.abs(lay.pressure - cla.pressure).max() < tol * scale
    np.testing.assert_allclose(lay.force, cla.force, rtol=tol)


def test_shear_thinning_load_lies_between_the_two_viscosities():
    """The Gecim viscosity lies in [mu_2, mu_1] everywhere: the load of the shear-thinning film lies between
    those of Newtonian films of viscosity mu_2 and mu_1, and a larger kappa (less thinning) raises it."""
    loads = [bearing(cavitation="reynolds", groove=None, **kw).steady_state(0.6, RPM).load for kw in (
        dict(viscosity=0.57 * MU), dict(rheology=GECIM), dict(rheology=Gecim(kappa=10 * KAPPA, viscosity_ratio=0.57)),
        dict())]
    assert loads[0] < loads[1] < loads[2] < loads[3], loads


def test_reynolds_film_jacobian_matches_finite_differences(fd_jacobian):
    """dG/dP (no longer affine) and the journal columns of the Reynolds-condition film with a Gecim bulk and
    mobile layers, at a solved pressure with cavitated cells; nothing outside the 9-point pattern."""
    b = bearing((16, 4), cavitation="reynolds", rheology=GECIM,
                layers=BoundaryLayers(0.1 * CL, (10 * MU, 20 * MU), 0.05 * CL))
    f = b.film(RPM)
    n = f.n
    q = np.array([0.5, 0.3, 0.05, -0.04])
    P, _ = f.solve(*q)
    assert np.any(P[f.free] == 0.0) and np.any(P[f.free] > 0.0)
    P = P + 0.05 * np.cos(np.arange(n))  # off the solution: the Jacobian must hold anywhere
    M = f.op.matrix(f.jacobian_data(P, *q)).toarray()
    pattern = f.op.matrix(np.ones(f.op.nnz)).toarray() != 0
    Ju = fd_jacobian(lambda v: f.residual(v, *q).copy(), P, n, 1e-5, relative=False)
    Jq = fd_jacobian(lambda v: f.residual(P, *v).copy(), q, n, 1e-6, relative=False)
    for an, fd, pat in ((M[:n, :n], Ju, pattern[:n, :n]), (M[:n, n:n + 4], Jq, pattern[:n, n:n + 4])):
        scale = np.abs(an).max(axis=0)
        assert float((np.abs(fd - an).max(axis=0) / scale).max()) < 1e-6
        assert np.all(np.abs(fd[~pat]) < 1e-12 * scale.max())
    assert np.abs(M[:n, :n][pattern[:n, :n] & ~_five_point(f)]).max() > 0  # the corner entries are used


def _five_point(f):
    from transient.fv.stencil import Stencil

    st = Stencil(f.op.grid, f.op.n_extra)
    return st.to_matrix(np.ones(st.nnz)).toarray()[:f.n, :f.n] != 0


def test_orbit_with_a_gecim_bulk_conserves_mass():
    """One revolution of the small orbit with a Gecim bulk and mobile layers (Elrod film, IDA): the film
    content changes by exactly what flows through the ends and the groove (relative 1e-5 at rtol 1e-7)."""
    ly = BoundaryLayers(thickness=0.1 * CL, viscosity=10 * MU, alpha=0.05 * CL)
    o = JournalOrbit(bearing((32, 6), layers=ly, rheology=GECIM), ROTOR["rotor_mass"], 0.01 * CL, ROTOR["load"], RPM)
    r = o.run(1, integration=Integration(rtol=1e-7, atol=1e-9),
              recording=Recording(outputs_per_revolution=200, record=("mass", "outflow")),
              long_run=LongRun(progress=False))
    mb = o.mass_balance(r)
    assert r.success and mb["relative"][0] < 1e-5, mb["relative"]


def test_bad_rheology_is_named():
    with pytest.raises(TypeError, match="rheology"):
        bearing(rheology="gecim")
    with pytest.raises(ValueError, match="kappa"):
        Gecim(kappa=-1.0, viscosity_ratio=0.5)
    with pytest.raises(ValueError, match="viscosity_ratio"):
        Gecim(kappa=1e4, viscosity_ratio=1.5)
    assert bearing(rheology=GECIM).parameters()["rheology"] == dict(kappa=KAPPA, viscosity_ratio=0.57)
    assert bearing(groove=Groove()).parameters()["rheology"] is None


def test_velocity_profile_2d_integrates_to_the_flow_and_interface_shear_is_the_law():
    """The 2-D velocity across a layered Gecim film integrates to the 2-D flow; FilmState's interface shear is the
    law's interface stress at the cell's gradients; its velocity profile starts at the journal speed plus the slip."""
    from transient import LayeredFilm

    law = LayeredFilm(MU, GECIM, BoundaryLayers(0.1 * CL, 0.3, 0.05 * CL))
    h, G, U = 0.6 * CL, np.array([-3e9, 1e9]), np.array([omega(RPM) * R, 0.0])
    z = np.linspace(0.0, h, 40001)
    u = law.velocity_2d(h, G, U, (0.0, 0.0), z)
    fl = law.flow_2d(h, G, U, (0.0, 0.0))
    np.testing.assert_allclose(np.trapezoid(u, z, axis=0), fl.q_couette + fl.q_pressure, rtol=1e-8)
    s = bearing(layers=BoundaryLayers(0.1 * CL, 10 * MU, 0.05 * CL), rheology=GECIM).steady_state(0.6, RPM)
    lower, upper = s.interface_shear(0)
    k = int(np.argmax(s.pressure[0]))
    ref = law.__class__(MU, GECIM, BoundaryLayers(0.1 * CL, 10 * MU, 0.05 * CL)).stresses_2d(
        s.film_thickness[0, k], (s.pressure_gradient[0, k], s.axial_pressure_gradient[0, k]), U, (0.0, 0.0))
    assert lower[k] == pytest.approx(ref.lower_interface[0], rel=1e-12)
    assert upper[k] == pytest.approx(ref.upper_interface[0], rel=1e-12)
    zz, uu = s.velocity_profile(float(s.angle_deg[k]), 0, 11)
    assert uu[0] == pytest.approx(U[0], rel=1e-2) and abs(uu[-1]) < 1e-2 * U[0]


def _long_reference(eps, law, U):
    """Infinitely long bearing (h = C (1 + eps cos theta)), film from the maximum film (theta = 0, p = 0) to the
    Swift-Stieber rupture theta_2 (p = dp/dtheta = 0), with the 1-D layered law (``law``, SI): every section
    carries the rupture's Couette flow, ``h U/2 + q_p(h, G) = h_2 U/2``, solved for ``G = dp/dx`` by Newton on the
    law; ``theta_2`` from ``p(theta_2) = R int G dtheta = 0``. Force per unit length [N/m] by parts,
    ``int p (cos, sin) R dtheta = R^2 int G (-sin, cos) dtheta`` (200-point Gauss-Legendre)."""
    from scipy.optimize import brentq

    x, w = np.polynomial.legendre.leggauss(200)

    def gradient(t, t2):
        h, h2 = CL * (1 + eps * np.cos(t)), CL * (1 + eps * np.cos(t2))
        target = 0.5 * (h2 - h) * U
        G = np.zeros_like(t)
        for _ in range(60):
            fl = law.flow(h, G, U, 0.0)
            G = G - (fl.q_pressure - target) / fl.dqp_dG
        assert np.all(np.abs(law.flow(h, G, U, 0.0).q_pressure - target) <= 1e-12 * np.abs(U * CL))
        return G

    def nodes(t2):
        return 0.5 * t2 * (x + 1), 0.5 * t2 * w

    def p_end(t2):
        t, wt = nodes(t2)
        return R * np.sum(wt * gradient(t, t2))

    t2 = brentq(p_end, np.pi + 1e-6, 2 * np.pi - 1e-6, xtol=1e-13)
    t, wt = nodes(t2)
    G = gradient(t, t2)
    return R * R * np.array([np.sum(wt * G * -np.sin(t)), np.sum(wt * G * np.cos(t))])


@pytest.mark.parametrize("rheology", [None, GECIM], ids=["newtonian", "gecim"])
def test_long_bearing_with_layers(rheology):
    """The journal film on one axial cell between symmetry faces (no end flow: the infinitely long bearing) with
    mobile layers on a Newtonian or a Gecim bulk, Reynolds condition, against the 1-D quadrature of the layered
    law (no axial gradient: the 2-D law is the 1-D one). Force error measured on 120 / 240 / 480 cells: Newtonian
    1.7e-3 / 4.3e-4 / 1.1e-4, Gecim 6.2e-4 / 2.3e-4 / 4.2e-5 (second order; the rupture point is not a node)."""
    from transient.fv.grid import Axis, Grid2D
    from transient import LayeredFilm, Newtonian

    eps, ly = 0.6, BoundaryLayers(0.1 * CL, 10 * MU, 0.05 * CL)
    U = omega(RPM) * R
    ref = _long_reference(eps, LayeredFilm(MU, rheology or Newtonian(), ly), U)
    errs = []
    for n in (120, 240):
        b = bearing((n, 1), cavitation="reynolds", supply_pressure=0.0, groove=Groove(0.0, 0.1), rheology=rheology,
                    layers=ly)
        z = Axis.uniform(1, 1.0, lower="symmetry", upper="symmetry", name="z")  # half length L/(2R) = 1
        b.grid = Grid2D(b.grid.x, z, fixed=b.grid.fixed, fixed_values=0.0)
        f = b.film(RPM)
        P, _ = f.solve(eps, 0.0)
        F = np.array(f.force(P, eps, 0.0)) * f.p0 * R / 2.0  # [N/m]: dimensionless force x p0 R^2 / (2 R)
        errs.append(np.hypot(*(F - ref)) / np.hypot(*ref))
    assert errs[1] < 1e-3 and errs[1] < 0.5 * errs[0], errs


@pytest.mark.parametrize("rheology, layers", [(None, None), (GECIM, BoundaryLayers(0.1 * CL, 10 * MU, 0.05 * CL))],
                         ids=["newtonian", "gecim-layers"])
def test_journal_and_bearing_friction_differ_by_the_pressure_moment(rheology, layers):
    """Torque balance of the film: the journal's drag less the bearing's equals the moment of the pressure force
    about the journal centre over R, ``(X F_y - Y F_x) / R`` (``tau(h) - tau(0) = G h`` integrates by parts to
    ``-int p dh/dx``). Reynolds film (full content everywhere): measured 0.29 % / 0.07 % off on 48x8 / 96x16
    (Newtonian)."""
    diffs = []
    for grid in ((48, 8), (96, 16)):
        s = bearing(grid, cavitation="reynolds", groove=None, rheology=rheology, layers=layers).steady_state(
            0.6, RPM, 40.0)
        (X, Y), (Fx, Fy) = s.position, s.force
        moment = (X * Fy - Y * Fx) / R
        assert s.friction_force > s.bearing_friction_force > 0
        diffs.append(abs((s.friction_force - s.bearing_friction_force) / moment - 1.0))
    assert diffs[1] < 5e-3 and diffs[1] < 0.5 * diffs[0], diffs


def test_stiffness_and_damping_with_a_gecim_bulk_match_finite_differences():
    """K and C of the Elrod film with a Gecim bulk and mobile layers: the implicit-differentiation sensitivities
    (9-point Jacobian) against central differences of the steady solve (step 1e-6): measured 1.9e-9."""
    b = bearing((48, 8), rheology=GECIM, layers=BoundaryLayers(0.1 * CL, 10 * MU, 0.05 * CL))
    f = b.film(RPM)
    X, Y, h = 0.5, 0.3, 1e-6
    u, _ = f.solve(X, Y)
    _, dF_dx, dF_dv = f.force_sensitivity(u, X, Y)
    fd = np.zeros((2, 4))
    for j, step in enumerate(np.eye(4) * h):
        dx, dy, vx, vy = step
        plus = np.array(f.force(f.solve(X + dx, Y + dy, vx, vy, u0=u)[0], X + dx, Y + dy))
        minus = np.array(f.force(f.solve(X - dx, Y - dy, -vx, -vy, u0=u)[0], X - dx, Y - dy))
        fd[:, j] = (plus - minus) / (2 * h)
    an = np.hstack([dF_dx, dF_dv])
    assert np.abs(an - fd).max() < 1e-6 * np.abs(an).max()
