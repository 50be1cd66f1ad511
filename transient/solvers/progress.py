"""The one way progress is shown: a tqdm bar on stderr (long runs, sweeps, continuation paths).

``progress_bar(enabled, total, unit, label)`` returns ``None`` when disabled, so callers write
``if bar: bar.update(...)``; the postfix carries the latest numbers (``bar.set_postfix_str``).
"""

from __future__ import annotations

import sys

#: the bar of fractional totals (revolutions, seconds): done / total in the caller's unit and the time left
FRACTIONAL = "{desc}: {percentage:3.0f}%|{bar}| {n:.4g}/{total:.4g} {unit} [{elapsed}<{remaining}] {postfix}"


def progress_bar(enabled: bool, total: float, unit: str, label: str, initial: float = 0, bar_format: str | None = None):
    """A tqdm bar over ``total`` ``unit`` named ``label`` (None when not ``enabled``)."""
    if not enabled:
        return None
    from tqdm.auto import tqdm

    return tqdm(total=total, initial=initial, unit=unit, desc=label, file=sys.stderr, dynamic_ncols=True,
                bar_format=bar_format)
