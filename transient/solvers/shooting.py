"""Periodic orbits of a system forced with period T: shooting on the once-per-period map.

A periodic orbit through ``y*`` at time ``t0`` is a fixed point of the period map
``Phi(y) = y(t0 + T)`` of the solution started at ``y(t0) = y``. The Jacobian of the map, the monodromy
matrix ``M = dPhi/dy``, has the Floquet multipliers as eigenvalues: the orbit is linearly stable when all
of them lie inside the unit circle. Nothing here knows a model: the caller hands over
``flow(y, t0, T, rtol) -> y(t0 + T)`` (one integration at relative tolerance ``rtol``) and, optionally,
``derivative(y, fy, v, rtol) -> M v`` (default: a one-sided finite difference of two flows).

**Newton-Picard** (:func:`newton_picard`; Lust, Roose, Spence & Champneys, SIAM J. Sci. Comput. 19 (1998)
1188; Shroff & Keller, SIAM J. Numer. Anal. 30 (1993) 1099). In a dissipative system only a few
multipliers are not small. With an orthonormal basis ``V`` (n x p) of their (approximately) invariant
subspace, ``P = V V^T`` and ``Q = I - P``, the Newton step for ``Phi(y) - y = 0`` splits into a p x p Newton
step with the projected monodromy ``S = V^T M V`` and a Picard (fixed-point) step on the rest::

    r = Phi(y) - y,    a = (I - S)^-1 V^T r,    d = Q r + V a,    y <- y + d

The Q part contracts at the rate of the largest multiplier left out; the P part converges like Newton.
``S`` costs p directional derivatives (p periods) and is kept (a chord) while the steps shrink at least
``1 / refresh``-fold per iteration, and recomputed otherwise. The error of the current iterate is
estimated by the step ``norm(d)``; the iteration stops when it and the measured residual ``norm(r)`` are
below ``tol`` at the final integration tolerance and returns that iterate (its period is integrated:
``image``). Early iterations run the flow
at a looser tolerance ``clip(eta * error estimate, rtol, rtol_max)`` (an inexact Newton method).
The eigenvalues of ``S`` are the Ritz values of the monodromy on ``V``: the dominant multipliers.
``W = M V`` spans a better approximation of the dominant subspace than ``V`` (one step of subspace
iteration): the iteration goes on in its orthonormal basis (unless the Ritz values are at the derivatives'
noise level), and returns it (``basis``) to start the next solve of a continuation. Plain iterations
(``relax``) before the first step let the fast modes of a poor start die out: the step leaves out the
coupling ``V^T M Q`` through which they would spoil it.

**Newton-Krylov** (:func:`newton_krylov`): GMRES on ``(I - M) d = r`` with ``M v`` matrix-free; every
Krylov vector costs one period. Kept for comparison: with few dominant multipliers it needs 3-5 periods of
derivatives per Newton step where Newton-Picard needs p once.

:func:`floquet_multipliers`: the k multipliers of largest modulus by Arnoldi (ARPACK,
``scipy.sparse.linalg.eigs``) on the monodromy as a LinearOperator (one period per product): the independent
check of the Ritz values.
"""

from __future__ import annotations

import time
from dataclasses import astuple, dataclass, field, fields
from typing import Callable

import numpy as np
import scipy.sparse.linalg as spla

from transient.checks import check_bool, check_int, check_positive, check_range
from transient.results import SteadyResult, result_type
from transient.solvers.legacy import run_settings
from transient.solvers.settings import check_unused


@result_type
class ShootingResult(SteadyResult):
    """Outcome of a shooting solve. ``state``: the accepted start state (a fixed point of the period map to
    ``error_estimate`` in the caller's norm), ``image``: its flow over one period, ``multipliers``: the
    Ritz values of the monodromy (dominant first), ``basis``/``monodromy``: ``W = M V`` orthonormalised
    and the projected monodromy on it (to warm-start a continuation). Histories per iteration:
    ``residual_norms`` (``norm(Phi(y) - y)``), ``step_norms`` (``norm(d)``, the error estimates) and
    ``rtols``; ``periods``: flows integrated, derivatives included; ``derivatives``: of those, the
    directional derivatives."""

    time_axis = None
    state: np.ndarray
    image: np.ndarray
    periods: int = 0
    derivatives: int = 0
    error_estimate: float = float("nan")
    multipliers: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=complex))
    basis: np.ndarray | None = None
    monodromy: np.ndarray | None = None
    step_norms: list = field(default_factory=list)
    rtols: list = field(default_factory=list)
    wall_time: float = 0.0


def _max_norm(d) -> float:
    return float(np.max(np.abs(d)))


def _step_taken(out, k, y, fy, residual_norm, est, rt, tol, rtol) -> bool:
    """Record iteration ``k`` in ``out``; True (and ``out`` converged at ``y``) when, with the flow integrated at
    the final ``rtol``, both the Newton step's error estimate and the measured residual ``norm(Phi(y) - y)`` are
    below ``tol``."""
    out.residual_norms.append(residual_norm)
    out.step_norms.append(est)
    out.rtols.append(rt)
    out.iterations = k + 1
    if est <= tol and residual_norm <= tol and rt <= rtol:
        out.state, out.image, out.success = y, fy, True
        out.message = (f"converged in {k + 1} iterations: error estimate {est:.2e} and residual "
                       f"|Phi(y) - y| {residual_norm:.2e} <= tol {tol:.2e}")
        return True
    return False


class _Counted:
    """The caller's flow and derivative, counted; the default derivative is a one-sided difference."""

    def __init__(self, flow, derivative, norm, fd_step):
        self.flow_fn, self.derivative_fn, self.norm, self.fd_step = flow, derivative, norm, fd_step
        self.periods = 0
        self.derivatives = 0

    def flow(self, y, t0, T, rtol):
        self.periods += 1
        return np.asarray(self.flow_fn(y, t0, T, rtol), dtype=float)

    def relaxed(self, y, t0, T, rtol, periods):
        """``periods`` plain iterations of the map from ``y``; stops at the last finite state if the flow fails."""
        for _ in range(int(periods)):
            fy = self.flow(y, t0, T, rtol)
            if not np.all(np.isfinite(fy)):
                break
            y = fy
        return y

    def jvp(self, y, fy, v, t0, T, rtol):
        """``M v`` at ``y`` (``fy = Phi(y)`` at the same ``rtol``)."""
        self.derivatives += 1
        if self.derivative_fn is not None:
            self.periods += 1
            return np.asarray(self.derivative_fn(y, fy, v, rtol), dtype=float)
        size = self.norm(v)
        if not size > 1e-3 * _max_norm(v):  # v hardly moves the observed part: scale on the whole vector
            size = _max_norm(v)
        eps = self.fd_step / size
        return (self.flow(y + eps * v, t0, T, rtol) - fy) / eps


def _orthonormal(basis) -> np.ndarray:
    V = np.asarray(basis, dtype=float)
    if V.ndim == 1:
        V = V[:, None]
    q, r = np.linalg.qr(V)
    keep = np.abs(np.diag(r)) > 1e-12 * max(1.0, float(np.abs(r).max()))
    if not keep.any():
        raise ValueError("basis: the columns are zero or linearly dependent")
    return q[:, keep]


def _ordered(mu) -> np.ndarray:
    mu = np.asarray(mu, dtype=complex)
    return mu[np.argsort(-np.abs(mu), kind="stable")]


@dataclass(frozen=True)
class ShootingSettings:
    """How :func:`newton_picard` and :func:`newton_krylov` iterate, validated on creation (module docstring).

    ``tol`` > 0: accept the iterate when ``norm(d) <= tol`` at the final tolerance ``rtol`` (0 < ``rtol`` <=
    ``rtol_max``, the loosest integration tolerance of the inexact iterations; ``eta`` > 0 the factor on the
    error estimate); ``fd_step`` > 0 the finite-difference step of the default derivative (in ``norm``'s unit),
    whose iterations integrate at ``fd_rtol`` (``None``: ``clip(fd_step / 100, rtol, rtol_max)``); ``max_iter``
    >= 1 iterations; ``relax`` >= 0 plain iterations of the map (at ``rtol_max``) before the first Newton step.
    Newton-Picard: ``refresh`` in (0, 1], ``second_ritz``, ``refine_floor`` in [0, 1). Newton-Krylov:
    ``krylov_tol`` > 0 (GMRES's relative residual), ``max_krylov`` >= 1."""

    tol: float = 1e-8
    rtol: float = 1e-8
    rtol_max: float = 1e-4
    eta: float = 3e-3
    fd_step: float = 1e-3
    fd_rtol: float | None = None
    max_iter: int = 25
    relax: int = 0
    refresh: float = 0.3
    second_ritz: bool = False
    refine_floor: float = 0.05
    krylov_tol: float = 1e-3
    max_krylov: int = 20

    def __post_init__(self):
        if not (self.tol > 0 and self.rtol > 0 and self.rtol_max >= self.rtol):
            raise ValueError(f"need tol > 0 and 0 < rtol <= rtol_max; got tol={self.tol!r}, rtol={self.rtol!r}, "
                             f"rtol_max={self.rtol_max!r}")
        check_positive("eta", self.eta, "-")
        check_positive("fd_step", self.fd_step, "-")
        if self.fd_rtol is not None:
            check_positive("fd_rtol", self.fd_rtol, "-")
        check_int("max_iter", self.max_iter, "-", 1, 1e6)
        check_int("relax", self.relax, "-", 0, 1e6)
        check_range("refresh", self.refresh, "-", 0.0, 1.0, low_open=True)
        check_bool("second_ritz", self.second_ritz)
        check_range("refine_floor", self.refine_floor, "-", 0.0, 1.0, high_open=True)
        check_positive("krylov_tol", self.krylov_tol, "-")
        check_int("max_krylov", self.max_krylov, "-", 1, 1e6)


#: The loose keywords of :func:`newton_picard` and :func:`newton_krylov` of earlier releases, now fields of
#: ``settings=ShootingSettings(...)``.
SHOOTING_KEYWORDS = {f.name: ("settings", ShootingSettings, f.name) for f in fields(ShootingSettings)}
PICARD_ONLY = ("refresh", "second_ritz", "refine_floor")
KRYLOV_ONLY = ("krylov_tol", "max_krylov")


def _settings(owner, settings, legacy, unused) -> tuple:
    """The fields of the shooting's settings (from ``settings`` or the old keywords), refusing those ``owner``
    does not use."""
    table = {k: v for k, v in SHOOTING_KEYWORDS.items() if k not in unused}
    settings = run_settings(owner, legacy, table, settings=settings)["settings"]
    check_unused(owner, "settings", settings, unused)
    return astuple(settings)


def newton_picard(flow: Callable, y0, period: float, basis, *, t0: float = 0.0, norm: Callable = _max_norm,
                  derivative: Callable | None = None, callback: Callable | None = None,
                  settings: ShootingSettings | None = None, **legacy) -> ShootingResult:
    """Fixed point of the period map by Newton-Picard (module docstring).

    Parameters
    ----------
    flow : ``flow(y, t0, T, rtol) -> y(t0 + T)``.
    y0 : start guess; period : T; t0 : start time (the phase of the forcing).
    basis : (n, p) guess of the dominant subspace (orthonormalised here).
    settings : :class:`ShootingSettings` (default ``ShootingSettings()``), with the fields below; as loose
        keywords (``tol=``, ``rtol=``, ...) they are deprecated (they still work for one release, with a
        ``DeprecationWarning``).
    tol : accept the iterate when ``norm(d) <= tol`` at the final tolerance ``rtol``.
    rtol_max, eta : loosest integration tolerance and the factor on the error estimate (inexact iterations).
    norm : ``norm(d) -> float``, the error measure (e.g. the journal position in units of its clearance).
    derivative : ``derivative(y, fy, v, rtol) -> M v``; default ``(Phi(y + e v) - Phi(y)) / e`` with ``e`` such
        that ``norm(e v) = fd_step``; the iteration that computes them integrates at ``fd_rtol`` or tighter
        (default ``clip(fd_step / 100, rtol, rtol_max)``).
    refresh : recompute ``S`` when a step is not at least ``1 / refresh`` times smaller than the last.
    second_ritz : take the derivatives once more at the iteration after the first ones, on the refined basis
        (p more periods; not when the basis was not refined, see ``refine_floor``): the Ritz values of a poor
        initial basis (e.g. from a linearised model) can be off by 2e-2, those of the refined one are within
        ~1e-3 of Arnoldi's (docs/periodic.md). A continuation, which passes the previous refined basis, does
        not need it.
    refine_floor : the basis follows ``W = M V`` only while every Ritz value exceeds it (the derivatives'
        relative noise is ~``rtol / fd_step``).
    relax : plain iterations of the map (at ``rtol_max``) before the first Newton step: they let the fast
        modes of a poor start die out so that they do not pollute the first step through the coupling
        ``V^T M Q`` that the Newton-Picard step leaves out.
    callback : ``callback(k, y, r, d, rtol)`` after every iteration.

    Returns a :class:`ShootingResult`; ``success`` False (with the histories) if ``max_iter`` is reached.
    """
    tol, rtol, rtol_max, eta, fd_step, fd_rtol, max_iter, relax, refresh, second_ritz, refine_floor, _, _ = \
        _settings("newton_picard", settings, legacy, KRYLOV_ONLY)
    if not period > 0:
        raise ValueError(f"period = {period!r}; allowed: > 0")
    wall0 = time.perf_counter()
    f = _Counted(flow, derivative, norm, fd_step)
    fd_rtol = float(np.clip(fd_step / 100.0, rtol, rtol_max)) if fd_rtol is None else float(fd_rtol)
    V = _orthonormal(basis)
    p = V.shape[1]
    S = None
    y = f.relaxed(np.array(y0, dtype=float), t0, period, rtol_max, relax)
    out = ShootingResult(state=y, image=y, success=False, message="")
    ritz, derived_at, refined = None, None, False
    rt = rtol_max
    for k in range(int(max_iter)):
        slow = len(out.step_norms) > 1 and out.step_norms[-1] > refresh * out.step_norms[-2]
        new_S = S is None or slow or (second_ritz and derived_at == k - 1 and k == 1 and refined)
        if new_S:  # the derivatives share the base flow: integrate it at least as tightly as they need
            rt = min(rt, fd_rtol)
        fy = f.flow(y, t0, period, rt)
        if not np.all(np.isfinite(fy)):
            out.message = f"the flow returned a non-finite state at iteration {k}"
            break
        r = fy - y
        if new_S:
            W = np.column_stack([f.jvp(y, fy, V[:, j], t0, period, rt) for j in range(p)])
            ritz, derived_at, V0 = np.linalg.eigvals(V.T @ W), k, V
            V, S = _refined(V, W, V.T @ W, refine_floor)
            refined = V is not V0
        a = np.linalg.solve(np.eye(p) - S, V.T @ r)
        d = r - V @ (V.T @ r) + V @ a
        est = norm(d)
        if callback is not None:
            callback(k, y, r, d, rt)
        if _step_taken(out, k, y, fy, norm(r), est, rt, tol, rtol):
            break
        y = y + d
        rt = float(np.clip(eta * est, rtol, rtol_max))
    else:
        out.state, out.image = y, fy
        out.message = (f"Newton-Picard did not converge in {max_iter} iterations: error estimates "
                       + ", ".join(f"{e:.2e}" for e in out.step_norms[-5:]))
    out.periods, out.derivatives = f.periods, f.derivatives
    out.error_estimate = out.step_norms[-1] if out.step_norms else float("nan")
    if ritz is not None:
        out.multipliers = _ordered(ritz)
    out.basis, out.monodromy = V, S
    out.wall_time = time.perf_counter() - wall0
    return out


def _refined(V, W, S, floor):
    """One step of subspace iteration: the orthonormal basis ``V'`` of ``W = M V`` and the monodromy on it,
    ``V'^T M V' = R (V'^T V)^-1`` (``W = V' R``; exact when ``M`` annihilates the part of ``V`` outside the
    dominant subspace). Keeps ``(V, S)`` when a Ritz value of ``S`` is below ``floor`` (then ``W`` is mostly the
    noise of the derivatives, and following it would lose the dominant subspace along a continuation) or
    when ``W`` does not span a p-dimensional space close to ``V``."""
    if np.abs(np.linalg.eigvals(S)).min() < floor:
        return V, S
    q, R = np.linalg.qr(W)
    G = q.T @ V
    if np.linalg.svd(G, compute_uv=False).min() < 0.5:
        return V, S
    return q, R @ np.linalg.inv(G)


def newton_krylov(flow: Callable, y0, period: float, *, t0: float = 0.0, norm: Callable = _max_norm,
                  derivative: Callable | None = None, settings: ShootingSettings | None = None,
                  **legacy) -> ShootingResult:
    """Fixed point of the period map by Newton-GMRES with matrix-free ``M v`` (one period per Krylov vector).

    Arguments as :func:`newton_picard`; ``settings.krylov_tol`` is GMRES's relative residual. Multipliers are not
    computed (use :func:`floquet_multipliers`)."""
    tol, rtol, rtol_max, eta, fd_step, fd_rtol, max_iter, relax, _, _, _, krylov_tol, max_krylov = \
        _settings("newton_krylov", settings, legacy, PICARD_ONLY)
    wall0 = time.perf_counter()
    f = _Counted(flow, derivative, norm, fd_step)
    fd_rtol = float(np.clip(fd_step / 100.0, rtol, rtol_max)) if fd_rtol is None else float(fd_rtol)
    y = f.relaxed(np.array(y0, dtype=float), t0, period, rtol_max, relax)
    out = ShootingResult(state=y, image=y, success=False, message="")
    rt = rtol_max
    n = y.size
    for k in range(int(max_iter)):
        fy = f.flow(y, t0, period, rt)
        if not np.all(np.isfinite(fy)):
            out.message = f"the flow returned a non-finite state at iteration {k}"
            break
        r = fy - y
        fr = f.flow(y, t0, period, fd_rtol) if fd_rtol != rt else fy
        A = spla.LinearOperator((n, n), matvec=lambda v: v - f.jvp(y, fr, np.ravel(v), t0, period, fd_rtol),
                                dtype=float)
        d, _ = spla.gmres(A, r, rtol=krylov_tol, atol=0.0, restart=max_krylov, maxiter=1)
        est = norm(d)
        if _step_taken(out, k, y, fy, norm(r), est, rt, tol, rtol):
            break
        y = y + d
        rt = float(np.clip(eta * est, rtol, rtol_max))
    else:
        out.state, out.image = y, fy
        out.message = f"Newton-Krylov did not converge in {max_iter} iterations"
    out.periods, out.derivatives = f.periods, f.derivatives
    out.error_estimate = out.step_norms[-1] if out.step_norms else float("nan")
    out.wall_time = time.perf_counter() - wall0
    return out

def extrapolate_state(speeds, states, speed, points) -> np.ndarray | None:
    """The continuation's predictor: Lagrange extrapolation of the last ``points`` periodic states (at ``speeds``) to
    ``speed`` (None without a previous state)."""
    m = min(points, len(states))
    if m == 0:
        return None
    xs, ys = speeds[-m:], states[-m:]
    out = np.zeros_like(ys[0])
    for i in range(m):
        out += np.prod([(speed - xs[j]) / (xs[i] - xs[j]) for j in range(m) if j != i]) * ys[i]
    return out



def stability_onset_speed(speeds, max_multiplier) -> float:
    """The first speed where the largest Floquet multiplier's modulus crosses 1, linearly interpolated between the
    two speeds that bracket it (NaN if it does not cross)."""
    for i in range(1, len(max_multiplier)):
        a, b = max_multiplier[i - 1], max_multiplier[i]
        if np.isfinite(a) and np.isfinite(b) and (a - 1.0) * (b - 1.0) < 0:
            return float(speeds[i - 1] + (1.0 - a) * (speeds[i] - speeds[i - 1]) / (b - a))
    return float("nan")


def floquet_multipliers(flow: Callable, y, period: float, k: int = 4, *, t0: float = 0.0, rtol: float = 1e-8,
                        derivative: Callable | None = None, fd_step: float = 1e-6, norm: Callable = _max_norm,
                        ncv: int | None = None, arnoldi_tol: float = 1e-6) -> tuple[np.ndarray, np.ndarray, int]:
    """The ``k`` Floquet multipliers of largest modulus of the orbit through ``y`` (Arnoldi on the
    monodromy, one period per product). Returns (multipliers, eigenvectors (n, k), periods integrated)."""
    f = _Counted(flow, derivative, norm, fd_step)
    fy = f.flow(y, t0, period, rtol)
    n = np.size(y)
    A = spla.LinearOperator((n, n), matvec=lambda v: f.jvp(y, fy, np.ravel(v), t0, period, rtol), dtype=float)
    vals, vecs = spla.eigs(A, k=k, which="LM", ncv=ncv or min(n - 1, max(2 * k + 1, 12)), tol=arnoldi_tol)
    order = np.argsort(-np.abs(vals), kind="stable")
    return vals[order], vecs[:, order], f.periods
