"""Thrust ball bearing starvation: the per-ball starvation / replenishment sequence (Jeong et al.).

Jeong, Lee, Yoo & Cho (J. Korean Soc. Tribol. Lubr. Eng. 33(3), 2017) follow the oil film on the
race of a thrust ball bearing from ball to ball:

1. Ball n meets an inlet film ``h_in^n`` (``h_in^1 = h_inf``, the ambient film). The inlet meniscus
   sits where the dry gap outside the Hertz ellipse equals it, ``g(m b) = h_in`` (Newton–Raphson,
   elastic displacement included; :func:`transient.physics.hertz.meniscus_position`).
2. Hamrock–Dowson: fully flooded central film ``H_F``, critical meniscus ``m_c``, starved film
   ``H_S = H_F ((m-1)/(m_c-1))^0.29`` for ``m < m_c`` (:mod:`transient.physics.film_formulas`).
3. Between balls the depleted track levels under surface tension (Chiu 1974); the paper's recursion
   is ``h_in^n = h_in^{n-1} - Delta zeta``.

Here step 3 is a transient on the oil layer ``h(x, t)`` across the track: each ball pass is an
event that leaves the race the outlet film of the pass, ``h_c/2`` (half the central film on each surface),
over the depression half width ``a'`` (the Hertz semi-axis across the track, the paper's ``a_x``) and moves the
displaced oil into side ridges (fraction ``ridge_fraction``; the rest is carried away by the ball); the
thin-film equation with the pure ``h^3`` mobility is then integrated over the time between two balls
``t_b = 4 pi / (Z omega)`` (cage at half the shaft speed, 90 deg contact angle) on a mesh that follows the
re-wetting front advancing over that outlet film (:mod:`transient.models.ball.track`,
:mod:`transient.models.ball.front`; docs/ball.md). The next inlet film is the film on the track centreline
just before the next ball. ``grid="uniform"`` keeps the earlier formulation (uniform cells, optional
mobility floor ``h^3 + b^3``, :mod:`transient.models.ball.levelling`); ``replenishment="chiu"`` propagates
the same events with Chiu's linear Stokes-layer kernel (the paper's model, linearised about ``h_inf``).

Regime of a pass (stated criterion): *fully flooded* if ``m >= m_c``; otherwise *starved* if the oil
regained on the track since the previous pass, ``h_in^n - h_out^{n-1}``, is at least what the
contact passes, ``h_c^n`` (the paper's criterion after Liu: parched when the replenishment is less
than the oil flow through the Hertz contact), else *parched*. The sequence reaches a *periodic
steady state* when ``h_in`` changes by less than ``periodic_tol`` (relative) over 3 consecutive
passes; a sequence that is still falling after ``n_passes`` with ``m < m_c`` is a *parched decline*.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, astuple, dataclass, field, replace

import numpy as np

from transient.physics import film_formulas as hd
from transient.physics.hertz import (HertzContact, gap_rolling_axis, gap_rolling_axis_slope, hertz_contact,
                                     meniscus_position, reduced_modulus)
from transient.models.ball.numerical_film import LayerTooThin, NumericalFilms
from transient.models.ball.passes import REGIMES, SERIES, PassMap, formula_film, numerical_film
from transient.models.ball.track import FrontTrack, UniformTrack
from transient.checks import check_bool, check_choice, check_instance, check_int, check_range
from transient.results import StatusResult, quantity, record_type, result_type
from transient.solvers.integrate import Stats, check_method
from transient.models.ball.settings import TrackSettings
from transient.solvers.legacy import flat_settings
from transient.solvers.model_run import ModelRun, Recorder, RunParts, check_run_memory, start_point
from transient.solvers.settings import (Integration, LongRun, Recording, check_unused, keyword_table,
                                        requested_method, run_settings)
from transient.units import rpm_to_rad_s

FLOODED, STARVED, PARCHED = REGIMES
OWNER = "ThrustBallBearing.sequence"
#: how the run driver says a run reached its last output (the sequence's message is then empty)
_NORMAL_END = "reached the final time"
#: the film of a pass: Hamrock-Dowson with the 0.29 starvation law, or the numerical starved point contact
CONTACTS = ("formula", "numerical")
#: The loose keywords of :meth:`ThrustBallBearing.sequence` of earlier releases and the settings field each now is.
SEQUENCE_KEYWORDS = (keyword_table("track", TrackSettings)
                     | keyword_table("integration", Integration, ("method", "rtol", "atol", "dt", "linear_solver"))
                     | {"record_profiles": ("recording", Recording, "record", lambda on: ("profiles",) if on else ())})
#: The sequence's own integration defaults (the levelling's film is in units of ``h_inf``).
SEQUENCE_DEFAULTS = {"integration": dict(method="cvode", atol=1e-10)}


def sequence_settings(**flat) -> dict:
    """The ``track``, ``integration`` and ``recording`` objects of :meth:`ThrustBallBearing.sequence` from a flat
    table of its settings (``sequence_settings(grid="uniform", rtol=1e-4)``; the sequence's own defaults for the
    rest), e.g. a parameter set such as :data:`transient.params.jeong.MAP_SETTINGS`:
    ``bearing.sequence(30, 80, 1e-4, **sequence_settings(**MAP_SETTINGS))``."""
    return flat_settings(SEQUENCE_KEYWORDS, flat, SEQUENCE_DEFAULTS)



@record_type
@dataclass(frozen=True)
class FloodedFilm:
    """Fully flooded Hamrock–Dowson film of one contact: groups, films [m], critical menisci."""

    U: float
    G: float
    W: float
    H_c: float
    H_min: float
    h_c: float
    h_min: float
    m_c: float
    m_star: float
    speed: float


@result_type
class BallSequence(StatusResult):
    """Ball-after-ball film sequence. Arrays indexed by pass n = 0 .. n_run-1 (films in m).

    ``h_inlet`` inlet film met by the ball, ``h_central``/``h_minimum`` Hamrock–Dowson films,
    ``m`` meniscus position, ``regime`` per pass, ``h_outlet`` film left on the track. ``m_c`` and
    ``m_star`` are the critical menisci (same for every pass), ``flooded`` the fully flooded film,
    ``t_between`` the time between balls [s], ``periodic`` whether a periodic steady state was
    found (``n_periodic`` the pass where it was detected), ``declining`` a parched decline,
    ``final_regime`` the regime of the sequence, ``stats`` integrator totals,
    ``profiles`` the track profiles [m] just before each ball (if recorded), ``x`` their abscissae [m].
    """

    time_axis = "h_inlet"  # one row per ball pass
    h_inlet: np.ndarray = quantity("m")
    h_central: np.ndarray = quantity("m")
    h_minimum: np.ndarray = quantity("m")
    h_outlet: np.ndarray = quantity("m")
    m: np.ndarray = quantity("-")
    regime: list = quantity("")
    m_c: float = quantity("-")
    m_star: float = quantity("-")
    flooded: FloodedFilm = None
    contact: HertzContact = None
    t_between: float = quantity("s", 0.0)
    periodic: bool = False
    n_periodic: int = -1
    declining: bool = False
    final_regime: str = ""
    stats: dict = field(default_factory=dict)
    x: np.ndarray | None = quantity("m", None)
    profiles: np.ndarray | None = quantity("m", None)
    volume: np.ndarray | None = quantity("m^2", None)
    final_state: np.ndarray | None = None
    final_time: float = quantity("-", 0.0)

    #: the run's state is for continuing it (``sequence(start=result)``), not a study's number
    record_skip = ("final_state",)

    @property
    def n_run(self) -> int:
        return self.h_inlet.size

    @property
    def H_central(self) -> np.ndarray:
        """Dimensionless central film ``H_c = h_c / r_b`` as plotted by the paper (r_b = ball radius = Rx)."""
        return self.h_central / self.contact.rx


class _Meniscus:
    """``meniscus_position`` with memory: a repeated inlet film is answered from the cache, a nearby one by
    Newton from the previous root (the sequence's inlet films change little from ball to ball; the cold start
    costs ~15 quadratures of Love's integral, a warm one ~4). Same tolerance, same root."""

    def __init__(self, contact: HertzContact):
        self.c = contact
        self.cache = {}
        self.last = None

    def __call__(self, h_in: float, tol: float = 1e-12) -> float:
        if h_in in self.cache:
            return self.cache[h_in]
        c = self.c
        m = None
        if self.last is not None and h_in > 0.0:
            x = self.last * c.b
            for _ in range(8):
                g = gap_rolling_axis(c, x) - h_in
                if abs(g) <= tol * h_in:
                    m = x / c.b
                    break
                dg = gap_rolling_axis_slope(c, x)
                xn = x - g / dg if dg > 0 else -1.0
                if not xn > c.b:
                    break
                x = xn
        if m is None:
            m = meniscus_position(c, h_in, tol=tol)
        if len(self.cache) < 4096:
            self.cache[h_in] = m
        self.last = m if m > 1.0 else None
        return m


@dataclass(frozen=True)
class ThrustBallBearing:
    """Thrust ball bearing (90 deg contact angle), one race rotating at the shaft speed, SI units.

    Defaults: the paper's Table 1 (E = 207 GPa, nu = 0.3, pitch diameter 31 mm, ball 3 mm,
    surface tension 0.036 N/m, viscosity 0.02 Pa s) and Table 2 (6 balls, conformity 0.52). The
    pressure–viscosity coefficient is not in the paper: 2.0e-8 1/Pa (a typical mineral oil).

    Geometry: the race is flat along the rolling direction and grooved across it with radius
    ``f d``, so ``Rx = d/2`` and ``Ry = f d / (2 f - 1)``.

    ``contact``: the film of each ball pass from ``"formula"`` (Hamrock-Dowson and the starvation law
    ``H_F ((m-1)/(m_c-1))^0.29``, the paper's) or ``"numerical"`` (the starved point contact at the pass's inlet
    film, :mod:`transient.models.ball.numerical_film`, on ``contact_grid`` nodes). The per-ball Hertz contact is
    :meth:`hertz`.
    """

    pitch_diameter: float = 0.031
    ball_diameter: float = 0.003
    n_balls: int = 6
    conformity: float = 0.52
    youngs_modulus: float = 207e9
    poisson_ratio: float = 0.3
    viscosity: float = 0.02
    pressure_viscosity: float = 2.0e-8
    surface_tension: float = 0.036
    contact: str = "formula"
    contact_grid: tuple = (65, 33)

    def __post_init__(self):
        check_choice("contact", self.contact, CONTACTS)
        check_range("ball_diameter", self.ball_diameter, "m", 1e-4, 1.0, high_open=True)
        check_range("pitch_diameter", self.pitch_diameter, "m", self.ball_diameter, 10.0, low_open=True, high_open=True,
                    why=f"(above ball_diameter = {self.ball_diameter:g} m)")
        z_max = int(math.pi * self.pitch_diameter / self.ball_diameter)
        check_int("n_balls", self.n_balls, "-", 1, z_max)
        check_range("conformity", self.conformity, "-", 0.5, 1.0, low_open=True, high_open=False,
                    why="(conformity = groove radius / ball diameter)")
        check_range("youngs_modulus", self.youngs_modulus, "Pa", 1e6, 1e13, high_open=True, why="(1 MPa to 10 TPa)")
        check_range("poisson_ratio", self.poisson_ratio, "-", 0.0, 0.5, low_open=False, high_open=True)
        check_range("viscosity", self.viscosity, "Pa s", 0.0, 1e4, low_open=True, high_open=True)
        check_range("pressure_viscosity", self.pressure_viscosity, "1/Pa", 1e-9, 1e-6, high_open=True,
                    why="(the Hamrock-Dowson fit behind the flooded film, h ~ (alpha E')^0.49, is for a "
                    "piezoviscous oil: mineral oils 1e-8 - 3e-8 1/Pa)")
        check_range("surface_tension", self.surface_tension, "N/m", 0.0, 1.0, low_open=True, high_open=True)

    # geometry -------------------------------------------------------------------------------------
    @property
    def rx(self) -> float:
        """Reduced radius along the rolling direction [m] (ball radius; flat race)."""
        return 0.5 * self.ball_diameter

    @property
    def ry(self) -> float:
        """Reduced radius across the track [m]: ``1/(2/d - 1/(f d)) = f d/(2 f - 1)``."""
        return self.conformity * self.ball_diameter / (2.0 * self.conformity - 1.0)

    @property
    def e_prime(self) -> float:
        return reduced_modulus(self.youngs_modulus, self.poisson_ratio)

    def with_(self, **kw) -> "ThrustBallBearing":
        return replace(self, **kw)

    # kinematics -----------------------------------------------------------------------------------
    def entrainment_speed(self, speed_rpm: float) -> float:
        """Mean rolling speed [m/s] ``u = omega d_e / 4`` (each race moves at ``omega/2`` relative to the cage)."""
        check_range("speed_rpm", speed_rpm, "rpm", 1e-3, 1e6, high_open=True)
        return rpm_to_rad_s(speed_rpm) * self.pitch_diameter / 4.0

    def pass_interval(self, speed_rpm: float) -> float:
        """Time between two balls over a point of either race [s]: ``4 pi / (Z omega)``."""
        check_range("speed_rpm", speed_rpm, "rpm", 1e-3, 1e6, high_open=True)
        return 4.0 * math.pi / rpm_to_rad_s(self.n_balls * speed_rpm)  # 4 pi / (Z omega)

    # contact --------------------------------------------------------------------------------------
    def hertz(self, load: float, exact: bool = True) -> HertzContact:
        """Per-ball Hertz contact for the bearing's TOTAL axial load [N] (per ball: load / n_balls)."""
        check_range("load", load, "N", 1e-6, 1e7, high_open=True)
        return hertz_contact(load / self.n_balls, self.rx, self.ry, self.e_prime, exact=exact)

    def flooded_film(self, load: float, speed_rpm: float) -> FloodedFilm:
        """Hamrock–Dowson fully flooded central/minimum film and critical menisci (per ball)."""
        c = self.hertz(load)
        u = self.entrainment_speed(speed_rpm)
        U, G, W = hd.dimensionless_groups(self.viscosity, u, self.pressure_viscosity, c.load_per_ball,
                                          c.e_prime, c.rx)
        Hc = hd.central_film_flooded(U, G, W, c.k)
        Hm = hd.minimum_film_flooded(U, G, W, c.k)
        return FloodedFilm(U=U, G=G, W=W, H_c=Hc, H_min=Hm, h_c=Hc * c.rx, h_min=Hm * c.rx,
                           m_c=hd.critical_meniscus_central(Hc, c.rx, c.b),
                           m_star=hd.critical_meniscus_minimum(Hm, c.rx, c.b), speed=u)

    # the sequence ---------------------------------------------------------------------------------
    def sequence(self, load: float, speed_rpm: float, ambient_film: float, n_passes: int = 200, *, start=None,
                 track: TrackSettings | None = None, periodic_tol: float = 1e-4, stop_at_periodic: bool = True,
                 integration: Integration | None = None, recording: Recording | None = None,
                 long_run: LongRun | None = None, **legacy) -> BallSequence:
        """Inlet and central film ball after ball (module docstring).

        Parameters
        ----------
        load : TOTAL axial load [N]; speed_rpm : shaft speed [rpm]; ambient_film : ``h_inf`` [m], at least the
            fully flooded central film (a thinner layer cannot feed the contact it is said to flood).
        n_passes : maximum number of ball passes over the same point of the race.
        track : :class:`~transient.models.ball.settings.TrackSettings`, how the track between passes is modelled
            (default ``TrackSettings()``): ``replenishment`` ``"thin_film"`` (nonlinear levelling, integrated by
            ``integration``), ``"chiu"`` (Chiu's linear kernel) or ``"chiu_thin"`` (its thin-film long-wave
            limit); ``grid`` ``"front"`` (default: a mesh that follows the re-wetting front, no mobility floor;
            see :mod:`transient.models.ball.front`) or ``"uniform"`` (``n_cells`` uniform cells: the earlier
            formulation, with the mobility floor ``mobility_film`` if given; Chiu always uses it); ``refine``,
            the front mesh's refinement factor (cell sizes and growth rates divided by it);
            ``reservoir_distance``, where the undisturbed ambient film is [m] (default: the ball radius, more
            than twice the contact half-width); ``bc`` ``"reservoir"`` (ambient film held there) or
            ``"closed"`` (no flux: a closed groove); ``ridge_fraction``, the share of the oil pushed off the
            track that stays on the race as side ridges, each ``ridge_width`` wide [m] (default ``a'``);
            ``precursor_film``, the film the ball leaves on the band [m] (default: the outlet film of the pass,
            half the central film on each surface, ``h_c/2``; a number replaces it by ``max(h_c/2, value)``, the
            convergence study towards the physical value; the uniform grid keeps its earlier floor of 1 nm by
            default, as its floor mobility can drain a cell below zero), below the ambient film;
            ``mobility_film``, ``b`` [m] of a regularised mobility ``h^3 + b^3`` (0: none, the physical model;
            ``h_inf/10`` was the earlier formulation's arbitrary floor), below the ambient film; ``edge_width``,
            the width [m] of the wall of the depression (``grid="front"``; default ``a'/50``, at most ``a'/2``;
            0 = the paper's rectangular depression, the limit it converges to); ``front_level``, ``front_tau``:
            the front mesh follows the level ``front_level * h_out`` with relaxation time ``front_tau``
            (scaled).
        integration : :class:`~transient.solvers.settings.Integration` of the levelling between passes
            (``method``, ``rtol``, ``atol`` in units of ``h_inf``, ``dt`` in units of the levelling time for
            ``rk4``, ``linear_solver``); default ``Integration(method="cvode", atol=1e-10)``.
        recording : ``Recording(record=("profiles",))`` keeps the film profile across the track before every
            pass (``BallSequence.profiles``); default: none.
        periodic_tol : relative change of ``h_inf`` over 3 passes that counts as periodic, in [0, 1];
            stop_at_periodic: end the sequence there.
        start : a previous :class:`BallSequence` (same load, ambient film and track settings): the sequence goes
            on from its last pass (the first pass of the new one), e.g. at another speed; ``None``: a uniform
            ambient film before the first ball.
        long_run : :class:`~transient.solvers.settings.LongRun`: ``checkpoint`` (an ``.npz`` rewritten after each
            tenth of the passes; ``resume=True`` continues from it bit for bit), ``progress``,
            ``stop(result_so_far)``, ``time_budget`` [s] (checked between passes). Ctrl-C says where the
            checkpoint is. The run is the one run driver's (:mod:`transient.solvers.model_run`) over the passes,
            its state the track and the row of the next pass (:mod:`transient.models.ball.passes`).

        The track and integration settings as loose keywords (``grid="uniform"``, ``rtol=1e-7``,
        ``record_profiles=True``) are deprecated: they still work for one release, with a ``DeprecationWarning``
        naming the new spelling (beside the object they belong in: an error).

        With ``contact="numerical"`` a pass whose inlet film is below 5 % of the flooded central film (the
        mass-conserving contact passes on less oil than it meets, so a parched sequence can run dry) ends the
        sequence before that pass: ``success=False``, ``final_regime`` parched, ``message`` naming the pass and
        the inlet film.
        """
        check_method(OWNER, requested_method(integration, legacy, "cvode"))
        tr, ig, rc = run_settings(OWNER, legacy, SEQUENCE_KEYWORDS, SEQUENCE_DEFAULTS,
                                  track=track, integration=integration, recording=recording).values()
        lr = LongRun() if long_run is None else check_instance("long_run", long_run, LongRun, "None or LongRun(...)")
        check_method(OWNER, ig.method)
        check_unused(OWNER, "long_run", lr, ("chunk_revolutions",))
        rc.check_names(("profiles",))
        record_profiles = "profiles" in rc.record
        replenishment, grid, n_cells, refine, reservoir_distance, bc, ridge_fraction, ridge_width, precursor_film, \
            mobility_film, front_level, front_tau, edge_width = astuple(tr)
        n_passes = check_int("n_passes", n_passes, "-", 1, 1e9)
        periodic_tol = check_range("periodic_tol", periodic_tol, "-", 0.0, 1.0)
        stop_at_periodic = check_bool("stop_at_periodic", stop_at_periodic)
        nodes = 401 if grid == "front" else n_cells
        check_run_memory(f"this sequence ({n_passes} passes on {nodes} nodes)", sequence_memory(n_passes, nodes,
                         record_profiles), "use fewer cells (n_cells, refine)",
                         "lower n_passes, or leave out recording=Recording(record=(\"profiles\",))")
        c = self.hertz(load)
        ff = self.flooded_film(load, speed_rpm)
        check_range("ambient_film", ambient_film, "m", ff.h_c, 1e-2, low_open=False, high_open=True,
                    why=f"(at least the fully flooded central film h_c = {ff.h_c:.4g} m at {load:g} N, "
                        f"{speed_rpm:g} rpm)")
        if precursor_film is not None:
            check_range("precursor_film", precursor_film, "m", 0.0, ambient_film, low_open=True, high_open=True,
                        why="(below the ambient film)")
        check_range("mobility_film", mobility_film, "m", 0.0, ambient_film, low_open=False, high_open=True,
                    why="(below the ambient film)")
        t_b = self.pass_interval(speed_rpm)
        a_p = c.a
        X = 0.5 * self.ball_diameter if reservoir_distance is None else reservoir_distance
        check_range("reservoir_distance", X, "m", 2.0 * a_p, 1.0, low_open=True, high_open=True,
                    why=f"(more than twice the contact half-width a = {a_p:.4g} m at load = {load!r} N)")
        w_r = a_p if ridge_width is None else ridge_width
        check_range("ridge_width", w_r, "m", 0.0, X - a_p, high_open=False, low_open=True)
        ew = 0.02 * a_p if edge_width is None else edge_width
        check_range("edge_width", ew, "m", 0.0, 0.5 * a_p, why="(the wall of the depression, at most a'/2)")
        h_ref = ambient_film
        T = 3.0 * self.viscosity * a_p ** 4 / (self.surface_tension * h_ref ** 3)  # levelling time [s]
        if replenishment == "thin_film" and grid == "front":
            track_ = FrontTrack(X / a_p, bc, refine=refine, level=front_level, tau=front_tau,
                                mobility_film=mobility_film / h_ref, edge=ew / a_p)
        else:
            track_ = UniformTrack(n_cells, X / a_p, bc, replenishment=replenishment,
                                  mobility_film=mobility_film / h_ref)
            if replenishment != "thin_film":
                track_.chiu_decay = UniformTrack.chiu_decay_factors(track_.grid, a_p, h_ref, self.surface_tension,
                                                                    self.viscosity, t_b, replenishment == "chiu_thin")
        track_.start(1.0)
        x_out = np.linspace(0.0, X / a_p, 401) if track_.kind == "front" else track_.grid.x
        if precursor_film is not None:
            floor = precursor_film
        else:  # the front mesh needs no floor; the uniform grid's floor mobility can drain a cell below zero
            floor = 0.0 if track_.kind == "front" else 1e-9
        films = NumericalFilms(self, c, ff.speed, self.contact_grid) if self.contact == "numerical" else None
        film = formula_film(ff, c) if films is None else numerical_film(films)
        pm = PassMap(track_, film, films, ff.m_c, (a_p, h_ref), floor, (ridge_fraction, w_r / a_p), t_b / T, ig,
                     (periodic_tol, stop_at_periodic), x_out if record_profiles else None, lambda: _Meniscus(c))
        wall0 = time.perf_counter()
        t0, y0 = start_point(start, BallSequence)
        if y0 is None:
            try:
                y0 = pm.first()
            except LayerTooThin as e:
                raise ValueError(f"ambient_film = {ambient_film!r} m: {e}") from None
        else:
            y0 = pm.restart(ModelRun.check_state(y0, y0.size, "sequence", lambda y: []))
            if t0 != int(t0) or t0 < 0:
                raise ValueError(f"start: a final time of {t0!r} passes; allowed: a whole number of passes >= 0")
        key = dict(asdict(self), load=load, speed_rpm=speed_rpm, ambient_film=ambient_film, track=asdict(tr),
                   **ig.key(), dt=ig.dt, linear_solver=ig.linear_solver, record=list(rc.record),
                   periodic_tol=periodic_tol, stop_at_periodic=stop_at_periodic)
        solver = dict(method=ig.method)
        series = SERIES + (("profile",) if record_profiles else ())
        parts = RunParts(label=f"ball sequence {load:g} N, {speed_rpm:g} rpm", omega=1.0, revolution=1.0,
                         unit="passes", problem_at=None, solver=solver, series=series, sample=pm.sample,
                         journals=lambda y: [], eccentricities=lambda r: [],
                         touch_message=lambda tau, y: f"periodic steady state at pass {int(tau)}",
                         result=lambda rec, stats, touched, message, tau: self._sequence_result(
                             pm, rec, stats, "" if touched is not None else message, ff, c, t_b, x_out * a_p, wall0),
                         key=key, status=lambda: "", advance=pm.advance, event_success=True)
        if n_passes == 1:   # the start's own pass: nothing to integrate
            rec = Recorder(pm.sample, 1.0, series)
            pm.advance(y0, np.array([t0]), rec.observe, None)
            rec.last_y = y0
            return self._sequence_result(pm, rec, Stats(), "", ff, c, t_b, x_out * a_p, wall0)
        run = ModelRun.at_times(n_passes - 1, lr)
        return run.go(parts, y0, t0, t0 + np.arange(n_passes, dtype=float))

    def _sequence_result(self, pm, rec, stats, message, ff, c, t_b, x, wall0) -> BallSequence:
        """The result of a sequence from its recorder (:class:`~transient.solvers.model_run.RunParts`); ``message``
        the run's (empty for a sequence that reached its last pass or its periodic state)."""
        a = rec.arrays()
        y = rec.last_y
        n_run = len(a["t"])
        h_in, h_cen, ms = a["h_in"], a["h_c"], a["m"]
        regime = [REGIMES[int(r)] for r in a["regime"]]
        h_out = np.maximum(0.5 * h_cen, pm.floor)
        periodic = PassMap.header(y, "periodic") == 1.0
        declining = False
        if not periodic and n_run >= 6:
            declining = bool(np.all(np.diff(h_in[n_run - 6:]) < 0) and ms[-1] < ff.m_c)
        final = PARCHED if declining or pm.stopped else regime[-1]
        st = {"n_steps": stats.n_steps, "n_rhs": stats.n_rhs, "n_jac": stats.n_jac,
              "n_freeze": int(PassMap.header(y, "n_freeze")), "n_remesh": int(PassMap.header(y, "n_remesh")),
              "wall_time": time.perf_counter() - wall0, "integrate_time": pm.integrate_time}
        ok = not pm.stopped
        return BallSequence(h_inlet=h_in, h_central=h_cen, h_minimum=a["h_min"], h_outlet=h_out, m=ms, regime=regime,
                            m_c=ff.m_c, m_star=ff.m_star, flooded=ff, contact=c, t_between=t_b, periodic=periodic,
                            n_periodic=int(PassMap.header(y, "n_periodic")), declining=declining, final_regime=final,
                            stats=st, x=x, profiles=np.array(a["profile"]) if "profile" in a else None,
                            volume=a["volume"], final_state=np.array(y), final_time=float(a["t"][-1]),
                            success=ok, message=pm.stopped or ("" if message == _NORMAL_END else message))


def sequence_memory(n_passes: int, nodes: int, profiles: bool) -> dict:
    """Bytes a :meth:`ThrustBallBearing.sequence` will need, by part: ``track`` (the levelling's ~200 arrays over
    its nodes), ``recordings`` (per pass six numbers as Python floats in lists, 32 bytes each, then the result's
    eight series; the profiles, ``nodes`` numbers per pass, twice: recorded and in the result)."""
    return dict(track=200.0 * 8 * nodes,
                recordings=n_passes * (6 * 32.0 + 8 * 8.0 + 2 * 8.0 * nodes * bool(profiles)))
