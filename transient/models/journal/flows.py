"""Oil flows of a journal bearing film: the supply of each feed, the side leakage at each end and the
dimensionless flow variables of the design charts (Raimondi & Boyd, "A solution for the finite journal bearing and
its application to analysis and design", ASLE Transactions 1, 1958).

The flow through a face of the finite-volume grid is the film's own flux (:mod:`transient.fv.reynolds`)::

    q_f = (-k_f (P_R - P_L) / d_LR + G_f) s_f,    k = H^3 / 2 (+ boundary layers),  G = c theta (upwind),  c = H / 2

(the Gecim bulk's Poiseuille flux from its face tables instead of ``k grad P``), in units of ``C R^2 omega``.
From the flows of the faces around each feed:

* ``supply_flow`` -- the net flow out of the feed into the film: what the oil supply delivers to the film;
* ``feed_inflow`` -- the flow leaving the feed into the film (faces with outflow only): with a groove at the
  maximum film, Raimondi & Boyd's ``Q`` (the flow into the film at its leading edge);
* ``side_leakage`` -- the outflow through the bearing ends ``z = -L/2`` and ``z = +L/2`` (Raimondi & Boyd's
  ``Q_s`` when the cavitated film is at the ambient pressure).

A groove open at the bearing ends also discharges straight out of its ends; that flow is set by the groove's depth,
not by the film, and is not counted. Where such a groove is held above the ambient pressure the film pressure jumps
at the corner where groove and end meet, and the film's flow near that corner grows like ``log(1 / cell size)``:
the flows of a full-length pressurised groove depend on the grid (docs/validation.md); those of a partial groove,
a hole or a circumferential groove converge.

In a steady Elrod film every film cell's net outflow is zero, so the supplies add up to the leakage (mass balance,
to the solver's tolerance). The Reynolds-condition film is not mass-conserving: its cavitated cells, held at the
cavitation pressure with a full film, pass on more Couette flow than they receive, so there the leakage exceeds the
supply.
"""

from __future__ import annotations

import numpy as np


def face_flows(film, u, X, Y):
    """Volume flow [C R^2 omega] through every face of ``film`` (:class:`~transient.models.journal.film.Film` or
    :class:`~transient.models.journal.reynolds_film.ReynoldsFilm`) at the state ``u``, journal at (X, Y):
    ``(a, b, q)`` -- the flow ``q`` from cell ``a`` to cell ``b`` (``b = -1``: out through a bearing end) -- and the
    end of each face (-1 lower, +1 upper, 0 interior)."""
    film.residual(u, X, Y)  # fills the fields at the state
    op = film.op
    elrod = hasattr(film, "P")
    P = film.P if elrod else np.asarray(u, dtype=float)
    C = film.C if elrod else np.ones(film.n)
    k, c = film.k, film.c  # k = 0 with a Gecim bulk (its Poiseuille flux is added below)
    L, R, axial = op.fL, op.fR, op.fdir == 1
    cL, cR = np.where(axial, 0.0, c[L]), np.where(axial, 0.0, c[R])
    if op.upwind:
        cf = 0.5 * (cL + cR)
        G = np.where(cf >= 0.0, cf * C[L], cf * C[R])
    else:
        G = 0.5 * (cL * C[L] + cR * C[R])
    kz = getattr(film, "k_axial", k)  # a rough film's axial conductance (roughness): its own
    kf = np.where(axial, 0.5 * (kz[L] + kz[R]), 0.5 * (k[L] + k[R]))
    q = (-kf * (P[R] - P[L]) / op.fd + G) * op.fs
    i, side = op.bcell, op.bside
    cb = np.where(op.bdir == 1, 0.0, c[i])
    up = side > 0
    if op.upwind:
        G = np.where(cb >= 0.0, cb * np.where(up, C[i], op.bC), cb * np.where(up, op.bC, C[i]))
    else:
        G = 0.5 * cb * (C[i] + op.bC)
    qb = side * (-np.where(op.bdir == 1, kz[i], k[i]) * side * (op.bP - P[i]) / op.bd + G) * op.bs
    bulk = film.bulk
    if bulk is not None and bulk.cells.shape[0] > 0:
        fq = bulk.out[:, 0] * bulk.length  # interior faces in the operator's order, then its Dirichlet faces
        q = q + fq[:L.size]
        qb = qb + side * fq[L.size:]
    a = np.concatenate([L, i])
    b = np.concatenate([R, np.full(i.size, -1)])
    end = np.concatenate([np.zeros(L.size, dtype=np.int64), np.where(op.bdir == 1, side, 0)])
    return a, b, np.concatenate([q, qb]), end


def film_flows(film, u, X, Y):
    """Dimensionless flows [C R^2 omega] of the whole bearing at the state ``u``: ``(supply, inflow, leakage)`` --
    the net supply and the inflow into the film of each feed (arrays over the bearing's feeds) and the outflow
    through the ends at ``z = -L/2`` and ``+L/2`` (module docstring). On a half grid both ends leak alike and each
    feed's flows are twice its half's."""
    sc = film.scales
    a, c, q, end = face_flows(film, u, X, Y)
    labels = sc.feed_cells
    la = labels[a]
    lc = np.where(c >= 0, labels[np.maximum(c, 0)], -1)
    n = sc.feed_edges.size
    out_a = (la >= 0) & (c >= 0) & (lc < 0)  # q leaves feed la into the film
    into_c = (lc >= 0) & (la < 0)  # q enters feed lc from the film
    supply = np.bincount(la[out_a], q[out_a], n) - np.bincount(lc[into_c], q[into_c], n)
    inflow = np.bincount(la[out_a], np.maximum(q[out_a], 0.0), n) + np.bincount(lc[into_c], np.maximum(-q[into_c], 0.0), n)
    end = np.where(la < 0, end, 0)  # the film's ends (a groove open at the ends discharges there too: not the film's)
    ends = np.array([q[end == -1].sum(), q[end == 1].sum()])
    if sc.sym == 2.0:
        return 2.0 * supply, 2.0 * inflow, np.array([ends[1], ends[1]])
    return supply, inflow, ends


def flow_fields(film, u, X, Y) -> dict:
    """The flows of a :class:`~transient.models.journal.results.FilmState` [m^3/s] and the design-chart variables:
    ``Q / (R C N L)`` with ``Q`` the total inflow of the feeds into the film (``N`` [rev/s]) and ``Q_s / Q`` with
    ``Q_s`` the side leakage of both ends (NaN without feeds)."""
    sc = film.scales
    unit = sc.clearance * sc.radius ** 2 * sc.omega  # m^3/s per dimensionless flow
    supply, inflow, leak = film_flows(film, u, X, Y)
    Q = float(inflow.sum()) * unit
    length = sc.sym * sc.radius * float(film.grid.z.widths.sum())
    rcnl = sc.radius * sc.clearance * (sc.omega / (2.0 * np.pi)) * length
    return dict(supply_flow=supply * unit, feed_inflow=inflow * unit, side_leakage=leak * unit,
                flow_variable=Q / rcnl if Q > 0 else float("nan"),
                side_flow_ratio=float(leak.sum()) * unit / Q if Q > 0 else float("nan"))
