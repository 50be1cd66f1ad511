"""The journal kernels' data, named and grouped by lifetime (numba takes named tuples as it takes tuples).

* per speed -- :class:`FilmScales` (Python side: p0, the force unit, the prescribed pressures; shared by the Elrod
  :class:`~transient.models.journal.film.Film` and the :class:`~transient.models.journal.reynolds_film.ReynoldsFilm`)
  and its kernel part :class:`Switch` (the Elrod switch and the boundary layers' Poiseuille law);
* per grid -- :class:`CellGeometry` (``cos phi``, ``sin phi``, area of every cell) and :class:`Operator` (the
  finite-volume operator's face tables, :class:`Cells`, and the Gecim bulk's faces);
* per film -- :class:`Scratch` (the cell fields of the last state evaluated), :class:`RotorColumns` (the
  rotor's rows and columns of the arrow Jacobian) and :class:`ContentScratch` (the content formulation's);
* per orbit -- :class:`Rotor` (the rotor groups of :mod:`transient.models.journal.kernels`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from transient.models.journal.feeds import feed_edges
from transient.models.journal.gecim_film import BulkFaces
from transient.units import rpm_to_rad_s

#: Default pressure width of the Elrod switch as a fraction of p0 = 6 mu omega (R/C)^2 (docs/journal.md).
SWITCH_WIDTH_P0 = 1e-4


class FilmScales(NamedTuple):
    """A bearing's film at one shaft speed in its own scales (module docstring of
    :mod:`transient.models.journal.kernels`): SI where a unit is given, else dimensionless."""

    speed_rpm: float            # [rpm]
    omega: float                # [rad/s]
    p0: float                   # [Pa] 6 mu omega (R/C)^2
    radius: float               # [m]
    clearance: float            # [m]
    cavitation_pressure: float  # [Pa] p_c (p = p_c + p0 P)
    force_scale: float          # [N] p0 R^2 per unit of Fbar
    u_supply: np.ndarray        # each prescribed (feed) cell's pressure (p_feed - p_c) / p0, in cell order
    u_ambient: float            # end pressure (p_a - p_c) / p0
    beta_bar: float             # bulk modulus / p0
    width: float                # pressure width of the Elrod switch / p0
    content_scale: float        # r = content width / pressure width of the switch
    layer_gap: float            # 2 delta / C of the boundary layers
    darcy: float                # 3 alpha^2 mu (1/mu_a + 1/mu_b) / C^2
    sym: float                  # 2 on a half bearing (symmetry plane), else 1
    feed_cells: np.ndarray      # feed index of every cell, -1 in the film (models.journal.feeds)
    feed_edges: np.ndarray      # per feed: True if its edges are cell faces (a circumferential groove)

    @property
    def switch(self) -> "Switch":
        """The kernels' part of the scales."""
        return Switch(self.beta_bar, self.width, self.content_scale, self.layer_gap, self.darcy)


def film_scales(bearing, speed_rpm) -> FilmScales:
    """The :class:`FilmScales` of a :class:`~transient.models.journal.bearing.JournalBearing` at ``speed_rpm``."""
    b = bearing
    p0 = b.pressure_scale(speed_rpm)
    width = SWITCH_WIDTH_P0 if b.switch_width is None else b.switch_width / p0
    layer_gap, darcy = b.layer_groups()
    return FilmScales(
        speed_rpm=float(speed_rpm), omega=rpm_to_rad_s(speed_rpm), p0=p0, radius=b.radius, clearance=b.clearance,
        cavitation_pressure=b.cavitation_pressure, force_scale=p0 * b.radius ** 2,
        u_supply=(b.feed_pressures[b.feed_cells[b.feed_cells >= 0]] - b.cavitation_pressure) / p0,
        u_ambient=(b.ambient_pressure - b.cavitation_pressure) / p0, beta_bar=b.bulk_modulus / p0, width=width,
        content_scale=b.switch_content_width / width, layer_gap=layer_gap, darcy=darcy,
        sym=2.0 if b.symmetric else 1.0, feed_cells=b.feed_cells, feed_edges=feed_edges(b.feeds))


class Switch(NamedTuple):
    """The Elrod switch (:mod:`transient.physics.cavitation`) and the boundary layers' Poiseuille law
    (:func:`~transient.models.journal.kernels.conductances`) at one speed."""

    beta_bar: float
    width: float
    content_scale: float
    layer_gap: float
    darcy: float


class CellGeometry(NamedTuple):
    """Per cell: ``cos phi``, ``sin phi``, the area (in R^2) and the gap of the centred journal ``gap0`` (in C: 1 for
    an aligned journal; ``1 + zbar (a cos phi + b sin phi)`` for a tilted one, :mod:`transient.models.journal.tilt`),
    so that the film thickness is ``H = gap0 + X cos phi + Y sin phi``."""

    cosp: np.ndarray
    sinp: np.ndarray
    area: np.ndarray
    gap0: np.ndarray


class Cells(NamedTuple):
    """The operator's cell table (:data:`transient.fv.reynolds.FACE_TUPLES`): free (not prescribed) cells, the
    prescribed values, the CSC position of every cell's diagonal."""

    free: np.ndarray
    u_fixed: np.ndarray
    pos_c: np.ndarray


class Operator(NamedTuple):
    """The finite-volume operator as the kernels take it: face, boundary-face and cell tables
    (:data:`transient.fv.reynolds.FACE_TUPLES`), per-face conductances (empty: the cells' mean) and the Gecim
    bulk's faces (None for a Newtonian bulk: the kernels then compile without the Gecim flux)."""

    faces: tuple
    boundary: tuple
    cells: Cells
    face_k: tuple
    bulk: BulkFaces | None


class Scratch(NamedTuple):
    """The cell fields of the last state evaluated: ``H``, ``P(u)``, ``P'``, ``theta = C(u)``, ``D = C'``, ``D'``,
    the Poiseuille and Couette coefficients ``k``, ``c``, zeros, and the net outflow ``R``."""

    H: np.ndarray
    P: np.ndarray
    dP: np.ndarray
    C: np.ndarray
    D: np.ndarray
    dD: np.ndarray
    k: np.ndarray
    c: np.ndarray
    zero: np.ndarray
    R: np.ndarray


class RotorColumns(NamedTuple):
    """The rotor's part of the arrow Jacobian: ``dk/dq``, ``dc/dq`` (and zeros) for the extra unknowns, the CSC
    positions of the extra rows and columns, the pattern's row indices and the row scaling of the ODE form."""

    dk_dq: np.ndarray
    dc_dq: np.ndarray
    no_dq: np.ndarray
    pos_row: np.ndarray
    pos_col: np.ndarray
    indices: np.ndarray
    scale: np.ndarray


class ContentScratch(NamedTuple):
    """The content formulation's scratch: the universal variable ``u`` of the cells, ``theta = m / H``,
    ``du/dm``, ``du/dX``, ``du/dY``, the CSC column pointers of the pattern, and the journal position ``(X, Y)``
    whose cell fields the BDF2 Newton variables left in :class:`Scratch` (NaN: none;
    :func:`~transient.models.journal.content_newton.fields_of`); for the BDF2 Newton's own pattern
    (:func:`~transient.models.journal.content_newton.decoupled_pattern`; empty until
    :meth:`~transient.models.journal.orbit.JournalOrbit.bdf2_model`): the Jacobian's data in the operator's pattern
    and the position there of each entry of the Newton's pattern."""

    u: np.ndarray
    theta: np.ndarray
    E: np.ndarray
    ux: np.ndarray
    uy: np.ndarray
    indptr: np.ndarray
    xy: np.ndarray
    jac: np.ndarray
    gather: np.ndarray


class Rotor(NamedTuple):
    """The rotor groups (module docstring of :mod:`transient.models.journal.kernels`): the film force group
    ``kappa = p0 R^2 / (m C omega^2)`` of the paper (not the Gecim bulk's stress ``kappa``), ``Wbar = W / (m C
    omega^2)``, ``ebar = e / C``, and ``sym``."""

    force_group: float
    wbar: float
    ebar: float
    sym: float


def cell_geometry(grid) -> CellGeometry:
    """The :class:`CellGeometry` of a bearing's grid (``phi`` = the cell centres along x), journal aligned."""
    return CellGeometry(np.ascontiguousarray(np.cos(grid.xc)), np.ascontiguousarray(np.sin(grid.xc)),
                        np.ascontiguousarray(grid.area), np.ones(grid.n))


def operator_tables(op, bulk: BulkFaces | None) -> Operator:
    """The :class:`Operator` of a :class:`~transient.fv.reynolds.ReynoldsOperator` and a Gecim bulk's faces."""
    return Operator(op.faces, op.boundary, Cells(*op.cells), op.no_face_k, bulk)
