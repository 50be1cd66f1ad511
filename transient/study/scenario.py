"""What every scenario script shares: one argument parser (``--quick``, ``--out``; ``--help`` runs nothing),
one output root, and a JSON record of its numbers rewritten atomically after every stage, so a crash loses at
most one stage and ``--resume`` reuses what is there when the settings match.

Outputs go under one root, :func:`default_root` (``./transient_out`` in the current folder, or the
environment variable ``TRANSIENT_OUT``; never the source tree): a scenario into ``ROOT/NAME/``, its
``--quick`` run into ``ROOT/NAME/quick/`` (a quick run never overwrites the full run's figures), a scene
into ``ROOT/SCENE/``, a sweep into ``ROOT/sweep_KIND/``. ``--out DIR`` replaces ``ROOT/NAME``."""

from __future__ import annotations

import argparse
import contextlib
import json
import os
from pathlib import Path

import numpy as np


#: the output root's folder name in the current folder
OUT_ROOT = "transient_out"


def default_root() -> Path:
    """The output root: ``$TRANSIENT_OUT`` if set, else ``./transient_out`` (relative to the current folder)."""
    return Path(os.environ.get("TRANSIENT_OUT") or OUT_ROOT)


class _ScenarioParser(argparse.ArgumentParser):
    """Fills ``--out``: ``ROOT/NAME`` by default, ``.../quick`` for a ``--quick`` run without ``--out``."""

    def parse_args(self, args=None, namespace=None):
        a = super().parse_args(args, namespace)
        if getattr(a, "out", None) is None:
            a.out = str(default_root() / self.output_name / ("quick" if getattr(a, "quick", False) else ""))
        return a


def parser(doc: str, default_out) -> argparse.ArgumentParser:
    """The scenario's parser: its docstring as the help, ``--quick`` (coarse and fast) and ``--out DIR``.

    ``default_out`` names the scenario's folder (its last part is used: ``ROOT/NAME``, module docstring)."""
    ap = _ScenarioParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.output_name = Path(str(default_out)).name or "scenario"
    where = f"{default_root() / ap.output_name}"
    ap.add_argument("--quick", action="store_true", help=f"coarse, fast version (minutes at most); into {where}/quick "
                                                         "unless --out is given")
    ap.add_argument("--out", default=None, help=f"output folder (default: {where}; the root is $TRANSIENT_OUT or "
                                                f"./{OUT_ROOT})")
    return ap


def log(msg: str):
    print(msg, flush=True)


def _plain(v):
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (np.integer, np.floating, np.bool_)):
        return v.item()
    if isinstance(v, Path):
        return str(v)
    raise TypeError(f"cannot write a {type(v).__name__} to JSON")


class JsonRecord:
    """A dict of a scenario's numbers, written to ``path`` whenever a stage adds to it.

    ``meta`` identifies the settings; with ``resume`` an existing file with the same meta is continued."""

    def __init__(self, path, meta: dict, resume: bool = False):
        from transient.results import file_error

        self.path = Path(path)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise file_error(e, self.path.parent, "create the folder") from None
        meta = json.loads(json.dumps(meta, default=_plain))
        self.data = {"meta": meta}
        if resume and self.path.exists():
            try:
                old = json.loads(self.path.read_text())
            except (OSError, ValueError, RecursionError) as e:
                old = {}
                log(f"{self.path} cannot be read ({type(e).__name__}): starting afresh")
            if isinstance(old, dict) and old.get("meta") == meta:
                self.data = old
                log(f"resuming from {self.path}")
            else:
                log(f"{self.path} was written with other settings: starting afresh")

    def put(self, key, value):
        self.data[key] = json.loads(json.dumps(value, default=_plain))
        self.save()

    def save(self):
        from transient.results import atomic_write

        text = json.dumps(self.data, indent=1).encode()
        atomic_write(self.path, lambda fh: fh.write(text))


@contextlib.contextmanager
def fresh_advice():
    """Inside it, a checkpoint that cannot be resumed (:class:`~transient.solvers.longrun.CheckpointError`) says
    what to do on the command line: run the same command with ``--fresh`` (not the Python keyword
    ``resume=False``)."""
    from transient.solvers.longrun import CheckpointError

    try:
        yield
    except CheckpointError as e:
        text = str(e).replace("delete it or run with resume=False to start afresh",
                              "run the same command with --fresh to start afresh")
        raise CheckpointError(text) from None
