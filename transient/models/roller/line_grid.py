"""The line contact's default domain and grid, chosen from its regime (Moes' M, L; elastic or rigid).

Two lengths set them (units of the Hertz half-width b):

* the hydrodynamic length ``s = sqrt(2 R h_c) / b = sqrt(pi H_c / (4 M))``, ``H_c`` Moes' central film
  (:func:`transient.physics.line_formulas.moes_central`; a rigid cylinder: its rigid branches
  ``max(3/M, 1.287 L^2/3)``): the inlet wedge over which the rigid film builds its pressure. Below M ~ 1 it
  is longer than b (``s -> 1.53/M``), so a domain in Hertz half-widths cuts the inlet off there;
* the inlet edge ``x = -b``, where an elastic film is set: a uniform spacing at most ``INLET_RESOLUTION/M``.

Default domain ``[-max(5, INLET_LENGTHS s), max(2.5, OUTLET_LENGTHS s)]`` (the paper's -5 ... 2.5 b where the
contact is elastic). Martin's rigid film with its inlet at ``k sqrt(2 R h_min)`` is low by ~``2.4/k^2``: at
26 s (k ~ 29) by 0.3 %. Measured on elastic contacts, inlet -5 b against 26 s (docs/validation.md): M = 10,
L = 0: -0.05 %; M = 2, L = 0: -1.6 %; M = 1, L = 0: -8 %.

Default grid: for an elastic contact at M >= ``CLUSTERED_FROM`` the nodes clustered on the Hertz zone, the
inlet edge and the outlet spike (:data:`LINE_CLUSTERS`, 1025 nodes, doubled until the inlet edge is
resolved): within 0.2 % of 2049 clustered and of 16385 uniform nodes at M = 1000 (L = 0 ... 10), 0.2-0.5 s
CPU. Below it, uniform, ``2^k + 1 >= 401`` nodes at the resolving spacing (:func:`resolving_spacing`).
"""

from __future__ import annotations

import math

import numpy as np

from transient.models.roller.grid import clustered_axis
from transient.physics.line_formulas import moes_central

#: largest M dx_in (dx_in: the node spacing at the inlet edge x = -b) at which the central film is resolved to
#: about 1 %; measured against grid limits (Barus, incompressible): M dx_in = 0.4 -> -0.2 %, 0.54 -> -0.9 %,
#: 1.6 -> -5 %, 2.4 -> -8 %, 5.4 -> -57 % (docs/validation.md)
INLET_RESOLUTION = 0.6
#: largest spacing, in hydrodynamic lengths s, of a resolving grid in the rigid regime (M < 1, or a rigid
#: cylinder): Martin's film is low by ~0.9 (dx/s)^2 (measured: dx = 0.081 s -> -0.55 %, 0.041 s -> -0.17 %)
RIGID_RESOLUTION = 0.05
#: an explicit grid coarser than this many s in the rigid regime is warned about (~1 % low)
RIGID_WARN = 0.1
#: the default inlet lies this many hydrodynamic lengths upstream (at least 5 b) ...
INLET_LENGTHS = 26.0
#: ... and the outlet this many downstream (at least 2.5 b)
OUTLET_LENGTHS = 3.0
#: an explicit inlet closer than this many s is warned about: rigid regime (Martin low by ~2 (s/x_in)^2: 1 %) ...
RIGID_INLET_WARN = 14.0
#: ... and elastic (M >= 1; measured starvation at x_in = 3.9-4.9 s: 1.6-2.3 %, at 7.3 s: 0.4 %)
ELASTIC_INLET_WARN = 5.0
#: node-density clusters ``(centre, width, weight)``, units of b (:func:`transient.models.roller.grid.clustered_axis`):
#: the Hertz zone, the inlet edge (where the film is set: at M = 1000 its pressure build-up spans ~0.01 b) and
#: the outlet spike. The inlet cluster is what brings H_c on 1025 nodes to within 0.2 % of the grid limit at
#: M = 1000 (a wider, weaker one left it 8 % below; docs/validation.md)
LINE_CLUSTERS = ((0.0, 1.1, 4.0), (-1.0, 0.03, 40.0), (1.0, 0.05, 8.0))
#: the default grid is clustered from this M on (elastic contacts), with at least this many nodes
CLUSTERED_FROM, CLUSTERED_NODES = 10.0, 1025
#: the uniform default grid has at least this many nodes
MIN_UNIFORM_NODES = 401


def rigid_regime(M: float, elastic: bool) -> bool:
    """Whether the film is set by the rigid inlet wedge over ``s`` (a rigid cylinder, or M < 1, where
    Moes' rigid-isoviscous branch ``3/M`` exceeds the elastic one ``2.621 M^-1/5``)."""
    return (not elastic) or M < 1.0


def hydrodynamic_length(M: float, L: float, elastic: bool = True) -> float:
    """``s = sqrt(2 R h_c)/b = sqrt(pi H_c/(4 M))`` [b] with Moes' central film ``H_c`` (module docstring)."""
    H = moes_central(M, L) if elastic else max(3.0 / M, 1.287 * L ** (2.0 / 3.0))
    return math.sqrt(math.pi * H / (4.0 * M))


def default_domain(M: float, L: float, elastic: bool = True) -> tuple[float, float]:
    """(inlet, outlet) [b]: ``(-max(5, INLET_LENGTHS s), max(2.5, OUTLET_LENGTHS s))``."""
    s = hydrodynamic_length(M, L, elastic)
    return -max(5.0, INLET_LENGTHS * s), max(2.5, OUTLET_LENGTHS * s)


def resolving_spacing(M: float, L: float, elastic: bool = True) -> float:
    """The uniform spacing [b] that resolves the film to a few tenths of a per cent: ``INLET_RESOLUTION/M``
    at the inlet edge of an elastic contact, and in the rigid regime ``RIGID_RESOLUTION s``."""
    dx = INLET_RESOLUTION / M if elastic else math.inf
    if rigid_regime(M, elastic):
        dx = min(dx, RIGID_RESOLUTION * hydrodynamic_length(M, L, elastic))
    return dx


def uniform_nodes(domain, spacing: float) -> int:
    """The smallest node count ``2^k + 1`` (``k >= 4``) of spacing at most ``spacing`` over ``domain`` (a power of
    two for the grid levels)."""
    intervals = (domain[1] - domain[0]) / spacing
    return 2 ** max(4, math.ceil(math.log2(intervals))) + 1


def clustered_nodes(domain, M: float, n: int = CLUSTERED_NODES) -> np.ndarray:
    """:data:`LINE_CLUSTERS` on ``n`` nodes over ``domain`` (a node at x = 0), ``n`` doubled (to at most 16385)
    until the spacing at the inlet edge is at most ``INLET_RESOLUTION / M``."""
    while True:
        x = clustered_axis(domain[0], domain[1], n, clusters=LINE_CLUSTERS, snap=(0.0,))
        k = int(np.clip(np.searchsorted(x, -1.0), 1, x.size - 1))
        if M * (x[k] - x[k - 1]) <= INLET_RESOLUTION or n >= 16385:
            return x
        n = 2 * n - 1


def default_grid(M: float, L: float, elastic: bool, domain):
    """The default grid: the clustered nodes (elastic, ``M >= CLUSTERED_FROM``) or the uniform node count at the
    resolving spacing, at least ``MIN_UNIFORM_NODES`` (module docstring)."""
    if elastic and M >= CLUSTERED_FROM:
        return clustered_nodes(domain, M)
    return max(MIN_UNIFORM_NODES, uniform_nodes(domain, resolving_spacing(M, L, elastic)))
