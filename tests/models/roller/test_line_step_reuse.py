"""The film-content step solve's reuse across steps (``LineFilmStep(reuse=...)``): simplified Newton's first
correction is the Newton step of the Schur system, and every reuse gives the same transient."""


import numpy as np
import pytest
import scipy.linalg as sla

from transient.models.roller import LineContact
from transient.models.roller.line_fbns import LineContentFilm, schur_system
from transient.models.roller.line_step import FrozenSchur, LineFilmStep, StepRows, consistent_content
from transient.solvers.integrate import Problem, Steps
from transient.solvers.integrate import solve as integrate

R, E, W = 0.01, 220e9, 3.1e4
pytestmark = pytest.mark.filterwarnings("ignore::transient.models.roller.line_contact.StarvedInletWarning")


@pytest.fixture(scope="module")
def contact():
    return LineContact(R, W, 1.0, 0.022, 2500 / E, E, grid=101, domain=(-5.0, 2.5))


def dry_state(contact):
    content = LineContentFilm(contact.film_problem())
    xi = contact.grid.x[1:-1]
    p = np.sqrt(np.clip(1.0 - xi * xi, 0.0, None))
    return content, consistent_content(content, p, 0.05)


def test_a_fresh_frozen_matrix_gives_the_newton_step(contact):
    content, u = dry_state(contact)
    q = content.storage_terms()[1] * u[content.n: 2 * content.n]
    rows = StepRows(content, contact.lam, 50.0, 0.9 * q, 1.0)
    e = rows.equations(u)
    S, r, (a_p, b_p, a_th, b_t) = schur_system(rows, u, e)
    z = sla.solve(S, r)
    n = content.n
    newton = np.concatenate([a_p + b_p * z[:n], a_th + b_t * z[:n], z[n:]])
    du = FrozenSchur(rows, u, rows.equations(u), 50.0).step(rows, rows.equations(u))
    assert np.max(np.abs(du - newton)) < 1e-9 * np.max(np.abs(newton))
    assert np.max(np.abs(newton)) > 1e-3  # a real step


@pytest.mark.slow
def test_every_reuse_gives_the_same_transient(contact):
    content, u0 = dry_state(contact)
    ends = {}
    for reuse in ("none", "preconditioner", "simplified"):
        step = LineFilmStep(content, contact.lam, u0, lambda tau: 1.0, reuse=reuse)
        sol = integrate(Problem(y0=u0, step_solve=step), np.linspace(0.0, 3.0, 4), method="bdf2", rtol=1e-5,
                        atol=1e-7, steps=Steps(first_step=1e-3, max_steps=5000), store=False)
        assert sol.success
        ends[reuse] = (step.last[1], step)
    assert ends["simplified"][1].simplified > 0  # simplified Newton was used
    ref = ends["none"][0]
    for reuse in ("preconditioner", "simplified"):
        assert np.max(np.abs(ends[reuse][0] - ref)) < 1e-4 * np.max(np.abs(ref))
    with pytest.raises(ValueError, match="reuse"):
        LineFilmStep(content, contact.lam, u0, lambda tau: 1.0, reuse="always")
