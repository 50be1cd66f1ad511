"""``as_read_only(a)``: the same array, typed read-only, inside numba code.

SUNDIALS hands its callbacks read-only arrays, so every kernel it reaches is compiled for read-only inputs (the
Python-side steady solves pass read-only views for the same reason, :func:`~transient.models.journal.film.read_only`).
A numba caller that hands one of those kernels an array of its own (the BDF2 Newton's buffers) would otherwise
compile the kernel, and everything it calls, a second time for the writable type: ~15 s CPU of a cold BDF2 journal
orbit. Wrapping the argument in :func:`as_read_only` reuses the one compiled signature; the data are not copied
(read-only and writable arrays have the same layout in numba)."""

from numba import types
from numba.core.extending import intrinsic
from numba.core.imputils import impl_ret_borrowed


@intrinsic
def as_read_only(typingctx, a):
    """``a`` as a read-only array of the same dtype, dimensions and layout (no copy)."""
    if not isinstance(a, types.Array):
        return None
    frozen = a.copy(readonly=True)

    def codegen(context, builder, signature, args):
        return impl_ret_borrowed(context, builder, frozen, args[0])

    return frozen(a), codegen
