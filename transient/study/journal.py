"""Studies of the journal orbit (seed 003, Rho & Kim): the orbit from the equilibrium (Figs. 3-4), the
unbalance response over speed (Fig. 8) and the stability runs around the linear threshold.

Settling of the Fig. 8 sweep: each speed starts on the linear unbalance response
(:meth:`~transient.models.journal.JournalOrbit.linear_start`) and runs until the distance from the settled
orbit, estimated from the change between consecutive revolutions ``d`` and its decay ratio ``q`` as
``d q / (1 - q)``, is below ``settle_fraction`` of the orbit amplitude (checked every 2 revolutions after
``min_revolutions``, capped at ``max_revolutions``); the estimate is saved with each point.
"""

from __future__ import annotations

import numpy as np

from transient.analysis.orbits import (ellipse_semi_major, growth_per_revolution, orbit_shape, per_revolution,
                                       revolution_spectrum)


def orbit_from_equilibrium(orbit, revolutions, rtol, outputs_per_revolution=64, fft_revolutions=10,
                           settle_fraction=0.01):
    """The paper's Fig. 3/4 run: ``revolutions`` from the static equilibrium (IDA), the settled ellipse, the
    distance of each revolution from the last, and the x spectrum over the last ``fft_revolutions``.
    Returns (orbit result, record dict of the numbers)."""
    opr = outputs_per_revolution
    e = orbit.equilibrium()
    res = orbit.run(revolutions, method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=opr,
                    chunk_revolutions=5, progress=True)
    X, Y = per_revolution(res.x, res.y, opr, res.clearance)
    dist = np.max(np.hypot(X - X[-1], Y - Y[-1]), axis=1)  # each revolution vs the last
    shape = orbit_shape(X[-1], Y[-1])
    amp = shape["semi_major"]
    settled_at = next((k + 1 for k in range(len(dist)) if np.all(dist[k:-1] <= settle_fraction * amp)), len(dist))
    nf = min(fft_revolutions, X.shape[0])
    order, spec, harm, peak = revolution_spectrum(X[-nf:])
    rec = dict(speed_rpm=orbit.speed_rpm, revolutions=revolutions, wall_s=res.stats.wall_time,
               n_steps=res.stats.n_steps, eps_equilibrium=e.eccentricity_ratio, attitude_deg=e.attitude_angle_deg,
               equilibrium=(e.position[0] / res.clearance, e.position[1] / res.clearance), settled_orbit=shape,
               settle_distance_per_rev=dist.tolist(), settled_within_1pct_after_revs=settled_at,
               spectrum_peak_order=peak, harmonics_C=harm, ratio_2x_to_1x=harm["2x"] / harm["1x"],
               fft_revolutions=nf, spectrum_order=order.tolist(), spectrum_amplitude_C=spec.tolist())
    return res, rec


def settled_unbalance_orbit(orbit, rtol, outputs_per_revolution=64, min_revolutions=4, max_revolutions=40,
                            settle_fraction=1e-2):
    """Settle from the linear start by the extrapolated-distance estimate (module docstring). Returns (the
    last revolution's shape dict, revolutions run, estimated distance / amplitude, steps, wall [s])."""
    opr = outputs_per_revolution
    res = orbit.run(min_revolutions, method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=opr,
                    y0=orbit.linear_start(), progress=False)
    xs, ys = [res.x], [res.y]
    steps, wall = res.stats.n_steps, res.stats.wall_time
    n = min_revolutions
    while True:
        X, Y = per_revolution(np.concatenate(xs), np.concatenate(ys), opr, res.clearance)
        amp = orbit_shape(X[-1], Y[-1])["radius_max"]
        d = np.max(np.hypot(X[1:] - X[:-1], Y[1:] - Y[:-1]), axis=1)  # change from one revolution to the next
        q = min(d[-1] / d[-2], 0.99) if d.size > 1 and d[-2] > 0 else 0.99
        change = float(d[-1] * q / (1.0 - q))  # remaining distance if the decay is geometric
        if change <= settle_fraction * amp or n >= max_revolutions or res.touched_at is not None:
            break
        extra = min(2, max_revolutions - n)
        res = orbit.run(extra, method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=opr, start=res,
                        progress=False)
        xs.append(res.x[1:])
        ys.append(res.y[1:])
        steps += res.stats.n_steps
        wall += res.stats.wall_time
        n += extra
    return orbit_shape(X[-1], Y[-1]), n, change / max(amp, 1e-300), steps, wall


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
    res = orbit.run(revolutions, method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=outputs_per_revolution,
                    y0=orbit.perturbed_start(perturbation), chunk_revolutions=5, progress=True)
    r = np.hypot(res.x / C - e.position[0] / C, res.y / C - e.position[1] / C)
    slope, sel = growth_per_revolution(r, res.revolutions)
    lin = orbit.bearing.growth_rate(orbit.rotor_mass, orbit.load, orbit.speed_rpm) * 60.0 / orbit.speed_rpm
    return res, dict(speed_rpm=orbit.speed_rpm, revolutions=revolutions, growth_per_rev=slope,
                     linear_growth_per_rev=lin, envelope_first=float(r[sel][0]), envelope_last=float(r[sel][-1]),
                     verdict="grows" if slope > 0 else "decays", wall_s=res.stats.wall_time,
                     touched=res.touched_at is not None, revolutions_axis=res.revolutions.tolist(),
                     distance_C=r.tolist())
