"""Timing of rough-surface generation: ``transient bench roughness``.

Section: FFT spectral synthesis of a 1024 x 1024 surface (Gaussian,
gamma and Johnson heights, triangular and exponential ACF) and Patir's linear transformation on
1024 x 1024 and 256 x 256 surfaces, best of ``repeat`` runs, with the statistics of each surface.
"""

from __future__ import annotations

import platform
import sys

import numpy as np

from transient.bench import best_of
from transient.surfaces.roughness import RoughSurface

UM = 1e-6


def bench_surface(repeat: int = 3) -> str:
    """Time surface generation; returns the markdown table (``transient bench roughness`` writes it)."""
    cases = [
        ("fft", (1024, 1024), "triangular", dict(), (4 * UM, 4 * UM)),
        ("fft", (1024, 1024), "exponential", dict(), (8 * UM, 8 * UM)),
        ("fft", (1024, 1024), "triangular", dict(skewness=0.3, heights="gamma"), (4 * UM, 4 * UM)),
        ("fft", (1024, 1024), "triangular", dict(skewness=0.3, kurtosis=3.09), (4 * UM, 4 * UM)),
        ("linear", (1024, 1024), "triangular", dict(), (4 * UM, 4 * UM)),
        ("linear", (1024, 1024), "triangular", dict(), (16 * UM, 16 * UM)),
        ("linear", (256, 256), "triangular", dict(), (4 * UM, 4 * UM)),
        ("linear", (256, 256), "exponential", dict(), (4 * UM, 4 * UM)),
        ("linear", (1024, 1024), "triangular", dict(skewness=0.3, kurtosis=3.09), (4 * UM, 4 * UM)),
    ]
    rows = []
    for method, shape, acf, extra, cl in cases:
        def run():
            return RoughSurface.generate(shape, 1 * UM, 1 * UM, correlation_lengths=cl, acf=acf, seed=1,
                                         method=method, **extra)
        t, s = best_of(run, repeat)
        lx, ly = s.correlation_lengths
        heights = s.meta["heights"]
        rows.append(f"| {method} | {shape[0]}x{shape[1]} | {acf} | {cl[0] / UM:g} | {heights} | "
                    f"{s.meta['kernel_shape'][0]}x{s.meta['kernel_shape'][1]} | {t * 1e3:.0f} | "
                    f"{s.rq / UM:.4f} | {s.skewness:+.4f} | {s.kurtosis:.4f} | {lx / UM:.3f} | {lx / ly:.3f} |")
    lines = [
        "# Rough-surface generation timing",
        "",
        f"Machine: {platform.processor() or platform.machine()}, Python {sys.version.split()[0]}, "
        f"numpy {np.__version__}; best of {repeat}; spacing 1 um, Rq = 1 um, seed 1; "
        f"`transient bench roughness`.",
        "",
        "| method | grid | ACF | l [um] | heights | kernel | time [ms] | Rq [um] | Sk | Ku | lx meas. [um] | gamma |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
        *rows,
        "",
        "The FFT method costs two real 2-D FFTs of the grid whatever the correlation length; the",
        "linear transformation costs one FFT convolution of the (n+ny) x (m+nx) input plus the",
        "coefficient solve (1-D Newton per axis for the separable triangular ACF; Levenberg-Marquardt",
        "over all lags for the exponential ACF, which dominates for long correlation lengths).",
        "Johnson heights add the (S_U/S_B) fit, a few ms.",
        "",
    ]
    return "\n".join(lines[2:])


TITLE = "rough-surface generation time (FFT synthesis, Patir's linear transform)"


def main(out, quick: bool = False) -> str:
    """``transient bench roughness``."""
    return "## Rough-surface generation (Lee & Rhim)\n" + bench_surface(repeat=1 if quick else 3)
