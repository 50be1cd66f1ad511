"""Thrust-pad descent benchmark (Lee & Rhim): ``run(quick=False) -> markdown``.

Work-precision of the rough-pad squeeze descent (massless force balance, Gaussian roughness, steel
contact) on the separable path -- SUNDIALS CVODE and IDA vs scipy BDF / LSODA vs fixed-step RK4 --
against a tight CVODE reference (rtol 1e-11), one run each; then the full 2-D path (the DAE in IDA
with the analytic sparse Jacobian, and the pressure eliminated per right-hand side in CVODE) against
the separable path at the same tolerance, for two grids.
"""

from __future__ import annotations

import platform
import sys
import time

import numpy as np

from transient.models.pad.pad import ThrustPad
from transient.solvers.settings import Integration

SIG = 2e-6
L = 0.02
MU = 0.03


def _case(grid=(40, 40)):
    pad = ThrustPad(L, L, MU, surface=SIG, grid=grid)
    return pad, 1.5e6 * pad.area


def _err(r, ref, sig):
    return float(np.max(np.abs(r.h0 - ref.h0)) / sig)


def run(quick: bool = False) -> str:
    """Run the benchmark and return its markdown section."""
    pad, W = _case()
    kw = dict(load=W, h0_start=5 * SIG, t_end=0.5, n_out=51)
    ref = pad.descent(integration=Integration(method="cvode", rtol=1e-11, atol=1e-13), **kw)
    rows = []
    tols = (1e-4, 1e-6) if quick else (1e-4, 1e-6, 1e-8)
    for method in ("cvode", "ida", "bdf", "lsoda"):
        for rt in tols:
            r = pad.descent(integration=Integration(method=method, rtol=rt, atol=rt * 1e-2), **kw)
            rows.append((method, f"rtol {rt:g}", r.stats.wall_time, r.stats.n_steps, r.stats.n_rhs, _err(r, ref, SIG)))
    for dt in ((4e-3, 1e-3) if quick else (8e-3, 4e-3, 2e-3, 1e-3)):
        r = pad.descent(integration=Integration(method="rk4", dt=dt), **kw)
        rows.append(("rk4", f"dt {dt * 1e3:g} ms", r.stats.wall_time, r.stats.n_steps, r.stats.n_rhs, _err(r, ref, SIG)))
    base = {rt: w for (m, t, w, *_), rt in zip(rows, list(tols) * 4) if m == "cvode"}
    lines = [
        "## Thrust pad squeeze descent (Lee & Rhim)",
        "",
        f"Machine: {platform.processor() or platform.machine()}, Python {sys.version.split()[0]}; "
        f"`transient bench pad`. Pad 20 x 20 mm, mu = 0.03 Pa s, Gaussian Rq = 2 um, steel contact, "
        f"W = {W:g} N, h0: 5 Rq -> equilibrium {pad.equilibrium(W) / SIG:.3f} Rq over 0.5 s, massless; "
        "error = max |h0 - h0_ref| / Rq at 51 outputs, reference CVODE rtol 1e-11. One run each.",
        "",
        "### Separable path (scalar ODE)",
        "",
        "| method | setting | wall [ms] | steps | rhs calls | error [Rq] | wall / CVODE same rtol |",
        "|---|---|---|---|---|---|---|",
    ]
    for m, s, w, ns, nr, e in rows:
        ratio = ""
        if s.startswith("rtol"):
            rt = float(s.split()[1])
            ratio = f"{w / base[rt]:.2f}" if rt in base else ""
        lines.append(f"| {m} | {s} | {w * 1e3:.1f} | {ns} | {nr} | {e:.2e} | {ratio} |")
    lines += ["", "### Full 2-D path vs separable (rtol 1e-7, atol 1e-9)", "",
              "| grid | path / method | wall [s] | steps | Jacobians | max abs(h0 - h0_sep) / Rq | wall / separable |",
              "|---|---|---|---|---|---|---|"]
    for grid in (((20, 20),) if quick else ((20, 20), (40, 40))):
        pad, W = _case(grid)
        k2, tight = dict(kw), dict(rtol=1e-7, atol=1e-9)
        sep = pad.descent(integration=Integration(method="cvode", **tight), path="separable", **k2)
        for lab, r in (("separable / cvode", sep),
                       ("full DAE / ida (analytic sparse Jacobian)", pad.descent(integration=Integration(method="ida", **tight), path="full", **k2)),
                       ("full, p eliminated / cvode", pad.descent(integration=Integration(method="cvode", **tight), path="full", **k2))):
            lines.append(f"| {grid[0]}x{grid[1]} | {lab} | {r.stats.wall_time:.3f} | {r.stats.n_steps} | "
                         f"{r.stats.n_jac} | {_err(r, sep, SIG):.2e} | {r.stats.wall_time / sep.stats.wall_time:.1f} |")
    lines += ["", "The full/separable difference is the finite-volume discretisation error of the squeeze "
              "coefficient K(h0) (second order; 0.24 % at 40 x 40 for a square pad)."]
    return "\n".join(lines)


if __name__ == "__main__":
    t = time.perf_counter()
    print(run(quick="--quick" in sys.argv))
    print(f"\n({time.perf_counter() - t:.1f} s)")


TITLE = "thrust-pad squeeze descent work-precision: separable and full 2-D paths"


def main(out, quick: bool = False) -> str:
    """``transient bench pad`` (its section has its own heading)."""
    return run(quick=quick)
