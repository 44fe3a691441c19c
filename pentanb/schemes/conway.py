"""Conway's polyhedron operators that the paper's schemes do not already cover.

The paper's pentagonalization is Conway's *gyro* and its comparison schemes
are *expand* (corner cutting), *ortho* (vertex insertion), *chamfer* (hexagon
preservation), *zip* (honeycomb), *subdivide* (Loop's remeshing) and
*needle* (the sqrt(3) remeshing): :mod:`pentanb.notation` calls those
functions for those letters.  This module adds the rest of Conway's and
Hart's set (Hart, "Conway notation for polyhedra", and the extended set of
Antiprism's ``conway``), written like the other remeshings: whole-array
numpy over the input's half-edges, outputs valid by construction.

Positions follow the package's conventions: old vertices stay where they
are, new points sit at fixed fractions of edges (midpoints, thirds) or at
face centroids (the plain mean of a face's vertices).  They are a starting
point, not the literature's geometry: Hart and Antiprism put the results in
canonical form (:func:`pentanb.canonical`), which depends only on the
topology.

=============  ==========  =====================  ====================================
function       letter      V, E, F after          new positions
=============  ==========  =====================  ====================================
``ambo``       a           E, 2E, V+F             edge midpoints
``truncate``   t, tN       2E, 3E, V+F            ``ratio`` (1/3) along each edge
``kis``        k, kN       V+F, 3E, 2E            face centroids (flat pyramids)
``join``       j           V+F, 2E, E             face centroids
``snub``       s           2E, 5E, V+2E+F         ``dual(pentagonalize(mesh))``
``propeller``  p           V+2E, 5E, F+2E         edge thirds (as pentagonalize)
``whirl``      w           V+4E, 7E, F+2E         edge thirds; 1/3 from centroid
``meta``       m           V+E+F, 6E, 4E          midpoints and centroids
``bevel``      b           4E, 6E, V+E+F          ``truncate(ambo(mesh))``
``reflect``    r           V, E, F                mirror image (x -> -x)
=============  ==========  =====================  ====================================

(For ``tN`` and ``kN`` only the N-valent vertices or N-sided faces are cut
or raised; the counts then depend on how many there are.)
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh
from ._build import (
    check_mesh,
    concat_faces,
    edge_points,
    fixed_size,
    halfedge_edge_point,
    output,
)
from .pentagonal import pentagonalize
from .smoothing import dual

__all__ = [
    "ambo",
    "truncate",
    "kis",
    "join",
    "snub",
    "propeller",
    "whirl",
    "meta",
    "bevel",
    "reflect",
]


def _check_sides(n, what: str) -> int | None:
    """``None`` or an integer >= 3 (a face size or a valence)."""
    if n is None:
        return None
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"{what} must be an integer or None, got {n!r}")
    if n < 3:
        raise ValueError(f"{what} must be at least 3, got {n}")
    return int(n)


def ambo(mesh: Mesh) -> Mesh:
    """Conway's ambo ``a`` (rectification): a vertex at every edge midpoint.

    Every n-gon gives the n-gon of its edge midpoints and every k-valent
    vertex the k-gon of the midpoints around it; every new vertex is
    4-valent.  ``aC`` is the cuboctahedron, ``aT`` the octahedron.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces.

    Returns
    -------
    Mesh
        E vertices (edge ``e``'s midpoint is vertex ``e``), 2E edges,
        F + V faces: the face copies in the input's order, then one face per
        vertex (its outgoing edges counter-clockwise).
    """
    check_mesh(mesh, "ambo")
    e = mesh.halfedge_edge
    ring, ring_off = mesh.vertex_ring
    corners, offsets = concat_faces((e, mesh.offsets), (e[ring], ring_off))
    return output(edge_points(mesh, 1), corners, offsets)


def truncate(mesh: Mesh, n: int | None = None, ratio: float = 1.0 / 3.0) -> Mesh:
    """Conway's truncate ``t`` (``tN``: only the N-valent vertices).

    Every cut vertex is replaced by the polygon of the points at ``ratio``
    of the way along its edges; each face keeps its uncut corners and gets
    two points for every cut one.  ``tI`` is the truncated icosahedron
    (with ``ratio = 1/3`` the regular one: 12 regular pentagons, 20 regular
    hexagons), ``t = dkd``.

    Parameters
    ----------
    mesh : Mesh
    n : int >= 3, optional
        Cut only the vertices of valence ``n`` (all when None).
    ratio : float in (0, 1/2)
        Where a cut crosses an edge, from the cut vertex.

    Returns
    -------
    Mesh
        With every vertex cut: 2E vertices, 3E edges, F + V faces.  With
        ``n``: V + (n - 1) V_n vertices, E + n V_n edges, F + V_n faces
        (``V_n`` the number of n-valent vertices).  Vertices: the uncut old
        vertices in order, then one point per half-edge leaving a cut
        vertex; faces: the old faces in order, then one per cut vertex.
    """
    check_mesh(mesh, "truncate")
    n = _check_sides(n, "truncate's valence n")
    r = _check_ratio(ratio)
    cut = np.ones(mesh.n_vertices, dtype=bool) if n is None else mesh.valences == n
    if not cut.any():
        return mesh
    tail, head = mesh.corners, mesh.head
    kept = np.flatnonzero(~cut)
    new_id = np.empty(mesh.n_vertices, dtype=np.int64)
    new_id[kept] = np.arange(kept.size, dtype=np.int64)
    from_cut = cut[tail]  # half-edges leaving a cut vertex get a point
    point = np.full(mesh.n_halfedges, -1, dtype=np.int64)
    point[from_cut] = kept.size + np.arange(int(from_cut.sum()), dtype=np.int64)
    # old face: each uncut corner stays; a cut corner (tail of h) becomes the
    # point on the incoming edge, then the point on h
    first = np.where(from_cut, point[mesh.twin[mesh.prev]], new_id[tail])
    pairs = np.stack([first, point], axis=1)
    keep = np.stack([np.ones_like(from_cut), from_cut], axis=1)
    face_corners = pairs[keep]
    sizes = np.add.reduceat(1 + from_cut.astype(np.int64), mesh.offsets[:-1])
    face_off = np.concatenate([[0], np.cumsum(sizes)])
    # one face per cut vertex, its points counter-clockwise
    ring, _ = mesh.vertex_ring
    ring_cut = np.repeat(cut, mesh.valences)
    vert_corners = point[ring[ring_cut]]
    vert_off = np.concatenate([[0], np.cumsum(mesh.valences[cut])])
    corners, offsets = concat_faces((face_corners, face_off), (vert_corners, vert_off))
    v = mesh.vertices
    h = np.flatnonzero(from_cut)
    points = v[tail[h]] + r * (v[head[h]] - v[tail[h]])
    return output(np.concatenate([v[kept], points]), corners, offsets)


def _check_ratio(ratio: float) -> float:
    try:
        r = float(ratio)
    except (TypeError, ValueError):
        raise ValueError(f"ratio must be a number in (0, 1/2), got {ratio!r}") from None
    if not (0.0 < r < 0.5):
        raise ValueError(f"ratio must be in (0, 1/2), got {ratio!r}")
    return r


def kis(mesh: Mesh, n: int | None = None) -> Mesh:
    """Conway's kis ``k`` (``kN``: only the N-sided faces): a pyramid on every face.

    A vertex at each chosen face's centroid, joined to the face's corners.
    With the package's convention the apex stays *in* the face (the
    pyramids are flat); :func:`pentanb.canonical` raises them.  ``kD`` is
    the pentakis dodecahedron, ``k = dtd``.

    Parameters
    ----------
    mesh : Mesh
    n : int >= 3, optional
        Raise pyramids only on the ``n``-sided faces (all when None).

    Returns
    -------
    Mesh
        With every face: V + F vertices, 3E edges, 2E triangles.  With
        ``n``: V + F_n vertices, E + n F_n edges, F + (n - 1) F_n faces.
        Vertices: the old ones, then one centroid per chosen face; faces:
        the other faces in order, then one triangle ``(u, w, c_f)`` per
        half-edge of each chosen face.
    """
    check_mesh(mesh, "kis")
    n = _check_sides(n, "kis's face size n")
    chosen = np.ones(mesh.n_faces, dtype=bool) if n is None else mesh.face_sizes == n
    if not chosen.any():
        return mesh
    faces = np.flatnonzero(chosen)
    apex = np.full(mesh.n_faces, -1, dtype=np.int64)
    apex[faces] = mesh.n_vertices + np.arange(faces.size, dtype=np.int64)
    hf = mesh.halfedge_face
    fan = chosen[hf]
    h = np.flatnonzero(fan)
    tris = np.stack([mesh.corners[h], mesh.head[h], apex[hf[h]]], axis=1)
    other = np.flatnonzero(~chosen)
    kept = mesh.corners[~fan]
    kept_off = np.concatenate([[0], np.cumsum(mesh.face_sizes[other])])
    corners, offsets = concat_faces((kept, kept_off), fixed_size(tris))
    vertices = np.concatenate([mesh.vertices, mesh.face_centroids[faces]])
    return output(vertices, corners, offsets)


def join(mesh: Mesh) -> Mesh:
    """Conway's join ``j``: a quad across every edge, joining its ends and its faces' centres.

    ``jX`` is ``kX`` without the old edges (``j = da``); ``jC`` is the
    rhombic dodecahedron, ``jT`` the cube.

    Returns
    -------
    Mesh
        V + F vertices (old, then face centroids), 2E edges, E quads: edge
        ``e`` with ends ``u < w`` gives ``(u, c_g, w, c_f)`` where f lies to
        the left of ``u -> w``.
    """
    check_mesh(mesh, "join")
    h = mesh.edge_halfedge
    c = mesh.n_vertices + mesh.halfedge_face
    quads = np.stack([mesh.corners[h], c[mesh.twin[h]], mesh.head[h], c[h]], axis=1)
    corners, offsets = fixed_size(quads)
    return output(np.concatenate([mesh.vertices, mesh.face_centroids]), corners, offsets)


def snub(mesh: Mesh) -> Mesh:
    """Conway's snub ``s = dg``: the dual of pentagonalization (gyro).

    Every face becomes a smaller twisted copy, every vertex a face, every
    edge two triangles; every vertex is 5-valent.  ``sC`` is the snub cube,
    ``sT`` the icosahedron.  Conway defines it as the dual of gyro, and so
    it is built here, with the package's dual (vertices at the centroids of
    the gyro pentagons).

    Returns
    -------
    Mesh
        2E vertices, 5E edges, V + 2E + F faces.
    """
    check_mesh(mesh, "snub")
    return dual(pentagonalize(mesh))


def _thirds(mesh: Mesh):
    """Vertex ids (after the V old ones) of the trisection points of every
    half-edge: ``t1`` near its tail, ``t2`` near its head (as in
    :func:`~pentanb.schemes.pentagonal.pentagonalize`)."""
    n = mesh.n_vertices
    return n + halfedge_edge_point(mesh, 2, 0), n + halfedge_edge_point(mesh, 2, 1)


def propeller(mesh: Mesh) -> Mesh:
    """Hart's propeller ``p``: each n-gon becomes a twisted n-gon and n quads.

    "Makes each n-gon face into a 'propeller' of an n-gon surrounded by n
    quadrilaterals" (Hart).  Every edge is cut in three (as in
    pentagonalization); the face's inner n-gon joins the points just after
    its corners, and half-edge ``h = (u, w)`` gives the quad
    ``(t1(h), t2(h), w, t1(next h))``.  The new vertices are 4-valent.
    ``pT`` is the propello-tetrahedron (4 triangles, 12 quads).

    Returns
    -------
    Mesh
        V + 2E vertices (old, then two per edge as in pentagonalize), 5E
        edges, F + 2E faces: the inner faces in the input's order, then one
        quad per half-edge.  With the package's positions every new face
        lies in its old face's plane.
    """
    check_mesh(mesh, "propeller")
    t1, t2 = _thirds(mesh)
    quads = np.stack([t1, t2, mesh.head, t1[mesh.next]], axis=1)
    corners, offsets = concat_faces((t1, mesh.offsets), fixed_size(quads))
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 2)])
    return output(vertices, corners, offsets)


def whirl(mesh: Mesh) -> Mesh:
    """Whirl ``w``: pentagonalization with every face centre truncated.

    Antiprism: "Gyro followed by truncation of vertices centered on
    original faces.  This create 2 new hexagons for every original edge."
    Every n-gon becomes a small twisted n-gon and n hexagons; half-edge
    ``h = (u, w)`` gives ``(t1(h), t2(h), w, t1(next h), q(next h), q(h))``
    where ``q(h)`` lies on the gyro spoke from the centroid ``c_f`` to
    ``t1(h)``, a third of the way from ``c_f`` (as :func:`truncate` cuts).
    ``wD`` is the Goldberg polyhedron GP(2, 1).

    Returns
    -------
    Mesh
        V + 4E vertices (old; two per edge; one per half-edge), 7E edges,
        F + 2E faces: the inner faces in the input's order, then one
        hexagon per half-edge.
    """
    check_mesh(mesh, "whirl")
    t1, t2 = _thirds(mesh)
    thirds = edge_points(mesh, 2)
    q = mesh.n_vertices + thirds.shape[0] + np.arange(mesh.n_halfedges, dtype=np.int64)
    nxt = mesh.next
    hexagons = np.stack([t1, t2, mesh.head, t1[nxt], q[nxt], q], axis=1)
    corners, offsets = concat_faces((q, mesh.offsets), fixed_size(hexagons))
    c = mesh.face_centroids[mesh.halfedge_face]
    inner = c + (thirds[t1 - mesh.n_vertices] - c) / 3.0
    return output(np.concatenate([mesh.vertices, thirds, inner]), corners, offsets)


def meta(mesh: Mesh) -> Mesh:
    """Conway's meta ``m = kj``: every n-gon cut into 2n triangles.

    The vertex-insertion (ortho) quads ``(m_h, w, m_next, c_f)`` split along
    ``w - c_f``; ``mC`` is the disdyakis dodecahedron.

    Returns
    -------
    Mesh
        V + E + F vertices (old, edge midpoints, face centroids: the layout
        of :func:`~pentanb.schemes.classic.vertex_insertion`), 6E edges, 4E
        triangles: ``(u, m_h, c_f)`` and ``(m_h, w, c_f)`` for every
        half-edge ``h = (u, w)`` of face f.
    """
    check_mesh(mesh, "meta")
    n, E = mesh.n_vertices, mesh.n_edges
    mid = n + mesh.halfedge_edge
    c = n + E + mesh.halfedge_face
    tris = np.stack(
        [
            np.stack([mesh.corners, mid, c], axis=1),
            np.stack([mid, mesh.head, c], axis=1),
        ],
        axis=1,
    ).reshape(-1, 3)
    corners, offsets = fixed_size(tris)
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 1), mesh.face_centroids])
    return output(vertices, corners, offsets)


def bevel(mesh: Mesh) -> Mesh:
    """Conway's bevel ``b = ta`` (omnitruncation): ``truncate(ambo(mesh))``.

    Every n-gon becomes a 2n-gon, every edge a quad, every k-valent vertex a
    2k-gon.  ``bC`` is the truncated cuboctahedron.

    Returns
    -------
    Mesh
        4E vertices, 6E edges, V + E + F faces (faces: F 2n-gons, then V
        2k-gons, then E quads, the order :func:`truncate` gives the faces
        of :func:`ambo`).
    """
    check_mesh(mesh, "bevel")
    return truncate(ambo(mesh))


def reflect(mesh: Mesh) -> Mesh:
    """Hart's reflect ``r``: the mirror image (x -> -x, every face reversed).

    The orientation stays outward.  ``rsC`` is the other snub cube.

    Returns
    -------
    Mesh
        The same counts; face ``f`` keeps its first corner and lists the
        others backwards.
    """
    check_mesh(mesh, "reflect")
    hf = mesh.halfedge_face
    start = mesh.offsets[:-1][hf]
    size = mesh.face_sizes[hf]
    i = np.arange(mesh.n_halfedges, dtype=np.int64) - start
    corners = mesh.corners[start + (size - i) % size]
    v = mesh.vertices * np.array([-1.0, 1.0, 1.0])
    return output(v, corners, mesh.offsets)
