"""The friction rig of Sander et al. (Tribol. Int. 96 (2016) 173-183): the shaft torque against speed, computed as
the test bearing's friction torque plus that of its two support bearings (each under half the load), each from its
Stribeck curve (:func:`~transient.study.stribeck.stribeck_curve`) on rigid, isothermal, isoviscous bearings
(:mod:`transient.params.sander`), and compared with the measured curves.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from transient.params import sander
from transient.study.stribeck import StribeckCurve, stribeck_curve


def torque_minimum(speed_rpm, torque) -> float:
    """The speed [rpm] of the least torque: the vertex of the parabola in log(speed) through the least sample and
    its two neighbours (the least sample's speed if it is the first or the last)."""
    speed = np.asarray(speed_rpm, dtype=float)
    t = np.asarray(torque, dtype=float)
    k = int(np.argmin(t))
    if k == 0 or k == t.size - 1:
        return float(speed[k])
    a, b, _ = np.polyfit(np.log(speed[k - 1:k + 2]), t[k - 1:k + 2], 2)
    return float(np.exp(-b / (2.0 * a))) if a > 0 else float(speed[k])


@dataclass(frozen=True)
class RigCurve:
    """The rig's shaft torque at one ``load`` [N]: the test bearing's and one support bearing's Stribeck curves
    (:class:`~transient.study.stribeck.StribeckCurve`) at the same speeds."""

    load: float
    test: StribeckCurve
    support: StribeckCurve

    @property
    def speed_rpm(self) -> np.ndarray:
        return self.test.speed_rpm

    @property
    def torque(self) -> np.ndarray:
        """The shaft torque [N m]: the test bearing's plus the two supports'."""
        return self.test.friction_torque + 2.0 * self.support.friction_torque

    @property
    def minimum_speed_rpm(self) -> float:
        """The speed [rpm] of the least shaft torque (:func:`torque_minimum`)."""
        return torque_minimum(self.speed_rpm, self.torque)

    def at(self, speed_rpm) -> np.ndarray:
        """The shaft torque [N m] at computed speeds ``speed_rpm`` (each must be one of the curve's)."""
        idx = [int(np.flatnonzero(np.isclose(self.speed_rpm, s, rtol=1e-12))[0]) for s in np.atleast_1d(speed_rpm)]
        return self.torque[idx]


def rig_curve(load, speeds_rpm, grid=(151, 21), surface=None, support_surface=None) -> RigCurve:
    """The rig's shaft torque under ``load`` [N] at ``speeds_rpm``: the test bearing under ``load`` and a support
    bearing under ``load / 2``, each on ``grid`` with ``surface`` (default :func:`transient.params.sander.roughness`),
    the support with ``support_surface`` if given (a support's bore differs from the test bearing's)."""
    test = stribeck_curve(sander.test_bearing(grid, surface), load, speeds_rpm)
    support = stribeck_curve(sander.support_bearing(grid, surface if support_surface is None else support_surface),
                             0.5 * load, speeds_rpm)
    return RigCurve(load=float(load), test=test, support=support)


def measured_minimum(load) -> float:
    """The speed [rpm] of the least measured torque at ``load`` [N] (:func:`torque_minimum` on the measured points)."""
    s, t = sander.MEASURED[load]
    order = np.argsort(s)
    return torque_minimum(np.asarray(s)[order], np.asarray(t)[order])


def deviations(curve: RigCurve) -> dict:
    """Per measured speed [rpm] of the curve's load that the curve computed: (measured, computed) torque [N m] and
    the relative deviation computed / measured - 1."""
    out = {}
    for n, m in zip(*sander.MEASURED[curve.load]):
        if np.any(np.isclose(curve.speed_rpm, n, rtol=1e-12)):
            c = float(curve.at(n)[0])
            out[float(n)] = (float(m), c, c / m - 1.0)
    return out
