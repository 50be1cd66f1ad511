"""Bad input to the rotor and to the rotor on bearings is refused when the object is built, in one line naming the
parameter, its value and the allowed range, before any equilibrium is solved (each case was an unnamed error or
silently accepted)."""

import warnings

import pytest

from transient.models.journal import JournalBearing
from transient.models.rotor import Rotor, RotorBearingSystem


def one_line(excinfo):
    assert "\n" not in str(excinfo.value).strip()
    return str(excinfo.value)


# --------------------------------------------------------------------------------------------------
# the rotor and the rotor on bearings
# --------------------------------------------------------------------------------------------------

def rigid():
    return Rotor.rigid(20.0, 0.5, 0.3)


@pytest.mark.parametrize("key, value, match", [
    ("nodes", 5, r"nodes = 5; allowed: a list of integer node labels"),
    ("dofs", 5, r"dofs = 5; allowed: \('x', 'y'\) or \('x', 'y', 'tx', 'ty'\)"),
    ("gravity_load", 5, r"gravity_load has shape \(\); allowed: a finite \(2, 4\) matrix"),
    ("basis", {}, r"basis = \{\} \(dict\); allowed: a finite \(n_full, 4\) matrix"),
])
def test_rotor_arguments_of_the_wrong_shape_are_named(key, value, match):
    r = rigid()
    with pytest.raises(ValueError, match=match) as e:
        Rotor(**dict(mass=r.mass, stiffness=r.stiffness, nodes=[0, 1]) | {key: value})
    one_line(e)


def bearing(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return JournalBearing(**dict(dict(diameter=0.08, length=0.04, clearance=8e-5, viscosity=0.03, grid=(24, 4)),
                                     **kw))


@pytest.mark.parametrize("kw, match", [
    (dict(unbalance=5), r"unbalance = 5; allowed: a list of \(node, m e \[kg m\], phase \[deg\]\)"),
    (dict(rotor=5), r"rotor = 5 \(int\); allowed: a transient Rotor"),
])
def test_system_arguments_of_the_wrong_kind_are_named(kw, match):
    b = bearing()
    with pytest.raises(ValueError, match=match) as e:
        RotorBearingSystem(**dict(dict(rotor=rigid(), bearings={0: b, 1: b}), **kw))
    one_line(e)


def test_implausible_unbalance_is_refused_with_its_range():
    """20 kg m on the 146 kg example rotor puts its mass centre 0.14 m off the axis of bearings with a 80 um
    clearance; allowed: up to 10 x mass x clearance (0.117 kg m), which the 1e-4 kg m of the whirl scenario is far
    below."""
    b = bearing()
    rotor = Rotor.example()
    with pytest.raises(ValueError, match=r"unbalance: sum of m e = 20 \[kg m\] is out of range; allowed: \[0, 0\.117\] "
                                         r"kg m \(10 x rotor mass 146 kg x smallest clearance 8e-05 m") as e:
        RotorBearingSystem(rotor, {n: b for n in rotor.bearing_nodes}, unbalance=[(6, 20.0, 0.0)])
    one_line(e)
    RotorBearingSystem(rotor, {n: b for n in rotor.bearing_nodes}, unbalance=[(6, 0.1, 0.0)])  # inside the range
