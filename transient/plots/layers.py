"""Figures of the layered journal case of Jang, "Study on boundary lubrication in the sliding bearing system
under high load and speed" (:func:`transient.study.layers.layered_cases`): mid-plane
pressure against the angle for thicker layers (Fig. 7's question) and for stiffer layers (Fig. 8's)."""

from __future__ import annotations

import numpy as np

from transient.plots import figure


def layered_profiles(res):
    """Two panels: p*(angle) at the mid-plane per layer thickness (solid: mobile layers, alpha = 0.1 h_min;
    dashed: immobile), and per layer viscosity at delta = 0.1 h_min."""
    a = res.angle_deg
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.3))
    ax.plot(a, res.base["profile"], "k-", lw=1.2, label="no layers")
    for row, col in zip(res.thickness, ("tab:blue", "tab:orange", "tab:red")):
        d = row["delta_over_hmin"]
        ax.plot(a, row["mobile"]["profile"], "-", color=col, label=f"delta = {d:g} h_min")
        ax.plot(a, row["immobile"]["profile"], "--", color=col, lw=0.8)
    ax.set(xlabel="angle from the top, with the rotation [deg]", ylabel="p / p0 at the mid-plane [-]",
           title="layer thickness (dashed: immobile layers, alpha = 0)", xlim=(90, 270))
    ax.legend(fontsize=8)
    bx.plot(a, res.base["profile"], "k-", lw=1.2, label="no layers")
    for row in res.viscosity:
        bx.plot(a, row["profile"], label=f"mu_ab = {row['mu_ab_over_mu']:g} mu")
    bx.set(xlabel="angle [deg]", ylabel="p / p0 at the mid-plane [-]", title="layer viscosity (delta = 0.1 h_min)",
           xlim=(90, 270))
    bx.legend(fontsize=8)
    return fig


def gecim_profiles(res):
    """Two panels with the Gecim bulk (:func:`transient.study.layers.gecim_cases`): p*(angle) at the mid-plane per
    layer thickness (solid: Gecim bulk, dashed: Newtonian bulk; mobile layers), and per layer viscosity."""
    a = res.angle_deg
    fig, (ax, bx) = figure(1, 2, size=(11.5, 4.3))
    ax.plot(a, res.base["gecim"]["profile"], "k-", lw=1.2, label="no layers")
    ax.plot(a, res.base["newtonian"]["profile"], "k--", lw=0.8)
    for row, col in zip(res.thickness, ("tab:blue", "tab:orange", "tab:red")):
        ax.plot(a, row["gecim"]["profile"], "-", color=col, label=f"delta = {row['delta_over_hmin']:g} h_min")
        ax.plot(a, row["newtonian"]["profile"], "--", color=col, lw=0.8)
    ax.set(xlabel="angle from the top, with the rotation [deg]", ylabel="p / p0 at the mid-plane [-]",
           title="Gecim bulk, layer thickness (dashed: Newtonian bulk)", xlim=(90, 270))
    ax.legend(fontsize=8)
    bx.plot(a, res.base["gecim"]["profile"], "k-", lw=1.2, label="no layers")
    for row in res.viscosity:
        bx.plot(a, row["profile"], label=f"mu_ab = {row['mu_ab_over_mu']:g} mu")
    bx.set(xlabel="angle [deg]", ylabel="p / p0 at the mid-plane [-]", title="Gecim bulk, layer viscosity "
           "(delta = 0.1 h_min)", xlim=(90, 270))
    bx.legend(fontsize=8)
    return fig


def immobility(res):
    """Figs. 9-11's question with the Gecim bulk, from mobile to immobile layers: the velocity across the film at the
    mid-plane pressure peak and the shear stress at the journal-side interface along the angle for the first case
    (top), and each other case's difference from it (bottom: the cases lie within a line width of each other)."""
    a = res.angle_deg
    rows = res.immobility
    ref = rows[0]
    fig, ((ax, bx), (cx, dx)) = figure(2, 2, size=(11.5, 7.4))
    lab = lambda r: f"alpha = {r['alpha_over_hmin']:g} h_min, mu_ab = {r['mu_ab_over_mu']:g} mu"  # noqa: E731
    ax.plot(ref["u_over_U"], ref["z_over_h"], color="k")
    bx.plot(a, ref["interface_lower_Pa"] / 1e3, color="k")
    for r in rows[1:]:
        cx.plot(np.asarray(r["u_over_U"]) - np.asarray(ref["u_over_U"]), r["z_over_h"], label=lab(r))
        dx.plot(a, (np.asarray(r["interface_lower_Pa"]) - np.asarray(ref["interface_lower_Pa"])) / 1e3, label=lab(r))
    ax.set(xlabel="u / U (journal speed U) [-]", ylabel="z / h (0: journal) [-]",
           title=f"{lab(ref)}: velocity across the film at {ref['peak_angle_deg']:.0f} deg (peak pressure)")
    bx.set(xlabel="angle [deg]", ylabel="shear stress at the journal-side interface [kPa]",
           title=f"{lab(ref)}: interface shear at the mid-plane", xlim=(90, 270))
    cx.set(xlabel="u / U minus the case above [-]", ylabel="z / h (0: journal) [-]",
           title="velocity: difference from the case above")
    dx.set(xlabel="angle [deg]", ylabel="interface shear minus the case above [kPa]",
           title="interface shear: difference from the case above", xlim=(90, 270))
    cx.legend(fontsize=7)
    for g in (ax, bx, cx, dx):
        g.title.set_fontsize(9)
        g.grid(True, lw=0.3)
    return fig


def pressure_fields(res):
    """Figs. 3-6's view with the Gecim bulk: p/p0 over the angle and the half length (mid-plane at 0) for each
    layer thickness, on one colour scale."""
    a, z = res.angle_deg, res.z_over_B
    cases = [("no layers", res.base["gecim"]["field"])] + [
        (f"delta = {r['delta_over_hmin']:g} h_min", r["gecim"]["field"]) for r in res.thickness]
    top = max(float(f.max()) for _, f in cases)
    fig, axes = figure(1, len(cases), size=(3.3 * len(cases), 3.6))
    for ax, (title, f) in zip(axes, cases):
        im = ax.pcolormesh(a, z, f, vmin=0.0, vmax=top, shading="nearest", cmap="viridis")
        ax.set(xlabel="angle [deg]", ylabel="z / (L/2) (0: mid-plane) [-]", title=f"{title}: peak {float(f.max()):.2f}",
               xlim=(90, 270))
    fig.colorbar(im, ax=list(axes), label="p / p0 (Gecim bulk) [-]", shrink=0.85)
    return fig


def dynamics(res):
    """The periodic unbalance orbit (one closed revolution, x, y in C) with the Newtonian and the Gecim bulk
    (:func:`transient.study.layers.shear_thinning_dynamics`), axes as Rho & Kim's Fig. 3: y to the right, x
    (towards the load) downwards; the static equilibria marked; thresholds and the shooting's convergence in the
    legend."""
    fig, ax = figure(1, 1, size=(5.8, 5.4))
    for name, colour in (("newtonian", "black"), ("gecim", "tab:red")):
        r = getattr(res, name)
        x, y = np.asarray(r["x_C"]), np.asarray(r["y_C"])
        state = (f"periodic, |mu| {r['max_multiplier']:.2f}" if r.get("converged") else "NOT converged")
        ax.plot(np.append(y, y[0]), np.append(x, x[0]), "-", color=colour,
                label=f"{name} bulk: e/C {r['eccentricity']:.3f}, threshold {r['threshold_rpm']:.0f} rpm ({state})")
        if "equilibrium_C" in r:
            ax.plot(r["equilibrium_C"][1], r["equilibrium_C"][0], "+", color=colour, ms=9)
    ax.set(xlabel="y / C (90 deg ahead of the load, with the rotation) [-]", ylabel="x / C (towards the load) [-]",
           title=f"periodic unbalance orbit at {res.speed_rpm:.0f} rpm (+: static equilibrium)")
    ax.invert_yaxis()
    ax.set_aspect("equal", adjustable="datalim")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    ax.grid(True, lw=0.3)
    return fig
