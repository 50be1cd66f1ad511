"""The Stribeck curve of a journal bearing: friction torque against speed at a fixed load, from the static
equilibrium at each speed (:meth:`~transient.models.journal.bearing.JournalBearing.equilibrium`), taken from the
highest speed down with each equilibrium started from the journal position of the speed above (continuation). On a
rough bearing (``JournalBearing(roughness=...)``) the asperities take a growing share of the load as the speed falls:
mixed lubrication, the rising branch of the curve left of its minimum.
"""

from __future__ import annotations

import numpy as np

from transient.checks import check_positive, check_range
from transient.models.journal.bearing import check_speed
from transient.results import SteadyResult, quantity, result_type

#: Contact share of the load below which the bearing counts as lifted off (:func:`stribeck_curve`).
LIFT_OFF_FRACTION = 0.01


@result_type
class StribeckCurve(SteadyResult):
    """A Stribeck curve at one ``load`` [N]: per speed (ascending) ``speed_rpm``, ``friction_torque`` [N m],
    ``friction_coefficient`` = torque / (R load), ``h_min`` [m], ``eccentricity_ratio``, ``contact_load`` [N] (the
    asperities' share), ``power_loss`` [W]; ``lift_off_speed_rpm``: the speed where the contact load falls to
    ``lift_off_fraction`` of the load (NaN if it does not cross it in the speed range)."""

    load: float = quantity("N")
    speed_rpm: np.ndarray = quantity("rpm")
    friction_torque: np.ndarray = quantity("N m")
    friction_coefficient: np.ndarray = quantity("-")
    h_min: np.ndarray = quantity("m")
    eccentricity_ratio: np.ndarray = quantity("-")
    contact_load: np.ndarray = quantity("N")
    power_loss: np.ndarray = quantity("W")
    lift_off_speed_rpm: float = quantity("rpm", float("nan"))
    lift_off_fraction: float = quantity("-", LIFT_OFF_FRACTION)


def lift_off_speed(speed_rpm, contact_load, load, fraction=LIFT_OFF_FRACTION) -> float:
    """The lowest speed [rpm] above which the contact share ``contact_load / load`` stays below ``fraction``: the
    crossing interpolated linearly in the share against log(speed) between the two speeds around it (speeds
    ascending). NaN if the share is below ``fraction`` at every speed or above it at the highest speed."""
    s = np.asarray(speed_rpm, dtype=float)
    share = np.asarray(contact_load, dtype=float) / load
    above = np.nonzero(share >= fraction)[0]
    if above.size == 0 or above[-1] == s.size - 1:
        return float("nan")
    i = above[-1]
    t = (share[i] - fraction) / (share[i] - share[i + 1])
    return float(np.exp(np.log(s[i]) + t * (np.log(s[i + 1]) - np.log(s[i]))))


def stribeck_curve(bearing, load, speeds_rpm, lift_off_fraction=LIFT_OFF_FRACTION) -> StribeckCurve:
    """The Stribeck curve of ``bearing`` (a :class:`~transient.models.journal.bearing.JournalBearing`, smooth or
    rough) under ``load`` [N] at ``speeds_rpm`` (module docstring): the equilibria from the highest speed down,
    each started from the position of the one above. Lift-off: the speed at which the asperities' share of the load
    falls to ``lift_off_fraction`` (default 1 %), interpolated (:func:`lift_off_speed`).
    Raises :class:`~transient.models.journal.bearing.NoEquilibriumError` if the bearing cannot carry the load at a
    speed (a smooth bearing below its lowest film speed; a rough one beyond ``e/C = 0.999``)."""
    W = check_positive("load", load, "N")
    frac = check_range("lift_off_fraction", lift_off_fraction, "-", 0.0, 1.0, low_open=True, high_open=True)
    speeds = np.unique(np.asarray([check_speed(s) for s in np.atleast_1d(speeds_rpm)], dtype=float))
    if speeds.size < 1:
        raise ValueError("speeds_rpm = [] [rpm]: give at least one speed")
    states = {}
    start = None
    for s in speeds[::-1]:
        f, u, q, it, _ = bearing._equilibrium(W, s, start=start)
        states[s] = f.state(u, q[0], q[1], it)
        start = q
    st = [states[s] for s in speeds]
    contact = np.array([x.contact_load for x in st])
    return StribeckCurve(
        load=W, speed_rpm=speeds, friction_torque=np.array([x.friction_torque for x in st]),
        friction_coefficient=np.array([x.friction_coefficient for x in st]),
        h_min=np.array([x.min_film for x in st]), eccentricity_ratio=np.array([x.eccentricity_ratio for x in st]),
        contact_load=contact, power_loss=np.array([x.power_loss for x in st]),
        lift_off_speed_rpm=lift_off_speed(speeds, contact, W, frac), lift_off_fraction=frac,
        iterations=int(sum(x.iterations for x in st)))
