"""The ball-pass sequence as a map from pass to pass, in the form the one run driver takes
(:mod:`transient.solvers.model_run`): the run's "time" is the pass number, its output times the passes, and its
state one fixed-size array that holds everything the next pass needs, so a sequence can be checkpointed, resumed
bit for bit and continued from a result.

The state (:class:`PassState`) before pass ``n``:

* the row of pass ``n`` (what the ball meets and what it makes of it): inlet film ``h_in``, central and minimum
  film, meniscus ``m``, regime, the oil on the half track, the outlet film of the previous pass;
* the bookkeeping of the sequence: passes in a row within ``periodic_tol`` (``calm``), the pass where a periodic
  state was found, the meniscus root it was found from (:class:`~transient.models.ball.bearing._Meniscus` starts
  its Newton there; 0: none), the counts of the front mesh's redesigns and freezes;
* the scales the track is in (``a'`` [m], ``h_inf`` [m]: a start from a result under other scales is refused);
* the track: a uniform grid's films, or the front mesh's contents with what rebuilds the mesh -- the precursor it
  was designed for (:meth:`~transient.models.ball.track.FrontTrack._mesh_for`), the front position it was
  redesigned at (0: not redesigned) and the front ``s`` -- padded to the capacity of the finest mesh the
  precursor can ask for (:func:`front_capacity`).

One step of the map (:meth:`PassMap.advance`): the ball pass (the outlet film on the band, the ridges), the
levelling until the next ball, the row of the next pass. Each call of :meth:`PassMap.advance` (a chunk of the
run) starts from the state alone -- the meniscus and the numerical contact's caches are emptied -- so a run
resumed from a checkpoint repeats the uninterrupted one bit for bit.
"""

from __future__ import annotations

import time
from functools import lru_cache

import numpy as np

from transient.physics import film_formulas as hd
from transient.models.ball.front import FrontMesh
from transient.models.ball.numerical_film import LayerTooThin
from transient.solvers.integrate import Solution, Stats

#: the regimes of a pass, by their code in the state
REGIMES = ("fully flooded", "starved", "parched")
#: the header of the state: one number each, then the track
HEADER = ("h_in", "h_c", "h_min", "m", "regime", "volume", "h_out_prev", "calm", "periodic", "n_periodic",
          "meniscus", "n_freeze", "n_remesh", "a_p", "h_ref")
_I = {name: i for i, name in enumerate(HEADER)}
#: the front track's own numbers before its contents: design precursor, redesign position, front, cell count
FRONT_HEADER = ("eps", "design", "s", "n")
#: the recorded series of one pass (the state's header fields of the row)
SERIES = ("h_in", "h_c", "h_min", "m", "regime", "volume")


def front_capacity(track) -> int:
    """The most cells a front mesh of ``track`` (:class:`~transient.models.ball.track.FrontTrack`) can have: the
    mesh for the thinnest precursor that still gives increasing faces (the cluster grows as the log of the
    precursor: found by bisection in its logarithm), redesigned at front positions down to a twentieth of the
    band, with a margin of 5 % and 16 cells."""
    return _capacity(track.X, track.refine, tuple(sorted(track.mesh_options.items())))


@lru_cache(maxsize=64)
def _capacity(length, refine, options) -> int:
    def mesh(log_eps):
        try:
            return FrontMesh(length, min(0.5 * 10.0 ** log_eps, 0.05), refine=refine, **dict(options))
        except ValueError:
            return None

    ok, bad = -1.0, -300.0
    finest = mesh(ok)
    for _ in range(24):
        mid = 0.5 * (ok + bad)
        m = mesh(mid)
        if m is None:
            bad = mid
        else:
            ok, finest = mid, m
    most = finest.n
    for s0 in (0.9, 0.6, 0.3, 0.1, 0.05):
        try:
            most = max(most, finest.redesign(s0).n)
        except ValueError:
            pass
    return int(1.05 * most) + 16


class PassMap:
    """The sequence's map from pass to pass (module docstring) on ``track`` (a started
    :class:`~transient.models.ball.track.FrontTrack` or :class:`~transient.models.ball.track.UniformTrack`).

    ``film(h_in, n, meniscus) -> (h_c, h_min, m)`` [m, m, -] the film of pass ``n`` at the inlet film ``h_in``
    [m] (raises :class:`LayerTooThin` to end the sequence), ``films`` the numerical contact's cache holder or
    ``None``; ``m_c`` the critical meniscus; ``scales`` = ``(a_p [m], h_ref [m])``; ``floor`` [m] the least
    outlet film; ``ridge`` = ``(fraction, width [a'])``; ``tb_hat`` the time between balls in levelling times;
    ``integration`` the levelling's settings; ``periodic`` = ``(periodic_tol, stop_at_periodic)``: the periodic
    state (module docstring of :mod:`transient.models.ball.bearing`); ``x_out`` [a'] where profiles are sampled
    (``None``: none); ``meniscus()`` a new meniscus solver."""

    def __init__(self, track, film, films, m_c, scales, floor, ridge, tb_hat, integration, periodic, x_out,
                 meniscus):
        self.track, self.film, self.films, self.m_c = track, film, films, m_c
        (self.a_p, self.h_ref), self.floor = scales, floor
        self.ridge, self.tb_hat, self.ig = ridge, tb_hat, integration
        (self.periodic_tol, self.stop_at_periodic), self.x_out = periodic, x_out
        self.new_meniscus = meniscus
        self.front = track.kind == "front"
        self.capacity = front_capacity(track) if self.front else track.grid.n
        self.size = len(HEADER) + (len(FRONT_HEADER) + self.capacity if self.front else self.capacity)
        self.integrate_time = 0.0
        self.stopped = ""
        self.eps = 1e-3   # the precursor the front track's mesh was designed for (FrontTrack.start)
        self._meshes = {}

    # the state ------------------------------------------------------------------------------------
    def first(self) -> np.ndarray:
        """The state before the first pass: the started track and the row of pass 0."""
        head = np.zeros(len(HEADER))
        head[_I["n_periodic"]] = -1.0
        head[_I["a_p"]], head[_I["h_ref"]] = self.a_p, self.h_ref
        meniscus = self.new_meniscus()
        self._row(head, 0, meniscus)
        return self._encode(head, meniscus)

    def restart(self, y: np.ndarray) -> np.ndarray:
        """A previous run's final state as the start of a new sequence (its periodic flag cleared: the new sequence
        finds its own); ``ValueError`` if it does not fit this sequence."""
        if y.shape != (self.size,):
            raise ValueError(f"start: a state of {y.size} numbers; this sequence's track has {self.size} (a start "
                             "continues a sequence with the same track settings)")
        for name, mine, unit in (("a_p", self.a_p, "m"), ("h_ref", self.h_ref, "m")):
            if y[_I[name]] != mine:
                what = "contact half-width a'" if name == "a_p" else "ambient film"
                raise ValueError(f"start: a sequence whose track is in units of the {what} {y[_I[name]]:.6g} {unit}; "
                                 f"this one has {mine:.6g} {unit} (same load and ambient film needed)")
        y = np.array(y, dtype=float)
        y[_I["periodic"]], y[_I["n_periodic"]] = 0.0, -1.0
        self._decode(y)   # checks the track's part
        return y

    def _encode(self, head, meniscus) -> np.ndarray:
        head[_I["meniscus"]] = 0.0 if meniscus.last is None else meniscus.last
        tr = self.track
        if not self.front:
            return np.concatenate([head, tr.h])
        n = tr.c.size
        if n > self.capacity:
            raise RuntimeError(f"the front mesh has {n} cells, more than the state holds ({self.capacity}): "
                               f"precursor {self.eps:.3g} h_inf")
        design = 0.0 if tr.mesh.s0 == 1.0 else tr.mesh.s0   # a redesign is at a front below 1/3
        out = np.zeros(self.size)
        out[:len(HEADER)] = head
        out[len(HEADER):len(HEADER) + 4] = (self.eps, design, tr.s, n)
        out[len(HEADER) + 4:len(HEADER) + 4 + n] = tr.c
        return out

    def _base(self, eps):
        return self.track._mesh_for(eps)

    def _decode(self, y: np.ndarray) -> np.ndarray:
        """Set the track from ``y``; the header (a copy)."""
        head = np.array(y[:len(HEADER)])
        tr = self.track
        if not self.front:
            tr.h = np.array(y[len(HEADER):])
            return head
        eps, design, s, n = y[len(HEADER):len(HEADER) + 4]
        if not (eps > 0 and n == int(n) and 1 <= n <= self.capacity):
            raise ValueError(f"start: not a front track's state (precursor {eps!r}, {n!r} cells)")
        base = self._base(float(eps))
        if design == 0.0:
            mesh = base
        else:
            key = (float(eps), float(design))
            if key not in self._meshes:
                if len(self._meshes) > 64:
                    self._meshes.clear()
                self._meshes[key] = base.redesign(float(design))
            mesh = self._meshes[key]
        if mesh.n != int(n):
            raise ValueError(f"start: the front track's state holds {int(n)} cells, its mesh has {mesh.n}")
        self.eps = float(eps)
        tr.mesh, tr.s, tr.c = mesh, float(s), np.array(y[len(HEADER) + 4:len(HEADER) + 4 + int(n)])
        return head

    # one pass ---------------------------------------------------------------------------------------
    def _row(self, head, n: int, meniscus):
        """The row of pass ``n`` into ``head`` from the track as it is: inlet film, films, regime, periodic count."""
        tr, h_ref = self.track, self.h_ref
        volume = tr.volume() * h_ref * self.a_p
        h_in = tr.inlet() * h_ref
        hc, hm, m = self.film(h_in, n, meniscus)
        h_prev = head[_I["h_in"]]
        if m >= self.m_c:
            regime = 0
        elif (h_in - head[_I["h_out_prev"]] if n > 0 else h_in) >= hc:
            regime = 1
        else:
            regime = 2
        calm = head[_I["calm"]]
        calm = calm + 1 if n > 0 and abs(h_in - h_prev) <= self.periodic_tol * max(h_in, 1e-300) else 0.0
        head[[_I[k] for k in ("h_in", "h_c", "h_min", "m", "regime", "volume", "calm")]] = (
            h_in, hc, hm, m, regime, volume, calm)
        if calm >= 3 and head[_I["periodic"]] == 0:
            head[_I["periodic"]], head[_I["n_periodic"]] = 1.0, n

    def outlet(self, h_c: float) -> float:
        """The film a pass of central film ``h_c`` [m] leaves on the track [m]."""
        return max(0.5 * h_c, self.floor)

    def ends(self, y) -> bool:
        """Whether the sequence ends at the state ``y`` (its periodic state found, with ``stop_at_periodic``)."""
        return bool(self.stop_at_periodic and y[_I["periodic"]] == 1 and y[_I["n_periodic"]] >= 0)

    def advance(self, y, passes, observer, time_budget) -> Solution:
        """The map over the passes ``passes`` (output times, the first that of ``y``): each step the ball pass,
        the levelling, the next row, handed to ``observer(pass, state)``. A periodic state that ends the sequence
        is a terminal event at its pass; a layer the numerical contact cannot carry, a failed levelling or the time
        budget end the chunk with ``success=False``."""
        wall0 = time.perf_counter()
        head = self._decode(y)
        meniscus = self.new_meniscus()
        meniscus.last = float(head[_I["meniscus"]]) or None
        if self.films is not None:
            self.films.cache.clear()
        counts = {"n_steps": 0, "n_rhs": 0, "n_jac": 0}
        observer(passes[0], y)
        ok, message, events = True, "reached the final time", ()
        fraction, width = self.ridge
        for k in range(len(passes) - 1):
            if self.ends(y):
                events = ((passes[k], y),)
                message = f"periodic steady state at pass {int(passes[k])}"
                break
            if time_budget is not None and time.perf_counter() - wall0 > time_budget:
                ok, message = False, f"time budget of {time_budget:g} s used up at pass {int(passes[k])}"
                break
            n = int(passes[k])
            h_out = self.outlet(head[_I["h_c"]])
            if not h_out > 0:
                raise RuntimeError(f"pass {n}: the contact left no film (h_in = {head[_I['h_in']]:.3g} m); the "
                                   "precursor must be > 0")
            self.track.ball_pass(h_out / self.h_ref, fraction, width)
            self.eps = h_out / self.h_ref
            t0 = time.perf_counter()
            before = {key: counts.get(key, 0) for key in ("n_freeze", "n_remesh")}
            try:
                self.track.relax(self.tb_hat, counts, method=self.ig.method, rtol=self.ig.rtol, atol=self.ig.atol,
                                 linear_solver=self.ig.linear_solver, dt=self.ig.dt)
            except RuntimeError as e:
                raise RuntimeError(f"levelling after pass {n}: {e}") from None
            self.integrate_time += time.perf_counter() - t0
            for key, i in (("n_freeze", _I["n_freeze"]), ("n_remesh", _I["n_remesh"])):
                head[i] += counts.get(key, 0) - before[key]
            head[_I["h_out_prev"]] = h_out
            try:
                self._row(head, n + 1, meniscus)
            except LayerTooThin as e:
                ok, message = False, f"stopped: {e}"
                self.stopped = message
                break
            y = self._encode(head, meniscus)
            observer(passes[k + 1], y)
        else:
            if self.ends(y):
                events = ((passes[-1], y),)
                message = f"periodic steady state at pass {int(passes[-1])}"
        stats = Stats(n_steps=counts["n_steps"], n_rhs=counts["n_rhs"], n_jac=counts["n_jac"])
        te = np.array([e[0] for e in events], dtype=float)
        ye = np.array([e[1] for e in events]) if events else np.zeros((0, 0))
        return Solution(t=np.asarray(passes, dtype=float), y=None, yp=None, success=ok, message=message,
                        method=self.ig.method, stats=stats, t_events=te, y_events=ye)

    # what a run records -----------------------------------------------------------------------------
    def sample(self, tau, y) -> dict:
        """The recorded row of the pass whose state is ``y`` (the track's profile [m] at ``x_out`` too, when
        profiles are recorded: the track is ``y``'s while it is observed)."""
        row = {k: float(y[_I[k]]) for k in SERIES}
        if self.x_out is not None:
            row["profile"] = self.track.profile(self.x_out) * self.h_ref
        return row

    @staticmethod
    def header(y, name: str) -> float:
        return float(y[_I[name]])


def formula_film(flooded, contact):
    """``film(h_in, n, meniscus) -> (h_c, h_min, m)`` of Hamrock-Dowson's starvation law (the paper's)."""

    def film(h_in, n, meniscus):
        m = meniscus(h_in)
        return (hd.starved_central_film(flooded.H_c, m, flooded.m_c) * contact.rx,
                hd.starved_minimum_film(flooded.H_min, m, flooded.m_star) * contact.rx, m)

    return film


def numerical_film(films):
    """``film(h_in, n, meniscus) -> (h_c, h_min, m)`` of the numerical starved point contact
    (:class:`~transient.models.ball.numerical_film.NumericalFilms`)."""

    def film(h_in, n, meniscus):
        m = meniscus(h_in)
        hc, hm = films(h_in, n)
        return hc, hm, m

    return film
