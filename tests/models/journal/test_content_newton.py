"""The BDF2 kernels of the journal's content film (models/journal/content_newton.py): the Newton Jacobian in the
variables z = [u, X, Y, VX, VY] against central differences for every film (plain, boundary layers, Gecim bulk),
the residual on the Newton variables' own cell fields against the one through the inversion u = C^-1(m / H), and
the half bearing (symmetry plane at the mid-plane) against the whole length on the same cells: the IDA residual and
Jacobian mirrored, and a fixed-step BDF2 orbit."""

import numpy as np
import pytest

from transient.models.journal.bearing import JournalBearing, omega
from transient.models.journal.content_newton import bdf2_from_state, bdf2_jacobian, bdf2_residual, bdf2_to_state
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.physics.layered import BoundaryLayers, Gecim
from transient.solvers.integrate import solve
from transient.solvers.integrate import bdf2 as bdf2_stepper

CL, MU, W, MASS, RPM = BEARING["clearance"], BEARING["viscosity"], ROTOR["load"], ROTOR["rotor_mass"], 6000.0
LAYERS = BoundaryLayers(thickness=0.1 * CL, viscosity=(10 * MU, 20 * MU), alpha=0.05 * CL)
GECIM = Gecim(kappa=0.65 * MU * omega(RPM) * 0.5 * BEARING["diameter"] / CL, viscosity_ratio=0.57)
FILMS = {"classical": (None, None), "layers": (LAYERS, None), "gecim": (LAYERS, GECIM)}
CJ, TAU = 37.0, 0.3


def orbit(grid=(16, 4), film="classical", unbalance=0.3, **kw):
    layers, rheology = FILMS[film]
    b = JournalBearing(**BEARING, grid=grid, layers=layers, rheology=rheology, **kw)
    return JournalOrbit(b, MASS, unbalance * CL, W, RPM)


def moving_state(o):
    """Newton variables at the equilibrium film with the journal moved and moving (cavitated, full-film and
    switching cells), and a BDF2 history ``b`` off the solution."""
    n = o.film.n
    z = o.initial_state()
    z[n:] = z[n] + 0.1, z[n + 1] - 0.05, 0.3, -0.2
    b = -CJ * o.content_state(z) + 0.01 * np.random.default_rng(0).standard_normal(z.size)
    return z, b


@pytest.mark.parametrize("film", FILMS)
def test_newton_jacobian_matches_finite_differences(film, fd_jacobian):
    """dF/dz with y' = cj y + b (the film's outflow in u plus cj A dm/dz, the force rows in u) against central
    differences of F(to_state(z)), every film, wide switch (the Gecim flux has rounding-level panel jumps that a
    narrow switch's small FD step turns into noise, tests/models/journal/test_journal_model.py)."""
    o = orbit(film=film, switch_width=1e5)
    n, args = o.film.n, o.bdf2_model().args
    z, b = moving_state(o)
    y = np.empty_like(z)

    def F(zz):
        bdf2_to_state(zz, y, args)
        out = np.empty_like(zz)
        bdf2_residual(TAU, y, CJ * y + b, out, args)
        return out

    bdf2_to_state(z, y, args)
    data = np.zeros(o.film.op.nnz)
    bdf2_jacobian(TAU, y, CJ * y + b, CJ, data, args)
    J = o.film.op.matrix(data).toarray()
    cols = np.flatnonzero(np.concatenate([o.film.op.free, np.ones(4, bool)]))
    Jfd = fd_jacobian(F, z, o.n, step=5e-4 * o.film.width)
    scale = np.max(np.abs(J[:, cols]), axis=0)
    rel = np.max(np.abs(J[:, cols] - Jfd[:, cols]), axis=0) / scale
    assert np.max(rel) < 1e-6, (np.max(rel), cols[np.argmax(rel)])
    assert np.abs(J[n + 2:, :n]).max() > 0 and np.abs(J[:n, n:n + 2]).max() > 0  # the arrow is really there


@pytest.mark.parametrize("film", ["classical", "gecim"])
def test_residual_on_the_newton_fields_equals_the_inverted_one(film):
    """The residual and Jacobian at y = to_state(z) on the fields to_state left equal those through the inversion
    u = C^-1(m / H) (the fields of another state in between) to rounding; from_state maps y back to z and leaves
    the fields alone."""
    o = orbit(film=film)
    n, args = o.film.n, o.bdf2_model().args
    z, b = moving_state(o)
    y, y_other = np.empty_like(z), np.empty_like(z)
    fast, slow = np.empty(o.n), np.empty(o.n)
    J_fast, J_slow = np.zeros(o.film.op.nnz), np.zeros(o.film.op.nnz)
    bdf2_to_state(z, y, args)
    bdf2_residual(TAU, y, CJ * y + b, fast, args)
    bdf2_jacobian(TAU, y, CJ * y + b, CJ, J_fast, args)
    back = np.empty_like(z)
    bdf2_from_state(y, back, args)
    assert np.max(np.abs(back - z) / np.maximum(1.0, np.abs(z))) < 1e-12
    again = np.empty(o.n)
    bdf2_residual(TAU, y, CJ * y + b, again, args)  # from_state did not move the fields
    assert np.array_equal(again, fast)
    z2 = z.copy()
    z2[n] += 0.01
    bdf2_to_state(z2, y_other, args)  # the fields of another state
    bdf2_residual(TAU, y, CJ * y + b, slow, args)
    bdf2_to_state(z2, y_other, args)
    bdf2_jacobian(TAU, y, CJ * y + b, CJ, J_slow, args)
    assert np.max(np.abs(slow - fast)) <= 1e-12 * np.max(np.abs(fast))
    assert np.max(np.abs(J_slow - J_fast)) <= 1e-12 * np.max(np.abs(J_fast))


def mirror(o_half, o_full, y_half):
    """A half bearing's state on the whole length: axial rows k-1 .. 0 of the half below the mid-plane, 0 .. k-1
    above it (cells in x-fastest order), the rotor states as they are."""
    nt, nz = o_half.bearing.grid_shape
    n = o_half.film.n
    cells = y_half[:n].reshape(nz, nt)
    return np.concatenate([cells[::-1].ravel(), cells.ravel(), y_half[n:]])


def half_and_whole(grid=(24, 4)):
    half = orbit(grid=grid)
    whole = orbit(grid=(grid[0], 2 * grid[1]), symmetric=False)
    assert half.bearing.symmetric and not whole.bearing.symmetric and whole.film.n == 2 * half.film.n
    return half, whole


def test_half_bearing_ida_residual_and_jacobian_mirror_the_whole_length():
    """The universal DAE (IDA) of the half bearing at a moving state and of the whole length at its mirror image:
    film rows mirrored, rotor rows (the force: the half's counted twice) and every Jacobian entry (folded over the
    plane) equal to 1e-12. (Whole IDA runs differ at the tolerance, not at rounding: IDA's error norm is an RMS
    over all unknowns, which counts the rotor's four once among n cells on the half and among 2 n on the whole.)"""
    half, whole = half_and_whole()
    z, _ = moving_state(half)
    yp = np.random.default_rng(3).standard_normal(half.n) * 1e-2
    zw, ypw = mirror(half, whole, z), mirror(half, whole, yp)
    ph, pw = half.problem(z), whole.problem(zw)
    Fh, Fw = np.empty(half.n), np.empty(whole.n)
    ph.residual(TAU, z, yp, Fh)
    pw.residual(TAU, zw, ypw, Fw)
    assert np.max(np.abs(mirror(half, whole, Fh) - Fw)) <= 1e-12 * np.max(np.abs(Fh))
    Jh, Jw = np.zeros(half.film.op.nnz), np.zeros(whole.film.op.nnz)
    ph.jac_residual(TAU, z, yp, CJ, Jh)
    pw.jac_residual(TAU, zw, ypw, CJ, Jw)
    Jh, Jw = half.film.op.matrix(Jh).toarray(), whole.film.op.matrix(Jw).toarray()
    n, nt = half.film.n, half.bearing.grid_shape[0]
    idx = np.arange(half.n)  # the whole length's index of each half state, above the mid-plane
    idx[:n] += n
    idx[n:] += n
    # a perturbation of the half's cell j moves the whole length's cell j above the mid-plane and its mirror below:
    # the half's column j is the sum of those two columns of the whole (rows above the plane and the rotor's)
    below = n - nt - (np.arange(n) // nt) * nt + np.arange(n) % nt
    Jw_folded = Jw[np.ix_(idx, idx)]
    Jw_folded[:, :n] += Jw[np.ix_(idx, below)]
    scale = np.max(np.abs(Jh))
    assert np.max(np.abs(Jw_folded - Jh)) <= 1e-12 * scale


@pytest.mark.slow  # two fixed-step orbits of 50 steps each
def test_half_bearing_bdf2_orbit_equals_the_whole_length(monkeypatch):
    """A fixed-step BDF2 orbit of the half bearing and of the whole length from the mirrored state: journal
    path and velocity, film content and mass equal to 1e-10 (same Newton decisions on the same cells). The
    stepper's weighed switch refresh prices a refresh by the band width, which differs between the two, so every
    switch refreshes here (``REFRESH_PER_BAND = 0``) to keep the Newton decisions the same."""
    monkeypatch.setattr(bdf2_stepper, "REFRESH_PER_BAND", 0.0)
    half, whole = half_and_whole((24, 3))
    y0 = half.initial_state()
    tau = np.linspace(0.0, 0.25 * 2 * np.pi, 6)
    runs = []
    for o, y in ((half, y0), (whole, mirror(half, whole, y0))):
        runs.append(solve(o.problem(y, formulation="content"), tau, method="bdf2", rtol=1e-3, atol=1e-9,
                          options={"bdf2": o.bdf2_model(), "fixed_step": 2 * np.pi / 200}))
        assert runs[-1].success, runs[-1].message
    sh, sw = runs
    n = half.film.n
    assert np.max(np.abs(sh.y[:, n:] - sw.y[:, 2 * n:])) <= 1e-10 * np.max(np.abs(sh.y[:, n:]))
    mass_h = 2 * sh.y[:, :n] @ half.film.area
    mass_w = sw.y[:, :2 * n] @ whole.film.area
    assert np.allclose(mass_h, mass_w, rtol=1e-12, atol=0)
    cells_h = np.array([mirror(half, whole, y)[:2 * n] for y in sh.y])
    assert np.max(np.abs(cells_h - sw.y[:, :2 * n])) <= 1e-10 * np.max(np.abs(sh.y[:, :n]))


@pytest.mark.parametrize("film", FILMS)
def test_newton_pattern_drops_only_zeros(film):
    """The BDF2 Newton's pattern leaves out only entries that are exactly zero in the Jacobian (a prescribed cell's
    couplings), its Jacobian is the operator-pattern one gathered, and the full-length axial groove cuts the
    periodic wrap: the band of the film block halves."""
    from transient.models.journal.content_newton import newton_jacobian
    from transient.solvers.bandlu import BorderedBandLU

    o = orbit(grid=(24, 5), film=film, switch_width=1e5)
    args = o.bdf2_model().args
    z, b = moving_state(o)
    y = np.empty_like(z)
    bdf2_to_state(z, y, args)
    full = np.zeros(o.film.op.nnz)
    bdf2_jacobian(TAU, y, CJ * y + b, CJ, full, args)
    pattern, gather = o.newton_pattern()
    data = np.zeros(pattern.nnz)
    newton_jacobian(TAU, y, CJ * y + b, CJ, data, args)
    assert np.array_equal(data, full[gather])
    dropped = np.ones(full.size, bool)
    dropped[gather] = False
    assert dropped.sum() > 0 and np.all(full[dropped] == 0.0)
    J = o.film.op.matrix(full).toarray()
    kept = np.zeros_like(J)
    kept[pattern.nonzero()] = 1.0
    assert np.array_equal(J * kept, J)
    bands = BorderedBandLU(o.film.op.pattern, 4).kl, BorderedBandLU(pattern, 4).kl  # 11, 5 (Gecim's 9 points: 19, 9)
    assert bands[1] <= 0.5 * bands[0], bands


def test_start_slope_is_that_of_the_state_whatever_fields_the_film_holds():
    """The BDF2 start's slope y' (the residual at y' = 0 solved for y') is a function of the start state alone: the
    same bits after the Newton left that state's own fields (an uninterrupted run at a chunk boundary) as after the
    fields of another state (a run resumed from a checkpoint), so a resumed run is the uninterrupted one."""
    o = orbit()
    n, args = o.film.n, o.bdf2_model().args
    pattern = o.newton_pattern()[0]
    z, _ = moving_state(o)
    y, y_other = np.empty_like(z), np.empty_like(z)
    bdf2_to_state(z, y, args)  # the film holds y's fields as the Newton left them (u = z)
    held = o._problem(y, TAU, 0.0, "content", pattern).yp0
    z2 = z.copy()
    z2[n] += 0.01
    bdf2_to_state(z2, y_other, args)  # the fields of another state
    other = o._problem(y, TAU, 0.0, "content", pattern).yp0
    assert np.array_equal(held, other)
