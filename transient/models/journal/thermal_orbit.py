"""The journal orbit of a thermal (THD) bearing: the film's temperatures as states of the orbit, advanced on their
own time scale (multirate), and the shaft's speed as a function of time.

The two time scales: the orbit moves in a fraction of a revolution (milliseconds: BDF2 takes about 550 steps per
revolution), the temperatures in seconds (the oil's residence time in the film is about a revolution; the bush and
shaft metal next to it, ``ThermalFilm.wall_heat_capacity``, stretches that to seconds). One stepper for both would
hold the orbit to no purpose on the thermal field's implicit solve at every step, or the thermal field to the
orbit's steps. So the run goes in thermal intervals of ``thermal_interval`` revolutions (whole output intervals):

* over an interval the film runs on the viscosities of the temperatures at its start -- the per-cell fluidity of
  :mod:`~transient.models.journal.viscous_film`, frozen -- in the BDF2 content formulation
  (:mod:`~transient.models.journal.content_newton`; the kernels here are its residual and Jacobian with the
  Poiseuille conductances times the fluidity and the Couette flux times the shaft's speed ratio);
* the interval's film is sampled at every output (and at the interval's start, after the viscosities changed) and
  the flows, the dissipation, the wall coefficients and the oil's content averaged over the interval (trapezoid);
* at its end the temperatures take one backward-Euler step of the interval's length: the energy equation of
  :mod:`~transient.models.journal.thermal` on the mean flows and dissipation, with the cells' heat capacity ``rho c_p
  (m A C R^2) + c_w A / A_film`` (oil content ``m = H theta``, the wall's share by area) on the diagonal::

      (c_i / dt) (T_i^+ - T_i) + sum_faces rho c_p Q_f T_up(f)^+ + w_i (T_i^+ - T_w) = Phi_i

  -- an M-matrix like the steady one (the capacity only adds to its diagonal): the temperatures stay within the
  supply, wall and heated range (no overshoot), and summed over the cells the step is the interval's energy
  balance exactly. The viscosities of the new temperatures (at the interval's last pressures) go into the film.

The splitting error is first order in the interval (the film lags the temperatures by one interval, the temperatures
see the interval's mean flows): the long-time limit at constant speed is not affected (a fixed point of the
alternation is the steady THD film), and the transient error halves with the interval (docs/validation.md, "Thermal
orbit"). BDF2 restarts at each interval's start (its history does not carry across a change of viscosity).

The shaft's speed ``speed(t)`` [rpm] enters per interval as the straight line through its values at the interval's
ends (ratio ``s = Omega / omega`` to the orbit's speed, which keeps the pressure unit and the time ``tau = omega t``):
the Couette flux times ``s``, the dissipation's Couette part times ``s^2`` and the unbalance force
``e (s^2 cos phi + s' sin phi, s^2 sin phi - s' cos phi)`` at the shaft angle ``phi = tau + int (s - 1) dtau``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numba import njit

import transient.solvers.integrate.bdf2 as stepper
from transient.checks import check_range
from transient.fv.reynolds import jacobian_kernel
from transient.models.journal.content_newton import (bdf2_from_state, bdf2_to_state, content_columns, fields_of,
                                                     film_newton_norm)
from transient.models.journal.film import read_only
from transient.models.journal.film_temperatures import FilmTemperatures
from transient.models.journal.kernels import N_ROTOR, film_force, position_derivatives, state_fields, stencil_flux
from transient.solvers.integrate import Problem
from transient.solvers.integrate.bdf2 import Bdf2Model, newton_step
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient.solvers.read_only import as_read_only

#: Series a thermal orbit records besides the isothermal orbit's (``Recording(record=...)``).
THERMAL_RECORDABLE = ("max_temperature", "power_loss", "heat_flow", "stored_heat", "shaft_speed", "temperature")
#: ... of them the fields (kept from ``record_from_revolution`` on, like the pressure).
THERMAL_FIELDS = ("temperature",)


@njit(cache=True)
def shaft(t, drive):
    """The shaft's speed ratio ``s``, its rate ``s'`` (per unit of tau) and angle ``phi`` at ``t`` on the interval
    line ``drive = (tau_k, s_k, s', phi_k - tau_k)``: ``phi = t + (phi_k - tau_k) + (s_k - 1) dt + s' dt^2 / 2``
    (exactly ``t`` at the orbit's own constant speed)."""
    dt = t - drive[0]
    return drive[1] + drive[2] * dt, drive[2], t + drive[3] + (drive[1] - 1.0) * dt + 0.5 * drive[2] * dt * dt


@njit(cache=True)
def scale_fields(fields, fluidity, s, switch):
    """The conductances of the cells' fields (from their H, idempotent): ``k = f (H - gap)^3 / 2 + darcy H`` times
    the fluidity ``f``, ``c = s H / 2``."""
    layer_gap, darcy = switch.layer_gap, switch.darcy
    H, k, c = fields.H, fields.k, fields.c
    for i in range(H.size):
        h = H[i]
        hb = h - layer_gap if h > layer_gap else 0.0
        k[i] = fluidity[i] * (0.5 * hb * hb * hb + darcy * h)
        c[i] = s * (0.5 * h)


@njit(cache=True)
def thermal_fields(u, X, Y, s, fluidity, switch, geo, fields, fv):
    """The cell fields of the universal state ``u`` at ``(X, Y)`` with the fluidity and speed ratio ``s``."""
    state_fields(u, X, Y, switch, geo, fields, fv)
    scale_fields(fields, fluidity, s, switch)


@njit(cache=True)
def thermal_residual(t, y, yp, out, args):
    """The content residual (:func:`~transient.models.journal.content_newton.bdf2_residual`) on the frozen
    fluidity, the Couette flux at the shaft's speed and the unbalance at its angle (module docstring);
    ``args = (content args, fluidity, drive)``."""
    base, flu, drive = args
    switch, rotor, geo, fields, extras, fv, work, tol, regime = base
    kappa, wbar, ebar, sym = rotor
    fields_of(y, base)
    s, ds, phi = shaft(t, drive)
    scale_fields(fields, flu, s, switch)
    stencil_flux(as_read_only(work.u), fields, fv, fields.R, 1.0)
    fx, fy = film_force(fields.P, geo.cosp, geo.sinp, geo.area, sym)
    free, area, R = fv.cells.free, geo.area, fields.R
    n = free.size
    for i in range(n):
        out[i] = area[i] * yp[i] + R[i] if free[i] else yp[i]
    e2 = ebar * s * s
    ax = kappa * fx + wbar + e2 * np.cos(phi) + ebar * ds * np.sin(phi)
    ay = kappa * fy + e2 * np.sin(phi) - ebar * ds * np.cos(phi)
    out[n] = yp[n] - y[n + 2]
    out[n + 1] = yp[n + 1] - y[n + 3]
    out[n + 2] = yp[n + 2] - ax
    out[n + 3] = yp[n + 3] - ay


@njit(cache=True)
def thermal_jacobian(t, y, yp, cj, data, args):
    """:func:`~transient.models.journal.content_newton.bdf2_jacobian` (operator pattern) with the conductances of
    :func:`scale_fields` and their position derivatives times the fluidity (Poiseuille) and ``s`` (Couette)."""
    base, flu, drive = args
    switch, rotor, geo, fields, extras, fv, work, tol, regime = base
    cosp, sinp = geo.cosp, geo.sinp
    H, P, dP, C, D, dD, k, c, zero, R = fields
    dk_dq, dc_dq, no_dq, pos_row, pos_col, indices, scale = extras
    faces, boundary, cells, face_k, bulk = fv
    n = cells.free.size
    fields_of(y, base)
    s = shaft(t, drive)[0]
    scale_fields(fields, flu, s, switch)
    position_derivatives(H, cosp, sinp, switch.layer_gap, switch.darcy, dk_dq, dc_dq)
    for i in range(n):
        for e in range(2):
            dk_dq[e, i] *= flu[i]
            dc_dq[e, i] *= s
    jacobian_kernel(P, dP, C, D, k, zero, k, zero, c, zero, dk_dq[:2], dk_dq[:2], dc_dq[:2], no_dq[:2], True,
                    faces, boundary, cells, face_k, pos_col, data)
    content_columns(cj, rotor, geo, fields, extras, fv, work.u, switch.width, regime, data)


@njit(cache=True)
def thermal_newton_jacobian(t, y, yp, cj, data, args):
    """:func:`thermal_jacobian` in the problem's pattern (the operator's, or the decoupled one gathered from it)."""
    work = args[0][6]
    full, gather = work.jac, work.gather
    if data.size == gather.size and data.size != full.size:
        thermal_jacobian(t, y, yp, cj, full, args)
        for k in range(gather.size):
            data[k] = full[gather[k]]
    else:
        thermal_jacobian(t, y, yp, cj, data, args)


@njit(cache=True)
def thermal_norm(z, dz, args):
    return film_newton_norm(z, dz, args[0])


@njit(cache=True)
def thermal_to_state(z, y, args):
    bdf2_to_state(z, y, args[0])


@njit(cache=True)
def thermal_from_state(y, z, args):
    bdf2_from_state(y, z, args[0])


@njit(cache=True)  # newton_step is inlined (its kernels are this module's globals): cached on disk like a kernel
def thermal_newton(args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts):
    """:func:`~transient.solvers.integrate.bdf2.newton_step` on the thermal content film + rotor."""
    return newton_step(thermal_residual, thermal_newton_jacobian, thermal_norm, thermal_to_state, thermal_from_state,
                       args, t, cj, b, y, yp, F, dz, data, lu, y_pred, z, pick, err_idx, err_w, state, counts)


drop_stale_cache(thermal_newton, stepper.__file__)  # numba keys the cache on this file only; newton_step is inlined


class ThermalRun(FilmTemperatures):
    """The temperatures of one thermal orbit run and their multirate coupling to the film (module docstring; the
    temperatures, their averaging and step: :class:`~transient.models.journal.film_temperatures.FilmTemperatures`).

    ``orbit``: the :class:`~transient.models.journal.orbit.JournalOrbit` (its film a
    :class:`~transient.models.journal.viscous_film.ViscousFilm`); ``speed(t)`` [rpm] or None (the orbit's speed);
    ``temperature``: the cells' and feeds' temperatures [K] at the start (``film.n + feeds``); the fluidity of the
    film is set from them at the start state (:meth:`problem_at`)."""

    def __init__(self, orbit, speed, temperature):
        super().__init__(orbit.film, orbit.bearing, temperature)
        self.orbit = orbit
        film = self.film
        self.speed = speed
        self.drive = np.array([0.0, 1.0, 0.0, 0.0])
        self.model = Bdf2Model(newton=thermal_newton, args=(orbit.bdf2_model().args, film.fluidity, self.drive),
                               error_components=np.arange(film.n, orbit.n), n_border=N_ROTOR)

    # the shaft ----------------------------------------------------------------------------------------------
    def speed_ratio(self, tau) -> float:
        """``speed(t) / speed_rpm`` at ``tau`` (1 without a speed function)."""
        if self.speed is None:
            return 1.0
        return float(self.speed(tau / self.film.omega)) / self.orbit.speed_rpm

    def _line(self, tau, tau_end):
        """The drive's line over the interval ``[tau, tau_end]`` (module docstring), the angle continued."""
        d = self.drive
        if self.started:
            dt = tau - d[0]
            d[3] += (d[1] - 1.0) * dt + 0.5 * d[2] * dt * dt
        s0, s1 = self.speed_ratio(tau), self.speed_ratio(tau_end)
        if s0 <= 0.0 or s1 <= 0.0:
            raise ValueError(f"speed(t = {tau / self.film.omega:.6g} s) = {s0 * self.orbit.speed_rpm:g} [rpm]; "
                             "allowed: > 0 (a film carries no load at rest)")
        d[0], d[1], d[2] = tau, s0, (s1 - s0) / (tau_end - tau)

    def max_step_scale(self, tau) -> float:
        """The BDF2 step cap's scale at ``tau``: the cap is in shaft angle (the film's fronts move with the shaft)."""
        return 1.0 / max(shaft(tau, self.drive)[0], 0.1)

    # the film's rates, sampled ----------------------------------------------------------------------------
    def rates(self, tau, u, X, Y):
        """The energy equation's rates and the oil's content per cell of the universal state at ``tau``."""
        film = self.film
        s = shaft(tau, self.drive)[0]
        thermal_fields(read_only(np.ascontiguousarray(u)), X, Y, s, film.fluidity, film.switch, film.geo,
                       film.fields, film.fv)
        return self.energy.rates(s), film.H * film.C

    # the run ------------------------------------------------------------------------------------------------
    def problem_at(self, y, tau, tau_end, events=None):
        """The problem of the interval from ``tau`` (content layout ``y``) to ``tau_end``: the temperatures
        stepped over the interval that ended here, the new interval's line of the shaft speed and its first
        sample (at the new viscosities)."""
        film = self.film
        n = film.n
        u = film.universal(y[:n], y[n], y[n + 1])
        if self.started:
            self.advance(tau)
        else:
            thermal_fields(read_only(u), y[n], y[n + 1], 1.0, film.fluidity, film.switch, film.geo, film.fields,
                           film.fv)
            self.set_fluidity()  # the start temperatures' viscosities at the start's pressures
        self._line(tau, tau_end)
        self.started = True
        self._reset()
        self.observe(tau, *self.rates(tau, u, y[n], y[n + 1]))
        args = self.model.args
        yp0 = np.zeros(y.size)
        F = np.empty(y.size)
        thermal_residual(tau, read_only(np.ascontiguousarray(y)), read_only(yp0), F, args)
        scale = np.ones(y.size)
        scale[:n] = np.where(film.op.free, film.area, 1.0)
        yp0 = -F / scale
        yp0[:n][~film.op.free] = 0.0

        def residual(t, y_, yp_, out):
            thermal_residual(t, y_, yp_, out, args)

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
        b = self.energy.balance(r, self.T, self.T_mix)
        free = film.op.free
        return dict(max_temperature=float(np.max(self.T[free])), power_loss=b.dissipation,
                    heat_flow=b.convected + b.conducted, stored_heat=self.stored_heat(m, self.T),
                    shaft_speed=shaft(tau, self.drive)[0] * self.orbit.speed_rpm)


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
    and feed), else the final temperatures of a ``start`` result, else those of the orbit's static equilibrium."""
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
    e = orbit.equilibrium()
    return np.concatenate([np.asarray(e.temperature, dtype=float).ravel(), e.mixing_temperature])


def thermal_parts(orbit, parts, run, record, record_from_revolution, speed, temperature, start, tau0, dt_out):
    """The :class:`~transient.solvers.model_run.RunParts` of a thermal orbit from the isothermal ones: the problem
    of each thermal interval (:meth:`ThermalRun.problem_at`), BDF2 on its kernels with the step cap in shaft angle,
    the thermal outputs and the result's final temperatures."""
    tr = ThermalRun(orbit, speed, start_temperature(orbit, start, temperature))
    n = orbit.film.n
    chunk, tau_run_end = run.chunk_outputs * dt_out, tau0 + run.n_outputs * dt_out
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

    # the orbit's own BDF settings (order, travel bound) with the thermal interval's model and step cap
    solver = dict(parts.solver, options={**parts.solver.get("options", {}), "bdf2": tr.model,
                                         "max_step_scale": tr.max_step_scale})
    return replace(parts, problem_at=lambda y, tau: tr.problem_at(y, tau, min(tau + chunk, tau_run_end), events),
                   solver=solver, sample=sample, result=result, sparse=(*parts.sparse, *THERMAL_FIELDS))
