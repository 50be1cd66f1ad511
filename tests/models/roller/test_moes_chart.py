"""The EHL line contact over the Moes chart: continuation from the easy corner, Martin's rigid limit with a
stiff elastic body, Moes' formula and its asymptotes, the named failure on a grid too coarse for the load."""

import math

import numpy as np
import pytest

from transient.models.roller import LineContact
from transient.models.roller.continuation import follow
from transient.models.roller.results import EHLConvergenceError
from transient.physics.line_formulas import (dowson_toyoda_central, moes_asymptotes, moes_central,
                                             moes_groups)
from transient.solvers.newton import NewtonError, NewtonResult
from transient.study.ehl_chart import chart_contact, chart_point
from transient.verification.ehl_reference import martin_film


def test_moes_groups_and_formula_limits():
    U, G, W = 1e-11, 5000.0, 1e-4
    M, L = moes_groups(U, G, W)
    assert M == pytest.approx(W / math.sqrt(2 * U)) and L == pytest.approx(G * (2 * U) ** 0.25)
    # the elastic-piezoviscous asymptote in these groups is Dowson-Toyoda's central film (independent fit)
    assert moes_asymptotes(M, L)["EP"] * math.sqrt(2 * U) == pytest.approx(dowson_toyoda_central(U, G, W), rel=2e-3)
    # far corners: the formula tends to its asymptotes
    assert moes_central(1e5, 0.0) == pytest.approx(moes_asymptotes(1e5, 0.0)["EI"], rel=1e-3)
    assert moes_central(1e-3, 0.0) == pytest.approx(moes_asymptotes(1e-3, 0.0)["RI"], rel=1e-3)
    assert moes_central(1e6, 25.0) == pytest.approx(moes_asymptotes(1e6, 25.0)["EP"], rel=0.02)


def test_continuation_rejects_a_branch_jump_and_halves_the_step():
    calls = []

    def solve(s, u0):
        calls.append(s)
        if s > 0.5 and len(calls) == 2:  # the first long step "converges" to a film ten times thinner
            return NewtonResult(x=np.array([0.1]), iterations=3, residual_norm=0.0, success=True, message="")
        return NewtonResult(x=np.array([1.0 + s]), iterations=3, residual_norm=0.0, success=True, message="")

    path = follow(solve, lambda s0, u, s1: u, lambda s, u: float(u[0]), np.array([1.0]), first_step=0.6)
    assert path.success and path.rejected == 1 and path.state[0] == pytest.approx(2.0)
    assert calls[1] == pytest.approx(0.3)  # the rejected step 0.6 was halved


def test_continuation_stops_with_the_newton_history_when_no_step_converges():
    def solve(s, u0):
        raise NewtonError("no", NewtonResult(x=u0, iterations=2, residual_norm=1.0, success=False, message="",
                                             residual_norms=[3.0, 2.0, 1.0]))

    path = follow(solve, lambda s0, u, s1: u, lambda s, u: 1.0, np.array([1.0]))
    assert not path.success and path.s == 0.0 and path.residual_norms == [3.0, 2.0, 1.0]
    assert "stopped at s = 0.0000" in path.message


def _stiff(n, E=1e16, elastic=True):
    R, w, u, eta = 0.01, 2e4, 1.0, 0.05
    probe = LineContact(R, w, u, eta, 0.0, E, density="incompressible", viscosity_law="isoviscous")
    a = math.sqrt(2 * R * 4.9 * eta * u * R / w) / probe.b  # sqrt(2 R h_Martin) in units of b
    c = LineContact(R, w, u, eta, 0.0, E, density="incompressible", viscosity_law="isoviscous", grid=n,
                    domain=(-20 * a, 10 * a), elastic=elastic)
    return c, martin_film(w, R, eta, u, inlet=-20 * a * c.b)


def test_stiff_elastic_body_tends_to_martin_with_second_order_convergence():
    err = []
    for n in (401, 801):
        c, h_martin = _stiff(n)
        assert c.M < 0.01
        s = c.steady()
        err.append(s.h_min / h_martin - 1.0)
    assert abs(err[1]) < 1e-3 and 3.0 < err[0] / err[1] < 5.5, err


@pytest.mark.parametrize("M,L", [(100.0, 20.0), pytest.param(1000.0, 0.0, marks=pytest.mark.slow),
                                 pytest.param(1000.0, 25.0, marks=pytest.mark.slow),
                                 pytest.param(1.0, 25.0, marks=pytest.mark.slow)])
def test_chart_corner_converges_from_a_cold_start(M, L):
    r = chart_point(M, L, nodes=513 if M < 1000 else 1025)
    assert r["success"], r["message"]
    assert r["residual"] <= 1e-9 and r["H_min"] > 0


def test_grid_too_coarse_for_the_load_raises_with_the_residual_history():
    c = chart_contact(1000.0, 10.0, nodes=129, grid="uniform")
    with pytest.raises(EHLConvergenceError) as e:
        c.steady()
    assert "exceeds 4/M" in str(e.value) and "did not converge" in str(e.value)
    r = e.value.result
    assert r.success is False and len(r.residual_norms) >= 2


def test_line_steady_exports_its_fields_as_a_node_table():
    s = chart_contact(10.0, 2.0, nodes=129).steady()
    df = s.to_dataframe()
    assert len(df) == s.x.size and df.attrs["units"] == {"x": "m", "pressure": "Pa", "film": "m"}
    assert np.array_equal(df["film"].to_numpy(), s.film)


def test_a_film_that_closes_on_a_too_coarse_grid_is_a_named_failure_not_a_result():
    """At M ~ 30 on 61 nodes over the paper's domain the continuation converges the equations to a film with h_min < 0: refused, named."""
    c = LineContact(radius=0.01, load_per_length=1e5, speed=0.0625, viscosity=0.04, pressure_viscosity=2e-8,
                    modulus=2.2e11, grid=61, domain=(-5.0, 2.5))
    with pytest.raises(EHLConvergenceError, match=r"h_min = .* m <= 0.*too coarse"):
        c.steady()
    s = c.steady(raise_on_failure=False)
    assert not s.success and s.h_min <= 0


def test_moes_formula_tends_to_its_isoviscous_branch_as_L_vanishes():
    """No overflow for a vanishing pressure-viscosity group: the piezoviscous part tends to zero."""
    assert moes_central(30.0, 1e-290) == pytest.approx(moes_central(30.0, 0.0), rel=1e-12)


def test_load_path_stopped_by_the_grid_names_the_resolution_and_keeps_the_history():
    """513 uniform nodes cannot carry M = 1000 (the inlet edge needs M dx <~ 4): a named error whose message
    says how far the grid resolves, with the residual history of the last attempt."""
    c = chart_contact(1000.0, 0.0, nodes=513, grid="uniform")
    with pytest.raises(EHLConvergenceError, match=r"resolves the inlet and the contact up to M ~") as e:
        c.steady()
    r = e.value.result
    assert r.success is False and len(r.residual_norms) >= 2 and np.all(np.isfinite(r.residual_norms))
