"""Rotors on journal bearings: a rotor from matrices (or from ROSS), any number of journal bearings with their
own transient Elrod films at its nodes, static equilibrium, time runs, linear unbalance response and stability."""

from transient.models.rotor.results import (PeriodicResponse, RotorEquilibrium, RotorResponseCurve, RotorRunResult,
                                           UnbalanceResponse)
from transient.models.rotor.rotor import Rotor
from transient.models.rotor.system import RotorBearingSystem

__all__ = ["PeriodicResponse", "Rotor", "RotorBearingSystem", "RotorEquilibrium", "RotorResponseCurve", "RotorRunResult",
           "UnbalanceResponse"]
