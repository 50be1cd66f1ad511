"""Numba kernels that only other kernels call, compiled without entry points for Python.

numba compiles every ``@njit`` function with two wrappers besides the function itself: one that Python calls
(unboxing every argument: for a kernel taking a model's argument tuple, dozens of arrays) and one for C callers;
each caller links both in and optimises them again. A kernel that Python never calls needs neither:
:func:`inner_kernel` compiles it without them (measured on the journal's BDF2 Newton kernels: about half of each
small kernel's compile time). It is not cached on disk itself: its callers are, with its code linked in.
Called from Python it raises ``TypeError`` (there is no entry to call); :func:`entry_point` gives the same
function as a cached kernel Python can call (tests, diagnostics).
"""

from __future__ import annotations

from numba import njit
from numba.core.registry import CPUDispatcher


class InnerKernel(CPUDispatcher):
    """A numba dispatcher without the wrappers Python and C callers need (:func:`inner_kernel`)."""

    def __call__(self, *args, **kwargs):
        raise TypeError(f"{self.py_func.__module__}.{self.py_func.__qualname__} is a kernel for numba kernels only "
                        f"(compiled without an entry point for Python); call its entry_point() from Python")


def inner_kernel(func) -> InnerKernel:
    """``@njit`` for a kernel that only other kernels call (module docstring); ``func`` may be a numba dispatcher."""
    return InnerKernel(getattr(func, "py_func", func),
                       targetoptions={"nopython": True, "no_cpython_wrapper": True, "no_cfunc_wrapper": True})


def entry_point(kernel):
    """The function of an :func:`inner_kernel` as an ordinary cached ``@njit`` kernel that Python can call."""
    return njit(cache=True)(kernel.py_func)
