"""Lee & Rhim, "Mixed lubrication analysis of parallel thrust bearing by surface topography": a parallel thrust
pad in mixed lubrication with generated rough surfaces, Figs. 4-6.

    transient run scenarios/thrust_pad.py [--quick] [--out DIR]

Our choices where the paper gives no values are in transient.params.lee_rhim (pad 20 x 20 mm, 0.03 Pa s,
600 N, Rq = 5 um, l0 = 16 um) and transient.physics.asperity.STEEL_CONTACT (E' = 115.4 GPa, H = 4 GPa,
sqrt(Rq/Rp) = 0.01, N Rq Rp = 0.04: psi = 0.29, elastic). Surfaces of 512 x 512 samples (256 with --quick),
the same seed for the three gammas; W_asp, A_re and phi_c from each surface's height density, the flow
factors from its measured gamma. PNGs and thrust_pad.json into transient_out/thrust_pad/.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import Integration, ThrustPad
from transient.params import lee_rhim as P
from transient.plots import pad as plots, save
from transient.study import pad as study
from transient.study.scenario import JsonRecord, log, parser

OUT = "thrust_pad"  # output folder name: ROOT/thrust_pad (transient.study.scenario)


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    out = Path(a.out)
    n = 256 if a.quick else 512
    rq, t_end = P.SURFACE["rq"], 0.6
    rec = JsonRecord(out / "thrust_pad.json", dict(pad=P.PAD, load=P.LOAD, surface=P.SURFACE, samples=n))
    t0 = time.perf_counter()
    fig4 = {"Gaussian": study.surface(1.0, n, seed=5), "gamma-type": study.surface(1.0, n, seed=5, **P.SURFACE_4B)}
    save(plots.surfaces(fig4), out / "fig4_surfaces.png")
    rec.put("fig4", {k: s.statistics() for k, s in fig4.items()})
    pads = {g: ThrustPad(P.PAD["length"], P.PAD["width"], P.PAD["viscosity"], surface=study.surface(g, n), grid=(40, 40))
            for g in P.GAMMAS}
    times = study.descent_times(t_end, 301 if a.quick else 601)
    runs = {g: pad.descent(load=P.LOAD, h0_start=5 * rq, t_end=t_end, t_eval=times,
                           integration=Integration(method="cvode", rtol=1e-8, atol=1e-10))
            for g, pad in pads.items()}
    c = pads[1.0].contact
    rec.put("contact", dict(e_prime=c.e_prime, hardness=c.hardness, Rp=c.asperity_radius, N=c.asperity_density,
                            psi=c.plasticity_index, sigma=c.sigma))
    rec.put("surfaces", {f"{g:.4g}": dict(rq=p.sigma, gamma_measured=p.gamma, skewness=p.surface.skewness,
                                          kurtosis=p.surface.kurtosis) for g, p in pads.items()})
    # cross-check: the 2-D DAE against the separable path
    full = pads[1.0].descent(load=P.LOAD, h0_start=5 * rq, t_end=t_end, path="full", n_out=61,
                             integration=Integration(method="ida", rtol=1e-7, atol=1e-9))
    rel = float(np.max(np.abs(full.h0 / np.interp(full.t, runs[1.0].t, runs[1.0].h0) - 1)))
    rec.put("full_vs_separable", dict(max_rel_h0=rel, full_wall_s=full.stats.wall_time,
                                      separable_wall_s=runs[1.0].stats.wall_time))
    save(plots.descent_vs_time(runs, rq, P.LOAD), out / "fig5_vs_time.png")
    save(plots.vs_h0(study.curves_vs_h0(pads, np.linspace(0.5, 4.0, 200)), runs), out / "fig5_vs_h0.png")
    trends = study.trends(pads, P.LOAD)
    rec.put("trends", trends.rows)
    rec.put("seed_spread_H1.5", study.seed_spread(lambda s: ThrustPad(P.PAD["length"], P.PAD["width"],
                                                                      P.PAD["viscosity"], surface=s, grid=(4, 4)),
                                                  P.GAMMAS, n).per_gamma)
    fit = study.asperity_load_vs_area(pads, np.geomspace(50.0, 8000.0, 8 if a.quick else 14))
    save(plots.asperity_load_vs_area(fit, runs), out / "fig6_wasp_vs_area.png")
    rec.put("fig6", dict(fit.per_gamma, all=fit.overall))
    rec.put("descent", {f"{g:.4g}": dict(h_eq_over_rq=pads[g].equilibrium(P.LOAD) / pads[g].sigma,
                                         h_end_over_rq=float(r.h0[-1] / pads[g].sigma),
                                         t_to_2rq_ms=float(np.interp(-2.0, -r.h0 / pads[g].sigma, r.t) * 1e3),
                                         wall_s=r.stats.wall_time, n_steps=r.stats.n_steps) for g, r in runs.items()})
    for g, d in rec.data["descent"].items():
        log(f"gamma {g}: h_eq/Rq = {d['h_eq_over_rq']:.4f}, h(t_end)/Rq = {d['h_end_over_rq']:.4f}, "
            f"t(h0 = 2 Rq) = {d['t_to_2rq_ms']:.2f} ms")
    log(f"full 2-D DAE vs separable (gamma 1, 40x40): max |dh0/h0| = {rel:.2e}")
    for line in study.claim_verdicts(trends):
        log(line)
    log(f"Fig. 6: W_asp against A_re over all gammas: R^2 = {fit.overall['R2']:.5f}, mean contact pressure "
        f"{fit.overall['slope'] / 1e6:.1f} MPa")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"wrote {out} ({rec.data['wall_s']:.1f} s)")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
