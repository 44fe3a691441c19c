"""PLY (Stanford polygon files): ASCII and binary, both byte orders, polygon faces kept.

A PLY file is a header that declares *elements* (``vertex``, ``face``, and
any others) and their *properties* (scalars, or lists with a count), then
the elements' rows, as text lines or as packed binary records.  The mesh
is the ``vertex`` element's ``x``, ``y``, ``z`` and the ``face`` element's
``vertex_indices`` (or ``vertex_index``) list; every other property and
element is skipped, with an :class:`IgnoredDataWarning` that names them.

Binary rows are read with numpy structured dtypes, a run of rows of one
layout (faces of one size) at a time; text rows block by block as in
:mod:`pentanb.io.obj`.
"""

from __future__ import annotations

import os
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

import numpy as np

from ..mesh import Mesh, MeshError
from ._common import (
    BOM,
    MAX_COUNT,
    IgnoredDataWarning,
    Rows,
    bad_coordinate,
    check_mesh,
    finish,
    line_blocks,
    offsets_of,
    open_source,
    parse_floats,
    read_after,
    scan,
    show,
    write_as,
)
from .obj import WRITE_ROWS, write_faces, write_vertices

__all__ = ["read_ply", "write_ply", "IgnoredDataWarning"]


#: PLY's scalar types, by both their old and their sized names.
TYPES = {
    "char": "i1",
    "int8": "i1",
    "uchar": "u1",
    "uint8": "u1",
    "short": "i2",
    "int16": "i2",
    "ushort": "u2",
    "uint16": "u2",
    "int": "i4",
    "int32": "i4",
    "uint": "u4",
    "uint32": "u4",
    "float": "f4",
    "float32": "f4",
    "double": "f8",
    "float64": "f8",
}
_ENCODINGS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}
_INDEX_NAMES = ("vertex_indices", "vertex_index")
_DIGITS = re.compile(r"[0-9]+")  # str.isdigit() takes '²' too
#: Longest header line, and most header lines, a PLY file may have.
MAX_HEADER_LINE = 4096
MAX_HEADER_LINES = 10_000


@dataclass
class _Property:
    name: str
    type: str  # numpy type code without byte order, e.g. "f4"
    count: str | None = None  # the count's type code for a list


@dataclass
class _Element:
    name: str
    count: int
    line: int
    props: list[_Property] = field(default_factory=list)

    @property
    def fixed(self) -> bool:
        return all(p.count is None for p in self.props)

    def dtype(self, order: str, counts: tuple[int, ...] = ()) -> np.dtype:
        """The structured dtype of a row (``counts``: the lengths of its lists)."""
        fields: list[tuple[Any, ...]] = []
        lists = iter(counts)
        for i, p in enumerate(self.props):
            if p.count is None:
                fields.append((f"f{i}", order + p.type))
            else:
                fields.append((f"n{i}", order + p.count))
                fields.append((f"f{i}", order + p.type, (next(lists),)))
        return np.dtype(fields)


class _HeaderLines:
    """The lines of a PLY header, read from the stream without seeking.

    A line ends in ``\\n``, ``\\r\\n`` or a bare ``\\r``.  ``rest`` holds the
    bytes read past the line last returned (the start of the body).
    """

    _EOL = re.compile(rb"\r\n?|\n")

    def __init__(self, fh: IO[bytes]) -> None:
        self.fh = fh
        self.buf = b""
        self.pos = 0
        self.eof = False
        self.consumed = 0  # bytes of the lines returned, line breaks included

    def next(self, limit: int) -> tuple[bytes, bytes] | None:
        """The next line and its line break (b"" at the end of the file); a
        line longer than ``limit`` comes back cut at ``limit + 1`` bytes.
        None at the end of the file."""
        while True:
            m = self._EOL.search(self.buf, self.pos)
            # a "\r" that ends what was read may be half of a "\r\n"
            if m and (m.end() < len(self.buf) or m.group() != b"\r" or self.eof):
                line, self.pos = self.buf[self.pos : m.start()], m.end()
                self.consumed += m.end() - m.start() + len(line)
                return line, m.group()
            if len(self.buf) - self.pos > limit:
                return self.buf[self.pos : self.pos + limit + 1], b""
            if self.eof:
                if self.pos == len(self.buf):
                    return None
                line, self.pos = self.buf[self.pos :], len(self.buf)
                self.consumed += len(line)
                return line, b""
            more = self.fh.read(1 << 16)
            self.eof = not more
            self.buf = self.buf[self.pos :] + (more or b"")
            self.pos = 0

    def unread(self, n: int) -> None:
        """Give back the last ``n`` bytes returned (part of a line break)."""
        self.pos -= n
        self.consumed -= n

    @property
    def rest(self) -> bytes:
        return self.buf[self.pos :]


def _read_header(fh: IO[bytes], path: Path) -> tuple[str | None, list[_Element], int, _HeaderLines]:
    """Read the header: (byte order or None for ASCII, elements, lines read, the line reader)."""
    lines = _HeaderLines(fh)
    got = lines.next(16)
    first, first_break = got if got else (b"", b"")
    if first.startswith(BOM):
        first = first[len(BOM) :]
    if first.rstrip() != b"ply":
        raise MeshError(f"{path}:1: not a PLY file (the first line is not 'ply')")
    order: str | None = None
    encoding = None
    elements: list[_Element] = []
    n = 1
    while True:
        got = lines.next(MAX_HEADER_LINE)
        n += 1
        if got is None:
            raise MeshError(f"{path}:{n}: the file ends inside the header (no 'end_header')")
        raw, line_break = got
        if len(raw) > MAX_HEADER_LINE or n > MAX_HEADER_LINES:
            raise MeshError(f"{path}:{n}: a damaged PLY header (a line or the header too long)")
        if b"\x00" in raw:
            raise MeshError(f"{path}:{n}: a NUL byte in the header: a damaged PLY file")
        parts = raw.decode("latin-1").split()
        if not parts:
            continue
        key = parts[0]
        if key == "end_header":
            if line_break == b"\r\n" and first_break == b"\r":
                lines.unread(1)  # lines end in a bare CR: the LF is the body's first byte
            break
        if key in ("comment", "obj_info"):
            continue
        bad = f"{path}:{n}: bad header line {show(raw)}"
        if key == "format":
            if len(parts) != 3 or parts[1] not in _ENCODINGS:
                raise MeshError(
                    f"{bad}: the format is ascii, binary_little_endian or binary_big_endian"
                )
            encoding = parts[1]
            order = _ENCODINGS[encoding]
        elif key == "element":
            if len(parts) != 3 or not _DIGITS.fullmatch(parts[2]):
                raise MeshError(
                    f"{bad}: 'element NAME COUNT' with a count >= 0 in ASCII digits 0-9"
                )
            count = int(parts[2])
            if count >= MAX_COUNT:
                raise MeshError(
                    f"{bad}: a count of {count:,} rows, more than any file holds "
                    f"(at most {MAX_COUNT:,})"
                )
            elements.append(_Element(parts[1], count, n))
        elif key == "property":
            if not elements:
                raise MeshError(f"{bad}: a property before any element")
            if len(parts) == 3 and parts[1] in TYPES:
                elements[-1].props.append(_Property(parts[2], TYPES[parts[1]]))
            elif len(parts) == 5 and parts[1] == "list" and parts[2] in TYPES and parts[3] in TYPES:
                if TYPES[parts[2]][0] == "f":
                    raise MeshError(f"{bad}: a list's count must be an integer type")
                elements[-1].props.append(_Property(parts[4], TYPES[parts[3]], TYPES[parts[2]]))
            else:
                raise MeshError(
                    f"{bad}: 'property TYPE NAME' or 'property list TYPE TYPE NAME' "
                    f"with TYPE one of {', '.join(TYPES)}"
                )
        else:
            raise MeshError(f"{bad}: unknown keyword {key!r}")
    if encoding is None:
        raise MeshError(f"{path}: the header has no 'format' line")
    return order, elements, n, lines


def _layout(path: Path, elements: list[_Element]) -> tuple[_Element, _Element, list[int], int]:
    """The vertex and face elements, the x, y, z columns and the index list's position."""
    named = {e.name: e for e in elements}
    if "vertex" not in named or "face" not in named:
        missing = [name for name in ("vertex", "face") if name not in named]
        have = ", ".join(e.name for e in elements) or "none"
        raise MeshError(
            f"{path}: no {' and no '.join(repr(m) for m in missing)} element (elements: {have})"
        )
    vertex, face = named["vertex"], named["face"]
    names = [p.name for p in vertex.props]
    for axis in "xyz":
        if axis not in names:
            raise MeshError(f"{path}:{vertex.line}: the vertex element has no property {axis!r}")
        if vertex.props[names.index(axis)].count is not None:
            raise MeshError(f"{path}:{vertex.line}: the vertex property {axis!r} is a list")
    xyz = [names.index(a) for a in "xyz"]
    lists = [i for i, p in enumerate(face.props) if p.name in _INDEX_NAMES and p.count]
    if not lists:
        raise MeshError(
            f"{path}:{face.line}: the face element has no list property 'vertex_indices'"
        )
    ignored = [f"vertex {p.name}" for i, p in enumerate(vertex.props) if i not in xyz]
    ignored += [f"face {p.name}" for i, p in enumerate(face.props) if i != lists[0]]
    ignored += [f"element {e.name}" for e in elements if e.name not in ("vertex", "face")]
    if ignored:
        warnings.warn(
            f"{path}: ignored (a pentanb mesh keeps positions and faces only): "
            + ", ".join(ignored),
            IgnoredDataWarning,
            stacklevel=4,
        )
    return vertex, face, xyz, lists[0]


def read_ply(path: str | os.PathLike | IO[bytes]) -> Mesh:
    """Read a PLY file, ASCII or binary (either byte order).

    The header's lines (and an ASCII file's rows) may end in LF, CRLF or
    CR, and a UTF-8 byte-order mark before ``ply`` is skipped.  List
    properties are skipped on any element, ASCII or binary.  Vertex indices
    of a float type are taken if every one is a whole number.

    Parameters
    ----------
    path : str, path-like or binary file object
        The file to read: a regular file or a pipe (see :func:`pentanb.read`).

    Returns
    -------
    Mesh
        Positions from the ``vertex`` element's ``x``, ``y``, ``z``; faces
        (any sizes, kept as they are) from the ``face`` element's
        ``vertex_indices`` (or ``vertex_index``) list.

    Warns
    -----
    IgnoredDataWarning
        Other vertex and face properties (normals, colours, texture
        coordinates) and other elements are skipped; the warning names them.

    Raises
    ------
    MeshError
        A damaged header, a file shorter than its header says, a bad number;
        the message names the file and the line (or the element and row).  A
        file whose mesh is not an oriented 2-manifold (closed or with
        boundary) raises the mesh's own
        error, prefixed with the file name.
    """
    with open_source(path, "read_ply") as src:
        fh, path = src.fh, src.name
        order, elements, header_lines, lines = _read_header(fh, path)
        vertex, face, xyz, index = _layout(path, elements)
        body = None if src.size is None else src.size - lines.consumed
        least = sum(
            e.count
            * (
                e.dtype(order, (0,) * _lists(e)).itemsize
                if order
                else 2 * max(1, len(e.props))  # "0 " per property
            )
            for e in elements
        ) - (order is None)  # the last line may lack its line break
        if body is not None and least > body:
            rows = ", ".join(f"{e.count:,} {e.name}" for e in elements)
            raise MeshError(
                f"{path}: the header announces {rows} rows; that needs at least {least:,} "
                f"bytes but the file has {body:,} after the header"
            )
        if order is None:
            got = _read_text(
                fh, path, elements, header_lines + 1, vertex, face, xyz, index, lines.rest, body
            )
        else:
            rest = lines.rest
            data = read_after(fh, rest, None if body is None else body - len(rest))
            got = _read_binary(data, path, elements, order, vertex, face, xyz, index)
            del data  # not held while the mesh is validated
    vertices, sizes, corners = got
    return finish(path, vertices, corners, offsets_of(sizes))


def _lists(e: _Element) -> int:
    return sum(p.count is not None for p in e.props)


# ---------------------------------------------------------------------- binary
def _read_binary(data, path, elements, order, vertex, face, xyz, index):
    pos = 0
    vertices = sizes = corners = None
    for e in elements:
        if e.fixed:
            dt = e.dtype(order)
            need = e.count * dt.itemsize
            if pos + need > len(data):
                raise MeshError(
                    f"{path}: the file ends inside element {e.name!r}: the header says "
                    f"{e.count:,} rows of {dt.itemsize} bytes, the file holds "
                    f"{(len(data) - pos) // dt.itemsize:,}"
                )
            rows = np.frombuffer(data, dtype=dt, count=e.count, offset=pos)
            pos += need
            if e is vertex:
                vertices = np.stack([rows[f"f{i}"] for i in xyz], axis=1).astype(np.float64)
        else:
            pos, got = _binary_lists(data, pos, path, e, order, index if e is face else None)
            if e is face:
                sizes, corners = got
            elif e is vertex:
                vertices = np.stack([got[i] for i in xyz], axis=1).astype(np.float64)
    if pos != len(data):
        warnings.warn(
            f"{path}: {len(data) - pos:,} bytes after the last element ignored",
            IgnoredDataWarning,
            stacklevel=3,
        )
    return vertices, sizes, corners


def _binary_lists(data: bytes, pos: int, path: Path, e: _Element, order: str, want: int | None):
    """Walk the rows of an element with list properties, a run of one layout at a time.

    Returns the new position and, for ``want`` (a list property's index),
    ``(sizes, flat values)``; for an element without ``want``, its scalar
    columns by property index.
    """
    lists = [i for i, p in enumerate(e.props) if p.count is not None]
    sizes_parts: list[np.ndarray] = []
    value_parts: list[np.ndarray] = []
    scalars: dict[int, list[np.ndarray]] = {i: [] for i, p in enumerate(e.props) if p.count is None}
    done, window = 0, 64
    while done < e.count:
        counts = []
        p = pos
        for prop in e.props:  # the layout of the next row
            if prop.count is None:
                p += np.dtype(prop.type).itemsize
                continue
            ct = np.dtype(order + prop.count)
            if p + ct.itemsize > len(data):
                p = len(data) + 1
                break
            c = int(np.frombuffer(data, dtype=ct, count=1, offset=p)[0])
            if c < 0:
                raise MeshError(f"{path}: row {done} of element {e.name!r} has a list of {c} items")
            counts.append(c)
            p += ct.itemsize + c * np.dtype(prop.type).itemsize
        if p > len(data):
            raise MeshError(
                f"{path}: the file ends inside element {e.name!r}, at row {done:,} of {e.count:,}"
            )
        dt = e.dtype(order, tuple(counts))
        w = min(e.count - done, window, (len(data) - pos) // dt.itemsize)
        rows = np.frombuffer(data, dtype=dt, count=w, offset=pos)
        same = np.ones(w, dtype=bool)
        for i, c in zip(lists, counts):
            same &= rows[f"n{i}"] == c
        run = w if same.all() else int(np.argmin(same))
        rows = rows[:run]
        if want is not None:
            k = counts[lists.index(want)]
            sizes_parts.append(np.full(run, k, dtype=np.int64))
            value_parts.append(
                as_indices(
                    rows[f"f{want}"].reshape(-1),
                    lambda i, done=done, k=k: (
                        f"{path}: row {done + i // k:,} of element {e.name!r} (item {i % k})"
                    ),
                )
            )
        for i in scalars:
            scalars[i].append(rows[f"f{i}"])
        pos += run * dt.itemsize
        done += run
        window = window * 2 if run == w else 64
    if want is not None:
        return pos, (_cat(sizes_parts, np.int64), _cat(value_parts, np.int64))
    return pos, {i: _cat(v, np.float64) for i, v in scalars.items()}


def _cat(parts: list[np.ndarray], dtype) -> np.ndarray:
    return np.concatenate(parts) if parts else np.zeros(0, dtype=dtype)


# ---------------------------------------------------------------------- text
def _read_text(fh, path, elements, lineno, vertex, face, xyz, index, head, body):
    """Rows as lines: every element's rows parsed block by block (numbers as floats)."""
    bounds = np.cumsum([0] + [e.count for e in elements])
    total = int(bounds[-1])
    seen = 0
    vertex_at = elements.index(vertex)
    face_at = elements.index(face)
    known = body is not None  # a pipe: rows kept as they come
    vertices = Rows(vertex.count, (3,), np.float64, known)
    sizes = Rows(face.count, (), np.int64, known)
    corners: list[np.ndarray] = []
    for first_line, block in line_blocks(fh, path, "PLY", head=head, start=False):
        n0 = lineno + first_line - 1
        s = scan(block, comments=False)
        data = np.flatnonzero(s.ntok)
        g = seen + np.arange(data.size)
        seen += data.size
        if data.size and g[-1] >= total:
            extra = int(data[np.argmax(g >= total)])
            limit = total
            # rows of the elements before the extra line are still read first
            data, g = data[g < limit], g[g < limit]
        else:
            extra = -1
        for k, e in enumerate(elements):
            sel = (g >= bounds[k]) & (g < bounds[k + 1])
            if not sel.any() or k not in (vertex_at, face_at):
                continue
            lines = data[sel]
            at = int(g[sel][0] - bounds[k])
            if k == vertex_at:
                vertices.put(at, _text_vertices(s, lines, block, n0, path, e, xyz, at))
            else:
                got_sizes, got_corners = _text_faces(s, lines, block, n0, path, e, index)
                sizes.put(at, got_sizes)
                corners.append(got_corners)
        if extra >= 0:
            raise MeshError(
                f"{path}:{n0 + extra}: more rows than the header announces ({total:,}): "
                f"{show(block[int(s.start[extra]) : int(s.end[extra])])}"
            )
    if seen < total:
        have = ", ".join(f"{e.count:,} {e.name}" for e in elements)
        raise MeshError(f"{path}: the header announces {have} rows, the file has {seen:,}")
    return vertices.result(), sizes.result(), _cat(corners, np.int64)


def _text_rows(s, lines, block, n0, path, e):
    """Every token of ``lines`` as a float, and each line's token count and first token."""
    ntok = s.ntok[lines]
    data = s.select(lines, True)
    values = parse_floats(data, int(ntok.sum()))
    if values is None:  # line by line: read what numpy would not, or name the bad line
        parsed: list[float] = []
        for line in lines.tolist():
            text = block[int(s.start[line]) : int(s.end[line])]
            try:
                row: list[float] | None = [float(x) for x in text.split()]
            except ValueError:
                row = None
            if row is None or len(row) != s.ntok[line]:
                raise MeshError(f"{path}:{n0 + line}: bad number in a {e.name} row: {show(text)}")
            parsed += row
        values = np.array(parsed)
    first = np.cumsum(ntok) - ntok
    return values, ntok, first


def _text_vertices(s, lines, block, n0, path, e, xyz, at0):
    values, ntok, first = _text_rows(s, lines, block, n0, path, e)
    if e.fixed:
        wrong = np.flatnonzero(ntok != len(e.props))
        if wrong.size:
            line = int(lines[wrong[0]])
            raise MeshError(
                f"{path}:{n0 + line}: a vertex row needs {len(e.props)} numbers, "
                f"this one has {int(ntok[wrong[0]])}"
            )
        at = first[:, None] + np.asarray(xyz)
    else:  # list properties too (skipped): row by row
        at = _walk(values, ntok, first, lines, n0, path, e)[0][:, xyz]
    got = values[at]
    if not np.isfinite(got).all():  # nan, inf or an overflow: name the line
        r = int(np.flatnonzero(~np.isfinite(got).all(axis=1))[0])
        line = int(lines[r])
        text = block[int(s.start[line]) : int(s.end[line])]
        tokens = text.split()
        picked = [tokens[int(t - first[r])] for t in at[r]]
        error = bad_coordinate(f"{path}:{n0 + line}", f"vertex {at0 + r}", text, picked)
        raise error or MeshError(f"{path}:{n0 + line}: a non-finite coordinate in {show(text)}")
    return got


def _text_faces(s, lines, block, n0, path, e, index):
    values, ntok, first = _text_rows(s, lines, block, n0, path, e)
    if _lists(e) > 1:  # several lists (texture coordinates): row by row
        return _text_faces_slowly(values, ntok, first, lines, n0, path, e, index)
    before, after = index, len(e.props) - index - 1
    k = values[first + before]
    ok = (k >= 0) & (k == np.floor(k)) & (ntok == before + 1 + k + after)
    if not ok.all():
        return _text_faces_slowly(values, ntok, first, lines, n0, path, e, index)
    k = k.astype(np.int64)
    at = np.repeat(first + before + 1 - (np.cumsum(k) - k), k) + np.arange(int(k.sum()))
    return k, _whole(values[at], path, n0, lines, np.repeat(np.arange(lines.size), k))


def _text_faces_slowly(values, ntok, first, lines, n0, path, e, index):
    start, count = _walk(values, ntok, first, lines, n0, path, e)
    sizes = count[:, index]
    at = np.repeat(start[:, index] - (np.cumsum(sizes) - sizes), sizes) + np.arange(sizes.sum())
    flat = values[at]
    return sizes, _whole(flat, path, n0, lines, np.repeat(np.arange(lines.size), sizes))


def _walk(values, ntok, first, lines, n0, path, e) -> tuple[np.ndarray, np.ndarray]:
    """Text rows with list properties, row by row: where every property's
    values start in ``values`` and how many it has (1 for a scalar)."""
    start = np.empty((lines.size, len(e.props)), dtype=np.int64)
    count = np.ones((lines.size, len(e.props)), dtype=np.int64)
    for r in range(lines.size):
        j, end = int(first[r]), int(first[r] + ntok[r])
        for i, p in enumerate(e.props):
            c = float(values[j]) if j < end else -1.0
            if p.count is not None and not (0 <= c <= end - j - 1 and c == int(c)):
                j = -1  # no count, or not one that fits the row (nan, a fraction)
            if j < 0 or j >= end:
                raise MeshError(
                    f"{path}:{n0 + int(lines[r])}: a {e.name} row that does not match "
                    "the header's properties"
                )
            if p.count is None:
                start[r, i] = j
                j += 1
            else:
                start[r, i], count[r, i] = j + 1, int(c)
                j += 1 + int(c)
        if j != end:
            raise MeshError(
                f"{path}:{n0 + int(lines[r])}: a {e.name} row that does not match "
                "the header's properties"
            )
    return start, count


def _whole(values: np.ndarray, path, n0, lines, row_of) -> np.ndarray:
    """Text rows' vertex indices (parsed as floats) as int64, or the line of a bad one."""
    return as_indices(values, lambda i: f"{path}:{n0 + int(lines[row_of[i]])}")


def as_indices(values: np.ndarray, where) -> np.ndarray:
    """Vertex indices as int64: integers as they are; floats only if every one
    is a whole number (a MeshError at ``where(i)`` names the first that is
    not: a fraction, nan, an infinity, or one beyond any vertex count)."""
    if values.dtype.kind != "f":
        return values.astype(np.int64)
    with np.errstate(invalid="ignore"):
        ok = (values == np.floor(values)) & (np.abs(values) < MAX_COUNT)
    if not ok.all():
        i = int(np.argmin(ok))
        v, shown = float(values[i]), str(values[i])  # as the file's type prints it: 0.7
        if np.isnan(v):
            why = "vertex index nan (not a number)"
        elif np.isinf(v):
            why = f"vertex index {shown} (an infinity)"
        elif v == np.floor(v):
            why = f"vertex index {shown} out of range (far beyond any vertex count)"
        else:
            why = f"vertex index {shown} is not an integer (a float index must be a whole number)"
        raise MeshError(f"{where(i)}: {why}")
    return values.astype(np.int64)


# ---------------------------------------------------------------------- writing
def check_write_options(ascii: Any = False, byteorder: Any = "little") -> None:
    """Refuse bad :func:`write_ply` options (before anything is written)."""
    if not isinstance(ascii, (bool, np.bool_)):
        raise TypeError(f"write_ply: ascii must be True or False, got {ascii!r}")
    if byteorder not in ("little", "big"):
        raise ValueError(f"write_ply: byteorder must be 'little' or 'big', got {byteorder!r}")


def write_ply(
    mesh: Mesh,
    path: str | os.PathLike,
    *,
    ascii: bool = False,
    byteorder: str = "little",
    force: bool = False,
) -> None:
    """Write a PLY file to exactly ``path``: binary (default) or ``ascii=True``.

    Positions are written as ``double`` (exact), faces as a ``vertex_indices``
    list (a ``uchar`` count, ``int`` indices; an ``int`` count for faces of
    more than 255 sides).

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
    ascii : bool
        Text instead of binary (coordinates in ``repr`` precision).
    byteorder : {"little", "big"}
        Of a binary file.
    force : bool
        Replace a read-only file too (see :func:`pentanb.write`).
    """
    check_write_options(ascii, byteorder)
    write_as(mesh, path, "ply", "write_ply", _write, force=force, ascii=ascii, byteorder=byteorder)


def _write(mesh: Mesh, fh: IO[bytes], ascii: bool = False, byteorder: str = "little") -> None:
    check_mesh(mesh, "write_ply")
    check_write_options(ascii, byteorder)
    order = "<" if byteorder == "little" else ">"
    big = int(mesh.face_sizes.max()) > 255
    count = "int" if big else "uchar"
    index = "int" if mesh.n_vertices < 2**31 else "uint"
    encoding = "ascii" if ascii else f"binary_{byteorder}_endian"
    fh.write(
        (
            f"ply\nformat {encoding} 1.0\ncomment written by pentanb\n"
            f"element vertex {mesh.n_vertices}\n"
            "property double x\nproperty double y\nproperty double z\n"
            f"element face {mesh.n_faces}\n"
            f"property list {count} {index} vertex_indices\nend_header\n"
        ).encode()
    )
    if ascii:
        write_vertices(fh, mesh.vertices, "")
        write_faces(fh, mesh, "", 0, with_size=True)
        return
    v = mesh.vertices
    for a in range(0, v.shape[0], WRITE_ROWS):
        fh.write(v[a : a + WRITE_ROWS].astype(order + "f8").tobytes())
    ct = np.dtype(order + TYPES[count])
    it = np.dtype(order + TYPES[index])
    sizes, offsets, corners = mesh.face_sizes, mesh.offsets, mesh.corners
    for a in range(0, sizes.size, WRITE_ROWS):
        s = sizes[a : a + WRITE_ROWS]
        lo, hi = int(offsets[a]), int(offsets[a + s.size])
        c = corners[lo:hi]
        if s.min() == s.max():
            rows = np.empty(s.size, dtype=[("n", ct), ("i", it, (int(s[0]),))])
            rows["n"] = s
            rows["i"] = c.reshape(s.size, -1)
            fh.write(rows.tobytes())
            continue
        row_bytes = ct.itemsize + it.itemsize * s
        start = np.cumsum(row_bytes) - row_bytes
        out = np.empty(int(row_bytes.sum()), dtype=np.uint8)
        out[start[:, None] + np.arange(ct.itemsize)] = (
            s.astype(ct).view(np.uint8).reshape(-1, ct.itemsize)
        )
        face = np.repeat(np.arange(s.size), s)
        slot = np.arange(c.size) - (offsets[a : a + s.size] - lo)[face]
        at = start[face] + ct.itemsize + it.itemsize * slot
        out[at[:, None] + np.arange(it.itemsize)] = (
            c.astype(it).view(np.uint8).reshape(-1, it.itemsize)
        )
        fh.write(out.tobytes())
