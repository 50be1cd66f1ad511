"""Settle a periodically forced model onto its periodic response: one protocol for every model.

A response forced with period T returns to the same point every period once it has settled, so its
once-per-period (Poincare) samples converge (:mod:`transient.analysis.periodic`). :func:`settle` runs the
model period by period (in chunks, nothing recorded but the Poincare samples) and stops as soon as
``confirm`` consecutive Poincare steps are below ``tol``; it raises
:class:`~transient.analysis.periodic.NotPeriodicError` with a diagnosis when that does not happen within
``max_periods`` (still decaying, or not periodic: whirl past the threshold) or when the run hits a
terminal event (the journal touches the bearing).

The model needs ``run(periods, outputs_per_revolution=1, chunk_revolutions=, stop=, start=, ...)``
returning a result with ``final_state``/``final_time`` (e.g. :class:`~transient.models.journal.JournalOrbit`)
and an ``observable(result) -> (n, d)`` array of the Poincare samples in the units of ``tol``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from transient.analysis.periodic import NotPeriodicError, find_settled, not_periodic_message, poincare_steps


@dataclass
class Settled:
    """A settled run: the last result (continue from it with ``start=``), where it settled, the Poincare
    steps, the periods integrated and the wall time [s]."""

    result: object
    settled_at: int | None
    poincare_steps: np.ndarray
    periods: int
    wall_time: float


def journal_observable(result) -> np.ndarray:
    """Poincare samples of a journal orbit: the journal centre in units of the clearance."""
    return np.column_stack([result.x, result.y]) / result.clearance


def settle(model, *, tol: float = 1e-4, confirm: int = 2, max_periods: int = 60, chunk_periods: int = 5,
           periods: int | None = None, start=None, observable=journal_observable, what: str | None = None,
           **run_kwargs) -> Settled:
    """Run ``model`` until its Poincare samples settle to ``tol`` (module docstring).

    ``periods`` = int skips the detection and runs exactly that many. ``run_kwargs`` go to ``model.run``
    (method, rtol, ...)."""
    what = what or f"the response of {type(model).__name__}"
    t0 = time.perf_counter()
    if periods is not None:
        r = model.run(int(periods), outputs_per_revolution=1, start=start, **run_kwargs) if periods > 0 else None
        _no_event(r, what)
        z = observable(r) if r is not None else np.zeros((0, 2))
        return Settled(r, None, poincare_steps(z), int(periods), time.perf_counter() - t0)
    if int(max_periods) < 1:
        raise ValueError(f"max_periods = {max_periods!r} [-]; allowed: >= 1")

    def settled(partial):
        k = find_settled(observable(partial), tol, 1.0, confirm)
        return f"settled to {tol:g} after {k} periods" if k is not None else None

    r = model.run(int(max_periods), outputs_per_revolution=1, chunk_revolutions=max(1, int(chunk_periods)),
                  stop=settled, start=start, progress=False, **run_kwargs)
    _no_event(r, what)
    z = observable(r)
    k = find_settled(z, tol, 1.0, confirm)
    if k is None:
        raise NotPeriodicError(not_periodic_message(z, tol, 1.0, what))
    return Settled(r, k, poincare_steps(z), len(z) - 1, time.perf_counter() - t0)


def _no_event(r, what):
    if r is not None and (getattr(r, "touched_at", None) is not None or not r.success):
        raise NotPeriodicError(f"{what}: {r.message}")
