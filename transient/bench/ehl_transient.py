"""EHL transients side by side: IDA on the penalty form against BDF2 on the film-content form.

In one run, from the dry contact to the steady film over 40 transit times:

1. The line contact (the paper's extent, -5 b .. 2.5 b; 101 and 201 nodes): CPU time, steps, Jacobians or
   factorisations, and the error of ``h_c`` and ``h_min`` over 41 outputs against a tight reference of the
   film-content form (BDF2 at rtol 1e-8; the penalty form differs from it by ``O(1/GAMMA)``) and against each
   method's own tight reference (IDA at rtol 1e-10), at rtol 1e-4, 1e-5, 1e-6; the long-time limit against
   ``steady()``.
2. The levers of BDF2's step solve (``transient.models.roller.line_step``), switched on one by one at rtol 1e-5:
   the full semismooth Newton per step (new factorisations every step) with BLAS threads, on one BLAS thread, with
   the GMRES preconditioner of its Newton steps kept across steps (above 400 unknowns; the default), and simplified
   Newton (the Schur matrix's LU kept across iterations and steps, ``FrozenSchur``).
3. The tapered roller at the paper's loading on the paper case's test grid (40 x 25 clustered): from the penalty
   form's steady film to the film-content one, and a load step, BDF2 (within a wall-clock budget) and IDA.

``main(out, quick)`` writes ``ehl_transient.json`` into ``out`` and returns the markdown section.
"""

from __future__ import annotations

import contextlib
import json
import time
import warnings
from functools import partial
from pathlib import Path

import numpy as np

import transient.models.roller.line_step as line_step_module
from transient.models.roller import LineContact, RollerContact, TaperedRoller
from transient.models.roller.line_contact import StarvedInletWarning
from transient.models.roller.line_step import LineFilmStep
from transient.models.roller.transient import GAMMA
from transient.solvers.settings import Integration, LongRun

TITLE = "EHL transients: IDA on the penalty form vs BDF2 on the film content (line contact, tapered roller)"
R, E, W = 0.01, 220e9, 3.1e4
RTOLS = (1e-4, 1e-5, 1e-6)
#: the film-content form's tight reference (BDF2, second order: its steps grow as rtol^-1/2)
REFERENCE_RTOL = 1e-8
#: the first output (of 41 over 40 transits) of the late error: after the inlet has filled
LATE = 5
#: wall-clock budget [s] of each BDF2 run of the roller (its steps are cut where nodes switch, see the section)
ROLLER_BUDGET = 240.0


def _line(n):
    return LineContact(R, W, 1.0, 0.022, 2500 / E, E, grid=n, domain=(-5.0, 2.5))


def _run(c, method, rtol, n_out=41, reuse="preconditioner", one_thread=True, t_end=40.0, **kw):
    """CPU seconds and the transient; ``reuse``/``one_thread``: the BDF2 levers (line contact only)."""
    saved = line_step_module.LineFilmStep, line_step_module.threadpool_limits
    line_step_module.LineFilmStep = partial(LineFilmStep, reuse=reuse)
    if not one_thread:
        line_step_module.threadpool_limits = lambda **_: contextlib.nullcontext()
    try:
        c0 = time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)  # the penalty form (ida) is compared on purpose
            r = c.transient(t_end=t_end * c.time_scale, n_out=n_out, integration=Integration(method=method, rtol=rtol),
                            **kw)
        return time.process_time() - c0, r
    finally:
        line_step_module.LineFilmStep, line_step_module.threadpool_limits = saved


def _error(r, ref, first=0):
    """The largest relative deviation of h_c and h_min from ``ref``'s over the outputs from ``first`` on."""
    return float(max(np.max(np.abs(r.h_central[first:] / ref.h_central[first:] - 1.0)),
                     np.max(np.abs(r.h_min[first:] / ref.h_min[first:] - 1.0))))


def _row(label, cpu, r, ref, own, steady):
    return dict(case=label, cpu_s=cpu, steps=int(r.n_steps), jacobians=int(r.n_jacobians), success=bool(r.success),
                error=_error(r, ref), late_error=_error(r, ref, LATE), own_error=_error(r, own), limit=abs(r.h_central[-1] / steady.h_central - 1.0))


def line_case(n: int, levers: bool) -> dict:
    c = _line(n)
    steady = c.steady()
    _run(c, "bdf2", 1e-4, n_out=3, t_end=2.0)  # compile and warm every kernel of both methods
    _run(c, "ida", 1e-4, n_out=3, t_end=2.0)
    ref_cpu, ref = _run(c, "bdf2", REFERENCE_RTOL, start="dry", max_steps=10 ** 6)
    ida_ref_cpu, ida_ref = _run(c, "ida", 1e-10, start="dry")
    rows = []
    for rtol in RTOLS:
        for method in ("ida", "bdf2"):
            cpu, r = _run(c, method, rtol, start="dry")
            rows.append(dict(_row(method, cpu, r, ref, ida_ref if method == "ida" else ref, steady), rtol=rtol))
    lever_rows = []
    if levers:
        for label, kw in (("full Newton per step, new factorisations, BLAS threads", dict(reuse="none", one_thread=False)),
                          ("full Newton per step, new factorisations, one BLAS thread", dict(reuse="none")),
                          ("full Newton, GMRES preconditioner (LU) kept across steps, one BLAS thread", {}),
                          ("simplified Newton (Schur LU kept across steps), one BLAS thread", dict(reuse="simplified"))):
            cpu, r = _run(c, "bdf2", 1e-5, start="dry", **kw)
            lever_rows.append(dict(_row(label, cpu, r, ref, ref, steady), newton=int(r.stats.n_rhs)))
    return dict(nodes=n, reference_cpu_s=ref_cpu, ida_reference_cpu_s=ida_ref_cpu, reference_steps=int(ref.n_steps),
                rows=rows, levers=lever_rows)


def roller_case(quick: bool) -> dict:
    """The tapered roller (paper's loading, 40 x 25 clustered): from the penalty form's steady film (IDA's limit)
    to the film-content one over 5 transits (BDF2), and a load step to 1.5x over 0.1 transit, each method within
    a wall-clock budget (the time reached says how far it got)."""
    ro = TaperedRoller(R, 10.0, 2 * R, 0.5 * R, 0.2 * R, 0.002)
    c = RollerContact.from_dimensionless(U=1e-11, G=2500.0, W=2e-5 * 0.4 / 1.4, modulus=E, roller=ro,
                                         grid=("clustered", 32, 25) if quick else ("clustered", 40, 25))
    c.dry()
    c0 = time.process_time()
    content = c.steady(method="fbns", tol=1e-10)
    steady_cpu = time.process_time() - c0
    penalty = c.steady(penalty=GAMMA, tol=1e-10)
    out = dict(grid=list(c.grid_spec[1:]), unknowns=int(c.grid.n + 1), steady_cpu_s=steady_cpu, rows=[],
               budget_s=ROLLER_BUDGET)
    ts = c.time_scale
    cases = (("from the penalty film, 5 transits", dict(t_end=5 * ts, start=penalty, n_out=6)),
             ("load step to 1.5x over 0.1 transit, 2 transits",
              dict(t_end=2 * ts, start=content, n_out=21, load=1.5 * c.load, ramp_time=0.1 * ts)))
    for label, kw in cases:
        for method in ("bdf2", "ida"):
            c0 = time.process_time()
            extra = dict(long_run=LongRun(time_budget=ROLLER_BUDGET)) if method == "bdf2" else {}
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", DeprecationWarning)  # the penalty form (ida) is compared on purpose
                r = c.transient(integration=Integration(method=method, rtol=1e-5), **kw, **extra)
            out["rows"].append(dict(case=label, method=method, cpu_s=time.process_time() - c0, steps=int(r.n_steps),
                                    jacobians=int(r.n_jacobians), reached=r.final_time / ts,
                                    t_end=kw["t_end"] / ts, success=bool(r.success),
                                    vs_content=abs(r.h_min[-1] / content.h_min - 1.0),
                                    vs_penalty=abs(r.h_min[-1] / penalty.h_min - 1.0)))
    return out


def main(out, quick: bool = False) -> str:
    out = Path(out)
    t_all = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StarvedInletWarning)  # the paper's short inlet, on purpose
        lines_ = [line_case(101, levers=True)] + ([] if quick else [line_case(201, levers=True)])
        roller = roller_case(quick)
    data = dict(line=lines_, roller=roller, total_s=time.perf_counter() - t_all)
    (out / "ehl_transient.json").write_text(json.dumps(data, indent=1, default=float))
    return _markdown(data, quick)


def _markdown(data, quick) -> str:
    lines = ["## EHL transients: IDA on the penalty form, BDF2 on the film content", "",
             f"`transient bench ehl_transient`{' --quick' if quick else ''}; CPU seconds (`time.process_time`) on 2 "
             "cores shared with other work: the ratios within one run are the numbers. From the dry contact (half the "
             "Dowson-Toyoda film) over 40 transit times b/u, 41 outputs. error: the largest relative deviation of h_c "
             "and h_min over the outputs from the film-content form's tight reference (BDF2 at rtol 1e-8); own: from "
             "the method's own tight reference (IDA at rtol 1e-10); limit: the last h_c against `steady()` (the "
             "penalty form's limit differs from it by O(1/GAMMA)).", ""]
    for lc in data["line"]:
        lines += [f"### Line contact, {lc['nodes']} nodes (paper's extent -5 b .. 2.5 b)", "",
                  "| rtol | method | CPU [s] | steps | Jacobians / LUs | error | error from 5 b/u on | own | limit vs steady() | CPU / IDA |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        ida = {r["rtol"]: r["cpu_s"] for r in lc["rows"] if r["case"] == "ida"}
        for r in lc["rows"]:
            lines.append(f"| {r['rtol']:.0e} | {r['case']} | {r['cpu_s']:.2f} | {r['steps']} | {r['jacobians']} | "
                         f"{r['error']:.1e} | {r['late_error']:.1e} | {r['own_error']:.1e} | {r['limit']:.1e} | {r['cpu_s'] / ida[r['rtol']]:.2f} |")
        if lc["levers"]:
            base = lc["levers"][0]["cpu_s"]
            lines += ["", f"BDF2's levers at rtol 1e-5 ({lc['nodes']} nodes), switched on one by one:", "",
                      "| step solve | CPU [s] | speed-up | steps | Newton iterations | LUs | error |", "|---|---|---|---|---|---|---|"]
            for r in lc["levers"]:
                lines.append(f"| {r['case']} | {r['cpu_s']:.2f} | {base / r['cpu_s']:.1f}x | {r['steps']} | "
                             f"{r['newton']} | {r['jacobians']} | {r['error']:.1e} |")
        lines.append("")
    ro = data.get("roller")
    if not ro:
        return "\n".join(lines + [f"Total bench time {data['total_s']:.0f} s."])
    lines += [f"### Tapered roller, the paper's loading, clustered {ro['grid'][0]} x {ro['grid'][1]} "
              f"({ro['unknowns']} pressure unknowns)", "",
              f"rtol 1e-5; the steady film-content solve takes {ro['steady_cpu_s']:.1f} s CPU. BDF2 runs within a "
              f"wall-clock budget of {ro['budget_s']:.0f} s; reached: the time it got to (transits c/u). h_min at the "
              "end against the steady film-content film (`steady(method=\"fbns\")`) and the penalty form's "
              "(`steady(penalty=GAMMA)`).", "",
              "| case | method | CPU [s] | steps | LUs / Jacobians | reached / asked [c/u] | h_min vs content | "
              "h_min vs penalty |", "|---|---|---|---|---|---|---|---|"]
    for r in ro["rows"]:
        lines.append(f"| {r['case']} | {r['method']} | {r['cpu_s']:.1f} | {r['steps']} | {r['jacobians']} | "
                     f"{r['reached']:.3g} / {r['t_end']:g} | {r['vs_content']:.1e} | {r['vs_penalty']:.1e} |")
    lines += ["", f"Total bench time {data['total_s']:.0f} s."]
    return "\n".join(lines)
