"""Bearing noise at one speed (Rho & Kim, sections 2.3-2.4): the periodic orbit, a recorded window,
the analysis.

1. the settled orbit: by default its periodic state by shooting
   (:func:`~transient.models.journal.periodic.periodic_response`: Newton-Picard on the once-per-revolution map,
   no settling run); with ``periodic=False`` by :func:`~transient.study.settle.settle` from the static
   equilibrium, recording nothing but the journal position once per revolution, until the motion is
   periodic to ``tol``;
2. integrate ``revolutions`` more revolutions from it (phase kept) recording the pressure field only there, at
   ``samples_per_revolution`` (> 2 * harmonics);
3. :func:`~transient.analysis.acoustics.analyse_pressure`: mean and fluctuation per node, harmonics,
   transmission, levels.
"""

from __future__ import annotations

import time

import numpy as np

from transient.analysis.acoustics import TRANSMISSIONS, BearingNoise, analyse_pressure
from transient.analysis.periodic import NotPeriodicError
from transient.checks import check_range
from transient.study.settle import SETTLE_LONG_RUN, Settled, Settling, settle
from transient.solvers.settings import Integration, LongRun, Recording, keyword_table, run_settings

#: The loose keywords of :func:`bearing_noise` of earlier releases and the settings field each now is.
NOISE_KEYWORDS = ({"settle_revolutions": ("settling", Settling, "periods"),
                   "max_settle_revolutions": ("settling", Settling, "max_periods"),
                   "confirm": ("settling", Settling, "confirm")}
                  | keyword_table("integration", Integration, ("method", "rtol"))
                  | {"chunk_revolutions": ("long_run", LongRun, "chunk_revolutions"),
                     "progress": ("long_run", LongRun, "progress")})


def default_samples_per_revolution(harmonics) -> int:
    """2 * harmonics + a margin: max(16, 4 * harmonics), even."""
    s = max(16, 4 * int(harmonics))
    return s + (s % 2)


def bearing_noise(orbit, revolutions=4, harmonics=5, *, tol=1e-4, transmission="printed", samples_per_revolution=None,
                  periodic=True, settling: Settling | None = None, integration: Integration | None = None,
                  long_run: LongRun | None = None, **legacy) -> BearingNoise:
    """Bearing noise of a :class:`~transient.models.journal.JournalOrbit` at its speed (module docstring).

    ``tol`` [C]: the distance from the periodic orbit accepted (default 1e-4 C, ~1 % of the 6000 rpm orbit
    amplitude): the shooting's error estimate (``periodic=True``), or the Poincare step below which the settling
    run counts as settled, ``settling.confirm`` consecutive times (``periodic=False``;
    :class:`~transient.study.settle.Settling`: ``periods`` = int skips the detection and settles for exactly that
    many, ``max_periods`` bounds it, default 60). ``integration``: the method and ``rtol`` of every run (the
    shooting takes the rtol; default ``Integration()``); ``long_run``: the settling run's chunks
    (``chunk_revolutions``, default 5) and progress bar (default off). Raises
    :class:`~transient.analysis.periodic.NotPeriodicError` if there is no stable periodic orbit (past the onset of
    whirl: the shooting's dominant Floquet multiplier is outside the unit circle, or the settling run does not
    settle within ``settling.max_periods``) or the journal touches the bearing. The loose keywords of earlier
    releases (``method``, ``rtol``, ``settle_revolutions``, ``max_settle_revolutions``, ``confirm``,
    ``chunk_revolutions``, ``progress``) are deprecated."""
    from transient.models.journal import JournalOrbit
    from transient.models.journal.periodic import periodic_response

    if not isinstance(orbit, JournalOrbit):
        raise TypeError(f"orbit must be a JournalOrbit, got {type(orbit).__name__}")
    revolutions = int(check_range("revolutions", revolutions, "rev", 1, 1e6))
    harmonics = int(check_range("harmonics", harmonics, "-", 1, 1e4))
    S = default_samples_per_revolution(harmonics) if samples_per_revolution is None else int(samples_per_revolution)
    if S <= 2 * harmonics:
        raise ValueError(f"samples_per_revolution = {S} [1/rev] cannot resolve harmonic {harmonics}; "
                         f"allowed: > {2 * harmonics}")
    if transmission not in TRANSMISSIONS:
        raise ValueError(f"transmission = {transmission!r}; allowed: {', '.join(TRANSMISSIONS)}")
    what = f"the journal orbit at {orbit.speed_rpm:g} rpm"
    settling, ig, lr = run_settings("bearing_noise", legacy, NOISE_KEYWORDS, {"long_run": SETTLE_LONG_RUN},
                                    settling=settling, integration=integration, long_run=long_run).values()
    if periodic:
        p = periodic_response(orbit, rtol=ig.rtol, tol=tol)
        if not p.success:
            raise NotPeriodicError(f"{what}: {p.message}")
        # periodic after the periods the shooting integrated; its "Poincare steps" are the residuals |Phi(y) - y|
        s = Settled(result=(0.0, p.state), settled_at=p.revolutions_integrated, periods=p.revolutions_integrated,
                    poincare_steps=np.array(p.residual_norms) / p.clearance, wall_time=p.wall_time)
    else:
        s = settle(orbit, tol=tol, confirm=settling.confirm, max_periods=settling.max_periods,
                   periods=settling.periods, what=what, integration=ig, long_run=lr)  # its tqdm bar, no print
    t1 = time.perf_counter()
    r = orbit.run(revolutions, recording=Recording(outputs_per_revolution=S, record=("pressure",)),
                  long_run=LongRun(progress=False), start=s.result, integration=ig)
    if r.touched_at is not None or not r.success:
        raise NotPeriodicError(f"{what}, analysis window: {r.message}")
    t_window = time.perf_counter() - t1
    N = revolutions * S
    if r.pressure.shape[0] != N + 1:
        raise RuntimeError(f"expected {N + 1} pressure samples over the window, got {r.pressure.shape[0]}")
    C = orbit.bearing.clearance
    closure = float(np.hypot(r.x[-1] - r.x[0], r.y[-1] - r.y[0]) / C)
    per_rev = s.wall_time / s.periods if s.periods else 0.0
    timings = dict(integration=s.wall_time, recording=t_window,
                   recording_overhead=max(0.0, t_window - per_rev * revolutions) if s.periods else float("nan"))
    grid = orbit.bearing.grid
    return analyse_pressure(r.pressure[:N], r.x[:N], r.y[:N], r.t[:N], orbit.speed_rpm, revolutions, harmonics,
                            transmission, angle_deg=np.degrees(grid.x.centres), z=grid.z.centres * orbit.bearing.radius,
                            timings=timings, settle_revolutions=s.periods, settled_at=s.settled_at,
                            poincare_steps=s.poincare_steps, window_closure=closure)
