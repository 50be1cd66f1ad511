"""A journal tilted in its bearing: the gap, the film moments and the 4 x 4 linear coefficients.

Axes (those of :mod:`transient.models.rotor`): x towards the load, y at +90 deg in the direction of rotation, z
along the shaft so that (x, y, z) is right-handed (the shaft turns about +z); the bearing's mid-plane is z = 0.
The rotor's tilts ``tx``, ``ty`` [rad] are right-handed rotations about x and y, so a shaft tilted by them has
its centre at ``x(z) = x + ty z``, ``y(z) = y - tx z``. The gap of a journal tilted by ``t_j`` in a bush tilted by
``t_b`` (the bearing's static misalignment) depends on the difference ``t = t_j - t_b``::

    h(phi, z) = C + e_x(z) cos(phi) + e_y(z) sin(phi),   e_x(z) = x + t_y z,   e_y(z) = y - t_x z

or, in the film's groups (:mod:`transient.models.journal.kernels`, ``zbar = z / R``)::

    H = gap0 + X cos(phi) + Y sin(phi),   gap0 = 1 + zbar (a cos(phi) + b sin(phi)),   a = t_y R / C,  b = -t_x R / C

The film's pressure acts on the journal at ``r = (-R cos(phi), -R sin(phi), z)`` with the force
``p (cos(phi), sin(phi), 0) dA``; its moment about the bearing centre is::

    M_x = -int z p sin(phi) dA = -p0 R^3 sym sum zbar P sin(phi) A,   M_y = int z p cos(phi) dA

(the generalised forces of ``tx`` and ``ty``: ``(M_x, M_y) = p0 R^3 (-F_b, F_a)`` with ``F_a = sum zbar P cos A``,
``F_b = sum zbar P sin A`` the forces conjugate to ``a`` and ``b``).

The gap is affine in ``(a, b)`` as it is in ``(X, Y)``: the same film on the geometry ``(zbar cos, zbar sin, area,
1 + X cos + Y sin)`` at the "position" ``(a, b)`` has the same gap, and its position and velocity columns and its
"force" are those of the tilts, the tilt rates (in the squeeze term ``theta dH/dtau``) and ``(F_a, F_b)``
(:func:`tilt_view`). The 4 x 4 sensitivities (:func:`sensitivity`) are the implicit derivatives of the film
equations through both geometries, with the exact Jacobians of the film's own kernels.
"""

from __future__ import annotations

import copy

import numpy as np
import scipy.sparse as sp

from transient.checks import check_vector
from transient.models.journal.kernels import film_force
from transient.models.journal.scales import CellGeometry

#: Largest tilt [rad] a bearing takes (a journal tilted by more is no longer a small rotation)
MAX_TILT = 0.1


def check_tilt(name, tilt) -> tuple[float, float]:
    """A (tilt about x, tilt about y) pair [rad] within ``MAX_TILT``."""
    tx, ty = check_vector(name, tilt, "rad", 2, -MAX_TILT, MAX_TILT, why="(tilt about x, tilt about y)")
    return float(tx), float(ty)


def tilt_groups(tilt, radius, clearance) -> tuple[float, float]:
    """The film's tilt groups ``(a, b) = (t_y, -t_x) R / C`` of a relative tilt ``(t_x, t_y)`` [rad]."""
    tx, ty = tilt
    return ty * radius / clearance, -tx * radius / clearance


def set_gap(geo: CellGeometry, zbar, a, b):
    """Fill ``geo.gap0 = 1 + zbar (a cos + b sin)`` in place (the arrays the kernels hold stay the same)."""
    geo.gap0[:] = 1.0 + zbar * (a * geo.cosp + b * geo.sinp)


def edge_eccentricities(X, Y, a, b, half) -> tuple[float, float]:
    """The journal's eccentricity ratio at the two ends ``zbar = -half, +half`` of the bearing."""
    return float(np.hypot(X - a * half, Y - b * half)), float(np.hypot(X + a * half, Y + b * half))


def check_open(X, Y, a, b, half, limit, tilt, what="the journal"):
    """Refuse a journal position and tilt whose gap closes at an end (eccentricity ratio there ``>= limit``)."""
    e = max(edge_eccentricities(X, Y, a, b, half))
    if not e < limit:
        raise ValueError(f"tilt = ({tilt[0]:.6g}, {tilt[1]:.6g}) [rad] with {what} at eccentricity ratio "
                         f"{np.hypot(X, Y):.4g}: the film closes at a bearing end (eccentricity ratio {e:.4g} there); "
                         f"allowed: a tilt whose edge eccentricity ratio stays below {limit:.4g}")


def half_length(grid) -> float:
    """Half the bearing length in R: the largest ``|zbar|`` of the grid's axial edges."""
    return float(max(abs(grid.z.edges[0]), abs(grid.z.edges[-1])))


def tilt_min_film(film, X, Y) -> float:
    """Smallest gap [C] of a film over the bearing at (X, Y) with its tilt: ``1 - max`` of the end eccentricities
    (``|e(z)|`` is convex in z; ``1 - e`` for an aligned journal)."""
    a, b = film.tilt
    return 1.0 - max(edge_eccentricities(X, Y, a, b, half_length(film.grid)))


def zbar_of(film) -> np.ndarray:
    """Axial coordinate ``z / R`` of every cell of a film (z = 0 at the mid-plane)."""
    return film.grid.zc


def moment(film, P) -> tuple[float, float]:
    """Moments ``(M_x, M_y)`` [N m] of the film pressure ``P`` (p0 units) about the bearing centre (module
    docstring); zero on a half bearing with a symmetry plane (the mirror halves cancel)."""
    if film.sym != 1.0:
        return 0.0, 0.0
    z = zbar_of(film)
    fa, fb = film_force(np.ascontiguousarray(P, dtype=float), z * film.cosp, z * film.sinp, film.area, 1.0)
    scale = film.force_scale * film.scales.radius
    return -fb * scale, fa * scale


def tilt_view(film, X, Y):
    """The film with the tilts as its position (module docstring): a shallow copy on the geometry
    ``(zbar cos, zbar sin, area, 1 + X cos + Y sin)`` (scratch arrays shared); evaluate it at ``(a, b)``."""
    z = zbar_of(film)
    view = copy.copy(film)
    geo = CellGeometry(np.ascontiguousarray(z * film.cosp), np.ascontiguousarray(z * film.sinp), film.area,
                       1.0 + X * film.cosp + Y * film.sinp)
    view.geo = geo
    view.cosp, view.sinp, view.area, view.gap0 = geo
    return view


def sensitivity(film, u, X, Y):
    """The generalised forces ``F = (F_x, F_y, F_a, F_b)`` of a steady film ``u`` at ``(X, Y)`` with its tilt
    groups ``film.tilt = (a, b)``, and their exact derivatives by ``q = (X, Y, a, b)`` and by the rates
    ``v = dq/dtau``: implicit differentiation ``G_u du = -G_q dq`` with the film's own linear response
    (``film.linear_response``: the Reynolds film's on its active set) and ``dF = F_u du``.
    Returns ``(F, dF/dq, dF/dv)`` (4, 4 x 4, 4 x 4), dimensionless."""
    n = film.n
    a, b = film.tilt
    view = tilt_view(film, X, Y)
    Jt = view.op.matrix(view.jacobian_data(u, a, b))
    Ft = np.array(view.force(u, a, b))
    J = film.op.matrix(film.jacobian_data(u, X, Y))  # last: the film's fields are those of (u, X, Y)
    F = np.array(film.force(u, X, Y))
    Gq = sp.hstack([J[:n, n:n + 2], Jt[:n, n:n + 2], J[:n, n + 2:n + 4], Jt[:n, n + 2:n + 4]]).toarray()
    du = film.linear_response(u, J[:n, :n], Gq)
    w = film.pressure_slope(u) * film.sym * film.area
    z = zbar_of(film)
    rows = np.vstack([w * film.cosp, w * film.sinp, w * z * film.cosp, w * z * film.sinp])
    dF = rows @ du
    return np.concatenate([F, Ft]), dF[:, :4], dF[:, 4:]


def si_coefficients(dF_dq, dF_dv, force_scale, radius, clearance, omega):
    """The 4 x 4 stiffness K and damping C (SI; rows F_x [N], F_y [N], M_x [N m], M_y [N m], columns x, y [m],
    tx, ty [rad] and their rates) of the dimensionless sensitivities of :func:`sensitivity`:
    ``K = -A dF/dq B``, ``C = -A dF/dv B / omega`` with ``F_SI = A F`` and ``q = B q_SI`` (module docstring)."""
    s, R, C = force_scale, radius, clearance
    A = np.array([[s, 0, 0, 0], [0, s, 0, 0], [0, 0, 0, -s * R], [0, 0, s * R, 0]], dtype=float)
    B = np.array([[1 / C, 0, 0, 0], [0, 1 / C, 0, 0], [0, 0, 0, R / C], [0, 0, -R / C, 0]], dtype=float)
    return -A @ dF_dq @ B, -A @ dF_dv @ B / omega
