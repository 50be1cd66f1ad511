"""``transient.integrate`` is a documented path of the integrator facade: it lives in
:mod:`transient.solvers.integrate`."""

from transient.results import Result  # noqa: F401
from transient.solvers.integrate import METHODS, Problem, Solution, Stats, solve  # noqa: F401
