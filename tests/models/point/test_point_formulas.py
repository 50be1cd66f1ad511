"""Film formulas of the point contact: the Nijenbanning-Venner-Moes central film (its four asymptotes in
the chart's corners, SI form), and the numerical films against it and against Hamrock-Dowson."""

import math

import pytest

from transient.models.point import PointContact
from transient.models.point.formulas import nvm_asymptotes, nvm_central, nvm_central_film


@pytest.mark.parametrize("M, L, regime", [(0.01, 0.0, "RI"), (1e7, 0.0, "EI"), (10.0, 1e4, "RP"), (1e9, 1e3, "EP")])
@pytest.mark.parametrize("D", [1.0, 0.25])
def test_nvm_tends_to_its_asymptote_in_each_corner(M, L, regime, D):
    assert nvm_central(M, L, D) / nvm_asymptotes(M, L, D)[regime] == pytest.approx(1.0, abs=0.01)


def test_nvm_in_si_uses_moes_groups():
    w, u, eta, alpha, E, R = 20.0, 0.2, 0.04, 2e-8, 2.2e11, 0.01
    pc = PointContact(R, load=w, speed=u, viscosity=eta, pressure_viscosity=alpha, modulus=E, grid=(33, 33))
    M, L = pc.moes
    two_u = 2.0 * eta * u / (E * R)
    assert nvm_central_film(w, u, eta, alpha, E, R) == pytest.approx(nvm_central(M, L) * R * math.sqrt(two_u),
                                                                     rel=1e-12)
