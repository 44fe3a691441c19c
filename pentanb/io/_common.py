"""What the readers and writers share.

* the formats and how a path names one (:func:`format_of`);
* what a reader reads (:func:`open_source`): a path to a regular file or a
  pipe (FIFO, ``/dev/stdin``), or a binary file object; a device is refused
  and a FIFO without a writer reads as empty instead of blocking;
* writing to a temporary name and renaming (:func:`write_atomically`),
  through symbolic links to their target, never over a read-only file
  unless asked;
* a text file read as bytes, in blocks of whole lines (:func:`line_blocks`),
  and the tokens of such a block located with whole-array numpy expressions
  (:func:`scan`): the readers parse numbers block by block, so memory stays
  a small multiple of the arrays read, and a damaged file fails at its first
  inconsistency, not after it has been loaded;
* the mesh built from the arrays read (:func:`finish`), its errors
  prefixed with the file name;
* the error for a coordinate that is not a finite float64
  (:func:`bad_coordinate`), and arrays of rows a header announces
  (:class:`Rows`), allocated at once only when the file's size vouches for
  the count.
"""

from __future__ import annotations

import contextlib
import errno
import io
import math
import os
import secrets
import stat
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import IO, Any

import numpy as np

from .._checks import bounded
from ..mesh import Mesh, MeshError
from ..mesh import check_mesh as check_mesh  # (the readers and writers take it from here)
from ..mesh.build import adopted

#: The file formats, by the suffix that names them.
FORMATS = {".obj": "obj", ".off": "off", ".ply": "ply", ".stl": "stl"}

#: Bytes read at a time from a text file (blocks end at a line break).
BLOCK_BYTES = 1 << 20

#: The longest line a text mesh file may have; longer means a damaged or binary file.
MAX_LINE_BYTES = 1 << 24

#: The most rows a header may announce for one element (or an OFF count):
#: more than any file holds, and small enough for exact int64 arithmetic.
MAX_COUNT = 1 << 48

#: Bytes read at a time from a pipe whose length is not known in advance.
STREAM_BYTES = 1 << 24

BOM = _BOM = b"\xef\xbb\xbf"


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


def is_file_object(source: Any) -> bool:
    """Whether ``source`` is a file object (has ``read``), not a path."""
    return hasattr(source, "read") and not isinstance(source, (str, bytes, os.PathLike))


def name_of(source: Any) -> Path | None:
    """The path whose suffix tells the format of ``source``: the path itself,
    or a file object's ``name`` when that is a path (None otherwise)."""
    if not is_file_object(source):
        return as_path(source, "read")
    name = getattr(source, "name", None)
    if isinstance(name, (str, bytes, os.PathLike)):
        return Path(os.fsdecode(name))
    return None


@dataclass
class Source:
    """An open input: ``fh`` (binary), ``name`` for messages, and ``size``,
    the bytes from the current position to the end, or None for a pipe."""

    fh: IO[bytes]
    name: Path
    size: int | None


@contextlib.contextmanager
def open_source(source: Any, caller: str) -> Iterator[Source]:
    """Open what a reader is given: a path, or a binary file object.

    * A path to a regular file is read; so is a path to a FIFO (a named
      pipe, ``/dev/stdin`` under ``cat file |``): it is opened with
      ``O_NONBLOCK``, which is then cleared, so a FIFO that no process
      writes to reads as empty instead of blocking forever.
    * A path to a device (a terminal, ``/dev/zero``, a disk) or a socket is
      refused with a ValueError before anything is read; a directory raises
      IsADirectoryError.
    * A binary file object (``io.BytesIO``, ``open(path, "rb")``,
      ``sys.stdin.buffer``) is read from its current position and left open.

    Raises
    ------
    TypeError
        ``source`` is neither a path nor a binary file object (a text file
        object is refused: its bytes are not what is in the file).
    ValueError
        A device or socket path.
    """
    if is_file_object(source):
        if isinstance(source, io.TextIOBase) or not isinstance(source.read(0), bytes):
            raise TypeError(
                f"{caller} expects a path or a binary file object (open(path, 'rb')), "
                f"got a text file object ({type(source).__name__})"
            )
        name = getattr(source, "name", None)
        shown = os.fsdecode(name) if isinstance(name, (str, bytes, os.PathLike)) else None
        yield Source(source, Path(shown or f"<{type(source).__name__}>"), _remaining(source))
        return
    path = as_path(source, caller)
    nonblock = getattr(os, "O_NONBLOCK", 0)  # POSIX: a FIFO opens without waiting
    fd = os.open(path, os.O_RDONLY | nonblock | getattr(os, "O_BINARY", 0))
    try:
        mode = os.fstat(fd).st_mode
        if stat.S_ISDIR(mode):
            raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
        if not (stat.S_ISREG(mode) or stat.S_ISFIFO(mode)):
            kind = (
                "a character device (a terminal or a device such as /dev/zero)"
                if stat.S_ISCHR(mode)
                else "a block device"
                if stat.S_ISBLK(mode)
                else "a socket or other special file"
            )
            raise ValueError(
                f"{path} is {kind}, not a file: pentanb reads regular files and pipes only"
            )
        if nonblock:
            os.set_blocking(fd, True)  # reads wait for a writer's data again
        fh = os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise
    with fh:
        yield Source(fh, path, os.fstat(fd).st_size if stat.S_ISREG(mode) else None)


def _remaining(fh: Any) -> int | None:
    """Bytes from a file object's position to its end, or None (a pipe)."""
    try:
        if not fh.seekable():
            return None
        at = fh.tell()
        end = fh.seek(0, os.SEEK_END)
        fh.seek(at)
    except (OSError, AttributeError, ValueError):
        return None
    return max(0, int(end) - int(at))


def read_after(fh: IO[bytes], head: bytes, n: int | None) -> bytes | np.ndarray:
    """``head`` followed by the next ``n`` bytes of ``fh`` (fewer at its end), or
    by all the rest for ``n=None``.  A known ``n`` (from the size of a file,
    never from a header's count) is read into one buffer, a uint8 array."""
    if n is None:
        return read_rest(fh, head)
    out = np.empty(len(head) + n, dtype=np.uint8)  # not zero-filled: read over at once
    out[: len(head)] = np.frombuffer(head, dtype=np.uint8)
    view = memoryview(out.data)
    got = len(head)
    while got < out.size:
        k = fh.readinto(view[got:]) if hasattr(fh, "readinto") else None
        if k is None:  # no readinto, or a non-blocking read without data
            more = fh.read(out.size - got) or b""
            k = len(more)
            out[got : got + k] = np.frombuffer(more, dtype=np.uint8)
        if not k:
            return out[:got]
        got += k
    return out


def read_exactly(fh: IO[bytes], n: int) -> bytes:
    """``n`` bytes from ``fh``, or fewer at the end of the file.

    Read in pieces of at most :data:`STREAM_BYTES`, so memory grows with the
    bytes that arrive, never with a count a header claims."""
    first = fh.read(min(n, STREAM_BYTES)) or b""
    if len(first) == n or not first:
        return first
    parts = [first]
    got = len(first)
    while got < n:
        more = fh.read(min(n - got, STREAM_BYTES))
        if not more:
            break
        parts.append(more)
        got += len(more)
    return b"".join(parts)


def read_rest(fh: IO[bytes], head: bytes = b"") -> bytes:
    """``head`` and everything from ``fh`` to its end (a pipe: until its writer
    closes it), read in pieces as they arrive."""
    parts = [head]
    while True:
        more = fh.read(STREAM_BYTES)
        if not more:
            return b"".join(parts)
        parts.append(more)


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


#: The most symbolic links a write follows from the path it is given to the file it replaces.
MAX_LINKS = 40


def link_target(path: Path) -> Path:
    """The file a write to ``path`` replaces: ``path`` itself, or the file its
    symbolic links lead to (which may not exist yet: a dangling link).

    Every link is followed one step at a time, a relative one from the folder
    that holds it, so the file is written where the link points and the
    link is kept.

    Raises
    ------
    OSError
        More than :data:`MAX_LINKS` links in a row (a loop), errno ``ELOOP``.
    """
    target = path
    for _ in range(MAX_LINKS):
        if not target.is_symlink():
            return target
        target = target.parent / os.readlink(target)
    raise OSError(errno.ELOOP, f"more than {MAX_LINKS} symbolic links in a row", str(path))


def is_read_only(path: Path, mode: int) -> bool:
    """Whether the existing file ``path`` (permission bits ``mode``) is read-only:
    its mode lets no one write it (``0444``), or this process may not."""
    return not mode & 0o222 or not os.access(path, os.W_OK)


def writable_target(path: Path, *, force: bool, caller: str) -> tuple[Path, int | None]:
    """The file a write to ``path`` replaces (:func:`link_target`) and its
    permission bits (None: it does not exist yet), or a ValueError naming
    ``caller`` if it must not be replaced (see :func:`write_atomically`)."""
    target = link_target(path)
    shown = f"{path}" if target == path else f"{path} (a link to {target})"
    try:
        info = os.stat(target)
    except FileNotFoundError:
        return target, None
    mode = stat.S_IMODE(info.st_mode)
    if not stat.S_ISREG(info.st_mode):
        raise ValueError(
            f"{caller}: {shown} exists and is not a regular file: pentanb will not replace it"
        )
    if not force and is_read_only(target, mode):
        raise ValueError(
            f"{caller}: {shown} is read-only (mode {mode:04o}): pentanb will not replace "
            "it; pass force=True to replace it anyway, with the same mode"
        )
    return target, mode


def write_atomically(
    path: Path, write: Callable[[IO[bytes]], None], *, force: bool = False, caller: str = "write"
) -> Path:
    """Run ``write(file)`` on a new temporary file beside ``path``, then rename it to ``path``.

    The temporary file is created exclusively under a fresh random name
    (never an existing file of the user's) and gets the permissions of the
    file it replaces (a new file: the usual ones, after the umask).  A
    failure (an exception from ``write``, a full disk) removes it and leaves
    an existing ``path`` as it was.

    A symbolic link is kept: the file it points to (followed link by link;
    a dangling link's target is created) is the one replaced, by a
    temporary file beside that file.

    Parameters
    ----------
    path : Path
        The file to write.
    write : callable
        ``write(fh)`` writes the content to the binary file ``fh``.
    force : bool
        Replace a read-only file too (see :func:`is_read_only`).
    caller : str
        The public function, for messages.

    Returns
    -------
    Path
        The file written: ``path``, or the target of its links.

    Raises
    ------
    ValueError
        Before anything is written: ``path`` (or its link's target) exists
        and is not a regular file (a directory, a device, a FIFO, a socket):
        it is never replaced; or it is a read-only file and ``force`` is
        False.
    OSError
        The folder does not exist or cannot be written, a loop of links, a
        full disk.
    """
    target, mode = writable_target(path, force=force, caller=caller)
    stem = os.fsencode(target.name)[:200].decode(errors="ignore")  # room for the suffix
    while True:
        tmp = target.with_name(f".{stem}.{secrets.token_hex(6)}.tmp")
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
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
    return target


def write_as(
    mesh: Mesh,
    path: str | os.PathLike,
    format: str | None,
    caller: str,
    writer: Callable[..., None],
    *,
    force: bool = False,
    **options: Any,
) -> None:
    """Check ``mesh`` and ``path`` (the name must not name another format), then
    write ``writer(mesh, file, **options)`` to ``path`` atomically
    (:func:`write_atomically`; ``force``: replace a read-only file too)."""
    check_mesh(mesh, caller)
    checked = as_path(path, caller)
    format_of(checked, format)
    force = check_force(force, caller)
    write_atomically(checked, partial(writer, mesh, **options), force=force, caller=caller)


def check_force(force: Any, caller: str) -> bool:
    """``force`` as a bool; a TypeError naming ``caller`` for anything else."""
    if not isinstance(force, (bool, np.bool_)):
        raise TypeError(f"{caller}: force must be True or False, not {type(force).__name__}")
    return bool(force)


def show(line: bytes, limit: int = 60) -> str:
    """A line of a file for an error message: decoded leniently, stripped, shortened."""
    text = line[: 4 * limit].decode("utf-8", "replace").strip()
    if len(text) > limit:
        text = text[:limit] + "..."
    return repr(text)


def line_blocks(
    fh: IO[bytes],
    path: Path,
    kind: str,
    block_bytes: int | None = None,
    head: bytes = b"",
    start: bool = True,
) -> Iterator[tuple[int, bytes]]:
    """The file as blocks of whole lines: ``(number of the block's first line, bytes)``.

    Every block ends with ``b"\\n"``; blocks are about ``block_bytes``
    long (default :data:`BLOCK_BYTES`).  ``head``: bytes already read from
    ``fh``, which come first.  At the ``start`` of a file a UTF-8
    byte-order mark is dropped.  Lines may end in ``\\n``, ``\\r\\n`` or a
    bare ``\\r`` (old Mac), mixed as they come: every one of them is made
    ``\\n`` (one line break each).

    Raises
    ------
    MeshError
        A NUL byte (a binary file, or UTF-16 text) or a line longer than
        :data:`MAX_LINE_BYTES`, naming the file and line.
    """
    block_bytes = block_bytes or BLOCK_BYTES
    lineno = 1
    rest = b""
    for chunk in _text_chunks(fh, block_bytes, head, start):
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
    if rest:
        yield lineno, _checked(rest + b"\n", lineno, path, kind)


def _text_chunks(fh: IO[bytes], block_bytes: int, head: bytes, start: bool) -> Iterator[bytes]:
    """The bytes of ``fh`` (after ``head``) in pieces, every line break made ``\\n``.

    A ``\\r`` that ends a piece becomes ``\\n`` at once; a ``\\n`` that begins
    the next piece is then the rest of that ``\\r\\n`` and is dropped.
    """
    data = head
    if start:
        while len(data) < len(_BOM):  # a short read must not split the mark
            more = fh.read(block_bytes)
            if not more:
                break
            data += more
        if data.startswith(_BOM):
            data = data[len(_BOM) :]
    after_cr = False
    while True:
        if not data:
            data = fh.read(block_bytes)
            if not data:
                return
        if after_cr and data[:1] == b"\n":
            data = data[1:]
        after_cr = False
        if b"\r" in data:
            after_cr = data.endswith(b"\r")
            data = data.replace(b"\r\n", b"\n").replace(b"\r", b"\n")
        if data:
            yield data
        data = b""


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


_NON_FINITE = (b"inf", b"infinity", b"nan")


def bad_coordinate(where: str, what: str, text: bytes, tokens: list[bytes]) -> MeshError | None:
    """The error for the first of ``tokens`` (a line's coordinates) that is
    not a finite float64, or None if all are.

    ``where`` is ``"file:line"``, ``what`` the point (``"vertex 6"``); the
    message tells a bad number, a non-finite one written as such (``nan``,
    ``inf``) and one too large for float64 (``1e999``, a 400-digit integer)
    apart, and shows the line.
    """
    for token in tokens:
        try:
            value = float(token)
        except ValueError:
            return MeshError(f"{where}: {what}: bad number {show(token)} in {show(text)}")
        if math.isfinite(value):
            continue
        if token.lower().lstrip(b"+-") in _NON_FINITE:
            return MeshError(
                f"{where}: {what} has a non-finite coordinate ({token.decode()}) in "
                f"{show(text)}: a mesh's positions must be finite"
            )
        return MeshError(
            f"{where}: {what} has a coordinate {show(token, 30)} that overflows float64 (beyond "
            f"+-{np.finfo(np.float64).max:.4g}) in {show(text)}"
        )
    return None


class Rows:
    """The ``count`` rows of one array a header announces, filled in order.

    With ``allocate`` (the file's size has shown that ``count`` rows fit in
    it) the array is allocated once and filled in place; without (a pipe,
    whose length is unknown) the rows are kept as they arrive and joined at
    the end, so a header cannot make the reader allocate rows that never
    come.
    """

    def __init__(self, count: int, shape: tuple[int, ...], dtype: Any, allocate: bool) -> None:
        self.count, self.shape, self.dtype = count, shape, dtype
        self.filled = 0
        self.array = np.empty((count, *shape), dtype=dtype) if allocate else None
        self.parts: list[np.ndarray] = []

    def put(self, at: int, values: np.ndarray) -> None:
        """Rows ``at, at + 1, ...`` (``at`` is the next row to fill)."""
        assert at == self.filled
        if self.array is not None:
            self.array[at : at + len(values)] = values
        else:
            self.parts.append(np.array(values, dtype=self.dtype))
        self.filled += len(values)

    def result(self) -> np.ndarray:
        if self.array is not None:
            return self.array
        if not self.parts:
            return np.empty((0, *self.shape), dtype=self.dtype)
        out = np.concatenate(self.parts)
        self.parts.clear()
        return out


def finish(path: Path, vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray) -> Mesh:
    """The mesh of the arrays read (taken over without a copy), validated.

    Raises
    ------
    MeshError
        The mesh's own message, prefixed with the file name, and cut to an
        excerpt with its length when it is long (:func:`pentanb._checks.bounded`).
    """
    try:
        mesh = adopted(vertices, corners, offsets)
    except MeshError as exc:
        raise MeshError(bounded(f"{path}: {exc}")) from None
    return mesh


def offsets_of(sizes: np.ndarray) -> np.ndarray:
    """(m + 1,) int: the CSR offsets of faces of these sizes."""
    offsets = np.zeros(sizes.size + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    return offsets
