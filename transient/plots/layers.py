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


def gecim_profiles(res):
    """Two panels with the Gecim bulk (:func:`transient.study.layers.gecim_cases`): p*(angle) at the mid-plane per
    layer thickness (solid: Gecim bulk, dashed: Newtonian bulk; mobile layers), and per layer viscosity."""
    a = res["angle_deg"]
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.3))
    ax.plot(a, res["base"]["gecim"]["profile"], "k-", lw=1.2, label="no layers")
    ax.plot(a, res["base"]["newtonian"]["profile"], "k--", lw=0.8)
    for row, col in zip(res["thickness"], ("tab:blue", "tab:orange", "tab:red")):
        ax.plot(a, row["gecim"]["profile"], "-", color=col, label=f"delta = {row['delta_over_hmin']:g} h_min")
        ax.plot(a, row["newtonian"]["profile"], "--", color=col, lw=0.8)
    ax.set(xlabel="angle from the top, with the rotation [deg]", ylabel="p / p0 at the mid-plane",
           title="Gecim bulk, layer thickness (dashed: Newtonian bulk)", xlim=(90, 270))
    ax.legend(fontsize=8)
    bx.plot(a, res["base"]["gecim"]["profile"], "k-", lw=1.2, label="no layers")
    for row in res["viscosity"]:
        bx.plot(a, row["profile"], label=f"mu_ab = {row['mu_ab_over_mu']:g} mu")
    bx.set(xlabel="angle [deg]", ylabel="p / p0 at the mid-plane", title="Gecim bulk, layer viscosity "
           "(delta = 0.1 h_min)", xlim=(90, 270))
    bx.legend(fontsize=8)
    return fig


def immobility(res):
    """Figs. 9-11's question with the Gecim bulk: the velocity across the film at the mid-plane pressure peak, and
    the shear stress at the journal-side interface along the angle, from mobile to immobile layers."""
    a = res["angle_deg"]
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.3))
    for row in res["immobility"]:
        lab = f"alpha = {row['alpha_over_hmin']:g} h_min, mu_ab = {row['mu_ab_over_mu']:g} mu"
        ax.plot(row["u_over_U"], row["z_over_h"], label=lab)
        bx.plot(a, row["interface_lower_Pa"] / 1e3, label=lab)
    row = res["immobility"][0]
    ax.set(xlabel="u / U (journal speed U)", ylabel="z / h (0: journal)",
           title=f"velocity across the film at {row['peak_angle_deg']:.0f} deg (peak pressure)")
    ax.legend(fontsize=7)
    bx.set(xlabel="angle [deg]", ylabel="shear stress at the journal-side interface [kPa]",
           title="interface shear at the mid-plane", xlim=(90, 270))
    return fig


def pressure_fields(res):
    """Figs. 3-6's view with the Gecim bulk: p/p0 over the angle and the half length (mid-plane at 0) for each
    layer thickness, on one colour scale."""
    a, z = res["angle_deg"], res["z_over_B"]
    cases = [("no layers", res["base"]["gecim"]["field"])] + [
        (f"delta = {r['delta_over_hmin']:g} h_min", r["gecim"]["field"]) for r in res["thickness"]]
    top = max(float(f.max()) for _, f in cases)
    fig, axes = figure(1, len(cases), size=(3.3 * len(cases), 3.6))
    for ax, (title, f) in zip(axes, cases):
        im = ax.pcolormesh(a, z, f, vmin=0.0, vmax=top, shading="nearest", cmap="viridis")
        ax.set(xlabel="angle [deg]", title=f"{title}: peak {float(f.max()):.2f}", xlim=(90, 270))
    axes[0].set_ylabel("z / (L/2) (0: mid-plane)")
    fig.colorbar(im, ax=list(axes), label="p / p0 (Gecim bulk)", shrink=0.85)
    return fig


def dynamics(res):
    """The unbalance orbit's last revolution (x, y in C, centred on its mean) with the Newtonian and the Gecim bulk
    (:func:`transient.study.layers.shear_thinning_dynamics`), the Lund thresholds in the legend."""
    fig, ax = figure(1, 1, size=(5.4, 4.8))
    for name, colour in (("newtonian", "black"), ("gecim", "tab:red")):
        r = res[name]
        x, y = r["x_C"] - r["x_C"].mean(), r["y_C"] - r["y_C"].mean()
        ax.plot(x, y, "-", color=colour,
                label=f"{name}: e/C {r['eccentricity']:.3f}, threshold {r['threshold_rpm']:.0f} rpm")
    ax.set(xlabel="x - mean [C] (load direction)", ylabel="y - mean [C]", aspect="equal",
           title=f"unbalance orbit at {res['speed_rpm']:.0f} rpm, last of {res['revolutions']:g} revolutions")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    return fig
