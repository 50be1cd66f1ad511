"""Guard of numba's on-disk cache for a kernel that inlines code from other files.

numba keys a cached function on its own source file's stamp (modification time and size) and on its own
bytecode. A function that inlines another module's functions (``inline="always"``, as the BDF2 stepper's
:func:`~transient.solvers.integrate.bdf2.newton_step` is inlined into each model's Newton caller) would therefore
load stale machine code after an edit of the inlined module. :func:`drop_stale_cache` empties such a function's
cache index when one of the files it inlines is newer than the index, so the next call compiles again.
"""

from __future__ import annotations

import os


def drop_stale_cache(dispatcher, *sources: str) -> bool:
    """Empty the cache index of the numba ``dispatcher`` if any file in ``sources`` was modified after it was
    written; returns whether it did. A dispatcher without a cache or an index does nothing."""
    cache = getattr(dispatcher, "_cache", None)
    index = getattr(getattr(cache, "_cache_file", None), "_index_path", None)
    if index is None or not os.path.exists(index):
        return False
    written = os.path.getmtime(index)
    if all(os.path.getmtime(s) <= written for s in sources):
        return False
    cache.flush()
    return True
