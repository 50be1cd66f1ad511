"""Studies of the thrust ball bearing (Jeong, Lee, Yoo & Cho, thrust ball bearing starvation with film replenishment):
ball-pass sequences swept over one parameter, the regime map over three (ball count x speed x load), the regime
boundaries they give (the paper's way: "flooded up to X, starved up to Y, parched beyond"), the critical ambient
film / surface tension at which a bearing stops re-wetting its track, and the convergence tables of the front-
following levelling (grid, precursor)."""

from __future__ import annotations

import math
import time

import numpy as np

from transient.models.ball.bearing import FLOODED, PARCHED, STARVED, sequence_settings
from transient.params import jeong
from transient.results import StatusResult, quantity, result_type

SWEPT = ("n_balls", "speed_rpm", "load", "ambient_film")
REGIMES = (FLOODED, STARVED, PARCHED)
#: settings of the regime maps (transient.params.jeong.MAP_SETTINGS): the physical model, BDF2 at rtol 1e-3
MAP_SETTINGS = jeong.MAP_SETTINGS


def _point(bearing, p: dict, n_passes: int, kw: dict):
    b = bearing.with_(n_balls=int(p["n_balls"]))
    return b.sequence(load=p["load"], speed_rpm=p["speed_rpm"], ambient_film=p["ambient_film"],
                      n_passes=n_passes, **sequence_settings(**kw))


def sweep(bearing, swept: str, values, fixed: dict | None = None, n_passes: int = 100, **sequence_kwargs) -> list:
    """One ball-pass sequence per value of ``swept`` (one of ``n_balls``, ``speed_rpm`` [rpm], ``load`` [N],
    ``ambient_film`` [m]), the others at ``fixed`` (default: the paper's reference point)."""
    if swept not in SWEPT:
        raise ValueError(f"swept = {swept!r}; allowed: {', '.join(SWEPT)}")
    out = []
    for v in values:
        p = dict(jeong.REFERENCE, **(fixed or {}))
        p[swept] = v
        out.append(_point(bearing, p, n_passes, sequence_kwargs))
    return out


def boundaries(values, sequences) -> dict:
    """(first, last) swept value of each final regime."""
    res = {}
    for v, s in zip(values, sequences):
        res.setdefault(s.final_regime, []).append(float(v))
    return {k: (min(v), max(v)) for k, v in res.items()}


# --------------------------------------------------------------------------------------------------
# regime map
# --------------------------------------------------------------------------------------------------

@result_type
class RegimeMap(StatusResult):
    """Final regime of the ball-pass sequence over ball count x speed x load (one ambient film).

    Arrays are indexed ``[i_balls, i_speed, i_load]``; ``regime`` holds indices into ``regimes``
    (0 fully flooded, 1 starved, 2 parched); ``H_central`` the central film ``h_c / r_b`` of the last pass,
    ``h_inlet`` the last inlet film [m], ``m`` / ``m_c`` the last and critical meniscus, ``n_run`` the passes
    run, ``wall`` the seconds per point."""

    time_axis = None
    n_balls: np.ndarray = quantity("-")
    speed_rpm: np.ndarray = quantity("rpm")
    load: np.ndarray = quantity("N")
    ambient_film: float = quantity("m", 0.0)
    regimes: tuple = REGIMES
    regime: np.ndarray = quantity("-", None)
    H_central: np.ndarray = quantity("-", None)
    h_inlet: np.ndarray = quantity("m", None)
    m: np.ndarray = quantity("-", None)
    m_c: np.ndarray = quantity("-", None)
    n_run: np.ndarray = quantity("-", None)
    wall: np.ndarray = quantity("s", None)
    settings: dict = None

    def names(self) -> np.ndarray:
        """The regime of every point as a string array."""
        return np.array(self.regimes, dtype=object)[np.asarray(self.regime, dtype=np.int64)]

    def line(self, axis: str, **at) -> tuple[np.ndarray, np.ndarray]:
        """(values, regime names) along ``axis`` (``n_balls``, ``speed_rpm`` or ``load``) at the other two
        given as keywords (nearest map values)."""
        axes = ("n_balls", "speed_rpm", "load")
        idx = []
        for a in axes:
            if a == axis:
                idx.append(slice(None))
            else:
                vals = np.asarray(getattr(self, a), float)
                idx.append(int(np.argmin(np.abs(vals - float(at[a])))))
        return np.asarray(getattr(self, axis)), self.names()[tuple(idx)]


def regime_map(bearing, n_balls, speeds, loads, ambient_film: float = 100e-6, n_passes: int = 60,
               progress=None, **sequence_kwargs) -> RegimeMap:
    """Run one ball-pass sequence per (ball count, speed, load) point, serially (a loop over independent points:
    a process pool can split it later). ``sequence_kwargs`` override :data:`MAP_SETTINGS`; ``progress(i, n,
    point, sequence)`` is called after each point."""
    kw = dict(MAP_SETTINGS, **sequence_kwargs)
    Z, N, W = (np.asarray(v) for v in (n_balls, speeds, loads))
    shape = (Z.size, N.size, W.size)
    reg = np.zeros(shape, dtype=np.int64)
    out = {k: np.full(shape, np.nan) for k in ("H_central", "h_inlet", "m", "m_c", "wall")}
    n_run = np.zeros(shape, dtype=np.int64)
    total, k = int(np.prod(shape)), 0
    for i, z in enumerate(Z):
        for j, rpm in enumerate(N):
            for l, w in enumerate(W):
                t0 = time.perf_counter()
                p = dict(n_balls=int(z), speed_rpm=float(rpm), load=float(w), ambient_film=ambient_film)
                s = _point(bearing, p, n_passes, kw)
                reg[i, j, l] = REGIMES.index(s.final_regime)
                out["H_central"][i, j, l] = s.H_central[-1]
                out["h_inlet"][i, j, l] = s.h_inlet[-1]
                out["m"][i, j, l] = s.m[-1]
                out["m_c"][i, j, l] = s.m_c
                out["wall"][i, j, l] = time.perf_counter() - t0
                n_run[i, j, l] = s.n_run
                k += 1
                if progress is not None:
                    progress(k, total, p, s)
    return RegimeMap(n_balls=Z, speed_rpm=N, load=W, ambient_film=float(ambient_film), regime=reg,
                     n_run=n_run, settings={k: (v if isinstance(v, (int, float, str)) else str(v))
                                            for k, v in dict(kw, n_passes=n_passes).items()}, **out)


# --------------------------------------------------------------------------------------------------
# what would reproduce the paper
# --------------------------------------------------------------------------------------------------

def _flooded(bearing, p, n_passes, kw) -> bool:
    return _point(bearing, p, n_passes, kw).final_regime == FLOODED


def critical_value(bearing, name: str, lo: float, hi: float, point: dict | None = None, rel_tol: float = 0.02,
                   n_passes: int = 60, log: bool = True, **sequence_kwargs) -> dict:
    """Bisect ``name`` (``ambient_film`` [m], ``surface_tension`` [N/m], ``speed_rpm``, ``load`` or ``n_balls``)
    between ``lo`` and ``hi`` for the value where the final regime changes between fully flooded and not, at
    the other parameters of ``point`` (default: the paper's reference). Returns ``{"lo", "hi", "regime_lo",
    "regime_hi", "value"}`` (``value`` the geometric mean of the final bracket, or None if ``lo`` and ``hi``
    give the same verdict)."""
    kw = dict(MAP_SETTINGS, **sequence_kwargs)
    p = dict(jeong.REFERENCE, **(point or {}))

    def verdict(v):
        if name == "surface_tension":
            return _point(bearing.with_(surface_tension=v), p, n_passes, kw).final_regime
        q = dict(p)
        q[name] = v
        return _point(bearing, q, n_passes, kw).final_regime

    r_lo, r_hi = verdict(lo), verdict(hi)
    res = dict(name=name, lo=float(lo), hi=float(hi), regime_lo=r_lo, regime_hi=r_hi, value=None, point=p)
    if (r_lo == FLOODED) == (r_hi == FLOODED):
        return res
    while (hi / lo - 1.0 if log else (hi - lo) / abs(hi)) > rel_tol:
        mid = math.sqrt(lo * hi) if log else 0.5 * (lo + hi)
        if name == "n_balls":
            mid = int(round(mid))
            if mid in (int(lo), int(hi)):
                break
        r = verdict(mid)
        if (r == FLOODED) == (r_lo == FLOODED):
            lo, r_lo = mid, r
        else:
            hi, r_hi = mid, r
    res.update(lo=float(lo), hi=float(hi), regime_lo=r_lo, regime_hi=r_hi,
               value=float(math.sqrt(lo * hi) if log else 0.5 * (lo + hi)))
    return res


# --------------------------------------------------------------------------------------------------
# convergence of the front-following levelling
# --------------------------------------------------------------------------------------------------

def convergence(bearing, *, refines=(0.5, 1.0, 2.0, 4.0), precursors=None, n_passes: int = 3,
                point: dict | None = None, **sequence_kwargs) -> dict:
    """Inlet films of the first ``n_passes`` balls on refined front meshes (``refines``, physical precursor) and,
    if ``precursors`` [m] is given, for precursor films decreasing to the physical one (``None`` in the list:
    the outlet film ``h_c/2``), at ``refine=1``. Returns ``{"grid": rows, "precursor": rows}`` with per row
    the inlet films [m], the regime list, the steps and the wall time."""
    p = dict(jeong.REFERENCE, **(point or {}))
    kw = dict(dict(rtol=1e-5, atol=1e-8), **sequence_kwargs)
    b = bearing.with_(n_balls=int(p["n_balls"]))
    out = {"grid": [], "precursor": []}

    def row(**extra):
        t0 = time.perf_counter()
        s = b.sequence(load=p["load"], speed_rpm=p["speed_rpm"], ambient_film=p["ambient_film"], n_passes=n_passes,
                       stop_at_periodic=False, **sequence_settings(**dict(kw, **extra)))
        return dict(h_inlet=s.h_inlet.tolist(), regime=list(s.regime), steps=int(s.stats["n_steps"]),
                    wall=time.perf_counter() - t0, h_out=s.h_outlet.tolist())

    for f in refines:
        out["grid"].append(dict(refine=float(f), **row(refine=f)))
    for pf in precursors or ():
        out["precursor"].append(dict(precursor=pf, **row(precursor_film=pf)))
    return out


def paper_regime(axis: str, value: float, reported: dict = jeong.REPORTED) -> str:
    """The regime the paper reports at ``value`` of ``axis`` (n_balls, speed_rpm, load) at the reference
    point: fully flooded up to its flooded boundary, starved up to its starved boundary, parched beyond."""
    b = reported[axis]
    return FLOODED if value <= b["flooded"] else STARVED if value <= b["starved"] else PARCHED


def paper_verdict(axis: str, values, regimes, reported: dict = jeong.REPORTED) -> str:
    """"reproduced" when the model's regimes at ``values`` of ``axis`` are the paper's (:func:`paper_regime`)
    at every sampled value, else "NOT reproduced" with the number of points that differ."""
    paper = [paper_regime(axis, float(v), reported) for v in values]
    bad = [f"{float(v):g}: {r} (paper {p})" for v, r, p in zip(values, regimes, paper) if r != p]
    if not bad:
        return f"reproduced at all {len(paper)} sampled values"
    return f"NOT reproduced at {len(bad)} of {len(paper)} sampled values ({'; '.join(bad[:4])}{' ...' if len(bad) > 4 else ''})"
