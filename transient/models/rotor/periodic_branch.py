"""The whole system's periodic unbalance response traced in speed through its folds: pseudo-arclength continuation
of the shooting equations, with the Floquet multipliers along the branch.

The unknowns are the period map's reduced state ``z`` (free film cells, the rotor's coordinates and velocities at
shaft angle 0: :class:`~transient.models.rotor.periodic.PeriodMap`) and the speed ratio ``s = n / n_0``; the
equations ``G(z, s) = Phi(z, s) - z = 0`` (one revolution of the whole system at the speed ``s n_0``) and the
hyperplane ``t . (X - X_pred) = 0`` through the predicted point normal to the branch's tangent ``t`` (Keller 1977;
Allgower & Georg, *Introduction to Numerical Continuation Methods*, SIAM 2003, ch. 2). The arclength is measured on
the rotor's states (in the smallest clearance) and ``s``; the film cells, slaved to the rotor, carry no weight.

Each Newton step is a Newton-Picard step (Lust, Roose, Spence & Champneys, SIAM J. Sci. Comput. 19, 1998, the
continuation's bordered form): on the dominant subspace ``V`` of the monodromy ``M`` (``S = V^T M V``) the step
solves the bordered system exactly, on its complement ``Q = I - V V^T`` a Picard step (the fast film modes,
multipliers ~1e-3 here), with ``Phi_s`` by a difference in speed::

    dz = Q (r + Phi_s ds) + V a,     [ S - I          V^T Phi_s              ] [a ]   [ -V^T r           ]
                                     [ t_z^T V   t_z^T Q Phi_s + t_s         ] [ds] = [ -g - t_z^T Q r   ]

(``r = Phi - z``, ``g`` the hyperplane's residual). ``S`` and ``Phi_s`` are taken at every converged point (``p``
and one more revolutions): they give the point's Floquet multipliers (the eigenvalues of ``S``), the tangent (the
same bordered system with right-hand side ``(0, 1)``) and the chord of the next point's corrector. A fold is
where the tangent's speed component changes sign (a real multiplier crosses +1 there); it is located on the
parabola in arclength through the three points around the turn.
"""

from __future__ import annotations

import numpy as np

from transient.checks import check_choice, check_int, check_range
from transient.models.journal.bearing import check_speed
from transient.results import StatusResult, quantity, result_type

#: relative speed step of the difference ``Phi_s``; step of the monodromy's differences [smallest clearance]
SPEED_STEP, FD_STEP = 2e-3, 1e-3
#: corrector iterations before the step is halved
MAX_CORRECTOR = 10


@result_type
class PeriodicBranch(StatusResult):
    """The whole system's periodic orbits along a pseudo-arclength path in speed (module docstring), one row per
    point: ``speed_rpm`` [rpm]; ``radius`` [m] (n_points, n_nodes) the mean distance of every node from the origin
    over the orbit, ``peak`` [m] its largest; ``multipliers`` (n_points, p) the Floquet multipliers of the dominant
    subspace (largest modulus first), ``stable`` all inside the unit circle; ``arclength`` (rotor states in the
    smallest clearance and the speed ratio), ``speed_slope`` the tangent's speed component (its sign changes at a
    fold), ``states`` the system's state at shaft angle 0 per point (a run's ``start=(0, state)`` at that speed);
    ``folds_rpm`` [rpm], ``fold_arclength`` and ``fold_index`` (the row after which each fold lies); ``periods``
    integrated in all."""

    speed_rpm: np.ndarray = quantity("rpm", None)
    radius: np.ndarray = quantity("m", None)
    peak: np.ndarray = quantity("m", None)
    multipliers: np.ndarray = None
    stable: np.ndarray = None
    arclength: np.ndarray = quantity("-", None)
    speed_slope: np.ndarray = quantity("-", None)
    states: np.ndarray = quantity("-", None, repr=False)
    folds_rpm: np.ndarray = quantity("rpm", None)
    fold_arclength: np.ndarray = quantity("-", None)
    fold_index: np.ndarray = None
    nodes: list = None
    periods: int = 0

    @property
    def max_multiplier(self) -> np.ndarray:
        """The modulus of the dominant multiplier per point."""
        return np.abs(self.multipliers[:, 0])


class _Maps:
    """The period maps of ``system`` by speed ratio (a few kept), and the revolutions integrated."""

    def __init__(self, system, speed0, rtol, integrator):
        self.system, self.speed0, self.rtol, self.integrator = system, speed0, rtol, integrator
        self.maps, self.periods, self.rotor = {}, 0, None

    def __call__(self, s):
        from transient.models.rotor.periodic import PeriodMap

        key = float(s)
        if key not in self.maps:
            if len(self.maps) > 3:
                self.maps.pop(next(iter(self.maps)))
            dae = self.system.dae(key * self.speed0)
            self.maps[key] = PeriodMap(dae, 32, atol=1e-3 * self.rtol, integrator=self.integrator)
        return self.maps[key]

    def flow(self, z, s) -> np.ndarray:
        self.periods += 1
        return self(s)(z, 0.0, 2.0 * np.pi, self.rtol)

    def norm(self, d) -> float:
        """The period map's measure: the rotor's states in the smallest clearance."""
        return self(1.0).norm(d) if self.rotor is None else float(np.max(np.abs(d[self.rotor])))


class _Point:
    """A converged point: the reduced state ``z``, the speed ratio ``s``, the monodromy ``S`` on the basis ``V``
    (the chord of the next corrector), ``phi_s`` the map's speed derivative, and the next point's basis ``V_next``
    (one step of subspace iteration, ``W = M V``)."""

    def __init__(self, z, s, V, S, phi_s, multipliers, V_next):
        self.z, self.s, self.V, self.S, self.phi_s = z, s, V, S, phi_s
        self.multipliers, self.V_next = multipliers, V_next


def _derivatives(maps, z, s, fz, V) -> _Point:
    """``M V`` by differences (``FD_STEP`` on the rotor's states), the Ritz values, the refined basis and
    ``Phi_s``: the point's linearisation."""
    W = np.empty_like(V)
    for j in range(V.shape[1]):
        size = max(maps.norm(V[:, j]), 1e-3 * float(np.max(np.abs(V[:, j]))))
        e = FD_STEP / size
        W[:, j] = (maps.flow(z + e * V[:, j], s) - fz) / e
    S = V.T @ W
    mu = np.linalg.eigvals(S)
    mu = mu[np.argsort(-np.abs(mu), kind="stable")]
    ds = SPEED_STEP * s
    phi_s = (maps.flow(z, s + ds) - fz) / ds
    return _Point(z, s, V, S, phi_s, mu, np.linalg.qr(W)[0])


def _bordered(V, S, phi_s, weight, t_z, t_s, r, g):
    """The Newton-Picard step (dz, ds) of the module docstring (``weight`` selects the rotor's states)."""
    Qr = r - V @ (V.T @ r)
    Qp = phi_s - V @ (V.T @ phi_s)
    tw = weight * t_z
    p = V.shape[1]
    A = np.zeros((p + 1, p + 1))
    A[:p, :p] = S - np.eye(p)
    A[:p, p] = V.T @ phi_s
    A[p, :p] = tw @ V
    A[p, p] = tw @ Qp + t_s
    b = np.concatenate([-(V.T @ r), [-g - tw @ Qr]])
    x = np.linalg.solve(A, b)
    a, ds = x[:p], x[p]
    return Qr + Qp * ds + V @ a, ds


def _tangent(point, weight, t_z, t_s):
    """The unit tangent (in the weighted norm) at ``point``, oriented along ``(t_z, t_s)``."""
    dz, ds = _bordered(point.V, point.S, point.phi_s, weight, t_z, t_s, np.zeros_like(point.z), -1.0)
    size = float(np.sqrt(np.sum(weight * dz * dz) + ds * ds))
    return dz / size, ds / size


def _correct(maps, point, z_pred, s_pred, t_z, t_s, weight, tol):
    """The corrector from the prediction on ``point``'s chord: (z, s, Phi(z), iterations) or None."""
    z, s = z_pred.copy(), s_pred
    for it in range(1, MAX_CORRECTOR + 1):
        if not 0.0 < s:
            return None
        fz = maps.flow(z, s)
        if not np.all(np.isfinite(fz)):
            return None
        r = fz - z
        g = float((weight * t_z) @ (z - z_pred) + t_s * (s - s_pred))
        dz, ds = _bordered(point.V, point.S, point.phi_s, weight, t_z, t_s, r, g)
        if maps.norm(r) < tol and abs(ds) < tol:
            return z, s, fz, it
        z, s = z + dz, s + ds
    return None


def continue_fixed_points(maps, z0, V, weight, direction, bounds, path: PathSettings, orbit=None) -> tuple:
    """Pseudo-arclength continuation of the fixed points of ``maps.flow(z, s)`` in ``s`` from the fixed point
    ``z0`` at ``s = 1`` (module docstring), model-free: ``maps.norm(d)`` the convergence measure, ``V`` the start
    basis of the dominant subspace, ``weight`` per component of ``z`` in the arclength, ``direction`` +-1 the first
    sense of ``s``, ``bounds`` the (low, high) ``s`` that end the path, ``path`` the steps, ``orbit(z, s)`` a row per
    converged point (default None). Returns (points, rows, speed slopes, arclengths, fold rows, message)."""
    flow0 = maps.flow(z0, 1.0)
    point = _derivatives(maps, z0, 1.0, flow0, V)
    t_z, t_s = _tangent(point, weight, np.zeros_like(z0), float(direction))
    points, rows, slopes, arc = [point], [orbit(z0, 1.0) if orbit else None], [t_s], [0.0]
    fold_at, h, message = [], path.step, ""
    while len(points) < path.max_points:
        out = _correct(maps, point, point.z + h * t_z, point.s + h * t_s, t_z, t_s, weight, path.tol)
        if out is None:
            if h <= path.step / 32:
                message = f"the continuation stalled at s = {point.s:.6g} (step {h:.3g})"
                break
            h *= 0.5
            continue
        z, s, fz, its = out
        rows.append(orbit(z, s) if orbit else None)
        new = _derivatives(maps, z, s, fz, point.V_next)
        n_z, n_s = _tangent(new, weight, t_z, t_s)
        if np.sign(n_s) != np.sign(t_s):
            fold_at.append(len(points) - 1)
        dz = z - point.z
        arc.append(arc[-1] + float(np.sqrt(np.sum(weight * dz * dz) + (s - point.s) ** 2)))
        points.append(new)
        slopes.append(n_s)
        point, t_z, t_s = new, n_z, n_s
        if not bounds[0] <= s <= bounds[1]:
            break
        h = min(path.max_step, 1.5 * h) if its <= 4 else h
    else:
        message = f"max_points = {path.max_points} reached"
    return points, rows, slopes, arc, fold_at, message


class PathSettings:
    """The continuation's steps, checked: ``step`` and ``max_step`` in the arclength, ``max_points``, ``tol`` on
    ``maps.norm`` of the residual and on the step in ``s``."""

    def __init__(self, step=0.02, max_step=0.05, max_points=40, tol=1e-6):
        self.step = check_range("step", step, "-", 1e-5, 0.5)
        self.max_step = check_range("max_step", max_step, "-", self.step, 1.0)
        self.max_points = check_int("max_points", max_points, "-", 2, 10000)
        self.tol = check_range("tol", tol, "-", 1e-14, 1e-2)


def trace_branch(system, start_rpm, speed_range_rpm, start, *, step=0.02, max_step=0.05, max_points=40,
                 rtol=1e-6, tol=None, integrator="bdf2", direction=1) -> PeriodicBranch:
    """The whole system's periodic orbits from the orbit through ``start`` (a state at shaft angle 0 near a periodic
    orbit at ``start_rpm``, e.g. ``periodic_response(...).state``) along the branch by pseudo-arclength continuation
    (module docstring), speed rising first (``direction`` 1) or falling (-1), until the path leaves
    ``speed_range_rpm`` or ``max_points`` are reached; ``step``, ``max_step`` in the arclength (rotor states in the
    smallest clearance, speed ratio); ``tol`` [smallest clearance] on the rotor's states and the speed ratio
    (default ``rtol``); the period map's ``integrator`` and its ``rtol`` as :func:`periodic_response`."""
    from transient.models.rotor.circular_orbits import rotor_basis
    from transient.models.rotor.periodic import INTEGRATORS

    n0 = check_speed(start_rpm)
    lo, hi = (check_speed(v) for v in speed_range_rpm)
    if not lo <= n0 <= hi:
        raise ValueError(f"start_rpm = {start_rpm!r} [rpm] outside speed_range_rpm = {speed_range_rpm!r}; allowed: "
                         "low <= start_rpm <= high")
    rtol = check_range("rtol", rtol, "-", 1e-12, 1e-2)
    path = PathSettings(step, max_step, max_points, rtol if tol is None else tol)
    check_choice("integrator", integrator, INTEGRATORS)
    if direction not in (1, -1):
        raise ValueError(f"direction = {direction!r}; allowed: 1 (speed rising first) or -1 (falling)")
    maps = _Maps(system, n0, rtol, integrator)
    F = maps(1.0)
    maps.rotor = F.rotor
    weight = np.zeros(int(np.count_nonzero(F.keep)))
    weight[F.rotor] = 1.0
    p0 = system.periodic_response(n0, rtol=rtol, tol=path.tol, integrator=integrator, start=start)
    maps.periods += p0.periods
    if not p0.converged:
        return _branch(system, [], [], [], [], [], [], f"no periodic orbit at {n0:g} rpm: {p0.message}", 1.0,
                       maps.periods)
    V = np.linalg.qr(rotor_basis(system, n0))[0] if p0.basis is None else np.asarray(p0.basis)
    points, rows, slopes, arc, fold_at, message = continue_fixed_points(
        maps, F.reduce(p0.state), V, weight, direction, (lo / n0, hi / n0), path,
        lambda z, s: _orbit(system, maps, z, s))
    message = message.replace("s = ", "").replace(" (step", f" x {n0:g} rpm (step") if message else message
    speeds = np.array([q.s * n0 for q in points])
    folds = [_fold(np.array(arc), speeds, i, slopes[i] > 0) for i in fold_at]
    return _branch(system, points, rows, slopes, arc, folds, fold_at, message, n0, maps.periods)


def _fold(arc, speeds, i, rising):
    """(speed, arclength) of the turn between rows ``i`` and ``i + 1`` (a largest speed when the path was
    ``rising``): the vertex of the parabola in arclength through the three rows around the extreme one."""
    j = i if (speeds[i] > speeds[i + 1]) == rising else i + 1
    j = int(np.clip(j, 1, arc.size - 2))
    a, b, c = np.polyfit(arc[j - 1:j + 2], speeds[j - 1:j + 2], 2)
    if a == 0.0:
        return float(speeds[j]), float(arc[j])
    return float(c - b * b / (4 * a)), float(-b / (2 * a))


def _orbit(system, maps, z, s):
    """(mean radius, peak radius) [m] per node over the orbit from ``z`` at ``s``, and the system's state there."""
    F = maps(s)
    key = np.asarray(z, dtype=float).tobytes()
    if key not in F.samples:
        maps.flow(z, s)
    _, _, Q = F.samples[key]
    d = system._node_displacements(Q * F.dae.L)
    r = np.hypot(d[..., 0], d[..., 1])
    return r.mean(axis=0), r.max(axis=0), F.embed(z)


def _branch(system, points, rows, tangents, arc, folds, fold_at, message, n0, periods) -> PeriodicBranch:
    nodes = list(system.rotor.nodes)
    n = len(points)
    p = max([q.multipliers.size for q in points], default=0)
    mu = np.full((n, p), np.nan, dtype=complex)
    for i, q in enumerate(points):
        mu[i, :q.multipliers.size] = q.multipliers
    radius = np.array([r[0] for r in rows]).reshape(n, len(nodes))
    peak = np.array([r[1] for r in rows]).reshape(n, len(nodes))
    return PeriodicBranch(
        speed_rpm=np.array([q.s * n0 for q in points], dtype=float), radius=radius, peak=peak, multipliers=mu,
        stable=np.all(np.abs(np.nan_to_num(mu)) < 1.0, axis=1), arclength=np.asarray(arc, dtype=float),
        speed_slope=np.asarray(tangents, dtype=float), states=np.array([r[2] for r in rows]).reshape(n, -1),
        folds_rpm=np.array([f[0] for f in folds]), fold_arclength=np.array([f[1] for f in folds]),
        fold_index=np.array(fold_at, dtype=int), nodes=nodes, periods=int(periods),
        success=bool(points) and not message, message=message or f"{len(folds)} folds")


__all__ = ["PathSettings", "PeriodicBranch", "continue_fixed_points", "trace_branch"]
