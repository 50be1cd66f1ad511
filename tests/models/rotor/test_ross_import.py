"""A ROSS rotor's matrices in this package's conventions, and the linear analysis of this package against ROSS's
own on the same rotor with bearings carrying this package's film coefficients (skipped without ROSS)."""

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    rs = pytest.importorskip("ross")

from transient.models.journal.bearing import JournalBearing
from transient.models.rotor import linear as lin
from transient.models.rotor.ross_import import matrices_from_ross
from transient.models.rotor.shaft import Disk, shaft_matrices
from transient.params.rho_kim import BEARING

ELEMENTS, LENGTH, DIAMETER = 6, 0.2, 0.08  # a 1.2 m steel shaft of 80 mm with a 400 mm disk at mid-span


@pytest.fixture(scope="module")
def film_coefficients():
    """K [N/m], C [N s/m] of Rho & Kim's bearing under 700 N at 4000 rpm (coarse grid: any K/C will do)."""
    return JournalBearing(**BEARING, grid=(61, 11)).coefficients(700.0, 4000.0)


def _ross_rotor(Kb=None, Cb=None):
    steel = rs.materials.steel
    shaft = [rs.ShaftElement(L=LENGTH, idl=0.0, odl=DIAMETER, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(ELEMENTS)]
    disk = rs.DiskElement.from_geometry(n=ELEMENTS // 2, material=steel, width=0.1, i_d=DIAMETER, o_d=0.4)
    bearings = [] if Kb is None else [
        rs.BearingElement(n=n, kxx=Kb[0, 0], kxy=Kb[0, 1], kyx=Kb[1, 0], kyy=Kb[1, 1], cxx=Cb[0, 0], cxy=Cb[0, 1],
                          cyx=Cb[1, 0], cyy=Cb[1, 1]) for n in (0, ELEMENTS)]
    return rs.Rotor(shaft, [disk], bearings)


def _bearings(Kb, Cb):
    return [(0, 1, Kb, Cb), (4 * ELEMENTS, 4 * ELEMENTS + 1, Kb, Cb)]


def test_ross_matrices_equal_this_packages_shaft_elements(film_coefficients):
    """Same Timoshenko elements, same frames: ROSS's matrices equal shaft_matrices' to round-off; the bearings
    are left out (the free rotor's stiffness carries a rigid translation without force)."""
    rotor = _ross_rotor(*film_coefficients)
    m = matrices_from_ross(rotor)
    steel = rs.materials.steel
    disk = rotor.disk_elements[0]
    mine = shaft_matrices(np.full(ELEMENTS, LENGTH), DIAMETER, density=steel.rho, young_modulus=steel.E,
                          poisson_ratio=steel.Poisson, disks=[Disk(ELEMENTS // 2, disk.m, disk.Ip, disk.Id)])
    assert m["dofs"] == ("x", "y", "tx", "ty") and m["nodes"] == list(range(ELEMENTS + 1))
    for key in ("mass", "stiffness", "gyroscopic"):
        assert np.abs(m[key] - mine[key]).max() <= 1e-12 * np.abs(mine[key]).max(), key
    assert not m["damping"].any()
    assert m["positions"] == pytest.approx(mine["positions"])
    ux = np.zeros(m["mass"].shape[0])
    ux[0::4] = 1.0
    assert np.abs(m["stiffness"] @ ux).max() <= 1e-9 * np.abs(m["stiffness"]).max()


def test_four_dof_node_layout_gives_the_same_matrices():
    """ROSS 1.x numbers (x, y, alpha, beta) per node: the same elements laid out that way import the same
    (ROSS 1.x does not install here, so its layout is rebuilt from the installed elements)."""
    rotor = _ross_rotor()

    def four_dof(element):
        six = element.dof_global_index
        names = [k for k in six if k.split("_")[0] in ("x", "y", "alpha", "beta")]
        local = [list(six).index(k) for k in names]
        order = {"x": 0, "y": 1, "alpha": 2, "beta": 3}
        index = {k: 4 * int(k.split("_")[1]) + order[k.split("_")[0]] for k in names}
        pick = np.ix_(local, local)
        return SimpleNamespace(dof_global_index=index, **{
            name: (lambda A=getattr(element, name)(), pick=pick: A[pick]) for name in ("M", "K", "C", "G")})

    old = SimpleNamespace(shaft_elements=[four_dof(e) for e in rotor.shaft_elements],
                          disk_elements=[four_dof(e) for e in rotor.disk_elements], nodes=rotor.nodes,
                          ndof=4 * len(rotor.nodes))
    a, b = matrices_from_ross(rotor), matrices_from_ross(old)
    for key in ("mass", "stiffness", "damping", "gyroscopic"):
        assert np.array_equal(a[key], b[key]), key


def test_unbalance_response_equals_ross(film_coefficients):
    """The disk unbalance response through the first critical speeds, this package's linear analysis on the
    imported matrices against ROSS's run_unbalance_response on the ROSS rotor with the same K/C (measured
    agreement 1e-12; the requirement is 1 %)."""
    Kb, Cb = film_coefficients
    rotor = _ross_rotor(Kb, Cb)
    m = matrices_from_ross(rotor)
    speeds = np.linspace(100.0, 1000.0, 10)  # rad/s
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ross = rotor.run_unbalance_response(ELEMENTS // 2, 1e-4, 0.0, frequency=speeds).forced_resp
    n = m["mass"].shape[0]
    ross_dofs = [6 * k + d for k in (0, ELEMENTS // 2, ELEMENTS) for d in (0, 1, 3, 4)]
    mine_dofs = [4 * k + d for k in (0, ELEMENTS // 2, ELEMENTS) for d in range(4)]
    for j, w in enumerate(speeds):
        F = lin.unbalance_forces(n, 4, [(ELEMENTS // 2, 1e-4, 0.0)], w)
        x = lin.unbalance_response(m["mass"], m["damping"], m["gyroscopic"], m["stiffness"], _bearings(Kb, Cb), F, w)
        ref = ross[ross_dofs, j]
        assert np.abs(x[mine_dofs] - ref).max() <= 1e-8 * np.abs(ref).max()


@pytest.mark.slow
def test_critical_speeds_equal_ross(film_coefficients):
    """ROSS's run_critical_speed (Newton on each mode's speed = frequency; rtol 1e-8) against critical_speeds'
    forward crossings, damped (Im lambda) and undamped (|lambda|). Measured: 260.519, 268.516, 309.503 rad/s
    damped; 260.613, 343.359, 424.668 undamped, equal to 1e-9."""
    Kb, Cb = film_coefficients
    rotor = _ross_rotor(Kb, Cb)
    m = matrices_from_ross(rotor)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ross = rotor.run_critical_speed(num_modes=8, rtol=1e-10)
    forward = np.asarray(ross.whirl_direction) == "Forward"
    args = (m["mass"], m["damping"], m["gyroscopic"], m["stiffness"], lambda w: _bearings(Kb, Cb), (10.0, 1500.0), 4)
    damped = lin.critical_speeds(*args, dofs=m["dofs"])
    undamped = lin.critical_speeds(*args, dofs=m["dofs"], frequency="undamped")
    assert damped == pytest.approx(np.sort(np.asarray(ross.wd())[forward]), rel=1e-6)
    assert undamped == pytest.approx(np.sort(np.asarray(ross.wn())[forward]), rel=1e-6)
    assert damped.size == 3


@pytest.mark.slow
def test_campbell_equals_ross_modal_analysis(film_coefficients):
    """The six lowest damped frequencies and log decrements at 0, 500 and 1000 rad/s against ROSS's run_modal
    (dense) on the same rotor and bearings (measured: equal to 3e-13); where ROSS calls a mode's whirl forward or
    backward (not "Mixed"), the whirl index has that sign."""
    Kb, Cb = film_coefficients
    rotor = _ross_rotor(Kb, Cb)
    m = matrices_from_ross(rotor)
    speeds = [0.0, 500.0, 1000.0]
    ours = lin.campbell(m["mass"], m["damping"], m["gyroscopic"], m["stiffness"], lambda w: _bearings(Kb, Cb), speeds,
                        6, dofs=m["dofs"])
    for i, w in enumerate(speeds):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            modal = rotor.run_modal(w, sparse=False)
        wd, log_dec, whirl = np.asarray(modal.wd), np.asarray(modal.log_dec), modal.whirl_direction()
        for f, delta, index in zip(ours.frequencies[i], ours.log_decrements[i], ours.whirl[i]):
            k = np.argmin(np.abs(wd - f))
            assert f == pytest.approx(wd[k], rel=1e-9) and delta == pytest.approx(log_dec[k], rel=1e-9)
            if whirl[k] in ("Forward", "Backward"):
                assert np.sign(index) == (1 if whirl[k] == "Forward" else -1)


def test_support_masses_and_bearings_are_left_out(film_coefficients):
    """A bearing linked to a support point mass (ROSS's extra dofs after the shaft's): the import is the shaft and
    disks alone."""
    Kb, Cb = film_coefficients
    plain = _ross_rotor()
    steel = rs.materials.steel
    shaft = [rs.ShaftElement(L=LENGTH, idl=0.0, odl=DIAMETER, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(ELEMENTS)]
    disk = rs.DiskElement.from_geometry(n=ELEMENTS // 2, material=steel, width=0.1, i_d=DIAMETER, o_d=0.4)
    support = ELEMENTS + 1
    bearings = [rs.BearingElement(n=0, n_link=support, kxx=Kb[0, 0], kyy=Kb[1, 1], cxx=Cb[0, 0], cyy=Cb[1, 1]),
                rs.BearingElement(n=support, kxx=1e9, cxx=1e3),
                rs.BearingElement(n=ELEMENTS, kxx=Kb[0, 0], kyy=Kb[1, 1], cxx=Cb[0, 0], cyy=Cb[1, 1])]
    supported = rs.Rotor(shaft, [disk], bearings, point_mass_elements=[rs.PointMass(n=support, m=20.0)])
    assert supported.ndof > 6 * (ELEMENTS + 1)
    a, b = matrices_from_ross(plain), matrices_from_ross(supported)
    for key in ("mass", "stiffness", "damping", "gyroscopic"):
        assert np.array_equal(a[key], b[key]), key


def test_not_a_ross_rotor():
    with pytest.raises(TypeError, match="ross_rotor must be a ross.Rotor"):
        matrices_from_ross(object())
