"""Features of a steady EHL roller solution (Park) that the paper's statements are about.

All functions take :class:`~transient.models.roller.results.RollerSteady` results and return plain
dictionaries of SI numbers (lengths [m], pressures [Pa]):

* :func:`midplane_features` -- on the mid-plane row: central film, minimum film and its position (the
  outlet constriction), flatness of the central film, the pressure spike (the outlet-side local maximum
  of the pressure) and its height above the pressure at ``x = 0``;
* :func:`end_features` -- per end (``"small"``: ``y < 0``, ``"large"``: ``y > 0``): maximum pressure
  and minimum film with their positions;
* :func:`transverse_features` -- along ``x = x0`` near each end: where the transverse pressure peaks and
  where the film is thinnest (the paper: the peak lies inboard of the minimum film);
* :func:`section_features`, :func:`tilt_effects` -- the rolling-direction sections at the profile starts
  (Figs. 7, 8) and how much the tilt changes them, per end.
"""

from __future__ import annotations

import numpy as np


def midplane_features(s, c: float | None = None, at: float = 0.0) -> dict:
    """Features of the rolling-direction section at ``y = at`` (default the mid-plane): film at ``x = 0``
    (``h_central``), minimum film and its position (outlet constriction), variation of the film over
    ``|x| <= c/2`` relative to ``h_central`` (flatness), and the spike -- the largest local pressure
    maximum above half the section's maximum on the outlet side (``x > 0.3 c``) after a local minimum, i.e. a
    second peak (``spike_over_centre``:
    its height over the pressure at ``x = 0``); ``c`` defaults to the result's ``half_width``."""
    c = s.half_width if c is None else c
    x, p, h = s.section_x(at)
    i0 = int(np.argmin(np.abs(x)))
    core = np.abs(x) <= 0.5 * c
    k = int(np.argmin(h[1:-1])) + 1
    out = dict(h_central=float(h[i0]), h_min=float(h[k]), x_of_h_min=float(x[k]),
               central_film_variation=float((h[core].max() - h[core].min()) / h[i0]), p_centre=float(p[i0]))
    loc = np.flatnonzero((p[1:-1] > p[:-2]) & (p[1:-1] >= p[2:]) & (x[1:-1] > 0.3 * c) & (p[1:-1] > 0.5 * p.max())) + 1
    dips = np.flatnonzero((p[1:-1] < p[:-2]) & (p[1:-1] <= p[2:])) + 1
    loc = [j for j in loc if np.any((dips < j) & (x[dips] > x[i0] - c))]
    if loc:
        j = max(loc, key=lambda q: p[q])
        out.update(spike=True, p_spike=float(p[j]), x_of_spike=float(x[j]),
                   spike_over_centre=float(p[j] / p[i0] - 1.0))
    else:
        out.update(spike=False, p_spike=float("nan"), x_of_spike=float("nan"), spike_over_centre=0.0)
    return out


def end_features(s) -> dict:
    """Maximum pressure and minimum film on each half of the roller (``small``: y < 0, ``large``: y > 0)."""
    out = {}
    for name, sel in (("small", s.y < 0.0), ("large", s.y > 0.0)):
        P, H = s.pressure[sel], s.film[sel][:, 1:-1]
        ys = s.y[sel]
        jp, ip = np.unravel_index(int(np.argmax(P)), P.shape)
        jh, ih = np.unravel_index(int(np.argmin(H)), H.shape)
        out[name] = dict(p_max=float(P[jp, ip]), x_of_p_max=float(s.x[ip]), y_of_p_max=float(ys[jp]),
                         h_min=float(H[jh, ih]), x_of_h_min=float(s.x[ih + 1]), y_of_h_min=float(ys[jh]))
    return out


def transverse_features(s, x0: float = 0.0) -> dict:
    """Along ``x = x0``: for each end, the ``y`` of the pressure peak nearest that end and of the
    minimum film there, and whether the peak is inboard (closer to the mid-plane) of the minimum."""
    y, p, h = s.section_y(x0)
    out = {}
    for name, sel in (("small", y < 0.0), ("large", y > 0.0)):
        ys, ps, hs = y[sel], p[sel], h[sel]
        jp, jh = int(np.argmax(ps)), int(np.argmin(hs))
        out[name] = dict(y_of_peak=float(ys[jp]), p_peak=float(ps[jp]), y_of_min_film=float(ys[jh]),
                         h_min=float(hs[jh]), peak_inboard=bool(abs(ys[jp]) < abs(ys[jh])))
    return out


def section_features(s, y: float) -> dict:
    """Along the rolling direction at ``y`` (Park's Figs. 7, 8 sections): the maximum pressure, the film
    at ``x = 0`` and the minimum film of the section."""
    x, p, h = s.section_x(y)
    return dict(p_max=float(p.max()), h_at_x0=float(np.interp(0.0, x, h)), h_min=float(h[1:-1].min()))


def tilt_effects(results: dict, y_section: float) -> dict:
    """Spread of the end features over the tilts of ``results`` (``{tilt_deg: RollerSteady}``), relative
    to the untilted value: ``(max - min) / value at tilt 0``. For each end: the section at
    ``y = -+y_section`` (``section_*``: its maximum pressure, film at x = 0, minimum film) and the whole
    half of the roller (``end_*``: maximum pressure, minimum film)."""
    tilts = sorted(results)
    out = {}
    for end, ys in (("small", -y_section), ("large", y_section)):
        feats = {t: dict({f"section_{k}": v for k, v in section_features(results[t], ys).items()},
                         **{f"end_{k}": end_features(results[t])[end][k] for k in ("p_max", "h_min")}) for t in tilts}
        for key in feats[tilts[0]]:
            vals = np.array([feats[t][key] for t in tilts])
            out[f"{end}_{key}_change"] = float((vals.max() - vals.min()) / feats[0.0][key])
    return out
