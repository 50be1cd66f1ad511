"""Squeeze-film damper: a non-rotating journal (held by an anti-rotation pin) whirling in an oil film, on the journal
bearing's mass-conserving Elrod film (or its Reynolds-condition film).

The film is :class:`~transient.models.journal.bearing.JournalBearing`'s, not a second solver. For a circular centred
orbit the problem is steady in the frame that whirls with the journal: there ``h = c (1 - eps cos phi)`` is fixed
and ``dh/dt = -omega dh/dphi``, so the squeeze term of the Reynolds (and of Elrod's content) equation,
``d(rho theta h)/dt``, is a Couette transport of the content at the mean velocity ``-omega R``: exactly the steady
journal bearing whose surfaces' mean velocity is ``U / 2 = -omega R``, a journal spinning at ``-2 omega`` at a fixed
eccentricity. The damper therefore solves the bearing's steady film at the speed ``2 omega`` with the angles
mirrored (the whirl runs against the bearing's direction of rotation); cavitation, and with it the pi-film /
2-pi-film limits, comes from the film's own mass balance and supply, not from a switch. The feeds this frame keeps
steady are those all round the damper: the ends (end feed) and circumferential grooves; holes and axial grooves turn
in the whirling frame (they need a time run). Closed forms to check against: :mod:`.closed_forms`.
"""

from __future__ import annotations

import numpy as np

from transient.checks import check_choice, check_instance, check_positive, check_range
from transient.models.damper.closed_forms import FILMS, land_forces
from transient.models.damper.results import CircularOrbit
from transient.models.journal.bearing import SPEED_RANGE_RPM, JournalBearing
from transient.models.journal.feeds import CircumferentialGroove
from transient.units import rpm_to_rad_s

#: The damper's feeds by name: ``"ends"`` (both ends held at the supply pressure) and ``"groove"`` (a circumferential
#: groove at the mid-plane, the ends at ``ambient_pressure``); or pass :class:`CircumferentialGroove` objects.
FEEDS = ("ends", "groove")
#: The damper's ends: ``"open"`` (held at their pressure) or ``"closed"`` (sealed: no flow through them).
END_SEALS = ("open", "closed")
#: The journal bearing's films (``cavitation=``).
CAVITATION = ("elrod", "reynolds")


class _DamperFilm(JournalBearing):
    """The journal bearing's film with closed ends (no flow through them)."""

    end_kind = "symmetry"


class SqueezeFilmDamper:
    """Squeeze-film damper on the journal bearing's film at zero spin (module docstring).

    Parameters (SI)
    ----------
    diameter, length, clearance [m] : journal diameter D, damper (land) length L, radial clearance c.
    viscosity [Pa s] : the oil's mu.
    supply_pressure [Pa, absolute] : the feed's pressure (above ``cavitation_pressure`` for the Elrod film: at it the
        film has nothing to fill from).
    feed : ``"ends"`` (default; both ends at the supply pressure), ``"groove"`` (a circumferential groove of
        ``groove_width`` at the mid-plane at the supply pressure, the ends at ``ambient_pressure``), or a
        :class:`CircumferentialGroove` or a sequence of them (each at its own pressure, default the supply pressure).
    groove_width [m] : width of the ``"groove"`` feed (default L / 10).
    end_seals : ``"open"`` (default: the ends held at their pressure) or ``"closed"`` (sealed ends: no oil leaves
        through them; needs a groove feed).
    ambient_pressure, cavitation_pressure [Pa, absolute] : the pressure outside the ends of a groove-fed damper and
        the film's cavitation pressure (both 0 by default).
    centring_stiffness [N/m] : the centring spring (squirrel cage) in parallel with the film, or None (none).
    cavitation : ``"elrod"`` (default: the mass-conserving film) or ``"reynolds"`` (the Reynolds-condition film,
        ``p >= p_c`` without mass conservation: at the supply pressure ``p_c`` it is the classical pi-film).
    bulk_modulus [Pa] : the oil's (Elrod film).
    grid : (n_theta, n_axial) cells, n_axial over the half length when the damper is symmetric about its mid-plane.
    """

    def __init__(self, diameter, length, clearance, viscosity, supply_pressure, *, feed="ends", groove_width=None,
                 end_seals="open", ambient_pressure=0.0, cavitation_pressure=0.0, centring_stiffness=None,
                 cavitation="elrod", bulk_modulus=1e9, grid=(96, 12)):
        self.cavitation = check_choice("cavitation", cavitation, CAVITATION)
        self.end_seals = check_choice("end_seals", end_seals, END_SEALS)
        p_c = check_range("cavitation_pressure", cavitation_pressure, "Pa", 0.0, 1e9, why="(absolute)")
        self.supply_pressure = check_range("supply_pressure", supply_pressure, "Pa", p_c, 1e9,
                                           low_open=cavitation == "elrod",
                                           why=f"(absolute; above cavitation_pressure = {p_c:g} Pa for the Elrod film, "
                                               "which has nothing to fill from at it)")
        self.ambient_pressure = check_range("ambient_pressure", ambient_pressure, "Pa", p_c, 1e9,
                                            why=f"(absolute; at least cavitation_pressure = {p_c:g} Pa)")
        self.centring_stiffness = None if centring_stiffness is None else check_range(
            "centring_stiffness", centring_stiffness, "N/m", 0.0, 1e12, why="(a centring spring; None: none)")
        length = check_positive("length", length, "m")
        self.feed, groove = self._feeds(feed, groove_width, length)
        if self.end_seals == "closed" and groove is None:
            raise ValueError(f"end_seals = 'closed' with feed = {self.feed!r}: a damper fed through its ends cannot "
                             "have them closed; allowed: end_seals = 'open', or feed = 'groove' or "
                             "CircumferentialGroove(...)")
        kind = _DamperFilm if self.end_seals == "closed" else JournalBearing
        self.bearing = kind(diameter, length, clearance, viscosity, bulk_modulus=bulk_modulus,
                         supply_pressure=self.supply_pressure, groove=groove, grid=grid, cavitation_pressure=p_c,
                         ambient_pressure=self.supply_pressure if groove is None else self.ambient_pressure,
                         cavitation=cavitation)
        # the journal bearing whose film this is (the rotor system runs it at zero spin)
        self.diameter, self.length, self.clearance = self.bearing.diameter, self.bearing.length, self.bearing.clearance
        self.radius, self.viscosity = self.bearing.radius, self.bearing.viscosity

    @staticmethod
    def _feeds(feed, groove_width, length):
        """The feed's name or grooves, and the journal film's ``groove=`` (None: fed through the ends)."""
        if isinstance(feed, str):
            check_choice("feed", feed, FEEDS)
            if feed == "ends":
                return feed, None
            w = 0.1 * length if groove_width is None else check_range(
                "groove_width", groove_width, "m", 0.0, length, low_open=True, high_open=True,
                why=f"(inside the damper of length {length:g} m)")
            return feed, CircumferentialGroove(width=w)
        grooves = (feed,) if isinstance(feed, CircumferentialGroove) else feed
        allowed = ("'ends', 'groove', a CircumferentialGroove or a sequence of them (holes and axial grooves turn "
                   "in the whirling frame of a circular orbit)")
        check_instance("feed", grooves, (list, tuple), allowed)
        for i, g in enumerate(grooves):
            check_instance(f"feed[{i}]", g, CircumferentialGroove, allowed)
        if not grooves:
            raise ValueError(f"feed = {feed!r} names no groove; allowed: {allowed}")
        return tuple(grooves), list(grooves)

    def __repr__(self):
        return (f"SqueezeFilmDamper(diameter={self.diameter:g} m, length={self.length:g} m, "
                f"clearance={self.clearance:g} m, viscosity={self.viscosity:g} Pa s, "
                f"supply_pressure={self.supply_pressure:g} Pa, feed={self.feed!r}, end_seals={self.end_seals!r}, "
                f"cavitation={self.cavitation!r}, grid={self.bearing.grid_shape})")

    @staticmethod
    def check_whirl(whirl_speed_rpm) -> float:
        """A whirl speed [rpm]: the film at twice it is in the journal bearing's speed range."""
        lo, hi = SPEED_RANGE_RPM
        return check_range("whirl_speed_rpm", whirl_speed_rpm, "rpm", 0.5 * lo, 0.5 * hi)

    def circular_orbit(self, eccentricity_ratio, whirl_speed_rpm) -> CircularOrbit:
        """The film of the journal whirling at ``whirl_speed_rpm`` on a circular orbit of radius ``eps c`` about the
        damper's centre: the forces on the journal along and across the line of centres, the pressure and the film
        content (:class:`~transient.models.damper.results.CircularOrbit`). A steady solve in the whirling frame:
        the bearing's film at ``2 omega`` with the angles mirrored (module docstring)."""
        eps = check_range("eccentricity_ratio", eccentricity_ratio, "-", 0.0, 1.0, low_open=True, high_open=True)
        w = self.check_whirl(whirl_speed_rpm)
        s = self.bearing.steady_state(eps, 2.0 * w)
        # the bearing's angles run from the top (the minimum film at 180 deg with the journal at +x) in its direction
        # of rotation, against the whirl: from the minimum film in the whirl direction is 180 deg - angle
        order = np.argsort(np.mod(180.0 - s.angle_deg, 360.0), kind="stable")
        k = 0.0 if self.centring_stiffness is None else self.centring_stiffness
        return CircularOrbit(
            eccentricity_ratio=eps, whirl_speed_rpm=w, clearance=self.clearance, radial_force=float(s.force[0]),
            tangential_force=-float(s.force[1]), spring_force=-k * eps * self.clearance,
            pressure=s.pressure[:, order], film_content=s.film_content[:, order],
            angle_deg=np.mod(180.0 - s.angle_deg, 360.0)[order], z=s.z, iterations=s.newton_iterations,
            success=s.success, message=s.message)

    def pure_squeeze(self, eccentricity_ratio, eccentricity_rate) -> tuple[float, float]:
        """The film force [N] (along the line of centres, + outwards; across it) on the journal at
        ``eccentricity_ratio`` moving along the line of centres at ``eccentricity_rate`` [1/s] (d(e/c)/dt, > 0
        towards the minimum film), on this damper's Reynolds-condition film at zero spin
        (:mod:`~transient.models.damper.squeeze`; Butenschoen's displacement case)."""
        from transient.models.damper.squeeze import pure_squeeze_force

        return pure_squeeze_force(self, eccentricity_ratio, eccentricity_rate)

    def lands(self) -> list[tuple[float, bool]]:
        """The film's lands on the modelled grid: (axial length [m], closed: one end sealed shut), the stretches of
        film between the feeds and the ends (the grooves' edges are the grid's cell faces)."""
        g = self.bearing.grid
        edges = g.z.edges * self.radius
        fed = (self.bearing.feed_cells.reshape(g.nz, g.nx) >= 0).all(axis=1)
        if self.bearing.symmetric:  # the whole length from the half
            edges = np.concatenate([-edges[:0:-1], edges])
            fed = np.concatenate([fed[::-1], fed])
        closed_ends = self.end_seals == "closed"
        out, start = [], None
        for i in range(fed.size + 1):
            if i < fed.size and not fed[i]:
                start = i if start is None else start
            elif start is not None:
                touches = start == 0 or i == fed.size
                out.append((float(edges[i] - edges[start]), closed_ends and touches))
                start = None
        return out

    def short_damper_forces(self, eccentricity_ratio, whirl_speed_rpm, film="2pi") -> tuple:
        """The short-damper closed forms (:mod:`~transient.models.damper.closed_forms`) on this damper's
        :meth:`lands`: (radial, tangential) force [N] of the ``"pi"`` or ``"2pi"`` film."""
        check_choice("film", film, FILMS)
        w = rpm_to_rad_s(self.check_whirl(whirl_speed_rpm))
        return land_forces(self.lands(), eccentricity_ratio, w, self.viscosity, self.radius, self.clearance, film)
