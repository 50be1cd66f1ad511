"""Journal bearing with a mass-conserving Elrod film (or the classical Reynolds-condition film) and the
unbalanced rotor on it (Rho & Kim)."""

from transient.models.journal.bearing import JournalBearing, omega
from transient.models.journal.feeds import CircumferentialGroove, Groove, OilHole
from transient.models.journal.orbit import JournalOrbit
from transient.models.journal.periodic import (PeriodicOrbit, ResponseCurve, WhirlResponse, periodic_response,
                                               response_curve, stability_onset)
from transient.models.journal.results import FilmState, OrbitResult
from transient.models.journal.reynolds_film import ReynoldsFilm
from transient.models.journal.thermal_settings import BushConvection, IsothermalShaft, ThermalFilm

__all__ = ["BushConvection", "CircumferentialGroove", "IsothermalShaft", "ThermalFilm", "FilmState", "Groove", "JournalBearing", "JournalOrbit", "OilHole", "OrbitResult",
           "PeriodicOrbit", "ResponseCurve", "ReynoldsFilm", "WhirlResponse", "omega", "periodic_response",
           "response_curve", "stability_onset"]
