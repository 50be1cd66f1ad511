"""Variable-step BDF2 with its own Newton on a bordered band LU, for DAEs ``F(t, y, y') = 0`` whose step size is
set by a few declared components (a rotor) while the others (a film) are only solved to a Newton tolerance.

With ``h = t_(n+1) - t_n`` and ``w = h / h_(n-1)`` the variable-step BDF2 derivative (the first step of every
solve is backward Euler) is::

    y'_(n+1) = cj y_(n+1) + b,   cj = (1 + 2 w) / (h (1 + w)),   b = -(1 + w) / h y_n + w^2 / (h (1 + w)) y_(n-1)

Its local error ``h^3 y''' (1 + w)^2 / (6 w (1 + 2 w))`` is estimated from the distance between the converged
step and the quadratic predictor through the last three points (Hermite with y'(t_0) after the first step),
on the declared ``error_components`` only, in the weighted RMS norm of ``rtol |y| + atol``. The step follows a
PI controller (Gustafsson; Hairer & Wanner, Solving ODEs II, IV.2: exponents 0.7/3 and 0.4/3), its ratio kept
in [0.2, 2] (BDF2 is zero-stable for ratios below 1 + sqrt 2) and the step below ``max_step``.

Newton, iterated on the model's Newton variables ``z`` (``y = to_state(z)``): it starts, component by component,
from the quadratic extrapolation of ``z`` through the last three steps or from that of ``y`` mapped to ``z``,
whichever was clearly closer (by ``PICK_RATIO``) to the converged ``z`` in the previous step (a film cell: its
pressure extrapolated where it stays in the full film, its content where it cavitates or crosses). Chord iterations
on the last factorisation (the model's Jacobian ``(dF/dy + cj dF/dy') dy/dz``, factored by
:class:`~transient.solvers.bandlu.BorderedBandLU`), the update scaled by ``2 / (1 + cj / cj_J)`` when cj changed
since the factorisation (as SUNDIALS IDA does). A fresh Jacobian at the current iterate when the contraction
rate exceeds 0.3, or when the model reports components that switched regime since the last one and the refresh
pays (more than 3 of them, or the chord iterations it saves at the chord's contraction rate exceed its cost in
iterations, taken proportional to the band width); at most 10 per solve, the residual at that iterate solved
again, not re-evaluated; and before a step whose cj moved by more than 30 % or whose last Newton contracted
slowly. An update larger than the previous one halves the previous update instead (damping down to 1/16). Convergence is judged on the update in the model's own units: the error components
against ``0.1 (rtol |y| + atol)``, the others by the model's ``norm`` kernel (e.g. the film's pressure and content
updates): an update within tolerance, or one whose remaining error the chord's contraction rate ``r`` bounds,
``max(r / (1 - r), 0.3) |dz| <= 1`` (Hairer & Wanner II, IV.8; SUNDIALS). A Newton failure (25 iterations, no
convergence) is retried once with every switch refreshing the Jacobian (the weighed refresh can starve a hard
step), then cuts the step by 4. The cost by operation (residuals, Jacobians, iterations, refreshes and why) is
added to ``options["newton_counts"]`` (an int64 array of ``N_COUNTS``) if given.

The Newton iteration (residual, solves, Jacobian, factorisation, norm) is one numba kernel; Python runs once per
step (predictor, error test, step control, dense output, events). Outputs at ``t_eval`` come from the step's
quadratic interpolant (dense output); events are located on it with Brent's method.

The model hands the kernels as a :class:`Bdf2Model` in ``solve(..., options={"bdf2": model})``;
``options["fixed_step"] = h`` takes steps of exactly h with no error test (convergence studies).
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np
from numba import njit

from transient.solvers.bandlu import BorderedBandLU, band_factor, band_solve
from transient.solvers.integrate.guard import SIGINT
from transient.solvers.integrate.outputs import Events, step_events

NEWTON_FACTOR = 0.1  # Newton tolerance on the error components, as a fraction of rtol |y| + atol
MAX_ITER = 25
MAX_REFRESH = 10  # Jacobian re-evaluations inside one Newton solve
RATE_REFRESH = 0.3  # a step after a Newton that contracted slower than this starts with a fresh Jacobian
SWITCH_ALWAYS = 3  # more switched components than this always refresh the Jacobian
#: a refresh (Jacobian + band factorisation) costs this many chord iterations (residual + band solve) per band width
#: ``kl + ku + 1`` (measured on the journal's content film, 151 x 21: 1.38 ms against 0.215 ms at width 43)
REFRESH_PER_BAND = 0.15
CJ_REFRESH = 0.3  # ... and so does a step whose cj moved by more than this fraction since the factorisation
RATE_FLOOR = 0.3  # an update is accepted if max(rate / (1 - rate), RATE_FLOOR) times its size is within tolerance
PICK_RATIO = 0.5  # a component starts from the extrapolation in z if that was this much closer than the one in y
MIN_RATIO, MAX_RATIO, SAFETY = 0.2, 2.0, 0.9
#: slots of the Newton's ``counts`` (the stepper's cost by operation, ``options["newton_counts"]``): residuals,
#: Jacobians (each one factored), Newton iterations, Jacobians refreshed inside a solve because components switched
#: regime / because the contraction was slow / at a solve's start, damped updates, Newton solves, switched
#: components summed over the refreshes they caused
RESIDUALS, J_EVALS, ITERATIONS, J_SWITCH, J_RATE, J_START, DAMPED, SOLVES, SWITCHED = range(9)
N_COUNTS = 9
#: slots of the Newton's ``state``: cj of the factorisation (0: none), refresh flag, last contraction rate, iterations
#: of the last solve, the iteration start z given (1) or from the predictor y_pred (0), a refresh's cost in chord
#: iterations (0: every switch refreshes)
CJ_J, REFRESH, RATE, ITERS, Z_GIVEN, REFRESH_COST = range(6)


class Bdf2Model(NamedTuple):
    """What a model hands the BDF2 stepper.

    ``newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts) -> int``: the model's
    own ``@njit`` function returning :func:`newton_step` called with its kernels (compiled once per process: numba
    cannot cache a function that receives kernels as arguments, their keys never match in a new process and each
    process would add an index entry until saving the index fails)::

        residual(t, y, yp, out, args)          out = F(t, y, y')
        jacobian(t, y, yp, cj, data, args)     CSC data (Problem.jac_pattern order) of (dF/dy + cj dF/dy') dy/dz
        norm(z, dz, args) -> (float, int)      a Newton update dz of the components NOT in error_components in units
                                               of their Newton tolerance (<= 1: converged; the fields of the last
                                               residual are at hand), and how many components switched regime
                                               (e.g. cavitated / full film) since the last jacobian (> 0: refresh);
                                               it may shorten dz first (a step limiter at a kink)
        to_state(z, y, args), from_state(y, z, args)   the Newton variables z <-> the state y

    Newton iterates on variables ``z`` of the model's choice (e.g. the film's universal variable, smooth across
    the cavitation switch where the content is not); the time discretisation, error test and outputs stay on the
    state ``y``; ``z`` (in/out: the extrapolation in z, then the solution) and ``pick`` (in/out, bool per component)
    carry the predictor choice between steps (:func:`newton_step`). ``error_components``: the indices the error test and step control act on (identical in ``y`` and
    ``z``); ``n_border``: the trailing dense unknowns of the arrow pattern."""

    newton: Callable
    args: tuple
    error_components: np.ndarray
    n_border: int


@njit(inline='always')  # inlined into the model's own cached caller, which holds its kernels as globals
def _refactor(jacobian, to_state, args, t, cj, b, z, y, yp, data, lu, state, counts):
    """Jacobian ``dF/dz`` (with ``y' = cj y + b``) at the Newton variables ``z`` and its factorisation; False if
    singular."""
    to_state(z, y, args)
    for i in range(y.size):
        yp[i] = cj * y[i] + b[i]
    jacobian(t, y, yp, cj, data, args)
    counts[J_EVALS] += 1
    state[REFRESH] = 0.0
    if band_factor(data, lu) != 0:
        state[CJ_J] = 0.0
        return False
    state[CJ_J] = cj
    return True


@njit(inline='always')  # inlined into the model's own cached caller, which holds its kernels as globals
def _update(residual, norm, to_state, args, lu, t, cj, b, z, y, yp, F, dz, scale, err_idx, err_w, counts):
    """Residual at ``z`` and the chord update ``dz``; returns (its size in tolerance units, switched components),
    size = inf if the residual is not finite."""
    n = y.size
    to_state(z, y, args)
    for i in range(n):
        yp[i] = cj * y[i] + b[i]
    residual(t, y, yp, F, args)
    counts[RESIDUALS] += 1
    for i in range(n):
        if not np.isfinite(F[i]):
            return np.inf, 0
    return _chord(norm, args, lu, z, F, dz, scale, err_idx, err_w)


@njit(inline='always')  # inlined into the model's own cached caller, which holds its kernels as globals
def _chord(norm, args, lu, z, F, dz, scale, err_idx, err_w):
    """The update ``dz = scale M^-1 F`` on the current factorisation for the residual ``F`` at ``z``, its size and
    switched components (:func:`_update`)."""
    band_solve(lu, F, dz)
    for i in range(dz.size):
        dz[i] *= scale
    size, switched = norm(z, dz, args)
    for k in range(err_idx.size):
        v = abs(dz[err_idx[k]]) * err_w[k]
        if v > size:
            size = v
    return size, switched


@njit(cache=True)
def _switch_pays(size, rate, switched, cost):
    """Whether a Jacobian refresh for ``switched`` components pays: always for more than ``SWITCH_ALWAYS`` of them,
    else when the chord iterations still needed at contraction ``rate`` from an update of ``size`` (tolerance
    units), ``log(size max(RATE_FLOOR, r / (1 - r))) / -log r``, exceed the one a fresh Jacobian needs by more than
    ``cost`` (a refresh in chord iterations)."""
    if switched > SWITCH_ALWAYS or cost <= 0.0:
        return True
    r = min(max(rate, 0.01), 0.9)
    left = math.log(size * max(RATE_FLOOR, r / (1.0 - r))) / -math.log(r)
    return left - 1.0 > cost


@njit(inline='always')  # inlined into the model's own cached caller, which holds its kernels as globals
def newton_step(residual, jacobian, norm, to_state, from_state, args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z,
                pick, err_idx, err_w, state, counts):
    """Solve one implicit step ``F(t, y, cj y + b) = 0`` (the result in ``y``, ``yp`` and, in the Newton variables,
    ``z``), iterating on the model's Newton variables ``z`` (``y = to_state(z)``). Start: component ``i`` of the
    extrapolation ``z`` (given if ``state[Z_GIVEN]``) where ``pick[i]``, else of the predictor ``y_pred`` mapped to
    z; on convergence ``pick[i]`` says whether the extrapolation in z was closer (by ``PICK_RATIO``).

    Chord iterations on the current factorisation. The Jacobian is re-evaluated at the current iterate (and
    factored) when the contraction rate exceeds ``RATE_REFRESH``, or the model reports components that switched
    regime since the Jacobian (cells crossing the cavitation switch) and :func:`_switch_pays` (the refresh's cost
    ``state[REFRESH_COST]`` against the chord iterations it saves), at most ``MAX_REFRESH`` times; the residual
    at that iterate is solved again on the new factorisation (not re-evaluated). An update larger than the previous
    one (no contraction) halves the previous update instead (damping, down to 1/16). Converged when the update
    is within tolerance, or (Hairer & Wanner II, IV.8; SUNDIALS) when the contraction rate ``r`` of the chord
    bounds the error left after it, ``max(r / (1 - r), RATE_FLOOR) |dz| <= 1`` (``r`` of this solve, on the first
    iteration the last solve's; not on an update from a fresh Jacobian). ``state`` and ``counts``: the slots
    named in this module. Returns 0 (converged), 1 (no convergence), 2 (singular)."""
    n = y.size
    z_y = np.empty(n)
    from_state(y_pred, z_y, args)
    z_z = z.copy()
    for i in range(n):
        if state[Z_GIVEN] == 0.0 or not pick[i]:
            z[i] = z_y[i]
    counts[SOLVES] += 1
    fresh = 0  # the iteration whose update came from a fresh Jacobian (its rate is not the chord's)
    if state[CJ_J] == 0.0 or state[REFRESH] != 0.0:
        counts[J_START] += 1
        if not _refactor(jacobian, to_state, args, t, cj, b, z, y, yp, data, lu, state, counts):
            return 2
    else:
        fresh = -1
    z_base = z.copy()
    d_base = np.zeros(n)
    refreshed = 0
    prev = np.inf
    lam = 1.0
    rate = 0.0
    for it in range(MAX_ITER):
        size, switched = _update(residual, norm, to_state, args, lu, t, cj, b, z, y, yp, F, dz,
                                 2.0 / (1.0 + cj / state[CJ_J]), err_idx, err_w, counts)
        state[ITERS] = it + 1
        counts[ITERATIONS] += 1
        if it > 0 and size > prev and lam > 1.0 / 16.0:  # damp the last update
            counts[DAMPED] += 1
            lam *= 0.5
            for i in range(n):
                z[i] = z_base[i] - lam * d_base[i]
            continue
        slow = it > 0 and size > RATE_REFRESH * prev
        if (1.0 < size < np.inf and refreshed < MAX_REFRESH
                and (slow or (switched > 0 and _switch_pays(size, size / prev if it > 0 else state[RATE], switched,
                                                            state[REFRESH_COST])))):
            refreshed += 1
            fresh = it
            counts[J_SWITCH if switched > 0 else J_RATE] += 1
            counts[SWITCHED] += switched
            if not _refactor(jacobian, to_state, args, t, cj, b, z, y, yp, data, lu, state, counts):
                return 2
            size, switched = _chord(norm, args, lu, z, F, dz, 1.0, err_idx, err_w)  # F is the residual at z
        if not np.isfinite(size):
            state[REFRESH] = 1.0
            return 1
        rate = size / prev if it > 0 else 0.0
        r = rate if it > 0 else state[RATE]
        state[RATE] = rate
        z_base[:] = z
        d_base[:] = dz
        for i in range(n):
            z[i] -= dz[i]
        done = size <= 1.0
        if not done and fresh != it and 0.0 < r < 0.9:
            done = size * max(RATE_FLOOR, r / (1.0 - r)) <= 1.0
        if done:
            to_state(z, y, args)
            for i in range(n):
                yp[i] = cj * y[i] + b[i]
            for i in range(n):  # each component starts the next step from the predictor closer to it in this one
                pick[i] = state[Z_GIVEN] != 0.0 and abs(z[i] - z_z[i]) < PICK_RATIO * abs(z[i] - z_y[i])
            if rate > RATE_REFRESH:
                state[REFRESH] = 1.0
            return 0
        prev = size
        lam = 1.0
    state[REFRESH] = 1.0
    return 1


def _quadratic(ts, ys, t, slope=None):
    """The quadratic through the points ``(ts[k], ys[k])`` (3 of them), or through 2 points with the slope at
    the first (Hermite), or the line through 1 point with its slope, at ``t``."""
    if len(ts) == 3:
        t0, t1, t2 = ts
        return (ys[0] * ((t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)))
                + ys[1] * ((t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)))
                + ys[2] * ((t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1))))
    if len(ts) == 2:
        h1 = ts[1] - ts[0]
        c = (ys[1] - ys[0] - slope * h1) / (h1 * h1)
        s = t - ts[0]
        return ys[0] + slope * s + c * (s * s)
    return ys[0] + slope * (t - ts[0])


def integrate_bdf2(problem, t_eval, out, guard, rtol, atol, max_step, first_step, max_steps, options, step_events,
                   interrupt):
    """The step loop (module docstring). ``out``/``guard``/``step_events``/``interrupt`` are the integrator facade's
    output collector, callback guard, per-step event helper and Ctrl-C check. Returns (success, message)."""
    model = options.get("bdf2")
    if not isinstance(model, Bdf2Model):
        raise ValueError(f"method 'bdf2' needs options={{'bdf2': Bdf2Model(...)}} from the model (its compiled residual, "
                         f"Jacobian and Newton norm); problem '{problem.name}' gave {type(model).__name__}")
    if problem.jac_pattern is None:
        raise ValueError(f"method 'bdf2' needs the sparse Jacobian pattern; problem '{problem.name}' has none")
    n = problem.n
    err_idx = np.ascontiguousarray(model.error_components, dtype=np.int64)
    atol_v = np.broadcast_to(np.asarray(atol, dtype=float), (n,))[err_idx]
    lu = BorderedBandLU(problem.jac_pattern, model.n_border)
    data = np.zeros(problem.jac_pattern.nnz)
    F, dy, yp, y_new = (np.empty(n) for _ in range(4))
    state = np.zeros(6)
    refresh_cost = REFRESH_PER_BAND * (lu.kl + lu.ku + 1)
    state[REFRESH_COST] = refresh_cost
    pick = np.zeros(n, dtype=np.bool_)
    z_new = np.empty(n)
    counts = np.zeros(N_COUNTS, dtype=np.int64)
    events = out.events
    t_end = float(t_eval[-1])
    t = float(t_eval[0])
    y = problem.y0.copy()
    slope = np.zeros(n) if problem.yp0 is None else problem.yp0.copy()
    out.put(y)
    g_prev = events.values(t, y) if events is not None else None
    span = t_end - t
    fixed = float(options.get("fixed_step", 0.0))
    h = fixed if fixed > 0 else (first_step if first_step > 0 else 1e-4 * span)
    t_start, k_step = t, 0
    h_cap = max_step if max_step > 0 else span
    ts, ys, zs = [t], [y], [None]  # the last (up to 3) accepted points, oldest first
    err_prev = 1.0
    n_etf = n_nlf = 0
    message = "reached the final time"

    def finish(success, msg):
        guard.n_rhs += int(counts[RESIDUALS])
        guard.n_jac += int(counts[J_EVALS])
        tally = options.get("newton_counts")
        if tally is not None:
            tally += counts
        guard.n_error_test_failures = n_etf
        guard.n_nonlinear_failures = n_nlf
        return success, msg

    while out.k < t_eval.size:
        if fixed > 0:  # step k ends at t_start + k h exactly (no drift), the last one at t_end
            t_new = min(t_end, t_start + (k_step + 1) * fixed)
            h = t_new - t
        else:
            h = min(h, h_cap)
            if t + h >= t_end - 1e-9 * h:
                h = t_end - t
            t_new = t + h
        if t_new <= t or h <= 1e-14 * max(1.0, abs(t)):
            return finish(False, f"bdf2: the step size collapsed to {h:.3g} at t={t:.9g} ({n_nlf} Newton failures, "
                                 f"{n_etf} error-test failures)")
        if len(ts) == 1:  # backward Euler
            cj = 1.0 / h
            b = -y / h
            y_pred = _quadratic(ts, ys, t_new, slope)
            h1 = h2 = 0.0
        else:
            h1 = t - ts[-2]
            w = h / h1
            cj = (1.0 + 2.0 * w) / (h * (1.0 + w))
            b = (-(1.0 + w) / h) * y + (w * w / (h * (1.0 + w))) * ys[-2]
            y_pred = _quadratic(ts, ys, t_new, slope)
            h2 = ts[-2] - ts[-3] if len(ts) == 3 else 0.0
        if state[CJ_J] != 0.0 and abs(cj / state[CJ_J] - 1.0) > CJ_REFRESH:
            state[REFRESH] = 1.0
        err_w = 1.0 / (NEWTON_FACTOR * (rtol * np.abs(y_pred[err_idx]) + atol_v))
        if len(ts) == 3 and zs[0] is not None:
            z_new[:] = _quadratic(ts, zs, t_new)
            state[Z_GIVEN] = 1.0
        else:
            state[Z_GIVEN] = 0.0
        code = model.newton(model.args, t_new, cj, np.ascontiguousarray(b), y_new, yp, F, dy, data, lu.arrays,
                            np.ascontiguousarray(y_pred), z_new, pick, err_idx, err_w, state, counts)
        interrupt()
        if code != 0 and state[REFRESH_COST] > 0.0:  # the same step again, every switch refreshing the Jacobian
            n_nlf += 1
            state[REFRESH_COST] = 0.0
            state[REFRESH] = 1.0
            continue
        state[REFRESH_COST] = refresh_cost
        if code != 0:
            n_nlf += 1
            if fixed > 0:
                return finish(False, f"bdf2: Newton failed at t={t_new:.9g} with the fixed step {fixed:.4g}")
            h *= 0.25
            continue
        d = (y_new - y_pred)[err_idx]
        if len(ts) == 1:
            est = 0.5 * d
        else:
            est = d * (h * h * (1.0 + w) ** 2 / (w * (1.0 + 2.0 * w)) / ((h + h1) * (h + h1 + h2)))
        err = math.sqrt(float(np.mean((est / (rtol * np.abs(y_new[err_idx]) + atol_v)) ** 2)))
        if not math.isfinite(err):
            n_nlf += 1
            h *= 0.25
            continue
        if err > 1.0 and fixed == 0:
            n_etf += 1
            h *= max(MIN_RATIO, SAFETY * err ** (-1.0 / 3.0))
            continue
        # accepted
        guard.n_steps += 1
        k_step += 1
        y_acc = y_new.copy()
        pts_t, pts_y = (ts[-2:] + [t_new], ys[-2:] + [y_acc]) if len(ts) >= 2 else ([t, t_new], [y, y_acc])

        def state_at(s, pts_t=pts_t, pts_y=pts_y, y_acc=y_acc, t_new=t_new):
            return y_acc if s >= t_new else _quadratic(pts_t, pts_y, s, slope)

        t_old = t
        ts, ys, zs = (ts + [t_new])[-3:], (ys + [y_acc])[-3:], (zs + [z_new.copy()])[-3:]
        t, y = t_new, y_acc
        if events is not None:
            g_prev, te = step_events(events, state_at, t_old, t_new, g_prev, y_acc, out)
            if te is not None:
                return finish(True, f"terminal event at t={te:.9g}")
        while out.k < t_eval.size and out.pending <= t_new + 1e-9 * h:
            out.put(state_at(out.pending) if out.pending < t_new - 1e-9 * h else y_acc)
        late = guard.over_budget(t_new)
        if late:
            return finish(False, late)
        if guard.n_steps >= max_steps and out.k < t_eval.size:
            return finish(False, f"bdf2: max_steps={max_steps} reached at t={t:.9g}")
        e = max(err, 1e-10)
        ratio = SAFETY * e ** (-0.7 / 3.0) * err_prev ** (0.4 / 3.0)
        h *= min(MAX_RATIO, max(MIN_RATIO, ratio))
        err_prev = e
    return finish(True, message)


def solve(problem, t_eval, out, guard, s):
    """The back end of :func:`~transient.solvers.integrate.solve`: :func:`integrate_bdf2` with the facade's
    settings ``s``, events located on the step's quadratic; returns ``(success, message)``."""
    out.events = Events(problem, guard, poison=False) if problem.n_events else None
    return integrate_bdf2(problem, t_eval, out, guard, s.rtol, s.atol, s.max_step, s.first_step, s.max_steps,
                          s.options, step_events, SIGINT.check)
