"""A rotor on squeeze-film dampers: the damper's film in the system at zero spin, its centring spring in the rotor's
stiffness. The static equilibrium hangs on the springs; the settled synchronous orbit of a balanced-by-symmetry rotor
is a circular centred orbit whose film force is the damper's own steady whirling-frame solve
(``SqueezeFilmDamper.circular_orbit``), to the two discretisations' second-order difference. On the conservative BDF2
stepper each film block has its own spin (a damper's 0): its Newton Jacobian against central differences, a damper +
journal bearing rotor's run against IDA's."""

import numpy as np
import pytest

from transient import Integration, JournalBearing, LongRun, Recording, Rotor, RotorBearingSystem, SqueezeFilmDamper
from transient.models.journal.bearing import NoEquilibriumError
from transient.models.rotor.content_form import ContentSystem
from transient.models.rotor.kernels import block_residual
from transient.params.rho_kim import BEARING

from content_jacobian import content_jacobians

C = 200e-6
DAMPER = dict(diameter=0.1, length=0.02, clearance=C, viscosity=0.01, supply_pressure=2e5, centring_stiffness=5e6)
ROTOR = dict(shaft_stiffness=1e7, disk_mass=20.0, journal_mass=2.0)
SPEED = 6000.0


def _settled_forces(grid, revolutions, rtol):
    """(e/c, radial, tangential force [N]) of the damper at node 0 over the last revolution of an unbalance run, and
    the damper."""
    d = SqueezeFilmDamper(**DAMPER, grid=grid)
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=0.0)
    r = s.run(revolutions, SPEED, integration=Integration(rtol=rtol), recording=Recording(outputs_per_revolution=16),
              long_run=LongRun(progress=False))
    assert r.success, r.message
    x, y = (v[-17:] for v in r.position(0))
    F = r.bearing_force[-17:, 0, :]
    e = np.hypot(x, y)
    radial, tangential = (F[:, 0] * x + F[:, 1] * y) / e, (F[:, 1] * x - F[:, 0] * y) / e
    assert np.ptp(e) < 5e-3 * e.mean()  # circular and centred (settling to within 1e-5 by 20 revolutions)
    assert np.all(np.diff(np.unwrap(np.arctan2(y, x))) > 0)  # forward whirl, with the shaft
    return e.mean() / C, radial.mean(), tangential.mean(), d


def test_the_equilibrium_hangs_on_the_centring_springs():
    d = SqueezeFilmDamper(**DAMPER, grid=(16, 4))
    eq = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, gravity=9.81).equilibrium(SPEED)
    weight = (ROTOR["disk_mass"] + 2 * ROTOR["journal_mass"]) * 9.81
    sag = 0.5 * weight / (DAMPER["centring_stiffness"] * C)
    assert eq.eccentricity_ratio == pytest.approx(np.full(2, sag), rel=1e-6)
    assert np.max(np.abs(eq.bearing_force)) < 1e-9 * weight  # a film at rest that does not turn carries nothing


def test_the_run_settles_on_the_dampers_circular_orbit():
    eps, radial, tangential, d = _settled_forces((24, 2), 12, 1e-6)
    orbit = d.circular_orbit(eps, SPEED)
    # measured: +1.15 % on 24 cells round, +0.28 % on 48, +0.07 % on 96 (test_..._converge_together)
    assert tangential == pytest.approx(orbit.tangential_force, rel=0.02)
    assert abs(radial) < 1e-3 * abs(tangential) and abs(orbit.radial_force) < 1e-3 * abs(tangential)  # full film


@pytest.mark.slow
def test_the_time_domain_and_the_whirling_frame_films_converge_together():
    """The squeeze term in time (the rotor's film) and as a Couette transport (the whirling frame): their difference
    falls at second order in the circumferential cells."""
    diff = []
    for n in (24, 48, 96):
        eps, _, tangential, d = _settled_forces((n, 4), 20, 1e-7)
        diff.append(tangential / d.circular_orbit(eps, SPEED).tangential_force - 1.0)
    assert diff[0] / diff[1] > 3.0 and diff[1] / diff[2] > 3.0 and abs(diff[2]) < 1e-3


def test_what_a_damper_refuses_in_the_system():
    d = SqueezeFilmDamper(**dict(DAMPER, centring_stiffness=None), grid=(16, 4))
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=9.81)
    with pytest.raises(NoEquilibriumError, match="centring"):
        s.equilibrium(SPEED)
    d = SqueezeFilmDamper(**DAMPER, grid=(16, 4))
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: d, 2: d}, unbalance=[(1, 4e-4, 0.0)], gravity=9.81)
    for analysis in (lambda: s.unbalance_response(SPEED), lambda: s.unbalance_response(SPEED, film_states=False),
                     lambda: s.coefficients(SPEED), lambda: s.eigenvalues(SPEED)):
        with pytest.raises(ValueError, match="quasi-static K and C"):
            analysis()
    assert s.parameters()["bearings"]["0"]["damper"] is True


def _mixed(grid=(16, 4), damper=None, unbalance=1e-4):
    """A Jeffcott rotor on a journal bearing (node 0) and a squeeze-film damper (node 2), under gravity."""
    d = SqueezeFilmDamper(**DAMPER, grid=(grid[0], 2)) if damper is None else damper
    b = JournalBearing(**BEARING, grid=grid)
    return RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: b, 2: d}, unbalance=[(1, unbalance, 0.0)], gravity=9.81)


def test_the_bdf2_newton_jacobian_with_a_damper_matches_finite_differences(fd_jacobian):
    """dF/dz of the content residual (y' = cj y + b, as in a BDF2 step) with a spinning journal film and a pinned
    damper film on a speed ramp, at a moving, off-centre shaft: the damper's block takes no Couette flow."""
    form, dae, J, Jfd, cols = content_jacobians(_mixed(), SPEED, 2, fd_jacobian)
    assert [f.spin for f in form.args[0]] == [1.0, 0.0]
    scale = np.max(np.abs(J[:, cols]), axis=0)
    assert np.max(np.abs(J[:, cols] - Jfd[:, cols]) / scale) < 1e-6


def test_the_content_residual_of_a_damper_has_no_couette_flow():
    """The content residual of the system equals the universal (IDA) residual's film rows where they coincide: at a
    state with the rotor at rest (no squeeze, y' = 0) each film row is its net outflow ``R(u; k s)``, the journal's
    at the shaft's speed, the damper's at none (spin 1 for both would give the damper a Couette outflow)."""
    s = _mixed()
    dae = s.dae(SPEED)
    form = ContentSystem(dae)
    y = s._start_guess(dae, 1.0)
    y[dae.Q0:dae.V0] += 0.1  # journals off their equilibria
    y[dae.V0:dae.P0] = 0.0
    d = dae.blocks[1]
    free = d.offset + np.flatnonzero(d.film.op.free)
    y[free] *= 1.0 + 0.2 * np.random.default_rng(3).random(free.size)  # a damper film with pressure gradients
    universal, content = np.empty(dae.n), np.empty(dae.n)
    dae.residual(0.0, y, np.zeros(dae.n), universal)
    form.residual(0.0, form.content_state(y), np.zeros(dae.n), content)
    for blk in dae.blocks:
        free = blk.offset + np.flatnonzero(blk.film.op.free)
        assert np.max(np.abs(content[free] - universal[free])) < 1e-9 * np.abs(universal[free]).max()
    film = d.film
    wedge = np.empty(d.n)  # the damper's film spinning with the shaft: another outflow
    X, Y = d.position(y[dae.Q0:dae.V0])
    block_residual(y[d.offset:d.offset + d.n], np.zeros(d.n), X, Y, 0.0, 0.0, 1.0, wedge, film.switch, film.geo,
                   film.fields, film.fv, film.sym)
    free = np.flatnonzero(film.op.free)
    assert np.max(np.abs(wedge[free] - universal[d.offset + free])) > 1e-3 * np.abs(wedge[free]).max()


def test_a_damper_and_a_journal_bearing_on_bdf2_run_as_on_ida():
    """The conservative BDF2 (content films, the damper's at zero spin) and IDA (universal films) integrate the same
    semi-discrete model: over a revolution from the static equilibrium with the unbalance on, every node's orbit
    agrees within the two integrators' tolerances."""
    s = _mixed()
    runs = {m: s.run(1, SPEED, integration=Integration(method=m, rtol=1e-7, atol=1e-10),
                     recording=Recording(outputs_per_revolution=16), long_run=LongRun(progress=False))
            for m in ("ida", "bdf2")}
    assert all(r.success for r in runs.values()) and runs["bdf2"].method == "bdf2"
    L = s.length_scale
    for node in (0, 1, 2):
        xa, ya = runs["ida"].position(node)
        xb, yb = runs["bdf2"].position(node)
        assert np.max(np.hypot(xa - xb, ya - yb)) < 1e-5 * L  # measured 0.7-1.6e-6 L
        assert np.ptp(xa) > 0.02 * L  # the orbit moves
    for k in (0, 1):  # the films' forces: both films carry load, the damper's without Couette flow
        assert np.max(np.abs(runs["bdf2"].bearing_force[:, k] - runs["ida"].bearing_force[:, k])) < \
            1e-4 * np.max(np.abs(runs["ida"].bearing_force[:, k]))  # measured 5e-6 (journal), 2e-5 (damper)


def test_a_damper_beside_a_gecim_bearing_is_refused_on_bdf2():
    """What still cannot run on BDF2: films of different kinds (here a damper beside a bearing with the Gecim bulk);
    the refusal names the method to use."""
    from transient.models.journal.bearing import omega
    from transient.physics.layered import Gecim

    cl, mu = BEARING["clearance"], BEARING["viscosity"]
    gecim = JournalBearing(**BEARING, grid=(16, 4), rheology=Gecim(kappa=0.65 * mu * omega(SPEED) * 0.5 *
                                                                     BEARING["diameter"] / cl, viscosity_ratio=0.57))
    s = RotorBearingSystem(Rotor.jeffcott(**ROTOR), {0: gecim, 2: SqueezeFilmDamper(**DAMPER, grid=(16, 2))},
                           unbalance=[(1, 1e-4, 0.0)], gravity=9.81)
    with pytest.raises(ValueError, match='method "bdf2" takes bearings of one film kind.*damper.*method="ida"'):
        ContentSystem(s.dae(SPEED))  # what run(integration=Integration(method="bdf2")) builds
