"""Numba kernels that only other kernels call, compiled without entry points for Python.

numba compiles every ``@njit`` function with two wrappers besides the function itself: one that Python calls
(unboxing every argument: for a kernel taking a model's argument tuple, dozens of arrays) and one for C callers;
each caller links both in and optimises them again. A kernel that Python never calls needs neither:
:func:`inner_kernel` compiles it without them (measured on the journal's BDF2 Newton kernels: about half of each
small kernel's compile time). It is not cached on disk itself: its callers are, with its code linked in. Nor is
its module optimised as a whole or turned into machine code (:class:`LinkOnlyLibrary`): numba does both again in
every caller, over the caller's code and all it links (measured on the journal's BDF2 Newton caller with its inner
kernels: 26.5 -> 20.7 s CPU to compile, the same steps bit for bit).
Called from Python it raises ``TypeError`` (there is no entry to call); :func:`entry_point` gives the same
function as a cached kernel Python can call (tests, diagnostics).
"""

from __future__ import annotations

import llvmlite.binding as llvm
import llvmlite.ir as llvm_ir
from numba import njit
from numba.core.codegen import JITCodeLibrary
from numba.core.compiler import Compiler
from numba.core.registry import CPUDispatcher


class LinkOnlyLibrary(JITCodeLibrary):
    """The code of an inner kernel: optimised function by function, then only linked into its callers, whose module
    is optimised as a whole and turned into machine code with this code in it. numba does both for every library
    and again in each caller; here the library's own module does neither: only its environment pointers (the
    globals numba fills once the kernel is compiled) go to the JIT, in a module of their own."""

    def _optimize_final_module(self):
        pass

    def _finalize_final_module(self):
        self._finalize_dynamic_globals()
        self._verify_declare_only_symbols()
        stub = self._codegen._create_empty_module(self.name + ".env")
        for gv in self._final_module.global_variables:
            if "NumbaEnv" in gv.name:
                env = llvm_ir.GlobalVariable(stub, llvm_ir.IntType(8).as_pointer(), name=gv.name)
                env.linkage = "common"
                env.initializer = llvm_ir.Constant(env.type.pointee, None)
        self._codegen._add_module(llvm.parse_assembly(str(stub)))
        self._codegen._engine.finalize_object()
        self._finalized = True


class _InnerCompiler(Compiler):
    """numba's compiler with the kernel's code in a :class:`LinkOnlyLibrary`."""

    def compile_extra(self, func):
        if self.state.library is None:
            self.state.library = LinkOnlyLibrary(self.state.targetctx.codegen(), func.__qualname__)
        return super().compile_extra(func)


class InnerKernel(CPUDispatcher):
    """A numba dispatcher without the wrappers Python and C callers need (:func:`inner_kernel`)."""

    def __call__(self, *args, **kwargs):
        raise TypeError(f"{self.py_func.__module__}.{self.py_func.__qualname__} is a kernel for numba kernels only "
                        f"(compiled without an entry point for Python); call its entry_point() from Python")


def inner_kernel(func) -> InnerKernel:
    """``@njit`` for a kernel that only other kernels call (module docstring); ``func`` may be a numba dispatcher."""
    return InnerKernel(getattr(func, "py_func", func),
                       targetoptions={"nopython": True, "no_cpython_wrapper": True, "no_cfunc_wrapper": True},
                       pipeline_class=_InnerCompiler)


def entry_point(kernel):
    """The function of an :func:`inner_kernel` as an ordinary cached ``@njit`` kernel that Python can call."""
    return njit(cache=True)(kernel.py_func)
