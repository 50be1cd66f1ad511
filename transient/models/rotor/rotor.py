"""A rotor as matrices: mass, stiffness, damping and gyroscopic matrices over the degrees of freedom of its
nodes (translations x, y and, where the model has them, tilts tx, ty), possibly reduced to modal coordinates.

The equations of motion (SI; ``Omega`` the shaft speed [rad/s], the gyroscopic matrix per rad/s)::

    M q'' + (C + Omega G) q' + K q = f,      x_full = basis q

``basis`` is the identity for a nodal model; a reduced model (:func:`transient.models.rotor.modal.reduce`: the
first modes plus the static correction at the bearing nodes) keeps it to map its coordinates back to the
nodes. Frames as in :class:`~transient.models.journal.JournalBearing`: x towards the static load, y at +90 deg
in the direction of rotation.
"""

from __future__ import annotations

import numpy as np

from transient.checks import check_int, check_items, check_positive, short_repr

DOF_LAYOUTS = (("x", "y"), ("x", "y", "tx", "ty"))


def _square(name, a, n=None, unit=""):
    """``a`` as a finite square float array (of size ``n`` if given), else a one-line ValueError."""
    try:
        arr = np.array(a, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a square array of numbers [{unit}], got {type(a).__name__}") from None
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
        raise ValueError(f"{name} has shape {arr.shape} [{unit}]; allowed: a non-empty square array")
    if n is not None and arr.shape[0] != n:
        raise ValueError(f"{name} has shape {arr.shape} [{unit}]; allowed: ({n}, {n}), the size of mass")
    if not np.all(np.isfinite(arr)):
        i, j = np.argwhere(~np.isfinite(arr))[0]
        raise ValueError(f"{name}[{i}, {j}] = {arr[i, j]!r} [{unit}]; allowed: finite numbers")
    return arr


def _matrix(name, a, allowed, shape=None):
    """``a`` as a finite 2-D float array (of ``shape`` if given), else a one-line ValueError naming ``allowed``."""
    try:
        arr = np.array(a, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {short_repr(a)} ({type(a).__name__}); allowed: {allowed}") from None
    if arr.ndim != 2 or 0 in arr.shape or (shape is not None and arr.shape != shape) or not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} has shape {arr.shape}{'' if np.all(np.isfinite(arr)) else ' and non-finite entries'}"
                         f"; allowed: {allowed}")
    return arr


class Rotor:
    """A rotor from its matrices (SI).

    Parameters
    ----------
    mass [kg, kg m^2 for tilts] : symmetric positive-definite mass matrix.
    stiffness [N/m, N m/rad] : stiffness matrix (square, same size; the rotor alone: zero rigid-body modes allowed).
    damping [N s/m] : structural damping matrix, or None (zero).
    gyroscopic [N s/m per rad/s] : gyroscopic matrix per rad/s of shaft speed, or None (zero).
    nodes : the node labels (integers), in the order of the degrees of freedom.
    dofs : the degrees of freedom of every node, ``("x", "y")`` or ``("x", "y", "tx", "ty")``.
    basis : for a reduced model, the (n_nodes * len(dofs), n) matrix mapping its coordinates to the nodal
        degrees of freedom (None: the matrices are nodal).
    gravity_load : for a reduced model, the (2, n) generalised forces of a unit acceleration [1 m/s^2] along x and
        y (``basis.T M_full e_x``); default ``mass @ basis_rigid`` computed from a nodal model.
    """

    def __init__(self, mass, stiffness, damping=None, gyroscopic=None, nodes=None, dofs=("x", "y"), *,
                 basis=None, gravity_load=None):
        self.mass = _square("mass", mass, unit="kg")
        n = self.mass.shape[0]
        if not np.allclose(self.mass, self.mass.T, rtol=1e-9, atol=1e-12 * np.max(np.abs(self.mass))):
            i, j = np.unravel_index(np.argmax(np.abs(self.mass - self.mass.T)), self.mass.shape)
            raise ValueError(f"mass is not symmetric: mass[{i}, {j}] = {self.mass[i, j]:.6g}, mass[{j}, {i}] = "
                             f"{self.mass[j, i]:.6g} [kg]; allowed: a symmetric positive-definite matrix")
        try:
            np.linalg.cholesky(self.mass)
        except np.linalg.LinAlgError:
            low = float(np.min(np.linalg.eigvalsh(self.mass)))
            raise ValueError(f"mass is singular or indefinite: smallest eigenvalue {low:.6g} [kg]; allowed: a "
                             "symmetric positive-definite matrix (every degree of freedom carries mass)") from None
        self.stiffness = _square("stiffness", stiffness, n, "N/m")
        self.damping = np.zeros((n, n)) if damping is None else _square("damping", damping, n, "N s/m")
        self.gyroscopic = np.zeros((n, n)) if gyroscopic is None else _square("gyroscopic", gyroscopic, n,
                                                                              "N s/m per rad/s")
        allowed = f"{DOF_LAYOUTS[0]!r} or {DOF_LAYOUTS[1]!r}"
        dofs = (dofs,) if isinstance(dofs, str) else check_items("dofs", dofs, allowed)
        if dofs not in DOF_LAYOUTS:
            raise ValueError(f"dofs = {dofs!r}; allowed: {allowed}")
        self.dofs = dofs = DOF_LAYOUTS[DOF_LAYOUTS.index(dofs)]
        n_full = n if basis is None else None
        if basis is not None:
            basis = _matrix("basis", basis, f"a finite (n_full, {n}) matrix with {n} the size of mass")
            if basis.shape[1] != n:
                raise ValueError(f"basis has shape {basis.shape}; allowed: a finite (n_full, {n}) matrix with {n} the "
                                 "size of mass")
            n_full = basis.shape[0]
        if nodes is None:
            if n_full % len(dofs):
                raise ValueError(f"mass has {n_full} degrees of freedom, not a multiple of {len(dofs)} (dofs={dofs})")
            nodes = list(range(n_full // len(dofs)))
        nodes = [check_int(f"nodes[{k}]", v, "-") for k, v in enumerate(check_items("nodes", nodes, "a list of "
                                                                                      "integer node labels"))]
        if len(set(nodes)) != len(nodes):
            raise ValueError(f"nodes = {nodes!r} repeats a label; allowed: distinct integers")
        if len(nodes) * len(dofs) != n_full:
            raise ValueError(f"nodes has {len(nodes)} labels x {len(dofs)} dofs = {len(nodes) * len(dofs)} degrees "
                             f"of freedom; the matrices have {n_full}")
        self.nodes = nodes
        self.basis = np.eye(n) if basis is None else basis
        self.reduced = basis is not None
        if gravity_load is None:
            if self.reduced:
                raise ValueError("a reduced rotor needs gravity_load (the generalised forces of a unit acceleration)")
            gravity_load = np.vstack([self.mass @ self._rigid(0), self.mass @ self._rigid(1)])
        self.gravity_load = _matrix("gravity_load", gravity_load, f"a finite (2, {n}) matrix [N per m/s^2]: the "
                                    "generalised forces of a unit acceleration along x and y", shape=(2, n))

    def _rigid(self, axis) -> np.ndarray:
        """The nodal translation field of a unit rigid displacement along x (0) or y (1)."""
        e = np.zeros(self.n_full)
        e[axis::len(self.dofs)] = 1.0
        return e

    @property
    def n(self) -> int:
        """Number of coordinates q (nodal degrees of freedom, or modal coordinates of a reduced model)."""
        return self.mass.shape[0]

    @property
    def n_full(self) -> int:
        return self.basis.shape[0]

    def __repr__(self):
        return (f"Rotor({len(self.nodes)} nodes, dofs={self.dofs}, {self.n} coordinates"
                f"{' (reduced)' if self.reduced else ''}, mass {self.total_mass:.4g} kg)")

    @property
    def total_mass(self) -> float:
        """Translational mass [kg] (the x-load of a unit acceleration, mapped to the nodes)."""
        return float(self.gravity_load[0] @ np.linalg.solve(self.mass, self.gravity_load[0]))

    def dof(self, node, name="x") -> int:
        """Index of the nodal degree of freedom ``name`` of ``node`` (in ``basis`` rows)."""
        if node not in self.nodes:
            raise ValueError(f"node = {node!r} is not a node of this rotor; allowed: {self.nodes}")
        if name not in self.dofs:
            raise ValueError(f"dof {name!r} is not in this rotor's dofs {self.dofs}")
        return self.nodes.index(node) * len(self.dofs) + self.dofs.index(name)

    def translation(self, node) -> np.ndarray:
        """(2, n): the rows mapping q to the (x, y) displacement [m] of ``node``."""
        return self.basis[[self.dof(node, "x"), self.dof(node, "y")]]

    @classmethod
    def rigid(cls, mass, inertia, span) -> "Rotor":
        """A rigid rotor of ``mass`` [kg] and transverse moment of inertia ``inertia`` [kg m^2] about its centre,
        carried at nodes 0 and 1 a ``span`` [m] apart (centre mid-way), x and y at each: the mass matrix from the
        kinetic energy of the centre ``(x_0 + x_1) / 2`` and the tilt ``(x_1 - x_0) / span``; no stiffness."""
        m = check_positive("mass", mass, "kg")
        inertia = check_positive("inertia", inertia, "kg m^2")
        span = check_positive("span", span, "m")
        t = m / 4 * np.ones((2, 2)) + inertia / span ** 2 * np.array([[1.0, -1.0], [-1.0, 1.0]])
        return cls(mass=np.kron(t, np.eye(2)), stiffness=np.zeros((4, 4)), nodes=[0, 1])

    @classmethod
    def jeffcott(cls, shaft_stiffness, disk_mass, journal_mass) -> "Rotor":
        """A disk of ``disk_mass`` [kg] at node 1 on a massless shaft between two journals of ``journal_mass``
        [kg] at nodes 0 and 2, each half of the shaft a spring ``shaft_stiffness`` [N/m] in x and y."""
        k = check_positive("shaft_stiffness", shaft_stiffness, "N/m")
        md = check_positive("disk_mass", disk_mass, "kg")
        mj = check_positive("journal_mass", journal_mass, "kg")
        chain = k * np.array([[1.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]])
        return cls(mass=np.kron(np.diag([mj, md, mj]), np.eye(2)), stiffness=np.kron(chain, np.eye(2)),
                   nodes=[0, 1, 2])

    @classmethod
    def example(cls) -> "Rotor":
        """The built-in flexible rotor (a steel shaft with disks on two bearing nodes,
        :func:`transient.models.rotor.shaft.example_matrices`); its bearing nodes are ``example_bearing_nodes``."""
        from transient.models.rotor.shaft import example_matrices

        m = example_matrices()
        r = cls(mass=m["mass"], stiffness=m["stiffness"], damping=m.get("damping"), gyroscopic=m.get("gyroscopic"),
                nodes=m["nodes"], dofs=m["dofs"])
        r.bearing_nodes = tuple(m["bearing_nodes"])
        r.disk_nodes = tuple(m.get("disk_nodes", ()))
        return r

    @classmethod
    def from_ross(cls, ross_rotor, modes=None, bearing_nodes=None) -> "Rotor":
        """A rotor from a ROSS ``Rotor`` (optional extra ``transient[ross]``): its shaft and disks' mass, stiffness,
        damping and gyroscopic matrices (:func:`~transient.models.rotor.ross_import.matrices_from_ross`; ROSS's own
        bearings are left out: :class:`~transient.models.rotor.system.RotorBearingSystem` adds the films). With
        ``modes``: reduced to that many fixed-interface modes plus the static correction at the bearing nodes
        (:func:`~transient.models.rotor.modal.reduce`, Craig-Bampton); ``bearing_nodes`` default: the nodes of
        ROSS's bearing elements. ``rotor.bearing_nodes`` holds them."""
        from transient.models.rotor.ross_import import matrices_from_ross

        m = matrices_from_ross(ross_rotor)
        full = cls(mass=m["mass"], stiffness=m["stiffness"], damping=m.get("damping"),
                   gyroscopic=m.get("gyroscopic"), nodes=m["nodes"], dofs=m["dofs"])
        if bearing_nodes is None:
            bearing_nodes = sorted({int(b.n) for b in getattr(ross_rotor, "bearing_elements", [])})
        full.bearing_nodes = tuple(bearing_nodes)
        if modes is None:
            return full
        if not full.bearing_nodes:
            raise ValueError("bearing_nodes = () [-]; allowed: the nodes the bearings will sit at (a reduced rotor "
                             "keeps their x and y exactly), e.g. from ROSS's bearing elements")
        return full.reduce(modes)

    def reduce(self, modes, bearing_nodes=None) -> "Rotor":
        """This nodal rotor reduced to its ``modes`` lowest fixed-interface modes plus the static correction at the
        bearing nodes (:func:`~transient.models.rotor.modal.reduce`, Craig-Bampton): the x and y of
        ``bearing_nodes`` (default ``self.bearing_nodes``) stay the first coordinates, exactly. A whirl or whip
        study needs the modes near the whirl frequency, not the shaft's stiff high bending modes, whose light
        structural damping would otherwise set the integrator's step."""
        from transient.models.rotor.modal import reduce

        if self.reduced:
            raise ValueError("rotor: already reduced; allowed: a nodal rotor (Rotor(...) without basis)")
        nodes = tuple(getattr(self, "bearing_nodes", ()) if bearing_nodes is None else bearing_nodes)
        if not nodes:
            raise ValueError("bearing_nodes = () [-]; allowed: the nodes the bearings will sit at (a reduced rotor "
                             "keeps their x and y exactly)")
        modes = check_int("modes", modes, "-", 0, self.n)
        keep = [self.dof(nd, d) for nd in nodes for d in ("x", "y")]
        red = reduce(self.mass, self.stiffness, self.damping, self.gyroscopic, keep, modes)
        B = np.asarray(red.basis)
        r = type(self)(mass=red.mass, stiffness=red.stiffness, damping=red.damping, gyroscopic=red.gyroscopic,
                       nodes=self.nodes, dofs=self.dofs, basis=B, gravity_load=self.gravity_load @ B)
        r.bearing_nodes = nodes
        r.disk_nodes = tuple(getattr(self, "disk_nodes", ()))
        return r
