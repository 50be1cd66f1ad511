"""Figures of the rough parallel thrust pad (Lee & Rhim, "Mixed lubrication analysis of parallel thrust bearing by
surface topography", Figs. 4-6)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure

UM = 1e-6
GAMMA_LABEL = {"0.3333": "γ = 1/3 (transverse)", "1": "γ = 1 (isotropic)", "3": "γ = 3 (longitudinal)"}
GAMMA_COLOUR = {"0.3333": "tab:blue", "1": "tab:red", "3": "tab:green"}


def _style(g):
    key = f"{g:.4g}"
    return dict(color=GAMMA_COLOUR.get(key, "k"), label=GAMMA_LABEL.get(key, f"γ = {key}"))


def surfaces(named: dict, window=96):
    """Fig. 4: a corner of each generated surface and its height histogram beside the Gaussian of the same Rq."""
    fig, ax = figure(2, len(named), size=(5 * len(named), 8))
    for j, (name, s) in enumerate(named.items()):
        st = s.statistics()
        m = window
        dx = s.spacing[0] / UM if np.ndim(s.spacing) else s.spacing / UM
        im = ax[0, j].imshow(s.heights[:m, :m] / UM, cmap="viridis", origin="lower", extent=(0, m * dx, 0, m * dx))
        fig.colorbar(im, ax=ax[0, j], label="z [µm]")
        ax[0, j].set(xlabel="x [µm]", ylabel="y [µm]",
                     title=f"{name}: Rq = {st['rq'] / UM:.3f} µm, Sk = {st['skewness']:.3f}, Ku = {st['kurtosis']:.3f}")
        ax[0, j].title.set_fontsize(9)
        z = s.heights.ravel() / UM
        ax[1, j].hist(z, bins=100, density=True, color="0.6")
        zz = np.linspace(z.min(), z.max(), 300)
        sd = st["rq"] / UM
        ax[1, j].plot(zz, np.exp(-0.5 * (zz / sd) ** 2) / (sd * np.sqrt(2 * np.pi)), "k--", label="Gaussian, same Rq")
        ax[1, j].set(xlabel="height z [µm]", ylabel="density [1/µm]")
        ax[1, j].legend()
    fig.suptitle("Fig. 4: generated surfaces and height histograms")
    return fig


def descent_vs_time(runs: dict, rq, load):
    """Fig. 5 against time: h0/Rq, film load, asperity load and real contact area of each descent (log time)."""
    fig, ax = figure(2, 2, size=(11, 8))
    for g, r in runs.items():
        t = r.t[1:] * 1e3  # t = 0 cannot sit on a log axis
        kw = _style(g)
        ax[0, 0].plot(t, r.h0[1:] / rq, **kw)
        ax[0, 1].plot(t, r.w_hyd[1:], **kw)
        ax[1, 0].plot(t, r.w_asp[1:], **kw)
        ax[1, 1].plot(t, r.contact_area[1:] * 1e6, **kw)
    for a, yl in zip(ax.ravel(), ("h0/Rq [-]", "W_hyd [N]", "W_asp [N]", "A_re [mm²]")):
        a.set(xlabel="t [ms]", ylabel=yl, xscale="log")
        a.legend(fontsize=8)
        a.grid(True, which="both", lw=0.3)
    fig.suptitle(f"Squeeze descent under W = {load:g} N from rest at 5 Rq (massless force balance, eq. 14)")
    return fig


def vs_h0(curves, runs: dict):
    """Fig. 5 against h0/Rq: contact area, asperity load, film load in the descent and at a fixed closing rate."""
    fig, ax = figure(1, 4, size=(17, 4.2))
    v_ref = curves.v_ref
    for g, c in curves.per_gamma.items():
        kw = _style(g)
        ax[0].semilogy(c["H"], c["area_pct"], **kw)
        ax[1].semilogy(c["H"], c["w_asp"], **kw)
        r = runs[g]
        ax[2].plot(r.h0 / (r.h0[0] / 5.0), r.w_hyd, **kw)
        ax[3].semilogy(c["H"], c["w_fixed_rate"], **kw)
    for a, yl, t in zip(ax, ("A_re/A [%]", "W_asp [N]", "W_hyd [N] (descent under W)",
                             f"W_hyd [N] at dh0/dt = -{v_ref * 1e3:g} mm/s"),
                        ("(a) real contact area", "(b) asperity load", "(c) film load in the descent",
                         "(c') film load at a fixed closing rate")):
        a.set(xlabel="h0/Rq [-]", ylabel=yl, title=t)
        a.legend(fontsize=8)
        a.grid(True, which="both", lw=0.3)
    return fig


def asperity_load_vs_area(fit, runs: dict):
    """Fig. 6: asperity load against real contact area: equilibria of a load sweep (markers), the descents
    (lines) and the straight line through all points."""
    fig, ax = figure(size=(6.5, 5))
    for g, r in runs.items():
        f = fit.per_gamma[f"{g:.4g}"]
        kw = _style(g)
        ax.plot(f["A_re"] * 1e6, f["W_asp"], "o", color=kw["color"],
                label=f"{kw['label']}: R² = {f['R2']:.4f}, slope {f['slope'] / 1e6:.0f} MPa")
        ax.plot(r.contact_area * 1e6, r.w_asp, "-", color=kw["color"], lw=0.8, alpha=0.6)
    a = fit.overall
    xx = np.linspace(0, max(f["A_re"].max() for f in fit.per_gamma.values()), 10)
    ax.plot(xx * 1e6, a["slope"] * xx + a["intercept"], "k--", lw=1,
            label=f"all: R² = {a['R2']:.4f}, p_r = {a['slope'] / 1e6:.0f} MPa")
    ax.set(xlabel="real contact area A_re [mm²]", ylabel="W_asp [N]", title="Fig. 6: asperity load vs real contact area")
    ax.legend(fontsize=7)
    ax.grid(True, lw=0.3)
    return fig
