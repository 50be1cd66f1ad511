"""Oil whirl and whip of a flexible rotor on two plain journal bearings: a run-up through its first critical
speed to twice the whirl onset, and the coast-down back.

    transient run scenarios/rotor_whip.py [--quick] [--out DIR] [--grid 76 11] [--revolutions 400] [--method bdf2]
                                          [--nodal] [--fresh]

The built-in flexible rotor (``Rotor.example()``: an 80 mm steel shaft of 1.2 m with a 400 mm disk at mid-span,
Timoshenko elements; stiffness-proportional structural damping 1e-5 s) on two bearings of Rho & Kim ("Noise
estimation of oil lubricated journal bearings": D = 80 mm, L/D = 0.3, C = 80 um) at its end nodes, an unbalance
at the disk (:func:`transient.bench.rotor_whip.whip_system`). The shaft runs in its 4 lowest fixed-interface modes
(``Rotor.reduce``: the bearing nodes' x, y kept, the modes at 49 and 271 Hz in both planes; ``--nodal``: its 52
nodal coordinates).

1. Static equilibrium; the whirl threshold of the linearised system with the films' own states and of the
   quasi-static bearing coefficients (Lund); the Campbell diagram (bearings as K, C).
2. The linear unbalance response against the speed, both ways.
3. A run-up from 0.3x to 2x the threshold (linear in time), then the coast-down back, each over
   ``--revolutions`` shaft revolutions, checkpointed every 10 (the same command resumes; --fresh starts over).
   Waterfalls of the disk's x at every speed show the 1x line, the whirl near 0.5x above the onset and its
   lock-in at the first critical frequency (whip); orbits at a bearing and at mid-span; the run's 1x amplitude
   beside the linear curves (a run-up is transient: its 1x amplitude is not a settled response).

Writes DIR/campbell.png, response.png, waterfall_run_up.png, waterfall_coast_down.png, orbits.png, the runs
DIR/run_up.npz, DIR/coast_down.npz (transient.load_result) and every number in DIR/rotor_whip.json.
A ROSS rotor (``Rotor.from_ross``) runs the same way; this script uses the built-in one.

The grid: a whip study needs less than the paper's 151 x 21. The same bearing on one journal at 1.5x the
threshold (``transient bench whip``, docs/bench/whip.md): the settled whirl's amplitude on 76 x 11 is 0.64 % above
151 x 21's (0.9955 against 0.9891 C), its ratio the same (0.5000), at a quarter of the CPU per revolution.

The shaft's modes and the tolerance (docs/validation.md, "The rotor's whirl revolution: where it goes, and the
shaft's modes"; ``transient bench rotor-whip``): in the nodal shaft the error test follows the ringing of its high
bending modes (252 Hz to 2.6 kHz on stiff supports, damping ratios 0.008-0.08), not the whirl. In the 4-mode shaft
the bearing journals' velocities set the step: one whirl revolution on 51 x 11 (2x the threshold, disk swing 14.5
C) takes 200 BDF2 steps at rtol 1e-3 against the nodal shaft's 512 (1,264 at rtol 1e-4), 1.8x less CPU at rtol 1e-3
and 2.4x at 1e-4 (2.3x on 76 x 11 at 1e-3; 1.6x two revolutions further into the whirl). Its error after one revolution against the nodal shaft at rtol 1e-6:
2.8e-3 C at the disk (2e-4 of its swing), 6.4e-4 C at a bearing, the disk's largest swing -6e-4 relative (the
reduction 3.7e-3 C, the time step at rtol 1e-3 against rtol 1e-6 9.6e-4 C).

Duration: the default (76 x 11, 400 revolutions each way) is checkpointed, so it can be stopped and resumed; it was
not run to the end. About three quarters of its revolutions turn above the whirl threshold (the speed is linear in
time from 0.3x to 2x it). The BDF's error test weighs each journal's x and y together by their length (a whirling
journal's x and y pass through zero, where each alone would be held to atol): a whip revolution of the 4-mode shaft
at rtol 1e-3 on 76 x 11 (e/C 0.93-0.95, the disk swinging 29 C) costs 2.0-2.3 s of CPU on a machine loaded 13-18 on
2 cores (4.4 s with x and y weighed each by itself). Measured with the latter as far as it went: the analyses and
the run-up's first 280 revolutions (to 1.7x the threshold, no whirl yet: the ramp outruns its growth) within 4 min
of CPU, whip from revolution ~300, 330 revolutions after 7.2 min of CPU; the whole run is an estimated ~20-25 min of
CPU now (~410 whirl revolutions at 2-2.5 s, the rest and the analyses ~5 min), not measured end to end. ``--quick`` (32 x 6, 30 revolutions each way) with the nodal shaft
took about 2.5 min of CPU with plain BDF2 and about 3 min with ``--method ida``.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import Integration, LongRun, Recording
from transient.analysis.rotor import synchronous_amplitude, waterfall
from transient.bench.rotor_whip import MODES, whip_system
from transient.plots import rotor as plots, save
from transient.study.scenario import JsonRecord, fresh_advice, log, parser

OUT = "rotor_whip"
OPR = 40  # outputs per revolution
GRID = (76, 11)  # the whip study's grid (module docstring: its whirl against the paper's 151 x 21)
RTOL = {"bdf2": 1e-3, "ida": 1e-5}  # the runs' tolerance by method (module docstring)


def build(grid, modes=MODES):
    """``(system, bearing node, disk node)`` (:func:`transient.bench.rotor_whip.whip_system`; ``modes`` None: the
    nodal rotor)."""
    return whip_system(grid, modes)


def ramp(n0, n1, revolutions, t0=0.0):
    """Speed linear in time from n0 to n1 [rpm] from t0 [s] over the time in which the shaft turns ``revolutions``
    times."""
    duration = 120.0 * revolutions / (n0 + n1)
    return lambda t: n0 + (n1 - n0) * min(max(t - t0, 0.0), duration) / duration


def mostly_synchronous(run, node, speeds_rpm, window_revolutions) -> np.ndarray:
    """At each of ``speeds_rpm`` along ``run``: whether the motion of the node's x there is mostly at 1x, i.e. the
    largest peak of its order spectrum between 0.1x and 0.9x (:func:`transient.plots.rotor.order_spectra`, windows
    of ``window_revolutions``) is below its 1x amplitude. Where it is not, the whirl (or a mode ringing near 1x)
    is larger than the 1x response and leaks into its least-squares 1x amplitude."""
    sp, orders, amp = plots.order_spectra(run, node, plots.fitting_window(run, window_revolutions))
    sub = (orders >= 0.1) & (orders <= 0.9)
    ok = amp[:, sub].max(axis=1) < amp[:, int(np.argmin(np.abs(orders - 1.0)))]
    return ok[np.argmin(np.abs(np.asarray(speeds_rpm)[:, None] - sp[None, :]), axis=1)]


def main(argv=None):
    ap = parser(__doc__, OUT)
    ap.add_argument("--grid", type=int, nargs=2, metavar=("NT", "NZ"), help="film grid (default 76 11; quick 32 6)")
    ap.add_argument("--revolutions", type=float, help="revolutions of the run-up and of the coast-down (400; quick 30)")
    ap.add_argument("--method", choices=("bdf2", "ida"), default="bdf2",
                    help="integrator of the runs: BDF2 on the films' content form (default) or IDA")
    ap.add_argument("--nodal", action="store_true",
                    help=f"the nodal shaft (52 coordinates) instead of its {MODES} lowest fixed-interface modes")
    ap.add_argument("--fresh", action="store_true", help="ignore existing checkpoints")
    a = ap.parse_args(argv)
    grid = tuple(a.grid) if a.grid else ((32, 6) if a.quick else GRID)
    revs = a.revolutions or (30.0 if a.quick else 400.0)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    rec = JsonRecord(out / "rotor_whip.json", dict(grid=grid, revolutions=revs, quick=a.quick, method=a.method,
                                                  modes=None if a.nodal else MODES))
    s, bnode, disk = build(grid, None if a.nodal else MODES)
    t0 = time.perf_counter()
    eq = s.equilibrium(3000.0)
    log(f"[rotor] grid {grid[0]} x {grid[1]}: bearing loads {eq.bearing_load.round(1)} N, e/C "
        f"{eq.eccentricity_ratio.round(3)} at 3000 rpm")
    th = s.stability_threshold((1000.0, 30000.0))
    th_qs = s.stability_threshold((1000.0, 30000.0), film_states=False)
    log(f"[rotor] whirl threshold: {th:.0f} rpm with the film states, {th_qs:.0f} rpm with quasi-static K, C")
    rec.put("thresholds_rpm", dict(film_states=th, quasi_static=th_qs))

    speeds = np.linspace(0.3, 2.0, 12 if a.quick else 35) * th
    eig = [s.quasi_static_eigenvalues(n) for n in speeds]
    top = np.asarray(eig[-1])[np.asarray(eig[-1]).imag > 1e-6]
    mode_hz = float(top[np.argmax(top.real)].imag / (2 * np.pi))  # the least-damped mode, where whip locks in
    log(f"[rotor] least-damped mode at {speeds[-1]:.0f} rpm: {mode_hz:.1f} Hz")
    rec.put("least_damped_mode_hz", mode_hz)
    log(f"written: {save(plots.campbell(speeds, eig, {'threshold, film states': th, 'threshold, K and C': th_qs}), out / 'campbell.png')}")
    lin = {}
    for label, film in (("linear, bearings as K, C", False), ("linear, film states", True)):
        amp = [abs(s.unbalance_response(n, film_states=film).position(disk)[0]) for n in speeds]
        lin[label] = (speeds, np.array(amp))
    rec.put("linear", {k: dict(speeds_rpm=v[0], disk_x_m=v[1]) for k, v in lin.items()})

    runs = {}
    for name, (n0, n1), start in (("run_up", (0.3 * th, 2.0 * th), None), ("coast_down", (2.0 * th, 0.3 * th), "run_up")):
        ckpt = out / f"{name}_{a.method}{'_nodal' if a.nodal else ''}_checkpoint.npz"
        if a.fresh and ckpt.exists():
            ckpt.unlink()
        log(f"[rotor] {name.replace('_', '-')} {n0:.0f} -> {n1:.0f} rpm over {revs:g} revolutions; checkpoint {ckpt}")
        t_start = runs[start].final_time if start else 0.0
        with fresh_advice():
            r = s.run(revs, ramp(n0, n1, revs, t_start), integration=Integration(method=a.method, rtol=RTOL[a.method]),
                      long_run=LongRun(checkpoint=ckpt, resume=True, chunk_revolutions=10.0, progress=True),
                      recording=Recording(outputs_per_revolution=OPR), start=runs.get(start), touch_gap=1e-3,
                      reference_speed_rpm=2.0 * th)
        r.save(out / f"{name}.npz")
        runs[name] = r
        ns, amp = synchronous_amplitude(r.t, r.position(disk)[0], r.speed_rpm, 2.0)
        window = max(6.0, revs / 25.0)  # revolutions per spectrum (a whirl at 0.25x needs a few periods)
        sp, f, spec = waterfall(r.t, r.position(disk)[0], r.speed_rpm, window)
        peak = f[np.argmax(spec[:, 1:], axis=1) + 1]
        rec.put(name, dict(message=r.message, steps=r.stats.n_steps, wall_s=r.stats.wall_time, speeds_rpm=ns,
                           disk_1x_m=amp, window_speeds_rpm=sp, window_revolutions=window, dominant_frequency_hz=peak,
                           dominant_order=peak * 60.0 / sp))
        log(f"  {r.message}; {r.stats.n_steps / revs:.0f} steps per revolution; dominant order of the disk's x "
            f"per window: {np.round(peak * 60.0 / sp, 2).tolist()}")
        title = f"{name.replace('_', '-')}: the disk's x"
        log(f"written: {save(plots.waterfall(r, disk, title, window, critical_hz=mode_hz, threshold_rpm=th), out / f'waterfall_{name}.png')}")
    r = runs["run_up"]
    pts = {}
    for k, v in runs.items():
        sp, amp = synchronous_amplitude(v.t, v.position(disk)[0], v.speed_rpm, 2.0)
        pts[f"{k.replace('_', '-')} (transient)"] = (sp, amp, mostly_synchronous(v, disk, sp, window))
    for k, (sp, amp, sync) in pts.items():
        log(f"  {k}: 1x amplitude of the disk's x {1e6 * amp.min():.1f}-{1e6 * amp.max():.1f} um; "
            f"{int((~sync).sum())} of {sync.size} windows mostly whirl (drawn open)")
        rec.put(f"{k.split(' ')[0]}_one_x", dict(speeds_rpm=sp, disk_x_m=amp, synchronous=sync))
    log(f"written: {save(plots.response_curve(lin, pts, 'the disk (x)', threshold_rpm=th), out / 'response.png')}")
    marks = [n for n in (0.8 * th, 1.2 * th, 1.9 * th) if r.speed_rpm.min() <= n <= r.speed_rpm.max()]
    log(f"written: {save(plots.orbits(r, {bnode: f'bearing (node {bnode})', disk: f'mid-span (node {disk})'}, marks), out / 'orbits.png')}")
    rec.put("wall_s", time.perf_counter() - t0)
    log(f"[rotor] done in {time.perf_counter() - t0:.0f} s; numbers in {out / 'rotor_whip.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
