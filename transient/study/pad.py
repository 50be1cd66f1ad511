"""Studies of the rough parallel thrust pad (Lee & Rhim, "Mixed lubrication analysis of parallel thrust bearing by
surface topography"): surfaces per gamma, descents, the contact and film loads against h0/Rq, the isotropic-surface
trends and the W_asp-A_re line (Fig. 6)."""

from __future__ import annotations

import numpy as np

from transient.params import lee_rhim
from transient.results import StatusResult, quantity, result_type
from transient.surfaces.roughness import RoughSurface


@result_type
class PadCurves(StatusResult):
    """:func:`curves_vs_h0`: per gamma (``per_gamma``, keyed by gamma) H = h0/Rq, the real contact area [%],
    the asperity load [N] and the film load [N] at the closing speed ``v_ref`` [m/s]."""

    time_axis = None
    per_gamma: dict = quantity("-", default_factory=dict)
    v_ref: float = quantity("m/s", 1e-3)


@result_type
class Trends(StatusResult):
    """:func:`trends`: one row per h0/Rq (``rows``, keyed "H=1.5"): per gamma A_re [m^2], W_asp [N], the film
    load in the descent and at a fixed closing rate [N] and the flow factors, and the flags of the paper's
    claims (:data:`CLAIMS`) with the relative spread of A_re."""

    time_axis = None
    rows: dict = quantity("-", default_factory=dict)
    load: float = quantity("N", 0.0)
    v_ref: float = quantity("m/s", 1e-3)


@result_type
class AsperityFit(StatusResult):
    """:func:`asperity_load_vs_area` (Fig. 6): per gamma (``per_gamma``) the equilibria of the load sweep
    (A_re [m^2], W_asp [N], h0/Rq, loads [N]) with their line fit (:func:`line_fit`) and the range of the mean
    real contact pressure [Pa]; ``overall``: the line through every gamma's points."""

    time_axis = None
    per_gamma: dict = quantity("-", default_factory=dict)
    overall: dict = quantity("-", default_factory=dict)


@result_type
class SeedSpread(StatusResult):
    """:func:`seed_spread`: per gamma (``per_gamma``) the mean and standard deviation of A_re [m^2] and W_asp
    [N] at h0 = ``H`` Rq over independent surfaces (``seeds``)."""

    time_axis = None
    per_gamma: dict = quantity("-", default_factory=dict)
    H: float = quantity("-", 1.5)
    seeds: tuple = ()


def surface(gamma, n, seed=11, **overrides):
    """A generated n x n surface with the study's correlation lengths for ``gamma`` (params.lee_rhim)."""
    s = dict(lee_rhim.SURFACE, **overrides)
    l0 = s.pop("l0")
    s.pop("acf")
    return RoughSurface.generate((n, n), s.pop("spacing"), s.pop("rq"),
                                 correlation_lengths=(l0 * np.sqrt(gamma), l0 / np.sqrt(gamma)), seed=seed, **s)


def descent_times(t_end, n_out):
    """Output times for a descent seen on a log time axis: 0, then geometric from t_end / 1e5 (a linear
    grid would draw a false plateau over its first interval on a log axis)."""
    return np.concatenate([[0.0], np.geomspace(t_end * 1e-5, t_end, n_out - 1)])


def curves_vs_h0(pads: dict, H, v_ref=1e-3) -> PadCurves:
    """Per gamma: real contact area fraction [%], asperity load [N] and the film load at a fixed closing
    speed ``v_ref`` [m/s] against H = h0/Rq."""
    out = {}
    for g, pad in pads.items():
        h = np.asarray(H) * pad.sigma
        out[g] = dict(H=np.asarray(H), area_pct=np.asarray(pad.contact_area(h)) / pad.area * 100,
                      w_asp=np.asarray(pad.asperity_load(h)), w_fixed_rate=np.array([pad.squeeze_coefficient(x) * v_ref
                                                                                     for x in h]))
    return PadCurves(per_gamma=out, v_ref=v_ref)


def trends(pads: dict, load, H_values=(1.0, 1.5, 2.0, 3.0), v_ref=1e-3) -> Trends:
    """The paper's claims at equal h0/Rq: the isotropic surface has the largest A_re and W_asp and the
    smallest film load (in the descent: W - W_asp; at a fixed closing rate)."""
    out = {}
    for H in H_values:
        row = {}
        for g, pad in pads.items():
            h = H * pad.sigma
            w_asp = float(pad.asperity_load(h))
            row[f"{g:.4g}"] = dict(A_re=float(pad.contact_area(h)), W_asp=w_asp, W_hyd_descent=load - w_asp,
                                   W_hyd_fixed_rate=pad.squeeze_coefficient(h) * v_ref, phi=pad.flow_factors(h)[:2])
        iso = row["1"]
        others = [v for k, v in row.items() if k != "1"]
        row["iso_largest_A_re"] = all(iso["A_re"] > o["A_re"] for o in others)
        row["iso_largest_W_asp"] = all(iso["W_asp"] > o["W_asp"] for o in others)
        row["iso_smallest_W_hyd_descent"] = all(iso["W_hyd_descent"] < o["W_hyd_descent"] for o in others)
        row["iso_smallest_W_hyd_fixed_rate"] = all(iso["W_hyd_fixed_rate"] < o["W_hyd_fixed_rate"] for o in others)
        a = [v["A_re"] for k, v in row.items() if isinstance(v, dict)]
        row["A_re_spread_rel"] = float((max(a) - min(a)) / np.mean(a))
        out[f"H={H:g}"] = row
    return Trends(rows=out, load=load, v_ref=v_ref)


#: the paper's claims checked by :func:`trends` (key, wording, why it does not hold in this model where it
#: does not: docs/validation.md, section "Parallel thrust pad in mixed lubrication -- validation")
CLAIMS = (
    ("iso_largest_A_re", "the isotropic surface (gamma = 1) has the largest real contact area A_re",
     "A_re (eq. 16) depends only on the height density, not on gamma; the differences are sampling noise"),
    ("iso_largest_W_asp", "the isotropic surface has the largest asperity load W_asp",
     "W_asp (eq. 15) depends only on the height density, not on gamma; the differences are sampling noise"),
    ("iso_smallest_W_hyd_descent", "the isotropic surface has the smallest film load in the descent",
     "in the massless descent W_hyd = W - W_asp only mirrors W_asp"),
    ("iso_smallest_W_hyd_fixed_rate", "the isotropic surface has the smallest film load at a fixed closing rate",
     "the flow factors make the isotropic film load the largest: the film drains through the direction "
     "with phi > 1"),
)
VALIDATION_SECTION = "Parallel thrust pad in mixed lubrication — validation"


def claim_verdicts(trends_: Trends) -> list[str]:
    """One line per paper's claim (``CLAIMS``) from :func:`trends`: "reproduced" when it holds at every
    h0/Rq checked, else "NOT reproduced" with the h0/Rq where it fails, the section of docs/validation.md and
    the reason."""
    lines = []
    for key, claim, why in CLAIMS:
        checked = [H.removeprefix("H=") for H in trends_.rows]
        fails = [H.removeprefix("H=") for H, row in trends_.rows.items() if not row[key]]
        where = f"h0/Rq = {', '.join(checked)}"
        if not fails:
            lines.append(f"paper's claim: {claim}: reproduced (at {where})")
        else:
            at = "all of " + where if len(fails) == len(checked) else f"h0/Rq = {', '.join(fails)} of {where}"
            lines.append(f"paper's claim: {claim}: NOT reproduced (fails at {at}; see docs/validation.md, section "
                         f"\"{VALIDATION_SECTION}\": {why})")
    return lines


def line_fit(x, y) -> dict:
    """Least-squares line y = k x + b, its R^2, and the slope through the origin."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    k, b = np.polyfit(x, y, 1)
    r2 = 1 - np.sum((y - (k * x + b)) ** 2) / np.sum((y - y.mean()) ** 2)
    return dict(slope=float(k), intercept=float(b), R2=float(r2), slope_origin=float(x @ y / (x @ x)))


def asperity_load_vs_area(pads: dict, loads) -> AsperityFit:
    """Fig. 6: equilibria of a load sweep per gamma, (A_re [m^2], W_asp [N]) and their straight-line fit."""
    out = {}
    for g, pad in pads.items():
        heq = np.array([pad.equilibrium(W) for W in loads])
        A, Wa = np.asarray(pad.contact_area(heq)), np.asarray(pad.asperity_load(heq))
        out[f"{g:.4g}"] = dict(A_re=A, W_asp=Wa, h0_over_rq=heq / pad.sigma, loads=np.asarray(loads), **line_fit(A, Wa),
                               p_r_min_Pa=float(np.min(Wa / A)), p_r_max_Pa=float(np.max(Wa / A)))
    overall = line_fit(np.concatenate([v["A_re"] for v in out.values()]),
                       np.concatenate([v["W_asp"] for v in out.values()]))
    return AsperityFit(per_gamma=out, overall=overall)


def seed_spread(make_pad, gammas, n, H=1.5, seeds=range(100, 105)) -> SeedSpread:
    """Sampling spread of A_re [m^2] and W_asp [N] at h0 = H Rq over independent surfaces per gamma:
    ``make_pad(surface)`` builds the pad of one surface."""
    out = {}
    for g in gammas:
        v = np.array([(float(p.contact_area(H * p.sigma)), float(p.asperity_load(H * p.sigma)))
                      for p in (make_pad(surface(g, n, seed=s)) for s in seeds)])
        out[f"{g:.4g}"] = dict(A_re_mean=float(v[:, 0].mean()), A_re_sd=float(v[:, 0].std(ddof=1)),
                               W_asp_mean=float(v[:, 1].mean()), W_asp_sd=float(v[:, 1].std(ddof=1)))
    return SeedSpread(per_gamma=out, H=H, seeds=tuple(seeds))
