"""Seed 003 scenarios (Rho & Kim): unbalance orbit of a rigid rotor on the Elrod journal bearing.

Run: ``python scenarios/journal_orbit.py [--out DIR] [--grid NT NZ] [--quick] [--resume]``
(default: the paper's 151 x 21 half grid, figures and ``journal_orbit.json`` into
scenarios/out/journal/). Figures (paper numbering):

* Fig. 3 -- orbit from the static equilibrium at 6000 rpm settling onto the ellipse;
* Fig. 4 -- spectrum of x(t) over an integer number of revolutions of the settled orbit;
* Fig. 8 -- unbalance response amplitude against speed, 1000-7500 rpm (nonlinear transient runs,
  with the linearised K, C prediction as a line);
* stability -- the linear (Lund) threshold bracketed by nonlinear runs of a perturbed, balanced rotor
  just below and just above it (decay vs growth, compared with the linear growth rate).

Settling. The transient from the equilibrium decays as the bearing's least-damped mode; at 6000 rpm
(51 x 8 study, CVODE rtol 1e-6) the distance of each revolution from the settled one fell by ~1.6x per
revolution: 1e-4 C (1 % of the 0.013 C amplitude) after 10 revolutions, 1e-5 C after 15, the
integrator's noise (1e-6 C) after ~18. Fig. 3 therefore runs 30 revolutions and the spectrum uses the
last 10. Near the threshold the decay is slower (linear: -0.14 per revolution at 0.9 x threshold),
so the sweep does not start from the equilibrium: each speed is started on the linear unbalance
response (position and velocity from K and C, film solved quasi-steadily there) and run until the
distance from the settled orbit, estimated from the change between consecutive revolutions and its
decay ratio q (d q / (1 - q)), is below ``SETTLE_TOL`` of the amplitude (checked every 2 revolutions
after the first few, capped); the estimate is saved with each point (``settle_estimate``).

The JSON is rewritten after every stage and every sweep speed, so a crash loses at most one run;
``--resume`` reuses the sweep points already in it (same grid and settings).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from transient.params.rho_kim import BEARING as RHO_KIM_BEARING, ROTOR as RHO_KIM_ROTOR
from transient.models.journal.bearing import JournalBearing, omega
from transient.models.journal.orbit import JournalOrbit

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "out", "journal")
BEARING = RHO_KIM_BEARING
C = BEARING["clearance"]
MASS, LOAD, UNBALANCE = (RHO_KIM_ROTOR[k] for k in ("rotor_mass", "load", "unbalance"))
PAPER = dict(speed_rpm=6000, peak_speed_rpm=5000, threshold_rpm=7800, spectrum="1x dominant",
             orbit="settles from the equilibrium onto an ellipse")
PERTURB = 0.01  # initial offset of the balanced rotor in the stability runs [C]
SETTLE_TOL = 1e-2  # estimated distance from the settled orbit, as a fraction of its amplitude
OPR = 64  # outputs per revolution (spectrum up to 32x)

FULL = dict(grid=(151, 21), fig3_revs=30, fft_revs=10, speeds=(1000, 2000, 3000, 4000, 4500, 5000, 5500, 6000,
                                                                 6500, 7000, 7500),
            sweep_min_revs=4, sweep_max_revs=40, stab_revs=20, stab_factor=0.1, linear_speeds=40)
QUICK = dict(grid=(41, 6), fig3_revs=12, fft_revs=4, speeds=(1000, 3000, 5000, 6000, 7500),
             sweep_min_revs=3, sweep_max_revs=8, stab_revs=8, stab_factor=0.15, linear_speeds=15)


def log(msg):
    print(msg, flush=True)


class Saver:
    """The results dict, rewritten to disk (atomically) whenever a stage adds to it."""

    def __init__(self, path, meta, resume):
        self.path = path
        self.data = {"meta": meta}
        if resume and os.path.exists(path):
            old = json.load(open(path))
            if old.get("meta") == meta:
                self.data = old
                log(f"resuming from {path}")
            else:
                log(f"{path} was written with other settings: starting afresh")

    def put(self, key, value):
        self.data[key] = value
        self.save()

    def save(self):
        tmp = self.path + ".tmp"
        with open(tmp, "w") as f:
            json.dump(self.data, f, indent=1, default=float)
        os.replace(tmp, self.path)


def make_orbit(bearing, speed, unbalance=UNBALANCE):
    return JournalOrbit(bearing, rotor_mass=MASS, unbalance=unbalance, load=LOAD, speed_rpm=speed)


def per_rev(res, opr=OPR):
    """x, y [C] of the run reshaped to (revolution, sample) (the start sample dropped)."""
    n = (res.t.size - 1) // opr
    X = (res.x[1:1 + n * opr] / C).reshape(n, opr)
    Y = (res.y[1:1 + n * opr] / C).reshape(n, opr)
    return X, Y


def orbit_shape(X, Y):
    """Centre, semi-axes (from the covariance of a sampled ellipse: a = sqrt(2 lambda)) and the half
    peak-to-peak amplitudes of one revolution of samples [C]."""
    xc, yc = X.mean(), Y.mean()
    lam = np.linalg.eigvalsh(np.cov(np.vstack([X - xc, Y - yc]), bias=True))
    return dict(centre=(float(xc), float(yc)), semi_major=float(np.sqrt(2 * lam[1])),
                semi_minor=float(np.sqrt(2 * lam[0])), amp_x=float(0.5 * np.ptp(X)), amp_y=float(0.5 * np.ptp(Y)),
                radius_max=float(np.max(np.hypot(X - xc, Y - yc))))


def linear_response(bearing, speed):
    """Steady unbalance response of the linearised rotor m x'' + C x' + K x = m e W^2 (cos, sin):
    complex amplitudes Z [m] with x(t) = Re(Z_x e^{i W t}), y = Re(Z_y e^{i W t})."""
    K, Cm = bearing.coefficients(LOAD, speed)
    w = omega(speed)
    A = K + 1j * w * Cm - MASS * w * w * np.eye(2)
    return np.linalg.solve(A, MASS * UNBALANCE * w * w * np.array([1.0, -1j]))


def hot_start(orbit, Z):
    """State on the linear unbalance response at t = 0: position and velocity (d/dtau) from Z, film
    solved quasi-steadily for them."""
    e = orbit.equilibrium()
    X = e.position[0] / C + Z[0].real / C
    Y = e.position[1] / C + Z[1].real / C
    VX, VY = (1j * Z[0]).real / C, (1j * Z[1]).real / C
    f = orbit.film
    u, _ = f.solve(X, Y, VX, VY, u0=e.u)
    y0 = orbit.initial_state()
    y0[:f.n] = u
    y0[f.n:f.n + 4] = X, Y, VX, VY
    return y0


# --------------------------------------------------------------------------------------------------
def fig3_fig4(bearing, cfg, rtol, out, saver):
    """Orbit from the equilibrium at 6000 rpm; settling; x spectrum of the settled orbit."""
    speed = PAPER["speed_rpm"]
    o = make_orbit(bearing, speed)
    e = o.equilibrium()
    log(f"[fig 3] {speed} rpm: equilibrium e/C = {e.eccentricity_ratio:.4f}, attitude "
        f"{e.attitude_angle_deg:.1f} deg; {cfg['fig3_revs']} revolutions from it (IDA rtol {rtol:g}) ...")
    t0 = time.perf_counter()
    res = o.run(cfg["fig3_revs"], method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=OPR,
                chunk_revolutions=5, progress=True)
    wall = time.perf_counter() - t0
    X, Y = per_rev(res)
    dist = np.max(np.hypot(X - X[-1], Y - Y[-1]), axis=1)  # each revolution vs the last
    shape = orbit_shape(X[-1], Y[-1])
    amp = shape["semi_major"]
    settled_at = next((k + 1 for k in range(len(dist)) if np.all(dist[k:-1] <= 0.01 * amp)), len(dist))
    # spectrum of x over the last fft_revs revolutions (integer number: harmonics fall on bins)
    nf = cfg["fft_revs"]
    xs = X[-nf:].ravel()
    spec = np.abs(np.fft.rfft(xs - xs.mean())) * 2 / xs.size
    order = np.fft.rfftfreq(xs.size, d=1.0 / OPR)  # in multiples of the shaft speed
    harm = {f"{h}x": float(spec[int(np.argmin(np.abs(order - h)))]) for h in (0.5, 1, 2, 3, 4)}
    peak_order = float(order[1 + int(np.argmax(spec[1:]))])
    rec = dict(speed_rpm=speed, revolutions=cfg["fig3_revs"], wall_s=wall, n_steps=res.stats.n_steps,
               eps_equilibrium=e.eccentricity_ratio, attitude_deg=e.attitude_angle_deg,
               equilibrium=(e.position[0] / C, e.position[1] / C), settled_orbit=shape,
               settle_distance_per_rev=dist.tolist(), settled_within_1pct_after_revs=settled_at,
               spectrum_peak_order=peak_order, harmonics_C=harm, ratio_2x_to_1x=harm["2x"] / harm["1x"],
               fft_revolutions=nf)
    saver.put("fig3_fig4", rec)
    np.savez(os.path.join(out, "orbit_6000rpm.npz"), t=res.t, x=res.x, y=res.y)

    fig, axs = plt.subplots(1, 2, figsize=(11, 4.8))
    ax = axs[0]
    ax.plot(res.y / C, res.x / C, lw=0.5, color="0.6", label="transient from equilibrium")
    ax.plot(np.append(Y[-1], Y[-1][0]), np.append(X[-1], X[-1][0]), lw=1.8, color="tab:red",
            label=f"settled orbit (rev {len(dist)})")
    ax.plot(e.position[1] / C, e.position[0] / C, "k+", ms=10, label="static equilibrium")
    ax.set_xlabel("y / C  (90 deg ahead of the load in the direction of rotation)")
    ax.set_ylabel("x / C  (towards the load)")
    ax.invert_yaxis()
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    ax.set_title(f"Fig. 3: journal orbit, {speed} rpm, {bearing.grid_shape[0]}x{bearing.grid_shape[1]}", fontsize=10)
    ax = axs[1]
    ax.semilogy(np.arange(1, len(dist)), dist[:-1], "o-", ms=3)  # the last revolution is the reference
    ax.axhline(0.01 * amp, color="0.5", ls=":", lw=0.8)
    ax.set_xlabel("revolution")
    ax.set_ylabel("max distance from the last revolution [C]")
    ax.set_title(f"settling (1 % of the amplitude: dotted) -- within 1 % after {settled_at} rev", fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "journal_fig3_orbit.png"), dpi=130)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.semilogy(order, np.maximum(spec, 1e-12), lw=1.0)
    for h, v in harm.items():
        if h != "0.5x":
            ax.annotate(h, (float(h[:-1]), v), textcoords="offset points", xytext=(3, 4), fontsize=8)
    ax.set_xlim(0, 8)
    ax.set_ylim(max(spec[1:].max() * 1e-8, 1e-12), spec.max() * 3)
    ax.set_xlabel("frequency / shaft speed")
    ax.set_ylabel("amplitude of x [C]")
    ax.set_title(f"Fig. 4: spectrum of x, {speed} rpm, last {nf} revolutions (largest peak at {peak_order:g}x)",
                 fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "journal_fig4_spectrum.png"), dpi=130)
    plt.close(fig)
    log(f"[fig 3] {wall:.1f} s; settled orbit semi-axes {shape['semi_major']:.4f} / {shape['semi_minor']:.4f} C, "
        f"within 1 % after {settled_at} revolutions")
    log(f"[fig 4] largest peak at {peak_order:g}x; 1x {harm['1x']:.3e} C, 2x/1x = {harm['2x'] / harm['1x']:.2e}")
    return rec


def settle_run(o, y0, cfg, rtol, ckpt):
    """Run from y0 until two consecutive revolutions agree to SETTLE_TOL of the amplitude (or the cap).
    Extensions continue from the checkpoint ``ckpt`` (the run's final state), so nothing is redone."""
    if os.path.exists(ckpt):
        os.remove(ckpt)
    n = cfg["sweep_min_revs"]
    steps = wall = 0
    while True:
        res = o.run(n, method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=OPR, y0=y0, checkpoint=ckpt,
                    resume=True, chunk_revolutions=n, progress=False)
        steps += res.stats.n_steps
        wall += res.stats.wall_time
        X, Y = per_rev(res)
        amp = orbit_shape(X[-1], Y[-1])["radius_max"]
        d = np.max(np.hypot(X[1:] - X[:-1], Y[1:] - Y[:-1]), axis=1)  # change from one revolution to the next
        q = min(d[-1] / d[-2], 0.99) if d.size > 1 and d[-2] > 0 else 0.99
        change = float(d[-1] * q / (1.0 - q))  # remaining distance if the decay is geometric
        if change <= SETTLE_TOL * amp or n >= cfg["sweep_max_revs"] or res.touched_at is not None:
            break
        n = min(cfg["sweep_max_revs"], n + 2)
    os.remove(ckpt)
    return res, n, change / max(amp, 1e-300), steps, wall


def fig8(bearing, cfg, rtol, out, saver):
    """Unbalance response amplitude against speed (nonlinear points + linear line)."""
    sweep = {int(p["speed_rpm"]): p for p in saver.data.get("fig8", {}).get("points", [])}
    lin_speeds = np.linspace(min(cfg["speeds"]), max(cfg["speeds"]), cfg["linear_speeds"])
    lin = saver.data.get("fig8", {}).get("linear")
    if lin is None:
        log(f"[fig 8] linear unbalance response at {len(lin_speeds)} speeds ...")
        lin = []
        for s in lin_speeds:
            Z = linear_response(bearing, s)
            lin.append(dict(speed_rpm=float(s), amp_x=float(abs(Z[0]) / C), amp_y=float(abs(Z[1]) / C),
                            semi_major=float(_semi_major(Z) / C)))
        saver.put("fig8", dict(points=list(sweep.values()), linear=lin))
    for s in cfg["speeds"]:
        if s in sweep:
            log(f"[fig 8] {s} rpm: from the saved results")
            continue
        o = make_orbit(bearing, s)
        Z = linear_response(bearing, s)
        y0 = hot_start(o, Z)
        res, n, change, steps, wall = settle_run(o, y0, cfg, rtol, os.path.join(out, "sweep_checkpoint.npz"))
        X, Y = per_rev(res)
        shape = orbit_shape(X[-1], Y[-1])
        p = dict(speed_rpm=s, revolutions=n, settle_estimate=change, n_steps=steps, wall_s=wall,
                 eps_equilibrium=o.equilibrium().eccentricity_ratio, **shape,
                 linear_amp_x=float(abs(Z[0]) / C), linear_amp_y=float(abs(Z[1]) / C),
                 linear_semi_major=float(_semi_major(Z) / C))
        sweep[s] = p
        saver.put("fig8", dict(points=[sweep[k] for k in sorted(sweep)], linear=lin))
        log(f"[fig 8] {s:5d} rpm: semi-major {shape['semi_major']:.4f} C (linear {p['linear_semi_major']:.4f}), "
            f"amp x {shape['amp_x']:.4f}, y {shape['amp_y']:.4f} C; {n} rev, est. distance from settled {change:.1e} of amplitude, {wall:.1f} s")
    pts = [sweep[k] for k in sorted(sweep)]
    sp = np.array([p["speed_rpm"] for p in pts], float)
    peak = {k: _peak(sp, np.array([p[k] for p in pts])) for k in ("semi_major", "amp_x", "amp_y")}
    ls = np.array([p["speed_rpm"] for p in lin])
    peak_lin = {k: _peak(ls, np.array([p[k] for p in lin])) for k in ("semi_major", "amp_x", "amp_y")}
    rec = dict(points=pts, linear=lin, peak_speed_rpm=peak, linear_peak_speed_rpm=peak_lin)
    saver.put("fig8", rec)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, c, lab in (("semi_major", "k", "orbit semi-major axis"), ("amp_x", "tab:blue", "x amplitude"),
                      ("amp_y", "tab:orange", "y amplitude")):
        ax.plot(ls, [p[k] for p in lin], "-", color=c, lw=0.8, alpha=0.7)
        ax.plot(sp, [p[k] for p in pts], "o", color=c, ms=5, label=f"{lab} (peak {peak[k]:.0f} rpm)")
    ax.axvline(PAPER["peak_speed_rpm"], color="0.5", ls=":", lw=0.8)
    ax.text(PAPER["peak_speed_rpm"], ax.get_ylim()[1] * 0.98, " paper peak", va="top", fontsize=8, color="0.4")
    ax.set_xlabel("shaft speed [rpm]")
    ax.set_ylabel("unbalance response amplitude [C]")
    ax.set_title("Fig. 8: unbalance response (markers: nonlinear transient; lines: linearised K, C)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "journal_fig8_response.png"), dpi=130)
    plt.close(fig)
    log(f"[fig 8] peak of the semi-major axis at {peak['semi_major']:.0f} rpm (linear {peak_lin['semi_major']:.0f}; "
        f"paper ~{PAPER['peak_speed_rpm']})")
    return rec


def _semi_major(Z):
    """Semi-major axis of the ellipse Re(Z e^{it})."""
    M = np.array([[Z[0].real, -Z[0].imag], [Z[1].real, -Z[1].imag]])
    return float(np.linalg.svd(M, compute_uv=False)[0])


def _peak(x, y):
    """Abscissa of the maximum, refined by a parabola through it and its neighbours."""
    i = int(np.argmax(y))
    if 0 < i < len(y) - 1:
        A = np.vstack([x[i - 1:i + 2] ** 2, x[i - 1:i + 2], np.ones(3)]).T
        a, b, _ = np.linalg.solve(A, y[i - 1:i + 2])
        if a < 0:
            return float(np.clip(-b / (2 * a), x[i - 1], x[i + 1]))
    return float(x[i])


def stability(bearing, cfg, rtol, out, saver):
    """Linear threshold and nonlinear runs of a balanced rotor, perturbed from the equilibrium by
    PERTURB, at (1 -/+ stab_factor) x threshold. Growth per revolution: slope of log r at the local
    maxima of the distance r(t) from the equilibrium (past the first quarter of the run); the speed
    where the two slopes interpolate to zero is the transient runs' estimate of the threshold."""
    log("[stability] linear threshold (Lund) ...")
    t0 = time.perf_counter()
    th = bearing.stability_threshold(rotor_mass=MASS, load=LOAD)
    log(f"[stability] threshold {th:.0f} rpm ({time.perf_counter() - t0:.1f} s; paper ~{PAPER['threshold_rpm']})")
    rec = dict(threshold_rpm=th, runs=[])
    saver.put("stability", rec)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for f in (1 - cfg["stab_factor"], 1 + cfg["stab_factor"]):
        s = f * th
        o = make_orbit(bearing, s, unbalance=0.0)
        e = o.equilibrium()
        y0 = o.initial_state()
        n = o.film.n
        y0[n] += PERTURB  # towards the load, film solved for it (journal at rest)
        y0[:n] = o.film.solve(y0[n], y0[n + 1], u0=e.u)[0]
        log(f"[stability] {s:.0f} rpm ({f:.2f} x threshold): {cfg['stab_revs']} revolutions, balanced rotor, "
            f"perturbed by {PERTURB:g} C ...")
        res = o.run(cfg["stab_revs"], method="ida", rtol=rtol, atol=1e-9, outputs_per_revolution=OPR, y0=y0,
                    chunk_revolutions=5, progress=True)
        r = np.hypot(res.x / C - e.position[0] / C, res.y / C - e.position[1] / C)
        rev = res.revolutions
        pk = np.flatnonzero((r[1:-1] > r[:-2]) & (r[1:-1] >= r[2:])) + 1  # local maxima of r(t)
        sel = pk[rev[pk] > 0.25 * rev[-1]]
        if sel.size < 2:
            sel = pk[-2:] if pk.size >= 2 else np.array([0, r.size - 1])
        slope = float(np.polyfit(rev[sel], np.log(r[sel]), 1)[0])  # growth per revolution
        env = r[sel]
        lin = bearing.growth_rate(MASS, LOAD, s) * 60.0 / s
        run = dict(speed_rpm=s, factor=f, revolutions=cfg["stab_revs"], growth_per_rev=slope,
                   linear_growth_per_rev=lin, envelope_first=float(env[0]), envelope_last=float(env[-1]),
                   verdict="grows" if slope > 0 else "decays", wall_s=res.stats.wall_time,
                   touched=res.touched_at is not None)
        rec["runs"].append(run)
        saver.put("stability", rec)
        ax.semilogy(res.revolutions, np.maximum(r, 1e-12), lw=0.6,
                    label=f"{s:.0f} rpm ({f:.2f} x): {slope:+.3f}/rev (linear {lin:+.3f})")
        log(f"[stability] {s:.0f} rpm: envelope {env[0]:.3e} -> {env[-1]:.3e} C, {slope:+.4f} per rev "
            f"(linear {lin:+.4f}) -> {run['verdict']}")
    (a, b) = rec["runs"]
    if a["growth_per_rev"] < 0 < b["growth_per_rev"]:
        rec["transient_threshold_rpm"] = a["speed_rpm"] - a["growth_per_rev"] * (b["speed_rpm"] - a["speed_rpm"]) / (
            b["growth_per_rev"] - a["growth_per_rev"])
        log(f"[stability] zero growth interpolated between the transient runs: {rec['transient_threshold_rpm']:.0f} rpm")
    saver.put("stability", rec)
    ax.set_xlabel("revolutions")
    ax.set_ylabel("distance from the equilibrium [C]")
    ax.set_title(f"Stability: linear threshold {th:.0f} rpm (paper ~{PAPER['threshold_rpm']}), nonlinear runs",
                 fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "journal_stability.png"), dpi=130)
    plt.close(fig)
    return rec


def summary(data):
    f3, f8, st = data.get("fig3_fig4", {}), data.get("fig8", {}), data.get("stability", {})
    rows = [("quantity", "this model", "paper")]
    if f3:
        so = f3["settled_orbit"]
        rows += [("equilibrium e/C at 6000 rpm", f"{f3['eps_equilibrium']:.4f}", "(not given)"),
                 ("orbit at 6000 rpm", f"ellipse, semi-axes {so['semi_major']:.4f} / {so['semi_minor']:.4f} C, "
                                       f"within 1 % after {f3['settled_within_1pct_after_revs']} rev", PAPER["orbit"]),
                 ("x spectrum", f"largest peak {f3['spectrum_peak_order']:g}x, 2x/1x = {f3['ratio_2x_to_1x']:.1e}",
                  PAPER["spectrum"])]
    if f8.get("peak_speed_rpm"):
        pk, pl = f8["peak_speed_rpm"], f8["linear_peak_speed_rpm"]
        rows.append(("unbalance response peak", f"{pk['semi_major']:.0f} rpm (x {pk['amp_x']:.0f}, y {pk['amp_y']:.0f}; "
                                                 f"linear {pl['semi_major']:.0f})", f"~{PAPER['peak_speed_rpm']} rpm"))
    if st.get("threshold_rpm"):
        runs = "; ".join(f"{r['speed_rpm']:.0f} rpm {r['verdict']} ({r['growth_per_rev']:+.3f}/rev, linear "
                         f"{r['linear_growth_per_rev']:+.3f})" for r in st.get("runs", []))
        tt = st.get("transient_threshold_rpm")
        tt = f"; zero growth between them at {tt:.0f} rpm" if tt else ""
        rows.append(("instability onset", f"{st['threshold_rpm']:.0f} rpm (linear); transient runs: {runs}{tt}",
                     f"~{PAPER['threshold_rpm']} rpm"))
    return "\n".join(f"{q}\n    this model: {m}\n    paper:      {p}" for q, m, p in rows[1:])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=OUT, help="output folder (default: scenarios/out/journal)")
    ap.add_argument("--grid", nargs=2, type=int, metavar=("NT", "NZ"), help="film grid (default 151 21; quick 41 6)")
    ap.add_argument("--quick", action="store_true", help="coarse, fast version")
    ap.add_argument("--rtol", type=float, default=1e-5, help="IDA relative tolerance (default 1e-5)")
    ap.add_argument("--resume", action="store_true", help="reuse the sweep points already in the JSON")
    ap.add_argument("--only", choices=("fig3", "fig8", "stability"), nargs="+", help="run only these stages")
    a = ap.parse_args(argv)
    cfg = dict(QUICK if a.quick else FULL)
    if a.grid:
        cfg["grid"] = tuple(a.grid)
    os.makedirs(a.out, exist_ok=True)
    meta = dict(grid=list(cfg["grid"]), quick=a.quick, rtol=a.rtol, bearing=BEARING, mass=MASS, load=LOAD,
                unbalance=UNBALANCE, speeds=list(cfg["speeds"]))
    saver = Saver(os.path.join(a.out, "journal_orbit.json"), meta, a.resume)
    bearing = JournalBearing(**BEARING, grid=cfg["grid"])
    log(f"journal orbit scenarios: grid {cfg['grid'][0]} x {cfg['grid'][1]}, rtol {a.rtol:g}, out {a.out}")
    t0 = time.perf_counter()
    stages = a.only or ("fig3", "fig8", "stability")
    if "fig3" in stages:
        fig3_fig4(bearing, cfg, a.rtol, a.out, saver)
    if "fig8" in stages:
        fig8(bearing, cfg, a.rtol, a.out, saver)
    if "stability" in stages:
        stability(bearing, cfg, a.rtol, a.out, saver)
    saver.put("wall_s", time.perf_counter() - t0)
    text = summary(saver.data)
    log("\n" + text + f"\n\ntotal {time.perf_counter() - t0:.0f} s; results in {saver.path}")
    return saver.data


if __name__ == "__main__":
    main(sys.argv[1:])
