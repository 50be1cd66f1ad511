"""Kernels compiled without entry points for Python (solvers/inner_kernel.py)."""

import numpy as np
import pytest
from numba import njit

from transient.solvers.inner_kernel import entry_point, inner_kernel


@inner_kernel
def _weighted_sum(x, w):
    s = 0.0
    for i in range(x.size):
        s += w * x[i]
    return s


@njit
def _caller(x):
    return _weighted_sum(x, 2.0)


def test_a_kernel_calls_an_inner_kernel():
    x = np.arange(5.0)
    assert _caller(x) == 2.0 * x.sum()


def test_python_cannot_call_an_inner_kernel_but_its_entry_point():
    x = np.arange(4.0)
    with pytest.raises(TypeError, match="_weighted_sum is a kernel for numba kernels only"):
        _weighted_sum(x, 3.0)
    assert entry_point(_weighted_sum)(x, 3.0) == 3.0 * x.sum()


def test_the_newton_kernels_python_calls_have_entry_points():
    from transient.models.journal import content_newton as cn
    from transient.solvers import bandlu
    for name in ("newton_jacobian", "bdf2_jacobian", "bdf2_to_state", "bdf2_from_state", "bdf2_residual"):
        assert not isinstance(getattr(cn, name), type(_weighted_sum)), name
    for name in ("band_factor", "band_solve"):
        assert not isinstance(getattr(bandlu, name), type(_weighted_sum)), name


@inner_kernel
def _checked_sum(x):
    if x.size == 0:
        raise ValueError("no values")
    return _weighted_sum(x, 1.0)


@njit
def _checked_caller(x):
    return _checked_sum(x)


def test_an_inner_kernel_calls_another_and_its_error_reaches_python():
    """Inner kernels' code reaches the JIT only through their callers (LinkOnlyLibrary): a chain of them runs and
    an exception raised inside one comes out of the caller."""
    assert _checked_caller(np.arange(3.0)) == 3.0
    with pytest.raises(ValueError, match="no values"):
        _checked_caller(np.empty(0))
