"""EHL of line and finite line contacts: the tilted tapered roller of Park.

:class:`LineContact` (1-D, infinitely long), :class:`TaperedRoller` (geometry), :class:`RollerContact`
(finite line contact: dry footprint, steady EHL, transient).
"""

from transient.models.roller.contact import RollerContact
from transient.models.roller.geometry import TaperedRoller
from transient.models.roller.line_contact import LineContact

__all__ = ["LineContact", "RollerContact", "TaperedRoller"]
