"""The EHL contacts' films in time on the one run driver (:mod:`transient.solvers.model_run`).

A contact's ``transient`` keeps what is its own -- the step solve (the FBNS Newton on one BDF2 step of its film
content: :class:`~transient.models.point.step_solve.FilmStep`,
:class:`~transient.models.roller.line_step.LineFilmStep`), its start, what it samples at an output -- and hands the
run to :class:`~transient.solvers.model_run.ModelRun`, as the journal orbit, the rotor system, the thrust pad and the
ball sequence do: outputs at equally spaced times, a progress bar in transit times, a checkpoint rewritten after each
tenth of the outputs and resumed bit for bit (``long_run=LongRun(checkpoint="run.npz", resume=True)``), Ctrl-C,
``stop(result_so_far)`` and the wall-clock budget.

The settings come as objects: ``integration=Integration(method="bdf2", rtol=1e-4)`` (the absolute tolerance on
the scaled pressure, content and approach is ``ATOL_PER_RTOL`` times ``rtol``, not a setting) and
``long_run=LongRun(...)``; the loose keywords of earlier releases (``rtol=``, ``method=``, ``time_budget=``) still
work for one release, with a ``DeprecationWarning`` naming the new spelling.
"""

from __future__ import annotations

import hashlib
import warnings
from dataclasses import fields, is_dataclass

import numpy as np

from transient.checks import check_range
from transient.solvers.integrate import Problem, Steps, check_method
from transient.solvers.model_run import ModelRun, RunParts
from transient.solvers.settings import Integration, LongRun, check_unused, keyword_table, requested_method, run_settings

#: The transients' relative tolerance when none is given.
TRANSIENT_RTOL = 1e-4
#: The absolute tolerance per unit of ``rtol`` on the scaled states (pressure / p_Hertz, content, approach / film
#: scale, all O(1)).
ATOL_PER_RTOL = 1e-2
#: The old loose keywords of a contact's ``transient`` and the settings they now belong in.
TRANSIENT_KEYWORDS = (keyword_table("integration", Integration, ("method", "rtol"))
                      | keyword_table("long_run", LongRun, ("time_budget",)))
#: The series every line and roller transient records at its outputs.
TRANSIENT_SERIES = ("h_central", "h_min", "p_max", "h0", "load")
#: The first step of every chunk, in transit times (the dry start's jump onto the film's constraints).
FIRST_STEP = 1e-3
#: The unit of the progress bar: a transit time (the run's scaled time is time over the transit time).
TRANSIT = "transit"


def transient_settings(owner: str, methods: tuple, default_method: str, integration, long_run,
                       legacy: dict) -> tuple[Integration, LongRun]:
    """The ``(Integration, LongRun)`` of a contact's ``transient``: the objects given, else built from the old
    keywords ``legacy`` over the contact's defaults (``default_method``, ``TRANSIENT_RTOL``); a method outside
    ``methods`` is refused before any work, naming ``owner``, and so is a setting the films do not use (``atol``
    among them: the run's is ``ATOL_PER_RTOL rtol``)."""
    check_method(owner, requested_method(integration, legacy, default_method), step_solve=True, among=methods)
    defaults = {"integration": dict(method=default_method, rtol=TRANSIENT_RTOL)}
    given = run_settings(owner, legacy, TRANSIENT_KEYWORDS, defaults, integration=integration, long_run=long_run)
    ig, lr = given["integration"], given["long_run"]
    check_method(owner, ig.method, step_solve=True, among=methods)
    check_range("rtol", ig.rtol, "-", 1e-12, 0.5)
    check_unused(owner, "integration", ig, ("atol", "formulation", "steps_per_revolution", "max_order",
                                            "linear_solver"))
    check_unused(owner, "long_run", lr, ("chunk_revolutions",))
    return ig, lr


def penalty_deprecated(owner: str, long_run: LongRun) -> None:
    """Warn that ``method="ida"`` of a line or roller transient -- the exit condition in penalty form, whose limit
    is ``steady(penalty=GAMMA)``, not the contact's ``steady()`` -- goes in the next release; it runs outside the
    run driver, so a ``long_run`` other than the default is refused, naming it."""
    warnings.warn(f"{owner}: method='ida' (the penalty form, whose limit is steady(penalty=...)) is deprecated and "
                  "will be removed in the next release; the default method='bdf2' integrates the film content, "
                  "whose limit is steady()", DeprecationWarning, stacklevel=3)
    check_unused(owner, "long_run", long_run, [f.name for f in fields(LongRun)])


def load_digest(ratio, tau_end: float, n_out: int) -> str:
    """A short digest of the load ratio ``ratio(tau)`` at a run's ``n_out`` output times on [0, ``tau_end``] (the
    load history, to key a checkpoint: a function has no other fingerprint)."""
    loads = np.array([ratio(tau) for tau in np.linspace(0.0, tau_end, n_out)])
    return hashlib.sha256(loads.tobytes()).hexdigest()[:16]


def contact_digest(contact) -> str:
    """A short digest of every number, string and array a contact holds (its parameters, to key a checkpoint)."""
    items = ({f.name: getattr(contact, f.name) for f in fields(contact)} if is_dataclass(contact)
             else dict(vars(contact)))
    h = hashlib.sha256()
    for name in sorted(items):
        v = items[name]
        if isinstance(v, (bool, int, float, str, tuple, type(None))):
            h.update(f"{name}={v!r};".encode())
        elif isinstance(v, np.ndarray) and v.dtype.kind in "biuf":
            h.update(name.encode() + np.ascontiguousarray(v, dtype=float).tobytes())
    return h.hexdigest()[:16]


def run_film(label: str, step_at, u0, tau_end: float, n_out: int, sample, series: tuple, result,
             ig: Integration, lr: LongRun, max_steps: int, key: dict):
    """Integrate a contact's film from ``u0`` at scaled time 0 to ``tau_end`` (transit times) by BDF2 on the step
    solve ``step_at(u, tau)`` (a fresh one at each chunk's start), ``n_out`` outputs equally spaced, each sampled
    by ``sample(tau, u) -> {name: value}`` (the names ``series``); ``result(arrays, last_state, stats, message)``
    builds the contact's result from the recorded arrays (``t`` in transit times). ``key``: what changes the run
    besides the start (keys the checkpoint)."""
    run = ModelRun.at_times(n_out - 1, lr)
    solver = dict(method="bdf2", rtol=ig.rtol, atol=ATOL_PER_RTOL * ig.rtol,
                  steps=Steps(first_step=FIRST_STEP, max_steps=max_steps))
    parts = RunParts(label=label, omega=1.0, revolution=1.0, unit=TRANSIT, status=lambda: "",
                     problem_at=lambda u, tau: Problem(y0=u, step_solve=step_at(u, tau), name=label),
                     solver=solver, series=series, sample=sample, journals=lambda u: [],
                     eccentricities=lambda r: [], touch_message=None,
                     result=lambda rec, stats, touched, message, tau: result(rec.arrays(), rec.last_y, stats, message),
                     key=dict(key, method=ig.method, rtol=ig.rtol, max_steps=max_steps, n_out=n_out, tau_end=tau_end))
    return run.go(parts, np.asarray(u0, float), 0.0, np.linspace(0.0, tau_end, n_out))
