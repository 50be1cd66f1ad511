"""Parameter validation shared by every model: errors name the parameter, its value, its unit and the
allowed range, in one line.

Numbers must be real and finite (no strings, no booleans, no NaN, no infinity: an infinite "upper bound" is
never a value); integers must be whole (a grid of 41.5 cells is an error, not 41); flags must be booleans
(the string ``'False'`` is not false).

The integrator's arguments (tolerances, steps, output times) are checked here too, by :func:`check_rtol`,
:func:`check_atol`, :func:`check_step`, :func:`check_count` and :func:`check_times`: they are unitless or in the
problem's own time unit, so their messages say "must be ..., got ..." instead of naming a unit.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

#: The smallest absolute tolerance any integration accepts: the error weights ``1 / atol`` of states at zero
#: overflow SUNDIALS' weighted norms below it (IDA then crashes the process).
ATOL_FLOOR = 1e-30
ATOL_WHY = f"(below {ATOL_FLOOR:g} the error weights 1/atol of states at zero overflow the integrators' norms)"


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
    """One of ``choices`` (strings)."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} must be one of {tuple(choices)!r}, got {name} = {value!r}")
    return value


# --------------------------------------------------------------------------------------------------
# Integrator arguments (unitless, or in the problem's own time unit)
# --------------------------------------------------------------------------------------------------

def short_repr(x, limit=60) -> str:
    """``repr(x)`` cut to ``limit`` characters (for one-line error messages)."""
    r = repr(x)
    return r if len(r) <= limit else r[:limit - 3] + "..."


def _number(value):
    """``value`` as a float if it is a real number (not a bool, a string or an array), else None."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        return None
    return float(value)


def _show(value) -> str:
    """A value for an error message: numbers plainly (0.5, nan; not np.float64(0.5))."""
    x = _number(value)
    return repr(x) if x is not None else short_repr(value)


def check_step(name, value, *, free_zero=False) -> float:
    """A finite number > 0 (a fixed step), or >= 0 with ``free_zero`` (a step limit where 0 means free)."""
    x = _number(value)
    if free_zero:
        if x is None or not (0.0 <= x < math.inf):
            raise ValueError(f"{name} must be a finite number >= 0 (0 = free), got {_show(value)}")
        return x
    if x is None or not (0.0 < x < math.inf):
        raise ValueError(f"{name} must be a finite number in (0, inf), got {_show(value)}")
    return x


def check_rtol(value) -> float:
    """A relative tolerance: a finite number in (0, 1)."""
    x = _number(value)
    if x is None or not (0.0 < x < 1.0):
        raise ValueError(f"rtol must be a finite number in (0, 1), got {_show(value)}")
    return x


def check_atol(value, n=None):
    """An absolute tolerance: a finite number >= :data:`ATOL_FLOOR`, or (given ``n``) one such value per state."""
    what = "a finite number > 0" + (f" or an array of {n} such numbers (one per state)" if n is not None else "")
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"atol must be {what}, got {value!r}")
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"atol must be {what}, got {short_repr(value)}") from None
    if a.ndim == 0:
        v = check_step("atol", value if _number(value) is not None else float(a))
        if v < ATOL_FLOOR:
            raise ValueError(f"atol = {v!r} is below {ATOL_FLOOR:g} {ATOL_WHY}")
        return v
    if n is None or a.shape != (n,):
        raise ValueError(f"atol must be a scalar or an array of length n={n} (one per state), got shape {a.shape}")
    bad = np.flatnonzero(~(np.isfinite(a) & (a >= ATOL_FLOOR)))
    if bad.size:
        raise ValueError(f"atol[{bad[0]}] must be a finite number > 0 (at least {ATOL_FLOOR:g}), got "
                         f"{_show(a[bad[0]])} ({bad.size} bad of {n})")
    return np.ascontiguousarray(a)


def check_count(name, value, low=1) -> int:
    """A whole number >= ``low`` given as an int (or a whole float); not a bool."""
    if (isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer, float))
            or not math.isfinite(value) or int(value) != value or value < low):
        raise ValueError(f"{name} must be an integer >= {low}, got {value!r}")
    return int(value)


def check_times(name, value) -> np.ndarray:
    """A 1-D array of at least 2 strictly increasing finite times."""
    try:
        t = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a 1-D array of at least 2 increasing finite times, got "
                         f"{short_repr(value)}") from None
    if t.ndim != 1 or t.size < 2:
        raise ValueError(f"{name} must be a 1-D array of at least 2 times [s], got shape {t.shape}")
    bad = np.flatnonzero(~np.isfinite(t))
    if bad.size:
        raise ValueError(f"{name} must be finite, got {name}[{bad[0]}] = {_show(t[bad[0]])}")
    d = np.flatnonzero(~(np.diff(t) > 0))
    if d.size:
        k = d[0]
        raise ValueError(f"{name} must be strictly increasing [s], got {name}[{k + 1}] = {_show(t[k + 1])} <= "
                         f"{name}[{k}] = {_show(t[k])}")
    return t


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


# --------------------------------------------------------------------------------------------------
# objects and short vectors of numbers (constructors' structured arguments)
# --------------------------------------------------------------------------------------------------

class ParameterTypeError(ValueError, TypeError):
    """A parameter of the wrong kind (e.g. a number where a bearing is expected): a ``ValueError`` like every bad
    input, and a ``TypeError`` for callers that catch that."""


def check_instance(name, value, types, allowed: str):
    """``value`` if it is an instance of ``types``, else a one-line :class:`ParameterTypeError` naming the parameter,
    its value and ``allowed`` (what it must be, in words)."""
    if not isinstance(value, types):
        raise ParameterTypeError(f"{name} = {short_repr(value)} ({type(value).__name__}); allowed: {allowed}")
    return value


def check_items(name, value, allowed: str, length=None) -> tuple:
    """``value`` as a tuple if it is a sequence (list, tuple, 1-D array; not a string, a mapping or a set) of
    ``length`` items (any number if None), else a one-line ``ValueError`` naming the parameter and ``allowed``."""
    if isinstance(value, np.ndarray):
        items = tuple(value) if value.ndim == 1 else None
    elif isinstance(value, (list, tuple)):
        items = tuple(value)
    else:
        items = None
    if items is None or (length is not None and len(items) != length):
        count = "" if items is None else f" ({len(items)} items)"
        raise ValueError(f"{name} = {short_repr(value)}{count}; allowed: {allowed}")
    return items


def check_vector(name, value, unit, length, low=-math.inf, high=math.inf, *, why="") -> tuple:
    """A sequence of ``length`` finite numbers, each in [low, high] (:func:`check_items`, :func:`check_range`);
    returns them as a tuple of floats."""
    items = check_items(name, value, f"{length} numbers [{unit}]" + (f" {why}" if why else ""), length)
    return tuple(check_range(f"{name}[{k}]", v, unit, low, high, why=why) for k, v in enumerate(items))
