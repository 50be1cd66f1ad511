"""The deprecated loose keywords of a run, mapped onto its settings objects for one release.

A run takes its settings that are not physics as frozen objects (``integration=Integration(rtol=1e-8)``,
``steps=Steps(dt=0.01)``); the keywords earlier releases took one by one (``rtol=1e-8``) arrive in the run's
``**legacy`` and :func:`run_settings` builds the objects from them, with a ``DeprecationWarning`` that names the
old keyword and its new spelling. A keyword the run never took is a ``TypeError`` naming it, as Python's own.
"""

from __future__ import annotations

import sys
import warnings
from dataclasses import fields
from pathlib import Path

from transient.checks import short_repr

#: The package's folder: a deprecation warning points at the first frame outside it (the caller's line).
PACKAGE = str(Path(__file__).resolve().parents[1])


def _caller_level() -> int:
    """The ``stacklevel`` of the first frame outside the package, seen from :func:`run_settings`'s caller's
    ``warnings.warn`` (level 1: this function's caller)."""
    frame, level = sys._getframe(1), 1
    while frame.f_back is not None and frame.f_code.co_filename.startswith(PACKAGE):
        frame, level = frame.f_back, level + 1
    return level


def keyword_table(argument: str, cls, names=None) -> dict:
    """``{field: (argument, cls, field)}`` for the fields ``names`` of ``cls`` (default: all): the part of a
    :func:`run_settings` table saying that the old keyword ``field`` now goes in ``argument=cls(field=...)``."""
    names = [f.name for f in fields(cls)] if names is None else names
    return {n: (argument, cls, n) for n in names}


def run_settings(owner: str, legacy: dict, table: dict, defaults: dict | None = None, **given) -> dict:
    """The settings objects of a run: ``given`` (argument name -> the object the caller passed, or ``None``)
    completed from the deprecated loose keywords ``legacy`` and the model's defaults.

    ``table`` maps each old keyword to ``(argument, settings class, field)`` -- or ``(argument, class, field,
    convert)`` when the old value needs converting (``record_profiles=True`` -> ``record=("profiles",)``), see
    :func:`keyword_table` -- and so names the class of every argument; ``defaults`` maps an argument to the
    model's own defaults of its class (``{"integration": {"method": "cvode"}}``). An argument left out is its
    class built from the old keywords given for it over the defaults.

    An unknown keyword is a ``TypeError`` naming it (as Python's own); every old keyword a
    ``DeprecationWarning`` naming it and its new spelling; an old keyword beside the object it belongs in a
    ``ValueError`` naming both; an argument that is not its class a ``ValueError``."""
    unknown = [k for k in legacy if k not in table]
    if unknown:
        raise TypeError(f"{owner}() got an unexpected keyword argument {unknown[0]!r}")
    built: dict = {}
    for old, value in legacy.items():
        arg, cls, name, *convert = table[old]
        spelling = f"{arg}={cls.__name__}({name}=...)"
        if given[arg] is not None:
            raise ValueError(f"{owner}: {old}={short_repr(value)} and {arg}={cls.__name__}(...) both given; pass the "
                             f"setting once, as {spelling}")
        warnings.warn(f"{owner}: the keyword {old}= is deprecated and will be removed in the next release; "
                      f"pass {spelling}", DeprecationWarning, stacklevel=_caller_level())
        _place(built, table[old], value)
    return settings_objects(table, built, defaults, given)


def settings_objects(table: dict, flat: dict, defaults: dict | None = None, given: dict | None = None) -> dict:
    """The settings objects that ``table`` (see :func:`run_settings`) names, built from ``flat`` (argument ->
    ``{field: value}``, already converted) over ``defaults``, or taken from ``given`` (argument -> object or
    ``None``; an object must be its class)."""
    classes = {arg: cls for arg, cls, *_ in table.values()}
    given = given if given is not None else dict.fromkeys(classes)
    out = {}
    for arg, obj in given.items():
        cls = classes[arg]
        if obj is None:
            obj = cls(**dict((defaults or {}).get(arg, {}), **flat.get(arg, {})))
        elif not isinstance(obj, cls):
            raise ValueError(f"{arg} = {short_repr(obj)}; allowed: None or {cls.__name__}(...)")
        out[arg] = obj
    return out


def flat_settings(table: dict, flat: dict, defaults: dict | None = None) -> dict:
    """The settings objects of a flat table of settings (a parameter set, a scene file, a sweep's fixed
    settings: ``{"grid": "front", "rtol": 1e-3}``), keyed by argument, every argument of ``table`` present; a
    key ``table`` does not know is a ``ValueError`` naming it. No warning: a flat table is a description, not a
    call."""
    unknown = [k for k in flat if k not in table]
    if unknown:
        raise ValueError(f"{unknown[0]!r} is not a setting; allowed: {', '.join(table)}")
    built: dict = {}
    for key, value in flat.items():
        _place(built, table[key], value)
    return settings_objects(table, built, defaults)


def _place(built: dict, entry: tuple, value) -> None:
    """Put ``value`` (converted if the table ``entry`` says how) in ``built[argument][field]``."""
    arg, cls, name, *convert = entry
    built.setdefault(arg, {})[name] = convert[0](value) if convert else value
