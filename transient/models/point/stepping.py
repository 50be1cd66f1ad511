"""Implicit time stepping of the point-contact film: variable-step BDF2 with FBNS Newton at every step.

The transient Reynolds rows of :mod:`transient.models.point.ehl_problem`, time ``T = t u/b``::

    R(P, theta, H0) - d(rho theta H)/dT = 0,   FB(P, 1 - theta) = 0,   load balance at W(T)/W

are a DAE whose algebraic part switches node by node between the pressure and the content (the
complementarity rows). As Hansen, Kacan, Frohnapfel & Codrignani (*Tribol. Lett.* 70, 2022) do for the
unsteady FBNS, every step solves the full nonsmooth system by Newton (:func:`~transient.models.point.fbns.fbns`)
with the storage term discretised by BDF (the first step backward Euler), here second order with variable
steps::

    dq/dT ~ cj (q - q_hat),  cj = (1 + 2w)/((1 + w) h),  q_hat = ((1 + w) q_n - w^2/(1 + w) q_{n-1}) / (cj h),
    w = h / h_prev

The local error is estimated from the distance between the converged step and the linear predictor
(``|u - u_pred|/3`` in a weighted RMS norm relative to ``rtol``); the step grows by at most
2x and is halved when Newton fails. (The SUNDIALS integrators of :func:`transient.solvers.integrate.solve`
are not used: their corrector stalls where the complementarity rows switch, as documented for the roller.)
"""

from __future__ import annotations

import numpy as np

from transient.models.point.fbns import fbns, merit


def bdf_coefficients(h, h_prev, q_n, q_prev):
    """``(cj, q_hat)`` of variable-step BDF2 (backward Euler when ``h_prev`` is None)."""
    if h_prev is None:
        return 1.0 / h, q_n
    w = h / h_prev
    cj = (1.0 + 2.0 * w) / ((1.0 + w) * h)
    return cj, ((1.0 + w) * q_n - w * w / (1.0 + w) * q_prev) / (cj * h)


def error_norm(film, u, u_pred, rtol):
    """Weighted RMS norm (as SUNDIALS') of the BDF2 error estimate ``|u - u_pred|/3``: pressure and content
    relative to ``rtol max(|.|, 0.01)``, ``H0`` to ``rtol max(|H0|, 0.01)``."""
    w = rtol * np.maximum(np.abs(u), 1e-2)
    return float(np.sqrt(np.mean((np.abs(u - u_pred) / (3.0 * w)) ** 2)))


def march(film, u0, t_end, load_ratio, rtol=1e-4, h0=1e-3, h_max=None, tol=1e-9, max_steps=5000, observe=None,
          stop=None):
    """Integrate from ``u0`` at ``T = 0`` to ``t_end`` (scaled). ``load_ratio(T)``: ``W(T)/W``. ``observe(T, u)``
    is called after every accepted step; ``stop(T, u)`` may end the run early (returns True).

    Returns ``(T, u, ok, message, counts)``."""
    h_max = t_end if h_max is None else h_max
    T, u = 0.0, np.array(u0, float)
    q_n = film.storage(film.equations(u, load_ratio(0.0)))
    u_prev, q_prev, h_prev = None, None, None
    h = min(h0, t_end)
    counts = dict(steps=0, rejected=0, newton_failures=0, newton=0)
    while T < t_end * (1.0 - 1e-12):
        if counts["steps"] >= max_steps:
            return T, u, False, f"{max_steps} steps reached at T = {T:.4g}", counts
        h = min(h, t_end - T, h_max)
        cj, q_hat = bdf_coefficients(h, h_prev, q_n, q_prev)
        u_pred = u if u_prev is None else u + (h / h_prev) * (u - u_prev)
        start = u_pred if u_prev is not None and np.min(u_pred[film.n:2 * film.n]) >= 0.0 else u
        un, ok, norms = fbns(film, start, tol, 30, load_ratio(T + h), cj=cj, q_hat=q_hat)
        counts["newton"] += len(norms) - 1
        if not ok and start is not u:
            un, ok, norms = fbns(film, u, tol, 30, load_ratio(T + h), cj=cj, q_hat=q_hat)
            counts["newton"] += len(norms) - 1
        if not ok:
            counts["newton_failures"] += 1
            h *= 0.25
            if h < 1e-10 * max(t_end, 1.0):
                return T, u, False, f"Newton failed at T = {T:.4g} with step {h:.3g}", counts
            continue
        err = error_norm(film, un, u_pred, rtol) if u_prev is not None else 0.0
        if err > 1.0:
            counts["rejected"] += 1
            h *= max(0.2, 0.9 * err ** (-1.0 / 3.0))
            continue
        u_prev, q_prev, h_prev = u, q_n, h
        u, T = un, T + h
        q_n = film.storage(film.equations(u, load_ratio(T)))
        counts["steps"] += 1
        if observe is not None:
            observe(T, u)
        if stop is not None and stop(T, u):
            break
        h *= min(2.0, 0.9 * err ** (-1.0 / 3.0)) if err > 0 else 2.0
    return T, u, True, "ok", counts


def steady_by_time_steps(film, u0, tol=1e-8, t_max=1e4, rtol=0.3):
    """Pseudo-transient continuation to the steady state: the physical transient with a loose error control
    until the steady residual falls below 1e-3, then steady Newton; if Newton stalls there (a node cycling on a
    kink of the complementarity), the transient goes on (its steps grow to ~T) until the steady residual is
    below ``tol``. Returns ``(u, ok, norms, counts)``."""
    def below(level):
        return lambda T, u: float(np.max(np.abs(merit(film, film.equations(u))))) < level

    T, u, _, _, counts = march(film, u0, t_max, lambda T: 1.0, rtol=rtol, h0=1e-2, stop=below(1e-3))
    us, oks, norms = fbns(film, u, tol, 60)
    if not oks:
        T2, u, _, _, more = march(film, u, t_max, lambda T: 1.0, rtol=rtol, h0=T / 10.0 if T > 0 else 1e-2,
                                  stop=below(tol))
        T += T2
        counts = {k: counts[k] + more[k] for k in counts}
        norms = [float(np.max(np.abs(merit(film, film.equations(u)))))]
        us, oks = u, norms[-1] < tol
    counts["T"] = T
    return us, oks, norms, counts
