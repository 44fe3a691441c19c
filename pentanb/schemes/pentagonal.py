"""The paper's two schemes (Section 5): pentagonalization and pentagon preservation.

Both are remeshings: the old vertices stay where they are and new vertices
are placed by affine rules.  Smoothing is the dual's job
(:func:`pentanb.smooth`).
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh
from ._build import (
    check_mesh,
    check_scale,
    concat_faces,
    edge_points,
    fixed_size,
    halfedge_edge_point,
    output,
)

__all__ = ["pentagonalize", "preserve_pentagons"]


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
        V vertices, E edges, F faces.

    Returns
    -------
    Mesh
        V + 2E + F vertices, 5E edges, 2E pentagons.  Vertices are numbered
        old vertices first, then the two trisection points of every edge
        (edge ``e``: rows ``V + 2e`` at 1/3 and ``V + 2e + 1`` at 2/3 from its
        smaller vertex), then the face centroids.  The pentagon of half-edge
        ``h = (u, w)`` in face ``f`` is ``(t1, t2, w, t1', c_f)``: the
        trisection points of ``h`` near u and near w, w, the point just after w
        on the next half-edge, and the centre.
    """
    check_mesh(mesh, "pentagonalize")
    n, E = mesh.n_vertices, mesh.n_edges
    nxt, prv, twin = mesh.next, mesh.prev, mesh.twin
    t1 = n + halfedge_edge_point(mesh, 2, 0)
    t2 = n + halfedge_edge_point(mesh, 2, 1)
    centre = n + 2 * E + mesh.halfedge_face
    faces = np.stack([t1, t2, mesh.head, t1[nxt], centre], axis=1)
    vertices = np.concatenate([mesh.vertices, edge_points(mesh, 2), mesh.face_centroids])
    corners, offsets = fixed_size(faces)
    # the output's twins and vertex rings follow from the input's; written when
    # first asked for (by the dual, say), never found by sorting
    return output(
        vertices,
        corners,
        offsets,
        twin=lambda: np.stack(
            [5 * twin, 5 * prv[twin] + 2, 5 * twin[nxt] + 1, 5 * nxt + 4, 5 * prv + 3], axis=1
        ).reshape(-1),
        rings=lambda: _pentagonalized_rings(mesh, t1 - n),
    )


def _pentagonalized_rings(mesh: Mesh, t1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The vertex rings of ``pentagonalize(mesh)``, written from ``mesh``'s.

    Half-edge ``5h + s`` is slot ``s`` of the pentagon of ``h``.  Around an
    old vertex v: ``5 prev[h] + 2`` for v's outgoing h, in v's order; around
    the trisection point t1(h): ``5h, 5 prev[h] + 3, 5 twin[h] + 1``; around
    the centre of f: ``5h + 4`` for f's half-edges in face order.
    """
    prv, twin = mesh.prev, mesh.twin
    ring, ring_off = mesh.vertex_ring
    H = mesh.n_halfedges
    h_of_point = np.empty(H, dtype=np.int64)
    h_of_point[t1] = np.arange(H, dtype=np.int64)
    h = h_of_point
    trisection = np.stack([5 * h, 5 * prv[h] + 3, 5 * twin[h] + 1], axis=1).reshape(-1)
    rings = np.concatenate([5 * prv[ring] + 2, trisection, 5 * np.arange(H, dtype=np.int64) + 4])
    offsets = np.concatenate(
        [ring_off, ring_off[-1] + 3 * np.arange(1, H + 1), ring_off[-1] + 3 * H + mesh.offsets[1:]]
    )
    return rings, offsets


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
        V vertices, E edges, F faces.
    scale : float in (0, 1)
        Size of the inner copy relative to the polygon of edge midpoints.

    Returns
    -------
    Mesh
        V + 3E vertices, 6E edges, F + 2E faces: the F inner copies (same
        sizes and order as the input's faces) followed by one pentagon per
        half-edge ``h = (u, w)``: ``(m_h, w, m_next, q_next, q_h)``.
        Vertices: old vertices, edge midpoints (``V + e``), then one copy
        vertex per half-edge (``V + E + h``).
    """
    check_mesh(mesh, "preserve_pentagons")
    s = check_scale(scale)
    n, E, H = mesh.n_vertices, mesh.n_edges, mesh.n_halfedges
    nxt = mesh.next
    mids = edge_points(mesh, 1)
    mid = n + mesh.halfedge_edge
    q = n + E + np.arange(H, dtype=np.int64)
    p = mids[mesh.halfedge_edge]
    centre = np.add.reduceat(p, mesh.offsets[:-1], axis=0) / mesh.face_sizes[:, None]
    centre = centre[mesh.halfedge_face]
    copies = centre + s * (p - centre)
    pentagons = np.stack([mid, mesh.head, mid[nxt], q[nxt], q], axis=1)
    corners, offsets = concat_faces((q, mesh.offsets), fixed_size(pentagons))
    vertices = np.concatenate([mesh.vertices, mids, copies])
    return output(vertices, corners, offsets)
