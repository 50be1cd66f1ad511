"""Parameter validation shared by every model: errors name the parameter, its value, its unit and the
allowed range, in one line.

Numbers must be real and finite (no strings, no booleans, no NaN, no infinity: an infinite "upper bound" is
never a value); integers must be whole (a grid of 41.5 cells is an error, not 41); flags must be booleans
(the string ``'False'`` is not false).
"""

from __future__ import annotations

import math
import numbers


def _real(name, value, unit):
    if isinstance(value, (str, bytes, bool)) or not isinstance(value, numbers.Real):
        if not (hasattr(value, "__float__") and not isinstance(value, (str, bytes, bool))):
            raise ValueError(f"{name} = {value!r} [{unit}] is not a real number")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r} [{unit}] is not a real number") from None


def check_range(name, value, unit, low=-math.inf, high=math.inf, *, low_open=False, high_open=False, why=""):
    """Return ``float(value)`` if it is a finite real number in the range, else raise ``ValueError`` naming
    the parameter, the value, the unit and the allowed range."""
    v = _real(name, value, unit)
    ok = math.isfinite(v) and (v > low if low_open else v >= low) and (v < high if high_open else v <= high)
    if not ok:
        lo = f"{'(' if low_open else '['}{low:g}"
        hi = f"{high:g}{')' if high_open else ']'}"
        raise ValueError(f"{name} = {value!r} [{unit}] is out of range; allowed: {lo}, {hi} {unit}"
                         + (f" {why}" if why else ""))
    return v


def check_positive(name, value, unit):
    """``value > 0`` and finite."""
    return check_range(name, value, unit, 0.0, math.inf, low_open=True, high_open=True)


def check_int(name, value, unit, low=-math.inf, high=math.inf):
    """A whole number in [low, high] (``41.0`` is accepted as 41; ``41.5``, ``'41'`` and ``True`` are not)."""
    v = check_range(name, value, unit, low, high)
    if v != int(v):
        raise ValueError(f"{name} = {value!r} [{unit}] is not a whole number; allowed: integers in "
                         f"[{low:g}, {high:g}]")
    return int(v)


def check_bool(name, value):
    """A flag: ``True`` or ``False`` only."""
    if not isinstance(value, bool) and type(value).__name__ != "bool_":
        raise ValueError(f"{name} = {value!r} is not a flag; allowed: True, False")
    return bool(value)


def check_choice(name, value, choices):
    """One of ``choices``."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} = {value!r}; allowed: {', '.join(map(repr, choices))}")
    return value


# --------------------------------------------------------------------------------------------------
# memory: estimated before a run, refused beyond a stated share of the machine
# --------------------------------------------------------------------------------------------------

#: share of the machine's physical memory a run may plan to use (and a loaded file may expand to)
MEMORY_SHARE = 0.5


class MemoryLimitError(ValueError):
    """A run (or a file) that would need more than :data:`MEMORY_SHARE` of the machine's memory."""


def machine_memory() -> int:
    """Physical memory of this machine [bytes] (the environment variable ``TRANSIENT_MEMORY_BYTES``
    overrides it, e.g. to plan for a smaller machine)."""
    import os

    if os.environ.get("TRANSIENT_MEMORY_BYTES"):
        return int(float(os.environ["TRANSIENT_MEMORY_BYTES"]))
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):
        return 8 * 1024 ** 3


def memory_limit() -> int:
    """The most bytes a run may plan for: :data:`MEMORY_SHARE` of :func:`machine_memory`."""
    return int(MEMORY_SHARE * machine_memory())


def _gb(n) -> str:
    return f"{n / 1e9:.3g} GB" if n >= 1e8 else f"{n / 1e6:.3g} MB"


def check_memory(what: str, parts: dict, advice: str) -> float:
    """Refuse, before anything is allocated, a run whose estimated memory (``parts``: name -> bytes, e.g.
    states, Jacobian, recordings) exceeds :data:`MEMORY_SHARE` of this machine's memory: one line naming the
    estimate by part and ``advice`` (the parameters to change). Returns the estimate [bytes]."""
    total = float(sum(parts.values()))
    limit = memory_limit()
    if not math.isfinite(total) or total > limit:
        shown = ", ".join(f"{name} {_gb(v)}" for name, v in parts.items())
        raise MemoryLimitError(f"{what} would need about {_gb(total)} of memory ({shown}), more than "
                               f"{MEMORY_SHARE:.0%} of this machine's {_gb(machine_memory())}; {advice}")
    return total
