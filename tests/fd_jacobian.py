"""Central finite-difference Jacobians, the reference of the tests that check analytic Jacobians."""

import numpy as np


def central_jacobian(f, y, rows, step=1e-6, relative=True):
    """``(rows, y.size)`` central differences of ``f(y) -> array``. Column ``j`` steps by ``step max(1, |y_j|)``
    (``relative``) or by ``step``; the step must be well below the scale on which ``f`` bends."""
    y = np.asarray(y, dtype=float)
    J = np.zeros((rows, y.size))
    for j in range(y.size):
        hj = step * max(1.0, abs(y[j])) if relative else step
        yp, ym = y.copy(), y.copy()
        yp[j] += hj
        ym[j] -= hj
        J[:, j] = (f(yp) - f(ym)) / (2 * hj)
    return J
