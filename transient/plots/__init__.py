"""matplotlib figures drawn from Results (and the tables studies make of them) only: every paper figure is
drawable from the installed package, e.g. ``transient.plots.journal.orbit_settling(result, record)``.

Figures are built on :class:`matplotlib.figure.Figure` directly (no pyplot state, no GUI backend), so they
work headless and in worker processes; :func:`save` writes one and returns its path.
"""

from __future__ import annotations

from pathlib import Path

from matplotlib.figure import Figure


def figure(nrows=1, ncols=1, size=(7.0, 4.5), **kw):
    """A new figure and its axes (an array when there is more than one)."""
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.subplots(nrows, ncols, **kw)


def save(fig: Figure, path, dpi=120) -> Path:
    """Write ``fig`` to ``path`` (folders created) and return the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    return path
