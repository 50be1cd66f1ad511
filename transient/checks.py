"""Parameter validation shared by every model: errors name the parameter, its value, its unit and the
allowed range."""

from __future__ import annotations

import math


def check_range(name, value, unit, low=-math.inf, high=math.inf, *, low_open=False, high_open=False, why=""):
    """Return ``float(value)`` if it lies in the range, else raise ``ValueError`` naming all of it."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r} [{unit}] is not a real number") from None
    ok = math.isfinite(v) or (v == high == math.inf)
    ok = ok and (v > low if low_open else v >= low) and (v < high if high_open else v <= high)
    if not ok:
        lo = f"{'(' if low_open else '['}{low:g}"
        hi = f"{high:g}{')' if high_open else ']'}"
        raise ValueError(f"{name} = {value!r} [{unit}] is out of range; allowed: {lo}, {hi} {unit}"
                         + (f" {why}" if why else ""))
    return v


def check_positive(name, value, unit):
    """``value > 0`` and finite."""
    return check_range(name, value, unit, 0.0, math.inf, low_open=True, high_open=True)
