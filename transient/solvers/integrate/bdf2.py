"""Variable-step BDF2 with its own Newton on a bordered band LU, for DAEs ``F(t, y, y') = 0`` whose step size is
set by a few declared components (a rotor) while the others (a film) are only solved to a Newton tolerance.

The time discretisation, error test, step control, dense output and the step loop are the
:class:`~transient.solvers.integrate.stepper.BDF2` stepper's (:mod:`transient.solvers.integrate.stepper`); this
module is the step solve of a model that hands its kernels as a :class:`Bdf2Model` (:class:`BandNewton`), and
the back end ``method="bdf2"`` of the integrator facade, which also takes a model's own
:class:`~transient.solvers.integrate.stepper.StepSolve` as ``Problem.step_solve`` (the point contact's FBNS).

The Newton, iterated on the model's Newton variables ``z`` (``y = to_state(z)``): it starts, component by component,
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
step (predictor, error test, step control, dense output, events).

The model hands the kernels as a :class:`Bdf2Model` in ``solve(..., options={"bdf2": model})``;
``options["fixed_step"] = h`` takes steps of exactly h with no error test (convergence studies);
``options["max_step_scale"]``, a function of t, scales ``max_step`` at each step's start (a cap in shaft angle);
``options["max_order"]`` (2 to 5, default 2) the highest order of the stepper's variable-order BDF;
``options["max_travel"] = (components, distance)`` bounds each step by the travel of those components (a journal's);
``options["error_pairs"]``, rows ``(i, j)`` of error components weighed by the length of their plane vector
(:func:`~transient.solvers.integrate.stepper.magnitude`: a journal's x and y), in the error test and the Newton
tolerance.
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np
from numba import njit

from transient.solvers.bandlu import BorderedBandLU, band_factor, band_solve
from transient.solvers.inner_kernel import inner_kernel
from transient.solvers.integrate.guard import SIGINT
from transient.solvers.integrate.outputs import Events, step_events
from transient.solvers.integrate.stepper import BDF2, StepBounds, StepSolve, drive, magnitude, quadratic

# the band LU as the Newton calls it (inlined into a model's caller): without the entry points Python calls
_band_factor = inner_kernel(band_factor)
_band_solve = inner_kernel(band_solve)

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
    own ``@njit(cache=True)`` function returning :func:`newton_step` called with its kernels as module globals.
    :func:`newton_step` and its helpers are ``inline="always"``: inlined there, the kernels are static calls and the
    caller is cached on disk like any kernel (a dispatcher handed to a non-inlined function is lowered as a dynamic
    address, which numba's cache refuses: every process compiled the Newton again, ~40 s CPU). numba keys the cache
    on the caller's file only, so the caller's module guards it against edits of this one
    (:func:`~transient.solvers.integrate.cache_guard.drop_stale_cache`)::

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


@njit(inline="always")  # inlined into the model's cached caller (Bdf2Model.newton), where its kernels are globals
def _refactor(jacobian, to_state, args, t, cj, b, z, y, yp, data, lu, state, counts):
    """Jacobian ``dF/dz`` (with ``y' = cj y + b``) at the Newton variables ``z`` and its factorisation; False if
    singular."""
    to_state(z, y, args)
    for i in range(y.size):
        yp[i] = cj * y[i] + b[i]
    jacobian(t, y, yp, cj, data, args)
    counts[J_EVALS] += 1
    state[REFRESH] = 0.0
    if _band_factor(data, lu) != 0:
        state[CJ_J] = 0.0
        return False
    state[CJ_J] = cj
    return True


@njit(inline="always")  # inlined into the model's cached caller (Bdf2Model.newton), where its kernels are globals
def _chord(norm, args, lu, z, F, dz, scale, err_idx, err_w):
    """The update ``dz = scale M^-1 F`` on the current factorisation for the residual ``F`` at ``z``, its size in
    tolerance units and switched components (:func:`newton_step`)."""
    _band_solve(lu, F, dz)
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


@njit(inline="always")  # inlined into the model's cached caller (Bdf2Model.newton), where its kernels are globals
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
    factor = state[CJ_J] == 0.0 or state[REFRESH] != 0.0  # a Jacobian at z is due before the next update
    if factor:
        counts[J_START] += 1
    else:
        fresh = -1
    again = False  # the update is that of the residual F at z on a fresh factorisation (not re-evaluated)
    z_base = z.copy()
    d_base = np.zeros(n)
    refreshed = 0
    prev = np.inf
    lam = 1.0
    rate = 0.0
    it = 0
    while it < MAX_ITER:  # one call site per kernel: a smaller caller to compile
        if factor:
            factor = False
            if not _refactor(jacobian, to_state, args, t, cj, b, z, y, yp, data, lu, state, counts):
                return 2
        scale = 1.0
        finite = True
        if not again:
            scale = 2.0 / (1.0 + cj / state[CJ_J])
            to_state(z, y, args)
            for i in range(n):
                yp[i] = cj * y[i] + b[i]
            residual(t, y, yp, F, args)
            counts[RESIDUALS] += 1
            for i in range(n):
                if not np.isfinite(F[i]):
                    finite = False
                    break
        size, switched = np.inf, 0
        if finite:
            size, switched = _chord(norm, args, lu, z, F, dz, scale, err_idx, err_w)
        if not again:
            state[ITERS] = it + 1
            counts[ITERATIONS] += 1
            if it > 0 and size > prev and lam > 1.0 / 16.0:  # damp the last update
                counts[DAMPED] += 1
                lam *= 0.5
                for i in range(n):
                    z[i] = z_base[i] - lam * d_base[i]
                it += 1
                continue
            slow = it > 0 and size > RATE_REFRESH * prev
            if (1.0 < size < np.inf and refreshed < MAX_REFRESH
                    and (slow or (switched > 0 and _switch_pays(size, size / prev if it > 0 else state[RATE],
                                                                switched, state[REFRESH_COST])))):
                refreshed += 1
                fresh = it
                counts[J_SWITCH if switched > 0 else J_RATE] += 1
                counts[SWITCHED] += switched
                factor = again = True  # F is the residual at z: solved again on the new factorisation
                continue
        again = False
        if not np.isfinite(size):
            state[REFRESH] = 1.0
            return 1
        rate = size / prev if it > 0 else 0.0
        r = rate if it > 0 else state[RATE]
        state[RATE] = rate
        for i in range(n):  # element loops: an array assignment compiles numba's shape-mismatch error path
            z_base[i] = z[i]
            d_base[i] = dz[i]
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
        it += 1
    state[REFRESH] = 1.0
    return 1


class BandNewton(StepSolve):
    """The step solve of a :class:`Bdf2Model`: its compiled Newton (:func:`newton_step`) on a bordered band LU of
    the problem's Jacobian pattern, the Newton tolerance of the error components ``NEWTON_FACTOR (rtol |y_pred| +
    atol)``, the extrapolation of the Newton variables through the last three steps, and one retry of a failed
    solve with every switch refreshing the Jacobian (the weighed refresh can starve a hard step)."""

    def __init__(self, model: Bdf2Model, pattern, n, rtol, atol):
        self.model = model
        self.error_components = np.ascontiguousarray(model.error_components, dtype=np.int64)
        self.rtol = rtol
        self.atol = np.broadcast_to(np.asarray(atol, dtype=float), (n,))[self.error_components]
        self.lu = BorderedBandLU(pattern, model.n_border)
        self.data = np.zeros(pattern.nnz)
        self.F, self.dz, self.yp = (np.empty(n) for _ in range(3))
        self.state = np.zeros(6)
        self.refresh_cost = REFRESH_PER_BAND * (self.lu.kl + self.lu.ku + 1)
        self.state[REFRESH_COST] = self.refresh_cost
        self.pick = np.zeros(n, dtype=np.bool_)
        self.z = np.empty(n)
        self.zs = [None]  # the Newton variables at the accepted points, aligned with the stepper's
        self.newton_counts = np.zeros(N_COUNTS, dtype=np.int64)
        self.may_retry = False
        self.pairs = None  # error_pairs: the Newton tolerance's weights as the error test's

    def solve(self, t, cj, history, ts, ys, y_pred):
        state, z = self.state, self.z
        if state[CJ_J] != 0.0 and abs(cj / state[CJ_J] - 1.0) > CJ_REFRESH:
            state[REFRESH] = 1.0
        idx = self.error_components
        err_w = 1.0 / (NEWTON_FACTOR * (self.rtol * magnitude(y_pred, self.pairs)[idx] + self.atol))
        if len(ts) >= 3 and self.zs[0] is not None:
            z[:] = quadratic(ts[-3:], self.zs, t)
            state[Z_GIVEN] = 1.0
        else:
            state[Z_GIVEN] = 0.0
        y = np.empty(z.size)
        code = self.model.newton(self.model.args, t, cj, np.ascontiguousarray(history(ys)), y, self.yp, self.F,
                                 self.dz, self.data, self.lu.arrays, np.ascontiguousarray(y_pred), z, self.pick, idx,
                                 err_w, state, self.newton_counts)
        self.may_retry = code != 0 and state[REFRESH_COST] > 0.0
        if not self.may_retry:
            state[REFRESH_COST] = self.refresh_cost
        return code, y

    def retry(self) -> bool:
        if not self.may_retry:
            return False
        self.state[REFRESH_COST] = 0.0
        self.state[REFRESH] = 1.0
        return True

    def accepted(self, t, y):
        self.zs = (self.zs + [self.z.copy()])[-3:]

    def counts(self):
        return int(self.newton_counts[RESIDUALS]), int(self.newton_counts[J_EVALS])


def step_solve(problem, s) -> StepSolve:
    """The model's step solve for :func:`solve`: the problem's own (``problem.step_solve``, a :class:`StepSolve`) or
    ``s.options["bdf2"]``, a :class:`Bdf2Model` (wrapped in :class:`BandNewton`, which needs the problem's
    Jacobian pattern)."""
    if isinstance(problem.step_solve, StepSolve):
        return problem.step_solve
    model = s.options.get("bdf2")
    if not isinstance(model, Bdf2Model):
        raise ValueError(f"method 'bdf2' needs the model's step solve: Problem(step_solve=StepSolve) or "
                         f"options={{'bdf2': Bdf2Model(...)}} (its compiled residual, Jacobian and Newton norm); "
                         f"problem '{problem.name}' gave {type(model).__name__}")
    if problem.jac_pattern is None:
        raise ValueError(f"method 'bdf2' needs the sparse Jacobian pattern; problem '{problem.name}' has none")
    return BandNewton(model, problem.jac_pattern, problem.n, s.rtol, s.atol)


def solve(problem, t_eval, out, guard, s):
    """The back end of :func:`~transient.solvers.integrate.solve`: :class:`~transient.solvers.integrate.stepper.BDF2`
    on the model's step solve (:func:`step_solve`), run by :func:`~transient.solvers.integrate.stepper.drive`
    (events located on the step's quadratic); returns ``(success, message)``."""
    solver = step_solve(problem, s)
    pairs = s.options.get("error_pairs")
    if isinstance(solver, BandNewton):
        solver.pairs = None if pairs is None else np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    out.events = Events(problem, guard, poison=False) if problem.n_events else None
    bounds = StepBounds(first_step=s.first_step, fixed_step=float(s.options.get("fixed_step", 0.0)),
                        max_step=((s.max_step, s.options["max_step_scale"]) if "max_step_scale" in s.options
                                  else s.max_step), max_travel=s.options.get("max_travel"))
    stepper = BDF2(solver, problem.y0, t_eval[0], t_eval[-1], rtol=s.rtol, atol=s.atol,
                   error_components=solver.error_components, yp0=problem.yp0, bounds=bounds,
                   test_first_step=solver.test_first_step, max_order=int(s.options.get("max_order", 2)),
                   error_pairs=pairs)
    result = drive(stepper, out, guard, SIGINT.check, s.max_steps, step_events)
    tally = s.options.get("newton_counts")
    if tally is not None and isinstance(solver, BandNewton):  # the Newton's cost by operation, summed over solves
        tally += solver.newton_counts
    return result
