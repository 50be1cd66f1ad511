"""Rho & Kim, "Noise estimation of oil lubricated journal bearings", sections 2.3-2.4: bearing noise from the film
pressure fluctuation against speed.

    transient run scenarios/journal_noise.py [--quick] [--out DIR] [--grid NT NZ] [--speeds ...] [--settle]

Default: the paper's 151 x 21 half grid, 1000-7500 rpm (quick: 41 x 6, 3 speeds). Each speed:
transient.bearing_noise (the periodic orbit by shooting to 1e-4 C -- no settling run; --settle: settle from
the static equilibrium until the once-per-revolution journal position repeats to 1e-4 C -- then record the
pressure over an integer number of revolutions only). Figures and journal_noise.json (rewritten after each
speed) into transient_out/noise/:
* Fig. 9/10 -- N_b (eq. 16) and A-weighted N_b against speed; Fig. 11/12 -- per-harmonic levels;
* Fig. 5/6 -- equilibrium pressure, RMS fluctuation p_f and its level in the oil at 6000 rpm;
* Fig. 4/7 -- journal x spectrum and nodal spectra at film rupture, reformation, 96 deg and max p_f;
* Fig. 8 -- whirl amplitude of the settled orbit.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import Integration, JournalBearing, JournalOrbit, Settling, bearing_noise
from transient.analysis import NotPeriodicError, film_transitions
from transient.compile_notice import announce
from transient.params import rho_kim
from transient.plots import journal as plots, save
from transient.study.scenario import JsonRecord, log, parser

OUT = "noise"  # output folder name: ROOT/noise (transient.study.scenario)
FULL = dict(grid=(151, 21), speeds=(1000, 2000, 3000, 4000, 5000, 6000, 7000, 7500))
QUICK = dict(grid=(41, 6), speeds=(2000, 4000, 6000))
FIG_SPEED = 6000
TIMINGS = ("integration", "recording", "recording_overhead", "analysis")


def local_ratio(n, col, row=0):
    """Level of harmonics 2x.. relative to 1x at a node [dB]."""
    h = n.harmonic_rms[:, row, col]
    with np.errstate(divide="ignore"):
        return [float(20 * np.log10(h[k] / h[0])) for k in range(1, n.harmonics)] if h[0] > 0 else None


def point(n, eq, tr):
    """The numbers of one speed."""
    r = np.hypot(n.x - n.x.mean(), n.y - n.y.mean())
    p = n.summary()
    p.update(whirl_amplitude_um=float(r.max() * 1e6), equilibrium_eccentricity=eq.eccentricity_ratio, transitions=tr,
             harmonic_max_angle_deg=[float(n.angle_deg[int(np.argmax(n.harmonic_rms[k, 0]))]) for k in range(n.harmonics)],
             p_fluct_max_angle_deg=float(n.angle_deg[int(np.argmax(n.p_fluct[0]))]),
             x_1x_over_2x=float(n.x_spectrum[1][n.revolutions] / n.x_spectrum[1][2 * n.revolutions]))
    if tr:
        p["harmonics_rel_1x_db"] = {k: local_ratio(n, i) for k, i in (
            ("rupture", tr["rupture_index"]), ("reformation", tr["reformation_index"]),
            ("max_p_fluct", int(np.argmax(n.p_fluct[0]))), ("max_pressure", tr["max_pressure_index"]))}
    return p


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--grid", nargs=2, type=int, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 41 6)")
    ap.add_argument("--speeds", nargs="+", type=float, help="speeds [rpm]")
    ap.add_argument("--revolutions", type=int, default=4, help="analysis window [rev] (default 4)")
    ap.add_argument("--harmonics", type=int, default=5)
    ap.add_argument("--transmission", choices=("printed", "two_interface"), default="printed")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--max-settle", type=int, default=60, help="max settling revolutions (default 60)")
    ap.add_argument("--settle", action="store_true", help="settling runs instead of the periodic orbit by shooting")
    a = ap.parse_args(argv)
    announce("journal")
    cfg = dict(QUICK if a.quick else FULL)
    grid = tuple(a.grid) if a.grid else cfg["grid"]
    speeds = a.speeds or cfg["speeds"]
    out = Path(a.out)
    rec = JsonRecord(out / "journal_noise.json", dict(grid=grid, speeds=speeds, revolutions=a.revolutions,
                     harmonics=a.harmonics, transmission=a.transmission, rtol=a.rtol, method="ida", settle_tol_C=1e-4,
                     periodic=not a.settle,
                     rotor=rho_kim.ROTOR))
    bearing = JournalBearing(**rho_kim.BEARING, grid=grid)
    wall0 = time.perf_counter()
    tot = dict.fromkeys(TIMINGS + ("equilibrium",), 0.0)
    points = []
    for sp in speeds:
        o = JournalOrbit(bearing, **rho_kim.ROTOR, speed_rpm=sp)
        t0 = time.perf_counter()
        eq = o.equilibrium()
        tot["equilibrium"] += time.perf_counter() - t0
        tr = film_transitions(eq)
        try:
            n = bearing_noise(o, revolutions=a.revolutions, harmonics=a.harmonics, transmission=a.transmission,
                              integration=Integration(rtol=a.rtol), settling=Settling(max_periods=a.max_settle),
                              periodic=not a.settle)
        except NotPeriodicError as exc:
            log(f"{sp:6.0f} rpm: {exc}")
            points.append(dict(speed_rpm=sp, error=str(exc)))
            rec.put("points", points)
            continue
        for k in TIMINGS:
            tot[k] += n.timings.get(k, 0.0)
        points.append(point(n, eq, tr))
        log(f"{sp:6.0f} rpm: N_b = {n.level_db:6.2f} dB, A-weighted {n.level_dba:6.2f} dB(A), harmonics "
            f"{np.array2string(n.harmonic_levels_db, precision=1)} dB; {n.settle_revolutions} rev "
            + ("to settle" if a.settle else "integrated by shooting"))
        if abs(sp - FIG_SPEED) < 1e-9:
            save(plots.noise_maps(n, eq, tr), out / "fig5_fig6_pfluct.png")
            save(plots.noise_spectra(n, tr), out / "fig4_fig7_spectra.png")
            n.save(out / f"noise_{sp:.0f}rpm.npz")
            rec.put("equilibrium_6000", dict(angle_deg=eq.angle_deg, film_content_midplane=eq.film_content[0],
                                             pressure_midplane=eq.pressure[0], p_fluct_midplane=n.p_fluct[0],
                                             harmonic_rms_midplane=n.harmonic_rms[:, 0]))
        rec.put("points", points)
        rec.put("timings", dict(tot, total=time.perf_counter() - wall0))
        if any("level_db" in p for p in points):
            save(plots.noise_levels(points, grid), out / "fig9_to_fig12_levels.png")
            save(plots.whirl_amplitude(points), out / "fig8_whirl.png")
    ok = [p for p in points if "level_db" in p]
    if len(ok) >= 3:
        L, s = np.array([p["level_db"] for p in ok]), np.array([p["speed_rpm"] for p in ok])
        rec.put("slope_db_per_krpm", np.diff(L) / np.diff(s) * 1e3)
    total = time.perf_counter() - wall0
    log(f"total {total:.1f} s: {'settling' if a.settle else 'periodic orbits'} {tot['integration']:.1f} s ({100 * tot['integration'] / total:.0f} %), recording "
        f"{tot['recording']:.1f} s, analysis {tot['analysis']:.3f} s, equilibria {tot['equilibrium']:.1f} s; {rec.path}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
