"""Journal bearing with a mass-conserving Elrod film and the unbalanced rotor on it (seed 003, Rho & Kim)."""

from transient.models.journal.bearing import FilmState, Groove, JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit, OrbitResult
from transient.models.journal.periodic import (PeriodicOrbit, ResponseCurve, WhirlResponse, periodic_response,
                                               response_curve, stability_onset)

__all__ = ["FilmState", "Groove", "JournalBearing", "JournalOrbit", "OrbitResult", "PeriodicOrbit", "ResponseCurve",
           "WhirlResponse", "omega", "periodic_response", "response_curve", "stability_onset"]
