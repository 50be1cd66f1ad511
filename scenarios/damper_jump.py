"""The jump of a rotor on a squeeze-film damper: both stable branches of its unbalance response, the folds, the
Floquet multipliers, and speed ramps that jump.

    transient run scenarios/damper_jump.py [--quick] [--out DIR]

A rigid rotor of 20 kg on one squeeze-film damper (D 0.1 m, L 10 mm, c 100 um, 0.01 Pa s, fed through its open ends
at 5 kPa: a cavitated film) with a weak centring spring (2e6 N/m: 3020 rpm on the spring alone), an unbalance of
0.3 clearances (6e-4 kg m), no gravity. The cavitated film's radial force stiffens with the orbit: the response
bends to high speed and folds over. The circular orbits (each film steady in the whirling frame) are traced by
pseudo-arclength continuation through both folds (``RotorBearingSystem.circular_orbits``); at speeds between the
folds the whole system's shooting (``periodic_response``, BDF2 period map) started on each orbit gives its Floquet
multipliers; a run-up from the upper branch and a run-down from the lower one (BDF2, linear speed ramps) jump
where the folds are. Writes DIR/damper_jump.png and DIR/damper_jump.json.

The grid is 24 x 4 cells: its lower fold is within 0.6 % of the converged film's, but its upper fold is the coarse
grid's (the film short of 7 % of its radial force): on 48 cells round or more this rotor has no upper fold and the
run-up stays on the large orbit (``scenarios/damper_upper_fold.py``, docs/validation.md "The damper's upper fold").
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from transient import Integration, LongRun, Recording, Rotor, RotorBearingSystem, SqueezeFilmDamper
from transient.models.rotor.circular_orbits import orbits_at_speed
from transient.plots import damper as plots, save
from transient.study.scenario import JsonRecord, log, parser

OUT = "damper_jump"
C = 100e-6
DAMPER = dict(diameter=0.1, length=0.01, clearance=C, viscosity=0.01, supply_pressure=5e3, centring_stiffness=2e6)
MASS = 20.0
UNBALANCE = 0.3 * MASS * C  # [kg m]
GRID = (24, 4)
SPEED_RANGE = (4000.0, 7500.0)  # the circular orbits traced; the run-up goes 300 rpm beyond


def system(grid=GRID) -> RotorBearingSystem:
    """The rigid rotor on its damper (module docstring)."""
    d = SqueezeFilmDamper(**DAMPER, grid=grid)
    return RotorBearingSystem(Rotor(mass=MASS * np.eye(2), stiffness=np.zeros((2, 2))), {0: d},
                              unbalance=[(0, UNBALANCE, 0.0)], gravity=0.0)


def transmitted(r) -> np.ndarray:
    """|film force + centring spring force| [N] along a run."""
    x, y = r.position(0)
    k = DAMPER["centring_stiffness"]
    return np.hypot(r.bearing_force[:, 0, 0] - k * x, r.bearing_force[:, 0, 1] - k * y)


def ramp(s, start_rpm, end_rpm, start, other_eps, revolutions):
    """A linear speed ramp from the state ``start`` at ``start_rpm`` (the whole system's periodic orbit there, at
    shaft angle 0) to ``end_rpm`` over ``revolutions``: the run, its e/c every sixteenth of a revolution, the speed
    where e/c first crosses the midpoint of its start and ``other_eps`` (the other stable orbit at the start speed:
    the jump; NaN without one), the CPU time."""
    mean_rpm = 0.5 * (start_rpm + end_rpm)
    duration = revolutions * 60.0 / mean_rpm
    rate = (end_rpm - start_rpm) / duration
    t0 = time.process_time()
    r = s.run(revolutions, lambda t: start_rpm + rate * t, start=(0.0, start), reference_speed_rpm=start_rpm,
              integration=Integration(method="bdf2", rtol=1e-6), recording=Recording(outputs_per_revolution=16),
              long_run=LongRun(progress=False))
    cpu = time.process_time() - t0
    eps = r.eccentricity_ratio(0)
    mid = 0.5 * (eps[0] + other_eps)
    cross = np.flatnonzero((eps[:-1] - mid) * (eps[1:] - mid) <= 0)
    jump = float(r.speed_rpm[cross[0]]) if cross.size else float("nan")
    return r, eps, jump, cpu


def main(argv=None):
    a = parser(__doc__, OUT).parse_args(argv)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t_all = time.perf_counter()
    rec = JsonRecord(out / "damper_jump.json", dict(grid=GRID, quick=a.quick, damper=DAMPER, mass=MASS,
                                                    unbalance=UNBALANCE))
    s = system()
    t0 = time.process_time()
    curve = s.circular_orbits(SPEED_RANGE)
    log(f"  circular orbits: {curve.speed_rpm.size} points, {curve.message}; folds at "
        f"{', '.join(f'{f:.1f} rpm (e/c {e:.4f})' for f, e in zip(curve.folds_rpm, curve.fold_eccentricity))}; "
        f"{time.process_time() - t0:.0f} s CPU")
    rec.put("curve", dict(speed_rpm=curve.speed_rpm, eccentricity_ratio=curve.eccentricity_ratio[:, 0],
                          transmitted_force=curve.transmitted_force[:, 0], backward=curve.backward,
                          folds_rpm=curve.folds_rpm, fold_eccentricity=curve.fold_eccentricity))
    lower_fold, upper_fold = sorted(curve.folds_rpm)

    floquet, rows = [], []
    speeds = [0.5 * (lower_fold + upper_fold)] if a.quick else [lower_fold + f * (upper_fold - lower_fold)
                                                                for f in (0.15, 0.5, 0.85)]
    for n in speeds:
        for z in orbits_at_speed(s, curve, n):
            t0 = time.process_time()
            p = s.periodic_response(n, start=s.circular_orbit_state(n, z), integrator="bdf2")
            x, y = p.position(0)
            e = np.hypot(x, y) / C
            k = DAMPER["centring_stiffness"]
            mu = np.asarray(p.multipliers)
            row = dict(speed_rpm=n, circular_eps=float(abs(z[0])), shooting_eps=float(e.mean()),
                       eps_ripple=float(np.ptp(e)), multipliers_abs=np.abs(mu), multipliers=[str(m) for m in mu],
                       stable=bool(p.stable), converged=bool(p.converged), periods=int(p.periods),
                       cpu_s=time.process_time() - t0)
            rows.append(row)
            o = s.dampers[0].circular_orbit(e.mean(), n)
            force = abs(complex(o.radial_force - k * e.mean() * C, o.tangential_force))
            floquet.append((n, float(e.mean()), force, bool(p.stable)))
            log(f"  {n:.0f} rpm, circular orbit e/c {abs(z[0]):.4f}: shooting e/c {e.mean():.4f} (ripple "
                f"{np.ptp(e):.1e}), |mu| {', '.join(f'{v:.4f}' for v in np.abs(mu))}, "
                f"{'stable' if p.stable else 'UNSTABLE'}, converged {p.converged}, {p.periods} periods, "
                f"{row['cpu_s']:.0f} s CPU")
    rec.put("floquet", rows)

    revolutions = 80 if a.quick else 240
    ramps, jumps = {}, {}
    up_start, down_start = lower_fold + 0.6 * (upper_fold - lower_fold), lower_fold + 0.4 * (upper_fold - lower_fold)
    # the whole system's upper branch past the circular orbits' upper fold, by shooting from the last orbit
    p = s.periodic_response(up_start, start=s.circular_orbit_state(up_start, orbits_at_speed(s, curve, up_start)[0]),
                            integrator="bdf2")
    upper = []
    for n in np.arange(6600.0, SPEED_RANGE[1] + 301.0, 400.0 if a.quick else 200.0):
        p = s.periodic_response(n, start=p.state, integrator="bdf2")
        e = float(np.mean(np.hypot(*p.position(0))) / C)
        upper.append(dict(speed_rpm=float(n), shooting_eps=e, multipliers_abs=np.abs(np.asarray(p.multipliers)),
                          stable=bool(p.stable), converged=bool(p.converged)))
        floquet.append((float(n), e, float("nan"), bool(p.stable)))
        log(f"  the system's upper branch at {n:.0f} rpm: e/c {e:.4f}, |mu| {np.abs(p.multipliers[0]):.4f}, "
            f"{'stable' if p.stable else 'UNSTABLE'}, converged {p.converged}")
        if not (p.converged and e > 0.7):
            break
    rec.put("system_upper_branch", upper)
    cases = {"run-up": (up_start, SPEED_RANGE[1] + 300.0, 0, upper_fold),
             "run-down": (down_start, SPEED_RANGE[0] + 300.0, -1, lower_fold)}
    for name, (n0, n1, which, fold) in cases.items():
        found = orbits_at_speed(s, curve, n0)  # the first crossing is the upper branch, the last the lower one
        p = s.periodic_response(n0, start=s.circular_orbit_state(n0, found[which]), integrator="bdf2")
        r, eps, jump, cpu = ramp(s, n0, n1, p.state, abs(found[-1 - which][0]), revolutions)
        label = f"{name} {n0:.0f} -> {n1:.0f} rpm in {revolutions} rev (BDF2)"
        ramps[label] = (r.speed_rpm, eps, transmitted(r))
        jumps[name] = dict(start_rpm=n0, end_rpm=n1, revolutions=revolutions, fold_rpm=fold, jump_rpm=jump,
                           lag=(jump - fold) / fold, cpu_s=cpu, success=bool(r.success),
                           start_eps=float(eps[0]), end_eps=float(eps[-1]))
        log(f"  {label}: from e/c {eps[0]:.4f} to {eps[-1]:.4f}, jumps at {jump:.0f} rpm, the circular orbits' fold at "
            f"{fold:.0f} rpm ({(jump - fold) / fold:+.2%}); {cpu:.0f} s CPU, {r.message}")
    rec.put("ramps", jumps)
    title = (f"rigid rotor {MASS:g} kg on a squeeze-film damper (D 0.1 m, L 10 mm, c 100 um, 0.01 Pa s, supply 5 kPa, "
             f"centring spring 2e6 N/m), unbalance {UNBALANCE:g} kg m, grid {GRID[0]}x{GRID[1]}")
    log(f"written: {save(plots.jump(curve, ramps, floquet, title), out / 'damper_jump.png')}")
    rec.put("wall_s", time.perf_counter() - t_all)
    log(f"[damper jump] done in {time.perf_counter() - t_all:.0f} s; numbers in {out / 'damper_jump.json'}")
    return rec.data


if __name__ == "__main__":
    main(sys.argv[1:])
