"""Figures of a parameter sweep, drawn from its table (one row per point): scalars against the swept value,
and regimes by colour over one or two swept values. Column names become axis labels with units
(:func:`label`); points whose ``settled`` column is false are drawn open and named in the legend."""

from __future__ import annotations

import numpy as np

from transient.plots import figure

REGIME_COLOURS = {"fully flooded": "tab:green", "starved": "tab:orange", "parched": "tab:red", "failed": "0.5"}

#: axis labels of the scene kinds' parameters and scalars (transient.study.scene)
LABELS = {
    "speed_rpm": "speed [rpm]", "load": "load [N]", "ambient_film": "ambient film [m]", "n_balls": "balls [-]",
    "semi_major_C": "orbit semi-major axis / C [-]", "semi_minor_C": "orbit semi-minor axis / C [-]",
    "eps_max": "largest eccentricity ratio e/C [-]", "eps_min_last_rev": "smallest e/C, last revolution [-]",
    "settle_estimate": "distance from the settled orbit / radius [-]",
    "level_db": "bearing noise level [dB]", "level_dba": "A-weighted noise level [dB(A)]",
    "whirl_amplitude_um": "whirl amplitude [um]", "H_central": "central film H_c [-]",
    "h_inlet_um": "inlet film [um]", "h_eq_over_rq": "equilibrium film h_eq / Rq [-]",
    "t_to_2rq_ms": "time to h0 = 2 Rq [ms]", "contact_area_end_mm2": "real contact area at the end [mm^2]",
    "h_min_um": "minimum film [um]", "h_central_um": "central film [um]", "p_max_GPa": "peak pressure [GPa]",
    "gamma": "surface pattern gamma [-]", "rq": "roughness Rq [m]", "tilt_deg": "tilt [deg]",
    "viscosity": "viscosity [Pa s]", "clearance": "clearance [m]", "unbalance": "unbalance [m]",
}
_SUFFIX_UNITS = {"_C": "C", "_um": "um", "_mm": "mm", "_ms": "ms", "_mm2": "mm^2", "_GPa": "GPa", "_db": "dB",
                 "_rpm": "rpm", "_deg": "deg", "_s": "s"}


def label(name: str) -> str:
    """Axis label with unit of a sweep column: from ``LABELS``, else from the name's unit suffix (``_um`` ->
    ``[um]``), else ``[-]``."""
    if name in LABELS:
        return LABELS[name]
    for suffix, unit in sorted(_SUFFIX_UNITS.items(), key=lambda kv: -len(kv[0])):
        if name.endswith(suffix):
            return f"{name[:-len(suffix)].replace('_', ' ')} [{unit}]"
    return f"{name.replace('_', ' ')} [-]"


def scalar_curves(table: dict, x: str, ys: list, title: str = ""):
    """One panel per scalar ``ys`` against the swept parameter ``x`` (failed points left out; points with
    ``settled`` false drawn as open red circles: their value is not that of a settled state)."""
    n = len(table[x])
    ok = np.asarray(table.get("status", ["ok"] * n)) == "ok"
    settled = np.asarray([True if v is None else bool(v) for v in table.get("settled", [True] * n)])
    fig, axs = figure(1, max(len(ys), 1), size=(4.5 * max(len(ys), 1), 3.8), squeeze=False)
    xv = np.asarray(table[x], float)
    order = np.argsort(xv)
    sel = order[ok[order]]
    for ax, y in zip(axs[0], ys):
        yv = np.asarray(table[y], float)
        good = sel[settled[sel]]
        ax.plot(xv[sel], yv[sel], "-", color="tab:blue", lw=0.8)
        ax.plot(xv[good], yv[good], "o", color="tab:blue", ms=4, label="settled")
        bad = sel[~settled[sel]]
        if bad.size:
            ax.plot(xv[bad], yv[bad], "o", mfc="white", color="tab:red", ms=6, label="NOT settled")
            ax.legend(fontsize=8)
        ax.set(xlabel=label(x), ylabel=label(y), title=f"{title}{': ' if title else ''}{label(y).split(' [')[0]}")
        ax.title.set_fontsize(9)
        ax.grid(True, lw=0.3)
    return fig


def regime_map(table: dict, swept: list, column: str = "final_regime"):
    """Regime of each point by colour over one (a strip) or two swept values."""
    regimes = [r if s == "ok" else "failed" for r, s in zip(table[column], table.get("status", ["ok"] * len(table[column])))]
    colours = [REGIME_COLOURS.get(r, "k") for r in regimes]
    x = np.asarray(table[swept[0]], float)
    y = np.asarray(table[swept[1]], float) if len(swept) > 1 else np.zeros_like(x)
    fig, ax = figure(size=(6.0, 4.2 if len(swept) > 1 else 2.4))
    ax.scatter(x, y, c=colours, s=120, marker="s", edgecolors="k", linewidths=0.4)
    for r, c in REGIME_COLOURS.items():
        if r in regimes:
            ax.scatter([], [], c=c, marker="s", label=r)
    ax.set(xlabel=label(swept[0]), ylabel=label(swept[1]) if len(swept) > 1 else "")
    if len(swept) == 1:
        ax.set_yticks([])
    ax.legend(fontsize=8, loc="best")
    ax.set_title(f"{column.replace('_', ' ')} over {' x '.join(swept)}", fontsize=9)
    return fig
