"""What a revolution of mixed lubrication costs: ``transient bench mixed``.

On one grid and with each stepper (IDA, universal; BDF2, content), CPU seconds of one revolution of a settled
unbalance whirl (the lower of two, alternating, in one process), for three orbits:

* ``smooth``: Rho & Kim's smooth bearing and rotor (100 kg, 981 N, unbalance 0.01 C) at 3000 rpm;
* ``rough, no contact``: the same orbit on the rough bearing (sigma 1 um, the Stribeck scenario's surfaces): h_min
  is 18 sigma, the asperities carry nothing: the pure cost of the average flow kernels;
* ``mixed, 200 rpm`` and ``mixed, 60 rpm``: the rough bearing under 5 kN with a 500 kg rotor (unbalance 20 um)
  in the mixed regime; the table gives the asperities' share of the load and h_min / sigma on the grid run (on
  24 x 4 at 60 rpm h_min is 0.42 sigma, below the flow factor fits' floor, 0.5 sigma at gamma 1).

The ratios mixed / smooth are the numbers the target (at most 2) is about; rough / smooth the kernels' overhead.
"""

from __future__ import annotations

import json
import time
import warnings
from pathlib import Path

from transient import JournalBearing, JournalOrbit, Roughness, steel_asperity_contact
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "Mixed lubrication: a revolution in contact against a smooth one (same grid, same stepper)"
SIGMA = 1e-6
METHODS = ("ida", "bdf2")


def orbits(grid) -> dict:
    """The three orbits of the module docstring."""
    r = Roughness(steel_asperity_contact(SIGMA), gamma=1.0, boundary_friction=0.12, journal_variance_share=0.8)
    smooth = JournalBearing(**BEARING, grid=grid)
    rough = JournalBearing(**BEARING, grid=grid, roughness=r)
    rk = dict(rotor_mass=ROTOR["rotor_mass"], unbalance=0.01 * BEARING["clearance"], load=ROTOR["load"],
              speed_rpm=3000.0)
    return {"smooth": JournalOrbit(smooth, **rk), "rough, no contact": JournalOrbit(rough, **rk),
            "mixed, 200 rpm": JournalOrbit(rough, 500.0, 20e-6, 5000.0, 200.0),
            "mixed, 60 rpm": JournalOrbit(rough, 500.0, 20e-6, 5000.0, 60.0)}


def _rev(o, method, start):
    return o.run(1.0, start=start, integration=Integration(method=method),
                 recording=Recording(outputs_per_revolution=20), long_run=LongRun(progress=False))


def _contact_share(o, r) -> float:
    """The asperities' share of the load at the end of the run ``r`` of the orbit ``o``."""
    if o.rough is None:
        return 0.0
    n, y = o.film.n, r.final_state
    return float(abs(o.film.contact_force(y[n], y[n + 1])[0]) * o.film.force_scale / o.load)


def main(out, quick: bool = False) -> str:
    """``transient bench mixed``."""
    grid = (24, 4) if quick else (48, 8)
    rows, raw = [], {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        cases = orbits(grid)
        for method in METHODS:
            settled = {k: _rev(o, method, None) for k, o in cases.items()}  # settle (and compile)
            best = {k: float("inf") for k in cases}
            last = {}
            for _ in range(2):
                for k, o in cases.items():
                    c0 = time.process_time()
                    last[k] = _rev(o, method, settled[k])
                    best[k] = min(best[k], time.process_time() - c0)
            for k, o in cases.items():
                r = last[k]
                share = _contact_share(o, r)
                raw[f"{method} {k}"] = dict(cpu_s=best[k], steps=int(r.stats.n_steps), jacobians=int(r.stats.n_jac),
                                            contact_share=share, success=bool(r.success),
                                            h_min_over_sigma=float((1 - r.eccentricity_ratio.max()) *
                                                                   BEARING["clearance"] / SIGMA))
                rows.append(f"| {method} | {k} | {o.speed_rpm:g} | {100 * share:.0f} % | "
                            f"{raw[f'{method} {k}']['h_min_over_sigma']:.2f} | {r.stats.n_steps} | {r.stats.n_jac} | "
                            f"{best[k]:.3f} | {best[k] / best['smooth']:.2f} |")
    Path(out).mkdir(parents=True, exist_ok=True)
    (Path(out) / "mixed.json").write_text(json.dumps(dict(grid=grid, runs=raw), indent=1))
    lines = [f"## {TITLE}", "",
             f"Grid {grid[0]} x {grid[1]}; one revolution of a settled whirl, CPU seconds (the lower of two, "
             "alternating in one process), default tolerances (IDA rtol 1e-6; BDF2 rtol 1e-6, at least 550 steps per "
             "revolution); `transient bench mixed`. Orbits: the module docstring of `transient.bench.mixed`.", "",
             "| stepper | orbit | speed [rpm] | asperity share of the load | h_min / sigma | steps | Jacobians | "
             "CPU [s] | / smooth |", "|---|---|---|---|---|---|---|---|---|", *rows, ""]
    return "\n".join(lines)
