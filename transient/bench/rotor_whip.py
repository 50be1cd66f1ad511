"""Oil whip of the flexible rotor against one journal: the cost of a whirl revolution side by side.

The rotor is ``scenarios/rotor_whip.py``'s (:func:`whip_system`: ``Rotor.example()`` with stiffness-proportional
structural damping, reduced to its ``MODES`` lowest fixed-interface modes, on two of Rho & Kim's bearings, an
unbalance at the disk) at twice its whirl threshold with the
film states; its disk thrown sideways from the static equilibrium (``THROW`` clearances per radian of the shaft)
and settled over ``settle`` revolutions. The journal is ``transient bench whip``'s (Rho & Kim's 100 kg rotor at 1.5x
its Lund threshold) settled over ``settle`` revolutions from 0.4 C off its equilibrium. Both at the same grid; then
``timed`` revolutions from each settled state at each setting of ``SETTINGS`` (BDF2's rtol, least steps per
revolution, the travel bound on or off, atol), CPU seconds of the process, the cases alternating, the lower of two. The
rotor's error per setting: the largest distance of the disk and of a bearing node after the timed revolutions from
the run at ``TIGHT``, in clearances.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from transient.bench import timed as cpu_timed
from transient.bench.whip import _orbit, whirl
from transient.models.journal.bearing import JournalBearing
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.params import rho_kim
from transient.solvers.settings import Integration, LongRun, Recording

TITLE = "Oil whip: a whirl revolution of the flexible rotor on two bearings against one journal's"
STRUCTURAL_DAMPING = 1e-5  # [s]: C = beta K
UNBALANCE = 1e-4  # [kg m] at the disk
THROW = 5.0  # [C per radian of the shaft]: the disk's sideways velocity at the start
OPR = 40
MODES = 4  # the shaft's fixed-interface modes kept (Rotor.reduce): the scenario's rotor
#: name -> (rtol, least steps per revolution or None: the default travel bound and 50 per revolution, atol on the
#: rotor's states [C, C per radian])
SETTINGS = {"rtol 1e-3, atol 1e-4 (the scenario's)": (1e-3, None, 1e-4), "rtol 1e-3": (1e-3, None, 1e-9),
            "rtol 1e-4": (1e-4, None, 1e-9)}
TIGHT = (1e-6, None, 1e-9)
FULL = dict(grid=(51, 11), settle=10, timed=1)
QUICK = dict(grid=(24, 4), settle=2, timed=0.5)


def whip_system(grid, modes=None):
    """``(system, bearing node, disk node)``: ``Rotor.example()`` with structural damping ``STRUCTURAL_DAMPING`` K
    (reduced to its ``modes`` lowest fixed-interface modes, :meth:`~transient.models.rotor.Rotor.reduce`, unless
    None) on two of Rho & Kim's bearings of ``grid`` at its bearing nodes, ``UNBALANCE`` at its disk."""
    ex = Rotor.example()
    rotor = Rotor(mass=ex.mass, stiffness=ex.stiffness, damping=STRUCTURAL_DAMPING * ex.stiffness,
                  gyroscopic=ex.gyroscopic, nodes=ex.nodes, dofs=ex.dofs)
    if modes is not None:
        rotor = rotor.reduce(modes, bearing_nodes=ex.bearing_nodes)
    bearing = JournalBearing(**rho_kim.BEARING, grid=tuple(grid))
    a, b = ex.bearing_nodes
    disk = ex.disk_nodes[0]
    return RotorBearingSystem(rotor, {a: bearing, b: bearing}, unbalance=[(disk, UNBALANCE, 0.0)]), a, disk


def _integration(setting):
    rtol, spr, atol = setting
    return Integration(method="bdf2", rtol=rtol, steps_per_revolution=spr, atol=atol)


def _distance(a, b, node) -> float:
    """The distance [m] of ``node`` at the ends of the runs ``a`` and ``b``."""
    (xa, ya), (xb, yb) = a.position(node), b.position(node)
    return float(np.hypot(xa[-1] - xb[-1], ya[-1] - yb[-1]))


def run(quick=False, log=print) -> dict:
    cfg = QUICK if quick else FULL
    grid, timed = cfg["grid"], cfg["timed"]
    s, bnode, disk = whip_system(grid, MODES)
    speed = 2.0 * s.stability_threshold((1000.0, 30000.0))
    dae = s.dae(speed)
    y0 = s._steady(dae, 1.0)
    y0[dae.V0:dae.P0] += THROW * s.rotor.translation(disk)[0]
    rec, lr = Recording(outputs_per_revolution=OPR), LongRun(progress=False)

    def rotor_run(revs, setting, start):
        return s.run(revs, speed, start=start, integration=_integration(setting), recording=rec, long_run=lr,
                     reference_speed_rpm=speed)

    settled_rotor = rotor_run(cfg["settle"], SETTINGS["rtol 1e-4"], (0.0, y0))
    o = _orbit(grid, 1.5 * JournalBearing(**rho_kim.BEARING, grid=(151, 21)).stability_threshold(
        rho_kim.ROTOR["rotor_mass"], rho_kim.ROTOR["load"]))
    settled_orbit = o.run(cfg["settle"], integration=_integration(SETTINGS["rtol 1e-3"]),
                          recording=rec, long_run=lr, y0=o.perturbed_start(0.4))
    L = s.length_scale
    tight = rotor_run(timed, TIGHT, settled_rotor)
    rows = {}
    for _ in range(2):
        for name, setting in SETTINGS.items():
            for case, fn in (("rotor", lambda st=setting: rotor_run(timed, st, settled_rotor)),
                             ("journal", lambda st=setting: o.run(timed, integration=_integration(st), recording=rec,
                                                                  long_run=lr, start=settled_orbit))):
                r, _, cpu = cpu_timed(fn)
                key = f"{case}|{name}"
                if key in rows and rows[key]["cpu_per_rev"] <= cpu / timed:
                    continue
                row = dict(cpu_per_rev=cpu / timed, steps_per_rev=r.stats.n_steps / timed,
                           jac_per_rev=r.stats.n_jac / timed, res_per_rev=r.stats.n_rhs / timed, ok=bool(r.success))
                if case == "rotor":
                    row.update({f"{w}_error": _distance(r, tight, node) / L
                                for w, node in (("disk", disk), ("bearing", bnode))})
                rows[key] = row
    for name in SETTINGS:
        rows[f"rotor|{name}"]["ratio"] = rows[f"rotor|{name}"]["cpu_per_rev"] / rows[f"journal|{name}"]["cpu_per_rev"]
    d = np.array(settled_rotor.position(disk))[:, -OPR:] / L
    return dict(grid=list(grid), quick=quick, speed_rpm=speed, settle=cfg["settle"], timed=timed,
                settings={k: list(v) for k, v in SETTINGS.items()}, tight=list(TIGHT), rows=rows,
                rotor_disk_swing=float(np.hypot(*d).max()),
                rotor_e_max=[float(settled_rotor.eccentricity_ratio(n)[-OPR:].max()) for n in s.bearing_nodes],
                journal_whirl=list(whirl(settled_orbit, min(cfg["settle"], 4))))


def markdown(res) -> str:
    g = f"{res['grid'][0]} x {res['grid'][1]}"
    L = [f"`Rotor.example()` as `scenarios/rotor_whip.py` builds it, at {res['speed_rpm']:.0f} rpm (2x its threshold "
         f"with the film states), settled {res['settle']} revolutions from the thrown disk (disk swing "
         f"{res['rotor_disk_swing']:.1f} C, e/C up to {max(res['rotor_e_max']):.3f}); one journal (`bench whip`'s, "
         f"whirl amplitude {res['journal_whirl'][0]:.3f} C, ratio {res['journal_whirl'][2]:.3f}) settled likewise; "
         f"both on {g}; {res['timed']:g} revolution(s) timed from each settled state, CPU seconds of the process, the "
         f"lower of two alternating runs" + (" -- **quick smoke run, not the benchmark**" if res["quick"] else "") +
         f". Rotor error: distance after the timed revolutions from the run at rtol {res['tight'][0]:g}, in C.", "",
         ("| setting | rotor: steps / Jacobians per rev | rotor CPU s/rev | journal: steps / Jacobians per rev | "
          "journal CPU s/rev | rotor / journal | rotor error at the disk / a bearing [C] |"),
         "|---|---|---|---|---|---|---|"]
    for name in res["settings"]:
        r, j = res["rows"][f"rotor|{name}"], res["rows"][f"journal|{name}"]
        L.append(f"| {name} | {r['steps_per_rev']:.0f} / {r['jac_per_rev']:.0f} | {r['cpu_per_rev']:.2f} | "
                 f"{j['steps_per_rev']:.0f} / {j['jac_per_rev']:.0f} | {j['cpu_per_rev']:.2f} | {r['ratio']:.2f}x | "
                 f"{r['disk_error']:.1e} / {r['bearing_error']:.1e} |")
    return "\n".join(L)


def main(out, quick=False) -> str:
    out = Path(out)
    res = run(quick=quick)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_rotor_whip.json").write_text(json.dumps(res, indent=1, default=float))
    return f"## {TITLE}\n\n{markdown(res)}\n"
