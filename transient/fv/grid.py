"""Cell-centred structured grids for the finite-volume film equations.

An :class:`Axis` is a 1-D sequence of cells given by their edges (uniform or stretched). It is either
*periodic* (the last cell's upper face is the first cell's lower face, e.g. the circumferential
coordinate of a journal bearing) or *bounded*, each end being

* ``"dirichlet"`` -- a face with a prescribed value (e.g. ambient pressure); the distance from the
  end cell's centre to that face is half the cell width;
* ``"symmetry"`` -- a symmetry plane / wall: zero normal flux (used for half domains).

A :class:`Grid2D` is the tensor product of two axes, ``x`` (first, e.g. circumferential) and ``z``
(second, e.g. axial). **Flattening order**: cell ``(i, j)`` (``i`` along x, ``j`` along z) has flat
index ``k = i + nx * j``; a flat field reshaped with ``field.reshape(nz, nx)`` is indexed ``[j, i]``.
Cells can be *prescribed* (mask + values of the unknown, e.g. an oil groove at supply pressure).

Lengths are unit-agnostic (metres, radians, or dimensionless): the model chooses and scales.
"""

from __future__ import annotations

import numpy as np

BOUNDARY_KINDS = ("dirichlet", "symmetry")


def stretched_edges(n: int, length: float, delta: float, start: float = 0.0, fine_at: float = 0.0) -> np.ndarray:
    """Smoothly stretched edges: ``x(s) = start + L [s - delta/(2 pi) (sin 2 pi (s - s0) + sin 2 pi s0)]``.

    ``s = k/n``, ``k = 0..n``. The cells are finest at the fraction ``s0 = fine_at`` of the axis and
    coarsest half a period away; the width ratio max/min is about ``(1 + delta)/(1 - delta)``. The
    mapping is smooth and periodic in its derivative, so it suits periodic axes too.
    """
    n = _check_int("n", n, 1)
    if not (np.isfinite(length) and length > 0):
        raise ValueError(f"length must be finite and > 0, got {_fmt(length)}")
    if not (0.0 <= delta < 1.0):
        raise ValueError(f"delta must be in [0, 1) (monotone mapping), got {_fmt(delta)}")
    s = np.arange(n + 1) / n
    s0 = float(fine_at)
    x = s - delta / (2 * np.pi) * (np.sin(2 * np.pi * (s - s0)) + np.sin(2 * np.pi * s0))
    return start + length * x


def _fmt(v):
    """repr of a value for an error message (numpy scalars shown as plain numbers)."""
    try:
        return repr(float(v)) if np.ndim(v) == 0 and not isinstance(v, (str, bool)) else repr(v)
    except (TypeError, ValueError):
        return repr(v)


def _check_int(name, value, minimum):
    if isinstance(value, bool) or int(value) != value:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    value = int(value)
    if value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value}")
    return value


class Axis:
    """One grid axis given by its cell edges.

    Parameters
    ----------
    edges : strictly increasing, finite, at least 2 values (n cells -> n + 1 edges).
    periodic : wrap the last cell to the first (``lower``/``upper`` must then be left at None).
    lower, upper : ``"dirichlet"`` or ``"symmetry"`` for a bounded axis (default ``"dirichlet"``).
    name : used in error messages.

    Attributes
    ----------
    n, edges, centres (= midpoints of the edges), widths, length, periodic, lower, upper,
    d_lower[i] : distance from centre i to the centre of cell i-1 (or, at i = 0, to the wrapped last
        cell if periodic, else half a cell to the lower face),
    d_upper[i] : same towards i+1 / the upper face.
    """

    def __init__(self, edges, periodic: bool = False, lower: str | None = None, upper: str | None = None,
                 name: str = "axis"):
        edges = np.asarray(edges, dtype=float)
        self.name = name
        if edges.ndim != 1 or edges.size < 2:
            raise ValueError(f"{name}.edges must be a 1-D array of at least 2 values, got shape {edges.shape}")
        if not np.all(np.isfinite(edges)):
            raise ValueError(f"{name}.edges must be finite")
        widths = np.diff(edges)
        if np.any(widths <= 0):
            k = int(np.argmin(widths))
            raise ValueError(f"{name}.edges must be strictly increasing; edges[{k + 1}] - edges[{k}] = {float(widths[k])!r} "
                             "(allowed range: > 0)")
        self.periodic = bool(periodic)
        if self.periodic:
            if lower is not None or upper is not None:
                raise ValueError(f"{name}: a periodic axis has no lower/upper boundary; got lower={lower!r}, "
                                 f"upper={upper!r} (allowed: None)")
            if edges.size - 1 < 3:
                raise ValueError(f"{name}: a periodic axis needs n >= 3 cells, got n={edges.size - 1}")
            lower = upper = "periodic"
        else:
            lower = "dirichlet" if lower is None else lower
            upper = "dirichlet" if upper is None else upper
            for side, kind in (("lower", lower), ("upper", upper)):
                if kind not in BOUNDARY_KINDS:
                    raise ValueError(f"{name}.{side} must be one of {BOUNDARY_KINDS}, got {kind!r}")
        self.lower, self.upper = lower, upper
        self.edges = edges
        self.widths = widths
        self.n = widths.size
        self.centres = 0.5 * (edges[:-1] + edges[1:])
        self.length = float(edges[-1] - edges[0])
        gaps = 0.5 * (widths[:-1] + widths[1:])  # centre-to-centre distances between neighbours
        wrap = 0.5 * (widths[-1] + widths[0])
        self.d_lower = np.empty(self.n)
        self.d_upper = np.empty(self.n)
        self.d_lower[1:] = gaps
        self.d_upper[:-1] = gaps
        self.d_lower[0] = wrap if self.periodic else 0.5 * widths[0]
        self.d_upper[-1] = wrap if self.periodic else 0.5 * widths[-1]

    @classmethod
    def uniform(cls, n: int, length: float, start: float = 0.0, centred: bool = False, periodic: bool = False,
                lower: str | None = None, upper: str | None = None, name: str = "axis") -> "Axis":
        """``n`` equal cells over ``length`` from ``start``; ``centred=True`` shifts the grid by half a
        cell so that the first cell *centre* (not edge) sits at ``start`` (e.g. theta = 0)."""
        n = _check_int(f"{name}.n", n, 1)
        if not (np.isfinite(length) and length > 0):
            raise ValueError(f"{name}.length must be finite and > 0, got {_fmt(length)}")
        edges = start + length * np.arange(n + 1) / n
        if centred:
            edges = edges - 0.5 * length / n
        return cls(edges, periodic=periodic, lower=lower, upper=upper, name=name)

    @classmethod
    def stretched(cls, n: int, length: float, delta: float, start: float = 0.0, fine_at: float = 0.0,
                  periodic: bool = False, lower: str | None = None, upper: str | None = None,
                  name: str = "axis") -> "Axis":
        """Smoothly stretched axis, see :func:`stretched_edges`."""
        return cls(stretched_edges(n, length, delta, start, fine_at), periodic=periodic, lower=lower,
                   upper=upper, name=name)

    def __repr__(self):
        return (f"Axis({self.name}: n={self.n}, [{self.edges[0]:.6g}, {self.edges[-1]:.6g}], "
                f"{'periodic' if self.periodic else self.lower + '/' + self.upper})")


class Grid2D:
    """Tensor-product grid of ``x`` (first, fastest index) and ``z`` axes.

    Flat index ``k = i + nx * j``. ``fixed`` (bool, shape (nz, nx) or (n,)) marks prescribed cells
    whose unknown is held at ``fixed_values`` (scalar or same shape): their residual is
    ``u - u_fixed`` and their neighbours see them as ordinary (Dirichlet) cells.

    Attributes: ``x, z, nx, nz, n, area`` (cell areas ``dx_i dz_j``, flat), ``xc, zc`` (flat cell-centre
    coordinates), ``fixed`` (flat bool), ``fixed_values`` (flat float, 0 where free), ``free`` (flat bool).
    """

    def __init__(self, x: Axis, z: Axis, fixed=None, fixed_values=0.0):
        if not isinstance(x, Axis) or not isinstance(z, Axis):
            raise TypeError(f"Grid2D needs two Axis objects, got {type(x).__name__} and {type(z).__name__}")
        self.x, self.z = x, z
        self.nx, self.nz = x.n, z.n
        self.n = self.nx * self.nz
        self.area = np.outer(z.widths, x.widths).ravel()
        self.xc = np.tile(x.centres, self.nz)
        self.zc = np.repeat(z.centres, self.nx)
        self.set_fixed(fixed, fixed_values)

    def set_fixed(self, fixed=None, fixed_values=0.0):
        """Mark prescribed cells (see class doc). ``fixed=None`` clears them."""
        if fixed is None:
            self.fixed = np.zeros(self.n, dtype=bool)
        else:
            f = np.asarray(fixed)
            if f.shape not in ((self.nz, self.nx), (self.n,)):
                raise ValueError(f"fixed must have shape ({self.nz}, {self.nx}) or ({self.n},), got {f.shape}")
            if f.dtype != bool:
                raise ValueError(f"fixed must be a boolean mask, got dtype {f.dtype}")
            self.fixed = f.ravel().copy()
        v = np.asarray(fixed_values, dtype=float)
        if v.ndim == 0:
            v = np.full(self.n, float(v))
        elif v.shape in ((self.nz, self.nx), (self.n,)):
            v = v.ravel().copy()
        else:
            raise ValueError(f"fixed_values must be a scalar or of shape ({self.nz}, {self.nx}) or ({self.n},), "
                             f"got {v.shape}")
        if not np.all(np.isfinite(v[self.fixed])):
            raise ValueError("fixed_values must be finite on the fixed cells")
        v[~self.fixed] = 0.0
        self.fixed_values = v
        self.free = ~self.fixed

    def index(self, i, j):
        """Flat index of cell (i along x, j along z): ``i + nx * j``."""
        return np.asarray(i) + self.nx * np.asarray(j)

    def to_2d(self, field) -> np.ndarray:
        """Flat cell field -> array of shape (nz, nx), indexed ``[j, i]`` (a view when possible)."""
        return np.asarray(field)[: self.n].reshape(self.nz, self.nx)

    def __repr__(self):
        return f"Grid2D(nx={self.nx}, nz={self.nz}, x={self.x!r}, z={self.z!r}, fixed={int(self.fixed.sum())})"


def _centre_weights(axis: Axis, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For each point: the two cells of ``axis`` whose centres bracket it and the weight of the second (linear
    interpolation); a periodic axis wraps, a bounded one holds its end cells' values beyond their centres."""
    c, index = axis.centres, np.arange(axis.n)
    if axis.periodic:
        c = np.concatenate([[c[-1] - axis.length], c, [c[0] + axis.length]])
        index = np.concatenate([[axis.n - 1], index, [0]])
        p = axis.edges[0] + np.mod(np.asarray(points, dtype=float) - axis.edges[0], axis.length)
    else:
        p = np.asarray(points, dtype=float)
    if c.size == 1:
        zero = np.zeros(p.shape, dtype=np.int64)
        return zero, zero, np.zeros(p.shape)
    p = np.clip(p, c[0], c[-1])
    k = np.clip(np.searchsorted(c, p, side="right") - 1, 0, c.size - 2)
    return index[k], index[k + 1], (p - c[k]) / (c[k + 1] - c[k])


def interpolate_cells(source: Grid2D, values, target: Grid2D) -> np.ndarray:
    """The cell field ``values`` of ``source`` at the cell centres of ``target`` (a grid of the same domain, e.g. a
    refinement): bilinear in the cell centres, a periodic axis wrapped, a bounded one held at its end cells' values
    beyond their centres. The prolongation of grid sequencing (a fine solve started from a coarse solution)."""
    v = source.to_2d(np.asarray(values, dtype=float))
    i0, i1, wx = _centre_weights(source.x, target.x.centres)
    j0, j1, wz = _centre_weights(source.z, target.z.centres)
    rows = v[:, i0] * (1.0 - wx) + v[:, i1] * wx  # (source nz, target nx)
    return (rows[j0] * (1.0 - wz)[:, None] + rows[j1] * wz[:, None]).ravel()
