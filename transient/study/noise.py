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
from transient.study.settle import Settled, settle


def default_samples_per_revolution(harmonics) -> int:
    """2 * harmonics + a margin: max(16, 4 * harmonics), even."""
    s = max(16, 4 * int(harmonics))
    return s + (s % 2)


def bearing_noise(orbit, revolutions=4, harmonics=5, *, settle_revolutions=None, max_settle_revolutions=60, tol=1e-4,
                  transmission="printed", method="ida", rtol=1e-6, samples_per_revolution=None,
                  chunk_revolutions=5, confirm=2, progress=False, periodic=True) -> BearingNoise:
    """Bearing noise of a :class:`~transient.models.journal.JournalOrbit` at its speed (module docstring).

    ``tol`` [C]: the distance from the periodic orbit accepted (default 1e-4 C, ~1 % of the 6000 rpm orbit
    amplitude): the shooting's error estimate (``periodic=True``), or the Poincare step below which the settling
    run counts as settled, ``confirm`` consecutive times (``periodic=False``; ``settle_revolutions`` = int skips
    the detection and settles for exactly that many). Raises :class:`~transient.analysis.periodic.NotPeriodicError`
    if there is no stable periodic orbit (past the onset of whirl: the shooting's dominant Floquet multiplier is
    outside the unit circle, or the settling run does not settle within ``max_settle_revolutions``) or the
    journal touches the bearing."""
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
    kw = dict(method=method, rtol=rtol)
    if periodic:
        p = periodic_response(orbit, rtol=rtol, tol=tol)
        if not p.success:
            raise NotPeriodicError(f"{what}: {p.message}")
        # periodic after the periods the shooting integrated; its "Poincare steps" are the residuals |Phi(y) - y|
        s = Settled(result=(0.0, p.state), settled_at=p.revolutions_integrated, periods=p.revolutions_integrated,
                    poincare_steps=np.array(p.residual_norms) / p.clearance, wall_time=p.wall_time)
    else:
        s = settle(orbit, tol=tol, confirm=confirm, max_periods=max_settle_revolutions, chunk_periods=chunk_revolutions,
                   periods=settle_revolutions, what=what, progress=progress, **kw)  # its tqdm bar, no print
    t1 = time.perf_counter()
    r = orbit.run(revolutions, outputs_per_revolution=S, record=("pressure",), start=s.result, progress=False, **kw)
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
