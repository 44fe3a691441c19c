"""Measuring what the paper "visually confirmed": convergence under the dual.

Section 7: "we have visually confirmed that the algorithms converge with G1
continuity".  Two measurements turn that into numbers:

* :func:`dual_convergence`: one remeshing, then pairs of duals; after each
  pair, how round the mesh is (spread of the vertex radii) and how sharp
  its sharpest crease is (largest angle between the normals of two faces
  sharing an edge).
* :func:`subdivision_convergence`: the same after every subdivision level
  (one remeshing and two duals).  On a G1 (tangent-continuous) limit
  surface the largest crease angle must fall towards 0 as the mesh refines.
* :func:`edge_waviness`: Section 1's "lateral artifact": how much the
  surface's distance from a straight edge's axis varies along the edge (a
  wave pattern makes it oscillate).

Both need only numpy.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .. import shapes
from ..mesh import Mesh
from ..schemes.smoothing import dual
from ..subdivision import get_scheme, subdivide

__all__ = [
    "Convergence",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
    "dual_convergence",
    "subdivision_convergence",
    "study",
    "STUDY_MESHES",
    "STUDY_SCHEMES",
    "ROUND_MESHES",
]


@dataclass(frozen=True)
class Convergence:
    """Measurements after successive steps.

    Attributes
    ----------
    scheme : str
    steps : (k,) int
        1, 2, ...: pairs of duals (:func:`dual_convergence`) or subdivision
        levels (:func:`subdivision_convergence`).
    faces : (k,) int
        Number of faces after each step.
    radius_spread : (k,) float
        :func:`radius_spread` after each step.
    max_normal_angle : (k,) float
        Largest angle between neighbouring face normals, in degrees.
    mean_normal_angle : (k,) float
        Mean of those angles, in degrees.
    """

    scheme: str
    steps: NDArray[np.int64]
    faces: NDArray[np.int64]
    radius_spread: NDArray[np.float64]
    max_normal_angle: NDArray[np.float64]
    mean_normal_angle: NDArray[np.float64]


def radius_spread(mesh: Mesh) -> float:
    """std / mean of the vertices' distances to their centroid (0 on a sphere)."""
    r = np.linalg.norm(mesh.vertices - mesh.vertices.mean(axis=0), axis=1)
    return float(r.std() / r.mean())


def normal_angles(mesh: Mesh) -> NDArray[np.float64]:
    """(E,) float: angle in degrees between the normals of the two faces of every edge.

    Uses one half-edge per edge (``edge_halfedge``), its face
    (``halfedge_face``) and its twin's face.
    """
    h = mesh.edge_halfedge
    f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
    n = mesh.face_normals
    cos = np.einsum("ij,ij->i", n[f], n[g])
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def ray_distances(
    mesh: Mesh, origins: NDArray[np.float64], direction: NDArray[np.float64]
) -> NDArray[np.float64]:
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
    start=(-0.5, 0.0, 0.0),
    end=(0.5, 0.0, 0.0),
    direction=(0.0, 1.0, 1.0),
    samples: int = 41,
) -> float:
    """How much a surface wobbles along a straight edge: the range of its distance
    from the edge's axis, measured along rays perpendicular to the edge.

    The defaults probe the middle half of the edge ``y = z = 1`` of a cube
    ``[-1, 1]^3`` along its bisecting direction: rays from
    ``samples`` points between ``start`` and ``end`` towards ``direction``.
    A surface without "lateral artifacts" (Section 1: a smooth wave
    pattern along a straight edge) keeps that distance constant.

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


def _measure(meshes, scheme_name):
    angles = [normal_angles(m) for m in meshes]
    return Convergence(
        scheme=scheme_name,
        steps=np.arange(1, len(meshes) + 1, dtype=np.int64),
        faces=np.array([m.n_faces for m in meshes], dtype=np.int64),
        radius_spread=np.array([radius_spread(m) for m in meshes]),
        max_normal_angle=np.array([a.max() for a in angles]),
        mean_normal_angle=np.array([a.mean() for a in angles]),
    )


def _name(scheme) -> str:
    s = get_scheme(scheme)
    return getattr(s, "name", getattr(s, "__name__", str(scheme)))


def dual_convergence(mesh: Mesh, scheme="pentagonalize", pairs: int = 6, **options) -> Convergence:
    """Remesh once, then apply ``pairs`` pairs of duals, measuring after each pair.

    Parameters
    ----------
    mesh : Mesh
    scheme : str, Scheme or callable
        As for :func:`pentanb.subdivide`.
    pairs : int, >= 1
    **options
        Options of the scheme (e.g. ``scale``).

    Returns
    -------
    Convergence
        ``steps`` = 1 .. pairs.
    """
    if pairs < 1:
        raise ValueError(f"pairs must be >= 1, got {pairs}")
    m = subdivide(mesh, scheme, 1, 0, **options)
    out = []
    for _ in range(pairs):
        m = dual(dual(m))
        out.append(m)
    return _measure(out, _name(scheme))


def subdivision_convergence(
    mesh: Mesh, scheme="pentagonalize", levels: int = 4, duals: int = 2, **options
) -> Convergence:
    """Subdivide ``levels`` times (remesh + ``duals`` duals), measuring after each level.

    Returns
    -------
    Convergence
        ``steps`` = 1 .. levels.
    """
    if levels < 1:
        raise ValueError(f"levels must be >= 1, got {levels}")
    out = []
    m = mesh
    for _ in range(levels):
        m = subdivide(m, scheme, 1, duals, **options)
        out.append(m)
    return _measure(out, _name(scheme))


#: Meshes of the convergence study (name -> builder).
STUDY_MESHES = {
    "cube": shapes.cube,
    "tetrahedron": shapes.tetrahedron,
    "torus": lambda: shapes.torus(8, 6),
    "rabbit": shapes.animal,
}
#: Meshes of the study around a centre, for which the radius spread measures roundness.
ROUND_MESHES = ("cube", "tetrahedron")
#: Schemes of the convergence study: the paper's two.
STUDY_SCHEMES = ("pentagonalize", "preserve_pentagons")


@functools.lru_cache(maxsize=4)
def study(pairs: int = 6, levels: int = 4) -> dict:
    """Both schemes on :data:`STUDY_MESHES`.

    Returns
    -------
    dict
        ``"meshes"``: the mesh names; ``"pairs"`` and ``"levels"``: dicts
        ``{(mesh name, scheme): Convergence}`` from :func:`dual_convergence`
        and :func:`subdivision_convergence`.  (The rabbit is refined at most
        three levels, to keep the study to a few seconds.)
    """
    res_pairs, res_levels = {}, {}
    for name, build in STUDY_MESHES.items():
        mesh = build()
        for scheme in STUDY_SCHEMES:
            res_pairs[name, scheme] = dual_convergence(mesh, scheme, pairs)
            lv = min(levels, 3) if mesh.n_faces > 50 else levels
            res_levels[name, scheme] = subdivision_convergence(mesh, scheme, lv)
    return {"meshes": tuple(STUDY_MESHES), "pairs": res_pairs, "levels": res_levels}
