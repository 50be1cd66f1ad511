"""Figures of the EHL point contact (:class:`~transient.models.point.results.PointSteady`) and its starvation
studies (:mod:`transient.study.point`).

* :func:`maps` -- pressure and film maps of one or more contacts side by side (the horseshoe, the meniscus);
* :func:`starved_films` -- the central film against the inlet layer with Chevalier's law, and against the
  computed meniscus with Hamrock & Dowson's;
* :func:`ball_films` -- the ball bearing's central film from the formula and from the numerical contact against
  the inlet film, and the ball-pass sequences of both.
"""

from __future__ import annotations

import numpy as np

from transient.analysis.starvation import chevalier, hd_meniscus_law
from transient.plots import figure


def maps(results: dict, title: str = ""):
    """Pressure [GPa] and film [nm] over ``x/b``, ``y/b`` for each ``{label: PointSteady}`` (one column each):
    the film below three times its central value (the horseshoe), the central film and the minimum marked, the
    inlet meniscus (content 1) drawn in white on the film."""
    fig, axes = figure(2, len(results), size=(5.0 * len(results), 7.5), squeeze=False)
    for k, (label, s) in enumerate(results.items()):
        x, y = s.x / s.b, s.y / s.b
        ap, ah = axes[0, k], axes[1, k]
        p = np.clip(s.pressure, 0.0, None) * 1e-9
        cp = ap.contourf(x, y, p, levels=np.linspace(0.0, p.max(), 17), cmap="viridis")
        fig.colorbar(cp, ax=ap, label="p [GPa]")
        h = s.film * 1e9
        hc = s.h_central * 1e9
        ch = ah.contourf(x, y, np.minimum(h, 3.0 * hc), levels=np.linspace(h.min(), 3.0 * hc, 16), cmap="magma")
        fig.colorbar(ch, ax=ah, label="h [nm]")
        if np.any(s.theta < 1.0 - 1e-6):
            ah.contour(x, y, s.theta, levels=[1.0 - 1e-6], colors="w", linewidths=0.8)
        ah.plot([s.x_of_h_min / s.b], [s.y_of_h_min / s.b], "c^", ms=7, label=f"h_min = {s.h_min * 1e9:.3g} nm")
        ah.plot([0.0], [0.0], "wo", ms=5, label=f"h_c = {hc:.3g} nm")
        ah.legend(loc="lower left", fontsize=7)
        for ax, what in ((ap, "pressure"), (ah, "film")):
            ax.set(xlabel="x / b [-] (rolling)", ylabel="y / b [-]", title=f"{label}: {what}", aspect="equal")
            ax.set_xlim(x[0], x[-1])
            ax.set_ylim(max(y[0], -3.0 * np.abs(x[0])), min(y[-1], 3.0 * np.abs(x[0])))
    if title:
        fig.suptitle(title)
    return fig


def starved_films(checks: dict, title: str = ""):
    """(a) ``h_c/h_c,ff`` against ``r = h_oil/(rho_c h_c,ff)`` for each ``{label: chevalier_check(...)}``
    with the fitted Chevalier law and the limits ``r`` (all of a thin layer passes) and 1 (flooded); (b) the
    same films against the computed meniscus distance with Hamrock & Dowson's 0.29 law."""
    fig, (a, b) = figure(1, 2, size=(12.0, 4.8))
    rr = np.logspace(-1.3, 1.2, 200)

    for k, (label, c) in enumerate(checks.items()):
        line, = a.plot(c["r"], c["film"], "o", label=f"{label}: computed")
        a.plot(rr, chevalier(rr, c["gamma"]), "-", color=line.get_color(),
               label=f"Chevalier, fitted gamma = {c['gamma']:.2f} (max dev. {100 * c['max_deviation']:.1f} %)")
        b.plot(c["m"], c["film"], "o", color=line.get_color(), label=f"{label}: computed")
        mm = np.linspace(1.0, max(3.0, c["m_c"] * 1.1), 200)
        b.plot(mm, hd_meniscus_law(mm, c["m_c"]), "--", color=line.get_color(),
               label=f"Hamrock-Dowson 0.29 law, m_c = {c['m_c']:.2f}")
    a.plot(rr, np.minimum(rr, 1.0), "k:", lw=0.8, label="mass conservation / flooded limits")
    a.set(xscale="log", xlabel="r = h_oil / (rho_c h_c,ff) [-]", ylabel="h_c / h_c,ff [-]",
          title="(a) central film against the inlet layer")
    b.set(xlabel="meniscus distance m = -x_meniscus / b [-]", ylabel="h_c / h_c,ff [-]",
          title="(b) against the computed meniscus")
    for ax in (a, b):
        ax.set_ylim(0.0, 1.08)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    if title:
        fig.suptitle(title)
    return fig


def ball_films(tables: dict, sequences: dict, title: str = ""):
    """(a) the ball's central film relative to its flooded film against the inlet film relative to Hamrock-
    Dowson's flooded film, formula and numerical, for each ``{label: study.point.ball_films(...)}``; (b) the
    inlet film pass after pass for each ``{label: BallSequence}`` (log scale)."""
    fig, (a, b) = figure(1, 2, size=(12.0, 4.8))
    for label, t in tables.items():
        x = t["h_in"] / t["hd_central"]
        line, = a.plot(x, t["numerical"], "o-", label=f"{label}: numerical contact")
        a.plot(x, t["formula"], "s--", color=line.get_color(), mfc="none", label=f"{label}: formula (0.29 law)")
    a.set(xscale="log", xlabel="inlet film h_in / h_c,HD [-]", ylabel="h_c / h_c,ff [-]",
          title="(a) one pass: formula against numerical contact")
    a.set_ylim(0.0, 1.1)
    for label, s in sequences.items():
        n = np.arange(len(s.h_inlet))
        line, = b.semilogy(n, s.h_inlet * 1e9, "o-", label=f"{label}: inlet film")
        b.semilogy(n, s.h_central * 1e9, "x:", color=line.get_color(), label=f"{label}: central film")
    b.set(xlabel="ball pass n [-]", ylabel="film [nm]", title="(b) the ball-pass sequence")
    for ax in (a, b):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    if title:
        fig.suptitle(title)
    return fig
