"""Figures of the tapered-roller EHL (Park, Figs. 3-10), drawn from
:class:`~transient.models.roller.results.RollerSteady` results only, in the paper's dimensionless units
(X, Y by R_m; P = p/E' x 10^3; H = h/R_m x 10^5), or for the maps in engineering units
(``units="SI"``: x, y in mm, pressure in GPa, film in um).

* :func:`maps` -- contours of pressure or film: the whole contact and zooms on the small and large end
  (Figs. 3-6);
* :func:`rolling_sections` -- pressure and film along X at a given Y for several results (Figs. 7, 8);
* :func:`transverse_sections` -- pressure and film along Y at X = 0 near one end (Figs. 9, 10).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from transient.plots import figure

P_UNIT, H_UNIT = 1e3, 1e5
STYLES = ("-", "--", ":", "-.")


def _zoom(s, end: str) -> tuple[float, float]:
    """Y window (units of R_m) around one profiled end: from 6 c inboard of the profile start to
    2 c beyond the footprint end."""
    rm, c = s.mean_radius, s.half_width
    yd, half = s.profile_start / rm, 0.5 * s.footprint_length / rm
    lo, hi = yd - 6 * c / rm, half + 2 * c / rm
    return (-hi, -lo) if end == "small" else (lo, hi)


def maps(s, quantity: str = "pressure", title: str = "", units: str = "paper"):
    """Contour maps of ``quantity`` (``"pressure"`` or ``"film"``): (a) complete, (b) small end,
    (c) large end. The film is drawn where it is below three times the central film. ``units``:
    ``"paper"`` (X, Y, P x 10^3, H x 10^5) or ``"SI"`` (mm, GPa, um)."""
    if units not in ("paper", "SI"):
        raise ValueError(f"units = {units!r}: use 'paper' or 'SI'")
    si = units == "SI"
    length = 1e3 * s.mean_radius if si else 1.0  # axis values per unit of X, Y
    X, Y = s.X * length, s.Y * length
    if quantity == "pressure":
        Z, label = (s.pressure * 1e-9, "p [GPa]") if si else (s.P * P_UNIT, r"$P \times 10^3$ [-]")
        levels = np.linspace(0.0, Z.max(), 16)[1:]
    else:
        Z, label = (s.film * 1e6, r"h [$\mu$m]") if si else (s.H * H_UNIT, r"$H \times 10^5$ [-]")
        hc = s.h_central * (1e6 if si else H_UNIT / s.mean_radius)
        levels = np.linspace(Z[1:-1, 1:-1].min(), 3.0 * hc, 16)
    fig = Figure(figsize=(12, 8), layout="constrained")
    gs = fig.add_gridspec(2, 2, height_ratios=(1.0, 1.1))
    panels = [(fig.add_subplot(gs[0, :]), None, "(a) complete"), (fig.add_subplot(gs[1, 0]), "small", "(b) small end"),
              (fig.add_subplot(gs[1, 1]), "large", "(c) large end")]
    cs = None
    for ax, end, name in panels:
        cs = ax.contourf(Y, X, Z.T, levels=levels, cmap="viridis", extend="max")
        ax.contour(Y, X, Z.T, levels=levels[::3], colors="k", linewidths=0.5)
        if end is not None:
            ax.set_xlim(*(length * v for v in _zoom(s, end)))
        ax.set_ylim(-1.6 * length * s.half_width / s.mean_radius, 1.6 * length * s.half_width / s.mean_radius)
        ax.set_xlabel("y [mm] (along the roller; small end < 0)" if si else "Y = y / R_m [-] (along the roller; small end < 0)")
        ax.set_ylabel("x [mm] (rolling)" if si else "X = x / R_m [-] (rolling)")
        ax.set_title(name, fontsize=10)
    fig.colorbar(cs, ax=[p[0] for p in panels], label=label, shrink=0.8)
    fig.suptitle(title)
    return fig


def rolling_sections(results: dict, y: float, title: str = ""):
    """Pressure and film along the rolling direction at ``y`` [m] for ``{label: RollerSteady}``."""
    fig, (ap, ah) = figure(2, 1, size=(7.5, 7), sharex=True)
    for k, (label, s) in enumerate(results.items()):
        x, p, h = s.section_x(y)
        ap.plot(x / s.mean_radius, p / s.modulus * P_UNIT, STYLES[k % 4], label=label)
        ah.plot(x / s.mean_radius, h / s.mean_radius * H_UNIT, STYLES[k % 4], label=label)
    s0 = next(iter(results.values()))
    c = s0.half_width / s0.mean_radius
    return _sections_frame(fig, ap, ah, s0, 4.0, (-2.5 * c, 2.0 * c), "X = x / R_m [-]", title)


def transverse_sections(results: dict, end: str, x: float = 0.0, title: str = ""):
    """Pressure and film along the roller at ``x`` [m] near the ``end`` (``"small"``/``"large"``)."""
    fig, (ap, ah) = figure(2, 1, size=(7.5, 7), sharex=True)
    s0 = next(iter(results.values()))
    for k, (label, s) in enumerate(results.items()):
        y, p, h = s.section_y(x)
        ap.plot(y / s.mean_radius, p / s.modulus * P_UNIT, STYLES[k % 4], marker=".", ms=3, label=label)
        ah.plot(y / s.mean_radius, h / s.mean_radius * H_UNIT, STYLES[k % 4], marker=".", ms=3, label=label)
    return _sections_frame(fig, ap, ah, s0, 3.0, _zoom(s0, end), "Y = y / R_m [-]", title)


def _sections_frame(fig, ap, ah, s0, film_top, xlim, xlabel, title):
    """Axes of a pressure (top) / film (bottom) section figure: the film up to ``film_top`` central films of
    ``s0``, the abscissa window ``xlim``, labels in the paper's units, legend, grid, title."""
    ah.set_ylim(0.0, film_top * s0.h_central / s0.mean_radius * H_UNIT)
    ah.set_xlim(*xlim)
    ap.set_ylabel(r"$P = p / E' \times 10^3$ [-]")
    ah.set_ylabel(r"$H = h / R_m \times 10^5$ [-]")
    ah.set_xlabel(xlabel)
    ap.legend()
    for a in (ap, ah):
        a.grid(alpha=0.3)
    fig.suptitle(title)
    return fig


def moes_chart(rows: list[dict], curves: dict, title: str = ""):
    """The Moes chart of the line contact from :func:`transient.study.ehl_chart.run_chart` rows and
    :func:`transient.study.ehl_chart.moes_curves`: (a) the central film ``H_c = (h_c/R)(2U)^-1/2``
    against M for each L (markers: solved; lines: Moes' formula; dotted: the four asymptotes, the
    piezoviscous ones at the largest L; x: not converged), (b) the minimum film; (c), (d) contours of
    ``H_c`` and ``H_min`` over the (M, L) plane (filled: solved points; dashed in (c): Moes' formula)."""
    Ls = sorted({r["L"] for r in rows})
    Mf = curves["M"]
    fig = Figure(figsize=(12, 10), layout="constrained")
    ax_c, ax_m = fig.add_subplot(2, 2, 1), fig.add_subplot(2, 2, 2)
    for k, L in enumerate(Ls):
        col = f"C{k}"
        pts = sorted((r for r in rows if r["L"] == L and r["success"]), key=lambda r: r["M"])
        ax_c.loglog([r["M"] for r in pts], [r["H_c"] for r in pts], "o", color=col, label=f"L = {L:g}")
        ax_c.loglog(Mf, curves["formula"][L], "-", color=col, lw=1)
        ax_m.loglog([r["M"] for r in pts], [r["H_min"] for r in pts], "s-", color=col, label=f"L = {L:g}")
        failed = [r for r in rows if r["L"] == L and not r["success"]]
        ax_c.loglog([r["M"] for r in failed], [r["moes"] for r in failed], "x", color="k", ms=9)
    for name, values in curves["asymptotes"].items():
        ax_c.loglog(Mf, values, ":", color="0.5", lw=0.8)
        at = -1 if name in ("EI", "EP") else 0
        ax_c.annotate(name, (Mf[at], values[at]), fontsize=8, color="0.4")
    ok = [r["H_c"] for r in rows if r["success"]] or [1.0]
    ax_c.set_ylim(0.5 * min(ok), 2.0 * max(ok))
    for ax, name in ((ax_c, r"central film $H_c = (h_c/R)(2U)^{-1/2}$"),
                     (ax_m, r"minimum film $H_{min} = (h_{min}/R)(2U)^{-1/2}$")):
        ax.set_xlabel(r"load $M = W (2U)^{-1/2}$ [-]")
        ax.set_ylabel(name + " [-]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    ax_c.set_title("(a) markers: this solver; lines: Moes' formula; dotted: asymptotes", fontsize=9)
    ax_m.set_title("(b) minimum film (outlet constriction)", fontsize=9)
    good = [r for r in rows if r["success"]]
    for pos, key, label in ((3, "H_c", "(c) central film $H_c$"), (4, "H_min", "(d) minimum film $H_{min}$")):
        ax = fig.add_subplot(2, 2, pos)
        if len({r["M"] for r in good}) >= 2 and len({r["L"] for r in good}) >= 2:
            lm = np.log10([r["M"] for r in good])
            lv = np.array([r["L"] for r in good])
            val = np.log10([r[key] for r in good])
            cs = ax.tricontourf(lm, lv, val, levels=14, cmap="viridis")
            fig.colorbar(cs, ax=ax, label=f"log10 {key} [-]")
            lines = ax.tricontour(lm, lv, val, levels=cs.levels[::2], colors="w", linewidths=0.6)
            ax.clabel(lines, fmt=lambda v: f"{10 ** v:.3g}", fontsize=7)
            if key == "H_c":
                moes = np.log10([r["moes"] for r in good])
                ax.tricontour(lm, lv, moes, levels=cs.levels[::2], colors="k", linewidths=0.8, linestyles="--")
            ax.plot(lm, lv, "k.", ms=3)
        ax.set_xlabel(r"$\log_{10} M$ [-]")
        ax.set_ylabel(r"$L = G (2U)^{1/4}$ [-]")
        ax.set_title(label + (" (dashed: Moes' formula)" if key == "H_c" else ""), fontsize=9)
    fig.suptitle(title)
    return fig
