"""transient: method-of-lines time-domain simulator for lubricated machine elements.

SI units at the API. See docs/architecture.md for how the layers fit together.
"""

from transient.integrate import Problem, Result, Stats, solve

__all__ = ["Problem", "Result", "Stats", "solve"]
__version__ = "0.1.0"
