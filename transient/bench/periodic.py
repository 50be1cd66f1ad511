"""Periodic orbits of the journal orbit by shooting against brute-force settling (Rho & Kim).

Paper case (Table 1, m = 100 kg, e = 0.01 C, W = 981 N) on the paper's 151 x 21 half grid (quick: 41 x 6). The
methods of each comparison run one after the other in one process from the same start; on the project's 2
shared cores the ratios are the meaningful numbers.

1. **The Fig. 8 curve**, 1000-7500 rpm in 250 rpm steps (27 speeds) at the scenario's rtol 1e-5:
   * today's settle loop, per speed: the linearised start, at least 4 revolutions, until the distance from the
     settled orbit extrapolated from consecutive revolutions is 1 % of the amplitude, at most 40
     (``study.journal.settled_unbalance_orbit``);
   * continuation (:func:`~transient.models.journal.periodic.response_curve`): periodic orbits by Newton-Picard
     with their Floquet multipliers, each warm-started from the previous speeds; then continued past 7500 rpm in
     250 rpm steps until the orbit is unstable, and the onset located by secant steps
     (:func:`~transient.models.journal.periodic.stability_onset`).
   Accuracy: the semi-major axis of each against a reference continuation at rtol 1e-7 (full bench only).
2. **Single speeds to 1e-8 C** (rtol 1e-9), 6000 rpm and 0.95 of the onset found in 1: Newton-Picard shooting and
   Newton-Krylov from the linearised start; brute force from the same start (IDA continuing across revolutions)
   until its once-per-revolution point is within 1e-8 C of the shooting solution -- an oracle stop, the
   cheapest settling run possible (a detector that does not know the answer needs more revolutions).
3. **The monodromy's spectrum** at 6000 rpm: Arnoldi (6 multipliers) on the full film + rotor map.

``main(out, quick)`` writes ``out/bench_periodic.json`` and returns the markdown section.
"""

from __future__ import annotations

import json
import platform
import time
from pathlib import Path

import numpy as np

from transient.analysis.orbits import orbit_shape
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.models.journal.periodic import floquet_check, periodic_response, response_curve, stability_onset
from transient.params.rho_kim import BEARING, ROTOR
from transient.study.journal import settled_unbalance_orbit
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "journal periodic orbits: shooting and continuation vs brute-force settling"
FULL = dict(grid=(151, 21), speeds=tuple(range(1000, 7501, 250)), rtol=1e-5, reference_rtol=1e-7, single=True,
            arnoldi=True, max_revolutions=600)
QUICK = dict(grid=(41, 6), speeds=tuple(range(1000, 7501, 750)), rtol=1e-5, reference_rtol=None, single=True,
             arnoldi=False, max_revolutions=300)
OPR = 64


def _orbit(bearing, speed):
    return JournalOrbit(bearing, speed_rpm=float(speed), **ROTOR)


def _semi_major(p, C):
    return orbit_shape(p.x[:-1] / C, p.y[:-1] / C)["semi_major"]


def curve_part(bearing, cfg, log):
    """Part 1: the settle loop and the continuation over the same speeds, then the onset."""
    C = bearing.clearance
    sp, rtol = cfg["speeds"], cfg["rtol"]
    _orbit(bearing, sp[0]).run(0.05, integration=Integration(rtol=1e-3), long_run=LongRun(progress=False))  # JIT warm-up outside the timings
    rows = []
    t0 = time.perf_counter()
    for s in sp:
        t = time.perf_counter()
        u = settled_unbalance_orbit(_orbit(bearing, s), rtol, OPR)
        rows.append(dict(speed_rpm=s, settle_wall=time.perf_counter() - t, settle_revolutions=u.revolutions,
                         settle_estimate=u.settle_estimate, settle_semi_major=u.shape["semi_major"], settled=u.success))
        log(f"  settle {s:5d} rpm: {u.revolutions} rev, {rows[-1]['settle_wall']:.1f} s ({u.message})")
    settle_wall = time.perf_counter() - t0
    t0 = time.perf_counter()
    curve = response_curve(_orbit(bearing, sp[0]), sp, rtol=rtol, outputs_per_revolution=OPR)
    cont_wall = time.perf_counter() - t0
    for r, p in zip(rows, curve.orbits):
        r.update(cont_wall=p.wall_time, cont_periods=p.revolutions_integrated, cont_iterations=p.iterations,
                 cont_semi_major=_semi_major(p, C), max_multiplier=p.max_multiplier,
                 cont_error_estimate=p.error_estimate / C)
    log(f"  settle loop {settle_wall:.1f} s, continuation {cont_wall:.1f} s")
    out = dict(rows=rows, settle_wall=settle_wall, cont_wall=cont_wall, periodic_all=bool(curve.converged.all()),
               stable_all=bool(not curve.unstable.any()))
    # past the curve: on until unstable, then the onset
    history, s, t0 = list(curve.orbits), float(sp[-1]), time.perf_counter()
    beyond = []
    while all(p.stable for p in history) and s < 12000:
        s += 250.0
        p = response_curve(_orbit(bearing, s), [s], rtol=rtol, previous=history).orbits[0]
        beyond.append(dict(speed_rpm=s, max_multiplier=p.max_multiplier, periods=p.revolutions_integrated))
        if not p.converged:
            break
        history.append(p)
    onset = stability_onset(_orbit(bearing, s), history[-2], history[-1], rtol=rtol) if not history[-1].stable else None
    out.update(beyond=beyond, onset_rpm=None if onset is None else onset.onset_rpm,
               onset_wall=time.perf_counter() - t0,
               onset_search=None if onset is None else dict(speed_rpm=onset.speed_rpm.tolist(),
                                                            max_multiplier=onset.max_multiplier.tolist()))
    log(f"  onset of the periodic orbit: {out['onset_rpm']} rpm ({out['onset_wall']:.1f} s)")
    if cfg["reference_rtol"]:
        ref = response_curve(_orbit(bearing, sp[0]), sp, rtol=cfg["reference_rtol"], outputs_per_revolution=OPR)
        for r, p in zip(rows, ref.orbits):
            r["reference_semi_major"] = _semi_major(p, C)
            r["settle_error"] = abs(r["settle_semi_major"] / r["reference_semi_major"] - 1)
            r["cont_error"] = abs(r["cont_semi_major"] / r["reference_semi_major"] - 1)
    return out


def single_part(bearing, speed, tol, log, max_revolutions):
    """Part 2 at one speed: Newton-Picard, Newton-Krylov and the oracle-stopped brute force, from one start."""
    o = _orbit(bearing, speed)
    C, n = bearing.clearance, o.film.n
    rtol = tol / 10.0
    y0 = o.linear_start()
    t = time.perf_counter()
    p = periodic_response(o, rtol=rtol, tol=tol, start=y0)
    np_wall = time.perf_counter() - t
    t = time.perf_counter()
    k = periodic_response(o, rtol=rtol, tol=tol, start=y0, method="newton-krylov")
    nk_wall = time.perf_counter() - t
    ref = p.state[n:n + 2]

    def close(r):
        return "within tol" if np.hypot(r.x[-1] / C - ref[0], r.y[-1] / C - ref[1]) <= 0.5 * tol else None

    t = time.perf_counter()
    b = o.run(max_revolutions, y0=y0, integration=Integration(rtol=rtol, atol=1e-3 * rtol),
              recording=Recording(outputs_per_revolution=1),
              long_run=LongRun(chunk_revolutions=2, stop=close, progress=False))
    bf_wall = time.perf_counter() - t
    d = np.hypot(b.x / C - ref[0], b.y / C - ref[1])
    row = dict(speed_rpm=speed, tol=tol, rtol=rtol, np_wall=np_wall, np_periods=p.revolutions_integrated,
               np_iterations=p.iterations, np_residuals=[v / C for v in p.residual_norms], np_error=p.error_estimate / C,
               multipliers=[[m.real, m.imag] for m in p.multipliers], max_multiplier=p.max_multiplier,
               nk_wall=nk_wall, nk_periods=k.revolutions_integrated, nk_iterations=k.iterations,
               nk_vs_np=float(np.abs(k.state[n:] - p.state[n:]).max()),
               bf_wall=bf_wall, bf_revolutions=len(b.t) - 1, bf_reached=bool(b.message == "within tol"),
               bf_final_distance=float(d[-1]), bf_distance=d.tolist())
    log(f"  {speed:.0f} rpm: Newton-Picard {np_wall:.1f} s ({p.revolutions_integrated} periods), Newton-Krylov "
        f"{nk_wall:.1f} s ({k.revolutions_integrated}), brute force {bf_wall:.1f} s ({len(b.t) - 1} rev)")
    return row, (o, p)


def run(quick=False, log=print) -> dict:
    cfg = QUICK if quick else FULL
    bearing = JournalBearing(**BEARING, grid=cfg["grid"])
    out = dict(config=dict(cfg, machine=f"{platform.machine()} {platform.system()}", quick=quick))
    log(f"periodic bench, grid {cfg['grid']}: Fig. 8 curve ...")
    out["curve"] = curve_part(bearing, cfg, log)
    onset = out["curve"]["onset_rpm"]
    speeds = [6000.0] + ([round(0.95 * onset)] if onset else [])
    out["single"] = [single_part(bearing, s, 1e-8, log, cfg["max_revolutions"])[0] for s in speeds]
    if cfg["arnoldi"]:
        o = _orbit(bearing, 6000.0)
        p = periodic_response(o, rtol=1e-9, tol=1e-8)
        t = time.perf_counter()
        mu, share, periods = floquet_check(o, p, k=6, rtol=1e-8, fd_step=1e-4)
        out["arnoldi"] = dict(multipliers=[[m.real, m.imag] for m in mu], modulus=np.abs(mu).tolist(),
                              rotor_share=share.tolist(), periods=periods, wall=time.perf_counter() - t,
                              ritz=[[m.real, m.imag] for m in p.multipliers])
    return out


def _f(v, spec=".3g"):
    return "—" if v is None or (isinstance(v, float) and not np.isfinite(v)) else format(v, spec)


def markdown(r) -> str:
    c, cv = r["config"], r["curve"]
    rows = cv["rows"]
    lines = [f"Grid {c['grid'][0]} x {c['grid'][1]}, {c['machine']}; Table 1 rotor, e = 0.01 C.", "",
             f"### Fig. 8 curve: {len(rows)} speeds {rows[0]['speed_rpm']}-{rows[-1]['speed_rpm']} rpm, "
             f"rtol {c['rtol']:g}", "",
             "| speed [rpm] | settle loop [s] | revolutions | est. distance / amp. | continuation [s] | periods | "
             "\\|mu\\| | semi-major [C] | settle error | continuation error |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for w in rows:
        lines.append(f"| {w['speed_rpm']} | {w['settle_wall']:.2f} | {w['settle_revolutions']} | "
                     f"{w['settle_estimate']:.1e} | {w['cont_wall']:.2f} | {w['cont_periods']} | "
                     f"{w['max_multiplier']:.3f} | {w['cont_semi_major']:.5f} | {_f(w.get('settle_error'), '.1e')} | "
                     f"{_f(w.get('cont_error'), '.1e')} |")
    tot_rev = sum(w["settle_revolutions"] for w in rows)
    tot_per = sum(w["cont_periods"] for w in rows)
    lines += ["", f"**Settle loop {cv['settle_wall']:.1f} s ({tot_rev} revolutions + {len(rows)} linearised starts), "
                  f"continuation {cv['cont_wall']:.1f} s ({tot_per} periods): "
                  f"{cv['settle_wall'] / cv['cont_wall']:.1f}x** (target >= 10x). Errors: relative, of the semi-major "
                  f"axis against the continuation at rtol {_f(c['reference_rtol'], 'g')}.", "",
              f"Past {rows[-1]['speed_rpm']} rpm: "
              + ", ".join(f"{b['speed_rpm']:.0f} rpm \\|mu\\| = {b['max_multiplier']:.4f}" for b in cv["beyond"])
              + f"; the periodic orbit loses stability at **{_f(cv['onset_rpm'], '.0f')} rpm** (continuation past "
                f"{rows[-1]['speed_rpm']} rpm and secant search: {cv['onset_wall']:.1f} s)."]
    lines += ["", "### One periodic orbit to 1e-8 C (rtol 1e-9)", "",
              "| speed [rpm] | \\|mu\\| | Newton-Picard [s] (periods) | Newton-Krylov [s] (periods) | "
              "brute force [s] (revolutions) | brute / Newton-Picard |", "|---|---|---|---|---|---|"]
    for s in r["single"]:
        lines.append(f"| {s['speed_rpm']:.0f} | {s['max_multiplier']:.4f} | {s['np_wall']:.1f} ({s['np_periods']}) | "
                     f"{s['nk_wall']:.1f} ({s['nk_periods']}) | {s['bf_wall']:.1f} ({s['bf_revolutions']}"
                     f"{'' if s['bf_reached'] else ', not reached'}) | **{s['bf_wall'] / s['np_wall']:.1f}x** |")
    lines += ["", "Newton-Picard residual histories [C]: " + "; ".join(
        f"{s['speed_rpm']:.0f} rpm: " + ", ".join(f"{v:.1e}" for v in s["np_residuals"]) for s in r["single"])
        + ". Targets: >= 5x at 6000 rpm, >= 20x at 0.95 of the onset."]
    a = r.get("arnoldi")
    if a:
        lines += ["", f"### Monodromy spectrum at 6000 rpm (Arnoldi, {a['periods']} periods, {a['wall']:.0f} s)", "",
                  "| multiplier | \\|mu\\| | rotor share |", "|---|---|---|"]
        for m, mod, sh in zip(a["multipliers"], a["modulus"], a["rotor_share"]):
            lines.append(f"| {m[0]:+.5f} {m[1]:+.5f}i | {mod:.2e} | {sh:.2f} |")
        lines += ["", "Ritz values of the shooting: " + ", ".join(f"{m[0]:+.5f} {m[1]:+.5f}i" for m in a["ritz"]) + "."]
    lines += ["", "Reproduce: `transient bench periodic" + (" --quick" if c["quick"] else "") + "`."]
    return "\n".join(lines)


def main(out, quick: bool = False) -> str:
    """``transient bench periodic``: the runs above, raw numbers in ``out/bench_periodic.json``."""
    result = run(quick=quick)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_periodic.json").write_text(json.dumps(result, indent=1, default=float))
    return "## Journal periodic orbits (Rho & Kim): shooting and continuation vs settling\n\n" + markdown(result)
