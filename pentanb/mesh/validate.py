"""Validation: is a mesh a consistently oriented 2-manifold (closed or with boundary)
the operators can take?

:func:`validate` is the one check every mesh built from outside data goes
through (the constructor, :meth:`Mesh.from_csr`, the readers).  It runs
every check first as whole-array passes that only say yes or no
(:func:`_valid`, fast on meshes of millions of faces); a mesh that fails is
checked again, in order, by :func:`_diagnose`, which finds the first culprit
and raises a :class:`MeshError` naming it (a face, an edge, a vertex).

One pairing serves closed and open meshes
(:func:`~pentanb.mesh.boundary.open_twins`: on large meshes one compiled
counting sort; the numpy path sorts packed keys once, closed or not);
a mesh with boundary half-edges is then checked as a surface with boundary
(:func:`_valid_open`): every edge with one or two faces, every vertex's
faces one fan or one cycle.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .boundary import CLOSED, open_twins, orientation_classes, pair_open
from .coerce import MeshError, readonly
from .halfedge import (
    BLOCK,
    RotateUniform,
    heads_at,
    multi_fan_vertex,
    open_extension,
    open_vertex_rings,
    pair_twins,
    rotation_of,
    vertex_rings,
    walk_rings,
)

__all__ = ["validate", "validate_rings"]

#: Values per block of :func:`_repeats_in_a_face` (a few hundred kilobytes).
_ROWS = 1 << 16


def validate(
    mesh: Any,
    *,
    twin: np.ndarray | None = None,
    strict: bool = True,
) -> None:
    """Check that the mesh is an oriented 2-manifold, closed or with boundary; raise
    MeshError if not.

    Every check runs first as a whole-array pass that only says whether
    the mesh is valid (:func:`_valid`); only a mesh that fails one is
    checked again, in order, by :func:`_diagnose`, which finds
    the first culprit and names it.  The twins and vertex rings the
    checks derive stay cached.

    Parameters
    ----------
    mesh : Mesh
        A mesh just built from arrays nothing has checked yet.
    twin : (H,) int, optional
        The twins, when the caller knows them: checked to be the opposite
        half-edges (an involution without fixed points, each reversing its
        partner) instead of derived by sorting.
    strict : bool
        False accepts what the operators refuse one by one with their own
        message (interior vertices of fewer than 3 edges, unused vertices,
        two faces sharing two edges) but keeps every check that the arrays'
        consistency rests on: indices in range, faces of at least 3
        distinct vertices, every directed edge once (with its opposite, or
        on the boundary), one fan or cycle round every vertex.

    Raises
    ------
    MeshError
        Naming the first culprit.
    """
    if twin is not None:
        _check_twin(mesh, twin)
    if not _valid(mesh, twin, strict):
        _diagnose(mesh, strict)


def validate_rings(mesh: Any, rings: tuple[np.ndarray, np.ndarray]) -> None:
    """Keep ``rings`` as the vertex rings of a valid ``mesh``, or MeshError unless
    they are its rings (each vertex's outgoing half-edges in rotation order,
    starting anywhere)."""
    ring, off = (np.asarray(a) for a in rings)
    derived, derived_off = mesh.vertex_ring
    c = mesh._corners
    ok = ring.shape == derived.shape and np.array_equal(off, derived_off)
    if ok and ring.size:
        ok = ring.dtype.kind in "iu" and 0 <= int(ring.min()) and int(ring.max()) < c.size
    if ok and ring.size:
        slot = np.arange(ring.size)
        first = np.repeat(derived_off[:-1], np.diff(derived_off))
        following = np.where(
            slot + 1 < np.repeat(derived_off[1:], np.diff(derived_off)), slot + 1, first
        )
        ok = bool(
            np.array_equal(c[ring], c[derived])
            and np.array_equal(mesh.rotation[ring], ring[following])
        )
    if not ok:
        raise MeshError("the vertex rings handed over are not the rings of these faces")
    dtype = c.dtype
    mesh._shared.values["vertex_ring"] = (readonly(ring.astype(dtype)), readonly(off.astype(dtype)))


def _check_twin(mesh: Any, twin: np.ndarray) -> None:
    """MeshError unless ``twin`` pairs every half-edge with its opposite."""
    c = mesh._corners
    H = c.size
    if twin.shape != (H,):
        raise MeshError(f"twin must have one entry per corner ({H:,}), got {twin.size:,}")
    if H and (int(twin.min()) < 0 or int(twin.max()) >= H):
        bad = int(np.flatnonzero((twin < 0) | (twin >= H))[0])
        raise MeshError(
            f"twin of half-edge {bad} is {int(twin[bad])}, outside the {H:,} half-edges"
        )
    h = np.arange(H, dtype=twin.dtype)
    if (c.size and int(c.min()) < 0) or (c.size and int(c.max()) >= mesh.n_vertices):
        return  # the corners' own check names this
    head = mesh.head
    wrong = (twin == h) | (twin[twin] != h) | (c[twin] != head)
    if wrong.any():
        bad = int(np.flatnonzero(wrong)[0])
        raise MeshError(
            f"twin of half-edge {bad} ({int(c[bad])} -> {int(head[bad])}) is half-edge "
            f"{int(twin[bad])} ({int(c[twin[bad]])} -> {int(head[twin[bad]])}), not its opposite"
        )


def _valid(mesh: Any, twin: np.ndarray | None = None, strict: bool = True) -> bool:
    """Every check of :func:`_diagnose`, without messages.

    Faces of at least 3 corners; indices in range; no vertex twice in a
    face; every directed edge once and with its opposite, or on the
    boundary (:func:`~pentanb.mesh.boundary.open_twins`: one compiled
    counting sort, or sorts of packed 64-bit keys; a mesh with boundary
    half-edges goes on in :func:`_valid_open`); at least 3 edges at every
    vertex (so none unused); no two faces sharing two edges (no face twice
    among a face's neighbours); one fan around every vertex (the vertex
    rings, walked by one compiled kernel or in whole-array steps, use
    every half-edge once).
    """
    n, c, o = mesh.n_vertices, mesh._corners, mesh._offsets
    if n == 0 or o.size < 2 or c.size == 0:
        return False
    k = mesh._uniform_size
    if (k < 3) if k else int(mesh.face_sizes.min()) < 3:
        return False
    if int(c.min()) < 0 or int(c.max()) >= n:
        return False
    if _repeats_in_a_face(mesh, c, n):
        return False
    # the arrays below are not kept (only the twins and rings are): the
    # peak stays a few bytes per corner above the faces themselves
    if twin is None:
        got = open_twins(c, None if k else mesh.head, n, k)
        if got is None:  # no manifold
            return False
        twin, boundary = got
        if boundary[0].size:  # a surface with boundary
            return _valid_open(mesh, twin, boundary, strict)
    mesh._shared.values.setdefault("_boundary", CLOSED)
    if strict:
        if int(mesh.valences.min()) < 3:
            return False
        neighbour = twin // k if k else mesh.halfedge_face[twin]
        if _repeats_in_a_face(mesh, neighbour, mesh.n_faces):
            return False
        del neighbour
    mesh._shared.values["twin"] = readonly(twin)
    walked = walk_rings(twin, c, k, None if k else mesh.prev, mesh.valences)
    if walked is not None:  # (compiled: one walk round every vertex)
        ring, ring_off, ok = walked
        if not ok:
            return False
    else:
        # (no rotation array: a column copy of the twins walks the rings a
        # little faster, but raises the peak of reading a 1,000,000-triangle
        # file from 2.9x to 3.3x the arrays read)
        if k:  # rotation[h] = twin[prev[h]], prev computed as needed (no array kept)
            ring, ring_off = vertex_rings(RotateUniform(twin, k), c, mesh.valences)
        else:
            ring, ring_off = vertex_rings(rotation_of(twin, o, k, mesh), c, mesh.valences)
        if not _each_once(ring):
            return False
    mesh._shared.values["vertex_ring"] = (readonly(ring), readonly(ring_off))
    return True


def _valid_open(
    mesh: Any, twin: np.ndarray, boundary: tuple[np.ndarray, np.ndarray], strict: bool
) -> bool:
    """Every check of :func:`_diagnose` on a mesh with boundary, its twins paired.

    ``twin`` and ``boundary`` as :func:`~pentanb.mesh.boundary.open_twins`
    gives them (the boundary half-edges chained into loops, one leaving
    every boundary vertex); then as on a closed mesh: no interior vertex of
    fewer than 3 edges, no two faces sharing two edges, and the vertex
    rings (hole half-edges included) using every half-edge once.
    """
    bh, loop_off = boundary
    c, k = mesh._corners, mesh._uniform_size
    F, B = mesh.n_faces, bh.size
    mesh._shared.values["_boundary"] = boundary
    if strict:
        val = mesh.valences
        if val.size and int(val.min()) < 3:  # on the boundary only, and none unused
            low = np.flatnonzero(val < 3)
            if int(val[low].min()) < 1 or not mesh.is_boundary_vertex[low].all():
                return False
        # the face across every half-edge; F + j across the boundary half-edge bh[j]
        if k:
            neighbour = twin // k
        else:
            inner = twin.copy()
            inner[bh] = 0
            neighbour = mesh.halfedge_face[inner]
            del inner
        neighbour[bh] = np.arange(F, F + B, dtype=neighbour.dtype)
        if _repeats_in_a_face(mesh, neighbour, F + B):
            return False
        del neighbour
    mesh._shared.values["twin"] = readonly(twin)
    hole_tail = heads_at(c, bh, k, None if k else mesh.head)
    prv = None if k else mesh.prev
    got = walk_rings(twin, c, k, prv, mesh.valences, boundary, hole_tail)
    if got is None:  # the numpy path
        # (the rotation is not kept: the rings are what the mesh keeps)
        rotation = rotation_of(twin, mesh._offsets, k, mesh)
        ring, ring_off = open_vertex_rings(
            rotation, c, None, bh, loop_off, mesh.valences, hole_tail
        )
        del rotation
        ok = _each_once(ring)
    else:
        ring, ring_off, ok = got
    if not ok:
        return False
    mesh._shared.values["vertex_ring"] = (readonly(ring), readonly(ring_off))
    return True


def _each_once(ring: np.ndarray) -> bool:
    """Whether the vertex rings hold every half-edge (``ring.size`` of them) once."""
    seen = np.zeros(ring.size, dtype=bool)
    # (in blocks: numpy widens a scatter's index array, the whole of it at once otherwise)
    for a in range(0, ring.size, BLOCK):
        seen[ring[a : a + BLOCK]] = True
    return bool(seen.all())


def _repeats_in_a_face(mesh: Any, values: np.ndarray, bound: int) -> bool:
    """Whether some face holds a value twice (``values``: one per corner, in ``[0, bound)``).

    Faces of k sides: every pair of columns of the (m, k) table compared,
    block of rows by block (each block read once from memory, and a
    column of a block is one strided pass: several times faster than
    comparing two-dimensional slices).  Faces of several sizes: every
    corner with the corners 1, 2, ..., k // 2 places further round its
    face (every pair once), in whole-array passes.  Faces of more than 16
    sides are checked by one sort instead.
    """
    k = mesh._uniform_size
    if k:
        if k <= 16:
            a = values.reshape(-1, k)
            rows = max(_ROWS // k, 1)
            for lo in range(0, a.shape[0], rows):
                b = a[lo : lo + rows]
                for i in range(k - 1):
                    col = b[:, i]
                    for j in range(i + 1, k):
                        if (col == b[:, j]).any():
                            return True
            return False
    else:
        sizes = mesh.face_sizes
        top = int(sizes.max())
        if top <= 16:
            slot = mesh.halfedge_slot
            size = sizes[mesh.halfedge_face]
            h = np.arange(values.size, dtype=slot.dtype)
            for s in range(1, top // 2 + 1):
                # s places further round the face (faces of more than s sides)
                longer = size > s
                p = h + s
                p -= np.where(slot + s >= size, size, 0).astype(p.dtype, copy=False)
                p = np.where(longer, p, h)
                if ((values[p] == values) & longer).any():
                    return True
            return False
    key = mesh.halfedge_face.astype(np.int64) * np.int64(bound) + values
    key.sort()
    return bool((key[1:] == key[:-1]).any())


def _diagnose(mesh: Any, strict: bool = True) -> None:
    """Find the first culprit of an invalid mesh and raise a MeshError naming it."""
    n = mesh.n_vertices
    c = mesh._corners
    sizes = mesh.face_sizes
    small = np.flatnonzero(sizes < 3)
    if small.size:
        f = int(small[0])
        raise MeshError(
            f"face {f} has {sizes[f]} vertices {mesh.faces[f].tolist()}; "
            "a face needs at least 3 distinct vertices"
        )
    bad = np.flatnonzero((c < 0) | (c >= n))
    if bad.size:
        f = int(np.searchsorted(mesh._offsets, bad[0], side="right") - 1)
        raise MeshError(
            f"face {f} uses vertex index {int(c[bad[0]])}, out of range for {n} vertices"
        )
    # repeated vertex inside a face
    fid = mesh.halfedge_face
    key = fid.astype(np.int64) * n + c
    order = np.argsort(key, kind="stable")
    dup = np.flatnonzero(key[order][1:] == key[order][:-1])
    if dup.size:
        h = int(order[dup[0]])
        f = int(fid[h])
        distinct = np.unique(mesh.faces[f]).size
        raise MeshError(
            f"face {f} {mesh.faces[f].tolist()} repeats vertex {int(c[h])} "
            f"({distinct} distinct vertices); a face needs at least 3 "
            "distinct vertices and may use each vertex once"
        )
    if n == 0:
        raise MeshError("the mesh has no vertices")
    head = mesh.head
    twin = pair_twins(c, head, n)
    if twin is not None:
        mesh._shared.values.setdefault("_boundary", CLOSED)
    else:  # a surface with boundary, or faces that are no manifold
        _diagnose_pairing(mesh, head)
        got = open_twins(c, head, n)
        assert got is not None  # (every way for it to fail was named above)
        twin, boundary = got
        mesh._shared.values["_boundary"] = boundary
    mesh._shared.values["twin"] = readonly(twin)
    if strict:
        _diagnose_strict(mesh, twin)
    ring, _ = mesh.vertex_ring
    if not np.array_equal(np.sort(ring), np.arange(ring.size)):
        # a vertex whose rotation orbit is shorter than its valence
        if mesh.is_closed:
            rotation, tail = mesh.rotation, c
        else:
            bh, off = mesh._boundary
            rotation, tail = open_extension(mesh.rotation, c, head, bh, off)
        bad_v = multi_fan_vertex(rotation, tail, mesh.valences)
        raise MeshError(
            f"vertex {bad_v} is non-manifold: its faces form more than one fan"
            + ("" if mesh.is_closed else " (or a fan and a cycle)")
        )


def _diagnose_pairing(mesh: Any, head: np.ndarray) -> None:
    """Name why the half-edges do not pair up as an oriented manifold with boundary.

    In order: an edge with more than two faces (a non-manifold edge); two
    faces running along an edge in the same direction (non-orientable
    when no choice of the faces' orientations mends it, inconsistent
    orientation otherwise); a vertex the boundary passes through more
    than once (two fans meeting at one vertex).  Returns when none of
    these holds: the faces are an oriented manifold with boundary.
    """
    c, n, fid = mesh._corners, mesh.n_vertices, mesh.halfedge_face
    t = c.astype(np.int64)
    w = head.astype(np.int64)
    lo, hi = np.minimum(t, w), np.maximum(t, w)
    key = (lo * np.int64(n) + hi) * 2 + (t > w)
    order = np.argsort(key, kind="stable")
    skey = key[order] >> 1  # the undirected edge
    first = np.flatnonzero(np.r_[True, skey[1:] != skey[:-1]])
    sizes = np.diff(np.r_[first, skey.size])

    def used_by(u: int, v: int) -> list[int]:
        return fid[np.flatnonzero((c == u) & (head == v))].tolist()

    many = np.flatnonzero(sizes > 2)
    if many.size:
        hs = order[first[many[0]] : first[many[0]] + sizes[many[0]]]
        a, b = int(lo[hs[0]]), int(hi[hs[0]])
        u, v = (a, b) if len(used_by(a, b)) > 1 else (b, a)
        raise MeshError(
            f"directed edge ({u}, {v}) is used by faces {used_by(u, v)}: edge ({a}, {b}) "
            f"has {int(sizes[many[0]])} faces {sorted(fid[hs].tolist())}, a non-manifold "
            "edge (an edge has two faces, or one on the boundary)"
        )
    dkey = t * np.int64(n) + w
    sd = np.sort(dkey)
    twice = np.flatnonzero(sd[1:] == sd[:-1])
    if twice.size:
        u, v = divmod(int(sd[twice[0]]), n)
        pairs = first[sizes == 2]
        h1, h2 = order[pairs], order[pairs + 1]
        same = c[h1] == c[h2]
        flip, conflicts = orientation_classes(fid[h1], fid[h2], same, mesh.n_faces)
        if conflicts.size:
            e = int(conflicts[0])
            raise MeshError(
                f"directed edge ({u}, {v}) is used by faces {used_by(u, v)}: the surface is "
                "non-orientable (a Moebius band, say): no choice of its faces' orientations "
                "makes the two faces of every edge run along it in opposite directions "
                f"(faces {int(fid[h1[e]])} and {int(fid[h2[e]])} cannot both agree with "
                "their neighbours)"
            )
        wrong = np.flatnonzero(flip).tolist()
        shown = ", ".join(str(f) for f in wrong[:8]) + (", ..." if len(wrong) > 8 else "")
        raise MeshError(
            f"directed edge ({u}, {v}) is used by faces {used_by(u, v)}: inconsistent "
            f"orientation (both run along it from {u} to {v}, none from {v} to {u}); "
            f"reversing face{'s' if len(wrong) > 1 else ''} {shown} would orient the mesh "
            "consistently"
        )
    twin = pair_open(c, head, n)
    assert twin is not None
    bh = np.flatnonzero(twin < 0)
    leaving = np.bincount(c[bh], minlength=n)
    more = np.flatnonzero(leaving > 1)
    if more.size:
        v = int(more[0])
        raise MeshError(
            f"vertex {v} is non-manifold: its faces form more than one fan "
            f"({int(leaving[v])} fans meet there: the boundary passes through it "
            f"{int(leaving[v])} times)"
        )


def _diagnose_strict(mesh: Any, twin: np.ndarray) -> None:
    """The checks of :func:`_diagnose` that ``strict=False`` leaves out."""
    fid = mesh.halfedge_face
    unused = np.flatnonzero(mesh.valences == 0)
    if unused.size:
        raise MeshError(
            f"vertex {int(unused[0])} is not used by any face ({unused.size} unused vertices)"
        )
    few = np.flatnonzero((mesh.valences < 3) & ~mesh.is_boundary_vertex)
    if few.size:
        v = int(few[0])
        inner = "" if mesh.is_closed else "interior "
        raise MeshError(
            f"{inner}vertex {v} has only {int(mesh.valences[v])} edges; every {inner}vertex "
            "needs at least 3 (Section 4 rules out 1- and 2-valent vertices, "
            "and the dual of such a vertex would be a face of fewer than "
            "3 sides)"
        )
    eh = mesh.edge_halfedge
    eh = eh[twin[eh] < twin.size]  # the edges with two faces
    f1, f2 = fid[eh], fid[twin[eh]]
    # (a face on both sides of an edge would repeat a vertex: refused above)
    m = np.int64(mesh.n_faces)
    pair = np.minimum(f1, f2) * m + np.maximum(f1, f2)
    order = np.argsort(pair, kind="stable")
    dup = np.flatnonzero(pair[order][1:] == pair[order][:-1])
    if dup.size:
        a, b = order[dup[0]], order[dup[0] + 1]
        e1, e2 = (tuple(int(x) for x in mesh.edges[i]) for i in (a, b))
        raise MeshError(
            f"faces {int(min(f1[a], f2[a]))} and {int(max(f1[a], f2[a]))} "
            f"share more than one edge ({e1} and {e2}); the dual would "
            "have a double edge"
        )
