"""Analytic Jacobians of the finite-volume Reynolds operator against central finite differences."""

import numpy as np
import pytest
from scipy.special import expit

from transient.fv.grid import Axis, Grid2D, stretched_edges
from transient.fv.reynolds import Fields, ReynoldsOperator, integrate, integrate_gradient

BETA, WIDTH, ALPHA = 5.0, 0.05, 0.3


def _grid(case):
    if case == "periodic-x":
        x = Axis(stretched_edges(7, 2 * np.pi, 0.4, fine_at=0.3), periodic=True, name="x")
        z = Axis.uniform(5, 0.8, lower="dirichlet", upper="symmetry", name="z")
        fixed = np.zeros((5, 7), bool)
        fixed[1, 0] = fixed[3, 4] = True
    else:  # bounded x with Dirichlet ends, periodic z
        x = Axis(np.array([0.0, 0.3, 0.5, 0.9, 1.2, 1.4, 2.0]), lower="dirichlet", upper="dirichlet", name="x")
        z = Axis.stretched(6, 1.5, 0.3, periodic=True, name="z")
        fixed = np.zeros((6, 6), bool)
        fixed[2, 3] = True
    return Grid2D(x, z, fixed=fixed, fixed_values=1.05)


def _fields(g, u, q):
    """Elrod-like smooth switch P, nonlinear C, Barus-like k(u), Couette fields of both signs; h(q)."""
    th = g.xc
    h = 1.0 + q[0] * np.cos(th) + q[1] * np.sin(th) + 0.1 * g.zc
    dh = np.stack([np.cos(th), np.sin(th)])
    x = (u - 1.0) / WIDTH
    P = BETA * WIDTH * np.logaddexp(0.0, x)
    dP = BETA * expit(x)
    C = u * (1.0 + 0.1 * u)
    dC = 1.0 + 0.2 * u
    ex = np.exp(-ALPHA * P)
    kx = h**3 / 12.0 * ex
    dkx = -ALPHA * kx * dP
    kz, dkz = 0.7 * kx, 0.7 * dkx
    Ux = np.cos(2.0 * th + 0.3)
    Uz = 0.4 * np.sin(th + 1.0)
    cx, cz = 0.5 * Ux * h, 0.5 * Uz * h
    dq = (3.0 * kx / h * dh, 3.0 * kz / h * dh, 0.5 * Ux * dh, 0.5 * Uz * dh)
    return Fields(P, dP, C, dC, kx, dkx, kz, dkz, cx, cz), dq


def _face_margin(op, f):
    """Smallest |c_L + c_R| over interior faces and |c| over Dirichlet faces (upwind switch distance)."""
    c = np.where(op.fdir == 0, f.cx[op.fL] + f.cx[op.fR], f.cz[op.fL] + f.cz[op.fR])
    cb = np.where(op.bdir == 0, f.cx[op.bcell], f.cz[op.bcell])
    return min(np.min(np.abs(c)), np.min(np.abs(cb)) if cb.size else np.inf)


@pytest.mark.parametrize("case", ["periodic-x", "dirichlet-x"])
@pytest.mark.parametrize("upwind", [False, True])
@pytest.mark.parametrize("n_extra", [0, 2])
def test_jacobian_matches_finite_differences(case, upwind, n_extra):
    g = _grid(case)
    op = ReynoldsOperator(g, n_extra=n_extra, upwind=upwind, boundary_P=0.2, boundary_C=0.9)
    if case == "dirichlet-x":
        op.set_boundary("x+", P=np.linspace(0.1, 0.4, g.nz), C=0.7)
    rng = np.random.default_rng(3)
    u = 0.9 + 0.4 * rng.random(g.n)
    u[g.fixed] = 1.05
    q = np.array([0.3, -0.2])
    f, dq = _fields(g, u, q)
    assert _face_margin(op, f) > 1e-3  # FD steps must not cross an upwind switch
    assert np.any(f.cx < 0) and np.any(f.cx > 0)

    data = op.jacobian_of(f, dq=dq if n_extra else None)
    J = op.matrix(data).toarray()[: g.n]

    def R(v, qq):
        return op.residual_of(v, _fields(g, v, qq)[0])

    n_cols = g.n + n_extra
    J_fd = np.zeros((g.n, n_cols))
    for c in range(n_cols):
        du = np.zeros(g.n)
        dqv = np.zeros(2)
        eps = 1e-6
        if c < g.n:
            du[c] = eps
        else:
            dqv[c - g.n] = eps
        J_fd[:, c] = (R(u + du, q + dqv) - R(u - du, q - dqv)) / (2 * eps)
    err = np.max(np.abs(J - J_fd[:, : J.shape[1]])) / np.max(np.abs(J_fd))
    assert err < 1e-6, err
    # the pattern holds every nonzero derivative; fixed rows are the identity
    assert np.all(np.abs(J_fd[:, : g.n][op.matrix(np.ones(op.nnz)).toarray()[: g.n, : g.n] == 0]) < 1e-12)
    fixed = np.flatnonzero(g.fixed)
    assert np.allclose(J[fixed][:, : g.n], np.eye(g.n)[fixed])
    if n_extra:
        Jq, Jq_fd = J[:, g.n:], J_fd[:, g.n:]
        assert np.max(np.abs(Jq_fd)) > 0.1  # the extras really couple
        assert np.max(np.abs(Jq - Jq_fd)) / np.max(np.abs(Jq_fd)) < 1e-6


def test_integrate_gradient_matches_finite_differences():
    g = _grid("periodic-x")
    u = 0.9 + 0.4 * np.random.default_rng(5).random(g.n)
    w = -np.cos(g.xc)
    f, _ = _fields(g, u, np.array([0.3, -0.2]))
    grad = np.empty(g.n)
    integrate_gradient(f.dP, w, g.area, grad)
    fd = np.empty(g.n)
    for i in range(g.n):
        e = np.zeros(g.n)
        e[i] = 1e-6
        fd[i] = (integrate(_fields(g, u + e, [0.3, -0.2])[0].P, w, g.area)
                 - integrate(_fields(g, u - e, [0.3, -0.2])[0].P, w, g.area)) / 2e-6
    assert np.max(np.abs(grad - fd)) / np.max(np.abs(fd)) < 1e-6
    assert integrate(np.ones(g.n), np.ones(g.n), g.area) == pytest.approx(2 * np.pi * 0.8, rel=1e-14)


SHEAR = 0.5  # strength of the pressure-gradient dependence of the per-face conductance below


def _face_k(op, f, dq):
    """A per-face conductance that depends on the face's own pressure gradient G (shear-thinning-like):
    k_f = kbar_f / (1 + SHEAR G^2), kbar_f the arithmetic mean of the cells; with its exact derivatives."""
    def one(kL, kR, dkL, dkR, PL, PR, dPL, dPR, d, dkqL, dkqR):
        G = (PR - PL) / d
        s = 1.0 + SHEAR * G * G
        kbar = 0.5 * (kL + kR)
        kf = kbar / s
        dk_dG = -kbar * 2.0 * SHEAR * G / s**2
        return kf, 0.5 * dkL / s + dk_dG * (-dPL / d), 0.5 * dkR / s + dk_dG * (dPR / d), 0.5 * (dkqL + dkqR) / s

    kx_or_kz = lambda d, a, b: np.where(d == 0, a, b)  # noqa: E731
    L, R = op.fL, op.fR
    k = kx_or_kz(op.fdir, f.kx[L], f.kz[L]), kx_or_kz(op.fdir, f.kx[R], f.kz[R])
    dk = kx_or_kz(op.fdir, f.dkx[L], f.dkz[L]), kx_or_kz(op.fdir, f.dkx[R], f.dkz[R])
    dkq = (kx_or_kz(op.fdir, dq[0][:, L], dq[1][:, L]), kx_or_kz(op.fdir, dq[0][:, R], dq[1][:, R]))
    kf, dkf_L, dkf_R, dkf_q = one(k[0], k[1], dk[0], dk[1], f.P[L], f.P[R], f.dP[L], f.dP[R], op.fd, dkq[0], dkq[1])
    i = op.bcell
    sign = op.bside  # the boundary value is on the cell's upper (+1) or lower (-1) side
    kc, dkc = kx_or_kz(op.bdir, f.kx[i], f.kz[i]), kx_or_kz(op.bdir, f.dkx[i], f.dkz[i])
    dkcq = kx_or_kz(op.bdir, dq[0][:, i], dq[1][:, i])
    G = sign * (op.bP - f.P[i]) / op.bd
    s = 1.0 + SHEAR * G * G
    kb = kc / s
    dkb = dkc / s - kc * 2.0 * SHEAR * G / s**2 * (-sign * f.dP[i] / op.bd)
    return (kf, dkf_L, dkf_R, np.ascontiguousarray(dkf_q), kb, dkb, np.ascontiguousarray(dkcq / s))


@pytest.mark.parametrize("case", ["periodic-x", "dirichlet-x"])
def test_per_face_conductances_jacobian_matches_finite_differences(case):
    """The per-face seam: a conductance of the face's own pressure gradient, derivatives by both cells and by
    the extras, against central finite differences; and the arithmetic mean given per face changes nothing."""
    g = _grid(case)
    op = ReynoldsOperator(g, n_extra=2, upwind=True, boundary_P=0.2, boundary_C=0.9)
    rng = np.random.default_rng(4)
    u = 0.9 + 0.4 * rng.random(g.n)
    u[g.fixed] = 1.05
    q = np.array([0.3, -0.2])
    f, dq = _fields(g, u, q)
    fk = _face_k(op, f, dq)
    assert np.max(np.abs(fk[0] / (0.5 * (np.where(op.fdir == 0, f.kx[op.fL] + f.kx[op.fR],
                                                          f.kz[op.fL] + f.kz[op.fR]))) - 1)) > 0.05  # really nonlinear
    J = op.matrix(op.jacobian(*f[:10], dq=dq, face_k=fk)).toarray()[: g.n]

    def R(v, qq):
        fv, dqv = _fields(g, v, qq)
        return op.residual(v, fv.P, fv.C, fv.kx, fv.kz, fv.cx, fv.cz, face_k=_face_k(op, fv, dqv))

    J_fd = np.zeros((g.n, g.n + 2))
    for c in range(g.n + 2):
        du, dqv = np.zeros(g.n), np.zeros(2)
        if c < g.n:
            du[c] = 1e-6
        else:
            dqv[c - g.n] = 1e-6
        J_fd[:, c] = (R(u + du, q + dqv) - R(u - du, q - dqv)) / 2e-6
    assert np.max(np.abs(J - J_fd)) / np.max(np.abs(J_fd)) < 1e-6
    # the arithmetic mean handed in per face gives the default operator exactly
    kx_or_kz = lambda d, a, b: np.where(d == 0, a, b)  # noqa: E731
    L, Rr, i = op.fL, op.fR, op.bcell
    mean = (0.5 * kx_or_kz(op.fdir, f.kx[L] + f.kx[Rr], f.kz[L] + f.kz[Rr]),
            0.5 * kx_or_kz(op.fdir, f.dkx[L], f.dkz[L]), 0.5 * kx_or_kz(op.fdir, f.dkx[Rr], f.dkz[Rr]),
            np.ascontiguousarray(0.5 * kx_or_kz(op.fdir, dq[0][:, L] + dq[0][:, Rr], dq[1][:, L] + dq[1][:, Rr])),
            kx_or_kz(op.bdir, f.kx[i], f.kz[i]), kx_or_kz(op.bdir, f.dkx[i], f.dkz[i]),
            np.ascontiguousarray(kx_or_kz(op.bdir, dq[0][:, i], dq[1][:, i])))
    np.testing.assert_array_equal(op.residual(u, f.P, f.C, f.kx, f.kz, f.cx, f.cz, face_k=mean), op.residual_of(u, f))
    np.testing.assert_allclose(op.jacobian(*f[:10], dq=dq, face_k=mean), op.jacobian_of(f, dq=dq), rtol=1e-15, atol=1e-15)
