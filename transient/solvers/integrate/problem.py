"""What a model hands the integrator and what it gets back: :class:`Problem`, :class:`Stats`, :class:`Solution`,
:class:`Steps` (the step control a caller may set) and :class:`Settings`, the validated arguments of one
:func:`~transient.solvers.integrate.solve` call that every back end reads."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
import scipy.sparse as sp

from transient.checks import check_count, check_step, short_repr
from transient.results import Result, Stats, result_type


@dataclass
class Problem:
    """What a model hands to :func:`solve`.

    Callables fill their last argument in place (no return value), as SUNDIALS wants:

    * ``rhs(t, y, out)``: ``out = f(t, y)`` for ``y' = f(t, y)``. For a semi-explicit DAE the entries
      of ``out`` at the algebraic indices are ignored (used by ``rk4`` only).
    * ``residual(t, y, yp, out)``: ``out = F(t, y, y')`` (IDA). If absent, IDA uses ``y' - f(t, y)``.
    * ``jac_rhs(t, y, data)``: the CSC data array of ``df/dy`` in the order of ``jac_pattern``; with no
      ``jac_pattern`` the Jacobian is dense and ``data`` is the (n, n) array to fill (small or dense
      problems, e.g. elastic contact).
    * ``jac_residual(t, y, yp, cj, data)``: ``dF/dy + cj dF/dy'``, CSC data in pattern order, or the
      (n, n) array when there is no pattern.
    * ``events(t, y, out)``: event functions; a zero crossing is an event.
    * ``algebraic_solve(t, y) -> y``: for ``rk4`` on a DAE, returns ``y`` with its algebraic part
      solved for the given differential part (the per-stage inner solve).
    * ``step_begin(t, y)``: for ``rk4``, called at the start of every step (e.g. to store the history
      a time-discretised inner solve needs).
    * ``step_solve``: for ``bdf2``, the model's own solve of one implicit step
      (:class:`~transient.solvers.integrate.stepper.StepSolve`); a problem with one needs no other callback.
    """

    y0: np.ndarray
    rhs: Callable | None = None
    residual: Callable | None = None
    yp0: np.ndarray | None = None
    jac_pattern: sp.spmatrix | None = None
    jac_rhs: Callable | None = None
    jac_residual: Callable | None = None
    algebraic: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    band: tuple[int, int] | None = None
    events: Callable | None = None
    n_events: int = 0
    event_terminal: Sequence[bool] | None = None
    event_direction: Sequence[int] | None = None
    algebraic_solve: Callable | None = None
    step_begin: Callable | None = None
    step_solve: object | None = None
    name: str = "problem"

    def __post_init__(self):
        if np.ndim(self.y0) != 1:
            raise ValueError(f"Problem '{self.name}': y0 must be a non-empty 1-D array (one entry per state), "
                             f"got {np.ndim(self.y0)}-D {np.asarray(self.y0).shape!r}: {short_repr(self.y0)}")
        self.y0 = np.ascontiguousarray(self.y0, dtype=float)
        if self.y0.ndim != 1 or self.y0.size == 0:
            raise ValueError(f"Problem '{self.name}': y0 must be a non-empty 1-D array, got shape {self.y0.shape}")
        if self.rhs is None and self.residual is None and self.step_solve is None:
            raise ValueError(f"Problem '{self.name}': give rhs (ODE) or residual (DAE), or both, or a step_solve")
        if self.yp0 is not None:
            if np.ndim(self.yp0) != 1:
                raise ValueError(f"Problem '{self.name}': yp0 must be a 1-D array like y0, got {short_repr(self.yp0)}")
            self.yp0 = np.ascontiguousarray(self.yp0, dtype=float)
            if self.yp0.shape != self.y0.shape:
                raise ValueError(f"Problem '{self.name}': yp0 shape {self.yp0.shape} != y0 shape {self.y0.shape}")
        self.algebraic = np.asarray(self.algebraic, dtype=np.int64)
        if self.jac_pattern is not None:
            pat = sp.csc_matrix(self.jac_pattern, dtype=float)
            pat.sort_indices()
            if pat.shape != (self.n, self.n):
                raise ValueError(f"Problem '{self.name}': jac_pattern shape {pat.shape} != ({self.n}, {self.n})")
            self.jac_pattern = pat
        if self.n_events:
            if self.events is None:
                raise ValueError(f"Problem '{self.name}': n_events={self.n_events} but no events function")
            self.event_terminal = list(self.event_terminal or [True] * self.n_events)
            self.event_direction = list(self.event_direction or [0] * self.n_events)

    @property
    def n(self) -> int:
        """Number of states."""
        return self.y0.size

    @property
    def is_dae(self) -> bool:
        return self.algebraic.size > 0


@result_type
class Solution(Result):
    """What :func:`solve` returns, for every method. ``y[k]`` is the state at ``t[k]`` (rows = output times;
    ``t`` in the problem's own time unit)."""

    t: np.ndarray
    y: np.ndarray | None
    yp: np.ndarray | None
    success: bool
    message: str
    method: str
    stats: Stats
    t_events: np.ndarray = field(default_factory=lambda: np.zeros(0))
    y_events: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    i_events: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    @property
    def y_final(self) -> np.ndarray:
        return self.y[-1]


@dataclass(frozen=True)
class Steps:
    """The step control of one :func:`~transient.solvers.integrate.solve`, validated on creation.

    ``dt`` the fixed step of ``rk4`` [the problem's time unit], finite and > 0 (required for ``rk4``, refused
    by no method: the adaptive ones ignore it); ``max_step``, ``first_step`` step limits of the adaptive methods
    [the problem's time unit], finite and >= 0 (0 = free); ``max_steps`` the most steps of the whole run, an
    integer >= 1."""

    dt: float | None = None
    max_step: float = 0.0
    first_step: float = 0.0
    max_steps: int = 1_000_000

    def __post_init__(self):
        if self.dt is not None:
            object.__setattr__(self, "dt", check_step("dt", self.dt))
        object.__setattr__(self, "max_step", check_step("max_step", self.max_step, free_zero=True))
        object.__setattr__(self, "first_step", check_step("first_step", self.first_step, free_zero=True))
        object.__setattr__(self, "max_steps", check_count("max_steps", self.max_steps))


@dataclass(frozen=True)
class Settings:
    """The arguments of one solve, validated once by :func:`~transient.solvers.integrate.solve` and read by every
    back end (a back end ignores what it does not use: ``dt`` for the adaptive ones, the tolerances for ``rk4``)."""

    method: str
    rtol: float
    atol: float | np.ndarray
    dt: float | None
    max_step: float
    first_step: float
    max_steps: int
    linear_solver: str
    options: dict
