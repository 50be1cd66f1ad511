"""Linear rotor-bearing analysis: unbalance response, eigenvalues, Campbell diagram, critical speeds and the
quasi-static stability threshold, from the rotor's matrices and linear bearing coefficients, SI.

The linearised system at shaft speed Omega [rad/s] (Lund, "Stability and damped critical speeds of a flexible
rotor in fluid-film bearings", 1974; Friswell et al., "Dynamics of Rotating Machines", ch. 3 and 5):

    M q'' + (C + Omega G + C_b(Omega)) q' + (K + K_b(Omega)) q = f(t)

where each bearing adds its 2x2 stiffness K_b [N/m] and damping C_b [N s/m] on the (x, y) dofs of its node
(``bearings``: a list of ``(ix, iy, K2x2, C2x2)``; the bearing force on the shaft is ``-K_b (x, y) - C_b (x', y')``,
the sign of ``JournalBearing.coefficients``). ``G`` is the gyroscopic matrix per rad/s of shaft speed
(:mod:`transient.models.rotor.shaft` for its sign: the shaft spins from +x towards +y).

Complex amplitudes: ``q(t) = Re(Q e^{i w t})``; a synchronous unbalance u = m e [kg m] at phase phi at a node
gives ``F_x = u Omega^2 e^{i phi}``, ``F_y = -i u Omega^2 e^{i phi}`` (the force m e Omega^2 (cos, sin)(Omega t +
phi)). Eigenvalues ``lambda = sigma + i w_d`` of the state matrix; damping ratio ``-sigma / |lambda|``, log
decrement ``-2 pi sigma / w_d``. A mode whirls forward (with the spin, x towards y) when ``Im(X conj(Y)) > 0``
summed over its (x, y) pairs.
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np
import scipy.linalg as sl
from scipy.optimize import brentq

from transient.checks import check_count, check_range, short_repr


# --------------------------------------------------------------------------------------------------
# Inputs
# --------------------------------------------------------------------------------------------------

def _square(name, a, n=None, unit=""):
    a = np.asarray(a, dtype=float) if not np.iscomplexobj(a) else np.asarray(a)
    if a.ndim != 2 or a.shape[0] != a.shape[1] or (n is not None and a.shape[0] != n):
        want = f"({n}, {n})" if n is not None else "square"
        raise ValueError(f"{name} [{unit}] must be a {want} array, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} [{unit}] has non-finite entries; allowed: finite numbers")
    return a


def check_matrices(mass, damping, gyroscopic, stiffness):
    """The rotor's matrices as float arrays (damping/gyroscopic None -> zeros); mass symmetric positive
    definite, stiffness symmetric, gyroscopic skew-symmetric."""
    M = _square("mass", mass, unit="kg, kg m^2")
    n = M.shape[0]
    if not np.allclose(M, M.T, rtol=1e-10, atol=1e-12 * np.abs(M).max()):
        raise ValueError(f"mass [kg] is not symmetric (largest |M - M^T| = {np.abs(M - M.T).max():.3g}); "
                         "allowed: a symmetric positive definite matrix")
    try:
        np.linalg.cholesky(M)
    except np.linalg.LinAlgError:
        raise ValueError(f"mass [kg] is not positive definite (smallest eigenvalue "
                         f"{np.linalg.eigvalsh(M).min():.3g}); allowed: a symmetric positive definite matrix") from None
    K = _square("stiffness", stiffness, n, "N/m")
    if not np.allclose(K, K.T, rtol=1e-10, atol=1e-12 * max(np.abs(K).max(), 1e-300)):
        raise ValueError(f"stiffness [N/m] is not symmetric (largest |K - K^T| = {np.abs(K - K.T).max():.3g}); "
                         "allowed: a symmetric matrix (bearings' cross-coupling goes in `bearings`)")
    C = np.zeros((n, n)) if damping is None else _square("damping", damping, n, "N s/m")
    G = np.zeros((n, n)) if gyroscopic is None else _square("gyroscopic", gyroscopic, n, "N s^2/m per rad/s")
    if not np.allclose(G, -G.T, rtol=1e-10, atol=1e-12 * max(np.abs(G).max(), 1e-300)):
        raise ValueError("gyroscopic [N s^2/m per rad/s] is not skew-symmetric; allowed: G = -G^T")
    return M, C, G, K


def check_bearings(bearings, n):
    """``[(ix, iy, K2x2, C2x2), ...]`` with dof indices in [0, n) and finite 2x2 coefficients; a bearing with tilt
    coefficients ``(ix, iy, itx, ity, K4x4, C4x4)`` (x, y, tilt about x, tilt about y)."""
    if bearings is None:
        return []
    out = []
    for b, item in enumerate(bearings):
        try:
            *idx, kb, cb = item
            if len(idx) not in (2, 4):
                raise ValueError
        except (TypeError, ValueError):
            raise ValueError(f"bearings[{b}] = {short_repr(item)} must be (ix, iy, K2x2 [N/m], C2x2 [N s/m]) or "
                             "(ix, iy, itx, ity, K4x4, C4x4)") from None
        for name, i in zip(("ix", "iy", "itx", "ity"), idx):
            if isinstance(i, bool) or not isinstance(i, (int, np.integer)) or not 0 <= i < n:
                raise ValueError(f"bearings[{b}] {name} = {i!r} [-] is not a dof index; allowed: integers in "
                                 f"[0, {n - 1}]")
        if len(set(idx)) < len(idx):
            raise ValueError(f"bearings[{b}] dofs = {tuple(idx)}: the bearing's dofs must be different dofs")
        kb = _square(f"bearings[{b}] K", kb, len(idx), "N/m")
        cb = _square(f"bearings[{b}] C", cb, len(idx), "N s/m")
        out.append((*(int(i) for i in idx), kb, cb))
    return out


def _speed(name, omega):
    return check_range(name, omega, "rad/s", 0.0, 1e7)


def assemble(mass, damping, gyroscopic, stiffness, bearings, omega):
    """The matrices of the linearised system at shaft speed ``omega``: (M, C + omega G + C_b, K + K_b)."""
    M, C, G, K = check_matrices(mass, damping, gyroscopic, stiffness)
    w = _speed("omega", omega)
    Ct = C + w * G
    Kt = K.copy()
    for *dofs, kb, cb in check_bearings(bearings, M.shape[0]):
        idx = np.ix_(dofs, dofs)
        Kt[idx] += kb
        Ct[idx] += cb
    return M, Ct, Kt


# --------------------------------------------------------------------------------------------------
# Forced response and eigenvalues
# --------------------------------------------------------------------------------------------------

def unbalance_response(mass, damping, gyroscopic, stiffness, bearings, forces, omega) -> np.ndarray:
    """Steady synchronous response Q [m, rad] to force amplitudes ``forces`` [N, N m] (complex, (n,)) at
    shaft speed = excitation frequency ``omega`` [rad/s]: ``(K_t - omega^2 M + i omega C_t) Q = F``."""
    M, Ct, Kt = assemble(mass, damping, gyroscopic, stiffness, bearings, omega)
    n = M.shape[0]
    F = np.asarray(forces, dtype=complex)
    if F.shape != (n,) or not np.all(np.isfinite(F)):
        raise ValueError(f"forces [N] must be {n} finite complex amplitudes, got shape {F.shape}")
    Z = Kt - omega * omega * M + 1j * omega * Ct
    try:
        return sl.solve(Z, F)
    except sl.LinAlgError:
        raise ValueError(f"omega = {omega!r} [rad/s] is an undamped resonance of the system (singular dynamic "
                         "stiffness); allowed: a speed off the undamped natural frequencies") from None


def unbalance_forces(n, dofs_per_node, unbalances, omega) -> np.ndarray:
    """Complex force amplitudes (n,) [N] of unbalances ``[(node, m e [kg m], phase [deg]), ...]`` at ``omega``
    [rad/s] for a node-ordered layout whose first two dofs per node are x, y."""
    F = np.zeros(n, dtype=complex)
    for node, me, phase in unbalances:
        a = me * omega * omega * np.exp(1j * math.radians(phase))
        F[dofs_per_node * node] += a
        F[dofs_per_node * node + 1] += -1j * a
    return F


def _state_matrix(M, Ct, Kt):
    n = M.shape[0]
    lu = sl.lu_factor(M)
    return np.block([[np.zeros((n, n)), np.eye(n)], [-sl.lu_solve(lu, Kt), -sl.lu_solve(lu, Ct)]])


def _eig(mass, damping, gyroscopic, stiffness, bearings, omega, vectors=False):
    M, Ct, Kt = assemble(mass, damping, gyroscopic, stiffness, bearings, omega)
    A = _state_matrix(M, Ct, Kt)
    if not vectors:
        lam = np.linalg.eigvals(A)
        return lam[np.lexsort((lam.real, np.abs(lam.imag)))]
    lam, V = np.linalg.eig(A)
    order = np.lexsort((lam.real, np.abs(lam.imag)))
    return lam[order], V[: M.shape[0], order]


def eigenvalues(mass, damping, gyroscopic, stiffness, bearings, omega) -> np.ndarray:
    """The 2n eigenvalues [1/s] of the linearised system at shaft speed ``omega`` [rad/s], sorted by |imag|
    (then by real part)."""
    return _eig(mass, damping, gyroscopic, stiffness, bearings, omega)


def whirl_direction(vector, pairs) -> float:
    """+1 for a purely forward circular whirl, -1 backward: ``2 sum Im(X conj(Y)) / sum(|X|^2 + |Y|^2)`` over
    the dof pairs ``pairs`` ((x, y) and, where the model has them, (tx, ty): with tx = -dy/dz, ty = dx/dz a
    forward whirl of the centreline is a forward whirl of (tx, ty) in the same order)."""
    X = vector[[p[0] for p in pairs]]
    Y = vector[[p[1] for p in pairs]]
    den = np.sum(np.abs(X) ** 2 + np.abs(Y) ** 2)
    return float(2.0 * np.sum(np.imag(X * np.conj(Y))) / den) if den > 0 else 0.0


def _whirls(lam, V, pairs):
    """Whirl directions of the modes ``V[:, k]``. A degenerate eigenvalue (an isotropic rotor at rest: forward
    and backward whirl at one frequency) has any mix of them as eigenvectors; its cluster's vectors are
    replaced by the combinations that diagonalise the whirl form ``2 Im(X conj(Y))`` against
    ``|X|^2 + |Y|^2``, which whirl purely forward and backward."""
    n = V.shape[0]
    H = np.zeros((n, n), dtype=complex)
    N = np.zeros((n, n))
    for ia, ib in pairs:
        H[ia, ib] += 1j
        H[ib, ia] -= 1j
        N[ia, ia] += 1.0
        N[ib, ib] += 1.0
    out = np.array([whirl_direction(V[:, k], pairs) for k in range(lam.size)])
    done = np.zeros(lam.size, dtype=bool)
    for k in range(lam.size):
        if done[k]:
            continue
        cluster = np.flatnonzero(np.abs(lam - lam[k]) <= 1e-8 * max(abs(lam[k]), 1e-300))
        done[cluster] = True
        if cluster.size > 1:
            B = V[:, cluster]
            nb = B.conj().T @ N @ B
            if np.linalg.cond(nb) < 1e8:
                out[cluster] = sl.eigh(B.conj().T @ H @ B, nb, eigvals_only=True)
    return out


class Campbell(NamedTuple):
    """Campbell diagram: for each speed [rad/s] the ``n_modes`` lowest damped natural frequencies [rad/s] of the
    underdamped modes, their damping ratios [-], log decrements [-] and whirl directions (+1 forward, -1 backward,
    :func:`whirl_direction`); missing modes are NaN."""
    speeds: np.ndarray
    frequencies: np.ndarray
    damping_ratios: np.ndarray
    log_decrements: np.ndarray
    whirl: np.ndarray


def _pairs(n, bearings, dofs):
    """The dof pairs a whirl is measured on: every node's (x, y) and (tx, ty) given ``dofs``, else the bearings'."""
    if dofs is not None:
        nd = len(dofs)
        if n % nd or "x" not in dofs or "y" not in dofs:
            raise ValueError(f"dofs = {short_repr(dofs)} does not tile {n} degrees of freedom with x and y per node")
        local = [(dofs.index("x"), dofs.index("y"))]
        if "tx" in dofs and "ty" in dofs:
            local.append((dofs.index("tx"), dofs.index("ty")))
        return [(k * nd + a, k * nd + b) for k in range(n // nd) for a, b in local]
    pairs = [(b[0], b[1]) for b in bearings]
    if not pairs:
        raise ValueError("whirl directions need the (x, y) dofs: give dofs=(...) per node or at least one bearing")
    return pairs


def _modes(mass, damping, gyroscopic, stiffness, bearings, omega, dofs):
    """The underdamped modes (eigenvalues with positive imaginary part, ascending) and their whirl directions."""
    lam, V = _eig(mass, damping, gyroscopic, stiffness, bearings, omega, vectors=True)
    pairs = _pairs(V.shape[0], check_bearings(bearings, V.shape[0]), dofs)
    up = np.flatnonzero(lam.imag > 1e-9 * np.maximum(np.abs(lam), 1e-300))
    return lam[up], _whirls(lam[up], V[:, up], pairs)


def modes_at(mass, damping, gyroscopic, stiffness, bearings, omega, n_modes, dofs=None):
    """(frequencies [rad/s], damping ratios, log decrements, whirl) of the ``n_modes`` lowest underdamped modes
    (eigenvalues with positive imaginary part) at shaft speed ``omega`` [rad/s], NaN-padded."""
    n_modes = check_count("n_modes", n_modes)
    lam, whirl = _modes(mass, damping, gyroscopic, stiffness, bearings, omega, dofs)
    lk, wk = lam[:n_modes], whirl[:n_modes]
    out = np.full((4, n_modes), np.nan)
    out[0, : lk.size] = lk.imag
    out[1, : lk.size] = -lk.real / np.abs(lk)
    out[2, : lk.size] = -2 * np.pi * lk.real / lk.imag
    out[3, : lk.size] = wk
    return out


def _speeds(speeds_rad_s):
    s = np.atleast_1d(np.asarray(speeds_rad_s, dtype=float))
    if s.ndim != 1 or s.size == 0:
        raise ValueError(f"speeds_rad_s [rad/s] must be a 1-D array of speeds, got shape {s.shape}")
    for i, v in enumerate(s):
        _speed(f"speeds_rad_s[{i}]", v)
    return s


def campbell(mass, damping, gyroscopic, stiffness, bearings_of_speed: Callable, speeds_rad_s, n_modes, *,
             dofs=None) -> Campbell:
    """Campbell diagram over ``speeds_rad_s`` [rad/s]; ``bearings_of_speed(omega)`` gives the bearings at each
    speed; ``dofs`` (names per node, e.g. ("x", "y", "tx", "ty")) classifies the whirl over every node, else over
    the bearings' (x, y)."""
    s = _speeds(speeds_rad_s)
    rows = np.array([modes_at(mass, damping, gyroscopic, stiffness, bearings_of_speed(w), w, n_modes, dofs)
                     for w in s])
    return Campbell(s, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3])


def _forward(mass, damping, gyroscopic, stiffness, bearings_of_speed, w, n_modes, dofs, frequency, zeta_max):
    """The forward-whirl natural frequencies [rad/s] at speed ``w`` of modes with damping ratio <= zeta_max,
    ascending."""
    lam, whirl = _modes(mass, damping, gyroscopic, stiffness, bearings_of_speed(w), w, dofs)
    lam = lam[(whirl > 0) & (-lam.real <= zeta_max * np.abs(lam))]
    f = np.abs(lam) if frequency == "undamped" else lam.imag
    return np.sort(f)[:n_modes]


def critical_speeds(mass, damping, gyroscopic, stiffness, bearings_of_speed: Callable, speed_range, n_modes=4, *,
                    dofs=None, frequency="damped", max_damping_ratio=1.0, samples=60) -> np.ndarray:
    """Speeds [rad/s] in ``speed_range`` = (low, high) where the k-th forward-whirl natural frequency (k <
    ``n_modes``; ``frequency="damped"``: Im(lambda), ``"undamped"``: |lambda|) of the modes with damping ratio
    <= ``max_damping_ratio`` crosses the 1x line, by sampling ``samples`` speeds and brentq on each sign change of
    ``f_k(Omega) - Omega``; ascending. A sign change where the k-th mode changes (modes entering or leaving the
    set: a jump, not a crossing) is not reported."""
    lo, hi = (_speed("speed_range[0]", speed_range[0]), _speed("speed_range[1]", speed_range[1]))
    if not hi > lo:
        raise ValueError(f"speed_range = {short_repr(speed_range)} [rad/s] must be (low, high) with high > low")
    if frequency not in ("damped", "undamped"):
        raise ValueError(f"frequency must be one of ('damped', 'undamped'), got frequency = {frequency!r}")
    zeta_max = check_range("max_damping_ratio", max_damping_ratio, "-", 0.0, 1.0, low_open=True)
    samples = check_count("samples", samples, 2)
    grid = np.linspace(lo, hi, samples)

    def forward_minus_speed(w):
        f = _forward(mass, damping, gyroscopic, stiffness, bearings_of_speed, w, n_modes, dofs, frequency, zeta_max)
        return np.concatenate([f, np.full(n_modes - f.size, np.inf)]) - w

    def f_k(w, k):
        return forward_minus_speed(w)[k]

    table = np.array([forward_minus_speed(w) for w in grid])
    out = []
    for k in range(n_modes):
        g = table[:, k]
        for j in range(samples - 1):
            if np.isfinite(g[j]) and np.isfinite(g[j + 1]) and g[j] * g[j + 1] <= 0 and g[j] != g[j + 1]:
                root = grid[j] if g[j] == 0 else brentq(f_k, grid[j], grid[j + 1], args=(k,), xtol=1e-10,
                                                         rtol=1e-12)
                if abs(f_k(root, k)) <= 1e-6 * max(root, 1.0):
                    out.append(root)
    return np.array(sorted(set(out)))


def largest_real_part(mass, damping, gyroscopic, stiffness, bearings, omega) -> float:
    """The largest real part [1/s] of the eigenvalues at speed ``omega`` [rad/s] (> 0: unstable)."""
    return float(eigenvalues(mass, damping, gyroscopic, stiffness, bearings, omega).real.max())


def quasi_static_threshold(mass, damping, gyroscopic, stiffness, bearings_of_speed: Callable, speed_range, *,
                           samples=40):
    """The lowest speed [rad/s] in ``speed_range`` = (low, high) where the largest real part of the eigenvalues
    crosses zero from below (the bearings' K/C quasi-static at each speed: the film's own dynamics left out), by
    sampling ``samples`` speeds and brentq on the first sign change; None if the system is stable throughout
    (or unstable already at ``low``: then ``low`` is returned)."""
    lo, hi = (_speed("speed_range[0]", speed_range[0]), _speed("speed_range[1]", speed_range[1]))
    if not hi > lo:
        raise ValueError(f"speed_range = {short_repr(speed_range)} [rad/s] must be (low, high) with high > low")
    samples = check_count("samples", samples, 2)

    def g(w):
        return largest_real_part(mass, damping, gyroscopic, stiffness, bearings_of_speed(w), w)

    grid = np.linspace(lo, hi, samples)
    if g(grid[0]) >= 0:
        return lo
    for a, b in zip(grid[:-1], grid[1:]):
        if g(b) >= 0:
            return brentq(g, a, b, xtol=1e-9 * b, rtol=1e-12)
    return None
