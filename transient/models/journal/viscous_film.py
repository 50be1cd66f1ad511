"""The Elrod film of a journal bearing with a viscosity that varies from cell to cell (the thermal film).

With the cell viscosity ``mu_i`` and the reference ``mu`` of the pressure unit ``p0 = 6 mu omega (R/C)^2``, the
Poiseuille conductance of a cell is its isoviscous one times the cell's fluidity ``f_i = mu / mu_i``::

    k_i = f_i (H_i^3 / 2 + darcy H_i),   q = theta H / 2 e_phi - k grad P

and a face takes the mean of its two cells' conductances (the stencil of :mod:`transient.fv.reynolds`); the Couette
flux does not depend on the viscosity. ``f = 1`` everywhere is the isoviscous film to the last bit. The fluidity is
a frozen field of the film (``ViscousFilm.fluidity``): the steady thermal solve
(:mod:`transient.models.journal.thd`) sets it from the temperatures between film solves, so the film's Jacobian
and its force sensitivities are at frozen temperatures.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.fv.reynolds import jacobian_kernel
from transient.models.journal.film import Film, read_only
from transient.models.journal.kernels import N_ROTOR, film_columns, position_derivatives, state_fields, stencil_flux


@njit(cache=True)
def viscous_film_residual(u, X, Y, VX, VY, rate, C_ref, out, switch, geo, fields, fv, fluidity):
    """:func:`~transient.models.journal.kernels.film_residual` with the Poiseuille conductances times ``fluidity``."""
    cosp, sinp, area = geo.cosp, geo.sinp, geo.area
    H, P, dP, C, D, dD, k, c, zero, R = fields
    free = fv.cells.free
    state_fields(u, X, Y, switch, geo, fields, fv)
    for i in range(u.size):
        k[i] *= fluidity[i]
    stencil_flux(u, fields, fv, out, 1.0)
    for i in range(u.size):
        if free[i]:
            out[i] += area[i] * (C[i] * (VX * cosp[i] + VY * sinp[i]) + rate * H[i] * (C[i] - C_ref[i]))


@njit(cache=True)
def viscous_film_jacobian(u, X, Y, VX, VY, rate, data, switch, geo, fields, extras, fv, fluidity):
    """:func:`~transient.models.journal.kernels.film_jacobian` with the Poiseuille conductances and their position
    derivatives times ``fluidity`` (frozen: no derivative of the viscosity)."""
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    state_fields(u, X, Y, switch, geo, fields, fv)
    for i in range(u.size):
        k[i] *= fluidity[i]
    if dk_dq.shape[0] > 0:
        fluidity_flux_jacobian(fluidity, 1.0, switch, geo, fields, extras, fv, data)
    else:
        jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq, dk_dq, dc_dq, no_dq, True, faces, boundary,
                        cells, face_k, pos_col, data)
    film_columns(VX, VY, rate, geo, fields, extras, fv, data)


@njit(cache=True)
def fluidity_flux_jacobian(fluidity, s, switch, geo, fields, extras, fv, data):
    """The film's flux columns (:func:`~transient.fv.reynolds.jacobian_kernel`: ``dR/du``, ``dR/d(X, Y)``) on the
    conductances in ``fields`` (already scaled: ``k`` by ``fluidity``, ``c`` by the speed ratio ``s``) with their
    position derivatives (:func:`~transient.models.journal.kernels.position_derivatives`) scaled likewise; the thermal
    film's, the driven content film's (:mod:`~transient.models.journal.driven_film`) and the thermal rotor's."""
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    position_derivatives(H, geo.cosp, geo.sinp, switch.layer_gap, switch.darcy, dk_dq, dc_dq)
    for i in range(H.size):
        for e in range(2):
            dk_dq[e, i] *= fluidity[i]
            dc_dq[e, i] *= s
    jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq[:2], dk_dq[:2], dc_dq[:2], no_dq[:2], True,
                    faces, boundary, cells, face_k, pos_col, data)


class ViscousFilm(Film):
    """The Elrod :class:`~transient.models.journal.film.Film` (Newtonian bulk) with a per-cell ``fluidity``
    ``mu / mu_i`` (ones: the isoviscous film) in its Poiseuille flux; every evaluation of the film (steady solve,
    force, sensitivities, flows, mass balance) goes through :meth:`residual` and :meth:`jacobian_data`."""

    def __init__(self, grid, scales, law, n_extra=N_ROTOR):
        super().__init__(grid, scales, law, n_extra)
        if self.shear_thinning:
            raise ValueError("a ViscousFilm takes a Newtonian bulk (rheology=None or Newtonian())")
        self.fluidity = np.ones(self.n)

    def residual(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, C_ref=None, out=None):
        out = np.empty(self.n) if out is None else out
        viscous_film_residual(read_only(u), X, Y, VX, VY, rate, self.zero if C_ref is None else C_ref, out,
                              self.switch, self.geo, self.fields, self.fv, self.fluidity)
        return out

    def jacobian_data(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, data=None):
        data = np.empty(self.op.nnz) if data is None else data
        viscous_film_jacobian(read_only(u), X, Y, VX, VY, rate, data, self.switch, self.geo, self.fields,
                              self.extras, self.fv, self.fluidity)
        return data
