"""EHL point contacts (circular and elliptical): steady and transient, fully flooded or starved.

:class:`PointContact` (mass-conserving fractional film with Fischer-Burmeister complementarity, DC-FFT
elasticity; :mod:`transient.models.point.ehl_problem`).
"""

from transient.models.point.contact import PointContact

__all__ = ["PointContact"]
