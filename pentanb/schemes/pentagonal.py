"""The paper's two schemes (Section 5): pentagonalization and pentagon preservation.

Both are remeshings: the old vertices stay where they are and new vertices
are placed by affine rules.  Smoothing is the dual's job
(:func:`pentanb.smooth`).

On an open mesh both work face by face as on a closed one: a boundary edge
is split as an interior edge is (in three, in two), so the output's
boundary is the input's, refined, and its faces are the same pentagons
(and copies).  The output's twins and rings are written from the
input's as on a closed mesh (the rings in one compiled pass, the
boundary's few rows among them), its boundary half-edges paired with
hole half-edges in the order of its boundary loops, which are the input's,
refined.  The boundary, the twins and the rings are written apart, each
when first asked for: the dual needs the rings and the boundary only.
"""

from __future__ import annotations

import numpy as np

from .. import _jit
from ..mesh import Mesh, Rings, Several
from ..mesh import build as _mesh
from ..mesh.boundary import canonical_loops, hole_twins
from ..mesh.halfedge import next_of, prev_of
from ._build import (
    BLOCK,
    ROOM_CORNERS,
    ROOM_OFFSETS,
    boundary_prev,
    check_mesh,
    check_scale,
    edge_points,
    index_dtype,
    output,
    remeshed,
    running_sum,
    scale_safe,
    start_at_max,
    turned,
    with_room,
)

__all__ = ["pentagonalize", "preserve_pentagons"]

#: Edges per block where an open output's rings are written block by block
#: (the blocks' temporaries, under a megabyte, stay in cache and out of the peak).
EDGE_BLOCK = 1 << 15


def _midpoint_rings(mids: np.ndarray, eh: np.ndarray, back: np.ndarray, prv: np.ndarray, H: int):
    """Fill ``mids`` (E, 4): the four output half-edges round every edge's midpoint.

    Those of its half-edge ``eh``, of ``prev[eh]``, of the opposite ``back``
    and of ``prev[back]``: ``H + 5 h`` and ``H + 5 h + 2`` in pentagon
    preservation's numbering.
    """
    for s, (part, add) in enumerate(((eh, 0), (prv[eh], 2), (back, 0), (prv[back], 2))):
        col = part * 5
        col += H + add
        mids[:, s] = col


def _copy_rings(prv: np.ndarray, H: int, dt) -> np.ndarray:
    """(H, 3): the ring of every half-edge h's copy vertex: h, H + 5 prev[h] + 3, H + 5h + 4."""
    copies = np.empty((H, 3), dtype=dt)
    h = np.arange(H, dtype=dt)
    copies[:, 0] = h
    col = prv * 5
    col += H + 3
    copies[:, 1] = col
    col = h * 5
    col += H + 4
    copies[:, 2] = col
    return copies


@scale_safe
def pentagonalize(mesh: Mesh) -> Mesh:
    """Pentagonalization (pentagonal conversion), Section 5.1 steps 1-2, Figure 6.

    1. Every edge is cut into three equal parts.
    2. A point (the paper's *point sphere*) is put at every face's centroid and
       joined to the trisection point just after each face corner (every
       third corner of the subdivided face).

    Every n-gon becomes n pentagons, so the result has only pentagons, for
    any input.  This is Conway's *gyro* operator.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces; open meshes too (B boundary edges).

    Returns
    -------
    Mesh
        V + 2E + F vertices, 5E edges, 2E pentagons (open: V + 2E + F
        vertices, 5E - B edges, 2E - B pentagons, 3B boundary edges: a
        pentagon per half-edge, and each boundary edge in three).  Vertices are numbered
        old vertices first, then the two trisection points of every edge
        (edge ``e``: rows ``V + 2e`` at 1/3 and ``V + 2e + 1`` at 2/3 from its
        smaller vertex), then the face centroids.  The pentagon of half-edge
        ``h = (u, w)`` in face ``f`` is ``(t1, t2, w, t1', c_f)``: the
        trisection points of ``h`` near u and near w, w, the point just after w
        on the next half-edge, and the centre.

    Notes
    -----
    The output's faces are written column by column into one (2E, 5)
    array; its twins and vertex rings follow from the input's and are
    written when first asked for (by the dual, say), never found by sorting.
    """
    check_mesh(mesh, "pentagonalize")
    closed = mesh.is_closed
    n, E, F, H = mesh.n_vertices, mesh.n_edges, mesh.n_faces, mesh.n_halfedges
    dt = index_dtype(n + 2 * E + F, 5 * H)
    forward = _mesh.forward(mesh)
    # every column is computed contiguously and written once: numpy is slow on
    # strided views, and slower still on views whose last axis is short
    B_out = 0 if closed else 3 * mesh.boundary_halfedges.size  # (room for the dual's dual)
    buffer = with_room(5 * H, B_out, ROOM_CORNERS, dt)
    faces = buffer[: 5 * H].reshape(H, 5)
    base = mesh.halfedge_edge.astype(dt)  # V + 2e
    base *= 2
    base += n
    t1 = base + 1  # the trisection point near the tail: V + 2e + (0 forward, 1 backward)
    t1 -= forward
    faces[:, 0] = t1
    base += forward  # the one near the head: V + 2e + (1 forward, 0 backward)
    faces[:, 1] = base
    del t1, base
    faces[:, 2] = mesh.head
    k = _mesh.uniform_size(mesh)
    if k:  # every face a k-gon: the next half-edge is the next row of the face
        block = faces.reshape(F, k, 5)
        centres = np.arange(n + 2 * E, n + 2 * E + F, dtype=dt)
        for j in range(k):
            block[:, j, 3] = block[:, (j + 1) % k, 0]
            block[:, j, 4] = centres
    else:
        faces[:, 3] = faces[:, 0][mesh.next]
        centre = mesh.halfedge_face.astype(dt)
        centre += n + 2 * E
        faces[:, 4] = centre
    vertices = np.empty((n + 2 * E + F, 3))
    vertices[:n] = mesh.vertices
    edge_points(mesh, 2, out=vertices[n : n + 2 * E])
    vertices[n + 2 * E :] = mesh.face_centroids
    if not closed:  # its twins, boundary and rings written from the input's, apart
        offsets = with_room(H + 1, B_out, ROOM_OFFSETS, dt)
        offsets[: H + 1] = np.arange(0, 5 * H + 1, 5, dtype=dt)
        return _open_output(
            mesh,
            vertices,
            buffer[: 5 * H],
            offsets[: H + 1],
            dt,
            _pentagonalized_chain,
            _pentagonalized_open_twin,
            _pentagonalized_open_rings,
            room=(buffer, offsets),
        )
    # the twins' producer holds the input's twins and offsets only, not its
    # faces (whose cached connectivity would then stay alive until the
    # output's twins are asked for, maybe an iteration later)
    twin_in, offsets_in, source = mesh.twin, mesh.offsets, _mesh.faces_only(mesh)
    return output(
        vertices,
        faces.reshape(-1),
        np.arange(0, 5 * H + 1, 5, dtype=dt),
        twin=lambda: _pentagonalized_twin(twin_in, offsets_in, dt),
        rings=lambda: _pentagonalized_rings(source, dt),
        closed=True,
    )


def _pentagonalized_twin(twin: np.ndarray, offsets: np.ndarray, dt: np.dtype) -> np.ndarray:
    """The twins of ``pentagonalize(mesh)`` from ``mesh``'s twins and offsets.

    Half-edge ``5h + s`` is slot ``s`` of the pentagon of ``h``: its twins
    are ``5 twin[h]``, ``5 prev[twin[h]] + 2``, ``5 twin[next[h]] + 1``,
    ``5 next[h] + 4`` and ``5 prev[h] + 3``.
    """
    H = twin.size
    tw = twin.astype(dt, copy=False)
    nxt, prv = next_of(offsets, H, dt), prev_of(offsets, H, dt)
    out = np.empty((H, 5), dtype=dt)
    # column by column, each computed contiguously and written once
    for s, part in enumerate((tw, prv[tw], tw[nxt], nxt, prv)):
        col = part * 5
        col += (0, 2, 1, 4, 3)[s]
        out[:, s] = col
    return out.reshape(-1)


def _open_output(
    mesh, vertices, corners, offsets, dt, chain_of, twin_of, rings_of, room=None, **kw
) -> Mesh:
    """:func:`output` of a scheme's open output, its boundary, twins and rings written apart.

    ``chain_of(faces)`` gives the output's boundary half-edges ``(B, p)``:
    the ``p`` pieces of every boundary half-edge of the input, in its loop
    order; the output's boundary loops are those chained
    (:func:`~pentanb.mesh.boundary.canonical_loops`), found here (a few
    arrays of ``p B`` entries) for its boundary, twins (``twin_of(faces,
    bh_out, dt)``, ``bh_out`` its boundary half-edges loop after loop) and
    rings (``rings_of(faces, hole, dt)``, ``hole`` ``(B, p)`` its hole
    half-edge along every piece), whichever is asked for first.
    The rings do not wait for the twins: the dual of an open mesh needs
    its rings and boundary only.  ``room``: the buffers ``corners`` and
    ``offsets`` are the first entries of, with room for the dual of its
    dual (:class:`~pentanb.mesh.build.Room`).
    """
    faces = _mesh.faces_only(mesh)
    # the boundary now (a few arrays of p B entries), so that no producer
    # but the rings' holds the input's faces
    chain = chain_of(faces)
    chain_off = chain.shape[1] * _mesh.loop_offsets(faces).astype(np.int64)
    hole = _hole_of(chain, chain_off, corners.size)
    loops = canonical_loops(chain.reshape(-1), chain_off)
    del chain, chain_off
    # the twins may be asked for an iteration later, or never: their
    # producer holds the input's twins and boundary, not all its connectivity
    source = _mesh.faces_keeping(mesh, ("twin", "_boundary"))

    def twin() -> Several:
        return Several(twin=twin_of(source, loops[0], dt), _boundary=loops)

    def rings() -> Several:
        made = rings_of(faces, hole, dt)
        if isinstance(made, Several):  # with the face of every ring entry
            made["_boundary"] = loops
            return made
        return Several(vertex_ring=made, _boundary=loops)

    out = output(vertices, corners, offsets, twin=twin, rings=rings, **kw)
    _mesh.note_boundary(out, lambda: loops)
    if room is not None:
        _mesh.note_room(out, *room)
    return out


def _hole_of(chain: np.ndarray, offsets: np.ndarray, H: int) -> np.ndarray:
    """(B, p) int64: the output's hole half-edge ``H + j`` along every half-edge of
    ``chain`` (its boundary half-edges, loop ``i`` at ``offsets[i]:offsets[i + 1]``
    of the flat chain), ``j`` its place once the loops are put in order as
    :func:`~pentanb.mesh.boundary.canonical_loops` puts them: every loop turned
    to start at its smallest half-edge, loops in the order of those."""
    flat = chain.reshape(-1)
    start, sizes = offsets[:-1], np.diff(offsets)
    least = np.minimum.reduceat(flat, start)
    shift = np.flatnonzero(flat == np.repeat(least, sizes))  # one per loop: half-edges differ
    shift -= start
    order = np.argsort(least, kind="stable")
    first = np.empty(sizes.size, dtype=np.int64)  # where every loop starts in the order
    first[order] = np.cumsum(sizes[order]) - sizes[order]
    first += H
    # the q-th half-edge of loop i goes to first[i] + (q - shift[i]) mod sizes[i]
    q = np.arange(flat.size, dtype=np.int64)
    q -= np.repeat(start + shift, sizes)
    size = np.repeat(sizes, sizes)
    q += size  # (q - shift > -size)
    q %= size
    q += np.repeat(first, sizes)
    return q.reshape(chain.shape)


def _pentagonalized_chain(mesh) -> np.ndarray:
    """(B, 3): the output's boundary half-edges along every boundary half-edge ``b`` of the
    input, in loop order: ``5 prev[b] + 2`` (its first third, on the pentagon of
    ``prev[b]``), ``5b`` and ``5b + 1``."""
    bh = mesh.boundary_halfedges
    chain = np.empty((bh.size, 3), dtype=np.int64)
    chain[:, 0] = 5 * boundary_prev(mesh.offsets, bh, _mesh.uniform_size(mesh)) + 2
    chain[:, 1] = 5 * bh
    chain[:, 2] = chain[:, 1] + 1
    return chain


def _pentagonalized_open_twin(mesh, bh_out: np.ndarray, dt: np.dtype) -> np.ndarray:
    """The twins of ``pentagonalize(mesh)`` for an open ``mesh``.

    As :func:`_pentagonalized_twin` inside; the output's boundary
    half-edges ``bh_out`` (:func:`_pentagonalized_chain`, in loop order)
    paired with its hole half-edges.
    """
    safe = mesh.twin.astype(dt, copy=True)
    safe[mesh.boundary_halfedges] = 0  # (a hole half-edge has no prev: any, written over)
    out = _pentagonalized_twin(safe, mesh.offsets, dt)
    del safe
    return hole_twins(out, bh_out)


def _pentagonalized_open_rings(mesh, hole: np.ndarray, dt: np.dtype) -> Rings:
    """The vertex rings of ``pentagonalize(mesh)`` for an open ``mesh``.

    The rings are :func:`_pentagonalized_rings`', each turned to start at
    its largest half-edge (a boundary vertex's: at its hole half-edge), as
    derived rings do.  On the boundary: round an old vertex, its hole
    half-edge stands for the input's; round the trisection point t1 of a
    boundary half-edge b (near its tail): the hole half-edge, ``5b`` and
    ``5 prev[b] + 3``; round t2 (near its head, a vertex of one face): the
    hole half-edge and ``5b + 1``.  ``hole`` (B, 3): the output's hole
    half-edges along ``5 prev[b] + 2``, ``5b`` and ``5b + 1``.
    """
    H, E, bh = mesh.n_halfedges, mesh.n_edges, mesh.boundary_halfedges
    prv = mesh.prev.astype(dt, copy=False)
    ring, ring_off = mesh.vertex_ring
    eh = mesh.edge_halfedge.astype(dt, copy=False)
    jit = _jit.kernels(5 * H)
    if jit is not None:  # the same rings and offsets, written in one pass
        return jit.pentagonalized_open_rings(
            ring,
            ring_off,
            eh,
            mesh.twin,
            prv,
            mesh.corners,
            mesh.head,
            mesh.offsets,
            hole.reshape(-1),
            dt,
        )
    n, N, B = ring_off.size - 1, ring.size, bh.size
    P = 6 * E - B  # the trisection points' ring entries: 3 each, 2 for t2 of a boundary edge
    rings = np.empty(N + P + H, dtype=dt)  # old vertices, trisection points, centres
    # round an old vertex: 5 prev[h] + 2, the hole half-edge for the input's
    old = rings[:N]
    prv.take(ring, mode="clip", out=old)  # (a hole half-edge: any, written over)
    old *= 5
    old += 2
    hp = np.flatnonzero(ring >= H)
    old[hp] = hole[ring[hp] - H, 2]
    # round the trisection points, 3 each (rows (2, 3) per edge: the edge's
    # points 2e, 2e + 1), every row turned to start at its largest; edge
    # block by edge block, so that the temporaries stay small
    edge_of_b = mesh.halfedge_edge[bh].astype(np.int64)
    order = np.argsort(edge_of_b, kind="stable")  # the boundary edges in edge order
    on_b = edge_of_b[order]
    b = bh[order].astype(np.int64)
    t1 = (mesh.corners[b] > mesh.head[b]).astype(np.int64)  # t1 is 2e + 1 when b runs down
    pb = prv[b].astype(np.int64)
    hole_b = hole[order]
    starts = np.arange(0, E + EDGE_BLOCK, EDGE_BLOCK)
    cut = np.searchsorted(on_b, starts)  # the boundary edges of every block
    for i, a in enumerate(starts[:-1].tolist()):
        z, lo, hi = min(a + EDGE_BLOCK, E), int(cut[i]), int(cut[i + 1])
        h = eh[a:z]
        back = mesh.twin.take(h).astype(dt, copy=False)
        j = on_b[lo:hi] - a  # the block's boundary edges
        back[j] = h[j]  # (their twin is a hole half-edge: any face half-edge, written over)
        pts = np.empty((z - a, 2, 3), dtype=dt)
        for p, parts in enumerate(
            (((h, 0), (prv.take(h), 3), (back, 1)), ((back, 0), (prv.take(back), 3), (h, 1)))
        ):
            cols = []
            for part, add in parts:
                col = part * 5
                col += add
                cols.append(col)
            turned(cols, pts[:, p])
        flat = pts.reshape(-1)
        if hi > lo:  # rows that start at their largest (the hole half-edge)
            up, bb, pp = t1[lo:hi], b[lo:hi], pb[lo:hi]
            pts[j, up, 0] = hole_b[lo:hi, 0]
            pts[j, up, 1] = 5 * bb
            pts[j, up, 2] = 5 * pp + 3
            pts[j, 1 - up, 0] = hole_b[lo:hi, 1]
            pts[j, 1 - up, 1] = 5 * bb + 1
            # t2: two half-edges, its row's last place left out
            written = np.ones(flat.size, dtype=bool)
            written[3 * (2 * j + 1 - up) + 2] = False
            flat = flat[written]
        at = N + 6 * a - lo  # (every boundary edge before a left one place out)
        rings[at : at + flat.size] = flat
    # round the centre of f: 5h + 4 for f's half-edges, from its last (the
    # largest) on: 5 (h - 1) + 4, and 5 (last h) + 4 at its first
    offsets = mesh.offsets
    centres = rings[N + P :]
    centres[:] = np.arange(-1, 5 * H - 1, 5, dtype=dt)
    last = offsets[1:].astype(dt)
    last *= 5
    last -= 1
    centres[offsets[:-1]] = last
    # the trisection points' offsets: 3 places each, less one for every t2
    # of a boundary edge up to there (point 2 on_b + 1 - t1)
    out_off = np.empty(n + 2 * E + mesh.n_faces + 1, dtype=dt)
    out_off[: n + 1] = ring_off
    tri_off = out_off[n + 1 : n + 2 * E + 1]
    t2 = np.sort(2 * on_b + 1 - t1)
    tri_off[...] = running_sum(t2, np.ones(t2.size, dtype=dt), 2 * E, dt)
    np.subtract(np.arange(3, 6 * E + 1, 3, dtype=dt), tri_off, out=tri_off)
    tri_off += ring_off[-1]
    out_off[n + 2 * E + 1 :] = offsets[1:]
    out_off[n + 2 * E + 1 :] += out_off[n + 2 * E]
    return rings, out_off


def _pentagonalized_rings(mesh, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """The vertex rings of ``pentagonalize(mesh)``, written from ``mesh``'s.

    Half-edge ``5h + s`` is slot ``s`` of the pentagon of ``h``.  Around an
    old vertex v: ``5 prev[h] + 2`` for v's outgoing h, in v's order; around
    the trisection point t1(h): ``5h, 5 prev[h] + 3, 5 twin[h] + 1``; around
    the centre of f: ``5h + 4`` for f's half-edges in face order.  The
    trisection point ``2e`` is t1 of edge e's forward half-edge, ``2e + 1``
    of its twin.
    """
    twin = mesh.twin.astype(dt, copy=False)
    ring, ring_off = mesh.vertex_ring
    H, n = mesh.n_halfedges, ring_off.size - 1
    offsets = np.empty(n + H + mesh.n_faces + 1, dtype=dt)
    offsets[: n + 1] = ring_off
    offsets[n + 1 : n + H + 1] = np.arange(H + 3, 4 * H + 1, 3, dtype=dt)
    offsets[n + H + 1 :] = mesh.offsets[1:]
    offsets[n + H + 1 :] += 4 * H
    eh = mesh.edge_halfedge.astype(dt, copy=False)
    jit = _jit.kernels(5 * H)
    if jit is not None:  # the same rings, written in one pass
        prv = mesh.prev.astype(dt, copy=False)
        return jit.pentagonalized_rings(ring.astype(dt, copy=False), eh, twin, prv), offsets
    # prev[h] from the offsets: an arange and one scatter, then plain gathers
    # (cheaper than mesh.prev's cache, and than h - 1 fixed at every first corner)
    prv = prev_of(mesh.offsets, H, dt)
    out = np.empty(5 * H, dtype=dt)
    old = out[:H]
    old[:] = prv[ring]
    old *= 5
    old += 2
    back = twin[eh]
    h = np.empty(H, dtype=dt)  # the half-edge of every trisection point
    h[0::2] = eh
    h[1::2] = back
    across = np.empty(H, dtype=dt)  # twin[h]: back for eh, eh for back
    across[0::2] = back
    across[1::2] = eh
    del back
    tri = out[H : 4 * H].reshape(H, 3)
    for s, part in enumerate((h, prv[h], across)):
        col = part * 5
        col += (0, 3, 1)[s]
        tri[:, s] = col
    centre = out[4 * H :]
    centre[:] = np.arange(4, 5 * H, 5, dtype=dt)
    return out, offsets


@scale_safe
def preserve_pentagons(mesh: Mesh, scale: float = 0.75) -> Mesh:
    """Pentagon preservation, Section 5.2 steps 1-3, Figure 10.

    1. Every edge is cut at its midpoint.
    2. For every face, the midpoints of its edges are scaled by ``scale``
       about their mean, giving a smaller copy of the face.
    3. Each vertex of the copy is joined to its midpoint.

    Every n-gon becomes one n-gon (the copy) and n pentagons, so a
    pentagonal mesh stays pentagonal.  Conway's *quinto* when ``scale=0.5``.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces; open meshes too (B boundary edges).
    scale : float in (0, 1)
        Size of the inner copy relative to the polygon of edge midpoints.

    Returns
    -------
    Mesh
        V + 3E vertices, 6E edges, F + 2E faces (open: V + 3E - B vertices,
        6E - 2B edges, F + 2E - B faces, 2B boundary edges): the F inner copies (same
        sizes and order as the input's faces) followed by one pentagon per
        half-edge ``h = (u, w)``: ``(m_h, w, m_next, q_next, q_h)``.
        Vertices: old vertices, edge midpoints (``V + e``), then one copy
        vertex per half-edge (``V + E + h``).
    """
    check_mesh(mesh, "preserve_pentagons")
    s = check_scale(scale)
    n, E, H, F = mesh.n_vertices, mesh.n_edges, mesh.n_halfedges, mesh.n_faces
    dt = index_dtype(n + E + H, 6 * H)
    vertices = np.empty((n + E + H, 3))
    vertices[:n] = mesh.vertices
    edge_points(mesh, 1, out=vertices[n : n + E])
    mid = mesh.halfedge_edge.astype(dt)
    mid += n
    # the copies: every face's edge midpoints scaled about their mean
    copies, offsets, sizes = vertices[n + E :], mesh.offsets, mesh.face_sizes
    jit = _jit.kernels(H) if int(sizes.max()) <= 129 else None
    if jit is not None:  # the same sums and products, compiled
        jit.scaled_copies(vertices, mid, offsets, s, copies)
    for a in range(0, 0 if jit is not None else F, BLOCK):
        o = offsets[a : a + BLOCK + 1]
        lo, hi = int(o[0]), int(o[-1])
        p = vertices.take(mid[lo:hi], axis=0)
        centre = np.add.reduceat(p, o[:-1] - lo, axis=0) / sizes[a : a + BLOCK, None]
        centre = np.repeat(centre, sizes[a : a + BLOCK], axis=0)
        p -= centre
        p *= s
        np.add(centre, p, out=copies[lo:hi])
        del p, centre  # (a block's temporaries: gone before the next allocations)
    B_out = 0 if mesh.is_closed else 2 * mesh.boundary_halfedges.size  # (room: dual's dual)
    faces_jit = _jit.kernels(6 * H)
    if faces_jit is not None:  # the same corners, written in one pass
        buffer = faces_jit.preserved_faces(mid, mesh.head, mesh.next, n + E, ROOM_CORNERS * B_out)
        corners = buffer[: 6 * H]
    else:
        buffer = with_room(6 * H, B_out, ROOM_CORNERS, dt)
        corners = buffer[: 6 * H]
        corners[:H] = np.arange(n + E, n + E + H, dtype=dt)  # the copies, face by face
        pentagons = corners[H:].reshape(H, 5)
        nxt = mesh.next
        pentagons[:, 0] = mid
        pentagons[:, 1] = mesh.head
        pentagons[:, 2] = mid[nxt]
        np.add(nxt, n + E, out=pentagons[:, 3])
        pentagons[:, 4] = corners[:H]
    offsets_buffer = with_room(F + H + 1, B_out, ROOM_OFFSETS, dt)
    face_offsets = offsets_buffer[: F + H + 1]
    face_offsets[: F + 1] = offsets
    face_offsets[F + 1 :] = np.arange(H + 5, 6 * H + 1, 5, dtype=dt)
    # the face sizes: the input's (the copies) and H pentagons
    histogram = dict(_mesh.size_counts(mesh))
    histogram[5] = histogram.get(5, 0) + H
    counts = tuple(sorted(histogram.items()))
    if not mesh.is_closed:  # its twins, boundary and rings written from the input's, apart
        return _open_output(
            mesh,
            vertices,
            corners,
            face_offsets,
            dt,
            _preserved_chain,
            _preserved_open_twin,
            _preserved_open_rings,
            room=(buffer, offsets_buffer),
            size_counts=counts,
        )
    return remeshed(
        mesh, vertices, corners, face_offsets, dt, _preserved_twin, _preserved_rings, counts
    )


def _preserved_twin(mesh, dt: np.dtype) -> np.ndarray:
    """The twins of ``preserve_pentagons(mesh)``, from ``mesh``'s faces.

    Half-edge h (< H) is the copy's edge ``q_h -> q_next``; ``H + 5h + s``
    is slot s of the pentagon of h, ``(m_h, w, m_next, q_next, q_h)``.  Twins:
    ``h`` and ``H + 5h + 3``; ``H + 5h`` and ``H + 5 prev[twin[h]] + 1``;
    ``H + 5h + 2`` and ``H + 5 next[h] + 4``.
    """
    return _preserved_twin_of(mesh.twin, mesh.next, mesh.prev, dt)


def _preserved_chain(mesh) -> np.ndarray:
    """(B, 2): the output's boundary half-edges along every boundary half-edge ``b`` of the
    input, in loop order: ``H + 5 prev[b] + 1`` (its first half, on the pentagon of
    ``prev[b]``) and ``H + 5b``."""
    H, bh = mesh.n_halfedges, mesh.boundary_halfedges
    chain = np.empty((bh.size, 2), dtype=np.int64)
    chain[:, 0] = H + 5 * boundary_prev(mesh.offsets, bh, _mesh.uniform_size(mesh)) + 1
    chain[:, 1] = H + 5 * bh.astype(np.int64)
    return chain


def _preserved_open_twin(mesh, bh_out: np.ndarray, dt: np.dtype) -> np.ndarray:
    """The twins of ``preserve_pentagons(mesh)`` for an open ``mesh``.

    As :func:`_preserved_twin` inside; the output's boundary half-edges
    ``bh_out`` (:func:`_preserved_chain`, in loop order) paired with its
    hole half-edges.
    """
    safe = mesh.twin.astype(dt, copy=True)
    safe[mesh.boundary_halfedges] = 0  # (a hole half-edge has no prev: any, written over)
    out = _preserved_twin_of(safe, mesh.next, mesh.prev, dt)
    del safe
    return hole_twins(out, bh_out)


def _preserved_open_rings(mesh, hole: np.ndarray, dt: np.dtype) -> Rings | Several:
    """The vertex rings of ``preserve_pentagons(mesh)`` for an open ``mesh``.

    The rings are :func:`_preserved_rings`', each turned to start at its
    largest half-edge (a boundary vertex's: at its hole half-edge), as
    derived rings do.  On the boundary: round an old vertex, its hole
    half-edge stands for the input's; round the midpoint of a boundary
    half-edge b: the hole half-edge, ``H + 5b`` and ``H + 5 prev[b] + 2``.
    ``hole`` (B, 2): the output's hole half-edges along ``H + 5 prev[b] + 1``
    and ``H + 5b``.
    """
    H, E, bh = mesh.n_halfedges, mesh.n_edges, mesh.boundary_halfedges
    prv = mesh.prev.astype(dt, copy=False)
    ring, ring_off = mesh.vertex_ring
    eh = mesh.edge_halfedge.astype(dt, copy=False)
    jit = _jit.kernels(6 * H)
    if jit is not None:  # the same rings and offsets, written in one pass, with
        # the face of every ring entry (the open dual's corners but at the
        # boundary), as the closed kernels write them
        face_in = mesh.halfedge_face.astype(dt, copy=False)
        rings, offsets, faces = jit.preserved_open_rings(
            ring, ring_off, eh, mesh.twin, prv, hole.reshape(-1), face_in, mesh.n_faces, dt
        )
        return Several(vertex_ring=(rings, offsets), _ring_faces=faces)
    n = ring_off.size - 1
    # round an old vertex: H + 5 prev[h] + 1, the hole half-edge for the input's
    old = prv.take(ring, mode="clip")  # (a hole half-edge: any, written over)
    old *= 5
    old += H + 1
    hp = np.flatnonzero(ring >= H)
    old[hp] = hole[ring[hp] - H, 1]
    # round the midpoints, 4 each (3 on the boundary)
    back = mesh.twin[eh].astype(dt, copy=False)  # (a new array: written below)
    edge_of_b = mesh.halfedge_edge[bh].astype(np.int64)
    back[edge_of_b] = eh[edge_of_b]  # (any face half-edge: written over below)
    mids = np.empty((E, 4), dtype=dt)
    _midpoint_rings(mids, eh, back, prv, H)
    b = bh.astype(np.int64)
    pb = prv[bh].astype(np.int64)
    mids[edge_of_b, 0] = hole[:, 0]
    mids[edge_of_b, 1] = H + 5 * b
    mids[edge_of_b, 2] = H + 5 * pb + 2
    mids[edge_of_b, 3] = -1  # three half-edges
    mid_ring = np.delete(start_at_max(mids.reshape(-1), None, 4), 4 * edge_of_b + 3)
    # round the copy vertex of h: h, H + 5 prev[h] + 3, H + 5h + 4
    copies = _copy_rings(prv, H, dt)
    sizes = np.full(E, 4, dtype=dt)
    sizes[edge_of_b] = 3
    out_off = np.empty(n + E + H + 1, dtype=dt)
    out_off[: n + 1] = ring_off
    np.cumsum(sizes, out=out_off[n + 1 : n + E + 1])
    out_off[n + 1 : n + E + 1] += ring_off[-1]
    out_off[n + E + 1 :] = np.arange(3, 3 * H + 1, 3, dtype=dt)
    out_off[n + E + 1 :] += out_off[n + E]
    rings = np.concatenate([old, mid_ring, start_at_max(copies.reshape(-1), None, 3)])
    return rings, out_off


def _preserved_twin_of(twin: np.ndarray, nxt: np.ndarray, prv: np.ndarray, dt: np.dtype):
    """:func:`_preserved_twin` from the input's twins, next and prev."""
    H = twin.size
    nxt, prv = nxt.astype(dt, copy=False), prv.astype(dt, copy=False)
    twin = twin.astype(dt, copy=False)
    out = np.empty(6 * H, dtype=dt)
    out[:H] = np.arange(H + 3, 6 * H, 5, dtype=dt)
    pent = out[H:].reshape(H, 5)
    for s, (part, add) in enumerate(
        ((prv[twin], 1), (twin[nxt], 0), (nxt, 4), (None, 0), (prv, 2))
    ):
        if part is None:
            pent[:, s] = np.arange(H, dtype=dt)
            continue
        col = part * 5
        col += H + add
        pent[:, s] = col
    return out


def _preserved_rings(mesh, dt: np.dtype) -> Rings | Several:
    """The vertex rings of ``preserve_pentagons(mesh)``, from ``mesh``'s.

    Around an old vertex: ``H + 5 prev[h] + 1`` for its outgoing h, in its
    order; around the midpoint of edge e (forward half-edge h):
    ``H + 5h, H + 5 prev[h] + 2, H + 5 twin[h], H + 5 prev[twin[h]] + 2``;
    around the copy vertex of h: ``h, H + 5 prev[h] + 3, H + 5h + 4``.  Each
    ring then starts at its largest half-edge, as derived rings do.
    """
    H, E = mesh.n_halfedges, mesh.n_edges
    ring, ring_off = mesh.vertex_ring
    n = ring_off.size - 1
    offsets = np.empty(n + E + H + 1, dtype=dt)
    offsets[: n + 1] = ring_off
    offsets[n + 1 : n + E + 1] = np.arange(H + 4, H + 4 * E + 1, 4, dtype=dt)
    offsets[n + E + 1 :] = np.arange(H + 4 * E + 3, H + 4 * E + 3 * H + 1, 3, dtype=dt)
    prv, twin = mesh.prev.astype(dt, copy=False), mesh.twin.astype(dt, copy=False)
    eh = mesh.edge_halfedge.astype(dt, copy=False)
    jit = _jit.kernels(6 * H)
    if jit is not None:  # the same rings, each written turned, in one pass,
        # with the face of every ring entry (the dual's corners), from the
        # numbering, without the output's face of every half-edge
        face_in = mesh.halfedge_face.astype(dt, copy=False)
        rings, faces = jit.preserved_rings(
            ring.astype(dt, copy=False), ring_off, eh, twin, prv, face_in, mesh.n_faces
        )
        return Several(vertex_ring=(rings, offsets), _ring_faces=faces)
    old = prv[ring] * 5
    old += H + 1
    back = twin[eh]
    mids = np.empty((E, 4), dtype=dt)
    _midpoint_rings(mids, eh, back, prv, H)
    copies = _copy_rings(prv, H, dt)
    rings = np.concatenate(
        [
            start_at_max(old, ring_off),
            start_at_max(mids.reshape(-1), None, 4),
            start_at_max(copies.reshape(-1), None, 3),
        ]
    )
    return rings, offsets
