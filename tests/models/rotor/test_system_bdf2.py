"""``RotorBearingSystem.run(method="bdf2")`` (models/rotor/content_newton.py, content_form.py): the Newton Jacobian
in the variables z = [u_1, ..., u_k, q, v, phi] against central differences, the band of the whole system equal to one
film's, the one-node rotor and the symmetric two-bearing rotor against the journal orbit's BDF2, BDF2 against IDA on a
flexible two-bearing rotor (constant speed and a run-up), the touch event per bearing, checkpoint/resume bitwise."""

from dataclasses import replace

import numpy as np
import pytest

from transient import Integration, JournalBearing, JournalOrbit, LongRun, Recording
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.models.rotor.content_form import BDF2_STEPS_PER_REVOLUTION, ContentSystem, bdf2_refusal
from transient.models.rotor.content_newton import rotor_jacobian, rotor_to_state
from transient.params.rho_kim import BEARING
from transient.solvers.bandlu import BorderedBandLU
from transient.solvers.longrun import Interrupted

from content_jacobian import content_jacobians
from test_system import ECC, G, M_ROTOR, flexible_system


@pytest.fixture(scope="module")
def bearing():
    return JournalBearing(**BEARING, grid=(48, 8))


def one_node(bearing, me=M_ROTOR * ECC):
    rotor = Rotor(mass=M_ROTOR * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0])
    return RotorBearingSystem(rotor, {0: bearing}, unbalance=[(0, me, 0.0)], gravity=G)


def test_newton_jacobian_matches_finite_differences(fd_jacobian):
    """dF/dz of the content residual with y' = cj y + b (as in a BDF2 step), a speed ramp (s, s' != 1, 0), on the
    flexible rotor's two films of different grids and clearances (one on a reduced basis), at a state with
    cavitated, full-film and switching cells and a moving, tilted shaft; nothing outside the Newton pattern."""
    form, dae, J, Jfd, cols = content_jacobians(flexible_system(JournalBearing(**BEARING, grid=(16, 4))), 6000.0, 1,
                                                fd_jacobian)
    scale = np.max(np.abs(J[:, cols]), axis=0)
    rel = np.max(np.abs(J[:, cols] - Jfd[:, cols]), axis=0) / scale
    assert np.max(rel) < 1e-6, (np.max(rel), cols[np.argmax(rel)])
    outside = form.pattern.toarray() == 0
    assert np.max(np.abs(Jfd[outside])) < 1e-8 * np.max(np.abs(Jfd))
    for blk in dae.blocks:  # the arrow is there: films on the rotor's coordinates and back
        o, n = blk.offset, blk.n
        assert np.abs(J[dae.V0:dae.P0, o:o + n]).max() > 0 and np.abs(J[o:o + n, dae.Q0:dae.V0]).max() > 0
    assert J[dae.V0:dae.P0, dae.P0].any()  # the unbalances on the shaft angle


def test_the_band_of_two_films_is_one_films(bearing):
    """One band block per film: the films couple only through the rotor, so the bordered band LU of the two-bearing
    system has the band of one film's Newton pattern (the journal orbit's)."""
    s = RotorBearingSystem(Rotor.rigid(M_ROTOR, 3.0, 0.5), {0: bearing, 1: bearing}, gravity=G)
    form = ContentSystem(s.dae(6000.0))
    lu = BorderedBandLU(form.pattern, 2 * s.rotor.n + 1)
    one = BorderedBandLU(JournalOrbit(bearing, M_ROTOR, 0.0, M_ROTOR * G, 6000).newton_pattern()[0], 4)
    assert (lu.kl, lu.ku) == (one.kl, one.ku)
    assert lu.n == 2 * one.n


def test_one_node_rotor_is_the_journal_orbit(bearing):
    """The same equations as the journal orbit's content form (the rotor row scaled by its mass, the unbalance on
    the shaft angle) and the same step bounds at the defaults (variable order, the journal's travel, the least steps
    per revolution): the same steps, the orbit to 1e-6 C."""
    r = one_node(bearing).run(1, 6000, integration=Integration(method="bdf2", rtol=1e-7, atol=1e-10))
    o = JournalOrbit(bearing, M_ROTOR, ECC, M_ROTOR * G, 6000).run(
        1, integration=Integration(method="bdf2", rtol=1e-7, atol=1e-10))
    assert r.success and r.method == "bdf2" and np.array_equal(r.t, o.t)
    assert r.stats.n_steps == o.stats.n_steps
    x, y = r.position(0)
    assert np.max(np.abs(x - o.x)) < 1e-6 * bearing.clearance
    assert np.max(np.abs(y - o.y)) < 1e-6 * bearing.clearance
    assert np.max(np.hypot(o.x - o.x[0], o.y - o.y[0])) > 1e-3 * bearing.clearance  # the orbit moves
    n = bearing.film(6000).n  # the final state in the universal layout, as IDA's
    assert np.allclose(r.final_state[:n], o.final_state[:n], atol=1e-6)


def test_symmetric_rotor_on_two_bearings_is_the_half_orbit(bearing):
    rotor = Rotor.rigid(M_ROTOR, 3.0, 0.5)
    s = RotorBearingSystem(rotor, {0: bearing, 1: bearing}, unbalance=[(0, M_ROTOR * ECC / 2, 0.0),
                                                                       (1, M_ROTOR * ECC / 2, 0.0)], gravity=G)
    plain = Integration(method="bdf2", rtol=1e-7, atol=1e-10, max_order=2,
                        steps_per_revolution=BDF2_STEPS_PER_REVOLUTION)
    r = s.run(1, 6000, integration=plain)  # plain BDF2 with a cap in shaft angle, as the orbit's
    o = JournalOrbit(bearing, M_ROTOR / 2, ECC, M_ROTOR * G / 2, 6000).run(1, integration=plain)
    assert r.success
    for node in (0, 1):
        x, y = r.position(node)
        assert np.max(np.hypot(x - o.x, y - o.y)) < 1e-6 * bearing.clearance


def test_bdf2_agrees_with_ida_on_a_flexible_rotor(bearing):
    """Two films of different clearances and grids on a reduced, gyroscopic, damped shaft with two unbalances:
    BDF2 within 1e-6 C (its rtol times the journal positions, below 1 C) of IDA at rtol 1e-9 at rtol 1e-6, and
    closer at rtol 1e-7 (the error follows the tolerance)."""
    s = flexible_system(bearing)
    kw = dict(recording=Recording(outputs_per_revolution=40))
    ref = s.run(0.25, 6000, integration=Integration(rtol=1e-9, atol=1e-10), **kw)
    runs = [s.run(0.25, 6000, integration=Integration(method="bdf2", rtol=rtol, atol=1e-10), **kw)
            for rtol in (1e-6, 1e-7)]
    assert all(r.success and np.allclose(r.t, ref.t, rtol=1e-12) for r in runs)
    assert np.max(np.abs(ref.displacement - ref.displacement[0])) > 5e-3 * bearing.clearance  # it moves
    err = [np.max(np.abs(r.displacement - ref.displacement)) / bearing.clearance for r in runs]
    assert err[0] < 1e-6 and err[1] < err[0] / 2, err


def test_run_up_agrees_with_ida(bearing):
    """A speed ramp (the films' Couette flow and the unbalance's s^2 and s' terms): BDF2 and IDA agree."""
    s = one_node(bearing)
    ramp = lambda t: 3000.0 + 60000.0 * t  # noqa: E731
    kw = dict(recording=Recording(outputs_per_revolution=20))
    ida = s.run(1, ramp, integration=Integration(rtol=1e-8, atol=1e-10), **kw)
    bdf2 = s.run(1, ramp, integration=Integration(method="bdf2", rtol=1e-6, atol=1e-10), **kw)
    assert bdf2.success and np.allclose(bdf2.speed_rpm, ramp(bdf2.t))
    assert np.max(np.abs(bdf2.displacement - ida.displacement)) < 1e-4 * bearing.clearance


def test_touch_event_per_bearing(bearing):
    """The flexible rotor with a large unbalance at the second node: the run stops when that journal (in its own
    clearance) reaches the touch limit, located on the step's interpolant."""
    s = flexible_system(bearing)
    s.unbalance = [(1, 5e-2, 0.0)]
    r = s.run(2, 6000, integration=Integration(method="bdf2"), recording=Recording(outputs_per_revolution=32),
              touch_gap=0.5)
    assert r.touched_at is not None and "touches its bearing" in r.message, r.message
    e = [r.eccentricity_ratio(k)[-1] for k in (0, 1)]
    assert e[1] == pytest.approx(0.5, abs=1e-6) and e[0] < 0.5


def test_checkpoint_resume_is_bitwise(bearing, tmp_path, monkeypatch):
    """A run killed (Ctrl-C) in its third chunk and resumed from its checkpoint ends where the uninterrupted run
    does, bit for bit."""
    s = flexible_system(bearing)
    kw = dict(integration=Integration(method="bdf2"), recording=Recording(outputs_per_revolution=40))
    lr = LongRun(chunk_revolutions=0.125, progress=False)
    full = s.run(0.5, 6000, long_run=lr, **kw)
    path = tmp_path / "rotor.npz"
    set_speed = ContentSystem.set_speed

    def killed(self, tau):
        if tau > 2 * np.pi * 0.3:
            raise KeyboardInterrupt
        set_speed(self, tau)

    monkeypatch.setattr(ContentSystem, "set_speed", killed)
    with pytest.raises(Interrupted, match="run again with resume=True"):
        flexible_system(bearing).run(0.5, 6000, long_run=replace(lr, checkpoint=str(path)), **kw)
    monkeypatch.undo()
    assert path.exists()
    resumed = flexible_system(bearing).run(0.5, 6000, long_run=replace(lr, checkpoint=str(path), resume=True), **kw)
    assert resumed.success and resumed.stats.n_steps < 2 * full.stats.n_steps
    for k in ("t", "displacement", "bearing_force", "final_state"):
        np.testing.assert_array_equal(getattr(resumed, k), getattr(full, k))


def test_a_mix_of_film_kinds_is_refused():
    from transient.models.journal.bearing import omega
    from transient.physics.layered import BoundaryLayers, Gecim

    cl, mu = BEARING["clearance"], BEARING["viscosity"]
    gecim = JournalBearing(**BEARING, grid=(16, 4), rheology=Gecim(kappa=0.65 * mu * omega(6000) * 0.5 *
                                                                     BEARING["diameter"] / cl, viscosity_ratio=0.57),
                           layers=BoundaryLayers(thickness=0.1 * cl, viscosity=(10 * mu, 20 * mu), alpha=0.05 * cl))
    s = RotorBearingSystem(Rotor.rigid(M_ROTOR, 3.0, 0.5), {0: JournalBearing(**BEARING, grid=(16, 4)), 1: gecim},
                           gravity=G)
    with pytest.raises(ValueError, match='method "bdf2" takes bearings of one film kind'):
        ContentSystem(s.dae(6000.0))
    assert bdf2_refusal(s.dae(6000.0)) is not None
    r = s.run(0.02, 6000.0, recording=Recording(outputs_per_revolution=50))  # the default: IDA for this mix
    assert r.success and r.method == "ida"


def test_the_default_method_is_chosen_by_the_films(bearing):
    """Without integration settings the run takes the BDF (its defaults: the same steps as an explicit
    ``Integration(method="bdf2")``); an ``Integration`` without a method and the deprecated integration keywords keep
    IDA; a mix of film kinds takes IDA (above)."""
    s = one_node(bearing)
    rec = Recording(outputs_per_revolution=50)
    default = s.run(0.1, 6000.0, recording=rec)
    explicit = s.run(0.1, 6000.0, recording=rec, integration=Integration(method="bdf2"))
    assert default.success and default.method == "bdf2" and bdf2_refusal(s.dae(6000.0)) is None
    assert default.stats.n_steps == explicit.stats.n_steps
    np.testing.assert_array_equal(default.displacement, explicit.displacement)
    assert s.run(0.1, 6000.0, recording=rec, integration=Integration()).method == "ida"
    with pytest.warns(DeprecationWarning, match="rtol"):
        assert s.run(0.1, 6000.0, recording=rec, rtol=1e-6).method == "ida"


def test_step_cap_is_per_shaft_revolution(bearing, monkeypatch):
    """The step cap (here plain BDF2's ``BDF2_STEPS_PER_REVOLUTION`` per revolution) is in shaft angle: at half the reference speed a loose
    tolerance takes about as many steps per shaft revolution as at the reference speed, half as many as with the
    cap per revolution at the reference speed (``MIN_CAP_SPEED`` = 1), at the same distance from IDA's motion."""
    import transient.models.rotor.system as system

    s = one_node(bearing)
    kw = dict(integration=Integration(method="bdf2", rtol=1e-3, max_order=2,
                                      steps_per_revolution=BDF2_STEPS_PER_REVOLUTION),
              recording=Recording(outputs_per_revolution=20),
              long_run=LongRun(progress=False))
    own = s.run(0.5, 3000.0, **kw)
    half = s.run(0.5, 3000.0, reference_speed_rpm=6000.0, **kw)
    monkeypatch.setattr(system, "MIN_CAP_SPEED", 1.0)
    at_reference = s.run(0.5, 3000.0, reference_speed_rpm=6000.0, **kw)
    ida = s.run(0.5, 3000.0, integration=Integration(rtol=1e-8, atol=1e-10),
                recording=Recording(outputs_per_revolution=20))
    assert own.success and half.success and at_reference.success
    assert half.stats.n_steps < 1.1 * own.stats.n_steps, (half.stats.n_steps, own.stats.n_steps)
    assert half.stats.n_steps < 0.6 * at_reference.stats.n_steps
    moved = lambda r: r.displacement - r.displacement[0]  # noqa: E731  (each run from its own equilibrium)
    err = [np.max(np.abs(moved(r) - moved(ida))) / bearing.clearance for r in (half, at_reference)]
    assert err[0] < 1.2 * err[1] + 1e-7, err


def test_journal_travel_is_the_largest_bearing_node_travel_in_its_clearance(bearing):
    """The step bound's measure (``ContentSystem.journal_travel``): for a change of the state, the largest travel of
    a bearing node in its own bearing's clearance, on a reduced basis with two clearances (against the nodes'
    displacements from the rotor's basis); the films' and the velocities' changes do not count."""
    s = flexible_system(bearing)
    dae = s.dae(6000.0)
    form = ContentSystem(dae)
    rng = np.random.default_rng(3)
    for _ in range(3):
        dy = rng.standard_normal(dae.n)
        d = s._node_displacements(dy[dae.Q0:dae.V0] * dae.L)  # (nodes, 2) [m]
        expected = max(np.hypot(*d[s.rotor.nodes.index(node)]) / b.clearance for node, b in s.bearings.items())
        assert form.journal_travel(dy) == pytest.approx(expected, rel=1e-12)
        dy[dae.Q0:dae.V0] = 0.0
        assert form.journal_travel(dy) == 0.0


def test_a_jacobian_refreshes_only_the_film_whose_cells_switched(bearing):
    """At the same cj, cells of one film moved across the cavitation switch since the last Jacobian: that film's
    block is evaluated again (equal to a full evaluation at the new state), the other film's entries are kept; a new
    cj or no switch at all refreshes every film, as ``per_film=False`` always does."""
    s = flexible_system(JournalBearing(**BEARING, grid=(16, 4)))
    dae = s.dae(6000.0)
    form = ContentSystem(dae)
    z = s._start_guess(dae, 1.0)
    form.set_speed(0.0)
    args, cj = form.args, 37.0
    y, yp = np.empty(dae.n), np.zeros(dae.n)

    def jacobian(zz, cj_, a=args):
        rotor_to_state(zz, y, a)
        data = np.zeros(form.pattern.nnz)
        rotor_jacobian(0.0, y, yp, cj_, data, a)
        return data

    first, second = dae.blocks
    rows = form.pattern.indices
    cols = np.repeat(np.arange(dae.n), np.diff(form.pattern.indptr))
    of_second = ((rows >= second.offset) & (rows < second.offset + second.n)
                 | (cols >= second.offset) & (cols < second.offset + second.n))
    of_first = ((rows >= first.offset) & (rows < first.offset + first.n)
                | (cols >= first.offset) & (cols < first.offset + first.n))
    before = jacobian(z, cj)
    moved = z.copy()
    cells = first.offset + np.flatnonzero(first.film.op.free)[:3]
    moved[cells] = -np.sign(z[cells]) * 0.5 - (z[cells] == 0)  # across the switch
    moved[second.offset:second.offset + second.n] *= 1.0 + 1e-7  # the second film changed, no cell switched
    after = jacobian(moved, cj)
    full = ContentSystem(dae)
    fresh = jacobian(moved, cj, full.args)
    assert np.array_equal(after[of_second], before[of_second])
    assert np.array_equal(after[of_first], fresh[of_first]) and not np.array_equal(after[of_first], before[of_first])
    assert np.array_equal(jacobian(moved, 1.5 * cj), jacobian(moved, 1.5 * cj, ContentSystem(dae).args))
    every = ContentSystem(dae)
    every_args = (every.args[0], every.rotor._replace(per_film=False))
    jacobian(z, cj, every_args)
    assert np.array_equal(jacobian(moved, cj, every_args), fresh)
