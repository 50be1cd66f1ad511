"""Seed 003 (Rho & Kim) sections 2.3-2.4: bearing noise from the film pressure fluctuation vs speed.

Run: ``python scenarios/journal_noise.py [--quick] [--grid NT NZ] [--speeds ...] [--out DIR]``
(default: the paper's 151 x 21 half grid, speeds 1000-7500 rpm; ``--quick``: 41 x 6, 3 speeds).
Figures and ``journal_noise.json`` (rewritten after each speed) into scenarios/out/noise/:

* Fig. 9/10 -- N_b (eq. 16) and A-weighted N_b vs speed (with the whirl amplitude, Fig. 8);
* Fig. 11/12 -- per-harmonic bearing levels (1x..5x), unweighted and A-weighted, vs speed;
* Fig. 5 -- equilibrium pressure (a) and RMS fluctuation p_f (b) at 6000 rpm; Fig. 6 -- level of p_f
  in the oil re 1 uPa; Fig. 4 -- journal x spectrum;
* Fig. 7 -- nodal spectra (re 1 uPa, in the oil) at mid-plane nodes: film rupture and reformation
  of the equilibrium (theta crossing 1 on the mid-plane row), the paper's 96 deg, and max p_f.

Each speed: :func:`transient.analysis.bearing_noise` (settles from the static equilibrium until the
once-per-revolution journal position repeats to 1e-4 C, then records the pressure over an integer
number of revolutions only). The total time and its split integration / recording / analysis are
printed and saved.
"""

from __future__ import annotations

import argparse
import json
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from transient import bearing_noise
from transient.analysis import NotPeriodicError, film_transitions
from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "out", "noise")
FULL = dict(grid=(151, 21), speeds=(1000, 2000, 3000, 4000, 5000, 6000, 7000, 7500))
QUICK = dict(grid=(41, 6), speeds=(2000, 4000, 6000))
FIG_SPEED = 6000


def log(msg):
    print(msg, flush=True)


def save(path, data):
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        json.dump(data, fh, indent=1, default=lambda v: v.tolist() if hasattr(v, "tolist") else float(v))
    os.replace(tmp, path)


def harmonic_locations(n, row=0):
    """Angle [deg] of the largest RMS amplitude of each harmonic along the mid-plane row."""
    return [float(n.angle_deg[int(np.argmax(n.harmonic_rms[k, row]))]) for k in range(n.harmonics)]


def local_ratio(n, col, row=0):
    """Level of harmonics 2x.. relative to 1x at a node [dB]."""
    h = n.harmonic_rms[:, row, col]
    if h[0] <= 0:
        return None
    with np.errstate(divide="ignore"):
        return [float(20 * np.log10(h[k] / h[0])) for k in range(1, n.harmonics)]


def figures_6000(n, eq, tr, out):
    ang = n.angle_deg
    zz = n.z * 1e3
    fig, ax = plt.subplots(1, 3, figsize=(15, 4))
    spl = np.asarray(n.oil_spl(), dtype=float)
    top = np.nanmax(spl[np.isfinite(spl)])
    spl = np.where(np.isfinite(spl), np.maximum(spl, top - 100.0), top - 100.0)  # cavitated: p_f ~ 0
    for a, data, title, unit in ((ax[0], eq.pressure / 1e6, "(a) equilibrium pressure", "MPa"),
                                 (ax[1], n.p_fluct / 1e3, "(b) pressure fluctuation p_f", "kPa"),
                                 (ax[2], spl, "Fig. 6: level of p_f in the oil (floor: max - 100 dB)",
                                  "dB re 1 uPa")):
        m = a.pcolormesh(ang, zz, data, shading="nearest")
        fig.colorbar(m, ax=a, label=unit)
        a.set(xlabel="angle [deg]", ylabel="z from mid-plane [mm]", title=title)
        for key, c in (("rupture_deg", "r"), ("reformation_deg", "w")):
            if key in tr:
                a.axvline(tr[key], color=c, ls="--", lw=0.8)
    fig.suptitle(f"Fig. 5/6 at {n.speed_rpm:g} rpm (grid {n.p_fluct.shape[1]} x {n.p_fluct.shape[0]}; "
                 "dashed: rupture red, reformation white)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig5_fig6_pfluct.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(1, 2, figsize=(12, 4))
    f, a = n.x_spectrum
    ax[0].semilogy(f[1:] / n.frequency_hz, a[1:] * 1e6, "o-", ms=3)
    ax[0].set(xlabel="frequency / shaft frequency", ylabel="x amplitude [um]", title="Fig. 4: journal x spectrum",
              xlim=(0, n.samples_per_revolution / 2))
    nodes = [("max p_f", int(np.argmax(n.p_fluct[0])))]
    if tr:
        nodes += [(f"rupture {tr['rupture_deg']:.0f} deg", tr["rupture_index"]),
                  (f"reformation {tr['reformation_deg']:.0f} deg", tr["reformation_index"])]
    nodes.append(("paper's reformation 96 deg", n.node(96.0)[1]))
    for lab, col in nodes:
        f, L = n.spectrum("pressure", node=(0, col), db=True)
        ax[1].plot(f[1:] / n.frequency_hz, L[1:], "o-", ms=3, label=f"{lab} (node {col})")
    ax[1].set(xlabel="frequency / shaft frequency", ylabel="dB re 1 uPa (oil)", title="Fig. 7: nodal spectra, mid-plane",
              xlim=(0, n.samples_per_revolution / 2))
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig4_fig7_spectra.png"), dpi=110)
    plt.close(fig)


def sweep_figures(points, out, grid):
    ok = [p for p in points if "level_db" in p]
    if not ok:
        return
    sp = np.array([p["speed_rpm"] for p in ok])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4))
    ax[0].plot(sp, [p["level_db"] for p in ok], "o-", label="N_b (eq. 16)")
    ax[0].plot(sp, [p["level_dba"] for p in ok], "s-", label="N_b, A-weighted")
    ax[0].set(xlabel="speed [rpm]", ylabel="dB re 20 uPa (printed eq. 14)", title="Fig. 9/10: bearing noise")
    ax[0].legend()
    H = np.array([p["harmonic_levels_db"] for p in ok])
    HA = np.array([p["harmonic_levels_dba"] for p in ok])
    for k in range(H.shape[1]):
        ax[1].plot(sp, H[:, k], "o-", label=f"{k + 1}x")
        ax[2].plot(sp, HA[:, k], "o-", label=f"{k + 1}x")
    ax[1].set(xlabel="speed [rpm]", ylabel="dB", title="Fig. 11: harmonic levels")
    ax[2].set(xlabel="speed [rpm]", ylabel="dB(A)", title="Fig. 12: A-weighted harmonic levels")
    ax[1].legend(fontsize=8)
    fig.suptitle(f"grid {grid[0]} x {grid[1]}")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig9_to_fig12_levels.png"), dpi=110)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(sp, [p["whirl_amplitude_um"] for p in ok], "o-")
    ax.set(xlabel="speed [rpm]", ylabel="max |r - r_mean| [um]", title="Fig. 8: unbalance response")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig8_whirl.png"), dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--grid", nargs=2, type=int, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 41 6)")
    ap.add_argument("--quick", action="store_true", help="coarse grid, 3 speeds")
    ap.add_argument("--speeds", nargs="+", type=float, help="speeds [rpm]")
    ap.add_argument("--revolutions", type=int, default=4, help="analysis window [rev] (default 4)")
    ap.add_argument("--harmonics", type=int, default=5)
    ap.add_argument("--transmission", choices=("printed", "two_interface"), default="printed")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--max-settle", type=int, default=60, help="max settling revolutions (default 60)")
    args = ap.parse_args(argv)
    cfg = dict(QUICK if args.quick else FULL)
    grid = tuple(args.grid) if args.grid else cfg["grid"]
    speeds = args.speeds or cfg["speeds"]
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "journal_noise.json")
    bearing = JournalBearing(**RHO_KIM_BEARING, grid=grid)
    data = dict(meta=dict(grid=list(grid), speeds=list(speeds), revolutions=args.revolutions, harmonics=args.harmonics,
                          transmission=args.transmission, rtol=args.rtol, method="ida", settle_tol_C=1e-4,
                          rotor=RHO_KIM_ROTOR),
                points=[])
    wall0 = time.perf_counter()
    tot = dict(integration=0.0, recording=0.0, recording_overhead=0.0, analysis=0.0, equilibrium=0.0)
    for sp in speeds:
        o = JournalOrbit(bearing, **RHO_KIM_ROTOR, speed_rpm=sp)
        t0 = time.perf_counter()
        eq = o.equilibrium()
        tot["equilibrium"] += time.perf_counter() - t0
        tr = film_transitions(eq)
        try:
            n = bearing_noise(o, revolutions=args.revolutions, harmonics=args.harmonics, transmission=args.transmission,
                              rtol=args.rtol, max_settle_revolutions=args.max_settle)
        except NotPeriodicError as exc:
            log(f"{sp:6.0f} rpm: {exc}")
            data["points"].append(dict(speed_rpm=sp, error=str(exc)))
            save(path, data)
            continue
        for k in tot:
            tot[k] += n.timings.get(k, 0.0)
        r = np.hypot(n.x - n.x.mean(), n.y - n.y.mean())
        p = n.summary()
        p.update(whirl_amplitude_um=float(r.max() * 1e6), equilibrium_eccentricity=eq.eccentricity_ratio,
                 transitions=tr, harmonic_max_angle_deg=harmonic_locations(n),
                 p_fluct_max_angle_deg=float(n.angle_deg[int(np.argmax(n.p_fluct[0]))]),
                 x_1x_over_2x=float(n.x_spectrum[1][n.revolutions] / n.x_spectrum[1][2 * n.revolutions]))
        if tr:
            p["harmonics_rel_1x_db"] = {"rupture": local_ratio(n, tr["rupture_index"]),
                                        "reformation": local_ratio(n, tr["reformation_index"]),
                                        "max_p_fluct": local_ratio(n, int(np.argmax(n.p_fluct[0]))),
                                        "max_pressure": local_ratio(n, tr["max_pressure_index"])}
        data["points"].append(p)
        log(f"{sp:6.0f} rpm: N_b = {n.level_db:6.2f} dB, A-weighted {n.level_dba:6.2f} dB(A), harmonics "
            f"{np.array2string(n.harmonic_levels_db, precision=1)} dB; settled after {n.settle_revolutions} rev; "
            f"whirl {p['whirl_amplitude_um']:.3f} um; timings {dict((k, round(v, 2)) for k, v in n.timings.items())}")
        if abs(sp - FIG_SPEED) < 1e-9:
            figures_6000(n, eq, tr, args.out)
            theta_row = eq.film_content[0]
            data["equilibrium_6000"] = dict(angle_deg=eq.angle_deg, film_content_midplane=theta_row,
                                            pressure_midplane=eq.pressure[0], p_fluct_midplane=n.p_fluct[0],
                                            harmonic_rms_midplane=n.harmonic_rms[:, 0])
        data["timings"] = dict(tot, total=time.perf_counter() - wall0)
        save(path, data)
        sweep_figures(data["points"], args.out, grid)
    total = time.perf_counter() - wall0
    data["timings"] = dict(tot, total=total)
    ok = [p for p in data["points"] if "level_db" in p]
    if len(ok) >= 3:
        L = np.array([p["level_db"] for p in ok])
        s = np.array([p["speed_rpm"] for p in ok])
        data["slope_db_per_krpm"] = list(np.diff(L) / np.diff(s) * 1e3)
    save(path, data)
    log(f"total {total:.1f} s: integration (settling) {tot['integration']:.1f} s "
        f"({100 * tot['integration'] / total:.0f} %), recording window {tot['recording']:.1f} s "
        f"({100 * tot['recording'] / total:.0f} %, of which recording overhead ~{tot['recording_overhead']:.1f} s), "
        f"analysis {tot['analysis']:.3f} s ({100 * tot['analysis'] / total:.2f} %), equilibria {tot['equilibrium']:.1f} s")
    log(f"wrote {path}")
    return data


if __name__ == "__main__":
    main()
