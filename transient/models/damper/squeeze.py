"""Pure squeeze of a damper's film: the journal, not turning, moves along the line of centres.

The damper's Reynolds-condition film (:class:`~transient.models.journal.reynolds_film.ReynoldsFilm`: the
incompressible film with ``p >= p_c`` as a complementarity problem, the discrete Swift-Stieber condition) with its
Couette conductance set to zero, so that only the squeeze term drives it::

    div(H^3 / 2 grad P) = dH/dtau = -eps' cos(phi)    (phi from the minimum film, eps' = d(e/c)/dtau)

in the film's groups (``p = p_c + p0 P``, ``p0 = 6 mu omega (R/c)^2``, ``tau = omega t`` for any ``omega``: the
solution scales with ``eps' omega``). The journal at ``(eps, 0)`` moving at ``(eps', 0)``: ``eps' > 0`` towards the
minimum film (the film there is squeezed out), ``eps' < 0`` back towards the centre. This is the case Butenschoen
(1976) tabulates as the "Verdraengung" (displacement) Sommerfeld number ``So_D = F psi^2 / (B D eta |eps_dot|)``
with ``psi = 2 c / D`` (``tests/data/butenschoen_squeeze.json``).
"""

from __future__ import annotations


from transient.checks import check_range
from transient.models.journal.reynolds_film import ReynoldsFilm
from transient.models.journal.scales import film_scales

#: the film's time unit: any speed serves (the pressure scales with the squeeze rate); this one is in range
UNIT_RPM = 1000.0


class PureSqueezeFilm(ReynoldsFilm):
    """The Reynolds-condition film without Couette flow (a journal that does not turn): module docstring."""

    def _fields(self, X, Y):
        super()._fields(X, Y)
        self.c[:] = 0.0
        self.dc_dq[:] = 0.0


def pure_squeeze_force(damper, eccentricity_ratio, eccentricity_rate) -> tuple[float, float]:
    """The film force [N] on the journal of ``damper`` (a :class:`~transient.models.damper.SqueezeFilmDamper`,
    its geometry, feeds, ends and pressures) at ``eccentricity_ratio`` moving along the line of centres at
    ``eccentricity_rate`` [1/s] (d(e/c)/dt; > 0 towards the minimum film): (along the line of centres, + outwards;
    across it), on the Reynolds-condition film at zero spin (module docstring)."""
    eps = check_range("eccentricity_ratio", eccentricity_ratio, "-", 0.0, 1.0, high_open=True)
    rate = check_range("eccentricity_rate", eccentricity_rate, "1/s", -1e9, 1e9)
    b = damper.bearing
    film = PureSqueezeFilm(b.grid, film_scales(b, UNIT_RPM), b.flow_law)
    P, _ = film.solve(eps, 0.0, VX=rate / film.scales.omega, VY=0.0)
    fx, fy = film.force(P, eps, 0.0)
    return float(fx * film.scales.force_scale), float(fy * film.scales.force_scale)
