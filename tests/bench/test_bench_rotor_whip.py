"""The whip scenario's system as the rotor-whip bench builds it: the 4-mode shaft keeps the bearing nodes' x, y, the
nodal shaft's mass and its bearing loads (the bench itself is run by ``transient bench rotor-whip``)."""

import numpy as np
import pytest

from transient.bench.rotor_whip import MODES, whip_system


def test_whip_system_reduced_and_nodal():
    red, bnode, disk = whip_system((16, 4), MODES)
    full, _, _ = whip_system((16, 4), None)
    assert (bnode, disk) == (0, 6) and red.bearing_nodes == full.bearing_nodes == [0, 12]
    assert full.rotor.n == 52 and red.rotor.n == 4 + MODES
    assert np.array_equal(red.rotor.translation(12), np.eye(red.rotor.n)[2:4])
    assert red.rotor.total_mass == pytest.approx(full.rotor.total_mass, rel=1e-12)
    assert np.allclose(red.rotor.damping, red.rotor.basis.T @ full.rotor.damping @ red.rotor.basis)
    loads = [np.array([s.static_loads()[n] for n in (0, 12)]) for s in (red, full)]
    # two supports: the reactions are the whole shaft's statics, which the reduction keeps (its rigid-body modes)
    assert loads[0] == pytest.approx(loads[1], rel=1e-9, abs=1e-9 * np.abs(loads[1]).max())
