"""The line contact with default arguments: the film of the continuous problem over the Moes chart (against Moes'
formula) and in the rigid-isoviscous limit (against Martin's exact solution), and the warnings of explicit
grids and domains that cannot give it."""

import math
import warnings

import pytest

from transient.models.roller import LineContact
from transient.models.roller.line_contact import FilmResolutionWarning, StarvedInletWarning
from transient.models.roller.line_grid import default_domain, hydrodynamic_length
from transient.physics.line_formulas import moes_central

R, E, ETA, U = 0.01, 220e9, 0.02, 1e-11


def chart_contact(M, L, **kw):
    """Barus, incompressible: the lubricant of Moes' formula."""
    W, G = M * math.sqrt(2 * U), L / (2 * U) ** 0.25
    return LineContact(R, W * E * R, U * E * R / ETA, ETA, G / E, E, density="incompressible", **kw)


@pytest.mark.parametrize("M,L", [(100.0, 0.0), (300.0, 5.0), (1000.0, 10.0), (3.0, 10.0)])
def test_default_film_is_moes_over_the_chart(M, L):
    """Moes' fit is within 6 % of the flooded, grid-settled films for 3 <= M <= 1000 except M = 10, L >= 20
    (+6.2, +6.9 %; docs/validation.md); the default contact converges to them, with no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = chart_contact(M, L).steady()
    H = s.h_central / (R * math.sqrt(2 * U))
    assert s.success and H == pytest.approx(moes_central(M, L), rel=0.06)


def test_rigid_isoviscous_default_is_martin():
    """M = 0.04: the Hertz half-width is a small fraction of the inlet wedge sqrt(2 R h), which the default domain
    contains; h_min = 4.895 eta u R / w' within the inlet's (0.3 %) and the grid's (0.2 %) error."""
    w, u, eta = 2e3, 10.0, 0.05
    h_martin = 4.895 * eta * u * R / w
    for elastic in (False, True):
        c = LineContact(R, w, u, eta, 0.0, E, density="incompressible", viscosity_law="isoviscous", elastic=elastic)
        assert c.M < 0.05
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            s = c.steady()
        assert s.h_min == pytest.approx(h_martin, rel=0.01), elastic


def test_an_inlet_cut_off_by_an_explicit_domain_warns():
    """The paper's domain (-5 ... 2.5 b) at M = 0.04 lies inside the inlet wedge: the film is starved (a
    fraction of Martin's) and the warning says so."""
    c = LineContact(R, 2e3, 10.0, 0.05, 0.0, E, density="incompressible", viscosity_law="isoviscous",
                    elastic=False, domain=(-5.0, 2.5), grid=401)
    with pytest.warns(StarvedInletWarning, match="starved inlet"):
        s = c.steady()
    assert s.h_min < 0.5 * 4.895 * 0.05 * 10.0 * R / 2e3 and "starved inlet" in s.message


def test_an_explicit_coarse_grid_still_warns():
    c = chart_contact(100.0, 0.0, grid=401)
    with pytest.warns(FilmResolutionWarning, match="under-resolved"):
        c.steady()


def test_default_domain_is_the_papers_where_elastic_and_follows_the_inlet_wedge_where_rigid():
    assert default_domain(100.0, 5.0) == (-5.0, 2.5)
    lo, hi = default_domain(0.01, 0.0)
    s = hydrodynamic_length(0.01, 0.0)
    assert s == pytest.approx(math.sqrt(math.pi * 3.0 / 4.0) / 0.01, rel=0.01)  # 3/M: the rigid branch
    assert lo == pytest.approx(-26.0 * s) and hi == pytest.approx(3.0 * s)
