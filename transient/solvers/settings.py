"""Run settings as frozen objects: how to integrate, what to record, how to drive a long run.

A model's time-domain run takes three groups of settings that have nothing to do with its physics:

* :class:`Integration` -- the method and its tolerances (``method``, ``rtol``, ``atol``, ``formulation``,
  the fixed-step and Newton settings of ``rk4`` / ``bdf2``, ``dt``, ``linear_solver``);
* :class:`Recording` -- the output rate and the series kept (``outputs_per_revolution``, ``record``,
  ``record_from_revolution``);
* :class:`LongRun` -- chunks, checkpoint/resume, progress bar, early stop and wall-clock budget
  (:func:`transient.solvers.longrun.run_long`).

Each is validated on creation through :mod:`transient.checks` (one-line errors naming the parameter, its
value, its unit and the allowed range) and is immutable, so one object can key a checkpoint
(:meth:`Integration.key`) and be shared by many runs. A run takes them as objects
(``integration=Integration(rtol=1e-8)``); the loose keywords of earlier releases (``rtol=1e-8``) still work
for one release through :func:`~transient.solvers.legacy.run_settings`, with a ``DeprecationWarning`` naming the new spelling.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from transient.checks import (ATOL_FLOOR, ATOL_WHY, check_bool, check_choice, check_int, check_positive, check_range,
                              check_rtol)
from transient.solvers.integrate import LINEAR_SOLVERS, METHODS
from transient.solvers.legacy import keyword_table, run_settings  # noqa: F401 (the models' door)

#: Film formulations of the journal orbit: the universal variable (every method) or the content ``H theta``.
FORMULATIONS = ("content", "universal")
#: The per-stage film criterion of ``rk4`` when ``inner_tolerance`` is left out (Rho & Kim's eq. 6).
RK4_INNER_TOLERANCE = 1e-6
#: The settings of :class:`Integration` that only some methods use, by method (the others are refused when given):
#: ``linear_solver`` the SUNDIALS methods, ``dt`` and ``inner_tolerance`` the fixed-step ``rk4``,
#: ``steps_per_revolution`` ``rk4`` (its steps) and ``bdf2`` (its least number of steps), ``max_order`` ``bdf2``.
METHOD_SETTINGS = {"cvode": ("linear_solver",), "ida": ("linear_solver",), "bdf": (), "radau": (), "lsoda": (),
                   "rk4": ("dt", "inner_tolerance", "steps_per_revolution"), "bdf2": ("steps_per_revolution", "max_order")}


@dataclass(frozen=True)
class Integration:
    """How to integrate a run.

    ``method`` one of :data:`~transient.solvers.integrate.METHODS`; ``rtol`` in (0, 1) [-]; ``atol`` [-] (on
    the model's dimensionless states) in [1e-30, 1]; ``formulation`` ``None`` (the model's default),
    ``"universal"`` or ``"content"``; ``steps_per_revolution`` [1/rev] ``None`` (the method's default) or in
    [4, 1e7] (``rk4``: its fixed steps; ``bdf2``: its least number of steps); ``inner_tolerance`` [-] > 0
    (``rk4``: the per-stage film criterion; default ``RK4_INNER_TOLERANCE``); ``max_order`` [-] ``None`` (the
    model's default) or an integer in [2, 5] (``bdf2``: the highest order of its variable-order BDF); ``dt`` [-] ``None`` or > 0 (the
    fixed step of ``rk4`` in the model's time unit); ``linear_solver`` one of
    :data:`~transient.solvers.integrate.LINEAR_SOLVERS` (the SUNDIALS methods ``cvode`` and ``ida``).

    A setting the chosen method does not use is refused, naming the setting and the method
    (:data:`METHOD_SETTINGS`): ``Integration(method="bdf2", dt=0.5)`` is an error, not a silent no-op."""

    method: str = "ida"
    rtol: float = 1e-6
    atol: float = 1e-9
    formulation: str | None = None
    steps_per_revolution: float | None = None
    inner_tolerance: float | None = None
    dt: float | None = None
    max_order: int | None = None
    linear_solver: str = "auto"

    def __post_init__(self):
        check_choice("method", self.method, METHODS)
        _set(self, "rtol", check_rtol(self.rtol))
        _set(self, "atol", check_range("atol", self.atol, "-", ATOL_FLOOR, 1.0, why=ATOL_WHY))
        if self.formulation is not None:
            check_choice("formulation", self.formulation, FORMULATIONS)
        if self.steps_per_revolution is not None:
            _set(self, "steps_per_revolution", check_range("steps_per_revolution", self.steps_per_revolution,
                                                           "1/rev", 4, 1e7))
        if self.inner_tolerance is not None:
            _set(self, "inner_tolerance", check_positive("inner_tolerance", self.inner_tolerance, "-"))
        if self.dt is not None:
            _set(self, "dt", check_positive("dt", self.dt, "-"))
        if self.max_order is not None:
            _set(self, "max_order", check_int("max_order", self.max_order, "-", 2, 5))
        check_choice("linear_solver", self.linear_solver, LINEAR_SOLVERS)
        for name, unit, unused in (("steps_per_revolution", " [1/rev]", self.steps_per_revolution is None),
                                   ("inner_tolerance", " [-]", self.inner_tolerance is None),
                                   ("dt", " [-]", self.dt is None),
                                   ("max_order", " [-]", self.max_order is None),
                                   ("linear_solver", "", self.linear_solver == "auto")):
            if not unused and name not in METHOD_SETTINGS.get(self.method, ()):
                users = [m for m in METHODS if name in METHOD_SETTINGS.get(m, ())]
                raise ValueError(f"{name} = {getattr(self, name)!r}{unit} is not used by method {self.method!r}; "
                                 f"allowed: {name} with method {' or '.join(map(repr, users))}, or leave it out")
        if self.method == "rk4" and self.inner_tolerance is None:
            _set(self, "inner_tolerance", RK4_INNER_TOLERANCE)

    def key(self) -> dict:
        """The settings that change a run of this method (the others ``None``), to key a checkpoint."""
        fixed = self.method == "rk4"
        extra = dict(max_order=self.max_order) if self.method == "bdf2" else {}
        return extra | dict(method=self.method, rtol=None if fixed else self.rtol, atol=None if fixed else self.atol,
                    steps_per_revolution=self.steps_per_revolution if self.method in ("rk4", "bdf2") else None,
                    inner_tolerance=self.inner_tolerance if fixed else None)


@dataclass(frozen=True)
class Recording:
    """What a run keeps: ``outputs_per_revolution`` [1/rev] an integer in [1, 1e6]; ``record`` the extra
    series (names the model knows; a single name is taken as a one-element tuple); ``record_from_revolution``
    [rev] >= 0: field series are stored only from there on."""

    outputs_per_revolution: int = 100
    record: tuple = ()
    record_from_revolution: float = 0.0

    def __post_init__(self):
        _set(self, "outputs_per_revolution", check_int("outputs_per_revolution", self.outputs_per_revolution,
                                                       "1/rev", 1, 1e6))
        if not isinstance(self.record, (str, tuple, list)):
            raise ValueError(f"record = {self.record!r}; allowed: a series name or a tuple of them")
        record = (self.record,) if isinstance(self.record, str) else tuple(self.record)
        bad = [r for r in record if not isinstance(r, str)]
        if bad:
            raise ValueError(f"record = {self.record!r}: series are named by strings, got {bad[0]!r}")
        _set(self, "record", record)
        _set(self, "record_from_revolution", check_range("record_from_revolution", self.record_from_revolution,
                                                         "rev", 0.0, math.inf, high_open=True))

    def check_names(self, allowed) -> None:
        """Raise naming the first series this model cannot record."""
        bad = [r for r in self.record if r not in allowed]
        if bad:
            raise ValueError(f"record: unknown series {bad}; allowed: {tuple(allowed)}")


@dataclass(frozen=True)
class LongRun:
    """How a long run is driven (:func:`transient.solvers.longrun.run_long`).

    ``chunk_revolutions`` [rev] ``None`` (the whole run, or 10 with a checkpoint) or > 0; ``checkpoint`` a path
    ending in ``.npz`` or ``None``; ``resume`` a flag; ``progress`` ``None`` (a bar when there is more than one
    chunk) or a flag; ``stop`` ``None`` or ``stop(result_so_far) -> str | None``; ``time_budget`` [s of wall
    time] ``None`` or > 0."""

    chunk_revolutions: float | None = None
    checkpoint: str | Path | None = None
    resume: bool = False
    progress: bool | None = None
    stop: Callable | None = None
    time_budget: float | None = None

    def __post_init__(self):
        if self.chunk_revolutions is not None:
            _set(self, "chunk_revolutions", check_positive("chunk_revolutions", self.chunk_revolutions, "rev"))
        if self.checkpoint is not None and not str(self.checkpoint).endswith(".npz"):
            raise ValueError(f"checkpoint = {str(self.checkpoint)!r}: the file name must end in .npz")
        check_bool("resume", self.resume)
        if self.progress is not None:
            check_bool("progress", self.progress)
        if self.stop is not None and not callable(self.stop):
            raise ValueError(f"stop = {self.stop!r} is not callable; allowed: None or stop(result) -> str | None")
        if self.time_budget is not None:
            _set(self, "time_budget", check_positive("time_budget", self.time_budget, "s"))


def requested_method(integration, legacy: dict, default: str = "ida"):
    """The method a run's caller asks for -- ``integration.method``, else the deprecated ``method=`` keyword, else
    the run's ``default`` -- before the settings object is built, so the model's door
    (:func:`~transient.solvers.integrate.check_method`) names itself and the methods it takes."""
    if integration is not None:
        return getattr(integration, "method", default)
    return legacy.get("method", default)


def check_unused(owner: str, argument: str, obj, names) -> None:
    """Refuse, naming it, a field of the settings object ``obj`` among ``names`` that ``owner`` does not use and
    that differs from its default: ``check_unused("RotorBearingSystem.run", "recording", rc, ("record",))``."""
    default = type(obj)()
    for name in names:
        if getattr(obj, name) != getattr(default, name):
            raise ValueError(f"{owner}: {argument}={type(obj).__name__}({name}={getattr(obj, name)!r}) is not used "
                             f"by this model; allowed: leave {name} out")


def _set(obj, name, value):
    object.__setattr__(obj, name, value)
