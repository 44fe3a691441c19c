"""The paper's two schemes (Section 5): pentagonalization and pentagon preservation.

Each is a :class:`~pentanb.schemes.table.Table` (where its points sit and
which faces join them) evaluated by the one engine
(:mod:`pentanb.schemes.engine`), on closed and open meshes alike: a
boundary edge is split as an interior one is, so the output's boundary is
the input's, refined.  Both are remeshings: the old vertices stay where they
are; smoothing is the dual's job (:func:`pentanb.smooth`).
"""

from __future__ import annotations

from ..mesh import Mesh
from .table import Table

__all__ = ["pentagonalize", "preserve_pentagons", "PENTAGONALIZE", "PRESERVE_PENTAGONS"]

#: Section 5.1, Figure 6.  "1. Subdivide all edges in the mesh into 3 equal parts.
#: 2. (a) Create a point sphere at the centroid of the face.  (b) Insert an edge
#: between the point sphere and ... every third corner."  Half-edge h = (u, w) of
#: face f gives the pentagon (t1, t2, w, t1', c_f).
PENTAGONALIZE = Table(
    "pentagonalize",
    label="Pentagonalization",
    edge_points=(1 / 3, 2 / 3),  # step 1: every edge in three equal parts
    face_points=True,  # step 2(a): the point sphere at the centroid
    faces=(
        # E0 = t1, the trisection point near u; E1 = t2, near w; n:V = w;
        # n:E0 = t1', just after w on the next edge; F = c_f, joined in 2(b)
        ("halfedge", ("E0", "E1", "n:V", "n:E0", "F")),
    ),
)

#: Section 5.2, Figure 10.  "1. Subdivide all edges in the mesh into 2 equal
#: parts.  2. ... (b) Scale the points in P_i around their centroid ... (c) Create
#: a new face using the scaled points.  3. ... insert an edge between v_ij and the
#: point in V_s corresponding to v_ij."  Half-edge h = (u, w) gives the pentagon
#: (m_h, w, m_next, q_next, q_h); every face its scaled copy.
PRESERVE_PENTAGONS = Table(
    "preserve_pentagons",
    label="Pentagon preservation",
    edge_points=(0.5,),  # step 1: the midpoints
    corner_points=("E0", "scale"),  # step 2(b): the midpoints' polygon, scaled
    options={"scale": 0.75},
    faces=(
        ("face", ("C",)),  # step 2(c): the copy q_h of every midpoint, in face order
        # E0 = m_h, n:V = w, n:E0 = m_next, n:C = q_next, C = q_h: step 3's edges
        ("halfedge", ("E0", "n:V", "n:E0", "n:C", "C")),
    ),
)


def pentagonalize(mesh: Mesh) -> Mesh:
    """Pentagonalization (pentagonal conversion), Section 5.1 steps 1-2, Figure 6.

    Every n-gon becomes n pentagons, so the result has only pentagons, for
    any input: Conway's *gyro*.  The table is :data:`PENTAGONALIZE`.

    Parameters
    ----------
    mesh : Mesh
        V vertices, E edges, F faces; open meshes too (B boundary edges).

    Returns
    -------
    Mesh
        V + 2E + F vertices, 5E edges, 2E pentagons (open: 5E - B edges,
        2E - B pentagons, 3B boundary edges).  Vertices: the old ones, the
        trisection points of every edge (edge ``e``: ``V + 2e`` at 1/3 and
        ``V + 2e + 1`` at 2/3 from its smaller vertex), the face centroids.
        The pentagon of half-edge ``h = (u, w)`` of face f is
        ``(t1, t2, w, t1', c_f)``.
    """
    return PENTAGONALIZE(mesh)


def preserve_pentagons(mesh: Mesh, scale: float = 0.75) -> Mesh:
    """Pentagon preservation, Section 5.2 steps 1-3, Figure 10.

    Every n-gon becomes one n-gon (the copy) and n pentagons, so a
    pentagonal mesh stays pentagonal; Conway's *quinto* when ``scale=0.5``.
    The table is :data:`PRESERVE_PENTAGONS`.

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
        6E - 2B edges, F + 2E - B faces, 2B boundary edges): the F copies,
        then a pentagon ``(m_h, w, m_next, q_next, q_h)`` per half-edge h.
        Vertices: the old ones, the midpoints (``V + e``), then a copy
        vertex per half-edge (``V + E + h``).
    """
    return PRESERVE_PENTAGONS(mesh, scale=scale)
