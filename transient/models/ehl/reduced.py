"""The Schur-reduced FBNS Newton system of the EHL films: the node-wise elimination of the Fischer-Burmeister
rows and the dense reduced matrix (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.* 58, 2015). Each FB row
``a dP + g dtheta = -FB`` is diagonal, so one unknown per node is eliminated; what is left is ``(N + 1)`` square
(one unknown per node and ``dH0``), dense through the elasticity::

    A = [ D_H K diag(b_P) + A_P diag(b_P) + A_theta diag(b_theta)    D_H 1 ]
        [ w^T diag(b_P)                                                0   ]

Two builders of ``A``: :func:`dense_reduced` from sparse local blocks (the point film's half grid, whose mirror
images the CSR sums) and :func:`schur_rows` from the local slots of :mod:`transient.models.ehl.rows` (the line
and the roller). They differ in the rounding of the local pressure block: the point's adds ``(D_H K) b_P`` and
``A_P b_P``, the slots' ``(D_H K + A_P) b_P``.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from numba import njit


class Elimination:
    """The node-wise elimination of the Fischer-Burmeister rows ``alpha dP + gamma dtheta = -FB`` at their
    derivatives ``alpha``, ``gamma``: the remaining unknown ``z`` per node is the pressure where ``|gamma| >=
    |alpha|`` (``keep_p``), the content otherwise; ``dP = a_p + b_p z``, ``dtheta = a_theta + b_theta z`` (all
    ``|b| <= 1``), with ``b_p``, ``b_t`` fixed here and the offsets from the rows' values (:meth:`offsets`)."""

    def __init__(self, alpha, gamma):
        self.keep_p = np.abs(gamma) >= np.abs(alpha)
        self.sg = np.where(self.keep_p, gamma, 1.0)
        self.sa = np.where(self.keep_p, 1.0, alpha)
        self.b_p = np.where(self.keep_p, 1.0, -gamma / self.sa)
        self.b_t = np.where(self.keep_p, -alpha / self.sg, 1.0)

    def offsets(self, fb):
        """``(a_p, a_theta)`` for the Fischer-Burmeister rows' values ``fb``."""
        return np.where(self.keep_p, 0.0, -fb / self.sa), np.where(self.keep_p, -fb / self.sg, 0.0)


def schur(film, u, e):
    """Node-wise elimination of the Fischer-Burmeister rows (:class:`Elimination`) at ``u``:
    ``(a_p, b_p, a_theta, b_theta)`` with ``dP = a_p + b_p z`` and ``dtheta = a_theta + b_theta z``."""
    el = Elimination(*film.fb_derivatives(u, e))
    a_p, a_th = el.offsets(e["fb"])
    return a_p, el.b_p, a_th, el.b_t


def dense_reduced(film, local, b_p, b_t) -> np.ndarray:
    """The reduced Newton matrix (``(N + 1)`` square, dense: the elastic block in full), filled from the
    sparse local blocks by :func:`reduced_kernel`."""
    a_p, d_h, a_t = (sp.csr_matrix(m) for m in local)
    n = film.n
    A = np.empty((n + 1, n + 1))
    reduced_kernel(a_p.indptr, a_p.indices, a_p.data, d_h.indptr, d_h.indices, d_h.data, a_t.indptr, a_t.indices,
                   a_t.data, film.kernel(), np.ascontiguousarray(b_p, dtype=float),
                   np.ascontiguousarray(b_t, dtype=float), film.weight / film.load, A)
    return A


@njit(cache=True)
def reduced_kernel(ap_ptr, ap_idx, ap_val, dh_ptr, dh_idx, dh_val, at_ptr, at_idx, at_val, K, b_p, b_t, w, A):
    """Fill ``A`` (module docstring) row by row: ``D_H K`` over the few half-grid nodes each Reynolds row
    touches (CSR ``dh_*``), the local blocks ``A_P`` and ``A_theta`` (CSR ``ap_*``, ``at_*``), the ``H0``
    column (row sums of ``D_H``) and the load row ``w b_P``."""
    n = b_p.size
    for r in range(n):
        row = A[r]
        for q in range(n + 1):
            row[q] = 0.0
        h0 = 0.0
        for k in range(dh_ptr[r], dh_ptr[r + 1]):
            v = dh_val[k]
            h0 += v
            kr = K[dh_idx[k]]
            for q in range(n):
                row[q] += v * kr[q]
        for q in range(n):
            row[q] *= b_p[q]
        for k in range(ap_ptr[r], ap_ptr[r + 1]):
            q = ap_idx[k]
            row[q] += ap_val[k] * b_p[q]
        for k in range(at_ptr[r], at_ptr[r + 1]):
            q = at_idx[k]
            row[q] += at_val[k] * b_t[q]
        row[n] = h0
    for q in range(n):
        A[n, q] = w[q] * b_p[q]
    A[n, n] = 0.0


@njit(cache=True, error_model="numpy")
def reynolds_row(Sp, Sh, colp, colh, K, elastic, r, row):
    """Row ``r`` of the Reynolds rows' Newton matrix in the pressures, ``Sp + Sh K`` (``K`` not read for a rigid
    body, ``elastic=False``), into ``row[:n]`` (zeroed first); returns its ``h0`` entry, the sum of ``Sh``."""
    n = Sp.shape[0]
    for q in range(n):
        row[q] = 0.0
    s_h0 = 0.0
    for s in range(Sp.shape[1]):
        ch = colh[r, s]
        if ch >= 0:
            v = Sh[r, s]
            s_h0 += v
            if elastic and v != 0.0:
                krow = K[ch]
                for q in range(n):
                    row[q] += v * krow[q]
        cp = colp[r, s]
        if cp >= 0:
            row[cp] += Sp[r, s]
    return s_h0


@njit(cache=True, error_model="numpy")
def schur_rows(Sp, Sh, St, colp, colh, K, elastic, b_p, b_t, area_w, S):
    """Dense Schur matrix of the film-content Newton step (the line's and the roller's content films):
    ``S = [[(Sp + Sh K) diag(b_p) + St diag(b_t), Sh 1], [area_w diag(b_p), 0]]``, the Reynolds rows' Newton
    matrix after the node-wise substitution ``dp = b_p z``, ``dtheta = b_t z``. ``K`` (n_full, n): film change
    per unit interior pressure (not read for a rigid body, ``elastic=False``); ``colp`` / ``colh`` map the slots
    to interior / full node indices (-1: none)."""
    n = Sp.shape[0]
    for r in range(n):
        row = S[r]
        s_h0 = reynolds_row(Sp, Sh, colp, colh, K, elastic, r, row)
        for q in range(n):
            row[q] *= b_p[q]
        for s in range(Sp.shape[1]):
            cp = colp[r, s]
            if cp >= 0:
                row[cp] += St[r, s] * b_t[cp]
        row[n] = s_h0
    for q in range(n):
        S[n, q] = area_w[q] * b_p[q]
    S[n, n] = 0.0
