"""EHL of a tilted tapered roller: Park, "Elastohydrodynamic lubrication analysis of a tilted tapered roller", the
paper's Figs. 3-10.

Run: ``transient run scenarios/roller_ehl.py [--quick] [--out DIR]`` (PNGs and ``roller_ehl.json`` into
``transient_out/roller_ehl/`` by default). The paper's case (:mod:`transient.params.park`): U_m = 1e-11,
G = 2500, W = 2e-5, E' = 220 GPa, theta = 10 deg, R_d* = 0.5, Y_d = 0.7, tilt +0.002, -0.002 and 0 deg,
on the paper's 94 x 45 non-uniform grid (``--quick``: 62 x 45). Prints the paper's statements checked.
"""

from __future__ import annotations

import json
import os
import time

from transient.analysis.ehl import end_features, midplane_features, tilt_effects, transverse_features
from transient.compile_notice import announce
from transient.models.roller import RollerContact, TaperedRoller
from transient.params import park
from transient.plots import roller as plots
from transient.plots import save as save_figure
from transient.study.scenario import parser

HERE = os.path.dirname(os.path.abspath(__file__))


def solve_all(grid):
    out = {}
    for tilt in park.TILTS_DEG:
        roller = TaperedRoller(**park.ROLLER, tilt_deg=tilt)
        contact = RollerContact.from_dimensionless(**park.DIMENSIONLESS, roller=roller, speed=park.SPEED,
                                                   grid=grid)
        t0 = time.perf_counter()
        out[tilt] = contact.steady()
        d = contact.dry()
        print(f"tilt {tilt:+.3f} deg: {out[tilt].message} in {time.perf_counter() - t0:.1f} s "
              f"(dry c = {d.half_width * 1e6:.1f} um, d = {d.footprint_length * 1e3:.3f} mm)")
    return out


def statements(res) -> dict:
    """The paper's statements, each with the numbers that decide it (sections at Y = -+0.7: Figs. 7-10)."""
    s0, yd = res[0.0], park.ROLLER["profile_start"]
    sec = {e: midplane_features(s0, at=y) for e, y in (("small", -yd), ("large", yd))}
    ends0, eff = end_features(s0), tilt_effects(res, yd)
    tr = {f"{t:+.3f} {e}": v for t, r in res.items() for e, v in transverse_features(r).items()}
    spikes = {f"{t:+.3f} Y={y / park.MEAN_RADIUS:+.1f}": midplane_features(r, at=y) for t, r in res.items()
              for y in (-yd, 0.0, yd)}
    out = {
        "spike": dict(holds=all(v["spike"] for v in spikes.values()),
                      **{k: v["spike_over_centre"] if v["spike"] else None for k, v in spikes.items()}),
        "flat_central_film": dict(holds=all(v["central_film_variation"] < 0.05 for v in sec.values()),
                                  **{e: v["central_film_variation"] for e, v in sec.items()}),
        "outlet_constriction": dict(holds=all(v["h_min"] < 0.95 * v["h_central"] and v["x_of_h_min"] > 0
                                              for v in sec.values()),
                                    **{e: v["h_min"] / v["h_central"] for e, v in sec.items()}),
        "small_end_more_affected": dict(
            holds=all(eff[f"small_{k}_change"] > eff[f"large_{k}_change"] for k in
                      ("section_p_max", "end_p_max", "section_h_at_x0", "end_h_min")), **eff),
        "pressure_more_affected_than_film": dict(
            holds=all(eff[f"{e}_{p}_change"] > eff[f"{e}_{h}_change"] for e in ("small", "large")
                      for p, h in (("section_p_max", "section_h_at_x0"), ("end_p_max", "end_h_min"))), **eff),
        "transverse_peak_inboard_of_min_film": dict(holds=all(v["peak_inboard"] for v in tr.values()), **tr),
        "untilted_max_pressure_and_min_film_at_small_end": dict(
            holds=ends0["small"]["p_max"] > ends0["large"]["p_max"]
            and ends0["small"]["h_min"] < ends0["large"]["h_min"],
            **ends0),
    }
    return out


def save(fig, out, name):
    save_figure(fig, os.path.join(out, name), dpi=110)


def main(argv=None):
    args = parser(__doc__, os.path.join(HERE, "out", "roller_ehl")).parse_args(argv)
    announce("roller")
    os.makedirs(args.out, exist_ok=True)
    grid = ("clustered", 62, 45) if args.quick else "paper"
    res = solve_all(grid)
    lab = {t: f"φ = {t:+.3f}°" for t in res}
    named = {lab[t]: res[t] for t in res}
    rm, out = park.MEAN_RADIUS, args.out
    for no, tilt in ((3, 0.002), (5, -0.002)):
        save(plots.maps(res[tilt], "pressure", f"Fig. {no}: pressure, {lab[tilt]}"), out, f"fig{no}_pressure.png")
        save(plots.maps(res[tilt], "film", f"Fig. {no + 1}: film, {lab[tilt]}"), out, f"fig{no + 1}_film.png")
    save(plots.maps(res[0.0], "pressure", "no tilt: pressure"), out, "fig_untilted_pressure.png")
    for name, y, title in (("fig7_section_small_end", -0.7, "Fig. 7: rolling direction at Y = -0.7 (small end)"),
                           ("fig8_section_large_end", 0.7, "Fig. 8: rolling direction at Y = +0.7 (large end)"),
                           ("fig_section_midplane", 0.0, "rolling direction at Y = 0 (mid-plane)")):
        save(plots.rolling_sections(named, y * rm, title), out, name + ".png")
    for no, end in ((9, "small"), (10, "large")):
        save(plots.transverse_sections(named, end, 0.0, f"Fig. {no}: along X = 0 near the {end} end"), out,
             f"fig{no}_transverse_{end}_end.png")
    st = statements(res)
    summary = {f"{t:+.3f}": dict(r.summary(), H_central=r.h_central / rm, H_min=r.h_min / rm, P_max=r.p_max / r.modulus,
                                 ends=end_features(r), midplane=midplane_features(r)) for t, r in res.items()}
    with open(os.path.join(out, "roller_ehl.json"), "w") as fh:
        json.dump({"grid": grid, "results": summary, "statements": st}, fh, indent=1, default=float)
    for name, v in st.items():
        print(f"{name}: {'reproduced' if v['holds'] else 'NOT reproduced'}")
    return res


if __name__ == "__main__":
    main()
