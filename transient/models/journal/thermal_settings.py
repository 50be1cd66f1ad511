"""What a thermal (THD) journal film is told: the oil's viscosity against temperature and its thermal properties,
the supply temperature, the heat path to the walls and the mixing at the feeds (``JournalBearing(thermal=...)``).

Walls (``boundary=``):

* ``"adiabatic"`` -- all the heat leaves with the oil;
* :class:`BushConvection` -- heat flux ``h_b (T - T_b)`` per unit area into the bush (``coefficient`` h_b
  [W/(m^2 K)], bush temperature ``T_b``, default the supply temperature);
* :class:`IsothermalShaft` -- the shaft surface held at ``T_s``: conduction through half the film,
  ``2 k (T - T_s) / h`` per unit area (k the oil's conductivity; the film-averaged temperature sits mid-film).

In a cavitated cell only the liquid striations (fraction theta) touch the walls: the wall flux is times
``min(theta, 1)``.

Mixing at each feed (``mixing=`` lambda, the hot-oil carry-over coefficient; ROSS uses 0.8): of the oil that
reaches a feed from the film (``Q_rec`` at its mixed-mean temperature ``T_rec``) the fraction lambda stays and mixes
with fresh supply oil to make up the feed's inflow ``Q_in``::

    Q_in T_mix = lambda Q_rec T_rec + (Q_in - lambda Q_rec) T_supply      (lambda Q_rec <= Q_in)

(when ``lambda Q_rec`` exceeds ``Q_in`` the inflow is all recirculated oil, ``T_mix = T_rec``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from transient.checks import check_instance, check_int, check_items, check_positive, check_range
from transient.physics.lubricant import (TEMPERATURE_RANGE_K, ExponentialViscosity, ThermalProperties,
                                         VogelViscosity)

#: The walls' names (``boundary=``) besides the objects :class:`BushConvection` and :class:`IsothermalShaft`.
ADIABATIC = "adiabatic"
#: ROSS's hot-oil carry-over coefficient (the default ``mixing``).
ROSS_MIXING = 0.8


def _temperature(name, value):
    return check_range(name, value, "K", *TEMPERATURE_RANGE_K, why="(absolute temperature)")


@dataclass(frozen=True)
class BushConvection:
    """Heat flux ``coefficient (T - temperature)`` [W/m^2] from the film into the bush; ``coefficient`` [W/(m^2 K)],
    ``temperature`` [K] (None: the supply temperature)."""

    coefficient: float
    temperature: float | None = None

    def __post_init__(self):
        check_range("boundary.coefficient", self.coefficient, "W/(m^2 K)", 0.0, 1e7)
        if self.temperature is not None:
            _temperature("boundary.temperature", self.temperature)


@dataclass(frozen=True)
class IsothermalShaft:
    """The shaft surface at ``temperature`` [K] (None: the supply temperature); heat flux ``2 k (T - T_s) / h``."""

    temperature: float | None = None

    def __post_init__(self):
        if self.temperature is not None:
            _temperature("boundary.temperature", self.temperature)


@dataclass(frozen=True)
class ThermalFilm:
    """The thermal film of a journal bearing (module docstring), SI and K.

    ``supply_temperature`` [K]; the viscosity law: ``viscosity_at = ((T1, mu1), (T2, mu2))`` (the exponential law
    through two points, :meth:`~transient.physics.lubricant.ExponentialViscosity.two_point`) or ``viscosity_law`` (an
    :class:`~transient.physics.lubricant.ExponentialViscosity` or
    :class:`~transient.physics.lubricant.VogelViscosity`), one of them; ``density`` [kg/m^3], ``heat_capacity``
    [J/(kg K)], ``conductivity`` [W/(m K)]; ``boundary``: ``"adiabatic"``, :class:`BushConvection` or
    :class:`IsothermalShaft`; ``mixing``: the hot-oil carry-over coefficient lambda in [0, 1].

    ``tolerance`` [K]: the steady film and temperatures are solved alternately until the temperatures change by
    less than this; at most ``max_iterations`` times.

    ``wall_heat_capacity`` [J/K]: the heat capacity of the bush and shaft metal next to the film (0: none, the oil's
    own only), for the transient film (:mod:`transient.models.journal.thermal_orbit`): spread over the film's area
    in proportion to each cell's area, each share at its cell's temperature. It sets how many seconds the film's
    temperatures lag a change of speed or load; it does not change a steady state.
    """

    supply_temperature: float
    viscosity_at: tuple | None = None
    density: float = None
    heat_capacity: float = None
    boundary: object = ADIABATIC
    mixing: float = ROSS_MIXING
    conductivity: float = 0.13
    viscosity_law: object = None
    tolerance: float = 1e-4
    max_iterations: int = 100
    wall_heat_capacity: float = 0.0

    def __post_init__(self):
        _temperature("supply_temperature", self.supply_temperature)
        if (self.viscosity_at is None) == (self.viscosity_law is None):
            raise ValueError(f"viscosity_at = {self.viscosity_at!r}, viscosity_law = {self.viscosity_law!r}; allowed: "
                             "one of them (two (temperature [K], viscosity [Pa s]) points, or a viscosity law)")
        if self.viscosity_law is not None:
            check_instance("viscosity_law", self.viscosity_law, (ExponentialViscosity, VogelViscosity),
                           "ExponentialViscosity(...) or VogelViscosity(...)")
        else:
            ExponentialViscosity.two_point(*self._pairs())
        for name in ("density", "heat_capacity"):
            if getattr(self, name) is None:
                raise ValueError(f"{name} = None; allowed: the oil's {name.replace('_', ' ')} "
                                 f"[{'kg/m^3' if name == 'density' else 'J/(kg K)'}]")
        object.__setattr__(self, "properties", ThermalProperties(self.density, self.heat_capacity, self.conductivity))
        if isinstance(self.boundary, str):
            if self.boundary != ADIABATIC:
                raise ValueError(f"boundary = {self.boundary!r}; allowed: 'adiabatic', BushConvection(coefficient=..., "
                                 "temperature=...) or IsothermalShaft(temperature=...)")
        else:
            check_instance("boundary", self.boundary, (BushConvection, IsothermalShaft),
                           "'adiabatic', BushConvection(...) or IsothermalShaft(...)")
        check_range("mixing", self.mixing, "-", 0.0, 1.0, why="(the hot-oil carry-over coefficient)")
        check_positive("tolerance", self.tolerance, "K")
        check_int("max_iterations", self.max_iterations, "-", 1, 10000)
        check_range("wall_heat_capacity", self.wall_heat_capacity, "J/K", 0.0, 1e9,
                    why="(the bush and shaft metal next to the film; 0: the oil's own heat capacity only)")
        self.viscosity(self.supply_temperature)  # a Vogel law must hold at the supply temperature

    @cached_property
    def law(self):
        """The viscosity law: ``viscosity_law``, or the exponential law through ``viscosity_at``."""
        return self.viscosity_law or ExponentialViscosity.two_point(*self._pairs())

    def _pairs(self):
        return check_items("viscosity_at", self.viscosity_at, "two (temperature [K], viscosity [Pa s]) pairs", 2)

    def viscosity(self, temperature, pressure=0.0):
        """The oil's viscosity [Pa s] at ``temperature`` [K] (and gauge ``pressure`` [Pa])."""
        return self.law.at(temperature, pressure)

    def wall(self) -> tuple[str, float, float]:
        """The wall as ``(kind, coefficient, temperature)``: ``("adiabatic", 0, T_supply)``, ``("bush", h_b, T_b)``
        or ``("shaft", k, T_s)`` (the kernel computes ``2 k / h`` per cell)."""
        b, Ts = self.boundary, self.supply_temperature
        if isinstance(b, BushConvection):
            return "bush", b.coefficient, Ts if b.temperature is None else b.temperature
        if isinstance(b, IsothermalShaft):
            return "shaft", self.conductivity, Ts if b.temperature is None else b.temperature
        return ADIABATIC, 0.0, Ts

    def parameters(self) -> dict:
        """Every parameter that changes the thermal film (SI, K)."""
        law = self.law
        kind, coefficient, wall_temperature = self.wall()
        return dict(supply_temperature=self.supply_temperature, viscosity_law=type(law).__name__,
                    viscosity_constants=list(law.kernel_args()[1:]), pressure_viscosity=law.pressure_viscosity,
                    density=self.density, heat_capacity=self.heat_capacity, conductivity=self.conductivity,
                    boundary=kind, wall_coefficient=coefficient, wall_temperature=wall_temperature,
                    mixing=self.mixing, tolerance=self.tolerance, max_iterations=self.max_iterations,
                    **({} if self.wall_heat_capacity == 0.0 else dict(wall_heat_capacity=self.wall_heat_capacity)))
