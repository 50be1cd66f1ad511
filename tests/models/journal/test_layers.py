"""Boundary layers of seed 004 (Newtonian bulk) inside every journal computation (issue 13).

The journal film's Poiseuille conductance becomes ``k = (H - 2 delta/C)^3/2 + 3 alpha^2 mu (1/mu_a + 1/mu_b) / C^2 H``
(kernels.conductances); the Couette flux stays ``H/2``. Checked against: the classical film (no layers:
identical to round-off), the exact mapping of immobile layers onto a classical bearing of clearance C - 2 delta,
the flow law of :mod:`transient.physics.layered` integrated by its own quadrature (Gecim with mu_2 = mu_1), the
orbit's mass balance, and the named event where the layers touch. The analytic Jacobians with layers are
checked against finite differences in tests/models/journal/test_journal_model.py (``layers`` parametrisation).
"""

import numpy as np
import pytest

from transient import BoundaryLayers, Gecim, JournalBearing, JournalOrbit, LayeredFilm, Newtonian
from transient.models.journal.bearing import omega
from transient.params.rho_kim import BEARING, ROTOR
from transient import Integration, LongRun, Recording

CL, MU, RPM = BEARING["clearance"], BEARING["viscosity"], 6000.0
GRID = (48, 8)


def bearing(**kw):
    return JournalBearing(**(BEARING | dict(grid=GRID) | kw))


def test_no_layers_is_the_classical_film_to_round_off():
    a = bearing().steady_state(0.6, RPM, 40.0)
    b = bearing(layers=BoundaryLayers(0.0, MU, 0.0)).steady_state(0.6, RPM, 40.0)
    np.testing.assert_array_equal(a.pressure, b.pressure)
    np.testing.assert_array_equal(a.force, b.force)


def test_the_conductance_is_the_flow_law_of_seed_004():
    """k of the journal kernels (dimensionless, p0 = 6 mu omega (R/C)^2) against the pressure flow of the layered
    film computed by the Gecim quadrature with mu_2 = mu_1 (Newtonian, but through the velocity-profile integrals,
    the Darcy slip and the continuity condition): k = 6 mu (-dq_p/dG) / C^3."""
    ly = BoundaryLayers(thickness=0.12 * CL, viscosity=(8 * MU, 30 * MU), alpha=0.07 * CL)
    b = bearing(layers=ly)
    f = b.film(RPM)
    X, Y = 0.45, -0.2
    f.residual(np.zeros(f.n), X, Y)
    h = f.H * CL
    law = LayeredFilm(MU, Gecim(kappa=1e3, viscosity_ratio=1.0), ly).flow(h, G=-1e9, U1=0.0, U2=omega(RPM) * b.radius)
    np.testing.assert_allclose(f.k, -6 * MU * law.dqp_dG / CL**3, rtol=1e-9)


@pytest.mark.parametrize("cavitation", ["reynolds", "elrod"])
def test_immobile_layers_are_a_bearing_of_clearance_c_minus_two_delta(cavitation):
    """alpha = 0: the bulk is h - 2 delta thick and the layers move with their walls; their Couette flux
    delta U is the same through every face, so it drops out of every cell balance, and the film is the
    classical one of clearance C - 2 delta at the same journal position (exact in the Reynolds film even
    with cavitation; the Elrod film flooded and incompressible)."""
    delta = 0.15 * CL
    kw = dict(cavitation=cavitation)
    e = 0.5 * CL  # the same absolute eccentricity
    if cavitation == "elrod":  # flooded: ends and groove at 30 MPa, nothing cavitates; nearly incompressible
        # (the force differs by 2.7e-6, 2.7e-7, 2.7e-8 at beta = 1e12, 1e13, 1e14 Pa: the compressible
        # content theta = 1 + p / beta makes the layers' Couette flux non-uniform, O(p / beta))
        kw |= dict(bulk_modulus=1e14, supply_pressure=3e7, ambient_pressure=3e7)
        e = 0.3 * CL
    lay = bearing(layers=BoundaryLayers(delta, MU, 0.0), **kw).steady_state(e / CL, RPM, 30.0)
    cla = bearing(**(kw | dict(clearance=CL - 2 * delta))).steady_state(e / (CL - 2 * delta), RPM, 30.0)
    if cavitation == "elrod":
        assert lay.pressure.min() > 1e6 and cla.pressure.min() > 1e6
    scale = np.abs(cla.pressure).max()
    assert np.abs(lay.pressure - cla.pressure).max() < 1e-7 * scale
    np.testing.assert_allclose(lay.force, cla.force, rtol=1e-7)


def test_layers_raise_the_load_and_their_darcy_flow_lowers_it():
    """Seed 004's finding at a fixed position: thicker immobile layers raise the load (the bulk is thinner);
    the Darcy flow through mobile layers gives some of it back."""
    loads = [np.hypot(*bearing(layers=ly).steady_state(0.6, RPM).force) for ly in
             (None, BoundaryLayers(0.05 * CL, 10 * MU, 0.0), BoundaryLayers(0.1 * CL, 10 * MU, 0.0),
              BoundaryLayers(0.1 * CL, 10 * MU, 0.1 * CL))]
    assert loads[0] < loads[1] < loads[2]
    assert loads[0] < loads[3] < loads[2]


def test_orbit_with_layers_conserves_mass_and_stops_where_the_layers_touch():
    ly = BoundaryLayers(thickness=0.1 * CL, viscosity=10 * MU, alpha=0.05 * CL)
    o = JournalOrbit(bearing(layers=ly), ROTOR["rotor_mass"], 0.01 * CL, ROTOR["load"], RPM)
    r = o.run(1, integration=Integration(rtol=1e-7, atol=1e-9),
              recording=Recording(outputs_per_revolution=400, record=("mass", "outflow")),
              long_run=LongRun(progress=False))
    mb = o.mass_balance(r)
    assert r.success and mb["relative"][0] < 1e-5, mb["relative"]
    # a journal thrown outwards at 10 C per radian of shaft rotation reaches the layers: a named event
    o = JournalOrbit(bearing(layers=BoundaryLayers(0.2 * CL, 10 * MU, 0.0)), ROTOR["rotor_mass"], 0.01 * CL,
                     ROTOR["load"], RPM)
    y = o.perturbed_start(0.3)
    y[o.film.n + 2] = 10.0
    r = o.run(0.5, integration=Integration(rtol=1e-5), long_run=LongRun(progress=False), y0=y)
    assert r.touched_at is not None and "boundary layers touch" in r.message, r.message
    assert np.hypot(r.x[-1], r.y[-1]) / CL == pytest.approx(0.6 - 1e-3, abs=1e-6)


def test_bad_layers_are_named():
    with pytest.raises(ValueError, match="layers.thickness"):
        bearing(layers=BoundaryLayers(0.5 * CL, MU, 0.0))
    with pytest.raises(TypeError, match="rheology"):
        bearing(rheology=Newtonian)  # the class, not an instance
    with pytest.raises(TypeError, match="layers"):
        bearing(layers=0.1)
    b = bearing(layers=BoundaryLayers(0.2 * CL, MU, 0.0))
    with pytest.raises(ValueError, match="eccentricity_ratio"):
        b.steady_state(0.65, RPM)


def test_seed_004_findings(tmp_path, scenario_loader):
    """The scenario (quick grid), with the Newtonian and with the Gecim bulk: thicker layers raise the pressure
    strongly, more for thicker layers; the layer viscosity matters less than the thickness (2 -> 100 mu moves the
    load less than 0.1 -> 0.2 h_min does); the Gecim bulk carries 0.57..1 of the Newtonian load and less friction;
    the interface shear grows as the layers become immobile (Figs. 9-11: mu_ab up, alpha down)."""

    data = scenario_loader("journal_layers").main(["--quick", "--out", str(tmp_path)])
    c = data["cases"]
    peaks = [c["base"]["peak"]] + [r["mobile"]["peak"] for r in c["thickness"]]
    assert all(b > 1.3 * a for a, b in zip(peaks[:-1], peaks[1:])), peaks
    loads_mu = [r["load_N"] for r in c["viscosity"]]
    thick = [r["mobile"]["load_N"] for r in c["thickness"]]
    assert loads_mu[-1] - loads_mu[0] < 0.5 * (thick[1] - thick[0])
    assert all(r["darcy_share"] < 0 for r in c["thickness"])  # the Darcy flow relieves the film
    g = data["gecim"]
    peaks = [g["base"]["gecim"]["peak"]] + [r["gecim"]["peak"] for r in g["thickness"]]
    assert all(b > 1.3 * a for a, b in zip(peaks[:-1], peaks[1:])), peaks
    loads_mu = [r["load_N"] for r in g["viscosity"]]
    thick = [r["gecim"]["load_N"] for r in g["thickness"]]
    assert loads_mu[-1] - loads_mu[0] < 0.5 * (thick[1] - thick[0])
    assert all(0.57 < r["thinning_load_ratio"] < 1.0 for r in g["thickness"])
    assert g["base"]["gecim"]["friction_N"] < g["base"]["newtonian"]["friction_N"]
    shear = [np.abs(r["interface_lower_Pa"]).max() for r in g["immobility"]]
    assert shear[0] < shear[1] < shear[2] and shear[3] < shear[4], shear  # mu_ab 2 < 10 < 100; alpha 0.05 > 0
    for name in ("layers.png", "gecim.png", "gecim_fields.png", "immobility.png", "dynamics.png"):
        assert (tmp_path / name).exists()


@pytest.mark.parametrize("layers", [None, BoundaryLayers(0.2 * CL, 10 * MU, 0.0), BoundaryLayers(0.2 * CL, 10 * MU, 0.05 * CL)])
def test_concentric_friction_is_petroff(layers):
    """Concentric, flooded film (no pressure gradient): the friction is Petroff's mu U (2 pi R L) / (C - 2 delta),
    exactly (layers of any mobility move with their walls when the pressure is uniform)."""
    b = bearing(groove=None, ambient_pressure=1e5, supply_pressure=1e5, layers=layers)
    s = b.steady_state(0.0, RPM)
    gap = CL - (0.0 if layers is None else 2 * layers.thickness)
    petroff = MU * omega(RPM) * b.radius / gap * 2 * np.pi * b.radius * b.length
    assert s.friction_force == pytest.approx(petroff, rel=1e-12)


def test_velocity_profile_and_saved_state(tmp_path):
    """The velocity across the film at a cell: the journal's speed at z = 0 and rest at z = h (no layers); with
    immobile layers plug flow in both (journal speed over delta, rest over the last delta); its integral is the
    flow of the law (Couette h U/2 plus the pressure flow). The state saves and loads with the new fields."""
    from transient import load_result

    for ly in (None, BoundaryLayers(0.1 * CL, 10 * MU, 0.0)):
        s = bearing(layers=ly).steady_state(0.6, RPM)
        z, v = s.velocity_profile(120.0, points=2001)
        U = s.sliding_speed
        assert v[0] == pytest.approx(U, rel=1e-12) and abs(v[-1]) < 1e-12 * U
        if ly is not None:
            inner = z <= ly.thickness
            outer = z >= z[-1] - ly.thickness
            assert np.allclose(v[inner], U, rtol=1e-12) and np.allclose(v[outer], 0.0, atol=1e-12 * U)
        col = int(np.argmin(np.abs(s.angle_deg - 120.0)))
        h, G = s.film_thickness[0, col], s.pressure_gradient[0, col]
        law = LayeredFilm(MU, Gecim(kappa=1e12, viscosity_ratio=1.0), ly or BoundaryLayers(0.0, MU, 0.0)).flow(h, G, U, 0.0)
        q = np.trapezoid(v, z)
        assert q == pytest.approx(float(law.q_couette + law.q_pressure), rel=1e-6)
    s.save(tmp_path / "state.npz")
    r = load_result(tmp_path / "state.npz")
    assert r.friction_force == s.friction_force and r.layers == s.layers
    np.testing.assert_array_equal(r.film_thickness, s.film_thickness)
