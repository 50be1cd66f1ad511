"""Pseudo-arclength continuation of fixed points of a period map (``models/rotor/periodic_branch.py``) on a map
whose fixed points and multipliers are known: ``x' = x + (2 - s - x^2) / 4``, ``y' = y / 100 + x / 10``. Its
fixed points are ``x = +-sqrt(2 - s)``, ``y = 10 x / 99``, with the multipliers ``1 - x / 2`` and ``1 / 100``: a fold
at ``s = 2`` where the multiplier crosses +1, the branch ``x > 0`` stable, ``x < 0`` a saddle."""

import numpy as np
import pytest

from transient.models.rotor.periodic_branch import PathSettings, continue_fixed_points


class FoldMap:
    """The map of the module docstring, ``y`` the fast (Picard) component."""

    periods = 0

    def flow(self, z, s):
        self.periods += 1
        x, y = z
        return np.array([x + 0.25 * (2.0 - s - x * x), 0.01 * y + 0.1 * x])

    def norm(self, d):
        return float(np.max(np.abs(d)))


def _trace():
    path = PathSettings(step=0.05, max_step=0.2, max_points=200, tol=1e-10)
    z0 = np.array([1.0, 10.0 / 99.0])
    V = np.array([[1.0], [0.0]])
    return continue_fixed_points(FoldMap(), z0, V, np.array([1.0, 0.0]), 1, (0.8, 3.0), path)


def test_the_path_turns_at_the_fold_and_the_multiplier_crosses_one_there():
    points, _, slopes, arc, fold_at, message = _trace()
    assert message == "" and len(fold_at) == 1
    s = np.array([p.s for p in points])
    x = np.array([p.z[0] for p in points])
    assert s[-1] < 0.8 and x[-1] < 0  # back down the saddle branch
    # every point is a fixed point of the map (the corrector's tolerance) with the known multiplier
    np.testing.assert_allclose(x * x, 2.0 - s, atol=1e-8)
    mu = np.array([p.multipliers[0].real for p in points])
    np.testing.assert_allclose(mu, 1.0 - 0.5 * x, atol=1e-3)  # differences of step 1e-3 on a quadratic map
    i = fold_at[0]
    assert slopes[i] > 0 > slopes[i + 1] and mu[i] < 1.0 < mu[i + 1]
    from transient.models.rotor.periodic_branch import _fold

    top, _ = _fold(np.array(arc), s, i, True)
    assert top == pytest.approx(2.0, abs=2e-3)  # the parabola through three points of the exact fold's path


def test_path_settings_refuse_bad_steps():
    with pytest.raises(ValueError, match="max_step"):
        PathSettings(step=0.1, max_step=0.05)
    with pytest.raises(ValueError, match="max_points"):
        PathSettings(max_points=1)
