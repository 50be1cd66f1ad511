"""When has a periodically forced response settled? The stopping rule of every settle loop, free of any model.

A response forced with period T returns to the same point every period once it has settled, so its
once-per-period (Poincare) samples ``z_k = z(t0 + k T)`` converge. :func:`find_settled` returns the first
sample from which ``confirm`` consecutive Poincare steps ``|z_k - z_{k-1}| / scale`` are all below ``tol``
(Euclidean or largest-component norm). :func:`settled_stop` turns an observable and a criterion into the
``stop(result_so_far)`` callback of a chunked run (:func:`~transient.solvers.longrun.run_long`), so a model's
own loop (the journal's shooting fallback) and the studies' :func:`~transient.study.settle.settle` stop by the
same rule.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

NORMS = {"2": 2, "max": np.inf}


def poincare_steps(samples, scale=1.0, norm: str = "2") -> np.ndarray:
    """Distances between consecutive Poincare samples, ``|z_k - z_{k-1}| / scale`` (length n - 1), in the
    Euclidean (``norm="2"``) or largest-component (``"max"``) norm.

    ``samples``: (n,) or (n, d) once-per-period samples."""
    if norm not in NORMS:
        raise ValueError(f"norm = {norm!r}; allowed: {', '.join(NORMS)}")
    z = np.asarray(samples, dtype=float)
    if z.ndim == 1:
        z = z[:, None]
    if len(z) < 2:
        return np.zeros(0)
    return np.linalg.norm(np.diff(z, axis=0), ord=NORMS[norm], axis=1) / float(scale)


def find_settled(samples, tol, scale=1.0, confirm=2, norm: str = "2") -> int | None:
    """Index k of the first Poincare sample from which the motion is periodic to ``tol``: the
    ``confirm`` steps ending at sample k are all below ``tol`` (relative to ``scale``). ``None`` if
    not reached."""
    if confirm < 1:
        raise ValueError(f"confirm must be >= 1, got {confirm}")
    d = poincare_steps(samples, scale, norm)
    below = d < tol
    for k in range(confirm - 1, len(d)):
        if below[k - confirm + 1: k + 1].all():
            return k + 1  # sample index (step k joins samples k and k + 1)
    return None


def settles(tol: float, confirm: int = 2, norm: str = "2") -> Callable:
    """The Poincare criterion as a function of the samples: ``criterion(samples) -> int | None``
    (:func:`find_settled` with unit scale: the samples are already in the units of ``tol``)."""
    return lambda samples: find_settled(samples, tol, 1.0, confirm, norm)


def settled_stop(observable: Callable, criterion: Callable, label: str = "settled") -> Callable:
    """``stop(result_so_far) -> str | None`` for a chunked run: ``"<label> after k periods"`` once
    ``criterion(observable(result_so_far))`` returns a sample index k, else None."""

    def stop(partial):
        k = criterion(observable(partial))
        return None if k is None else f"{label} after {k} periods"

    return stop
