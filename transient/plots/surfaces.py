"""Figures of rough surfaces and their flow factors (Lee & Rhim, "Mixed lubrication analysis of parallel thrust
bearing by surface topography")."""

from __future__ import annotations

from transient.plots import figure

_COLOURS = ("tab:blue", "tab:red", "tab:green", "tab:purple")


def flow_factors(results: dict, fits: dict, names: dict):
    """phi_x against H: the Patir-Cheng fits as lines, the numerical flow simulation as points with +-1 std.
    ``results``: gamma -> :class:`~transient.surfaces.flow_simulation.FlowFactorResult`; ``fits``: gamma ->
    (H, phi_x) of the fit."""
    fig, ax = figure(size=(7, 5))
    for (g, res), c in zip(results.items(), _COLOURS):
        ax.plot(*fits[g], color=c, lw=1.5, label=f"Patir–Cheng fit, γ = {names[g]}")
        ax.errorbar(res.H, res.phi_mean, yerr=res.phi_std, fmt="o", color=c, capsize=3, ms=5,
                    label=f"flow simulation, γ = {names[g]} (mean ± std, {res.phi.shape[0]} patches)")
    ax.axhline(1.0, color="0.6", lw=0.8, ls=":")
    ax.set(xlabel="H = h / σ [-]", ylabel="pressure flow factor φx [-]",
           title="Pressure flow factor: numerical flow simulation vs Patir–Cheng (1978) fits")
    ax.title.set_fontsize(10)
    ax.legend(fontsize=7.5)
    return fig
