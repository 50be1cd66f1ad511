"""transient: method-of-lines time-domain simulator for lubricated machine elements.

SI units at the API. See docs/architecture.md for how the layers fit together.

Public API (re-exported here):

* integration: :func:`solve`, :class:`Problem`, :class:`Solution`, :class:`Stats`, :class:`Steps` (its step
  control); run settings :class:`Integration`, :class:`Recording`, :class:`LongRun` (``JournalOrbit.run``,
  ``RotorBearingSystem.run``, ``ThrustBallBearing.sequence``) and :class:`TrackSettings` (the ball sequence's
  track between passes)
* results: :class:`Result` (the base of every result: units, save/load, summary), :func:`load_result`
* journal bearing (Rho & Kim): :class:`JournalBearing`, its oil feeds :class:`Groove`, :class:`OilHole`,
  :class:`CircumferentialGroove`, :class:`JournalOrbit` (with ``periodic_response`` and ``response_curve``:
  periodic orbits by shooting), :func:`stability_onset`; rough surfaces and mixed lubrication: :class:`Roughness`
  (``JournalBearing(..., roughness=)``), :func:`stribeck_curve` (:class:`StribeckCurve`);
  bearing noise: :func:`bearing_noise` (its settling run: :class:`Settling`), :func:`a_weighting`;
  thermal (THD) films: :class:`ThermalFilm` (``JournalBearing(..., thermal=)``) with its walls
  :class:`BushConvection`, :class:`IsothermalShaft`
* layered boundary films and shear-thinning bulk (Jang): :class:`BoundaryLayers` (``JournalBearing(...,
  layers=)``), :class:`Gecim`, :class:`Newtonian`, :class:`LayeredFilm` (the pointwise flow law)
* thrust ball bearing starvation (Jeong et al.): :class:`ThrustBallBearing`
* rotors on journal bearings: :class:`Rotor` (from matrices, ``Rotor.example()``, ``Rotor.from_ross``),
  :class:`RotorBearingSystem` (equilibrium, time runs with a transient film per bearing, linear unbalance
  response, stability threshold)
* squeeze-film dampers on the journal film at zero spin: :class:`SqueezeFilmDamper` (``circular_orbit``: the film
  forces on a circular centred orbit)
* EHL of a tilted tapered roller (Park): :class:`LineContact`, :class:`TaperedRoller`, :class:`RollerContact`
* EHL point contacts, flooded or starved, steady and transient: :class:`PointContact`
* rough surfaces and asperity contact (Lee & Rhim): :class:`RoughSurface`, :func:`greenwood_tripp`,
  :class:`AsperityContact`, :class:`DiscreteDensity`, :func:`steel_asperity_contact`,
  :func:`pressure_flow_factors`, :func:`shear_flow_factor`, :func:`contact_factor`, :class:`ThrustPad`
"""

import os as _os

# scikit-sundae's SuperLU_MT runs on an OpenMP runtime whose idle threads spin by default: with the other
# core busy that made every CVODE/IDA call 1.5x (journal orbit) to 5x (small systems) slower. Passive
# waiting costs nothing measurable on an idle machine. Set before sksundae loads; a user's value wins.
_os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
# Dense LU (EHL elasticity) through a multi-threaded OpenBLAS: with the other core busy a 401 x 401 LU took
# 190 ms on two threads against 4.4 ms on one. Takes effect only if numpy is not loaded yet; a user's value wins.
_os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from transient._version import __version__  # noqa: E402,F401
from transient.analysis.acoustics import a_weighting
from transient.models.ball import ThrustBallBearing
from transient.models.ball.settings import TrackSettings
from transient.models.damper import SqueezeFilmDamper
from transient.models.journal import CircumferentialGroove, Groove, JournalBearing, JournalOrbit, OilHole, stability_onset
from transient.models.journal.roughness import Roughness
from transient.models.journal.thermal_settings import BushConvection, IsothermalShaft, ThermalFilm
from transient.models.journal.speed_law import SpeedProfile
from transient.models.pad import ThrustPad
from transient.models.point import PointContact
from transient.models.roller import LineContact, RollerContact, TaperedRoller
from transient.models.rotor import Rotor, RotorBearingSystem
from transient.physics.asperity import AsperityContact, DiscreteDensity, greenwood_tripp, steel_asperity_contact
from transient.physics.flow_factors import contact_factor, pressure_flow_factors, shear_flow_factor
from transient.physics.layered import BoundaryLayers, Gecim, LayeredFilm, Newtonian
from transient.results import Result, load_result
from transient.solvers.integrate import Problem, Solution, Stats, Steps, solve
from transient.solvers.settings import Integration, LongRun, Recording
from transient.study.noise import bearing_noise  # the public API re-exports the noise protocol
from transient.study.settle import Settling
from transient.study.stribeck import StribeckCurve, stribeck_curve
from transient.surfaces.roughness import RoughSurface

__all__ = [
    "AsperityContact", "BoundaryLayers", "BushConvection", "IsothermalShaft", "ThermalFilm", "SpeedProfile", "CircumferentialGroove", "DiscreteDensity", "Gecim", "Groove", "Integration",
    "LayeredFilm", "LongRun", "Newtonian", "JournalBearing", "JournalOrbit", "LineContact", "OilHole", "PointContact",
    "Problem", "Recording", "Result", "RollerContact", "Rotor", "RotorBearingSystem", "TaperedRoller",
    "Roughness", "RoughSurface", "Settling", "Solution", "SqueezeFilmDamper", "Stats", "Steps", "StribeckCurve",
    "ThrustBallBearing", "ThrustPad", "TrackSettings", "a_weighting", "bearing_noise", "contact_factor",
    "stribeck_curve",
    "greenwood_tripp", "load_result", "pressure_flow_factors", "stability_onset", "shear_flow_factor", "solve", "steel_asperity_contact",
]
