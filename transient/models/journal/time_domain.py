"""What the time-domain films take: one statement for the journal orbit and the rotor system.

:class:`~transient.models.journal.JournalOrbit` and :class:`~transient.models.rotor.RotorBearingSystem` integrate the
bearing's film in time. A bearing setting they do not integrate yet is refused at their door, by
:func:`check_time_domain`, in one wording: ``<owner>: <where>cavitation = 'reynolds'; allowed: 'elrod' (...)``.
:data:`NOT_IN_TIME_DOMAIN` is the statement: one entry per setting, naming the models that refuse it, so lifting a
refusal for a model is one line.
"""

from __future__ import annotations

from typing import NamedTuple


class Refusal(NamedTuple):
    """A bearing setting a time-domain model does not take: ``allowed`` the one value it takes; ``shown(value)``
    how a refused value reads in the message (with its unit); ``why`` what the time-domain film is instead and
    which analyses take the setting; ``refused_by`` the models that refuse it."""

    allowed: object
    shown: str
    why: str
    refused_by: tuple


#: The bearing settings the time-domain films do not take, by the bearing's attribute (``shown`` a format of the
#: refused ``value``). Lifting one for a model: take the model out of ``refused_by`` (the last one: drop the entry).
NOT_IN_TIME_DOMAIN = {
    "cavitation": Refusal("elrod", "{value!r}", "the time-domain films are the mass-conserving Elrod film; the "
                          "Reynolds-condition film serves the steady and linear analyses",
                          ("JournalOrbit", "RotorBearingSystem")),
}


def check_time_domain(owner: str, bearing, where: str = "") -> None:
    """Refuse (one-line ``ValueError``) a ``bearing`` whose settings the time-domain model ``owner``
    (``"JournalOrbit"``, ``"RotorBearingSystem"``) does not take (:data:`NOT_IN_TIME_DOMAIN`); ``where`` names the
    bearing in the message (e.g. ``"bearings[2] "``)."""
    for name, r in NOT_IN_TIME_DOMAIN.items():
        value = getattr(bearing, name, r.allowed)
        if owner in r.refused_by and value != r.allowed:
            allowed = repr(r.allowed) if not isinstance(r.allowed, tuple) else f"{r.allowed}"
            raise ValueError(f"{owner}: {where}{name} = {r.shown.format(value=value)}; allowed: {allowed} "
                             f"({r.why})")
