"""The mass-conserving (Elrod) film against the classical Reynolds-condition film: stiffness and damping over a
load range, with the supply groove at the maximum film or away from it.

The Reynolds condition resets the film to full at the reformation line whatever oil the cavity carries; the
Elrod film carries the cavity's content (striations) into the converging gap and runs partly starved until
the groove or the pressure refills it. The difference is largest at light load, where the cavity holds a
large share of the film's circumference (scenarios/journal_cavitation_modes.py: tens of percent in K and C
below e/C ~ 0.3 with the groove at the top, up to 100 % with the groove at 270 deg, a few percent above
e/C ~ 0.5).
"""

from __future__ import annotations


import numpy as np

from transient.models.journal.bearing import Groove, JournalBearing
from transient.results import StatusResult, quantity, result_type


@result_type
class ModeComparison(StatusResult):
    """Both films with the groove at one angle, per load: the equilibrium eccentricity ratios, the stiffness
    ``K`` [N/m] and damping ``C`` [N s/m] (loads, 2, 2) of the Elrod and the Reynolds film, and ``dK_max``,
    ``dC_max``: the largest entry of :func:`relative_difference` per load."""

    time_axis = "loads"
    groove_angle_deg: float = quantity("deg")
    loads: np.ndarray = quantity("N")
    eps_elrod: np.ndarray = quantity("-")
    eps_reynolds: np.ndarray = quantity("-")
    K_elrod: np.ndarray = quantity("N/m")
    K_reynolds: np.ndarray = quantity("N/m")
    C_elrod: np.ndarray = quantity("N s/m")
    C_reynolds: np.ndarray = quantity("N s/m")
    dK_max: np.ndarray = quantity("-", None)
    dC_max: np.ndarray = quantity("-", None)

    def __post_init__(self):
        for q in ("K", "C"):
            if getattr(self, f"d{q}_max") is None:
                d = np.abs(relative_difference(self, q))
                setattr(self, f"d{q}_max", d.reshape(len(self.loads), -1).max(axis=1))


@result_type
class CavitationModes(StatusResult):
    """The comparison at every groove angle (:class:`ModeComparison`, in the order asked);
    ``items()`` gives (angle [deg], comparison) pairs."""

    time_axis = None
    comparisons: list

    def items(self):
        return [(c.groove_angle_deg, c) for c in self.comparisons]


def coefficients_by_mode(bearing_kw: dict, loads_N, speed_rpm: float,
                         groove_angles_deg=(0.0, 90.0)) -> CavitationModes:
    """For each groove angle and load: equilibrium eccentricity, K [N/m] and C [N s/m] (2x2) of both films and
    their largest relative difference (:class:`ModeComparison`)."""
    out = []
    for ang in groove_angles_deg:
        kw = dict(bearing_kw, groove=Groove(angle_deg=ang))
        rows = {m: dict(eps=[], K=[], C=[]) for m in ("elrod", "reynolds")}
        for mode in rows:
            b = JournalBearing(**kw, cavitation=mode)
            for W in loads_N:
                rows[mode]["eps"].append(b.equilibrium(W, speed_rpm).eccentricity_ratio)
                K, C = b.coefficients(W, speed_rpm)
                rows[mode]["K"].append(K)
                rows[mode]["C"].append(C)
        out.append(ModeComparison(groove_angle_deg=float(ang), loads=np.asarray(loads_N, dtype=float),
                                  **{f"{q}_{m}": np.asarray(rows[m][q]) for m in rows for q in ("eps", "K", "C")}))
    return CavitationModes(comparisons=out)


def relative_difference(comparison: ModeComparison, quantity: str) -> np.ndarray:
    """(Elrod - Reynolds) / max|Reynolds| per load for the 2x2 ``quantity`` ("K" or "C"): shape (loads, 2, 2)."""
    e, r = getattr(comparison, f"{quantity}_elrod"), getattr(comparison, f"{quantity}_reynolds")
    scale = np.abs(r).reshape(len(r), -1).max(axis=1)[:, None, None]
    return (e - r) / scale
