"""Seed 004's journal case with boundary layers and a Newtonian bulk: how much the layers raise the film and why.

Jang's bearing (R/B = 1, eps = 0.9, h_min = 0.1 C; the paper's example D = 25 mm, C = 10 um) with layers of
thickness delta = 0, 0.1, 0.2, 0.3 h_min on both walls, layer viscosity mu_ab = 10 mu (2 ... 100 explored)
and permeability length alpha = 0.1 h_min, on the classical Reynolds-condition film (the Gecim bulk is not in
the journal film yet: :class:`~transient.models.journal.bearing.JournalBearing` refuses it by name). For each
case the steady film at the fixed position; the rise of the load over the layer-free film splits exactly into

* the thinner bulk: the immobile layers (alpha = 0) are a bearing of clearance C - 2 delta
  (tests/test_journal_layers.py), and
* the Darcy flow through mobile layers (alpha > 0), which gives part of it back.

Pressures are reported as p* = p / p0, p0 = 6 mu omega (R/C)^2 (the layer-free bearing's scale).
"""

from __future__ import annotations


from transient.models.journal.bearing import JournalBearing
from transient.physics.layered import BoundaryLayers

#: Jang's example bearing (seed 004: D = 25 mm, c = 10 um, R/B = 1); viscosity and speed set only the scale
BEARING = dict(diameter=0.025, length=0.0125, clearance=10e-6, viscosity=0.01, groove=None,
               cavitation="reynolds")
SPEED_RPM = 300.0  # keeps the thickest layers' peak (~19 p0) below the 100 MPa validity warning
ECCENTRICITY = 0.9
H_MIN = 1.0 - ECCENTRICITY  # h_min / C
THICKNESS = (0.0, 0.1, 0.2, 0.3)  # delta / h_min
LAYER_VISCOSITY = (2.0, 10.0, 100.0)  # mu_ab / mu
ALPHA = 0.1  # alpha / h_min


def _state(grid, thickness, viscosity_ratio, alpha):
    C = BEARING["clearance"]
    layers = None if thickness == 0 else BoundaryLayers(thickness * H_MIN * C, viscosity_ratio * BEARING["viscosity"],
                                                        alpha * H_MIN * C)
    b = JournalBearing(**BEARING, grid=grid, layers=layers)
    return b, b.steady_state(ECCENTRICITY, SPEED_RPM)


def layered_cases(grid=(121, 20)) -> dict:
    """The cases of the module docstring: per layer thickness (alpha = 0 and alpha = 0.1 h_min) and per layer
    viscosity (delta = 0.1 h_min); loads [N], peak p*, and the mid-plane p*(angle) profiles."""
    b0, s0 = _state(grid, 0.0, 1.0, 0.0)
    p0 = b0.pressure_scale(SPEED_RPM)
    out = dict(grid=list(grid), p0_Pa=p0, angle_deg=s0.angle_deg, base=dict(load_N=s0.load,
               peak=s0.max_pressure / p0, profile=s0.pressure[0] / p0), thickness=[], viscosity=[])
    for d in THICKNESS[1:]:
        row = dict(delta_over_hmin=d)
        for tag, a in (("immobile", 0.0), ("mobile", ALPHA)):
            _, s = _state(grid, d, 10.0, a)
            row[tag] = dict(load_N=s.load, peak=s.max_pressure / p0, profile=s.pressure[0] / p0)
        row["rise_thinner_bulk"] = row["immobile"]["load_N"] / s0.load - 1.0
        row["darcy_share"] = (row["mobile"]["load_N"] - row["immobile"]["load_N"]) / s0.load
        out["thickness"].append(row)
    for v in LAYER_VISCOSITY:
        _, s = _state(grid, 0.1, v, ALPHA)
        out["viscosity"].append(dict(mu_ab_over_mu=v, load_N=s.load, peak=s.max_pressure / p0,
                                     profile=s.pressure[0] / p0))
    return out
