"""The friction rig of Sander et al. (Tribol. Int. 96 (2016)): computed shaft torque against the measured curves.

    transient run scenarios/sander_stribeck.py [--quick] [--out DIR]

The big-end bearing (D 47.8 mm, L 17.2 mm, C 23.9 um) of a connecting rod on a shaft held by two support bearings
(D 54 mm, L 25 mm), oil at 100 C (6.8 mPa s), under 4 and 8 kN (about 5 and 10 MPa): the surfaces' Greenwood-Tripp
summits and Patir-Cheng flow factors as transcribed in MBDyn's test (transient.params.sander). At each load the
Stribeck curves of the test bearing and of one support (half the load) from 4000 rpm down, the shaft torque their
sum with both supports; beside it the measured torque and MBDyn's elastic model at 8 kN. The same with the summits'
mean plane on the surfaces' (delta = 0) as the sensitivity to the contact's offset, with the oil's
pressure-viscosity (Barus, 9.5e-9 1/Pa) in the films, with Winkler bores of the housings' Lame compliance
(transient.params.sander.bore_compliance), and with both. --quick: 48 x 8 and 12 speeds; else 151 x 21 and 26
speeds (the measured ones among them). Writes DIR/sander_stribeck.png, _delta0.png, _barus.png, _elastic.png,
_barus_elastic.png and .json.
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import numpy as np

from transient.compile_notice import announce
from transient.params import sander
from transient.plots import mixed as plots, save
from transient.study.sander import deviations, measured_minimum, rig_curve
from transient.study.scenario import JsonRecord, log, parser

OUT = "sander_stribeck"


def speeds(quick):
    """The measured speeds and a geometric series from 150 to 4000 rpm without its speeds within 5 % of a measured
    one (26 in all; 11 with ``quick``)."""
    given = np.unique(np.concatenate([np.asarray(s, dtype=float) for s, _ in sander.MEASURED.values()]))
    extra = np.geomspace(150.0, 4000.0, 4 if quick else 24)
    extra = extra[np.min(np.abs(np.log(extra[:, None] / given[None, :])), axis=1) > np.log(1.05)]
    return np.unique(np.concatenate([given, extra]))


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    announce("journal")
    grid = (48, 8) if a.quick else (151, 21)
    sp = speeds(a.quick)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    rec = JsonRecord(out / "sander_stribeck.json", dict(grid=grid, quick=a.quick))
    t0 = time.perf_counter()
    curves = {}
    elastic = (sander.roughness(bore_compliance=sander.bore_compliance(sander.TEST, sander.CONROD)),
               sander.roughness(bore_compliance=sander.bore_compliance(sander.SUPPORT, sander.SUPPORT_HOUSING)))
    variants = (("transcribed", (None, None)), ("delta0", (sander.roughness(summit_height=0.0), None)),
                ("barus", (sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY), None)),
                ("elastic", elastic),
                ("barus_elastic", tuple(sander.roughness(pressure_viscosity=sander.PRESSURE_VISCOSITY,
                                                         bore_compliance=e.bore_compliance) for e in elastic)))
    for label, (surface, support_surface) in variants:
        for load in sander.LOADS:
            c0 = time.process_time()
            with warnings.catch_warnings():  # contact pressures above the isoviscous film's range at low speed
                warnings.simplefilter("ignore", UserWarning)
                curve = rig_curve(load, sp, grid, surface, support_surface)
            cpu = time.process_time() - c0
            curves[label, load] = curve
            dev = deviations(curve)
            log(f"[{label}] {load:g} N: least torque at {curve.minimum_speed_rpm:.0f} rpm (measured "
                f"{measured_minimum(load):.0f}); test bearing lift-off {curve.test.lift_off_speed_rpm:.0f} rpm; "
                f"{cpu:.0f} s CPU")
            for n, (m, c, d) in sorted(dev.items()):
                log(f"    {n:6.0f} rpm: measured {m:.3f} N m, computed {c:.3f} N m ({100 * d:+.0f} %)")
            rec.put(f"{label}_{load:g}", dict(
                speed_rpm=curve.speed_rpm, torque=curve.torque, test_torque=curve.test.friction_torque,
                support_torque=curve.support.friction_torque, test_h_min=curve.test.h_min,
                test_contact_load=curve.test.contact_load, support_contact_load=curve.support.contact_load,
                minimum_speed_rpm=curve.minimum_speed_rpm, measured_minimum_rpm=measured_minimum(load),
                test_lift_off_rpm=curve.test.lift_off_speed_rpm, deviations=dev, cpu_s=cpu))
    h_min = {8000.0: ((3000, 150), (2e-6, 0.7e-6))}
    titles = {"transcribed": "rigid isoviscous bearings, summit offset 0.6 um (transcribed)",
              "delta0": "rigid isoviscous bearings, summit offset 0",
              "barus": "rigid bearings, Barus oil (9.5e-9 1/Pa), summit offset 0.6 um",
              "elastic": "Winkler bores (Lame: 5.3e-13, 2.5e-13 m/Pa), isoviscous, summit offset 0.6 um",
              "barus_elastic": "Winkler bores (Lame), Barus oil (9.5e-9 1/Pa), summit offset 0.6 um"}
    for label in titles:
        name = "sander_stribeck.png" if label == "transcribed" else f"sander_stribeck_{label}.png"
        title = f"Sander et al. 2016 rig: {titles[label]}, grid {grid[0]} x {grid[1]}"
        fig = plots.rig_torque([curves[label, w] for w in sander.LOADS], sander.MEASURED, sander.PEER, h_min, title)
        log(f"written: {save(fig, out / name)}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[sander_stribeck] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'sander_stribeck.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
