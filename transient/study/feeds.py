"""Design study of a plain journal bearing's oil feed: load capacity, attitude, minimum film, supply flow and side
leakage against eccentricity for several feed geometries (scenarios/journal_feeds.py).

Each feed is swept over a range of loads; at each load the static equilibrium (:meth:`JournalBearing.equilibrium`)
gives the eccentricity, attitude angle, minimum film and the flows (:mod:`transient.models.journal.flows`). The
feeds are held at the supply pressure above an ambient at the cavitation pressure, so the oil the film loses at its
ends is what the feeds supply (the steady mass balance, checked at every point). A groove open at the bearing
ends meets the ambient in a pressure jump whose flow the film sets only up to the cell size
(:mod:`~transient.models.journal.flows`): its supply flow is the film's at the grid used.
"""

from __future__ import annotations

import numpy as np

from transient.models.journal.bearing import JournalBearing, NoEquilibriumError
from transient.models.journal.feeds import Groove, OilHole

QUANTITIES = ("load", "eccentricity_ratio", "attitude_angle_deg", "min_film", "supply_flow", "side_leakage",
              "flow_variable", "side_flow_ratio", "balance")


def feed_designs(length, groove_width_deg=15.0, hole_diameter=None) -> dict:
    """The four feeds of the study: a full-length groove at the top (0 deg, opposite the load), a groove of 3/4 of
    the length there, two full-length grooves at +-90 deg and a hole at the top (default diameter: a quarter of the
    bearing length)."""
    d = 0.25 * length if hole_diameter is None else hole_diameter
    return {"full groove": Groove(0.0, groove_width_deg),
            "3/4-length groove": Groove(0.0, groove_width_deg, length=0.75 * length),
            "two grooves at +-90 deg": [Groove(90.0, groove_width_deg), Groove(-90.0, groove_width_deg)],
            "oil hole": OilHole(0.0, d)}


def feed_sweep(bearing_kw: dict, feeds: dict, loads_N, speed_rpm: float) -> dict:
    """For each feed (name -> ``groove=`` value) and load: the equilibrium's :data:`QUANTITIES` -- ``supply_flow``
    [m^3/s] all feeds together, ``side_leakage`` [m^3/s] both ends, ``balance`` = (supply - leakage) / leakage.
    A load the film cannot carry gives NaN. Returns ``{name: {quantity: array over loads}}``."""
    out = {}
    for name, feed in feeds.items():
        b = JournalBearing(**dict(bearing_kw, groove=feed))
        rows = {q: [] for q in QUANTITIES}
        for W in loads_N:
            try:
                s = b.equilibrium(W, speed_rpm)
            except NoEquilibriumError:
                for q in QUANTITIES:
                    rows[q].append(np.nan)
                continue
            supply, leak = float(np.sum(s.supply_flow)), float(np.sum(s.side_leakage))
            for q, v in (("load", s.load), ("eccentricity_ratio", s.eccentricity_ratio),
                         ("attitude_angle_deg", s.attitude_angle_deg), ("min_film", s.min_film),
                         ("supply_flow", supply), ("side_leakage", leak), ("flow_variable", s.flow_variable),
                         ("side_flow_ratio", s.side_flow_ratio), ("balance", (supply - leak) / leak)):
                rows[q].append(v)
        out[name] = {q: np.asarray(v, dtype=float) for q, v in rows.items()}
    return out
