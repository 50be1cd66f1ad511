"""The shear-thinning (Gecim) bulk of seed 004 inside the journal film (issue 13; models/journal/gecim_film.py).

Checked against: the classical film in the Newtonian limit (second-order convergence of the difference, which
is the face-film discretisation), the exact mapping of immobile layers onto a bearing of clearance C - 2 delta
(which also checks every scale: kappa*, p0, the gradient factor 6), the bounds set by the two viscosities, the
analytic Jacobian of the Reynolds-condition film (the Elrod film's ODE, DAE and content Jacobians are in
tests/test_journal_model.py, ``gecim`` case), the orbit's mass balance and bad input.
"""

import numpy as np
import pytest

from fd_jacobian import central_jacobian
from transient import BoundaryLayers, Gecim, JournalBearing, JournalOrbit
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


def test_reynolds_film_jacobian_matches_finite_differences():
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
    Ju = central_jacobian(lambda v: f.residual(v, *q).copy(), P, n, 1e-5, relative=False)
    Jq = central_jacobian(lambda v: f.residual(P, *v).copy(), q, n, 1e-6, relative=False)
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
    r = o.run(1, rtol=1e-7, atol=1e-9, outputs_per_revolution=200, record=("mass", "outflow"), progress=False)
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
