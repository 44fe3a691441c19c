"""Measures of a mesh shared by the figures, the convergence study and the notebooks.

Combinatorics (Section 5.1's semi-regular regions):

* :func:`vertex_configurations`: the sizes of the faces around every vertex,
  e.g. ``"3.3.4.3.4"``;
* :func:`face_configurations`: the valences of every face's corners (the
  vertex configurations of the dual);
* :func:`canonical_configuration`, :func:`configuration_counts`.

Geometry (what the paper judges by eye):

* :func:`radius_spread`: how round a mesh is (0 on a sphere);
* :func:`normal_angles`: the crease angle at every edge;
* :func:`ray_distances`, :func:`edge_waviness`: Section 1's "lateral
  artifact", a wave along a straight edge.

numpy only.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mesh import Mesh

__all__ = [
    "vertex_configurations",
    "face_configurations",
    "canonical_configuration",
    "configuration_counts",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
]


# ====================================================================== configurations
def _canonical_rows(seqs: np.ndarray) -> np.ndarray:
    """Lexicographically smallest rotation or reflection of every row.

    Parameters
    ----------
    seqs : (k, n) int

    Returns
    -------
    (k, n) int
    """
    k, n = seqs.shape
    if k == 0:
        return seqs
    idx = (np.arange(n)[:, None] + np.arange(n)[None, :]) % n  # rotations
    cands = np.concatenate([seqs[:, idx], seqs[:, ::-1][:, idx]], axis=1)  # (k, 2n, n)
    order = np.lexsort(cands.transpose(2, 0, 1)[::-1].reshape(n, -1))
    # position of the smallest candidate of every row: rank candidates, take min rank
    rank = np.empty(k * 2 * n, dtype=np.int64)
    rank[order] = np.arange(k * 2 * n)
    best = rank.reshape(k, 2 * n).argmin(axis=1)
    return cands[np.arange(k), best]


def _configurations(
    values: np.ndarray, sizes: np.ndarray, order: np.ndarray, offsets: np.ndarray
) -> list[str]:
    """Canonical cyclic sequences ``values[order[offsets[i]:offsets[i+1]]]`` as strings.

    Parameters
    ----------
    values : (H,) int
        A value per half-edge.
    sizes : (k,) int
        Length of every sequence (``offsets[i+1] - offsets[i]``).
    order : (H,) int
        Half-edges in the order the sequences visit them.
    offsets : (k + 1,) int
    """
    out = np.empty(sizes.size, dtype=object)
    for k in np.unique(sizes):
        rows = np.flatnonzero(sizes == k)
        cols = offsets[rows][:, None] + np.arange(k)[None, :]
        canon = _canonical_rows(values[order[cols]])
        out[rows] = [".".join(map(str, r)) for r in canon.tolist()]
    return out.tolist()


def vertex_configurations(mesh: Mesh) -> list[str]:
    """The vertex configuration of every vertex: face sizes around it, e.g. ``"3.3.4.3.4"``.

    The cyclic sequence of the sizes of the faces met going round the
    vertex, written from its lexicographically smallest rotation or
    reflection (so ``4.3.3.4.3`` and ``3.4.3.4.3`` are both ``3.3.4.3.4``).
    Section 5.1 names the semi-regular regions of Figures 8, 9 and 11 this
    way.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (V,) list of str
        Vertex ``i``'s configuration at position ``i``.
    """
    ring, ring_off = mesh.vertex_ring
    face_size_of_he = mesh.face_sizes[mesh.halfedge_face]
    return _configurations(face_size_of_he, mesh.valences, ring, ring_off)


def face_configurations(mesh: Mesh) -> list[str]:
    """The valences of every face's corners, in order and canonical form.

    A face configuration of a mesh is the vertex configuration of the same
    element of its dual: the pentagons of Figure 8.A have corners of valence
    4.3.3.4.3, the vertices of Figure 8.B are surrounded by a 4.3.3.4.3 ring of
    faces.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (F,) list of str
        Face ``i``'s configuration at position ``i``.
    """
    order = np.arange(mesh.n_halfedges, dtype=np.int64)
    return _configurations(mesh.valences[mesh.corners], mesh.face_sizes, order, mesh.offsets)


def canonical_configuration(config: str | Sequence[int]) -> str:
    """Canonical form of a configuration given in any rotation or reflection.

    Parameters
    ----------
    config : str or sequence of int
        E.g. the paper's ``"4.3.3.4.3"`` or ``[4, 3, 3, 4, 3]``.

    Returns
    -------
    str
        E.g. ``"3.3.4.3.4"``, as :func:`vertex_configurations` writes it.
    """
    seq = [int(x) for x in config.split(".")] if isinstance(config, str) else list(config)
    return ".".join(map(str, _canonical_rows(np.array([seq]))[0].tolist()))


def configuration_counts(configs: Iterable[str]) -> dict[str, int]:
    """``{configuration: count}``, most frequent first (ties by name).

    Parameters
    ----------
    configs : iterable of str
        E.g. the output of :func:`vertex_configurations`.
    """
    names, counts = np.unique(
        np.asarray(list(configs), dtype=object).astype(str), return_counts=True
    )
    pairs = sorted(zip(names.tolist(), counts.tolist()), key=lambda p: (-p[1], p[0]))
    return {k: int(v) for k, v in pairs}


# ====================================================================== geometry
def radius_spread(mesh: Mesh) -> float:
    """How far a mesh is from round: std / mean of the vertices' distances to their centroid.

    0 when every vertex lies on one sphere around the centroid (a Platonic
    solid); Figure 7's duals make the tetrahedron's dodecahedron rounder.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    float
    """
    r = np.linalg.norm(mesh.vertices - mesh.vertices.mean(axis=0), axis=1)
    return float(r.std() / r.mean())


def normal_angles(mesh: Mesh) -> NDArray[np.float64]:
    """The crease angle of every edge: the angle between the normals of its two faces.

    Uses one half-edge per edge (``edge_halfedge``), its face
    (``halfedge_face``) and its twin's face.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (E,) float
        Degrees; 0 where the two faces are coplanar, 90 on a cube's edges.
    """
    h = mesh.edge_halfedge
    f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
    n = mesh.face_normals
    cos = np.einsum("ij,ij->i", n[f], n[g])
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def ray_distances(mesh: Mesh, origins: ArrayLike, direction: ArrayLike) -> NDArray[np.float64]:
    """Distance from every origin to the farthest crossing of the mesh along ``direction``.

    Every face is fanned from its centroid (one triangle per half-edge) and
    all rays are intersected with all triangles at once (Moller-Trumbore).

    Parameters
    ----------
    mesh : Mesh
    origins : (k, 3) float
        Points inside the mesh.
    direction : (3,) float
        Unit direction of the rays.

    Returns
    -------
    (k,) float
        NaN where a ray misses.
    """
    d = np.asarray(direction, dtype=np.float64)
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    a = mesh.face_centroids[mesh.halfedge_face]
    e1 = mesh.vertices[mesh.corners] - a
    e2 = mesh.vertices[mesh.head] - a
    pvec = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, pvec)
    good = np.abs(det) > 1e-14
    a, e1, e2, pvec, det = a[good], e1[good], e2[good], pvec[good], det[good]
    tvec = o[:, None, :] - a[None]  # (k, T, 3)
    u = np.einsum("ktj,tj->kt", tvec, pvec) / det
    q = np.cross(tvec, e1[None])
    v = (q @ d) / det
    t = np.einsum("tj,ktj->kt", e2, q) / det
    eps = 1e-9
    hit = (u >= -eps) & (v >= -eps) & (u + v <= 1 + eps) & (t > 0)
    return np.where(hit.any(axis=1), np.where(hit, t, -np.inf).max(axis=1), np.nan)


def edge_waviness(
    mesh: Mesh,
    start: ArrayLike = (-0.5, 0.0, 0.0),
    end: ArrayLike = (0.5, 0.0, 0.0),
    direction: ArrayLike = (0.0, 1.0, 1.0),
    samples: int = 41,
) -> float:
    """How much a surface wobbles along a straight edge (Section 1's "lateral artifact").

    Rays leave ``samples`` evenly spaced points of the segment ``start`` ->
    ``end`` in ``direction``; the result is the range of the distances at
    which they leave the mesh (:func:`ray_distances`).  The defaults probe
    the middle half of the edge ``y = z = 1`` of a cube ``[-1, 1]^3``: the
    rays start on the cube's x axis (parallel to the edge) and point along
    the edge's bisecting direction.  A surface without a wave pattern along
    the edge keeps that distance constant (0).

    Parameters
    ----------
    mesh : Mesh
    start, end : (3,) float
        The segment the rays start from, inside the mesh and parallel to the edge.
    direction : (3,) float
        Direction of the rays (need not be unit length).
    samples : int
        Number of rays.

    Returns
    -------
    float
        ``max - min`` of the distances (in the mesh's units).
    """
    s, e = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    d = np.asarray(direction, dtype=float)
    t = np.linspace(0.0, 1.0, samples)[:, None]
    dist = ray_distances(mesh, s + t * (e - s), d / np.linalg.norm(d))
    return float(np.nanmax(dist) - np.nanmin(dist))
