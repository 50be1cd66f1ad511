"""A rough journal bearing at rest: the static contact equilibrium under a load (the start of a run-up from 0 rpm).

With the shaft at rest and the journal still, the film has neither a Couette nor a squeeze flux: its steady pressure
is the Poiseuille balance between the feeds and the ends (uniform when they are at one pressure), and the load is
carried by the asperities (Greenwood & Tripp) where the gap closes, plus whatever force that feed pressure field
exerts. The journal position solves ``F_film + F_asperity + W = 0``: first along the load line (the asperity force
grows monotonically as the journal approaches the bush: a bracketed root), then a 2-D Newton with the contact
stiffness (``RoughFilm.force_sensitivity``) for the small force across it that the discrete grid leaves.

The film is a :class:`~transient.models.journal.rough_film.RoughFilm` built at a nominal speed ``unit_rpm`` that sets
only its pressure unit ``p0`` (the journal's speed is 0: its Couette flux is switched off, ``couette = 0``); a run
that starts here takes its state in its own reference speed's unit.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy.optimize import brentq

from transient.models.journal.errors import NoEquilibriumError
from transient.models.journal.film import wall_friction

TOL = 1e-10  # force residual relative to the load
MAX_NEWTON = 40
EXACT = 1e-14  # a film residual this small (relative to |u|) is the rounding of a solution


def rest_film(bearing, unit_rpm):
    """The rough film of ``bearing`` at rest, in the pressure unit of ``unit_rpm`` [rpm]."""
    film = bearing.film(unit_rpm)
    film.couette = 0.0
    return film


def _film_at(film, X, Y, u):
    """The film's steady state at rest at (X, Y) from ``u`` (default: full at the highest feed pressure); ``u`` as it
    is if it solves the film equations already (feeds and ends at one pressure: the uniform film, exactly)."""
    if u is None:
        sc = film.scales
        u = np.full(film.n, max(sc.u_ambient, float(np.max(sc.u_supply, initial=0.0))))
        u[~film.op.free] = sc.u_supply
    r = film.residual(u, X, Y)
    if float(np.max(np.abs(r[film.op.free]), initial=0.0)) <= EXACT * max(1.0, float(np.max(np.abs(u)))):
        return u, 0
    return film.solve(X, Y, u0=u)


def rest_equilibrium(bearing, load, unit_rpm):
    """``(film, u, (X, Y), iterations)``: the journal of the rough ``bearing`` at rest under ``load`` [N] (in +x)
    where the film at rest and the asperities carry it (module docstring); ``u`` in the pressure unit of
    ``unit_rpm``. Raises :class:`~transient.models.journal.errors.NoEquilibriumError` if the asperities cannot
    carry it inside the bearing's reach."""
    film = rest_film(bearing, unit_rpm)
    wbar = load / film.force_scale
    u, _ = _film_at(film, 0.0, 0.0, None)
    reach = bearing._reach * bearing.max_eccentricity_ratio

    def along(e):  # the force balance along the load line, the film's pressure field held (uniform: exact)
        return film.force(u, e, 0.0)[0] + wbar

    if along(0.0) <= 0.0:  # the feeds' pressure field alone pushes the journal against the load
        e = 0.0
    elif along(reach) > 0.0:
        raise NoEquilibriumError(f"equilibrium(load={load} N, speed_rpm=0): the asperities at rest carry at most "
                                 f"{-film.force(u, reach, 0.0)[0] * film.force_scale:.6g} N with the journal at "
                                 f"e/C = {reach:.4f}")
    else:
        e = brentq(along, 0.0, reach, xtol=1e-14, rtol=1e-14)
    q = np.array([e, 0.0])
    for it in range(MAX_NEWTON):
        u, _ = _film_at(film, q[0], q[1], u)
        F, dF_dq, _ = film.force_sensitivity(u, q[0], q[1])
        r = np.array([F[0] + wbar, F[1]])
        if np.max(np.abs(r)) <= TOL * wbar:
            return film, u, q, it
        dq = -np.linalg.solve(dF_dq, r)
        lam = 1.0
        while np.hypot(*(q + lam * dq)) >= reach:
            lam *= 0.5
        q = q + lam * dq
    raise NoEquilibriumError(f"equilibrium(load={load} N, speed_rpm=0) did not converge in {MAX_NEWTON} iterations; "
                             f"force residual {np.max(np.abs(r)) * film.force_scale:.3e} N")


def rest_state(film, u, X, Y, iterations=0):
    """The SI :class:`~transient.models.journal.results.FilmState` of the film at rest: speed 0, its friction torque
    the boundary friction ``mu_b R sum p_a dA`` (the torque that starts the shaft) and the Poiseuille wall stress of
    the feeds' pressure field (no Couette shear)."""
    s = film.state(u, X, Y, iterations)
    drag, bush = wall_friction(_Still(film), s.film_thickness, s.pressure_gradient, s.axial_pressure_gradient,
                               s.film_content, None if film.alpha_p0 == 0.0 else film.viscosity_factor)
    R = film.scales.radius
    return dataclasses.replace(s, speed_rpm=0.0, sliding_speed=0.0, rest_radius=R, friction_force=drag,
                               bearing_friction_force=bush,
                               friction_torque=R * (drag + film.roughness.boundary_friction * s.contact_normal_load))


class _Still:
    """A film's view with the journal's speed 0 (for :func:`~transient.models.journal.film.wall_friction`)."""

    def __init__(self, film):
        self._film = film
        self.scales = film.scales._replace(omega=0.0)

    def __getattr__(self, name):
        return getattr(self._film, name)
