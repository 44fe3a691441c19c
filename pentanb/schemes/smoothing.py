"""The dual, the paper's smoothing operator (Sections 3 and 5).

"We do not directly compute the weights ... We then apply dual operation
even number of times to create a smooth mesh."  The dual puts a vertex at
each face's centroid and makes a face of each vertex; applied twice it gives
back the mesh's type with every vertex moved to the average of the centroids
of its neighbouring faces.

On an open mesh the dual stays open.  Its vertices are the face centroids,
the midpoints of the boundary edges and the boundary's *corners*
(:func:`~pentanb.schemes._build.boundary_corners`: vertices of one face
where the boundary turns by more than 30 degrees), kept where they are.  A
boundary vertex's face goes round its faces' centroids and is closed along
the boundary through the midpoints of its two boundary edges, and through
the vertex itself at a corner.  A vertex of one face on a straight boundary
is cut off like the others (pentagonalization leaves one at two thirds of
every boundary edge: keeping them would pin the boundary to its first
polygon); a corner is kept, as Catmull-Clark's and Doo-Sabin's boundary
rules keep theirs (cut off, the faces next to it fold after a few
iterations).  So the dual's boundary is the polygon of the midpoints of the
boundary's edges, corners kept, and two duals replace every boundary vertex
p_i that is not a corner by ``(p_{i-1} + 2 p_i + p_{i+1}) / 4``: two rounds
of midpoint averaging, as in Lane and Riesenfeld's B-spline subdivision.  After a
remeshing that splits boundary edges at their midpoints (pentagon
preservation, Loop's, vertex insertion) that makes the boundary follow
cubic B-spline subdivision, the boundary rule of Loop and Catmull-Clark;
after pentagonalization's trisection, the ternary scheme of mask
``(1, 4, 8, 10, 8, 4, 1) / 12``, which is C1.
"""

from __future__ import annotations

import functools

import numpy as np

from .._checks import MAX_STEPS
from ..mesh import Mesh, Several
from ..mesh import build as _mesh
from ..mesh.boundary import canonical_loops, canonical_order
from ._build import (
    boundary_next,
    check_count,
    check_mesh,
    check_vertex_faces,
    corner_ids,
    index_dtype,
    inverse,
    loop_successor,
    open_dual_faces,
    open_twins_from,
    output,
    ring_places,
    start_at_max,
)

__all__ = ["dual", "smooth"]


def dual(mesh: Mesh) -> Mesh:
    """The dual mesh: a vertex at every face centroid, a face for every vertex.

    Parameters
    ----------
    mesh : Mesh
        Any polygon mesh with V vertices, E edges and F faces; open meshes
        too (B boundary edges, C corners: boundary vertices of one face).

    Returns
    -------
    Mesh
        F vertices (the plain mean of each face's vertices), E edges and V
        faces; face ``v`` of the dual goes round vertex ``v`` of ``mesh``
        counter-clockwise, so the orientation (the sign of the enclosed
        volume) is kept.  A k-valent vertex becomes a k-gon.

        Open (B boundary edges, C corners): F + B + C vertices (the
        centroids, the midpoints of the boundary edges in the order of
        :attr:`~pentanb.Mesh.boundary_halfedges`, then the corners in
        vertex order, where they are), E + B + C edges, V faces, B + C
        boundary edges and the same C corners.  The face of a boundary
        vertex with k faces has k + 2 sides (k + 3 at a corner): the
        module's docstring gives the rule and the curve scheme the
        boundary follows.

    Notes
    -----
    Built from the input's vertex rings; the output's twins and vertex
    rings are written directly (no sorting) when first asked for: the dual
    half-edge at the corner of half-edge ``h`` is the twin of the one at
    ``next[twin[prev[h]]]``, and the dual half-edges of a face's half-edges,
    in face order, go round the dual vertex of that face.  The dual of a
    closed dual reuses the connectivity of the mesh it came from.  On an
    open mesh the twins, boundary loops and rings are written from the
    input's rings and loops too (no sorting); the dual of an open dual has
    the faces of the mesh it came from first, as they are (each face's
    corners in that mesh's order), then those of the boundary.  When that
    mesh is an output of the paper's two schemes, which keep room after
    their faces for this, it shares that mesh's face arrays, as the dual
    of a closed dual does; else it copies them.

    Raises
    ------
    MeshError
        A vertex with fewer than 3 edges (its dual face would have fewer
        than 3 sides), named in the message.  The constructor refuses such
        meshes; only ``Mesh.from_csr(..., validate=False)`` can build one.
    """
    check_mesh(mesh, "dual")
    if not mesh.is_closed:
        return _open_dual(mesh)
    source_offsets = _mesh.dual_source_offsets(mesh)
    if source_offsets is not None:
        # mesh is itself a dual: its vertex f is the source's face f, with as
        # many edges as that face has sides; its dual has the connectivity of
        # the mesh it came from (dual(dual(m)) has m's faces in m's order),
        # only new positions
        check_vertex_faces(mesh, "dual", np.diff(source_offsets))
        again = _mesh.dual_again(mesh)
        assert again is not None
        return again
    check_vertex_faces(mesh, "dual")
    _, ring_off = mesh.vertex_ring
    # the dual's face v: the faces round vertex v, in rotation order
    corners = _mesh.ring_faces(mesh)
    faces = _mesh.faces_only(mesh)
    out = output(
        mesh.face_centroids,
        corners,
        ring_off,
        twin=lambda: _dual_twin(faces),
        rings=lambda: (inverse(faces.vertex_ring[0]), faces.offsets),
        dual_of=mesh,
        closed=True,
    )
    _mesh.note_extent(out, _mesh.extent(mesh))
    return out


def _open_dual(mesh: Mesh) -> Mesh:
    """The dual of an open mesh (numpy; its twins and rings written when asked for).

    Vertices: the F face centroids, the B midpoints of the boundary edges,
    then the C corners.  The face of vertex v: the centroids of v's faces
    in its ring's order, preceded on the boundary by the midpoint of the
    boundary edge entering v, v itself at a corner, and the midpoint of the
    one leaving it.
    """
    record = _mesh.open_dual_record(mesh)
    if record is not None:  # mesh is itself the dual of an open mesh
        return _open_dual_again(mesh, *record)
    check_vertex_faces(mesh, "dual")
    F, bh = mesh.n_faces, mesh.boundary_halfedges
    B = bh.size
    nxt = boundary_next(mesh.offsets, bh, _mesh.uniform_size(mesh))
    keep, kept = corner_ids(mesh, F + B, nxt)
    corners, offsets = open_dual_faces(mesh, keep, F + B + kept.size, nxt)
    return _open_dual_output(mesh, keep, kept, corners, offsets, nxt)


def _open_dual_output(
    mesh: Mesh,
    keep: np.ndarray,
    kept: np.ndarray,
    corners: np.ndarray,
    offsets: np.ndarray,
    nxt: np.ndarray,
    turned: tuple[np.ndarray, np.ndarray, int] | None = None,
) -> Mesh:
    """The dual of the open ``mesh`` from its faces (``nxt``: ``next`` of its
    boundary half-edges), with producers of its twins, rings and boundary, and
    a record for its own dual.  ``keep`` and ``kept``: :func:`corner_ids`.

    The faces of ``mesh``'s vertices go round their rings, from where the
    rings start; ``turned`` (the corners, offsets and size of the faces of
    the mesh ``mesh`` is the dual of) says that the first faces are those
    faces instead, as they are (:func:`_open_dual_again`)."""
    F, bh = mesh.n_faces, mesh.boundary_halfedges
    B = bh.size
    v = mesh.vertices
    vertices = np.empty((F + B + kept.size, 3))
    _mesh.face_centroids_into(mesh, vertices[:F])
    heads = mesh.corners[nxt]
    a, b = v.take(mesh.corners[bh], axis=0), v.take(heads, axis=0)
    vertices[F : F + B] = 0.5 * a + 0.5 * b  # (no sum that could overflow)
    v.take(kept, axis=0, out=vertices[F + B :])
    faces = _mesh.faces_only(mesh)
    one = (keep < 0).astype(np.int64)  # boundary half-edges at head(bh[j]): 1 or 2
    n_out, size = vertices.shape[0], corners.size
    dt = index_dtype(n_out, size)

    def connectivity() -> Several:  # from where the ring entries went in the faces
        at = ring_places(faces, keep, n_out)
        if turned is not None:
            H = turned[0].size
            at[:H] = _unturned(*turned).take(at[:H])
        return _open_dual_connectivity(faces, at, one, size, dt)

    written = functools.cache(connectivity)
    out = output(vertices, corners, offsets, twin=written, rings=written)
    base = offsets[heads].astype(np.int64)  # the first corner of every boundary face
    loops = _mesh.loop_offsets(faces)
    _mesh.note_boundary(out, lambda: canonical_loops(*_open_dual_chain(base, one, loops)))
    # for the dual of this dual: the input's faces and boundary (arrays only,
    # so that a chain of duals keeps no earlier mesh's connectivity alive)
    room = _mesh.room(faces)  # where the dual of this dual may write its boundary's faces
    record = (faces.corners, faces.offsets, _mesh.uniform_size(faces), bh, loops, base, one, room)
    _mesh.note_open_dual(out, record)
    _mesh.note_extent(out, _mesh.extent(mesh))
    return out


def _open_dual_chain(
    base: np.ndarray, one: np.ndarray, loops: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The boundary half-edges of an open dual, loop after loop from any start.

    The face of ``head[bh[j]]`` starts at ``base[j]`` with its boundary
    half-edges: ``base[j]`` (from the midpoint of ``bh[j]`` to that of the
    next, or to the corner) and, at a corner (``one[j] == 0``), ``base[j] + 1``.
    """
    per = np.zeros(base.size + 1, dtype=np.int64)
    np.cumsum(2 - one, out=per[1:])
    chain = np.repeat(base, 2 - one)
    chain[per[:-1][one == 0] + 1] += 1
    return chain, per[loops]


def _open_dual_again(
    mesh: Mesh,
    source_corners: np.ndarray,
    source_offsets: np.ndarray,
    k: int,
    bh: np.ndarray,
    loops: np.ndarray,
    base: np.ndarray,
    one: np.ndarray,
    room: _mesh.Room | None,
) -> Mesh:
    """The dual of ``mesh``, itself the open dual of a mesh ``source``, from
    ``source``'s faces (corners, offsets, k: their one size or 0), boundary
    half-edges ``bh`` and loop offsets: no pass over ``mesh``'s vertex rings.

    ``mesh``'s vertex f (``f`` < F, the centroid of ``source``'s face f) is
    interior; its ring's faces are ``source``'s face f's vertices, from its
    largest: the dual's face f is ``source``'s face f, kept as it is (as
    the dual of a closed dual keeps its source's faces).  ``mesh``'s
    vertex ``F + j`` (the midpoint of ``source``'s boundary half-edge
    ``b = bh[j]``) gives the quad of the midpoints of its two boundary
    edges, ``head[b]`` and ``tail[b]``; the corner of ``source`` kept as
    ``mesh``'s vertex ``F + B + c`` gives the midpoints of its two
    boundary edges, itself when it is still a corner, and the face it is
    a vertex of.  ``base`` and ``one`` are as in :func:`_open_dual_chain`.

    The faces along the boundary follow ``source``'s.  When ``source``'s
    arrays have room after them (``room``, :class:`~pentanb.mesh.build.Room`),
    they are written there and the dual shares ``source``'s faces, as the
    dual of a closed dual does; else every corner is copied.
    """
    F1 = mesh.n_faces  # source's vertices
    bh1 = mesh.boundary_halfedges
    B1 = bh1.size
    # mesh's boundary half-edges are the first one or two of their faces
    # (see _open_dual_chain), of at least 3 sides: the next is the one after
    nxt = bh1.astype(np.int64) + 1
    keep, kept = corner_ids(mesh, F1 + B1, nxt)
    # where mesh's boundary half-edges base[j] (and base[j] + 1) are in bh1
    chain, chain_off = _open_dual_chain(base, one, loops)
    where = np.empty(B1, dtype=np.int64)
    where[canonical_order(chain, chain_off)[0]] = np.arange(F1, F1 + B1)
    first = np.zeros(base.size, dtype=np.int64)  # where base[j] is in the chain
    np.cumsum(2 - one[:-1], out=first[1:])

    def index(j: np.ndarray, second: np.ndarray | int = 0) -> np.ndarray:
        # the dual's vertex at mesh's boundary half-edge base[j] (+ 1 with second)
        return where[first[j] + second]

    F, B = source_offsets.size - 1, bh.size
    tail = source_corners[bh].astype(np.int64)
    head = source_corners[boundary_next(source_offsets, bh, k)].astype(np.int64)
    before = np.arange(-1, B - 1, dtype=np.int64)  # the loop predecessor of every j
    before[loops[:-1]] = loops[1:] - 1
    quads = np.empty((B, 4), dtype=np.int64)
    quads[:, 0] = index(before, 1 - one[before])
    quads[:, 1] = where[first]
    quads[:, 2] = head
    quads[:, 3] = tail
    two = np.flatnonzero(one == 0)
    two = two[np.argsort(head[two], kind="stable")]  # source's corners in vertex order
    still = keep[where[first[two]] - F1]  # at mesh's vertex F + B + c, the head of base[j]
    ends = np.empty((two.size, 4), dtype=np.int64)
    ends[:, 0] = index(two)
    ends[:, 1] = still
    ends[:, 2] = index(two, 1)
    ends[:, 3] = head[two]
    ends_flat = ends.reshape(-1)
    ends_flat = ends_flat[ends_flat >= 0]
    offsets_in = source_offsets
    H = int(offsets_in[-1])
    n_out = F1 + B1 + kept.size
    total = H + 4 * B + ends_flat.size
    dt = index_dtype(n_out, total)
    n_offsets = F + B + two.size + 1
    shared = None if room is None else room.take(total, n_offsets, dt)
    if shared is not None:  # source's faces are there already
        corners, offsets = shared
    else:
        corners = np.empty(total, dtype=dt)
        corners[:H] = source_corners  # (the dual of the dual's rings would turn them)
        offsets = np.empty(n_offsets, dtype=dt)
        offsets[: F + 1] = offsets_in
    corners[H : H + 4 * B] = quads.reshape(-1)
    corners[H + 4 * B :] = ends_flat
    offsets[F + 1 : F + B + 1] = H + 4 * np.arange(1, B + 1)
    offsets[F + B + 1 :] = H + 4 * B + np.cumsum(3 + (still >= 0))
    turned = (source_corners, source_offsets, k)
    return _open_dual_output(mesh, keep, kept, corners, offsets, nxt, turned)


def _unturned(corners: np.ndarray, offsets: np.ndarray, k: int) -> np.ndarray:
    """(H,) int64: where every corner of the faces turned to start at their
    largest vertex (:func:`~pentanb.schemes._build.start_at_max`) sits in
    the faces as they are (``k``: their one size, or 0)."""
    H = corners.size
    if k:
        rows = corners.reshape(-1, k)
        place = np.arange(k, dtype=np.int64) + rows.argmax(axis=1)[:, None]
        place %= k
        place += np.arange(0, H, k, dtype=np.int64)[:, None]
        return place.reshape(-1)
    start = offsets[:-1].astype(np.int64)
    sizes = np.diff(offsets).astype(np.int64)
    top = np.maximum.reduceat(corners, start)
    shift = np.flatnonzero(corners == np.repeat(top, sizes)) - start  # (a face's corners differ)
    first = np.repeat(start, sizes)
    place = np.arange(H, dtype=np.int64) - first
    place += np.repeat(shift, sizes)
    place %= np.repeat(sizes, sizes)
    place += first
    return place


def _open_dual_connectivity(
    mesh, at: np.ndarray, one: np.ndarray, size: int, dt: np.dtype
) -> Several:
    """The twins, boundary and vertex rings of the dual of an open mesh (its faces),
    written from its rings.

    ``at`` is where every vertex ring entry of ``mesh`` went in the dual's
    corners (:func:`~pentanb.schemes._build.ring_places`); ``one``
    is 1 where the face of ``head[bh[j]]`` has one boundary half-edge, 0
    where it has two (a corner kept); ``size`` and ``dt`` are the dual's
    number of half-edges and index dtype.  The dual half-edge at the centroid
    of face half-edge ``h``'s face (position ``pos[h]``) is the twin of the
    one at ``next[rotation[h]]``, as on a closed mesh; where ``rotation[h]``
    is a hole half-edge (``prev[h]`` on the boundary), of the one from the
    midpoint of ``prev[h]`` (just before ``pos[prev[h]]``).  A boundary
    vertex's face starts with its boundary half-edges (1 or 2), which
    follow the input's loops.
    """
    ring, _ = mesh.vertex_ring
    H, bh = mesh.n_halfedges, mesh.boundary_halfedges
    # the ring holds every half-edge once, hole half-edges too: one scatter
    placed = np.empty(ring.size, dtype=dt)
    placed[ring] = at
    pos = placed[:H]
    base = placed[H:].astype(np.int64)  # hole half-edge H + j: at head(bh[j])
    nxt = mesh.next
    after = nxt[bh]  # the half-edges whose rotation is a hole half-edge
    tgt = np.minimum(mesh.rotation, H - 1)  # (a hole half-edge: any, written over)
    tgt = pos.take(nxt.take(tgt))
    tgt[after] = pos[bh] - 1
    twin = np.empty(size, dtype=dt)
    twin[pos] = tgt
    twin[pos[bh] - 1] = pos[after]
    # the boundary: base[j] (mid(bh[j]) -> mid of the next, or -> the corner), base[j] + 1
    got = open_twins_from(twin, *_open_dual_chain(base, one, _mesh.loop_offsets(mesh)))
    twin = got["twin"]
    # the rings: round the centroid of face f, the dual half-edges of f's
    # half-edges in face order; round the midpoint of bh[j], its hole
    # half-edge, base[j] and the one to the centroid of bh[j]'s face; round
    # a corner, its hole half-edge and base[j] + 1
    before = np.empty(bh.size, dtype=np.int64)  # the loop predecessor of every j
    before[loop_successor(mesh)] = np.arange(bh.size)
    last_in = base[before] + 1 - one[before]  # the boundary half-edge entering mid(bh[j])
    mids = np.empty((bh.size, 3), dtype=dt)
    mids[:, 0] = twin[last_in]
    mids[:, 1] = base
    mids[:, 2] = pos[bh] - 1
    two = np.flatnonzero(one == 0)
    two = two[np.argsort(mesh.head[bh[two]], kind="stable")]  # the corners in vertex order
    corners = np.empty((two.size, 2), dtype=dt)
    corners[:, 0] = twin[base[two]]
    corners[:, 1] = base[two] + 1
    F, offsets = mesh.n_faces, mesh.offsets
    ring = np.concatenate(
        [
            start_at_max(pos, offsets, _mesh.uniform_size(mesh)),
            mids.reshape(-1),
            corners.reshape(-1),
        ]
    )
    ring_off = np.empty(F + bh.size + two.size + 1, dtype=dt)
    ring_off[: F + 1] = offsets
    ring_off[F + 1 : F + bh.size + 1] = np.arange(1, bh.size + 1) * 3 + H
    ring_off[F + bh.size + 1 :] = np.arange(1, two.size + 1) * 2 + H + 3 * bh.size
    got["vertex_ring"] = (ring, ring_off)
    return got


def _dual_twin(mesh) -> np.ndarray:
    """The twins of the dual of ``mesh`` (its faces, see :func:`pentanb.mesh.build.faces_only`).

    The dual half-edge at ring position ``i`` (half-edge ``h = ring[i]``)
    runs from the face of ``h`` to the face of ``rotation[h]``; its twin is
    the dual half-edge at ``next[rotation[h]]``.
    """
    ring, _ = mesh.vertex_ring
    pos = inverse(ring)
    return pos[mesh.next[mesh.rotation[ring]]]


def smooth(mesh: Mesh, duals: int = 2) -> Mesh:
    """Apply :func:`dual` ``duals`` times (the paper's smoothing).

    An even count keeps the mesh's type (a pentagonal mesh stays pentagonal).

    Parameters
    ----------
    mesh : Mesh
    duals : int, in [0, :data:`pentanb.subdivision.MAX_STEPS`]

    Returns
    -------
    Mesh
        ``mesh`` after ``duals`` duals (``mesh`` itself for 0).

    Raises
    ------
    TypeError
        ``mesh`` is not a Mesh, or ``duals`` not an integer.
    ValueError
        ``duals`` is negative or over ``MAX_STEPS`` (100,000 duals: hours
        of work that no longer changes the counts), refused before the first.
    """
    check_mesh(mesh, "smooth")
    duals = check_count(duals, "duals", MAX_STEPS)
    for _ in range(duals):
        mesh = dual(mesh)
    return mesh
