"""The rotor system's content formulation for ``RotorBearingSystem.run(method="bdf2")``: the state maps, the
Newton pattern and the :class:`~transient.solvers.integrate.bdf2.Bdf2Model` of
:mod:`transient.models.rotor.content_newton` for a :class:`~transient.models.rotor.model.SystemDAE`.

The Newton pattern is the system's without the entries that are zero by construction (a groove cell's couplings,
:func:`~transient.models.journal.content_newton.decoupled_pattern`): the films are then separate blocks of the
bordered band LU (reverse Cuthill-McKee orders them one after the other), so the band is one film's, whatever the
number of bearings. The error test acts on the rotor's coordinates and velocities; the films are solved to the
journal's Newton tolerance (``BDF2_FILM_TOL``) every step, the shaft angle to ``PHI_TOL``.
"""

from __future__ import annotations

import math

import numpy as np
import numba

from transient.models.journal.content_newton import decoupled_pattern
from transient.models.journal.film import read_only
from transient.models.journal.orbit import BDF2_FILM_TOL
from transient.models.rotor.content_newton import FilmArgs, RotorArgs, rotor_newton, rotor_residual
from transient.models.rotor.rough_content import content_args
from transient.solvers.integrate import Problem
from transient.solvers.integrate.bdf2 import Bdf2Model

#: Newton tolerance on the shaft angle [rad] (its row is linear: Newton meets it once the films converge)
PHI_TOL = 1e-10

#: plain second-order BDF's step cap, steps per shaft revolution (the rotor's local error does not see the films'
#: fronts, whose error the cap bounds; one journal on 151 x 21 at 0.3 C: 9.5e-5 C at 550, 1.15e-4 C at 500): the
#: period map's (:mod:`~transient.models.rotor.periodic`). ``run(method="bdf2")`` at its defaults bounds the steps as
#: the journal orbit's (:meth:`ContentSystem.journal_travel`, ``BDF2_TRAVEL``, ``BDF2_MIN_STEPS``).
BDF2_STEPS_PER_REVOLUTION = 550


class ContentSystem:
    """The content formulation of ``dae`` (module docstring) with its shaft speed ``speed(tau) -> (s, s')``
    (``dae.speed``): ``model()`` the stepper's kernels, ``problem(y, tau, events)`` the problem at a chunk's
    start, ``content_state`` / ``universal_state`` the maps between the layouts (the universal one is
    ``SystemDAE``'s, what results and starts hold)."""

    def __init__(self, dae):
        self.dae = dae
        free = np.concatenate([b.film.op.free for b in dae.blocks])
        self.pattern, gather = decoupled_pattern(dae.pattern, free)
        films = film_args(dae)
        refusal = bdf2_refusal(dae, films)
        if refusal:
            raise ValueError(refusal)
        kin_q, kin_v, mom_q, mom_v, mom_phi, phi_phi = dae.rotor_pos
        v_rows, v_cols = np.nonzero(dae.v_mask)
        unb = dae.unbalance
        nq = dae.nq
        self.rotor = RotorArgs(
            Q0=int(dae.Q0), V0=int(dae.V0), P0=int(dae.P0), M=np.ascontiguousarray(dae.M, dtype=float),
            Cw=np.ascontiguousarray(dae.Cw, dtype=float), G=np.ascontiguousarray(dae.G, dtype=float),
            Kw=np.ascontiguousarray(dae.Kw, dtype=float), f_static=np.ascontiguousarray(dae.f_static, dtype=float),
            ub_x=np.array([T[0] for T, _ in unb], dtype=float).reshape(-1, nq),
            ub_y=np.array([T[1] for T, _ in unb], dtype=float).reshape(-1, nq),
            ub_a=np.array([a for _, a in unb], dtype=float),
            kin_q=_ints(kin_q), kin_v=_ints(kin_v), mom_q=_ints(mom_q),
            k_vals=np.ascontiguousarray(dae.Kw[dae.q_mask], dtype=float), mom_v=_ints(mom_v), v_rows=_ints(v_rows),
            v_cols=_ints(v_cols), mom_phi=_ints(mom_phi), phi_rows=_ints(dae.phi_rows), phi_phi=_ints(phi_phi),
            full=np.zeros(dae.pattern.nnz), gather=gather, speed=np.array([1.0, 0.0]), force=np.zeros(nq),
            phi_tol=PHI_TOL, block_cj=np.full(len(films), np.nan), per_film=True)
        self.args = (tuple(films), self.rotor)
        self.newton, self.kernel = rotor_newton, rotor_residual
        if dae.rough:  # rough bearings: their film blocks (rough_content.py)
            self.args, self.newton, self.kernel = content_args(self)
        self.error_components = np.arange(dae.Q0, dae.P0)

    def journal_travel(self, dy) -> float:
        """The largest travel of a journal in its own clearance for a change ``dy`` of the state: of its centre, or
        of the worse end of a film that takes its node's tilts. The films' fronts move with the journals, so
        ``run(method="bdf2")`` bounds each step's travel (``StepBounds.max_travel``) as the journal orbit's."""
        dq = np.asarray(dy)[self.dae.Q0:self.dae.V0]
        worst = 0.0
        for b in self.dae.blocks:
            dX, dY = b.position(dq)
            dA, dB = b.tilt_groups(dq)
            dA, dB = dA * b.half, dB * b.half
            worst = max(worst, math.hypot(dX + dA, dY + dB), math.hypot(dX - dA, dY - dB))
        return worst

    def error_pairs(self) -> np.ndarray:
        """The rows ``(i, j)`` of the state whose components are a journal's x and y (a bearing node's own
        coordinates: its block's position ``X = a q_i``, ``Y = a q_j``), for its coordinates and its velocities: the BDF's
        error test weighs each pair by its length (``options["error_pairs"]``), so a journal on an orbit is held to
        rtol of its distance from the centre and its speed, not to atol where x or y passes through zero."""
        dae, rows = self.dae, []
        for b in self.dae.blocks:
            ix, iy = np.flatnonzero(b.ax), np.flatnonzero(b.ay)
            if (b.support.size == 2 and ix.size == 1 and iy.size == 1 and ix[0] != iy[0]
                    and b.ax[ix[0]] == b.ay[iy[0]]):
                i, j = int(b.support[ix[0]]), int(b.support[iy[0]])
                rows += [(dae.Q0 + i, dae.Q0 + j), (dae.V0 + i, dae.V0 + j)]
        return np.array(sorted(set(rows)), dtype=np.int64).reshape(-1, 2)

    def set_speed(self, tau):
        """The shaft speed ratio and its rate at ``tau`` into the kernels' ``speed``."""
        self.rotor.speed[:] = self.dae.speed(tau)

    def model(self) -> Bdf2Model:
        """The :class:`~transient.solvers.integrate.bdf2.Bdf2Model`: the compiled Newton
        (:func:`~transient.models.rotor.content_newton.rotor_newton`) with the step's shaft speed set first."""
        def newton(args, t, *rest):
            self.set_speed(t)
            return self.newton(args, t, *rest)

        return Bdf2Model(newton=newton, args=self.args, error_components=self.error_components,
                         n_border=2 * self.dae.nq + 1)

    def residual(self, tau, y, yp, out):
        """``F(tau, y, y')`` of the content formulation (:func:`~transient.models.rotor.content_newton.rotor_residual`)."""
        self.set_speed(tau)
        self.kernel(tau, np.ascontiguousarray(y, dtype=float), np.ascontiguousarray(yp, dtype=float), out, self.args)

    def derivative(self, tau, y) -> np.ndarray:
        """``y'`` consistent with the content state ``y``: ``m' = -R / A`` (groove cells 0), ``q~' = v``, the
        momentum solved for ``v'``, ``phi' = s``."""
        dae = self.dae
        out = np.empty(dae.n)
        self.residual(tau, y, np.zeros(dae.n), out)
        yp = np.zeros(dae.n)
        for b in dae.blocks:
            free = b.film.op.free
            yp[b.offset:b.offset + b.n][free] = -out[b.offset:b.offset + b.n][free] / b.film.area[free]
        yp[dae.Q0:dae.V0] = -out[dae.Q0:dae.V0]
        yp[dae.V0:dae.P0] = np.linalg.solve(dae.M, -out[dae.V0:dae.P0])
        yp[dae.P0] = -out[dae.P0]
        return yp

    def problem(self, y, tau, events=None, n_events=0) -> Problem:
        """The content problem from the content state ``y`` at ``tau`` in the Newton pattern (its Jacobian is
        :meth:`model`'s); ``events(t, y, out)``: ``n_events`` terminal events crossing downwards."""
        y = np.array(y, dtype=float)
        return Problem(y0=y, yp0=self.derivative(tau, y), residual=self.residual, jac_pattern=self.pattern,
                       events=events, n_events=n_events, event_terminal=[True] * n_events,
                       event_direction=[-1] * n_events, name="rotor on journal bearings (content)")

    def content_state(self, y) -> np.ndarray:
        """A state of the universal layout ``[u_1, ..., u_k, q~, v, phi]`` in the content layout (``m = H theta``)."""
        y = np.array(y, dtype=float)
        q = y[self.dae.Q0:self.dae.V0]
        for b in self.dae.blocks:
            X, Y = b.position(q)
            b.set_gap(q)
            y[b.offset:b.offset + b.n] = b.film.content(read_only(y[b.offset:b.offset + b.n]), X, Y)
        return y

    def universal_state(self, y) -> np.ndarray:
        """The inverse of :meth:`content_state`."""
        y = np.array(y, dtype=float)
        q = y[self.dae.Q0:self.dae.V0]
        for b in self.dae.blocks:
            X, Y = b.position(q)
            b.set_gap(q)
            y[b.offset:b.offset + b.n] = b.film.universal(y[b.offset:b.offset + b.n], X, Y)
        return y


def film_args(dae) -> list:
    """One :class:`~transient.models.rotor.content_newton.FilmArgs` per film block of ``dae``."""
    films = []
    for b in dae.blocks:
        fl = b.film
        film = (fl.switch, None, fl.geo, fl.fields, fl.extras, fl.fv, fl.work, (BDF2_FILM_TOL, BDF2_FILM_TOL),
                np.zeros(fl.n, dtype=np.int8))
        films.append(FilmArgs(film=film, offset=int(b.offset), n=int(b.n), sym=float(fl.sym), spin=float(b.spin),
                              support=np.ascontiguousarray(b.support, dtype=np.int64), ax=b.ax, ay=b.ay,
                              gx=b.gx, gy=b.gy, maps=b.maps, local=b.local, up=np.zeros(fl.n),
                              ym=np.zeros(fl.n + 2), tilted=bool(b.tilted), aa=b.aa, ab=b.ab, ga=b.ga, gb=b.gb,
                              tilt=b.tilt))
    return films


def bdf2_refusal(dae, films=None) -> str | None:
    """Why ``method="bdf2"`` cannot integrate ``dae`` (a one-line message naming ``method="ida"``), or None: its
    kernels take the smooth and the rough film blocks each as a tuple of one numba type, so the films of each must be
    of one kind (all Newtonian or all with the Gecim bulk, with or without boundary layers alike; a squeeze-film
    damper's film is Newtonian without boundary layers). ``RotorBearingSystem.run`` chooses its default method by
    it."""
    films = film_args(dae) if films is None else films
    for rough in (False, True):
        kinds = {str(numba.typeof(f)) for f, b in zip(films, dae.blocks) if (b.rough is not None) == rough}
        if len(kinds) > 1:
            return ("bearings: method \"bdf2\" takes bearings of one film kind (all Newtonian or all with the Gecim "
                    "bulk, with or without boundary layers alike; a squeeze-film damper's film is Newtonian without "
                    "boundary layers); allowed: method=\"ida\" for a mix")
    return None


def _ints(a) -> np.ndarray:
    return np.ascontiguousarray(np.asarray(a).ravel(), dtype=np.int64)
