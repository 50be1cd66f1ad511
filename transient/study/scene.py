"""Scene files: one model run described in TOML, validated before anything is computed.

A scene names a model kind, a parameter set of a paper (by name) with overrides, run options and the
outputs wanted::

    kind = "journal_orbit"          # journal_orbit | journal_noise | ball_sequence | pad_descent
    parameters = "rho_kim"          # a paper's set (transient.params); overrides below
    [overrides]
    speed_rpm = 6000.0
    grid = [151, 21]
    # speed_profile = [[0.0, 3000.0], [0.1, 6000.0]]   # a run-up [s, rpm] (journal_orbit; speed_rpm the reference)
    [run]
    revolutions = 20
    rtol = 1e-5
    [outputs]
    save_result = true              # the Result of every point as .npz (load with transient.load_result)
    figures = true

``transient run SCENE.toml`` runs one point; ``transient sweep SCENE.toml --param NAME=a:b:n`` sweeps
(:mod:`transient.study.sweep`). Unknown keys and out-of-range values are errors naming the key, the value,
the unit and the allowed range; every point's parameters are checked by building its model (cheap: no
solve) before the first point is computed.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from transient.checks import check_int, check_range
from transient.params import jeong, lee_rhim, park, rho_kim
from transient.solvers.settings import Integration, LongRun, Recording
from transient.models.ball.settings import TrackSettings

SECTIONS = ("kind", "parameters", "overrides", "run", "outputs", "title")


@dataclass(frozen=True)
class Option:
    """A run option: unit, allowed range (numbers) or choices (strings), default."""

    unit: str
    default: object
    low: float = -math.inf
    high: float = math.inf
    choices: tuple = ()
    integer: bool = False

    def check(self, name, value):
        if self.choices:
            if value not in self.choices:
                raise ValueError(f"{name} = {value!r}; allowed: {', '.join(map(str, self.choices))}")
            return value
        v = check_range(name, value, self.unit, self.low, self.high)
        if self.integer:
            if v != int(v):
                raise ValueError(f"{name} = {value!r} [{self.unit}] must be an integer")
            return int(v)
        return v


@dataclass(frozen=True)
class Kind:
    """A model kind of the scene files: its parameter sets, units of its parameters, run options, the
    function computing one point (``point(params, run) -> (Result, scalars)``), the one building its model
    without solving (validation), and the figures of a sweep over it."""

    name: str
    sets: dict
    units: dict
    run: dict
    point: Callable
    build: Callable
    figures: Callable | None = None
    figure: Callable | None = None
    doc: str = ""
    memory: Callable | None = None

    def resolve(self, set_name, overrides: dict) -> dict:
        if set_name not in self.sets:
            raise ValueError(f"parameters = {set_name!r} is not a parameter set of {self.name}; allowed: "
                             f"{', '.join(self.sets)}")
        params = dict(self.sets[set_name])
        for k, v in overrides.items():
            if k not in self.units:
                raise ValueError(f"overrides: unknown parameter {k!r} of {self.name}; allowed: {', '.join(sorted(self.units))}")
            params[k] = v
        return params

    def run_options(self, given: dict) -> dict:
        out = {}
        for k, v in given.items():
            if k not in self.run:
                raise ValueError(f"run: unknown option {k!r} of {self.name}; allowed: {', '.join(sorted(self.run))}")
            out[k] = self.run[k].check(f"run.{k}", v)
        for k, opt in self.run.items():
            out.setdefault(k, opt.default)
        return out


@dataclass
class Scene:
    """A validated scene: the kind, the resolved parameters (SI), run options and outputs."""

    kind: Kind
    parameter_set: str
    params: dict
    run: dict
    outputs: dict = field(default_factory=lambda: dict(save_result=True, figures=True))
    title: str = ""
    source: str = ""

    def with_params(self, **changes) -> dict:
        """The parameters of one point: the scene's with ``changes`` (validated names)."""
        bad = [k for k in changes if k not in self.kind.units]
        if bad:
            raise ValueError(f"unknown parameter {bad[0]!r} of {self.kind.name}; allowed: "
                             f"{', '.join(sorted(self.kind.units))}")
        return {**self.params, **changes}

    def check_point(self, params: dict):
        """Check the point's memory estimate and build its model (no solve): a bad value raises the model's
        own named error, a run too large for this machine a :class:`~transient.checks.MemoryLimitError`."""
        if self.kind.memory is not None:
            self.kind.memory(params, self.run)
        self.kind.build(params)


def run_scene(scene: Scene, out) -> tuple:
    """Run the scene's one point; write its Result (``result.npz``), its scalars (``scalars.json``) and its
    figure into ``out``. Returns (result, scalars)."""
    import json

    from transient.plots import save

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    result, scalars = scene.kind.point(scene.params, scene.run)
    if scene.outputs.get("save_result", True):
        result.save(out / "result.npz")
    (out / "scalars.json").write_text(json.dumps(dict(kind=scene.kind.name, parameters=scene.params, run=scene.run,
                                                      scalars=scalars), indent=1, default=str))
    if scene.outputs.get("figures", True) and scene.kind.figure is not None:
        save(scene.kind.figure(result, scene.run), out / f"{scene.kind.name}.png")
    return result, scalars


def load_scene(path) -> Scene:
    """Read and validate a scene file."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"scene file not found: {path}")
    try:
        doc = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise ValueError(f"{path}: not a valid TOML text file ({type(e).__name__}: {' '.join(str(e).split())[:160]})") from None
    except OSError as e:
        raise ValueError(f"{path}: cannot be read ({e.strerror})") from None
    return scene_from_dict(doc, source=str(path))


def scene_from_dict(doc: dict, source: str = "<dict>") -> Scene:
    """Validate a scene given as a dict (the TOML's structure)."""
    if not isinstance(doc, dict):
        raise ValueError(f"{source}: a scene is a table of keys, got {type(doc).__name__}")
    bad = [k for k in doc if k not in SECTIONS]
    if bad:
        raise ValueError(f"{source}: unknown key {bad[0]!r}; allowed: {', '.join(SECTIONS)}")
    name = doc.get("kind")
    if not isinstance(name, str) or name not in KINDS:
        raise ValueError(f"{source}: kind = {name!r}; allowed: {', '.join(KINDS)}")
    kind = KINDS[name]
    for section in ("overrides", "run", "outputs"):
        if not isinstance(doc.get(section, {}), dict):
            raise ValueError(f"{source}: {section} = {doc[section]!r} must be a table ([{section}] with NAME = value "
                             "lines)")
    set_name = doc.get("parameters", next(iter(kind.sets)))
    if not isinstance(set_name, str):
        raise ValueError(f"{source}: parameters = {set_name!r} must be the name of a parameter set; allowed: "
                         f"{', '.join(map(repr, kind.sets))} (change values under [overrides])")
    params = kind.resolve(set_name, doc.get("overrides", {}))
    run = kind.run_options(doc.get("run", {}))
    outputs = dict(save_result=True, figures=True)
    for k, v in doc.get("outputs", {}).items():
        if k not in outputs:
            raise ValueError(f"{source}: outputs: unknown key {k!r}; allowed: {', '.join(outputs)}")
        if not isinstance(v, bool):
            raise ValueError(f"{source}: outputs.{k} = {v!r}; allowed: true, false")
        outputs[k] = v
    scene = Scene(kind, set_name, params, run, outputs, str(doc.get("title", "")), source)
    scene.check_point(params)
    return scene


# --------------------------------------------------------------------------------------------------
# the kinds
# --------------------------------------------------------------------------------------------------

def _journal_split(p):
    from transient import JournalBearing

    bearing = {k: p[k] for k in ("diameter", "length", "clearance", "viscosity", "bulk_modulus", "supply_pressure")}
    b = JournalBearing(**bearing, grid=_grid(p["grid"]))
    return b, {k: p[k] for k in ("rotor_mass", "unbalance", "load")}


def _grid(g, name="grid") -> tuple:
    """A grid of two whole numbers of cells (``[151, 21]``): a named error otherwise (no truncation)."""
    if not isinstance(g, (list, tuple)) or len(g) != 2:
        raise ValueError(f"{name} = {g!r} [cells]; allowed: two whole numbers, e.g. [151, 21]")
    return tuple(check_int(f"{name}[{i}]", v, "cells", 1, 1e6) for i, v in enumerate(g))


def _journal_memory(p, run):
    from transient.models.journal.orbit import check_orbit_memory

    nx, nz = _grid(p["grid"])
    revolutions = run["revolutions"] + run.get("max_settle_revolutions", 0)
    check_orbit_memory(nx * nz, revolutions, run.get("outputs_per_revolution", 64), (), 0.0)


def _journal_build(p):
    from transient import JournalOrbit

    b, rotor = _journal_split(p)
    return JournalOrbit(b, speed_rpm=p["speed_rpm"], speed_profile=p.get("speed_profile"), **rotor)


def _journal_orbit_point(p, run):
    from transient.analysis.orbits import orbit_shape, per_revolution
    from transient.study.journal import settle_estimate

    o = _journal_build(p)
    r = o.run(run["revolutions"],
              integration=Integration(method=run["method"], rtol=run["rtol"], atol=1e-3 * run["rtol"]),
              recording=Recording(outputs_per_revolution=run["outputs_per_revolution"]),
              long_run=LongRun(progress=False))
    X, Y = per_revolution(r.x, r.y, run["outputs_per_revolution"], r.clearance)
    shape = orbit_shape(X[-1], Y[-1]) if X.shape[0] else {}
    eps = r.eccentricity_ratio
    settle = settle_estimate(X, Y)
    return r, dict(success=r.success, touched=r.touched_at is not None, eps_max=float(eps.max()),
                   eps_min_last_rev=float(np.hypot(X[-1], Y[-1]).min()) if X.shape[0] else math.nan,
                   semi_major_C=shape.get("semi_major", math.nan), semi_minor_C=shape.get("semi_minor", math.nan),
                   settle_estimate=settle, settled=bool(settle <= run["settle_tol"]),
                   n_steps=r.stats.n_steps, wall_s=r.stats.wall_time)


def _journal_noise_point(p, run):
    from transient.study.noise import bearing_noise
    from transient.study.settle import Settling

    n = bearing_noise(_journal_build(p), revolutions=run["revolutions"], harmonics=run["harmonics"],
                      integration=Integration(rtol=run["rtol"]),
                      settling=Settling(max_periods=run["max_settle_revolutions"]))
    s = dict(level_db=n.level_db, level_dba=n.level_dba, settle_revolutions=n.settle_revolutions,
             whirl_amplitude_um=float(np.max(np.hypot(n.x - n.x.mean(), n.y - n.y.mean())) * 1e6))
    s.update({f"harmonic_{k + 1}x_db": float(v) for k, v in enumerate(n.harmonic_levels_db)})
    return n, s


def _ball_build(p):
    from transient import ThrustBallBearing

    b = ThrustBallBearing(**{k: (check_int("n_balls", p[k], "-", 1, 1e4) if k == "n_balls" else p[k])
                             for k in jeong.BEARING})
    b.flooded_film(p["load"], p["speed_rpm"])  # validates load and speed
    check_range("ambient_film", p["ambient_film"], "m", 0.0, 0.1, low_open=True)
    return b


def _ball_point(p, run):
    s = _ball_build(p).sequence(load=p["load"], speed_rpm=p["speed_rpm"], ambient_film=p["ambient_film"],
                                n_passes=run["n_passes"], track=TrackSettings(replenishment=run["replenishment"]))
    return s, dict(final_regime=s.final_regime, periodic=s.periodic, H_central=float(s.H_central[-1]),
                   h_inlet_um=float(s.h_inlet[-1] * 1e6), meniscus=float(s.m[-1]), m_c=float(s.m_c),
                   passes=int(s.n_run))


def _pad_build(p):
    from transient import ThrustPad
    from transient.study.pad import surface

    gamma = check_range("gamma", p["gamma"], "-", 0.0, 100.0)
    surf = (surface(gamma, check_int("samples", p["samples"], "-", 16, 8192), seed=check_int("seed", p["seed"], "-", 0, 2**32 - 1),
                    rq=p["rq"]) if gamma else p["rq"])
    return ThrustPad(p["length"], p["width"], p["viscosity"], surface=surf, grid=_grid(p["grid"]))


def _pad_memory(p, run):
    from transient.models.pad.pad import check_descent_memory

    nx, ny = _grid(p["grid"])
    check_descent_memory(nx * ny, run["outputs"], "separable")


def _pad_point(p, run):
    pad = _pad_build(p)
    rq = pad.sigma
    r = pad.descent(load=p["load"], h0_start=5 * rq, t_end=run["t_end"], n_out=run["outputs"],
                    integration=Integration(method="cvode", rtol=run["rtol"], atol=1e-2 * run["rtol"]))
    return r, dict(success=r.success, h_end_over_rq=float(r.h0[-1] / rq), h_eq_over_rq=float(pad.equilibrium(p["load"]) / rq),
                   t_to_2rq_ms=float(np.interp(-2.0, -r.h0 / rq, r.t) * 1e3) if r.h0[-1] < 2 * rq else math.nan,
                   w_asp_end=float(r.w_asp[-1]), contact_area_end_mm2=float(r.contact_area[-1] * 1e6))


def _roller_build(p):
    from transient import RollerContact, TaperedRoller

    roller = TaperedRoller(**{k: p[k] for k in ("mean_radius", "half_angle_deg", "length", "dub_off_radius",
                                                  "profile_start", "tilt_deg")})
    g = p["grid"]  # "paper", (nx, ny) uniform, or ("clustered", nx, ny)
    if not isinstance(g, (str, list, tuple)):
        raise ValueError(f"grid = {g!r}; allowed: \"paper\", [nx, ny] (uniform) or [\"clustered\", nx, ny]")
    grid = g if isinstance(g, str) else tuple(v if isinstance(v, str) else check_int("grid", v, "nodes", 12, 4097)
                                              for v in g)
    return RollerContact.from_dimensionless(U=p["U"], G=p["G"], W=p["W"], modulus=p["modulus"], roller=roller,
                                            grid=grid)


def _roller_point(p, run):
    s = _roller_build(p).steady(tol=run["tol"])
    return s, dict(h_min_um=s.h_min * 1e6, h_central_um=s.h_central * 1e6, p_max_GPa=s.p_max / 1e9,
                   y_of_h_min_mm=s.y_of_h_min * 1e3, y_of_p_max_mm=s.y_of_p_max * 1e3, load_error=s.load_error,
                   wall_s=s.wall_time)


def _figures(x_label_units):
    def make(table, swept):
        from transient.plots.sweep import regime_map, scalar_curves

        ys = x_label_units["curves"]
        figs = {}
        if len(swept) == 1:
            figs["curves"] = scalar_curves(table, swept[0], [y for y in ys if y in table])
        if "final_regime" in table and 1 <= len(swept) <= 2:
            figs["regimes"] = regime_map(table, swept, "final_regime")
        return figs
    return make


def _plots(element):
    import importlib

    return importlib.import_module(f"transient.plots.{element}")


_JOURNAL_UNITS = dict(diameter="m", length="m", clearance="m", viscosity="Pa s", bulk_modulus="Pa",
                      supply_pressure="Pa", rotor_mass="kg", unbalance="m", load="N", speed_rpm="rpm", grid="cells")
_RHO_KIM = dict(**rho_kim.BEARING, **rho_kim.ROTOR, speed_rpm=rho_kim.REPORTED["speed_rpm"], grid=[151, 21])
#: a journal orbit's scene may give the shaft's speed in time: ``speed_profile = [[t_0, n_0], [t_1, n_1], ...]``
#: ([s, rpm], :class:`~transient.models.journal.speed_law.SpeedProfile`; ``speed_rpm`` the reference)
_ORBIT_UNITS = dict(_JOURNAL_UNITS, speed_profile="s, rpm")

KINDS = {
    "journal_orbit": Kind(
        "journal_orbit", {"rho_kim": _RHO_KIM}, _ORBIT_UNITS,
        dict(revolutions=Option("rev", 20.0, 1e-3, 1e6), method=Option("", "ida", choices=("ida", "cvode", "bdf", "bdf2")),
             rtol=Option("-", 1e-5, 1e-12, 1e-2), outputs_per_revolution=Option("1/rev", 64, 1, 1e5, integer=True),
             settle_tol=Option("-", 0.01, 1e-9, 1.0)),
        _journal_orbit_point, _journal_build, _figures(dict(curves=("semi_major_C", "eps_max"))),
        lambda r, run: _plots("journal").long_run(r, run["outputs_per_revolution"]),
        "unbalanced rotor on the Elrod journal bearing (Rho & Kim), run from the static equilibrium", _journal_memory),
    "journal_noise": Kind(
        "journal_noise", {"rho_kim": _RHO_KIM}, _JOURNAL_UNITS,
        dict(revolutions=Option("rev", 4, 1, 1000, integer=True), harmonics=Option("-", 5, 1, 100, integer=True),
             rtol=Option("-", 1e-6, 1e-12, 1e-2), max_settle_revolutions=Option("rev", 60, 1, 1e5, integer=True)),
        _journal_noise_point, _journal_build, _figures(dict(curves=("level_db", "level_dba", "whirl_amplitude_um"))),
        lambda r, run: _plots("journal").noise_spectra(r, {}),
        "bearing noise of the settled orbit (Rho & Kim)", _journal_memory),
    "ball_sequence": Kind(
        "ball_sequence", {"jeong": {**jeong.BEARING, **jeong.REFERENCE}},
        dict(pitch_diameter="m", ball_diameter="m", n_balls="-", conformity="-", youngs_modulus="Pa", poisson_ratio="-",
             viscosity="Pa s", pressure_viscosity="1/Pa", surface_tension="N/m", load="N", speed_rpm="rpm",
             ambient_film="m"),
        dict(n_passes=Option("-", 100, 1, 1e5, integer=True),
             replenishment=Option("", "thin_film", choices=("thin_film", "chiu", "chiu_thin"))),
        _ball_point, _ball_build, _figures(dict(curves=("H_central", "h_inlet_um"))),
        lambda r, run: _plots("ball").inlet_sequence({"this run": r}, {}),
        "ball-pass starvation sequence of a thrust ball bearing (Jeong et al.)"),
    "pad_descent": Kind(
        "pad_descent", {"lee_rhim": dict(**lee_rhim.PAD, load=lee_rhim.LOAD, rq=lee_rhim.SURFACE["rq"], gamma=1.0,
                                         samples=256, seed=11, grid=[40, 40])},
        dict(length="m", width="m", viscosity="Pa s", load="N", rq="m", gamma="-", samples="-", seed="-", grid="cells"),
        dict(t_end=Option("s", 0.6, 1e-9, 1e4), outputs=Option("-", 201, 2, 1e6, integer=True),
             rtol=Option("-", 1e-8, 1e-12, 1e-2)),
        _pad_point, _pad_build, _figures(dict(curves=("h_eq_over_rq", "t_to_2rq_ms", "contact_area_end_mm2"))),
        lambda r, run: _plots("pad").descent_vs_time({1.0: r}, r.h0[0] / 5.0, r.load),
        "squeeze descent of a rough parallel thrust pad (Lee & Rhim); gamma = 0: Gaussian heights, no generated surface",
        _pad_memory),
    "roller_ehl": Kind(
        "roller_ehl", {"park": dict(**park.ROLLER, tilt_deg=0.0, **park.DIMENSIONLESS, grid="paper")},
        dict(mean_radius="m", half_angle_deg="deg", length="m", dub_off_radius="m", profile_start="m", tilt_deg="deg",
             U="-", G="-", W="-", modulus="Pa", grid="nodes"),
        dict(tol=Option("-", 1e-8, 1e-14, 1e-3)),
        _roller_point, _roller_build, _figures(dict(curves=("h_min_um", "h_central_um", "p_max_GPa"))),
        None, "steady EHL of the tilted tapered roller (Park), the paper's dimensionless case"),
}
