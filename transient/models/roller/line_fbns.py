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

The rows are the one rows kernel's (:func:`~transient.models.ehl.rows.rows_kernel`, on one row: the
Reynolds-condition film's, with the content). :class:`LineContentFilm` gives the residual pieces as
:class:`transient.models.point.ehl_problem.PointFilm` (``equations``, ``fb_derivatives``) and the Schur matrix of
its Newton step (``schur_matrix``, :func:`~transient.models.ehl.reduced.schur_rows`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from transient.models.ehl.complementarity import CavitationRows, fb_residual
from transient.models.ehl.reduced import schur, schur_rows
from transient.models.ehl.rows import LINE_SLOTS, rows_kernel
from transient.models.roller.ehl_problem import EHLFilm

#: local Jacobian slots (:data:`~transient.models.ehl.rows.LINE_SLOTS`): centre, west, east, west-west, and their
#: offsets in full nodes
N_LOCAL = 4
OFFSETS = np.array([0, -1, 1, -2])


class LineContentFilm(CavitationRows):
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
        #: interior (``colp``) and full (``colh``) node of each stored slot of each row (-1: none)
        stored = LINE_SLOTS >= 0
        self.colp, self.colh = film.colp[:, stored], film.colh[:, stored]

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
        n = self.n
        res, scale = np.empty(n), np.empty(n)
        dp, dh, dt = np.empty((n, N_LOCAL)), np.empty((n, N_LOCAL)), np.empty((n, N_LOCAL))
        nf = self.nf
        rows_kernel(pf.reshape(1, nf), H.reshape(1, nf), tf.reshape(1, nf), self.x, b.y_nodes, b.rs, b.lam, False,
                    b.scheme_code, v, al, ln0, d, c1, c2, b.p_scale, True, res, dp, dh, dt, scale, self.props,
                    LINE_SLOTS)
        p = u[:n]
        fb, rad = fb_residual(p, u[n: 2 * n])
        return dict(H=H, res=res, scale=scale, dp=dp, dh=dh, dt=dt, fb=fb, rad=rad,
                    load=self.weight @ p - load_ratio)

    def schur_matrix(self, e, b_p, b_t) -> np.ndarray:
        """Dense ``S = [[J_p diag(b_p) + J_theta diag(b_t), dR/dh0], [load row diag(b_p), 0]]``: the Newton
        matrix of the Reynolds rows and the load balance after the node-wise substitution
        ``dp = b_p z``, ``dtheta = b_t z`` (``J_p = dR/dp`` local plus through the film, ``J_theta = dR/dtheta``)."""
        if self.matrix_free:
            raise ValueError(f"{self.nf} nodes, DC-FFT elasticity: the Schur matrix is matrix-free (line_fft.SchurOperator)")
        S = np.empty((self.n + 1, self.n + 1))
        elastic = self.K is not None
        schur_rows(e["dp"], e["dh"], e["dt"], self.colp, self.colh, self.K if elastic else np.zeros((1, 1)), elastic,
                   b_p, b_t, self.weight, S)
        return S

    def storage_terms(self):
        """``(rho, rho h, d(rho h)/dp)`` at the interior nodes of the last :meth:`equations`: the pieces of the
        transient's storage ``q = rho theta h`` (:mod:`transient.models.roller.line_step`)."""
        return self.props[0, 1:-1], self.props[5, 1:-1], self.props[6, 1:-1]

    def local_columns(self) -> np.ndarray:
        """The interior node of each local slot of each row (n, 4; -1: none), as ``equations``' ``dt``."""
        return self.colp

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
