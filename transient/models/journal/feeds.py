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

import warnings
from dataclasses import dataclass

import numpy as np

from transient.checks import check_range


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
        if inside.any():
            return inside
        warnings.warn(f"{name}.diameter = {self.diameter:g} m covers no cell centre: the hole is smaller than a cell "
                      "of this grid and is modelled as the nearest cell (refine the grid to resolve it)", UserWarning,
                      stacklevel=5)
        return np.arange(r.size) == np.argmin(r)

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
        raise TypeError(f"groove must be a Groove, OilHole, CircumferentialGroove, a sequence of them or None, got "
                        f"{type(groove).__name__}")
    feeds = tuple(feeds)
    for k, f in enumerate(feeds):
        if not isinstance(f, FEED_TYPES):
            raise TypeError(f"groove[{k}] must be a Groove, OilHole or CircumferentialGroove, got {type(f).__name__}")
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
