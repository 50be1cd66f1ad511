"""Fischer-Burmeister-Newton-Schur (FBNS) iteration of the point-contact film.

Woloszynski, Podsiadlo & Stachowiak (*Tribol. Lett.* 58, 2015) for the mass-conserving cavitation problem;
Hansen, Kacan, Frohnapfel & Codrignani (*Tribol. Lett.* 70, 2022) with the elastic film. Newton on
``[P, theta, H0]``: Reynolds rows (mass conservation everywhere), ``FB(P, 1 - theta) = 0`` rows, and the
load balance. Each FB row ``a dP + g dtheta = -FB`` is diagonal, so one unknown per node is eliminated
(theta where ``|g| >= |a|``, the pressure otherwise): the reduced ``(N + 1)`` system is dense (elasticity)
and solved by LU (Hansen et al. keep only five diagonals of the elastic block and iterate more; the exact
block is affordable up to ~10^4 unknowns and converges quadratically). Globalisation: backtracking on the
scaled residual norm with the film kept positive.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp


def newton_step(film, u, e, res=None, cj=0.0):
    """The full Newton step ``du`` at ``u`` (``e = film.equations(u)``), by the node-wise Schur reduction.

    ``res``, ``cj``: the Reynolds rows of a time step, ``R - cj (q - q_hat)``, and their storage coefficient
    (default: the steady rows ``e["res"]``, ``cj = 0``)."""
    n = film.n
    j_pp, a_t, j_h0, w = film.newton_matrix(u, e, cj)
    res = e["res"] if res is None else res
    alpha, gamma = film.fb_derivatives(u, e)
    fb = e["fb"]
    keep_p = np.abs(gamma) >= np.abs(alpha)
    sg = np.where(keep_p, gamma, 1.0)
    sa = np.where(keep_p, 1.0, alpha)
    # dP = a_p + b_p z,  dtheta = a_t + b_t z
    b_p = np.where(keep_p, 1.0, -gamma / sa)
    a_p = np.where(keep_p, 0.0, -fb / sa)
    b_t = np.where(keep_p, -alpha / sg, 1.0)
    a_th = np.where(keep_p, -fb / sg, 0.0)
    A = np.empty((n + 1, n + 1))
    A[:n, :n] = j_pp * b_p[None, :]
    A[:n, :n] += (a_t @ sp.diags(b_t)).toarray()
    A[:n, n] = j_h0
    A[n, :n] = w * b_p
    A[n, n] = 0.0
    r = np.empty(n + 1)
    r[:n] = -res - j_pp @ a_p - a_t @ a_th
    r[n] = -e["load"] - w @ a_p
    z = sla.solve(A, r, overwrite_a=True, overwrite_b=True, check_finite=False)
    du = np.empty(2 * n + 1)
    du[:n] = a_p + b_p * z[:n]
    du[n: 2 * n] = a_th + b_t * z[:n]
    du[-1] = z[n]
    return du


def rows(film, e, cj=0.0, q_hat=None):
    """``(Reynolds rows, their scales)``: steady ``R``, or a time step's ``R - cj (q - q_hat)``."""
    if not cj:
        return e["res"], e["scale"]
    q = film.storage(e)
    rho_h = (e["rho"] * e["H"]).ravel()[film.flat]
    return e["res"] - cj * (q - q_hat), e["scale"] + cj * rho_h


def merit(film, e, cj=0.0, q_hat=None):
    """The scaled residual vector: Reynolds rows by their scale, Fischer-Burmeister rows, load balance."""
    r, s = rows(film, e, cj, q_hat)
    return np.concatenate([r / s, e["fb"], [e["load"]]])


def fbns(film, u0, tol=1e-8, max_iter=60, load_ratio=1.0, step_max=0.5, cj=0.0, q_hat=None, memory=1):
    """Newton from ``u0`` until the largest scaled residual is below ``tol`` (steady, or one implicit time
    step ``R - cj (q - q_hat) = 0`` when ``cj > 0``).

    Returns ``(u, converged, norms)``; ``norms`` the infinity norm of the scaled residual per iteration.
    The step is cut so that the film stays positive and no pressure moves by more than ``step_max`` (of
    p_h) plus half its value in one step, then halved until the residual norm decreases below the largest of
    the last ``memory`` norms (1: monotone; more: the non-monotone rule of Grippo, Lampariello & Lucidi, 1986)."""
    u = np.array(u0, float)
    e = film.equations(u, load_ratio)
    f = merit(film, e, cj, q_hat)
    norms = [float(np.max(np.abs(f)))]
    merits = [float(np.sqrt(f @ f))]
    n = film.n
    for _ in range(max_iter):
        if norms[-1] < tol:
            return u, True, norms
        du = newton_step(film, u, e, rows(film, e, cj, q_hat)[0], cj)
        big = np.max(np.abs(du[:n]) / (step_max + 0.5 * np.abs(u[:n])))
        s = min(1.0, 1.0 / big) if big > 0 else 1.0
        phi0 = max(v * v for v in merits[-memory:])
        accepted = False
        for _ in range(30):
            ut = u + s * du
            et = film.equations(ut, load_ratio)
            if np.min(et["H"]) > 0.0:
                ft = merit(film, et, cj, q_hat)
                if np.all(np.isfinite(ft)) and float(ft @ ft) < (1.0 - 1e-4 * s) * phi0:
                    accepted = True
                    break
            s *= 0.5
        if not accepted:
            return u, False, norms
        u, e, f = ut, et, ft
        norms.append(float(np.max(np.abs(f))))
        merits.append(float(np.sqrt(f @ f)))
    return u, norms[-1] < tol, norms
