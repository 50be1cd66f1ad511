"""The temperatures of one thermal (THD) film in a time run, advanced per thermal interval: what the journal orbit
(:mod:`~transient.models.journal.thermal_orbit`) and the rotor system (:mod:`~transient.models.rotor.thermal_films`)
share.

Over a thermal interval the film runs on the viscosities of the temperatures at its start (the film's frozen
fluidity, :mod:`~transient.models.journal.viscous_film`). The film is sampled at every output (:meth:`observe`):
its flows, dissipation and wall coefficients (:class:`~transient.models.journal.thermal.EnergyRates`), averaged over
the interval by the trapezoid rule, and the oil's content per cell ``m = H theta`` at its two ends. At the interval's
end (:meth:`advance`) the temperatures take one backward-Euler step of its length on the mean rates with the cells'
heat capacity ``rho c_p (m_0 A C R^2) + c_w A / A_film``
(:meth:`~transient.models.journal.thermal.EnergyEquation.solve_rates`; an M-matrix: no overshoot), the interval's
heat ledger is kept (:meth:`heat_balance`) and the film's fluidity is set from the new temperatures.

The capacity takes the content ``m_0`` at the interval's START. The step is written in the advective form
``m_0 (T+ - T) / dt + sum_inflows Q (T+ - T_up+)`` and the mean flows' divergence is the content's change,
``div Q = -(m_1 - m_0) / dt`` (to the trapezoid's error in the flows); so the step is the conservative
``(m_1 T+ - m_0 T) / dt + div(Q T+)``, and summed over the cells it is the interval's heat ledger (the heat stored
at the content and temperatures of the interval's two ends). With the interval's mean content instead the step
missed the ledger by ``(m_mean - m_0)(T+ - T)``, largest where content and temperatures both move: 1.4 % of the
heat made in the first revolution of a cold start at 1 rev intervals (docs/validation.md, "Thermal orbit").
"""

from __future__ import annotations

import numpy as np

from transient.models.journal.thd import fluidity
from transient.models.journal.thermal import EnergyEquation, EnergyRates


class FilmTemperatures:
    """The cells' and feeds' temperatures of one thermal film (module docstring).

    ``film``: a :class:`~transient.models.journal.viscous_film.ViscousFilm` (its ``fluidity`` is what the
    temperatures set); ``bearing``: its :class:`~transient.models.journal.bearing.JournalBearing` (``thermal``, the
    reference ``viscosity`` of the film's pressure unit, ``grid``); ``temperature``: the cells' then the feeds'
    temperatures [K] at the start (``film.n + feeds``)."""

    def __init__(self, film, bearing, temperature):
        self.film, self.bearing = film, bearing
        th = self.thermal = bearing.thermal
        self.energy = EnergyEquation(film, th)
        temperature = np.asarray(temperature, dtype=float)
        self.T, self.T_mix = temperature[:film.n].copy(), temperature[film.n:].copy()
        s = film.scales
        free = film.op.free
        self.area = film.area
        # the wall's share of each cell [C R^2 of oil]: c_w A_i / (sym sum A) / (rho c_p C R^2)
        self.wall_volume = (th.wall_heat_capacity * film.area / (s.sym * float(np.sum(film.area[free])))
                            / (th.properties.volumetric_heat * s.clearance * s.radius ** 2))
        self.started = False
        self.stepped_at = None
        self.ledger = []
        self._reset()

    def _reset(self):
        self.tau_start = self.tau_last = None
        self.sums = None
        self.last = None

    def next_interval(self):
        """Start the next interval: its samples from the next :meth:`observe` on."""
        self.started = True
        self._reset()

    def rates_of_fields(self, speed_ratio):
        """The energy equation's rates and the oil's content per cell at the cell fields of the film's last
        evaluation (its Couette dissipation at the shaft's ``speed_ratio`` to the film's speed)."""
        film = self.film
        return self.energy.rates(speed_ratio), film.H * film.C

    def observe(self, tau, r, m):
        """Add the sample ``(r, m)`` at ``tau`` to the interval's trapezoid (a repeated time is not added)."""
        if self.tau_last is not None and tau <= self.tau_last:
            return
        if self.tau_last is None:
            self.tau_start, self.first = tau, (r, m)
            self.sums = [np.zeros_like(a) for a in r]
        else:
            h = 0.5 * (tau - self.tau_last)
            for acc, a, b in zip(self.sums, self.last[0], r, strict=True):
                acc += h * (a + b)
        self.tau_last, self.last = tau, (r, m)

    def advance(self, tau):
        """The temperatures' backward-Euler step over the interval that ends at ``tau`` (module docstring) and the
        film's fluidity at them (the pressures of the last sample); once per interval."""
        if self.tau_start is None:
            return
        dtau = tau - self.tau_start
        if dtau <= 0.0 or tau == self.stepped_at:
            return
        self.stepped_at = tau
        r = EnergyRates(*(a / dtau for a in self.sums))
        capacity = (self.first[1] * self.area + self.wall_volume) / dtau
        stored = self.stored_heat(self.first[1], self.T)
        b = self.energy.solve_rates(r, capacity, self.T)
        self.T, self.T_mix = b.temperature, b.mixing_temperature
        seconds = dtau / self.film.omega
        self.ledger.append((tau / self.film.omega, b.dissipation * seconds, (b.convected + b.conducted) * seconds,
                            self.stored_heat(self.last[1], self.T) - stored))
        self.set_fluidity()

    def stored_heat(self, m, T) -> float:
        """The heat [J] in the oil (content ``m`` per cell) and the walls above the supply temperature at the cells'
        temperatures ``T``."""
        s, free = self.film.scales, self.film.op.free
        volume = m * self.area + self.wall_volume
        return (self.energy.heat_unit / s.omega * s.sym
                * float(np.sum((volume * (T - self.thermal.supply_temperature))[free])))

    def outputs(self, r, m) -> dict:
        """The thermal outputs at a sample ``(r, m)``: the largest film temperature [K], the film's dissipation
        [W], the heat the oil carries away and the walls take [W] and the heat stored in the oil and the walls
        above the supply temperature [J] (at the temperatures the film runs on)."""
        b = self.energy.balance(r, self.T, self.T_mix)
        return {"max_temperature": float(np.max(self.T[self.film.op.free])), "power_loss": b.dissipation,
                "heat_flow": b.convected + b.conducted, "stored_heat": self.stored_heat(m, self.T)}

    def heat_balance(self) -> dict:
        """The energy balance of every thermal interval: its end ``t`` [s], the heat the film made in it
        (``dissipation`` [J], its mean over the outputs), the heat the oil carried away and the walls took
        (``heat_out`` [J], at the interval's new temperatures) and the change of the ``stored`` heat [J] (oil
        content and temperatures at the interval's ends)."""
        a = np.array(self.ledger, dtype=float).reshape(-1, 4)
        return {"t": a[:, 0], "dissipation": a[:, 1], "heat_out": a[:, 2], "stored": a[:, 3]}

    def set_fluidity(self):
        """The film's fluidity at the temperatures (and the pressures of the film's last evaluation)."""
        self.film.fluidity[:] = fluidity(self.film, self.thermal, self.T, self.bearing.viscosity)

    def temperature_field(self) -> np.ndarray:
        """The cells' temperatures [K] on the grid (feed cells at their feed's mixing temperature)."""
        return self.bearing.grid.to_2d(self.T).astype(np.float32)

    def final_temperature(self) -> np.ndarray:
        """The cells' and feeds' temperatures [K] (a result's ``final_temperature``: ``run(start=...)``)."""
        return np.concatenate([self.T, self.T_mix])

    def arrays(self) -> dict:
        """What a checkpoint keeps of the film's temperatures at an interval's end (after :meth:`advance`): the
        temperatures and the heat ledger."""
        return {"temperature": self.final_temperature(), "ledger": np.array(self.ledger, dtype=float).reshape(-1, 4)}

    def restore(self, a: dict):
        """Take the temperatures and the ledger of :meth:`arrays`: the next interval starts at them."""
        T, ledger = np.asarray(a["temperature"], dtype=float), np.asarray(a["ledger"], dtype=float)
        if T.shape != (self.T.size + self.T_mix.size,) or ledger.ndim != 2 or ledger.shape[1:] != (4,):
            raise ValueError(f"its temperatures have shape {T.shape}, its heat ledger {ledger.shape}")
        self.T, self.T_mix = T[:self.T.size].copy(), T[self.T.size:].copy()
        self.ledger = [tuple(row) for row in ledger]
        self.started, self.stepped_at = False, None
        self._reset()
