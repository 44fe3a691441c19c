"""Wavefront OBJ: ``v`` and ``f`` lines, polygon faces kept as they are.

Reading is done in blocks of whole lines (about a megabyte each), every
block parsed with whole-array numpy expressions; a block the fast parser
does not understand is read again line by line, which either reads it (an
unusual but valid line: ``nan``, ``1_000``) or names the first bad line.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import IO

import numpy as np

from ..mesh import Mesh, MeshError
from ._common import (
    Scan,
    bad_coordinate,
    check_mesh,
    contiguous,
    finish,
    line_blocks,
    offsets_of,
    open_source,
    parse_floats,
    parse_ints,
    scan,
    show,
    write_as,
)

__all__ = ["read_obj", "write_obj"]

_V, _F, _SLASH, _SPACE = ord("v"), ord("f"), ord("/"), 32

#: Rows written per chunk (bounds the memory a write takes).
WRITE_ROWS = 1 << 16


class _Part:
    """What one block of lines holds."""

    __slots__ = ("vertices", "corners", "sizes", "face_lines", "first_line")

    def __init__(self, vertices, corners, sizes, face_lines, first_line):
        self.vertices = vertices  # (k, 3) float
        self.corners = corners  # (h,) int, 0-based, relative indices resolved
        self.sizes = sizes  # (f,) int
        self.face_lines = face_lines  # (f,) int: line number of every face
        self.first_line = first_line


def read_obj(path: str | os.PathLike | IO[bytes]) -> Mesh:
    """Read an OBJ file: ``v`` and ``f`` lines.

    ``f 1/2/3`` and ``f 1//3`` (the vertex index comes first) and negative
    (relative) indices are understood, as are faces that refer to vertices
    defined further down; extra ``v`` components (``w``, colours) are
    ignored, and so are all other lines.  The file is read as bytes: any
    encoding of comments and names is fine, a UTF-8 byte-order mark is
    skipped, and lines may end in LF, CRLF or CR, mixed.

    Parameters
    ----------
    path : str, path-like or binary file object
        The file to read: a regular file or a pipe (see :func:`pentanb.read`).

    Returns
    -------
    Mesh
        The vertices in the file's order, the faces as written.

    Raises
    ------
    MeshError
        A malformed file (a bad number, a face index out of range, a NUL
        byte); the message names the file and line.  A file whose mesh is
        not an oriented 2-manifold (closed or with boundary) raises the
        mesh's own error, prefixed with the file name.
    """
    parts: list[_Part] = []
    nv = 0
    with open_source(path, "read_obj") as src:
        path = src.name
        for lineno, block in line_blocks(src.fh, path, "OBJ"):
            part = _fast(block, nv, lineno)
            if part is None:
                part = _slow(block, nv, lineno, path)
            parts.append(part)
            nv += part.vertices.shape[0]
    if not any(p.sizes.size for p in parts):
        raise MeshError(f"{path}: no faces")
    for p in parts:  # indices of vertices further down: checked now all are known
        if p.corners.size and p.corners.max() >= nv:
            h = int(np.flatnonzero(p.corners >= nv)[0])
            f = int(np.searchsorted(np.cumsum(p.sizes), h, side="right"))
            raise MeshError(
                f"{path}:{int(p.face_lines[f])}: face index {int(p.corners[h]) + 1} out of "
                f"range ({nv} vertices in the file)"
            )
    vertices = np.concatenate([p.vertices for p in parts]) if nv else np.zeros((0, 3))
    for p in parts:
        p.vertices = None
    sizes = np.concatenate([p.sizes for p in parts])
    corners = np.concatenate([p.corners for p in parts])
    parts.clear()
    return finish(path, vertices, corners, offsets_of(sizes))


def _fast(block: bytes, nv: int, lineno: int) -> _Part | None:
    """Parse a block with whole-array expressions; None if anything is unusual."""
    s: Scan = scan(block)
    lines = np.flatnonzero(s.ntok)
    key = s.tok[s.first[lines]]
    alone = s.buf[key + 1] <= _SPACE  # a one-letter keyword
    is_v = alone & (s.buf[key] == _V)
    is_f = alone & (s.buf[key] == _F)
    s.buf[key[is_v | is_f]] = _SPACE
    vl, fl = lines[is_v], lines[is_f]

    vertices = np.zeros((0, 3))
    if vl.size:
        count = s.ntok[vl] - 1
        uniform = bool(count.min() == count.max())
        values = parse_floats(
            s.select(vl, contiguous(is_v)), int(count.sum()), int(count[0]) if uniform else None
        )
        if values is None or count.min() < 3:
            return None
        if uniform:
            vertices = values.reshape(-1, int(count[0]))[:, :3]
        else:
            first = np.cumsum(count) - count
            vertices = values[first[:, None] + np.arange(3)]
        vertices = np.ascontiguousarray(vertices)
        if not np.isfinite(vertices).all():
            return None  # nan, inf or an overflow: the slow path names the line

    corners = np.zeros(0, dtype=np.int64)
    sizes = s.ntok[fl] - 1
    if fl.size:
        data = s.select(fl, contiguous(is_f))
        total = int(sizes.sum())
        if np.any(data == _SLASH):
            # v/vt/vn: keep the first number of every token
            space = data <= _SPACE
            token = ~space
            token[1:] &= space[:-1]
            slash = data == _SLASH
            data[slash] = _SPACE
            space |= slash
            number = ~space
            number[1:] &= space[:-1]
            at = np.flatnonzero(number)
            values = parse_ints(data, at.size)
            if values is None:
                return None
            idx = values[token[at]]
            if idx.size != total:
                return None
        else:
            values = parse_ints(data, total)
            if values is None:
                return None
            idx = values
        if total:
            if not idx.all():
                return None  # index 0: the slow path names the line
            negative = idx < 0
            if negative.any():
                before = np.repeat(nv + np.searchsorted(vl, fl), sizes)
                idx = np.where(negative, idx + before, idx - 1)
                if idx.min() < 0:
                    return None
            else:
                idx -= 1
        corners = idx
    return _Part(vertices, corners, sizes, lineno + fl, lineno)


def _slow(block: bytes, nv: int, lineno: int, path: Path) -> _Part:
    """Parse a block line by line (the reference the fast path agrees with)."""
    vertices: list[list[float]] = []
    corners: list[int] = []
    sizes: list[int] = []
    face_lines: list[int] = []
    for n, line in enumerate(block.split(b"\n")[:-1], lineno):
        parts = line.split(b"#", 1)[0].split()
        if not parts:
            continue
        if parts[0] == b"v":
            if len(parts) < 4:
                raise MeshError(f"{path}:{n}: a 'v' line needs 3 coordinates: {show(line)}")
            try:
                vertex = [float(x) for x in parts[1:4]]
            except ValueError:
                raise MeshError(f"{path}:{n}: bad number in {show(line)}") from None
            if not all(map(math.isfinite, vertex)):
                what = f"vertex {nv + len(vertices)}"
                raise bad_coordinate(f"{path}:{n}", what, line, parts[1:4]) or AssertionError
            vertices.append(vertex)
        elif parts[0] == b"f":
            for token in parts[1:]:
                try:
                    i = int(token.split(b"/", 1)[0])
                except ValueError:
                    raise MeshError(f"{path}:{n}: bad face index {show(token)}") from None
                if abs(i) >= 1 << 62:
                    raise MeshError(
                        f"{path}:{n}: face index {i} out of range "
                        "(no file holds that many vertices)"
                    )
                if i > 0:
                    i -= 1  # may refer to a vertex defined further down
                elif i < 0:
                    seen = nv + len(vertices)
                    i += seen
                    if i < 0:
                        raise MeshError(
                            f"{path}:{n}: face index {token.decode()} out of range "
                            "(a relative index before the first vertex; "
                            f"{seen} vertices so far)"
                        )
                else:
                    raise MeshError(f"{path}:{n}: face index 0 (OBJ counts from 1)")
                corners.append(i)
            sizes.append(len(parts) - 1)
            face_lines.append(n)
    return _Part(
        np.array(vertices, dtype=np.float64).reshape(-1, 3),
        np.array(corners, dtype=np.int64),
        np.array(sizes, dtype=np.int64),
        np.array(face_lines, dtype=np.int64),
        lineno,
    )


def write_obj(mesh: Mesh, path: str | os.PathLike, *, force: bool = False) -> None:
    """Write an OBJ file (``v`` and ``f`` lines, 1-based indices) to exactly ``path``.

    Coordinates are written with ``repr`` precision, so reading the file
    back gives the very same numbers.  A name ending in another format's
    suffix (``.off``) is refused (ValueError).

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
        The file to write; its name is used as given.
    force : bool
        Replace a read-only file too (see :func:`pentanb.write`).
    """
    write_as(mesh, path, "obj", "write_obj", _write, force=force)


def _write(mesh: Mesh, fh: IO[bytes]) -> None:
    check_mesh(mesh, "write_obj")
    fh.write(f"# pentanb: {mesh.n_vertices} vertices, {mesh.n_faces} faces\n".encode())
    write_vertices(fh, mesh.vertices, "v ")
    write_faces(fh, mesh, "f ", 1, with_size=False)


def write_vertices(fh: IO[bytes], vertices: np.ndarray, prefix: str) -> None:
    """``prefix x y z`` lines, coordinates in ``repr`` precision, in chunks."""
    row = prefix + "%r %r %r\n"
    for a in range(0, vertices.shape[0], WRITE_ROWS):
        chunk = vertices[a : a + WRITE_ROWS]
        fh.write(((row * chunk.shape[0]) % tuple(chunk.ravel().tolist())).encode())


def write_faces(fh: IO[bytes], mesh: Mesh, prefix: str, base: int, with_size: bool) -> None:
    """One line per face: ``prefix [k] i1 ... ik`` with indices counted from ``base``."""
    sizes = mesh.face_sizes
    offsets = mesh.offsets
    formats: dict[int, str] = {}
    for a in range(0, sizes.size, WRITE_ROWS):
        chunk = sizes[a : a + WRITE_ROWS]
        lo, hi = int(offsets[a]), int(offsets[a + chunk.size])
        values = mesh.corners[lo:hi] + base
        if with_size:  # each face's size before its indices
            values = np.insert(values, offsets[a : a + chunk.size] - lo, chunk)
        k = int(chunk[0])
        if chunk.min() == chunk.max():
            fmt = _face_format(k, prefix, with_size) * chunk.size
        else:
            for size in np.unique(chunk).tolist():
                formats.setdefault(size, _face_format(size, prefix, with_size))
            fmt = "".join([formats[size] for size in chunk.tolist()])
        fh.write((fmt % tuple(values.tolist())).encode())


def _face_format(k: int, prefix: str, with_size: bool) -> str:
    return prefix + ("%d " if with_size else "") + " ".join(["%d"] * k) + "\n"
