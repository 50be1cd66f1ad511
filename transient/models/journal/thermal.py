"""The film-averaged energy equation of a journal film on its Elrod grid (steady), for a film state whose flows
are given.

One temperature ``T_i`` [K] per cell (the mixed-mean temperature across the film) and one mixing temperature per
feed. In each film cell the heat the oil carries out equals the heat made in it less the heat its walls take::

    sum_faces rho c_p Q_f T_up(f) = Phi_i - w_i (T_i - T_w)

* ``Q_f``: the Elrod film's own face flows (:mod:`transient.models.journal.flows`: ``-k grad P + c theta``, so
  in the cavitated zone only the liquid fraction theta carries heat) as two streams, the Couette part
  ``c theta`` and the Poiseuille part ``-k grad P``, each at the temperature of its own upstream cell (first-order
  upwind: the matrix is an M-matrix, so the temperatures obey a discrete maximum principle -- no overshoot on any
  grid). Where the pressure drives oil back against the shaft's drag (upstream of a feed) the two streams run in
  opposite directions and exchange heat; upwinding their net flow instead made the cells there flip between the
  feed's and the recirculated oil's temperature from one film solve to the next (at e/C = 0.9 the alternation did
  not settle). Oil entering through a bearing end comes in at the supply temperature;
* ``Phi_i`` viscous dissipation: Couette ``min(theta, 1) mu_i U^2 / h_i A_i`` in the cell and Poiseuille
  ``Q_p,f (p_L - p_R)`` on each face (the pressure flow times its pressure drop; half to each of the face's
  cells, all of it on a bearing-end face to its cell) -- together the film's ``int mu (du/dy)^2 dy dA``;
* ``w_i (T_i - T_w)``: the wall (:mod:`transient.models.journal.thermal_settings`), times ``min(theta, 1)``;
* at each feed: ``Q_in T_mix = f Q_rec T_rec + (Q_in - f Q_rec) T_supply + Phi_feed / (rho c_p)``, with the
  carry-over ``f = min(lambda, Q_in / Q_rec)`` (the heat made in the feed's own cells goes into its oil).

Summed over the cells and feeds the equations state the global balance: the dissipation equals the heat carried
away by the side leakage and the discharged recirculated oil (above the supply temperature) plus the heat to the
walls. Units inside: flows in ``C R^2 omega``, pressures in ``p0``, so ``Phi`` in ``p0 C R^2 omega`` [W] and the
equations in ``K C R^2 omega`` after dividing by ``rho c_p``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numba import njit


@njit(cache=True)
def face_flows(P, C, k, c, faces, boundary, q, qp, qb):
    """Volume flow of every interior face ``q`` (from ``fL`` to ``fR``), its Poiseuille part ``qp``, and the outflow
    of every bearing-end face ``qb`` (out of its cell; Poiseuille only: the Couette flow is circumferential), in
    ``C R^2 omega``, from the cell fields of the film's last evaluation (the upwinded Elrod flux of
    :func:`~transient.fv.reynolds.residual_kernel`)."""
    fL, fR, fdir, fd, fs, fpos = faces
    bcell, bside, bdir, bd, bs, bP, bC, bpos = boundary
    for f in range(fL.size):
        L = fL[f]
        R = fR[f]
        kf = 0.5 * (k[L] + k[R])
        qp[f] = -kf * (P[R] - P[L]) / fd[f] * fs[f]
        G = 0.0
        if fdir[f] == 0:
            cf = 0.5 * (c[L] + c[R])
            G = cf * C[L] if cf >= 0.0 else cf * C[R]
        q[f] = qp[f] + G * fs[f]
    for b in range(bcell.size):
        i = bcell[b]
        qb[b] = k[i] * (P[i] - bP[b]) / bd[b] * bs[b]


@njit(cache=True)
def dissipation(P, C, H, fluidity, area, faces, boundary, qp, qb, out):
    """Viscous dissipation of every cell [p0 C R^2 omega] (module docstring): Couette ``min(theta, 1) A / (6 f H)``
    (``f = mu / mu_i``), Poiseuille ``qp (P_L - P_R)`` per face, halved between its cells, and ``qb (P_i - P_b)``
    on an end face."""
    fL, fR, fdir, fd, fs, fpos = faces
    bcell, bside, bdir, bd, bs, bP, bC, bpos = boundary
    for i in range(P.size):
        out[i] = min(C[i], 1.0) * area[i] / (6.0 * fluidity[i] * H[i])
    for f in range(fL.size):
        half = 0.5 * qp[f] * (P[fL[f]] - P[fR[f]])
        out[fL[f]] += half
        out[fR[f]] += half
    for b in range(bcell.size):
        out[bcell[b]] += qb[b] * (P[bcell[b]] - bP[b])


@njit(cache=True)
def feed_totals(free, feed, n_feeds, faces, q):
    """Per feed: the flow it sends into the film ``Q_in`` and the flow reaching it from the film ``Q_rec``, over the
    streams ``q`` between the cells ``faces[0]``, ``faces[1]``."""
    fL, fR = faces[0], faces[1]
    q_in = np.zeros(n_feeds)
    q_rec = np.zeros(n_feeds)
    for f in range(fL.size):
        L = fL[f]
        R = fR[f]
        if free[L] == free[R]:
            continue
        g = feed[R] if free[L] else feed[L]
        into_feed = q[f] >= 0.0 if free[L] else q[f] < 0.0
        if into_feed:
            q_rec[g] += abs(q[f])
        else:
            q_in[g] += abs(q[f])
    return q_in, q_rec


@njit(cache=True)
def energy_system(free, feed, n_feeds, faces, boundary, q, qb, source, wall, T_wall, T_supply, carry, q_in, q_rec,
                  rows, cols, vals, rhs):
    """The energy equations (module docstring) as triplets ``(rows, cols, vals)`` and right side ``rhs`` for the
    streams ``q`` between the cells ``faces[0]`` and ``faces[1]`` and the end faces' outflows ``qb``; unknowns:
    the cells' temperatures, then one mixing temperature per feed (a feed's cells equal it). ``source``: the
    dissipation per cell and ``wall`` the wall coefficient per cell, both divided by ``rho c_p``; ``carry``: the
    carry-over fraction per feed. Returns the number of triplets."""
    fL, fR = faces[0], faces[1]
    bcell = boundary[0]
    n = free.size
    m = 0
    for i in range(n + n_feeds):
        rhs[i] = 0.0
    for f in range(fL.size):
        L = fL[f]
        R = fR[f]
        up, down = (L, R) if q[f] >= 0.0 else (R, L)
        qa = abs(q[f])
        col = up if free[up] else n + feed[up]
        if free[up]:  # the upstream cell's outflow
            rows[m] = up
            cols[m] = up
            vals[m] = qa
            m += 1
        if free[down]:  # the downstream cell's inflow at the upstream temperature (a feed's: its mixing temperature)
            rows[m] = down
            cols[m] = col
            vals[m] = -qa
            m += 1
        elif free[up]:  # recirculated oil reaching a feed
            g = feed[down]
            if q_in[g] > 0.0:
                rows[m] = n + g
                cols[m] = up
                vals[m] = -carry[g] * qa / q_in[g]
                m += 1
    for b in range(bcell.size):
        i = bcell[b]
        if not free[i]:
            continue
        if qb[b] >= 0.0:
            rows[m] = i
            cols[m] = i
            vals[m] = qb[b]
            m += 1
        else:
            rhs[i] -= qb[b] * T_supply
    for i in range(n):
        rows[m] = i
        cols[m] = i
        if free[i]:
            vals[m] = wall[i]
            rhs[i] += source[i] + wall[i] * T_wall
        else:  # a feed's cell: its mixing temperature
            vals[m] = 1.0
            m += 1
            rows[m] = i
            cols[m] = n + feed[i]
            vals[m] = -1.0
            g = feed[i]
            if q_in[g] > 0.0:
                rhs[n + g] += source[i] / q_in[g]
        m += 1
    for g in range(n_feeds):
        rows[m] = n + g
        cols[m] = n + g
        vals[m] = 1.0
        m += 1
        if q_in[g] > 0.0:
            rhs[n + g] += (1.0 - carry[g] * q_rec[g] / q_in[g]) * T_supply
        else:
            rhs[n + g] = T_supply
    return m


#: SuperLU's column ordering for the energy equations: the cells' own order (circumferential index fastest, the
#: upwinded flow mostly along it) factorised in 2.3 ms at 151 x 21 against 7 ms with the default COLAMD and 120 ms
#: with minimum degree on A^T + A (one run on the loaded machine).
ENERGY_ORDERING = "NATURAL"


class EnergyBalance(NamedTuple):
    """A solved energy equation: ``temperature`` [K] per cell, ``mixing_temperature`` [K] per feed, the oil's
    ``outlet_temperature`` [K] (mixed mean of the side leakage), the film's ``dissipation`` [W], the heat
    ``convected`` [W] away by the oil above the supply temperature (side leakage and discharged recirculated oil) and
    ``conducted`` [W] to the walls; all on the modelled grid times ``sym`` (whole bearing)."""

    temperature: np.ndarray
    mixing_temperature: np.ndarray
    outlet_temperature: float
    dissipation: float
    convected: float
    conducted: float


class EnergyRates(NamedTuple):
    """What drives the energy equation (:meth:`EnergyEquation.rates`): the ``stream_flow`` of every face's two
    streams (Poiseuille, then Couette) and the end faces' outflows ``qb`` [C R^2 omega], the dissipation per cell
    ``source`` [p0 C R^2 omega] and the wall coefficient per cell ``wall`` [W/K] -- at one instant, or their means
    over an interval (they enter the equations linearly)."""

    stream_flow: np.ndarray
    qb: np.ndarray
    source: np.ndarray
    wall: np.ndarray


class EnergyEquation:
    """The energy equation of a :class:`~transient.models.journal.viscous_film.ViscousFilm` for a
    :class:`~transient.models.journal.thermal_settings.ThermalFilm`: :meth:`solve` at the film's state."""

    def __init__(self, film, thermal):
        self.film, self.thermal = film, thermal
        s = film.scales
        self.feed = np.ascontiguousarray(s.feed_cells, dtype=np.int64)
        self.n_feeds = int(s.feed_edges.size)
        self.free = film.op.free
        n_faces, n_bound = film.op.fL.size, film.op.bcell.size
        self.q, self.qp, self.qb = np.empty(n_faces), np.empty(n_faces), np.empty(n_bound)
        # each face's two streams (Poiseuille, then Couette) between the same cells
        self.streams = (np.concatenate([film.op.fL, film.op.fL]), np.concatenate([film.op.fR, film.op.fR]))
        self.stream_flow = np.empty(2 * n_faces)
        size = 6 * n_faces + n_bound + 2 * film.n + self.n_feeds
        self.rows, self.cols = np.empty(size, dtype=np.int64), np.empty(size, dtype=np.int64)
        self.vals, self.rhs = np.empty(size), np.empty(film.n + self.n_feeds)
        self.source = np.empty(film.n)
        # the heat unit: flows [C R^2 omega] times rho c_p [J/(m^3 K)] -> W/K
        self.heat_unit = thermal.properties.volumetric_heat * s.clearance * s.radius ** 2 * s.omega
        self.power_unit = film.p0 * s.clearance * s.radius ** 2 * s.omega  # W per p0 C R^2 omega

    def wall_coefficients(self):
        """``w_i`` [W/K] per cell (times min(theta, 1)) and the wall temperature [K]."""
        film, s = self.film, self.film.scales
        kind, coefficient, T_wall = self.thermal.wall()
        liquid = np.minimum(film.C, 1.0) * film.area * s.radius ** 2
        if kind == "bush":
            return coefficient * liquid, T_wall
        if kind == "shaft":
            return 2.0 * coefficient / (s.clearance * film.H) * liquid, T_wall
        return np.zeros(film.n), T_wall

    def solve(self, u, X, Y) -> EnergyBalance:
        """The temperatures of the film at state ``u``, journal at (X, Y), with the film's current fluidity."""
        self.film.residual(u, X, Y)  # the cell fields (H, P, theta, k with the fluidity, c) of the state
        return self.solve_rates(self.rates())

    def rates(self, speed_ratio=1.0) -> "EnergyRates":
        """What drives the temperatures at the cell fields of the film's last evaluation (``film.P``, ``C``, ``H``,
        ``k`` with the fluidity, ``c`` with the shaft's speed): the streams, the end faces' outflows, the
        dissipation per cell [p0 C R^2 omega] -- its Couette part at ``speed_ratio`` (the shaft's speed over the
        film's) squared -- and the wall coefficients [W/K]."""
        film = self.film
        fv = film.fv
        face_flows(film.P, film.C, film.k, film.c, fv.faces, fv.boundary, self.q, self.qp, self.qb)
        # the Couette dissipation min(theta, 1) A s^2 / (6 f H): the fluidity over s^2 (its only use in the kernel)
        dissipation(film.P, film.C, film.H, film.fluidity / speed_ratio ** 2, film.area, fv.faces, fv.boundary,
                    self.qp, self.qb, self.source)
        nf = self.q.size
        self.stream_flow[:nf] = self.qp
        self.stream_flow[nf:] = self.q - self.qp
        return EnergyRates(self.stream_flow.copy(), self.qb.copy(), self.source.copy(), self.wall_coefficients()[0])

    def solve_rates(self, r: "EnergyRates", capacity=None, T_old=None) -> EnergyBalance:
        """The temperatures driven by ``r`` (:meth:`rates`, or their mean over an interval): steady, or with
        ``capacity`` per cell [C R^2 per unit of tau: the heat capacity over rho c_p and the time step] one
        backward-Euler step from the cells' temperatures ``T_old`` [K] of the advective form
        ``capacity (T - T_old) + sum_inflows Q (T - T_up) + w (T - T_w) = Phi``: the free cells' diagonal takes the
        capacity less their net outflow (mean flows over an interval in which the film's content changed need not be
        free of divergence; the flux form would then make ``T div Q`` a spurious source), ``capacity T_old`` the
        right side -- every row sums to ``capacity + w`` > 0, a diagonally dominant M-matrix: no temperature leaves
        the range of the old, supply, wall and heated ones."""
        A, rhs = self.system(r, capacity, T_old)
        x = spla.splu(A, permc_spec=ENERGY_ORDERING).solve(rhs)
        return self.balance(r, x[:self.film.n], x[self.film.n:])

    def system(self, r: EnergyRates, capacity=None, T_old=None):
        """The equations of :meth:`solve_rates` as a CSC matrix and right side (cells' temperatures, then the
        feeds' mixing temperatures)."""
        film, th = self.film, self.thermal
        q_in, q_rec, carry = self.carry_over(r)
        _, T_wall = self.wall_coefficients()
        Ts = th.supply_temperature
        scale = self.power_unit / self.heat_unit  # K C R^2 omega per p0 C R^2 omega
        fv = film.fv
        m = energy_system(self.free, self.feed, self.n_feeds, self.streams, fv.boundary, r.stream_flow, r.qb,
                          r.source * scale, r.wall / self.heat_unit, T_wall, Ts, carry, q_in, q_rec,
                          self.rows, self.cols, self.vals, self.rhs)
        N = film.n + self.n_feeds
        rows, cols, vals, rhs = self.rows[:m], self.cols[:m], self.vals[:m], self.rhs
        if capacity is not None:
            cells = np.flatnonzero(self.free)
            (fL, fR), n = self.streams, film.n
            net_out = (np.bincount(fL, r.stream_flow, n) - np.bincount(fR, r.stream_flow, n)
                       + np.bincount(film.op.bcell, r.qb, n))
            rows, cols = np.concatenate([rows, cells]), np.concatenate([cols, cells])
            vals = np.concatenate([vals, (capacity - net_out)[cells]])
            rhs = rhs.copy()
            rhs[cells] += capacity[cells] * T_old[cells]
        return sp.csc_matrix((vals, (rows, cols)), shape=(N, N)), rhs.copy()

    def carry_over(self, r: "EnergyRates"):
        """Per feed: the inflow ``Q_in``, the recirculated flow ``Q_rec`` and the carry-over fraction of ``r``."""
        q_in, q_rec = feed_totals(self.free, self.feed, self.n_feeds, self.streams, r.stream_flow)
        with np.errstate(divide="ignore", invalid="ignore"):
            carry = np.where(q_rec > 0.0, np.minimum(self.thermal.mixing, q_in / np.where(q_rec > 0.0, q_rec, 1.0)),
                             0.0)
        return q_in, q_rec, carry

    def balance(self, r: "EnergyRates", T, T_mix) -> EnergyBalance:
        """The :class:`EnergyBalance` of the temperatures ``T`` (cells) and ``T_mix`` (feeds) under the rates ``r``."""
        film, Ts = self.film, self.thermal.supply_temperature
        q_in, q_rec, carry = self.carry_over(r)
        wall, T_wall = r.wall, self.wall_coefficients()[1]
        sym = film.scales.sym
        leak = (r.qb > 0.0) & self.free[film.op.bcell]  # the film's side leakage (a groove's own ends: not film)
        out_T = T[film.op.bcell[leak]]
        q_out = r.qb[leak]
        outlet = float(np.sum(q_out * out_T) / np.sum(q_out)) if np.sum(q_out) > 0 else float("nan")
        T_rec = self._recirculated(T, T_mix, q_rec, r.stream_flow)
        convected = self.heat_unit * sym * (float(np.sum(q_out * (out_T - Ts)))
                                              + float(np.sum((1.0 - carry) * q_rec * (T_rec - Ts))))
        conducted = sym * float(np.sum(wall[self.free] * (T - T_wall)[self.free]))
        return EnergyBalance(np.array(T), np.array(T_mix), outlet, sym * self.power_unit * float(r.source.sum()),
                             convected, conducted)

    def _recirculated(self, T, T_mix, q_rec, q):
        """Mixed-mean temperature of the oil reaching each feed from the film (the feed's own if none reaches it)."""
        (fL, fR), free = self.streams, self.free
        cross = free[fL] != free[fR]
        up_is_L = q >= 0.0
        up = np.where(up_is_L, fL, fR)
        down = np.where(up_is_L, fR, fL)
        rec = cross & free[up] & ~free[down]
        heat = np.bincount(self.feed[down[rec]], np.abs(q[rec]) * T[up[rec]], self.n_feeds)
        return np.where(q_rec > 0.0, heat / np.where(q_rec > 0.0, q_rec, 1.0), T_mix)
