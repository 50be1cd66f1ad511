"""Oil whip on one journal: what 1000 revolutions of a settled whirl cost with BDF2, and the grid a whip study needs.

Rho & Kim's bearing and rotor (m = 100 kg, W = 981 N, unbalance 0.01 C) at one speed, 1.5x the Lund threshold of
the paper's 151 x 21 grid, on several grids. On each grid: ``settle`` revolutions from 0.4 C off the equilibrium
with BDF2 at the study's settings (``STUDY``: at least ``cap`` steps per revolution, ``rtol`` on the rotor), then
the whirl over the last ``window`` revolutions: its amplitude (half the peak-to-peak of the journal's x, in C), the
largest e/C and the whirl ratio (the dominant frequency of x over the shaft's). Then, from the settled state, the
timed runs side by side in one process (CPU seconds of the process, alternating, the lower of two): the study's
settings and the orbit-size bench's (``ORBIT_SIZE``: cap 300, rtol 1e-4), each over ``timed`` revolutions and
extrapolated to 1000; and on the coarsest grid a tight run (``TIGHT``) from the same state, whose whirl amplitude
measures the study settings' time-step error. The grid error is the whirl amplitude and ratio against the finest
grid's.
"""

from __future__ import annotations


import numpy as np

from transient.bench import save_raw, timed
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "Oil whip on one journal: BDF2 cost per 1000 revolutions and the grid a whip study needs"
CLEARANCE = BEARING["clearance"]
STUDY = (100, 1e-3)  # (least steps per revolution, rtol): the whip study's settings
ORBIT_SIZE = (300, 1e-4)  # the orbit-size bench's whip settings
TIGHT = (1000, 1e-6)
OPR = 40
FULL = dict(grids=((151, 21), (101, 15), (76, 11)), settle=40, window=10, timed=2)
QUICK = dict(grids=((48, 8), (32, 6)), settle=12, window=4, timed=1)


def _orbit(grid, speed_rpm):
    return JournalOrbit(JournalBearing(**BEARING, grid=tuple(grid)), ROTOR["rotor_mass"], 0.01 * CLEARANCE,
                        ROTOR["load"], speed_rpm)


def _run(o, revs, setting, **kw):
    cap, rtol = setting
    return o.run(revs, integration=Integration(method="bdf2", rtol=rtol, steps_per_revolution=cap),
                 recording=Recording(outputs_per_revolution=OPR), long_run=LongRun(progress=False), **kw)


def whirl(r, window):
    """(amplitude [C]: half the peak-to-peak of x, the largest e/C, whirl ratio) over the last ``window``
    revolutions of ``r`` (outputs ``OPR`` per revolution)."""
    n = int(window * OPR)
    x = r.x[-n:] / CLEARANCE
    spec = np.abs(np.fft.rfft((x - x.mean()) * np.hanning(n), n=16 * n))
    ratio = float(np.argmax(spec[1:]) + 1) / (16 * n) * OPR
    return 0.5 * float(x.max() - x.min()), float(r.eccentricity_ratio[-n:].max()), ratio


def run(quick=False, log=print) -> dict:
    cfg = QUICK if quick else FULL
    grids = cfg["grids"]
    speed = 1.5 * JournalBearing(**BEARING, grid=tuple(grids[0])).stability_threshold(ROTOR["rotor_mass"], ROTOR["load"])
    rows = []
    for grid in grids:
        o = _orbit(grid, speed)
        _run(o, 0.05, STUDY)  # warm-up (a cold numba cache compiles here), not timed
        settled, _, cpu = timed(lambda: _run(o, cfg["settle"], STUDY, y0=o.perturbed_start(0.4)))
        amp, e_max, ratio = whirl(settled, cfg["window"])
        row = dict(grid=list(grid), cells=grid[0] * grid[1], settle_cpu=cpu, amplitude=amp, e_max=e_max,
                   whirl_ratio=ratio, message=settled.message)
        for _ in range(2):
            for name, setting in (("study", STUDY), ("orbit_size", ORBIT_SIZE)):
                r, _, c = timed(lambda: _run(o, cfg["timed"], setting, start=settled))
                prev = row.get(name)
                if prev is None or c < prev["cpu"]:
                    row[name] = dict(setting=list(setting), cpu=c, cpu_per_rev=c / cfg["timed"],
                                     minutes_per_1000=c / cfg["timed"] * 1000 / 60,
                                     steps_per_rev=r.stats.n_steps / cfg["timed"],
                                     jac_per_rev=r.stats.n_jac / cfg["timed"], res_per_rev=r.stats.n_rhs / cfg["timed"],
                                     amplitude=whirl(r, cfg["timed"])[0])
        log(f"[whip] {grid[0]} x {grid[1]}: amplitude {amp:.4f} C, e/C max {e_max:.4f}, whirl ratio {ratio:.4f}; "
            f"study {row['study']['minutes_per_1000']:.1f} min / 1000 rev, orbit-size settings "
            f"{row['orbit_size']['minutes_per_1000']:.1f}")
        rows.append(row)
    o = _orbit(grids[-1], speed)
    settled = _run(o, cfg["settle"], STUDY, y0=o.perturbed_start(0.4))
    tight = _run(o, cfg["timed"], TIGHT, start=settled)
    study = _run(o, cfg["timed"], STUDY, start=settled)
    a_tight, a_study = whirl(tight, cfg["timed"])[0], whirl(study, cfg["timed"])[0]
    step_error = dict(grid=list(grids[-1]), tight=list(TIGHT), amplitude_tight=a_tight, amplitude_study=a_study,
                      relative=a_study / a_tight - 1.0,
                      position_first_rev=float(np.max(np.hypot(study.x[:OPR + 1] - tight.x[:OPR + 1],
                                                               study.y[:OPR + 1] - tight.y[:OPR + 1])) / CLEARANCE))
    ref = rows[0]
    for row in rows:
        row["amplitude_error"] = row["amplitude"] / ref["amplitude"] - 1.0
        row["ratio_error"] = row["whirl_ratio"] - ref["whirl_ratio"]
    return dict(quick=quick, speed_rpm=speed, config=dict(cfg, study=STUDY, orbit_size=ORBIT_SIZE, tight=TIGHT),
                rows=rows, step_error=step_error)


def markdown(res) -> str:
    c = res["config"]
    g0 = "x".join(map(str, c["grids"][0]))
    L = [f"Rho & Kim bearing and rotor at {res['speed_rpm']:.0f} rpm (1.5x the {g0} Lund threshold), BDF2 on the "
         f"content film; each grid settled over {c['settle']} revolutions from 0.4 C off the equilibrium at the study "
         f"settings (at least {c['study'][0]} steps per revolution, rtol {c['study'][1]:g}); the whirl over the last "
         f"{c['window']}; then {c['timed']} revolutions timed from the settled state (CPU seconds of the process, the "
         f"lower of two alternating runs) at the study settings and the orbit-size bench's (cap {c['orbit_size'][0]}, "
         f"rtol {c['orbit_size'][1]:g})" + (" — **quick smoke run, not the benchmark**" if res["quick"] else "") + ".",
         "", f"| grid | whirl amplitude [C] | against {g0} | max e/C | whirl ratio | study: steps / Jacobians per rev | "
         "study: CPU s/rev | study: min per 1000 rev | cap 300, rtol 1e-4: steps per rev | CPU s/rev | min per 1000 rev |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in res["rows"]:
        s, o = r["study"], r["orbit_size"]
        L.append(f"| {r['grid'][0]} x {r['grid'][1]} | {r['amplitude']:.4f} | {100 * r['amplitude_error']:+.2f} % | "
                 f"{r['e_max']:.4f} | {r['whirl_ratio']:.4f} | {s['steps_per_rev']:.0f} / {s['jac_per_rev']:.0f} | "
                 f"{s['cpu_per_rev']:.2f} | {s['minutes_per_1000']:.1f} | {o['steps_per_rev']:.0f} | "
                 f"{o['cpu_per_rev']:.2f} | {o['minutes_per_1000']:.1f} |")
    e = res["step_error"]
    L += ["", f"Time-step error of the study settings ({e['grid'][0]} x {e['grid'][1]}, {c['timed']} revolutions from "
          f"the settled state against cap {e['tight'][0]}, rtol {e['tight'][1]:g}): whirl amplitude "
          f"{e['amplitude_study']:.5f} against {e['amplitude_tight']:.5f} C ({e['relative']:+.1e}), journal position "
          f"{e['position_first_rev']:.1e} C apart after one revolution."]
    return "\n".join(L)


def main(out, quick=False) -> str:
    res = run(quick=quick)
    save_raw(out, "whip", res)
    return f"## {TITLE}\n\n{markdown(res)}\n"
