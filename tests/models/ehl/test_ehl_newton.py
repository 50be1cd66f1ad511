"""The EHL engine's FBNS Newton (``models/ehl/newton.py``) on a toy complementarity problem whose solution is
known, its pluggable linear solver, and the flag on steps taken with a Krylov solve short of its tolerance."""

import numpy as np
import pytest

from transient.models.ehl.errors import InexactStepWarning
from transient.models.ehl.newton import fbns_newton, warn_inexact
from transient.models.point import PointContact
from transient.models.point.fbns import fbns
from transient.models.ehl.krylov import KrylovSolver, TwoLevel

K = 2.0  # the toy's content coupling


class ToyRows:
    """Per node ``R = p - g - K (1 - theta) = 0``, ``FB(p, 1 - theta) = 0``, and ``h0 = 1``: the solution is
    ``p = max(g, 0)``, ``theta = 1 - max(-g, 0)/K`` (pressurised where ``g > 0``, cavitated elsewhere)."""

    def __init__(self, g):
        self.g, self.n = np.asarray(g, float), len(g)

    def equations(self, u):
        n = self.n
        p, t = u[:n], u[n: 2 * n]
        b = 1.0 - t
        rad = np.sqrt(p * p + b * b)
        return dict(res=p - self.g - K * b, scale=np.ones(n), fb=p + b - rad, rad=rad, load=u[-1] - 1.0,
                    H=np.ones(n))

    def fb_derivatives(self, u, e):
        p, b, rad = u[: self.n], 1.0 - u[self.n: 2 * self.n], e["rad"]
        safe = np.where(rad > 0, rad, 1.0)
        return np.where(rad > 0, 1.0 - p / safe, 0.0), -np.where(rad > 0, 1.0 - b / safe, 1.0)


class DiagonalSolve:
    """The toy's reduced system (diagonal); ``miss``: report every solve as a Krylov solve short of its tolerance."""

    def __init__(self, miss=False):
        self.miss, self.calls = miss, 0

    def solve(self, rows, u, e, elimination, stats):
        a_p, b_p, a_th, b_t = elimination
        self.calls += 1
        stats.krylov_misses += self.miss
        z = (-e["res"] - a_p - K * a_th) / (b_p + K * b_t)
        return np.append(z, -e["load"])


@pytest.mark.parametrize("armijo", ["start", "trial"])
def test_toy_complementarity_converges_to_its_known_solution(armijo):
    g = np.linspace(-1.0, 1.5, 11)
    rows = ToyRows(g)
    u0 = np.concatenate([np.full(11, 0.3), np.ones(11), [0.0]])
    solver = DiagonalSolve()
    u, ok, stats = fbns_newton(rows, u0, solver, tol=1e-12, max_iter=30, armijo=armijo)
    assert ok and stats.norms[-1] < 1e-12 and stats.iterations == solver.calls <= 10
    assert np.allclose(u[:11], np.maximum(g, 0.0), atol=1e-12)
    assert np.allclose(u[11:22], 1.0 - np.maximum(-g, 0.0) / K, atol=1e-12)
    assert u[-1] == pytest.approx(1.0, abs=1e-12)


def test_a_start_that_meets_the_tolerance_takes_no_step_and_bad_armijo_is_refused():
    g = np.array([1.0, -1.0])
    rows = ToyRows(g)
    exact = np.array([1.0, 0.0, 1.0, 0.5, 1.0])
    solver = DiagonalSolve()
    u, ok, stats = fbns_newton(rows, exact, solver, tol=1e-12, max_iter=5)
    assert ok and stats.iterations == 0 and solver.calls == 0
    with pytest.raises(ValueError, match="armijo"):
        fbns_newton(rows, exact, solver, tol=1e-12, max_iter=5, armijo="middle")


def test_steps_short_of_the_krylov_tolerance_are_counted_and_warned():
    rows = ToyRows(np.linspace(-1.0, 1.0, 5))
    u0 = np.concatenate([np.full(5, 0.3), np.ones(5), [0.0]])
    _, ok, stats = fbns_newton(rows, u0, DiagonalSolve(miss=True), tol=1e-12, max_iter=30)
    assert ok and stats.krylov_misses == stats.iterations > 0
    with pytest.warns(InexactStepWarning, match=f"{stats.iterations} of {stats.iterations} Newton steps"):
        warn_inexact(stats, ok)


def test_point_newton_krylov_flags_gmres_short_of_its_tolerance(monkeypatch):
    """The point film's Newton-Krylov steps go through the same flag as the line's and the roller's."""
    pc = PointContact(0.01, grid=(33, 33), load=20.0, speed=0.2, viscosity=0.04, pressure_viscosity=2e-8,
                      modulus=2.2e11)
    f = pc.film_problem()
    monkeypatch.setattr(TwoLevel, "solve", lambda self, b: 1e-3 * b)  # a useless preconditioner
    solver = KrylovSolver(f, max_iter=3)
    with pytest.warns(InexactStepWarning, match="1 of 1 Newton steps were taken with GMRES short of its tolerance"):
        fbns(f, pc.hertz_start(f), 1e-8, 1, solver=solver)
    assert solver.stats["failures"] == 1
