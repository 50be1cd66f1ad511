"""Vertex-centred tensor grids for the EHL film (Park): nodes, control volumes, clustering.

Nodes include the boundary nodes, where ``P = 0`` (paper eq. 6); the unknowns are the interior nodes.
Node ``i``'s control volume (and elastic patch, on which its pressure is uniform) runs between the
mid-points to its neighbours, so the load ``W = sum_i A_i P_i`` and the deformation integrals use the
same patches. Flat order: full node ``(I, J)`` is ``J * nx_full + I``; interior node ``(i, j)`` is
``j * nx + i`` (x fastest). A 1-D grid (line contact) has no y axis.

Non-uniform axes place their nodes by equidistribution of a density ``g(s) = 1 + sum_k w_k
sech^2((s - c_k)/d_k)``: ``int_{a}^{x_k} g = k/(n - 1) int_a^b g``, then move the nodes closest to
requested positions (e.g. ``X = 0``, ``Y = +-Y_d``) onto them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class TensorGrid:
    """Nodes ``x`` (and ``y``) including the boundary nodes, in the model's scaled length unit."""

    x: np.ndarray
    y: np.ndarray | None = None

    def __post_init__(self):
        for name, a in (("x", self.x), ("y", self.y)):
            if a is None:
                continue
            if a.ndim != 1 or a.size < 3 or not np.all(np.diff(a) > 0):
                raise ValueError(f"grid {name} must be >= 3 strictly increasing node positions")

    @property
    def two_d(self) -> bool:
        return self.y is not None

    @property
    def nx(self) -> int:
        """Interior nodes along x."""
        return self.x.size - 2

    @property
    def ny(self) -> int:
        """Interior nodes along y (1 for a line contact)."""
        return self.y.size - 2 if self.two_d else 1

    @property
    def n(self) -> int:
        """Number of unknown (interior) nodes."""
        return self.nx * self.ny

    @property
    def shape_full(self) -> tuple[int, int]:
        return (self.y.size if self.two_d else 1, self.x.size)

    @property
    def x_edges(self) -> np.ndarray:
        """Control-volume edges of the interior x nodes (``nx + 1`` values)."""
        return 0.5 * (self.x[1:] + self.x[:-1])

    @property
    def y_edges(self) -> np.ndarray:
        return 0.5 * (self.y[1:] + self.y[:-1])

    @property
    def dx(self) -> np.ndarray:
        """Control-volume widths along x of all nodes (boundary nodes: their inner half)."""
        e = np.concatenate(([self.x[0]], self.x_edges, [self.x[-1]]))
        return np.diff(e)

    @property
    def dy(self) -> np.ndarray:
        if not self.two_d:
            return np.ones(1)
        e = np.concatenate(([self.y[0]], self.y_edges, [self.y[-1]]))
        return np.diff(e)

    @property
    def area(self) -> np.ndarray:
        """Control-volume areas of the interior nodes, flat (x fastest)."""
        if not self.two_d:
            return self.dx[1:-1].copy()
        return np.outer(self.dy[1:-1], self.dx[1:-1]).ravel()

    @property
    def uniform_x(self) -> bool:
        """Equally spaced x nodes."""
        return bool(np.allclose(np.diff(self.x), self.x[1] - self.x[0], rtol=1e-9, atol=0.0))

    @property
    def uniform(self) -> bool:
        ux = self.uniform_x
        uy = (not self.two_d) or np.allclose(np.diff(self.y), self.y[1] - self.y[0], rtol=1e-9, atol=0.0)
        return bool(ux and uy)

    def interior(self, full: np.ndarray) -> np.ndarray:
        """Interior values (flat) of a full-grid field given flat or as ``(ny_full, nx_full)``."""
        f = np.asarray(full).reshape(self.shape_full)
        return (f[1:-1, 1:-1] if self.two_d else f[:, 1:-1]).ravel()

    def full(self, interior: np.ndarray, boundary: float = 0.0) -> np.ndarray:
        """Full-grid field ``(ny_full, nx_full)`` from interior values, ``boundary`` on the boundary."""
        f = np.full(self.shape_full, float(boundary))
        if self.two_d:
            f[1:-1, 1:-1] = np.asarray(interior).reshape(self.ny, self.nx)
        else:
            f[0, 1:-1] = interior
        return f


def clustered_axis(a: float, b: float, n: int, clusters=(), snap=()) -> np.ndarray:
    """``n`` nodes on ``[a, b]`` (both ends included) by equidistribution of the density
    ``1 + sum w sech^2((s - c)/d)`` over ``clusters = [(c, d, w), ...]``; nodes nearest to the points
    in ``snap`` are moved onto them."""
    if n < 3:
        raise ValueError(f"an axis needs at least 3 nodes, got {n}")
    s = np.linspace(a, b, 20001)
    g = np.ones_like(s)
    for c, d, w in clusters:
        e = np.exp(-2.0 * np.abs(s - c) / d)  # sech^2 z = 4 e^-2|z| / (1 + e^-2|z|)^2, no overflow far away
        g += w * 4.0 * e / (1.0 + e) ** 2
    cum = np.concatenate(([0.0], np.cumsum(0.5 * (g[1:] + g[:-1]) * np.diff(s))))
    x = np.interp(np.linspace(0.0, cum[-1], n), cum, s)
    x[0], x[-1] = a, b
    for p in snap:
        if a < p < b:
            k = int(np.argmin(np.abs(x[1:-1] - p))) + 1
            x[k] = p
    if not np.all(np.diff(x) > 0):
        raise ValueError("snapping the requested nodes made the axis non-monotone: use more nodes")
    return x
