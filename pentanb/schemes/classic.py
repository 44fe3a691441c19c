"""The remeshings the paper compares its schemes with (Sections 3 and 6).

Each works on any closed polygon mesh, keeps the Euler characteristic, and
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
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh
from ._build import (
    check_mesh,
    check_scale,
    check_vertex_faces,
    concat_faces,
    edge_points,
    fixed_size,
    index_dtype,
    output,
    scale_safe,
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
    return output(vertices, corners, offsets)


@scale_safe
def loop_remesh(mesh: Mesh) -> Mesh:
    """Loop's remeshing (Figure 3): a triangle-preserving scheme on any mesh.

    "We first subdivide every edge at its midpoint and connect these
    midpoints to create a central face in the middle of each original face
    and triangles in each corner."

    Returns
    -------
    Mesh
        V + E vertices (old, then edge midpoints), 4E edges, F + 2E faces:
        the central faces (one n-gon per n-gon) then the corner triangles
        ``(m_h, w, m_next)``.
    """
    check_mesh(mesh, "loop_remesh")
    dt = index_dtype(mesh.n_vertices + mesh.n_edges, 4 * mesh.n_halfedges)
    mid = mesh.halfedge_edge.astype(dt)
    mid += mesh.n_vertices
    corner_tris = np.stack([mid, mesh.head, mid[mesh.next]], axis=1)
    corners, offsets = concat_faces((mid, mesh.offsets), fixed_size(corner_tris))
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 1)])
    return output(vertices, corners, offsets)


@scale_safe
def sqrt3_remesh(mesh: Mesh) -> Mesh:
    """The remeshing of sqrt(3) subdivision: a centroid fan, then every old edge flipped.

    A triangulization (conversion) scheme: the result is all triangles.

    Returns
    -------
    Mesh
        V + F vertices (old, then centroids), 3E edges, 2E triangles
        ``(u, c_g, c_f)`` for every half-edge ``h = (u, w)`` of face f whose
        twin lies in face g.
    """
    check_mesh(mesh, "sqrt3_remesh")
    dt = index_dtype(mesh.n_vertices + mesh.n_faces, 3 * mesh.n_halfedges)
    c = mesh.halfedge_face.astype(dt)
    c += mesh.n_vertices
    tris = np.stack([mesh.corners, c[mesh.twin], c], axis=1)
    corners, offsets = fixed_size(tris)
    vertices = np.concatenate([mesh.vertices, mesh.face_centroids])
    return output(vertices, corners, offsets)


@scale_safe
def vertex_insertion(mesh: Mesh) -> Mesh:
    """Catmull-Clark's remeshing (vertex insertion), a quadrilateralization.

    A point on every edge midpoint and at every face centroid; every n-gon
    becomes n quads ``(m_h, w, m_next, c_f)``.

    Returns
    -------
    Mesh
        V + E + F vertices (old, midpoints, centroids), 4E edges, 2E quads.
    """
    check_mesh(mesh, "vertex_insertion")
    n, E = mesh.n_vertices, mesh.n_edges
    dt = index_dtype(n + E + mesh.n_faces, 4 * mesh.n_halfedges)
    mid = mesh.halfedge_edge.astype(dt)
    mid += n
    centre = mesh.halfedge_face.astype(dt)
    centre += n + E
    quads = np.stack([mid, mesh.head.astype(dt), mid[mesh.next], centre], axis=1)
    corners, offsets = fixed_size(quads)
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 1), mesh.face_centroids])
    return output(vertices, corners, offsets)


def _corner_points(mesh: Mesh, scale: float) -> np.ndarray:
    """One point per half-edge: its tail pulled towards its face's centroid.

    ``c_f + scale * (v - c_f)``.
    """
    c = mesh.face_centroids[mesh.halfedge_face]
    return c + scale * (mesh.vertices[mesh.corners] - c)


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
    k = np.arange(mesh.n_halfedges, dtype=mesh.corners.dtype)
    nxt, twin = mesh.next, mesh.twin
    eh = mesh.edge_halfedge
    quads = np.stack([nxt[eh], eh, nxt[twin[eh]], twin[eh]], axis=1)
    ring, ring_off = mesh.vertex_ring
    corners, offsets = concat_faces((k, mesh.offsets), fixed_size(quads), (ring, ring_off))
    return output(_corner_points(mesh, s), corners, offsets)


@scale_safe
def preserve_hexagons(mesh: Mesh, scale: float = 0.5) -> Mesh:
    """Hexagon preservation: the dual of Loop's remeshing (Conway's chamfer).

    Figures 4-5: applied to a (6, 3) mesh (all hexagons, 3-valent vertices)
    it gives a (6, 3) mesh again.  The old vertices stay; every face gets a
    smaller copy (corner ``(v, f)`` at ``c_f + scale * (v - c_f)``); every
    old edge ``(a, b)`` becomes a hexagon between the copies of its two
    faces; each old vertex is joined to its copies.

    Returns
    -------
    Mesh
        V + 2E vertices (old, then one per half-edge), 4E edges, F + E faces:
        face copies (same sizes) then one hexagon per edge.  The same
        topology as ``dual(loop_remesh(dual(mesh)))``.
    """
    check_mesh(mesh, "preserve_hexagons")
    s = check_scale(scale)
    n = mesh.n_vertices
    dt = index_dtype(n + 2 * mesh.n_edges, 4 * mesh.n_halfedges)
    k = np.arange(n, n + mesh.n_halfedges, dtype=dt)
    nxt, twin, tail = mesh.next, mesh.twin, mesh.corners
    h = mesh.edge_halfedge
    g = twin[h]
    # h = (a, b) in face f, g = (b, a) in face g:
    # hexagon (k(b,f), k(a,f), a, k(a,g), k(b,g), b)
    hexagons = np.stack([k[nxt[h]], k[h], tail[h], k[nxt[g]], k[g], tail[g]], axis=1)
    corners, offsets = concat_faces((k, mesh.offsets), fixed_size(hexagons))
    vertices = np.concatenate([mesh.vertices, _corner_points(mesh, s)])
    return output(vertices, corners, offsets)


@scale_safe
def honeycomb(mesh: Mesh) -> Mesh:
    """Honeycomb subdivision: the dual of sqrt(3)'s remeshing (Conway's zip).

    Figure 13: on a pentagonal mesh it makes a "soccerball" -- every vertex
    3-valent, the pentagons kept, every k-valent vertex turned into a
    2k-gon (hexagons around 3-valent vertices).  No triangle or quad appears.

    One new vertex per half-edge ``h = (u, w)`` of face f, at the centroid of
    the triangle ``(u, w, c_f)`` (the dual of the centroid fan).

    Returns
    -------
    Mesh
        2E vertices, 3E edges, F + V faces: one n-gon per n-gon (in order),
        then one 2k-gon per k-valent vertex.
    """
    check_mesh(mesh, "honeycomb")
    H = mesh.n_halfedges
    k = np.arange(H, dtype=mesh.corners.dtype)
    ring, ring_off = mesh.vertex_ring
    # around vertex v: z(h_0), z(prev h_0), z(h_1), z(prev h_1), ...
    vfaces = np.stack([ring, mesh.prev[ring]], axis=1).reshape(-1)
    corners, offsets = concat_faces((k, mesh.offsets), (vfaces, 2 * ring_off.astype(np.int64)))
    v = mesh.vertices
    points = (v[mesh.corners] + v[mesh.head] + mesh.face_centroids[mesh.halfedge_face]) / 3.0
    return output(points, corners, offsets)
