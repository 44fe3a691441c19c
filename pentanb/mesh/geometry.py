"""Face means and normals that stay exact and finite at any scale.

Means are summed in the order numpy's whole-array expressions would sum them
(so the results are theirs bit for bit) but in blocks of faces, so the memory
beyond the result stays small; positions beyond :data:`SAFE_EXTENT` are
scaled by a power of two first (exact), so no sum overflows.
"""

from __future__ import annotations

import numpy as np

from .. import _jit
from .coerce import FloatArray, MeshError
from .halfedge import BLOCK

__all__ = ["SAFE_EXTENT", "face_means", "scaled_newell"]

#: Above this absolute coordinate, geometry is computed on positions scaled
#: down by a power of two (sums of up to 2**23 coordinates cannot overflow).
SAFE_EXTENT = 2.0**1000


def face_means(
    values: np.ndarray,
    corners: np.ndarray,
    offsets: np.ndarray,
    k: int,
    extent: float,
    out: np.ndarray | None = None,
) -> FloatArray:
    """(m, d) the mean of ``values`` (n, d) over every face, in blocks of faces.

    The sums run in the order of the faces' corners, as numpy's
    ``reshape(m, k).sum(axis=1)`` (faces of k < 8 corners) or
    ``np.add.reduceat`` (mixed sizes) would add them, so the results are
    those of those whole-array expressions, bit for bit; only the memory
    they need is bounded (a block at a time).  Values beyond
    :data:`SAFE_EXTENT` are scaled down by a power of two first (exact),
    so no sum overflows.  ``out``, (m, d) float64 and C-contiguous when
    given, receives the means (and is returned).
    """
    values = values.reshape(values.shape[0], -1)
    if extent >= SAFE_EXTENT:
        shift = int(np.frexp(extent)[1]) - 1000
        out = face_means(np.ldexp(values, -shift), corners, offsets, k, 0.0, out)
        np.ldexp(out, shift, out=out)
        if not np.isfinite(out).all():
            raise MeshError(
                f"coordinates up to {extent:.3g} are too large: a mean of them "
                "is not a finite float64"
            )
        return out
    m, d = offsets.size - 1, values.shape[1]
    if m == 0:
        return np.empty((m, d)) if out is None else out
    if not values.flags.c_contiguous:
        values = np.ascontiguousarray(values)
    jit = _jit.kernels(corners.size)
    if jit is not None:  # the same sums in the same order, compiled
        if k and k < 8:
            return jit.face_means_uniform(values, corners, k, out)
        if not k:
            sizes = np.diff(offsets)
            if 3 <= int(sizes.min()) and int(sizes.max()) <= 129:
                return jit.face_means_mixed(values, corners, offsets, out)
    if out is None:
        out = np.empty((m, d))
    if k and k < 8:
        block = BLOCK
        corner_rows = corners.reshape(m, k)
        for a in range(0, m, block):
            rows = corner_rows[a : a + block]
            acc = out[a : a + block]
            np.take(values, rows[:, 0], axis=0, out=acc)
            for j in range(1, k):
                acc += values.take(rows[:, j], axis=0)
        out /= k
        return out
    if k:  # k >= 8: numpy's pairwise sums, one coordinate at a time
        block = max(1, (BLOCK * 4) // k)
        for i in range(d):
            col = np.ascontiguousarray(values[:, i])
            for a in range(0, m, block):
                g = col.take(corners[a * k : (a + block) * k])
                out[a : a + block, i] = g.reshape(-1, k).sum(axis=1)
                del g
            del col
        out /= k
        return out
    # mixed sizes: np.add.reduceat adds a face's corners as a0 + (a1 + a2 + ...),
    # the sum in brackets from left to right while it has fewer than 8 terms
    # (pairwise beyond); the same order here, slot by slot over blocks of faces
    sizes = np.diff(offsets)
    a = 0
    while a < m:
        # blocks of at most BLOCK faces and about 4 * BLOCK corners
        b = int(np.searchsorted(offsets, offsets[a] + 4 * BLOCK, side="right")) - 1
        b = min(max(b, a + 1), a + BLOCK, m)
        size, start, acc = sizes[a:b], offsets[a:b], out[a:b]
        a = b
        np.take(values, corners[start + 1], axis=0, out=acc)
        top = int(size.max())
        for j in range(2, min(top, 8)):
            longer = size > j
            count = int(np.count_nonzero(longer))
            if count == size.size:
                acc += values.take(corners[start + j], axis=0)
            elif 2 * count >= size.size:
                # most faces have a slot j (a few short faces on an open
                # mesh's boundary): every face's place j is read (a short
                # face's is its successor's corner, or clipped at the end)
                # and added where the face has it, the others left as they are
                got = values.take(corners.take(start + j, mode="clip"), axis=0)
                np.add(acc, got, out=acc, where=longer[:, None])
            else:
                at = np.flatnonzero(longer)
                acc[at] += values.take(corners[start[at] + j], axis=0)
        acc += values.take(corners[start], axis=0)
        long = np.flatnonzero(size > 8)  # 8 or more terms in the brackets: numpy's own sums
        if long.size:
            o = np.stack([start[long], start[long] + size[long]], axis=1).reshape(-1)
            h = np.repeat(o[0::2] - np.cumsum(np.r_[0, size[long][:-1]]), size[long])
            h += np.arange(h.size, dtype=h.dtype)
            g = values.take(corners[h], axis=0)
            acc[long] = np.add.reduceat(g, np.cumsum(np.r_[0, size[long][:-1]]), axis=0)
            del g, h, o
    out /= sizes[:, None]
    return out


def scaled_newell(
    vertices: np.ndarray, corners: np.ndarray, offsets: np.ndarray, faces: np.ndarray
) -> FloatArray:
    """(len(faces), 3) Newell normals of some faces, safe from overflow and underflow.

    Each face's corners are scaled by a power of two to at most 1, taken
    relative to its first corner, and scaled again so that the largest of
    those differences is about 1: the cross products then neither
    overflow nor underflow, and the direction is the face's.
    """
    start, stop = offsets[faces].astype(np.int64), offsets[faces + 1].astype(np.int64)
    sizes = stop - start
    local = np.repeat(np.arange(faces.size), sizes)
    first = np.repeat(start, sizes)
    h = first + np.arange(local.size) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    p = vertices[corners[h]]

    def exponent(a: np.ndarray) -> np.ndarray:
        top = np.maximum.reduceat(np.abs(a).max(axis=1), np.cumsum(sizes) - sizes)
        return np.frexp(top)[1]

    p = np.ldexp(p, -exponent(p)[local][:, None])
    p -= p[np.cumsum(sizes) - sizes][local]
    p = np.ldexp(p, -exponent(p)[local][:, None])
    nxt = np.arange(local.size) + 1
    last = np.cumsum(sizes) - 1
    nxt[last] = last - sizes + 1
    return np.add.reduceat(np.cross(p, p[nxt]), np.cumsum(sizes) - sizes, axis=0)
