"""The measures :func:`~pentanb.notation.positions.canonical` and
:func:`~pentanb.notation.positions.planarize` work to and report: the tangency
point of every edge (:func:`tangency_points`), every face's best-fit plane
(:func:`best_fit_planes`) and its distance from planar
(:func:`face_planarity`).

They live here, below :mod:`pentanb.analysis` (which may import them; nothing
in :mod:`pentanb.notation` imports :mod:`pentanb.analysis`).  Every public
name is importable from :mod:`pentanb.notation.positions` too.
"""

from __future__ import annotations

import numpy as np

from ..mesh import Mesh

__all__ = [
    "tangency_points",
    "best_fit_planes",
    "face_planarity",
]


# ---------------------------------------------------------------------- measures
def tangency_points(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """The point of every edge's line closest to the origin, and its distance.

    Parameters
    ----------
    mesh : Mesh
        E edges.

    Returns
    -------
    points : (E, 3) float
    distances : (E,) float
    """
    u = mesh.vertices[mesh.edges[:, 0]]
    w = mesh.vertices[mesh.edges[:, 1]]
    lv = w - u
    s = -np.einsum("ij,ij->i", u, lv) / np.einsum("ij,ij->i", lv, lv)
    t = u + s[:, None] * lv
    return t, np.linalg.norm(t, axis=1)


def best_fit_planes(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """The least-squares plane of every face (through its corners' mean).

    Parameters
    ----------
    mesh : Mesh
        m faces.

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
        m faces.
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


def _canonical_measures(mesh: Mesh) -> tuple[float, float, float, bool]:
    t, d = tangency_points(mesh)
    tangency = float(np.abs(d - 1.0).max())
    centring = float(np.linalg.norm(t.mean(axis=0)))
    planar = float(face_planarity(mesh, relative_to="face").max(initial=0.0))
    return tangency, centring, planar, _convex(mesh)


def _convex(mesh: Mesh, slack: float = 1e-9) -> bool:
    """No vertex beyond any face's plane (by the Newell normal through the face's mean)."""
    c = mesh.face_centroids
    n = mesh.face_normals
    x = mesh.vertices
    size = np.abs(x).max()
    step = max(1, 1_000_000 // x.shape[0])  # faces at a time: bounded memory
    for lo in range(0, c.shape[0], step):
        d = x @ n[lo : lo + step].T - np.einsum("ij,ij->i", c[lo : lo + step], n[lo : lo + step])
        if d.max() > slack * size:
            return False
    return True


def _mean_edge_length(mesh: Mesh) -> float:
    v = mesh.vertices
    return float(np.linalg.norm(v[mesh.edges[:, 1]] - v[mesh.edges[:, 0]], axis=1).mean())
