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

import numpy as np

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


#: the paper's statements checked, in the order of docs/ehl.md's table (section 3)
STATEMENTS = {
    "spike": "pressure spike in the rolling direction",
    "flat_central_film": "flat central film",
    "outlet_constriction": "outlet constriction",
    "tilt_acts_at_the_ends": "tilt changes pressure and film strongly at the profiled ends, hardly at the centre",
    "small_end_more_affected": "larger effect at the small end than at the large end",
    "pressure_more_affected_than_film": "larger effect on pressure than on film",
    "transverse_peak_inboard_of_min_film": "transverse pressure peak inboard of the minimum film",
    "untilted_max_pressure_and_min_film_at_small_end": "without tilt, maximum pressure and minimum film at the small end",
}


def _verdict(passed: int, of: int) -> str:
    return "reproduced" if passed == of else "partly" if passed else "NOT reproduced"


def _pct(v: float) -> str:
    return f"{100 * v:.1f} %"


def statements(res) -> dict:
    """The paper's statements (:data:`STATEMENTS`), each with its verdict ("reproduced", "partly": in some of the
    places or measures it is about, "NOT reproduced"), the numbers that decide it (``numbers``, one line) and
    those numbers in full (sections at Y = -+0.7: Figs. 7-10)."""
    s0, yd, rm = res[0.0], park.ROLLER["profile_start"], park.MEAN_RADIUS
    sec = {e: midplane_features(s0, at=y) for e, y in (("small", -yd), ("large", yd))}
    ends0, eff = end_features(s0), tilt_effects(res, yd)
    tr = {f"{t:+.3f} {e}": v for t, r in res.items() for e, v in transverse_features(r).items()}
    spikes = {f"{t:+.3f} Y={y / rm:+.1f}": midplane_features(r, at=y) for t, r in res.items()
              for y in (-yd, 0.0, yd)}
    centre = np.array([midplane_features(r)["h_central"] for r in res.values()])
    centre_change = float((centre.max() - centre.min()) / midplane_features(s0)["h_central"])
    end_changes = {f"{e}_{k}_change": eff[f"{e}_{k}_change"] for e in ("small", "large") for k in ("end_p_max", "end_h_min")}
    out = {}

    def put(key, passed, of, numbers, **details):
        verdict = _verdict(passed, of)
        out[key] = dict(statement=STATEMENTS[key], verdict=verdict, holds=verdict == "reproduced", numbers=numbers,
                        **details)

    found = {k: v["spike_over_centre"] for k, v in spikes.items() if v["spike"]}
    put("spike", len(found), len(spikes), f"a second, outlet-side pressure peak in {len(found)} of {len(spikes)} "
        "rolling sections (Y = -0.7, 0, +0.7 x three tilts)" + (": " + ", ".join(
            f"{k} {100 * v:+.1f} % of the centre pressure" for k, v in found.items()) if found else ""),
        **{k: found.get(k) for k in spikes})
    put("flat_central_film", sum(v["central_film_variation"] < 0.05 for v in sec.values()), 2,
        "film variation over |X| < c/2 (flat: below 5 %): " + ", ".join(
            f"{_pct(v['central_film_variation'])} at the {e} end" for e, v in sec.items()),
        **{e: v["central_film_variation"] for e, v in sec.items()})
    put("outlet_constriction", sum(v["h_min"] < 0.95 * v["h_central"] and v["x_of_h_min"] > 0 for v in sec.values()), 2,
        "section minimum / film at X = 0 (a constriction: below 0.95, on the outlet side): " + ", ".join(
            f"{v['h_min'] / v['h_central']:.2f} at the {e} end" for e, v in sec.items()),
        **{e: v["h_min"] / v["h_central"] for e, v in sec.items()})
    put("tilt_acts_at_the_ends", (centre_change < 0.01) + sum(v > 0.1 for v in end_changes.values()), 5,
        f"spread over the tilts, relative to tilt 0 (hardly: below 1 %, strongly: above 10 %): mid-plane central "
        f"film {100 * centre_change:.2f} %, end maxima and minima " + ", ".join(
            f"{k.replace('_change', '')} {_pct(v)}" for k, v in end_changes.items()),
        centre_film_change=centre_change, **end_changes)
    measures = ("section_p_max", "end_p_max", "section_h_at_x0", "end_h_min")
    put("small_end_more_affected", sum(eff[f"small_{k}_change"] > eff[f"large_{k}_change"] for k in measures),
        len(measures), "spread over the tilts, small vs large end: " + ", ".join(
            f"{k} {_pct(eff[f'small_{k}_change'])} vs {_pct(eff[f'large_{k}_change'])}" for k in measures), **eff)
    pairs = [(e, p, h) for e in ("small", "large") for p, h in (("section_p_max", "section_h_at_x0"),
                                                              ("end_p_max", "end_h_min"))]
    put("pressure_more_affected_than_film", sum(eff[f"{e}_{p}_change"] > eff[f"{e}_{h}_change"] for e, p, h in pairs),
        len(pairs), "spread over the tilts, pressure vs film: " + ", ".join(
            f"{e} {p} {_pct(eff[f'{e}_{p}_change'])} vs {h} {_pct(eff[f'{e}_{h}_change'])}" for e, p, h in pairs),
        **eff)
    yp = [abs(v["y_of_peak"]) / rm for v in tr.values()]
    yh = [abs(v["y_of_min_film"]) / rm for v in tr.values()]
    put("transverse_peak_inboard_of_min_film", sum(v["peak_inboard"] for v in tr.values()), len(tr),
        f"along X = 0, {sum(v['peak_inboard'] for v in tr.values())} of {len(tr)} ends (three tilts): peak at "
        f"|Y| = {min(yp):.4f}-{max(yp):.4f}, minimum film at |Y| = {min(yh):.4f}-{max(yh):.4f} (R_m)", **tr)
    sm, lg = ends0["small"], ends0["large"]
    put("untilted_max_pressure_and_min_film_at_small_end", (sm["p_max"] > lg["p_max"]) + (sm["h_min"] < lg["h_min"]), 2,
        f"tilt 0: P_max {sm['p_max'] / s0.modulus:.4g} (small end) vs {lg['p_max'] / s0.modulus:.4g} (large), "
        f"H_min {sm['h_min'] / rm:.3g} vs {lg['h_min'] / rm:.3g}", **ends0)
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
    counts = {v: sum(x["verdict"] == v for x in st.values()) for v in ("reproduced", "partly", "NOT reproduced")}
    print(f"the paper's {len(st)} statements: " + ", ".join(f"{n} {v}" for v, n in counts.items()))
    for v in st.values():
        print(f"  {v['statement']}: {v['verdict']} ({v['numbers']})")
    return res


if __name__ == "__main__":
    main()
