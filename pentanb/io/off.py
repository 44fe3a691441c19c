"""OFF: a header ``OFF``, the counts ``V F E``, V vertex lines, then F face lines ``k i1 .. ik``.

The counts are checked as the file is read: a file with more data lines
than its header announces fails at the first extra line (without reading
the rest), one whose counts could not fit in its size fails at the header,
and the arrays are allocated once, from the header.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import IO

import numpy as np

from ..mesh import Mesh, MeshError
from ._common import (
    MAX_COUNT,
    Rows,
    bad_coordinate,
    check_mesh,
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
from .obj import write_faces, write_vertices

__all__ = ["read_off", "write_off"]


def read_off(path: str | os.PathLike | IO[bytes]) -> Mesh:
    """Read an OFF file (header ``OFF``, counts, vertices, then ``k i1 .. ik`` faces).

    ``COFF``, ``NOFF`` and the like are read too: columns after a vertex's
    three coordinates and after a face's indices (colours, normals) are
    ignored.  Comments (``#``) and blank lines may appear anywhere.  The
    file is read as bytes, so any encoding of its comments is fine; a UTF-8
    byte-order mark is skipped, and lines may end in LF, CRLF or CR, mixed.

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
        A missing header, bad counts, a bad number or index, or counts that
        do not match the data lines; the message names the file and line.
        A file whose mesh is not an oriented 2-manifold (closed or with
        boundary) raises the mesh's own
        error, prefixed with the file name.
    """
    with open_source(path, "read_off") as src:
        reader = _Reader(src.name, src.size)
        for lineno, block in line_blocks(src.fh, src.name, "OFF"):
            reader.block(block, lineno)
        return reader.finish()


class _Reader:
    """The state of an OFF file read block by block."""

    def __init__(self, path: Path, size: int | None) -> None:
        self.path = path
        self.size = size
        self.header: list[bytes] | None = None  # tokens after "OFF" until the counts are read
        self.header_line = 0
        self.nv = self.nf = -1
        self.seen = 0  # data lines after the header
        self.vertices = Rows(0, (3,), np.float64, True)
        self.sizes = Rows(0, (), np.int64, True)
        self.corners: list[np.ndarray] = []

    # ------------------------------------------------------------------ header
    def _head(self, text: bytes, n: int) -> None:
        """Read one data line of the header (``OFF``, maybe with the counts, or the counts)."""
        parts = text.split(b"#", 1)[0].split()
        if self.header is None:
            if not parts[0].upper().endswith(b"OFF"):
                raise MeshError(f"{self.path}:{n}: not an OFF file (no 'OFF' header)")
            if len(parts) > 1 and parts[1].upper() == b"BINARY":
                raise MeshError(f"{self.path}:{n}: a binary OFF file; only text OFF is read")
            self.header, self.header_line = parts[1:], n
            if not self.header:
                return
        else:
            self.header, self.header_line = parts, n
        self._counts()

    def _counts(self) -> None:
        path, head = self.path, self.header or []
        try:
            nv, nf = int(head[0]), int(head[1])
            if nv < 0 or nf < 0:
                raise ValueError
        except (ValueError, IndexError):
            shown = show(b" ".join(head))
            raise MeshError(f"{path}:{self.header_line}: bad counts line {shown}") from None
        # every vertex line takes at least 6 bytes ("0 0 0\n"), every face line 2
        if self.size is not None and 6 * nv + 2 * nf > self.size + 1:
            raise MeshError(
                f"{path}:{self.header_line}: the header says {nv:,} vertices and {nf:,} "
                f"faces, more than a file of {self.size:,} bytes can hold"
            )
        if max(nv, nf) >= MAX_COUNT:
            raise MeshError(
                f"{path}:{self.header_line}: the header says {nv:,} vertices and {nf:,} "
                f"faces, more than any file holds (at most {MAX_COUNT:,} each)"
            )
        self.nv, self.nf = nv, nf
        known = self.size is not None  # a pipe: rows kept as they come
        self.vertices = Rows(nv, (3,), np.float64, known)
        self.sizes = Rows(nf, (), np.int64, known)

    # ------------------------------------------------------------------ body
    def block(self, block: bytes, lineno: int) -> None:
        s = scan(block)
        data = np.flatnonzero(s.ntok)
        if self.nv < 0:  # the header: a line or two, read one by one
            used = 0
            for line in data.tolist():
                self._head(_line(block, s, line), lineno + line)
                used += 1
                if self.nv >= 0:
                    break
            data = data[used:]
            if self.nv < 0:
                return
        nv, nf = self.nv, self.nf
        g = self.seen + np.arange(data.size)
        self.seen += data.size
        is_v = g < nv
        is_f = (g >= nv) & (g < nv + nf)
        vl, fl = data[is_v], data[is_f]
        if vl.size:
            at = int(g[is_v][0])
            self.vertices.put(at, self._read_vertices(s, vl, block, lineno))
        if fl.size:
            at = int(g[is_f][0]) - nv
            sizes, corners = self._faces(s, fl, block, lineno)
            self.sizes.put(at, sizes)
            self.corners.append(corners)
        if data.size > vl.size + fl.size:
            line = int(data[vl.size + fl.size])
            raise MeshError(
                f"{self.path}:{lineno + line}: the header says {nv} vertices and {nf} faces "
                f"({nv + nf} lines) but the file has more data lines, from this one on: "
                f"{show(_line(block, s, line))}"
            )

    def _read_vertices(self, s, vl: np.ndarray, block: bytes, lineno: int) -> np.ndarray:
        count = s.ntok[vl]
        uniform = bool(count.min() == count.max())
        values = parse_floats(
            s.select(vl, True), int(count.sum()), int(count[0]) if uniform else None
        )
        if values is not None and count.min() >= 3:
            if uniform:
                got = values.reshape(-1, int(count[0]))[:, :3]
            else:
                first = np.cumsum(count) - count
                got = values[first[:, None] + np.arange(3)]
            if np.isfinite(got).all():
                return got
        out = np.empty((vl.size, 3))
        for i, line in enumerate(vl.tolist()):
            text = _line(block, s, line)
            parts = text.split(b"#", 1)[0].split()
            try:
                if len(parts) < 3:
                    raise ValueError
                out[i] = [float(x) for x in parts[:3]]
            except ValueError:
                raise MeshError(
                    f"{self.path}:{lineno + line}: bad vertex line {show(text.split(b'#')[0])}"
                ) from None
            what = f"vertex {self.vertices.filled + i}"
            error = bad_coordinate(f"{self.path}:{lineno + line}", what, text, parts[:3])
            if error is not None:
                raise error
        return out

    def _faces(self, s, fl: np.ndarray, block: bytes, lineno: int) -> tuple[np.ndarray, np.ndarray]:
        ntok = s.ntok[fl]
        values = parse_ints(s.select(fl, True), int(ntok.sum()))
        if values is not None:
            first = np.cumsum(ntok) - ntok
            k = values[first]
            if k.min() >= 0 and np.all(ntok > k):
                at = np.repeat(first + 1 - (np.cumsum(k) - k), k) + np.arange(int(k.sum()))
                idx = values[at]
                if not idx.size or (idx.min() >= 0 and idx.max() < self.nv):
                    return k, idx
        return self._faces_slowly(s, fl, block, lineno)

    def _faces_slowly(self, s, fl, block, lineno) -> tuple[np.ndarray, np.ndarray]:
        path, nv = self.path, self.nv
        sizes = np.empty(fl.size, dtype=np.int64)
        corners: list[int] = []
        for i, line in enumerate(fl.tolist()):
            n = lineno + line
            text = _line(block, s, line).split(b"#", 1)[0]
            parts = text.split()
            try:
                k = int(parts[0])
                idx = [int(x) for x in parts[1 : 1 + k]]
            except (ValueError, IndexError):
                raise MeshError(f"{path}:{n}: bad face line {show(text)}") from None
            if len(idx) != k:
                raise MeshError(f"{path}:{n}: face says {k} vertices but lists {len(idx)}")
            bad = [i for i in idx if not 0 <= i < nv]
            if bad:
                raise MeshError(f"{path}:{n}: face index {bad[0]} out of range ({nv} vertices)")
            sizes[i] = k
            corners += idx
        return sizes, np.array(corners, dtype=np.int64)

    def finish(self) -> Mesh:
        path = self.path
        if self.header is None:
            raise MeshError(f"{path}:1: not an OFF file (no 'OFF' header; the file is empty)")
        if self.nv < 0:
            raise MeshError(f"{path}: missing the vertex and face counts")
        if self.seen != self.nv + self.nf:
            raise MeshError(
                f"{path}: header says {self.nv} vertices and {self.nf} faces "
                f"({self.nv + self.nf} lines) but the file has {self.seen} data lines"
            )
        corners = np.concatenate(self.corners) if self.corners else np.zeros(0, np.int64)
        self.corners.clear()
        return finish(path, self.vertices.result(), corners, offsets_of(self.sizes.result()))


def _line(block: bytes, s, line: int) -> bytes:
    """Line ``line`` of ``block`` as written (the scan's copy has comments blanked)."""
    return block[int(s.start[line]) : int(s.end[line])]


def write_off(mesh: Mesh, path: str | os.PathLike, *, force: bool = False) -> None:
    """Write an OFF file to exactly ``path`` (coordinates in ``repr`` precision).

    A name ending in another format's suffix (``.obj``) is refused (ValueError).

    Parameters
    ----------
    mesh : Mesh
    path : str or path-like
        The file to write; its name is used as given.
    force : bool
        Replace a read-only file too (see :func:`pentanb.write`).
    """
    write_as(mesh, path, "off", "write_off", _write, force=force)


def _write(mesh: Mesh, fh: IO[bytes]) -> None:
    check_mesh(mesh, "write_off")
    fh.write(f"OFF\n{mesh.n_vertices} {mesh.n_faces} {mesh.n_edges}\n".encode())
    write_vertices(fh, mesh.vertices, "")
    write_faces(fh, mesh, "", 0, with_size=True)
