"""What every figure the package draws must have: a title, and on every visible axis with tick labels a label
naming its unit in square brackets ("[rpm]", "[C]", "[-]" for dimensionless) or a count ("number of balls"). Checked on the
:class:`matplotlib.figure.Figure` objects (after a draw, so tick labels exist), not on pixels."""

import re

from matplotlib.backends.backend_agg import FigureCanvasAgg

UNIT = re.compile(r"\[[^\]]+\]")


def figure_problems(fig) -> list[str]:
    """The problems of ``fig``: empty list when it passes."""
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    problems = []
    titled = bool(fig._suptitle and fig._suptitle.get_text().strip())
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        is_colorbar = ax.get_label() == "<colorbar>"
        titled |= any(ax.get_title(loc=loc).strip() for loc in ("left", "center", "right"))
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            if not axis.get_visible() or not any(t.get_text().strip() for t in axis.get_ticklabels()):
                continue
            text = axis.get_label().get_text()
            if not (UNIT.search(text) or text.startswith("number of")):
                what = "colorbar" if is_colorbar else f"axes {k} ({ax.get_title()[:40]!r})"
                problems.append(f"{what}: {name} label {text!r} names no unit in [...]")
    if not titled:
        problems.append("no title (neither a suptitle nor an axes title)")
    return problems
