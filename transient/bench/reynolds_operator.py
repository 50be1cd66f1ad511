"""Benchmark of the finite-volume Reynolds operator on the journal-bearing geometry.

Periodic theta, half bearing (symmetry plane at the mid-plane z = 0, ambient at z = L/2), Elrod-like
unknown (film content) with a smooth switch ``P = beta w softplus((u - 1)/w)``, upwind Couette, and two
dense trailing unknowns (the journal position: the arrow pattern). Times per call, median of repeats
after the JIT warm-up:

* residual -- model fields (numba) + :func:`residual_kernel` via :meth:`ReynoldsOperator.residual`;
* Jacobian -- model fields + :func:`jacobian_kernel` with the dense ``dR/dq`` columns;
* fields -- the softplus switch alone, :func:`transient.physics.cavitation.softplus_pressure` on the
  pressure-like variable ``beta (u - 1)`` (the journal model's kernel; included in both of the above).

``run()`` returns the rows, :func:`markdown` formats them; ``transient bench reynolds-operator`` writes them to docs/.
"""

from __future__ import annotations

import platform
import time

import numpy as np

from transient.physics.cavitation import softplus_pressure
from transient.fv.grid import Axis, Grid2D
from transient.fv.reynolds import ReynoldsOperator


def _journal(nt, nz, eps=0.6, L_over_D=0.5, beta=50.0, w=1e-3):
    R = 1.0
    x = Axis.uniform(nt, 2 * np.pi * R, centred=True, periodic=True, name="x")
    z = Axis.uniform(nz, L_over_D * R, lower="symmetry", upper="dirichlet", name="z")
    g = Grid2D(x, z)
    op = ReynoldsOperator(g, n_extra=2, upwind=True, boundary_P=0.0, boundary_C=1.0)
    th = g.xc / R
    h = 1.0 + eps * np.cos(th)
    dh = np.stack([np.cos(th), np.sin(th)])
    k = h**3 / 12.0
    zero = np.zeros(g.n)
    dq = (3 * k / h * dh, np.zeros((2, g.n)), 0.5 * dh, np.zeros((2, g.n)))
    rng = np.random.default_rng(0)
    u = 1.0 + 0.05 * np.sin(th) + 1e-3 * rng.standard_normal(g.n)
    return g, op, u, h, k, zero, dq, beta, w


def _median_time(fn, repeats=7, min_time=2e-3):
    fn()
    t0 = time.perf_counter()
    fn()
    single = max(time.perf_counter() - t0, 1e-7)
    inner = max(1, int(min_time / single))
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(inner):
            fn()
        samples.append((time.perf_counter() - t0) / inner)
    return float(np.median(samples))


def run(grids=((151, 21), (301, 41), (601, 81))):
    """Time residual and Jacobian on each (n_theta, n_z) grid; return the rows (see :func:`markdown`)."""
    rows = []
    for nt, nz in grids:
        g, op, u, h, k, zero, dq, beta, w = _journal(nt, nz)
        ub, wb = beta * (u - 1.0), beta * w  # P = beta w softplus((u - 1)/w) = softplus_pressure(ub, wb)
        P, dP = np.empty(g.n), np.empty(g.n)
        one = np.ones(g.n)
        cx = 0.5 * h
        out = np.empty(op.n)
        data = np.empty(op.nnz)

        def residual():
            softplus_pressure(ub, wb, P, dP)
            op.residual(u, P, u, k, k, cx, zero, out)

        def jacobian():
            softplus_pressure(ub, wb, P, dP)
            op.jacobian(P, dP, u, one, k, zero, k, zero, cx, zero, dq=dq, data=data)

        t_fields = _median_time(lambda: softplus_pressure(ub, wb, P, dP))
        t_res = _median_time(residual)
        t_jac = _median_time(jacobian)
        rows.append({"n_theta": nt, "n_z": nz, "cells": g.n, "nnz": op.nnz,
                     "fields_us": 1e6 * t_fields, "residual_us": 1e6 * t_res, "jacobian_us": 1e6 * t_jac,
                     "residual_ns_per_cell": 1e9 * t_res / g.n, "jacobian_ns_per_cell": 1e9 * t_jac / g.n})
    return rows


def markdown(rows) -> str:
    """Markdown table of :func:`run` rows."""
    lines = ["| grid (theta x z) | cells | Jacobian nnz | fields P(u) [us] | residual [us] | Jacobian [us] "
             "| residual [ns/cell] | Jacobian [ns/cell] |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['n_theta']} x {r['n_z']} | {r['cells']} | {r['nnz']} | {r['fields_us']:.1f} | "
                     f"{r['residual_us']:.1f} | "
                     f"{r['jacobian_us']:.1f} | {r['residual_ns_per_cell']:.1f} | {r['jacobian_ns_per_cell']:.1f} |")
    lines.append("")
    lines.append(f"Journal half bearing, Elrod-like smooth switch, upwind Couette, 2 dense rotor columns; "
                 f"median per call after JIT warm-up; {platform.processor() or platform.machine()}, "
                 f"numba, 1 thread.")
    return "\n".join(lines)


TITLE = "film operator: residual and Jacobian time against grid size; integrator callback overhead"


def main(out, quick: bool = False) -> str:
    """``transient bench reynolds-operator``: the operator timings and the callback overhead as one section."""
    from transient.bench import callbacks

    rows = run(grids=((151, 21), (301, 41)) if quick else ((151, 21), (301, 41), (601, 81)))
    return ("## Film operator: residual and Jacobian evaluation time against grid size\n\n" + markdown(rows)
            + "\n\n## Integrator callback overhead\n\n"
            "Wall time per right-hand-side call of a CVODE run (linear decay, 1000 states, sparse diagonal "
            "Jacobian): the numba kernel alone, scikit-sundae called directly, and through `transient.solve`.\n\n"
            + callbacks.markdown(callbacks.run()))
