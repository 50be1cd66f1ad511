"""Rough (mixed-lubrication) bearings in the rotor system: each rough bearing's film block with the Patir-Cheng flow
factors and the contact factor, its Greenwood-Tripp asperity force on its node's equations, on both of the system's
paths (IDA, :mod:`transient.models.rotor.model`; the content BDF, :mod:`transient.models.rotor.content_form`).

The per-cell physics is the rough journal orbit's (:mod:`transient.models.journal.rough_orbit`: the coefficients,
the asperity table, the flux and its Jacobian are its kernels, imported). A rough block of the system, at its node's
position ``(X, Y)`` and velocity ``(X', Y')`` (its clearance), shaft speed ratio ``s``::

    A_i (h_T,i D_i u_i' + theta_i phi_c,i (X' cos + Y' sin)) + R_i(k_x, k_z, s c_x) = 0      (universal, IDA)
    A_i m_i' + R_i = 0,   m_i = (h_T,i / C) theta_i                                         (content, BDF)
    Fbar = sym sum_i (P_i + p_a,i / p0) (cos, sin) A_i                                      (film + asperities)

The asperity force depends on the node's position directly: its stiffness ``sym sum (dp_a/dH / p0) (cos, sin)
(cos, sin) A`` enters the momentum rows on the node's rotor coordinates (``dF_r/dq_j -= gx_r (k_xx ax_j + k_xy ay_j)
+ gy_r (k_xy ax_j + k_yy ay_j)``), entries the system pattern holds for a rough block's support
(:func:`contact_mask`). ``s`` is the system's (a speed function of time); the speed law of the orbit's kernels
(``RoughCells.knots``) is not used here.

The content BDF's Newton (:func:`~transient.models.rotor.rough_content.rough_rotor_newton`) takes ``args = (films,
roughs, rotor)``: the system's :class:`~transient.models.rotor.content_newton.FilmArgs`, per film ``(cells, contact,
contact_pos)`` (its :class:`~transient.models.journal.rough_orbit.RoughCells`, the contact stiffness scratch and its
positions; every film rough: the tuple is of one numba type) and the rotor rows
(:class:`~transient.models.rotor.content_newton.RotorArgs`): :func:`~transient.models.rotor.rough_content.content_args`.

Records of a run (:func:`tribology_sample`): per bearing the asperity load [N], the friction torque [N m] (film shear
plus ``mu_b`` times the asperity normal load), the minimum film [m] and the peak asperity pressure [Pa]; the contact
events where the film parameter ``h_min / sigma`` crosses ``CONTACT_LAMBDA``
(:func:`~transient.models.journal.orbit.contact_events`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.models.journal.film import film_geometry, read_only
from transient.models.journal.kernels import film_force
from transient.models.journal.orbit import contact_events
from transient.models.journal.rough_orbit import (CONTACT_LAMBDA, orbit_tribology, rough_cells, rough_flux,
                                                  rough_flux_jacobian, rough_force, rough_state_fields)


# ------------------------------------------------------------------------------------------------- set-up
def attach_rough(blocks) -> bool:
    """Give every :class:`~transient.models.rotor.model.BearingBlock` its ``rough`` cells (``RoughCells`` of a rough
    bearing, None of a smooth one) and its contact stiffness ``contact`` (k_xx, k_xy, k_yy) scratch; True when any is
    rough."""
    any_rough = False
    for b in blocks:
        r = getattr(b.bearing, "roughness", None)
        b.rough = None if r is None else rough_cells(r, b.bearing.clearance, b.film.p0, b.film.n)
        b.contact = np.zeros(3)
        any_rough |= r is not None
    return any_rough


def contact_mask(blocks, nq) -> np.ndarray:
    """(nq, nq) bool: the momentum rows' entries in the rotor coordinates that a rough block's contact stiffness
    fills (its support by its support)."""
    mask = np.zeros((nq, nq), dtype=bool)
    for b in blocks:
        if b.rough is not None:
            mask[np.ix_(b.support, b.support)] = True
    return mask


def contact_positions(blocks, q_mask, mom_q) -> None:
    """Each rough block's ``contact_pos`` (support x support): the CSC positions of its contact stiffness among the
    momentum rows' entries ``mom_q`` (row-major order of ``q_mask``)."""
    index = -np.ones(q_mask.shape, dtype=np.int64)
    r, c = np.nonzero(q_mask)
    index[r, c] = np.arange(r.size)
    for b in blocks:
        b.contact_pos = np.zeros((0, 0), dtype=np.int64) if b.rough is None else \
            np.ascontiguousarray(np.asarray(mom_q)[index[np.ix_(b.support, b.support)]], dtype=np.int64)


# ------------------------------------------------------------------------------------------------- one block
@njit(cache=True)
def rough_block_residual(u, up, X, Y, Xd, Yd, s, out, switch, geo, fields, fv, sym, rough):
    """The rough block's residual (universal form, module docstring) into ``out``; returns the film + asperity force
    ``(Fx, Fy)``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    free = fv.cells.free
    rough_state_fields(u, X, Y, switch, geo, fields, fv, rough)
    R = fields.R
    rough_flux(s, u, fields, fv, rough, R)
    C, D, hT, pc = fields.C, fields.D, rough.mean_gap, rough.phi_c
    for i in range(free.size):
        if free[i]:
            out[i] = area[i] * (hT[i] * D[i] * up[i] + C[i] * pc[i] * (Xd * cosp[i] + Yd * sinp[i])) + R[i]
        else:
            out[i] = up[i]
    return rough_force(fields.P, geo, rough, sym)


@njit(cache=True)
def rough_block_jacobian(u, up, X, Y, Xd, Yd, s, cj, local, switch, geo, fields, extras, fv, sym, rough, contact):
    """``dF/du + cj dF/du'`` of :func:`rough_block_residual` in the film's arrow pattern (``local``, as
    :func:`~transient.models.rotor.kernels.block_jacobian`: the cell block, ``dF_i/d(X, Y)`` in extra columns 0 and
    1, ``dFx/du_j``, ``dFy/du_j`` in extra rows 2 and 3); the asperities' ``d Fbar/d(X, Y)`` into ``contact`` =
    (k_xx, k_xy, k_yy)::

        dF_i/du_i += A_i (h_T D'_i u_i' + D_i phi_c H'_i + cj h_T D_i)
        dF_i/dX   += A_i cos (phi_c D_i u_i' + theta_i phi_c' H'_i + cj theta_i phi_c)
    """
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    pos_row, pos_col = extras.pos_row, extras.pos_col
    free, pos_c = fv.cells.free, fv.cells.pos_c
    rough_state_fields(u, X, Y, switch, geo, fields, fv, rough)
    rough_flux_jacobian(s, geo, fields, extras, fv, rough, local)
    C, D, dD, dP = fields.C, fields.D, fields.dD, fields.dP
    hT, pc, dpc, dpa = rough.mean_gap, rough.phi_c, rough.dphi_c, rough.dpa
    kxx = 0.0
    kxy = 0.0
    kyy = 0.0
    for i in range(free.size):
        a = area[i]
        if free[i]:
            hd = Xd * cosp[i] + Yd * sinp[i]
            local[pos_c[i]] += a * (hT[i] * dD[i] * up[i] + D[i] * pc[i] * hd + cj * hT[i] * D[i])
            w = a * (pc[i] * D[i] * up[i] + C[i] * dpc[i] * hd + cj * C[i] * pc[i])
            local[pos_col[i, 0]] += w * cosp[i]
            local[pos_col[i, 1]] += w * sinp[i]
        else:
            local[pos_c[i]] = cj
        g = sym * dP[i] * a
        local[pos_row[2, i]] = g * cosp[i]
        local[pos_row[3, i]] = g * sinp[i]
        k = sym * dpa[i] * a
        kxx += k * cosp[i] * cosp[i]
        kxy += k * cosp[i] * sinp[i]
        kyy += k * sinp[i] * sinp[i]
    contact[0] = kxx
    contact[1] = kxy
    contact[2] = kyy


@njit(cache=True)
def add_contact_stiffness(data, pos, contact, ax, ay, gx, gy):
    """The asperity stiffness of a block (``contact`` = k_xx, k_xy, k_yy of ``d Fbar/d(X, Y)``) added to the momentum
    rows at ``pos`` (support x support): ``dF_r/dq_j -= gx_r (k_xx ax_j + k_xy ay_j) + gy_r (k_xy ax_j + k_yy ay_j)``
    (the force enters row ``r`` as ``-(gx_r Fx + gy_r Fy)``, ``X = ax . q``)."""
    kxx, kxy, kyy = contact[0], contact[1], contact[2]
    for r in range(gx.size):
        for j in range(ax.size):
            data[pos[r, j]] -= gx[r] * (kxx * ax[j] + kxy * ay[j]) + gy[r] * (kxy * ax[j] + kyy * ay[j])


# ------------------------------------------------------------------------------------------------- records
#: The series a run of a system with rough bearings records at every output (per bearing).
TRIBOLOGY = ("contact_load", "friction_torque", "min_film", "contact_pressure")


def tribology_sample(dae, y, speed_rpm) -> dict:
    """A run's tribology records at the state ``y`` (universal layout) and shaft speed [rpm]: per bearing (the
    system's order) ``contact_load`` [N], ``friction_torque`` [N m], ``min_film`` [m], ``contact_pressure`` [Pa]
    (the peak asperity pressure); a smooth bearing's contact entries 0 (its torque
    :func:`~transient.models.journal.rough_orbit.orbit_tribology`'s)."""
    q = np.asarray(y[dae.Q0:dae.V0])
    out = {k: [] for k in TRIBOLOGY}
    for b in dae.blocks:
        X, Y = b.position(q)
        u = y[b.offset:b.offset + b.n]
        if b.rough is None:
            t = orbit_tribology(b.film, b.bearing, u, X, Y, speed_rpm * b.spin)
            t["contact_pressure"] = 0.0
        else:
            t = rough_tribology(b, u, X, Y, speed_rpm)
        for k in ("contact_load", "friction_torque", "contact_pressure"):
            out[k].append(t[k])
        out["min_film"].append(b.bearing.clearance * (1.0 - np.sqrt(b.reach2(q))))
    return out


def rough_block_force(b, u, X, Y) -> tuple:
    """The film + asperity force (dimensionless, :func:`rough_block_residual`) of rough block ``b`` at its film ``u``
    and position (X, Y) [C]; leaves the block's fields of that state in its film's scratch."""
    fl = b.film
    return rough_block_residual(read_only(np.ascontiguousarray(u, dtype=float)), read_only(np.zeros(b.n)), X, Y, 0.0,
                                0.0, 0.0, np.empty(b.n), fl.switch, fl.geo, fl.fields, fl.fv, fl.sym, b.rough)


def rough_tribology(b, u, X, Y, speed_rpm) -> dict:
    """The records of rough block ``b`` at its film ``u`` and position (X, Y) [C], on its kernels' fields (the
    asperity pressure of the orbit's table): the friction torque on the journal
    ``R^3 sym sum (mu U / h + (h / 2) dp/ds) min(theta, 1) A + R mu_b sum p_a dA`` (the Newtonian wall stress of
    :func:`~transient.models.journal.film.wall_friction`, ``U = Omega R``, the rough film's bulk), the asperity
    load [N] and the peak asperity pressure [Pa]."""
    fl, sc = b.film, b.film.scales
    rough_block_force(b, u, X, Y)  # the block's fields at this state
    R = sc.radius
    h, G, _ = film_geometry(fl, X, Y, fl.P)
    U = speed_rpm * np.pi / 30.0 * R
    theta = np.minimum(fl.grid.to_2d(np.asarray(fl.C, dtype=float)), 1.0)
    shear = fl.sym * float(np.sum((fl.law.viscosity * U / h + 0.5 * h * G) * theta * fl.grid.to_2d(fl.area))) * R ** 2
    pa = b.rough.pa
    normal = fl.sym * float(pa @ fl.area) * fl.p0 * R ** 2
    Fc = np.array(film_force(pa, fl.cosp, fl.sinp, fl.area, fl.sym)) * fl.force_scale
    return dict(friction_torque=R * (shear + b.bearing.roughness.boundary_friction * normal),
                contact_load=float(np.hypot(*Fc)), contact_pressure=fl.p0 * float(np.max(pa)))


def rough_records(a, dae, nodes) -> dict:
    """The :class:`~transient.models.rotor.results.RotorRunResult` fields of the recorded ``TRIBOLOGY`` series ``a``
    (n_t, n_bearings) and the contact events of the rough bearings (``h_min / sigma`` across ``CONTACT_LAMBDA``,
    :func:`~transient.models.journal.orbit.contact_events`), in time order."""
    nb = len(dae.blocks)
    out = {k: np.asarray(a[k], dtype=float).reshape(-1, nb) for k in TRIBOLOGY}
    events = []
    for k, (node, b) in enumerate(zip(nodes, dae.blocks)):
        if b.rough is not None:
            lam = out["min_film"][:, k] / b.bearing.roughness.sigma
            events += [(t, node, what) for t, what in contact_events(a["t"], lam, CONTACT_LAMBDA)]
    out["contact_events"] = sorted(events, key=lambda e: e[0])
    return out
