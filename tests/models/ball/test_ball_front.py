"""Front-following levelling (transient.models.ball.front, .track): Jacobian, conservation, closed forms,
Chiu's linear limit, grid convergence."""

import math

import numpy as np
import pytest

from transient.models.ball.front import FixedMesh, FrontLevelling, FrontMesh, remap, sine_hump_share, _graded
from transient.models.ball.levelling import chiu_depression
from transient.models.ball.track import FrontTrack
from transient.solvers.integrate import solve

EPS = 8.46e-5          # h_c/2 / h_inf at the paper's reference point
X = 9.368              # ball radius / a'


def _front_state(L, s, rng):
    """A front at s: precursor ahead, a rising film behind, a little noise (so every Jacobian entry is exercised)."""
    zc = L.mesh.centres(s)
    h = EPS + 0.6 * np.clip(zc - s, 0, None) ** 1.2 / (1e-3 + np.clip(zc - s, 0, None) ** 0.2)
    h *= 1.0 + 0.05 * rng.random(zc.size)
    return h


@pytest.mark.parametrize("bc", ["reservoir", "closed"])
@pytest.mark.parametrize("moving", [False, True])
def test_front_jacobian_matches_finite_differences(bc, moving):
    rng = np.random.default_rng(3)
    m = FrontMesh(X, 0.5 * EPS)
    L = FrontLevelling(m, bc, hstar=3 * EPS, tau=1e-3, mobility_film=0.02 if bc == "closed" else 0.0)
    s = 0.63
    y = L.state(_front_state(L, s, rng), s, moving)
    if moving:  # a mesh speed at which some faces are capillary-dominated and some advection-dominated
        sdot = L.rhs(y, moving, s)[-1]
        assert abs(sdot) > 1e-3
    J = L.jac_matrix(y, moving, s).toarray()
    n = y.size
    Jfd = np.zeros((n, n))
    for j in range(n):
        d = 1e-6 * max(abs(y[j]), 1e-6 * np.diff(m.faces(s)).min())
        e = np.zeros(n)
        e[j] = d
        Jfd[:, j] = (L.rhs(y + e, moving, s) - L.rhs(y - e, moving, s)) / (2 * d)
    scale = np.abs(J).max(axis=1, keepdims=True)
    assert np.max(np.abs(J - Jfd) / scale) < 1e-5
    pat = L.patterns[moving].toarray() > 0
    assert np.all(np.abs(Jfd)[~pat] <= 1e-9 * scale.max())


def test_uniform_film_stays_uniform_on_a_moving_mesh():
    # geometric conservation: faces moving (the level law drives s at full speed), a flat film stays flat
    m = FrontMesh(X, 0.5 * EPS)
    L = FrontLevelling(m, "closed", hstar=3 * EPS, tau=1e-3)
    y0 = L.state(np.full(m.n, 0.7), 1.0, True)
    res = solve(L.problem(y0, True), [0.0, 1e-3], rtol=1e-8, atol=1e-12)
    y = res.y_events[-1] if res.t_events.size else res.y[-1]
    s = y[-1]
    assert abs(s - 1.0) > 0.1  # the mesh moved a long way
    h = y[:-1] / m.widths(s)
    assert np.max(np.abs(h - 0.7)) < 1e-8   # (round-off of the third differences on 2e-5 cells: ~1e-9)
    assert abs(np.sum(y[:-1]) - np.sum(y0[:-1])) < 1e-12 * np.sum(y0[:-1])


def test_remap_conserves_and_is_exact_for_linear_profiles():
    rng = np.random.default_rng(0)
    xo = np.concatenate([[0.0], np.cumsum(rng.uniform(0.1, 1.0, 30))])
    xn = np.concatenate([[0.0], np.sort(rng.uniform(0, xo[-1], 50)), [xo[-1]]])
    lin = lambda a, b: 2.0 * (b - a) + 0.3 * (b * b - a * a)  # int of 2 + 0.6 x
    c = remap(xo, lin(xo[:-1], xo[1:]), xn)
    np.testing.assert_allclose(c, lin(xn[:-1], xn[1:]), rtol=1e-12, atol=1e-13)
    c_rand = rng.random(30)
    assert abs(remap(xo, c_rand, xn).sum() - c_rand.sum()) < 1e-13
    share = sine_hump_share(xn, 1.0, 2.5)
    assert share.sum() == pytest.approx(1.0, abs=1e-14) and np.all(share >= 0)


def _stretched(n, length, ratio):
    """Faces from 0 to length, cells growing geometrically by `ratio`."""
    w = ratio ** np.arange(n)
    return np.concatenate([[0.0], np.cumsum(w / w.sum() * length)])


@pytest.mark.parametrize("mode", [0, 2])
def test_linearised_levelling_rate_on_a_stretched_mesh(mode):
    # closed form: cos(kappa x), kappa = (k + 1/2) pi / X (reservoir modes), decays at h0^3 kappa^4; on a mesh
    # stretched 3 % per cell the rate converges to it (between first and second order: the stretching)
    Xl, h0, eps = 2.0, 1.0, 1e-5
    kappa = (mode + 0.5) * math.pi / Xl
    rate = h0 ** 3 * kappa ** 4
    errs = []
    for n in (40, 80, 160):
        fm = FixedMesh(_stretched(n, Xl, 1.03 ** (80 / n)))
        L = FrontLevelling(fm, "reservoir", h_res=h0)
        zc = fm.centres()
        shape = np.cos(kappa * zc)
        c0 = (h0 + eps * shape) * fm.widths()
        t_end = 0.5 / rate
        res = solve(L.problem(c0, False), [0.0, t_end], rtol=1e-11, atol=1e-16)
        dev = res.y[-1] / fm.widths() - h0
        amp = np.sum(dev * shape * fm.widths()) / np.sum(shape * shape * fm.widths())
        errs.append(abs(-math.log(amp / eps) / t_end / rate - 1.0))
    assert errs[-1] < 2e-3
    assert errs[1] / errs[2] > 2.5 and errs[0] / errs[1] > 2.5


def test_front_mesh_reproduces_chiu_for_a_small_depression():
    # thin layer (h_inf/a' = 0.01), depression of 1e-3 h_inf: no front, the linear (Chiu) regime; a mesh
    # fine at the centreline and stretched outwards
    a, hinf, sig, eta = 1e-4, 1e-6, 0.036, 0.02
    T = 3 * eta * a ** 4 / (sig * hinf ** 3)
    D = 1e-3 * hinf
    F = lambda xi: D * math.exp(-xi * xi / 4) / (a * math.sqrt(math.pi))
    fm = FixedMesh(_stretched(160, 12.0, 1.02))
    L = FrontLevelling(fm, "reservoir")
    zc = fm.centres()
    c0 = (1.0 - (D / hinf) * np.exp(-zc ** 2)) * fm.widths()
    t_hat = [0.0, 0.05, 0.5, 2.0]
    res = solve(L.problem(c0, False), t_hat, rtol=1e-9, atol=1e-14)
    for k in range(1, 4):
        z_mol = (1.0 - res.y[k][0] / fm.widths()[0]) * hinf
        z_chiu = chiu_depression(zc[0] * a, t_hat[k] * T, F, a, hinf, sig, eta)
        assert abs(z_mol - z_chiu) < 1e-2 * abs(z_chiu)


def test_track_pass_and_levelling_keep_the_volume_in_a_closed_groove():
    tr = FrontTrack(X, "closed")
    tr.start(1.0)
    v = [tr.volume()]
    st = {}
    for k in range(3):
        tr.ball_pass(EPS, 1.0, 1.0)
        v.append(tr.volume())
        tr.relax(228.0 if k == 0 else 20.0, st, rtol=1e-5, atol=1e-9)
        v.append(tr.volume())
    assert st.get("n_remesh", 0) >= 1 and st.get("n_freeze", 0) >= 1  # remeshed as the front neared the centre
    assert np.max(np.abs(np.array(v) - v[0])) < 1e-9 * v[0]


def test_the_mesh_follows_the_front_foot():
    # the cell just behind s is held at the followed level H* while the front crosses the band (at the very
    # start, while the front is fast, the blended advection lets it sit near H* rather than at it)
    tr = FrontTrack(X, "reservoir")
    tr.start(1.0)
    tr.ball_pass(EPS, 1.0, 1.0)
    st = {}
    s_prev = tr.s
    for t, tol in ((1e-3, 0.7), (1.0, 0.05), (10.0, 0.05)):
        tr.relax(t, st, rtol=1e-5, atol=1e-8)
        h = tr.c / tr.mesh.widths(tr.s)
        assert tr.s < s_prev
        assert h[tr.mesh.jc] == pytest.approx(3 * EPS, rel=tol)
        assert np.all(h[:tr.mesh.jc - 3] < 3 * EPS)  # ahead: the precursor (and its dip)
        assert np.all(h > 0.5 * EPS)                  # positive everywhere
        s_prev = tr.s


def test_front_mesh_validation_messages():
    with pytest.raises(ValueError, match="dx_min"):
        FrontMesh(X, 0.5)
    with pytest.raises(ValueError, match="does not fit"):
        FrontMesh(1.2, 1e-4)
    with pytest.raises(ValueError, match="faces"):
        FixedMesh([0.0, 1.0, 0.5, 2.0, 3.0, 4.0])
    with pytest.raises(ValueError, match="bc"):
        FrontLevelling(FrontMesh(X, 1e-4), "periodic")


@pytest.mark.slow
def test_frozen_uniform_meshes_converge_to_the_front_mesh():
    # independent check of the moving mesh (no ALE, no front law): the first pass of the reference point on
    # frozen uniform meshes of dx = 1e-3 and 5e-4 a' over the band; their front position at t = 60 T converges
    # at first order (they do not resolve eps), and the first-order extrapolation lands on the front mesh
    tr = FrontTrack(X, "reservoir", refine=2.0)
    tr.start(1.0)
    tr.ball_pass(EPS, 1.0, 1.0)
    c0, faces0 = tr.c.copy(), tr.mesh.faces(tr.s)
    tr.relax(60.0, {}, rtol=1e-5, atol=1e-8)
    s_front = tr.s
    fronts = []
    for dx in (1e-3, 5e-4):
        n1 = int(round(1.05 / dx))
        far = 1.05 + _graded(dx, 1.05, 0.08, X - 1.05)
        far[-1] = X
        fm = FixedMesh(np.concatenate([np.linspace(0.0, 1.05, n1 + 1), far[1:]]))
        L = FrontLevelling(fm, "reservoir", hstar=3 * EPS)
        c = remap(faces0, c0, fm.faces())
        res = solve(L.problem(c, False), [0.0, 60.0], rtol=1e-5, atol=1e-7 * fm.widths(),
                    options={"max_order": 2})
        h = res.y[-1] / fm.widths()
        fronts.append(fm.centres()[np.flatnonzero(h > 3 * EPS)[0]])
    assert fronts[0] > fronts[1] > s_front            # coarser meshes lag behind
    extrapolated = 2 * fronts[1] - fronts[0]
    assert abs(extrapolated - s_front) < 0.02          # (0.168 against 0.177 a')
