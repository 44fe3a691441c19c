"""The dual, the paper's smoothing operator (Sections 3 and 5).

"We do not directly compute the weights ... We then apply dual operation
even number of times to create a smooth mesh."  The dual puts a vertex at
each face's centroid and makes a face of each vertex; applied twice it gives
back the mesh's type with every vertex moved to the average of the centroids
of its neighbouring faces.
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh
from ..mesh import build as _mesh
from ._build import check_count, check_mesh, check_vertex_faces, inverse, output

__all__ = ["dual", "smooth"]


def dual(mesh: Mesh) -> Mesh:
    """The dual mesh: a vertex at every face centroid, a face for every vertex.

    Parameters
    ----------
    mesh : Mesh
        Any closed polygon mesh with V vertices, E edges and F faces.

    Returns
    -------
    Mesh
        F vertices (the plain mean of each face's vertices), E edges and V
        faces; face ``v`` of the dual goes round vertex ``v`` of ``mesh``
        counter-clockwise, so the orientation (the sign of the enclosed
        volume) is kept.  A k-valent vertex becomes a k-gon.

    Notes
    -----
    Built from the input's vertex rings; the output's twins and vertex
    rings are written directly (no sorting) when first asked for: the dual
    half-edge at the corner of half-edge ``h`` is the twin of the one at
    ``next[twin[prev[h]]]``, and the dual half-edges of a face's half-edges,
    in face order, go round the dual vertex of that face.  The dual of a
    dual reuses the connectivity of the mesh it came from.

    Raises
    ------
    MeshError
        A vertex with fewer than 3 edges (its dual face would have fewer
        than 3 sides), named in the message.  The constructor refuses such
        meshes; only ``Mesh.from_csr(..., validate=False)`` can build one.
    """
    check_mesh(mesh, "dual")
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
    )
    _mesh.note_extent(out, _mesh.extent(mesh))
    return out


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
    duals : int, >= 0

    Returns
    -------
    Mesh
        ``mesh`` after ``duals`` duals (``mesh`` itself for 0).
    """
    check_mesh(mesh, "smooth")
    duals = check_count(duals, "duals")
    for _ in range(duals):
        mesh = dual(mesh)
    return mesh
