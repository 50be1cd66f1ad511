"""Cost of the oil-feed geometry in the journal kernels: the same film (Rho & Kim's bearing, 151 x 21, 6000 rpm, at
its static equilibrium) with the former single full-length groove and with other feeds, side by side in one run.

The feeds only change which cells are prescribed and at what pressure (and, for a circumferential groove, the centre
distance of its edge faces), so the kernels do the same work per call; this measures it. Per feed: the ODE
right-hand side and its Jacobian (best of interleaved repeats, microseconds per call), one shaft revolution of the
orbit (IDA, rtol 1e-6) and the flows a :class:`~transient.models.journal.results.FilmState` adds
(:func:`~transient.models.journal.flows.flow_fields`). ``transient bench feeds [--quick]``.
"""

from __future__ import annotations

import time

import numpy as np

from transient.bench import best_of, save_raw, table
from transient.models.journal.bearing import JournalBearing
from transient.models.journal.feeds import CircumferentialGroove, Groove, OilHole
from transient.models.journal.flows import flow_fields
from transient.models.journal.kernels import ode_jacobian, ode_rhs
from transient.models.journal.orbit import JournalOrbit
from transient.models.journal.scales import Rotor
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Recording

TITLE = "journal kernels with the oil-feed geometry: single full-length groove against partial, multiple and round feeds"
RPM = 6000.0


def feeds(length) -> dict:
    return {"full-length groove (former)": Groove(),
            "3/4-length groove + hole": [Groove(0.0, 6.0, length=0.75 * length), OilHole(180.0, 0.2 * length)],
            "two grooves at +-90 deg": [Groove(90.0, 6.0), Groove(-90.0, 6.0)],
            "circumferential groove": CircumferentialGroove(0.1 * length)}


def _case(feed, grid):
    b = JournalBearing(**dict(BEARING, groove=feed, grid=grid))
    o = JournalOrbit(b, ROTOR["rotor_mass"], 0.01 * b.clearance, ROTOR["load"], RPM)
    f = o.film
    st = b.equilibrium(ROTOR["load"], RPM)
    y = np.concatenate([st.u, np.array(st.position) / b.clearance, [0.0, 0.0]])
    out, data = np.empty(y.size), np.empty(f.op.nnz)
    rotor = Rotor(o.kappa, o.wbar, o.ebar, f.sym)
    rhs = lambda: ode_rhs(0.0, y, out, f.switch, rotor, f.geo, f.fields, f.fv)  # noqa: E731
    jac = lambda: ode_jacobian(0.0, y, data, out, f.switch, rotor, f.geo, f.fields, f.extras, f.fv)  # noqa: E731
    flows = lambda: flow_fields(f, y[:f.n], y[f.n], y[f.n + 1])  # noqa: E731
    rhs(), jac(), flows()
    return o, rhs, jac, flows


def run(quick=False) -> dict:
    grid = (76, 11) if quick else (151, 21)
    cases = {k: _case(v, grid) for k, v in feeds(BEARING["length"]).items()}
    calls, rounds = (200, 3) if quick else (2000, 7)
    best = {k: dict(rhs_us=np.inf, jac_us=np.inf, flows_us=np.inf) for k in cases}
    for _ in range(rounds):  # interleaved: every case in every round
        for k, (_, rhs, jac, flows) in cases.items():
            for name, fn, n in (("rhs_us", rhs, calls), ("jac_us", jac, calls // 3), ("flows_us", flows, calls // 10)):
                t = time.perf_counter()
                for _ in range(n):
                    fn()
                best[k][name] = min(best[k][name], 1e6 * (time.perf_counter() - t) / n)
    revs = 0.2 if quick else 1.0
    for k, (o, *_) in cases.items():
        o.run(0.02)  # warm-up
        best[k]["orbit_s"] = best_of(lambda: o.run(revs, recording=Recording(outputs_per_revolution=20)), 1 if quick else 2)[0]
    return dict(grid=grid, revolutions=revs, quick=quick, cases=best)


def markdown(r) -> str:
    ref = r["cases"]["full-length groove (former)"]
    rows = [f"| {k} | {c['rhs_us']:.0f} ({c['rhs_us'] / ref['rhs_us']:.2f}) | {c['jac_us']:.0f} "
            f"({c['jac_us'] / ref['jac_us']:.2f}) | {c['orbit_s']:.2f} ({c['orbit_s'] / ref['orbit_s']:.2f}) | "
            f"{c['flows_us']:.0f} |" for k, c in r["cases"].items()]
    return "\n".join([f"## {TITLE}", "", f"Grid {r['grid'][0]} x {r['grid'][1]} (half), 6000 rpm, "
                      f"{r['revolutions']:g} revolution(s) of the orbit" + (" -- quick smoke run" if r["quick"] else "")
                      + "; in brackets: the ratio to the former single groove.", "",
                      *table(("feeds", "ODE rhs [us]", "ODE Jacobian [us]", "orbit [s]",
                              "flows of a FilmState [us]"), rows), ""])


def main(out, quick: bool = False) -> str:
    r = run(quick=quick)
    save_raw(out, "feeds", r)
    return markdown(r)
