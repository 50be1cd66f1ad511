"""The films of the ball passes from the numerical starved point contact (``ThrustBallBearing(contact="numerical")``).

Instead of Hamrock-Dowson's flooded film and the starvation law ``H_F ((m - 1)/(m_c - 1))^0.29``, each pass's
central and minimum film are those of :class:`~transient.models.point.PointContact` (mass-conserving fractional
film, the meniscus a result) with the pass's inlet film as the inlet layer. A layer at least as thick as the gap
everywhere on the contact's inlet boundary floods it exactly (the flooded solution, computed once); thinner
layers are solved each (cached per inlet film to four significant digits, so a periodic sequence solves each
level once), each from the solution of the nearest thicker layer solved so far (continuation in the layer,
:meth:`PointContact.layer_start`). A layer below 5 % of the flooded film ends the sequence before that pass,
flagged (:class:`LayerTooThin`: the contact runs dry); one the contact does not carry on its grid stops it with an
error naming the pass and the inlet film.
"""

from __future__ import annotations

from transient.models.point import PointContact
from transient.physics.hertz import HertzContact


class LayerTooThin(RuntimeError):
    """The pass's inlet film is below the range the point contact accepts (5 % of the flooded central film): the
    contact runs dry (the sequence stops there, flagged)."""


class NumericalFilms:
    """``films(h_in, n) -> (h_central, h_min)`` [m] for the bearing's contact at entraining speed ``speed``
    [m/s] on ``grid`` nodes; ``n`` the pass (named in errors)."""

    def __init__(self, bearing, contact: HertzContact, speed: float, grid=(65, 33)):
        self._args = dict(radius_x=bearing.rx, radius_y=bearing.ry, load=contact.load_per_ball, speed=speed,
                          viscosity=bearing.viscosity, pressure_viscosity=bearing.pressure_viscosity,
                          modulus=contact.e_prime, grid=tuple(grid))
        self.flooded = PointContact(**self._args).steady()
        #: the thickest gap on the inlet boundary: a layer at least this thick floods the contact
        self.fill = float(self.flooded.film[:, 0].max())
        self.cache = {}
        self.solves = 0

    def __call__(self, h_in: float, n: int) -> tuple[float, float]:
        if h_in >= self.fill:
            return self.flooded.h_central, self.flooded.h_min
        key = float(f"{h_in:.4g}")
        if key not in self.cache:
            thicker = [h for h in self.cache if h > key]
            start = self.cache[min(thicker)] if thicker else self.flooded
            try:
                pc = PointContact(inlet_film=key, **self._args)
            except ValueError as e:
                raise LayerTooThin(f"pass {n}: inlet film {key:.4g} m: {e}") from None
            s = pc.steady(initial=start, raise_on_failure=False)
            if not s.success:
                raise RuntimeError(f"pass {n}: the numerical point contact did not converge: {pc.failure_message(s)}; "
                                   "use contact='formula' or a finer contact_grid")
            self.solves += 1
            self.cache[key] = s
        s = self.cache[key]
        return s.h_central, s.h_min
