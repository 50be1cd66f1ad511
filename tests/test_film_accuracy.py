"""Accuracy of the finite-volume Reynolds operator against closed forms (transient.film.reference)."""

import numpy as np
import pytest

from transient.film import reference as ref
from transient.film.grid import Axis, Grid2D, stretched_edges
from transient.film.reynolds import Fields, ReynoldsOperator
from transient.film.steady import solve_steady

EPS = 0.6


def _linear_fields(g, k, cx):
    """Incompressible film: P = u, C = 1, constant k and Couette field."""
    one, zero = np.ones(g.n), np.zeros(g.n)
    f = Fields(None, one, one, zero, k, zero, k, zero, cx, zero)
    return lambda u: f._replace(P=u)


def _sommerfeld(n, delta=0.0, mu=0.02, U=3.0, R=0.05, C=1e-4):
    """Infinitely long bearing: periodic x = R theta, one axial cell between two symmetry planes,
    p(0) = 0 imposed by a prescribed cell centred on theta = 0. Returns (pressure error, force error)."""
    if delta:
        e = stretched_edges(n, 2 * np.pi * R, delta, fine_at=0.5)
        x = Axis(e - 0.5 * (e[1] - e[0]), periodic=True, name="x")  # first centre at theta = 0
    else:
        x = Axis.uniform(n, 2 * np.pi * R, centred=True, periodic=True, name="x")
    z = Axis.uniform(1, 1.0, lower="symmetry", upper="symmetry", name="z")
    fixed = np.zeros(n, bool)
    fixed[0] = True
    g = Grid2D(x, z, fixed=fixed, fixed_values=0.0)
    assert g.xc[0] == pytest.approx(0.0, abs=1e-15)
    th = g.xc / R
    h = C * (1 + EPS * np.cos(th))
    res = solve_steady(ReynoldsOperator(g), _linear_fields(g, h**3 / (12 * mu), U * h / 2), np.zeros(g.n))
    pe = ref.sommerfeld_pressure(th, EPS, mu, U, R, C)
    p_err = np.max(np.abs(res.u - pe)) / np.max(np.abs(pe))
    Fx, Fy = -np.sum(res.u * np.cos(th) * g.area), -np.sum(res.u * np.sin(th) * g.area)
    Fxe, Fye = ref.sommerfeld_force(EPS, mu, U, R, C, L=1.0)
    return p_err, abs(Fy / Fye - 1), abs(Fx / Fye)


@pytest.mark.parametrize("delta", [0.0, 0.5])
def test_sommerfeld_second_order(delta):
    grids = (40, 80, 160, 320)
    out = [_sommerfeld(n, delta) for n in grids]
    p_err = np.array([o[0] for o in out])
    orders = np.log2(p_err[:-1] / p_err[1:])
    # measured: uniform p error 8.1e-3 .. 1.27e-4, orders 2.00 2.00 2.00;
    #           stretched (delta 0.5) 5.6e-3 .. 8.5e-5, orders 2.01 2.02 2.01
    assert np.all((orders > 1.8) & (orders < 2.2)), orders
    # measured force error on n = 320: 9.1e-5 (uniform), 6.1e-5 (stretched)
    assert out[-1][1] < 1.5e-4
    # Fx = 0: exact antisymmetry on the uniform centred grid; a discretisation error on the stretched one
    # (measured 1.3e-6 of |Fy|)
    assert out[-1][2] < (1e-10 if delta == 0.0 else 1e-5)


def _short(LD, nt=240, nz=160, mu=0.02, U=3.0, R=0.05, C=1e-4):
    L = LD * 2 * R
    x = Axis.uniform(nt, 2 * np.pi * R, centred=True, periodic=True, name="x")
    z = Axis.uniform(nz, L, start=-L / 2, name="z")  # ambient (P = 0) at both ends
    g = Grid2D(x, z)
    th = g.xc / R
    h = C * (1 + EPS * np.cos(th))
    res = solve_steady(ReynoldsOperator(g), _linear_fields(g, h**3 / (12 * mu), U * h / 2), np.zeros(g.n))
    Fx, Fy = -np.sum(res.u * np.cos(th) * g.area), -np.sum(res.u * np.sin(th) * g.area)
    Fxe, Fye = ref.short_bearing_force(EPS, mu, U, C, L, film="full")
    return abs(Fy / Fye - 1), abs(Fx / Fye)


def test_short_bearing_limit():
    """Full 2 pi film, negative pressures kept: the finite bearing tends to Ocvirk's as L/D -> 0."""
    errs = np.array([_short(LD) for LD in (0.1, 0.05, 0.025)])
    fy = errs[:, 0]
    # measured (240 x 160 cells): 1.22e-2, 3.13e-3, 8.1e-4 -- the (L/D)^2 trend of the short-bearing
    # approximation (the z discretisation contributes ~2e-4 at this resolution)
    assert fy[0] < 1.5e-2
    assert np.all(fy[1:] < fy[:-1] / 3.0), fy
    assert np.all(errs[:, 1] < 1e-10)


@pytest.mark.parametrize("ratio", [1, 2, 4])
def test_squeeze_rectangular_plates(ratio, n=64, a=0.01, h=2e-5, dhdt=-1e-3, mu=0.05):
    b = ratio * a
    g = Grid2D(Axis.uniform(n, a, name="x"), Axis.uniform(n * ratio, b, name="z"))  # all edges ambient
    k = np.full(g.n, h**3 / (12 * mu))
    res = solve_steady(ReynoldsOperator(g), _linear_fields(g, k, np.zeros(g.n)), np.zeros(g.n),
                       source=g.area * dhdt)
    W = res.u @ g.area
    # measured relative errors 9.4e-4, 6.2e-4, 5.4e-4 (ratios 1, 2, 4)
    assert abs(W / ref.squeeze_rect_load(a, b, h, dhdt, mu) - 1) < 5e-3


def test_squeeze_stretched_grid_second_order(a=0.01, h=2e-5, dhdt=-1e-3, mu=0.05):
    errs = []
    for n in (16, 32, 64):
        x = Axis.stretched(n, a, 0.5, name="x")
        z = Axis.stretched(2 * n, 2 * a, 0.5, fine_at=0.25, name="z")
        g = Grid2D(x, z)
        k = np.full(g.n, h**3 / (12 * mu))
        res = solve_steady(ReynoldsOperator(g), _linear_fields(g, k, np.zeros(g.n)), np.zeros(g.n),
                           source=g.area * dhdt)
        errs.append(abs(res.u @ g.area / ref.squeeze_rect_load(a, 2 * a, h, dhdt, mu) - 1))
    orders = np.log2(np.array(errs[:-1]) / errs[1:])
    # measured: 1.12e-2, 2.82e-3, 7.1e-4 (orders 1.99, 2.00)
    assert np.all((orders > 1.8) & (orders < 2.2)), (errs, orders)
