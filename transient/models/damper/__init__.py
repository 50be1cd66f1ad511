"""Squeeze-film dampers on the journal bearing's film at zero spin: circular centred orbits and their closed forms."""

from transient.models.damper.damper import SqueezeFilmDamper
from transient.models.damper.results import CircularOrbit

__all__ = ["CircularOrbit", "SqueezeFilmDamper"]
