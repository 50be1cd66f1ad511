"""``as_read_only``: a writable array handed to a kernel as the read-only type SUNDIALS gives, without a copy."""

import numpy as np
from numba import njit

from transient.solvers.read_only import as_read_only


@njit
def _total(a):
    return a.sum()


@njit
def _total_read_only(a):
    return _total(as_read_only(a))


@njit
def _first_after_write(a):
    v = as_read_only(a)
    a[0] = 7.0  # the view shares the data
    return v[0]


def test_a_writable_array_reaches_the_kernel_as_the_read_only_type_without_a_copy():
    assert _total_read_only(np.arange(6.0)) == 15.0
    assert [s[0].mutable for s in _total.signatures] == [False]  # compiled for the read-only type only
    ro = np.arange(6.0)
    ro.setflags(write=False)
    assert _total(ro) == 15.0  # what SUNDIALS hands: the same signature, nothing compiled again
    assert len(_total.signatures) == 1
    assert _first_after_write(np.zeros(3)) == 7.0
