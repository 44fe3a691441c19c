"""Half-edges derived from CSR faces with whole-array numpy passes.

A *half-edge* is a corner: half-edge ``h`` runs from ``corners[h]`` to the
next corner of its face.  ``next``, ``prev``, ``head``, the rotation round a
vertex, the vertex rings and the twins are derived here from ``corners`` and
``offsets`` (the optional compiled kernels of :mod:`pentanb._jit` take over
some passes on large meshes, with the same results bit for bit).  Twins are
paired by one function per path: :func:`pair_twins` (numpy: one sort of
packed keys, which :func:`pair_sorted` reads on when some half-edges have
no twin; compiled: a counting sort on the tails).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .. import _jit
from .coerce import IntArray, MeshError, readonly

__all__ = [
    "BLOCK",
    "uniform_size",
    "halfedge_face",
    "shifted",
    "head_of",
    "rotation_of",
    "RotateUniform",
    "next_of",
    "prev_of",
    "pair_twins",
    "vertex_rings",
    "open_extension",
    "open_vertex_rings",
    "hole_rotation",
    "heads_at",
    "walk_rings",
    "multi_fan_vertex",
    "fan_triangle_corners",
]

#: Elements per block of the block-wise passes: the temporaries of a pass
#: stay a few hundred kilobytes (in cache, and out of the peak memory).
BLOCK = 1 << 13

#: Keys per block where :func:`_pair_rest` pairs the sorted keys of a mesh
#: with boundary (at least 2): its blocks make a dozen passes each, so they
#: are larger than :data:`BLOCK` (under a megabyte of temporaries).
PAIR_BLOCK = 1 << 16


def uniform_size(offsets: np.ndarray, n_corners: int) -> int:
    """k when the faces of these offsets all have k corners, else 0."""
    m = offsets.size - 1
    if m < 1:
        return 0
    k = int(offsets[1] - offsets[0])
    if k < 1 or k * m != n_corners or np.any(np.diff(offsets) != k):
        return 0
    return k


def halfedge_face(offsets: np.ndarray, n_corners: int, k: int) -> IntArray:
    jit = _jit.kernels(n_corners)
    if jit is not None:  # the same array, each face's run written in one loop
        return jit.halfedge_face(offsets, n_corners)
    faces = np.arange(offsets.size - 1, dtype=offsets.dtype)
    return np.repeat(faces, k if k else np.diff(offsets))


def shifted(a: np.ndarray, k: int, step: int) -> np.ndarray:
    """``a`` (one value per corner of k-gons) moved ``step`` places round every face.

    ``out[h] = a[next[h]]`` for ``step = 1``, ``a[prev[h]]`` for ``step = -1``:
    the whole array copied one place along (one contiguous copy), then the
    faces' last (or first) places written from their first (or last) ones,
    without gathering (2-5 times faster than copying the k - 1 columns).
    """
    out = np.empty_like(a)
    if step == 1:
        out[:-1] = a[1:]
        out[k - 1 :: k] = a[0::k]
    else:
        out[1:] = a[:-1]
        out[0::k] = a[k - 1 :: k]
    return out


def head_of(corners: np.ndarray, offsets: np.ndarray, k: int) -> IntArray:
    """(H,) the vertex every half-edge reaches, for faces that are all k-gons."""
    return shifted(corners, k, 1)


def rotation_of(twin: np.ndarray, offsets: np.ndarray, k: int, mesh: Any = None) -> IntArray:
    """(H,) ``twin[prev]``: the next outgoing half-edge counter-clockwise round its tail."""
    if k:
        return shifted(twin, k, -1)
    prv = mesh.prev if mesh is not None else prev_of(offsets, twin.size, twin.dtype)
    return twin[prv]


class RotateUniform:
    """``rotation[h]`` of a mesh of k-gons from its twins, without a rotation array.

    ``rotate[cur]`` is ``twin[prev[cur]]``, ``prev[h]`` being ``h - 1``, or
    ``h + k - 1`` at the first corner of a face.
    """

    def __init__(self, twin: np.ndarray, k: int) -> None:
        self.twin, self.k = twin, k

    def __getitem__(self, cur: np.ndarray) -> np.ndarray:
        # the first corners: cur // k * k == cur (numpy divides by a constant
        # with a multiplication, 4x faster here than its remainder)
        first = cur // self.k
        first *= self.k
        first = first == cur
        prv = cur - 1
        prv[first] += self.k
        return self.twin[prv]


def next_of(offsets: np.ndarray, n_corners: int, dtype: Any) -> IntArray:
    """(H,) the next half-edge round each face, from the offsets alone."""
    nxt = np.arange(1, n_corners + 1, dtype=dtype)
    nxt[offsets[1:] - 1] = offsets[:-1]
    return nxt


def prev_of(offsets: np.ndarray, n_corners: int, dtype: Any) -> IntArray:
    """(H,) the previous half-edge round each face, from the offsets alone."""
    prv = np.arange(-1, n_corners - 1, dtype=dtype)
    prv[offsets[:-1]] = offsets[1:] - 1
    return prv


def pair_twins(tail: np.ndarray, head: np.ndarray | None, n: int, k: int = 0) -> IntArray | None:
    """The twin of every half-edge of a closed oriented manifold, or None.

    Every half-edge ``h = (u, w)`` gets the key ``(min, max, u > w)`` of its
    undirected edge and direction, packed with ``h`` itself into one 64-bit
    integer: one sort of plain integers (numpy's vectorized sort, several
    times faster than an argsort) then puts the two halves of every edge
    side by side, the forward one first.  None when that pattern breaks (a
    directed edge used twice, a boundary edge): the caller then looks for
    the culprit (:func:`pentanb.mesh.validate.validate`).  Beyond the twins, only the packed
    keys (8 bytes a half-edge) are allocated: keys are built, checked and
    unpacked in blocks.  ``head`` may be None when every face is a k-gon:
    it is then read block by block from ``tail``.

    When key and index need more than 63 bits (meshes of millions of
    vertices), the half-edges are first split by the high bits of their
    smaller vertex (a radix pass; both halves of an edge fall in the same
    part) and each part is sorted on its own.
    """
    H = tail.size
    if H % 2:
        return None
    jit = _jit.kernels(H)
    if jit is not None and n > 0:  # each half-edge's partner among its head's (compiled)
        got, _, alone = jit.pair_twins(tail, tail[:0] if head is None else head, max(k, 1), n)
        return got if alone == 0 else None
    paired = pair_sorted(tail, head, n, k)
    return None if paired is None else paired[0]


def pair_sorted(
    tail: np.ndarray, head: np.ndarray | None, n: int, k: int = 0, boundary: bool = False
) -> tuple[IntArray, np.ndarray] | None:
    """The twins by sorting packed keys (the numpy path of :func:`pair_twins`), with
    boundary half-edges when ``boundary`` is True.

    The keys of :func:`pair_twins`, sorted once.  When they do not fall
    into pairs and ``boundary`` is True, the same sorted keys are read
    again from where the pattern broke (:func:`_pair_rest`): a key alone on
    its edge is a boundary half-edge, every other edge must have two
    half-edges running oppositely.

    Parameters
    ----------
    tail : (H,) int
        The half-edges' tails, vertices in ``[0, n)``.
    head : (H,) int or None
        Their heads; None when every face has ``k`` corners (read from ``tail``).
    n : int
        Number of vertices.
    k : int
        The size of every face, or 0.
    boundary : bool
        False: None unless every half-edge has a twin.

    Returns
    -------
    twin : (H,) int
        ``twin[h]``, the half-edge ``head[h] -> tail[h]``, or -1 where there
        is none (a boundary half-edge).
    alone : (B,) int64
        The half-edges without a twin, in increasing order.

    None when an edge has more than two half-edges or two running the same
    way (and, ``boundary`` False, when some half-edge has no twin).  A
    half-edge from a vertex to itself is left without a twin.
    """
    H = tail.size
    twin = np.empty(H, dtype=tail.dtype)
    # (the boundary half-edges of every part, None: there must be none)
    alone: list[np.ndarray] | None = [] if boundary else None
    index_bits, vertex_bits, low_bits = key_bits(H, n)
    if low_bits >= vertex_bits:
        ok = _pair_part(tail, head, n, index_bits, None, None, twin, k, alone)
    else:
        if head is None:
            head = head_of(tail, np.empty(0), k)
        parts = vertex_bits - max(low_bits, 0)
        if low_bits < 1 or parts > 16:  # pragma: no cover - beyond 2**40 half-edges
            raise MeshError(f"{H:,} half-edges are more than twins can be paired for")
        ok = in_parts(
            tail,
            head,
            low_bits,
            parts,
            lambda t, h, ids, mask: _pair_part(t, h, n, index_bits, ids, mask, twin, 0, alone),
            tail.dtype,
        )
    if not ok:
        return None
    if not alone:
        return twin, np.zeros(0, dtype=np.int64)
    lone = np.sort(np.concatenate(alone))
    twin[lone] = -1
    return twin, lone


def key_bits(H: int, n: int) -> tuple[int, int, int]:
    """The bits of the packed keys that pair H half-edges on n vertices.

    Returns ``(index_bits, vertex_bits, low_bits)``: a key ``((lo * n + hi)
    * 2 + flip) << index_bits | h`` stays below ``2**63`` while ``lo <
    2**low_bits``; when ``low_bits < vertex_bits`` the half-edges are paired
    part by part (:func:`in_parts`).
    """
    index_bits = max(int(H - 1).bit_length(), 1)
    vertex_bits = max(int(n - 1).bit_length(), 1)
    return index_bits, vertex_bits, 62 - index_bits - int(n).bit_length()


def in_parts(tail, head, low_bits: int, parts: int, pair, dtype=None) -> bool:
    """Pair half-edges part by part: those whose smaller vertex has the same high bits.

    A radix split (``O(H)``) of the half-edges by ``min(tail, head) >>
    low_bits`` into ``2**parts`` parts, each handed to ``pair(tail, head,
    ids, mask)`` (``ids`` its half-edges, ``mask`` the low bits' mask);
    False as soon as one part does not pair.  Twins keyed by the smaller
    vertex meet in one part.
    """
    part = (np.minimum(tail, head) >> low_bits).astype(np.uint16)
    order = np.argsort(part, kind="stable")  # radix sort: O(H)
    if dtype is not None:
        order = order.astype(dtype)
    bounds = np.concatenate([[0], np.cumsum(np.bincount(part, minlength=1 << parts))])
    del part
    mask = (1 << low_bits) - 1
    for a, b in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
        if a == b:
            continue
        ids = order[a:b]
        if not pair(tail[ids], head[ids], ids, mask):
            return False
    return True


def _pair_part(tail, head, n, index_bits, ids, mask, twin, k=0, alone=None) -> bool:
    """Pair the half-edges of one part (see :func:`pair_sorted`); False if they do not pair.

    ``ids`` maps the part's half-edges to the mesh's (None: the whole mesh);
    ``mask`` keeps the low bits of the smaller vertex (None: all of it);
    ``head`` None: faces of ``k`` corners, heads read from ``tail``;
    ``alone`` None: every half-edge must have a twin, else a list that the
    half-edges without one are added to (by :func:`_pair_rest`).
    """
    size = tail.size
    if size % 2 and alone is None:
        return False
    key = np.empty(size, dtype=np.int64)
    step = BLOCK - BLOCK % k if head is None else BLOCK
    for a in range(0, size, step):
        t = tail[a : a + step]
        h = head_of(t, np.empty(0), k) if head is None else head[a : a + step]
        at = np.arange(a, a + t.size, dtype=np.int64)
        _pack(t, h, n, mask, index_bits, at, key[a : a + step])
        del t, h, at
    key.sort()
    # the two halves of every edge must sit side by side: keys 2K and 2K + 1,
    # which differ in their lowest bit only; then the low bits say which
    # half-edges they are
    a = 0
    if size % 2 == 0:
        while a < size and _pair_block(key[a : a + BLOCK], index_bits, ids, twin):
            a += BLOCK
    if a >= size:
        return True
    if alone is None:
        return False
    if a:  # the last key paired (unpacked in place) packed again: its edge ends the pairs
        h = key[a - 1 : a].copy()
        _pack(tail[h], heads_at(tail, h, k, head), n, mask, index_bits, h, key[a - 1 : a])
    return _pair_rest(key, a, index_bits, ids, twin, alone)


def _pack(tail, head, n, mask, index_bits, at, out) -> None:
    """Write the keys of :func:`pair_twins` of the half-edges ``tail -> head``
    numbered ``at`` into ``out`` (``mask`` None: all bits of the smaller vertex)."""
    lo = np.minimum(tail, head)
    np.multiply(lo & mask if mask is not None else lo, np.int64(n), out=out)
    out += np.maximum(tail, head)
    out <<= 1
    out |= tail > head
    out <<= index_bits
    out |= at


def _pair_block(key: np.ndarray, index_bits: int, ids, twin: np.ndarray) -> bool:
    """Pair sorted keys two by two (see :func:`_pair_part`); False, writing nothing,
    unless every two are the two half-edges of one edge.  The keys paired are
    unpacked in place (left holding their half-edges)."""
    pair = np.bitwise_xor(key[0::2], key[1::2])
    pair >>= index_bits
    if not (pair == 1).all():
        return False
    key &= np.int64((1 << index_bits) - 1)
    first, second = key[0::2], key[1::2]
    if ids is not None:
        first, second = ids[first], ids[second]
    twin[first] = second
    twin[second] = first
    return True


def _pair_rest(key, a, index_bits, ids, twin, alone) -> bool:
    """Pair the sorted keys ``key[a:]`` of a mesh that may have boundary half-edges.

    Block by block, every block ending between two edges: the keys alone
    on their edge (the boundary half-edges) are added to ``alone``, and the
    others must fall into pairs (:func:`_pair_block`).  False when an edge
    has more than two half-edges or two running the same way.  ``key[:a]``
    are paired already (``a`` falls between pairs).
    """
    size = key.size
    shift = index_bits + 1  # key >> shift: the undirected edge

    def one_edge(i: int) -> bool:  # keys i - 1 and i on one edge
        return bool(key[i - 1] >> shift == key[i] >> shift)

    if a and one_edge(a):  # a third half-edge on the edge of the last pair
        return False
    low = np.int64((1 << index_bits) - 1)
    while a < size:
        b = min(a + PAIR_BLOCK, size)
        if b < size and one_edge(b):
            b -= 1
            if one_edge(b):  # three half-edges on one edge
                return False
        part = key[a:b]
        edge = part >> shift
        # a key whose edge differs from both neighbours' (the block's ends
        # fall between edges) is alone on its edge
        apart = np.ones(part.size + 1, dtype=bool)
        np.not_equal(edge[1:], edge[:-1], out=apart[1:-1])
        single = apart[1:]
        single &= apart[:-1]
        if single.any():
            lone = part[single] & low
            alone.append(lone if ids is None else ids[lone].astype(np.int64))
            part = part[~single]
        if part.size % 2 or not _pair_block(part, index_bits, ids, twin):
            return False
        a = b
    return True


def vertex_rings(rotation, tail, valences, start=None):
    """Outgoing half-edges of every vertex in rotation order, as CSR.

    One vectorized step per position around the vertex (a loop over the
    largest valence, not over vertices).  On a non-manifold vertex the orbit
    closes early; the ring then repeats half-edges, which ``_validate``
    detects.  ``start`` (n,), when given, is every vertex's first
    half-edge (then ``rotation`` may number more half-edges than ``tail``:
    the ring holds ``valences.sum()`` of them, of ``start``'s dtype); by
    default its last (largest) outgoing half-edge.
    """
    n = valences.size
    dtype = tail.dtype if start is None else start.dtype
    ring_off = np.zeros(n + 1, dtype=dtype)
    np.cumsum(valences, out=ring_off[1:])
    if start is None:
        start = np.empty(n, dtype=dtype)
        # any outgoing half-edge per vertex: the last one written wins (in blocks:
        # numpy widens a scatter's index array, the whole of it at once otherwise)
        for a in range(0, tail.size, BLOCK):
            start[tail[a : a + BLOCK]] = np.arange(a, min(a + BLOCK, tail.size), dtype=dtype)
    size = int(ring_off[-1])
    if n == 0:
        return np.empty(size, dtype=dtype), ring_off
    low, top = int(valences.min()), int(valences.max())
    # the first steps run over all vertices in index order (writes in
    # increasing order of address): `low` of them, or, when all but a few
    # vertices (an eighth) have more edges, as many as those have; the few
    # (none unused: every vertex has a start) write their extra steps to a
    # spare slot past the end
    full = low
    if 0 < low < top:
        ended = np.cumsum(np.bincount(valences))  # the vertices of at most k edges
        while full < top and ended[full] <= n // 8:
            full += 1
    ring = np.empty(size + (full > low), dtype=dtype)
    shorter = np.flatnonzero(valences < full) if full > low else None
    base = ring_off[:-1]
    cur = start
    for k in range(full):
        if k:
            cur = rotation[cur]
        at = base + k
        if shorter is not None and k >= low:
            at[shorter[valences[shorter] <= k]] = size
        ring[at] = cur
    if shorter is not None:
        ring = ring[:size]
    if top == full:
        return ring, ring_off
    # the rest, for the vertices of more edges, by valence (a radix sort on
    # small ints): at step k the vertices still walking are a suffix
    more = np.flatnonzero(valences > full).astype(dtype)
    small = valences[more].astype(np.uint16 if top < 65536 else np.int64)
    order = np.argsort(small, kind="stable").astype(dtype)
    more = more[order]
    first = np.searchsorted(small[order], np.arange(top), side="right")
    cur = cur[more]
    base = base[more]
    for k in range(full, top):
        lo = int(first[k])
        c = rotation[cur[lo:]] if k else cur[lo:]
        cur[lo:] = c
        ring[base[lo:] + k] = c
    return ring, ring_off


def hole_rotation(bh: np.ndarray, loop_offsets: np.ndarray) -> np.ndarray:
    """(B,) int: the rotation of the hole half-edges, ``rotation[H + j]``.

    The next outgoing half-edge counter-clockwise round the tail of the hole
    half-edge ``H + j`` is the boundary half-edge after ``bh[j]`` in its loop
    (the loop's first after its last).

    Parameters
    ----------
    bh : (B,) int
        The boundary half-edges, loop after loop.
    loop_offsets : (L + 1,) int

    Returns
    -------
    (B,) int
    """
    B = bh.size
    j = np.arange(B, dtype=np.int64)
    loop_of = np.repeat(np.arange(loop_offsets.size - 1), np.diff(loop_offsets))
    after = j + 1
    last = after == loop_offsets[1:][loop_of]
    after[last] = loop_offsets[:-1][loop_of[last]]
    return bh[after]


def heads_at(
    tail: np.ndarray, hs: np.ndarray, k: int, head: np.ndarray | None = None
) -> np.ndarray:
    """The heads of the half-edges ``hs``: ``head[hs]``, or read from ``tail`` when
    ``head`` is None (faces of ``k`` corners: the next corner of ``h`` is ``h + 1``,
    or ``h + 1 - k`` at a face's last)."""
    if head is not None:
        return head[hs]
    nxt = hs + 1
    nxt[nxt % k == 0] -= k
    return tail[nxt]


def ring_dtype(dtype: Any, size: int) -> Any:
    """The dtype of the vertex rings of an open mesh of ``size`` half-edges
    (hole half-edges included) whose twins have ``dtype``."""
    return np.result_type(dtype, np.int32 if size < 2**31 else np.int64)


def open_extension(rotation, tail, head, bh, loop_offsets, hole_tail=None):
    """The rotation and tails of all half-edges of an open mesh, hole half-edges included.

    Parameters
    ----------
    rotation : (H,) int
        ``twin[prev[h]]`` of the face half-edges (hole half-edges ``>= H``).
    tail, head : (H,) int
        (``head`` may be None when ``hole_tail`` is given.)
    bh : (B,) int
        The boundary half-edges, loop after loop.
    loop_offsets : (L + 1,) int
    hole_tail : (B,) int, optional
        ``head[bh]``, when the caller has it.

    Returns
    -------
    rotation_all : (H + B,) int
        The hole half-edge ``H + j`` runs from ``head[bh[j]]`` to
        ``tail[bh[j]]``; the next outgoing half-edge counter-clockwise round
        its tail is the boundary half-edge after ``bh[j]`` in its loop.
    tail_all : (H + B,) int
    """
    dtype = ring_dtype(rotation.dtype, tail.size + bh.size)
    rotation_all = np.concatenate([rotation, hole_rotation(bh, loop_offsets)])
    rotation_all = rotation_all.astype(dtype, copy=False)
    hole_tail = head[bh] if hole_tail is None else hole_tail
    tail_all = np.concatenate([tail, hole_tail]).astype(dtype, copy=False)
    return rotation_all, tail_all


def open_vertex_rings(rotation, tail, head, bh, loop_offsets, valences, hole_tail=None):
    """The vertex rings of an open mesh (:attr:`pentanb.Mesh.vertex_ring`).

    Every vertex's outgoing half-edges, hole half-edges included, in
    rotation order; a boundary vertex's ring starts at its hole half-edge
    (its largest), an interior vertex's at its largest half-edge, as on a
    closed mesh.  Arguments as for :func:`open_extension`.

    Returns
    -------
    ring : (H + B,) int
    ring_offsets : (n + 1,) int
    """
    H, B = tail.size, bh.size
    dtype = ring_dtype(rotation.dtype, H + B)
    rotation_all = np.empty(H + B, dtype=dtype)
    rotation_all[:H] = rotation
    rotation_all[H:] = hole_rotation(bh, loop_offsets)
    start = np.empty(valences.size, dtype=dtype)
    for a in range(0, H, BLOCK):
        start[tail[a : a + BLOCK]] = np.arange(a, min(a + BLOCK, H), dtype=dtype)
    start[head[bh] if hole_tail is None else hole_tail] = np.arange(H, H + B, dtype=dtype)
    return vertex_rings(rotation_all, tail, valences, start)


def walk_rings(
    twin: np.ndarray,
    tail: np.ndarray,
    k: int,
    prv: np.ndarray | None,
    valences: np.ndarray,
    boundary: tuple[np.ndarray, np.ndarray] | None = None,
    hole_tail: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, bool] | None:
    """The vertex rings by the compiled kernel, or None without it (small meshes, no numba).

    The arrays of :func:`vertex_rings` (closed) or :func:`open_vertex_rings`
    (``boundary`` given), bit for bit, without a rotation array: one walk
    round every vertex from its largest half-edge.

    Parameters
    ----------
    twin : (H,) int
        The twins, ``H + j`` for ``boundary[0][j]``.
    tail : (H,) int
    k : int
        The size of every face, or 0 (faces of several sizes: ``prv`` given).
    prv : (H,) int or None
        The previous half-edge round every face, when ``k`` is 0.
    valences : (n,) int
    boundary : ((B,) int, (L + 1,) int), optional
        The boundary half-edges loop after loop and the loops' offsets.
    hole_tail : (B,) int, optional
        The tail of every hole half-edge: ``head[boundary[0]]``.

    Returns
    -------
    ring : (H + B,) int
    ring_offsets : (n + 1,) int
    ok : bool
        Whether the rings hold every half-edge once (else some vertex's
        faces form more than one fan).
    """
    H = tail.size
    jit = _jit.kernels(H)
    if jit is None:
        return None
    if boundary is None or not boundary[0].size:
        dtype, after, hole_tail = tail.dtype, np.zeros(0, np.int64), tail[:0]
    else:
        bh, loop_offsets = boundary
        dtype = ring_dtype(twin.dtype, H + bh.size)
        after = hole_rotation(bh, loop_offsets).astype(np.int64, copy=False)
        assert hole_tail is not None and hole_tail.size == bh.size
    ring_off = np.zeros(valences.size + 1, dtype=dtype)
    np.cumsum(valences, out=ring_off[1:])
    ring = np.empty(H + after.size, dtype=dtype)
    prv = tail[:0] if prv is None or k else prv
    ok = jit.open_rings(twin, tail, k, prv, after, hole_tail, ring, ring_off)
    return ring, ring_off, bool(ok)


def multi_fan_vertex(rotation, tail, valences) -> int:
    """The first vertex whose rotation orbit is shorter than its valence."""
    n = valences.size
    start = np.empty(n, dtype=np.int64)
    start[tail] = np.arange(tail.size, dtype=np.int64)
    cur = start.copy()
    closed_at = np.zeros(n, dtype=np.int64)
    for k in range(1, int(valences.max(initial=0)) + 1):
        cur = rotation[cur]
        newly = (cur == start) & (closed_at == 0)
        closed_at[newly] = k
    bad = np.flatnonzero((closed_at < valences) & (valences > 0))
    return int(bad[0]) if bad.size else -1


def fan_triangle_corners(offsets: ArrayLike) -> tuple[IntArray, IntArray]:
    """Fan triangulation of CSR polygons, as corner indices (for drawing).

    Parameters
    ----------
    offsets : (m + 1,) int
        Polygon ``f`` has corners ``offsets[f]`` to ``offsets[f + 1] - 1``.

    Returns
    -------
    triangles : (T, 3) int
        Triangle ``k`` of polygon ``f`` is corners ``(o, o + k + 1, o + k + 2)``
        with ``o = offsets[f]``, counter-clockwise like the polygon;
        ``T = offsets[-1] - 2m``.
    triangle_face : (T,) int
        The polygon each triangle comes from.

    See Also
    --------
    Mesh.fan_triangles : the same triangles as vertex indices.
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    sizes = np.diff(offsets)
    k = int(sizes[0]) if sizes.size else 0
    if k >= 3 and int(sizes.min()) == k == int(sizes.max()):
        # one size: every face's triangles are one pattern shifted by its offset
        pattern = np.stack([np.zeros(k - 2, np.int64), np.arange(1, k - 1), np.arange(2, k)], 1)
        tris = (offsets[:-1, None, None] + pattern).reshape(-1, 3)
        tri_face = np.repeat(np.arange(sizes.size, dtype=np.int64), k - 2)
        return readonly(tris), readonly(tri_face)
    per = np.maximum(sizes - 2, 0)
    tri_face = np.repeat(np.arange(per.size, dtype=np.int64), per)
    start = offsets[:-1][tri_face]
    k = np.arange(tri_face.size, dtype=np.int64) - (np.cumsum(per) - per)[tri_face]
    tris = np.stack([start, start + k + 1, start + k + 2], axis=1)
    return readonly(tris), readonly(tri_face)
