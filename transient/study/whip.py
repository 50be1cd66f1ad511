"""Oil whip of the Rho & Kim rotor (Rho & Kim, "A study of the dynamic characteristics of a journal bearing
with a mass-conserving cavitation algorithm"): a run-up through the Lund threshold and long runs above it.

* :func:`whirl_numbers` -- what a whirl is measured by, from an :class:`~transient.models.journal.OrbitResult`
  sampled at a fixed rate per revolution: the amplitude (half the peak-to-peak of x and y and the
  eccentricity range over the last revolutions) and whether it is a limit cycle (:func:`envelope_growth`: the
  eccentricity envelope of the last block of revolutions against the block before, per revolution, below
  ``ENVELOPE_TOL``), the whirl frequency ratio (the mean angular speed of the
  centre about the orbit's centre over the last four revolutions, in shaft orders: 1 for the synchronous
  unbalance orbit, near 0.5 in oil whirl and whip) and the sub-synchronous peak of the x spectrum, the Poincare section
  (the centre once per shaft revolution), the smallest film and the touch event (``touched_at``).
* :func:`run_up` -- a quasi-static run-up: constant-speed segments stepping through the threshold, each
  continuing the previous state. The film is carried over as its content ``m = H theta`` (speed-independent)
  and the journal velocity in m/s, and each segment's time origin is shifted so that the unbalance keeps
  its phase; the result (:class:`RunUp`) holds the physical time, the speed of every sample and the
  numbers of every segment.
* :func:`long_whip` -- a long run at one speed with a checkpoint (``JournalOrbit.run(checkpoint=, resume=)``):
  killed at any moment, the same call continues from the last chunk.

Both integrate with ``method=`` :data:`METHOD` (``"bdf2"``) unless given ``"ida"``.
"""

from __future__ import annotations

import numpy as np

from transient.analysis.orbits import per_revolution, revolution_spectrum
from transient.results import StatusResult, quantity, result_type
from transient.solvers.settings import Integration, LongRun, Recording


#: a whirl is a limit cycle when its eccentricity envelope (max and min over a block of revolutions) changes by
#: less than this per revolution [C/rev] between the last two blocks
ENVELOPE_TOL = 1e-3
#: revolutions per block of :func:`envelope_growth` (two whirl periods at a whirl frequency ratio of 0.5)
ENVELOPE_BLOCK = 4
#: the integrators of the whip runs (``JournalOrbit.run(method=)``) and the default: BDF2 on the content film,
#: ~10-15x less CPU per whip revolution than IDA at equal error on 151 x 21 (docs/bench/orbit_size.md), and the same
#: whirl numbers and verdicts as IDA on the scenario's quick grid (docs/journal.md)
METHODS = ("bdf2", "ida")
METHOD = "bdf2"


def envelope_growth(eps_max_per_rev, eps_min_per_rev, block: int = ENVELOPE_BLOCK) -> tuple[float, int]:
    """How fast the eccentricity envelope still moves: the largest of (max e/C over the last ``block``
    revolutions - max over the block before) / ``block`` and the same for the min, in C per revolution
    (signed: > 0 growing). The block shrinks to half the revolutions when there are fewer than ``2 block``;
    returns (growth, block used), growth = nan with fewer than 2 revolutions."""
    hi, lo = np.asarray(eps_max_per_rev, float), np.asarray(eps_min_per_rev, float)
    b = min(int(block), hi.size // 2)
    if b < 1:
        return float("nan"), 0
    g_hi = (hi[-b:].max() - hi[-2 * b:-b].max()) / b
    g_lo = (lo[-2 * b:-b].min() - lo[-b:].min()) / b  # a falling minimum is a growing orbit
    return float(g_hi if abs(g_hi) >= abs(g_lo) else g_lo), b


def settled_text(numbers: dict) -> str:
    """'limit cycle' or 'not settled (envelope +x C/rev over the last 2 x b rev)', from :func:`whirl_numbers`."""
    g, b = numbers["envelope_growth_per_rev"], numbers["envelope_block"]
    if numbers["settled"]:
        return f"limit cycle (envelope {g:+.1e} C/rev over the last {2 * b} rev, tolerance {ENVELOPE_TOL:g})"
    return f"NOT settled (envelope {g:+.1e} C/rev over the last {2 * b} rev, tolerance {ENVELOPE_TOL:g})"


def whirl_numbers(result, outputs_per_revolution: int, last_revolutions: int = 10) -> dict:
    """Amplitude, settling (:func:`envelope_growth` against ``ENVELOPE_TOL``: ``settled``), whirl frequency
    ratio, Poincare section, smallest film and touch of one orbit run."""
    opr = int(outputs_per_revolution)
    C = result.clearance
    X, Y = per_revolution(result.x, result.y, opr, C)
    n = X.shape[0]
    if n == 0:
        raise ValueError("whirl_numbers needs at least one full revolution of outputs")
    k = min(int(last_revolutions), n)
    x, y = X[-k:].ravel(), Y[-k:].ravel()
    eps = np.hypot(x, y)
    order, spec, harm, _ = revolution_spectrum(X[-k:])
    sub = (order > 0.05) & (order < 0.95)
    # whirl frequency: the mean angular speed of the centre about the orbit's centre, in shaft orders (exact
    # for a circular whirl, and 1 for the synchronous unbalance orbit below the threshold)
    # over the last (up to) 4 revolutions: a growing whirl spirals and its centre moves over longer spans
    xw, yw = X[-min(k, 4):].ravel(), Y[-min(k, 4):].ravel()
    ang = np.unwrap(np.arctan2(yw - yw.mean(), xw - xw.mean()))
    whirl = float((ang[-1] - ang[0]) / (2 * np.pi * (xw.size - 1) / opr))
    eps_all = np.hypot(result.x, result.y) / C
    e_rev = np.hypot(X, Y)
    growth, block = envelope_growth(e_rev.max(axis=1), e_rev.min(axis=1))
    return dict(speed_rpm=float(result.speed_rpm), revolutions=int(n), last_revolutions=k,
                amp_x=float(0.5 * np.ptp(x)), amp_y=float(0.5 * np.ptp(y)),
                eps_min=float(eps.min()), eps_max=float(eps.max()), eps_mean=float(eps.mean()),
                whirl_ratio=whirl, sub_amplitude=float(spec[sub].max()) if sub.any() else 0.0,
                synchronous_amplitude=harm["1x"], min_film_m=float(C * (1.0 - eps_all.max())),
                touched_at_s=result.touched_at, message=result.message,
                poincare_x=X[:, 0].tolist(), poincare_y=Y[:, 0].tolist(),
                eps_max_per_rev=e_rev.max(axis=1).tolist(), eps_min_per_rev=e_rev.min(axis=1).tolist(),
                envelope_growth_per_rev=growth, envelope_block=block,
                settled=bool(np.isfinite(growth) and abs(growth) < ENVELOPE_TOL and result.touched_at is None),
                steps=int(result.stats.n_steps), wall_s=float(result.stats.wall_time))


@result_type
class RunUp(StatusResult):
    """A quasi-static run-up (:func:`run_up`): ``t`` [s] physical time, ``x``, ``y`` [m] journal centre,
    ``speed_rpm`` [rpm] of every sample; ``speeds`` [rpm] of the segments with, per segment, the eccentricity
    range over its last revolutions ``eps_min``, ``eps_max``, how fast its envelope still moved
    ``envelope_growth`` [C/rev] and whether that is below ``ENVELOPE_TOL`` (``settled``), its whirl frequency
    ratio ``whirl_ratio`` (shaft orders) and the integrator steps per revolution; ``threshold_rpm`` (Lund)."""

    t: np.ndarray = quantity("s")
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    speed_rpm: np.ndarray = quantity("rpm")
    speeds: np.ndarray = quantity("rpm", default_factory=lambda: np.zeros(0))
    eps_min: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    eps_max: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    whirl_ratio: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    envelope_growth: np.ndarray = quantity("1/rev", default_factory=lambda: np.zeros(0))
    settled: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0, bool))
    steps_per_revolution: np.ndarray = quantity("1/rev", default_factory=lambda: np.zeros(0))
    threshold_rpm: float = quantity("rpm", 0.0)
    clearance: float = quantity("m", 0.0)
    touched_at: float | None = quantity("s", None)


def carry_state(old, new, y):
    """The state ``y`` (universal layout) of orbit ``old`` as a state of orbit ``new`` (another speed): the
    film keeps its content ``H theta`` (so its pressure follows the new speed's film), the journal its position
    and its velocity in m/s (the dimensionless velocity is per ``C omega``)."""
    n = old.film.n
    m = old.content_state(y)
    m[n + 2:] *= old.film.omega / new.film.omega
    return new.universal_state(m)


def run_up(make_orbit, speeds, revolutions_per_speed, rtol=1e-4, outputs_per_revolution=64,
           last_revolutions=4, threshold_rpm=0.0, touch_gap=1e-3, progress=False, method=METHOD) -> RunUp:
    """Step the speed through ``speeds`` [rpm], ``revolutions_per_speed`` at each, every segment continuing
    the previous one (:func:`carry_state`; the first starts from the static equilibrium), integrated by
    ``JournalOrbit.run(method=)`` (``"bdf2"`` or ``"ida"``, :data:`METHOD`).
    ``make_orbit(speed_rpm) -> JournalOrbit``. Stops at the first touch or failure."""
    opr = int(outputs_per_revolution)
    t_all, x_all, y_all, s_all = [], [], [], []
    seg = dict(speeds=[], eps_min=[], eps_max=[], whirl_ratio=[], steps=[], growth=[], settled=[])
    prev, state, t_phys, tau_end = None, None, 0.0, 0.0
    touched, ok, msg = None, True, "reached the last speed"
    for s in speeds:
        o = make_orbit(float(s))
        if prev is None:
            start = None
        else:
            # the new orbit's tau = omega_new t: start at the time whose phase is the old one's
            state = carry_state(prev, o, state)
            start = (tau_end / o.film.omega, state)
        r = o.run(revolutions_per_speed, integration=Integration(method=method, rtol=rtol),
                  recording=Recording(outputs_per_revolution=opr), long_run=LongRun(progress=progress), start=start,
                  touch_gap=touch_gap)
        t0 = r.t[0]
        keep = slice(0 if prev is None else 1, None)
        t_all.append(t_phys + (r.t[keep] - t0))
        x_all.append(r.x[keep])
        y_all.append(r.y[keep])
        s_all.append(np.full(r.t[keep].size, float(s)))
        w = whirl_numbers(r, opr, last_revolutions)
        seg["speeds"].append(float(s))
        seg["eps_min"].append(w["eps_min"])
        seg["eps_max"].append(w["eps_max"])
        seg["whirl_ratio"].append(w["whirl_ratio"])
        seg["growth"].append(w["envelope_growth_per_rev"])
        seg["settled"].append(w["settled"])
        seg["steps"].append(r.stats.n_steps / max(revolutions_per_speed, 1e-300))
        t_phys += r.t[-1] - t0
        if r.touched_at is not None or not r.success:
            touched = t_phys if r.touched_at is not None else None
            ok, msg = r.success, f"at {s:g} rpm: {r.message}"
            break
        prev, state, tau_end = o, r.final_state, r.final_time * o.film.omega
    return RunUp(t=np.concatenate(t_all), x=np.concatenate(x_all), y=np.concatenate(y_all),
                 speed_rpm=np.concatenate(s_all), speeds=np.array(seg["speeds"]), eps_min=np.array(seg["eps_min"]),
                 eps_max=np.array(seg["eps_max"]), whirl_ratio=np.array(seg["whirl_ratio"]),
                 envelope_growth=np.array(seg["growth"]), settled=np.array(seg["settled"], bool),
                 steps_per_revolution=np.array(seg["steps"]), threshold_rpm=float(threshold_rpm),
                 clearance=make_orbit(float(speeds[0])).bearing.clearance, touched_at=touched, success=ok,
                 message=msg)


def long_whip(orbit, revolutions, rtol=1e-4, outputs_per_revolution=64, checkpoint=None, resume=True,
              chunk_revolutions=10.0, last_revolutions=20, touch_gap=1e-3, progress=True, method=METHOD):
    """``revolutions`` at the orbit's speed from the static equilibrium, checkpointed, integrated by
    ``JournalOrbit.run(method=)`` (``"bdf2"`` or ``"ida"``, :data:`METHOD`); returns (result,
    :func:`whirl_numbers`)."""
    r = orbit.run(revolutions, integration=Integration(method=method, rtol=rtol),
                  recording=Recording(outputs_per_revolution=outputs_per_revolution),
                  long_run=LongRun(checkpoint=checkpoint, resume=resume, chunk_revolutions=chunk_revolutions,
                                   progress=progress),
                  touch_gap=touch_gap)
    return r, whirl_numbers(r, outputs_per_revolution, last_revolutions)
