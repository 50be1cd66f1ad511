"""Synchronous circular centred orbits of an axisymmetric rotor on squeeze-film dampers: the unbalance response
curve through its folds (the damper's jump), and the start of the whole system's shooting on it.

Without gravity, an axisymmetric rotor whose every film is a damper's settles under unbalance on a forward
synchronous whirl in which every node describes a circle: ``x + i y = Z e^{i Omega t}``. Each damper's film is then
steady in the frame whirling with its journal (:meth:`~transient.models.damper.SqueezeFilmDamper.circular_orbit`:
the force ``f(eps, Omega) = F_r + i F_t`` along and across the line of centres), and the rotor's equations are
algebraic in the complex amplitudes of the x coordinates (the y ones are ``-i`` times them)::

    D(Omega) Q = Omega^2 sum_u m e e^{i a} t_u + sum_d t_d f_d(|Z_d| / c_d, Omega) Z_d / |Z_d|,
    D = K - Omega^2 M + i Omega (C + Omega G),        t = T_x^T - i T_y^T,        Z_d = T_x,d Q

(``K`` with the dampers' centring springs). With ``z_d = Z_d / c_d`` and ``s = Omega / Omega_0`` the residual
``z_d - T_x,d Q / c_d`` is 2 n_dampers real equations in 2 n_dampers + 1 unknowns: a curve, traced by
pseudo-arclength continuation (Keller 1977; Allgower & Georg, *Introduction to Numerical Continuation Methods*,
SIAM 2003, ch. 2) so that it passes the folds where the speed turns back (the jump of a damper whose cavitated film
stiffens with the orbit: Vance, *Rotordynamics of Turbomachinery*, Wiley 1988, ch. 6). A fold is where the tangent's
speed component changes sign; it is located by the secant method on that component along the curve. Between two
folds the curve runs backwards in speed: there the orbit is a saddle (one Floquet multiplier above 1; the whole
system's shooting measures it, :func:`circular_start`).

The film of the whirling frame is the damper's own grid with its squeeze term as a transport in angle; the rotor
system's film has it in time. The two differ at second order in the circumferential cells (docs/validation.md).
"""

from __future__ import annotations

import numpy as np

from transient.checks import check_int, check_range
from transient.models.journal.bearing import check_speed
from transient.results import StatusResult, quantity, result_type
from transient.units import rpm_to_rad_s

#: finite-difference steps of the film force: in e/c and relative in the speed
EPS_STEP, SPEED_STEP = 1e-6, 1e-6
#: the largest e/c a traced orbit may reach (the film's boundary layers aside)
MAX_ORBIT = 0.97


@result_type
class CircularOrbitCurve(StatusResult):
    """The synchronous circular orbits of a rotor on squeeze-film dampers along a continuation path (module
    docstring), one row per point: ``speed_rpm`` [rpm]; per damper (``damper_nodes``) ``eccentricity_ratio`` (the
    orbit radius / clearance), ``amplitude`` (complex ``Z / c``: the journal at ``c Re(z)``, ``c Re(-i z)`` at shaft
    angle 0), ``radial_force``, ``tangential_force`` [N] (the film's, along and across the line of centres),
    ``transmitted_force`` [N] (the magnitude of film and centring spring together: what reaches the ground);
    ``arclength`` along the path (in the scaled unknowns), ``speed_slope`` the tangent's speed component (negative
    where the path runs back), ``folds_rpm`` [rpm] and ``fold_eccentricity`` (the first damper's e/c) at the folds,
    ``fold_index``: the row after which each fold lies."""

    speed_rpm: np.ndarray = quantity("rpm", None)
    eccentricity_ratio: np.ndarray = quantity("-", None)
    amplitude: np.ndarray = quantity("-", None)
    radial_force: np.ndarray = quantity("N", None)
    tangential_force: np.ndarray = quantity("N", None)
    transmitted_force: np.ndarray = quantity("N", None)
    arclength: np.ndarray = quantity("-", None)
    speed_slope: np.ndarray = quantity("-", None)
    folds_rpm: np.ndarray = quantity("rpm", None)
    fold_eccentricity: np.ndarray = quantity("-", None)
    fold_index: np.ndarray = None
    damper_nodes: list = None

    @property
    def backward(self) -> np.ndarray:
        """True on the rows where the path runs against its starting direction in speed (between folds)."""
        return np.sign(self.speed_slope) != np.sign(self.speed_slope[0])


class CircularOrbits:
    """The circular-orbit equations of ``system`` (module docstring): ``residual(x)`` of the scaled unknowns
    ``x = [Re z_1, Im z_1, ..., s]`` with the speed ``s * speed0_rpm``; the films' forces cached per (e/c, speed)."""

    def __init__(self, system, speed0_rpm):
        if not system.dampers or len(system.dampers) != len(system.bearings):
            raise ValueError("circular orbits need every film of the system to be a squeeze-film damper's (a journal "
                             "bearing's film is not steady in the whirling frame); allowed: a rotor on "
                             "SqueezeFilmDamper s only")
        if np.any(system.gravity_vector != 0.0):
            raise ValueError(f"gravity = {tuple(system.gravity_vector)} [m/s^2] with circular orbits; allowed: "
                             "gravity=0 (gravity offsets the orbits from the dampers' centres)")
        if not system.unbalance:
            raise ValueError("unbalance = []: circular orbits are the unbalance response; allowed: at least one "
                             "(node, m e, phase)")
        self.system, self.speed0 = system, float(speed0_rpm)
        r = system.rotor
        self.nodes = list(system.dampers)
        self.dampers = [system.dampers[n] for n in self.nodes]
        self.T = [r.translation(n) for n in self.nodes]
        self.tx = [T[0] for T in self.T]
        self.t = [T[0] - 1j * T[1] for T in self.T]  # the generalised force of a unit forward force, x amplitude
        self.unit = sum(me * np.exp(1j * np.radians(a)) * (r.translation(n)[0] - 1j * r.translation(n)[1])
                        for n, me, a in system.unbalance)
        self.cache = {}

    def speed(self, s) -> float:
        return float(s) * self.speed0

    def film(self, k, eps, speed_rpm) -> complex:
        """``F_r + i F_t`` [N] of damper ``k`` on the circular orbit ``eps`` at ``speed_rpm``."""
        key = (k, float(eps), float(speed_rpm))
        if key not in self.cache:
            o = self.dampers[k].circular_orbit(eps, speed_rpm)
            if not o.success:
                raise RuntimeError(f"the damper's film at e/c = {eps:.6g}, {speed_rpm:.6g} rpm: {o.message}")
            if len(self.cache) > 4000:
                self.cache.clear()
            self.cache[key] = complex(o.radial_force, o.tangential_force)
        return self.cache[key]

    def rotor_amplitudes(self, z, speed_rpm, forces=None) -> np.ndarray:
        """The rotor's complex amplitudes Q [m] (x rows; y = -i x) with the journals on ``z`` (Z / c)."""
        s, r = self.system, self.system.rotor
        w = rpm_to_rad_s(speed_rpm)
        D = s.stiffness - w * w * r.mass + 1j * w * (r.damping + w * r.gyroscopic)
        f = w * w * self.unit
        for k, (d, zk) in enumerate(zip(self.dampers, z)):
            eps = abs(zk)
            fk = self.film(k, eps, speed_rpm) if forces is None else forces[k]
            f = f + self.t[k] * fk * zk / eps
        return np.linalg.solve(D, f)

    def residual(self, x) -> np.ndarray:
        z = x[0:-1:2] + 1j * x[1:-1:2]
        if np.any(np.abs(z) >= MAX_ORBIT) or np.any(np.abs(z) <= 1e-9) or x[-1] <= 0:
            return np.full(x.size - 1, np.nan)
        Q = self.rotor_amplitudes(z, self.speed(x[-1]))
        out = np.empty(x.size - 1)
        for k, d in enumerate(self.dampers):
            rk = z[k] - self.tx[k] @ Q / d.clearance
            out[2 * k], out[2 * k + 1] = rk.real, rk.imag
        return out

    def jacobian(self, x, r0=None) -> np.ndarray:
        """(2 n, 2 n + 1) forward differences of :meth:`residual`."""
        r0 = self.residual(x) if r0 is None else r0
        J = np.empty((r0.size, x.size))
        for j in range(x.size):
            h = SPEED_STEP * x[j] if j == x.size - 1 else EPS_STEP
            xp = x.copy()
            xp[j] += h
            J[:, j] = (self.residual(xp) - r0) / h
        return J

    def check_axisymmetric(self, x):
        """Refuse a rotor whose synchronous response to a forward force is not circular at the dampers."""
        s, r = self.system, self.system.rotor
        w = rpm_to_rad_s(self.speed(x[-1]))
        D = s.stiffness - w * w * r.mass + 1j * w * (r.damping + w * r.gyroscopic)
        Q = np.linalg.solve(D, self.unit + sum(self.t))
        for n, T in zip(self.nodes, self.T):
            X, Y = T[0] @ Q, T[1] @ Q
            if abs(Y + 1j * X) > 1e-6 * max(abs(X), 1e-300):
                raise ValueError(f"rotor: the synchronous response at damper node {n} is not circular (|y + i x| = "
                                 f"{abs(Y + 1j * X) / abs(X):.3g} of |x|); allowed: an axisymmetric rotor (equal "
                                 "matrices in x and y) for circular orbits")


def _tangent(J, previous=None) -> np.ndarray:
    """The unit null vector of the (n, n + 1) Jacobian, oriented along ``previous`` (or with the speed rising)."""
    t = np.linalg.svd(J)[2][-1]
    ref = previous if previous is not None else np.eye(t.size)[-1]
    return -t if t @ ref < 0 else t


def _correct(orbits, x_pred, t, x_prev=None, max_iter=12, tol=1e-10):
    """Newton on the residual and the hyperplane ``t . (x - x_pred) = 0``: (x, its Jacobian, iterations) or None."""
    x = x_pred.copy()
    for it in range(1, max_iter + 1):
        r = orbits.residual(x)
        if not np.all(np.isfinite(r)):
            return None
        J = orbits.jacobian(x, r)
        A = np.vstack([J, t])
        dx = np.linalg.solve(A, -np.concatenate([r, [t @ (x - x_pred)]]))
        x = x + dx
        if np.max(np.abs(dx)) < tol and np.max(np.abs(r)) < 1e3 * tol:
            r = orbits.residual(x)
            if not np.all(np.isfinite(r)):
                return None
            return x, orbits.jacobian(x, r), it
    return None


def _solve_at_speed(orbits, z0, s):
    """Newton on the residual at the fixed speed ratio ``s`` from the amplitudes ``z0``: the unknowns or None."""
    x = np.concatenate([np.column_stack([z0.real, z0.imag]).ravel(), [s]])
    t = np.eye(x.size)[-1]
    out = _correct(orbits, x, t, max_iter=40)
    return None if out is None else out[0]


def first_orbit(orbits, speed_rpm) -> np.ndarray:
    """The circular orbit at ``speed_rpm`` reached from small orbits by Newton along a ramp of the unbalance (the
    unknowns ``x``); at a speed with several orbits, the one connected to the small-unbalance response."""
    s = speed_rpm / orbits.speed0
    full = orbits.unit
    z = np.full(len(orbits.dampers), 0.01 + 0.0j)
    share, dshare, x = 0.0, 0.05, None
    while share < 1.0:
        trial = min(1.0, share + dshare)
        orbits.unit = trial * full
        try:
            xt = _solve_at_speed(orbits, z, s)
        finally:
            orbits.unit = full
        if xt is None:
            dshare *= 0.5
            if dshare < 1e-4:
                raise RuntimeError(f"no circular orbit found at {speed_rpm:g} rpm (Newton along the unbalance "
                                   f"stalled at {share:.4g} of it: a fold in the unbalance)")
            continue
        x, share, dshare = xt, trial, min(0.2, 1.5 * dshare)
        z = x[0:-1:2] + 1j * x[1:-1:2]
    return x


def _fold(orbits, x, t, step, slope0, slope1, iterations=8):
    """The fold between the points ``x`` and ``x + step t`` (corrected) where the tangent's speed component changes
    sign from ``slope0`` to ``slope1``: the secant method on that component in the step along ``t``."""
    a, b, fa, fb = 0.0, step, slope0, slope1
    best = None
    for _ in range(iterations):
        c = b - fb * (b - a) / (fb - fa)
        out = _correct(orbits, x + c * t, t)
        if out is None:
            break
        y, J, _ = out
        tc = _tangent(J, t)
        best = y
        a, fa, b, fb = b, fb, c, tc[-1]
        if abs(fb) < 1e-8:
            break
    return best


def trace(system, speed_range_rpm, step=0.02, max_step=0.05, max_points=400, start_rpm=None) -> CircularOrbitCurve:
    """The circular orbits of ``system`` by pseudo-arclength continuation from ``start_rpm`` (default the low end of
    ``speed_range_rpm``) until the path leaves the range (module docstring); ``step``, ``max_step`` in the scaled
    unknowns (e/c and the speed over the start speed)."""
    lo, hi = (check_speed(v) for v in speed_range_rpm)
    if hi <= lo:
        raise ValueError(f"speed_range_rpm = {speed_range_rpm!r} [rpm]; allowed: (low, high) with low < high")
    step = check_range("step", step, "-", 1e-5, 0.5)
    max_step = check_range("max_step", max_step, "-", step, 1.0)
    max_points = check_int("max_points", max_points, "-", 2, 100000)
    start = lo if start_rpm is None else check_range("start_rpm", start_rpm, "rpm", lo, hi)
    orbits = CircularOrbits(system, start)
    x = first_orbit(orbits, start)
    orbits.check_axisymmetric(x)
    J = orbits.jacobian(x)
    t = _tangent(J)
    if start_rpm is not None and start >= hi:
        t = -t
    points, slopes, arc = [x], [t[-1]], [0.0]
    folds, fold_at = [], []
    h, message = step, ""
    while len(points) < max_points:
        out = _correct(orbits, x + h * t, t)
        if out is None or out[2] > 6:
            if h <= step / 64:
                message = f"the continuation stalled at {orbits.speed(x[-1]):.6g} rpm (step {h:.3g})"
                break
            h *= 0.5
            continue
        y, Jy, its = out
        ty = _tangent(Jy, t)
        if np.sign(ty[-1]) != np.sign(t[-1]):
            f = _fold(orbits, x, t, h, t[-1], ty[-1])
            if f is not None:
                folds.append(f)
                fold_at.append(len(points) - 1)
        arc.append(arc[-1] + float(np.linalg.norm(y - x)))
        x, t = y, ty
        points.append(x)
        slopes.append(t[-1])
        if not lo <= orbits.speed(x[-1]) <= hi:
            break
        h = min(max_step, 1.5 * h) if its <= 3 else h
    else:
        message = f"max_points = {max_points} reached"
    return _curve(orbits, np.array(points), np.array(slopes), np.array(arc), folds, fold_at, message)


def _curve(orbits, X, slopes, arc, folds, fold_at, message) -> CircularOrbitCurve:
    nd = len(orbits.dampers)
    z = X[:, 0:-1:2] + 1j * X[:, 1:-1:2]
    speeds = X[:, -1] * orbits.speed0
    eps = np.abs(z)
    fr, ft, ftr = (np.empty((len(X), nd)) for _ in range(3))
    for i in range(len(X)):
        for k, d in enumerate(orbits.dampers):
            f = orbits.film(k, eps[i, k], speeds[i])
            spring = -(d.centring_stiffness or 0.0) * eps[i, k] * d.clearance
            fr[i, k], ft[i, k], ftr[i, k] = f.real, f.imag, abs(complex(f.real + spring, f.imag))
    fz = np.array([abs(f[0] + 1j * f[1]) for f in folds])
    return CircularOrbitCurve(speed_rpm=speeds, eccentricity_ratio=eps, amplitude=z, radial_force=fr,
                              tangential_force=ft, transmitted_force=ftr, arclength=arc, speed_slope=slopes,
                              folds_rpm=np.array([f[-1] * orbits.speed0 for f in folds]), fold_eccentricity=fz,
                              fold_index=np.array(fold_at, dtype=int), damper_nodes=list(orbits.nodes),
                              success=not message, message=message or f"{len(folds)} folds")


def circular_start(system, speed_rpm, amplitude) -> np.ndarray:
    """The whole system's state at shaft angle 0 on the circular orbit whose journals are at ``amplitude``
    (complex ``Z / c`` per damper, e.g. a row of :attr:`CircularOrbitCurve.amplitude`) at ``speed_rpm`` (the
    system's DAE at that reference speed): the rotor's coordinates and velocities of the synchronous response, each
    damper's film the whirling frame's film rotated to its journal (the content carried over cell by cell,
    interpolated in angle, then the film's universal variable of it)."""
    speed = check_speed(speed_rpm)
    orbits = CircularOrbits(system, speed)
    z = np.asarray(amplitude, dtype=complex).ravel()
    if z.size != len(orbits.dampers) or np.any(np.abs(z) >= MAX_ORBIT) or np.any(np.abs(z) <= 0):
        raise ValueError(f"amplitude = {z!r}; allowed: one complex Z / c per damper ({len(orbits.dampers)}) with "
                         f"0 < |Z / c| < {MAX_ORBIT}")
    Q = orbits.rotor_amplitudes(z, speed)
    dae = system.dae(speed)
    w = rpm_to_rad_s(speed)
    y = np.zeros(dae.n)
    y[dae.Q0:dae.V0] = Q.real / dae.L
    y[dae.V0:dae.P0] = (-Q.imag * w) / (dae.L * w)  # d(q / L)/dtau, tau = w t
    for k, node in enumerate(orbits.nodes):
        blk = next(b for b in dae.blocks if b.node == node)
        d = orbits.dampers[k]
        eps, psi = float(abs(z[k])), float(np.angle(z[k]))
        film2 = d.bearing.film(2.0 * speed)
        u2 = d.bearing.steady_state(eps, 2.0 * speed).u
        m2 = film2.content(u2, eps, 0.0)
        f = blk.film
        angle = np.arctan2(f.sinp, f.cosp)
        nx = d.bearing.grid.nx
        rows = m2.reshape(-1, nx)
        ang2 = np.arctan2(film2.sinp, film2.cosp)[:nx]
        order = np.argsort(ang2)
        # the whirling film of a journal at psi: the steady film at +2w mirrored (phi -> -phi) and turned by psi
        target = np.mod(psi - angle.reshape(-1, nx) + np.pi, 2 * np.pi) - np.pi
        m = np.array([np.interp(target[i], ang2[order], rows[i, order], period=2 * np.pi) for i in range(len(rows))])
        X, Y = blk.position(y[dae.Q0:dae.V0])
        u = f.universal(m.ravel(), X, Y)
        y[blk.offset:blk.offset + blk.n] = u
    return y


def rotor_basis(system, speed_rpm) -> np.ndarray:
    """The unit vectors of the rotor's coordinates and velocities in the period map's reduced layout (the films'
    free cells first): the start basis of Newton-Picard on a rotor on dampers, whose dominant Floquet modes are the
    rotor's with its films slaved to them (the shooting's first step turns it into ``M V``)."""
    dae = system.dae(check_speed(speed_rpm))
    n_free = sum(int(np.count_nonzero(b.film.op.free)) for b in dae.blocks)
    n_rotor = 2 * dae.nq
    V = np.zeros((n_free + n_rotor, n_rotor))
    V[n_free:, :] = np.eye(n_rotor)
    return V


__all__ = ["CircularOrbitCurve", "circular_start", "rotor_basis", "trace"]


def orbits_at_speed(system, curve: CircularOrbitCurve, speed_rpm) -> list[np.ndarray]:
    """Every circular orbit of ``curve`` at ``speed_rpm`` (one per crossing of the path with that speed, in the
    path's order): the amplitudes ``Z / c`` per damper, each by Newton at that speed from the crossing interpolated
    between its two rows."""
    speed = check_speed(speed_rpm)
    orbits = CircularOrbits(system, speed)
    out = []
    n = curve.speed_rpm
    for i in np.flatnonzero((n[:-1] - speed) * (n[1:] - speed) <= 0):
        a = (speed - n[i]) / (n[i + 1] - n[i]) if n[i + 1] != n[i] else 0.0
        z0 = (1 - a) * curve.amplitude[i] + a * curve.amplitude[i + 1]
        x = _solve_at_speed(orbits, np.asarray(z0, dtype=complex), 1.0)
        if x is not None and not any(np.allclose(x[:-1], np.concatenate([[v.real, v.imag] for v in o]), atol=1e-8)
                                     for o in out):
            out.append(x[0:-1:2] + 1j * x[1:-1:2])
    return out


def default_start(system, speed_rpm):
    """The shooting's default start on a rotor with dampers: the state on the circular orbit reached from small
    unbalance (:func:`first_orbit`, :func:`circular_start`) where the system has circular orbits, else None (the
    linear response with the film states)."""
    try:
        orbits = CircularOrbits(system, speed_rpm)
        x = first_orbit(orbits, speed_rpm)
        orbits.check_axisymmetric(x)
    except (ValueError, RuntimeError):
        return None
    return circular_start(system, speed_rpm, x[0:-1:2] + 1j * x[1:-1:2])
