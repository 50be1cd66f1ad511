"""Mass-conserving (film-content) line-contact film for the Fischer-Burmeister-Newton-Schur iteration.

The line contact of :mod:`transient.models.roller.line_contact` in the fractional-film form of
Jakobsson-Floberg-Olsson / Elrod, as solved by FBNS (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.*
58, 2015; Hansen, Kacan, Frohnapfel & Codrignani, *Tribol. Lett.* 70, 2022, with the elastic film). Scaled
units of :mod:`transient.models.roller.ehl_problem` (x by b, p by p_h, h by b^2/R); per interior node ``I``
with control volume ``dx_I``::

    R_I = { e_{I+1/2} (p_{I+1} - p_I)/(x_{I+1} - x_I) - e_{I-1/2} (p_I - p_{I-1})/(x_I - x_{I-1})
            - lam (q_{I+1/2} - q_{I-1/2}) } / dx_I = 0,        e = rho h^3/eta,  m = rho theta h
    q_{I+1/2} = m_I + f_R (m_I - m_{I-1})     (the Reynolds residual's upwind flux, order 1 or 2)
    FB(p_I, 1 - theta_I) = 0,   FB(a, b) = a + b - sqrt(a^2 + b^2)      (p >= 0, theta <= 1, p (1 - theta) = 0)
    sum_I dx_I p_I / w_bar - 1 = 0                                        (the unknown h0)

with ``h = h0 + x^2/2 + K p`` (:class:`~transient.models.roller.ehl_problem.EHLFilm`'s influence matrix).
Where ``theta = 1`` the rows are those of the Reynolds-condition problem (``EHLFilm``); the two discrete
problems could differ only in the node where the film ruptures (on every chart point measured they do not:
``LineContact.steady`` checks the solution against the Reynolds-condition equations and finishes on them
otherwise). This form's Fischer-Burmeister pair is linear in the unknowns, so Newton's steps stay
meaningful from the Hertz pressure at any load.

:class:`LineContentFilm` gives the residual pieces as :class:`transient.models.point.ehl_problem.PointFilm`
(``equations``, ``fb_derivatives``) and the Schur matrix of its Newton step (``schur_matrix``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.models.ehl.reduced import schur
from transient.models.roller.ehl_problem import EHLFilm
from transient.models.roller.kernels import node_properties
from transient.models.ehl.complementarity import fb_derivatives, fb_residual

#: local Jacobian slots: centre, west, east, west-west, and their offsets in full nodes
N_LOCAL = 4
OFFSETS = np.array([0, -1, 1, -2])


@njit(cache=True, error_model="numpy")
def content_residual(p_full, t_full, x, props, lam, order2, res, scale, dp, dh, dt):
    """Reynolds rows ``res`` (module docstring), their scales (Poiseuille diagonal plus ``lam rho h / dx``)
    and the local derivatives ``dp``, ``dh``, ``dt`` (n, 4: slots centre, west, east, west-west) with
    respect to the full-node pressure, film and content; ``props`` from :func:`node_properties`
    (film-free quantities: rho, drho, eps, deps/dp, deps/dh, rho h, drho/dp h)."""
    nf = x.size
    rho, eps, deps_p, deps_h, rh, drh = props[0], props[2], props[3], props[4], props[5], props[6]
    dE = np.zeros(N_LOCAL)
    dM = np.zeros(N_LOCAL)
    dP = np.zeros(N_LOCAL)
    nb = np.zeros(N_LOCAL, np.int64)
    for I in range(1, nf - 1):
        r = I - 1
        dxR = x[I + 1] - x[I]
        dxL = x[I] - x[I - 1]
        A = 0.5 * (dxR + dxL)
        eR = 0.5 * (eps[I] + eps[I + 1])
        eL = 0.5 * (eps[I - 1] + eps[I])
        gR = (p_full[I + 1] - p_full[I]) / dxR
        gL = (p_full[I] - p_full[I - 1]) / dxL
        mC = rh[I] * t_full[I]
        mW = rh[I - 1] * t_full[I - 1]
        fR = 0.5 * dxR / dxL if order2 else 0.0
        fL = 0.0
        qL = mW
        if I >= 2:
            if order2:
                fL = 0.5 * dxL / (x[I - 1] - x[I - 2])
            qL = mW + fL * (mW - rh[I - 2] * t_full[I - 2])
        qR = mC + fR * (mC - mW)
        res[r] = (eR * gR - eL * gL - lam * (qR - qL)) / A
        scale[r] = (eR / dxR + eL / dxL + lam * rh[I]) / A
        for s in range(N_LOCAL):
            dE[s] = 0.0
            dM[s] = 0.0
            dP[s] = 0.0
            nb[s] = -1
        nb[0], nb[1], nb[2] = I, I - 1, I + 1
        dE[2] = 0.5 * gR
        dE[0] = 0.5 * (gR - gL)
        dE[1] = -0.5 * gL
        dP[2] = eR / dxR
        dP[0] = -(eR / dxR + eL / dxL)
        dP[1] = eL / dxL
        dM[0] = -lam * (1.0 + fR)
        dM[1] = lam * (1.0 + fR + fL)
        if I >= 2:
            nb[3] = I - 2
            dM[3] = -lam * fL
        for s in range(N_LOCAL):
            k = nb[s]
            if k < 0:
                dp[r, s] = 0.0
                dh[r, s] = 0.0
                dt[r, s] = 0.0
                continue
            dp[r, s] = (dP[s] + dE[s] * deps_p[k] + dM[s] * drh[k] * t_full[k]) / A
            dh[r, s] = (dE[s] * deps_h[k] + dM[s] * rho[k] * t_full[k]) / A
            dt[r, s] = dM[s] * rh[k] / A


class LineContentFilm:
    """The film-content form (module docstring) of an :class:`EHLFilm` line problem; unknowns
    ``u = [p (n), theta (n), h0]``."""

    def __init__(self, film: EHLFilm):
        if film.grid.two_d or film.elastic == "fft":
            raise ValueError("LineContentFilm: a line contact (1-D grid; dense, DC-FFT or rigid elasticity)")
        self.base = film
        self.x = film.grid.x
        self.nf = self.x.size
        self.n = self.nf - 2
        #: the dense influence matrix (None on the matrix-free DC-FFT film of :mod:`~transient.models.roller.line_fft`)
        self.K = film.K if film.elastic == "dense" else None
        self.matrix_free = film.elastic == "line-fft"
        self.weight = film.area_w
        self.props = np.empty((7, self.nf))

    def expand(self, u):
        """``(p_full, theta_full, h0)``; the boundary nodes carry ``p = 0``, ``theta = 1``."""
        n = self.n
        pf = np.zeros(self.nf)
        tf = np.ones(self.nf)
        pf[1:-1] = u[:n]
        tf[1:-1] = u[n: 2 * n]
        return pf, tf, float(u[-1])

    def equations(self, u, load_ratio=1.0):
        """Residual pieces at ``u`` (as :meth:`transient.models.point.ehl_problem.PointFilm.equations`)."""
        b = self.base
        pf, tf, h0 = self.expand(u)
        H = b.film(u[: self.n], h0)
        v, al, ln0, d, c1, c2 = b.rheo_args
        node_properties(pf, H, v, al, ln0, d, c1, c2, b.p_scale, self.props)
        n = self.n
        res, scale = np.empty(n), np.empty(n)
        dp, dh, dt = np.empty((n, N_LOCAL)), np.empty((n, N_LOCAL)), np.empty((n, N_LOCAL))
        content_residual(pf, tf, self.x, self.props, b.lam, b.order2, res, scale, dp, dh, dt)
        p = u[:n]
        fb, rad = fb_residual(p, u[n: 2 * n])
        return dict(H=H, res=res, scale=scale, dp=dp, dh=dh, dt=dt, fb=fb, rad=rad,
                    load=self.weight @ p - load_ratio)

    def fb_derivatives(self, u, e):
        """``(dFB/dp, dFB/dtheta)`` per node (:func:`~transient.models.ehl.complementarity.fb_derivatives`)."""
        return fb_derivatives(u[: self.n], u[self.n: 2 * self.n], e["rad"])

    def schur_matrix(self, e, b_p, b_t) -> np.ndarray:
        """Dense ``S = [[J_p diag(b_p) + J_theta diag(b_t), dR/dh0], [load row diag(b_p), 0]]``: the Newton
        matrix of the Reynolds rows and the load balance after the node-wise substitution
        ``dp = b_p z``, ``dtheta = b_t z`` (``J_p = dR/dp`` local plus through the film, ``J_theta = dR/dtheta``)."""
        if self.matrix_free:
            raise ValueError(f"{self.nf} nodes, DC-FFT elasticity: the Schur matrix is matrix-free (line_fft.SchurOperator)")
        S = np.empty((self.n + 1, self.n + 1))
        K = self.K if self.K is not None else np.zeros((self.nf, self.n))
        schur_kernel(e["dp"], e["dh"], e["dt"], K, b_p, b_t, self.weight, S)
        return S

    def storage_terms(self):
        """``(rho, rho h, d(rho h)/dp)`` at the interior nodes of the last :meth:`equations`: the pieces of the
        transient's storage ``q = rho theta h`` (:mod:`transient.models.roller.line_step`)."""
        return self.props[0, 1:-1], self.props[5, 1:-1], self.props[6, 1:-1]

    def local_columns(self) -> np.ndarray:
        """The interior node of each local slot of each row (n, 4; -1: none), as ``equations``' ``dt``."""
        col = np.arange(self.n)[:, None] + OFFSETS[None, :]
        return np.where((col >= 0) & (col < self.n), col, -1)

    def jacobian_product(self, e, v_p, v_t) -> np.ndarray:
        """``J_p v_p + J_theta v_t`` (the Reynolds rows' response to pressure and content changes)."""
        out = np.zeros(self.n)
        local_product(e["dh"], self.base.deformation(v_p), out)
        pad = np.zeros(self.nf)
        pad[1:-1] = v_p
        local_product(e["dp"], pad, out)
        pad[1:-1] = v_t
        local_product(e["dt"], pad, out)
        return out


@njit(cache=True)
def local_product(d, v_full, out):
    """``out[r] += sum_s d[r, s] v_full[r + 1 + offset_s]`` over the slots centre, west, east, west-west."""
    n = d.shape[0]
    for r in range(n):
        acc = 0.0
        for s in range(N_LOCAL):
            c = r + 1 + OFFSETS[s]
            if 0 <= c < v_full.size:
                acc += d[r, s] * v_full[c]
        out[r] += acc


@njit(cache=True)
def schur_kernel(dp, dh, dt, K, b_p, b_t, weight, S):
    """Fill ``S`` (:meth:`LineContentFilm.schur_matrix`); ``K`` (full nodes, interior nodes) the film's
    influence matrix, ``dp``, ``dh``, ``dt`` the local slots of :func:`content_residual`."""
    n = dp.shape[0]
    nf = K.shape[0]
    for r in range(n):
        row = S[r]
        for q in range(n + 1):
            row[q] = 0.0
        h0 = 0.0
        for s in range(N_LOCAL):
            c = r + 1 + OFFSETS[s]
            if c < 0 or c >= nf:
                continue
            v = dh[r, s]
            if v != 0.0:
                h0 += v
                kr = K[c]
                for q in range(n):
                    row[q] += v * kr[q]
            if 1 <= c <= n:
                row[c - 1] += dp[r, s]
        for q in range(n):
            row[q] *= b_p[q]
        for s in range(N_LOCAL):
            c = r + 1 + OFFSETS[s]
            if 1 <= c <= n:
                row[c - 1] += dt[r, s] * b_t[c - 1]
        row[n] = h0
    for q in range(n):
        S[n, q] = weight[q] * b_p[q]
    S[n, n] = 0.0


def schur_system(film, u, e):
    """``(S, r, (a_p, b_p, a_th, b_t))``: the Schur matrix and right-hand side of the Newton step at ``u``
    (Reynolds rows divided by their scales) and the node-wise back-substitution ``dp = a_p + b_p z``, ``dtheta = a_th + b_t z``."""
    elimination = schur(film, u, e)
    return scaled_schur(film, e, elimination) + (elimination,)


def scaled_schur(film, e, elimination):
    """``(S, r)``: the Schur matrix and right-hand side of the Newton step for the node-wise elimination
    ``elimination`` (:func:`~transient.models.ehl.reduced.schur`), the Reynolds rows divided by their scales."""
    a_p, b_p, a_th, b_t = elimination
    S = film.schur_matrix(e, b_p, b_t)
    # rows by their scales (the step is unchanged; the conditioning of S improves by many decades)
    S[:-1] /= e["scale"][:, None]
    return S, schur_rhs(film, e, a_p, a_th)


def schur_rhs(film, e, a_p, a_th):
    """The right-hand side of the Schur system (Reynolds rows divided by their scales)."""
    r = np.empty(film.n + 1)
    r[:-1] = (-e["res"] - film.jacobian_product(e, a_p, a_th)) / e["scale"]
    r[-1] = -e["load"] - film.weight @ a_p
    return r
