"""A rotor on rough (mixed-lubrication) bearings (models/rotor/rough_films.py, rough_content.py): the one-node rotor
against the rough journal orbit (IDA and BDF, constant speed and a speed ramp), vanishing roughness against the
smooth rotor, the symmetric rotor on two rough bearings against the half-mass orbit, the long-time limit against the
static equilibrium with contact, both Jacobians against finite differences, the records, a coast-down to rest."""

import warnings

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, Recording, Roughness, steel_asperity_contact
from transient.models.journal.film import read_only
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.models.rotor.content_form import BDF2_STEPS_PER_REVOLUTION, ContentSystem
from transient.models.rotor.rough_content import (mixed_rotor_jacobian, mixed_rotor_residual, mixed_rotor_to_state,
                                                  rough_rotor_jacobian, rough_rotor_residual, rough_rotor_to_state)
from transient.params.rho_kim import BEARING

M, G, SPEED = 500.0, 10.0, 60.0  # a 500 kg rotor whose weight, 5 kN, the asperities carry a third of at 60 rpm


def rough(sigma=1e-6, grid=(24, 4), gamma=3.0, share=0.8):
    """The Rho & Kim bearing with steel asperities of composite roughness ``sigma`` [m] (the rough orbit's tests'
    surface: streaks along the rotation, a rougher journal)."""
    r = Roughness(steel_asperity_contact(sigma), gamma=gamma, boundary_friction=0.12, journal_variance_share=share)
    return JournalBearing(**BEARING, grid=grid, roughness=r)


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # the contact pressure is above the isoviscous film's range
        return f(*a, **kw)


def one_node(bearing, mass=M, me=0.0):
    rotor = Rotor(mass=mass * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    return RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, me, 0.0)], gravity=G)


@pytest.fixture(scope="module")
def bearing():
    return rough()


@pytest.fixture(scope="module")
def orbit(bearing):
    o = JournalOrbit(bearing, M, 1e-6, M * G, SPEED)
    quiet(o.equilibrium)
    return o


def orbit_start(orbit):
    """The journal released 0.01 C above its equilibrium, the film solved for it, in the one-node rotor's layout
    (the shaft angle 0 appended)."""
    return np.concatenate([quiet(orbit.perturbed_start, -0.01), [0.0]])


METHODS = {"ida": (Integration(method="ida", rtol=1e-7, atol=1e-10),) * 2,
           "bdf2": (Integration(method="bdf2", rtol=1e-8, atol=1e-10),  # the orbit on the rotor's stepper
                    Integration(method="bdf2", rtol=1e-8, atol=1e-10, max_order=2,
                                steps_per_revolution=BDF2_STEPS_PER_REVOLUTION))}


@pytest.mark.parametrize("method", sorted(METHODS))
def test_one_node_rotor_is_the_rough_orbit(bearing, orbit, method):
    """The same equations as the rough journal orbit (the rotor row scaled by its mass): a revolution in contact from
    0.01 C off the equilibrium, the journal paths within 1e-6 C, contact load and friction torque within 1e-6 of the
    orbit's largest; and the static equilibria with contact equal."""
    mine, theirs = METHODS[method]
    s = one_node(bearing, me=M * 1e-6)
    eq = quiet(s.equilibrium, SPEED)
    C = bearing.clearance
    assert np.hypot(*(np.array(eq.position(0)) - orbit.equilibrium().position)) < 1e-9 * C
    y0 = orbit_start(orbit)
    r = quiet(s.run, 1, SPEED, start=(0.0, y0), integration=mine, recording=Recording(outputs_per_revolution=20))
    o = quiet(orbit.run, 1, y0=y0[:-1], integration=theirs,
              recording=Recording(outputs_per_revolution=20, record=("contact_load", "friction_torque")))
    assert r.success and o.success and r.method == method
    np.testing.assert_allclose(r.t, o.t, rtol=1e-12)
    x, y = r.position(0)
    assert np.max(np.hypot(x - o.x, y - o.y)) < 1e-6 * C
    assert np.max(np.hypot(o.x - o.x[0], o.y - o.y[0])) > 5e-3 * C  # the orbit moves
    for k in ("contact_load", "friction_torque"):
        assert np.max(np.abs(getattr(r, k)[:, 0] - getattr(o, k))) < 1e-6 * np.max(getattr(o, k))
    assert np.min(r.contact_load) > 0 and r.contact_load[-1, 0] > 0.2 * M * G and r.contact_events == [(0.0, 0, "begins")]
    assert np.all(r.min_film[:, 0] < 3 * bearing.roughness.sigma)


def test_one_node_rotor_on_a_speed_ramp_is_the_rough_orbit(bearing, orbit):
    """A shaft accelerating from 30 rpm by 6 rpm/s (the rotor's speed function, the orbit's speed profile; the same
    reference speed, 60 rpm) for 0.5 s from the 60 rpm equilibrium, IDA: the journal's final positions within
    1e-6 C, at the same final time."""
    ramp = ((0.0, 30.0), (10.0, 90.0))
    o = JournalOrbit(bearing, M, 1e-6, M * G, SPEED, speed_profile=ramp)
    y0 = orbit.initial_state()
    ig = Integration(method="ida", rtol=1e-7, atol=1e-10)
    a = quiet(o.run, 0.5, y0=y0, integration=ig)  # 0.5 s: half a revolution at the reference speed
    turns = (30.0 * 0.5 + 3.0 * 0.5 ** 2) / 60.0
    r = quiet(one_node(bearing, me=M * 1e-6).run, turns, lambda t: np.interp(t, *zip(*ramp)),
              start=(0.0, np.concatenate([y0, [0.0]])), reference_speed_rpm=SPEED, integration=ig)
    assert a.success and r.success
    assert r.final_time == pytest.approx(a.final_time, rel=1e-9)
    x, y = r.position(0)
    assert np.hypot(x[-1] - a.x[-1], y[-1] - a.y[-1]) < 1e-6 * bearing.clearance
    assert np.hypot(a.x[-1] - a.x[0], a.y[-1] - a.y[0]) > 1e-3 * bearing.clearance  # the speed moved the journal
    assert r.speed_rpm[0] == pytest.approx(30.0) and r.speed_rpm[-1] == pytest.approx(33.0)


def test_vanishing_roughness_is_the_smooth_rotor():
    """sigma = 1 nm on C = 80 um, isotropic, both surfaces alike: every rough coefficient is the smooth one to rounding
    and the asperities carry nothing, so the rough system (equilibrium and a run with the touch event off) is the
    smooth one: positions within 1e-9 C."""
    kw = dict(grid=(24, 4))
    smooth = JournalBearing(**BEARING, **kw)
    fine = rough(1e-9, gamma=1.0, share=0.5)
    a, b = one_node(smooth, 100.0, 8e-4), one_node(fine, 100.0, 8e-4)
    ea, eb = a.equilibrium(3000.0), b.equilibrium(3000.0)
    C = smooth.clearance
    assert np.hypot(*(np.array(ea.position(0)) - eb.position(0))) < 1e-9 * C
    ig = Integration(method="ida", rtol=1e-7, atol=1e-10)
    ra, rb = a.run(0.3, 3000.0, integration=ig), b.run(0.3, 3000.0, integration=ig)
    assert ra.success and rb.success
    assert np.max(np.abs(ra.displacement - rb.displacement)) < 1e-9 * C
    assert np.max(rb.contact_load) == 0.0 and rb.contact_events == []


def test_symmetric_rotor_on_two_rough_bearings_is_the_half_orbit(bearing):
    """A rigid rotor on two equal rough bearings under its weight, an unbalance at each: each journal runs the
    orbit of half the mass on one bearing, within 1e-6 C (BDF, the default of the equilibrium start)."""
    s = RotorBearingSystem(Rotor.rigid(2 * M, 3.0, 0.5), {0: bearing, 1: bearing},
                           unbalance=[(0, M * 1e-6, 0.0), (1, M * 1e-6, 0.0)], gravity=G)
    eq = quiet(s.equilibrium, SPEED)
    assert eq.bearing_load == pytest.approx([M * G] * 2, rel=1e-8)
    mine, theirs = METHODS["bdf2"]
    r = quiet(s.run, 1, SPEED, integration=mine)
    o = quiet(JournalOrbit(bearing, M, 1e-6, M * G, SPEED).run, 1, integration=theirs)
    assert r.success and o.success
    for node in (0, 1):
        x, y = r.position(node)
        assert np.max(np.hypot(x - np.interp(r.t, o.t, o.x), y - np.interp(r.t, o.t, o.y))) < 1e-6 * bearing.clearance


@pytest.mark.parametrize("method", sorted(METHODS))
def test_long_time_limit_is_the_equilibrium_with_contact(bearing, method):
    """Released 0.01 C off its static equilibrium (journals in contact), the two-bearing rotor settles on it:
    positions within 1e-6 C, the contact loads within 1e-5 of the equilibrium's."""
    s = RotorBearingSystem(Rotor.rigid(2 * M, 3.0, 0.5), {0: bearing, 1: bearing}, gravity=G)
    eq = quiet(s.equilibrium, SPEED)
    dae = s.dae(SPEED)
    y0 = np.array(eq.state)
    y0[dae.Q0] -= 0.01 * bearing.clearance / dae.L
    r = quiet(s.run, 1.0, SPEED, start=(0.0, y0), integration=Integration(method=method))
    assert r.success
    C = bearing.clearance
    for k, node in enumerate((0, 1)):
        assert np.hypot(*(np.array(r.position(node))[:, -1] - eq.position(node))) < 1e-6 * C
    film = bearing.film(SPEED)
    X, Y = np.array(eq.position(0)) / C
    load = np.hypot(*film.contact_force(X, Y)) * film.force_scale
    assert 0.2 * M * G < load < 0.8 * M * G
    np.testing.assert_allclose(r.contact_load[-1], load, rtol=1e-5)


def flexible(bearing, other=None):
    """Two nodes joined by a shaft spring, each on a rough bearing (node 1 on ``other`` if given), gyroscopic
    coupling, unbalances (the smooth system's Jacobian case, tests/models/rotor/test_system.py)."""
    k = 2e8
    Mf = np.diag([300.0, 300.0, 200.0, 200.0])
    Kf = k * np.array([[1, 0, -1, 0], [0, 1, 0, -1], [-1, 0, 1, 0], [0, -1, 0, 1.0]])
    Gf = np.zeros((4, 4))
    Gf[0, 1], Gf[1, 0] = 0.02, -0.02
    rotor = Rotor(mass=Mf, stiffness=Kf, damping=1e-5 * Kf, gyroscopic=Gf, nodes=[0, 1])
    return RotorBearingSystem(rotor, {0: bearing, 1: bearing if other is None else other},
                              unbalance=[(0, 1e-4, 0.0), (1, 2e-4, 90.0)], gravity=G)


def test_ida_jacobian_matches_finite_differences(bearing, fd_jacobian):
    """dF/dy + cj dF/dy' of the system's DAE with rough films, in contact, moving, on a speed ramp: the film blocks,
    their coupling and border, and the asperity stiffness on the momentum rows."""
    s = flexible(bearing)
    dae = s.dae(SPEED, lambda tau: (0.8 + 0.01 * tau, 0.01))
    rng = np.random.default_rng(5)
    y = quiet(s._start_guess, dae, 0.8)
    y[dae.Q0:dae.P0] += 0.002 * rng.standard_normal(2 * dae.nq)
    yp = 0.01 * rng.standard_normal(dae.n)
    tau, cj = 0.3, 7.0

    def F(v):
        out = np.empty(dae.n)
        dae.residual(tau, read_only(v), read_only(yp + cj * (v - y)), out)
        return out

    data = np.zeros(dae.pattern.nnz)
    dae.jacobian(tau, read_only(y), read_only(yp), cj, data)
    J = dae.pattern.copy()
    J.data = data
    J = J.toarray()
    Jfd = fd_jacobian(F, y, dae.n, step=1e-7)
    scale = np.maximum(np.max(np.abs(Jfd), axis=1, keepdims=True), 1e-300)
    assert np.max(np.abs(J - Jfd) / scale) < 1e-5
    assert np.max(np.abs(Jfd[dae.pattern.toarray() == 0])) < 1e-8 * np.max(np.abs(Jfd))
    V0, Q0 = dae.V0, dae.Q0
    assert abs(J[V0, Q0]) > 2 * abs(dae.Kw[0, 0])  # the asperity stiffness is there, above the shaft's


#: the content kernels (to_state, residual, jacobian) of a system on rough bearings only / on a mix with smooth ones
KERNELS = {False: (rough_rotor_to_state, rough_rotor_residual, rough_rotor_jacobian),
           True: (mixed_rotor_to_state, mixed_rotor_residual, mixed_rotor_jacobian)}


@pytest.mark.parametrize("mixed", [False, True])
def test_bdf_jacobian_matches_finite_differences(bearing, fd_jacobian, mixed):
    """dF/dz of the rough content residual with y' = cj y + b (a BDF step) in the Newton variables
    z = [u_1, u_2, q, v, phi] (m = h_T C(u)) against central differences; nothing outside the Newton pattern. Both
    bearings rough, or (``mixed``) node 0 on a rougher bearing (sigma 2 um, in contact) and node 1 on a smooth one, at
    300 rpm (the smooth film carries its 2 kN there): the smooth block through the smooth kernels."""
    if mixed:
        s, speed = flexible(rough(2e-6), JournalBearing(**BEARING, grid=(24, 4))), 300.0
    else:
        s, speed = flexible(bearing), SPEED
    dae = s.dae(speed, lambda tau: (0.8 + 0.01 * tau, 0.01))
    form = ContentSystem(dae)
    to_state, residual, jacobian = KERNELS[mixed]
    assert form.kernel is residual
    rng = np.random.default_rng(6)
    z = quiet(s._start_guess, dae, 0.8)
    z[dae.Q0:dae.P0] += 0.002 * rng.standard_normal(2 * dae.nq)
    z[dae.P0] = 0.7
    tau, cj = 0.3, 37.0
    form.set_speed(tau)
    args = form.args
    y = np.empty(dae.n)
    to_state(z, y, args)
    b = -cj * y + 0.01 * rng.standard_normal(dae.n)

    def F(zz):
        yy, out = np.empty(dae.n), np.empty(dae.n)
        to_state(zz, yy, args)
        residual(tau, yy, cj * yy + b, out, args)
        return out

    data = np.zeros(form.pattern.nnz)
    to_state(z, y, args)
    jacobian(tau, y, cj * y + b, cj, data, args)
    J = form.pattern.copy()
    J.data = data
    J = J.toarray()
    free = np.ones(dae.n, dtype=bool)
    for blk in dae.blocks:
        free[blk.offset:blk.offset + blk.n] = blk.film.op.free
    free[dae.P0] = False  # the angle's column (the unbalances) by its own step: its rows are large, its entries not
    cols = np.flatnonzero(free)
    Jfd = fd_jacobian(F, z, dae.n, step=5e-4 * min(blk.film.width for blk in dae.blocks))
    scale = np.max(np.abs(Jfd), axis=1, keepdims=True)  # by row: the momentum rows' rounding is their size's
    assert np.max(np.abs(J[:, cols] - Jfd[:, cols]) / scale) < 1e-6
    e = np.zeros(dae.n)
    e[dae.P0] = 1e-4
    phi = (F(z + e) - F(z - e)) / 2e-4
    assert np.max(np.abs(J[:, dae.P0] - phi)) < 1e-6 * np.max(np.abs(phi))
    assert np.max(np.abs(Jfd[form.pattern.toarray() == 0])) < 1e-8 * np.max(np.abs(Jfd))


def test_rough_bearing_refuses_tilt_coupling(bearing):
    tilting = Rotor(mass=np.eye(4), stiffness=np.eye(4), nodes=[0], dofs=("x", "y", "tx", "ty"))
    with pytest.raises(ValueError, match=r"bearings\[0\] roughness = Roughness\(\.\.\.\) with tilt_coupling"):
        RotorBearingSystem(tilting, {0: bearing}, tilt_coupling=True)


def test_ida_takes_a_mix_of_rough_and_smooth(bearing):
    """A rough and a smooth bearing on one rotor (IDA): the rough block's records beside the smooth one's zeros, the
    touch event on the smooth bearing only (a touch_gap that the smooth journal reaches stops the run there)."""
    smooth = JournalBearing(**BEARING, grid=(24, 4))
    s = RotorBearingSystem(Rotor.rigid(200.0, 3.0, 0.5), {0: bearing, 1: smooth}, gravity=9.81)
    r = quiet(s.run, 0.05, 3000.0, recording=Recording(outputs_per_revolution=20),
              integration=Integration(method="ida"))
    assert r.success and r.method == "ida"
    assert r.contact_load.shape == (2, 2) and np.all(r.contact_load[:, 1] == 0.0)
    assert np.all(r.min_film > 0) and r.contact_events == []
    whirl = RotorBearingSystem(Rotor.rigid(200.0, 3.0, 0.5), {0: bearing, 1: smooth}, gravity=9.81,
                               unbalance=[(0, 60.0 * smooth.clearance, 0.0), (1, 60.0 * smooth.clearance, 0.0)])
    touched = quiet(whirl.run, 3, 6000.0, touch_gap=0.4, recording=Recording(outputs_per_revolution=32),
                    integration=Integration(method="ida"))
    assert touched.touched_at is not None and "node 1 touches" in touched.message


def test_mix_of_rough_and_smooth_at_vanishing_roughness_is_the_smooth_rotor():
    """A rigid rotor on a rough bearing of sigma = 1 nm (every coefficient the smooth one to rounding, no asperity
    load) and a smooth one, BDF at its defaults (the mixed kernels): the rotor on two smooth bearings, within 1e-9 C
    over 0.3 revolution at 3000 rpm (the default method: BDF for both)."""
    smooth = JournalBearing(**BEARING, grid=(24, 4))
    fine = rough(1e-9, gamma=1.0, share=0.5)
    unb = [(0, 8e-4, 0.0), (1, 5e-4, 90.0)]  # m e [kg m]: 0.1 C and 0.06 C of each bearing's 100 kg
    a = RotorBearingSystem(Rotor.rigid(200.0, 3.0, 0.5), {0: smooth, 1: smooth}, unbalance=unb, gravity=9.81)
    b = RotorBearingSystem(Rotor.rigid(200.0, 3.0, 0.5), {0: fine, 1: smooth}, unbalance=unb, gravity=9.81)
    ra, rb = a.run(0.3, 3000.0), quiet(b.run, 0.3, 3000.0)
    assert ra.success and rb.success and ra.method == rb.method == "bdf2"
    C = smooth.clearance
    assert np.max(np.abs(ra.displacement - rb.displacement)) < 1e-9 * C
    assert np.max(np.abs(ra.displacement[-1] - ra.displacement[0])) > 1e-3 * C  # the journals moved
    assert np.max(rb.contact_load) == 0.0 and rb.contact_events == []


def test_mix_of_rough_and_smooth_bdf_is_ida():
    """A rigid rotor (1000 kg, 5 kN per bearing) on a rough bearing in contact (sigma 2 um) and a smooth one at
    300 rpm: half a revolution released 0.01 C above the static equilibrium, BDF (the mixed kernels) against IDA at
    rtol 1e-8: positions within 1e-6 C, the rough bearing's contact load within 1e-5, the smooth one's 0."""
    bearing, smooth = rough(2e-6), JournalBearing(**BEARING, grid=(24, 4))
    s = RotorBearingSystem(Rotor.rigid(2 * M, 3.0, 0.5), {0: bearing, 1: smooth},
                           unbalance=[(0, M * 1e-6, 0.0), (1, M * 1e-6, 0.0)], gravity=G)
    speed = 300.0
    eq = quiet(s.equilibrium, speed)
    dae = s.dae(speed)
    y0 = np.array(eq.state)
    y0[dae.Q0] -= 0.01 * bearing.clearance / dae.L
    runs = {m: quiet(s.run, 0.5, speed, start=(0.0, y0), integration=Integration(method=m, rtol=1e-8, atol=1e-11))
            for m in ("ida", "bdf2")}
    ida, bdf = runs["ida"], runs["bdf2"]
    assert ida.success and bdf.success and bdf.method == "bdf2"
    C = bearing.clearance
    assert np.max(np.abs(bdf.displacement - ida.displacement)) < 1e-6 * C
    assert np.max(ida.contact_load[:, 0]) > 0.05 * M * G and np.all(bdf.contact_load[:, 1] == 0.0)
    np.testing.assert_allclose(bdf.contact_load[:, 0], ida.contact_load[:, 0], rtol=1e-5)


def test_records_save_and_load(bearing, tmp_path):
    from transient.results import load_result

    r = quiet(one_node(bearing).run, 0.1, SPEED, recording=Recording(outputs_per_revolution=20))
    assert r.success and r.contact_load.shape == (3, 1)
    p = tmp_path / "r.npz"
    r.save(p)
    back = load_result(p)
    np.testing.assert_array_equal(back.friction_torque, r.friction_torque)
    assert [tuple(e) for e in back.contact_events] == [tuple(e) for e in r.contact_events]


@pytest.mark.slow
def test_coast_down_to_rest_through_contact(bearing):
    """A flexible two-bearing rotor coasting down from 600 rpm to rest in 2 s (BDF, the default stepper): no NaN, no
    stall, the journals sinking into contact (events recorded; as the shaft stops the asperities carry 41 % of the
    weight, the squeeze films the rest), the contact pressures bounded."""
    s = flexible(bearing)
    T, n0 = 2.0, 600.0
    turns = n0 / 60.0 * T / 2.0
    r = quiet(s.run, 0.999 * turns, lambda t: max(0.0, n0 * (1.0 - t / T)), integration=Integration(method="bdf2"))
    assert r.success, r.message
    assert np.all(np.isfinite(r.displacement)) and r.speed_rpm[-1] < 0.05 * n0
    assert [e[2] for e in r.contact_events if e[1] == 0][:1] == ["begins"]
    weight = G * 500.0  # the squeeze film still carries part of it just after the shaft stops
    assert np.sum(r.contact_load[-1]) > 0.3 * weight and np.sum(r.contact_load[-1]) > 100 * np.sum(r.contact_load[0])
    assert np.max(r.contact_pressure) < 1e10
