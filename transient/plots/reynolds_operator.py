"""Figures of the finite-volume Reynolds operator's verification against closed forms."""

from __future__ import annotations

import numpy as np

from transient.plots import figure


def _plain_ticks(axis, values):
    """Major ticks at exactly ``values`` (plain numbers), no minor labels, on a log axis."""
    from matplotlib.ticker import FixedLocator, NullFormatter
    axis.set_major_locator(FixedLocator(list(values)))
    axis.set_major_formatter(lambda v, _: f"{v:g}")
    axis.set_minor_formatter(NullFormatter())


def validation(res):
    """The four panels: (a) Sommerfeld pressure against the closed form, (b) its grid convergence,
    (c) the finite full-film bearing against the short-bearing limit, (d) the squeeze-plate load
    convergence. ``res``: what :func:`transient.study.film_validation.run_validation` returns."""
    profile, somm, short, sq = res["sommerfeld_profile"], res["sommerfeld"], res["short_bearing"], res["squeeze"]
    EPS = res["eps"]
    fig, ax = figure(2, 2, size=(11, 8.5))
    # (a) Sommerfeld pressure profile
    a = ax[0, 0]
    theta = np.mod(np.asarray(profile["theta"]), 2 * np.pi)
    order = np.argsort(theta)
    tt = np.asarray(profile["theta_exact"])
    a.plot(np.degrees(tt), np.asarray(profile["p_exact"]) / 1e6, "k-", label="closed form")
    a.plot(np.degrees(theta[order]), np.asarray(profile["p"])[order] / 1e6, "o", ms=4, mfc="none",
           label=f"finite volume, n = {profile['n']}")
    a.set(xlabel=r"$\theta$ [deg] (from the maximum film)", ylabel="p [MPa]",
          title=rf"(a) Sommerfeld pressure, $\varepsilon$ = {EPS} (max error {profile['p_err']:.1e})")
    a.set_xticks(range(0, 361, 60))
    a.legend()
    a.grid(alpha=0.3)
    # (b) Sommerfeld convergence
    a = ax[0, 1]
    for kind, mk in (("uniform", "o-"), ("stretched", "s-")):
        s = somm[kind]
        lab = kind if kind == "uniform" else f"stretched ($\\delta$ = {s['delta']})"
        a.loglog(s["n"], s["p_err"], mk, label=lab + f", orders {' '.join(f'{o:.2f}' for o in s['orders'])}")
    n = np.array(somm["uniform"]["n"], dtype=float)
    e0 = somm["uniform"]["p_err"][0]
    a.loglog(n, 1.5 * e0 * (n / n[0]) ** -2, "k--", lw=1, label="slope 2")
    a.set(xlabel="cells around the circumference [-]", ylabel="max |p - p_exact| / max |p_exact| [-]",
          title="(b) Sommerfeld grid convergence")
    _plain_ticks(a.xaxis, somm["uniform"]["n"])
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    # (c) short bearing
    a = ax[1, 0]
    ld = np.array(short["L_over_D"])
    a.loglog(ld, short["fy_err"], "o-", label=f"finite bearing, {short['grid'][0]} x {short['grid'][1]} cells")
    a.loglog(ld, short["fy_err"][0] * (ld / ld[0]) ** 2, "k--", lw=1, label="slope 2")
    a.set(xlabel="L/D [-]", ylabel="|Fy / Fy_Ocvirk - 1| [-]", title="(c) full-film bearing -> short-bearing limit")
    _plain_ticks(a.xaxis, ld)
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    # (d) squeeze plates
    a = ax[1, 1]
    for label, s in sq.items():
        a.loglog(s["n"], s["err"], "o-" if s["delta"] == 0 else "s--",
                 label=f"{label}, orders {' '.join(f'{o:.2f}' for o in s['orders'])}")
    first = next(iter(sq.values()))
    n = np.array(first["n"], dtype=float)
    a.loglog(n, 1.5 * max(s["err"][0] for s in sq.values()) * (n / n[0]) ** -2, "k--", lw=1, label="slope 2")
    a.set(xlabel="cells across the short side a [-]", ylabel="|W / W_exact - 1| [-]",
          title="(d) squeeze film between rectangular plates")
    _plain_ticks(a.xaxis, first["n"])
    a.legend(fontsize=8)
    a.grid(alpha=0.3, which="both")
    fig.suptitle("transient.fv: finite-volume Reynolds operator against closed forms")
    return fig
