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
from ._build import (
    check_mesh,
    check_scale,
    check_vertex_faces,
    corner_ids,
    fixed_size,
    index_dtype,
    open_vertex_faces,
    output,
    scale_safe,
)
from .table import Table

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


#: Figure 3: "we first subdivide every edge at its midpoint and connect these
#: midpoints to create a central face in the middle of each original face and
#: triangles in each corner."
LOOP = Table(
    "loop_remesh",
    label="Loop remeshing",
    edge_points=(0.5,),
    faces=(
        ("face", ("E0",)),  # the central face: the midpoints, in face order
        ("halfedge", ("E0", "n:V", "n:E0")),  # the corner triangle (m_h, w, m_next)
    ),
)

#: sqrt(3)'s remeshing: a centroid fan, then every old edge flipped: half-edge
#: h = (u, w) of face f, its twin in face g, gives (u, c_g, c_f); on the boundary
#: (no face across) the edge is kept: (u, w, c_f).
SQRT3 = Table(
    "sqrt3_remesh",
    label="sqrt(3) remeshing",
    face_points=True,
    faces=(("halfedge", ("V", "t:F|n:V", "F")),),
)

#: Catmull-Clark's remeshing: a point on every edge and face; every n-gon gives
#: n quads (m_h, w, m_next, c_f).
VERTEX_INSERTION = Table(
    "vertex_insertion",
    label="Vertex insertion (Catmull-Clark)",
    edge_points=(0.5,),
    face_points=True,
    faces=(("halfedge", ("E0", "n:V", "n:E0", "F")),),
)

#: Doo-Sabin's remeshing (closed meshes; the open boundary rule is below): a
#: point per corner, c_f + scale (v - c_f); a copy of every face, a quad across
#: every edge, a face round every vertex.
CORNER_CUTTING = Table(
    "corner_cutting",
    label="Corner cutting (Doo-Sabin)",
    vertices=False,
    corner_points=("V", "scale"),
    options={"scale": 0.5},
    faces=(
        ("face", ("C",)),  # the face's copy
        ("edge", ("n:C", "C", "tn:C", "t:C")),  # the quad between the copies across h
        ("vertex", ("C",)),  # the vertex's face, through its corners' points
    ),
)

#: The dual of Loop's remeshing (closed meshes; the open rule is below): every
#: face's copy, and a hexagon (k(b,f), k(a,f), a, k(a,g), k(b,g), b) per edge.
PRESERVE_HEXAGONS = Table(
    "preserve_hexagons",
    label="Hexagon preservation (dual of Loop)",
    corner_points=("V", "scale"),
    options={"scale": 0.5},
    faces=(("face", ("C",)), ("edge", ("n:C", "C", "V", "tn:C", "t:C", "t:V"))),
)

#: The dual of sqrt(3)'s remeshing (closed meshes; the open rule is below): a
#: point per half-edge at the centroid of (u, w, c_f); every face's copy, and a
#: 2k-gon round every k-valent vertex.
HONEYCOMB = Table(
    "honeycomb",
    label="Honeycomb (dual of sqrt(3))",
    vertices=False,
    face_points=False,
    corner_points={"V": 1 / 3, "n:V": 1 / 3, "F": 1 / 3},
    faces=(("face", ("C",)), ("vertex", ("C", "p:C"))),
)


def loop_remesh(mesh: Mesh) -> Mesh:
    """Loop's remeshing (Figure 3): a triangle-preserving scheme on any mesh (:data:`LOOP`).

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (every edge split at its midpoint).

    Returns
    -------
    Mesh
        V + E vertices (old, then edge midpoints), 4E edges, F + 2E faces:
        the central faces (one n-gon per n-gon) then the corner triangles
        ``(m_h, w, m_next)``.
    """
    return LOOP(mesh)


def sqrt3_remesh(mesh: Mesh) -> Mesh:
    """The remeshing of sqrt(3) subdivision (:data:`SQRT3`), a triangulization.

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
    return SQRT3(mesh)


def vertex_insertion(mesh: Mesh) -> Mesh:
    """Catmull-Clark's remeshing, a quadrilateralization (:data:`VERTEX_INSERTION`).

    Parameters
    ----------
    mesh : Mesh
        A manifold polygon mesh, closed or open (every edge split at its midpoint).

    Returns
    -------
    Mesh
        V + E + F vertices (old, midpoints, centroids), 4E edges, 2E quads
        ``(m_h, w, m_next, c_f)``.
    """
    return VERTEX_INSERTION(mesh)


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
    return CORNER_CUTTING(mesh, scale=s)


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
    return PRESERVE_HEXAGONS(mesh, scale=s)


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
    return HONEYCOMB(mesh)


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
