"""numba's on-disk cache of the BDF2 Newton: the model's caller is cached (no compile in a new process) and
:func:`~transient.solvers.integrate.cache_guard.drop_stale_cache` empties a cache index older than a file the
cached function inlines."""

import os
import sys
import textwrap

from transient.models.journal.content_newton import bdf2_newton
from transient.models.journal.orbit import JournalOrbit
from transient.models.journal.bearing import JournalBearing
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.integrate.cache_guard import drop_stale_cache
from transient import Integration


def test_journal_bdf2_newton_is_saved_in_the_disk_cache():
    """A dispatcher handed to a non-inlined function is a dynamic global, and numba refuses to cache its caller:
    after a BDF2 run the caller's cache index must hold its compiled signature."""
    b = JournalBearing(**BEARING, grid=(12, 4))
    r = JournalOrbit(b, ROTOR["rotor_mass"], 0.3 * BEARING["clearance"], ROTOR["load"], 6000.0).run(
        0.05, integration=Integration(method="bdf2"))
    assert r.success
    assert bdf2_newton.signatures
    index = bdf2_newton._cache._cache_file._load_index()
    assert any(key[0] == sig for sig in bdf2_newton.signatures for key in index), \
        f"bdf2_newton not in its cache index ({len(index)} entries)"


def test_drop_stale_cache_empties_an_index_older_than_an_inlined_file(tmp_path, monkeypatch):
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "cache"))
    callee = tmp_path / "callee_mod.py"
    callee.write_text("from numba import njit\n\n@njit(inline='always')\ndef twice(x):\n    return 2 * x\n")
    (tmp_path / "caller_mod.py").write_text(textwrap.dedent("""
        from numba import njit
        from callee_mod import twice

        @njit(cache=True)
        def f(x):
            return twice(x) + 1
        """))
    monkeypatch.syspath_prepend(str(tmp_path))
    import numba.core.config
    monkeypatch.setattr(numba.core.config, "CACHE_DIR", str(tmp_path / "cache"))
    import caller_mod
    try:
        assert caller_mod.f(3) == 7
        index = caller_mod.f._cache._cache_file._index_path
        assert os.path.exists(index) and caller_mod.f._cache._cache_file._load_index()
        assert not drop_stale_cache(caller_mod.f, str(callee))  # the callee is older than the index
        later = os.path.getmtime(index) + 10.0
        os.utime(callee, (later, later))
        assert drop_stale_cache(caller_mod.f, str(callee))
        assert caller_mod.f._cache._cache_file._load_index() == {}
    finally:
        sys.modules.pop("caller_mod", None)
        sys.modules.pop("callee_mod", None)
