"""Rotor matrices from beam finite elements: Timoshenko shaft elements and rigid disks, SI.

Equation of motion of the free rotor (no bearings), shaft speed Omega [rad/s]:

    M q'' + (C + Omega G) q' + K q = f

with four degrees of freedom per node, in node order ``q = (x0, y0, tx0, ty0, x1, y1, ...)``: the lateral
displacements x, y [m] and the small rotations tx, ty [rad] about the x and y axes. The shaft axis z = x cross y
runs from node 0 to node n-1, and the shaft spins about +z, i.e. from +x towards +y (the sense of the journal
bearing's rotation: an unbalance force m e Omega^2 (cos Omega t, sin Omega t)). With this right-handed frame a
slope of the centreline is ``ty = dx/dz`` and ``tx = -dy/dz``.

Shaft element (Timoshenko beam, shear deformation and rotary inertia; Przemieniecki, "Theory of Matrix
Structural Analysis", and Friswell, Penny, Garvey & Lees, "Dynamics of Rotating Machines", ch. 5): in each plane
with dofs (w1, psi1, w2, psi2), psi the section rotation, and Phi = 12 E I / (kappa G A L^2),

    K = E I / ((1 + Phi) L^3) [[12, 6L, -12, 6L], [6L, (4+Phi)L^2, -6L, (2-Phi)L^2], ...]

the consistent translational mass rho A L (...) and rotary mass rho I / L (...) polynomials in Phi of the same
reference; ``shear=False`` sets Phi = 0 (Euler-Bernoulli with rotary inertia; ``rotary_inertia=False`` drops it
too). The gyroscopic matrix follows from the kinetic energy of the spinning section (polar inertia per length
rho J = 2 rho I) through the same rotation shape functions as the rotary mass R:
``G[x-plane, y-plane] = 2 R T``, ``G[y-plane, x-plane] = -2 T R`` with T = diag(1, -1, 1, -1) (tx = -psi_y).
Rigid disk at a node (mass m, polar I_p, diametral I_d): m on x, y; I_d on tx, ty; ``G[tx, ty] = +I_p``,
``G[ty, tx] = -I_p``, so that ``I_d tx'' + Omega I_p ty' = M_x`` and ``I_d ty'' - Omega I_p tx' = M_y`` (the
forward whirl stiffens).

Shear coefficient of a circular (hollow) section: Cowper, "The shear coefficient in Timoshenko's beam theory"
(1966): kappa = 6 (1 + nu)(1 + r^2)^2 / ((7 + 6 nu)(1 + r^2)^2 + (20 + 12 nu) r^2), r = d_in / d_out.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from transient.checks import check_int, check_positive, check_range

DOFS = ("x", "y", "tx", "ty")
STEEL = dict(density=7850.0, young_modulus=211e9, poisson_ratio=0.3)


class Disk(NamedTuple):
    """A rigid disk at ``node``: mass [kg], polar and diametral moments of inertia [kg m^2] about its centre."""
    node: int
    mass: float
    polar_inertia: float
    diametral_inertia: float


def disk_from_geometry(node, outer_diameter, width, inner_diameter=0.0, density=STEEL["density"]) -> Disk:
    """A solid (or bored) cylindrical disk: m = rho pi (D^2 - d^2) w / 4, I_p = m (D^2 + d^2) / 8,
    I_d = I_p / 2 + m w^2 / 12."""
    D = check_positive("outer_diameter", outer_diameter, "m")
    d = check_range("inner_diameter", inner_diameter, "m", 0.0, D, high_open=True)
    w = check_positive("width", width, "m")
    rho = check_positive("density", density, "kg/m^3")
    m = rho * math.pi * (D * D - d * d) * w / 4.0
    ip = m * (D * D + d * d) / 8.0
    return Disk(int(node), m, ip, ip / 2.0 + m * w * w / 12.0)


def shear_coefficient(outer_diameter, inner_diameter, poisson_ratio) -> float:
    """Cowper's shear coefficient of a hollow circular section."""
    r2 = (inner_diameter / outer_diameter) ** 2
    nu = poisson_ratio
    return 6.0 * (1 + nu) * (1 + r2) ** 2 / ((7 + 6 * nu) * (1 + r2) ** 2 + (20 + 12 * nu) * r2)


def _plane_matrices(L, EI, rhoA, rhoI, phi):
    """Stiffness, translational mass, rotary mass (per rho I) of one Timoshenko element in one plane,
    dofs (w1, psi1, w2, psi2)."""
    k = EI / ((1 + phi) * L ** 3) * np.array([
        [12, 6 * L, -12, 6 * L],
        [6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L],
        [-12, -6 * L, 12, -6 * L],
        [6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L]])
    p2 = phi * phi
    m1 = 13 / 35 + 7 * phi / 10 + p2 / 3
    m2 = (11 / 210 + 11 * phi / 120 + p2 / 24) * L
    m3 = 9 / 70 + 3 * phi / 10 + p2 / 6
    m4 = -(13 / 420 + 3 * phi / 40 + p2 / 24) * L
    m5 = (1 / 105 + phi / 60 + p2 / 120) * L * L
    m6 = -(1 / 140 + phi / 60 + p2 / 120) * L * L
    mt = rhoA * L / (1 + phi) ** 2 * np.array([
        [m1, m2, m3, m4], [m2, m5, -m4, m6], [m3, -m4, m1, -m2], [m4, m6, -m2, m5]])
    r1 = 6 / 5
    r2 = (1 / 10 - phi / 2) * L
    r3 = (2 / 15 + phi / 6 + p2 / 3) * L * L
    r4 = (-1 / 30 - phi / 6 + p2 / 6) * L * L
    rot = 1.0 / (L * (1 + phi) ** 2) * np.array([
        [r1, r2, -r1, r2], [r2, r3, -r2, r4], [-r1, -r2, r1, -r2], [r2, r4, -r2, r3]])
    return k, mt, rot * rhoI


def shaft_matrices(element_lengths, outer_diameters, inner_diameters=0.0, *, density=STEEL["density"],
                   young_modulus=STEEL["young_modulus"], poisson_ratio=STEEL["poisson_ratio"], disks=(),
                   shear=True, rotary_inertia=True) -> dict:
    """Mass, stiffness and gyroscopic (per rad/s) matrices of a shaft of ``len(element_lengths)`` elements
    (nodes 0..n_elements) with rigid disks at nodes (see the module docstring for the equation and frames).

    Parameters (SI)
    ----------
    element_lengths [m] : one per element.
    outer_diameters, inner_diameters [m] : per element (or one value for all); inner 0 for a solid shaft.
    density [kg/m^3], young_modulus [Pa], poisson_ratio [-] : the shaft material (default steel).
    disks : :class:`Disk` (or tuples ``(node, mass, polar_inertia, diametral_inertia)``) at nodes.
    shear : Timoshenko element (True) or Euler-Bernoulli (False, Phi = 0).
    rotary_inertia : include the rotary inertia (and the gyroscopic matrix) of the shaft sections.

    Returns dict(mass, stiffness, damping=None, gyroscopic, nodes=[0..n-1], dofs=("x","y","tx","ty"),
    positions [m] of the nodes along the axis).
    """
    lengths = np.atleast_1d(np.asarray(element_lengths, dtype=float))
    ne = lengths.size
    check_int("number of elements", ne, "-", 1, 10_000)
    do = np.broadcast_to(np.asarray(outer_diameters, dtype=float), (ne,))
    di = np.broadcast_to(np.asarray(inner_diameters, dtype=float), (ne,))
    for i in range(ne):
        check_positive(f"element_lengths[{i}]", lengths[i], "m")
        check_positive(f"outer_diameters[{i}]", do[i], "m")
        check_range(f"inner_diameters[{i}]", di[i], "m", 0.0, do[i], high_open=True)
    rho = check_positive("density", density, "kg/m^3")
    E = check_positive("young_modulus", young_modulus, "Pa")
    nu = check_range("poisson_ratio", poisson_ratio, "-", -1.0, 0.5, low_open=True, high_open=True)
    G_mod = E / (2 * (1 + nu))
    n = 4 * (ne + 1)
    M = np.zeros((n, n))
    K = np.zeros((n, n))
    G = np.zeros((n, n))
    T = np.diag([1.0, -1.0, 1.0, -1.0])
    for e in range(ne):
        L = lengths[e]
        A = math.pi * (do[e] ** 2 - di[e] ** 2) / 4
        I = math.pi * (do[e] ** 4 - di[e] ** 4) / 64
        phi = 12 * E * I / (shear_coefficient(do[e], di[e], nu) * G_mod * A * L * L) if shear else 0.0
        k, mt, mr = _plane_matrices(L, E * I, rho * A, rho * I if rotary_inertia else 0.0, phi)
        ix = np.array([0, 3, 4, 7]) + 4 * e  # (x1, ty1, x2, ty2): ty = dx/dz
        iy = np.array([1, 2, 5, 6]) + 4 * e  # (y1, tx1, y2, tx2): tx = -dy/dz
        M[np.ix_(ix, ix)] += mt + mr
        K[np.ix_(ix, ix)] += k
        M[np.ix_(iy, iy)] += T @ (mt + mr) @ T
        K[np.ix_(iy, iy)] += T @ k @ T
        g = 2.0 * mr @ T  # polar inertia per length = 2 rho I
        G[np.ix_(ix, iy)] += g
        G[np.ix_(iy, ix)] -= g.T
    for d in disks:
        d = Disk(*d)
        node = check_int("disk node", d.node, "-", 0, ne)
        m = check_range("disk mass", d.mass, "kg", 0.0)
        ip = check_range("disk polar_inertia", d.polar_inertia, "kg m^2", 0.0)
        idi = check_range("disk diametral_inertia", d.diametral_inertia, "kg m^2", 0.0)
        b = 4 * node
        M[b, b] += m
        M[b + 1, b + 1] += m
        M[b + 2, b + 2] += idi
        M[b + 3, b + 3] += idi
        G[b + 2, b + 3] += ip
        G[b + 3, b + 2] -= ip
    positions = np.concatenate([[0.0], np.cumsum(lengths)])
    return dict(mass=M, stiffness=K, damping=None, gyroscopic=G, nodes=list(range(ne + 1)), dofs=DOFS,
                positions=positions)


#: The built-in example: a steel shaft of 80 mm (the journal diameter of Rho & Kim's bearing) between two
#: bearings 1.2 m apart, with one steel disk of 400 mm x 100 mm at mid-span.
EXAMPLE = dict(span=1.2, shaft_diameter=0.08, elements=12, disk_diameter=0.4, disk_width=0.1)


def example_matrices() -> dict:
    """A small flexible rotor: a steel shaft (80 mm, 1.2 m, 12 Timoshenko elements, nodes 0..12) on bearings
    at its ends (nodes 0 and 12) with a steel disk (400 mm x 100 mm, 98.6 kg) at mid-span (node 6); 146 kg in all,
    so each bearing carries ~716 N under gravity. Its first critical speed on rigid supports is ~2900 rpm; on two
    of Rho & Kim's bearings (``transient.params.rho_kim``) the first critical speed and the oil-whirl onset
    both fall at a few thousand rpm (numbers measured in docs/validation.md).

    Returns :func:`shaft_matrices`'s dict plus ``bearing_nodes=(0, 12)`` and ``disk_nodes=(6,)``.
    """
    ne = EXAMPLE["elements"]
    mid = ne // 2
    disk = disk_from_geometry(mid, EXAMPLE["disk_diameter"], EXAMPLE["disk_width"])
    out = shaft_matrices(np.full(ne, EXAMPLE["span"] / ne), EXAMPLE["shaft_diameter"], disks=[disk])
    out.update(bearing_nodes=(0, ne), disk_nodes=(mid,))
    return out
