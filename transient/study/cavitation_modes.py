"""The mass-conserving (Elrod) film against the classical Reynolds-condition film: stiffness and damping over a
load range, with the supply groove at the maximum film or away from it (issue 17).

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


def coefficients_by_mode(bearing_kw: dict, loads_N, speed_rpm: float, groove_angles_deg=(0.0, 90.0)) -> dict:
    """For each groove angle and load: equilibrium eccentricity, K [N/m] and C [N s/m] (2x2) of both films, and
    ``dK_max``, ``dC_max``: the largest entry of :func:`relative_difference` per load.
    Returns ``{angle: dict(loads, eps_elrod, eps_reynolds, K_elrod, K_reynolds, C_elrod, C_reynolds, dK_max,
    dC_max)}``."""
    out = {}
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
        r = dict(loads=np.asarray(loads_N, dtype=float),
                 **{f"{q}_{m}": np.asarray(rows[m][q]) for m in rows for q in ("eps", "K", "C")})
        for q in ("K", "C"):
            r[f"d{q}_max"] = np.abs(relative_difference(r, q)).reshape(len(r["loads"]), -1).max(axis=1)
        out[float(ang)] = r
    return out


def relative_difference(res_angle: dict, quantity: str) -> np.ndarray:
    """(Elrod - Reynolds) / max|Reynolds| per load for the 2x2 ``quantity`` ("K" or "C"): shape (loads, 2, 2)."""
    e, r = res_angle[f"{quantity}_elrod"], res_angle[f"{quantity}_reynolds"]
    scale = np.abs(r).reshape(len(r), -1).max(axis=1)[:, None, None]
    return (e - r) / scale
