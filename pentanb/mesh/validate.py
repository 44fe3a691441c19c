"""Validation: is a mesh a closed, consistently oriented 2-manifold the operators can take?

:func:`validate` is the one check every mesh built from outside data goes
through (the constructor, :meth:`Mesh.from_csr`, the readers).  It runs
every check first as whole-array passes that only say yes or no
(:func:`_valid`, fast on meshes of millions of faces); a mesh that fails is
checked again, in order, by :func:`_diagnose`, which finds the first culprit
and raises a :class:`MeshError` naming it (a face, an edge, a vertex).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .boundary import describe_boundary
from .coerce import MeshError, readonly
from .halfedge import BLOCK, RotateUniform, multi_fan_vertex, pair_twins, rotation_of, vertex_rings

__all__ = ["validate", "validate_rings"]


def validate(
    mesh: Any,
    *,
    twin: np.ndarray | None = None,
    strict: bool = True,
) -> None:
    """Check that the mesh is a closed, oriented 2-manifold; raise MeshError if not.

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
        message (vertices of fewer than 3 edges, unused vertices, two faces
        sharing two edges) but keeps every check that the arrays'
        consistency rests on: indices in range, faces of at least 3
        distinct vertices, every directed edge once and with its opposite,
        one fan round every vertex.

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
    face; every directed edge once and with its opposite (one sort of
    packed 64-bit keys, :func:`~pentanb.mesh.halfedge.pair_twins`); at least 3 edges at every
    vertex (so none unused); no two faces sharing two edges (no face
    twice among a face's neighbours); one fan around every vertex (the
    vertex rings use every half-edge once).
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
        twin = pair_twins(c, None if k else mesh.head, n, k)
        if twin is None:
            return False
    if strict:
        if int(mesh.valences.min()) < 3:
            return False
        neighbour = twin // k if k else mesh.halfedge_face[twin]
        if _repeats_in_a_face(mesh, neighbour, mesh.n_faces):
            return False
        del neighbour
    mesh._shared.values["twin"] = readonly(twin)
    # (no rotation array: a column copy of the twins walks the rings a
    # little faster, but raises the peak of reading a 1,000,000-triangle
    # file from 2.9x to 3.3x the arrays read)
    if k:  # rotation[h] = twin[prev[h]], prev computed as needed (no array kept)
        ring, ring_off = vertex_rings(RotateUniform(twin, k), c, mesh.valences)
    else:
        ring, ring_off = vertex_rings(rotation_of(twin, o, k, mesh), c, mesh.valences)
    seen = np.zeros(c.size, dtype=bool)
    for a in range(0, ring.size, BLOCK):
        seen[ring[a : a + BLOCK]] = True
    if not seen.all():
        return False
    mesh._shared.values["vertex_ring"] = (readonly(ring), readonly(ring_off))
    return True


def _repeats_in_a_face(mesh: Any, values: np.ndarray, bound: int) -> bool:
    """Whether some face holds a value twice (``values``: one per corner, in ``[0, bound)``).

    Compares every corner with the corners 1, 2, ..., k // 2 places
    further round its face (every pair once), in whole-array passes;
    faces of more than 16 sides are checked by one sort instead.
    """
    k = mesh._uniform_size
    if k:
        if k <= 16:
            a = values.reshape(-1, k)
            for s in range(1, k // 2 + 1):
                if (a[:, s:] == a[:, :-s]).any() or (a[:, :s] == a[:, k - s :]).any():
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
    if twin is None:
        kind, h = _unpaired(c, head, n)
        u, w = int(c[h]), int(head[h])
        if kind == "duplicate":
            faces = np.flatnonzero((c == u) & (head == w))
            raise MeshError(
                f"directed edge ({u}, {w}) is used by faces "
                f"{fid[faces].tolist()}: inconsistent orientation or "
                "a non-manifold edge"
            )
        raise MeshError(
            f"edge ({u}, {w}) of face {int(fid[h])} has only one side "
            f"(a boundary): the mesh must be closed; it has {describe_boundary(c, head)}"
        )
    mesh._shared.values["twin"] = readonly(twin)
    if strict:
        _diagnose_strict(mesh, twin)
    ring, _ = mesh.vertex_ring
    if not np.array_equal(np.sort(ring), np.arange(c.size)):
        # a vertex whose rotation orbit is shorter than its valence
        bad_v = multi_fan_vertex(mesh.rotation, c, mesh.valences)
        raise MeshError(f"vertex {bad_v} is non-manifold: its faces form more than one fan")


def _unpaired(tail: np.ndarray, head: np.ndarray, n: int) -> tuple[str, int]:
    """Why the half-edges do not pair: ``("duplicate", h)``, a directed edge
    used twice (``h`` one of them), or ``("boundary", h)``, a half-edge
    without an opposite."""
    n64 = np.int64(n)
    lo = np.minimum(tail, head).astype(np.int64)
    hi = np.maximum(tail, head).astype(np.int64)
    key = (lo * n64 + hi) * 2 + (tail > head)
    order = np.argsort(key, kind="stable")
    skey = key[order]
    dup = np.flatnonzero(skey[1:] == skey[:-1])
    if dup.size:
        return "duplicate", int(order[dup[0]])
    want = (lo * n64 + hi) * 2 + (tail < head)
    pos = np.minimum(np.searchsorted(skey, want), skey.size - 1)
    return "boundary", int(np.flatnonzero(skey[pos] != want)[0])


def _diagnose_strict(mesh: Any, twin: np.ndarray) -> None:
    """The checks of :func:`_diagnose` that ``strict=False`` leaves out."""
    fid = mesh.halfedge_face
    unused = np.flatnonzero(mesh.valences == 0)
    if unused.size:
        raise MeshError(
            f"vertex {int(unused[0])} is not used by any face ({unused.size} unused vertices)"
        )
    few = np.flatnonzero(mesh.valences < 3)
    if few.size:
        v = int(few[0])
        raise MeshError(
            f"vertex {v} has only {int(mesh.valences[v])} edges; every vertex "
            "needs at least 3 (Section 4 rules out 1- and 2-valent vertices, "
            "and the dual of such a vertex would be a face of fewer than "
            "3 sides)"
        )
    eh = mesh.edge_halfedge
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
