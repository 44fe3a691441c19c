"""The boundary of an open mesh: its loops, found once, and the words for messages.

A :class:`~pentanb.Mesh` may have a boundary: edges with a face on one side
only.  Every such edge is traversed by one face half-edge (its *boundary
half-edge*, face on the left); following them head to tail gives the
*boundary loops*, one closed chain round every hole or open rim.

The representation (see :attr:`pentanb.Mesh.twin`) follows geometry-central:
every boundary loop is an implicit *hole face*, and the boundary half-edge
``boundary_halfedges[j]`` has as its twin the hole half-edge ``H + j``
(``H`` the number of face half-edges), running the other way.  Every
half-edge then has a twin; a closed mesh is the case of no loops, and all
its arrays are what they were before open meshes existed.

:func:`pair_halfedges` pairs the half-edges of an oriented manifold with
or without boundary (on the numpy path, one sort of packed keys read on
past where they stop falling into pairs; :func:`pair_open` gives the same
twins on their own); :func:`loop_order` chains the boundary half-edges
into loops.
:func:`boundary_loops` and :func:`describe_boundary` count loops for
messages, from plain ``tail`` and ``head`` arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .. import _jit
from .halfedge import heads_at, key_bits, pair_sorted

__all__ = [
    "boundary_edges",
    "boundary_loops",
    "describe_boundary",
    "pair_open",
    "pair_halfedges",
    "loop_order",
    "orientation_classes",
    "open_twins",
    "canonical_loops",
    "hole_twins",
    "CLOSED",
]


def _closed_boundary() -> tuple[np.ndarray, np.ndarray]:
    empty, one = np.zeros(0, dtype=np.int64), np.zeros(1, dtype=np.int64)
    empty.setflags(write=False)
    one.setflags(write=False)
    return empty, one


#: The boundary record of a closed mesh: no boundary half-edge, no loop
#: (shared, read-only; see :attr:`pentanb.Mesh.boundary_halfedges`).
CLOSED = _closed_boundary()


def boundary_edges(tail: ArrayLike, head: ArrayLike) -> np.ndarray:
    """(b,) int: the half-edges ``tail[h] -> head[h]`` without an opposite ``head -> tail``."""
    tail = np.asarray(tail, dtype=np.int64)
    head = np.asarray(head, dtype=np.int64)
    if tail.size == 0:
        return np.zeros(0, dtype=np.int64)
    n = np.int64(max(int(tail.max()), int(head.max())) + 1)
    key = np.sort(tail * n + head)
    want = head * n + tail
    pos = np.minimum(np.searchsorted(key, want), key.size - 1)
    return np.flatnonzero(key[pos] != want)


def boundary_loops(tail: ArrayLike, head: ArrayLike) -> list[int]:
    """The number of edges of every boundary loop, largest first.

    A loop is a connected chain of boundary edges (see
    :func:`boundary_edges`); on a manifold with boundary each is a cycle
    around a hole or along an open rim.

    Parameters
    ----------
    tail, head : (H,) int
        The half-edges of a mesh (``Mesh.tail``, ``Mesh.head``; or the
        corners and their successors in each face).

    Returns
    -------
    list of int
        Empty for a closed mesh.
    """
    tail = np.asarray(tail, dtype=np.int64)
    head = np.asarray(head, dtype=np.int64)
    b = boundary_edges(tail, head)
    if not b.size:
        return []
    u, w = tail[b], head[b]
    ids, inverse = np.unique(np.concatenate([u, w]), return_inverse=True)
    u, w = inverse[: b.size], inverse[b.size :]
    label = np.arange(ids.size, dtype=np.int64)
    while True:  # hook the larger label onto the smaller, then jump pointers
        lu, lw = label[u], label[w]
        differ = lu != lw
        if not differ.any():
            break
        np.minimum.at(label, np.maximum(lu[differ], lw[differ]), np.minimum(lu[differ], lw[differ]))
        while True:
            jumped = label[label]
            if np.array_equal(jumped, label):
                break
            label = jumped
    sizes = np.bincount(label[u], minlength=ids.size)
    return sorted((int(x) for x in sizes[sizes > 0]), reverse=True)


def describe_boundary(tail: ArrayLike, head: ArrayLike) -> str:
    """``"1 boundary loop (4 edges)"`` or ``"3 boundary loops (12, 4 and 3 edges)"``."""
    loops = boundary_loops(tail, head)
    if not loops:
        return "no boundary"
    if len(loops) == 1:
        return f"1 boundary loop ({loops[0]} edges)"
    shown = [str(x) for x in loops[:5]]
    edges = ", ".join(shown[:-1]) + " and " + shown[-1] if len(loops) <= 5 else ", ".join(shown)
    more = "" if len(loops) <= 5 else f", ... {sum(loops):,} in all"
    return f"{len(loops)} boundary loops ({edges}{more} edges)"


def pair_open(tail: np.ndarray, head: np.ndarray, n: int) -> np.ndarray | None:
    """The opposite of every half-edge of an oriented manifold with boundary.

    The packed keys of :func:`pentanb.mesh.halfedge.pair_twins`: every
    half-edge ``h = (u, w)`` gets the key ``(min, max, u > w)`` of its
    undirected edge and direction, packed with ``h`` into one 64-bit
    integer, and one sort of plain integers (several times faster than an
    argsort and a search) puts the half-edges of every edge side by side
    (:func:`pentanb.mesh.halfedge.pair_sorted`).  An edge met once is a
    boundary edge; twice, in opposite directions, an interior one.  When
    key and index need more than 63 bits, the half-edges are first split by
    the high bits of their smaller vertex (a radix pass) and every part is
    sorted on its own.

    Parameters
    ----------
    tail, head : (H,) int
        The half-edges ``tail[h] -> head[h]``, vertices in ``[0, n)``.
    n : int
        Number of vertices.

    Returns
    -------
    (H,) int or None
        ``twin[h]``, the half-edge ``head[h] -> tail[h]``, or -1 where there
        is none (a boundary half-edge); None when a directed edge is used
        twice (inconsistent orientation or a non-manifold edge) or a
        half-edge starts and ends at one vertex.
    """
    H = tail.size
    if H == 0:
        return np.empty(0, dtype=tail.dtype)
    n = max(int(n), 1)
    _, vertex_bits, low_bits = key_bits(H, n)
    if low_bits < vertex_bits and (low_bits < 1 or vertex_bits - low_bits > 16):
        return _pair_open_search(tail, head, n)  # pragma: no cover - beyond 2**40 half-edges
    got = _pair_sorted_open(tail, head, n, 0)
    return None if got is None else got[0]


def _pair_sorted_open(
    tail: np.ndarray, head: np.ndarray | None, n: int, k: int
) -> tuple[np.ndarray, np.ndarray] | None:
    """:func:`pentanb.mesh.halfedge.pair_sorted` with boundary half-edges, None
    also when one of them starts and ends at one vertex (which has no twin)."""
    got = pair_sorted(tail, head, n, k, boundary=True)
    if got is None:
        return None
    alone = got[1]
    if alone.size and (tail[alone] == heads_at(tail, alone, k, head)).any():
        return None
    return got


def _pair_open_search(tail: np.ndarray, head: np.ndarray, n: int) -> np.ndarray | None:
    """:func:`pair_open` by one argsort of the directed edges and one search for
    every half-edge's opposite (for counts beyond the packed keys)."""
    H = tail.size
    t = tail.astype(np.int64)
    w = head.astype(np.int64)
    key = t * np.int64(n) + w
    order = np.argsort(key, kind="stable")
    skey = key[order]
    if (skey[1:] == skey[:-1]).any():
        return None
    want = w * np.int64(n) + t
    pos = np.minimum(np.searchsorted(skey, want), H - 1)
    twin = np.where(skey[pos] == want, order[pos], -1)
    return twin.astype(tail.dtype)


def loop_order(
    tail: np.ndarray, head: np.ndarray, bh: np.ndarray, n: int
) -> tuple[np.ndarray, np.ndarray, int]:
    """Chain boundary half-edges into loops.

    Parameters
    ----------
    tail, head : (H,) int
        The half-edges of the mesh.
    bh : (B,) int
        Its boundary half-edges (those without an opposite), in increasing order.
    n : int
        Number of vertices.

    Returns
    -------
    loops : (B,) int
        ``bh`` reordered loop after loop; in every loop the head of a
        half-edge is the tail of the next (and the last's head the first's
        tail).  Every loop starts at its smallest half-edge; loops come in
        the order of those.
    offsets : (L + 1,) int
        Loop ``i`` is ``loops[offsets[i]:offsets[i + 1]]``.
    bad : int
        -1; or the first vertex that more than one boundary half-edge
        leaves (two fans of faces meet there: a non-manifold vertex), and
        then ``loops`` and ``offsets`` are empty.

    Notes
    -----
    Whole-array passes: the smallest half-edge of every loop and every
    half-edge's distance from it are found by pointer doubling
    (``O(B log B)``), so one loop of a million edges costs no Python loop
    of a million steps.
    """
    B = bh.size
    empty = np.zeros(0, dtype=np.int64)
    if B == 0:
        return empty, np.zeros(1, dtype=np.int64), -1
    t = tail[bh].astype(np.int64)
    w = head[bh].astype(np.int64)
    leaving = np.bincount(t, minlength=n)
    twice = np.flatnonzero(leaving > 1)
    if twice.size:
        return empty, np.zeros(1, dtype=np.int64), int(twice[0])
    out = np.full(n, -1, dtype=np.int64)
    out[t] = np.arange(B)
    nxt = out[w]
    if (nxt < 0).any():  # pragma: no cover - in and out balance at every vertex
        return empty, np.zeros(1, dtype=np.int64), int(w[np.flatnonzero(nxt < 0)[0]])
    # the smallest position of every loop: after s doublings lab[i] is the
    # least of the 2**s positions from i on
    ids = np.arange(B, dtype=np.int64)
    lab, p = ids.copy(), nxt.copy()
    span = 1
    while span < B:
        np.minimum(lab, lab[p], out=lab)
        p = p[p]
        span *= 2
    # the distance of every position from its loop's first (list ranking)
    leader = lab == ids
    prv = np.empty(B, dtype=np.int64)
    prv[nxt] = ids
    q = np.where(leader, ids, prv)
    d = np.where(leader, 0, 1).astype(np.int64)
    while True:
        qq = q[q]
        if np.array_equal(qq, q):
            break
        d += d[q]
        q = qq
    order = np.lexsort((d, lab))
    offsets = np.append(np.flatnonzero(d[order] == 0), B).astype(np.int64)
    return bh[order].astype(np.int64), offsets, -1


def orientation_classes(
    f1: np.ndarray, f2: np.ndarray, same: np.ndarray, m: int
) -> tuple[np.ndarray, np.ndarray]:
    """Which faces to reverse so that every edge's two faces run along it oppositely.

    Parameters
    ----------
    f1, f2 : (k,) int
        The two faces of every edge with two faces.
    same : (k,) bool
        Whether the two faces run along the edge in the same direction.
    m : int
        Number of faces.

    Returns
    -------
    flip : (m,) int8
        1 for the faces to reverse, 0 for the others: in every connected
        piece, the fewer of the two classes of faces that agree with each
        other (the class without the piece's smallest face when tied).
    conflicts : (c,) int
        The edges (indices into ``f1``) that no choice of ``flip`` mends:
        empty exactly when every piece is orientable.  A piece with such
        an edge is non-orientable (a Moebius band, say).

    Notes
    -----
    Breadth first from every piece's smallest face at once, one level at
    a time, with whole-array steps.
    """
    f1 = np.asarray(f1, dtype=np.int64)
    f2 = np.asarray(f2, dtype=np.int64)
    same = np.asarray(same, dtype=np.int8)
    src = np.concatenate([f1, f2])
    dst = np.concatenate([f2, f1])
    par = np.concatenate([same, same])
    order = np.argsort(src, kind="stable")
    src, dst, par = src[order], dst[order], par[order]
    start = np.searchsorted(src, np.arange(m + 1))
    # the pieces: the smallest face of every piece (hook and jump)
    lab = np.arange(m, dtype=np.int64)
    while True:
        lu, lw = lab[f1], lab[f2]
        differ = lu != lw
        if not differ.any():
            break
        np.minimum.at(lab, np.maximum(lu[differ], lw[differ]), np.minimum(lu[differ], lw[differ]))
        while True:
            jumped = lab[lab]
            if np.array_equal(jumped, lab):
                break
            lab = jumped
    flip = np.full(m, -1, dtype=np.int8)
    frontier = np.flatnonzero(lab == np.arange(m))
    flip[frontier] = 0
    while frontier.size:
        a, b = start[frontier], start[frontier + 1]
        sizes = b - a
        idx = np.repeat(a - np.cumsum(sizes) + sizes, sizes) + np.arange(int(sizes.sum()))
        nb = dst[idx]
        val = flip[src[idx]] ^ par[idx]
        new = flip[nb] < 0
        flip[nb[new]] = val[new]
        frontier = np.unique(nb[new])
    conflicts = np.flatnonzero((flip[f1] ^ flip[f2]) != same)
    # in every piece, reverse the fewer faces (the smallest face's side when tied)
    size = np.bincount(lab, minlength=m)
    flipped = np.bincount(lab, weights=flip, minlength=m)
    flip ^= (2 * flipped > size)[lab].astype(np.int8)
    return flip, conflicts


def pair_halfedges(
    tail: np.ndarray, head: np.ndarray | None, n: int, k: int = 0
) -> tuple[np.ndarray, np.ndarray] | None:
    """The opposite of every half-edge, closed mesh or not, and the half-edges without one.

    One call of the compiled pairing (:mod:`pentanb._jit`) on large meshes,
    which serves closed and open meshes alike; else the numpy path, one
    sort of packed keys (:func:`pentanb.mesh.halfedge.pair_sorted`) that
    serves them alike too: the keys of a closed mesh fall into pairs, and
    where they stop doing so the same sorted keys are read on for the
    boundary half-edges.

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

    Returns
    -------
    twin : (H,) int
        ``twin[h]``, the half-edge ``head[h] -> tail[h]``, or -1 where there
        is none (a boundary half-edge).
    alone : (B,) int64
        The half-edges without an opposite, in increasing order (empty: a
        closed mesh).

    None when a half-edge has two opposites or is a loop (the numpy path:
    also when a directed edge is used twice; the compiled one leaves that to
    :func:`loop_order`, which refuses the vertex two boundary half-edges
    leave: :func:`open_twins` fails on the same meshes either way).
    """
    jit = _jit.kernels(tail.size)
    if jit is not None and n > 0:  # (compiled: closed or not, one counting sort)
        twin, alone, b = jit.pair_twins(tail, tail[:0] if head is None else head, max(k, 1), n)
        return None if b < 0 else (twin, alone)
    return _pair_sorted_open(tail, head, n, k)


def open_twins(
    tail: np.ndarray, head: np.ndarray | None, n: int, k: int = 0
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]] | None:
    """The twins and boundary loops of an oriented manifold, with boundary or not, or None.

    Parameters
    ----------
    tail : (H,) int
    head : (H,) int or None
        None when every face has ``k`` corners (read from ``tail``).
    n : int
    k : int
        The size of every face, or 0.

    Returns
    -------
    twin : (H,) int
        The opposite half-edge; ``H + j`` for the j-th boundary half-edge
        (its hole half-edge, see :attr:`pentanb.Mesh.twin`).
    boundary : ((B,) int, (L + 1,) int)
        The boundary half-edges loop after loop (read-only) and the loops'
        offsets (see :func:`loop_order`); :data:`CLOSED` when there are none.

    None when a directed edge is used twice, a half-edge is a loop, or a
    vertex has more than one boundary fan.
    """
    got = pair_halfedges(tail, head, n, k)
    if got is None:
        return None
    twin, bh = got
    if not bh.size:
        return twin, CLOSED
    # the loops of the few boundary half-edges (positions into bh)
    t, w = tail[bh], heads_at(tail, bh, k, head)
    jit = _jit.kernels(tail.size)
    if jit is not None:  # (the same loops, by one walk)
        at, off, bad = jit.loop_order(t, w, n)
    else:
        at, off, bad = loop_order(t, w, np.arange(bh.size), n)
    if bad >= 0:
        return None
    bh = bh[at]
    twin = hole_twins(twin, bh)
    bh.setflags(write=False)
    off.setflags(write=False)
    return twin, (bh, off)


def canonical_loops(chain: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Boundary half-edges chained into loops, in the order :func:`loop_order` gives.

    For operators that know their output's boundary loops (each the
    input's, refined): the loops are turned to start at their smallest
    half-edge and sorted by it, so that the result is what pairing the
    output's half-edges would record (:attr:`pentanb.Mesh.boundary_halfedges`).

    Parameters
    ----------
    chain : (B,) int
        Boundary half-edges, loop after loop; in every loop the head of a
        half-edge is the tail of the next (and the last's head the first's
        tail), starting anywhere.
    offsets : (L + 1,) int
        Loop ``i`` is ``chain[offsets[i]:offsets[i + 1]]``; no loop is empty.

    Returns
    -------
    loops : (B,) int64
        The same half-edges, every loop starting at its smallest, loops in
        the order of those (read-only).
    loop_offsets : (L + 1,) int64
        The offsets of the loops in ``loops`` (read-only).
    """
    chain = np.asarray(chain, dtype=np.int64)
    if chain.size == 0:
        return CLOSED
    order, new_off = canonical_order(chain, offsets)
    loops = chain[order]
    loops.setflags(write=False)
    new_off.setflags(write=False)
    return loops, new_off


def canonical_order(chain: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where :func:`canonical_loops` takes its loops from: ``chain[order]`` are they.

    Parameters
    ----------
    chain : (B,) int
        Boundary half-edges, loop after loop (B > 0), as :func:`canonical_loops` takes them.
    offsets : (L + 1,) int

    Returns
    -------
    order : (B,) int64
        The place in ``chain`` of every half-edge of the canonical loops.
    loop_offsets : (L + 1,) int64
        Their offsets.
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    B, L = chain.size, offsets.size - 1
    start, sizes = offsets[:-1], np.diff(offsets)
    least = np.minimum.reduceat(chain, start)
    at = np.flatnonzero(chain == np.repeat(least, sizes))  # one per loop: half-edges differ
    shift = at - start
    perm = np.argsort(least, kind="stable")
    new_sizes = sizes[perm]
    new_off = np.zeros(L + 1, dtype=np.int64)
    np.cumsum(new_sizes, out=new_off[1:])
    src_loop = np.repeat(perm, new_sizes)
    within = np.arange(B, dtype=np.int64) - np.repeat(new_off[:-1], new_sizes)
    within += shift[src_loop]
    within %= sizes[src_loop]
    within += start[src_loop]
    return within, new_off


def hole_twins(twin: np.ndarray, bh: np.ndarray) -> np.ndarray:
    """Set ``twin[bh[j]] = H + j`` (the hole half-edges, H = ``twin.size``), in place.

    Parameters
    ----------
    twin : (H,) int
        The twins of the face half-edges, the boundary's still to be set.
    bh : (B,) int
        The boundary half-edges, loop after loop (:func:`canonical_loops`).

    Returns
    -------
    (H,) int
        ``twin``, or a copy widened to int64 when ``H + B`` does not fit its dtype.
    """
    H = twin.size
    if H + bh.size > np.iinfo(twin.dtype).max:  # pragma: no cover - beyond 2**31 half-edges
        twin = twin.astype(np.int64)
    twin[bh] = np.arange(H, H + bh.size, dtype=twin.dtype)
    return twin
