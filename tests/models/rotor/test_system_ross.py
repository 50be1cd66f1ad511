"""A ROSS rotor on this package's films (skipped without ROSS): the reduced rotor's equilibrium and linear
response against the full one's."""

import warnings

import pytest

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    rs = pytest.importorskip("ross")

from transient import JournalBearing, Rotor, RotorBearingSystem
from transient.params.rho_kim import BEARING


def ross_rotor():
    """A 1.2 m steel shaft of 80 mm (6 Timoshenko elements) with a 400 mm disk at mid-span, on ROSS bearings at
    its ends (their coefficients are not imported)."""
    steel = rs.materials.steel
    shaft = [rs.ShaftElement(L=0.2, idl=0.0, odl=0.08, material=steel, shear_effects=True, rotary_inertia=True,
                             gyroscopic=True) for _ in range(6)]
    disk = rs.DiskElement.from_geometry(n=3, material=steel, width=0.1, i_d=0.08, o_d=0.4)
    return rs.Rotor(shaft, [disk], [rs.BearingElement(n=n, kxx=1e8, cxx=1e3) for n in (0, 6)])


@pytest.mark.slow
def test_ross_rotor_full_and_reduced_on_films():
    r = ross_rotor()
    full = Rotor.from_ross(r)
    reduced = Rotor.from_ross(r, modes=4)
    assert full.bearing_nodes == (0, 6) and reduced.n == 4 + 4 < full.n
    assert reduced.total_mass == pytest.approx(full.total_mass, rel=1e-9)
    b = JournalBearing(**BEARING, grid=(32, 6))
    systems = [RotorBearingSystem(rot, {0: b, 6: b}, unbalance=[(3, 1e-4, 0.0)]) for rot in (full, reduced)]
    eqs = [s.equilibrium(3000) for s in systems]
    assert eqs[1].bearing_load == pytest.approx(eqs[0].bearing_load, rel=1e-9)  # statics kept exactly
    lins = [s.unbalance_response(3000) for s in systems]
    X = [abs(lin.position(3)[0]) for lin in lins]
    assert X[1] == pytest.approx(X[0], rel=1e-3)
