"""Seed 000 scenario: parallel thrust pad in mixed lubrication with generated rough surfaces
(analogues of Figs. 4-6 of Lee & Rhim).

Run: ``python scenarios/thrust_pad.py [--out DIR] [--quick]`` (PNGs and ``thrust_pad.json`` into
``scenarios/out/thrust_pad/`` by default). Prints a summary with the paper's trends checked.

Choices (not given in the paper; stated here and in the JSON):
* pad L = B = 20 mm, mu = 0.03 Pa s, load W = 600 N (apparent pressure 1.5 MPa), massless force
  balance, start at h0 = 5 Rq from rest;
* surfaces: Gaussian heights, Rq = 5.0 um (Fig. 4a), triangular ACF, spacing 2 um, 512 x 512 samples
  (256 x 256 with --quick), correlation lengths lx = l0 sqrt(gamma), ly = l0 / sqrt(gamma) with
  l0 = 16 um (the same correlation area for every gamma), the same random seed for the three gammas;
  Fig. 4b: gamma-type heights, Rq = 2.07 um, Sk = 0.3;
* contact: :func:`transient.physics.asperity.steel_asperity_contact` defaults -- E' = 115.4 GPa,
  H = 4 GPa, sqrt(Rq/Rp) = 0.01, N Rq Rp = 0.04, i.e. Rp = 50 mm, N = 1.6e5 m^-2 at Rq = 5 um,
  plasticity index psi = 0.29 (elastic); W_asp, A_re and phi_c from each surface's discrete height
  density (256 bins), the flow factors from its measured gamma.
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

from transient.surfaces.roughness import RoughSurface
from transient.models.pad.pad import ThrustPad

HERE = os.path.dirname(os.path.abspath(__file__))
UM = 1e-6
L = B = 0.02
MU = 0.03
RQ = 5.0 * UM
LOAD = 600.0
GAMMAS = (1 / 3, 1.0, 3.0)
LABEL = {1 / 3: "γ = 1/3 (transverse)", 1.0: "γ = 1 (isotropic)", 3.0: "γ = 3 (longitudinal)"}
COLOR = {1 / 3: "tab:blue", 1.0: "tab:red", 3.0: "tab:green"}


def surface(gamma, n, seed=11, rq=RQ, **kw):
    l0 = 16 * UM
    return RoughSurface.generate((n, n), 2 * UM, rq, correlation_lengths=(l0 * np.sqrt(gamma), l0 / np.sqrt(gamma)),
                                 seed=seed, **kw)


def fig4(out, n):
    a = surface(1.0, n, seed=5)
    b = surface(1.0, n, seed=5, rq=2.07 * UM, skewness=0.3, heights="gamma")
    fig, ax = plt.subplots(2, 2, figsize=(10, 8))
    stats = {}
    for j, (s, name) in enumerate(((a, "Gaussian"), (b, "gamma-type"))):
        m = 96
        im = ax[0, j].imshow(s.heights[:m, :m] / UM, cmap="viridis", origin="lower",
                             extent=(0, m * 2, 0, m * 2))
        fig.colorbar(im, ax=ax[0, j], label="z [µm]")
        st = s.statistics()
        stats[name] = {k: float(v) for k, v in st.items()}
        ax[0, j].set_title(f"{name}: Rq = {st['rq'] / UM:.3f} µm, Sk = {st['skewness']:.3f}, "
                           f"Ku = {st['kurtosis']:.3f}", fontsize=9)
        ax[0, j].set_xlabel("x [µm]")
        ax[0, j].set_ylabel("y [µm]")
        z = s.heights.ravel() / UM
        ax[1, j].hist(z, bins=100, density=True, color="0.6")
        zz = np.linspace(z.min(), z.max(), 300)
        sd = st["rq"] / UM
        ax[1, j].plot(zz, np.exp(-0.5 * (zz / sd) ** 2) / (sd * np.sqrt(2 * np.pi)), "k--", label="Gaussian, same Rq")
        ax[1, j].set_xlabel("height z [µm]")
        ax[1, j].set_ylabel("density [1/µm]")
        ax[1, j].legend()
    fig.suptitle("Fig. 4 analogue: generated surfaces (γ = 1) and height histograms")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig4_surfaces.png"), dpi=110)
    plt.close(fig)
    return stats


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(HERE, "out", "thrust_pad"))
    ap.add_argument("--quick", action="store_true", help="smaller surfaces and fewer points")
    a = ap.parse_args(argv)
    os.makedirs(a.out, exist_ok=True)
    n = 256 if a.quick else 512
    t0 = time.perf_counter()
    res = {"choices": dict(L=L, B=B, mu=MU, rq=RQ, load=LOAD, h0_start=5 * RQ, samples=n, spacing=2 * UM,
                           l0=16 * UM, acf="triangular")}
    res["fig4"] = fig4(a.out, n)

    pads, runs = {}, {}
    t_end = 0.6
    for g in GAMMAS:
        s = surface(g, n)
        pad = ThrustPad(L, B, MU, surface=s, grid=(40, 40))
        pads[g] = pad
        runs[g] = pad.descent(load=LOAD, h0_start=5 * RQ, t_end=t_end, n_out=601 if not a.quick else 301,
                              rtol=1e-8, atol=1e-10)
    c = pads[1.0].contact
    res["contact"] = dict(e_prime=c.e_prime, hardness=c.hardness, Rp=c.asperity_radius, N=c.asperity_density,
                          psi=c.plasticity_index, sigma=c.sigma)
    res["surfaces"] = {f"{g:.4g}": dict(rq=pads[g].sigma, gamma_measured=pads[g].gamma,
                                        skewness=pads[g].surface.skewness, kurtosis=pads[g].surface.kurtosis)
                       for g in GAMMAS}
    # cross-check: the full 2-D DAE (IDA) on the isotropic pad
    rf = pads[1.0].descent(load=LOAD, h0_start=5 * RQ, t_end=t_end, method="ida", path="full", n_out=61,
                           rtol=1e-7, atol=1e-9)
    hs = np.interp(rf.t, runs[1.0].t, runs[1.0].h0)
    res["full_vs_separable_max_rel_h0"] = float(np.max(np.abs(rf.h0 / hs - 1)))
    res["full_path_wall_s"] = rf.stats.wall_time
    res["separable_path_wall_s"] = runs[1.0].stats.wall_time

    # ---- Fig. 5 analogues: vs time and vs h0/Rq
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for g in GAMMAS:
        r = runs[g]
        kw = dict(color=COLOR[g], label=LABEL[g])
        ax[0, 0].plot(r.t * 1e3, r.h0 / RQ, **kw)
        ax[0, 1].plot(r.t * 1e3, r.w_hyd, **kw)
        ax[1, 0].plot(r.t * 1e3, r.w_asp, **kw)
        ax[1, 1].plot(r.t * 1e3, r.contact_area / pads[g].area * 100, **kw)
    for axx, yl in zip(ax.ravel(), ("h0/Rq", "W_hyd [N]", "W_asp [N]", "A_re/A [%]")):
        axx.set_xlabel("t [ms]")
        axx.set_ylabel(yl)
        axx.set_xscale("log")
        axx.set_xlim(1e-2, t_end * 1e3)
        axx.legend(fontsize=8)
    fig.suptitle(f"Squeeze descent under W = {LOAD:g} N (massless balance, eq. 14)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "fig5_vs_time.png"), dpi=110)
    plt.close(fig)

    Hs = np.linspace(0.5, 4.0, 200)
    V_REF = 1e-3  # m/s closing speed for the fixed-rate squeeze load
    fig, ax = plt.subplots(1, 4, figsize=(17, 4.2))
    for g in GAMMAS:
        pad = pads[g]
        h = Hs * pad.sigma
        kw = dict(color=COLOR[g], label=LABEL[g])
        ax[0].semilogy(Hs, pad.contact_area(h) / pad.area * 100, **kw)
        ax[1].semilogy(Hs, pad.asperity_load(h), **kw)
        r = runs[g]
        ax[2].plot(r.h0 / pad.sigma, r.w_hyd, **kw)
        ax[3].semilogy(Hs, [pad.squeeze_coefficient(x) * V_REF for x in h], **kw)
    ax[0].set_ylabel("A_re/A [%]")
    ax[1].set_ylabel("W_asp [N]")
    ax[2].set_ylabel("W_hyd [N] (descent under W)")
    ax[3].set_ylabel(f"W_hyd [N] at dh0/dt = -{V_REF * 1e3:g} mm/s")
    for x, t in zip(ax, ("(a) real contact area", "(b) asperity load", "(c) film load in the descent",
                         "(c') film load at a fixed closing rate")):
        x.set_xlabel("h0/Rq")
        x.set_title(t, fontsize=10)
        x.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "fig5_vs_h0.png"), dpi=110)
    plt.close(fig)

    # ---- trends at the same h0/Rq
    trend = {}
    for H in (1.0, 1.5, 2.0, 3.0):
        row = {}
        for g in GAMMAS:
            pad = pads[g]
            h = H * pad.sigma
            w_asp = float(pad.asperity_load(h))
            row[f"{g:.4g}"] = dict(A_re=float(pad.contact_area(h)), W_asp=w_asp, W_hyd_descent=LOAD - w_asp,
                                   W_hyd_fixed_rate=pad.squeeze_coefficient(h) * V_REF,
                                   phi=pad.flow_factors(h)[:2])
        iso, others = row["1"], [row[f"{g:.4g}"] for g in (1 / 3, 3.0)]
        row["iso_largest_A_re"] = bool(all(iso["A_re"] > o["A_re"] for o in others))
        row["iso_largest_W_asp"] = bool(all(iso["W_asp"] > o["W_asp"] for o in others))
        row["iso_smallest_W_hyd_descent"] = bool(all(iso["W_hyd_descent"] < o["W_hyd_descent"] for o in others))
        row["iso_smallest_W_hyd_fixed_rate"] = bool(all(iso["W_hyd_fixed_rate"] < o["W_hyd_fixed_rate"]
                                                        for o in others))
        spread = [row[f"{g:.4g}"]["A_re"] for g in GAMMAS]
        row["A_re_spread_rel"] = float((max(spread) - min(spread)) / np.mean(spread))
        trend[f"H={H:g}"] = row
    res["trends"] = trend
    # sampling spread: the same statistics from 5 independent surfaces per gamma (H = 1.5)
    spread = {}
    for g in GAMMAS:
        vals = []
        for seed in range(100, 105):
            pd = ThrustPad(L, B, MU, surface=surface(g, n, seed=seed), grid=(4, 4))
            vals.append((float(pd.contact_area(1.5 * pd.sigma)), float(pd.asperity_load(1.5 * pd.sigma))))
        v = np.array(vals)
        spread[f"{g:.4g}"] = dict(A_re_mean=float(v[:, 0].mean()), A_re_sd=float(v[:, 0].std(ddof=1)),
                                  W_asp_mean=float(v[:, 1].mean()), W_asp_sd=float(v[:, 1].std(ddof=1)))
    res["seed_spread_H1.5"] = spread

    # ---- Fig. 6: W_asp vs A_re (equilibria of a load sweep + descent trajectories)
    loads = np.geomspace(50.0, 8000.0, 8 if a.quick else 14)
    fig, ax = plt.subplots(figsize=(6.5, 5))
    fit = {}
    allA, allW = [], []
    for g in GAMMAS:
        pad = pads[g]
        heq = np.array([pad.equilibrium(W) for W in loads])
        Are = np.asarray(pad.contact_area(heq))
        Wa = np.asarray(pad.asperity_load(heq))
        allA.append(Are)
        allW.append(Wa)
        k, b0 = np.polyfit(Are, Wa, 1)
        R2 = 1 - np.sum((Wa - (k * Are + b0)) ** 2) / np.sum((Wa - Wa.mean()) ** 2)
        k0 = float(Are @ Wa / (Are @ Are))  # through the origin
        fit[f"{g:.4g}"] = dict(slope_Pa=float(k), intercept_N=float(b0), R2=float(R2), slope_origin_Pa=k0,
                               p_r_min_Pa=float(np.min(Wa / Are)), p_r_max_Pa=float(np.max(Wa / Are)),
                               h0_over_rq=(heq / pad.sigma).tolist(), loads=loads.tolist())
        ax.plot(Are * 1e6, Wa, "o", color=COLOR[g], label=f"{LABEL[g]}: R² = {R2:.4f}, "
                                                           f"slope {k / 1e6:.0f} MPa")
        r = runs[g]
        ax.plot(r.contact_area * 1e6, r.w_asp, "-", color=COLOR[g], lw=0.8, alpha=0.6)
    A = np.concatenate(allA)
    Wv = np.concatenate(allW)
    k, b0 = np.polyfit(A, Wv, 1)
    R2 = 1 - np.sum((Wv - (k * A + b0)) ** 2) / np.sum((Wv - Wv.mean()) ** 2)
    fit["all"] = dict(slope_Pa=float(k), intercept_N=float(b0), R2=float(R2))
    xx = np.linspace(0, A.max(), 10)
    ax.plot(xx * 1e6, k * xx + b0, "k--", lw=1, label=f"all: R² = {R2:.4f}, p_r = {k / 1e6:.0f} MPa")
    ax.set_xlabel("real contact area A_re [mm²]")
    ax.set_ylabel("W_asp [N]")
    ax.set_title("Fig. 6 analogue: asperity load vs real contact area")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "fig6_wasp_vs_area.png"), dpi=110)
    plt.close(fig)
    res["fig6"] = fit
    res["descent"] = {f"{g:.4g}": dict(h_eq_over_rq=pads[g].equilibrium(LOAD) / pads[g].sigma,
                                       h_end_over_rq=float(runs[g].h0[-1] / pads[g].sigma),
                                       t_to_2rq_ms=float(np.interp(-2.0, -runs[g].h0 / pads[g].sigma,
                                                                   runs[g].t) * 1e3),
                                       wall_s=runs[g].stats.wall_time, n_steps=runs[g].stats.n_steps)
                      for g in GAMMAS}
    res["wall_s"] = time.perf_counter() - t0
    with open(os.path.join(a.out, "thrust_pad.json"), "w") as f:
        json.dump(res, f, indent=1, default=float)

    # ---- summary
    print(f"Thrust pad (seed 000): L = B = {L * 1e3:g} mm, mu = {MU} Pa s, W = {LOAD:g} N, Rq = {RQ / UM:g} um")
    print(f"contact: E' = {c.e_prime / 1e9:.1f} GPa, H = {c.hardness / 1e9:g} GPa, Rp = {c.asperity_radius * 1e3:.1f}"
          f" mm, N = {c.asperity_density:.3g} 1/m^2, psi = {c.plasticity_index:.2f}")
    for g in GAMMAS:
        d, sf = res["descent"][f"{g:.4g}"], res["surfaces"][f"{g:.4g}"]
        print(f"  gamma {g:.3g} (measured {sf['gamma_measured']:.3f}, Rq {sf['rq'] / UM:.3f} um): h_eq/Rq = "
              f"{d['h_eq_over_rq']:.4f}, h(t_end)/Rq = {d['h_end_over_rq']:.4f}, t(h0 = 2 Rq) = "
              f"{d['t_to_2rq_ms']:.2f} ms")
    print(f"full 2-D DAE vs separable (gamma 1, 40x40): max |dh0/h0| = {res['full_vs_separable_max_rel_h0']:.2e}; "
          f"wall {rf.stats.wall_time:.2f} s vs {runs[1.0].stats.wall_time:.3f} s")
    for key, row in trend.items():
        print(f"  {key}: A_re [mm^2] " + ", ".join(f"{row[f'{g:.4g}']['A_re'] * 1e6:.4f}" for g in GAMMAS)
              + " | W_asp [N] " + ", ".join(f"{row[f'{g:.4g}']['W_asp']:.2f}" for g in GAMMAS)
              + " | W_hyd(fixed rate) [N] " + ", ".join(f"{row[f'{g:.4g}']['W_hyd_fixed_rate']:.1f}" for g in GAMMAS)
              + f" | iso: largest A_re {row['iso_largest_A_re']}, largest W_asp {row['iso_largest_W_asp']}, "
              f"smallest W_hyd (descent) {row['iso_smallest_W_hyd_descent']}, (fixed rate) "
              f"{row['iso_smallest_W_hyd_fixed_rate']}")
    for g in GAMMAS:
        sp_ = spread[f"{g:.4g}"]
        print(f"  5 seeds, gamma {g:.3g}, H = 1.5: A_re = {sp_['A_re_mean'] * 1e6:.4f} +- {sp_['A_re_sd'] * 1e6:.4f} mm^2,"
              f" W_asp = {sp_['W_asp_mean']:.1f} +- {sp_['W_asp_sd']:.1f} N")
    for g in GAMMAS:
        f6 = fit[f"{g:.4g}"]
        print(f"  Fig. 6 gamma {g:.3g}: R^2 = {f6['R2']:.5f}, slope (mean contact pressure) = "
              f"{f6['slope_Pa'] / 1e6:.1f} MPa, W/A_re from {f6['p_r_min_Pa'] / 1e6:.0f} to {f6['p_r_max_Pa'] / 1e6:.0f} MPa")
    print(f"  Fig. 6 all: R^2 = {fit['all']['R2']:.5f}, p_r = {fit['all']['slope_Pa'] / 1e6:.1f} MPa")
    print(f"wrote {a.out} ({res['wall_s']:.1f} s)")
    return res


if __name__ == "__main__":
    main()
