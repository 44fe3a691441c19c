"""How far the faces of a mesh are from planar (issue 10; the paper's Section 2 motivation).

The paper's motivation is architectural ("sculptural and architectural
shapes"), and a panel is built flat: after two duals the faces of the
paper's meshes are not planar.  :func:`planarity` says by how much, in
units of the mesh's mean edge length; :func:`face_planarity` gives the
number for every face.  numpy only.
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh

__all__ = ["planarity", "face_planarity", "best_fit_planes"]


def best_fit_planes(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """The least-squares plane of every face (through its corners' mean).

    Returns
    -------
    centres : (m, 3) float
        The mean of each face's corners (a point of its plane).
    normals : (m, 3) float
        Unit normals, turned to agree with the face's orientation (Newell's
        normal); the direction of least spread of the corners.
    """
    v = mesh.vertices
    p = v[mesh.corners]
    starts = mesh.offsets[:-1]
    sizes = mesh.face_sizes[:, None]
    centres = np.add.reduceat(p, starts, axis=0) / sizes
    d = p - centres[mesh.halfedge_face]
    cov = np.add.reduceat(d[:, :, None] * d[:, None, :], starts, axis=0)
    _, vecs = np.linalg.eigh(cov)
    normals = vecs[:, :, 0]  # eigh sorts eigenvalues ascending
    newell = np.add.reduceat(np.cross(p, v[mesh.head]), starts, axis=0)
    flip = np.einsum("ij,ij->i", normals, newell) < 0
    normals[flip] *= -1.0
    return centres, normals


def face_planarity(mesh: Mesh, relative_to: str = "mesh") -> np.ndarray:
    """Largest distance of each face's corners from its best-fit plane.

    Parameters
    ----------
    mesh : Mesh
    relative_to : {"mesh", "face"}
        Divide by the mean edge length of the whole mesh (``"mesh"``) or by
        the mean length of the face's own edges (``"face"``).

    Returns
    -------
    (m,) float
        0 for triangles and for planar faces.
    """
    if relative_to not in ("mesh", "face"):
        raise ValueError(f"relative_to must be 'mesh' or 'face', got {relative_to!r}")
    centres, normals = best_fit_planes(mesh)
    hf = mesh.halfedge_face
    p = mesh.vertices[mesh.corners]
    dist = np.abs(np.einsum("ij,ij->i", p - centres[hf], normals[hf]))
    worst = np.maximum.reduceat(dist, mesh.offsets[:-1])
    lengths = np.linalg.norm(mesh.vertices[mesh.head] - p, axis=1)
    if relative_to == "mesh":
        return worst / lengths.mean()
    return worst / (np.add.reduceat(lengths, mesh.offsets[:-1]) / mesh.face_sizes)


def planarity(mesh: Mesh) -> float:
    """The largest distance of a corner from its face's best-fit plane,
    over the mesh's mean edge length (0 when every face is planar).

    The measure of issue 10: the paper's meshes after two duals (Figures 1B,
    9A, 12B) are 6-15 % of an edge length off; canonical positions
    (:func:`pentanb.canonical`) and :func:`pentanb.planarize` bring it to
    rounding level.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.analysis.planarity import planarity
    >>> planarity(pentanb.shapes.cube())
    0.0
    """
    return float(face_planarity(mesh).max(initial=0.0))
