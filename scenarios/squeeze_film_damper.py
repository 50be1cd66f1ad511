"""Squeeze-film damper on a circular centred orbit: film forces against the orbit radius and the supply pressure.

    transient run scenarios/squeeze_film_damper.py [--quick] [--out DIR]

A short damper (D 0.1 m, L 10 mm, c 100 um, 0.01 Pa s, fed through its open ends) whose journal whirls at 6000 rpm
without spinning. Its film is the journal bearing's, steady in the whirling frame
(:meth:`transient.SqueezeFilmDamper.circular_orbit`). Against the eccentricity ratio: the mass-conserving Elrod film
fed at a high pressure (the uncavitated 2-pi film), at 0.1 and 0.01 of the squeeze pressure mu w (L/c)^2, and the
Reynolds-condition film at the cavitation pressure (the pi-film), with the short-damper closed forms overlaid. Against
the supply pressure at e/c = 0.5: the Elrod film's forces as shares of the pi-film's, from starved to full.
Writes DIR/squeeze_film_damper.png, DIR/squeeze_film_damper_supply.png and DIR/squeeze_film_damper.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import SqueezeFilmDamper
from transient.plots import damper as plots, save
from transient.study.scenario import JsonRecord, log, parser

OUT = "squeeze_film_damper"
DAMPER = dict(diameter=0.1, length=0.01, clearance=100e-6, viscosity=0.01)
WHIRL_RPM = 6000.0
P_SQUEEZE = DAMPER["viscosity"] * WHIRL_RPM * np.pi / 30.0 * (DAMPER["length"] / DAMPER["clearance"]) ** 2  # [Pa]
#: the films drawn: name -> (SqueezeFilmDamper keywords, the closed form it is compared with or None)
FILMS = {"Elrod film, supply 300 mu w (L/c)^2 (full)": (dict(supply_pressure=300 * P_SQUEEZE, bulk_modulus=1e12),
                                                        "2pi"),
         "Reynolds-condition film at p_c": (dict(supply_pressure=0.0, cavitation="reynolds"), "pi"),
         "Elrod film, supply 0.1 mu w (L/c)^2": (dict(supply_pressure=0.1 * P_SQUEEZE), None),
         "Elrod film, supply 0.01 mu w (L/c)^2": (dict(supply_pressure=0.01 * P_SQUEEZE), None)}


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    grid = (48, 8) if a.quick else (144, 24)
    eps = np.linspace(0.1, 0.8, 4 if a.quick else 8)
    ratios = np.geomspace(1e-3, 30.0, 5 if a.quick else 13)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rec = JsonRecord(out / "squeeze_film_damper.json", dict(grid=grid, quick=a.quick, damper=DAMPER,
                                                             whirl_rpm=WHIRL_RPM, squeeze_pressure=P_SQUEEZE))
    curves, closed = {}, {}
    for name, (kw, form) in FILMS.items():
        d = SqueezeFilmDamper(**DAMPER, **kw, grid=grid)
        rows = [d.circular_orbit(e, WHIRL_RPM) for e in eps]
        fr, ft = np.array([r.radial_force for r in rows]), np.array([r.tangential_force for r in rows])
        curves[name] = (eps, fr, ft)
        entry = dict(eps=eps, radial_force=fr, tangential_force=ft, cavitated=[r.cavitated_fraction for r in rows])
        if form is not None:
            cr, ct = d.short_damper_forces(eps, WHIRL_RPM, form)
            closed[f"short damper, {form} film"] = (eps, cr, ct)
            entry.update(closed_form=form, tangential_deviation=ft / ct - 1.0,
                         radial_deviation=fr / cr - 1.0 if form == "pi" else fr / ct)
            log(f"  {name}: F_t / closed form - 1 from {entry['tangential_deviation'].min():+.4f} to "
                f"{entry['tangential_deviation'].max():+.4f}; radial {entry['radial_deviation'].min():+.4f} to "
                f"{entry['radial_deviation'].max():+.4f}" + (" (F_r / F_t)" if form == "2pi" else ""))
        rec.put(name, entry)
    title = (f"squeeze-film damper, D 0.1 m, L 10 mm, c 100 um, 0.01 Pa s, whirl {WHIRL_RPM:.0f} rpm, open ends fed at "
             f"the supply pressure, grid {grid[0]}x{grid[1]}: film (markers) and short-damper closed forms (lines)")
    log(f"written: {save(plots.orbit_forces(curves, closed, title), out / 'squeeze_film_damper.png')}")

    rows = [SqueezeFilmDamper(**DAMPER, supply_pressure=s * P_SQUEEZE, grid=grid).circular_orbit(0.5, WHIRL_RPM)
            for s in ratios]
    cr, ct = SqueezeFilmDamper(**DAMPER, supply_pressure=1.0, grid=grid).short_damper_forces(0.5, WHIRL_RPM, "pi")
    sweep = dict(pressure_ratio=ratios, radial_share=np.array([r.radial_force for r in rows]) / cr,
                 tangential_share=np.array([r.tangential_force for r in rows]) / ct,
                 cavitated=np.array([r.cavitated_fraction for r in rows]))
    rec.put("supply_sweep", sweep)
    for i, s in enumerate(ratios):
        log(f"  e/c 0.5, supply {s:8.3g} mu w (L/c)^2: F_t {sweep['tangential_share'][i]:.3f}, F_r "
            f"{sweep['radial_share'][i]:.3f} of the pi-film's; cavitated {sweep['cavitated'][i]:.2f}")
    title = f"the Elrod film at e/c 0.5 from starved to full, grid {grid[0]}x{grid[1]}"
    log(f"written: {save(plots.supply_sweep(**sweep, title=title), out / 'squeeze_film_damper_supply.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[squeeze-film damper] done in {time.perf_counter() - t0:.0f} s; numbers in "
        f"{out / 'squeeze_film_damper.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
