"""The method-of-lines DAE of a rotor on journal bearings: one Elrod film block per bearing, the rotor as the
border of a block-arrow Jacobian.

State (dimensionless; ``L`` the smallest bearing clearance, ``tau = omega_ref t``)::

    y = [u_1 (film of bearing 1), ..., u_k, q~ = q / L, v = dq~/dtau, phi]

``phi`` is the shaft angle (``phi' = s``, ``s = Omega(t) / omega_ref``). Equations::

    film b:      A (H D u' + theta (X_b' cos + Y_b' sin)) + R(u; s) = 0,   X_b = (L / C_b) t_x,b . q~  (kernels.py;
                 a squeeze-film damper's film at s = 0: its journal does not turn)
    kinematics:  q~' - v = 0
    momentum:    M v' + (C / omega_ref + s G) v + K / omega_ref^2 q~ = sum_b (t_x,b F_x,b + t_y,b F_y,b) / (L omega_ref^2)
                 + g_load / (L omega_ref^2) + sum_unbalance t_u (m e / L) (s^2 cos(phi + a) + s' sin(phi + a),
                                                                          s^2 sin(phi + a) - s' cos(phi + a))
    angle:       phi' - s = 0

(``t_x,b``, ``t_y,b``: the rows of the rotor's basis giving the x, y displacement of the bearing node; the
virtual work of the film force ``F_b = p0 R^2 Fbar_b`` on them is its generalised force). With
``tilt_coupling`` a film also takes its node's tilts as the tilt groups ``A_b = (R / C_b) r_y,b . q L``,
``B_b = -(R / C_b) r_x,b . q L`` (``r_x,b``, ``r_y,b`` the basis rows of the node's tx, ty): its gap
``gap_b + A_b zbar cos + B_b zbar sin + X_b cos + Y_b sin`` (``gap_b`` the bush's static misalignment), the rates
``A_b'``, ``B_b'`` in its squeeze term, and the moments ``(M_x, M_y) = p0 R^3 (-Fb_b, Fa_b)`` on the tilts
(:mod:`transient.models.journal.tilt`, the tilted blocks of :mod:`transient.models.rotor.kernels`). The Jacobian
``dF/dy + cj dF/dy'`` is analytic and sparse: each film's 5-point block with its coupling columns to the
rotor coordinates of its node, the dense rotor rows as the border (:func:`system_pattern`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.sparse as sp

from transient.models.journal.film import read_only
from transient.models.rotor.kernels import (block_jacobian, block_residual, scatter_block, scatter_tilted_block,
                                           tilt_gap, tilted_block_jacobian, tilted_block_residual)
from transient.models.rotor.rough_films import (add_contact_stiffness, attach_rough, contact_mask, contact_positions,
                                                rough_block_jacobian, rough_block_residual)


class BlockMaps(NamedTuple):
    """Where a film block's local Jacobian goes in the system's CSC data: the cell block (``src`` -> ``dst``; a
    groove cell's row only its diagonal), the local positions of ``dF_i/dX``, ``dF_i/dY`` of the free cells
    (``col_x``, ``col_y``) and of ``dFx/du_i``, ``dFy/du_i`` of every cell (``row_fx``, ``row_fy``), the system
    positions of the coupling (free cells, m) and of the border (cells, m); a tilted block's tilt columns
    ``col_a``, ``col_b`` (free cells) and its tilt-force rows ``row_fa``, ``row_fb`` (every cell; local extra
    columns 2, 3 and rows 0, 1, :func:`~transient.models.rotor.kernels.tilted_block_jacobian`)."""

    src: np.ndarray
    dst: np.ndarray
    col_x: np.ndarray
    col_y: np.ndarray
    coupling: np.ndarray
    row_fx: np.ndarray
    row_fy: np.ndarray
    border: np.ndarray
    col_a: np.ndarray
    col_b: np.ndarray
    row_fa: np.ndarray
    row_fb: np.ndarray


class BearingBlock:
    """One bearing's film in the system: its node, the film at the reference speed, its offset in the state,
    the rotor coordinates its node moves with (``support``), ``ax``, ``ay`` (node position in C_b per q~) and
    ``gx``, ``gy`` (the generalised force per unit of ``Fbar`` in the momentum rows); ``spin``: 1 for a journal
    bearing (its journal turns with the shaft), 0 for a squeeze-film damper (its journal is pinned: no Couette flow)."""

    def __init__(self, node, bearing, film, offset, translation, length, omega_ref, spin=1.0, rotation=None):
        self.node, self.bearing, self.film, self.offset, self.spin = node, bearing, film, offset, spin
        self.n = film.n
        moving = translation if rotation is None else np.vstack([translation, rotation])
        support = np.flatnonzero(np.any(moving != 0.0, axis=0))
        self.support = support
        self.ax = np.ascontiguousarray(translation[0, support] * length / bearing.clearance)
        self.ay = np.ascontiguousarray(translation[1, support] * length / bearing.clearance)
        unit = film.force_scale / (length * omega_ref ** 2)
        self.gx = np.ascontiguousarray(translation[0, support] * unit)
        self.gy = np.ascontiguousarray(translation[1, support] * unit)
        self.tilted = rotation is not None
        self.static_tilt = film.tilt  # the bush's misalignment as the film's tilt groups (a, b)
        if self.tilted:  # A = (t_y R / C) . q, B = -(t_x R / C) . q; the moments' virtual work on the tilts
            R = bearing.radius
            self.aa = np.ascontiguousarray(rotation[1, support] * length * R / bearing.clearance)
            self.ab = np.ascontiguousarray(-rotation[0, support] * length * R / bearing.clearance)
            self.ga = np.ascontiguousarray(rotation[1, support] * unit * R)
            self.gb = np.ascontiguousarray(-rotation[0, support] * unit * R)
            zbar = np.ascontiguousarray(film.grid.zc, dtype=float)
            self.tilt = (film.geo.gap0.copy(), np.ascontiguousarray(zbar * film.cosp),
                         np.ascontiguousarray(zbar * film.sinp), zbar, np.zeros(2))  # held: the gap at (0, 0)
        else:
            self.aa = self.ab = self.ga = self.gb = np.zeros(0)
            self.tilt = (np.zeros(0), np.zeros(0), np.zeros(0), np.zeros(0), np.zeros(2))
        self.half = 0.5 * bearing.length / bearing.radius
        self.local = np.zeros(film.op.nnz)
        self.maps: BlockMaps | None = None

    def position(self, q):
        """(X, Y) of the journal [C_b] for the rotor coordinates q~ (or their rates)."""
        qs = q[self.support]
        return float(self.ax @ qs), float(self.ay @ qs)

    def tilt_groups(self, q):
        """The node's tilt groups (A, B) [C_b per R] for the rotor coordinates q~ (or their rates); (0, 0) when its
        film does not take the tilts."""
        if not self.tilted:
            return 0.0, 0.0
        qs = q[self.support]
        return float(self.aa @ qs), float(self.ab @ qs)

    def set_gap(self, q):
        """The film's gap at the node's tilts of q~ (nothing for a block without them): before a film evaluation
        outside the system's residual and Jacobian (the steady solves, the samples)."""
        if self.tilted:
            tilt_gap(self.film.geo.gap0, self.tilt, *self.tilt_groups(q))

    def reach2(self, q) -> float:
        """The square of the journal's largest eccentricity ratio over the bearing length at q~: at the mid-plane
        for an aligned film, else at the worse end (the bush's misalignment and the node's tilts)."""
        X, Y = self.position(q)
        a, b = self.static_tilt
        A, B = self.tilt_groups(q)
        a, b = (a + A) * self.half, (b + B) * self.half
        if a == 0.0 and b == 0.0:
            return X * X + Y * Y
        return max((X - a) ** 2 + (Y - b) ** 2, (X + a) ** 2 + (Y + b) ** 2)

    def moment(self, fa, fb):
        """The film's moments (M_x, M_y) [N m] of its tilt forces (Fa, Fb)."""
        scale = self.film.force_scale * self.bearing.radius
        return -fb * scale, fa * scale


def system_pattern(blocks, nq, n_total, q_mask, v_mask, phi_rows):
    """The CSC pattern of the system Jacobian and each block's :class:`BlockMaps`; returns
    ``(pattern, rotor_positions)`` with ``rotor_positions = (kin_q, kin_v, mom_q, mom_v, mom_phi, phi_phi)``:
    the positions of the kinematic rows' entries, of the momentum rows' entries in the rotor coordinates where
    ``q_mask`` (stiffness) and ``v_mask`` (mass, damping, gyroscopic) are true (row-major order of the masks),
    in the angle column for ``phi_rows`` (the unbalances), and of the angle row's diagonal. Only the rotor
    matrices' own nonzeros enter: explicit zeros in the border let the fill-reducing ordering of the sparse LU
    go wrong (measured: 5x the fill on a Jeffcott rotor)."""
    Q0 = n_total - 2 * nq - 1
    V0, P0 = Q0 + nq, n_total - 1
    rows, cols = [], []

    def add(r, c):
        r, c = np.broadcast_arrays(np.asarray(r, dtype=np.int64), np.asarray(c, dtype=np.int64))
        start = sum(a.size for a in rows)
        rows.append(r.ravel())
        cols.append(c.ravel())
        return np.arange(start, start + r.size).reshape(r.shape)

    block_ids = []
    for b in blocks:
        pat = sp.csc_matrix(b.film.op.pattern)
        n = b.n
        row = pat.indices
        col = np.repeat(np.arange(pat.shape[1]), np.diff(pat.indptr))
        free = b.film.op.free
        keep = (row < n) & (col < n)
        keep[keep] = free[row[keep]] | (row[keep] == col[keep])  # a groove cell's row: u' = 0
        src = np.flatnonzero(keep)  # local CSC positions of the cell block
        ids_cells = add(b.offset + row[src], b.offset + col[src])
        cells = np.arange(n)
        ids_coup = add(b.offset + cells[free][:, None], Q0 + b.support[None, :])
        ids_border = add(V0 + b.support[None, :], b.offset + cells[:, None])
        st = b.film.op.stencil
        block_ids.append((src, ids_cells, ids_coup, ids_border, st))
    j = np.arange(nq)
    kin_q = add(Q0 + j, Q0 + j)
    kin_v = add(Q0 + j, V0 + j)
    r_q, c_q = np.nonzero(q_mask)
    mom_q = add(V0 + r_q, Q0 + c_q)
    r_v, c_v = np.nonzero(v_mask)
    mom_v = add(V0 + r_v, V0 + c_v)
    mom_phi = add(V0 + np.asarray(phi_rows, dtype=np.int64), P0)
    phi_phi = add(P0, P0)
    r, c = np.concatenate(rows), np.concatenate(cols)
    ids = np.arange(r.size, dtype=float) + 1.0
    m = sp.csc_matrix((ids, (r, c)), shape=(n_total, n_total))
    m.sort_indices()
    if m.nnz != r.size:
        raise AssertionError("duplicate entries in the system pattern")
    where = np.empty(r.size, dtype=np.int64)
    where[m.data.astype(np.int64) - 1] = np.arange(m.nnz)
    for b, (src, ids_cells, ids_coup, ids_border, st) in zip(blocks, block_ids):
        free = b.film.op.free
        b.maps = BlockMaps(np.ascontiguousarray(src, dtype=np.int64), where[ids_cells],
                           np.ascontiguousarray(st.pos_col_extra[:b.n, 0][free]),
                           np.ascontiguousarray(st.pos_col_extra[:b.n, 1][free]),
                           np.ascontiguousarray(where[ids_coup]), np.ascontiguousarray(st.pos_row_extra[2, :b.n]),
                           np.ascontiguousarray(st.pos_row_extra[3, :b.n]), np.ascontiguousarray(where[ids_border]),
                           np.ascontiguousarray(st.pos_col_extra[:b.n, 2][free]),
                           np.ascontiguousarray(st.pos_col_extra[:b.n, 3][free]),
                           np.ascontiguousarray(st.pos_row_extra[0, :b.n]),
                           np.ascontiguousarray(st.pos_row_extra[1, :b.n]))
    pattern = sp.csc_matrix((np.ones(m.nnz), m.indices, m.indptr), shape=m.shape)
    return pattern, tuple(where[x] for x in (kin_q, kin_v, mom_q, mom_v, mom_phi, phi_phi))


class SystemDAE:
    """The DAE of a :class:`~transient.models.rotor.system.RotorBearingSystem` at a reference speed
    ``speed_ref_rpm`` (module docstring), with ``speed(tau) -> (s, ds/dtau)``: residual, analytic Jacobian in
    its sparse pattern, consistent derivatives, per-state absolute tolerances."""

    def __init__(self, system, speed_ref_rpm, speed=None):
        from transient.units import rpm_to_rad_s

        self.system = system
        rotor = system.rotor
        self.speed_ref_rpm = float(speed_ref_rpm)
        self.omega = w = rpm_to_rad_s(speed_ref_rpm)
        self.L = L = system.length_scale
        self.speed = speed if speed is not None else (lambda tau: (1.0, 0.0))
        self.blocks = []
        off = 0
        for node, bearing in system.bearings.items():
            film = bearing.film(speed_ref_rpm)
            spin = 0.0 if node in system.dampers else 1.0
            rotation = system.rotation(node) if system.tilt_coupling else None
            self.blocks.append(BearingBlock(node, bearing, film, off, rotor.translation(node), L, w, spin, rotation))
            off += film.n
        self.n_film = off
        self.nq = nq = rotor.n
        self.Q0, self.V0, self.P0 = off, off + nq, off + 2 * nq
        self.n = off + 2 * nq + 1
        self.M = rotor.mass
        self.Cw = rotor.damping / w
        self.G = rotor.gyroscopic  # times s: Omega G / omega_ref
        self.Kw = system.stiffness / w ** 2  # the rotor's, with the dampers' centring springs
        self.f_static = system.gravity_vector @ rotor.gravity_load / (L * w ** 2)
        self.unbalance = [(rotor.translation(node) * me / L, np.radians(phase)) for node, me, phase
                          in system.unbalance]
        self.rough = attach_rough(self.blocks)  # rough bearings: their cells and contact stiffness (rough_films.py)
        self.q_mask = (system.stiffness != 0) | contact_mask(self.blocks, nq)
        self.v_mask = (rotor.mass != 0) | (rotor.damping != 0) | (rotor.gyroscopic != 0)
        np.fill_diagonal(self.v_mask, True)
        self.phi_rows = np.flatnonzero(np.any([np.any(T != 0, axis=0) for T, _ in self.unbalance], axis=0)) \
            if self.unbalance else np.zeros(0, dtype=np.int64)
        self.pattern, self.rotor_pos = system_pattern(self.blocks, nq, self.n, self.q_mask, self.v_mask,
                                                      self.phi_rows)
        self.pattern.sort_indices()
        contact_positions(self.blocks, self.q_mask, self.rotor_pos[2])
        self.forces = np.zeros((len(self.blocks), 2))
        self.tilt_forces = np.zeros((len(self.blocks), 2))  # (Fa, Fb) of the tilted blocks (kernels.py)

    # ------------------------------------------------------------------------------------------
    def rotor_force(self, tau, y, s, ds):
        """Generalised external force on the rotor coordinates: gravity and the unbalances (dimensionless)."""
        f = self.f_static.copy()
        phi = y[self.P0]
        for T, a in self.unbalance:
            c, sn = np.cos(phi + a), np.sin(phi + a)
            f += T[0] * (s * s * c + ds * sn) + T[1] * (s * s * sn - ds * c)
        return f

    def residual(self, tau, y, yp, out):
        s, ds = self.speed(tau)
        Q0, V0, P0 = self.Q0, self.V0, self.P0
        q, v, qp, vp = y[Q0:V0], y[V0:P0], yp[Q0:V0], yp[V0:P0]
        f = self.rotor_force(tau, y, s, ds)
        for k, b in enumerate(self.blocks):
            X, Y = b.position(q)
            Xd, Yd = b.position(qp)
            fl = b.film
            o = b.offset
            if b.tilted:
                A, B = b.tilt_groups(q)
                Ad, Bd = b.tilt_groups(qp)
                fx, fy, fa, fb = tilted_block_residual(y[o:o + b.n], yp[o:o + b.n], X, Y, A, B, Xd, Yd, Ad, Bd,
                                                       s * b.spin, out[o:o + b.n], fl.switch, fl.geo, fl.fields, fl.fv,
                                                       fl.sym, b.tilt)
                self.forces[k] = fx, fy
                self.tilt_forces[k] = fa, fb
                f[b.support] += b.gx * fx + b.gy * fy + b.ga * fa + b.gb * fb
                continue
            if b.rough is not None:
                fx, fy = rough_block_residual(y[o:o + b.n], yp[o:o + b.n], X, Y, Xd, Yd, s * b.spin, out[o:o + b.n],
                                              fl.switch, fl.geo, fl.fields, fl.fv, fl.sym, b.rough)
            else:
                fx, fy = block_residual(y[o:o + b.n], yp[o:o + b.n], X, Y, Xd, Yd, s * b.spin, out[o:o + b.n],
                                        fl.switch, fl.geo, fl.fields, fl.fv, fl.sym)
            self.forces[k] = fx, fy
            f[b.support] += b.gx * fx + b.gy * fy
        out[Q0:V0] = qp - v
        out[V0:P0] = self.M @ vp + (self.Cw + s * self.G) @ v + self.Kw @ q - f
        out[P0] = yp[P0] - s

    def jacobian(self, tau, y, yp, cj, data):
        s, ds = self.speed(tau)
        Q0, V0, P0, nq = self.Q0, self.V0, self.P0, self.nq
        q, qp = y[Q0:V0], yp[Q0:V0]
        for b in self.blocks:
            X, Y = b.position(q)
            Xd, Yd = b.position(qp)
            fl = b.film
            o = b.offset
            if b.tilted:
                A, B = b.tilt_groups(q)
                Ad, Bd = b.tilt_groups(qp)
                tilted_block_jacobian(y[o:o + b.n], yp[o:o + b.n], X, Y, A, B, Xd, Yd, Ad, Bd, s * b.spin, cj, b.local,
                                      fl.switch, fl.geo, fl.fields, fl.extras, fl.fv, fl.sym, b.tilt)
                scatter_tilted_block(b.local, data, b.maps, b.ax, b.ay, b.aa, b.ab, b.gx, b.gy, b.ga, b.gb)
                continue
            if b.rough is not None:
                rough_block_jacobian(y[o:o + b.n], yp[o:o + b.n], X, Y, Xd, Yd, s * b.spin, cj, b.local, fl.switch,
                                     fl.geo, fl.fields, fl.extras, fl.fv, fl.sym, b.rough, b.contact)
            else:
                block_jacobian(y[o:o + b.n], yp[o:o + b.n], X, Y, Xd, Yd, s * b.spin, cj, b.local, fl.switch, fl.geo,
                               fl.fields, fl.extras, fl.fv, fl.sym)
            scatter_block(b.local, data, b.maps, b.ax, b.ay, b.gx, b.gy)
        kin_q, kin_v, mom_q, mom_v, mom_phi, phi_phi = self.rotor_pos
        data[kin_q] = cj
        data[kin_v] = -1.0
        data[mom_q] = self.Kw[self.q_mask]
        data[mom_v] = (self.Cw + s * self.G + cj * self.M)[self.v_mask]
        phi = y[P0]
        dphi = np.zeros(nq)
        for T, a in self.unbalance:
            c, sn = np.cos(phi + a), np.sin(phi + a)
            dphi -= T[0] * (-s * s * sn + ds * c) + T[1] * (s * s * c + ds * sn)
        data[mom_phi] = dphi[self.phi_rows]
        data[phi_phi] = cj
        for b in self.blocks:
            if b.rough is not None:  # the asperity stiffness on the momentum rows (after K's own entries)
                add_contact_stiffness(data, b.contact_pos, b.contact, b.ax, b.ay, b.gx, b.gy)

    # ------------------------------------------------------------------------------------------
    def consistent_yp(self, tau, y) -> np.ndarray:
        """The derivatives ``y'`` consistent with ``y`` (the film's u' from its equation, v' from the momentum)."""
        y = read_only(np.asarray(y, dtype=float))
        Q0, V0, P0 = self.Q0, self.V0, self.P0
        yp = np.zeros(self.n)
        yp[Q0:V0] = y[V0:P0]
        out = np.empty(self.n)
        self.residual(tau, y, read_only(yp), out)
        for b in self.blocks:
            fl, o = b.film, b.offset
            free = fl.op.free
            hd = fl.area * (fl.H if b.rough is None else b.rough.mean_gap) * fl.D
            yp[o:o + b.n][free] = -out[o:o + b.n][free] / hd[free]
        yp[V0:P0] = np.linalg.solve(self.M, -out[V0:P0])
        yp[P0] = self.speed(tau)[0]
        return yp

    def absolute_tolerance(self, atol) -> np.ndarray:
        """``atol`` per state: a film cell's unknown is p/p0 in the full film but (theta - 1) / r in the cavity
        (``JournalOrbit.absolute_tolerance``), so cells get ``atol min(1, 1/r)``; the rotor states ``atol``."""
        out = np.full(self.n, atol)
        for b in self.blocks:
            out[b.offset:b.offset + b.n] = atol * min(1.0, 1.0 / b.film.content_scale)
        return out

    def split(self, y):
        """(q [m], per-bearing (X, Y) in C_b) of a state."""
        q = np.asarray(y[self.Q0:self.V0]) * self.L
        return q, [b.position(np.asarray(y[self.Q0:self.V0])) for b in self.blocks]
