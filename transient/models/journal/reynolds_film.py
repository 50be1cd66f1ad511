"""The classical incompressible film with the Reynolds (Swift-Stieber) cavitation condition.

Same grid, stencil and dimensionless groups as the Elrod film (:mod:`transient.models.journal.kernels`):
``H = 1 + X cos(phi) + Y sin(phi)``, ``p = p_c + p0 P``, ``p0 = 6 mu omega (R/C)^2``, ``tau = omega t``.
With the content held at 1 the finite-volume conservation law of a free cell is the Reynolds equation
(divided by ``C omega``) integrated over the cell::

    G_i(P; X, Y, VX, VY) = R_i(P) + A_i (VX cos(phi_i) + VY sin(phi_i)) ,
    R_i = net outflow of  q = H / 2 e_phi - H^3 / 2 grad P     (:func:`transient.fv.reynolds.residual_kernel`)

i.e. ``div(H^3/2 grad P) = d(H/2)/dphi + dH/dtau`` (Reynolds 1886 in the bearing's groups). The cavitation
condition is the linear complementarity problem (Christopherson 1941; Cryer 1971; Kumar & Booker)::

    P_i >= 0,    G_i(P) >= 0,    P_i G_i(P) = 0      for every free cell i

(a cell either carries pressure and conserves volume, or sits at the cavitation pressure and *loses*
Couette flow -- a diverging film cannot stay full). On the grid it is the discrete form of the
Swift-Stieber condition ``p = dp/dn = 0`` at rupture. Groove cells are held at the supply pressure, the
bearing ends at the ambient pressure, exactly as in the Elrod film. ``G`` is affine in ``P`` with the
M-matrix ``J = dG/dP`` (the Poiseuille stencil), so the problem is solved by the primal-dual active-set
method (= semismooth Newton on ``min(P_i, G_i / J_ii) = 0``; Hintermueller, Ito & Kunisch 2002), which
for an M-matrix stops after finitely many steps with the exact discrete solution.

Sensitivities: on the converged active set (cells at ``P = 0``) the pressurised cells satisfy
``G_I = 0``, so ``dP_I/dq = -J_II^{-1} dG_I/dq`` for ``q = (X, Y, VX, VY)`` (the velocity columns give the
damping). Moving the rupture boundary adds nothing to first order because ``p = dp/dn = 0`` there
(checked against finite differences of the complementarity solve in tests/models/journal/test_reynolds_film.py).

The kernels are those of :mod:`transient.fv.reynolds` (numba) with ``P = u``, ``C = 1``,
``k = H^3 / 2`` (boundary layers: :func:`~transient.models.journal.kernels.conductances`), ``c = H / 2``;
the Jacobian (cells and the four journal columns) is analytic and sparse.

**Shear-thinning bulk** (``JournalBearing(rheology=Gecim(...))``, Jang): the Poiseuille flux is the layered
Gecim law at every face (:mod:`transient.models.journal.gecim_film`), so ``G`` is no longer affine in ``P``;
the same active-set iteration then is a semismooth Newton method on ``min(P_i, G_i(P) / J_ii(P)) = 0`` with
``G`` and ``J = dG/dP`` re-evaluated at every iterate (no finite termination; it stops on the residual).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from transient.fv.reynolds import ReynoldsOperator, jacobian_kernel, residual_kernel
from transient.fv.stencil import five_point_mask
from transient.models.journal.feeds import apply_feed_edges
from transient.models.journal.film import FilmBlock, film_state
from transient.models.journal.gecim_film import bulk_jacobian, bulk_residual, bulk_tables, prefetch
from transient.models.journal.kernels import N_ROTOR, conductances, film_force, position_derivatives
from transient.models.journal.scales import FilmScales
from transient.physics.layered import LayeredFilm


class ReynoldsFilm(FilmBlock):
    """The incompressible Reynolds-condition film of a bearing at one shaft speed (module docstring).

    Same interface as :class:`~transient.models.journal.film.Film` for the steady computations
    (``solve``, ``force``, ``force_sensitivity``, ``state``, ``residual``, ``jacobian_data``); the state
    ``u`` is the dimensionless pressure ``P = (p - p_c) / p0`` of every cell.
    """

    def __init__(self, grid, scales: FilmScales, law: LayeredFilm, n_extra=N_ROTOR):
        super().__init__(grid, scales, law)
        s = scales
        self.op = op = ReynoldsOperator(grid, n_extra=n_extra, upwind=False, boundary_P=s.u_ambient, boundary_C=1.0,
                                        diagonals=self.shear_thinning)
        op.u_fixed[~op.free] = self.u_supply  # each feed's cells at its pressure
        apply_feed_edges(op, s)
        self.n = n = op.n_cells
        self.free = op.free
        self.ones = np.ones(n)
        self.zero = np.zeros(n)
        self.H, self.k, self.c = np.empty(n), np.empty(n), np.empty(n)
        ne = op.n_extra
        self.dk_dq = np.zeros((ne, n))
        self.dc_dq = np.zeros((ne, n))
        self.no_dq = np.zeros((ne, n))
        self.fv = op.face_tuples + (op.no_face_k,)
        self.layers = (s.layer_gap, s.darcy)
        self.bulk = bulk_tables(op, law, s.clearance, s.omega * s.radius) if self.shear_thinning else None
        # the solve's iteration matrix for a Gecim bulk keeps the 5-point part of dG/dP (see solve)
        self.five_point = None if self.bulk is None else five_point_mask(op.stencil)

    # fields, residual and Jacobian --------------------------------------------------------------
    def _fields(self, X, Y):
        """H, k, c (:func:`~transient.models.journal.kernels.conductances`, boundary layers included) and (if
        the operator has extras) their position derivatives."""
        gap, darcy = self.layers
        conductances(X, Y, self.cosp, self.sinp, self.gap0, gap, darcy, self.H, self.k, self.c)
        if self.op.n_extra >= 2:
            position_derivatives(self.H, self.cosp, self.sinp, gap, darcy, self.dk_dq, self.dc_dq)
        if self.bulk is not None:  # the Poiseuille flux is the Gecim bulk's (gecim_film)
            self.k[:] = 0.0
            self.dk_dq[:] = 0.0

    def residual(self, u, X, Y, VX=0.0, VY=0.0, out=None):
        """``G(P)`` of the module docstring (free cells; ``P - P_supply`` on the groove cells)."""
        out = np.empty(self.n) if out is None else out
        u = np.ascontiguousarray(u, dtype=float)
        self._fields(X, Y)
        residual_kernel(u, u, self.ones, self.k, self.k, self.c, self.zero, False, *self.fv, out)
        if self.bulk is not None:
            prefetch(u, self.H, self.bulk)
            bulk_residual(u, self.H, self.free, self.bulk, out)
        out += np.where(self.free, self.area * (VX * self.cosp + VY * self.sinp), 0.0)
        return out

    def jacobian_data(self, u, X, Y, VX=0.0, VY=0.0, data=None):
        """CSC data (operator pattern order) of ``dG/dP`` and, with 4 extra unknowns, of the journal
        columns ``dG/dX, dG/dY`` (through ``k`` and ``c``) and ``dG/dVX, dG/dVY = A (cos, sin)``.
        ``G`` is affine in ``P`` for a Newtonian bulk (the matrix does not depend on ``u``), not for a Gecim bulk."""
        op = self.op
        data = np.empty(op.nnz) if data is None else data
        u = np.ascontiguousarray(u, dtype=float)
        self._fields(X, Y)
        jacobian_kernel(u, self.ones, self.ones, self.zero, self.k, self.zero, self.k, self.zero, self.c,
                        self.zero, self.dk_dq, self.dk_dq, self.dc_dq, self.no_dq, False, *self.fv,
                        op.pos_col_extra, data)
        if self.bulk is not None:
            prefetch(u, self.H, self.bulk)
            bulk_jacobian(u, self.ones, self.H, self.cosp, self.sinp, self.free, self.bulk, op.pos_col_extra,
                          op.n_extra, data)
        if op.n_extra >= 4:
            f = self.free
            pc = op.pos_col_extra[:self.n]
            data[pc[f, 2]] = (self.area * self.cosp)[f]
            data[pc[f, 3]] = (self.area * self.sinp)[f]
        return data

    def matrix(self, X, Y, u=None):
        """``dG/dP`` at ``u`` (default 0; only a Gecim bulk depends on it) as a CSC matrix (cells only)."""
        return self.op.matrix(self.jacobian_data(self.zero if u is None else u, X, Y))[:self.n, :self.n].tocsc()

    # the complementarity solve -----------------------------------------------------------------
    def complementarity(self, u, X, Y, VX=0.0, VY=0.0):
        """``min(P_i, G_i / J_ii)`` on the free cells, ``P - P_supply`` on the groove cells: zero exactly at
        the solution of the complementarity problem."""
        J = self.matrix(X, Y, u)
        g = self.residual(u, X, Y, VX, VY)
        return np.where(self.free, np.minimum(u, g / J.diagonal()), g)

    def solve(self, X, Y, VX=0.0, VY=0.0, u0=None, tol=1e-10, max_iter=200):
        """Pressure of the complementarity problem for a prescribed journal state; returns (P, iterations).

        Primal-dual active set: the cells with ``P_i <= G_i / J_ii`` are held at ``P = 0``, the others
        solve ``G = 0`` (one Newton step on them); repeat until the set does not change (finite for the affine
        ``G`` with the M-matrix ``J`` of a Newtonian bulk; a semismooth Newton iteration for a Gecim bulk). The
        start is ``u0`` if given, else the full (Sommerfeld) film with negative pressures kept (linearised at
        ``P = 0`` for a Gecim bulk). Converged when the active set is unchanged and
        ``max |min(P, G/J_ii)| <= tol max(1, |P|)``.

        For a Gecim bulk the iteration matrix is the 5-point part of the analytic ``dG/dP`` at each iterate (the
        corner entries, from the transverse gradients, are left out: an inexact Newton step whose LU is the
        Newtonian film's). On Jang's case (241 x 40) it takes the same 18 iterations as the full 9-point
        matrix, reaches the same pressure (force to 1e-12) and factorises in ~14 ms instead of ~21 ms; the residual
        test decides convergence either way.
        """
        n, free = self.n, self.free
        nonlinear = self.bulk is not None
        J = self.matrix(X, Y).tocsr()
        if u0 is None:
            u = -spla.splu(J.tocsc()).solve(self.residual(self.zero, X, Y, VX, VY))
        else:
            u = np.array(u0, dtype=float)
            u[~free] = self.u_supply
        active_prev = None
        I_n = sp.identity(n, format="csr")
        for it in range(1, max_iter + 1):
            if nonlinear:
                J = self.matrix(X, Y, u).multiply(self.five_point).tocsr()
            g = self.residual(u, X, Y, VX, VY)
            d = J.diagonal()
            active = free & (u <= g / d)
            phi = np.where(active, u, g)
            scale = max(1.0, float(np.max(np.abs(u))))
            if active_prev is not None and np.array_equal(active, active_prev) and \
                    float(np.max(np.abs(np.where(free, np.minimum(u, g / d), g)))) <= tol * scale:
                u[active] = 0.0
                return u, it - 1
            a = active.astype(float)
            M = (sp.diags(1.0 - a) @ J + sp.diags(a) @ I_n).tocsc()
            u = u - spla.splu(M).solve(phi)
            u[active] = 0.0
            active_prev = active
        raise RuntimeError(f"Reynolds-condition film solve did not converge in {max_iter} active-set steps at "
                           f"X={X:.4g}, Y={Y:.4g}")

    # forces and their sensitivities ------------------------------------------------------------
    def force(self, u, X, Y):
        """Dimensionless film force ``sym * sum P (cos, sin) A`` on the journal."""
        return film_force(np.ascontiguousarray(u, dtype=float), self.cosp, self.sinp, self.area, self.sym)

    def force_sensitivity(self, u, X, Y):
        """Fbar and dFbar/d(X, Y), dFbar/d(VX, VY) at a steady solution ``u`` on its active set (module
        docstring): ``J_II dP_I/dq = -dG_I/dq``, the cavitated and groove cells kept fixed."""
        if self.op.n_extra < 4:
            raise ValueError("force_sensitivity needs a film built with n_extra=4")
        n = self.n
        F = np.array(self.force(u, X, Y))
        Mfull = self.op.matrix(self.jacobian_data(u, X, Y))
        J = Mfull[:n, :n].tocsr()
        Gq = Mfull[:n, n:n + 4].toarray()
        inner = (self.free & (u > 0.0)).astype(float)
        M = (sp.diags(inner) @ J + sp.diags(1.0 - inner)).tocsc()
        du = -spla.splu(M).solve(inner[:, None] * Gq)
        gx = self.sym * self.cosp * self.area
        gy = self.sym * self.sinp * self.area
        dF = np.vstack([gx @ du, gy @ du])
        return F, dF[:, :2], dF[:, 2:]

    def linear_response(self, u, G_u, G_q):
        """``du`` of the steady film ``u`` for the columns ``G_q``, on its active set (as :meth:`force_sensitivity`):
        the pressurised free cells solve ``G_u du = -G_q``, the others keep their pressure."""
        inner = (self.free & (u > 0.0)).astype(float)
        M = (sp.diags(inner) @ G_u.tocsr() + sp.diags(1.0 - inner)).tocsc()
        return -spla.splu(M).solve(inner[:, None] * G_q)

    def pressure_slope(self, u):
        """``dP/du = 1``: the state is the pressure."""
        return self.ones

    def mass_flows(self, u, X, Y):
        raise NotImplementedError("mass_flows: the Reynolds-condition film is not mass-conserving "
                                  "(use cavitation='elrod')")

    def state(self, u, X, Y, iterations=0):
        """The SI :class:`~transient.models.journal.results.FilmState`. ``film_content`` is 1 everywhere:
        the incompressible film has no content variable (its cavitated cells are those at p = p_c)."""
        return film_state(self, u, X, Y, self.force(u, X, Y), u, self.ones, iterations)
