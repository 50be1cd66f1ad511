"""The orbit of a rough journal bearing (mixed lubrication in the time domain): the kernels against the steady rough
film and finite differences, the smooth limit, the long-time limit, mass conservation, IDA against BDF2, the speed
law and the contact records."""

import math
import warnings

import numpy as np
import pytest

from transient import JournalBearing, JournalOrbit, Roughness, steel_asperity_contact
from transient.models.journal.film import read_only
from transient.models.journal.rough_orbit import (rough_bdf2_residual, rough_cell_fields, rough_dae_jacobian,
                                                  rough_dae_residual, rough_newton_jacobian, rough_to_state)
from transient.models.journal.speed_law import shaft_speed, speed_knots
from transient.models.journal.roughness import contact_pressure, rough_coefficients
from transient.models.journal.scales import Rotor
from transient.params.rho_kim import BEARING
from transient.solvers.settings import Integration, Recording

GRID = (36, 6)


def rough(sigma, grid=GRID, **kw):
    """The Rho & Kim bearing with steel asperities of composite roughness ``sigma`` [m], streaks along the rotation
    (gamma 3) and a rougher journal (the shear flow factor acts)."""
    r = Roughness(steel_asperity_contact(sigma), gamma=3.0, boundary_friction=0.12, journal_variance_share=0.8)
    return JournalBearing(**BEARING, grid=grid, roughness=r, **kw)


MASS = 500.0  # [kg] the rotor whose weight is the 5 kN load


@pytest.fixture(scope="module")
def mixed():
    """A 500 kg rotor under 5 kN at 60 rpm on 24 x 4 cells: the asperities carry a third of the load (h_min about
    0.64 sigma)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # the contact pressure is above the isoviscous film's range
        o = JournalOrbit(rough(1e-6, grid=(24, 4)), rotor_mass=MASS, unbalance=0.0, load=5000.0, speed_rpm=60.0)
        o.equilibrium()
    return o


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return f(*a, **kw)


def test_cell_coefficients_are_the_steady_films():
    """The orbit's numba coefficients against the steady film's (roughness.rough_coefficients, contact_pressure):
    the fits to rounding, the tabulated Greenwood-Tripp pressure to 1e-9 of its value at contact, over h / sigma
    from -1 (below the fits' floor) to 12."""
    o = JournalOrbit(rough(2e-6), rotor_mass=10.0, unbalance=0.0, load=100.0, speed_rpm=3000.0)
    sig = 2e-6 / o.bearing.clearance
    H = sig * np.linspace(-1.0, 12.0, 263)
    rc = rough_coefficients(H, o.bearing.roughness, o.bearing.clearance)
    k, c = np.empty(H.size), np.empty(H.size)
    r = o.rough._replace(**{f: np.zeros(H.size) for f in ("kz", "dkx", "dkz", "dcx", "mean_gap", "phi_c", "dphi_c",
                                                          "pa", "dpa")})
    rough_cell_fields(H, r, k, c)
    for mine, ref in ((k, rc.kx), (r.kz, rc.kz), (c, rc.cx), (r.dkx, rc.dkx), (r.dkz, rc.dkz), (r.dcx, rc.dcx),
                      (r.mean_gap, rc.mean_gap), (r.phi_c, rc.phi_c), (r.dphi_c, rc.dphi_c)):
        np.testing.assert_allclose(mine, ref, rtol=1e-12, atol=1e-15 * np.max(np.abs(ref)))
    pa, dpa = contact_pressure(H, o.bearing.roughness, o.bearing.clearance)
    p0 = o.film.p0
    np.testing.assert_allclose(r.pa * p0, pa, rtol=1e-7, atol=1e-9 * pa[np.argmin(np.abs(H))])
    np.testing.assert_allclose(r.dpa * p0, dpa, rtol=1e-7, atol=1e-9 * np.max(np.abs(dpa)))


def test_ida_jacobian_matches_finite_differences(mixed, fd_jacobian):
    """dF/dy + cj dF/dy' of the rough IDA residual against central differences, in contact, the journal moving and
    the shaft accelerating (speed law), the content rate arbitrary: film rows, the rotor rows with the contact
    stiffness."""
    o = JournalOrbit(mixed.bearing, MASS, 1e-6, 5000.0, 60.0, speed_profile=((0.0, 30.0), (1.0, 90.0)))
    f, n = o.film, o.film.n
    y = mixed.initial_state()
    y[n:] += [0.002, -0.001, 0.01, -0.02]
    yp = 0.01 * np.random.default_rng(3).standard_normal(o.n)
    rotor, tau, cj = Rotor(o.kappa, o.wbar, o.ebar, f.sym), 0.3 * f.omega, 7.0

    def F(v):
        out = np.empty(o.n)
        rough_dae_residual(tau, read_only(v), read_only(yp + cj * (v - y)), out, f.switch, rotor, f.geo, f.fields,
                           f.fv, o.rough)
        return out

    data = np.zeros(f.op.nnz)
    rough_dae_jacobian(tau, read_only(y), read_only(yp), cj, data, f.switch, rotor, f.geo, f.fields, f.extras, f.fv,
                       o.rough)
    J = f.op.matrix(data).toarray()
    J_fd = fd_jacobian(F, y, o.n, step=1e-7)
    scale = np.max(np.abs(J_fd), axis=1, keepdims=True)
    assert np.max(np.abs(J - J_fd) / scale) < 1e-5
    assert abs(J[n + 2, n]) > 10 * np.max(np.abs(J[n + 2, :n]))  # the contact stiffness is there and dominates


def test_bdf2_jacobian_matches_finite_differences(mixed, fd_jacobian):
    """The BDF2 Newton's Jacobian (in its variables z = [u, X, Y, VX, VY], m = h_T C(u)) against central
    differences of the content residual F(to_state(z), cj to_state(z) + b)."""
    o = mixed
    f, n = o.film, o.film.n
    args = o.bdf2_model().args
    z = o.initial_state()
    z[n:] += [0.002, -0.001, 0.01, -0.02]
    b = 0.01 * np.random.default_rng(4).standard_normal(o.n)
    cj, t = 5.0, 0.7

    def F(v):
        y, out = np.empty(o.n), np.empty(o.n)
        rough_to_state(v, y, args)
        rough_bdf2_residual(t, y, cj * y + b, out, args)
        return out

    y = np.empty(o.n)
    rough_to_state(z, y, args)
    data = np.zeros(f.op.nnz)
    rough_newton_jacobian(t, y, cj * y + b, cj, data, args)
    J = f.op.matrix(data).toarray()
    J_fd = fd_jacobian(F, z, o.n, step=1e-7)
    scale = np.max(np.abs(J_fd), axis=1, keepdims=True)
    assert np.max(np.abs(J - J_fd) / scale) < 1e-5


def test_vanishing_roughness_is_the_smooth_orbit():
    """sigma = 1 nm on C = 80 um (h / sigma >= 1000): every rough coefficient is the smooth one to rounding and the
    asperities carry nothing, so the rough orbit (IDA, from the same start) is today's smooth orbit: 0.3 revolution
    of the Rho & Kim rotor at 3000 rpm, the positions within 1e-9 C."""
    smooth = JournalBearing(**BEARING, grid=GRID)
    kw = dict(rotor_mass=100.0, unbalance=8e-6, load=981.0, speed_rpm=3000.0)
    a, b = JournalOrbit(smooth, **kw), JournalOrbit(rough(1e-9), **kw)
    y0 = a.initial_state()
    rec = Recording(outputs_per_revolution=20, record=("friction_torque", "contact_load"))
    ra = a.run(0.3, y0=y0, recording=rec)
    rb = b.run(0.3, y0=y0, recording=rec)
    assert ra.success and rb.success
    C = smooth.clearance
    np.testing.assert_allclose(rb.x, ra.x, rtol=0, atol=1e-9 * C)
    np.testing.assert_allclose(rb.y, ra.y, rtol=0, atol=1e-9 * C)
    assert np.all(rb.contact_load == 0.0) and rb.contact_events == []
    np.testing.assert_allclose(rb.friction_torque, ra.friction_torque, rtol=1e-8)


@pytest.mark.slow  # a stiff creep back into contact: 4-5 s of CPU each
@pytest.mark.parametrize("method", ["ida", "bdf2"])
def test_long_time_limit_is_the_steady_mixed_equilibrium(mixed, method):
    """Released 0.01 C off the equilibrium, the journal settles where the steady mixed solve puts it, the
    asperities carrying 36 % of the load: position to 1e-6 C, contact load and friction torque to 1e-5."""
    o, e = mixed, mixed.equilibrium()
    assert 0.2 * o.load < e.contact_load < 0.8 * o.load
    r = quiet(o.run, 1.0, y0=o.perturbed_start(-0.01), integration=Integration(method=method),
              recording=Recording(outputs_per_revolution=20, record=("friction_torque", "contact_load")))
    assert r.success
    C = o.bearing.clearance
    assert np.hypot(r.x[-1] - e.position[0], r.y[-1] - e.position[1]) < 1e-6 * C
    assert r.contact_load[-1] == pytest.approx(e.contact_load, rel=1e-5)
    assert r.friction_torque[-1] == pytest.approx(e.friction_torque, rel=1e-5)
    assert r.contact_events == [(0.0, "begins")]  # in contact throughout (h_min / sigma < 3)
    assert r.peak_contact_pressure == pytest.approx(np.max(r.contact_pressure))


@pytest.mark.parametrize("method", ["ida", "bdf2"])
def test_mass_is_conserved_through_contact(mixed, method):
    """A whirling journal in contact (unbalance 20 um): over a revolution the film's content changes by what flows
    out to 1e-7 of the throughput (measured 2.5e-8 with both steppers, of which 1.9e-8 is Simpson's rule on 40
    outputs: the quadrature, not the time integration, sets this number)."""
    o = JournalOrbit(mixed.bearing, MASS, 20e-6, 5000.0, 60.0)
    o._equilibrium = mixed.equilibrium()
    r = quiet(o.run, 1.0, integration=Integration(method=method),
              recording=Recording(outputs_per_revolution=40, record=("mass", "outflow")))
    assert r.success and np.ptp(r.eccentricity_ratio) > 1e-6
    mb = JournalOrbit.mass_balance(r)
    assert np.all(mb["relative"] < 1e-7) and np.all(mb["quadrature_relative"] < 1e-7)


@pytest.mark.slow  # 1.5 revolutions from deep contact, both steppers: 40 s of CPU
def test_ida_and_bdf2_agree_through_a_start_up(mixed):
    """A start-up from 6 to 60 rpm over the first revolution under 5 kN: the two steppers' journal paths within
    1e-4 C and their contact loads within 1e-4 of the load."""
    o = JournalOrbit(mixed.bearing, MASS, 0.0, 5000.0, 60.0, speed_profile=((0.0, 6.0), (1.0, 60.0)))
    rec = Recording(outputs_per_revolution=20, record=("contact_load", "shaft_speed"))
    y0 = quiet(lambda: JournalOrbit(mixed.bearing, MASS, 0.0, 5000.0, 6.0).initial_state())
    a = quiet(o.run, 1.5, y0=y0, integration=Integration(method="ida"), recording=rec)
    b = quiet(o.run, 1.5, y0=y0, integration=Integration(method="bdf2"), recording=rec)
    assert a.success and b.success
    C = o.bearing.clearance
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) < 1e-4 * C
    assert np.max(np.abs(a.contact_load - b.contact_load)) < 1e-4 * o.load
    np.testing.assert_allclose(a.shaft_speed[[0, 10, 20, -1]], [6.0, 33.0, 60.0, 60.0])  # 1 s per reference revolution
    assert a.contact_load[-1] < a.contact_load[0]  # the film takes over as the shaft speeds up


def test_speed_law_and_shaft_angle():
    """The piecewise-linear speed law: s, ds/dtau and the shaft angle (the integral of s) at points inside, on and
    outside the knots, against closed forms."""
    knots = speed_knots(((0.0, 0.0), (2.0, 1.0), (3.0, 1.0)))
    for tau, s, ds, phi in ((-1.0, 0.0, 0.0, 0.0), (1.0, 0.5, 0.5, 0.25), (2.0, 1.0, 0.0, 1.0),
                            (2.5, 1.0, 0.0, 1.5), (4.0, 1.0, 0.0, 3.0)):
        np.testing.assert_allclose(shaft_speed(tau, knots), (s, ds, phi), atol=1e-15)
    assert shaft_speed(7.5, speed_knots(((0.0, 1.0),))) == (1.0, 0.0, 7.5)


def test_speed_profile_is_checked():
    b = rough(1e-6)
    for bad, match in ((((0.0, 10.0), (0.0, 20.0)), "ascending"), (((0.0, -1.0),), "speed_profile speed"),
                       (((-1.0, 1.0),), "speed_profile time"), ((1.0, 2.0, 3.0), "speed_profile")):
        with pytest.raises(ValueError, match=match):
            JournalOrbit(b, 10.0, 0.0, 100.0, 60.0, speed_profile=bad)
    o = JournalOrbit(b, 10.0, 0.0, 100.0, 60.0)
    with pytest.raises(ValueError, match="rough orbit"):
        o.run(0.1, integration=Integration(method="cvode"))
    assert math.isclose(o.shaft_speed_rpm(3.0), 60.0)
