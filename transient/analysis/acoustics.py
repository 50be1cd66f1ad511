"""Bearing noise from the film pressure fluctuation (Rho & Kim, sections 2.3-2.4).

On the steady periodic response of :class:`~transient.models.journal.orbit.JournalOrbit`:

* per node, mean pressure p_m and RMS fluctuation p_f over an integer number of shaft periods
  (eqs. 11, 12), and the RMS amplitude of each shaft harmonic (1x, 2x, ...);
* plane-wave transmission to the air outside the shell (eqs. 13, 14), two forms:

  - ``"printed"`` (default, the paper's eq. 14): ``P_a = p_f * 2 / (1 + r_s / r_a)`` -- one interface,
    steel -> air, the oil film's pressure taken as the incident wave in the steel;
  - ``"two_interface"``: oil -> steel -> air, ``T = T_os * T_sa`` with the pressure transmission
    coefficient ``T_12 = 2 / (1 + r_1 / r_2)`` (eq. 13) at each interface, r = rho c. Oil
    rho = 870 kg/m^3, c = 1400 m/s are *assumed* (not in the paper). T_os = 1.94 so this form is
    5.75 dB above the printed one (a constant offset; every trend is the same);

* nodal sound pressure level ``N_ij = 20 log10(P_a / 20 uPa)`` (eq. 15), energy-averaged bearing
  level ``N_b = 10 log10(mean 10^(0.1 N_ij))`` over all nodes of the (half, symmetric) grid (eq. 16),
  per-harmonic bearing levels, and A-weighted levels (IEC 61672-1 A-weighting applied to each
  harmonic's mean square before summing; harmonics 1..``harmonics``).

Nodes with no fluctuation (the supply groove, held at p_s) have N_ij = -inf dB and contribute zero
energy to the average, but count in N_x N_y as in eq. (16).

:func:`analyse_pressure` takes a recorded window of the periodic response; the protocol that settles
the orbit and records that window is :func:`transient.study.noise.bearing_noise`.
"""

from __future__ import annotations

import time
from dataclasses import field

import numpy as np

from transient.analysis.spectra import amplitude_spectrum, harmonic_amplitudes, mean_and_fluctuation
from transient.results import StatusResult, quantity, result_type
from transient.units import rpm_to_hz

P_REF = 20e-6  #: reference sound pressure in air [Pa] (eq. 15)
P_REF_OIL = 1e-6  #: reference the paper uses for levels in the oil film (Figs. 6, 7) [Pa]
STEEL = dict(density=7700.0, sound_speed=5050.0)  #: bearing shell, paper Table 1
AIR = dict(density=1.18, sound_speed=344.0)  #: paper Table 1
OIL = dict(density=870.0, sound_speed=1400.0)  #: ASSUMED mineral oil (not in the paper)
TRANSMISSIONS = ("printed", "two_interface")


# -------------------------------------------------------------------------------------------------
def a_weighting(frequency_hz):
    """IEC 61672-1 A-weighting [dB] (closed form, normalised so that A(1000 Hz) = 0.00 dB).

    ``R_A(f) = 12194^2 f^4 / ((f^2 + 20.6^2) sqrt((f^2 + 107.7^2)(f^2 + 737.9^2)) (f^2 + 12194^2))``,
    ``A(f) = 20 log10(R_A(f) / R_A(1000))``. ``f = 0`` gives -inf."""
    f = np.asarray(frequency_hz, dtype=float)

    def ra(f):
        f2 = f * f
        return (12194.0 ** 2 * f2 * f2) / ((f2 + 20.6 ** 2) * np.sqrt((f2 + 107.7 ** 2) * (f2 + 737.9 ** 2))
                                           * (f2 + 12194.0 ** 2))

    with np.errstate(divide="ignore"):
        out = 20.0 * np.log10(ra(f) / ra(1000.0))
    return out if out.ndim else float(out)


def impedance(medium) -> float:
    """Characteristic acoustic impedance r = rho c [Pa s/m] of ``dict(density=, sound_speed=)``."""
    return float(medium["density"] * medium["sound_speed"])


def pressure_transmission(r1, r2) -> float:
    """Normal-incidence plane-wave pressure transmission coefficient medium 1 -> 2 (eq. 13):
    ``T_p = 2 / (1 + r_1 / r_2)``."""
    return 2.0 / (1.0 + r1 / r2)


def transmission_coefficient(transmission="printed", steel=STEEL, air=AIR, oil=OIL) -> float:
    """P_a / p_f: ``"printed"`` eq. (14) (steel -> air only) or ``"two_interface"`` (oil -> steel -> air)."""
    rs, ra = impedance(steel), impedance(air)
    if transmission == "printed":
        return pressure_transmission(rs, ra)
    if transmission == "two_interface":
        return pressure_transmission(impedance(oil), rs) * pressure_transmission(rs, ra)
    raise ValueError(f"transmission must be one of {TRANSMISSIONS}, got {transmission!r}")


def spl(p_rms, reference=P_REF):
    """Sound pressure level 20 log10(p / reference) [dB] (eq. 15); 0 Pa gives -inf."""
    with np.errstate(divide="ignore"):
        return 20.0 * np.log10(np.asarray(p_rms, dtype=float) / reference)


def energy_average(levels_db, axis=None):
    """10 log10(mean 10^(0.1 L)) (eq. 16); -inf entries count with zero energy."""
    L = np.asarray(levels_db, dtype=float)
    with np.errstate(divide="ignore"):
        return 10.0 * np.log10(np.mean(10.0 ** (0.1 * L), axis=axis))


def energy_sum(levels_db, axis=None):
    """10 log10(sum 10^(0.1 L)): the level of incoherent components together."""
    L = np.asarray(levels_db, dtype=float)
    with np.errstate(divide="ignore"):
        return 10.0 * np.log10(np.sum(10.0 ** (0.1 * L), axis=axis))


def film_transitions(state, row=0) -> dict:
    """Film reformation and rupture around the load-carrying film of a
    :class:`~transient.models.journal.FilmState` (e.g. the static equilibrium) along one axial row
    (row 0: next to the mid-plane), where the film content theta crosses 1.

    The full-film run (theta >= 1) containing the pressure maximum is the load-carrying film:
    ``reformation_index``/``reformation_deg`` is its first node (the film reforms there, coming out of
    the cavity upstream, in the direction of rotation) and ``rupture_index``/``rupture_deg`` its last
    (the film ruptures after it). ``cavities`` lists all cavitated runs as (first, last) node indices.
    Empty dict if the row has no cavitation."""
    th = np.asarray(state.film_content)[row]
    p = np.asarray(state.pressure)[row]
    ang = np.asarray(state.angle_deg)
    n = th.size
    full = th >= 1.0
    if full.all() or not full.any():
        return {}
    k = int(np.argmax(p))
    i = k
    while full[(i - 1) % n]:
        i -= 1
    j = k
    while full[(j + 1) % n]:
        j += 1
    ref, rup = i % n, j % n
    cavities = []
    for m in range(n):
        if not full[m] and full[(m - 1) % n]:
            e = m
            while not full[(e + 1) % n]:
                e += 1
            cavities.append((m, e % n))
    return dict(rupture_index=int(rup), rupture_deg=float(ang[rup]), reformation_index=int(ref),
                reformation_deg=float(ang[ref]), max_pressure_index=k, max_pressure_deg=float(ang[k]),
                cavities=cavities)


# -------------------------------------------------------------------------------------------------
@result_type
class BearingNoise(StatusResult):
    """Noise analysis of one speed. Arrays per node are (n_axial, n_theta) on the bearing grid (half
    bearing when symmetric, row 0 next to the mid-plane).

    ``p_mean``, ``p_fluct`` [Pa] (eqs. 12, 11); ``spl`` = N_ij [dB re 20 uPa, transmitted] (eq. 15);
    ``harmonic_rms`` [Pa] (harmonics, nz, nt) RMS amplitude of k x in the oil; ``harmonic_spl``
    transmitted N_ij of each harmonic; ``level_db`` = N_b (eq. 16, all content to Nyquist),
    ``level_db_harmonics`` (harmonics 1..H only), ``level_dba`` (A-weighted, harmonics 1..H),
    ``harmonic_levels_db`` / ``harmonic_levels_dba`` (energy average over nodes of each harmonic).
    ``timings`` [s]: ``integration`` (settling, no fields), ``recording`` (the analysis window, its
    integration plus the field recording), ``recording_overhead`` (estimate: window time minus the
    settling cost per revolution times its revolutions), ``analysis``.
    """

    speed_rpm: float = quantity("rpm")
    revolutions: int = quantity("rev")
    harmonics: int = quantity("-")
    samples_per_revolution: int = quantity("1/rev")
    settle_revolutions: int = quantity("rev")
    settled_at: int | None = quantity("rev")
    poincare_steps: np.ndarray = quantity("C")
    window_closure: float = quantity("C")
    transmission: str = quantity("")
    transmission_coefficient: float = quantity("-")
    angle_deg: np.ndarray = quantity("deg")
    z: np.ndarray = quantity("m")
    t: np.ndarray = quantity("s")
    x: np.ndarray = quantity("m")
    y: np.ndarray = quantity("m")
    pressure: np.ndarray = quantity("Pa", repr=False)
    p_mean: np.ndarray = quantity("Pa", repr=False)
    p_fluct: np.ndarray = quantity("Pa", repr=False)
    spl: np.ndarray = quantity("dB", repr=False)
    harmonic_rms: np.ndarray = quantity("Pa", repr=False)
    harmonic_spl: np.ndarray = quantity("dB", repr=False)
    harmonic_levels_db: np.ndarray = quantity("dB")
    harmonic_levels_dba: np.ndarray = quantity("dB(A)")
    level_db: float = quantity("dB")
    level_db_harmonics: float = quantity("dB")
    level_dba: float = quantity("dB(A)")
    timings: dict = quantity("s")
    message: str = field(default="periodic response analysed", kw_only=True)

    @property
    def frequency_hz(self) -> float:
        """Shaft frequency f_1 [Hz]."""
        return rpm_to_hz(self.speed_rpm)

    @property
    def harmonic_frequencies_hz(self) -> np.ndarray:
        return self.frequency_hz * np.arange(1, self.harmonics + 1)

    @property
    def x_spectrum(self):
        """(frequency [Hz], peak amplitude [m]) of the journal x motion over the window."""
        return self.spectrum("x")

    def oil_spl(self, reference=P_REF_OIL):
        """Level of p_f in the oil film, untransmitted (paper Fig. 6: re 1 uPa)."""
        return spl(self.p_fluct, reference)

    def node(self, angle_deg, row=0) -> tuple[int, int]:
        """(row, column) of the node nearest ``angle_deg`` on axial row ``row``."""
        d = np.abs(np.angle(np.exp(1j * np.radians(self.angle_deg - angle_deg))))
        return int(row), int(np.argmin(d))

    def spectrum(self, what="pressure", node=None, angle_deg=None, row=0, db=False, reference=None,
                 transmitted=False):
        """Amplitude spectrum over the analysis window: (frequency [Hz], amplitude).

        ``what``: ``"x"``, ``"y"`` [m] or ``"pressure"`` [Pa] at ``node`` = (row, column) or the node
        nearest ``angle_deg`` on ``row``. Amplitudes are peak values; ``db=True`` gives the level of
        the RMS value (peak / sqrt 2) re ``reference`` (default 1 uPa in the oil, 20 uPa when
        ``transmitted``), the mean (f = 0) excluded (set to -inf)."""
        dt = (self.t[1] - self.t[0]) if len(self.t) > 1 else 1.0
        if what in ("x", "y"):
            sig = self.x if what == "x" else self.y
        elif what == "pressure":
            if node is None:
                node = self.node(0.0 if angle_deg is None else angle_deg, row)
            sig = self.pressure[:, node[0], node[1]].astype(float)
        else:
            raise ValueError(f"what must be 'x', 'y' or 'pressure', got {what!r}")
        f, a = amplitude_spectrum(sig, dt)
        if transmitted:
            a = a * self.transmission_coefficient
        if not db:
            return f, a
        ref = reference if reference is not None else (P_REF if transmitted else P_REF_OIL)
        L = spl(a / np.sqrt(2.0), ref)
        L[0] = -np.inf
        return f, L

    def summary(self) -> dict:
        """JSON-ready scalars."""
        return dict(speed_rpm=self.speed_rpm, level_db=self.level_db, level_dba=self.level_dba,
                    level_db_harmonics=self.level_db_harmonics,
                    harmonic_levels_db=[float(v) for v in self.harmonic_levels_db],
                    harmonic_levels_dba=[float(v) for v in self.harmonic_levels_dba],
                    max_p_fluct_pa=float(self.p_fluct.max()), settle_revolutions=self.settle_revolutions,
                    settled_at=self.settled_at, window_closure=self.window_closure,
                    revolutions=self.revolutions, samples_per_revolution=self.samples_per_revolution,
                    transmission=self.transmission, transmission_coefficient=self.transmission_coefficient,
                    timings=dict(self.timings))


def analyse_pressure(pressure, x, y, t, speed_rpm, revolutions, harmonics, transmission="printed", angle_deg=None,
                     z=None, **meta) -> BearingNoise:
    """The noise analysis of a recorded window: ``pressure`` (N, nz, nt) [Pa] with N = revolutions * S
    uniform samples over exactly ``revolutions`` shaft periods (end point excluded)."""
    t0 = time.perf_counter()
    P = np.asarray(pressure)
    N = P.shape[0]
    S = N // revolutions
    if S * revolutions != N:
        raise ValueError(f"{N} samples are not an integer number of samples per revolution over {revolutions}")
    Pd = P.astype(float)
    p_m, p_f = mean_and_fluctuation(Pd, axis=0)
    h_rms = harmonic_amplitudes(Pd, revolutions, harmonics, axis=0, kind="rms")
    T = transmission_coefficient(transmission)
    N_ij = spl(T * p_f)
    h_spl = spl(T * h_rms)
    f1 = rpm_to_hz(speed_rpm)
    A = a_weighting(f1 * np.arange(1, harmonics + 1))
    h_levels = energy_average(h_spl.reshape(harmonics, -1), axis=1)
    h_levels_a = h_levels + A
    with np.errstate(divide="ignore"):
        ms_h = np.sum(h_rms ** 2, axis=0)
        ms_a = np.sum(h_rms ** 2 * (10.0 ** (0.1 * A))[:, None, None], axis=0)
    level_h = float(energy_average(spl(T * np.sqrt(ms_h))))
    level_a = float(energy_average(spl(T * np.sqrt(ms_a))))
    timings = dict(meta.pop("timings", {}))
    timings["analysis"] = time.perf_counter() - t0
    return BearingNoise(speed_rpm=float(speed_rpm), revolutions=int(revolutions), harmonics=int(harmonics),
                        samples_per_revolution=int(S), transmission=transmission, transmission_coefficient=T,
                        angle_deg=np.asarray(angle_deg) if angle_deg is not None else np.arange(P.shape[2]),
                        z=np.asarray(z) if z is not None else np.arange(P.shape[1]), t=np.asarray(t),
                        x=np.asarray(x), y=np.asarray(y), pressure=P, p_mean=p_m, p_fluct=p_f, spl=N_ij,
                        harmonic_rms=h_rms, harmonic_spl=h_spl, harmonic_levels_db=h_levels,
                        harmonic_levels_dba=h_levels_a, level_db=float(energy_average(N_ij)),
                        level_db_harmonics=level_h, level_dba=level_a, timings=timings,
                        settle_revolutions=meta.get("settle_revolutions", 0), settled_at=meta.get("settled_at"),
                        poincare_steps=np.asarray(meta.get("poincare_steps", np.zeros(0))),
                        window_closure=float(meta.get("window_closure", np.nan)))

