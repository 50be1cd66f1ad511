"""Studies of the thrust ball bearing (seed 002): ball-pass sequences swept over one parameter, and the
regime boundaries they give (the paper's way: "flooded up to X, starved up to Y, parched beyond")."""

from __future__ import annotations

from transient.params import jeong

SWEPT = ("n_balls", "speed_rpm", "load", "ambient_film")


def sweep(bearing, swept: str, values, fixed: dict | None = None, n_passes: int = 100, **sequence_kwargs) -> list:
    """One ball-pass sequence per value of ``swept`` (one of ``n_balls``, ``speed_rpm`` [rpm], ``load`` [N],
    ``ambient_film`` [m]), the others at ``fixed`` (default: the paper's reference point)."""
    if swept not in SWEPT:
        raise ValueError(f"swept = {swept!r}; allowed: {', '.join(SWEPT)}")
    out = []
    for v in values:
        p = dict(jeong.REFERENCE, **(fixed or {}))
        p[swept] = v
        b = bearing.with_(n_balls=int(p["n_balls"]))
        out.append(b.sequence(load=p["load"], speed_rpm=p["speed_rpm"], ambient_film=p["ambient_film"],
                              n_passes=n_passes, **sequence_kwargs))
    return out


def boundaries(values, sequences) -> dict:
    """(first, last) swept value of each final regime."""
    res = {}
    for v, s in zip(values, sequences):
        res.setdefault(s.final_regime, []).append(float(v))
    return {k: (min(v), max(v)) for k, v in res.items()}
