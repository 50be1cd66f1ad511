"""What every scenario script shares: one argument parser (``--quick``, ``--out``; ``--help`` runs nothing)
and a JSON record of its numbers rewritten atomically after every stage, so a crash loses at most one stage
and ``--resume`` reuses what is there when the settings match."""

from __future__ import annotations

import argparse
import json
import os
import tempfile
from pathlib import Path

import numpy as np


def parser(doc: str, default_out) -> argparse.ArgumentParser:
    """The scenario's parser: its docstring as the help, ``--quick`` (coarse and fast) and ``--out DIR``."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="coarse, fast version (minutes at most)")
    ap.add_argument("--out", default=str(default_out), help=f"output folder (default: {default_out})")
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
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        meta = json.loads(json.dumps(meta, default=_plain))
        self.data = {"meta": meta}
        if resume and self.path.exists():
            old = json.loads(self.path.read_text())
            if old.get("meta") == meta:
                self.data = old
                log(f"resuming from {self.path}")
            else:
                log(f"{self.path} was written with other settings: starting afresh")

    def put(self, key, value):
        self.data[key] = json.loads(json.dumps(value, default=_plain))
        self.save()

    def save(self):
        fd, tmp = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".tmp", dir=self.path.parent)
        with os.fdopen(fd, "w") as fh:
            json.dump(self.data, fh, indent=1)
        os.replace(tmp, self.path)
