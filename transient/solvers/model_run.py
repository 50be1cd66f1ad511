"""One run for every model in the time domain: the start, the memory check, the recorder, the long run, the end.

A model's ``run`` keeps what is its own -- its state layout (the run's, e.g. the film content, and the results',
the universal variable), its outputs (what it samples at an output time), its problem and its result -- and hands
the rest to :class:`ModelRun`, the same for the journal orbit, the rotor system and the thrust pad's descent:

* before anything is built (:class:`ModelRun`): the run against one output interval, the touch gap, the chunk
  (default the whole run, 10 revolutions with a checkpoint; a model without a shaft, :meth:`ModelRun.at_times`:
  a tenth of its outputs with a checkpoint); :func:`check_run_memory`: the memory the run will need,
  refused naming the grid when the model and its solver alone do not fit, else the run's length and recordings;
* the start (:func:`start_point`): a previous result of the model (its final state and time, so a forcing keeps
  its phase) or ``(t [s], state)``; :meth:`ModelRun.check_state`: its size, finite, every journal inside its
  clearance;
* :meth:`ModelRun.go`: the outputs kept by a :class:`Recorder` (the model's samples, streamed, never the state),
  the long run on :func:`~transient.solvers.longrun.run_long` (chunks, progress bar, a checkpoint keyed on the
  model's parameters, its settings, the touch gap, the chunk and the start, resumed bit for bit, Ctrl-C, time
  budget, and ``stop(result_so_far)``, the settle loops' hook), the terminal event (``success=False``,
  ``touched_at``, the model's message) and a run whose journal reached the wall with the event off
  (:func:`wall_crossing`), which is no success either.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from transient.checks import check_memory, check_range, memory_limit
from transient.solvers.integrate import Stats
from transient.solvers.longrun import Display, run_long
from transient.solvers.settings import LongRun

#: chunk length [rev] of a checkpointed run that does not choose one
CHECKPOINT_CHUNK_REVOLUTIONS = 10.0
#: chunks of a checkpointed run of a model without a shaft (:meth:`ModelRun.at_times`)
CHECKPOINT_CHUNKS = 10


def check_run_memory(what: str, parts: dict, grid_advice: str, run_advice: str) -> None:
    """Refuse (one line, :class:`~transient.checks.MemoryLimitError`) a run whose memory ``parts`` (bytes by part,
    ``recordings`` the outputs) exceed the machine's share, advising ``grid_advice`` when the model and its solver
    alone do not fit, else ``run_advice`` (the run's length and recordings)."""
    model = sum(v for k, v in parts.items() if k != "recordings")
    check_memory(what, parts, grid_advice if model > memory_limit() else run_advice)


def state_array(y) -> np.ndarray:
    """A user's initial state as a float array (a one-line error naming it otherwise)."""
    if isinstance(y, (str, bytes)):
        raise ValueError(f"the initial state must be an array of numbers, got {y!r}")
    try:
        return np.array(y, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"the initial state must be an array of numbers, got {type(y).__name__}") from None


def start_point(start, result_type) -> tuple:
    """``(t [s], state)`` of a run's ``start``: ``(0, None)`` for none (the model's own start), a previous result of
    ``result_type`` (its ``final_time`` and ``final_state``) or a pair ``(t [s], state)``."""
    if start is None:
        return 0.0, None
    if isinstance(start, result_type):
        return float(start.final_time), state_array(start.final_state)
    try:
        t, y = start
    except (TypeError, ValueError):
        raise ValueError(f"start = {type(start).__name__}; allowed: None, a {result_type.__name__} or "
                         "(t [s], state)") from None
    return float(t), state_array(y)


def wall_crossing(t, eps, limit) -> str:
    """Where a run's journal reached ``limit`` (e/C = 1, less any boundary layers) or beyond -- a negative film,
    no result (the touch event, ``touch_gap`` > 0, stops a run before it): "" if it never did, else a phrase with
    the first output time [s] there and the largest e/C."""
    over = np.flatnonzero(np.asarray(eps) >= limit)
    if over.size == 0:
        return ""
    return (f"reaches e/C = {float(np.max(eps)):.4f} from t = {float(t[over[0]]):.6g} s (allowed: below "
            f"{limit:.4g}): a negative film, not a result")


class Recorder:
    """Keeps a model's outputs at the output times, streamed, never the state: ``t`` [s] (the run's time tau over
    ``omega``) and the ``series`` the model's ``sample(tau, y) -> {name: row}`` returns (``y`` in the results'
    layout, ``universal(y)`` of the run's); a ``sparse`` series (sampled only where the model chooses, e.g. fields
    from a revolution on) with its own times ``<name>_t`` [s], stored in float32. An output at or before the last
    one (a chunk starts where the previous one ended) is not kept again. ``carry``: the model's own state beside the
    integrator's (e.g. a thermal film's temperatures), an object whose ``arrays()`` (at a chunk's end) and
    ``restore(arrays)`` a checkpoint keeps."""

    def __init__(self, sample: Callable, omega: float, series, sparse=(), universal: Callable | None = None,
                 carry=None):
        self.sample, self.omega, self.sparse = sample, float(omega), tuple(sparse)
        self.universal, self.carry = universal, carry
        self.t = []
        self.series = {k: [] for k in series}
        self.sparse_t = {k: [] for k in self.sparse if k in self.series}
        self.last_y = None
        self.last_tau = -np.inf

    def observe(self, tau, y):
        y = np.array(y) if self.universal is None else self.universal(y)
        self.last_y = y
        if tau <= self.last_tau:
            return
        self.last_tau = tau
        self.t.append(tau / self.omega)
        for k, v in self.sample(tau, y).items():
            self.series[k].append(v)
            if k in self.sparse_t:
                self.sparse_t[k].append(tau / self.omega)

    def times(self) -> np.ndarray:
        """The output times held, in the run's time tau (checked against a checkpoint's count)."""
        return np.array(self.t) * self.omega

    def arrays(self) -> dict:
        """Everything recorded, as plain arrays (checkpoints, results)."""
        out = dict(t=np.array(self.t), last_tau=np.array(self.last_tau))
        for k, v in self.series.items():
            out[k] = np.array(v, dtype=np.float32 if k in self.sparse else float)
        for k, v in self.sparse_t.items():
            out[k + "_t"] = np.array(v)
        if self.carry is not None:
            out.update({"carry." + k: np.asarray(v) for k, v in self.carry.arrays().items()})
        return out

    def restore(self, a: dict):
        """Take the arrays of a checkpoint; ``ValueError`` if they do not fit each other."""
        rows = len(a["t"])
        if np.ndim(a["t"]) != 1 or not np.all(np.isfinite(a["t"])) or np.any(np.diff(a["t"]) <= 0):
            raise ValueError("its times are not finite and increasing")
        for k in self.series:
            want = len(a[k + "_t"]) if k in self.sparse_t else rows
            if len(a[k]) != want:
                raise ValueError(f"{k} has {len(a[k])} rows, {'its times' if k in self.sparse_t else 't'} {want}")
        if rows and not np.isclose(float(a["last_tau"]), float(a["t"][-1]) * self.omega, rtol=1e-12):
            raise ValueError("its last output time does not match its last row")
        self.t, self.last_tau = list(a["t"]), float(a["last_tau"])
        for k in self.series:
            self.series[k] = list(a[k])
        for k in self.sparse_t:
            self.sparse_t[k] = list(a[k + "_t"])
        if self.carry is not None:
            self.carry.restore({k[6:]: v for k, v in a.items() if k.startswith("carry.")})


@dataclass
class RunParts:
    """What is a model's own in a run (:meth:`ModelRun.go`).

    ``label`` names the run in the progress bar and messages; ``omega`` [rad/s]: the run's time is
    ``tau = omega t``; ``revolution``: one shaft revolution in tau (the bar's unit); ``problem_at(y, tau)`` the
    :class:`~transient.solvers.integrate.Problem` at a chunk's start (``y`` in the run's layout); ``solver`` the
    keywords of :func:`~transient.solvers.integrate.solve`; ``series``, ``sparse``, ``sample``: the outputs
    (:class:`Recorder`); ``journals(y) -> [(where, e/C, limit)]`` each journal's place (``where`` e.g. "journal at
    bearing node 2") and the e/C it must stay below, ``y`` in the results' layout; ``eccentricities(result) ->
    [(where, e/C at the outputs, limit)]`` the same over a result; ``touch_message(tau, y)`` the message of the
    terminal event (``y`` in the run's layout); ``result(recorder, stats, touched_at, message, tau_end)`` the
    model's result (its ``final_state`` is ``recorder.last_y``); ``to_run``/``universal``: the maps between the
    results' layout and the run's (``None``: the same). ``unit`` names ``revolution`` in the bar and messages (a
    model without a shaft: ``unit="s"``, ``revolution=1``); ``status()`` the bar's short status (``None``: each
    journal's e/C); ``carry`` the model's own state a checkpoint keeps beside the integrator's (:class:`Recorder`).
    A model whose run is a map between output times hands ``advance`` (the ``advance`` of
    :func:`~transient.solvers.longrun.run_long`'s ``solver``) and no problem; ``event_success``: its terminal event
    ends the run as planned (the ball sequence's periodic state), not as a failure."""

    label: str
    omega: float
    revolution: float
    problem_at: Callable
    solver: dict
    series: tuple
    sample: Callable
    journals: Callable
    eccentricities: Callable
    touch_message: Callable
    result: Callable
    sparse: tuple = ()
    to_run: Callable | None = None
    universal: Callable | None = None
    key: dict = field(default_factory=dict)
    unit: str = "rev"
    status: Callable | None = None
    carry: object | None = None
    advance: Callable | None = None
    event_success: bool = False


class ModelRun:
    """One run of a model in the time domain (module docstring): created with the run's length and settings,
    before the model builds anything, it checks them; :meth:`go` runs it."""

    def __init__(self, revolutions: float, outputs_per_revolution: int, long_run: LongRun, touch_gap: float):
        opr = outputs_per_revolution
        if revolutions * opr < 1.0 - 1e-9:
            raise ValueError(f"revolutions = {revolutions!r} [rev] is less than one output interval; allowed: >= "
                             f"{1 / opr:g} rev at outputs_per_revolution = {opr}")
        self.touch_gap = check_range("touch_gap", touch_gap, "-", 0.0, 1.0, high_open=True,
                                     why="(0 turns touch detection off)")
        chunk = long_run.chunk_revolutions
        if chunk is None:
            chunk = CHECKPOINT_CHUNK_REVOLUTIONS if long_run.checkpoint else revolutions
        self.chunk_revolutions = check_range("chunk_revolutions", chunk, "rev", 1.0 / opr, np.inf,
                                             why="(at least one output interval)")
        self.long_run = long_run
        self.n_outputs = max(1, int(round(revolutions * opr)))
        self.chunk_outputs = max(1, int(round(self.chunk_revolutions * opr)))

    @classmethod
    def at_times(cls, n_outputs: int, long_run: LongRun) -> "ModelRun":
        """A run over ``n_outputs`` output intervals of a model without a shaft (no revolutions, no journal to
        touch): the whole run in one chunk, or ``CHECKPOINT_CHUNKS`` chunks with a checkpoint (the model refuses
        ``long_run.chunk_revolutions``)."""
        run = cls.__new__(cls)
        run.touch_gap, run.chunk_revolutions, run.long_run = 0.0, None, long_run
        run.n_outputs = int(n_outputs)
        run.chunk_outputs = -(-run.n_outputs // CHECKPOINT_CHUNKS) if long_run.checkpoint else run.n_outputs
        return run

    @staticmethod
    def check_state(y, n: int, what: str, journals: Callable) -> np.ndarray:
        """``y`` if it is a finite state of ``n`` numbers (``what`` has them) with every journal of ``journals(y)``
        (``[(where, e/C, limit)]``, :class:`RunParts`) inside its clearance, else a one-line ``ValueError``."""
        if y.shape != (n,):
            raise ValueError(f"the initial state has shape {y.shape}; this {what} has {n} states")
        if not np.all(np.isfinite(y)):
            raise ValueError(f"the initial state has a non-finite entry at index {int(np.argmin(np.isfinite(y)))}")
        for where, e, limit in journals(y):
            if e >= limit:
                raise ValueError(f"the initial state: the {where} is outside the clearance: e/C = {e:.4g} [-]; "
                                 f"allowed: [0, {limit:.4g})")
        return y

    def go(self, parts: RunParts, y, tau0: float, dt_out):
        """Run from ``y`` (results' layout) at ``tau0`` over the outputs every ``dt_out`` (in tau; or at the
        output times ``dt_out``, an array from ``tau0``); the model's result, ``success`` False after a terminal
        event, a failure or a journal through the wall."""
        rec = Recorder(parts.sample, parts.omega, parts.series, parts.sparse, parts.universal, parts.carry)
        rec.last_y = y
        lr = self.long_run
        if lr.stop is not None:
            lr = replace(lr, stop=lambda r: self.long_run.stop(parts.result(r, Stats(), None, "", r.last_tau)))
        key = dict(parts.key, touch_gap=self.touch_gap, chunk_revolutions=self.chunk_revolutions,
                   start_time=tau0 / parts.omega,
                   start_state=hashlib.sha256(np.ascontiguousarray(y).tobytes()).hexdigest()[:16])
        status = parts.status or (lambda: "e/C = " + ", ".join(f"{e:.4f}" for _, e, _ in parts.journals(rec.last_y)))
        solver = parts.solver if parts.advance is None else dict(parts.solver, advance=parts.advance)
        out = run_long(parts.problem_at, y if parts.to_run is None else parts.to_run(y), tau0, dt_out,
                       self.n_outputs, rec, solver=solver, long_run=lr, chunk_outputs=self.chunk_outputs,
                       key=key, display=Display(parts.label, (parts.unit, parts.revolution), status))
        touched, message, success = None, out.message, out.success
        if out.event is not None:
            touched = out.event[0] / parts.omega
            message, success = parts.touch_message(*out.event), parts.event_success
        # the driver's last state, also when a finished checkpoint is resumed and nothing was left to run
        rec.last_y = np.array(out.y) if parts.universal is None else parts.universal(out.y)
        r = parts.result(rec, out.stats, touched, message, out.t)
        for where, eps, limit in parts.eccentricities(r) if out.event is None else ():
            through = wall_crossing(r.t, eps, limit)
            if through:
                success, r.message = False, (f"the {where} {through} (touch_gap > 0 stops a run there)"
                                             + ("" if out.success else f"; then {out.message}"))
                break
        r.success = success and r.success  # a model's result may fail on its own (e.g. a pad whose gap closed)
        return r
