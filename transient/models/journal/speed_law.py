"""The shaft's speed as a function of time, one law for every journal orbit (smooth, rough, thermal bearings).

:class:`SpeedProfile` is what ``JournalOrbit(..., speed_profile=...)`` takes: a piecewise-linear table
``((t_0 [s], n_0 [rpm]), (t_1, n_1), ...)`` (t ascending, linear between, constant outside) or a function
``n(t)`` [rpm] of the time [s]. It gives the speed ``value(t)`` [rpm], its rate ``derivative(t)`` [rpm/s] and the
shaft angle ``angle(t) = int_0^t Omega dt`` [rad].

The kernels take the law as knots in the orbit's time ``tau = omega_ref t`` (:meth:`SpeedProfile.knots`; a table's
own knots, a function's straight lines through its values ``FUNCTION_KNOTS`` times per reference revolution) and
evaluate it with :func:`shaft_speed`: the speed ratio ``s = Omega / omega_ref``, its rate ``s' = ds/dtau`` and the
angle ``phi = int_0^tau s dtau`` (exact: ``s`` is linear between knots). What the orbits do with it: the film's
Couette (sliding) flux times ``s``, and the unbalance force ``m e (Omega^2 (cos, sin) + dOmega/dt (sin, -cos))`` at
the angle ``phi`` (:func:`~transient.models.journal.kernels.shaft_accelerations`; the tangential term is the
reaction of the mass centre's own acceleration ``e dOmega/dt (-sin, cos)``).
"""

from __future__ import annotations

import hashlib
import math
from typing import Callable

import numpy as np
from numba import njit

from transient.checks import check_range
from transient.units import rpm_to_rad_s

#: The fastest shaft a profile may give [rpm] (``SPEED_RANGE_RPM[1]`` of the bearing).
MAX_RPM = 1e6
#: A function's knots per revolution at the reference speed (its straight lines: the speed within
#: ``(dt)^2 |n''| / 8`` of the function, dt = 1/100 revolution).
FUNCTION_KNOTS = 100
#: The BDF2 step cap of an orbit with a speed law is in shaft angle (the film's fronts move with the shaft): the
#: reference revolution's cap over ``max(s, CAP_SPEED_FLOOR)``.
CAP_SPEED_FLOOR = 0.1


class SpeedProfile:
    """The shaft's speed against time: a table ``((t [s], n [rpm]), ...)`` or a function ``n(t)`` (module
    docstring). Bad tables raise a ``ValueError`` naming ``speed_profile``; a function's values are checked where
    they are taken (:meth:`knots`)."""

    def __init__(self, profile):
        if isinstance(profile, SpeedProfile):
            self.table, self.function = profile.table, profile.function
        elif callable(profile):
            self.table, self.function = None, profile
        else:
            self.table, self.function = _checked_table(profile), None

    # ----------------------------------------------------------------------------------------- the law in SI
    def value(self, t) -> np.ndarray | float:
        """The shaft speed [rpm] at the times ``t`` [s]."""
        if self.function is not None:
            return _function_values(self.function, t) if np.ndim(t) else float(_function_values(self.function, [t])[0])
        p = np.array(self.table)
        return np.interp(t, p[:, 0], p[:, 1])

    def derivative(self, t) -> np.ndarray | float:
        """The shaft's angular acceleration as a rate of speed [rpm/s] at ``t`` [s]: the table's slope (0 outside;
        at a knot the slope after it), a function's central difference."""
        if self.function is not None:
            tt = np.atleast_1d(np.asarray(t, dtype=float))
            h = 1e-6 * np.maximum(1.0, np.abs(tt))
            lo = np.maximum(tt - h, 0.0)
            d = (_function_values(self.function, tt + h) - _function_values(self.function, lo)) / (tt + h - lo)
            return d if np.ndim(t) else float(d[0])
        p = np.array(self.table)
        tt = np.asarray(t, dtype=float)
        k = np.clip(np.searchsorted(p[:, 0], tt, side="right") - 1, 0, max(len(p) - 2, 0))
        slope = np.diff(p[:, 1]) / np.diff(p[:, 0]) if len(p) > 1 else np.zeros(1)
        inside = (tt >= p[0, 0]) & (tt < p[-1, 0])
        return np.where(inside, slope[k], 0.0) if np.ndim(t) else float(np.where(inside, slope[k], 0.0))

    def angle(self, t) -> float:
        """The shaft angle [rad] turned from t = 0 to ``t`` [s]: a table's exactly, a function's by quadrature (an
        orbit turns its shaft on the function's knots, :meth:`knots`)."""
        if self.function is not None:
            from scipy.integrate import quad

            return rpm_to_rad_s(quad(lambda x: float(_function_values(self.function, [x])[0]), 0.0, float(t),
                                     limit=200)[0])
        w = rpm_to_rad_s(1.0)
        return float(shaft_speed(w * float(t), _table_knots(self.table, w, 1.0))[2])

    def start_rpm(self) -> float:
        """The speed at t = 0 [rpm]."""
        return float(self.value(0.0))

    def key(self, omega_ref, rpm_ref, t_end) -> object:
        """What keys a checkpoint: the table, or a digest of a function's :meth:`knots` of the run."""
        if self.table is not None:
            return [list(p) for p in self.table]
        return hashlib.sha256(self.knots(omega_ref, rpm_ref, t_end).tobytes()).hexdigest()[:16]

    # ------------------------------------------------------------------------------------- the kernels' form
    def knots(self, omega_ref, rpm_ref, t_end) -> np.ndarray:
        """The kernels' law (:func:`speed_knots`) in ``tau = omega_ref t`` [rad/s] and ``s = n / rpm_ref``: a table's
        own knots; a function's values at ``FUNCTION_KNOTS`` times per reference revolution from t = 0 to past
        ``t_end`` [s] (the same knots for every run that covers them: a continued run turns the same shaft)."""
        if self.table is not None:
            return _table_knots(self.table, omega_ref, rpm_ref)
        dtau = 2.0 * math.pi / FUNCTION_KNOTS
        k = max(1, int(math.ceil(omega_ref * float(t_end) / dtau - 1e-9)) + 1)
        tau = dtau * np.arange(k + 1)
        return speed_knots(np.column_stack([tau, _function_values(self.function, tau / omega_ref) / rpm_ref]))

    def __repr__(self) -> str:
        return f"SpeedProfile({self.table!r})" if self.table is not None else f"SpeedProfile({self.function!r})"


def _checked_table(profile) -> tuple:
    """``speed_profile`` as ((t [s], speed [rpm]), ...), checked."""
    try:
        p = np.asarray(profile, dtype=float)
    except (TypeError, ValueError):
        p = np.zeros(0)
    if p.ndim != 2 or p.shape[1] != 2 or p.shape[0] < 1:
        raise ValueError(f"speed_profile of shape {p.shape}: allowed ((t_0 [s], n_0 [rpm]), ...), at least one pair, "
                         "or a function n(t) [rpm]")
    for t, n in p:
        check_range("speed_profile time", t, "s", 0.0, np.inf, high_open=True)
        check_range("speed_profile speed", n, "rpm", 0.0, MAX_RPM)
    if np.any(np.diff(p[:, 0]) <= 0):
        raise ValueError(f"speed_profile times {p[:, 0].tolist()} [s] out of order: allowed strictly ascending")
    return tuple((float(t), float(n)) for t, n in p)


def _function_values(function: Callable, t) -> np.ndarray:
    """``function`` at the times ``t`` [s], each checked: finite, in [0, MAX_RPM] rpm."""
    out = np.empty(np.size(t))
    for k, tk in enumerate(np.ravel(np.asarray(t, dtype=float))):
        v = float(function(float(tk)))
        if not math.isfinite(v) or v < 0.0 or v > MAX_RPM:
            raise ValueError(f"speed_profile(t = {tk:.6g} s) = {v!r} [rpm]; allowed: [0, {MAX_RPM:g}]")
        out[k] = v
    return out


def _table_knots(table, omega_ref, rpm_ref) -> np.ndarray:
    p = np.array(table, dtype=float)
    return speed_knots(np.column_stack([p[:, 0] * omega_ref, p[:, 1] / rpm_ref]))


def speed_knots(profile) -> np.ndarray:
    """The kernels' speed law from ``profile`` = ((tau_k, s_k), ...) (tau ascending; constant outside): the knots
    and the shaft angle ``phi(tau_k) = int_0^tau_k s dtau`` at each (the constant ``s_0`` before the first knot,
    trapezoids between: exact, s is linear there)."""
    p = np.array(profile, dtype=float).reshape(-1, 2)
    tau, s = p[:, 0], p[:, 1]
    phase = s[0] * tau[0] + np.concatenate([[0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(tau))])
    return np.ascontiguousarray(np.vstack([tau, s, phase]))


CONSTANT = speed_knots(((0.0, 1.0),))  # the law of an orbit at its own speed: s = 1, phi = tau


@njit(cache=True)
def shaft_speed(tau, knots):
    """Speed ratio ``s``, its slope ``ds/dtau`` and the shaft angle ``phi`` at ``tau`` of the piecewise-linear law
    (:func:`speed_knots`; the knot found by bisection)."""
    t, s, ph = knots[0], knots[1], knots[2]
    K = t.size
    if tau <= t[0] or K == 1:
        return s[0], 0.0, ph[0] + s[0] * (tau - t[0])
    if tau >= t[K - 1]:
        return s[K - 1], 0.0, ph[K - 1] + s[K - 1] * (tau - t[K - 1])
    k = np.searchsorted(t, tau, side="right") - 1
    slope = (s[k + 1] - s[k]) / (t[k + 1] - t[k])
    dt = tau - t[k]
    return s[k] + slope * dt, slope, ph[k] + s[k] * dt + 0.5 * slope * dt * dt


def speed_range(knots, tau0, tau1) -> tuple:
    """The lowest and highest speed ratio of the law over ``[tau0, tau1]`` (at the knots inside and the ends)."""
    inside = knots[1][(knots[0] > tau0) & (knots[0] < tau1)]
    ends = [shaft_speed(tau0, knots)[0], shaft_speed(tau1, knots)[0]]
    v = np.concatenate([inside, ends])
    return float(v.min()), float(v.max())


def step_cap_scale(knots) -> Callable:
    """The BDF2 step cap's scale at ``tau`` (``options["max_step_scale"]``): the cap in shaft angle, the reference
    revolution's cap over ``max(s, CAP_SPEED_FLOOR)``."""
    return lambda tau: 1.0 / max(shaft_speed(tau, knots)[0], CAP_SPEED_FLOOR)
