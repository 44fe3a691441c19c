"""What the readers and writers share.

* the formats and how a path names one (:func:`format_of`);
* writing to a temporary name and renaming (:func:`write_atomically`);
* a text file read as bytes, in blocks of whole lines (:func:`line_blocks`),
  and the tokens of such a block located with whole-array numpy expressions
  (:func:`scan`): the readers parse numbers block by block, so memory stays
  a small multiple of the arrays read, and a damaged file fails at its first
  inconsistency, not after it has been loaded;
* the mesh built from the arrays read (:func:`finish`), its errors
  prefixed with the file name.
"""

from __future__ import annotations

import contextlib
import io
import os
import secrets
import stat
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import IO, Any

import numpy as np

from ..mesh import Mesh, MeshError
from ..mesh import check_mesh as check_mesh  # (the readers and writers take it from here)
from ..mesh.build import adopted

#: The file formats, by the suffix that names them.
FORMATS = {".obj": "obj", ".off": "off", ".ply": "ply", ".stl": "stl"}

#: Bytes read at a time from a text file (blocks end at a line break).
BLOCK_BYTES = 1 << 20

#: The longest line a text mesh file may have; longer means a damaged or binary file.
MAX_LINE_BYTES = 1 << 24

_BOM = b"\xef\xbb\xbf"


class IgnoredDataWarning(UserWarning):
    """A file holds data a pentanb mesh has no place for (normals, colours, other elements)."""


def as_path(path: Any, caller: str) -> Path:
    """``path`` as a :class:`~pathlib.Path`; a TypeError naming ``caller`` if it is not one."""
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(
            f"{caller} expects a file path (str or os.PathLike), got {type(path).__name__}"
        )
    return Path(path)


def format_of(path: Path, format: str | None) -> str:
    """The format to use for ``path``: ``format`` if given, else the suffix's.

    Raises
    ------
    ValueError
        An unknown ``format``; no ``format`` and a suffix that names none (the
        message names the suffix and the known ones); or a ``format`` that
        contradicts a known suffix.
    """
    suffixes = ", ".join(FORMATS)
    names = ", ".join(FORMATS.values())
    suffix = path.suffix.lower()
    from_suffix = FORMATS.get(suffix)
    if format is None:
        if from_suffix is None:
            shown = repr(suffix) if suffix else "no suffix"
            raise ValueError(
                f"{path}: unknown mesh format ({shown}); use a file ending in {suffixes} "
                f"(any case) or pass format= one of {names}"
            )
        return from_suffix
    if not isinstance(format, str) or format.lower().lstrip(".") not in FORMATS.values():
        raise ValueError(f"unknown mesh format {format!r}; known formats: {names}")
    chosen = format.lower().lstrip(".")
    if from_suffix is not None and from_suffix != chosen:
        raise ValueError(f"{path}: the name ends in {suffix!r} but format={format!r} was asked for")
    return chosen


def write_atomically(path: Path, write: Callable[[IO[bytes]], None]) -> None:
    """Run ``write(file)`` on a new temporary file beside ``path``, then rename it to ``path``.

    The temporary file is created exclusively under a fresh random name
    (never an existing file of the user's) and gets the permissions of the
    file it replaces (a new file: the usual ones, after the umask).  A
    failure (an exception from ``write``, a full disk) removes it and leaves
    an existing ``path`` as it was.

    Raises
    ------
    ValueError
        ``path`` exists and is not a regular file (a directory, a device, a
        FIFO, a socket): it is never replaced.
    """
    try:
        mode: int | None = stat.S_IMODE(os.stat(path).st_mode)
        if not path.is_file():
            raise ValueError(
                f"{path} exists and is not a regular file: pentanb will not replace it"
            )
    except FileNotFoundError:
        mode = None
    stem = os.fsencode(path.name)[:200].decode(errors="ignore")  # room for the suffix
    while True:
        tmp = path.with_name(f".{stem}.{secrets.token_hex(6)}.tmp")
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            break
        except FileExistsError:  # pragma: no cover - 2**48 names
            continue
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
        if mode is not None:
            os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def write_as(
    mesh: Mesh,
    path: str | os.PathLike,
    format: str | None,
    caller: str,
    writer: Callable[..., None],
    **options: Any,
) -> None:
    """Check ``mesh`` and ``path`` (the name must not name another format), then
    write ``writer(mesh, file, **options)`` to ``path`` atomically."""
    check_mesh(mesh, caller)
    checked = as_path(path, caller)
    format_of(checked, format)
    write_atomically(checked, partial(writer, mesh, **options))


def show(line: bytes, limit: int = 60) -> str:
    """A line of a file for an error message: decoded leniently, stripped, shortened."""
    text = line[: 4 * limit].decode("utf-8", "replace").strip()
    if len(text) > limit:
        text = text[:limit] + "..."
    return repr(text)


def line_blocks(
    fh: IO[bytes], path: Path, kind: str, block_bytes: int | None = None
) -> Iterator[tuple[int, bytes]]:
    """The file as blocks of whole lines: ``(number of the block's first line, bytes)``.

    Every block ends with ``b"\\n"``; blocks are about ``block_bytes``
    long (default :data:`BLOCK_BYTES`).  A UTF-8 byte-order mark at the start
    is dropped; a file whose lines end in a bare ``\\r`` (old Mac) is read
    as if they ended in ``\\n``.

    Raises
    ------
    MeshError
        A NUL byte (a binary file, or UTF-16 text) or a line longer than
        :data:`MAX_LINE_BYTES`, naming the file and line.
    """
    block_bytes = block_bytes or BLOCK_BYTES
    lineno = 1
    rest = b""
    first = True
    cr_only = False
    while True:
        chunk = fh.read(block_bytes)
        if first:
            first = False
            if chunk.startswith(_BOM):
                chunk = chunk[len(_BOM) :]
            cr_only = b"\r" in chunk and b"\n" not in chunk
        if cr_only:
            chunk = chunk.replace(b"\r", b"\n")
        if not chunk:
            if rest:
                yield lineno, _checked(rest + b"\n", lineno, path, kind)
            return
        data = rest + chunk if rest else chunk
        cut = data.rfind(b"\n")
        if cut < 0:
            if len(data) > MAX_LINE_BYTES:
                _checked(data, lineno, path, kind)  # a NUL byte is the likelier diagnosis
                raise MeshError(
                    f"{path}:{lineno}: a line longer than {MAX_LINE_BYTES:,} bytes: "
                    f"a damaged or binary file, not {kind} text"
                )
            rest = data
            continue
        block, rest = data[: cut + 1], data[cut + 1 :]
        yield lineno, _checked(block, lineno, path, kind)
        lineno += block.count(b"\n")


def _checked(block: bytes, lineno: int, path: Path, kind: str) -> bytes:
    nul = block.find(b"\x00")
    if nul >= 0:
        line = lineno + block.count(b"\n", 0, nul)
        raise MeshError(
            f"{path}:{line}: a NUL byte: a binary file (or UTF-16 text), not {kind} text"
        )
    return block


@dataclass
class Scan:
    """A block of whole lines with its lines and tokens located.

    Attributes
    ----------
    buf : (L,) uint8
        A writable copy of the block; with ``comments``, everything from a
        ``#`` to the end of its line is blanked.
    start, end : (n,) int
        The first byte and the line break of every line.
    tok : (T,) int
        The first byte of every token (a run of bytes above 32).
    first, ntok : (n,) int
        Every line's first token (an index into ``tok``) and its token count.
    """

    buf: np.ndarray
    start: np.ndarray
    end: np.ndarray
    tok: np.ndarray
    first: np.ndarray
    ntok: np.ndarray

    def select(self, lines: np.ndarray, contiguous: bool) -> np.ndarray:
        """The bytes of ``lines`` (sorted line indices): a view of ``buf``
        from the first to the last when nothing between them has tokens
        (``contiguous``), else a copy of just those lines."""
        if contiguous:
            return self.buf[self.start[lines[0]] : self.end[lines[-1]] + 1]
        keep = np.zeros(self.start.size, dtype=bool)
        keep[lines] = True
        return self.buf[np.repeat(keep, self.end - self.start + 1)]


def scan(block: bytes, comments: bool = True) -> Scan:
    """Locate the lines and whitespace-separated tokens of ``block`` (see :class:`Scan`)."""
    buf = np.frombuffer(block, dtype=np.uint8).copy()
    end = np.flatnonzero(buf == 10)
    start = np.empty_like(end)
    start[:1] = 0
    start[1:] = end[:-1] + 1
    if comments and b"#" in block:
        hashes = np.flatnonzero(buf == 35)
        line = np.searchsorted(end, hashes)
        firsts = np.ones(hashes.size, dtype=bool)
        firsts[1:] = line[1:] != line[:-1]
        mark = np.zeros(buf.size + 1, dtype=np.int8)
        mark[hashes[firsts]] = 1
        mark[end[line[firsts]]] = -1
        buf[np.cumsum(mark[:-1], dtype=np.int8).view(bool)] = 32
    space = buf <= 32
    starts = ~space
    starts[1:] &= space[:-1]
    tok = np.flatnonzero(starts)
    first = np.searchsorted(tok, start)
    ntok = np.empty_like(first)
    ntok[:-1] = first[1:] - first[:-1]
    ntok[-1:] = tok.size - first[-1:]
    return Scan(buf, start, end, tok, first, ntok)


def contiguous(mask: np.ndarray) -> bool:
    """Whether the True entries of ``mask`` form one run."""
    where = np.flatnonzero(mask)
    return bool(where.size) and int(where[-1] - where[0]) + 1 == where.size


def parse_ints(data: np.ndarray, expected: int) -> np.ndarray | None:
    """The ``expected`` whitespace-separated integers in ``data``, or None if
    anything else is there (the caller then finds the culprit line)."""
    if expected == 0:
        return np.zeros(0, dtype=np.int64) if not np.any(data > 32) else None
    try:
        values = np.fromstring(data, dtype=np.int64, sep=" ")  # type: ignore[call-overload]
    except ValueError:
        return None
    if values.size != expected:
        return None
    # np.fromstring saturates at +-2**63: such values go to the exact slow path
    if values.max() >= 1 << 62 or values.min() <= -(1 << 62):
        return None
    return values


def parse_floats(data: np.ndarray, expected: int, columns: int | None = None) -> np.ndarray | None:
    """The ``expected`` whitespace-separated numbers in ``data``, or None.

    With ``columns`` (every line holds that many numbers) numpy's C
    ``loadtxt`` parser is used (the faster one), else ``np.fromstring``.
    """
    if expected == 0:
        return np.zeros(0) if not np.any(data > 32) else None
    try:
        if columns:
            values = np.loadtxt(
                io.BytesIO(data.tobytes()), dtype=np.float64, comments=None, ndmin=2
            ).ravel()
        else:
            values = np.fromstring(data, dtype=np.float64, sep=" ")  # type: ignore[call-overload]
    except ValueError:
        return None
    return values if values.size == expected else None


def finish(path: Path, vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray) -> Mesh:
    """The mesh of the arrays read (taken over without a copy), validated.

    Raises
    ------
    MeshError
        The mesh's own message, prefixed with the file name.
    """
    try:
        mesh = adopted(vertices, corners, offsets)
    except MeshError as exc:
        raise MeshError(f"{path}: {exc}") from None
    return mesh


def offsets_of(sizes: np.ndarray) -> np.ndarray:
    """(m + 1,) int: the CSR offsets of faces of these sizes."""
    offsets = np.zeros(sizes.size + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    return offsets
