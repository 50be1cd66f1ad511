"""The Schur-reduced FBNS Newton system of the point film (and of the line film, :mod:`~transient.models.roller.line_newton`): the node-wise elimination of the
Fischer-Burmeister rows and the dense reduced matrix (Woloszynski, Podsiadlo & Stachowiak, *Tribol. Lett.*
58, 2015). Each FB row ``a dP + g dtheta = -FB`` is diagonal, so one unknown per node is eliminated; what is
left is ``(N + 1)`` square (one unknown per node and ``dH0``), dense through the elasticity::

    A = [ D_H K diag(b_P) + A_P diag(b_P) + A_theta diag(b_theta)    D_H 1 ]
        [ w^T diag(b_P)                                                0   ]
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp


def schur(film, u, e):
    """Node-wise elimination of the Fischer-Burmeister rows: ``(a_p, b_p, a_theta, b_theta)`` with
    ``dP = a_p + b_p z`` and ``dtheta = a_theta + b_theta z`` for the remaining unknown ``z`` per node (the
    pressure where ``|dFB/dtheta| >= |dFB/dP|``, the content otherwise; all ``|b| <= 1``)."""
    alpha, gamma = film.fb_derivatives(u, e)
    fb = e["fb"]
    keep_p = np.abs(gamma) >= np.abs(alpha)
    sg = np.where(keep_p, gamma, 1.0)
    sa = np.where(keep_p, 1.0, alpha)
    b_p = np.where(keep_p, 1.0, -gamma / sa)
    a_p = np.where(keep_p, 0.0, -fb / sa)
    b_t = np.where(keep_p, -alpha / sg, 1.0)
    a_th = np.where(keep_p, -fb / sg, 0.0)
    return a_p, b_p, a_th, b_t


def dense_reduced(film, local, b_p, b_t) -> np.ndarray:
    """The reduced Newton matrix (``(N + 1)`` square, dense: the elastic block in full)."""
    a_p, d_h, a_t = local
    n = film.n
    A = np.empty((n + 1, n + 1))
    A[:n, :n] = np.asarray(d_h @ film.kernel()) * b_p[None, :]
    A[:n, :n] += (a_p @ sp.diags(b_p) + a_t @ sp.diags(b_t)).toarray()
    A[:n, n] = np.asarray(d_h.sum(axis=1)).ravel()
    A[n, :n] = film.weight / film.load * b_p
    A[n, n] = 0.0
    return A
