"""Outputs and events of one solve, the same for every back end: :class:`Output` collects (or streams to an
observer) the states at the requested times, :class:`Events` keeps the event records, and :func:`step_events`
locates an event inside a step on the back end's interpolant (scipy, RK4; SUNDIALS locates its own)."""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from transient.solvers.integrate.guard import Guard
from transient.solvers.integrate.problem import Problem, Solution


class Output:
    """Collects (or streams to an observer) the states at the requested output times; every state
    is checked finite before anyone sees it."""

    def __init__(self, t_eval, n, store, observer, with_yp, guard):
        self.t_eval = t_eval
        self.k = 0
        self.store = store
        self.observer = observer
        self.guard = guard
        self.y = np.empty((t_eval.size, n)) if store else None
        self.yp = np.empty((t_eval.size, n)) if (store and with_yp) else None
        self.events: Events | None = None  # set by the backend if the problem has events

    @property
    def pending(self) -> float:
        return self.t_eval[self.k] if self.k < self.t_eval.size else np.inf

    def put(self, y, yp=None):
        self.guard.check_state(self.t_eval[self.k], y)
        if self.store:
            self.y[self.k] = y
            if self.yp is not None and yp is not None:
                self.yp[self.k] = yp
        if self.observer is not None:
            self.observer(self.t_eval[self.k], y)
        self.k += 1

    def result(self, **kw) -> Solution:
        k = self.k
        return Solution(t=self.t_eval[:k].copy(), y=None if self.y is None else self.y[:k],
                        yp=None if self.yp is None else self.yp[:k], **kw)


class Events:
    """Event bookkeeping shared by all methods: direction filter, terminal counts, records."""

    def __init__(self, problem: Problem, guard: Guard, poison: bool):
        self.p = problem
        self.guard = guard
        self.fn = guard.wrap(problem.events, "events", poison=poison, timed=False)
        self.t, self.y, self.i = [], [], []
        self.counts = np.zeros(problem.n_events, dtype=np.int64)
        self.buf = np.empty(problem.n_events)

    def values(self, t, y):
        self.fn(t, y, self.buf)
        return self.buf.copy()

    def crossed(self, g0, g1):
        """Indices of events whose sign change from g0 to g1 matches their direction."""
        out = []
        for i in range(self.p.n_events):
            d = self.p.event_direction[i]
            up = g0[i] < 0 <= g1[i]
            down = g0[i] > 0 >= g1[i]
            if (up and d >= 0) or (down and d <= 0):
                out.append(i)
        return out

    def record(self, t, y, idx) -> bool:
        """Record events idx at t; True if one of them is terminal."""
        stop = False
        if idx:
            self.guard.check_state(t, y, "state at an event")
        for i in idx:
            self.t.append(t)
            self.y.append(np.array(y, dtype=float))
            self.i.append(i)
            self.counts[i] += 1
            term = self.p.event_terminal[i]
            if term is True or (not isinstance(term, bool) and term and self.counts[i] >= term):
                stop = True
        return stop

    def fill(self, res: Solution):
        if self.t:
            res.t_events = np.array(self.t)
            res.y_events = np.array(self.y)
            res.i_events = np.array(self.i, dtype=np.int64)


def _locate(events, fn_y, ta, tb, ga, gb, idx):
    """Earliest root in (ta, tb] among the crossing events idx; fn_y(t) gives the state at t."""
    best_t, best = np.inf, []
    for i in idx:
        gi = lambda s: events.values(s, fn_y(s))[i]
        ti = tb if gb[i] == 0 else brentq(gi, ta, tb, xtol=1e-14 * max(1.0, abs(tb)), rtol=4 * np.finfo(float).eps)
        if ti < best_t - 1e-15:
            best_t, best = ti, [i]
        elif abs(ti - best_t) <= 1e-15:
            best.append(i)
    return best_t, best


def step_events(events, state_at, ta, tb, g_prev, y_b, out):
    """Events over the step (ta, tb]: locate the earliest crossing on the interpolant ``state_at(t)``,
    emit the outputs before it, record it. Returns (event values at tb, terminal event time or None)."""
    g_new = events.values(tb, y_b)
    idx = events.crossed(g_prev, g_new)
    if idx:
        te, which = _locate(events, state_at, ta, tb, g_prev, g_new, idx)
        while out.k < out.t_eval.size and out.pending <= te:
            out.put(state_at(out.pending))
        if events.record(te, state_at(te), which):
            return g_new, te
    return g_new, None
