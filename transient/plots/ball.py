"""Figures of the thrust ball bearing's starvation sequences (Jeong, Lee, Yoo & Cho, Figs. 7-11).

Readability rules: one colour per regime (the marker of each point), one line style and marker shape per
series (in the legend), the swept value on the x axis, the fixed values in the title, the paper's regime
boundaries drawn as labelled vertical lines."""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from transient.plots import figure, suptitle

REGIME_COLOURS = {"fully flooded": "tab:green", "starved": "tab:orange", "parched": "tab:red"}
LABELS = {"n_balls": "number of balls", "speed_rpm": "shaft speed [rpm]", "load": "axial load [N]",
          "ambient_film": "ambient film [um]"}
def _name(axis: str) -> str:
    """The label of ``axis`` without its unit."""
    return LABELS[axis].split(" [")[0]


_STYLES = [("o", "-"), ("s", "--"), ("^", ":"), ("D", "-."), ("v", (0, (5, 1))), ("P", (0, (1, 1)))]


def fixed_title(fixed: dict, swept: str) -> str:
    """'30 N, 80 rpm, 6 balls, h_inf = 100 um' without the swept parameter."""
    parts = {"load": lambda v: f"{v:g} N", "speed_rpm": lambda v: f"{v:g} rpm", "n_balls": lambda v: f"{int(v)} balls",
             "ambient_film": lambda v: f"h_inf = {v * 1e6:g} um"}
    return ", ".join(f(fixed[k]) for k, f in parts.items() if k != swept and fixed.get(k) is not None)


def _regime_legend(ax, handles):
    for r, c in REGIME_COLOURS.items():
        handles.append(ax.plot([], [], "o", color=c, label=r)[0])


def regime_sweep(swept: str, values, series: dict, fixed: dict, paper: dict | None = None, title: str = ""):
    """Central film H_c = h_c / r_b of the periodic state (or the last pass) against the swept value.

    ``series``: label -> list of sequences (one per value); ``paper``: the paper's last flooded / starved
    values of this sweep (drawn as vertical lines)."""
    x = np.asarray(values, float) * (1e6 if swept == "ambient_film" else 1.0)
    fig, ax = figure(size=(6.4, 4.4))
    handles = []
    dodge = 0.012 * (np.ptp(x) or 1.0)  # series that coincide stay visible side by side
    all_hc = []
    for i, ((label, seqs), (mk, ls)) in enumerate(zip(series.items(), _STYLES)):
        hc = np.array([s.H_central[-1] for s in seqs])
        all_hc.append(hc)
        xi = x + (i - (len(series) - 1) / 2) * dodge
        ax.plot(xi, hc, ls=ls, color="0.35", lw=1)
        for xv, s, h in zip(xi, seqs, hc):
            ax.plot(xv, h, mk, color=REGIME_COLOURS[s.final_regime], ms=6, mec="k", mew=0.4)
        handles.append(ax.plot([], [], ls=ls, marker=mk, color="0.35", mfc="w", mec="k", label=label)[0])
    _regime_legend(ax, handles)
    if paper:
        for k, v in paper.items():
            ax.axvline(v, color=REGIME_COLOURS["fully flooded" if k == "flooded" else "starved"], ls="--", lw=1)
            ax.annotate(f"paper: {k} to {v:g}", (v, 0.02), xycoords=("data", "axes fraction"), rotation=90,
                        fontsize=7, ha="right", va="bottom")
    ax.set(xlabel=LABELS[swept], ylabel="H_c = h_c / r_b, periodic state or last pass [-]")
    hc = np.concatenate(all_hc)
    if hc.min() > 0 and hc.max() / hc.min() > 10:
        ax.set_yscale("log")
    ax.legend(handles=handles, fontsize=7, loc="best")
    ax.set_title(title or f"Central film against {_name(swept)} ({fixed_title(fixed, swept)})", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    return fig


def meniscus(values, series: dict, fixed: dict, swept: str = "load"):
    """Fig. 10: the meniscus position m of the last pass and the critical meniscus m_c against the swept value."""
    fig, ax = figure(size=(6.4, 4.4))
    first = None
    for (label, seqs), (mk, ls) in zip(series.items(), _STYLES):
        ax.plot(values, [s.m[-1] for s in seqs], marker=mk, ls=ls, color="tab:blue", label=f"m, {label}")
        first = first or seqs
    ax.plot(values, [s.m_c for s in first], "k-", lw=2, label="critical meniscus m_c")
    ax.set_yscale("log")
    ax.set(xlabel=LABELS[swept], ylabel="meniscus position m = x_in / b [-]")
    ax.set_title(f"Inlet meniscus against {_name(swept)} ({fixed_title(fixed, swept)})", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    return fig


def inlet_sequence(series: dict, fixed: dict):
    """The inlet film met by each ball, pass after pass, for each series."""
    fig, ax = figure(size=(6.4, 4.4))
    for (label, s), (mk, ls) in zip(series.items(), _STYLES):
        ax.semilogy(np.arange(1, s.n_run + 1), np.maximum(s.h_inlet, 1e-10) * 1e6, ls=ls, label=label)
    ax.set(xlabel="ball pass n [-]", ylabel="inlet film h_in [um]")
    ax.set_title(f"Inlet film ball after ball ({fixed_title(fixed, '')})", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    return fig


_AXES = ("n_balls", "speed_rpm", "load")
_PAPER_EDGE = {"flooded": "fully flooded", "starved": "starved"}


def regime_map(rmap, x: str = "n_balls", y: str = "speed_rpm", at: dict | None = None, paper: dict | None = None,
               title: str = ""):
    """Regime map of the sampled points over two swept values (a :class:`transient.study.ball.RegimeMap`), the
    third fixed at ``at`` (nearest map value; default the middle one), drawn as a categorical map: one square
    per sampled point, equally spaced whatever the values (the axes show the sampled values only), coloured by
    its regime with ``H_c = h_c/r_b`` written in it. The paper's boundaries (``paper[axis] = {"flooded": last
    flooded, "starved": last starved}``) are drawn between the sampled values they fall between, and listed as
    outside the sampled range otherwise."""
    third = [a for a in _AXES if a not in (x, y)][0]
    vals3 = np.asarray(getattr(rmap, third), float)
    v3 = vals3[len(vals3) // 2] if not at or third not in at else float(at[third])
    k3 = int(np.argmin(np.abs(vals3 - v3)))
    names = rmap.names()
    order = {a: i for i, a in enumerate(_AXES)}
    sl = [slice(None)] * 3
    sl[order[third]] = k3
    reg = names[tuple(sl)]
    hc = rmap.H_central[tuple(sl)]
    if order[x] > order[y]:  # rows follow x
        reg, hc = reg.T, hc.T
    xs, ys = np.asarray(getattr(rmap, x), float), np.asarray(getattr(rmap, y), float)
    fig, ax = figure(size=(7.0, 4.6))
    for i in range(xs.size):
        for j in range(ys.size):
            ax.add_patch(Rectangle((i - 0.45, j - 0.45), 0.9, 0.9, color=REGIME_COLOURS[reg[i, j]], alpha=0.8, lw=0))
            ax.text(i, j, f"{hc[i, j] * 1e6:.1f}", ha="center", va="center", fontsize=7)
    present = [r for r in REGIME_COLOURS if r in set(reg.ravel())]
    handles = [Patch(color=REGIME_COLOURS[r], alpha=0.8, label=r) for r in present]
    for axis, vals, line, ls in ((x, xs, ax.axvline, "--"), (y, ys, ax.axhline, ":")):
        for k, v in (paper or {}).get(axis, {}).items():
            pos = v + 0.5 if axis == "n_balls" else v   # between the last ball count of a regime and the next
            col = REGIME_COLOURS[_PAPER_EDGE[k]]
            what = _name(axis)
            unit = {"n_balls": " balls", "speed_rpm": " rpm", "load": " N"}[axis]
            inside = vals.size > 1 and vals[0] <= pos <= vals[-1]
            if inside:
                line(float(np.interp(pos, vals, np.arange(vals.size))), color=col, ls=ls, lw=2.0)
            handles.append(Line2D([], [], color=col, ls=ls if inside else "none", lw=2.0,
                                  label=f"paper, {what}: {k} up to {v:g}{unit}"
                                        + ("" if inside else " (outside the sampled values)")))
    ax.set_xticks(range(xs.size), [f"{v:g}" for v in xs])
    ax.set_yticks(range(ys.size), [f"{v:g}" for v in ys])
    ax.set(xlabel=LABELS[x], ylabel=LABELS[y],
           xlim=(-0.5, xs.size - 0.5), ylim=(-0.5, ys.size - 0.5))
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fixed = {third: float(getattr(rmap, third)[k3]), "ambient_film": rmap.ambient_film}
    ax.set_title(title or f"Final regime of each sampled point (colour), H_c x 1e6 (number); {fixed_title(fixed, '')}",
                 fontsize=9)
    return fig


def critical_films(lines: dict, ambient: float | None = None, paper: dict | None = None, title: str = ""):
    """The ambient film at which the bearing stops re-wetting its track, against each swept value.

    ``lines``: axis -> (values, critical films [m], fixed dict); one panel per axis; ``ambient`` the paper's
    ambient film (horizontal line: below the curve the bearing parches); ``paper`` the paper's boundaries."""
    fig, axs = figure(1, len(lines), size=(3.3 * len(lines), 3.6))
    axs = np.atleast_1d(axs)
    for ax, (axis, (vals, crit, fixed)) in zip(axs, lines.items()):
        vals = np.asarray(vals, float)
        crit = np.asarray([np.nan if c is None else c for c in crit], float) * 1e6
        ax.fill_between(vals, crit, np.nanmax(crit) * 1.3 if np.isfinite(crit).any() else 1, color=REGIME_COLOURS["fully flooded"], alpha=0.3, lw=0)
        ax.fill_between(vals, 0, crit, color=REGIME_COLOURS["parched"], alpha=0.25, lw=0)
        ax.plot(vals, crit, "ko-", ms=4, label="model: critical ambient film")
        if ambient is not None:
            ax.axhline(ambient * 1e6, color="tab:blue", lw=1, label=f"paper's ambient film {ambient * 1e6:g} um")
        for k, v in (paper or {}).get(axis, {}).items():
            ax.axvline(v, color=REGIME_COLOURS[_PAPER_EDGE[k]], ls="--", lw=1, label=f"paper: {k} to {v:g}")
        ax.set(xlabel=LABELS[axis], ylabel="critical ambient film [um]")
        ax.set_ylim(bottom=0)
        ax.set_title(fixed_title(fixed, axis), fontsize=8)
        ax.grid(True, lw=0.3)
    axs[0].legend(fontsize=6, loc="lower left")
    suptitle(fig, title or "Ambient film needed to keep re-wetting the track (flooded above, parched below)", 9)
    return fig


def convergence(rows: list, key: str, label: str, title: str = ""):
    """Inlet film of the 2nd ball (the first re-wetting) against a convergence parameter (``key`` of the rows;
    ``None`` is the physical value, written as such)."""
    fig, ax = figure(size=(5.2, 3.8))
    xs = [r[key] for r in rows]
    ax.plot(range(len(xs)), [r["h_inlet"][1] * 1e6 for r in rows], "ko-")
    ax.set_xticks(range(len(xs)), [("physical" if x is None else f"{x:g}") for x in xs], fontsize=7)
    ax.set(xlabel=label if "[" in label else f"{label} [-]", ylabel="inlet film of ball 2 [um]")
    ax.set_title(title, fontsize=9)
    ax.grid(True, lw=0.3)
    return fig
