"""STL: triangles as loose corner triples, welded into a mesh with shared vertices.

An STL file lists every triangle with its own three corners (and a normal,
ignored here); a corner shared by six triangles is written six times.
:func:`read_stl` *welds* the corners: corners at the same point become one
vertex.  By default "the same point" means equal coordinates (after
``-0.0`` is taken as ``0.0``), which is what every STL writer produces for a
shared corner; with ``tolerance > 0`` corners closer than that are merged
too.  The welded triangles must form a consistently oriented 2-manifold, closed
(the paper's meshes) or open with boundary loops, or a
:class:`~pentanb.MeshError` says why.  Facets that share no corner with
their neighbours (an unwelded soup) read as an open mesh of loose
triangles: ``mesh.n_boundary_loops`` tells.
"""

from __future__ import annotations

import io
import os
import warnings
from pathlib import Path
from typing import IO, Any

import numpy as np

from ..mesh import Mesh, MeshError
from ..mesh.build import adopted
from ._common import (
    BOM,
    bad_coordinate,
    check_mesh,
    line_blocks,
    open_source,
    parse_floats,
    read_after,
    read_exactly,
    scan,
    show,
    write_as,
)
from .obj import WRITE_ROWS

__all__ = ["read_stl", "write_stl", "weld"]

#: Bytes after the header of a file that starts with 'solid' looked at for a
#: NUL byte (binary STL has one in nearly every triangle, ASCII STL none).
PEEK_BYTES = 4096

_BINARY = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])

# the keywords of an ASCII STL, by code
_KEYWORDS = [b"solid", b"facet", b"outer", b"vertex", b"endloop", b"endfacet", b"endsolid"]
SOLID, FACET, OUTER, VERTEX, ENDLOOP, ENDFACET, ENDSOLID = range(7)
_FACET_PATTERN = np.array([FACET, OUTER, VERTEX, VERTEX, VERTEX, ENDLOOP, ENDFACET])


def read_stl(path: str | os.PathLike | IO[bytes], tolerance: float = 0.0) -> Mesh:
    """Read an STL file (binary or ASCII) and weld its corners into shared vertices.

    A file is binary when its size is the one its triangle count gives (an
    80-byte header, a count, 50 bytes a triangle); else it is ASCII if it
    starts with ``solid`` (after a UTF-8 byte-order mark, if any) and holds
    no NUL byte.  From a pipe, whose size is not known beforehand, a file
    that starts with ``solid`` and has no NUL byte in its first kilobytes is
    ASCII, any other binary.  ASCII lines may end in LF, CRLF or CR, mixed.

    Parameters
    ----------
    path : str, path-like or binary file object
        The file to read: a regular file or a pipe (see :func:`pentanb.read`).
    tolerance : float, >= 0
        Corners at exactly equal coordinates are always one vertex.  With
        ``tolerance > 0``, corners closer than ``tolerance`` (Euclidean
        distance, in the file's units) are merged too, transitively: a
        chain of corners each within ``tolerance`` of the next becomes one
        vertex, at the position of its first corner in the file.  Needs
        scipy.

    Returns
    -------
    Mesh
        Triangles in the file's order; vertices in the order their first
        corner appears.

    Raises
    ------
    MeshError
        A damaged file (a size that does not match a binary file's count, a
        bad ASCII line, a facet that is not a triangle), a facet whose
        corners weld into fewer than three vertices, or welded triangles
        that are not an oriented 2-manifold (the mesh's message, e.g. the
        first non-manifold edge).

    Warns
    -----
    UserWarning
        No two of several facets share a corner: the file reads as loose
        triangles (an open mesh), usually a sign that ``tolerance`` is needed.
    """
    tolerance = _check_tolerance(tolerance)
    with open_source(path, "read_stl") as src:
        fh, path, size = src.fh, src.name, src.size
        head = read_exactly(fh, 84)
        count = int(np.frombuffer(head, "<u4", 1, 80)[0]) if len(head) == 84 else -1
        expected = 84 + 50 * count
        lines = None
        if size is not None and count >= 0 and size == expected:
            corners = _read_binary(fh, count)
        else:
            corners, lines = _read_other(fh, path, size, head, count)
    if corners.shape[0] == 0:
        raise MeshError(f"{path}: no triangles")
    bad = np.flatnonzero(~np.isfinite(corners).all(axis=1))
    if bad.size:
        raise MeshError(
            f"{path}: facet {int(bad[0]) // 3}{_at(lines, int(bad[0]) // 3)} has a non-finite "
            f"coordinate {corners[bad[0]].tolist()}"
        )
    vertices, index = weld(corners, tolerance)
    tri = index.reshape(-1, 3)
    flat = np.flatnonzero(
        (tri[:, 0] == tri[:, 1]) | (tri[:, 1] == tri[:, 2]) | (tri[:, 0] == tri[:, 2])
    )
    if flat.size:
        f = int(flat[0])
        raise MeshError(
            f"{path}: facet {f}{_at(lines, f)} has two corners at the same point after welding "
            f"{corners[3 * f : 3 * f + 3].tolist()} ({flat.size:,} such facets): a facet of no "
            "area cannot be part of a manifold"
        )
    if tri.shape[0] > 1 and vertices.shape[0] == index.size:
        warnings.warn(
            f"{path}: no two of the {tri.shape[0]:,} facets share a corner, so the mesh is "
            f"{tri.shape[0]:,} loose triangles (an open mesh with as many boundary loops); "
            "if corners differ by rounding, pass tolerance= to weld them",
            UserWarning,
            stacklevel=2,
        )
    try:
        mesh = adopted(vertices, index, np.arange(0, index.size + 1, 3, dtype=np.int64))
    except MeshError as exc:
        raise MeshError(
            f"{path}: the {tri.shape[0]:,} facets, welded into {vertices.shape[0]:,} vertices "
            f"(tolerance {tolerance}), are not an oriented 2-manifold: {exc}"
        ) from None
    return mesh


def _read_other(fh, path, size, head, count) -> tuple[np.ndarray, np.ndarray | None]:
    """An STL file whose size does not show it binary: ASCII, binary from a
    pipe (whose size is not known beforehand), or an error that says which
    it looks like and gives the sizes."""
    expected = 84 + 50 * count
    solid = head.removeprefix(BOM).lstrip().startswith(b"solid")
    peek = b""
    if solid:
        peek = read_exactly(fh, PEEK_BYTES)
        if b"\x00" not in head + peek:  # ASCII STL is text: no NUL byte
            return _read_text(fh, path, head + peek)
    more = False
    if size is None and count >= 0:  # a pipe: read what the count says, and a byte more
        data = peek + read_exactly(fh, max(0, expected - 84 + 1 - len(peek)))
        if len(data) == expected - 84:
            return _read_binary(io.BytesIO(data), count), None
        more = len(data) > expected - 84
        size = 84 + len(data)
    has = f"more than {expected:,}" if more else f"{size:,}"
    if solid:
        raise MeshError(
            f"{path}: a binary STL (its header begins with 'solid', but it holds NUL bytes) "
            f"whose header says {count:,} triangles ({expected:,} bytes) but the file has "
            f"{has} bytes: a truncated or damaged binary STL (or a damaged ASCII one)"
        )
    if count >= 0 and all(9 <= b < 127 for b in head):
        raise MeshError(
            f"{path}:1: text that does not start with 'solid': not an ASCII STL file (and "
            "not a binary one: its size does not match)"
        )
    if count >= 0:
        raise MeshError(
            f"{path}: a binary STL whose header says {count:,} triangles "
            f"({expected:,} bytes) but the file has {has} bytes"
        )
    raise MeshError(f"{path}: not an STL file (no 'solid' line, too short for binary STL)")


def _at(lines: np.ndarray | None, facet: int) -> str:
    return "" if lines is None else f" (line {int(lines[facet])})"


def _check_tolerance(tolerance: Any) -> float:
    if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float, np.number)):
        raise TypeError(f"tolerance must be a number >= 0, got {type(tolerance).__name__}")
    if not np.isfinite(tolerance) or tolerance < 0:
        raise ValueError(f"tolerance must be a finite number >= 0, got {tolerance!r}")
    return float(tolerance)


def _read_binary(fh: IO[bytes], count: int) -> np.ndarray:
    data = read_after(fh, b"", 50 * count)
    rows = np.frombuffer(data, dtype=_BINARY, count=count)
    return rows["corners"].reshape(-1, 3).astype(np.float64)


def _read_text(fh: IO[bytes], path: Path, head: bytes) -> tuple[np.ndarray, np.ndarray]:
    """ASCII STL (``head``: its first bytes, already read): the corners (3 per
    facet) and the line of every facet."""
    codes: list[np.ndarray] = []
    numbers: list[np.ndarray] = []
    points: list[np.ndarray] = []
    for lineno, block in line_blocks(fh, path, "STL", head=head):
        s = scan(block, comments=False)
        lines = np.flatnonzero(s.ntok)
        key = s.tok[s.first[lines]]
        code = np.full(lines.size, -1, dtype=np.int8)
        for c, word in enumerate(_KEYWORDS):
            at = key[:, None] + np.arange(len(word) + 1)
            ok = at[:, -1] < s.buf.size
            match = ok.copy()
            match[ok] = np.all(s.buf[at[ok, :-1]] == np.frombuffer(word, np.uint8), axis=1)
            match[ok] &= s.buf[at[ok, -1]] <= 32
            code[match] = c
        unknown = np.flatnonzero(code < 0)
        if unknown.size:
            line = int(lines[unknown[0]])
            raise MeshError(
                f"{path}:{lineno + line}: not an STL line: "
                f"{show(block[int(s.start[line]) : int(s.end[line])])}"
            )
        vl = lines[code == VERTEX]
        if vl.size:
            wrong = np.flatnonzero(s.ntok[vl] != 4)
            s.buf[s.tok[s.first[vl]][:, None] + np.arange(6)] = 32
            values = None if wrong.size else parse_floats(s.select(vl, False), 3 * vl.size, 3)
            if values is None or not np.isfinite(values).all():
                _bad_vertex(block, s, vl, lineno, path, sum(len(p) for p in points))
            points.append(np.asarray(values).reshape(-1, 3))
        codes.append(code)
        numbers.append(lineno + lines)
    code = np.concatenate(codes) if codes else np.zeros(0, np.int8)
    number = np.concatenate(numbers) if numbers else np.zeros(0, np.int64)
    if not code.size or code[0] != SOLID:
        raise MeshError(f"{path}:{int(number[0]) if number.size else 1}: no 'solid' line")
    body = (code != SOLID) & (code != ENDSOLID)
    c, n = code[body], number[body]
    usable = c.size - c.size % 7
    rows = c[:usable].reshape(-1, 7)
    wrong = np.flatnonzero((rows != _FACET_PATTERN).any(axis=1))
    if wrong.size or usable != c.size:
        r = int(wrong[0]) if wrong.size else usable // 7
        seen = c[7 * r : 7 * r + 7]
        j = int(np.argmax(seen != _FACET_PATTERN[: seen.size])) if seen.size else 0
        if seen.size and seen[j] == _FACET_PATTERN[j]:
            j = seen.size  # the file ends inside this facet
        line = int(n[7 * r + j]) if 7 * r + j < n.size else int(number[-1])
        found = _KEYWORDS[int(seen[j])].decode() if j < seen.size else "the end of the file"
        raise MeshError(
            f"{path}:{line}: facet {r} is not 'facet / outer loop / 3 vertex / endloop / "
            f"endfacet': expected {_KEYWORDS[int(_FACET_PATTERN[j])].decode()!r}, found "
            f"{found!r} (STL facets are triangles)"
        )
    corners = np.concatenate(points) if points else np.zeros((0, 3))
    return corners, n[0::7]


def _bad_vertex(block, s, vl, lineno, path, before):
    for k, line in enumerate(vl.tolist()):
        text = block[int(s.start[line]) : int(s.end[line])]
        parts = text.split()
        try:
            if len(parts) != 4:
                raise ValueError
            [float(x) for x in parts[1:]]
        except ValueError:
            raise MeshError(
                f"{path}:{lineno + line}: a vertex line needs 3 numbers: {show(text)}"
            ) from None
        what = f"facet {(before + k) // 3}"
        error = bad_coordinate(f"{path}:{lineno + line}", what, text, parts[1:])
        if error is not None:
            raise error
    raise MeshError(f"{path}:{lineno}: unreadable vertex lines in this block")


def weld(points: np.ndarray, tolerance: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Merge coincident points.

    Parameters
    ----------
    points : (k, 3) float
    tolerance : float, >= 0
        0: points with equal coordinates (``-0.0 == 0.0``) merge.  Above 0:
        also points closer than ``tolerance``, transitively (needs scipy).

    Returns
    -------
    vertices : (n, 3) float
        One point per group, the group's first, in the order of first
        appearance.
    index : (k,) int
        The vertex of every point.
    """
    p = np.ascontiguousarray(points, dtype=np.float64) + 0.0  # -0.0 becomes 0.0
    label, first = _groups(p)
    if tolerance > 0 and first.size > 1:
        merged = _near(p[first], tolerance)
        merged_first = np.full(int(merged.max()) + 1, p.shape[0], dtype=np.int64)
        np.minimum.at(merged_first, merged, first)
        label, first = merged[label], merged_first
    by_first = np.argsort(first, kind="stable")
    rank = np.empty_like(by_first)
    rank[by_first] = np.arange(by_first.size)
    return p[first[by_first]], rank[label]


def _groups(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Group equal points: a group label for every point and each group's first point.

    One sort by a 64-bit hash of the coordinates' bits, then a check that
    the points sharing a hash are equal; if two different points share one
    (a collision), a lexicographic sort of the coordinates instead.
    """
    cols = np.ascontiguousarray(p.T)  # one row per coordinate: 1-D takes are fastest
    key = _hash(cols)
    order = np.argsort(key)
    sk = key.take(order)
    runs = np.ones(p.shape[0], dtype=bool)
    runs[1:] = sk[1:] != sk[:-1]
    sorted_cols = [c.take(order) for c in cols]
    same = np.ones(p.shape[0] - 1, dtype=bool)
    for c in sorted_cols:
        same &= c[1:] == c[:-1]
    if np.any(~runs[1:] & ~same):  # a collision: sort the coordinates themselves
        order = np.lexsort(cols[::-1])
        sorted_cols = [c.take(order) for c in cols]
        runs[1:] = False
        for c in sorted_cols:
            runs[1:] |= c[1:] != c[:-1]
    starts = np.flatnonzero(runs)
    label = np.empty(p.shape[0], dtype=np.int64)
    label[order] = np.cumsum(runs) - 1
    return label, np.minimum.reduceat(order, starts)


def _hash(cols: np.ndarray) -> np.ndarray:
    """(n,) uint64: a hash of the bits of the coordinates ``cols`` (3, n)."""
    key = np.zeros(cols.shape[1], dtype=np.uint64)
    for b, k in zip(cols.view(np.uint64), (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B1)):
        # fold the high bits (sign, exponent, the mantissa's top) down before mixing
        key += (b ^ (b >> np.uint64(29))) * np.uint64(k)
    key ^= key >> np.uint64(31)
    return key


def _near(points: np.ndarray, tolerance: float) -> np.ndarray:
    """A group label for every point: points closer than ``tolerance``, transitively."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    n = points.shape[0]
    pairs = cKDTree(points).query_pairs(tolerance, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs), dtype=np.int8), (pairs[:, 0], pairs[:, 1])), (n, n))
    return connected_components(graph, directed=False)[1].astype(np.int64)


def check_write_options(ascii: Any = False) -> None:
    """Refuse bad :func:`write_stl` options (before anything is written)."""
    if not isinstance(ascii, (bool, np.bool_)):
        raise TypeError(f"write_stl: ascii must be True or False, got {ascii!r}")


def write_stl(
    mesh: Mesh, path: str | os.PathLike, *, ascii: bool = False, force: bool = False
) -> None:
    """Write an STL file to exactly ``path``: binary (default) or ``ascii=True``.

    STL holds triangles only: every polygon is fanned from its first corner
    (:meth:`Mesh.fan_triangles`), so reading the file back gives the
    triangles, not the polygons.  Binary STL stores ``float32``
    coordinates (a round trip is exact only for positions that are float32
    numbers); ASCII STL is written with ``repr`` precision (exact).  Each
    facet's normal is its polygon's unit normal.

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
        The file to write; its name is used as given.
    ascii : bool
        Write ASCII STL (exact coordinates) instead of binary (float32).
    force : bool
        Replace a read-only file too (see :func:`pentanb.write`).

    Raises
    ------
    MeshError
        Binary STL only, before anything is written: a vertex whose
        coordinates float32 cannot hold (beyond +-3.4e38; the message names
        it), a face whose fan triangle has two corners at one float32 point
        (it collapses to a line or a point; the message names the face), or
        two vertices at one float32 point (reading the file would weld them).
        Write ``ascii=True`` (exact) or scale the mesh.
    """
    check_mesh(mesh, "write_stl")
    check_write_options(ascii)
    prepared = prepare(mesh, ascii, "write_stl")
    write_as(mesh, path, "stl", "write_stl", _write, force=force, ascii=ascii, prepared=prepared)


def prepare(mesh: Mesh, ascii: Any = False, caller: str = "write") -> tuple[np.ndarray, ...]:
    """The triangles, their polygons, the normals and the coordinates to write
    (float32 for binary), checked so that the file reads back as these
    triangles; a MeshError (see :func:`write_stl`) before anything is written."""
    tris, face = mesh.fan_triangles()
    normals = mesh.face_normals
    if not np.isfinite(normals).all():  # (never, for a Mesh: zero for a degenerate face)
        normals = np.where(np.isfinite(normals).all(axis=1, keepdims=True), normals, 0.0)
    if ascii:
        return tris, face, normals, mesh.vertices
    if tris.shape[0] >= 1 << 32:
        raise MeshError(f"{caller}: {tris.shape[0]:,} triangles; binary STL holds fewer than 2**32")
    v = mesh.vertices
    with np.errstate(over="ignore", under="ignore"):
        v32 = v.astype(np.float32)
    bad = np.flatnonzero(~np.isfinite(v32).all(axis=1))
    if bad.size:
        i = int(bad[0])
        raise MeshError(
            f"{caller}: vertex {i} at {v[i].tolist()} is beyond the range of float32 "
            f"(+-{np.finfo(np.float32).max:.4g}), which binary STL stores ({bad.size:,} such "
            "vertices); write ascii=True (exact coordinates) or scale the mesh"
        )
    if _distinct(v32):  # the common case, at the cost of one sort of 64-bit keys
        return tris, face, normals, v32
    # some vertices share a float32 point: a face that collapses, or two vertices
    t = v32[tris]
    same = (t[:, 0] == t[:, 1]).all(axis=1) | (t[:, 1] == t[:, 2]).all(axis=1)
    same |= (t[:, 0] == t[:, 2]).all(axis=1)
    del t
    flat = np.flatnonzero(same)
    if flat.size:
        k = int(flat[0])
        f = int(face[k])
        ring = mesh.corners[mesh.offsets[f] : mesh.offsets[f + 1]].tolist()
        raise MeshError(
            f"{caller}: face {f} (vertices {ring}): its fan triangle "
            f"{tris[k].tolist()} has two corners at one float32 point (binary STL's "
            f"precision) and collapses to a line or a point ({flat.size:,} such triangles); "
            "the file could not be read back: write ascii=True (exact coordinates) or "
            "scale the mesh"
        )
    _, index = weld(v32.astype(np.float64))
    if index.max() + 1 < v.shape[0]:
        order = np.argsort(index, kind="stable")
        dup = np.flatnonzero(index[order][1:] == index[order][:-1])
        i, j = sorted((int(order[dup[0]]), int(order[dup[0] + 1])))
        raise MeshError(
            f"{caller}: vertices {i} and {j} ({v[i].tolist()} and {v[j].tolist()}) are at "
            "one float32 point (binary STL's precision): reading the file would weld "
            "them into one; write ascii=True (exact coordinates) or scale the mesh"
        )
    return tris, face, normals, v32


def _distinct(points: np.ndarray) -> bool:
    """Whether the rows of ``points`` ((n, 3) float32) are at distinct points
    (``-0.0`` is ``0.0``).  False may be a hash collision: the caller then
    compares the coordinates themselves."""
    bits = (points + np.float32(0.0)).view(np.uint32).astype(np.uint64)
    key = (bits[:, 0] << np.uint64(32)) | bits[:, 1]
    key ^= bits[:, 2] * np.uint64(0x9E3779B97F4A7C15)
    key.sort()
    return not np.any(key[1:] == key[:-1])


def _write(
    mesh: Mesh,
    fh: IO[bytes],
    ascii: bool = False,
    prepared: tuple[np.ndarray, ...] | None = None,
) -> None:
    check_mesh(mesh, "write_stl")
    check_write_options(ascii)
    tris, face, normals, v = prepared or prepare(mesh, ascii, "write_stl")
    if not ascii:
        fh.write(b"pentanb binary STL".ljust(80, b" "))
        fh.write(np.array([tris.shape[0]], dtype="<u4").tobytes())
    else:
        fh.write(b"solid pentanb\n")
    facet = (
        "facet normal %r %r %r\n outer loop\n  vertex %r %r %r\n  vertex %r %r %r\n"
        "  vertex %r %r %r\n endloop\nendfacet\n"
    )
    for a in range(0, tris.shape[0], WRITE_ROWS):
        t = tris[a : a + WRITE_ROWS]
        n = normals[face[a : a + WRITE_ROWS]]
        if ascii:
            values = np.concatenate([n, v[t].reshape(-1, 9)], axis=1)
            fh.write(((facet * t.shape[0]) % tuple(values.ravel().tolist())).encode())
        else:
            rows = np.zeros(t.shape[0], dtype=_BINARY)
            rows["normal"] = n
            rows["corners"] = v[t]
            fh.write(rows.tobytes())
    if ascii:
        fh.write(b"endsolid pentanb\n")
