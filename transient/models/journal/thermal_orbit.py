"""The journal orbit of a thermal (THD) bearing: the film's temperatures as states of the orbit, advanced on their
own time scale (multirate), and the shaft's speed as a function of time.

The two time scales: the orbit moves in a fraction of a revolution (milliseconds: BDF2 takes about 550 steps per
revolution), the temperatures in seconds (the oil's residence time in the film is about a revolution; the bush and
shaft metal next to it, ``ThermalFilm.wall_heat_capacity``, stretches that to seconds). One stepper for both would
hold the orbit to no purpose on the thermal field's implicit solve at every step, or the thermal field to the
orbit's steps. So the run goes in thermal intervals of ``thermal_interval`` revolutions (whole output intervals):

* over an interval the film runs on the viscosities of the temperatures at its start -- the per-cell fluidity of
  :mod:`~transient.models.journal.viscous_film`, frozen -- in the BDF2 content formulation
  (:mod:`~transient.models.journal.driven_film`: the content formulation's residual and Jacobian with the
  Poiseuille conductances times the fluidity and the Couette flux times the shaft's speed ratio);
* the interval's film is sampled at every output (and at the interval's start, after the viscosities changed) and
  the flows, the dissipation, the wall coefficients and the oil's content averaged over the interval (trapezoid);
* at its end the temperatures take one backward-Euler step of the interval's length: the energy equation of
  :mod:`~transient.models.journal.thermal` on the mean flows and dissipation, with the cells' heat capacity ``rho c_p
  (m_0 A C R^2) + c_w A / A_film`` (oil content ``m_0 = H theta`` at the interval's start, the wall's share by area)
  on the diagonal, in the advective form::

      (c_i / dt) (T_i^+ - T_i) + sum_inflows rho c_p Q_f (T_i^+ - T_up(f)^+) + w_i (T_i^+ - T_w) = Phi_i

  -- an M-matrix like the steady one (the capacity only adds to its diagonal): the temperatures stay within the
  supply, wall and heated range (no overshoot), and summed over the cells the step is the interval's energy
  balance to the mass balance of the sampled flows (the capacity at the start content makes the advective form the
  conservative one: :mod:`~transient.models.journal.film_temperatures`). The viscosities of the new temperatures
  (at the interval's last pressures) go into the film.

The splitting error is first order in the interval (the film lags the temperatures by one interval, the temperatures
see the interval's mean flows): the long-time limit at constant speed is not affected (a fixed point of the
alternation is the steady THD film), and the transient error halves with the interval (docs/validation.md, "Thermal
orbit"). BDF2 restarts at each interval's start (its history does not carry across a change of viscosity).

The shaft's speed is the orbit's speed law (``JournalOrbit(..., speed_profile=...)``,
:mod:`~transient.models.journal.speed_law`; ratio ``s = Omega / omega`` to the orbit's speed, which keeps the pressure
unit and the time ``tau = omega t``): the Couette flux times ``s``, the dissipation's Couette part times ``s^2`` and the
unbalance force at the shaft angle, in the kernels of :mod:`~transient.models.journal.driven_film`.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from transient.checks import check_range
from transient.models.journal.content_newton import forget_fields
from transient.models.journal.driven_film import driven_fields, driven_newton, driven_residual
from transient.models.journal.film import read_only
from transient.models.journal.film_temperatures import FilmTemperatures
from transient.models.journal.kernels import N_ROTOR
from transient.models.journal.speed_law import shaft_speed, speed_range, step_cap_scale
from transient.solvers.integrate import Problem
from transient.solvers.integrate.bdf2 import Bdf2Model

#: Series a thermal orbit records besides the isothermal orbit's (``Recording(record=...)``).
THERMAL_RECORDABLE = ("max_temperature", "power_loss", "heat_flow", "stored_heat", "shaft_speed", "temperature")
#: ... of them the fields (kept from ``record_from_revolution`` on, like the pressure).
THERMAL_FIELDS = ("temperature",)


class ThermalRun(FilmTemperatures):
    """The temperatures of one thermal orbit run and their multirate coupling to the film (module docstring; the
    temperatures, their averaging and step: :class:`~transient.models.journal.film_temperatures.FilmTemperatures`).

    ``orbit``: the :class:`~transient.models.journal.orbit.JournalOrbit` (its film a
    :class:`~transient.models.journal.viscous_film.ViscousFilm`); ``knots``: the shaft's speed law
    (:func:`~transient.models.journal.speed_law.shaft_speed`);
    ``temperature``: the cells' and feeds' temperatures [K] at the start (``film.n + feeds``); the fluidity of the
    film is set from them at the start state (:meth:`problem_at`)."""

    def __init__(self, orbit, knots, temperature):
        super().__init__(orbit.film, orbit.bearing, temperature)
        self.orbit = orbit
        film = self.film
        self.knots = knots
        self.model = Bdf2Model(newton=driven_newton, args=(orbit.content_args(), film.fluidity, knots),
                               error_components=np.arange(film.n, orbit.n), n_border=N_ROTOR)

    # the film's rates, sampled ----------------------------------------------------------------------------
    def rates(self, tau, u, X, Y):
        """The energy equation's rates and the oil's content per cell of the universal state at ``tau``."""
        film = self.film
        s = shaft_speed(tau, self.knots)[0]
        driven_fields(read_only(np.ascontiguousarray(u)), X, Y, s, film.fluidity, film.switch, film.geo,
                      film.fields, film.fv)
        return self.energy.rates(s), film.H * film.C

    # the run ------------------------------------------------------------------------------------------------
    def problem_at(self, y, tau, tau_end, events=None):
        """The problem of the interval from ``tau`` (content layout ``y``) to ``tau_end``: the temperatures
        stepped over the interval that ended here and the new interval's first sample (at the new viscosities)."""
        film = self.film
        n = film.n
        u = film.universal(y[:n], y[n], y[n + 1])
        if self.started:
            self.advance(tau)
        else:
            driven_fields(read_only(u), y[n], y[n + 1], shaft_speed(tau, self.knots)[0], film.fluidity, film.switch,
                          film.geo, film.fields, film.fv)
            self.set_fluidity()  # the start temperatures' viscosities at the start's pressures
        self.next_interval()
        self.observe(tau, *self.rates(tau, u, y[n], y[n + 1]))
        args = self.model.args
        yp0 = np.zeros(y.size)
        F = np.empty(y.size)
        forget_fields(args[0])  # the slope of y itself (not of the fields the last interval's Newton left)
        driven_residual(tau, read_only(np.ascontiguousarray(y)), read_only(yp0), F, args)
        scale = np.ones(y.size)
        scale[:n] = np.where(film.op.free, film.area, 1.0)
        yp0 = -F / scale
        yp0[:n][~film.op.free] = 0.0

        def residual(t, y_, yp_, out):
            driven_residual(t, y_, yp_, out, args)

        pattern = self.orbit.newton_pattern()[0]
        return Problem(y0=np.array(y, dtype=float), yp0=yp0, residual=residual, jac_pattern=pattern,
                       events=events, n_events=1 if events else 0, event_terminal=[True], event_direction=[-1],
                       name="thermal journal orbit (content)")

    def sample(self, tau, y) -> dict:
        """Observe the universal state ``y`` at ``tau`` and the thermal outputs there: the largest film
        temperature [K], the film's dissipation [W], the heat the oil carries away and the walls take [W], the heat
        stored in the oil and the walls above the supply temperature [J] and the shaft's speed [rpm]."""
        film = self.film
        n = film.n
        r, m = self.rates(tau, y[:n], y[n], y[n + 1])
        self.observe(tau, r, m)
        return dict(self.outputs(r, m), shaft_speed=shaft_speed(tau, self.knots)[0] * self.orbit.speed_rpm)


def thermal_long_run(long_run, interval, opr):
    """The long-run settings of a thermal orbit: chunks of one thermal interval (``interval`` [rev], whole output
    intervals), no progress bar unless asked; a checkpoint is refused (the temperatures are not in the state it
    keeps)."""
    check_range("thermal_interval", interval, "rev", 1.0 / opr, np.inf,
                why=f"(at least one output interval at outputs_per_revolution = {opr})")
    if long_run.checkpoint is not None or long_run.chunk_revolutions is not None:
        raise ValueError(f"checkpoint = {long_run.checkpoint!r}, chunk_revolutions = {long_run.chunk_revolutions!r} "
                         "with a thermal bearing; allowed: None (a thermal orbit runs in chunks of thermal_interval "
                         "and keeps its temperatures outside the checkpointed state: go on with start=result)")
    return replace(long_run, chunk_revolutions=interval, progress=bool(long_run.progress))


def start_temperature(orbit, start, temperature) -> np.ndarray:
    """The cells' and feeds' temperatures [K] at a thermal run's start: ``temperature`` (a number or one per cell
    and feed), else the final temperatures of a ``start`` result, else those of the static equilibrium the orbit
    starts from (:meth:`~transient.models.journal.orbit.JournalOrbit.start_equilibrium`)."""
    film = orbit.film
    size = film.n + int(film.scales.feed_edges.size)
    if temperature is not None:
        T = np.broadcast_to(np.asarray(temperature, dtype=float), (size,)).copy() if np.ndim(temperature) == 0 \
            else np.asarray(temperature, dtype=float)
        if T.shape != (size,):
            raise ValueError(f"temperature has shape {T.shape}; allowed: a number or {size} values [K] (one per cell "
                             "and feed)")
        orbit.bearing.thermal.viscosity(T)  # in the viscosity law's range
        return T
    final = getattr(start, "final_temperature", None)
    if final is not None:
        return np.asarray(final, dtype=float)
    e = orbit.start_equilibrium()
    return np.concatenate([np.asarray(e.temperature, dtype=float).ravel(), e.mixing_temperature])


def thermal_parts(orbit, parts, run, record, record_from_revolution, knots, temperature, start, tau0, dt_out):
    """The :class:`~transient.solvers.model_run.RunParts` of a thermal orbit from the isothermal ones: the problem
    of each thermal interval (:meth:`ThermalRun.problem_at`), BDF2 on its kernels with the step cap in shaft angle,
    the thermal outputs and the result's final temperatures. ``knots``: the shaft's speed law
    (:mod:`~transient.models.journal.speed_law`), above rest over the whole run."""
    n = orbit.film.n
    chunk, tau_run_end = run.chunk_outputs * dt_out, tau0 + run.n_outputs * dt_out
    low = speed_range(knots, tau0, tau_run_end)[0]
    if low <= 0.0:
        raise ValueError(f"speed_profile down to {low * orbit.speed_rpm:g} [rpm] with thermal = ThermalFilm(...); "
                         "allowed: > 0 over the whole run (a thermal film carries no load at rest)")
    tr = ThermalRun(orbit, knots, start_temperature(orbit, start, temperature))
    events = None
    if run.touch_gap > 0:
        limit = (orbit.bearing.max_eccentricity_ratio - run.touch_gap) ** 2

        def events(t, y, out):
            out[0] = limit - (y[n] ** 2 + y[n + 1] ** 2)

    names = [k for k in record if k in THERMAL_RECORDABLE]
    tau_fields = 2 * np.pi * record_from_revolution

    def sample(tau, y):
        row = parts.sample(tau, y)
        extra = tr.sample(tau, y)
        row.update({k: extra[k] for k in names if k not in THERMAL_FIELDS})
        if "temperature" in names and tau >= tau_fields - 1e-12:
            row["temperature"] = tr.temperature_field()
        return row

    def result(*args):
        tr.advance(tr.tau_last)  # the last interval's step (once; a run's stop hook may ask for a result between)
        r = parts.result(*args)
        r.final_temperature = tr.final_temperature()
        r.heat_balance = tr.heat_balance()
        return r

    # the orbit's own BDF settings (order, travel bound) with the thermal interval's model and the cap in shaft angle
    solver = dict(parts.solver, options={**parts.solver.get("options", {}), "bdf2": tr.model,
                                         "max_step_scale": step_cap_scale(knots)})
    return replace(parts, problem_at=lambda y, tau: tr.problem_at(y, tau, min(tau + chunk, tau_run_end), events),
                   solver=solver, sample=sample, result=result, sparse=(*parts.sparse, *THERMAL_FIELDS))
