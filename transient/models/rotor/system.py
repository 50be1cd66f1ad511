"""A rotor on several journal bearings: static equilibrium, time runs with a mass-conserving Elrod film per
bearing, the linear unbalance response and the stability threshold.

Each bearing's film is the journal film of :mod:`transient.models.journal` (Elrod; boundary layers and the Gecim
bulk included) driven by the motion of its rotor node; its force enters the rotor equations at that node
(:mod:`transient.models.rotor.model`)::

    M q'' + (C + Omega G) q' + K q = f_bearings + f_unbalance(t) + M g

With ``tilt_coupling=True`` the films also take the nodes' tilts and their moments act on them
(:mod:`transient.models.rotor.model`).

The static equilibrium solves the steady film of every bearing together with the shaft's statics (Newton on
the whole system, started from the bearing loads of the shaft on rigid supports); the linear analyses use each
bearing's own stiffness and damping (``JournalBearing.coefficients``) at the load it carries there (Lund's
method), and, for the stability threshold, also the full linearisation with the film states included: the
eigenvalues of the system's Jacobian pencil at the equilibrium closest to the quasi-static ones (sparse
shift-invert Arnoldi).
"""

from __future__ import annotations

import hashlib
import json
from typing import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.integrate import quad
from scipy.optimize import brentq

from transient.checks import (check_bool, check_choice, check_instance, check_int, check_items, check_memory,
                              check_positive, check_range, check_vector, short_repr)
from transient.models.journal.bearing import (FILM_BYTES_PER_CELL, GRID_ADVICE, SPEED_RANGE_RPM, JournalBearing,
                                              NoEquilibriumError, bearing_memory, check_speed)
from transient.compile_notice import announce
from transient.models.journal.rest import rest_equilibrium
from transient.models.journal.film import read_only
from transient.models.journal.kernels import film_force
from transient.models.journal.tilt import sensitivity, si_coefficients
from transient.models.damper.damper import SqueezeFilmDamper
from transient.models.journal.speed_law import SpeedProfile, shaft_speed
from transient.models.journal.time_domain import check_time_domain
from transient.models.journal.orbit import BDF2_MAX_ORDER, BDF2_MIN_STEPS, BDF2_TRAVEL, BDF2_TRAVEL_RTOL
from transient.models.rotor.content_form import ContentSystem, bdf2_refusal
from transient.models.rotor.model import SystemDAE
from transient.models.rotor import thermal_films
from transient.models.rotor.results import RotorEquilibrium, RotorRunResult, UnbalanceResponse
from transient.models.rotor.rough_films import TRIBOLOGY, rough_block_force, rough_records, tribology_sample
from transient.models.rotor.rotor import Rotor
from transient.solvers.bandlu import BorderedBandLU
from transient.solvers.integrate import Problem, Stats, Steps, check_method
from transient.solvers.model_run import ModelRun, RunParts, check_run_memory, start_point, wall_crossing
from transient.solvers.settings import (Integration, LongRun, Recording, check_unused, keyword_table,
                                       requested_method, run_settings)
from transient.solvers.newton import NewtonError, NewtonSettings, newton
from transient.solvers.shooting import ShootingSettings
from transient.units import rpm_to_rad_s

RUN_METHODS = ("ida", "bdf2")
#: :meth:`RotorBearingSystem.run`'s method when no integration setting is given, where the system's films allow it
#: (:func:`~transient.models.rotor.content_form.bdf2_refusal`; else ``"ida"``): the variable-order BDF on the content
#: films measured at least as fast as IDA at equal error on the two-bearing rotors and in whip (docs/validation.md)
DEFAULT_METHOD = "bdf2"
#: The loose keywords of :meth:`RotorBearingSystem.run` of earlier releases and the settings field each now is.
RUN_KEYWORDS = (keyword_table("integration", Integration, ("method", "rtol", "atol"))
                | keyword_table("recording", Recording, ("outputs_per_revolution",))
                | keyword_table("long_run", LongRun, ("checkpoint", "chunk_revolutions", "resume", "progress",
                                                      "time_budget")))
#: ``method="bdf2"``: its step cap (least steps per revolution) is per shaft revolution at the speed of the step, down
#: to this fraction of the reference speed (below it, per revolution at this fraction)
MIN_CAP_SPEED = 0.1
#: How :meth:`RotorBearingSystem.unbalance_response` linearised the bearings, by ``film_states``
#: (``UnbalanceResponse.linearisation``).
LINEARISATIONS = {True: "film states", False: "K and C"}
#: a shaft node's bearing support in the start of the equilibrium: this many times the largest of the rotor's
#: stiffness and its gravity load per clearance (the reactions are those of rigid supports to about 1e-6)
SUPPORT_STIFFNESS = 1e6
#: the largest total unbalance sum(m e) a system takes, in rotor mass x smallest bearing clearance (the mass centre's
#: distance from the shaft axis, in clearances; balanced rotors are far below one, test rigs' deliberate
#: unbalances about one)
MAX_UNBALANCE_CLEARANCES = 10.0
#: the longest run of a speed function [s] (a year): a shaft that has not turned its revolutions by then never will
MAX_RUN_SECONDS = 3.2e7


class RotorBearingSystem:
    """A :class:`~transient.models.rotor.rotor.Rotor` on :class:`~transient.models.journal.JournalBearing` s.

    Parameters (SI)
    ----------
    rotor : the rotor.
    bearings : ``{node: JournalBearing or SqueezeFilmDamper}``; a bearing node must carry x and y. A damper's
        journal does not turn (its film has no Couette flow) and its centring spring, if any, joins the rotor's
        stiffness at its node; a damper in series with a rolling bearing is a node of its own in the rotor's
        matrices, joined to the shaft by the rolling bearing's stiffness.
    unbalance : ``[(node, m e [kg m], phase [deg]), ...]``: each unbalance's force ``m e Omega^2`` rotates with
        the shaft from ``phase`` (measured from +x in the direction of rotation at t = 0).
    gravity [m/s^2] : a number (acting along +x, the bearings' load direction) or an (x, y) vector.
    tilt_coupling : True: every film takes its node's tilts ``tx``, ty`` [rad] (and their rates in the squeeze term)
        relative to its bush (a bearing's static ``misalignment`` included) and its moments enter the node's tilt
        equations (:mod:`transient.models.journal.tilt`; the rotor needs the dofs ``("x", "y", "tx", "ty")``, the
        films are modelled over the whole length, a Gecim bulk is not taken); the linear analyses then use each
        bearing's 4 x 4 coefficients. False (default): the films see the node's x and y only (a misaligned bush
        keeps its static tilt; the film's moment does not act on the rotor).
    """

    def __init__(self, rotor: Rotor, bearings: dict, unbalance=(), gravity=9.81, tilt_coupling=False):
        self.rotor = check_instance("rotor", rotor, Rotor, "a transient Rotor (Rotor(...), Rotor.example(), "
                                    "Rotor.from_ross(...))")
        if not isinstance(bearings, dict) or not bearings:
            raise ValueError(f"bearings = {short_repr(bearings)}; allowed: a non-empty dict {{node: JournalBearing}}")
        for node, b in bearings.items():
            if isinstance(node, (bool, np.bool_)) or node not in rotor.nodes:
                raise ValueError(f"bearings: node = {node!r} is not a node of the rotor; allowed: {rotor.nodes}")
            check_instance(f"bearings[{node!r}]", b, (JournalBearing, SqueezeFilmDamper),
                           "a JournalBearing or a SqueezeFilmDamper")
            if not np.any(rotor.translation(node)):
                raise ValueError(f"bearings: node {node!r} does not move in this rotor's coordinates")
        for node, b in bearings.items():
            check_time_domain("RotorBearingSystem", b, f"bearings[{node!r}] ")
        self.tilt_coupling = check_bool("tilt_coupling", tilt_coupling)
        if self.tilt_coupling:
            self._check_tilt_coupling(bearings)
        self.dampers = {n: b for n, b in bearings.items() if isinstance(b, SqueezeFilmDamper)}
        self.bearings = {n: b.bearing if n in self.dampers else b for n, b in bearings.items()}  # dampers: their films
        if self.tilt_coupling:  # a tilted gap: the film of the whole length
            self.bearings = {n: b.whole_length() for n, b in self.bearings.items()}
        self.stiffness = rotor.stiffness.copy()  # with the dampers' centring springs
        for node, d in self.dampers.items():
            if d.centring_stiffness:
                T = rotor.translation(node)
                self.stiffness += d.centring_stiffness * T.T @ T
        self.length_scale = min(b.clearance for b in self.bearings.values())
        self.unbalance = self._check_unbalance(unbalance)
        if np.ndim(gravity) == 0:
            g = np.array([check_range("gravity", gravity, "m/s^2", -1e4, 1e4), 0.0])
        else:
            g = np.array(check_vector("gravity", gravity, "m/s^2", 2, -1e4, 1e4, why="(a number along x or an "
                                      "(x, y) vector)"))
        self.gravity_vector = g
        thermal_films.check_thermal_system(self)
        self._check_units()

    @property
    def bearing_nodes(self) -> list:
        return list(self.bearings)

    def _check_tilt_coupling(self, bearings):
        """``tilt_coupling=True`` needs the nodes' tilts and films whose tilt columns the kernels write."""
        if self.rotor.dofs != ("x", "y", "tx", "ty"):
            raise ValueError(f"tilt_coupling = True with a rotor of dofs = {self.rotor.dofs}; allowed: a rotor with "
                             "the dofs (\"x\", \"y\", \"tx\", \"ty\") (or tilt_coupling=False)")
        for node, b in bearings.items():
            if getattr(b, "shear_thinning", False):
                raise ValueError(f"bearings[{node!r}] rheology = Gecim(...) with tilt_coupling = True; allowed: a "
                                 "Newtonian bulk (with or without boundary layers), or tilt_coupling=False")
            if getattr(b, "roughness", None) is not None:
                raise ValueError(f"bearings[{node!r}] roughness = Roughness(...) with tilt_coupling = True; allowed: "
                                 "a smooth bearing, or tilt_coupling=False (the rough film is aligned)")

    def rotation(self, node) -> np.ndarray:
        """(2, n): the rows mapping q to the tilts (tx, ty) [rad] of ``node``."""
        r = self.rotor
        return r.basis[[r.dof(node, "tx"), r.dof(node, "ty")]]

    def _check_unbalance(self, unbalance) -> list:
        """``[(node, m e, phase), ...]`` checked: each a rotor node, ``m e`` in [0, 1e3] kg m, the phase in
        [-360, 360] deg; and together at most :data:`MAX_UNBALANCE_CLEARANCES` smallest clearances times the rotor's
        mass (above the critical speeds a rotor turns about its mass centre, whose distance from the shaft axis is
        sum(m e) / mass: beyond that many clearances the journals could not stay inside their bearings)."""
        rotor = self.rotor
        out = []
        items = check_items("unbalance", unbalance, "a list of (node, m e [kg m], phase [deg])")
        for k, item in enumerate(items):
            node, me, phase = check_items(f"unbalance[{k}]", item, "(node, m e [kg m], phase [deg])", 3)
            if isinstance(node, (bool, np.bool_, list, dict, set, np.ndarray)) or node not in rotor.nodes:
                raise ValueError(f"unbalance[{k}]: node = {short_repr(node)} is not a node of the rotor; allowed: "
                                 f"{rotor.nodes}")
            me = check_range(f"unbalance[{k}] m e", me, "kg m", 0.0, 1e3)
            phase = check_range(f"unbalance[{k}] phase", phase, "deg", -360.0, 360.0)
            out.append((node, me, phase))
        total, mass = sum(me for _, me, _ in out), rotor.total_mass
        limit = MAX_UNBALANCE_CLEARANCES * mass * self.length_scale
        if total > limit:
            raise ValueError(f"unbalance: sum of m e = {total:.6g} [kg m] is out of range; allowed: [0, {limit:.3g}] "
                             f"kg m ({MAX_UNBALANCE_CLEARANCES:g} x rotor mass {mass:.4g} kg x smallest clearance "
                             f"{self.length_scale:.3g} m: above the critical speeds the rotor turns about its mass "
                             "centre, which this unbalance puts further than that from the shaft axis)")
        return out

    def _check_units(self):
        """A rotor whose gravity deflection on rigid supports is larger than a thousand clearances is in other
        units than its bearings (e.g. millimetres against metres)."""
        q = self._rigid_support_displacement()
        d = np.max(np.abs(self.rotor.basis @ q)) if q.size else 0.0
        if d > 1e3 * self.length_scale:
            raise ValueError(f"rotor: gravity deflects the shaft on rigid supports by {d:.3g} m, more than 1000 "
                             f"bearing clearances ({self.length_scale:.3g} m); allowed: the rotor's matrices in SI "
                             "(kg, N/m) like the bearings (m)")

    # ------------------------------------------------------------------------------------------
    def _support_stiffness(self):
        r = self.rotor
        f = np.abs(self.gravity_vector @ r.gravity_load).max() / self.length_scale
        return SUPPORT_STIFFNESS * max(np.max(np.abs(r.stiffness)), f, 1.0)

    def _supported(self, ks):
        """The rotor's stiffness with a spring ``ks`` in x and y at every bearing node."""
        K = self.rotor.stiffness.copy()
        for node in self.bearings:
            T = self.rotor.translation(node)
            K += ks * T.T @ T
        return K

    def _rigid_support_displacement(self):
        ks = self._support_stiffness()
        return _solve(self._supported(ks), self.gravity_vector @ self.rotor.gravity_load)

    def static_loads(self) -> dict:
        """The load [N] (x, y) each bearing carries when the shaft sits on rigid supports at its bearing nodes
        (the shaft's statics under gravity): ``{node: (Wx, Wy)}``."""
        ks = self._support_stiffness()
        q = self._rigid_support_displacement()
        return {node: tuple(ks * self.rotor.translation(node) @ q) for node in self.bearings}

    # ------------------------------------------------------------------------------------------
    def dae(self, speed_ref_rpm, speed=None) -> SystemDAE:
        """The system's DAE at a reference speed (:class:`~transient.models.rotor.model.SystemDAE`)."""
        return SystemDAE(self, speed_ref_rpm, speed)

    def equilibrium(self, speed_rpm) -> RotorEquilibrium:
        """Static equilibrium at ``speed_rpm``: every bearing's steady film and the shaft's statics solved
        together (no unbalance). Raises :class:`~transient.models.journal.bearing.NoEquilibriumError` naming the
        bearing whose load cannot be carried."""
        speed = check_speed(speed_rpm)
        for node, b in self.bearings.items():
            b._check_supplied()
        self._check_steady_memory()
        dae = self.dae(speed)
        if thermal_films.thermal_nodes(self):  # each thermal bearing's THD equilibrium at its load
            return thermal_films.thermal_equilibrium(self, dae, speed)
        y = self._steady(dae, 1.0)
        return self._equilibrium_result(dae, y, speed)

    def _equilibrium_result(self, dae, y, speed) -> RotorEquilibrium:
        q, xy = dae.split(y)
        forces, ecc, att, moments = [], [], [], []
        qt = np.asarray(y[dae.Q0:dae.V0])
        for b, (X, Y) in zip(dae.blocks, xy):
            fl = b.film
            b.set_gap(qt)
            F = np.array(fl.force(y[b.offset:b.offset + b.n], X, Y)) * fl.force_scale
            if b.tilted:
                moments.append(b.moment(*film_force(fl.P, *b.tilt[1:3], fl.area, fl.sym)))
            forces.append(F)
            ecc.append(np.hypot(X, Y))
            load_dir = np.arctan2(-F[1], -F[0])
            att.append(float(np.degrees(np.angle(np.exp(1j * (np.arctan2(Y, X) - load_dir))))))
        forces = np.array(forces)
        return RotorEquilibrium(displacement=self._node_displacements(q), bearing_force=forces,
                                bearing_load=np.hypot(forces[:, 0], forces[:, 1]), eccentricity_ratio=np.array(ecc),
                                attitude_angle_deg=np.array(att), nodes=list(self.rotor.nodes),
                                bearing_nodes=self.bearing_nodes, speed_rpm=speed, state=np.array(y),
                                bearing_moment=np.array(moments) if self.tilt_coupling else None,
                                success=True, message="converged")

    def _node_displacements(self, q) -> np.ndarray:
        """(..., n_nodes, 2): x, y [m] of every node for rotor coordinates q [m] (last axis of q)."""
        r = self.rotor
        full = np.asarray(q) @ r.basis.T
        full = full.reshape(full.shape[:-1] + (len(r.nodes), len(r.dofs)))
        return np.ascontiguousarray(full[..., :2])

    def _start_guess(self, dae, s, equilibria=None):
        """The state of the films at their bearings' own equilibria under the shaft's static loads (``equilibria``:
        those already solved, ``{node: FilmState}``), the shaft bent through those journal positions, at rest."""
        r = self.rotor
        y = np.zeros(dae.n)
        ks = self._support_stiffness()
        rhs = self.gravity_vector @ r.gravity_load
        speed = s * dae.speed_ref_rpm
        for blk in dae.blocks:
            blk.set_gap(np.zeros(dae.nq))  # the films' static gap (the node's tilts come with the Newton)
        for node, W in self.static_loads().items():
            b = self.bearings[node]
            blk = next(k for k in dae.blocks if k.node == node)
            load = float(np.hypot(*W))
            if node in self.dampers:
                X, Y = self._damper_start(node, W, load > 1e-12 * max(1.0, np.abs(rhs).max()))
                sc = blk.film.scales
                y[blk.offset:blk.offset + blk.n] = max(sc.u_ambient, float(np.max(sc.u_supply, initial=0.0)))
                T = r.translation(node)
                rhs = rhs + ks * T.T @ (np.array([X, Y]) * b.clearance)
                continue
            if load < 1e-12 * max(1.0, np.abs(rhs).max()):
                X = Y = 0.0
                u, _ = blk.film.solve(X, Y)
            elif s == 0.0 and b.roughness is not None:  # at rest: the bearing's static contact equilibrium
                _, u, (X0, Y0), _ = rest_equilibrium(b, load, dae.speed_ref_rpm)  # in the films' pressure unit
                a = np.arctan2(W[1], W[0])
                X, Y = X0 * np.cos(a) - Y0 * np.sin(a), X0 * np.sin(a) + Y0 * np.cos(a)
            else:
                try:
                    e = equilibria[node] if equilibria and node in equilibria else b.equilibrium(load, speed)
                except NoEquilibriumError as exc:
                    raise NoEquilibriumError(f"the bearing at node {node} cannot carry its static load {load:.6g} N at "
                                             f"speed_rpm = {speed:.6g} [rpm] ({exc}); allowed: a load the film "
                                             "carries inside the clearance (a larger, longer or more viscous "
                                             "bearing, or a higher speed)") from None
                a = np.arctan2(W[1], W[0])
                X0, Y0 = e.position[0] / b.clearance, e.position[1] / b.clearance
                X, Y = X0 * np.cos(a) - Y0 * np.sin(a), X0 * np.sin(a) + Y0 * np.cos(a)
                u = e.u
                u, _ = blk.film.solve(X, Y, u0=u if s == 1.0 else None)  # e.u is in p0 units of its own speed
            y[blk.offset:blk.offset + blk.n] = u
            T = r.translation(node)
            rhs = rhs + ks * T.T @ (np.array([X, Y]) * b.clearance)
        q = _solve(self._supported(ks), rhs)
        y[dae.Q0:dae.V0] = q / dae.L
        return y

    def _damper_start(self, node, W, loaded):
        """(X, Y) [C] of a damper's journal where its centring spring carries its static load ``W`` [N] (its film,
        at rest and not turning, carries none; it starts full at the highest of its feed and end pressures)."""
        d = self.dampers[node]
        if not loaded:
            return 0.0, 0.0
        if not d.centring_stiffness:
            raise NoEquilibriumError(f"the squeeze-film damper at node {node} carries a static load of "
                                     f"{float(np.hypot(*W)):.6g} N without a centring spring (its film does not turn "
                                     "and carries no static load); allowed: centring_stiffness > 0, or no gravity on "
                                     "it")
        X, Y = np.asarray(W, dtype=float) / (d.centring_stiffness * d.clearance)
        return float(X), float(Y)

    def _steady(self, dae, s, y0=None) -> np.ndarray:
        """Newton on the system at rest (``y' = 0``, no unbalance) at speed ratio ``s``: the films' steady
        equations with the groove cells held, the shaft's statics; pseudo-transient continuation if plain
        Newton fails. Its linear solves by the bordered band LU (one band block per film, the rotor's states the
        dense border: :class:`~transient.solvers.bandlu.BorderedBandLU`), whose cost grows linearly with the
        number of bearings, where a sparse LU of the whole system fills in."""
        y0 = self._start_guess(dae, s) if y0 is None else np.array(y0, dtype=float)
        saved = dae.speed, dae.unbalance
        dae.speed, dae.unbalance = (lambda tau: (s, 0.0)), []
        fixed_rows = np.concatenate([b.offset + np.flatnonzero(~b.film.op.free) for b in dae.blocks])
        fixed_vals = np.concatenate([b.film.op.u_fixed[~b.film.op.free] for b in dae.blocks])
        fixed_diag = _diagonal_positions(dae.pattern, fixed_rows)
        P0 = dae.P0
        zero = read_only(np.zeros(dae.n))
        data = np.empty(dae.pattern.nnz)

        def F(y):
            out = np.empty(dae.n)
            dae.residual(0.0, read_only(y), zero, out)
            out[fixed_rows] = y[fixed_rows] - fixed_vals
            out[P0] = y[P0]
            return out

        lu = BorderedBandLU(dae.pattern, dae.n - dae.Q0)  # a band block per film, the rotor as the border

        def J(y, shift):
            dae.jacobian(0.0, read_only(y), zero, shift, data)
            data[fixed_diag] = 1.0
            data[dae.rotor_pos[4]] = 0.0
            data[dae.rotor_pos[5]] = 1.0
            if lu.factor(data) != 0:
                raise RuntimeError("the bordered band LU met a zero pivot")
            return lu

        try:
            try:
                res = newton(F, J, y0, settings=NewtonSettings(xtol=1e-11, ftol=1e-10, max_iter=30),
                             name="rotor equilibrium")
            except NewtonError:
                res = newton(F, J, y0, settings=NewtonSettings(xtol=1e-11, ftol=1e-10, max_iter=300, pseudo_time=1.0),
                             name="rotor equilibrium")
        except NewtonError as exc:
            raise NoEquilibriumError(f"no static equilibrium of the rotor on its bearings at speed_rpm = "
                                     f"{s * dae.speed_ref_rpm:.6g} [rpm]: {exc}") from None
        finally:
            dae.speed, dae.unbalance = saved
        y = res.x
        for b in dae.blocks:
            lim = b.bearing.max_eccentricity_ratio
            e = float(np.sqrt(b.reach2(y[dae.Q0:dae.V0])))  # at the worse end of a tilted film
            if e >= lim:
                raise NoEquilibriumError(f"the bearing at node {b.node} cannot carry its load at speed_rpm = "
                                         f"{s * dae.speed_ref_rpm:.6g} [rpm]: the journal reaches e/C = "
                                         f"{e:.4f}; allowed: below {lim:.4g}")
        return y

    # ------------------------------------------------------------------------------------------
    def coefficients(self, speed_rpm, equilibrium: RotorEquilibrium | None = None) -> dict:
        """Each bearing's linearised stiffness K [N/m] and damping C [N s/m] (2x2, the bearing's frame) at the
        load it carries in the static equilibrium: ``{node: (K, C)}`` (``JournalBearing.coefficients``)."""
        self._refuse_dampers()
        eq = self.equilibrium(speed_rpm) if equilibrium is None else equilibrium
        if self.tilt_coupling:
            return self._tilt_coefficients(speed_rpm, eq)
        out, done = {}, {}
        for k, node in enumerate(self.bearing_nodes):
            key = (id(self.bearings[node]), float(eq.bearing_load[k]))  # a bearing shared at equal loads: once
            if key not in done:
                done[key] = self.bearings[node].coefficients(key[1], speed_rpm)
            out[node] = done[key]
        return out

    def _tilt_coefficients(self, speed_rpm, eq) -> dict:
        """Each bearing's 4 x 4 K [N/m, N/rad, N m/m, N m/rad] and C (their rates) in (x, y, tx, ty) at its film of
        the system's static equilibrium ``eq`` (position and tilt as they are there, the rotor's frame):
        :func:`~transient.models.journal.tilt.sensitivity` of that film."""
        dae = self.dae(check_speed(speed_rpm))
        y = np.asarray(eq.state)
        q = y[dae.Q0:dae.V0]
        out = {}
        for b in dae.blocks:
            X, Y = b.position(q)
            A, B = b.tilt_groups(q)
            fl = b.film
            a, c = b.static_tilt
            b.set_gap(q)
            fl.tilt = (a + A, c + B)  # the film's whole tilt for the tilt view of the sensitivity
            _, dF_dq, dF_dv = sensitivity(fl, read_only(y[b.offset:b.offset + b.n]), X, Y)
            out[b.node] = si_coefficients(dF_dq, dF_dv, fl.force_scale, b.bearing.radius, b.bearing.clearance,
                                          fl.omega)
        return out

    def _refuse_dampers(self):
        """The analyses that start from each bearing's quasi-static K and C refuse a system with dampers."""
        if self.dampers:
            raise ValueError(f"squeeze-film dampers at nodes {list(self.dampers)}: the linear analyses (coefficients, "
                             "unbalance_response, eigenvalues, stability) start from each bearing's quasi-static K "
                             "and C, which a damper does not give here; allowed with dampers: equilibrium, run, "
                             "periodic_response, response_curve and circular_orbits")

    def _linear_matrices(self, coefficients):
        """(M, C, G, K, bearings) for :mod:`transient.models.rotor.linear`: each bearing on the rotor coordinates
        that are its node's x and y (a nodal rotor's dofs, a Craig-Bampton rotor's kept boundary coordinates)."""
        r = self.rotor
        bearings = []
        for node, (kb, cb) in coefficients.items():
            T = r.translation(node) if kb.shape[0] == 2 else np.vstack([r.translation(node), self.rotation(node)])
            unit = [np.flatnonzero(row) for row in T]
            if not all(u.size == 1 and row[u[0]] == 1.0 for u, row in zip(unit, T)):
                raise ValueError(f"bearing node {node}: its x and y{' and tilts' if kb.shape[0] == 4 else ''} are not "
                                 "coordinates of this reduced rotor; allowed: a nodal rotor or one reduced keeping the "
                                 "bearing nodes' x and y (Rotor.from_ross(..., modes=) does)")
            bearings.append((*(int(u[0]) for u in unit), kb, cb))
        return r.mass, r.damping, r.gyroscopic, r.stiffness, bearings

    def unbalance_response(self, speed_rpm, film_states=True) -> UnbalanceResponse:
        """The linear unbalance response at ``speed_rpm``: complex amplitudes per node (``position(node)``,
        ``x(t) = Re(X e^{i Omega t})``). Default (``film_states=True``): the system linearised with the films' own
        states (:meth:`linearisation`), ``(A + i B) Z = F`` in the time ``tau = Omega t``, which the time domain
        settles to; ``film_states=False``: the rotor with each bearing's quasi-static K and C at its static load
        (:meth:`coefficients`, :mod:`transient.models.rotor.linear`; Lund's method, which leaves out the films' own
        dynamics). The result's ``linearisation`` says which (``"film states"`` or ``"K and C"``)."""
        speed = check_speed(speed_rpm)
        film_states = check_bool("film_states", film_states)
        w = rpm_to_rad_s(speed)
        eq = self.equilibrium(speed)
        coef = self.coefficients(speed, eq)
        r = self.rotor
        if film_states:
            lin = self.linearisation(speed, eq)
            q = lin.forced_response()[lin.dae.Q0:lin.dae.V0] * lin.dae.L
        else:
            from transient.models.rotor.linear import unbalance_response

            M, C, G, K, bearings = self._linear_matrices(coef)
            f = np.zeros(r.n, dtype=complex)
            for node, me, phase in self.unbalance:
                T = r.translation(node)
                amp = me * w * w * np.exp(1j * np.radians(phase))
                f += T[0] * amp - 1j * T[1] * amp
            q = np.asarray(unbalance_response(M, C, G, K, bearings, f, w))
        return UnbalanceResponse(displacement=self._node_displacements(q),
                                 stiffness=np.array([coef[n][0] for n in self.bearing_nodes]),
                                 damping=np.array([coef[n][1] for n in self.bearing_nodes]),
                                 nodes=list(r.nodes), bearing_nodes=self.bearing_nodes, speed_rpm=speed,
                                 linearisation=LINEARISATIONS[film_states], success=True,
                                 message=f"linear, {LINEARISATIONS[film_states]}")

    def linearisation(self, speed_rpm, equilibrium=None) -> "Linearisation":
        """The system linearised at its static equilibrium with the film states included
        (:class:`Linearisation`)."""
        thermal_films.refuse_thermal(self, "linearisation")
        speed = check_speed(speed_rpm)
        eq = self.equilibrium(speed) if equilibrium is None else equilibrium
        return Linearisation(self, self.dae(speed), eq)

    def linear_start(self, speed_rpm) -> np.ndarray:
        """The state at t = 0 on the linear unbalance response with the film states (equilibrium + Re Z): a run
        started there (``start=(0, state)``) is settled but for the nonlinearity of the films."""
        lin = self.linearisation(speed_rpm)
        return lin.equilibrium.state + lin.forced_response().real

    def quasi_static_eigenvalues(self, speed_rpm, equilibrium=None) -> np.ndarray:
        """Eigenvalues [1/s] of the rotor with each bearing's K and C (Lund's quasi-static bearings), sorted by
        the size of their imaginary part."""
        from transient.models.rotor.linear import eigenvalues

        speed = check_speed(speed_rpm)
        M, C, G, K, bearings = self._linear_matrices(self.coefficients(speed, equilibrium))
        return np.asarray(eigenvalues(M, C, G, K, bearings, rpm_to_rad_s(speed)))

    def eigenvalues(self, speed_rpm, count=4, equilibrium=None) -> np.ndarray:
        """Eigenvalues [1/s] of the system linearised at its static equilibrium with the film states included
        (:meth:`Linearisation.eigenvalues`): those nearest each of the ``count`` least stable quasi-static
        eigenvalues (:meth:`quasi_static_eigenvalues`), sorted by real part, largest last."""
        speed = check_speed(speed_rpm)
        count = check_int("count", count, "-", 1, 100)
        eq = self.equilibrium(speed) if equilibrium is None else equilibrium
        qs = self.quasi_static_eigenvalues(speed, eq)
        qs = qs[np.imag(qs) > 0]
        return self.linearisation(speed, eq).eigenvalues(qs[np.argsort(-qs.real)][:count])

    def growth_rate(self, speed_rpm, film_states=True) -> float:
        """Largest real part [1/s] of the linearised system's eigenvalues: with the film states
        (:meth:`eigenvalues`) or of the quasi-static bearings (``film_states=False``)."""
        eq = self.equilibrium(speed_rpm)
        lam = self.eigenvalues(speed_rpm, equilibrium=eq) if film_states else \
            self.quasi_static_eigenvalues(speed_rpm, eq)
        return float(np.max(lam.real))

    def stability_threshold(self, speed_range_rpm=(500.0, 30000.0), rtol=1e-4, film_states=True) -> float:
        """The lowest speed [rpm] in ``speed_range_rpm`` at which the linearised system's largest growth rate
        crosses zero (oil whirl onset): with the film states included (default), or from the quasi-static K and
        C (``film_states=False``, Lund's method; it leaves out the film's own dynamics)."""
        lo, hi = speed_range_rpm
        lo, hi = check_speed(lo), check_speed(hi)
        if hi <= lo:
            raise ValueError(f"speed_range_rpm = {speed_range_rpm!r} [rpm]; allowed: (low, high) with low < high")
        g = lambda n: self.growth_rate(n, film_states)  # noqa: E731
        speeds = np.geomspace(lo, hi, 9)
        vals = [g(speeds[0])]
        for k in range(len(speeds) - 1):
            vals.append(g(speeds[k + 1]))
            if vals[k] < 0 <= vals[k + 1]:
                return float(brentq(g, speeds[k], speeds[k + 1], rtol=rtol))
        raise ValueError(f"no stability threshold in speed_range_rpm = ({lo:g}, {hi:g}) [rpm] (largest growth rates "
                         f"{vals[0]:.3g} ... {vals[-1]:.3g} 1/s); allowed: a range where the growth rate changes sign")

    # ------------------------------------------------------------------------------------------
    def run(self, revolutions, speed_rpm=None, *, speed_profile=None, start=None, touch_gap=1e-3,
            reference_speed_rpm=None, integration: Integration | None = None, recording: Recording | None = None,
            long_run: LongRun | None = None, thermal_interval=1.0, temperature=None, **legacy) -> RotorRunResult:
        """Integrate the rotor on its films over ``revolutions`` shaft revolutions.

        Parameters
        ----------
        revolutions [rev] : the run's length in shaft revolutions (a speed function: the time in which the shaft
            turns that often).
        speed_rpm [rpm] : a number, or a function of the time t [s] (run-up, coast-down): it enters the films'
            Couette flow and the unbalance force (angle = integral of the speed, plus the m e Omega' term); a
            function's rate is its central difference.
        speed_profile : instead of ``speed_rpm``, the shaft's speed law as the journal orbit's
            (:class:`~transient.models.journal.speed_law.SpeedProfile`, or what it takes: a table ``((t [s],
            n [rpm]), ...)``, linear between its knots, or a function ``n(t)``, taken as straight lines through its
            values ``FUNCTION_KNOTS`` times per reference revolution): the speed and its rate exact on those lines
            (:func:`~transient.models.journal.speed_law.shaft_speed`), the shaft angle their integral.
        integration : :class:`~transient.solvers.settings.Integration`; when it is left out (and no deprecated
            integration keyword is given) the method is chosen by what the films allow: ``"bdf2"`` at its defaults
            (``DEFAULT_METHOD``), or ``"ida"`` for films ``bdf2`` does not take (a mix of film kinds,
            :func:`~transient.models.rotor.content_form.bdf2_refusal`); the result's ``method`` says which. An
            ``Integration`` given without a method is IDA's (its class default). ``method``
            ``"ida"`` (SUNDIALS IDA, sparse SuperLU on the block-arrow pattern) or ``"bdf2"`` (variable-step BDF2 on
            the films' content form, a bordered band LU with one band block per film and the rotor as its border,
            :mod:`~transient.models.rotor.content_form`; rtol and atol act on the rotor's coordinates and
            velocities, every film is solved to the journal's Newton tolerance each step; its steps as the journal
            orbit's: variable order up to ``max_order`` (default ``BDF2_MAX_ORDER`` = 5; 2: plain BDF2), each step at
            most ``BDF2_TRAVEL`` = 1e-3 of every journal's travel in its own clearance at rtol 1e-6, as sqrt(rtol)
            at others, and at least ``BDF2_MIN_STEPS`` = 50 steps per shaft revolution at the step's speed, down to
            ``MIN_CAP_SPEED`` of the reference speed; an explicit ``steps_per_revolution`` is that least number
            instead, without the travel bound); ``rtol``, ``atol`` (atol on the dimensionless states: p/p0, journal
            position in clearances).
        recording : :class:`~transient.solvers.settings.Recording`: ``outputs_per_revolution``, outputs per
            revolution at the reference speed (default 100).
        long_run : :class:`~transient.solvers.settings.LongRun`: ``checkpoint``, the path of an ``.npz``
            rewritten after every chunk (``resume=True`` continues from it), ``chunk_revolutions`` (default: the
            whole run, 10 with a checkpoint), ``progress``, ``time_budget`` [s of wall time], ``stop``:
            ``stop(result_so_far) -> str | None`` after every chunk, a non-empty string ends the run and becomes
            its message (e.g. "settled").
        start : None (the static equilibrium at the start speed, at rest), a previous :class:`RotorRunResult`
            (continued from its final state and time, at its reference speed) or ``(t [s], state)`` (a state at this
            run's reference speed: e.g. ``linear_start``, ``equilibrium(...).state`` or a periodic response's at the
            run's constant speed).
        touch_gap : > 0 stops the run (``success=False``, ``touched_at``, the message naming the bearing node, the
            time and e/C) when a journal reaches e/C = 1 - touch_gap (with boundary layers 1 - 2 delta / C -
            touch_gap); 0 turns the detection off, but a run whose journal reaches the wall (a negative film) is
            still never a success. A rough bearing's journal runs through contact (its asperities carry it): it is
            not watched, its contact is recorded (``contact_load``, ``friction_torque``, ``min_film``,
            ``contact_pressure``, ``contact_events``: :mod:`~transient.models.rotor.rough_films`).
        reference_speed_rpm : the speed of the films' pressure unit (default: the largest speed of the run;
            a continued run keeps its start's; thermal bearings without a start: the start speed).
        thermal_interval [rev], temperature [K] : thermal bearings (``JournalBearing(thermal=ThermalFilm(...))``,
            :mod:`~transient.models.rotor.thermal_films`; ``method="bdf2"``, its default there): the films run on
            the viscosities of their temperatures at the start of each thermal interval of ``thermal_interval``
            revolutions (whole output intervals), the temperatures take one step on the interval's mean flows and
            dissipation at its end. ``temperature``: every thermal film's cells and feeds at this temperature at the
            start (default: a ``start`` result's final temperatures, else the thermal equilibrium's).

        The settings as loose keywords (``method="bdf2"``, ``outputs_per_revolution=32``, ``checkpoint=PATH``) are
        deprecated: they still work for one release, with a ``DeprecationWarning`` naming the new spelling (beside
        the object they belong in: an error).
        """
        check_method("RotorBearingSystem.run", requested_method(integration, legacy), step_solve=True,
                     among=RUN_METHODS)
        thermal = bool(thermal_films.thermal_nodes(self))
        if thermal:
            integration = thermal_films.thermal_integration(integration, legacy)
        elif temperature is not None:
            raise ValueError(f"temperature = {temperature!r} [K] without thermal bearings; allowed: None (the start "
                             "temperature of thermal films: JournalBearing(thermal=ThermalFilm(...)))")
        revolutions = check_positive("revolutions", revolutions, "rev")
        # the default by capability only where no integration setting is given (the deprecated keywords keep IDA's)
        chosen = integration is None and not any(RUN_KEYWORDS.get(k, ("",))[0] == "integration" for k in legacy)
        ig, rc, lr = run_settings("RotorBearingSystem.run", legacy, RUN_KEYWORDS,
                                  {"integration": {"method": DEFAULT_METHOD if chosen else "ida"}},
                                  integration=integration, recording=recording, long_run=long_run).values()
        check_method("RotorBearingSystem.run", ig.method, step_solve=True, among=RUN_METHODS)
        check_unused("RotorBearingSystem.run", "integration", ig, ("formulation", "dt", "linear_solver"))
        check_unused("RotorBearingSystem.run", "recording", rc, ("record", "record_from_revolution"))
        method, rtol, atol, opr = ig.method, ig.rtol, ig.atol, rc.outputs_per_revolution
        if thermal:
            lr = thermal_films.thermal_long_run(method, lr, thermal_interval, opr)
        run = ModelRun(revolutions, opr, lr, touch_gap)
        self._check_run_memory(run.n_outputs)
        t0, y = start_point(start, RotorRunResult)
        if isinstance(start, RotorRunResult):
            if reference_speed_rpm is not None and reference_speed_rpm != start.reference_speed_rpm:
                raise ValueError(f"reference_speed_rpm = {reference_speed_rpm!r} [rpm]; allowed: the start's "
                                 f"{start.reference_speed_rpm!r} (its film state is in that speed's pressure unit)")
            reference_speed_rpm = start.reference_speed_rpm
        law = _speed_law(speed_rpm, speed_profile)
        speed_fn, t_end, n_max = _speed_schedule(speed_rpm if law is None else law.value, t0, revolutions)
        if thermal and y is None and reference_speed_rpm is None:  # the thermal start's films: at the start speed
            reference_speed_rpm = speed_fn(t0) or None
        ref = n_max if reference_speed_rpm is None else check_speed(reference_speed_rpm)
        if (callable(speed_rpm) or law is not None) and any(b.shear_thinning for b in self.bearings.values()):
            raise ValueError("speed_rpm as a function of time with a Gecim (shear-thinning) bearing: its bulk flux is "
                             "tabulated at one sliding speed; allowed: a constant speed")
        w = rpm_to_rad_s(ref)

        if law is None:
            def speed(tau):
                t = min(max(tau / w, t0), t_end)  # the speed function is taken only inside the run [t0, t_end]
                n = speed_fn(t)                   # (an integrator may try a step past the end)
                h = 1e-6 * max(t_end - t0, 1e-9)
                lo, hi = max(t - h, t0), min(t + h, t_end)
                dn = (speed_fn(hi) - speed_fn(lo)) / (hi - lo) if callable(speed_rpm) else 0.0
                return n / ref, rpm_to_rad_s(dn) / w ** 2
        else:  # the law's straight lines in tau: the speed ratio and its rate exact on them
            knots = law.knots(w, ref, t_end)

            def speed(tau):
                s_, ds, _ = shaft_speed(tau, knots)
                return s_, ds

        dae = self.dae(ref, speed)
        if chosen and bdf2_refusal(dae):  # films the BDF does not take: the default is IDA
            method = "ida"
        s0 = speed(t0 * w)[0]
        states = {}
        if y is None:
            if s0 <= 0 and not all(b.roughness is not None for b in self.bearings.values()):
                raise ValueError(f"speed_rpm(t = {t0:g} s) = {s0 * ref:g} [rpm]: a smooth film carries no load at "
                                 "rest; allowed: > 0 (start a run-up from a low speed), or rough bearings throughout "
                                 "(the static contact equilibrium at rest)")
            y, states = thermal_films.thermal_start(self, dae, s0) if thermal else (self._steady(dae, s0), {})
        elif thermal and temperature is None and getattr(start, "final_temperature", None) is None:
            states = thermal_films.thermal_states(self, thermal_films.bearing_equilibria(self, dae, s0 * ref)[0])

        def journals(y_):
            q = y_[dae.Q0:dae.V0]
            return [(f"journal at bearing node {b.node}", float(np.sqrt(b.reach2(q))),
                     b.bearing.max_eccentricity_ratio) for b in dae.blocks]

        run.check_state(y, dae.n, "system", journals)
        tau0, tau_end = t0 * w, t_end * w
        watched = [b for b in dae.blocks if b.rough is None]  # a rough journal's contact is a record, not a stop
        limits = [(b.bearing.max_eccentricity_ratio - run.touch_gap) ** 2 for b in watched]
        events = None
        if run.touch_gap > 0 and watched:
            def events(t, yy, out):  # the rotor's states sit at the same places in both layouts
                q = yy[dae.Q0:dae.V0]
                for k, b in enumerate(watched):
                    out[k] = limits[k] - b.reach2(q)
        n_events = len(watched) if events else 0
        solver = dict(method=method, rtol=rtol, atol=dae.absolute_tolerance(atol))
        to_run = universal = None
        if method == "bdf2":
            announce("rotor_bdf2")  # a cold cache compiles the films' content kernels and the Newton once
            form = (thermal_films.ThermalContentSystem if thermal else ContentSystem)(dae)
            to_run, universal = form.content_state, form.universal_state
            problem_at = lambda y_, tau_: form.problem(y_, tau_, events, n_events)  # noqa: E731
            # the step cap in shaft angle: per shaft revolution at any speed down to MIN_CAP_SPEED of the reference
            # speed, not per revolution at the reference speed; at the defaults each journal's travel bounded too
            # (the films' fronts move with the journals), as the journal orbit's steps
            cap_scale = lambda tau: 1.0 / max(speed(tau)[0], MIN_CAP_SPEED)  # noqa: E731
            options = {"bdf2": form.model(), "max_step_scale": cap_scale, "error_pairs": form.error_pairs(),
                       "max_order": BDF2_MAX_ORDER if ig.max_order is None else ig.max_order}
            spr = ig.steps_per_revolution
            if spr is None:
                spr = BDF2_MIN_STEPS
                options["max_travel"] = (form.journal_travel, BDF2_TRAVEL * np.sqrt(rtol / BDF2_TRAVEL_RTOL))
            solver.update(steps=Steps(max_step=2 * np.pi / spr, first_step=2 * np.pi * 1e-4), options=options)
        else:
            def problem_at(y_, tau_):
                y_ = np.array(y_, dtype=float)
                return Problem(y0=y_, yp0=dae.consistent_yp(tau_, y_), residual=dae.residual, jac_pattern=dae.pattern,
                               jac_residual=dae.jacobian, events=events, n_events=n_events,
                               event_terminal=[True] * n_events, event_direction=[-1] * n_events,
                               name="rotor on journal bearings")

        def touch_message(tau, y_):
            q = np.asarray(y_)[dae.Q0:dae.V0]
            gaps = [limits[k] - b.reach2(q) for k, b in enumerate(watched)]
            b = watched[int(np.argmin(gaps))]
            return (f"the journal at bearing node {b.node} touches its bearing (e/C = {np.sqrt(b.reach2(q)):.4f}, "
                    f"touch_gap = {run.touch_gap:g}) at t = {tau / w:.6g} s")

        key = dict(self.parameters(), speed=_speed_key(speed_fn, t0, t_end), reference_speed_rpm=ref, method=method,
                   rtol=rtol, atol=atol, outputs_per_revolution=opr, max_order=ig.max_order,
                   steps_per_revolution=ig.steps_per_revolution)
        parts = RunParts(label="rotor run", omega=w, revolution=(tau_end - tau0) / revolutions, problem_at=problem_at,
                         solver=solver, series=("speed", "d", "f") + (TRIBOLOGY if dae.rough else ()),
                         sample=self._sampler(dae, speed),
                         journals=journals,
                         eccentricities=lambda r: [(f"journal at bearing node {node}", r.eccentricity_ratio(node),
                                                    b.bearing.max_eccentricity_ratio)
                                                   for node, b in zip(self.bearing_nodes, dae.blocks)],
                         touch_message=touch_message,
                         result=lambda rec, stats, touched, message, tau_end_: self._run_result(
                             rec, dae, method, stats, touched, message, tau_end_ / w, ref),
                         to_run=to_run, universal=universal, key=key)
        if thermal:
            films = thermal_films.ThermalBearings(form, speed, thermal_films.start_temperatures(
                form, start, temperature, states))
            parts = thermal_films.thermal_parts(parts, films, events, n_events, thermal_interval)
        return run.go(parts, y, tau0, (tau_end - tau0) / run.n_outputs)

    def _sampler(self, dae, speed) -> Callable:
        """``sample(tau, y)``: a run's outputs at one output time, ``y`` in the universal layout: the speed [rpm],
        every node's x, y [m] and every bearing's film force [N]."""
        def sample(tau, y):
            q = y[dae.Q0:dae.V0]
            forces = []
            for b in dae.blocks:
                X, Y = b.position(q)
                b.set_gap(q)
                u = y[b.offset:b.offset + b.n]
                F = b.film.force(u, X, Y) if b.rough is None else rough_block_force(b, u, X, Y)  # rough: its kernels
                forces.append((F[0] * b.film.force_scale, F[1] * b.film.force_scale))
            row = dict(speed=speed(tau)[0] * dae.speed_ref_rpm, d=self._node_displacements(q * dae.L), f=forces)
            if dae.rough:  # rough bearings: the contact and friction records (rough_films.py)
                row.update(tribology_sample(dae, y, row["speed"]))
            return row

        return sample

    def _run_result(self, rec, dae, method, stats, touched, message, t_end, ref) -> RotorRunResult:
        a = rec.arrays()
        nodes = list(self.rotor.nodes)
        rough = rough_records(a, dae, self.bearing_nodes) if dae.rough else {}
        return RotorRunResult(t=a["t"], displacement=a["d"].reshape(-1, len(nodes), 2), speed_rpm=a["speed"],
                              bearing_force=a["f"].reshape(-1, len(dae.blocks), 2), nodes=nodes,
                              bearing_nodes=self.bearing_nodes,
                              clearance=np.array([b.bearing.clearance for b in dae.blocks]), method=method,
                              touched_at=touched, message=message, stats=stats or Stats(), final_state=rec.last_y,
                              final_time=float(t_end), reference_speed_rpm=ref, **rough)

    def _check_steady_memory(self):
        """Refuse, before the films are built, a static equilibrium (the whole system's Newton) that does not fit
        this machine: each film's grid, film and steady solve
        (:func:`~transient.models.journal.bearing.bearing_memory`)."""
        n_film = sum(b.n_cells for b in self.bearings.values())
        grids = " + ".join(f"{b.grid_shape[0]} x {b.grid_shape[1]}" for b in self.bearings.values())
        check_memory(f"the static equilibrium of this rotor ({n_film} film cells on bearing grids {grids})",
                     bearing_memory(n_film), GRID_ADVICE)

    def _check_run_memory(self, n_outputs):
        """Refuse, before the films, the equilibrium or the integrator are built, a run whose memory exceeds the
        machine's share (:func:`~transient.checks.check_memory`): per film cell the film (``FILM_BYTES_PER_CELL``)
        and the integrator's sparse Jacobian and LU (the orbit's measured 5.5 kB per state), the recordings."""
        n_film = sum(b.n_cells for b in self.bearings.values())
        n = n_film + 2 * self.rotor.n + 1
        grids = " + ".join(f"{b.grid_shape[0]} x {b.grid_shape[1]}" for b in self.bearings.values())
        outputs = 8.0 * n_outputs * (2 * len(self.rotor.nodes) + 2 * len(self.bearings) + 2)
        parts = dict(model=FILM_BYTES_PER_CELL * n_film, solver=5500.0 * n, recordings=outputs)
        check_run_memory(f"this rotor run ({n_outputs} outputs, {n} states on bearing grids {grids})", parts,
                         GRID_ADVICE, "lower revolutions or outputs_per_revolution")

    def periodic_response(self, speed_rpm, rtol=1e-6, tol=None, modes=2, outputs_per_revolution=64, max_iter=None, *,
                          integrator="ida", shooting: ShootingSettings | None = None, start=None, basis=None):
        """The settled unbalance orbit at ``speed_rpm`` by shooting (Newton-Picard on the ``modes`` least damped
        modes of the linearisation with the film states, :mod:`~transient.models.rotor.periodic`): ``p.position(node)``
        over one revolution [m], ``p.multipliers`` (Floquet), ``p.stable``; ``success`` when it converged to a
        stable orbit that stays inside every clearance.

        ``tol`` [smallest clearance] on the rotor's coordinates and velocities (default ``rtol``); ``integrator``:
        the period map's, ``"ida"`` (the universal films) or ``"bdf2"`` (the conservative stepper of
        ``run(method="bdf2")`` on the content films; its step cap ``BDF2_STEPS_PER_REVOLUTION`` per revolution, rtol and its
        atol ``1e-3 rtol`` on the rotor's states); ``shooting``: a
        :class:`~transient.solvers.shooting.ShootingSettings` taken as given but for its tolerances, which are
        ``tol`` and ``rtol`` (default ``ShootingSettings(max_iter=25, relax=1)``; ``max_iter`` is its field, kept
        as a keyword when no ``shooting`` is given); ``start``: a state at shaft angle 0 (a
        :class:`~transient.models.rotor.results.PeriodicResponse` or its ``state``; default the linear response
        with the film states) and ``basis`` its dominant subspace (a nearby speed's ``PeriodicResponse.basis``;
        default the linearisation's least damped modes)."""
        from transient.models.rotor.periodic import periodic_response

        thermal_films.refuse_thermal(self, "periodic_response")
        speed = check_speed(speed_rpm)
        args = self._shooting_args(rtol, tol, modes, outputs_per_revolution, max_iter, integrator, shooting)
        y0 = None
        if start is not None:
            y0 = np.array(getattr(start, "state", start), dtype=float)
            n = self.dae(speed).n
            if y0.shape != (n,) or not np.all(np.isfinite(y0)):
                raise ValueError(f"start has shape {y0.shape} or non-finite entries; this system has {n} finite states")
        return self._inside(periodic_response(self, speed, *args, y0,
                                              None if basis is None else np.asarray(basis, dtype=float)))

    def response_curve(self, speeds_rpm, rtol=1e-6, tol=None, modes=2, outputs_per_revolution=64, *,
                       integrator="ida", shooting: ShootingSettings | None = None, predictor="secant",
                       progress=False):
        """Periodic unbalance responses along the monotone ``speeds_rpm`` by continuation (each speed's shooting
        from the extrapolation of the last ones, ``predictor`` ``"secant"`` or ``"quadratic"``, on the last refined
        subspace) with their Floquet multipliers: a
        :class:`~transient.models.rotor.results.RotorResponseCurve` (``amplitudes(node)``, ``stable``,
        ``onset_rpm`` where the dominant multiplier crosses 1, every speed's orbit in ``orbits``). The other
        parameters as :meth:`periodic_response`."""
        from transient.models.rotor.periodic import response_curve

        thermal_films.refuse_thermal(self, "response_curve")
        speeds = np.array([check_speed(n) for n in check_items("speeds_rpm", speeds_rpm,
                                                                "a non-empty sequence of speeds [rpm]")])
        if speeds.size == 0:
            raise ValueError("speeds_rpm = []; allowed: a non-empty sequence of speeds [rpm]")
        if speeds.size > 1 and not (np.all(np.diff(speeds) > 0) or np.all(np.diff(speeds) < 0)):
            raise ValueError(f"speeds_rpm = {short_repr(speeds_rpm)} [rpm]; allowed: strictly monotone (a "
                             "continuation path)")
        predictor = check_choice("predictor", predictor, ("secant", "quadratic"))
        args = self._shooting_args(rtol, tol, modes, outputs_per_revolution, None, integrator, shooting)
        curve = response_curve(self, speeds, *args, predictor, check_bool("progress", progress))
        for p in curve.orbits:
            self._inside(p)
        return curve

    def circular_orbits(self, speed_range_rpm, *, step=0.02, max_step=0.05, max_points=400, start_rpm=None):
        """The synchronous circular orbits of an axisymmetric rotor on squeeze-film dampers without gravity, traced
        by pseudo-arclength continuation through the folds of the damper's jump, each damper's film steady in the
        frame whirling with its journal: a :class:`~transient.models.rotor.circular_orbits.CircularOrbitCurve`
        (``speed_rpm``, ``eccentricity_ratio``, ``transmitted_force``, ``folds_rpm``;
        :func:`~transient.models.rotor.circular_orbits.trace`). Their stability: :meth:`periodic_response` started
        on one (:meth:`circular_orbit_state`) gives its Floquet multipliers."""
        from transient.models.rotor.circular_orbits import trace

        return trace(self, speed_range_rpm, step, max_step, max_points, start_rpm)

    def circular_orbit_state(self, speed_rpm, amplitude) -> np.ndarray:
        """The system's state at shaft angle 0 on the circular orbit whose journals are at ``amplitude`` (complex
        e/c per damper, a row of ``CircularOrbitCurve.amplitude``): a ``start`` of :meth:`periodic_response` or of
        :meth:`run` (``start=(0, state)`` at this reference speed)."""
        from transient.models.rotor.circular_orbits import circular_start

        return circular_start(self, speed_rpm, amplitude)

    def _shooting_args(self, rtol, tol, modes, outputs_per_revolution, max_iter, integrator, shooting) -> tuple:
        """The checked (rtol, tol, modes, outputs per revolution, shooting settings, integrator) of a shooting."""
        from transient.models.rotor.periodic import INTEGRATORS, SHOOTING_DEFAULTS

        rtol = check_range("rtol", rtol, "-", 1e-12, 1e-2)
        tol = rtol if tol is None else check_positive("tol", tol, "-")
        modes = check_int("modes", modes, "-", 1, 20)
        opr = check_int("outputs_per_revolution", outputs_per_revolution, "1/rev", 4, 100000)
        integrator = check_choice("integrator", integrator, INTEGRATORS)
        if shooting is None:
            shooting = ShootingSettings(**dict(SHOOTING_DEFAULTS, max_iter=check_int(
                "max_iter", SHOOTING_DEFAULTS["max_iter"] if max_iter is None else max_iter, "-", 1, 1000)))
        else:
            check_instance("shooting", shooting, ShootingSettings, "ShootingSettings(...) or None")
            if max_iter is not None:
                raise ValueError(f"max_iter = {max_iter!r} with shooting = ShootingSettings(...); allowed: one of them "
                                 "(shooting=ShootingSettings(max_iter=...))")
            check_unused("periodic_response", "shooting", shooting, ("tol", "rtol", "rtol_max"))
        return rtol, tol, modes, opr, shooting, integrator

    def _inside(self, p):
        """``p`` (a periodic response) unsuccessful when an orbit goes through a bearing wall, converged or not."""
        for node, b in self.bearings.items():
            x, y = p.position(node)
            through = wall_crossing(p.t, np.hypot(x, y) / b.clearance, b.max_eccentricity_ratio)
            if through:
                p.success, p.message = False, f"the journal at bearing node {node} {through}; {p.message}"
                break
        return p

    def parameters(self) -> dict:
        """Every parameter of the system (SI), e.g. to key a checkpoint (the rotor's matrices as a digest)."""
        r = self.rotor
        h = hashlib.sha256()
        for a in (r.mass, r.stiffness, r.damping, r.gyroscopic, r.basis, r.gravity_load):
            h.update(np.ascontiguousarray(a).tobytes())
        return dict(rotor=h.hexdigest()[:16], nodes=list(r.nodes), dofs=list(r.dofs),
                    bearings={str(n): dict(b.parameters(), **({} if n not in self.dampers else dict(
                        damper=True, centring_stiffness=self.dampers[n].centring_stiffness)))
                        for n, b in self.bearings.items()},
                    unbalance=[list(u) for u in self.unbalance], gravity=list(self.gravity_vector),
                    **(dict(tilt_coupling=True) if self.tilt_coupling else {}))


class Linearisation:
    """The system linearised at its static equilibrium with the films' own states: ``B z' + A z = f`` in the
    time ``tau = Omega t`` (``A = dF/dy``, ``B = dF/dy'`` of the DAE at rest, the groove cells and the shaft angle
    left out: they do not move)."""

    def __init__(self, system, dae: SystemDAE, equilibrium: RotorEquilibrium):
        self.system, self.dae, self.equilibrium = system, dae, equilibrium
        dae.unbalance = []
        y = read_only(equilibrium.state)
        zero = read_only(np.zeros(dae.n))
        d0, d1 = np.empty(dae.pattern.nnz), np.empty(dae.pattern.nnz)
        dae.jacobian(0.0, y, zero, 0.0, d0)
        dae.jacobian(0.0, y, zero, 1.0, d1)
        keep = np.ones(dae.n, dtype=bool)
        for b in dae.blocks:
            keep[b.offset:b.offset + b.n] = b.film.op.free
        keep[dae.P0] = False
        self.keep = keep
        mat = lambda d: sp.csc_matrix((d, dae.pattern.indices, dae.pattern.indptr), shape=dae.pattern.shape)  # noqa: E731
        self.A = mat(d0)[keep][:, keep].tocsc()
        self.B = (mat(d1) - mat(d0))[keep][:, keep].tocsc()

    def forced_response(self) -> np.ndarray:
        """The complex amplitudes Z of the whole state (dimensionless, groove cells and angle 0) under the
        system's unbalances at the equilibrium's speed: ``(A + i B) Z = F``, ``F`` the unbalance force
        ``(m e / L) e^{i a} (t_x - i t_y)`` in the momentum rows."""
        dae, s = self.dae, self.system
        f = np.zeros(dae.n, dtype=complex)
        for node, me, phase in s.unbalance:
            T = s.rotor.translation(node)
            f[dae.V0:dae.P0] += (me / dae.L) * np.exp(1j * np.radians(phase)) * (T[0] - 1j * T[1])
        z = np.zeros(dae.n, dtype=complex)
        z[self.keep] = spla.spsolve((self.A + 1j * self.B).tocsc(), f[self.keep])
        return z

    def eigenvalues(self, shifts, k=3) -> np.ndarray:
        """Eigenvalues [1/s] of the pencil ``(A + lambda B) z = 0`` nearest each of ``shifts`` [1/s] (``k``
        each) by shift-invert Arnoldi on ``(A + sigma B)^-1 B``, sorted by real part, largest last."""
        w = self.dae.omega
        found = []
        for sigma in np.asarray(shifts, dtype=complex) / w:
            lu = spla.splu((self.A + sigma * self.B).tocsc())
            op = spla.LinearOperator(self.A.shape, matvec=lambda x, lu=lu: lu.solve(self.B @ x), dtype=complex)
            mu = spla.eigs(op, k=min(k, self.A.shape[0] - 2), which="LM", return_eigenvectors=False, tol=1e-10)
            found.extend(sigma - 1.0 / mu)
        lam = np.array(found) * w
        lam = np.unique(np.round(lam[np.isfinite(lam)], 9))
        return lam[np.argsort(lam.real)]


def _solve(K, f) -> np.ndarray:
    """``K q = f`` for the shaft on its supports; a rotor with a free rigid-body motion the bearings do not hold
    (e.g. tilts of a rotor with one bearing) gets the least-squares displacement."""
    try:
        return np.linalg.solve(K, f)
    except np.linalg.LinAlgError:
        return np.linalg.lstsq(K, f, rcond=None)[0]


def _diagonal_positions(pattern, rows) -> np.ndarray:
    """CSC positions of the diagonal entries (r, r) of ``pattern`` for ``rows``."""
    pos = np.empty(len(rows), dtype=np.int64)
    for k, r in enumerate(rows):
        s, e = pattern.indptr[r], pattern.indptr[r + 1]
        pos[k] = s + int(np.flatnonzero(pattern.indices[s:e] == r)[0])
    return pos


def _speed_law(speed_rpm, speed_profile) -> SpeedProfile | None:
    """The run's speed law: ``speed_profile`` as a :class:`SpeedProfile`, or None for a ``speed_rpm`` (exactly one
    of the two given)."""
    if (speed_rpm is None) == (speed_profile is None):
        raise ValueError(f"speed_rpm = {short_repr(speed_rpm)}, speed_profile = {short_repr(speed_profile)}; allowed: "
                         "one of them (a speed [rpm] or a function of t [s]; or a SpeedProfile, a table ((t [s], "
                         "n [rpm]), ...) or a function n(t))")
    return None if speed_profile is None else SpeedProfile(speed_profile)


def _speed_schedule(speed_rpm, t0, revolutions):
    """``(speed(t) [rpm], t_end [s], largest speed [rpm])`` of a constant speed or a speed function over the
    run: a function's run ends when the shaft has turned ``revolutions`` times since ``t0`` (:func:`_run_end`)."""
    if not callable(speed_rpm):
        n = check_speed(speed_rpm)
        return (lambda t: n), t0 + revolutions * 60.0 / n, n

    def fn(t):
        v = float(speed_rpm(t))
        if not np.isfinite(v) or v < 0 or v > SPEED_RANGE_RPM[1]:
            raise ValueError(f"speed_rpm(t = {t:.6g} s) = {v!r} [rpm]; allowed: [0, {SPEED_RANGE_RPM[1]:g}]")
        return v

    t_end = _run_end(fn, t0, revolutions)
    n_max = max(fn(t) for t in np.linspace(t0, t_end, 257))
    if n_max <= 0:
        raise ValueError("speed_rpm(t) is zero over the whole run; allowed: a shaft that turns")
    return fn, t_end, check_speed(n_max)


def _run_end(fn, t0, revolutions, max_steps=100_000) -> float:
    """The time [s] at which a shaft turning at ``fn(t)`` [rpm] from ``t0`` has turned ``revolutions`` times, found
    from below without evaluating ``fn`` after it (a run-up written for the run's own span may be undefined
    beyond). Each step turns at most the revolutions left at the fastest speed allowed, or half of them at twice the
    fastest speed seen, and at most doubles the time since ``t0``; it ends within 1e-12 of the revolutions."""
    left, t, n_seen = float(revolutions), float(t0), fn(t0)
    for _ in range(max_steps):
        if left <= 1e-12 * revolutions:
            return t
        if t - t0 > MAX_RUN_SECONDS:
            break
        dt = max(60.0 * left / SPEED_RANGE_RPM[1], min(30.0 * left / max(n_seen, 1e-300), t - t0))
        peak = [0.0]

        def seen(x):
            v = fn(x)
            peak[0] = max(peak[0], v)
            return v

        turned = quad(seen, t, t + dt, limit=200)[0] / 60.0
        if turned > left:  # the speed rose faster than the step allowed for: back to the end inside the step
            return brentq(lambda T: quad(fn, t, T, limit=200)[0] / 60.0 - left, t, t + dt, xtol=1e-12 * max(t, 1.0))
        t, left, n_seen = t + dt, left - turned, max(n_seen, peak[0], fn(t + dt))
    raise ValueError(f"speed_rpm(t): the shaft does not turn {revolutions:g} times in {t - t0:.3g} s (it turned "
                     f"{revolutions - left:.6g} times); allowed: a speed that turns the shaft")


def _speed_key(fn, t0, t_end) -> str:
    """A digest of a speed schedule (its values at 65 times of the run), to key a checkpoint."""
    v = np.array([fn(t) for t in np.linspace(t0, t_end, 65)])
    return hashlib.sha256(json.dumps([t0, t_end, *v.tolist()]).encode()).hexdigest()[:16]
