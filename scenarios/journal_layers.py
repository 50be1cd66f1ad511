"""Boundary layers in the journal bearing of Jang, "Study on boundary lubrication in the sliding bearing system
under high load and speed" (eps = 0.9, R/B = 1), Newtonian and shear-thinning bulk.

    transient run scenarios/journal_layers.py [--quick] [--out DIR]

Layers of 0.1, 0.2, 0.3 h_min on both walls (layer viscosity 10 mu; 2 and 100 mu at 0.1 h_min), immobile
(alpha = 0) and mobile (alpha = 0.1 h_min): the load and the peak pressure against the layer-free film, the
rise split into the thinner bulk and the Darcy flow, and the mid-plane pressure profiles (DIR/layers.png), with
a Newtonian bulk; the same with the paper's Gecim bulk (kappa* = 0.65, mu_2/mu_1 = 0.57) with the friction
(DIR/gecim.png, the pressure fields DIR/gecim_fields.png); and from mobile to immobile layers the velocity across the film and the interface shear
(DIR/immobility.png, Figs. 9-11); and the Gecim bulk in the rotor computations of the bearing of Rho & Kim, "Noise
estimation of oil lubricated journal bearings": equilibrium, K and C, Lund threshold and the periodic unbalance
orbit by shooting (DIR/dynamics.png). Numbers in DIR/layers.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from transient.compile_notice import announce
from transient.plots import layers as plots, save
from transient.study.layers import gecim_cases, layered_cases, shear_thinning_dynamics
from transient.study.scenario import JsonRecord, log, parser

OUT = "journal_layers"  # output folder name: ROOT/journal_layers (transient.study.scenario)


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    announce("journal", "layered")
    grid = (61, 10) if a.quick else (241, 40)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    res = layered_cases(grid)
    rec = JsonRecord(out / "layers.json", dict(grid=grid, quick=a.quick))
    rec.put("cases", res.record())
    b = res.base
    log(f"[layers] grid {grid[0]} x {grid[1]}: no layers: load {b['load_N']:.1f} N, peak p/p0 {b['peak']:.3f}")
    for row in res.thickness:
        im, mo = row["immobile"], row["mobile"]
        log(f"  delta {row['delta_over_hmin']:.1f} h_min: immobile {im['load_N']:.1f} N (peak {im['peak']:.3f}), "
            f"mobile {mo['load_N']:.1f} N (peak {mo['peak']:.3f}); thinner bulk +{100 * row['rise_thinner_bulk']:.1f} %, "
            f"Darcy {100 * row['darcy_share']:+.1f} % of the layer-free load")
    for row in res.viscosity:
        log(f"  mu_ab {row['mu_ab_over_mu']:g} mu (delta 0.1 h_min, mobile): load {row['load_N']:.1f} N, "
            f"peak {row['peak']:.3f}")
    log(f"written: {save(plots.layered_profiles(res), out / 'layers.png')}")
    g = gecim_cases(grid)
    rec.put("gecim", g.record())
    b = g.base
    log(f"[gecim bulk] kappa {g.kappa_Pa:.4g} Pa: no layers: load {b['gecim']['load_N']:.1f} N "
        f"({b['gecim']['load_N'] / b['newtonian']['load_N']:.3f} of the Newtonian bulk), friction "
        f"{b['gecim']['friction_N']:.3f} N (Newtonian {b['newtonian']['friction_N']:.3f} N)")
    for row in g.thickness:
        ge = row["gecim"]
        log(f"  delta {row['delta_over_hmin']:.1f} h_min: load {ge['load_N']:.1f} N ({row['thinning_load_ratio']:.3f} "
            f"of Newtonian), peak {ge['peak']:.3f}; thinner bulk +{100 * row['rise_thinner_bulk']:.1f} %, Darcy "
            f"{100 * row['darcy_share']:+.1f} %; friction {ge['friction_N']:.3f} N on the journal (f = "
            f"{ge['friction_coefficient']:.4f}), {ge['bearing_friction_N']:.3f} N on the bearing")
    for row in g.viscosity:
        log(f"  mu_ab {row['mu_ab_over_mu']:g} mu (delta 0.1 h_min): load {row['load_N']:.1f} N")
    for row in g.immobility:
        log(f"  alpha {row['alpha_over_hmin']:g} h_min, mu_ab {row['mu_ab_over_mu']:g} mu: load {row['load_N']:.1f} N, "
            f"max interface shear {abs(row['interface_lower_Pa']).max() / 1e3:.3f} kPa (journal side), "
            f"{abs(row['interface_upper_Pa']).max() / 1e3:.3f} kPa (bearing side); layer slip u_a/U "
            f"{row['u_over_U'][0]:.5f}")
    log(f"written: {save(plots.gecim_profiles(g), out / 'gecim.png')}")
    log(f"written: {save(plots.pressure_fields(g), out / 'gecim_fields.png')}")
    log(f"written: {save(plots.immobility(g), out / 'immobility.png')}")
    d = shear_thinning_dynamics((48, 8) if a.quick else (151, 21))
    rec.put("dynamics", d.record())
    for name in ("newtonian", "gecim"):
        r = getattr(d, name)
        orbit = (f"periodic orbit span {r['orbit_span_C'][0]:.4f} x {r['orbit_span_C'][1]:.4f} C (shooting converged, "
                 f"error {r['error_estimate_C']:.1e} C, |mu| {r['max_multiplier']:.3f}, {r['periods']} periods)"
                 if r["converged"] else f"periodic orbit NOT converged: {r['message']}")
        log(f"[rotor, {name} bulk] Rho & Kim at {d.speed_rpm:.0f} rpm: e/C {r['eccentricity']:.4f}, attitude "
            f"{r['attitude_deg']:.2f} deg, friction {r['friction_N']:.2f} N, Kxx {r['K'][0][0]:.4g} N/m, Cxx "
            f"{r['C'][0][0]:.4g} N s/m, threshold {r['threshold_rpm']:.0f} rpm, {orbit}")
    log(f"written: {save(plots.dynamics(d), out / 'dynamics.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[layers] done in {time.perf_counter() - t0:.1f} s; numbers in {out / 'layers.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
