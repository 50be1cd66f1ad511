"""The Elrod film of a rough journal bearing (mixed lubrication, steady evaluations): the average Reynolds equation
of Patir & Cheng in the mass-conserving film, and the asperity contact pressure of Greenwood & Tripp beside the film
pressure (coefficients: :mod:`transient.models.journal.roughness`).

The film equations are those of :func:`~transient.models.journal.kernels.film_residual` with the per-cell
coefficients of the average flow model in place of the smooth film's::

    G_i = R_i(k_x, k_z, c_x) + A_i theta_i (phi_c H')_i + rate A_i (h_T / C)_i (theta_i - theta_ref,i)

(``R`` the finite-volume net outflow, :func:`~transient.fv.reynolds.residual_kernel`; the squeeze term carries the
contact factor ``phi_c = d h_T / d h``). The content theta transports the Couette and shear flow (upwind), so in a
cavitated cell, where the pressure is flat and the Poiseuille flux vanishes, the flux is ``theta c_x``: the
striated film of Elrod carried at the mean gap. The force on the journal is the film's plus the asperities':
``F = sym sum (P_i + p_a,i / p0) (cos, sin) A_i``, and its sensitivities add the contact stiffness.

Pressure-viscosity (``Roughness.pressure_viscosity`` alpha > 0; C. Barus, Am. J. Sci. 45 (1893) 87-96): the
viscosity of a cell is ``mu0 exp(alpha p)`` at its film pressure p above cavitation, which divides the Poiseuille
conductances (``k_x, k_z <- k_x, k_z exp(-alpha p0 P)``, their slope ``d k / du = -alpha p0 (dP/du) k`` in the
Jacobian) and multiplies the Couette shear stress of the friction; the Couette and shear flows do not depend on the
viscosity. alpha = 0 is the isoviscous film, the same arithmetic.
"""

from __future__ import annotations

import numpy as np

from transient.fv.reynolds import jacobian_kernel, residual_kernel
from transient.models.journal.film import Film, film_state, read_only
from transient.models.journal.kernels import N_ROTOR, film_force, state_fields
from transient.models.journal.rough_orbit import rough_content_universal
from transient.models.journal.roughness import Roughness, contact_pressure, rough_coefficients


class RoughFilm(Film):
    """:class:`~transient.models.journal.film.Film` of a rough bearing (module docstring); the same interface."""

    def __init__(self, grid, scales, law, roughness: Roughness, n_extra=N_ROTOR):
        super().__init__(grid, scales, law, n_extra)
        self.roughness = roughness
        n, ne = self.n, self.op.n_extra
        self.k_axial = np.zeros(n)  # k_z (self.k holds k_x after every evaluation: the flows read both)
        self.dq = [np.zeros((ne, n)) for _ in range(3)]  # d k_x, d k_z, d c_x by (X, Y, VX, VY)
        self.no_dq = np.zeros((ne, n))
        self.no_du = np.zeros(n)
        self.alpha_p0 = roughness.pressure_viscosity * self.p0  # Barus exponent per unit of P
        self.viscosity_factor = np.ones(n)  # mu / mu0 of every cell at the state last evaluated
        self.dk_du = np.zeros(n)  # d k_x / du and d k_z / du (pressure-viscosity)
        self.dkz_du = np.zeros(n)
        self.coefficients = None

    def _fields(self, u, X, Y):
        """The smooth fields of ``u`` (P, theta, ...), then the average-flow coefficients in place of k and c."""
        state_fields(read_only(u), X, Y, self.switch, self.geo, self.fields, self.fv)
        rc = rough_coefficients(self.H, self.roughness, self.scales.clearance)
        self.c[:] = rc.cx
        self.coefficients = rc
        if self.alpha_p0 == 0.0:
            self.k[:] = rc.kx
            self.k_axial[:] = rc.kz
            return rc
        np.exp(self.alpha_p0 * self.P, out=self.viscosity_factor)
        self.k[:] = rc.kx / self.viscosity_factor
        self.k_axial[:] = rc.kz / self.viscosity_factor
        np.multiply(-self.alpha_p0 * self.dP, self.k, out=self.dk_du)
        np.multiply(-self.alpha_p0 * self.dP, self.k_axial, out=self.dkz_du)
        return rc

    def residual(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, C_ref=None, out=None):
        """G(u) of the module docstring; leaves the fields of ``u`` in the film's scratch arrays."""
        out = np.empty(self.n) if out is None else out
        rc = self._fields(u, X, Y)
        fv = self.fv
        residual_kernel(read_only(u), self.P, self.C, self.k, self.k_axial, self.c, self.zero, True, fv.faces,
                        fv.boundary, fv.cells, fv.face_k, out)
        free = fv.cells.free
        ref = self.zero if C_ref is None else C_ref
        squeeze = VX * self.cosp + VY * self.sinp
        out[free] += (self.area * (self.C * rc.phi_c * squeeze + rate * rc.mean_gap * (self.C - ref)))[free]
        return out

    def jacobian_data(self, u, X, Y, VX=0.0, VY=0.0, rate=0.0, data=None):
        """CSC data of dG/du and, with 4 extra unknowns, dG/d(X, Y) (rate = 0) and dG/d(VX, VY)."""
        data = np.empty(self.op.nnz) if data is None else data
        rc = self._fields(u, X, Y)
        fv, ex = self.fv, self.extras
        dkx, dkz, dcx = self.dq
        ne = dkx.shape[0]
        q = min(ne, 2)
        mu = self.viscosity_factor
        for e, trig in enumerate((self.cosp, self.sinp)[:q]):
            dkx[e] = rc.dkx * trig / mu
            dkz[e] = rc.dkz * trig / mu
            dcx[e] = rc.dcx * trig
        jacobian_kernel(self.P, self.dP, self.C, self.D, self.k, self.dk_du, self.k_axial, self.dkz_du, self.c,
                        self.zero, dkx[:q], dkz[:q], dcx[:q], self.no_dq[:q], True, fv.faces, fv.boundary, fv.cells,
                        fv.face_k, ex.pos_col, data)
        free, pos_c = fv.cells.free, fv.cells.pos_c
        squeeze = VX * self.cosp + VY * self.sinp
        a = self.area
        data[pos_c[free]] += (a * self.D * (rc.phi_c * squeeze + rate * rc.mean_gap))[free]
        if ne > 0:
            col = ex.pos_col[:self.n][free]  # CSC positions of (cell, extra column) of the free cells
            dphi = self.C * rc.dphi_c * squeeze * a  # the squeeze term's contact factor moves with H
            data[col[:, 0]] += (dphi * self.cosp)[free]
            data[col[:, 1]] += (dphi * self.sinp)[free]
            data[col[:, 2]] = (a * self.C * rc.phi_c * self.cosp)[free]
            data[col[:, 3]] = (a * self.C * rc.phi_c * self.sinp)[free]
        return data

    def content(self, u, X, Y):
        """The content state ``m = (h_T / C) theta(u)`` of the orbit's content formulation
        (:mod:`~transient.models.journal.rough_orbit`)."""
        self.residual(u, X, Y)
        return self.coefficients.mean_gap * self.C

    def universal(self, m, X, Y):
        """The inverse of :meth:`content` (groove cells: their prescribed u)."""
        y = np.concatenate([np.asarray(m, dtype=float), [X, Y]])
        u = np.empty(self.n)
        rough_content_universal(y, self.switch, self.geo, self.op.free, self.op.u_fixed,
                                self.roughness.sigma / self.scales.clearance, np.empty(self.n), u)
        return u

    def mass_flows(self, u, X, Y):
        """:meth:`Film.mass_flows <transient.models.journal.film.Film.mass_flows>` of the average flow: the content
        ``sym sum A (h_T / C) theta`` and the ends' flux with the axial conductance k_z."""
        R = self.residual(u, X, Y)
        op, free = self.op, self.op.free
        M = self.sym * float(np.sum((self.area * self.coefficients.mean_gap * self.C)[free]))
        total = self.sym * float(np.sum(R[free]))
        b = op.bcell
        ok = free[b]
        if np.any(op.bdir[ok] != 1):
            raise NotImplementedError("mass_flows assumes Dirichlet faces only at the bearing ends")
        ends = self.sym * float(np.sum((-self.k_axial[b] * (op.bP - self.P[b]) / op.bd * op.bs)[ok]))
        return M, ends, total - ends

    def contact(self, X, Y):
        """Asperity pressure [Pa] of every cell and its slope d p_a / dH [Pa] at the journal position (X, Y)."""
        H = self.gap0 + X * self.cosp + Y * self.sinp
        return contact_pressure(H, self.roughness, self.scales.clearance)

    def contact_force(self, X, Y):
        """Dimensionless asperity force on the journal, ``sym sum (p_a / p0) (cos, sin) A``."""
        pa, _ = self.contact(X, Y)
        return np.array(film_force(pa / self.p0, self.cosp, self.sinp, self.area, self.sym))

    def force(self, u, X, Y):
        """Dimensionless force on the journal: film + asperities."""
        self.residual(u, X, Y)
        return np.array(film_force(self.P, self.cosp, self.sinp, self.area, self.sym)) + self.contact_force(X, Y)

    def force_sensitivity(self, u, X, Y):
        """:meth:`Film.force_sensitivity <transient.models.journal.film.Film.force_sensitivity>` with the asperity
        force and its stiffness ``sym sum (dp_a/dH / p0) (cos, sin) (cos, sin) A``."""
        F, dF_dq, dF_dv = super().force_sensitivity(u, X, Y)
        _, dpa = self.contact(X, Y)
        g = self.sym * dpa / self.p0 * self.area
        c, s = self.cosp, self.sinp
        dF_dq = dF_dq + np.array([[g @ (c * c), g @ (c * s)], [g @ (s * c), g @ (s * s)]])
        return F, dF_dq, dF_dv

    def state(self, u, X, Y, iterations=0):
        """The SI :class:`~transient.models.journal.results.FilmState` with the asperity load and the boundary
        friction (:func:`~transient.models.journal.film.film_state`)."""
        F = self.force(u, X, Y)
        pa, _ = self.contact(X, Y)
        Fc = self.contact_force(X, Y) * self.force_scale
        normal = self.sym * float(pa @ self.area) * self.scales.radius ** 2  # sum of |p_a dA| [N]
        return film_state(self, u, X, Y, F, self.P, self.C, iterations,
                          contact=(pa, (float(Fc[0]), float(Fc[1])), normal, self.roughness.boundary_friction),
                          viscosity_factor=None if self.alpha_p0 == 0.0 else self.viscosity_factor)
