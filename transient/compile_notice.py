"""A one-line notice before the first run compiles numba kernels: "compiling kernels once (~N s)", then one line
per kernel compiled (its name and seconds), printed only when numba's on-disk cache holds no compiled code for the
model family's main kernel (a fresh install, a changed kernel source, or a new ``NUMBA_CACHE_DIR``).

The seconds of ``FAMILIES`` are measured cold compile times (fresh ``NUMBA_CACHE_DIR``, an idle 2-core machine;
README, section "How long things take"); a warm start loads the cached machine code in about a second.
"""

from __future__ import annotations

import importlib
import sys

#: family -> (module, kernel whose cache entry says whether the family is compiled, cold compile seconds measured
#: with a fresh cache on an idle 2-core machine (a busy one takes several times longer))
FAMILIES = {
    "journal": ("transient.models.journal.kernels", "dae_residual", 10),
    "ball": ("transient.models.ball.front", "front_kernel", 5),
    "roller": ("transient.models.ehl.rows", "rows_kernel", 5),
    "layered": ("transient.physics.layered", "gecim_face_2d", 25),
    "bdf2": ("transient.models.journal.content_newton", "bdf2_newton", 30),
    "rotor_bdf2": ("transient.models.rotor.content_newton", "rotor_newton", 30),
}


def is_cold(family: str) -> bool:
    """True when the on-disk cache holds no compiled code for ``family``'s kernel of ``FAMILIES``."""
    module, kernel, _ = FAMILIES[family]
    try:
        dispatcher = getattr(importlib.import_module(module), kernel)
        return not dispatcher._cache._cache_file._load_index()  # empty: no entry, or a stale one (source changed)
    except Exception:  # a cache numba cannot read counts as cold
        return True


def _progress_listener(stream):
    """A numba compile-event listener writing one line per compiled top-level kernel (name, seconds)."""
    import time

    from numba.core import event

    class Progress(event.Listener):
        def __init__(self):
            self.depth, self.start = 0, 0.0

        def on_start(self, ev):
            if self.depth == 0:
                self.start = time.perf_counter()
            self.depth += 1

        def on_end(self, ev):
            self.depth -= 1
            if self.depth == 0:
                name = getattr(ev.data.get("dispatcher"), "__name__", "kernel")
                stream.write(f"  compiled {name} ({time.perf_counter() - self.start:.1f} s)\n")
                stream.flush()

    return Progress()


def announce(*families: str, stream=None) -> bool:
    """Print the notice (to stderr) when any of ``families`` is cold, then one line per kernel compiled; returns
    whether it was printed."""
    stream = stream or sys.stderr
    cold = [f for f in families if is_cold(f)]
    if not cold:
        return False
    seconds = sum(FAMILIES[f][2] for f in cold)
    stream.write(f"compiling kernels once (~{seconds} s on an idle 2-core machine, longer on a busy one; cached for the "
                 "next runs)\n")
    stream.flush()
    try:
        from numba.core import event

        event.register("numba:compile", _progress_listener(stream))
    except Exception:  # numba without the event API: the notice without progress
        pass
    return True
