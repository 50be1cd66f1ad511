"""``transient.integrate`` is a documented path of the integrator facade: it lives in
:mod:`transient.solvers.integrate`."""

from transient.solvers.integrate import METHODS, Problem, Result, Stats, solve  # noqa: F401
