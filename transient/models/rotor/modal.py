"""Modal reduction of a rotor's matrices: Craig-Bampton (static constraint modes at the kept dofs + fixed-interface
normal modes), Craig & Bampton, "Coupling of substructures for dynamic analyses", AIAA J. 6 (1968).

The full dofs x are split into kept ones b (the bearings' x and y: the films act there, so they stay physical
coordinates) and interior ones i. With

    Psi = -K_ii^{-1} K_ib                 (the static shape of the interior for unit displacements at b)
    K_ii Phi = M_ii Phi diag(w^2)         (the ``modes`` lowest normal modes with b held fixed, M-normalised)

``x = T q`` with ``T[b] = [I, 0]``, ``T[i] = [Psi, Phi]``, ``q = (x_b, eta)``: the reduced matrices are
``T^T M T``, ``T^T K T``, ``T^T C T``, ``T^T G T``. The first ``len(keep)`` reduced coordinates ARE the kept dofs
(in the order of ``keep``), so a bearing attached at the full dof ``keep[j]`` attaches at reduced coordinate j,
and a force F on the full dofs acts as ``T^T F``. Statics under loads at the kept dofs is exact for any number of
modes; the dynamics converges as modes are added (the error against the full model is measured in
tests/models/rotor/test_modal.py and docs/validation.md). An axisymmetric rotor's fixed-interface modes come in
pairs (one per plane) with equal frequencies: take an even number of modes.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.linalg as sl

from transient.checks import check_int, short_repr
from transient.models.rotor.linear import check_matrices


class ReducedModel(NamedTuple):
    """The reduced matrices (damping None if the full one was) and the basis ``x_full = basis @ q``."""
    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray | None
    gyroscopic: np.ndarray | None
    basis: np.ndarray


def _keep(keep, n):
    k = np.atleast_1d(np.asarray(keep))
    if k.ndim != 1 or k.size == 0 or not np.issubdtype(k.dtype, np.integer):
        raise ValueError(f"keep = {short_repr(keep)} [-] must be a non-empty list of dof indices in [0, {n - 1}]")
    if k.min() < 0 or k.max() >= n or np.unique(k).size != k.size:
        raise ValueError(f"keep = {short_repr(keep)} [-] must hold distinct dof indices in [0, {n - 1}]")
    return k.astype(int)


def reduce(mass, stiffness, damping, gyroscopic, keep, modes) -> ReducedModel:
    """Craig-Bampton reduction keeping the dofs ``keep`` exactly and ``modes`` fixed-interface normal modes."""
    M, C, G, K = check_matrices(mass, damping, gyroscopic, stiffness)
    n = M.shape[0]
    b = _keep(keep, n)
    i = np.setdiff1d(np.arange(n), b)
    nm = check_int("modes", modes, "-", 0, i.size)
    if i.size == 0:  # everything kept: nothing to reduce
        return ReducedModel(M, K, None if damping is None else C, None if gyroscopic is None else G, np.eye(n))
    Kii, Kib, Mii = K[np.ix_(i, i)], K[np.ix_(i, b)], M[np.ix_(i, i)]
    w2, phi = sl.eigh(Kii, Mii, subset_by_index=[0, max(nm, 1) - 1])
    scale = np.max(np.diag(Kii) / np.diag(Mii))  # ~ the largest w^2 of the fixed-interface model
    if w2[0] <= 1e-12 * scale:
        raise ValueError(f"keep = {short_repr(keep)} [-] does not hold the rotor statically (K is singular with the "
                         "kept dofs fixed); allowed: the x and y of at least two bearing nodes")
    chol = sl.cho_factor(Kii)
    T = np.zeros((n, b.size + nm))
    T[b, np.arange(b.size)] = 1.0
    T[np.ix_(i, np.arange(b.size))] = -sl.cho_solve(chol, Kib)
    if nm:
        T[np.ix_(i, b.size + np.arange(nm))] = phi

    def project(A, sign=0):
        """T^T A T, made exactly symmetric (sign +1) or skew (-1) where A is."""
        R = T.T @ A @ T
        return 0.5 * (R + sign * R.T) if sign else R

    return ReducedModel(project(M, 1), project(K, 1), None if damping is None else project(C),
                        None if gyroscopic is None else project(G, -1), T)
