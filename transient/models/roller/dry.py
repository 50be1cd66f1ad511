"""Dry (elastostatic) contact of the tapered roller: the footprint that sizes the EHL domain (Park, seed
001, after Rahnejat & Gohar 1979), and the zero-speed limit of the EHL problem.

Dimensionless (lengths by R_m, ``P = p/E'``), on a uniform grid with patch-uniform pressure::

    gap = H_rigid(X, Y) + (2/pi) iint P / r dX'dY' - delta >= 0,   P >= 0,   P gap = 0,   iint P = W

(:mod:`transient.physics.elasticity`, DC-FFT). Solved by the conjugate-gradient method of Polonsky &
Keer (*Wear* 231, 1999): CG on the contact set with the mean gap removed (the approach ``delta`` is its
Lagrange multiplier), negative pressures cut, nodes with negative gap re-entered, the load imposed by
scaling. Two passes: the whole roller length on a coarse grid, then a finer grid around the footprint.

The footprint: ``c`` the half-width at the mid-plane ``Y = 0`` and ``d`` the length (Park's Fig. 2),
the contact edges located between nodes by extrapolating ``p^2`` linearly (exact for Hertz's
elliptical edge).
"""

from __future__ import annotations

import math
import time

import numpy as np

from transient.models.ehl.dry import edge_positions, polonsky_keer
from transient.models.roller.geometry import TaperedRoller
from transient.physics.elasticity import SurfaceConvolution
from transient.results import SteadyResult, quantity, result_type


@result_type
class DryContact(SteadyResult):
    """Dry contact of the roller: pressure map on a uniform grid and the footprint."""

    time_axis = None
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa")
    p_max: float = quantity("Pa")
    x_of_p_max: float = quantity("m")
    y_of_p_max: float = quantity("m")
    half_width: float = quantity("m")
    footprint_length: float = quantity("m")
    footprint_start: float = quantity("m")
    footprint_end: float = quantity("m")
    max_half_width: float = quantity("m")
    approach: float = quantity("m")
    load: float = quantity("N")
    wall_time: float = quantity("s", 0.0)


class DrySolver:
    """Two-pass dry contact of ``roller`` under the dimensionless load ``W = w/(E' R_m^2)``."""

    def __init__(self, roller: TaperedRoller, W: float, grid=(64, 512), coarse=(40, 256)):
        self.roller = roller
        self.W = W
        self.grid = grid
        self.coarse = coarse

    def _solve_on(self, xw, ya, yb, nx, ny, p0=None):
        x = np.linspace(-xw, xw, nx)
        y = np.linspace(ya, yb, ny)
        dx, dy = x[1] - x[0], y[1] - y[0]
        g0 = self.roller.gap(x[None, :], y[:, None])
        conv = SurfaceConvolution(nx, ny, dx, dy, scale=2.0 / math.pi)
        p, delta, it, ok = polonsky_keer(g0, conv, dx * dy, self.W, p0=p0)
        return x, y, p, delta, it, ok

    def solve(self):
        """Returns ``(x, y, P, delta, iterations, converged, footprint)`` in units of R_m."""
        ro = self.roller
        yl = ro.half_length
        w_len = self.W / (2.0 * max(ro.y_d, 0.1 * yl))
        xw = 4.0 * math.sqrt(8.0 * w_len / math.pi)
        for _ in range(8):  # pass 1: whole length; widen x until the footprint fits
            x, y, p, delta, it1, ok = self._solve_on(xw, -yl, yl, self.coarse[0], self.coarse[1])
            on_x = np.any(p[:, 0] > 0) or np.any(p[:, -1] > 0)
            if not on_x:
                break
            xw *= 2.0
        if np.any(p[0] > 0) or np.any(p[-1] > 0):
            raise ValueError("the dry footprint reaches the end of the roller (edge loading): increase length, "
                             "dub_off_radius or reduce the load / tilt")
        fp = self.footprint(x, y, p)
        if fp["c"] <= 0.0:
            return x, y, p, delta, it1, ok, fp
        d = fp["y_end"] - fp["y_start"]
        ya, yb = max(fp["y_start"] - 0.06 * d, -yl), min(fp["y_end"] + 0.06 * d, yl)
        xw2 = 1.35 * fp["c_max"]
        nx, ny = self.grid
        x2, y2, p2, delta2, it2, ok2 = self._solve_on(xw2, ya, yb, nx, ny)
        return x2, y2, p2, delta2, it1 + it2, ok and ok2, self.footprint(x2, y2, p2)

    @staticmethod
    def footprint(x, y, p) -> dict:
        """c (mid-plane half-width), its maximum over Y, the Y extent of the contact, in units of R_m."""
        if y[0] < 0.0 < y[-1]:
            j = int(np.searchsorted(y, 0.0))
            w = (0.0 - y[j - 1]) / (y[j] - y[j - 1])
            mid = (1 - w) * p[j - 1] + w * p[j]
        else:
            mid = np.zeros_like(x)
        e = edge_positions(x, mid)
        c = 0.0 if e is None else 0.5 * (e[1] - e[0])
        rows = np.flatnonzero(p.max(axis=1) > 0)
        c_max = max((np.ptp(x[p[j] > 0]) * 0.5 + (x[1] - x[0]) for j in rows), default=0.0)
        ey = edge_positions(y, p.max(axis=1))
        return {"c": c, "c_max": c_max, "y_start": ey[0], "y_end": ey[1]}


def dry_contact(roller: TaperedRoller, load: float, modulus: float, grid=(64, 512)) -> DryContact:
    """Dry contact of ``roller`` pressed by ``load`` [N], reduced modulus ``modulus`` [Pa]."""
    t0 = time.perf_counter()
    rm = roller.mean_radius
    W = load / (modulus * rm * rm)
    x, y, P, delta, it, ok, fp = DrySolver(roller, W, grid=grid).solve()
    j, i = np.unravel_index(int(np.argmax(P)), P.shape)
    msg = "converged" if ok else "Polonsky-Keer CG did not reach its tolerance"
    if fp["c"] <= 0.0:
        ok, msg = False, "the contact is open at the mid-plane Y = 0 (c = 0)"
    return DryContact(x=x * rm, y=y * rm, pressure=P * modulus, p_max=float(P.max() * modulus),
                      x_of_p_max=float(x[i] * rm), y_of_p_max=float(y[j] * rm), half_width=fp["c"] * rm,
                      footprint_length=(fp["y_end"] - fp["y_start"]) * rm, footprint_start=fp["y_start"] * rm,
                      footprint_end=fp["y_end"] * rm, max_half_width=fp["c_max"] * rm, approach=delta * rm,
                      load=float(load), success=ok, message=msg, iterations=it, wall_time=time.perf_counter() - t0)
