"""Settle a periodically forced model onto its periodic response: one loop for every study.

A response forced with period T returns to the same point every period once it has settled, so its
once-per-period (Poincare) samples converge (:mod:`transient.solvers.settling`). :func:`settle` runs the
model period by period in chunks (the model's long-run driver, its progress bar with ``progress=True``),
asks an ``observable(result_so_far)`` and a ``criterion(observable) -> int | None`` after every chunk, and
stops as soon as the criterion returns the period at which the response settled. The default is the
Poincare criterion: ``confirm`` consecutive once-per-period steps of the journal centre below ``tol`` [C]
(:func:`~transient.solvers.settling.settles`). When that does not happen within ``max_periods`` (still
decaying, or not periodic: whirl past the threshold) or the run hits a terminal event (the journal touches
the bearing), it raises :class:`~transient.analysis.periodic.NotPeriodicError` with a diagnosis, or, with
``require=False``, returns the result flagged ``success=False``.

The model needs ``run(periods, outputs_per_revolution=, chunk_revolutions=, stop=, start=, progress=, ...)``
returning a result with ``final_state``/``final_time`` (e.g. :class:`~transient.models.journal.JournalOrbit`).
"""

from __future__ import annotations

import time
from typing import Callable

import numpy as np

from transient.analysis.periodic import NotPeriodicError, not_periodic_message, poincare_steps
from transient.results import StatusResult, quantity, result_type
from transient.solvers.settling import settled_stop, settles


@result_type
class Settled(StatusResult):
    """A settle run: the last result (continue from it with ``start=``), the period at which it settled
    (None if it did not), the Poincare steps of the journal centre [C], the periods integrated and the wall
    time [s]; ``success`` says whether the criterion was met."""

    time_axis = None
    result: object
    settled_at: int | None
    poincare_steps: np.ndarray = quantity("-")
    periods: int = 0
    wall_time: float = quantity("s", 0.0)


def journal_observable(result) -> np.ndarray:
    """Poincare samples of a journal orbit: the journal centre in units of the clearance."""
    return np.column_stack([result.x, result.y]) / result.clearance


def settle(model, *, tol: float = 1e-4, confirm: int = 2, max_periods: int = 60, chunk_periods: int = 5,
           periods: int | None = None, start=None, observable: Callable = journal_observable,
           criterion: Callable | None = None, outputs_per_period: int = 1, require: bool = True,
           progress: bool = False, what: str | None = None, **run_kwargs) -> Settled:
    """Run ``model`` until ``criterion(observable(result))`` says it has settled (module docstring).

    ``criterion`` defaults to ``confirm`` Poincare steps below ``tol``; ``outputs_per_period`` > 1 hands the
    observable the whole orbit (e.g. per-revolution shapes). ``periods`` = int skips the detection and runs
    exactly that many. ``run_kwargs`` go to ``model.run`` (method, rtol, y0, ...)."""
    what = what or f"the response of {type(model).__name__}"
    opp = int(outputs_per_period)
    t0 = time.perf_counter()
    if periods is not None:
        r = model.run(int(periods), outputs_per_revolution=opp, start=start, progress=progress,
                      **run_kwargs) if periods > 0 else None
        _no_event(r, what, require)
        steps = poincare_steps(journal_observable(r)[::opp]) if r is not None else np.zeros(0)
        return Settled(r, None, steps, int(periods), time.perf_counter() - t0, message=f"ran {int(periods)} periods")
    if int(max_periods) < 1:
        raise ValueError(f"max_periods = {max_periods!r} [-]; allowed: >= 1")
    poincare = criterion is None
    criterion = settles(tol, confirm) if poincare else criterion
    r = model.run(int(max_periods), outputs_per_revolution=opp, chunk_revolutions=max(1, int(chunk_periods)),
                  stop=settled_stop(observable, criterion), start=start, progress=progress, **run_kwargs)
    done = (len(r.t) - 1) // opp
    if not _no_event(r, what, require):
        return Settled(r, None, poincare_steps(journal_observable(r)[::opp]), done, time.perf_counter() - t0,
                       success=False, message=f"{what}: {r.message}")
    z = observable(r)
    k = criterion(z)
    if k is None:
        msg = not_periodic_message(z, tol, 1.0, what) if poincare else f"{what} did not settle in {done} periods"
        if require:
            raise NotPeriodicError(msg)
        return Settled(r, None, poincare_steps(journal_observable(r)[::opp]), done, time.perf_counter() - t0,
                       success=False, message=f"NOT settled: {msg}")
    return Settled(r, k, poincare_steps(journal_observable(r)[::opp]), done, time.perf_counter() - t0,
                   message=f"settled after {k} periods")


def _no_event(r, what, require) -> bool:
    """True if the run ended without a terminal event or failure; else raise (``require``) or False."""
    if r is not None and (getattr(r, "touched_at", None) is not None or not r.success):
        if require:
            raise NotPeriodicError(f"{what}: {r.message}")
        return False
    return True
