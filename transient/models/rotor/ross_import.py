"""The matrices of a ROSS rotor (shaft elements and disks; bearings, seals and support masses left out: the
films replace them) in this package's conventions.

ROSS (Petrobras, "ROSS - Rotordynamic Open Source Software", J. Open Source Softw. 2020) writes
``M q'' + (C + Omega G) q' + K q = F`` with the shaft spinning from x towards y and unbalance forces
``m e Omega^2 (1, -i) e^{i phi}``, as :mod:`transient.models.rotor.shaft` and :mod:`.linear` do; its bending
rotations ``alpha`` (about x) and ``beta`` (about y) are ``tx`` and ``ty`` (the element matrices agree to round-off:
tests/models/rotor/test_ross_import.py). Two node layouts exist: 4 dofs per node ``(x, y, alpha, beta)`` (ROSS
1.x) and 6 ``(x, y, z, alpha, beta, theta)`` (ROSS 2 and later); the dofs are found by name in each element's
``dof_global_index``, so either works. The axial and torsional dofs of the 6-dof layout are dropped (they do not
couple with bending in ROSS's linear elements; :func:`matrices_from_ross` checks that).
"""

from __future__ import annotations

import numpy as np

from transient.models.rotor.shaft import DOFS

#: ROSS's names of this package's dofs.
ROSS_NAMES = dict(x="x", y="y", tx="alpha", ty="beta")


def _element_matrix(element, name):
    """``element.M()`` (or K, C, G), with ROSS versions whose methods take a frequency."""
    method = getattr(element, name)
    try:
        return np.asarray(method(), dtype=float)
    except TypeError:
        return np.asarray(method(0.0), dtype=float)


def matrices_from_ross(ross_rotor) -> dict:
    """dict(mass, stiffness, damping, gyroscopic, nodes, dofs=("x", "y", "tx", "ty"), positions [m]) of the shaft
    and disks of ``ross_rotor`` (a ``ross.Rotor``), SI, nodes 0..n-1 in ROSS's node order."""
    for attr in ("shaft_elements", "disk_elements", "nodes", "ndof"):
        if not hasattr(ross_rotor, attr):
            raise TypeError(f"ross_rotor must be a ross.Rotor (it has no {attr!r}), got {type(ross_rotor).__name__}")
    ndof = int(ross_rotor.ndof)
    parts = {name: np.zeros((ndof, ndof)) for name in ("M", "K", "C", "G")}
    where = {}
    for element in list(ross_rotor.shaft_elements) + list(ross_rotor.disk_elements):
        index = element.dof_global_index
        where.update(index)
        dofs = list(index.values())
        for name, A in parts.items():
            A[np.ix_(dofs, dofs)] += _element_matrix(element, name)
    nodes = [int(n) for n in ross_rotor.nodes]
    try:
        lateral = [where[f"{ROSS_NAMES[d]}_{n}"] for n in nodes for d in DOFS]
    except KeyError as e:
        raise ValueError(f"ross_rotor has no bending dof {e.args[0]!r}: a shaft node without the lateral "
                         "dofs (x, y, alpha, beta) cannot be imported") from None
    others = np.setdiff1d(np.arange(ndof), lateral)
    for name, A in parts.items():
        coupling = np.abs(A[np.ix_(lateral, others)]).max(initial=0.0)
        if coupling > 1e-12 * np.abs(A).max(initial=0.0):
            raise ValueError(f"ross_rotor's {name} couples bending with axial or torsional dofs (largest entry "
                             f"{coupling:.3g}); only bending rotors can be imported")
    pick = np.ix_(lateral, lateral)
    out = dict(mass=parts["M"][pick], stiffness=parts["K"][pick], damping=parts["C"][pick],
               gyroscopic=parts["G"][pick], nodes=list(range(len(nodes))), dofs=DOFS)
    if hasattr(ross_rotor, "nodes_pos"):
        out["positions"] = np.asarray(ross_rotor.nodes_pos, dtype=float)
    return out
