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

Winkler bore (``Roughness.bore_compliance`` K > 0; the elastic foundation model, K. L. Johnson, Contact Mechanics,
1985): the bore of a cell gives way by its film and asperity pressures, so the cell's gap is
``h = h_rigid + K (p + p_a(h))``, solved per cell (a scalar Newton: ``h - K p_a(h)`` rises and is concave, so the
iterates from below the root climb monotonically to it; they start at ``h_rigid + K p``, held above -10 sigma). Every
coefficient then moves with the pressure through ``dH/du = kappa (dP/du) / (1 - kappa p_a'(H) / p0)``
(``kappa = K p0 / C``) and with the journal position through ``dH/dX = cos / (1 - kappa p_a' / p0)``: the Poiseuille
conductances in the kernel's cell slopes, the Couette coefficient by :func:`couette_slope_kernel`, the asperity force
in :meth:`RoughFilm.force_sensitivity`.
K = 0 is the rigid bore, the same arithmetic.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla
from numba import njit

from transient.fv.reynolds import jacobian_kernel, residual_kernel
from transient.models.journal.film import Film, film_state, read_only
from transient.models.journal.kernels import N_ROTOR, film_force, state_fields
from transient.models.journal.rough_orbit import rough_content_universal
from transient.models.journal.roughness import Roughness, contact_pressure, rough_coefficients

ELASTIC_NEWTON_ITERATIONS = 60  # the per-cell gap solve converges monotonically, in a few steps at these slopes
ELASTIC_GAP_FLOOR = 10.0  # [sigma] the per-cell gap solve's iterates stay above -10 sigma (a root lies far above)


@njit(cache=True)
def couette_slope_kernel(C, cx, dcx_du, faces, cells, data):
    """Adds to the CSC ``data`` of dR/du the terms of the circumferential Couette flux ``G = c_f C_up`` (content
    upwind, ``c_f = (c_L + c_R) / 2``) from the cells' own slopes ``dcx_du``: ``dG/du_L = dc_L C_up / 2``, the same
    for R (the interior faces of :data:`~transient.fv.reynolds.FACE_TUPLES`; the ends carry no Couette flux)."""
    fL, fR, fdir, _, fs, fpos = faces
    free = cells[0]
    for f in range(fL.size):
        if fdir[f] != 0:
            continue
        L = fL[f]
        R = fR[f]
        cup = C[L] if cx[L] + cx[R] >= 0.0 else C[R]
        dFL = 0.5 * dcx_du[L] * cup * fs[f]
        dFR = 0.5 * dcx_du[R] * cup * fs[f]
        if free[L]:
            data[fpos[f, 0]] += dFL
            data[fpos[f, 1]] += dFR
        if free[R]:
            data[fpos[f, 2]] -= dFL
            data[fpos[f, 3]] -= dFR


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
        self.kappa = roughness.bore_compliance * self.p0 / scales.clearance  # gap per unit of P (Winkler bore)
        self.dH_du = np.zeros(n)  # d H / du of every cell (Winkler bore)
        self.dH_dq = np.ones(n)  # d H / d(X, Y) over (cos, sin): 1 / (1 - kappa p_a'(H) / p0)
        self.dcx_du = np.zeros(n)
        self.coefficients = None
        #: the Couette flux's share of the film speed's (1; 0: the journal at rest, :mod:`~.rest`)
        self.couette = 1.0

    def _fields(self, u, X, Y):
        """The smooth fields of ``u`` (P, theta, ...), then the average-flow coefficients in place of k and c."""
        state_fields(read_only(u), X, Y, self.switch, self.geo, self.fields, self.fv)
        if self.kappa != 0.0:
            self._elastic_gap()
        rc = rough_coefficients(self.H, self.roughness, self.scales.clearance)
        if self.couette != 1.0:  # the journal at rest: no Couette flux, nor its slopes
            rc = rc._replace(cx=rc.cx * self.couette, dcx=rc.dcx * self.couette)
        self.c[:] = rc.cx
        self.coefficients = rc
        if self.alpha_p0 == 0.0 and self.kappa == 0.0:
            self.k[:] = rc.kx
            self.k_axial[:] = rc.kz
            return rc
        if self.alpha_p0 != 0.0:
            np.exp(self.alpha_p0 * self.P, out=self.viscosity_factor)
        mu = self.viscosity_factor
        self.k[:] = rc.kx / mu
        self.k_axial[:] = rc.kz / mu
        self.dk_du[:] = -self.alpha_p0 * self.dP * self.k + rc.dkx * self.dH_du / mu
        self.dkz_du[:] = -self.alpha_p0 * self.dP * self.k_axial + rc.dkz * self.dH_du / mu
        self.dcx_du[:] = rc.dcx * self.dH_du
        return rc

    def _elastic_gap(self):
        """The Winkler bore's gap (module docstring) in place of the rigid ``self.H``, with ``dH/du`` and
        ``dH/dq``."""
        p0, C, r = self.p0, self.scales.clearance, self.roughness
        Hr = self.H + self.kappa * self.P
        floor = -ELASTIC_GAP_FLOOR * r.sigma / C  # below every root: asperities pressed 10 sigma into each other
        H = np.maximum(Hr, floor)
        for _ in range(ELASTIC_NEWTON_ITERATIONS):
            pa, dpa = contact_pressure(H, r, C)
            step = (H - Hr - self.kappa * pa / p0) / (1.0 - self.kappa * dpa / p0)
            H = np.maximum(H - step, floor)
            if np.max(np.abs(step) / (1.0 + np.abs(H))) <= 1e-13:
                break
        else:
            raise RuntimeError(f"Winkler bore: the gap did not converge in {ELASTIC_NEWTON_ITERATIONS} iterations")
        _, dpa = contact_pressure(H, r, C)
        self.dH_dq[:] = 1.0 / (1.0 - self.kappa * dpa / p0)
        self.dH_du[:] = self.kappa * self.dP * self.dH_dq
        self.H[:] = H

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
        hq = self.dH_dq
        for e, trig in enumerate((self.cosp, self.sinp)[:q]):
            dkx[e] = rc.dkx * trig * hq / mu
            dkz[e] = rc.dkz * trig * hq / mu
            dcx[e] = rc.dcx * trig * hq
        jacobian_kernel(self.P, self.dP, self.C, self.D, self.k, self.dk_du, self.k_axial, self.dkz_du, self.c,
                        self.zero, dkx[:q], dkz[:q], dcx[:q], self.no_dq[:q], True, fv.faces, fv.boundary, fv.cells,
                        fv.face_k, ex.pos_col, data)
        if self.kappa != 0.0:
            couette_slope_kernel(self.C, self.c, self.dcx_du, fv.faces, fv.cells, data)
        free, pos_c = fv.cells.free, fv.cells.pos_c
        squeeze = VX * self.cosp + VY * self.sinp
        a = self.area
        data[pos_c[free]] += (a * self.D * (rc.phi_c * squeeze + rate * rc.mean_gap))[free]
        if self.kappa != 0.0 and rate != 0.0:  # the storage's slope through the bore's give: d(h_T/C)/du = phi_c dH/du
            data[pos_c[free]] += (a * rate * rc.phi_c * self.C * self.dH_du)[free]
        if ne > 0:
            col = ex.pos_col[:self.n][free]  # CSC positions of (cell, extra column) of the free cells
            dphi = self.C * rc.dphi_c * squeeze * a * hq  # the squeeze term's contact factor moves with H
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
        """Asperity pressure [Pa] of every cell and its slope d p_a / dH [Pa] at the journal position (X, Y); with a
        Winkler bore at the gap of the state last evaluated (its gap moves with the film pressure)."""
        H = self.H if self.kappa != 0.0 else self.gap0 + X * self.cosp + Y * self.sinp
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
        if self.kappa != 0.0:
            return self._elastic_force_sensitivity(u, X, Y)
        F, dF_dq, dF_dv = super().force_sensitivity(u, X, Y)
        _, dpa = self.contact(X, Y)
        g = self.sym * dpa / self.p0 * self.area
        c, s = self.cosp, self.sinp
        dF_dq = dF_dq + np.array([[g @ (c * c), g @ (c * s)], [g @ (s * c), g @ (s * s)]])
        return F, dF_dq, dF_dv

    def _elastic_force_sensitivity(self, u, X, Y):
        """:meth:`force_sensitivity` with a Winkler bore: the asperity pressure moves with the film's unknowns through
        the gap (``dp_a/du = p_a' dH/du``) and with the position through ``dH/dq``."""
        if self.op.n_extra < 4:
            raise ValueError("force_sensitivity needs a film built with n_extra=4")
        n = self.n
        F = self.force(u, X, Y)
        M = self.op.matrix(self.jacobian_data(u, X, Y))
        du = -spla.splu(M[:n, :n].tocsc()).solve(M[:n, n:n + 4].toarray())
        _, dpa = self.contact(X, Y)
        w = self.sym * self.area
        ga = dpa / self.p0 * w
        c, s = self.cosp, self.sinp
        g = (self.dP * w + ga * self.dH_du)
        dF = np.vstack([(g * c) @ du, (g * s) @ du])
        gq = ga * self.dH_dq
        dF[:, :2] += np.array([[gq @ (c * c), gq @ (c * s)], [gq @ (s * c), gq @ (s * s)]])
        return F, dF[:, :2], dF[:, 2:]

    def state(self, u, X, Y, iterations=0):
        """The SI :class:`~transient.models.journal.results.FilmState` with the asperity load and the boundary
        friction (:func:`~transient.models.journal.film.film_state`)."""
        F = self.force(u, X, Y)
        pa, _ = self.contact(X, Y)
        Fc = self.contact_force(X, Y) * self.force_scale
        normal = self.sym * float(pa @ self.area) * self.scales.radius ** 2  # sum of |p_a dA| [N]
        return film_state(self, u, X, Y, F, self.P, self.C, iterations,
                          contact=(pa, (float(Fc[0]), float(Fc[1])), normal, self.roughness.boundary_friction),
                          viscosity_factor=None if self.alpha_p0 == 0.0 else self.viscosity_factor,
                          gap=None if self.kappa == 0.0 else self.H)
