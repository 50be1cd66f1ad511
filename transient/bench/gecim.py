"""Gecim bulk benchmark (Jang's shear-thinning bulk): what the shear-thinning bulk costs against the Newtonian one.

Side by side in one run, each pair alternating and the best of ``repeats`` kept:

* **steady**: the paper's layered case (:mod:`transient.study.layers`: eps 0.9, R/B 1, delta 0.2 h_min, layer
  viscosity 10 mu, alpha 0.1 h_min, Reynolds-condition film) with the Newtonian and the Gecim bulk
  (kappa* 0.65, mu_2/mu_1 0.57) on the same grid: wall time of ``steady_state`` and its active-set iterations;
* **orbit**: the Rho & Kim small orbit (0.01 C unbalance, 6000 rpm, Elrod film, IDA) with the two bulks at the
  same tolerance: wall time per revolution, steps and residual calls;
* **kernels**: one residual and one Jacobian evaluation of the Elrod film at a converged state (the Gecim faces
  computed on all cores, as the callers do), and the face law's cost per face.

The target is a ratio within 3 for the steady solve and the orbit; the table says whether it is met.
"""

from __future__ import annotations


import numpy as np

from transient.bench import best_of, save_raw
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params import rho_kim
from transient.physics.layered import BoundaryLayers
from transient.study import layers as paper
from transient.solvers.settings import Integration, LongRun

TITLE = "Gecim bulk: steady solve, orbit and kernel cost against the Newtonian bulk"
FULL = dict(steady_grid=(241, 40), orbit_grid=(151, 21), revolutions=1.0, rtol=1e-4, repeats=3)
QUICK = dict(steady_grid=(61, 10), orbit_grid=(48, 8), revolutions=0.25, rtol=1e-4, repeats=2)


def _paper_bearing(grid, rheology):
    C, mu = paper.BEARING["clearance"], paper.BEARING["viscosity"]
    d = paper.IMMOBILITY_DELTA * paper.H_MIN * C
    layers = BoundaryLayers(d, 10.0 * mu, paper.ALPHA * paper.H_MIN * C)
    return JournalBearing(**paper.BEARING, grid=grid, layers=layers, rheology=rheology)


def _orbit_bearing(grid, rheology):
    return JournalBearing(**rho_kim.BEARING, grid=grid, rheology=rheology)


def run(quick=False, log=print) -> dict:
    cfg = QUICK if quick else FULL
    reps = cfg["repeats"]
    out = dict(config=dict(cfg, quick=quick), steady={}, orbit={}, kernels={})
    # ---- steady ----------------------------------------------------------------------------------------------
    bearings = dict(newtonian=_paper_bearing(cfg["steady_grid"], None),
                    gecim=_paper_bearing(cfg["steady_grid"], paper.gecim_bulk()))
    for b in bearings.values():  # JIT warm-up
        b.steady_state(paper.ECCENTRICITY, paper.SPEED_RPM)
    for k in range(reps):
        for name in (("newtonian", "gecim") if k % 2 == 0 else ("gecim", "newtonian")):
            w, s = best_of(lambda: bearings[name].steady_state(paper.ECCENTRICITY, paper.SPEED_RPM), 1)
            prev = out["steady"].get(name)
            if prev is None or w < prev["wall"]:
                out["steady"][name] = dict(wall=w, iterations=s.newton_iterations, load_N=s.load)
    st = out["steady"]
    st["ratio"] = st["gecim"]["wall"] / st["newtonian"]["wall"]
    log(f"[gecim] steady {cfg['steady_grid']}: Newtonian {st['newtonian']['wall']:.3f} s "
        f"({st['newtonian']['iterations']} it), Gecim {st['gecim']['wall']:.3f} s ({st['gecim']['iterations']} it): "
        f"ratio {st['ratio']:.2f}")
    # ---- orbit -----------------------------------------------------------------------------------------------
    rpm, CL = 6000.0, rho_kim.BEARING["clearance"]
    orbits = {name: JournalOrbit(_orbit_bearing(cfg["orbit_grid"], rh), rho_kim.ROTOR["rotor_mass"], 0.01 * CL,
                                 rho_kim.ROTOR["load"], rpm)
              for name, rh in (("newtonian", None), ("gecim", paper.gecim_bulk(rho_kim.BEARING, rpm)))}
    starts = {name: o.initial_state() for name, o in orbits.items()}
    for name, o in orbits.items():
        o.run(0.02, y0=starts[name], long_run=LongRun(progress=False))
    revs, rtol = cfg["revolutions"], cfg["rtol"]
    for k in range(reps):
        for name in (("newtonian", "gecim") if k % 2 == 0 else ("gecim", "newtonian")):
            w, r = best_of(lambda: orbits[name].run(revs, integration=Integration(rtol=rtol),
                                                    long_run=LongRun(progress=False), y0=starts[name]), 1)
            prev = out["orbit"].get(name)
            if prev is None or w < prev["wall"] / revs:
                out["orbit"][name] = dict(wall=w / revs, steps=r.stats.n_steps / revs, residuals=r.stats.n_rhs / revs,
                                          jacobians=r.stats.n_jac / revs, callback=r.stats.callback_time / revs)
    ob = out["orbit"]
    ob["ratio"] = ob["gecim"]["wall"] / ob["newtonian"]["wall"]
    log(f"[gecim] orbit {cfg['orbit_grid']} rtol {rtol:g}: Newtonian {ob['newtonian']['wall']:.2f} s/rev "
        f"({ob['newtonian']['steps']:.0f} steps), Gecim {ob['gecim']['wall']:.2f} s/rev ({ob['gecim']['steps']:.0f} "
        f"steps): ratio {ob['ratio']:.2f}")
    # ---- kernels ---------------------------------------------------------------------------------------------
    for name, o in orbits.items():
        f = o.film
        u, X, Y = starts[name][:f.n], starts[name][f.n], starts[name][f.n + 1]
        data = np.empty(f.op.nnz)

        def residual():
            f.bulk.last_P[:] = np.nan  # forget the last state: every call evaluates the faces
            f.residual(u, X, Y)

        def jacobian():
            f.bulk.last_P[:] = np.nan
            f.jacobian_data(u, X, Y, data=data)

        n_calls = 20
        wr, _ = best_of(lambda: [residual() for _ in range(n_calls)], reps)
        wj, _ = best_of(lambda: [jacobian() for _ in range(n_calls)], reps)
        out["kernels"][name] = dict(residual_ms=1e3 * wr / n_calls, jacobian_ms=1e3 * wj / n_calls,
                                    faces=int(f.bulk.cells.shape[0]) if name == "gecim" else 0)
    kg = out["kernels"]["gecim"]
    kg["us_per_face"] = 1e3 * kg["residual_ms"] / kg["faces"]
    log(f"[gecim] kernels: residual {out['kernels']['newtonian']['residual_ms']:.3f} / {kg['residual_ms']:.3f} ms, "
        f"Jacobian {out['kernels']['newtonian']['jacobian_ms']:.3f} / {kg['jacobian_ms']:.3f} ms "
        f"(Newtonian / Gecim; {kg['us_per_face']:.2f} us per face on all cores)")
    return out


def markdown(res) -> str:
    c, st, ob, kn = res["config"], res["steady"], res["orbit"], res["kernels"]
    lines = [f"## {TITLE}\n",
             f"Paper case (steady, {c['steady_grid'][0]} x {c['steady_grid'][1]}, Reynolds-condition film) and Rho & Kim "
             f"small orbit ({c['orbit_grid'][0]} x {c['orbit_grid'][1]}, IDA rtol {c['rtol']:g}, "
             f"{c['revolutions']:g} revolution from the equilibrium); best of {c['repeats']} alternating runs. "
             f"Target: the Gecim bulk within 3x of the Newtonian one for the steady solve and the orbit: "
             f"{'met' if max(st['ratio'], ob['ratio']) <= 3.0 else 'NOT met'} ({st['ratio']:.2f}x, {ob['ratio']:.2f}x).\n",
             "| | Newtonian | Gecim | ratio |", "|---|---|---|---|",
             f"| steady solve [s] | {st['newtonian']['wall']:.3f} | {st['gecim']['wall']:.3f} | **{st['ratio']:.2f}** |",
             f"| active-set iterations | {st['newtonian']['iterations']} | {st['gecim']['iterations']} | |",
             f"| orbit [s/rev] | {ob['newtonian']['wall']:.3f} | {ob['gecim']['wall']:.3f} | **{ob['ratio']:.2f}** |",
             f"| orbit steps / residuals / Jacobians per rev | {ob['newtonian']['steps']:.0f} / "
             f"{ob['newtonian']['residuals']:.0f} / {ob['newtonian']['jacobians']:.0f} | {ob['gecim']['steps']:.0f} / "
             f"{ob['gecim']['residuals']:.0f} / {ob['gecim']['jacobians']:.0f} | |",
             f"| orbit callbacks [s/rev] | {ob['newtonian']['callback']:.3f} | {ob['gecim']['callback']:.3f} | "
             f"{ob['gecim']['callback'] / ob['newtonian']['callback']:.1f} |",
             f"| film residual [ms] | {kn['newtonian']['residual_ms']:.3f} | {kn['gecim']['residual_ms']:.3f} | "
             f"{kn['gecim']['residual_ms'] / kn['newtonian']['residual_ms']:.0f} |",
             f"| film Jacobian [ms] | {kn['newtonian']['jacobian_ms']:.3f} | {kn['gecim']['jacobian_ms']:.3f} | "
             f"{kn['gecim']['jacobian_ms'] / kn['newtonian']['jacobian_ms']:.0f} |",
             "", f"The Gecim face law costs {kn['gecim']['us_per_face']:.2f} us per face on all cores "
             f"({kn['gecim']['faces']} faces on the orbit grid).\n"]
    return "\n".join(lines)


def main(out, quick: bool = False) -> str:
    res = run(quick)
    save_raw(out, "gecim", res)
    return markdown(res)
