"""How :meth:`~transient.models.ball.ThrustBallBearing.sequence` models the oil track between two balls: one
frozen object, validated on creation (the limits that need the contact -- the reservoir beyond the Hertz
zone, films below the ambient film -- are checked by the sequence, which knows the load)."""

from __future__ import annotations

from dataclasses import dataclass

from transient.checks import check_choice, check_int, check_range

REPLENISHMENT = ("thin_film", "chiu", "chiu_thin")
GRIDS = ("front", "uniform")
BOUNDARIES = ("reservoir", "closed", "periodic")


@dataclass(frozen=True)
class TrackSettings:
    """The oil track between passes.

    ``replenishment`` ``"thin_film"`` (nonlinear levelling), ``"chiu"`` (Chiu's linear kernel) or
    ``"chiu_thin"`` (its thin-film long-wave limit); ``grid`` ``"front"`` (a mesh that follows the re-wetting
    front) or ``"uniform"`` (``n_cells`` uniform cells, an integer in [8, 1e7], across ``[0,
    reservoir_distance]``); ``refine`` [-] in [0.05, 64], the front mesh's refinement factor;
    ``reservoir_distance`` [m] > 0 or ``None`` (the ball radius): where the ambient film is; ``bc``
    ``"reservoir"`` (the ambient film held there), ``"closed"`` (no flux) or ``"periodic"`` (``grid="uniform"``); ``ridge_fraction`` [-] in [0, 1],
    the share of the oil pushed off the track that stays as side ridges; ``ridge_width`` [m] > 0 or ``None``
    (the Hertz semi-axis ``a'``); ``precursor_film`` [m] > 0 or ``None`` (the outlet film ``h_c/2``; a number
    replaces it by ``max(h_c/2, value)``); ``mobility_film`` [m] >= 0, ``b`` of a regularised mobility
    ``h^3 + b^3`` (0: none); ``front_level`` [-] in (1, 1e3] and ``front_tau`` [-] in (0, 1e3]: the front mesh
    follows the level ``front_level * h_out`` with this relaxation time (scaled); ``edge_width`` [m] >= 0 or
    ``None`` (``a'/50``): the wall of the depression (0: the paper's rectangular depression)."""

    replenishment: str = "thin_film"
    grid: str = "front"
    n_cells: int = 200
    refine: float = 1.0
    reservoir_distance: float | None = None
    bc: str = "reservoir"
    ridge_fraction: float = 1.0
    ridge_width: float | None = None
    precursor_film: float | None = None
    mobility_film: float = 0.0
    front_level: float = 3.0
    front_tau: float = 1e-3
    edge_width: float | None = None

    def __post_init__(self):
        check_choice("replenishment", self.replenishment, REPLENISHMENT)
        check_choice("grid", self.grid, GRIDS)
        check_choice("bc", self.bc, BOUNDARIES)
        _set(self, "n_cells", check_int("n_cells", self.n_cells, "-", 8, 1e7))
        _set(self, "refine", check_range("refine", self.refine, "-", 0.05, 64.0))
        _set(self, "ridge_fraction", check_range("ridge_fraction", self.ridge_fraction, "-", 0.0, 1.0))
        _set(self, "mobility_film", check_range("mobility_film", self.mobility_film, "m", 0.0, 1e-2, high_open=True))
        _set(self, "front_level", check_range("front_level", self.front_level, "-", 1.0, 1e3, low_open=True,
                                              why="(the level the front mesh follows, in units of the precursor "
                                                  "film)"))
        _set(self, "front_tau", check_range("front_tau", self.front_tau, "-", 0.0, 1e3, low_open=True))
        for name in ("reservoir_distance", "ridge_width", "precursor_film"):
            if getattr(self, name) is not None:
                _set(self, name, check_range(name, getattr(self, name), "m", 0.0, 1.0, low_open=True, high_open=True))
        if self.edge_width is not None:
            _set(self, "edge_width", check_range("edge_width", self.edge_width, "m", 0.0, 1.0, high_open=True))


def _set(obj, name, value):
    object.__setattr__(obj, name, value)
