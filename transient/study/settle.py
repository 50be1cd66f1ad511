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

The model needs ``run(periods, recording=Recording(outputs_per_revolution=), long_run=LongRun(chunk_revolutions=,
stop=, progress=), start=, ...)`` returning a result with ``final_state``/``final_time`` (e.g.
:class:`~transient.models.journal.JournalOrbit`). :class:`Settling` holds the detection's settings for a study
that settles a model on the way (:func:`~transient.study.noise.bearing_noise`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

from transient.analysis.periodic import NotPeriodicError, not_periodic_message, poincare_steps
from transient.results import StatusResult, quantity, result_type
from transient.solvers.settling import settled_stop, settles
from transient.checks import check_int
from transient.solvers.settings import LongRun, Recording, check_unused, run_settings


#: The loose keywords of :func:`settle` of earlier releases, now fields of ``long_run=LongRun(...)``.
SETTLE_KEYWORDS = {"chunk_periods": ("long_run", LongRun, "chunk_revolutions"),
                   "progress": ("long_run", LongRun, "progress")}
#: :func:`settle`'s own long-run defaults: chunks of 5 periods (the criterion is asked after each), no bar.
SETTLE_LONG_RUN = dict(chunk_revolutions=5, progress=False)


@dataclass(frozen=True)
class Settling:
    """How a study settles a model on the way (:func:`settle`): ``confirm`` consecutive Poincare steps below the
    tolerance count as settled (an integer in [1, 1000]); ``max_periods`` the most periods tried (an integer in
    [1, 1e7]); ``periods`` ``None`` (detect) or an integer >= 0: skip the detection and run exactly that many."""

    confirm: int = 2
    max_periods: int = 60
    periods: int | None = None

    def __post_init__(self):
        object.__setattr__(self, "confirm", check_int("confirm", self.confirm, "-", 1, 1000))
        object.__setattr__(self, "max_periods", check_int("max_periods", self.max_periods, "-", 1, 1e7))
        if self.periods is not None:
            object.__setattr__(self, "periods", check_int("periods", self.periods, "-", 0, 1e7))


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


def settle(model, *, tol: float = 1e-4, confirm: int = 2, max_periods: int = 60, periods: int | None = None,
           start=None, observable: Callable = journal_observable, criterion: Callable | None = None,
           outputs_per_period: int = 1, require: bool = True, what: str | None = None, **run_kwargs) -> Settled:
    """Run ``model`` until ``criterion(observable(result))`` says it has settled (module docstring).

    ``criterion`` defaults to ``confirm`` Poincare steps below ``tol``; ``outputs_per_period`` > 1 hands the
    observable the whole orbit (e.g. per-revolution shapes). ``periods`` = int skips the detection and runs
    exactly that many. ``run_kwargs`` go to ``model.run`` (``integration=``, ``y0=``, ...); its ``long_run``
    (:class:`~transient.solvers.settings.LongRun`) sets the chunk the criterion is asked after
    (``chunk_revolutions``, default 5 periods), the progress bar (default off) and a ``time_budget``. The loose
    keywords ``chunk_periods=`` and ``progress=`` are deprecated (``long_run=LongRun(chunk_revolutions=...,
    progress=...)``)."""
    legacy = {k: run_kwargs.pop(k) for k in SETTLE_KEYWORDS if k in run_kwargs}
    lr = run_settings("settle", legacy, SETTLE_KEYWORDS, {"long_run": SETTLE_LONG_RUN},
                      long_run=run_kwargs.pop("long_run", None))["long_run"]
    check_unused("settle", "long_run", lr, ("stop",))
    lr = replace(lr, chunk_revolutions=max(1, int(lr.chunk_revolutions or SETTLE_LONG_RUN["chunk_revolutions"])),
                 progress=bool(lr.progress))
    recording = replace(run_kwargs.pop("recording", None) or Recording(), outputs_per_revolution=int(outputs_per_period))
    what = what or f"the response of {type(model).__name__}"
    opp = int(outputs_per_period)
    t0 = time.perf_counter()
    if periods is not None:
        r = model.run(int(periods), recording=recording, long_run=replace(lr, chunk_revolutions=None), start=start,
                      **run_kwargs) if periods > 0 else None
        _no_event(r, what, require)
        steps = poincare_steps(journal_observable(r)[::opp]) if r is not None else np.zeros(0)
        return Settled(r, None, steps, int(periods), time.perf_counter() - t0, message=f"ran {int(periods)} periods")
    if int(max_periods) < 1:
        raise ValueError(f"max_periods = {max_periods!r} [-]; allowed: >= 1")
    poincare = criterion is None
    criterion = settles(tol, confirm) if poincare else criterion
    r = model.run(int(max_periods), recording=recording, long_run=replace(lr, stop=settled_stop(observable, criterion)),
                  start=start, **run_kwargs)
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
