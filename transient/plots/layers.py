"""Figures of seed 004's layered journal case (:func:`transient.study.layers.layered_cases`): mid-plane
pressure against the angle for thicker layers (Fig. 7's question) and for stiffer layers (Fig. 8's)."""

from __future__ import annotations

from transient.plots import figure


def layered_profiles(res):
    """Two panels: p*(angle) at the mid-plane per layer thickness (solid: mobile layers, alpha = 0.1 h_min;
    dashed: immobile), and per layer viscosity at delta = 0.1 h_min."""
    a = res["angle_deg"]
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.3))
    ax.plot(a, res["base"]["profile"], "k-", lw=1.2, label="no layers")
    for row, col in zip(res["thickness"], ("tab:blue", "tab:orange", "tab:red")):
        d = row["delta_over_hmin"]
        ax.plot(a, row["mobile"]["profile"], "-", color=col, label=f"delta = {d:g} h_min")
        ax.plot(a, row["immobile"]["profile"], "--", color=col, lw=0.8)
    ax.set(xlabel="angle from the top, with the rotation [deg]", ylabel="p / p0 at the mid-plane",
           title="layer thickness (dashed: immobile layers, alpha = 0)", xlim=(90, 270))
    ax.legend(fontsize=8)
    bx.plot(a, res["base"]["profile"], "k-", lw=1.2, label="no layers")
    for row in res["viscosity"]:
        bx.plot(a, row["profile"], label=f"mu_ab = {row['mu_ab_over_mu']:g} mu")
    bx.set(xlabel="angle [deg]", ylabel="p / p0 at the mid-plane", title="layer viscosity (delta = 0.1 h_min)",
           xlim=(90, 270))
    bx.legend(fontsize=8)
    return fig
