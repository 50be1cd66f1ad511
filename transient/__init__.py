"""transient: method-of-lines time-domain simulator for lubricated machine elements.

SI units at the API. See docs/architecture.md for how the layers fit together.

Public API (re-exported here):

* integration: :func:`solve`, :class:`Problem`, :class:`Result`, :class:`Stats`
* journal bearing (seed 003): :class:`JournalBearing`, :class:`Groove`, :class:`JournalOrbit`;
  bearing noise: :func:`bearing_noise`, :func:`a_weighting`
* thrust ball bearing starvation (seed 002): :class:`ThrustBallBearing`
* rough surfaces and asperity contact (seed 000): :class:`RoughSurface`, :func:`greenwood_tripp`,
  :class:`AsperityContact`, :class:`DiscreteDensity`, :func:`steel_asperity_contact`,
  :func:`pressure_flow_factors`, :func:`shear_flow_factor`, :func:`contact_factor`, :class:`ThrustPad`
"""

from transient.analysis.acoustics import a_weighting, bearing_noise
from transient.film.asperity import AsperityContact, DiscreteDensity, greenwood_tripp, steel_asperity_contact
from transient.film.flow_factors import contact_factor, pressure_flow_factors, shear_flow_factor
from transient.film.roughness import RoughSurface
from transient.integrate import Problem, Result, Stats, solve
from transient.models.ball_starvation import ThrustBallBearing
from transient.models.journal import Groove, JournalBearing
from transient.models.journal_orbit import JournalOrbit
from transient.models.thrust_pad import ThrustPad

__all__ = [
    "a_weighting", "bearing_noise", "AsperityContact", "DiscreteDensity", "Groove", "JournalBearing", "JournalOrbit", "Problem", "Result",
    "RoughSurface", "Stats", "ThrustBallBearing", "ThrustPad", "contact_factor", "greenwood_tripp", "pressure_flow_factors",
    "shear_flow_factor", "solve", "steel_asperity_contact",
]
__version__ = "0.1.0"
