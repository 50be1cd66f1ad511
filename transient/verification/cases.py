"""Verification cases of the film operator: discretised closed-form problems, solved and compared.

Each function builds one grid, solves the steady Reynolds equation with
:func:`~transient.solvers.newton.solve_steady` on an incompressible film (``P = u``, ``C = 1``) and
compares with the closed forms of :mod:`transient.verification.reference`. They are shared by the tests
(``tests/fv/test_reynolds_accuracy.py``) and the validation scenario (``scenarios/film_validation.py``), so
the numbers in ``docs/validation.md`` come from exactly the discretisations the tests check.

* :func:`sommerfeld_case` -- infinitely long journal bearing, full Sommerfeld pressure;
* :func:`short_bearing_case` -- finite full-film (2 pi, negative pressures kept) bearing against
  Ocvirk's short-bearing force as ``L/D -> 0``;
* :func:`squeeze_plate_case` -- squeeze film between parallel rectangular plates, all edges ambient.

Every case returns a small dataclass with the relative errors and the Newton iteration count.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from transient.verification import reference as ref
from transient.fv.grid import Axis, Grid2D, stretched_edges
from transient.fv.reynolds import Fields, ReynoldsOperator
from transient.solvers.newton import solve_steady

#: eccentricity ratio of the journal cases
EPS = 0.6


def linear_fields(grid: Grid2D, k, cx):
    """``fields(u)`` of an incompressible film: ``P = u``, ``C = 1``, constant ``kx = kz = k`` and Couette
    density ``cx`` (``cz = 0``), all derivatives zero except ``dP/du = 1``. ``k, cx``: per-cell arrays."""
    one, zero = np.ones(grid.n), np.zeros(grid.n)
    f = Fields(None, one, one, zero, k, zero, k, zero, cx, zero)
    return lambda u: f._replace(P=u)


@dataclass
class SommerfeldResult:
    """Infinitely long bearing on ``n`` cells (``delta`` = stretching, 0 = uniform).

    ``theta, p, p_exact`` per cell (p in Pa for the default SI data); ``p_err`` = max |p - p_exact| /
    max |p_exact|; ``fy_err`` = |Fy / Fy_exact - 1|; ``fx_rel`` = |Fx / Fy_exact| (exact Fx = 0);
    ``iterations`` of the steady Newton solve."""

    n: int
    delta: float
    theta: np.ndarray
    p: np.ndarray
    p_exact: np.ndarray
    p_err: float
    fy_err: float
    fx_rel: float
    iterations: int


def sommerfeld_case(n: int, delta: float = 0.0, eps: float = EPS, mu: float = 0.02, U: float = 3.0,
                    R: float = 0.05, C: float = 1e-4) -> SommerfeldResult:
    """Infinitely long bearing: periodic ``x = R theta`` with ``n`` cells, one axial cell between two
    symmetry planes; ``p(0) = 0`` imposed by a prescribed cell centred on ``theta = 0``. With
    ``delta > 0`` the cells are stretched (:func:`~transient.fv.grid.stretched_edges`, finest at
    ``theta = pi``, the minimum film), shifted so that the first centre is still at ``theta = 0``.
    Film ``h = C (1 + eps cos theta)``, ``k = h^3/(12 mu)``, Couette ``U h / 2``; force over ``L = 1``."""
    if delta:
        e = stretched_edges(n, 2 * np.pi * R, delta, fine_at=0.5)
        x = Axis(e - 0.5 * (e[1] - e[0]), periodic=True, name="x")  # first centre at theta = 0
    else:
        x = Axis.uniform(n, 2 * np.pi * R, centred=True, periodic=True, name="x")
    z = Axis.uniform(1, 1.0, lower="symmetry", upper="symmetry", name="z")
    fixed = np.zeros(n, bool)
    fixed[0] = True
    g = Grid2D(x, z, fixed=fixed, fixed_values=0.0)
    if abs(g.xc[0]) > 1e-15:
        raise AssertionError(f"first cell centre must sit on theta = 0, got x = {g.xc[0]!r}")
    th = g.xc / R
    h = C * (1 + eps * np.cos(th))
    res = solve_steady(ReynoldsOperator(g), linear_fields(g, h**3 / (12 * mu), U * h / 2), np.zeros(g.n))
    pe = ref.sommerfeld_pressure(th, eps, mu, U, R, C)
    Fx, Fy = -np.sum(res.u * np.cos(th) * g.area), -np.sum(res.u * np.sin(th) * g.area)
    _, Fye = ref.sommerfeld_force(eps, mu, U, R, C, L=1.0)
    return SommerfeldResult(n=n, delta=float(delta), theta=th, p=res.u.copy(), p_exact=pe,
                            p_err=float(np.max(np.abs(res.u - pe)) / np.max(np.abs(pe))),
                            fy_err=float(abs(Fy / Fye - 1)), fx_rel=float(abs(Fx / Fye)),
                            iterations=res.iterations)


@dataclass
class ShortBearingResult:
    """Finite full-film bearing of ratio ``L/D`` on ``nt x nz`` cells: ``fy_err`` = |Fy / Fy_Ocvirk - 1|
    (this is the short-bearing *model* error, ~(L/D)^2, plus the discretisation error), ``fx_rel`` =
    |Fx / Fy_Ocvirk| (exact Fx = 0 for the full film), ``iterations`` of the steady Newton solve."""

    L_over_D: float
    nt: int
    nz: int
    fy_err: float
    fx_rel: float
    iterations: int


def short_bearing_case(L_over_D: float, nt: int = 240, nz: int = 160, eps: float = EPS, mu: float = 0.02,
                       U: float = 3.0, R: float = 0.05, C: float = 1e-4) -> ShortBearingResult:
    """Full 2 pi film (negative pressures kept) of a bearing of length ``L = L_over_D * 2R``: periodic
    ``x = R theta`` (``nt`` cells, centred on theta = 0), ``z`` in ``[-L/2, L/2]`` (``nz`` cells) with
    ambient ``P = 0`` at both ends. Compared with :func:`~transient.verification.reference.short_bearing_force`."""
    L = L_over_D * 2 * R
    x = Axis.uniform(nt, 2 * np.pi * R, centred=True, periodic=True, name="x")
    z = Axis.uniform(nz, L, start=-L / 2, name="z")  # ambient (P = 0) at both ends
    g = Grid2D(x, z)
    th = g.xc / R
    h = C * (1 + eps * np.cos(th))
    res = solve_steady(ReynoldsOperator(g), linear_fields(g, h**3 / (12 * mu), U * h / 2), np.zeros(g.n))
    Fx, Fy = -np.sum(res.u * np.cos(th) * g.area), -np.sum(res.u * np.sin(th) * g.area)
    _, Fye = ref.short_bearing_force(eps, mu, U, C, L, film="full")
    return ShortBearingResult(L_over_D=float(L_over_D), nt=nt, nz=nz, fy_err=float(abs(Fy / Fye - 1)),
                              fx_rel=float(abs(Fx / Fye)), iterations=res.iterations)


@dataclass
class SqueezeResult:
    """Squeeze film on an ``a x (ratio a)`` plate with ``n x (ratio n)`` cells (``delta`` = stretching):
    ``W`` numeric load (N), ``W_exact`` the series, ``err`` = |W / W_exact - 1|, Newton ``iterations``."""

    ratio: float
    n: int
    delta: float
    W: float
    W_exact: float
    err: float
    iterations: int


def squeeze_plate_case(ratio: float, n: int = 64, delta: float = 0.0, a: float = 0.01, h: float = 2e-5,
                       dhdt: float = -1e-3, mu: float = 0.05) -> SqueezeResult:
    """Parallel plates ``a x b``, ``b = ratio * a``, gap ``h`` closing at ``dhdt``, all edges ambient.

    ``n`` cells across ``a`` and ``n * ratio`` along ``b`` (``ratio`` must make that an integer). With
    ``delta > 0`` both axes are stretched (x finest at its lower edge, z finest at a quarter of its
    length). The steady solve has source ``A_i dh/dt``; the load is ``sum p_i A_i`` against
    :func:`~transient.verification.reference.squeeze_rect_load`."""
    nz = n * ratio
    if int(nz) != nz:
        raise ValueError(f"n * ratio must be an integer, got n={n!r}, ratio={ratio!r}")
    nz = int(nz)
    b = ratio * a
    if delta:
        x = Axis.stretched(n, a, delta, name="x")
        z = Axis.stretched(nz, b, delta, fine_at=0.25, name="z")
    else:
        x = Axis.uniform(n, a, name="x")
        z = Axis.uniform(nz, b, name="z")
    g = Grid2D(x, z)  # all edges ambient (Dirichlet P = 0)
    k = np.full(g.n, h**3 / (12 * mu))
    res = solve_steady(ReynoldsOperator(g), linear_fields(g, k, np.zeros(g.n)), np.zeros(g.n),
                       source=g.area * dhdt)
    W = float(res.u @ g.area)
    We = float(ref.squeeze_rect_load(a, b, h, dhdt, mu))
    return SqueezeResult(ratio=float(ratio), n=int(n), delta=float(delta), W=W, W_exact=We,
                         err=float(abs(W / We - 1)), iterations=res.iterations)


def observed_orders(sizes, errors) -> np.ndarray:
    """Observed orders of convergence ``log(e_k / e_{k+1}) / log(n_{k+1} / n_k)`` between successive grids."""
    sizes = np.asarray(sizes, dtype=float)
    errors = np.asarray(errors, dtype=float)
    return np.log(errors[:-1] / errors[1:]) / np.log(sizes[1:] / sizes[:-1])
