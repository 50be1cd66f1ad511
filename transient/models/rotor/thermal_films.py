"""A rotor on thermal (THD) journal bearings: each thermal bearing's temperatures as states of the rotor system's
run, on their own time scale, and the rotor's thermal static equilibrium.

The coupling is the thermal journal orbit's (:mod:`~transient.models.journal.thermal_orbit`), per bearing: the run
goes in thermal intervals of ``thermal_interval`` revolutions (whole output intervals; the run's chunks); over an
interval each thermal film runs on the viscosities of its temperatures at the interval's start (its film block's
frozen fluidity, the kernels of :mod:`~transient.models.rotor.thermal_kernels`), its flows, dissipation and oil
content are sampled at the outputs and averaged over the interval, and at its end its temperatures take one
backward-Euler step on the means (:class:`~transient.models.journal.film_temperatures.FilmTemperatures`). The
shaft's speed is the rotor system's (its speed function at every step; the dissipation's Couette part at the
sample's speed). BDF2 only (``method="bdf2"``): it restarts at every interval's start.

The thermal static equilibrium of the rotor (:func:`thermal_start`): every thermal bearing at its steady THD
equilibrium (:meth:`~transient.models.journal.bearing.JournalBearing.equilibrium`) under the load it carries when
the shaft sits on rigid supports at its bearing nodes (``RotorBearingSystem.static_loads``), every other bearing at
its isothermal one, the shaft bent through the journals' positions -- the rotor's equilibrium itself where its loads
do not depend on the bearings' stiffness (two bearings, a statically determinate shaft), an approximation for a
shaft on three or more. A run without ``start`` starts there, its temperatures those of the equilibrium.

A checkpoint keeps the temperatures and the heat ledger of every thermal bearing at each interval's end
(``RunParts.carry``): a resumed run is the uninterrupted one bit for bit.
"""

from __future__ import annotations

import hashlib
from dataclasses import replace

import numpy as np

from transient.checks import check_range
from transient.models.journal.bearing import NoEquilibriumError
from transient.models.journal.film import read_only
from transient.models.journal.film_temperatures import FilmTemperatures
from transient.models.journal.driven_film import driven_fields
from transient.models.rotor.content_form import ContentSystem
from transient.models.rotor.thermal_kernels import thermal_rotor_newton, thermal_rotor_residual
from transient.solvers.integrate.bdf2 import Bdf2Model
from transient.solvers.settings import Integration

#: The series a thermal rotor run records per thermal bearing (``RotorRunResult``, columns ``thermal_nodes``).
THERMAL_SERIES = ("max_temperature", "power_loss", "heat_flow", "stored_heat")


def thermal_nodes(system) -> list:
    """The nodes of ``system`` whose bearing has a thermal film, in the system's bearing order."""
    return [n for n, b in system.bearings.items() if getattr(b, "thermal", None) is not None]


def refuse_thermal(system, what: str) -> None:
    """Refuse ``what`` (an analysis on the isothermal kernels) for a system with thermal bearings."""
    nodes = thermal_nodes(system)
    if nodes:
        raise ValueError(f"{what} with thermal bearings at nodes {nodes}: it linearises or integrates the isothermal "
                         "films; allowed: bearings without thermal=, or equilibrium, coefficients, the quasi-static "
                         "analyses and run(...) (the thermal films' temperatures as states)")


def check_thermal_system(system) -> None:
    """A rotor system takes thermal bearings without ``tilt_coupling``."""
    if system.tilt_coupling and thermal_nodes(system):
        raise ValueError(f"tilt_coupling = True with thermal bearings at nodes {thermal_nodes(system)}; allowed: "
                         "tilt_coupling=False (a thermal film in the rotor system is aligned)")


def thermal_integration(integration, legacy):
    """A thermal run's integration settings: BDF2 unless asked otherwise (and then refused by
    :func:`thermal_long_run`)."""
    if integration is None and "method" not in legacy:
        return Integration(method="bdf2")
    return integration


def thermal_long_run(method, long_run, interval, opr):
    """The long-run settings of a thermal rotor run: ``method`` BDF2, chunks of one thermal interval
    (``interval`` [rev], whole output intervals), no progress bar unless asked."""
    if method != "bdf2":
        raise ValueError(f"method = {method!r} with thermal bearings; allowed: 'bdf2' (the thermal films' kernels are "
                         "the content formulation's)")
    check_range("thermal_interval", interval, "rev", 1.0 / opr, np.inf,
                why=f"(at least one output interval at outputs_per_revolution = {opr})")
    if long_run.chunk_revolutions is not None:
        raise ValueError(f"chunk_revolutions = {long_run.chunk_revolutions!r} with thermal bearings; allowed: None "
                         "(a thermal run's chunks are its thermal intervals)")
    return replace(long_run, chunk_revolutions=interval, progress=bool(long_run.progress))


class ThermalContentSystem(ContentSystem):
    """:class:`~transient.models.rotor.content_form.ContentSystem` with its thermal films' rows on their fluidity
    (:mod:`~transient.models.rotor.thermal_kernels`): ``model()`` and ``residual`` (and so ``problem``)."""

    def __init__(self, dae):
        super().__init__(dae)
        self.rotor = self.rotor._replace(per_film=False)  # its Jacobian writes every thermal block again anyway
        self.args = (self.args[0], self.rotor)
        index = [k for k, b in enumerate(dae.blocks) if getattr(b.bearing, "thermal", None) is not None]
        self.thermal = np.array(index, dtype=np.int64)
        self.fluidity = tuple(dae.blocks[k].film.fluidity for k in index)
        which = np.full(len(dae.blocks), -1, dtype=np.int64)
        which[self.thermal] = np.arange(self.thermal.size)
        self.thermal_args = (self.args, self.fluidity, self.thermal, which)

    def model(self) -> Bdf2Model:
        def newton(args, t, *rest):
            self.set_speed(t)
            return thermal_rotor_newton(args, t, *rest)

        return Bdf2Model(newton=newton, args=self.thermal_args, error_components=self.error_components,
                         n_border=2 * self.dae.nq + 1)

    def residual(self, tau, y, yp, out):
        self.set_speed(tau)
        thermal_rotor_residual(tau, np.ascontiguousarray(y, dtype=float), np.ascontiguousarray(yp, dtype=float),
                               out, self.thermal_args)


def bearing_equilibria(system, dae, speed) -> tuple:
    """Every loaded bearing's steady film at ``speed`` [rpm] under its load on rigid supports (the thermal ones THD,
    their films' fluidity set from it): ``({node: FilmState}, {node: journal position (x, y) [m]})``."""
    loads = system.static_loads()
    states, journals = {}, {}
    for blk in dae.blocks:
        load = float(np.hypot(*loads[blk.node]))
        thermal = getattr(blk.bearing, "thermal", None) is not None
        if load <= 0.0 or blk.node in system.dampers:
            if thermal:
                raise NoEquilibriumError(f"the thermal bearing at node {blk.node} carries no static load; allowed: "
                                         "a loaded thermal bearing (its THD equilibrium is at its load)")
            continue
        e = blk.bearing.equilibrium(load, speed)
        a = np.arctan2(loads[blk.node][1], loads[blk.node][0])
        rotation = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        journals[blk.node] = rotation @ np.asarray(e.position[:2], dtype=float)  # [m], the rotor's frame
        if thermal:
            FilmTemperatures(blk.film, blk.bearing, equilibrium_temperature(e)).set_fluidity()
        states[blk.node] = e
    return states, journals


def thermal_states(system, states) -> dict:
    """The thermal bearings' among ``states``."""
    return {node: e for node, e in states.items() if getattr(system.bearings[node], "thermal", None) is not None}


def thermal_start(system, dae, s) -> tuple:
    """The rotor's thermal static equilibrium at the reference speed of ``dae`` (speed ratio ``s`` = 1; module
    docstring): ``(state, {node: FilmState})``, each thermal bearing's steady THD film; the thermal films' fluidity
    set from it. Every bearing's steady film at its load (``RotorBearingSystem._start_guess``), the shaft then bent
    exactly through the journals' positions: ``K q = f + sum_b T_b^T R_b``, ``T_b q = (X_b, Y_b) C_b`` with the
    reactions ``R_b`` (the shaft's statics on rigid supports at the journals)."""
    if s != 1.0:
        raise ValueError(f"reference_speed_rpm = {dae.speed_ref_rpm:g} [rpm] with thermal bearings and no start; "
                         f"allowed: None or the start speed {s * dae.speed_ref_rpm:g} rpm (the thermal start's films "
                         "are at their own speed)")
    states, journals = bearing_equilibria(system, dae, dae.speed_ref_rpm)
    y = system._start_guess(dae, s, states)
    if len(journals) == len(dae.blocks):  # every journal placed: the shaft through them
        r = system.rotor
        T = np.vstack([r.translation(node) for node in journals])
        n, m = r.n, T.shape[0]
        A = np.block([[system.stiffness, -T.T], [T, np.zeros((m, m))]])
        rhs = np.concatenate([system.gravity_vector @ r.gravity_load, np.concatenate(list(journals.values()))])
        y[dae.Q0:dae.V0] = np.linalg.lstsq(A, rhs, rcond=None)[0][:n] / dae.L
    return y, thermal_states(system, states)


def equilibrium_temperature(e) -> np.ndarray:
    """The cells' and feeds' temperatures [K] of a thermal bearing's steady state ``e``."""
    return np.concatenate([np.asarray(e.temperature, dtype=float).ravel(), e.mixing_temperature])


def thermal_equilibrium(system, dae, speed):
    """The rotor's thermal static equilibrium at ``speed`` [rpm] (module docstring) as a
    :class:`~transient.models.rotor.results.RotorEquilibrium` with each thermal bearing's ``max_temperature`` [K]
    and ``power_loss`` [W] (columns ``thermal_nodes``) and ``temperature`` [K] (their cells and feeds, in turn)."""
    y, states = thermal_start(system, dae, 1.0)
    eq = system._equilibrium_result(dae, y, speed)
    eq.thermal_nodes = list(states)
    eq.max_temperature = np.array([e.max_temperature for e in states.values()])
    eq.power_loss = np.array([e.dissipation for e in states.values()])
    eq.temperature = np.concatenate([equilibrium_temperature(e) for e in states.values()])
    return eq


class ThermalBearings:
    """The temperatures of a rotor run's thermal bearings (module docstring): one
    :class:`~transient.models.journal.film_temperatures.FilmTemperatures` per thermal film block of ``form``
    (a :class:`ThermalContentSystem`), ``speed(tau) -> (s, s')`` the run's shaft speed, ``temperatures``
    ``{node: cells' and feeds' temperatures [K]}`` at the start. ``arrays``/``restore``: the checkpoint's share."""

    def __init__(self, form, speed, temperatures: dict):
        self.form, self.speed = form, speed
        dae = form.dae
        self.blocks = [dae.blocks[k] for k in form.thermal]
        self.films = [FilmTemperatures(b.film, b.bearing, temperatures[b.node]) for b in self.blocks]
        self.nodes = [b.node for b in self.blocks]

    def _rates(self, tau, y):
        """Each thermal film's rates and oil content at the universal state ``y`` at ``tau``."""
        dae = self.form.dae
        q = y[dae.Q0:dae.V0]
        out = []
        for blk, ft in zip(self.blocks, self.films, strict=True):
            fl = blk.film
            X, Y = blk.position(q)
            s = self.speed(tau)[0] * blk.spin
            driven_fields(read_only(np.ascontiguousarray(y[blk.offset:blk.offset + blk.n])), X, Y, s, fl.fluidity,
                          fl.switch, fl.geo, fl.fields, fl.fv)
            fl.work.xy[0] = np.nan  # the kernels' fields are not these
            out.append(ft.rates_of_fields(s))
        return out

    def problem_at(self, y, tau, events, n_events):
        """The problem of the interval from ``tau`` (content layout ``y``): every thermal film's temperatures
        stepped over the interval that ended here (or, at the start, its fluidity set at the start's pressures) and
        its first sample at the new viscosities."""
        yu = self.form.universal_state(y)
        fresh = [not ft.started for ft in self.films]
        if any(fresh):
            self._rates(tau, yu)  # the films' pressures at the start
        for ft, new in zip(self.films, fresh, strict=True):
            if new:
                ft.set_fluidity()
            else:
                ft.advance(tau)
            ft.next_interval()
        for ft, (r, m) in zip(self.films, self._rates(tau, yu), strict=True):
            ft.observe(tau, r, m)
        return self.form.problem(y, tau, events, n_events)

    def sample(self, tau, y) -> dict:
        """Observe the universal state ``y`` at ``tau``: each thermal film's outputs
        (:meth:`~transient.models.journal.film_temperatures.FilmTemperatures.outputs`)."""
        rows = []
        for ft, (r, m) in zip(self.films, self._rates(tau, y), strict=True):
            ft.observe(tau, r, m)
            rows.append(ft.outputs(r, m))
        return {k: [row[k] for row in rows] for k in THERMAL_SERIES}

    def finish(self):
        """Step every film over its last sampled interval (once: a stop hook may ask between intervals)."""
        for ft in self.films:
            if ft.tau_last is not None:
                ft.advance(ft.tau_last)

    def arrays(self) -> dict:
        self.finish()
        return {f"{k}.{name}": v for k, ft in enumerate(self.films) for name, v in ft.arrays().items()}

    def restore(self, a: dict):
        for k, ft in enumerate(self.films):
            ft.restore({name: a[f"{k}.{name}"] for name in ("temperature", "ledger")})

    def final_temperature(self) -> np.ndarray:
        return np.concatenate([ft.final_temperature() for ft in self.films])


def start_temperatures(form, start, temperature, states) -> dict:
    """``{node: temperatures [K]}`` of the thermal films at a run's start: ``temperature`` (a number: every cell and
    feed), else a ``start`` result's ``final_temperature``, else those of the thermal equilibrium ``states``
    (``{node: FilmState}``)."""
    blocks = [form.dae.blocks[k] for k in form.thermal]
    sizes = [b.film.n + int(b.film.scales.feed_edges.size) for b in blocks]
    if temperature is not None:
        if np.ndim(temperature) != 0:
            raise ValueError(f"temperature has shape {np.shape(temperature)}; allowed: a number [K] (every thermal "
                             "film's cells and feeds at it)")
        for b in blocks:
            b.bearing.thermal.viscosity(float(temperature))  # in the viscosity law's range
        return {b.node: np.full(n, float(temperature)) for b, n in zip(blocks, sizes, strict=True)}
    final = getattr(start, "final_temperature", None)
    if final is not None:
        final = np.asarray(final, dtype=float)
        if final.shape != (sum(sizes),):
            raise ValueError(f"start.final_temperature has shape {final.shape}; allowed: ({sum(sizes)},) (the thermal "
                             "films' cells and feeds of this system)")
        return dict(zip([b.node for b in blocks], np.split(final, np.cumsum(sizes)[:-1]), strict=True))
    return {node: equilibrium_temperature(e) for node, e in states.items()}


def thermal_parts(parts, thermal: ThermalBearings, events, n_events, interval):
    """The :class:`~transient.solvers.model_run.RunParts` of a thermal rotor run from the isothermal ones: the
    problem of each thermal interval (:meth:`ThermalBearings.problem_at`), the thermal films' outputs, the result's
    thermal series, final temperatures and heat balances, the temperatures in the checkpoint."""
    def sample(tau, y):
        row = parts.sample(tau, y)
        row.update(thermal.sample(tau, y))
        return row

    def result(rec, *args):
        thermal.finish()
        r = parts.result(rec, *args)
        a = rec.arrays()
        r.thermal_nodes = list(thermal.nodes)
        for k in THERMAL_SERIES:
            setattr(r, k, np.asarray(a[k], dtype=float).reshape(-1, len(thermal.nodes)))
        r.final_temperature = thermal.final_temperature()
        r.heat_balance = [ft.heat_balance() for ft in thermal.films]
        return r

    start_T = hashlib.sha256(thermal.final_temperature().tobytes()).hexdigest()[:16]
    return replace(parts, problem_at=lambda y, tau: thermal.problem_at(y, tau, events, n_events),
                   series=(*parts.series, *THERMAL_SERIES), sample=sample, result=result, carry=thermal,
                   key=dict(parts.key, thermal_interval=interval, start_temperature=start_T))
