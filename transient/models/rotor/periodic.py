"""The periodic unbalance response of a rotor on journal bearings by shooting: a fixed point of the
once-per-revolution map of the whole system (films and rotor), by Newton-Picard
(:func:`transient.solvers.shooting.newton_picard`: Lust, Roose, Spence & Champneys 1998) on the subspace of the
least damped modes of the linearisation with the film states, with the Floquet multipliers of that subspace.

The map starts every period at shaft angle 0 (``tau = 0``, the unbalance forcing's phase); its unknowns are the
free film cells and the rotor's coordinates and velocities (the groove cells are held, the angle is the time).
The fixed-point tolerance is on the rotor's coordinates and velocities, in units of the smallest clearance.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla

from transient.models.rotor.model import SystemDAE
from transient.models.rotor.results import PeriodicResponse
from transient.solvers.integrate import Problem, solve
from transient.solvers.shooting import ShootingSettings, newton_picard


class PeriodMap:
    """``flow(z, t0, T, rtol)``: the reduced state ``z`` (free cells, q~, v) after ``T`` of the time tau at
    constant speed, keeping the outputs of the last flow of each state (``samples``)."""

    def __init__(self, dae: SystemDAE, outputs_per_revolution: int, atol: float):
        self.dae = dae
        keep = np.ones(dae.n, dtype=bool)
        for b in dae.blocks:
            keep[b.offset:b.offset + b.n] = b.film.op.free
        keep[dae.P0] = False
        self.keep = keep
        self.fixed = np.zeros(dae.n)
        for b in dae.blocks:
            self.fixed[b.offset:b.offset + b.n] = b.film.op.u_fixed
        self.opr = outputs_per_revolution
        self.atol = dae.absolute_tolerance(atol)
        self.last = None
        self.rotor = slice(int(np.count_nonzero(keep[:dae.Q0])), int(np.count_nonzero(keep)))

    def embed(self, z) -> np.ndarray:
        y = self.fixed.copy()
        y[self.dae.P0] = 0.0
        y[self.keep] = z
        return y

    def reduce(self, y) -> np.ndarray:
        return np.asarray(y)[self.keep] if np.ndim(y) == 1 else np.asarray(y)[self.keep, :]

    def __call__(self, z, t0, T, rtol):
        dae = self.dae
        y = self.embed(z)
        p = Problem(y0=y, yp0=dae.consistent_yp(t0, y), residual=dae.residual, jac_pattern=dae.pattern,
                    jac_residual=dae.jacobian, name="rotor period map")
        s = solve(p, np.linspace(t0, t0 + T, self.opr + 1), method="ida", rtol=rtol, atol=self.atol)
        if not s.success:
            return np.full(z.size, np.nan)
        self.last = s
        return s.y[-1][self.keep]

    def norm(self, d) -> float:
        """The rotor's coordinates and velocities, in the smallest clearance (per radian)."""
        return float(np.max(np.abs(d[self.rotor])))


def dominant_basis(lin, shifts, modes) -> np.ndarray:
    """(n, 2 modes) real basis of the ``modes`` least damped eigenvectors of the linearisation ``lin``
    (:class:`~transient.models.rotor.system.Linearisation`) nearest the ``shifts`` [1/s]."""
    w = lin.dae.omega
    cols = []
    for sigma in np.asarray(shifts, dtype=complex)[:modes] / w:
        lu = spla.splu((lin.A + sigma * lin.B).tocsc())
        op = spla.LinearOperator(lin.A.shape, matvec=lambda x, lu=lu: lu.solve(lin.B @ x), dtype=complex)
        mu, vec = spla.eigs(op, k=1, which="LM", tol=1e-10)
        cols += [vec[:, 0].real, vec[:, 0].imag]
    return np.column_stack(cols)


def periodic_response(system, speed_rpm, rtol=1e-6, tol=None, modes=2, outputs_per_revolution=64, max_iter=25):
    """The settled orbit of ``system`` at ``speed_rpm`` (module docstring) as a
    :class:`~transient.models.rotor.results.PeriodicResponse`."""
    eq = system.equilibrium(speed_rpm)
    lin = system.linearisation(speed_rpm, eq)
    dae = system.dae(speed_rpm)
    F = PeriodMap(dae, outputs_per_revolution, atol=1e-3 * rtol)
    qs = system.quasi_static_eigenvalues(speed_rpm, eq)
    qs = qs[np.imag(qs) > 0]
    V = dominant_basis(lin, qs[np.argsort(-qs.real)], modes)
    y0 = eq.state + lin.forced_response().real
    tol = rtol if tol is None else tol
    sh = newton_picard(F, F.reduce(y0), 2 * np.pi, V, norm=F.norm,
                       settings=ShootingSettings(tol=tol, rtol=rtol, rtol_max=max(rtol, 1e-4), max_iter=max_iter, relax=1))
    F(sh.state, 0.0, 2 * np.pi, rtol)  # the orbit of the accepted state, at the final tolerance
    s = F.last
    q = s.y[:, dae.Q0:dae.V0] * dae.L
    return PeriodicResponse(t=s.t / dae.omega, displacement=system._node_displacements(q),
                            multipliers=np.asarray(sh.multipliers), error_estimate=float(sh.error_estimate),
                            periods=int(sh.periods), nodes=list(system.rotor.nodes), speed_rpm=float(speed_rpm),
                            state=F.embed(sh.state), success=bool(sh.success), message=sh.message or "converged")
