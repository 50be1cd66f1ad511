"""Rotor on journal bearings: the cost per revolution of two transient films against one, and a run-up.

Rho & Kim's bearing (151 x 21 cells; ``--quick``: 48 x 8) at 6000 rpm, every run from the static equilibrium
with IDA (sparse SuperLU on the system's block-arrow pattern) at the same tolerances, side by side in one run
(the cases alternate, twice, and each keeps its lower CPU time):

* **orbit, 1 bearing**: :class:`~transient.models.journal.JournalOrbit` (100 kg, 981 N, unbalance 0.01 C);
* **system, 1 bearing**: the same rotor as a one-node :class:`~transient.models.rotor.Rotor` on one bearing;
* **rigid rotor, 2 bearings**: a 200 kg rigid rotor (:meth:`~transient.models.rotor.Rotor.rigid`) on two of the
  bearings, each carrying 981 N with unbalance 0.01 C at each;
* **Jeffcott rotor, 2 bearings**: a Jeffcott rotor (:meth:`~transient.models.rotor.Rotor.jeffcott`: 190 kg disk,
  5 kg journals, shaft springs 4e7 N/m) on two of the bearings;

and a run-up of the flexible rotor from 3000 to 9000 rpm (total wall time). Memory: the states, the stored
entries of the Jacobian and the model's own memory estimate.

**The run's default method against IDA** (``RotorBearingSystem.run`` without integration settings chooses by the
films, :data:`~transient.models.rotor.system.DEFAULT_METHOD`): each system case and the run-up with IDA at rtol
1e-6, the default at rtol 1e-6 and 1e-7, interleaved in the same repetitions, each run's error the largest distance
of a node from IDA at rtol 1e-9 over the outputs [C]; so the default is judged at equal error.
"""

from __future__ import annotations


import numpy as np

from transient.bench import save_raw, table, timed
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "Rotor on journal bearings: two transient films against one, per revolution, and a run-up"
FULL = dict(grid=(151, 21), revolutions=2, runup_revolutions=40, rtol=1e-6, atol=1e-9)
QUICK = dict(grid=(48, 8), revolutions=1, runup_revolutions=6, rtol=1e-6, atol=1e-9)
#: the reference of the method comparison: IDA at these tolerances
REFERENCE = Integration(method="ida", rtol=1e-9, atol=1e-12)
SPEED = 6000.0
G = ROTOR["load"] / ROTOR["rotor_mass"]


def cases(grid):
    """The four candidates: name -> (callable running ``revolutions`` revolutions, states, Jacobian entries)."""
    b = JournalBearing(**BEARING, grid=tuple(grid))
    m, e = ROTOR["rotor_mass"], ROTOR["unbalance"]
    orbit = JournalOrbit(b, m, e, ROTOR["load"], SPEED)
    one = RotorBearingSystem(Rotor(mass=m * np.eye(2), stiffness=np.zeros((2, 2)), nodes=[0]), {0: b},
                             unbalance=[(0, m * e, 0.0)], gravity=G)
    two = RotorBearingSystem(Rotor.rigid(2 * m, 5.0, 0.5), {0: b, 1: b}, unbalance=[(0, m * e, 0.0), (1, m * e, 0.0)],
                             gravity=G)
    flex = RotorBearingSystem(Rotor.jeffcott(4e7, 2 * m - 10.0, 5.0), {0: b, 2: b}, unbalance=[(1, 2 * m * e, 0.0)],
                              gravity=G)
    return orbit, dict(one=one, two=two, flex=flex)


def run(quick=False) -> dict:
    cfg = QUICK if quick else FULL
    revs, ig = cfg["revolutions"], Integration(rtol=cfg["rtol"], atol=cfg["atol"])
    orbit, systems = cases(cfg["grid"])
    starts = {k: s._steady(s.dae(SPEED), 1.0) for k, s in systems.items()}
    y_orbit = orbit.initial_state()
    runners = dict(orbit=lambda: orbit.run(revs, y0=y_orbit, integration=ig, long_run=LongRun(progress=False)))
    for k, s in systems.items():
        runners[k] = (lambda s=s, k=k: s.run(revs, SPEED, start=(0.0, starts[k]), integration=ig,
                                             long_run=LongRun(progress=False)))
    rows = {}
    for _ in range(2):
        for k, fn in runners.items():
            r, wall, cpu = timed(fn)
            best = rows.get(k)
            if best is None or cpu < best["cpu_per_rev"] * revs:
                rows[k] = dict(wall_per_rev=wall / revs, cpu_per_rev=cpu / revs, steps_per_rev=r.stats.n_steps / revs,
                               jac_per_rev=r.stats.n_jac / revs, res_per_rev=r.stats.n_rhs / revs, ok=bool(r.success))
    for k, s in systems.items():
        dae = s.dae(SPEED)
        rows[k].update(states=dae.n, jacobian_entries=int(dae.pattern.nnz),
                       memory_mb=(1100.0 * dae.n_film + 5500.0 * dae.n) / 1e6)
    rows["orbit"].update(states=orbit.n, jacobian_entries=int(orbit.film.op.nnz),
                         memory_mb=sum(orbit.memory_estimate(revs).values()) / 1e6)
    flex = systems["flex"]
    runup = lambda t: 3000.0 + 6000.0 * t / t_up  # noqa: E731
    t_up = cfg["runup_revolutions"] * 60.0 / 6000.0  # 3000 -> 9000 rpm: mean 6000 rpm
    r, wall, cpu = timed(lambda: flex.run(cfg["runup_revolutions"], runup,
                                           recording=Recording(outputs_per_revolution=20),
                                           long_run=LongRun(progress=False), integration=ig))
    base = rows["orbit"]["cpu_per_rev"]
    methods = compare_methods(systems, starts, revs, cfg, runup)
    return dict(grid=list(cfg["grid"]), revolutions=revs, quick=quick, rows=rows, methods=methods,
                ratio_two_to_one=rows["two"]["cpu_per_rev"] / rows["one"]["cpu_per_rev"],
                ratio_two_to_orbit=rows["two"]["cpu_per_rev"] / base,
                runup=dict(revolutions=cfg["runup_revolutions"], seconds=t_up, wall=wall, cpu=cpu, ok=bool(r.success),
                           steps=r.stats.n_steps, final_speed_rpm=float(r.speed_rpm[-1])))


def compare_methods(systems, starts, revs, cfg, runup) -> dict:
    """The default method against IDA (module docstring): ``{case: {run: row}}``, each row its CPU per revolution
    (the lower of two interleaved repetitions), steps, Jacobians, method and error [C] against :data:`REFERENCE`;
    the run-up's over its whole length."""
    quiet = LongRun(progress=False)
    cases = {k: (lambda s=s, k=k, **kw: s.run(revs, SPEED, start=(0.0, starts[k]), long_run=quiet, **kw), revs)
             for k, s in systems.items()}
    rec = Recording(outputs_per_revolution=20)
    cases["runup"] = (lambda **kw: systems["flex"].run(cfg["runup_revolutions"], runup, recording=rec,
                                                       long_run=quiet, **kw), cfg["runup_revolutions"])
    runs = {"IDA rtol 1e-6": dict(integration=Integration(method="ida", rtol=1e-6, atol=cfg["atol"])),
            "default": {}}
    out = {}
    for k, (fn, n_rev) in cases.items():
        ref = fn(integration=REFERENCE)
        clearance = float(np.min(ref.clearance))
        default = fn()  # the method the run chooses, for its rtol 1e-7 row
        runs["default rtol 1e-7"] = dict(integration=Integration(method=default.method, rtol=1e-7,
                                                                 atol=cfg["atol"]))
        rows = {}
        for _ in range(2):
            for name, kw in runs.items():
                r, wall, cpu = timed(lambda: fn(**kw))
                if name in rows and cpu >= rows[name]["cpu_per_rev"] * n_rev:
                    continue
                err = np.max(np.hypot(*np.moveaxis(r.displacement - ref.displacement, -1, 0))) / clearance \
                    if r.displacement.shape == ref.displacement.shape else float("nan")
                rows[name] = dict(method=r.method, cpu_per_rev=cpu / n_rev, steps_per_rev=r.stats.n_steps / n_rev,
                                  jac_per_rev=r.stats.n_jac / n_rev, error=float(err), ok=bool(r.success))
        out[k] = rows
    return out


LABELS = dict(orbit="JournalOrbit, 1 bearing", one="system: 1-node rotor, 1 bearing",
              two="system: rigid rotor, 2 bearings", flex="system: Jeffcott rotor, 2 bearings")


def markdown(res) -> str:
    g = "x".join(map(str, res["grid"]))
    lines = [f"Grid {g} per bearing, 6000 rpm, IDA rtol 1e-6, {res['revolutions']} revolution(s) from the static "
             f"equilibrium, best (CPU time) of two alternating runs{' (quick smoke run)' if res['quick'] else ''}. "
             "CPU time of the process: on the shared machine the wall time also counts the waits for a core.", "",
             *table(("case", "states", "Jacobian entries", "memory estimate [MB]", "CPU per rev [s]",
                     "wall per rev [s]", "steps per rev", "Jacobians per rev"),
                    [f"| {LABELS[k]} | {row['states']} | {row['jacobian_entries']} | {row['memory_mb']:.1f} | "
                     f"{row['cpu_per_rev']:.3g} | {row['wall_per_rev']:.3g} | {row['steps_per_rev']:.0f} | "
                     f"{row['jac_per_rev']:.0f} |" for k, row in res["rows"].items()])]
    u = res["runup"]
    lines += ["", f"Two bearings cost **{res['ratio_two_to_one']:.2f}x** one bearing per revolution (CPU) with the "
              f"same stepper (system against system; {res['ratio_two_to_orbit']:.2f}x the single-bearing JournalOrbit).",
              "", f"Run-up of the Jeffcott rotor from 3000 to 9000 rpm in {u['seconds']:.3g} s ({u['revolutions']} "
              f"revolutions): {u['cpu']:.3g} s CPU, {u['wall']:.3g} s wall, {u['steps']} steps{'' if u['ok'] else ' (FAILED)'}."]
    if "methods" in res:
        lines += ["", "The run's default method against IDA (error: the largest distance of a node from IDA at rtol "
                  "1e-9 over the outputs; CPU per revolution, the lower of two interleaved repetitions):", "",
                  *table(("case", "run", "method", "CPU per rev [s]", "steps per rev", "Jacobians per rev",
                          "error [C]"),
                         [f"| {LABELS.get(k, 'Jeffcott run-up 3000 -> 9000 rpm')} | {name} | {row['method']} | "
                          f"{row['cpu_per_rev']:.3g} | {row['steps_per_rev']:.0f} | {row['jac_per_rev']:.0f} | "
                          f"{row['error']:.2e}{'' if row['ok'] else ' (FAILED)'} |"
                          for k, rows in res["methods"].items() for name, row in rows.items()])]
    return "\n".join(lines)


def main(out, quick=False) -> str:
    res = run(quick=quick)
    save_raw(out, "rotor", res)
    return f"## {TITLE}\n\n{markdown(res)}\n"
