"""matplotlib figures drawn from Results (and the tables studies make of them) only: every paper figure is
drawable from the installed package.

The figures are grouped by model family, each a module reachable from here without a separate import::

    import transient.plots as tp
    fig = tp.journal.orbit_settling(orbit_from_equilibrium(orbit, 30, 1e-6), 64, bearing.grid_shape)
    tp.save(fig, "out/orbit.png")

``ball``, ``damper``, ``feeds``, ``film``, ``journal``, ``layers``, ``mixed``, ``pad``, ``point``, ``roller``, ``rotor``, ``surfaces``, ``sweep``, ``thermal``, ``tilt``, ``whip`` (imported on
first use). Figures are built on :class:`matplotlib.figure.Figure` directly (no pyplot state, no GUI backend),
so they work headless and in worker processes; :func:`save` writes one and returns its path.
"""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

from matplotlib.figure import Figure

#: the figure modules, one per model family (imported lazily by attribute access)
FAMILIES = ("ball", "damper", "feeds", "journal", "layers", "mixed", "pad", "point", "reynolds_operator", "roller", "rotor", "surfaces",
            "sweep", "thermal", "tilt", "whip")
__all__ = ["figure", "save", "suptitle", *FAMILIES]


def figure(nrows=1, ncols=1, size=(7.0, 4.5), **kw):
    """A new figure and its axes (an array when there is more than one)."""
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.subplots(nrows, ncols, **kw)


def suptitle(fig: Figure, text: str, fontsize: float = 10.0):
    """Set ``text`` as the figure's title, broken into lines that fit its width (a long title on a narrow figure
    would otherwise run past both edges)."""
    import textwrap

    chars = max(20, int(fig.get_figwidth() * 72.0 / (0.6 * fontsize)))  # a character is ~0.6 em wide
    return fig.suptitle("\n".join(textwrap.fill(line, chars) for line in text.split("\n")), fontsize=fontsize)


def save(fig: Figure, path, dpi=120, make_folders: bool = True) -> Path:
    """Write ``fig`` to ``path`` and return the path. A missing folder is created with a one-line note on
    stderr (``make_folders=True``, the default) or is an error naming it (``make_folders=False``)."""
    path = Path(path)
    if not path.parent.is_dir():
        if not make_folders:
            raise FileNotFoundError(f"save: folder {path.parent} does not exist (make_folders=False)")
        path.parent.mkdir(parents=True, exist_ok=True)
        print(f"save: created folder {path.parent}", file=sys.stderr)
    fig.savefig(path, dpi=dpi)
    return path


def __getattr__(name):
    if name in FAMILIES:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}; figure modules: {', '.join(FAMILIES)}")


def __dir__():
    return sorted(set(globals()) | set(FAMILIES))
