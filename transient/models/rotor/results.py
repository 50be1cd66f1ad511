"""Results of a rotor on journal bearings: SI fields with units, the displacement of every node by
``position(node)``."""

from __future__ import annotations

from dataclasses import field

import numpy as np

from transient.results import RunResult, StatusResult, SteadyResult, quantity, result_type


class _Nodes:
    """``position(node)``: the (x, y) of one node from the ``displacement`` array (last axis: x, y)."""

    labels = {"nodes": None}

    def _index(self, node) -> int:
        nodes = list(self.nodes)
        if node not in nodes:
            raise ValueError(f"node = {node!r} is not a node of this result; allowed: {nodes}")
        return nodes.index(node)

    def position(self, node):
        """The (x, y) displacement [m] of ``node`` (arrays over ``t`` for a run, numbers or complex amplitudes
        otherwise)."""
        d = self.displacement[..., self._index(node), :]
        return d[..., 0], d[..., 1]


@result_type
class RotorRunResult(_Nodes, RunResult):
    """A time run of a rotor on journal bearings.

    ``t`` [s]; ``displacement`` [m] (n_t, n_nodes, 2): x, y of every node (``position(node)``); ``speed_rpm``
    [rpm] (n_t) the shaft speed; ``bearing_force`` [N] (n_t, n_bearings, 2) the film force on the journal at
    each bearing node (``bearing_nodes``); ``clearance`` [m] per bearing; ``touched_at`` [s] when a journal
    reached its bearing (the run stopped there); ``reference_speed_rpm`` [rpm] the speed of the state's pressure
    unit; ``final_state`` (the system's dimensionless state) at
    ``final_time`` [s], from which ``run(..., start=result)`` continues. With rough bearings
    (:mod:`~transient.models.rotor.rough_films`), per bearing (n_t, n_bearings): ``contact_load`` [N] the asperities'
    force on the journal, ``friction_torque`` [N m] (film shear plus boundary friction on the asperity load),
    ``min_film`` [m], ``contact_pressure`` [Pa] the peak asperity pressure; ``contact_events``
    ``[(t [s], node, "begins" | "ends"), ...]`` where a bearing's ``h_min / sigma`` crosses 3 (a rough journal's
    contact is a record: the run goes on through it); ``bearing_force`` is then film plus asperities. Thermal bearings
    (:mod:`~transient.models.rotor.thermal_films`; None without): at their nodes ``thermal_nodes`` the series
    ``max_temperature`` [K], ``power_loss`` [W], ``heat_flow`` [W] (carried away by the oil and taken by the
    walls), ``stored_heat`` [J] (n_t, n_thermal), ``final_temperature`` [K] (each thermal film's cells and feeds,
    in turn; ``start=result`` continues from them) and ``heat_balance``, per thermal bearing in the order of
    ``thermal_nodes``, its energy balance per thermal interval
    (:meth:`~transient.models.journal.film_temperatures.FilmTemperatures.heat_balance`)."""

    shapes = {"displacement": ("t", "nodes", 2), "speed_rpm": ("t",), "bearing_force": ("t", "bearing_nodes", 2),
              "clearance": ("bearing_nodes",), "contact_load": ("t", "bearing_nodes"),
              "friction_torque": ("t", "bearing_nodes"), "min_film": ("t", "bearing_nodes"),
              "contact_pressure": ("t", "bearing_nodes"), "max_temperature": ("t", "thermal_nodes"),
              "power_loss": ("t", "thermal_nodes"), "heat_flow": ("t", "thermal_nodes"),
              "stored_heat": ("t", "thermal_nodes"), "final_temperature": (None,)}
    labels = {"bearing_nodes": "nodes", "thermal_nodes": "bearing_nodes"}

    displacement: np.ndarray = quantity("m", None)
    speed_rpm: np.ndarray = quantity("rpm", None)
    bearing_force: np.ndarray = quantity("N", None)
    nodes: list = None
    bearing_nodes: list = None
    clearance: np.ndarray = quantity("m", None)
    method: str = "ida"
    touched_at: float | None = quantity("s", None)
    reference_speed_rpm: float = quantity("rpm", 0.0)
    contact_load: np.ndarray | None = quantity("N", None)
    friction_torque: np.ndarray | None = quantity("N m", None)
    min_film: np.ndarray | None = quantity("m", None)
    contact_pressure: np.ndarray | None = quantity("Pa", None)
    contact_events: list | None = None
    thermal_nodes: list | None = None
    max_temperature: np.ndarray | None = quantity("K", None)
    power_loss: np.ndarray | None = quantity("W", None)
    heat_flow: np.ndarray | None = quantity("W", None)
    stored_heat: np.ndarray | None = quantity("J", None)
    final_temperature: np.ndarray | None = quantity("K", None)
    heat_balance: list | None = None

    def eccentricity_ratio(self, node) -> np.ndarray:
        """e/C of the journal at the bearing ``node``."""
        x, y = self.position(node)
        return np.hypot(x, y) / self.clearance[list(self.bearing_nodes).index(node)]

    @property
    def revolutions(self) -> np.ndarray:
        """Shaft revolutions at every output (trapezoidal integral of the speed)."""
        s = np.asarray(self.speed_rpm) / 60.0
        return np.concatenate([[0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(self.t))])


@result_type
class RotorEquilibrium(_Nodes, SteadyResult):
    """The static equilibrium of a rotor on journal bearings: ``displacement`` [m] (n_nodes, 2) of every node,
    ``bearing_force`` [N] (n_bearings, 2) the film force on the journal, ``bearing_load`` [N] its magnitude (the
    load each bearing carries), ``eccentricity_ratio`` and ``attitude_angle_deg`` per bearing (from the bearing's
    load line to the line of centres, in the direction of rotation), ``state`` the system's dimensionless state;
    ``bearing_moment`` [N m] (n_bearings, 2) the film's moment on the journal about the bearing centre (about x,
    about y) where the films take the shaft's tilts (``RotorBearingSystem(tilt_coupling=True)``), else None.
    Thermal bearings at ``thermal_nodes`` (:func:`~transient.models.rotor.thermal_films.thermal_equilibrium`; None
    without): their steady THD films' ``max_temperature`` [K], ``power_loss`` [W] and ``temperature`` [K] (each
    film's cells and feeds, in turn)."""

    shapes = {"displacement": ("nodes", 2), "bearing_force": ("bearing_nodes", 2), "bearing_load": ("bearing_nodes",),
              "eccentricity_ratio": ("bearing_nodes",), "attitude_angle_deg": ("bearing_nodes",), "state": (None,),
              "bearing_moment": ("bearing_nodes", 2), "max_temperature": ("thermal_nodes",),
              "power_loss": ("thermal_nodes",), "temperature": (None,)}
    labels = {"bearing_nodes": "nodes", "thermal_nodes": "bearing_nodes"}

    displacement: np.ndarray = quantity("m", None)
    bearing_force: np.ndarray = quantity("N", None)
    bearing_load: np.ndarray = quantity("N", None)
    eccentricity_ratio: np.ndarray = quantity("-", None)
    attitude_angle_deg: np.ndarray = quantity("deg", None)
    nodes: list = None
    bearing_nodes: list = None
    speed_rpm: float = quantity("rpm", 0.0)
    state: np.ndarray = quantity("-", None, repr=False)
    bearing_moment: np.ndarray | None = quantity("N m", None)
    thermal_nodes: list | None = None
    max_temperature: np.ndarray | None = quantity("K", None)
    power_loss: np.ndarray | None = quantity("W", None)
    temperature: np.ndarray | None = quantity("K", None)


@result_type
class UnbalanceResponse(_Nodes, StatusResult):
    """The linear unbalance response at one speed: ``displacement`` [m] (n_nodes, 2) complex amplitudes with
    ``x(t) = Re(X e^{i Omega t})`` (``position(node)``); ``stiffness`` [N/m] and ``damping`` [N s/m]
    (n_bearings, 2, 2) each bearing's quasi-static coefficients at its static load ((n_bearings, 4, 4) in (x, y,
    tx, ty) with ``tilt_coupling``: N/m, N/rad, N m/m, N m/rad and their rates); ``linearisation`` how the
    bearings entered: ``"film states"`` (the system linearised with the films' own states, the default) or
    ``"K and C"`` (the quasi-static coefficients above)."""

    time_axis = None
    shapes = {"displacement": ("nodes", 2), "stiffness": ("bearing_nodes", None, None),
              "damping": ("bearing_nodes", None, None)}
    labels = {"bearing_nodes": "nodes"}
    displacement: np.ndarray = quantity("m", None)
    stiffness: np.ndarray = quantity("N/m", None)
    damping: np.ndarray = quantity("N s/m", None)
    nodes: list = None
    bearing_nodes: list = None
    speed_rpm: float = quantity("rpm", 0.0)
    linearisation: str | None = None

    def amplitude(self, node) -> tuple[float, float]:
        """Peak amplitudes |X|, |Y| [m] of ``node``."""
        x, y = self.position(node)
        return float(abs(x)), float(abs(y))


@result_type
class PeriodicResponse(_Nodes, StatusResult):
    """The settled (periodic) unbalance response over one revolution by shooting: ``t`` [s] from shaft angle 0,
    ``displacement`` [m] (n_t, n_nodes, 2) (``position(node)``), ``multipliers`` the dominant Floquet
    multipliers (stable inside the unit circle), ``error_estimate`` [smallest clearance] of the fixed point,
    ``periods`` integrated, ``state`` the system's state at angle 0 (a run's ``start=(0, state)``); ``stable``: every
    multiplier inside the unit circle, ``converged``: the shooting met its tolerance (``success`` is both),
    ``integrator`` the period map's (``"ida"`` or ``"bdf2"``), ``basis`` the refined dominant subspace of the
    monodromy (the period map's reduced layout; a continuation starts the next speed's shooting on it)."""

    shapes = {"displacement": ("t", "nodes", 2), "state": (None,), "basis": (None, None)}

    t: np.ndarray = quantity("s", None)
    displacement: np.ndarray = quantity("m", None)
    multipliers: np.ndarray = None
    error_estimate: float = quantity("-", float("nan"))
    periods: int = 0
    nodes: list = None
    speed_rpm: float = quantity("rpm", 0.0)
    state: np.ndarray = quantity("-", None, repr=False)
    stable: bool = False
    converged: bool = False
    integrator: str = "ida"
    basis: np.ndarray | None = quantity("-", None, repr=False)

    @property
    def max_multiplier(self) -> float:
        """Modulus of the dominant Floquet multiplier."""
        m = np.asarray(self.multipliers if self.multipliers is not None else [])
        return float(np.abs(m).max()) if m.size else float("nan")

    def amplitude(self, node) -> tuple[float, float]:
        """Half the peak-to-peak excursion [m] of ``node`` in x and y."""
        x, y = self.position(node)
        return float(np.ptp(x) / 2), float(np.ptp(y) / 2)


@result_type
class RotorResponseCurve(StatusResult):
    """Periodic unbalance responses along a path of speeds (continuation), one row per speed: ``amplitude`` [m]
    (n_speeds, n_nodes, 2) half the peak-to-peak excursion of every node in x and y (``amplitudes(node)``),
    ``multipliers`` (n_speeds, 2) the dominant Floquet pair, ``max_multiplier``, ``stable`` (every multiplier inside
    the unit circle), ``converged``, ``periods`` integrated per speed; ``onset_rpm`` the speed where the dominant
    multiplier leaves the unit circle, interpolated between the bracketing speeds (nan if not bracketed);
    ``integrator`` the period map's; ``orbits`` every speed's
    :class:`PeriodicResponse`."""

    time_axis = "speed_rpm"
    shapes = {"amplitude": ("speed_rpm", "nodes", 2), "multipliers": ("speed_rpm", 2),
              "max_multiplier": ("speed_rpm",), "stable": ("speed_rpm",), "converged": ("speed_rpm",),
              "periods": ("speed_rpm",)}
    labels = {"nodes": None}
    record_skip = ("orbits",)

    speed_rpm: np.ndarray = quantity("rpm", None)
    amplitude: np.ndarray = quantity("m", None)
    multipliers: np.ndarray = quantity("-", None)
    max_multiplier: np.ndarray = quantity("-", None)
    stable: np.ndarray = None
    converged: np.ndarray = None
    periods: np.ndarray = None
    nodes: list = None
    onset_rpm: float = quantity("rpm", float("nan"))
    integrator: str = "ida"
    orbits: list = field(default_factory=list, repr=False)

    def amplitudes(self, node) -> tuple[np.ndarray, np.ndarray]:
        """Half peak-to-peak [m] of ``node`` in x and y at every speed."""
        nodes = list(self.nodes)
        if node not in nodes:
            raise ValueError(f"node = {node!r} is not a node of this result; allowed: {nodes}")
        a = self.amplitude[:, nodes.index(node), :]
        return a[:, 0], a[:, 1]
