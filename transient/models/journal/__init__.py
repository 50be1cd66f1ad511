"""Journal bearing with a mass-conserving Elrod film and the unbalanced rotor on it (seed 003, Rho & Kim)."""

from transient.models.journal.bearing import FilmState, Groove, JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit, OrbitResult

__all__ = ["FilmState", "Groove", "JournalBearing", "JournalOrbit", "OrbitResult", "omega"]
