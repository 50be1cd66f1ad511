"""Oil feeds of a journal bearing: axial grooves (full or partial length), oil holes and a circumferential groove.

A feed is a set of grid cells held at its supply pressure (prescribed cells of the finite-volume grid,
:class:`~transient.fv.grid.Grid2D`): the film ruptures and reforms around them and they deliver the oil the
film loses through its ends. The cells of a feed are those whose centres lie inside it (a feed narrower than a
cell takes the nearest cell), so an axial groove or a hole holds its pressure at those cell centres. A
circumferential groove takes whole rows of cells and its edges are placed on the cell faces around them (the
face between a groove cell and a land cell is a half-cell from the groove cell's centre, as at a bearing end):
a bearing with a circumferential groove at the mid-plane is then exactly two bearings, one per land, on
matched grids.

Angles are from the top of the bearing (opposite the load) in the direction of rotation [deg]; axial positions
[m] from the mid-plane.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from transient.checks import ParameterTypeError, check_range


def _pressure(name, value):
    return None if value is None else check_range(name, value, "Pa", 0.0, 1e9, why="(absolute)")


@dataclass(frozen=True)
class Groove:
    """Axial oil-supply groove: centre angle [deg], angular width [deg], axial ``length`` [m] centred on the
    mid-plane (None: the whole length, open at both ends) and its own supply ``pressure`` [Pa, absolute]
    (None: the bearing's ``supply_pressure``)."""

    angle_deg: float = 0.0
    width_deg: float = 6.0
    length: float | None = None
    pressure: float | None = None

    def __post_init__(self):
        check_range("groove.angle_deg", self.angle_deg, "deg", -360.0, 360.0)
        check_range("groove.width_deg", self.width_deg, "deg", 0.0, 90.0, low_open=True)
        if self.length is not None:
            check_range("groove.length", self.length, "m", 0.0, 10.0, low_open=True)
        _pressure("groove.pressure", self.pressure)

    symmetric = True  # centred on the mid-plane

    def check(self, name, length, radius):
        """Validate against the bearing (``length`` L [m]): the groove fits inside the bearing."""
        if self.length is not None:
            check_range(f"{name}.length", self.length, "m", 0.0, length, low_open=True,
                        why=f"(at most the bearing length {length:g} m; None: the whole length)")

    def cells(self, phi, z, radius, name="groove"):
        """Mask of the cells (centres phi [rad], z [m], flat) of the groove: the column nearest its angle if it is
        narrower than a cell, the row nearest the mid-plane if it is shorter than a cell."""
        dphi = np.abs(np.angle(np.exp(1j * (phi - np.radians(self.angle_deg)))))
        across = dphi <= 0.5 * np.radians(self.width_deg) + 1e-12
        if not across.any():
            across = phi == phi[np.argmin(dphi)]  # the first nearest column
        if self.length is None:
            return across
        along = np.abs(z) <= 0.5 * self.length * (1.0 + 1e-12)
        return across & (along if along.any() else np.abs(z) == np.abs(z).min())

    def area(self, length, radius):
        """Feed area [m^2] on the bearing surface."""
        return np.radians(self.width_deg) * radius * (length if self.length is None else self.length)


@dataclass(frozen=True)
class OilHole:
    """Round oil-supply hole: centre angle [deg], ``diameter`` [m], ``axial_position`` [m] of its centre from the
    mid-plane, its own supply ``pressure`` [Pa, absolute] (None: the bearing's ``supply_pressure``)."""

    angle_deg: float = 0.0
    diameter: float = 5e-3
    axial_position: float = 0.0
    pressure: float | None = None

    def __post_init__(self):
        check_range("hole.angle_deg", self.angle_deg, "deg", -360.0, 360.0)
        check_range("hole.diameter", self.diameter, "m", 0.0, 10.0, low_open=True)
        check_range("hole.axial_position", self.axial_position, "m", -10.0, 10.0)
        _pressure("hole.pressure", self.pressure)

    @property
    def symmetric(self):
        return self.axial_position == 0.0

    def check(self, name, length, radius):
        check_range(f"{name}.diameter", self.diameter, "m", 0.0, min(length, np.pi * radius), low_open=True,
                    why="(at most the bearing length and half its circumference)")
        room = 0.5 * (length - self.diameter)
        check_range(f"{name}.axial_position", self.axial_position, "m", -room, room,
                    why=f"(the hole of diameter {self.diameter:g} m inside the bearing of length {length:g} m)")

    def cells(self, phi, z, radius, name="groove"):
        """Mask of the cells whose centres lie in the hole (the nearest cell if none does)."""
        s = radius * np.angle(np.exp(1j * (phi - np.radians(self.angle_deg))))
        r = np.hypot(s, z - self.axial_position)
        inside = r <= 0.5 * self.diameter * (1.0 + 1e-12)
        return inside if inside.any() else np.arange(r.size) == np.argmin(r)

    def area(self, length, radius):
        return 0.25 * np.pi * self.diameter ** 2


@dataclass(frozen=True)
class CircumferentialGroove:
    """Circumferential oil-supply groove all round the bearing: axial ``width`` [m], ``axial_position`` [m] of its
    centre from the mid-plane, its own supply ``pressure`` [Pa, absolute] (None: the bearing's
    ``supply_pressure``). Its edges lie on the cell faces around the rows whose centres it covers."""

    width: float = 5e-3
    axial_position: float = 0.0
    pressure: float | None = None

    def __post_init__(self):
        check_range("circumferential_groove.width", self.width, "m", 0.0, 10.0, low_open=True)
        check_range("circumferential_groove.axial_position", self.axial_position, "m", -10.0, 10.0)
        _pressure("circumferential_groove.pressure", self.pressure)

    @property
    def symmetric(self):
        return self.axial_position == 0.0

    def check(self, name, length, radius):
        check_range(f"{name}.width", self.width, "m", 0.0, length, low_open=True, high_open=True,
                    why=f"(narrower than the bearing length {length:g} m: a land on each side)")
        room = 0.5 * (length - self.width)
        check_range(f"{name}.axial_position", self.axial_position, "m", -room, room, low_open=True, high_open=True,
                    why=f"(the groove of width {self.width:g} m inside the bearing of length {length:g} m)")

    def cells(self, phi, z, radius, name="groove"):
        """Mask of the rows whose centres lie in the groove (the nearest row if none does)."""
        d = np.abs(z - self.axial_position)
        inside = d <= 0.5 * self.width * (1.0 + 1e-12)
        return inside if inside.any() else d == d.min()

    def area(self, length, radius):
        return 2.0 * np.pi * radius * self.width


FEED_TYPES = (Groove, OilHole, CircumferentialGroove)


def as_feeds(groove) -> tuple:
    """The bearing's ``groove=`` argument as a tuple of feeds (None: no feed)."""
    if groove is None:
        return ()
    feeds = (groove,) if isinstance(groove, FEED_TYPES) else groove
    if isinstance(feeds, (str, bytes)) or not hasattr(feeds, "__iter__"):
        raise ParameterTypeError(f"groove must be a Groove, OilHole, CircumferentialGroove, a sequence of them or "
                                 f"None, got {type(groove).__name__}")
    feeds = tuple(feeds)
    for k, f in enumerate(feeds):
        if not isinstance(f, FEED_TYPES):
            raise ParameterTypeError(f"groove[{k}] must be a Groove, OilHole or CircumferentialGroove, got "
                                     f"{type(f).__name__}")
    return feeds


def feed_name(feeds, k) -> str:
    return "groove" if len(feeds) == 1 else f"groove[{k}]"


def check_feeds(feeds, length, radius, supply_pressure, cavitation_pressure):
    """Each feed fits in the bearing and its pressure is at least the cavitation pressure; returns the supply
    pressure [Pa] of each feed."""
    pressures = []
    for k, f in enumerate(feeds):
        name = feed_name(feeds, k)
        f.check(name, length, radius)
        p = supply_pressure if f.pressure is None else check_range(
            f"{name}.pressure", f.pressure, "Pa", cavitation_pressure, 1e9, why="(absolute; at least "
            f"cavitation_pressure = {cavitation_pressure:g} Pa)")
        pressures.append(p)
    return np.array(pressures, dtype=float)


#: a feed narrower than this fraction of a cell is refused: the grid models it by whole cells, so at least this many
#: times too wide (a width in radians given as degrees is 57 times too narrow)
MIN_CELL_FRACTION = 0.25
#: the largest grid a bearing takes (JournalBearing's grid check), for the advice on a finer one
N_THETA_MAX, N_AXIAL_MAX = 20000, 5000


def check_resolution(feeds, labels, grid_shape, length, radius, symmetric):
    """Each feed on the bearing's grid (``grid_shape`` (n_theta, n_axial) cells over the whole circumference and the
    modelled length, the half with ``symmetric``; ``labels`` from :func:`feed_labels`): a partial groove's length, a
    hole's diameter or a circumferential groove's width less than :data:`MIN_CELL_FRACTION` of a cell is refused, and
    so is a circumferential groove that leaves no land row between it and an end (the film there would have no
    cells); an axial groove narrower than that fraction of a cell (modelled as one column, as a cell pinned at a
    pressure is meant to be) and a hole smaller than a cell (modelled as the cells whose centres it covers, or the
    nearest one) warn, naming the grid."""
    n_theta, n_axial = grid_shape
    cell_deg, cell_s = 360.0 / n_theta, 2.0 * np.pi * radius / n_theta
    cell_z = (0.5 * length if symmetric else length) / n_axial
    grid = (f"the grid of {n_theta} x {n_axial} cells ({cell_deg:.3g} deg = {cell_s:.3g} m round, {cell_z:.3g} m "
            f"along{' the half length' if symmetric else ''})")
    q = MIN_CELL_FRACTION
    for k, f in enumerate(feeds):
        name = feed_name(feeds, k)
        if isinstance(f, Groove):
            if f.width_deg < q * cell_deg:  # a groove of one column (e.g. a cell pinned at p_c) is a valid model
                warnings.warn(f"{name}.width_deg = {f.width_deg!r} deg is less than {q:g} cell of {grid}: the "
                              f"groove is modelled as one column {cell_deg:.3g} deg wide (a width in radians? 0.52 rad "
                              f"is 30 deg; resolved by {_finer('n_theta', q * 360.0 / f.width_deg, N_THETA_MAX)})",
                              UserWarning, stacklevel=3)
            if f.length is not None:
                _resolved(f"{name}.length", f.length, "m", q * cell_z, length, grid,
                          _finer("n_axial", q * n_axial * cell_z / f.length, N_AXIAL_MAX))
        elif isinstance(f, OilHole):
            cell = max(cell_s, cell_z)
            _resolved(f"{name}.diameter", f.diameter, "m", q * cell, min(length, np.pi * radius), grid,
                      "a finer grid (more cells, n_theta and n_axial)")
            if f.diameter < cell:
                warnings.warn(f"{name}.diameter = {f.diameter:g} m is smaller than a cell of {grid}: the hole is "
                              f"modelled as {int(np.sum(labels == k))} whole cell(s) (refine the grid to resolve it)",
                              UserWarning, stacklevel=3)
        else:
            _resolved(f"{name}.width", f.width, "m", q * cell_z, length, grid,
                      _finer("n_axial", q * n_axial * cell_z / f.width, N_AXIAL_MAX))
            rows = np.flatnonzero((np.asarray(labels).reshape(n_axial, n_theta) == k).all(axis=1))
            ends = [rows.max() < n_axial - 1] + ([] if symmetric else [rows.min() > 0])
            if not all(ends):
                raise ValueError(f"{name}.width = {f.width!r} [m] at axial_position = {f.axial_position!r} m covers "
                                 f"cell rows {rows.min()} to {rows.max()} of {grid}, leaving no land row between it "
                                 "and an end; allowed: a narrower groove, or more rows (n_axial)")


def _finer(count, needed, most) -> str:
    """Advice: the cell count ``count`` that resolves a feed (``needed`` cells), or that no grid does."""
    return f"a finer grid, {count} >= {math.ceil(needed)}" if needed <= most else f"no grid ({count} at most {most})"


def _resolved(name, value, unit, low, high, grid, finer):
    if value < low:
        raise ValueError(f"{name} = {value!r} [{unit}] is less than {MIN_CELL_FRACTION:g} cell of {grid}; "
                         f"allowed on this grid: [{low:.3g}, {high:.3g}] {unit}; resolved by {finer}")


def feed_labels(feeds, phi, z, radius) -> np.ndarray:
    """Feed index of every cell (cell centres ``phi`` [rad], ``z`` [m], flat arrays), -1 for a film cell.
    Two feeds sharing a cell are an error."""
    labels = np.full(phi.size, -1, dtype=np.int64)
    for k, f in enumerate(feeds):
        inside = f.cells(phi, z, radius, feed_name(feeds, k))
        clash = inside & (labels >= 0)
        if clash.any():
            j = int(labels[clash][0])
            raise ValueError(f"{feed_name(feeds, k)} = {f!r} overlaps {feed_name(feeds, j)} = {feeds[j]!r} on the "
                             f"grid ({int(clash.sum())} shared cells); allowed: feeds on distinct cells")
        labels[inside] = k
    return labels


def feed_edges(feeds) -> np.ndarray:
    """Per feed: True where its edges are cell faces (a circumferential groove), False where its pressure is held at
    the centres of its cells (axial grooves, holes)."""
    return np.array([isinstance(f, CircumferentialGroove) for f in feeds], dtype=bool)


def apply_feed_edges(op, scales):
    """Halve the centre distance ``fd`` of the operator's interior faces between a film cell and a feed whose edges
    are faces (:func:`feed_edges`): that feed's edge is the face, half a cell from the film cell's centre as at a
    bearing end. Before the operator's face tables are read (a Gecim bulk's are built from ``fd``)."""
    labels = scales.feed_cells
    edged = np.append(scales.feed_edges, False)[labels]  # label -1 -> False
    L, R = op.fL, op.fR
    op.fd[(op.fdir == 1) & ((edged[L] & (labels[R] < 0)) | (edged[R] & (labels[L] < 0)))] *= 0.5
