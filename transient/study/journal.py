"""Studies of the journal orbit (Rho & Kim, "Noise estimation of oil lubricated journal bearings"): the orbit from the
equilibrium (Figs. 3-4), the unbalance response over speed (Fig. 8) and the stability runs around the linear
threshold.

Fig. 8 by continuation (:func:`continuation_response`, the default): the periodic orbit at every speed by
shooting (:mod:`transient.models.journal.periodic`), each warm-started from the previous ones, continued past
the last speed until the dominant Floquet multiplier leaves the unit circle, the onset then located by
secant steps in speed; no settling runs.

Fig. 8 by settling (:func:`settled_unbalance_orbit`, the former way): each speed starts on the linear unbalance
response (:meth:`~transient.models.journal.JournalOrbit.linear_start`) and runs until the distance from the
settled orbit, estimated from the change between consecutive revolutions ``d`` and its decay ratio ``q`` as
``d q / (1 - q)``, is below ``settle_fraction`` of the orbit amplitude (by :func:`~transient.study.settle.settle`:
checked every 2 revolutions from ``min_revolutions`` on, capped at ``max_revolutions``; a point that did not get
there says "NOT settled"); the estimate is saved with each point.
"""

from __future__ import annotations


import numpy as np

from transient.analysis.orbits import (ellipse_semi_major, growth_per_revolution, orbit_shape, per_revolution,
                                       revolution_spectrum)
from transient.models.journal import JournalOrbit, OrbitResult
from transient.models.journal.periodic import response_curve, stability_onset
from transient.results import StatusResult, quantity, result_type
from transient.study.settle import settle
from transient.solvers.settings import Integration, LongRun, Recording


@result_type
class EquilibriumOrbit(StatusResult):
    """The orbit from the static equilibrium (Figs. 3-4) and its numbers: the run (``orbit``), the speed
    [rpm], the revolutions run, the equilibrium (eccentricity ratio, attitude angle [deg], centre [C]), the last
    revolution's shape [C] (:func:`~transient.analysis.orbits.orbit_shape`), the distance of each revolution
    from the last [C] and the revolution from which every later one (the last, the reference, aside) stays within
    ``settle_fraction`` of the amplitude (``settled_within_1pct_after_revs``; 0: none in the run; in words:
    :meth:`settling`), and
    the spectrum of x over the last ``fft_revolutions`` (orders of the shaft speed, amplitudes [C], the
    harmonics [C] and the order of the largest peak). :meth:`record` is the JSON-ready record of the numbers."""

    time_axis = None
    orbit: OrbitResult
    speed_rpm: float = quantity("rpm")
    revolutions: int = 0
    wall_s: float = quantity("s", 0.0)
    n_steps: int = 0
    eps_equilibrium: float = quantity("-", 0.0)
    attitude_deg: float = quantity("deg", 0.0)
    equilibrium: tuple = quantity("-", (0.0, 0.0))
    settled_orbit: dict = quantity("-", default_factory=dict)
    settle_distance_per_rev: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    settled_within_1pct_after_revs: int = 0
    spectrum_peak_order: float = quantity("-", 0.0)
    harmonics_C: dict = quantity("-", default_factory=dict)
    ratio_2x_to_1x: float = quantity("-", 0.0)
    fft_revolutions: int = 0
    spectrum_order: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))
    spectrum_amplitude_C: np.ndarray = quantity("-", default_factory=lambda: np.zeros(0))

    record_skip = ("orbit",)  # the run itself is saved on its own

    def settling(self) -> str:
        """The settling verdict with its numbers, as the figure and the log state it."""
        dist = np.asarray(self.settle_distance_per_rev)
        amp = self.settled_orbit.get("semi_major", float("nan"))
        if self.settled_within_1pct_after_revs:
            return f"within 1 % of the amplitude from revolution {self.settled_within_1pct_after_revs} on"
        if len(dist) < 2:
            return "not measured (fewer than 2 revolutions)"
        return (f"NOT within 1 % of the amplitude in {len(dist)} revolutions (revolution {len(dist) - 1}: "
                f"{100 * dist[-2] / amp:.1f} %)")


def settled_from(dist, amplitude, fraction=0.01) -> int:
    """The first revolution (1-based) from which every later one is within ``fraction * amplitude`` of the last
    (``dist``: the distance of each revolution from the last); 0 if none is. The last revolution is the reference
    (distance 0) and does not count."""
    dist = np.asarray(dist, dtype=float)
    return next((k + 1 for k in range(len(dist) - 1) if np.all(dist[k:-1] <= fraction * amplitude)), 0)


def orbit_from_equilibrium(orbit, revolutions, rtol, outputs_per_revolution=64, fft_revolutions=10,
                           settle_fraction=0.01) -> EquilibriumOrbit:
    """The paper's Fig. 3/4 run: ``revolutions`` from the static equilibrium (IDA), the settled ellipse, the
    distance of each revolution from the last, and the x spectrum over the last ``fft_revolutions``."""
    opr = outputs_per_revolution
    e = orbit.equilibrium()
    res = orbit.run(revolutions, integration=Integration(method="ida", rtol=rtol, atol=1e-9),
                    recording=Recording(outputs_per_revolution=opr),
                    long_run=LongRun(chunk_revolutions=5, progress=True))
    X, Y = per_revolution(res.x, res.y, opr, res.clearance)
    dist = np.max(np.hypot(X - X[-1], Y - Y[-1]), axis=1)  # each revolution vs the last
    shape = orbit_shape(X[-1], Y[-1])
    amp = shape["semi_major"]
    settled_at = settled_from(dist, amp, settle_fraction)
    nf = min(fft_revolutions, X.shape[0])
    order, spec, harm, peak = revolution_spectrum(X[-nf:])
    return EquilibriumOrbit(
        orbit=res, speed_rpm=orbit.speed_rpm, revolutions=revolutions, wall_s=res.stats.wall_time,
        n_steps=res.stats.n_steps, eps_equilibrium=e.eccentricity_ratio, attitude_deg=e.attitude_angle_deg,
        equilibrium=(e.position[0] / res.clearance, e.position[1] / res.clearance), settled_orbit=shape,
        settle_distance_per_rev=dist, settled_within_1pct_after_revs=settled_at, spectrum_peak_order=peak,
        harmonics_C=harm, ratio_2x_to_1x=harm["2x"] / harm["1x"], fft_revolutions=nf, spectrum_order=order,
        spectrum_amplitude_C=spec, success=res.success, message=res.message)


def settle_estimate(X, Y) -> float:
    """Distance of the last revolution from the settled orbit, relative to the orbit's largest radius: the
    change from one revolution to the next ``d`` (largest over the revolution) extrapolated with its decay
    ratio ``q = d_n / d_(n-1)`` (capped at 0.99) as ``d q / (1 - q)``. ``X``, ``Y``: (revolutions, samples)
    of :func:`~transient.analysis.orbits.per_revolution`; inf with fewer than 3 revolutions."""
    if X.shape[0] < 3:
        return float("inf")
    amp = orbit_shape(X[-1], Y[-1])["radius_max"]
    d = np.max(np.hypot(X[1:] - X[:-1], Y[1:] - Y[:-1]), axis=1)  # change from one revolution to the next
    q = min(d[-1] / d[-2], 0.99) if d[-2] > 0 else 0.99
    return float(d[-1] * q / (1.0 - q) / max(amp, 1e-300))  # remaining distance if the decay is geometric


@result_type
class UnbalanceOrbit(StatusResult):
    """The unbalance response at one speed settled from the linear start (:func:`settled_unbalance_orbit`): the
    settling run (``orbit``), the last revolution's shape [C] (:func:`~transient.analysis.orbits.orbit_shape`),
    the revolutions run, the estimated distance from the settled orbit over the amplitude
    (:func:`settle_estimate`), the integrator steps and the wall time [s]. ``success``: the estimate fell below
    the asked fraction (else "NOT settled")."""

    time_axis = None
    orbit: OrbitResult
    shape: dict = quantity("-", default_factory=dict)
    revolutions: int = 0
    settle_estimate: float = quantity("-", float("inf"))
    n_steps: int = 0
    wall_s: float = quantity("s", 0.0)


def settled_unbalance_orbit(orbit, rtol, outputs_per_revolution=64, min_revolutions=4, max_revolutions=40,
                            settle_fraction=1e-2) -> UnbalanceOrbit:
    """Settle from the linear start by the extrapolated-distance estimate (module docstring), by
    :func:`~transient.study.settle.settle` with the whole revolutions as the observable, checked every 2
    revolutions from ``min_revolutions`` on."""
    opr = outputs_per_revolution

    def revolutions(r):
        return per_revolution(r.x, r.y, opr, r.clearance)

    def criterion(XY):
        n = XY[0].shape[0]
        return n if n >= min_revolutions and settle_estimate(*XY) <= settle_fraction else None

    s = settle(orbit, observable=revolutions, criterion=criterion, max_periods=max_revolutions,
               outputs_per_period=opr, require=False, what=f"the unbalance orbit at {orbit.speed_rpm:g} rpm",
               integration=Integration(method="ida", rtol=rtol, atol=1e-9), long_run=LongRun(chunk_revolutions=2),
               y0=orbit.linear_start())
    res = s.result
    X, Y = revolutions(res)
    change = settle_estimate(X, Y)
    ok = res.success and res.touched_at is None and change <= settle_fraction
    msg = (f"settled: distance from the settled orbit ~{change:.1e} of the amplitude after {X.shape[0]} revolutions"
           if ok else f"NOT settled to {settle_fraction:g} in {X.shape[0]} revolutions (estimate {change:.1e})"
           + ("" if res.success and res.touched_at is None else f": {res.message}"))
    return UnbalanceOrbit(orbit=res, shape=orbit_shape(X[-1], Y[-1]), revolutions=X.shape[0], settle_estimate=change,
                          n_steps=res.stats.n_steps, wall_s=res.stats.wall_time, success=ok, message=msg)


def continuation_response(bearing, rotor, speeds, rtol, outputs_per_revolution=64, step_beyond=250.0,
                          max_speed=12000.0, whirl_revolutions=0, progress=False):
    """Fig. 8 by continuation (module docstring): periodic orbits along ``speeds`` (rotor: rotor_mass, unbalance,
    load), then on in ``step_beyond`` steps until one is unstable (at most to ``max_speed``; its quasi-periodic
    response integrated for ``whirl_revolutions``) and the onset by secant steps between the last stable and the
    first unstable orbit. Returns (the :class:`~transient.models.journal.periodic.ResponseCurve` along ``speeds``,
    a record: ``points`` (per speed: the orbit shape [C] of :func:`~transient.analysis.orbits.orbit_shape` and the
    shooting's numbers), ``beyond`` (the speeds past ``speeds``), ``onset_rpm``, ``secant`` (the orbits of the
    onset search), ``wall_s`` and ``periods`` in all)."""
    o = JournalOrbit(bearing, speed_rpm=float(speeds[0]), **rotor)
    kw = dict(rtol=rtol, outputs_per_revolution=outputs_per_revolution, whirl_revolutions=whirl_revolutions,
              progress=progress)
    curve = response_curve(o, speeds, **kw)
    history, beyond = [p for p in curve.orbits if p.converged], []
    s = float(speeds[-1])
    while all(p.stable for p in history) and s + step_beyond <= max_speed:
        s += step_beyond
        c = response_curve(o, [s], previous=history, **kw)
        p = c.orbits[0]
        beyond.append(dict(speed_rpm=s, max_multiplier=p.max_multiplier, stable=p.stable, message=p.message,
                           whirl_frequency_ratio=float(c.whirl_frequency_ratio[0]),
                           whirl_amplitude_C=float(c.whirl_amplitude[0] / bearing.clearance), wall_s=p.wall_time,
                           periods=p.revolutions_integrated))
        if not p.converged:
            break
        history.append(p)
    k = next((i for i in range(1, len(history)) if history[i - 1].stable and not history[i].stable), None)
    onset = None if k is None else stability_onset(o, history[k - 1], history[k], rtol=rtol)
    C = bearing.clearance
    points = []
    for p in curve.orbits:
        shape = orbit_shape(p.x[:-1] / C, p.y[:-1] / C) if p.t.size else {}
        points.append(dict(speed_rpm=p.speed_rpm, revolutions=p.revolutions_integrated, iterations=p.iterations,
                           max_multiplier=p.max_multiplier, stable=p.stable, converged=p.converged,
                           error_estimate_C=p.error_estimate / C, wall_s=p.wall_time, **shape))
    extra = [] if onset is None else onset.orbits[1:-1]
    rec = dict(points=points, beyond=beyond, onset_rpm=None if onset is None else onset.onset_rpm,
               secant=None if onset is None else dict(speed_rpm=onset.speed_rpm, max_multiplier=onset.max_multiplier),
               wall_s=float(curve.wall_time.sum() + sum(b["wall_s"] for b in beyond) + sum(p.wall_time for p in extra)),
               periods=int(curve.revolutions_integrated.sum() + sum(b["periods"] for b in beyond)
                           + sum(p.revolutions_integrated for p in extra)))
    return curve, rec


def linear_response_curve(bearing, rotor, speeds):
    """Amplitudes [C] of the linearised unbalance response at each speed (rotor: rotor_mass, unbalance, load)."""
    C = bearing.clearance
    out = []
    for s in speeds:
        Z = bearing.unbalance_response(rotor["rotor_mass"], rotor["unbalance"], rotor["load"], s)
        out.append(dict(speed_rpm=float(s), amp_x=float(abs(Z[0]) / C), amp_y=float(abs(Z[1]) / C),
                        semi_major=float(ellipse_semi_major(Z) / C)))
    return out


def stability_run(orbit, perturbation, revolutions, rtol, outputs_per_revolution=64):
    """Free vibration of the (balanced) rotor perturbed from its equilibrium by ``perturbation`` [C]: the
    distance from the equilibrium [C] against revolutions, its growth per revolution (envelope slope) and the
    linear growth rate per revolution. Returns (result, record dict)."""
    e = orbit.equilibrium()
    C = orbit.bearing.clearance
    res = orbit.run(revolutions, integration=Integration(method="ida", rtol=rtol, atol=1e-9),
                    recording=Recording(outputs_per_revolution=outputs_per_revolution),
                    long_run=LongRun(chunk_revolutions=5, progress=True), y0=orbit.perturbed_start(perturbation))
    r = np.hypot(res.x / C - e.position[0] / C, res.y / C - e.position[1] / C)
    slope, sel = growth_per_revolution(r, res.revolutions)
    lin = orbit.bearing.growth_rate(orbit.rotor_mass, orbit.load, orbit.speed_rpm) * 60.0 / orbit.speed_rpm
    return res, dict(speed_rpm=orbit.speed_rpm, revolutions=revolutions, growth_per_rev=slope,
                     linear_growth_per_rev=lin, envelope_first=float(r[sel][0]), envelope_last=float(r[sel][-1]),
                     verdict="grows" if slope > 0 else "decays", wall_s=res.stats.wall_time,
                     touched=res.touched_at is not None, revolutions_axis=res.revolutions.tolist(),
                     distance_C=r.tolist())
