"""ROSS's ``SqueezeFilmDamper`` formulas (petrobras/ross, ``ross/bearings/squeeze_film_damper.py``, read at commits
383df835 and 02356c97: the same formulas) transcribed, against the short-damper closed forms of
:mod:`transient.models.damper.closed_forms` (ROSS is not a dependency; docs/disagreements.md records where they part).

ROSS gives a damping ``co`` [N s/m] and a stiffness ``ko`` [N/m] per geometry; ours give forces, ``C = -F_t / (e w)``
and ``K = -F_r / e``. ``geometry="groove"``: a central groove, open ends (two lands of L/2 each);
``"groove-end_seals"``: the same lands sealed at the ends."""

import numpy as np
import pytest

from transient.models.damper.closed_forms import land_forces

MU, R, L, C, W = 0.02, 0.065, 0.023, 76e-6, 2000.0


def ross_groove(eps, cavitation):
    if cavitation:
        co = MU * L ** 3 * R / (2 * C ** 3) * np.pi / (1 - eps ** 2) ** 1.5 / 4
        ko = 2 * MU * W * R * (L / C) ** 3 * eps / (1 - eps ** 2) ** 2 / 4
        return co, ko
    return MU * (L / C) ** 3 * R * np.pi / (1 - eps ** 2) ** 1.5, 0.0


def ross_groove_end_seals(eps, cavitation):
    if cavitation:
        co = MU * L ** 3 * R / (2 * C ** 3) * np.pi / (1 - eps ** 2) ** 1.5
        ko = 2 * MU * W * R * (L / C) ** 3 * eps / (1 - eps ** 2) ** 2
        return co, ko
    return MU * (L / C) ** 3 * R * np.pi / (1 - eps ** 2) ** 1.5, 0.0


def ours(eps, lands, film):
    fr, ft = land_forces(lands, eps, W, MU, R, C, film)
    e = eps * C
    return -ft / (e * W), -fr / e


@pytest.mark.parametrize("eps", [0.1, 0.4, 0.7])
def test_ross_agrees_where_its_branches_are_the_short_damper_forms(eps):
    open_lands, sealed_lands = [(L / 2, False)] * 2, [(L / 2, True)] * 2
    assert ross_groove(eps, True) == pytest.approx(ours(eps, open_lands, "pi"), rel=1e-12)
    assert ross_groove_end_seals(eps, True) == pytest.approx(ours(eps, sealed_lands, "pi"), rel=1e-12)
    assert ross_groove_end_seals(eps, False) == pytest.approx(ours(eps, sealed_lands, "2pi"), rel=1e-12, abs=1e-9)


@pytest.mark.parametrize("eps", [0.1, 0.4, 0.7])
def test_ross_uncavitated_grooved_damper_is_four_times_the_lands_film(eps):
    """The recorded disagreement: without cavitation ROSS's grooved damper with open ends damps like an ungrooved
    damper of length L, four times the two lands of L/2 (and twice its own cavitated branch x 4 / 2)."""
    co, ko = ross_groove(eps, False)
    c_ours, k_ours = ours(eps, [(L / 2, False)] * 2, "2pi")
    assert co / c_ours == pytest.approx(4.0, rel=1e-12) and ko == k_ours == 0.0
