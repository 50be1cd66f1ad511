"""One base for every result: named series with units, status and message, the final state with its time,
save/load in an open format without pickle, a one-screen summary and a DataFrame view.

A result type is a dataclass deriving from :class:`Result`, declared with :func:`result_type`. Units are declared per field with
:func:`quantity` (``x: np.ndarray = quantity("m")``); fields without a unit are dimensionless or
non-numeric. Every result answers ``success`` / ``message`` (a failed or stopped run says why), declared once
by :class:`StatusResult`; a run in time derives from :class:`RunResult` (``t``, ``stats``, ``final_state`` and
``final_time`` [s] to continue from, ``a + b`` to join chunks), a steady solve from :class:`SteadyResult`
(``iterations``, ``residual_norms``).

Files: :meth:`Result.save` writes one ``.npz`` (a zip of ``.npy`` arrays, readable by any numpy without
this package) holding every array field and a JSON document ``__meta__`` with the class, the scalar fields,
the units and the package version; :func:`load_result` reads it back with ``allow_pickle=False``, so a
crafted file cannot run code, and rebuilds only classes registered here (subclasses of :class:`Result`),
reading a regular file only, every array bounded by its declared size, and the result checked against its
class's fields, their types and its declared ``shapes`` and ``labels`` (:func:`check_result`).
"""

from __future__ import annotations

import dataclasses
import errno
import hashlib
import json
import math
import os
import stat
import tempfile
import zipfile
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from transient._version import __version__
from transient.checks import MEMORY_SHARE, memory_limit, short_repr

FORMAT = "transient-result/1"
_REGISTRY: dict[str, type] = {}


def quantity(unit: str, default: Any = dataclasses.MISSING, *, repr: bool = True, default_factory=dataclasses.MISSING):
    """A dataclass field carrying its unit (``field.metadata["unit"]``)."""
    kw = dict(metadata={"unit": unit}, repr=repr)
    if default is not dataclasses.MISSING:
        kw["default"] = default
    if default_factory is not dataclasses.MISSING:
        kw["default_factory"] = default_factory
    return dataclasses.field(**kw)


def result_type(cls=None, /, **kw):
    """``@result_type``: a dataclass that keeps :class:`Result`'s short repr and identity equality
    (array fields make the generated ``__eq__`` ambiguous)."""
    kw.setdefault("repr", False)
    kw.setdefault("eq", False)
    wrap = lambda c: dataclasses.dataclass(c, **kw)  # noqa: E731
    return wrap if cls is None else wrap(cls)


class ResultFileError(ValueError):
    """A result file that cannot be read: truncated, corrupted, foreign or of an unknown type."""


class Result:
    """Base of the package's results (see the module docstring). Subclasses are dataclasses."""

    #: name of the series indexing the rows of :meth:`to_dataframe` (None: no time axis)
    time_axis: ClassVar[str | None] = "t"
    #: declared shapes of array (and list) fields, merged over the class's bases: ``field -> axes``, each axis
    #: an int (that length), the name of a field (that field's length, e.g. the time axis ``"t"`` or
    #: ``"nodes"``), another name (a length every field naming it shares) or None (any length). A field whose
    #: first axis is the time axis is a series; the series of a successful run (:class:`RunResult`) are finite.
    #: Checked by :func:`check_result` when a file is loaded.
    shapes: ClassVar[dict] = {}
    #: fields holding labels (distinct integers), merged over the bases: ``field -> None``, or the name of the
    #: field whose labels they must be taken from
    labels: ClassVar[dict] = {}

    def __init_subclass__(cls, **kw):
        super().__init_subclass__(**kw)
        _REGISTRY[cls.__name__] = cls

    # status ---------------------------------------------------------------------------------------
    @property
    def ok(self) -> bool:
        return bool(getattr(self, "success", True))

    # units ----------------------------------------------------------------------------------------
    @classmethod
    def units(cls) -> dict[str, str]:
        """Unit of every field that declares one."""
        return {f.name: f.metadata["unit"] for f in dataclasses.fields(cls) if "unit" in f.metadata}

    # summary / repr -------------------------------------------------------------------------------
    def summary(self) -> dict:
        """The scalar fields (numbers, strings, booleans, None) as a JSON-ready dict."""
        out = {}
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if _is_scalar(v):
                out[f.name] = _plain(v)
        return out

    def __repr__(self) -> str:
        units = self.units()
        parts = []
        for f in dataclasses.fields(self):
            if not f.repr:
                continue
            v = getattr(self, f.name)
            u = f" {units[f.name]}" if f.name in units and units[f.name] not in ("", "-") and v is not None else ""
            if isinstance(v, np.ndarray):
                parts.append(f"{f.name}=<{v.dtype} {'x'.join(map(str, v.shape))}>{u}")
            elif _is_scalar(v):
                parts.append(f"{f.name}={_short(v)}{u}")
            elif isinstance(v, dict):
                parts.append(f"{f.name}={{{', '.join(map(str, v))}}}")
            elif dataclasses.is_dataclass(v):
                parts.append(f"{f.name}={type(v).__name__}(...)")
            else:
                parts.append(f"{f.name}=<{type(v).__name__}>")
        return f"{type(self).__name__}(" + ", ".join(parts) + ")"

    # tables ---------------------------------------------------------------------------------------
    def to_dataframe(self):
        """The series that share the time axis as a ``pandas.DataFrame`` (one row per output time;
        an (n, k) series becomes k columns ``name_0 .. name_k-1``); units in ``df.attrs["units"]``."""
        import pandas as pd

        if self.time_axis is None:
            raise TypeError(f"{type(self).__name__} has no time axis to tabulate")
        t = np.asarray(getattr(self, self.time_axis))
        units = self.units()
        cols, col_units = {}, {}
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if not isinstance(v, np.ndarray) or v.ndim == 0 or v.shape[0] != t.shape[0] or v.ndim > 2:
                continue
            if v.ndim == 1:
                cols[f.name] = v
                col_units[f.name] = units.get(f.name, "")
            else:
                for j in range(v.shape[1]):
                    cols[f"{f.name}_{j}"] = v[:, j]
                    col_units[f"{f.name}_{j}"] = units.get(f.name, "")
        df = pd.DataFrame(cols)
        df.attrs["units"] = col_units
        return df

    # files ----------------------------------------------------------------------------------------
    def save(self, path) -> Path:
        """Write the result to ``path`` (``.npz`` appended if missing), atomically; returns the path."""
        path = Path(path)
        if path.suffix != ".npz":
            path = path.with_name(path.name + ".npz")
        arrays: dict[str, np.ndarray] = {}
        meta = {"format": FORMAT, "class": type(self).__name__, "version": _version(), "units": self.units(),
                "fields": {}}
        for f in dataclasses.fields(self):
            meta["fields"][f.name] = _encode(getattr(self, f.name), f.name, arrays)
        arrays["__meta__"] = np.array(json.dumps(meta, allow_nan=True))
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise file_error(e, path.parent, "create the folder") from None
        return atomic_savez(path, arrays)


def atomic_savez(path, arrays: dict) -> Path:
    """``np.savez`` of ``arrays`` to ``path`` by :func:`atomic_write`."""
    return atomic_write(path, lambda fh: np.savez(fh, **arrays))


def atomic_write(path, write) -> Path:
    """``write(fh)`` into a unique temporary file (binary) in the same folder, then rename: a reader (or a
    crash) never sees a half-written file, and two writers never share a temporary file. The temporary file
    carries the writer's process id; temporary files of this ``path`` left by processes that no longer run
    (killed during a write) are removed first. An OS fault (full disk, read-only folder) raises
    :class:`FileFault` naming ``path`` and what to do, and leaves the previous file as it was."""
    path = Path(path)
    remove_stale_temporaries(path)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=path.parent)
    except OSError as e:
        raise file_error(e, path, "write") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
        os.replace(tmp, path)
    except BaseException as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        if isinstance(e, OSError):
            raise file_error(e, path, "write") from None
        raise
    return path


def remove_stale_temporaries(path) -> int:
    """Remove the temporary files ``.NAME.PID.*.tmp`` of ``path`` whose writing process no longer runs (on
    this machine); returns how many were removed. In-flight files of live writers are left alone."""
    path = Path(path)
    removed = 0
    try:
        candidates = list(path.parent.glob(f".{path.name}.*.tmp"))
    except OSError:
        return 0
    for f in candidates:
        pid = f.name[len(path.name) + 2:].split(".", 1)[0]
        if not pid.isdigit() or _alive(int(pid)):
            continue
        try:
            f.unlink()
            removed += 1
        except OSError:
            pass
    return removed


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


_ADVICE = {errno.ENOSPC: "the disk is full: free space or choose a folder on another disk",
           errno.EDQUOT: "the disk quota is exceeded: free space or choose a folder on another disk",
           errno.EROFS: "the file system is read-only: choose a writable folder",
           errno.EACCES: "permission denied: choose a folder you can write to",
           errno.EPERM: "permission denied: choose a folder you can write to",
           errno.ENOTDIR: "a part of the path is a file, not a folder: choose another path",
           errno.EEXIST: "a file of that name is in the way: choose another path or remove the file",
           errno.EISDIR: "it is a folder: choose a file name",
           errno.ENOENT: "the folder does not exist: create it or choose another path"}


class FileFault(OSError):
    """An OS fault on a file, in one line: the path, the OS's reason and what to do (``errno`` kept)."""

    def __str__(self):
        return str(self.strerror)


def file_error(e: OSError, path, action: str = "write") -> FileFault:
    """A one-line :class:`FileFault` of the same errno naming ``path``, the OS's reason and what to do."""
    if isinstance(e, FileFault):
        return e
    reason = e.strerror or str(e)
    advice = _ADVICE.get(e.errno, "check the path and the disk")
    return FileFault(e.errno, f"cannot {action} {path}: {reason}; {advice}")


# --------------------------------------------------------------------------------------------------
# reading .npz files safely: declared shapes and dtypes, a size cap, no pickle
# --------------------------------------------------------------------------------------------------

def load_cap() -> int:
    """The most bytes a loaded file may expand to: :data:`~transient.checks.MEMORY_SHARE` of the machine's
    memory (:func:`~transient.checks.machine_memory`)."""
    return memory_limit()


#: the most a file's arrays may expand beyond its size on disk (:meth:`Result.save` stores them uncompressed;
#: a file compressed afterwards shrinks a few times, a deflate bomb up to a thousand times) ...
MAX_EXPANSION = 100
#: ... once they expand to more than this [bytes] (below it any file is harmless)
EXPANSION_FLOOR = 16 * 1024 ** 2
#: bytes read from a zip member at a time
_CHUNK = 1 << 22

_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISSOCK, "a socket"))


class NotARegularFile(ValueError):
    """A path that is not a regular file (a device, a FIFO, a folder): never opened for reading. ``kind``
    says what it is (e.g. ``"a FIFO (named pipe)"``)."""

    def __init__(self, kind: str):
        super().__init__(f"not a regular file but {kind}")
        self.kind = kind


def open_regular(path):
    """Open ``path`` for binary reading if it is a regular file, else raise :class:`NotARegularFile` saying what
    it is. Checked before opening (a device or FIFO is never opened) and again on the opened descriptor, which
    is opened non-blocking (a FIFO swapped in between cannot block)."""
    def kind(mode):
        return next((name for test, name in _KINDS if test(mode)), "a special file")

    mode = os.stat(path).st_mode
    if not stat.S_ISREG(mode):
        raise NotARegularFile(kind(mode))
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        raise NotARegularFile(kind(mode))
    return os.fdopen(fd, "rb")


class NpzReader:
    """An ``.npz`` file opened once (a regular file only: :func:`open_regular`) and read with bounds: each
    member's ``.npy`` header (dtype, shape) is read without decompressing the data and must agree with the
    member's uncompressed size in the zip directory; an array is read into a buffer of exactly its header's
    size (the zip reader stops at the directory's size, so no header can make it inflate more). ``ValueError``
    (without the path: callers name the file) on anything foreign or damaged."""

    def __init__(self, path):
        self.fh = open_regular(path)
        try:
            self.size = os.fstat(self.fh.fileno()).st_size
            self.zip = zipfile.ZipFile(self.fh)
            self.heads = {}
            for info in self.zip.infolist():
                if not info.filename.endswith(".npy"):
                    raise ValueError(f"member {info.filename!r} is not an array")
                self.heads[info.filename[:-4]] = self._header(info)
        except BaseException:
            self.close()
            raise

    def _header(self, info):
        with self.zip.open(info) as fh:
            version = np.lib.format.read_magic(fh)
            if version == (1, 0):
                shape, fortran, dtype = np.lib.format.read_array_header_1_0(fh)
            elif version == (2, 0):
                shape, fortran, dtype = np.lib.format.read_array_header_2_0(fh)
            else:
                raise ValueError(f"array {info.filename!r}: .npy version {version}")
            offset = fh.tell()
        shape = tuple(shape)
        nbytes = math.prod(shape) * dtype.itemsize
        if not dtype.hasobject and info.file_size != offset + nbytes:
            raise ValueError(f"member {info.filename!r} expands to {info.file_size} bytes, but its .npy header "
                             f"declares {offset} + {nbytes} ({dtype.str} {list(shape)})")
        return dtype, shape, bool(fortran), offset

    def headers(self) -> dict:
        """``name -> (dtype, shape)`` of every array."""
        return {name: (dtype, shape) for name, (dtype, shape, _, _) in self.heads.items()}

    def read(self, name: str) -> np.ndarray:
        """The array ``name``, read in chunks into a buffer of its declared size (no object arrays)."""
        dtype, shape, fortran, offset = self.heads[name]
        if dtype.hasobject:
            raise ValueError(f"array {name!r} holds Python objects (refused: loading them would need pickle)")
        nbytes = math.prod(shape) * dtype.itemsize
        buf = np.empty(nbytes, dtype=np.uint8)
        with self.zip.open(name + ".npy") as fh:
            fh.read(offset)
            view, done = memoryview(buf), 0
            while done < nbytes:
                n = fh.readinto(view[done:done + _CHUNK])
                if not n:
                    raise ValueError(f"array {name!r} is truncated ({done} of {nbytes} bytes)")
                done += n
        if dtype.itemsize == 0:
            return np.zeros(shape, dtype=dtype)
        return buf.view(dtype).reshape(shape, order="F" if fortran else "C")

    def close(self):
        if getattr(self, "zip", None) is not None:
            self.zip.close()
        self.fh.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def npz_headers(path) -> dict:
    """``name -> (dtype, shape)`` of every array of an ``.npz`` file, read from the ``.npy`` headers only
    (nothing is decompressed beyond the headers). Raises ``ValueError`` on a foreign or damaged file, or a
    path that is not a regular file."""
    with NpzReader(path) as z:
        return z.headers()


def read_npz(path, *, wanted=None, declared: dict | None = None, cap: int | None = None, what: str = "file") -> dict:
    """Read arrays of an ``.npz`` file after checking their headers: no object arrays, every ``declared``
    name present with its declared ``(dtype, shape)``, and the arrays read (``wanted``: names, default all)
    together at most ``cap`` bytes once expanded (default :func:`load_cap`) and at most :data:`MAX_EXPANSION`
    times the file's size (above :data:`EXPANSION_FLOOR`). ``path`` may be an open :class:`NpzReader`.
    Raises ``ValueError`` (without the path: callers name the file) saying what is wrong."""
    if not isinstance(path, NpzReader):
        with NpzReader(path) as z:
            return read_npz(z, wanted=wanted, declared=declared, cap=cap, what=what)
    z = path
    cap = load_cap() if cap is None else int(cap)
    heads = z.headers()
    names = list(heads) if wanted is None else [n for n in wanted]
    for name in names:
        if name not in heads:
            raise ValueError(f"array {name!r} missing")
    total = 0
    for name in names:
        dtype, shape = heads[name]
        if dtype.hasobject:
            raise ValueError(f"array {name!r} holds Python objects (refused: loading them would need pickle)")
        if declared and declared.get(name) is not None:
            d_dtype, d_shape = declared[name]
            if np.dtype(d_dtype) != dtype or tuple(d_shape) != shape:
                raise ValueError(f"array {name!r} is {dtype.str} {list(shape)} but declared {np.dtype(d_dtype).str} "
                                 f"{list(d_shape)}")
        total += math.prod(shape) * dtype.itemsize
    if total > cap:
        raise ValueError(f"its arrays expand to {total / 1e9:.3g} GB, more than the cap of {cap / 1e9:.3g} GB "
                         f"({MEMORY_SHARE:.0%} of this machine's memory)")
    if total > max(MAX_EXPANSION * z.size, EXPANSION_FLOOR):
        raise ValueError(f"its arrays expand to {total / 1e6:.4g} MB, {total / max(z.size, 1):.0f} times the "
                         f"{z.size / 1e6:.3g} MB on disk (refused: more than {MAX_EXPANSION} times is a compression "
                         "bomb; files written by save() are not compressed)")
    return {name: z.read(name) for name in names}


def _content_digest(arrays: dict) -> str:
    """SHA-256 over the names, dtypes, shapes and bytes (C order) of ``arrays`` (in name order), streamed:
    contiguous arrays are hashed in place, others a block of rows at a time (no copy of a whole array)."""
    h = hashlib.sha256()
    for name in sorted(arrays):
        a = np.asarray(arrays[name])
        h.update(f"{name}|{a.dtype.str}|{a.shape}|".encode())
        if a.flags.c_contiguous:
            flat = a.reshape(-1).view(np.uint8)
            for i in range(0, flat.size, _CHUNK):
                h.update(flat[i:i + _CHUNK])
        else:
            rows = max(1, _CHUNK // max(1, a[0].nbytes))
            for i in range(0, a.shape[0], rows):
                h.update(np.ascontiguousarray(a[i:i + rows]).reshape(-1).view(np.uint8))
    return h.hexdigest()


_CODE_VERSION = None


def code_version() -> str:
    """The package version and a hash of its source files (any code change changes it)."""
    global _CODE_VERSION
    if _CODE_VERSION is None:
        h = hashlib.sha256()
        root = Path(__file__).parent  # the package's folder
        for f in sorted(root.rglob("*.py")):
            h.update(str(f.relative_to(root)).encode())
            h.update(f.read_bytes())
        _CODE_VERSION = f"{__version__}+{h.hexdigest()[:12]}"
    return _CODE_VERSION


def load_result(path, *, max_bytes: int | None = None) -> Result:
    """Read a result written by :meth:`Result.save` (no pickle; only this package's result types).

    Only a regular file is opened (a device, a FIFO or a folder is refused by what it is). Before any array is
    decompressed, the metadata is checked (a JSON object of this format naming a registered class, with its
    ``fields``) and every array's dtype and shape read from its header are checked against the metadata's
    declaration, against the member's size in the zip directory and, all together, against ``max_bytes``
    (default: half the machine's memory) and :data:`MAX_EXPANSION` times the file's size; each array is read
    into a buffer of its declared size; arrays the metadata does not name are not read. The result is then
    checked against its class (:func:`check_result`): every field the class has and no other, each of its
    declared type, numeric fields (those with a unit) holding numbers, the time axis one-dimensional, the
    declared shapes and labels. Anything else raises :class:`ResultFileError` naming the file (the result
    types are registered when ``transient`` is imported, which importing this module already did)."""

    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"result file not found: {path}")
    try:
        z = NpzReader(path)
    except NotARegularFile as e:
        raise ResultFileError(f"{path}: {e}; load_result reads the .npz files that Result.save writes") from None
    except Exception as e:  # zipfile / numpy errors on a truncated or foreign file
        raise ResultFileError(f"{path}: not a readable result file ({type(e).__name__}: {_one_line(e)})") from None
    with z:
        return _load(z, path, max_bytes)


def _load(z: NpzReader, path: Path, max_bytes) -> Result:
    heads = z.headers()
    try:
        if "__meta__" not in heads:
            raise ResultFileError(f"{path}: not a transient result file (no __meta__ entry)")
        dtype, shape = heads["__meta__"]
        if dtype.kind != "U" or shape != () or dtype.itemsize > 64 * 1024 ** 2:
            raise ResultFileError(f"{path}: not a transient result file (__meta__ is {dtype.str} {list(shape)})")
        meta_text = str(read_npz(z, wanted=["__meta__"])["__meta__"])
    except ResultFileError:
        raise
    except Exception as e:  # zipfile / numpy errors on a truncated or foreign file
        raise ResultFileError(f"{path}: not a readable result file ({type(e).__name__}: {_one_line(e)})") from None
    try:
        meta = json.loads(meta_text)
    except (ValueError, RecursionError) as e:
        raise ResultFileError(f"{path}: corrupted metadata ({type(e).__name__}: {_one_line(e)})") from None
    if not isinstance(meta, dict):
        raise ResultFileError(f"{path}: corrupted metadata (a JSON {type(meta).__name__}, not an object)")
    if meta.get("format") != FORMAT:
        raise ResultFileError(f"{path}: unknown format {short_repr(meta.get('format'))} (expected {FORMAT})")
    cls = _REGISTRY.get(meta.get("class")) if isinstance(meta.get("class"), str) else None
    if cls is None:
        raise ResultFileError(f"{path}: unknown result type {short_repr(meta.get('class'))}")
    fields = meta.get("fields")
    if not isinstance(fields, dict):
        raise ResultFileError(f"{path}: corrupted metadata (no 'fields' object)")
    invalid = f"{path}: not a valid {cls.__name__} file"
    try:
        declared = {}
        _declared_arrays(fields, declared, 0)
        missing = [name for name in declared if name not in heads]
        if missing:
            raise ValueError(f"array {missing[0]!r} missing")
    except (ValueError, TypeError, RecursionError) as e:
        raise ResultFileError(f"{invalid} ({type(e).__name__}: {_one_line(e)})") from None
    try:
        data = read_npz(z, wanted=list(declared), declared=declared, cap=max_bytes)
    except Exception as e:  # the headers' checks, a damaged member (CRC, truncated deflate stream)
        raise ResultFileError(f"{invalid} ({type(e).__name__}: {_one_line(e)})") from None
    try:
        obj = _build(cls, fields, data, path)
    except ResultFileError:
        raise
    except FieldError as e:
        raise ResultFileError(f"{invalid}: {_one_line(e)}") from None
    except (ValueError, TypeError, KeyError, AttributeError, IndexError, RecursionError) as e:
        raise ResultFileError(f"{invalid} ({type(e).__name__}: {_one_line(e)})") from None
    return obj


def _build(cls, fields: dict, data: dict, path):
    """The ``cls`` instance of decoded ``fields``, checked against its class (:func:`check_result`)."""
    names = {f.name for f in dataclasses.fields(cls)}
    unknown = [name for name in fields if name not in names]
    if unknown:
        raise FieldError(f"field {unknown[0]!r} is not a field of {cls.__name__}")
    init = {f.name for f in dataclasses.fields(cls) if f.init}
    kwargs = {}
    for name, enc in fields.items():
        if name in init:
            try:
                kwargs[name] = _decode(enc, data, path)
            except FieldError as e:  # in a nested result or record
                raise FieldError(f"in field {name!r}: {e}") from None
    _check_fields(cls, kwargs)
    obj = cls(**kwargs)
    for f in dataclasses.fields(cls):  # non-init fields (derived at construction) are set as saved
        if not f.init and f.name in fields:
            object.__setattr__(obj, f.name, _decode(fields[f.name], data, path))
    check_result(obj)
    return obj


def _one_line(e) -> str:
    text = " ".join(str(e).split())
    return text if len(text) <= 200 else text[:197] + "..."


_MAX_DEPTH = 32


def _declared_arrays(enc, out: dict, depth: int):
    """Collect ``name -> (dtype, shape)`` of every array the encoded fields declare (``None`` if the file is
    older and declares no dtype/shape); ``ValueError`` on a malformed encoding or nesting deeper than 32."""
    if depth > _MAX_DEPTH:
        raise ValueError(f"fields nested deeper than {_MAX_DEPTH} levels")
    if isinstance(enc, dict) and "array" in enc:
        name = enc["array"]
        if not isinstance(name, str):
            raise ValueError(f"array name {short_repr(name)} is not a string")
        if "dtype" in enc or "shape" in enc:
            dtype, shape = enc.get("dtype"), enc.get("shape")
            if not isinstance(dtype, str) or not isinstance(shape, list) or not all(
                    isinstance(n, int) and not isinstance(n, bool) and n >= 0 for n in shape):
                raise ValueError(f"array {name!r}: malformed declaration dtype={short_repr(dtype)}, "
                                 f"shape={short_repr(shape)}")
            out[name] = (np.dtype(dtype), tuple(shape))
        else:
            out[name] = None
        return
    if isinstance(enc, dict):
        for v in enc.values():
            if isinstance(v, (dict, list)):
                _declared_arrays(v, out, depth + 1)
    elif isinstance(enc, list):
        for v in enc:
            if isinstance(v, (dict, list)):
                _declared_arrays(v, out, depth + 1)


class FieldError(ValueError):
    """A loaded field that does not fit its class's declaration (the message names the field)."""


def _check_fields(cls, kwargs: dict):
    """Array fields declared with a unit hold numbers; the time axis is one-dimensional; every required
    field is present (``ValueError`` naming the field)."""
    units = {f.name: f.metadata["unit"] for f in dataclasses.fields(cls) if "unit" in f.metadata}
    for f in dataclasses.fields(cls):
        if not f.init:
            continue
        if f.name not in kwargs:
            if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING:
                raise FieldError(f"required field {f.name!r} missing")
            continue
        v = kwargs[f.name]
        if f.name in units and isinstance(v, np.ndarray) and v.dtype.kind not in "biufc":
            raise FieldError(f"field {f.name!r} [{units[f.name]}] holds {v.dtype.str}, not numbers")
    axis = getattr(cls, "time_axis", None)
    if axis is not None and isinstance(kwargs.get(axis), np.ndarray) and kwargs[axis].ndim != 1:
        raise FieldError(f"time axis {axis!r} has shape {list(kwargs[axis].shape)}, not one dimension")


def _merged(cls, name: str) -> dict:
    out = {}
    for klass in reversed(cls.__mro__):
        out.update(klass.__dict__.get(name, {}))
    return out


def check_result(obj):
    """Check a result (or a record) against its class: every field of its annotated type (:func:`_type_ok`),
    the time axis one-dimensional and real (on a run also finite and non-decreasing), the declared ``shapes``
    (the series of a successful run finite) and ``labels``. Raises :class:`FieldError` naming the field."""
    cls = type(obj)
    for f in dataclasses.fields(cls):
        v = getattr(obj, f.name)
        why = _type_ok(v, f.type, f.default)
        if why:
            raise FieldError(f"field {f.name!r} holds {_kind(v)}, not {why}")
    if not isinstance(obj, Result):
        return
    run = isinstance(obj, RunResult)
    axis = cls.time_axis if cls.time_axis in {f.name for f in dataclasses.fields(cls)} else None
    t = getattr(obj, axis) if axis else None
    if isinstance(t, np.ndarray):
        if t.ndim != 1 or t.dtype.kind not in "iuf":
            raise FieldError(f"time axis {axis!r} is {t.dtype.str} {list(t.shape)}, not one dimension of reals")
        if run and not np.all(np.isfinite(t)):
            raise FieldError(f"time axis {axis!r} holds {_first_bad(t)}")
        if run and np.any(np.diff(t) < 0):
            raise FieldError(f"time axis {axis!r} decreases at row {int(np.argmax(np.diff(t) < 0)) + 1}")
    sizes = {}
    for name, axes in _merged(cls, "shapes").items():
        v = getattr(obj, name, None)
        if v is None:
            continue
        shape = v.shape if isinstance(v, np.ndarray) else (len(v),) if isinstance(v, (list, tuple)) else None
        if shape is None:
            raise FieldError(f"field {name!r} holds {_kind(v)}, not an array")
        if len(shape) != len(axes):
            first = getattr(obj, axes[0], None) if isinstance(axes[0], str) and axes[0] in obj.__dataclass_fields__ \
                else None
            if shape and shape[0] == 0 and first is not None and len(first) == 0:
                continue  # an empty series (a run without outputs) may have lost its trailing axes
            raise FieldError(f"field {name!r} has {len(shape)} axes {list(shape)}, declared {len(axes)}: {_axes(axes)}")
        for i, (n, want) in enumerate(zip(shape, axes)):
            if want is None:
                continue
            if isinstance(want, str) and want in obj.__dataclass_fields__:
                ref = getattr(obj, want)
                if ref is None:
                    raise FieldError(f"field {name!r} is given without {want!r} (its axis {i})")
                want_n = len(ref) if isinstance(ref, (list, tuple)) or np.ndim(ref) else None
                what = f"{want!r} has {want_n}"
            elif isinstance(want, str):
                want_n = sizes.setdefault(want, n)
                what = f"{want} is {want_n} in the other fields"
            else:
                want_n, what = int(want), f"declared {want}"
            if want_n is not None and n != want_n:
                raise FieldError(f"field {name!r} has shape {list(shape)}, declared {_axes(axes)}: axis {i} is "
                                 f"{n}, {what}")
        if run and obj.ok and axes and axes[0] == axis and isinstance(v, np.ndarray) and v.dtype.kind in "fc" \
                and not np.all(np.isfinite(v)):
            raise FieldError(f"series {name!r} of a successful run holds {_first_bad(v)}")
    labels = _merged(cls, "labels")
    for name, among in labels.items():
        v = getattr(obj, name, None)
        if v is None:
            continue
        items = v.tolist() if isinstance(v, np.ndarray) and v.ndim == 1 else v
        if not isinstance(items, (list, tuple)) or not all(isinstance(k, int) and not isinstance(k, bool)
                                                           for k in items):
            raise FieldError(f"field {name!r} holds {short_repr(v)}, not a list of integer labels")
        if len(set(items)) != len(items):
            raise FieldError(f"field {name!r} = {short_repr(items)} repeats a label")
        pool = getattr(obj, among, None) if among else None
        if among and pool is not None:
            pool = set(pool.tolist() if isinstance(pool, np.ndarray) else pool)
            stray = [k for k in items if k not in pool]
            if stray:
                raise FieldError(f"field {name!r} names {stray[0]}, which is not in {among!r}")


def _first_bad(a: np.ndarray) -> str:
    i = np.unravel_index(int(np.argmin(np.isfinite(a))), a.shape)
    return f"{a[i]} at index {list(map(int, i))}"


def _axes(axes) -> str:
    return "(" + ", ".join("any length" if a is None else str(a) for a in axes) + ")"


def _kind(v) -> str:
    if isinstance(v, np.ndarray):
        return f"an array {v.dtype.str} {list(v.shape)}"
    return f"{type(v).__name__} {short_repr(v)}"


_REAL = (int, float, np.integer, np.floating)


def _real(v) -> bool:
    """A real number: int or float (not bool), or a 0-d real array."""
    if isinstance(v, np.ndarray):
        return v.ndim == 0 and v.dtype.kind in "iuf"
    return isinstance(v, _REAL) and not isinstance(v, (bool, np.bool_))


def _type_ok(v, annotation, default) -> str:
    """'' if ``v`` fits the field's annotation (a string such as ``"np.ndarray | None"``, ``"float"``,
    ``"tuple[float, float]"``, ``"Stats | None"``), else what it should be. The check tells kinds apart (a
    number, a string, an array, a list, a dictionary, a record) rather than Python types: ``int`` and ``float``
    both take any real number, and a scalar, list, dictionary or record may be None (an unset value); an
    array may be None only if the annotation or the default says so. Annotations it does not know
    (``object``, ``Any``, ...) accept anything."""
    text = annotation if isinstance(annotation, str) else getattr(annotation, "__name__", str(annotation))
    kinds = [k.strip() for k in text.split("|")]
    array_kinds = ("np.ndarray", "numpy.ndarray", "ndarray")
    if v is None and ("None" in kinds or default is None or not any(k in array_kinds for k in kinds)):
        return ""
    wants = []
    for k in kinds:
        base = k.split("[", 1)[0].strip()
        if base in array_kinds:
            if isinstance(v, np.ndarray):
                return ""
            wants.append("an array")
        elif base in ("float", "int"):
            if _real(v):
                return ""
            wants.append("a number")
        elif base == "bool":
            if isinstance(v, (bool, np.bool_)):
                return ""
            wants.append("True or False")
        elif base == "str":
            if isinstance(v, str):
                return ""
            wants.append("a string")
        elif base == "dict":
            if isinstance(v, dict):
                return ""
            wants.append("a dictionary")
        elif base in ("list", "tuple"):
            if isinstance(v, (list, tuple)) or (isinstance(v, np.ndarray) and v.ndim == 1):
                n = _tuple_length(k)
                if n is None or (len(v) == n and all(_real(x) for x in v)):
                    return ""
                wants.append(f"{n} numbers")
            else:
                wants.append(f"a {base}")
        elif base in _REGISTRY or base in _RECORDS:
            if isinstance(v, _REGISTRY.get(base) or _RECORDS[base]):
                return ""
            wants.append(f"a {base}")
        elif base != "None":
            return ""  # an annotation without a check (object, Any, a type of another module)
    return " or ".join(wants) if wants else ""


def _tuple_length(annotation: str):
    """``tuple[float, float]`` -> 2 (a fixed-length tuple of numbers); None for any other annotation."""
    if not annotation.startswith("tuple[") or "..." in annotation:
        return None
    parts = [p.strip() for p in annotation[6:-1].split(",")]
    return len(parts) if all(p in ("float", "int") for p in parts) else None


# --------------------------------------------------------------------------------------------------
# encoding of field values: arrays go to the npz, everything else into the JSON metadata
# --------------------------------------------------------------------------------------------------

def _encode(v, key, arrays):
    if isinstance(v, np.ndarray):
        if v.dtype == object:
            raise TypeError(f"field {key!r}: object arrays cannot be saved without pickle")
        arrays[key] = v
        return {"array": key, "dtype": v.dtype.str, "shape": list(v.shape)}
    if isinstance(v, Result) and dataclasses.is_dataclass(v):
        return {"result": type(v).__name__,
                "fields": {f.name: _encode(getattr(v, f.name), f"{key}.{f.name}", arrays)
                           for f in dataclasses.fields(v)}}
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {"record": type(v).__name__,
                "fields": {f.name: _encode(getattr(v, f.name), f"{key}.{f.name}", arrays)
                           for f in dataclasses.fields(v)}}
    if isinstance(v, dict):
        if not all(isinstance(k, str) for k in v):
            raise TypeError(f"field {key!r}: dictionary keys must be strings to be saved")
        return {"dict": {k: _encode(x, f"{key}.{k}", arrays) for k, x in v.items()}}
    if isinstance(v, (list, tuple)):
        if all(_is_scalar(x) for x in v):
            return {"list" if isinstance(v, list) else "tuple": [_plain(x) for x in v]}
        return {("list" if isinstance(v, list) else "tuple") + "_of": [_encode(x, f"{key}.{i}", arrays)
                                                                      for i, x in enumerate(v)]}
    if _is_scalar(v):
        return {"value": _plain(v)}
    raise TypeError(f"field {key!r}: cannot save a {type(v).__name__}")


def _decode(enc, arrays, path):
    if not isinstance(enc, dict):
        raise ValueError(f"field encoding {short_repr(enc)} is not an object")
    if "array" in enc:
        if enc["array"] not in arrays:
            raise ResultFileError(f"{path}: array {enc['array']!r} missing")
        return arrays[enc["array"]]
    if "value" in enc:
        return enc["value"]
    if "list" in enc:
        return list(enc["list"])
    if "tuple" in enc:
        return tuple(enc["tuple"])
    if "list_of" in enc:
        return [_decode(x, arrays, path) for x in enc["list_of"]]
    if "tuple_of" in enc:
        return tuple(_decode(x, arrays, path) for x in enc["tuple_of"])
    if "dict" in enc:
        return {k: _decode(x, arrays, path) for k, x in enc["dict"].items()}
    if "result" in enc or "record" in enc:
        name = enc.get("result") or enc.get("record")
        cls = _REGISTRY.get(name) or _RECORDS.get(name)
        if cls is None:
            raise ResultFileError(f"{path}: unknown record type {name!r}")
        if not isinstance(enc.get("fields"), dict):
            raise ValueError(f"record {name!r} has no 'fields' object")
        return _build(cls, enc["fields"], arrays, path)
    raise ResultFileError(f"{path}: unknown field encoding {sorted(enc)}")


#: plain dataclasses (not Results) that results may contain, e.g. the integrator's Stats
_RECORDS: dict[str, type] = {}


def record_type(cls):
    """Register a plain dataclass that results may hold as a field, so it loads back (decorator)."""
    _RECORDS[cls.__name__] = cls
    return cls


def _is_scalar(v) -> bool:
    return v is None or isinstance(v, (bool, int, float, str, np.integer, np.floating, np.bool_))


def _plain(v):
    if isinstance(v, np.bool_):
        return bool(v)
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, np.floating):
        return float(v)
    return v


def _short(v):
    if isinstance(v, (float, np.floating)) and math.isfinite(v):
        return f"{v:.6g}"
    return repr(_plain(v))


def _version() -> str:
    return __version__


# --------------------------------------------------------------------------------------------------
# the two kinds of result every model returns: a run (a time series) and a steady solve
# --------------------------------------------------------------------------------------------------

@record_type
@dataclasses.dataclass
class Stats:
    """Integrator statistics, counted by the integration facade's own wrappers so they mean the same for every
    method; summed over the chunks of a long run (``a + b``).

    ``None`` means the backend does not report that number (scikit-sundae 1.2 and scipy expose no
    error-test or nonlinear-failure counts; fixed-step RK4 has none by construction, reported as 0).
    """

    n_steps: int = 0
    n_rhs: int = 0
    n_jac: int = 0
    n_error_test_failures: int | None = None
    n_nonlinear_failures: int | None = None
    wall_time: float = 0.0
    callback_time: float = 0.0

    @property
    def callback_share(self) -> float:
        """Fraction of the wall time spent inside the Python callbacks (rhs, residual, Jacobian)."""
        return self.callback_time / self.wall_time if self.wall_time > 0 else 0.0

    def __add__(self, other: "Stats") -> "Stats":
        """Totals of two runs (a count unknown in either stays unknown)."""
        add = lambda a, b: None if a is None or b is None else a + b  # noqa: E731
        return Stats(*(add(getattr(self, f.name), getattr(other, f.name)) for f in dataclasses.fields(Stats)))


@result_type
class StatusResult(Result):
    """Base of every result that can fail: keyword-only ``success`` and ``message`` (a failed or stopped
    computation says why)."""

    _: dataclasses.KW_ONLY
    success: bool = True
    message: str = ""

    #: fields :meth:`record` leaves out besides ``success`` and ``message`` (e.g. a whole run)
    record_skip: ClassVar[tuple] = ()

    def record(self) -> dict:
        """The fields as a JSON-ready dict (arrays as lists), for a study's numbers file."""
        skip = {"success", "message", *self.record_skip}
        return {f.name: (lambda v: v.tolist() if isinstance(v, np.ndarray) else v)(getattr(self, f.name))
                for f in dataclasses.fields(self) if f.name not in skip}


@result_type
class RunResult(StatusResult):
    """Base of the results of a run in time: output times ``t`` [s] (the first field of every run result) and,
    keyword-only, ``success`` / ``message`` (a failed or stopped run says why; the outputs up to the failure
    are kept), the integrator statistics ``stats``, the final state (the model's own variables) and its time
    ``final_time`` [s], from which the model's ``run(..., start=result)`` continues.

    ``a + b`` concatenates two chunks of one run (``b`` continued from ``a``), as PyBaMM's
    ``Solution.__add__``: the series along ``t`` (arrays whose first axis has one row per output time) are
    joined, ``b``'s first output dropped when it repeats ``a``'s last time; the statistics are summed; every
    other field (status, final state and time, the fields named in ``snapshot_fields``: fields at the last
    output only) is ``b``'s."""

    #: array fields that hold one snapshot (e.g. the fields at the last output), never concatenated
    snapshot_fields: ClassVar[tuple[str, ...]] = ()

    shapes = {"final_state": (None,)}

    t: np.ndarray = quantity("s")
    _: dataclasses.KW_ONLY
    stats: Stats | None = dataclasses.field(default_factory=Stats)
    final_state: np.ndarray | None = quantity("-", None, repr=False)
    final_time: float = quantity("s", 0.0)

    def __add__(self, other: "RunResult") -> "RunResult":
        if type(other) is not type(self):
            return NotImplemented
        t0, t1 = np.asarray(self.t), np.asarray(other.t)
        skip = 1 if t0.size and t1.size and t1[0] == t0[-1] else 0
        n0, n1 = t0.shape[0], t1.shape[0]
        out = {}
        for f in dataclasses.fields(self):
            a, b = getattr(self, f.name), getattr(other, f.name)
            if f.name == "stats":
                out[f.name] = b if a is None else a if b is None else a + b
            elif (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.ndim >= 1 and b.ndim >= 1
                  and a.shape[0] == n0 and b.shape[0] == n1 and a.shape[1:] == b.shape[1:]
                  and f.name != "final_state" and f.name not in self.snapshot_fields):
                out[f.name] = np.concatenate([a, b[skip:]])
            else:
                out[f.name] = b
        init = {k: v for k, v in out.items() if k in {f.name for f in dataclasses.fields(self) if f.init}}
        obj = type(self)(**init)
        for f in dataclasses.fields(self):
            if not f.init:
                setattr(obj, f.name, out[f.name])
        return obj


@result_type
class SteadyResult(StatusResult):
    """Base of the results of a steady (time-independent) solve, keyword-only: ``success`` / ``message`` (a
    solve that did not converge says why), the ``iterations`` taken and the ``residual_norms`` per iteration
    (infinity norm of the scaled equations; empty when the solver does not keep them)."""

    time_axis = None
    _: dataclasses.KW_ONLY
    iterations: int = 0
    residual_norms: list = dataclasses.field(default_factory=list)
