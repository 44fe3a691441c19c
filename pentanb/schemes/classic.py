"""The remeshings the paper compares its schemes with (Sections 3 and 6).

Each works on any polygon mesh, closed or open, keeps the Euler characteristic, and
is a pure remeshing: old vertices (where kept) do not move and new ones are
placed by simple affine rules.

=====================  ===========================  ==================  =========
function               paper                        V, E, F after       Conway
=====================  ===========================  ==================  =========
``triangulate``        Figure 2, simplest           V+F', E+s', F-F'+s'  --
``loop_remesh``        Figure 3, Loop's remeshing   V+E, 4E, F+2E       subdivide
``sqrt3_remesh``       sqrt(3) (triangulization)    V+F, 3E, 2E         --
``vertex_insertion``   Catmull-Clark's remeshing    V+E+F, 4E, 2E       ortho
``corner_cutting``     Doo-Sabin's remeshing        2E, 4E, V+E+F       expand
``preserve_hexagons``  dual of Loop, Figures 4-5    V+2E, 4E, F+E       chamfer
``honeycomb``          dual of sqrt(3), Figure 13   2E, 3E, V+F         zip
=====================  ===========================  ==================  =========

(For ``triangulate``, F' counts the non-triangles and s' their sides.)

Open meshes (B boundary edges, C corners: boundary vertices of one face)
are remeshed face by face as closed ones; what a boundary edge becomes:

* ``loop_remesh``, ``vertex_insertion``: split at its midpoint, as every edge;
* ``triangulate``: kept;
* ``sqrt3_remesh``: kept, and the triangle ``(u, w, c_f)`` takes the place of
  the flipped edge's two (no edge to flip across the boundary), as in
  Kobbelt's sqrt(3) at a boundary step that does not split it;
* ``corner_cutting``: two points, ``m + scale (u - m)`` and
  ``m + scale (w - m)`` about its midpoint m (a quarter from each end for
  the default scale: Chaikin's corner cutting, Doo-Sabin's boundary rule),
  and a quad between them and its face's copy; every boundary vertex's
  face is closed through them (and through the vertex at a corner);
* ``preserve_hexagons``: cut in three, so that its hexagon
  ``(k_bf, k_af, a, t1, t2, b)`` stays a hexagon;
* ``honeycomb``: its midpoint, joined to the point of its half-edge; every
  boundary vertex's face is closed through the midpoints of its two
  boundary edges (and through the vertex at a corner), as the dual's.

Corners (boundary vertices of one face where the boundary turns by more
than 30 degrees, :func:`~pentanb.schemes._build.boundary_corners`) are kept
by the schemes that make a face of every vertex, as by the dual
(:mod:`pentanb.schemes.smoothing`).

The registry (:data:`pentanb.SCHEMES`) gives every scheme's counts with
these boundary terms.
"""

from __future__ import annotations

import numpy as np

from .. import _jit
from ..mesh import Mesh
from ..mesh import build as _mesh
from ._build import (
    affine,
    check_mesh,
    check_scale,
    check_vertex_faces,
    columns,
    corner_ids,
    edge_points,
    fixed_size,
    index_dtype,
    inverse,
    open_vertex_faces,
    output,
    remeshed,
    scale_safe,
    start_at_max,
)

__all__ = [
    "triangulate",
    "loop_remesh",
    "sqrt3_remesh",
    "vertex_insertion",
    "corner_cutting",
    "preserve_hexagons",
    "honeycomb",
]


@scale_safe
def triangulate(mesh: Mesh) -> Mesh:
    """The simplest triangulation of Figure 2: a centroid fan in every non-triangle.

    Triangles are kept as they are, so a second application changes nothing:
    the paper leaves this remeshing out because "after the first iteration it
    does not change the mesh (i.e., it becomes null algorithm)".

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).

    Returns
    -------
    Mesh
        The input's vertices, then one centroid per non-triangular face.
        Faces: the input's triangles (in order), then one triangle
        ``(u, w, c_f)`` per half-edge of each non-triangle.
    """
    check_mesh(mesh, "triangulate")
    n = mesh.n_vertices
    big = mesh.face_sizes > 3
    if not big.any():
        return mesh
    big_faces = np.flatnonzero(big)
    dt = index_dtype(n + big_faces.size, 3 * mesh.n_halfedges)
    centre_id = np.full(mesh.n_faces, -1, dtype=dt)
    centre_id[big_faces] = np.arange(n, n + big_faces.size, dtype=dt)
    hf = mesh.halfedge_face
    hb = np.flatnonzero(big[hf])
    fans = np.stack([mesh.corners[hb], mesh.head[hb], centre_id[hf[hb]]], axis=1)
    kept = mesh.corners[~big[hf]].reshape(-1, 3)
    corners, offsets = fixed_size(np.concatenate([kept, fans]))
    vertices = np.concatenate([mesh.vertices, mesh.face_centroids[big_faces]])
    return output(vertices, corners, offsets, closed=mesh.is_closed)


@scale_safe
def loop_remesh(mesh: Mesh) -> Mesh:
    """Loop's remeshing (Figure 3): a triangle-preserving scheme on any mesh.

    "We first subdivide every edge at its midpoint and connect these
    midpoints to create a central face in the middle of each original face
    and triangles in each corner."

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).

    Returns
    -------
    Mesh
        V + E vertices (old, then edge midpoints), 4E edges, F + 2E faces:
        the central faces (one n-gon per n-gon) then the corner triangles
        ``(m_h, w, m_next)``.
    """
    check_mesh(mesh, "loop_remesh")
    n, E, H = mesh.n_vertices, mesh.n_edges, mesh.n_halfedges
    dt = index_dtype(n + E, 4 * H)
    mid = affine(mesh.halfedge_edge, 1, n, dt)
    corners = np.empty(4 * H, dtype=dt)
    corners[:H] = mid
    corners[H:].reshape(H, 3)[:] = columns(dt, H, mid, mesh.head, mid[mesh.next])
    offsets = np.concatenate([mesh.offsets, np.arange(H + 3, 4 * H + 1, 3, dtype=dt)])
    vertices = np.empty((n + E, 3))
    vertices[:n] = mesh.vertices
    edge_points(mesh, 1, out=vertices[n:])
    return remeshed(mesh, vertices, corners, offsets, dt, _loop_twin, _loop_rings)


def _loop_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``loop_remesh``: central h and ``H + 3h + 2``; ``H + 3h`` and
    ``H + 3 prev[twin[h]] + 1``."""
    H = m.n_halfedges
    nxt, prv, twin = m.next, m.prev, m.twin
    tri = columns(
        dt, H, affine(prv[twin], 3, H + 1, dt), affine(twin[nxt], 3, H, dt), np.arange(H, dtype=dt)
    )
    return np.concatenate([np.arange(H + 2, 4 * H, 3, dtype=dt), tri.reshape(-1)])


def _loop_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``loop_remesh``: old vertex ``H + 3 prev[h] + 1`` for its h; midpoint
    of edge e (forward h, twin t):
    ``H + 3h, h, H + 3 prev[h] + 2, H + 3t, t, H + 3 prev[t] + 2``."""
    H, E = m.n_halfedges, m.n_edges
    prv, twin = m.prev, m.twin
    ring, ring_off = m.vertex_ring
    h = m.edge_halfedge
    t = twin[h]
    mids = columns(
        dt,
        E,
        affine(h, 3, H, dt),
        h,
        affine(prv[h], 3, H + 2, dt),
        affine(t, 3, H, dt),
        t,
        affine(prv[t], 3, H + 2, dt),
    )
    rings = np.concatenate(
        [
            start_at_max(affine(prv[ring], 3, H + 1, dt), ring_off),
            start_at_max(mids.reshape(-1), None, 6),
        ]
    )
    offsets = np.concatenate([ring_off, np.arange(H + 6, H + 6 * E + 1, 6, dtype=dt)])
    return rings, offsets


@scale_safe
def sqrt3_remesh(mesh: Mesh) -> Mesh:
    """The remeshing of sqrt(3) subdivision: a centroid fan, then every old edge flipped.

    A triangulization (conversion) scheme: the result is all triangles.

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).

    Returns
    -------
    Mesh
        V + F vertices (old, then centroids), 3E edges, 2E triangles
        ``(u, c_g, c_f)`` for every half-edge ``h = (u, w)`` of face f whose
        twin lies in face g.
    """
    check_mesh(mesh, "sqrt3_remesh")
    n, F, H = mesh.n_vertices, mesh.n_faces, mesh.n_halfedges
    dt = index_dtype(n + F, 3 * H)
    c = affine(mesh.halfedge_face, 1, n, dt)
    if mesh.is_closed:
        tris = columns(dt, H, mesh.corners, c[mesh.twin], c)
    else:  # a boundary half-edge (u, w) of f keeps its edge: (u, w, c_f)
        twin = mesh.twin
        across = np.where(twin < H, c[np.minimum(twin, H - 1)], mesh.head.astype(dt))
        tris = columns(dt, H, mesh.corners, across, c)
    corners, offsets = fixed_size(tris)
    vertices = np.empty((n + F, 3))
    vertices[:n] = mesh.vertices
    vertices[n:] = mesh.face_centroids
    return remeshed(mesh, vertices, corners, offsets, dt, _sqrt3_twin, _sqrt3_rings)


def _sqrt3_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``sqrt3_remesh``: ``3h`` and ``3 next[twin[h]] + 2``; ``3h + 1`` and
    ``3 twin[h] + 1``; ``3h + 2`` and ``3 twin[prev[h]]``."""
    H = m.n_halfedges
    twin = m.twin
    return columns(
        dt, H, affine(m.next[twin], 3, 2, dt), affine(twin, 3, 1, dt), affine(m.rotation, 3, 0, dt)
    ).reshape(-1)


def _sqrt3_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``sqrt3_remesh``: old vertex ``3h`` for its h; centroid of f
    ``3h + 2, 3 twin[h] + 1`` for f's half-edges in order."""
    H = m.n_halfedges
    ring, ring_off = m.vertex_ring
    centre = columns(dt, H, np.arange(2, 3 * H, 3, dtype=dt), affine(m.twin, 3, 1, dt))
    rings = np.concatenate(
        [
            start_at_max(affine(ring, 3, 0, dt), ring_off),
            start_at_max(centre.reshape(-1), 2 * m.offsets.astype(np.int64)),
        ]
    )
    offsets = np.concatenate([ring_off, H + 2 * m.offsets[1:].astype(dt)])
    return rings, offsets


@scale_safe
def vertex_insertion(mesh: Mesh) -> Mesh:
    """Catmull-Clark's remeshing (vertex insertion), a quadrilateralization.

    A point on every edge midpoint and at every face centroid; every n-gon
    becomes n quads ``(m_h, w, m_next, c_f)``.

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).

    Returns
    -------
    Mesh
        V + E + F vertices (old, midpoints, centroids), 4E edges, 2E quads.
    """
    check_mesh(mesh, "vertex_insertion")
    n, E, F, H = mesh.n_vertices, mesh.n_edges, mesh.n_faces, mesh.n_halfedges
    dt = index_dtype(n + E + F, 4 * H)
    mid = affine(mesh.halfedge_edge, 1, n, dt)
    quads = columns(dt, H, mid, mesh.head, mid[mesh.next], affine(mesh.halfedge_face, 1, n + E, dt))
    corners, offsets = fixed_size(quads)
    vertices = np.empty((n + E + F, 3))
    vertices[:n] = mesh.vertices
    edge_points(mesh, 1, out=vertices[n : n + E])
    vertices[n + E :] = mesh.face_centroids
    return remeshed(mesh, vertices, corners, offsets, dt, _insertion_twin, _insertion_rings)


def _insertion_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``vertex_insertion``: ``4h`` and ``4 prev[twin[h]] + 1``; ``4h + 2``
    and ``4 next[h] + 3``."""
    H = m.n_halfedges
    nxt, prv, twin = m.next, m.prev, m.twin
    return columns(
        dt,
        H,
        affine(prv[twin], 4, 1, dt),
        affine(twin[nxt], 4, 0, dt),
        affine(nxt, 4, 3, dt),
        affine(prv, 4, 2, dt),
    ).reshape(-1)


def _insertion_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``vertex_insertion``: old vertex ``4 prev[h] + 1``; midpoint of e
    (forward h, twin t) ``4h, 4 prev[h] + 2, 4t, 4 prev[t] + 2``; centroid of f
    ``4h + 3`` for f's half-edges in order."""
    H, E = m.n_halfedges, m.n_edges
    prv, twin = m.prev, m.twin
    ring, ring_off = m.vertex_ring
    h = m.edge_halfedge
    t = twin[h]
    mids = columns(
        dt,
        E,
        affine(h, 4, 0, dt),
        affine(prv[h], 4, 2, dt),
        affine(t, 4, 0, dt),
        affine(prv[t], 4, 2, dt),
    )
    rings = np.concatenate(
        [
            start_at_max(affine(prv[ring], 4, 1, dt), ring_off),
            start_at_max(mids.reshape(-1), None, 4),
            start_at_max(np.arange(3, 4 * H, 4, dtype=dt), m.offsets),
        ]
    )
    offsets = np.concatenate(
        [ring_off, np.arange(H + 4, H + 4 * E + 1, 4, dtype=dt), 3 * H + m.offsets[1:].astype(dt)]
    )
    return rings, offsets


def _corner_points(mesh: Mesh, scale: float) -> np.ndarray:
    """One point per half-edge: its tail pulled towards its face's centroid.

    ``c_f + scale * (v - c_f)``.
    """
    v, centres = mesh.vertices, mesh.face_centroids
    jit = _jit.kernels(mesh.n_halfedges)
    if jit is not None and v.flags.c_contiguous:  # the same sums, one pass, no temporaries
        return jit.corner_points(v, mesh.corners, centres, mesh.halfedge_face, float(scale))
    c = centres[mesh.halfedge_face]
    return c + scale * (v[mesh.corners] - c)


@scale_safe
def corner_cutting(mesh: Mesh, scale: float = 0.5) -> Mesh:
    """Doo-Sabin's remeshing (corner cutting), the dual of vertex insertion.

    Every corner (v, f) gets a new point ``c_f + scale * (v - c_f)``; every
    face gives a smaller copy of itself, every edge a quad and every vertex
    a k-gon.  After one application every vertex is 4-valent.

    Parameters
    ----------
    scale : float in (0, 1)

    Returns
    -------
    Mesh
        2E vertices (one per half-edge, at its tail), 4E edges, F + E + V
        faces: face copies, edge quads, then vertex faces.

    Raises
    ------
    MeshError
        A vertex with fewer than 3 edges (only ``Mesh.from_csr(...,
        validate=False)`` builds one): its vertex face would not be a polygon.
    """
    check_mesh(mesh, "corner_cutting")
    s = check_scale(scale)
    check_vertex_faces(mesh, "corner_cutting")
    if not mesh.is_closed:
        return _open_corner_cutting(mesh, s)
    H, E = mesh.n_halfedges, mesh.n_edges
    dt = index_dtype(H, 4 * H)
    nxt, twin = mesh.next, mesh.twin
    eh = mesh.edge_halfedge
    t = twin[eh]
    quads = columns(dt, E, nxt[eh], eh, nxt[t], t)
    ring, ring_off = mesh.vertex_ring
    corners = np.concatenate([np.arange(H, dtype=dt), quads.reshape(-1), ring.astype(dt)])
    offsets = np.concatenate(
        [mesh.offsets, np.arange(H + 4, 3 * H + 1, 4, dtype=dt), 3 * H + ring_off[1:].astype(dt)]
    )
    points = _corner_points(mesh, s)
    return remeshed(mesh, points, corners, offsets, dt, _cutting_twin, _cutting_rings)


def _open_corner_cutting(mesh: Mesh, s: float) -> Mesh:
    """Corner cutting of an open mesh (numpy; twins and rings derived when asked for).

    Points: the H corner points, two per boundary edge ``bh[j]`` (``H +
    2j`` near its tail, ``H + 2j + 1`` near its head, at ``scale`` about
    its midpoint), then the boundary's corners, kept.  Faces: the copies, one
    quad per edge in edge order (a boundary edge's: ``(next h, h, near
    tail, near head)``), one face per vertex (:func:`open_vertex_faces`).
    """
    H, E = mesh.n_halfedges, mesh.n_edges
    bh = mesh.boundary_halfedges
    B = bh.size
    keep, at = corner_ids(mesh, H + 2 * B)
    nxt, twin = mesh.next.astype(np.int64), mesh.twin.astype(np.int64)
    eh = mesh.edge_halfedge.astype(np.int64)
    t = twin[eh]
    inner = t < H
    slot = np.full(H, -1, dtype=np.int64)  # j of every boundary half-edge
    slot[bh] = np.arange(B)
    jb = slot[eh[~inner]]
    quads = np.empty((E, 4), dtype=np.int64)
    quads[:, 0] = nxt[eh]
    quads[:, 1] = eh
    quads[inner, 2] = nxt[t[inner]]
    quads[inner, 3] = t[inner]
    quads[~inner, 2] = H + 2 * jb
    quads[~inner, 3] = H + 2 * jb + 1
    h = np.arange(H, dtype=np.int64)
    near_tail = H + 2 * np.arange(B, dtype=np.int64)
    faces, face_off = open_vertex_faces(mesh, (h,), near_tail + 1, near_tail, keep)
    corners = np.concatenate([h, quads.reshape(-1), faces])
    offsets = np.concatenate(
        [mesh.offsets, np.arange(H + 4, H + 4 * E + 1, 4), H + 4 * E + face_off[1:]]
    )
    v = mesh.vertices
    points = np.empty((H + 2 * B + at.size, 3))
    points[:H] = _corner_points(mesh, s)
    a, b = v[mesh.corners[bh]], v[mesh.head[bh]]
    mid = 0.5 * a + 0.5 * b
    points[H : H + 2 * B : 2] = mid + s * (a - mid)
    points[H + 1 : H + 2 * B : 2] = mid + s * (b - mid)
    points[H + 2 * B :] = v[at]
    return output(points, corners, offsets)


def _edge_slot(m, h: np.ndarray, per: int, forward: int, backward: int, dt: np.dtype) -> np.ndarray:
    """``H + per edge[h] + (forward if h is its edge's forward half-edge else backward)``:
    the corner of a face made for every edge (``per`` corners each, after the H
    copied ones)."""
    col = affine(m.halfedge_edge[h], per, m.n_halfedges + backward, dt)
    if forward != backward:  # (one byte per half-edge, not a where() of ints)
        col += _mesh.forward(m)[h].view(np.int8) * np.int8(forward - backward)
    return col


def _quad_slot(m, h: np.ndarray, forward: int, backward: int, dt: np.dtype) -> np.ndarray:
    """The corner of the quad of ``h``'s edge (see :func:`_edge_slot`)."""
    return _edge_slot(m, h, 4, forward, backward, dt)


def _cutting_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``corner_cutting``.  Copy h and the quad of its edge (slot 0 for
    the forward half-edge, 2 for the other); quad slots 1 and 3 and the vertex
    faces: slot 1 of edge (h, t) is the twin of the vertex-face half-edge at
    ``next[t]``, slot 3 of that at ``next[h]``."""
    H = m.n_halfedges
    nxt, twin = m.next, m.twin
    ring, _ = m.vertex_ring
    pos = inverse(ring)
    eh = m.edge_halfedge
    t = twin[eh]
    h_all = np.arange(H, dtype=dt)
    copies = _quad_slot(m, h_all, 0, 2, dt)
    quads = columns(
        dt, eh.size, eh, affine(pos[nxt[t]], 1, 3 * H, dt), t, affine(pos[nxt[eh]], 1, 3 * H, dt)
    )
    faces = _quad_slot(m, m.rotation[ring], 1, 3, dt)
    return np.concatenate([copies, quads.reshape(-1), faces])


def _cutting_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``corner_cutting``: the point of h, ``3H + pos[h]``, its edge's
    quad (slot 1 forward, 3 backward), h's copy, the quad of prev[h]'s edge
    (slot 0 forward, 2 backward)."""
    H = m.n_halfedges
    ring, _ = m.vertex_ring
    pos = inverse(ring.astype(dt, copy=False))
    jit = _jit.kernels(4 * H)
    if jit is not None:  # the same rings, written in one pass
        edge, prv = m.halfedge_edge.astype(dt, copy=False), m.prev.astype(dt, copy=False)
        rings = jit.cutting_rings(pos, edge, _mesh.forward(m), prv)
        return rings, np.arange(0, 4 * H + 1, 4, dtype=dt)
    h = np.arange(H, dtype=dt)
    rings = columns(
        dt,
        H,
        affine(pos, 1, 3 * H, dt),
        _quad_slot(m, h, 1, 3, dt),
        h,
        _quad_slot(m, m.prev, 0, 2, dt),
    )
    return rings.reshape(-1), np.arange(0, 4 * H + 1, 4, dtype=dt)


@scale_safe
def preserve_hexagons(mesh: Mesh, scale: float = 0.5) -> Mesh:
    """Hexagon preservation: the dual of Loop's remeshing (Conway's chamfer).

    Figures 4-5: applied to a (6, 3) mesh (all hexagons, 3-valent vertices)
    it gives a (6, 3) mesh again.  The old vertices stay; every face gets a
    smaller copy (corner ``(v, f)`` at ``c_f + scale * (v - c_f)``); every
    old edge ``(a, b)`` becomes a hexagon between the copies of its two
    faces; each old vertex is joined to its copies.

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).
    scale : float in (0, 1)
        Size of every face's copy, relative to the face, about its centroid.

    Returns
    -------
    Mesh
        V + 2E vertices (old, then one per half-edge), 4E edges, F + E faces:
        face copies (same sizes) then one hexagon per edge.  The same
        topology as ``dual(loop_remesh(dual(mesh)))``.
    """
    check_mesh(mesh, "preserve_hexagons")
    s = check_scale(scale)
    if not mesh.is_closed:
        return _open_hexagons(mesh, s)
    n, H = mesh.n_vertices, mesh.n_halfedges
    dt = index_dtype(n + 2 * mesh.n_edges, 4 * H)
    k = np.arange(n, n + H, dtype=dt)
    nxt, twin, tail = mesh.next, mesh.twin, mesh.corners
    h = mesh.edge_halfedge
    g = twin[h]
    # h = (a, b) in face f, g = (b, a) in face g:
    # hexagon (k(b,f), k(a,f), a, k(a,g), k(b,g), b)
    hexagons = columns(dt, h.size, k[nxt[h]], k[h], tail[h], k[nxt[g]], k[g], tail[g])
    corners = np.concatenate([k, hexagons.reshape(-1)])
    offsets = np.concatenate([mesh.offsets, np.arange(H + 6, 4 * H + 1, 6, dtype=dt)])
    vertices = np.empty((n + H, 3))
    vertices[:n] = mesh.vertices
    vertices[n:] = _corner_points(mesh, s)
    return remeshed(mesh, vertices, corners, offsets, dt, _hexagons_twin, _hexagons_rings)


def _open_hexagons(mesh: Mesh, s: float) -> Mesh:
    """Hexagon preservation of an open mesh (numpy; twins and rings derived when asked for).

    Points: the old vertices, one copy point per half-edge (``V + h``),
    then the two trisection points of every boundary edge ``bh[j]``
    (``V + H + 2j`` at a third from its tail, ``V + H + 2j + 1`` at two
    thirds).  A boundary edge ``h = (a, b)``'s hexagon runs along the
    edge instead of round the missing face: ``(k_bf, k_af, a, t1, t2, b)``.
    """
    n, H, E = mesh.n_vertices, mesh.n_halfedges, mesh.n_edges
    bh = mesh.boundary_halfedges
    B = bh.size
    k = np.arange(n, n + H, dtype=np.int64)
    nxt, twin = mesh.next.astype(np.int64), mesh.twin.astype(np.int64)
    tail, head = mesh.corners.astype(np.int64), mesh.head.astype(np.int64)
    h = mesh.edge_halfedge.astype(np.int64)
    g = twin[h]
    inner = g < H
    slot = np.full(H, -1, dtype=np.int64)
    slot[bh] = np.arange(B)
    jb = slot[h[~inner]]
    hexagons = np.empty((E, 6), dtype=np.int64)
    hexagons[:, 0] = k[nxt[h]]
    hexagons[:, 1] = k[h]
    hexagons[:, 2] = tail[h]
    gi = g[inner]
    hexagons[inner, 3] = k[nxt[gi]]
    hexagons[inner, 4] = k[gi]
    hexagons[inner, 5] = tail[gi]
    hexagons[~inner, 3] = n + H + 2 * jb
    hexagons[~inner, 4] = n + H + 2 * jb + 1
    hexagons[~inner, 5] = head[h[~inner]]
    corners = np.concatenate([k, hexagons.reshape(-1)])
    offsets = np.concatenate([mesh.offsets, np.arange(H + 6, H + 6 * E + 1, 6)])
    v = mesh.vertices
    vertices = np.empty((n + H + 2 * B, 3))
    vertices[:n] = v
    vertices[n : n + H] = _corner_points(mesh, s)
    a, b = v[mesh.corners[bh]], v[mesh.head[bh]]
    vertices[n + H :: 2] = a * (2.0 / 3.0) + b * (1.0 / 3.0)
    vertices[n + H + 1 :: 2] = a * (1.0 / 3.0) + b * (2.0 / 3.0)
    return output(vertices, corners, offsets)


def _hex_slot(m, h: np.ndarray, forward: int, backward: int, dt: np.dtype) -> np.ndarray:
    """The corner of the hexagon of ``h``'s edge (see :func:`_edge_slot`)."""
    return _edge_slot(m, h, 6, forward, backward, dt)


def _hexagons_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``preserve_hexagons``: copy h and its edge's hexagon (slot 0 forward,
    3 backward); slot 1 of (h, g) and the hexagon of prev[h] (slot 5 forward,
    2 backward); slot 2 and that of next[g] (1, 4); slot 4 and prev[g] (5, 2);
    slot 5 and next[h] (1, 4)."""
    H = m.n_halfedges
    nxt, prv, twin = m.next, m.prev, m.twin
    h = m.edge_halfedge
    g = twin[h]
    hexagons = columns(
        dt,
        h.size,
        h,
        _hex_slot(m, prv[h], 5, 2, dt),
        _hex_slot(m, nxt[g], 1, 4, dt),
        g,
        _hex_slot(m, prv[g], 5, 2, dt),
        _hex_slot(m, nxt[h], 1, 4, dt),
    )
    return np.concatenate([_hex_slot(m, np.arange(H, dtype=dt), 0, 3, dt), hexagons.reshape(-1)])


def _hexagons_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``preserve_hexagons``: old vertex, for its h in order, its edge's
    hexagon (slot 2 forward, 5 backward); copy vertex of h: h, the hexagon of
    prev[h] (slot 0 forward, 3 backward), that of h (1 forward, 4 backward)."""
    H = m.n_halfedges
    ring, ring_off = m.vertex_ring
    offsets = np.concatenate([ring_off, np.arange(H + 3, 4 * H + 1, 3, dtype=dt)])
    jit = _jit.kernels(4 * H)
    if jit is not None:  # the same rings, each written turned, in one pass
        edge, prv = m.halfedge_edge.astype(dt, copy=False), m.prev.astype(dt, copy=False)
        ring = ring.astype(dt, copy=False)
        return jit.hexagons_rings(ring, ring_off, edge, _mesh.forward(m), prv), offsets
    h = np.arange(H, dtype=dt)
    copies = columns(dt, H, h, _hex_slot(m, m.prev, 0, 3, dt), _hex_slot(m, h, 1, 4, dt))
    rings = np.concatenate(
        [
            start_at_max(_hex_slot(m, ring, 2, 5, dt), ring_off),
            start_at_max(copies.reshape(-1), None, 3),
        ]
    )
    return rings, offsets


@scale_safe
def honeycomb(mesh: Mesh) -> Mesh:
    """Honeycomb subdivision: the dual of sqrt(3)'s remeshing (Conway's zip).

    Figure 13: on a pentagonal mesh it makes a "soccerball" -- every vertex
    3-valent, the pentagons kept, every k-valent vertex turned into a
    2k-gon (hexagons around 3-valent vertices).  No triangle or quad appears.

    One new vertex per half-edge ``h = (u, w)`` of face f, at the centroid of
    the triangle ``(u, w, c_f)`` (the dual of the centroid fan).

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (the module docstring says
        what a boundary edge becomes).

    Returns
    -------
    Mesh
        2E vertices, 3E edges, F + V faces: one n-gon per n-gon (in order),
        then one 2k-gon per k-valent vertex.
    """
    check_mesh(mesh, "honeycomb")
    if not mesh.is_closed:
        return _open_honeycomb(mesh)
    H = mesh.n_halfedges
    dt = index_dtype(H, 3 * H)
    ring, ring_off = mesh.vertex_ring
    # around vertex v: z(h_0), z(prev h_0), z(h_1), z(prev h_1), ...
    vfaces = columns(dt, H, ring, mesh.prev[ring])
    corners = np.concatenate([np.arange(H, dtype=dt), vfaces.reshape(-1)])
    offsets = np.concatenate([mesh.offsets, H + 2 * ring_off[1:].astype(dt)])
    v, centres = mesh.vertices, mesh.face_centroids
    jit = _jit.kernels(H)
    if jit is not None and v.flags.c_contiguous:  # the same sums, one pass, no temporaries
        points = jit.honeycomb_points(v, mesh.corners, mesh.head, centres, mesh.halfedge_face)
    else:
        points = (v[mesh.corners] + v[mesh.head] + centres[mesh.halfedge_face]) / 3.0
    return remeshed(mesh, points, corners, offsets, dt, _honeycomb_twin, _honeycomb_rings)


def _open_honeycomb(mesh: Mesh) -> Mesh:
    """Honeycomb of an open mesh (numpy; twins and rings derived when asked for).

    Points: the H points of the half-edges, the midpoints of the boundary
    edges (``H + j`` for ``bh[j]``), then the boundary's corners, kept.  Faces: the copies,
    then one face per vertex (:func:`open_vertex_faces`), closed along the
    boundary as the dual's.
    """
    H = mesh.n_halfedges
    bh = mesh.boundary_halfedges
    B = bh.size
    h = np.arange(H, dtype=np.int64)
    mids = np.arange(H, H + B, dtype=np.int64)
    keep, at = corner_ids(mesh, H + B)
    faces, face_off = open_vertex_faces(mesh, (h, mesh.prev.astype(np.int64)), mids, mids, keep)
    corners = np.concatenate([h, faces])
    offsets = np.concatenate([mesh.offsets, H + face_off[1:]])
    v, centres = mesh.vertices, mesh.face_centroids
    points = np.empty((H + B + at.size, 3))
    points[:H] = (v[mesh.corners] + v[mesh.head] + centres[mesh.halfedge_face]) / 3.0
    a, b = v[mesh.corners[bh]], v[mesh.head[bh]]
    points[H : H + B] = 0.5 * a + 0.5 * b
    points[H + B :] = v[at]
    return output(points, corners, offsets)


def _honeycomb_twin(m, dt: np.dtype) -> np.ndarray:
    """Twins of ``honeycomb``: copy h and ``H + 2 pos[next[h]]`` (the vertex-face
    half-edge ``H + 2i``, from the point of ``ring[i]`` to that of its prev);
    ``H + 2i + 1`` and ``H + 2 pos[next[twin[prev[ring[i]]]]] + 1``."""
    H = m.n_halfedges
    nxt = m.next
    ring, _ = m.vertex_ring
    pos = inverse(ring)
    before = m.prev[ring]
    faces = columns(dt, H, before, affine(pos[nxt[m.twin[before]]], 2, H + 1, dt))
    return np.concatenate([affine(pos[nxt], 2, H, dt), faces.reshape(-1)])


def _honeycomb_rings(m, dt: np.dtype) -> tuple[np.ndarray, np.ndarray]:
    """Rings of ``honeycomb``: the point of h: ``h, H + 2 pos[h], H + 2 pos[next[h]] + 1``."""
    H = m.n_halfedges
    ring, _ = m.vertex_ring
    pos = inverse(ring.astype(dt, copy=False))
    jit = _jit.kernels(3 * H)
    if jit is not None:  # the same rings, each written turned, in one pass
        rings = jit.honeycomb_rings(pos, m.next.astype(dt, copy=False))
        return rings, np.arange(0, 3 * H + 1, 3, dtype=dt)
    rings = columns(
        dt, H, np.arange(H, dtype=dt), affine(pos, 2, H, dt), affine(pos[m.next], 2, H + 1, dt)
    )
    return start_at_max(rings.reshape(-1), None, 3), np.arange(0, 3 * H + 1, 3, dtype=dt)
