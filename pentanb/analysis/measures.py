"""Measures of a mesh shared by the figures, the convergence study and the notebooks.

Combinatorics (Section 5.1's semi-regular regions):

* :func:`vertex_configurations`: the sizes of the faces around every vertex,
  e.g. ``"3.3.4.3.4"``;
* :func:`face_configurations`: the valences of every face's corners (the
  vertex configurations of the dual);
* :func:`canonical_configuration`, :func:`configuration_counts`.

Geometry (what the paper judges by eye):

* :func:`radius_spread`: how round a mesh is (0 on a sphere);
* :func:`edge_lengths`, :func:`edge_length_spread`, :func:`corner_angles`,
  :func:`angle_spread`, :func:`uniformity`: how uniform a mesh is (Section
  5.1: "the resulting shape becomes more and more uniform with each
  application of dual operation");
* :func:`face_planarity`, :func:`region_geometry`, :func:`flat_region`: how
  far a set of faces is from a flat tiling (Section 5.1's "classical (or
  geometrical) semi-regular regions");
* :func:`nearest_distance`, :func:`surface_distance`: where a remeshing put
  its points, found by position (Section 3: "newly created vertices do not
  change the shape of the initial mesh");
* :func:`normal_angles`, :func:`crease_angles`: the crease angle at every
  edge, and its largest value at the input's extraordinary vertices and
  elsewhere (Section 7's G1 convergence);
* :func:`ray_distances`, :func:`edge_waviness`, :func:`edge_profile`,
  :func:`lateral_amplitude`: Section 1's "lateral artifact", a wave along a
  straight edge.

numpy only.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mesh import Mesh, check_closed, check_mesh
from ..notation.positions import best_fit_planes, face_planarity

__all__ = [
    "vertex_configurations",
    "face_configurations",
    "canonical_configuration",
    "configuration_counts",
    "radius_spread",
    "normal_angles",
    "ray_distances",
    "edge_waviness",
    "edge_lengths",
    "edge_length_spread",
    "corner_angles",
    "angle_spread",
    "uniformity",
    "face_planarity",
    "planarity",
    "best_fit_planes",
    "region_geometry",
    "flat_region",
    "nearest_distance",
    "surface_distance",
    "crease_angles",
    "BOX_EDGES",
    "edge_profile",
    "lateral_amplitude",
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
    check_closed(mesh, "vertex_configurations")
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
    check_mesh(mesh, "face_configurations")
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

    Returns
    -------
    dict
        ``{configuration (str): count (int)}``, most frequent first.
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
    check_closed(mesh, "radius_spread")
    r = np.linalg.norm(mesh.vertices - mesh.vertices.mean(axis=0), axis=1)
    return float(r.std() / r.mean())


def _unit_normals(mesh: Mesh, block: int = 1 << 20) -> NDArray[np.float64]:
    """Unit face normals by Newell's method, in blocks of about ``block`` half-edges.

    The same normals as :attr:`Mesh.face_normals` (to rounding), with the
    cross products written out and the temporaries kept to a block; a mesh
    with a face whose normal could overflow, underflow or vanish gets
    :attr:`Mesh.face_normals` itself, which handles those.
    """
    v, corners, offsets = mesh.vertices, mesh.corners, mesh.offsets
    head = mesh.head
    n = np.empty((mesh.n_faces, 3))
    f0 = 0
    while f0 < mesh.n_faces:
        f1 = int(np.searchsorted(offsets, offsets[f0] + block, side="right")) - 1
        f1 = min(max(f1, f0 + 1), mesh.n_faces)
        h0, h1 = int(offsets[f0]), int(offsets[f1])
        p, q = v[corners[h0:h1]], v[head[h0:h1]]
        c = np.empty_like(p)
        c[:, 0] = p[:, 1] * q[:, 2] - p[:, 2] * q[:, 1]
        c[:, 1] = p[:, 2] * q[:, 0] - p[:, 0] * q[:, 2]
        c[:, 2] = p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0]
        n[f0:f1] = np.add.reduceat(c, offsets[f0:f1] - h0, axis=0)
        f0 = f1
    length = np.sqrt(np.einsum("ij,ij->i", n, n))
    if not np.all((length >= 2.0**-500) & (length <= 2.0**500)):
        return mesh.face_normals
    n /= length[:, None]
    return n


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
    check_closed(mesh, "normal_angles")
    h = mesh.edge_halfedge
    f, g = mesh.halfedge_face[h], mesh.halfedge_face[mesh.twin[h]]
    n = _unit_normals(mesh)
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
    check_mesh(mesh, "ray_distances")
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
    check_mesh(mesh, "edge_waviness")
    s, e = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    d = np.asarray(direction, dtype=float)
    t = np.linspace(0.0, 1.0, samples)[:, None]
    dist = ray_distances(mesh, s + t * (e - s), d / np.linalg.norm(d))
    return float(np.nanmax(dist) - np.nanmin(dist))


# ====================================================================== uniformity
def edge_lengths(mesh: Mesh) -> NDArray[np.float64]:
    """The length of every edge.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (E,) float
        Edge ``e`` from its half-edge ``edge_halfedge[e]``.
    """
    check_mesh(mesh, "edge_lengths")
    h = mesh.edge_halfedge
    return np.linalg.norm(mesh.vertices[mesh.head[h]] - mesh.vertices[mesh.corners[h]], axis=1)


def _face_edges(mesh: Mesh, faces: ArrayLike | None) -> NDArray[np.int64]:
    """The edges of ``faces`` (every edge once), or of the whole mesh."""
    if faces is None:
        return np.arange(mesh.n_edges, dtype=np.int64)
    hs = _face_halfedges(mesh, faces)
    return np.unique(mesh.halfedge_edge[hs])


def _face_halfedges(mesh: Mesh, faces: ArrayLike | None) -> NDArray[np.int64]:
    """The half-edges of ``faces`` (all of them when None)."""
    if faces is None:
        return np.arange(mesh.n_halfedges, dtype=np.int64)
    f = np.asarray(faces, dtype=np.int64).reshape(-1)
    if f.size and (f.min() < 0 or f.max() >= mesh.n_faces):
        raise ValueError(f"face index out of range 0..{mesh.n_faces - 1}")
    return np.flatnonzero(np.isin(mesh.halfedge_face, f))


def _spread(x: np.ndarray) -> float:
    """std / mean (0 for an empty or constant array)."""
    if x.size == 0:
        return 0.0
    return float(x.std() / x.mean())


def edge_length_spread(mesh: Mesh, faces: ArrayLike | None = None) -> float:
    """How unequal the edges are: std / mean of the edge lengths.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Only the edges of these faces (each edge once).

    Returns
    -------
    float
        0 when every edge has the same length (a Platonic solid).  Does not
        change with the mesh's position or scale.
    """
    check_mesh(mesh, "edge_length_spread")
    return _spread(edge_lengths(mesh)[_face_edges(mesh, faces)])


def corner_angles(mesh: Mesh) -> NDArray[np.float64]:
    """The angle of every face at every corner.

    Parameters
    ----------
    mesh : Mesh

    Returns
    -------
    (H,) float
        Degrees; the angle at the corner ``corners[h]`` of face
        ``halfedge_face[h]`` between its edges to the next and the previous
        corner.  A planar n-gon's angles add up to ``(n - 2) 180``.
    """
    check_mesh(mesh, "corner_angles")
    v = mesh.vertices
    e = v[mesh.head] - v[mesh.corners]  # half-edge h, from its corner to the next
    length = np.sqrt(np.einsum("ij,ij->i", e, e))
    prev = mesh.prev
    # the angle at corners[h] between e[h] and the reversed previous half-edge
    cos = -np.einsum("ij,ij->i", e, e[prev])
    cos /= length * length[prev]
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def angle_spread(mesh: Mesh, faces: ArrayLike | None = None, by: str = "size") -> float:
    """How unequal the corner angles are within their kind, over the mean angle.

    Corners are grouped by the size of their face (``by="size"``: a regular
    solid's faces are regular polygons) or by the valence of their vertex
    (``by="valence"``: in a classical tiling such as Section 5.1's
    4.3.3.4.3, the angle at a corner depends on its valence).  The result is
    the root mean square of every angle's deviation from its group's mean,
    divided by the mean of all the angles.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int, optional
        Only the corners of these faces.
    by : {"size", "valence"}

    Returns
    -------
    float
        0 when the angles within every group are equal.
    """
    check_mesh(mesh, "angle_spread")
    if by not in ("size", "valence"):
        raise ValueError(f"by must be 'size' or 'valence', got {by!r}")
    hs = _face_halfedges(mesh, faces)
    if hs.size == 0:
        return 0.0
    ang = corner_angles(mesh)[hs]
    key = (
        mesh.face_sizes[mesh.halfedge_face[hs]] if by == "size" else mesh.valences[mesh.corners[hs]]
    )
    count = np.bincount(key)  # sizes and valences are small non-negative integers
    means = np.bincount(key, weights=ang) / np.maximum(count, 1)
    dev = ang - means[key]
    return float(np.sqrt(np.mean(dev**2)) / ang.mean())


def uniformity(mesh: Mesh) -> dict[str, float]:
    """The three spreads of Figure 7's "more and more uniform".

    Parameters
    ----------
    mesh : Mesh
        A closed manifold polygon mesh.

    Returns
    -------
    dict
        ``"edge"``: :func:`edge_length_spread`; ``"angle"``:
        :func:`angle_spread` (corners grouped by face size); ``"radius"``:
        :func:`radius_spread`.  Each is 0 on a Platonic solid.
    """
    check_mesh(mesh, "uniformity")
    return {
        "edge": edge_length_spread(mesh),
        "angle": angle_spread(mesh),
        "radius": radius_spread(mesh),
    }


# ====================================================================== flatness
def planarity(mesh: Mesh) -> float:
    """The largest distance of a corner from its face's best-fit plane,
    over the mesh's mean edge length (0 when every face is planar).

    The meshes of the paper's figures after two duals (Figures 1B,
    9A, 12B) are 6-15 % of an edge length off; canonical positions
    (:func:`pentanb.canonical`) and :func:`pentanb.planarize` bring it to
    rounding level.

    Parameters
    ----------
    mesh : Mesh
        A closed manifold polygon mesh.

    Returns
    -------
    float, >= 0
        0 when every face is planar.

    Examples
    --------
    >>> import pentanb
    >>> from pentanb.analysis import planarity
    >>> planarity(pentanb.shapes.cube())
    0.0
    """
    check_mesh(mesh, "planarity")
    return float(face_planarity(mesh).max(initial=0.0))


def region_geometry(
    mesh: Mesh, faces: ArrayLike, ideal: dict[int, float] | None = None
) -> dict[str, object]:
    """The geometry of a set of faces, e.g. Section 5.1's 4.3.3.4.3 regions.

    Parameters
    ----------
    mesh : Mesh
    faces : (k,) int
        The faces of the region.
    ideal : dict, optional
        ``{valence: degrees}``: the angle a corner of that valence has on the
        tile compared with (e.g. ``{3: 120, 4: 90}``).

    Returns
    -------
    dict
        ``"faces"``: k; ``"edge_spread"``: :func:`edge_length_spread` of
        their edges; ``"angle_spread"``: :func:`angle_spread` of their
        corners grouped by the corners' valence; ``"planarity"``: the
        largest distance of a corner from its face's least-squares plane,
        over the mean length of the region's edges; ``"angles"``: ``{valence:
        mean corner angle in degrees}``; with ``ideal``, ``"angle_error"``:
        the largest difference in degrees between a corner's angle and the
        ideal angle of its valence (infinite for a valence it does not
        name).  (A flat classical tiling of congruent faces has angle spread
        and planarity 0; its edge spread is that of its tile, see
        :func:`pentanb.figures.claim.classical_tile`.)
    """
    check_mesh(mesh, "region_geometry")
    f = np.asarray(faces, dtype=np.int64).reshape(-1)
    if f.size == 0:
        raise ValueError("region_geometry needs at least one face")
    hs = _face_halfedges(mesh, f)
    edges = np.unique(mesh.halfedge_edge[hs])
    mean_len = float(edge_lengths(mesh)[edges].mean())
    mesh_len = float(
        np.linalg.norm(mesh.vertices[mesh.head] - mesh.vertices[mesh.corners], axis=1).mean()
    )
    flat = face_planarity(mesh)[f] * mesh_len / mean_len
    ang = corner_angles(mesh)[hs]
    val = mesh.valences[mesh.corners[hs]]
    out: dict[str, object] = {
        "faces": int(f.size),
        "edge_spread": edge_length_spread(mesh, f),
        "angle_spread": angle_spread(mesh, f, by="valence"),
        "planarity": float(flat.max()),
        "angles": {int(k): float(ang[val == k].mean()) for k in np.unique(val)},
    }
    if ideal is not None:
        target = np.array([ideal.get(int(k), np.inf) for k in val], dtype=float)
        out["angle_error"] = float(np.abs(ang - target).max())
    return out


def flat_region(
    mesh: Mesh, centre: ArrayLike, normal: ArrayLike, radius: float, tol: float = 1e-9
) -> NDArray[np.int64]:
    """The faces of a flat, round region: every corner in a plane and near a point.

    Parameters
    ----------
    mesh : Mesh
    centre : (3,) float
        A point of the plane, the region's centre.
    normal : (3,) float
        The plane's normal (any length).
    radius : float
        Largest distance of a corner from ``centre``.
    tol : float
        Largest distance of a corner from the plane.

    Returns
    -------
    (k,) int
        The faces all of whose corners lie within ``tol`` of the plane and
        within ``radius`` of ``centre``, increasing.
    """
    check_mesh(mesh, "flat_region")
    c = np.asarray(centre, dtype=float)
    n = np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    d = mesh.vertices - c
    ok = (np.abs(d @ n) <= tol) & (np.linalg.norm(d, axis=1) <= radius)
    if mesh.n_faces == 0:
        return np.zeros(0, dtype=np.int64)
    good = np.minimum.reduceat(ok[mesh.corners].astype(np.int8), mesh.offsets[:-1])
    return np.flatnonzero(good).astype(np.int64)


def nearest_distance(
    points: ArrayLike, targets: ArrayLike, block: int = 2048
) -> NDArray[np.float64]:
    """The distance from every point to the nearest of the targets (brute force, in blocks).

    Parameters
    ----------
    points : (n, 3) float
    targets : (m, 3) float, m >= 1
    block : int
        Points per block (the memory is ``block * m`` distances).

    Returns
    -------
    (n,) float
    """
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    t = np.asarray(targets, dtype=float).reshape(-1, 3)
    if t.shape[0] == 0:
        raise ValueError("nearest_distance needs at least one target")
    out = np.empty(p.shape[0])
    for i in range(0, p.shape[0], block):
        d = np.linalg.norm(p[i : i + block, None, :] - t[None, :, :], axis=2)
        out[i : i + block] = d.min(axis=1)
    return out


def _closest_on_triangles(p: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray):
    """Closest points on triangles ``(a, b, c)`` to ``p`` (broadcast), by Voronoi regions
    (Ericson, *Real-Time Collision Detection*, 5.1.5)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
    bp = p - b
    d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
    cp = p - c
    d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        denom = va + vb + vc
        v = vb / denom
        w = vc / denom
        out = a + ab * v[..., None] + ac * w[..., None]  # inside the face
        # the edges
        t_ab = d1 / (d1 - d3)
        t_ac = d2 / (d2 - d6)
        t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
    on_bc = (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)
    out = np.where(on_bc[..., None], b + (c - b) * t_bc[..., None], out)
    on_ac = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
    out = np.where(on_ac[..., None], a + ac * t_ac[..., None], out)
    on_ab = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
    out = np.where(on_ab[..., None], a + ab * t_ab[..., None], out)
    # the corners
    out = np.where(((d6 >= 0) & (d5 <= d6))[..., None], c, out)
    out = np.where(((d3 >= 0) & (d4 <= d3))[..., None], b, out)
    out = np.where(((d1 <= 0) & (d2 <= 0))[..., None], a, out)
    return out


def surface_distance(points: ArrayLike, mesh: Mesh, block: int = 256) -> NDArray[np.float64]:
    """The distance from every point to the surface of a mesh.

    Every face is fanned from its first corner into triangles (exact for
    planar convex faces, such as a cube's or a box's); the distance is the
    smallest to any of them.  Brute force in blocks of points: meant for
    checks on small meshes (a few hundred faces).

    Parameters
    ----------
    points : (n, 3) float
    mesh : Mesh
    block : int
        Points per block (the memory is ``block`` times the number of
        triangles).

    Returns
    -------
    (n,) float
        0 for a point on a face or an edge.
    """
    check_mesh(mesh, "surface_distance")
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    v = mesh.vertices
    tri = []
    for f in range(mesh.n_faces):
        ring = mesh.corners[mesh.offsets[f] : mesh.offsets[f + 1]]
        tri += [(ring[0], ring[i], ring[i + 1]) for i in range(1, ring.size - 1)]
    t = np.asarray(tri, dtype=np.int64).reshape(-1, 3)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    out = np.empty(p.shape[0])
    for i in range(0, p.shape[0], block):
        q = p[i : i + block, None, :]
        near = _closest_on_triangles(q, a[None], b[None], c[None])
        out[i : i + block] = np.linalg.norm(near - q, axis=2).min(axis=1)
    return out


# ====================================================================== creases
def crease_angles(
    mesh: Mesh, marked: ArrayLike, angles: ArrayLike | None = None
) -> dict[str, float]:
    """The largest crease angle at some vertices, and elsewhere.

    Parameters
    ----------
    mesh : Mesh
    marked : (V,) bool or (k,) int
        The vertices to look at (Section 7's G1 question is decided at the
        extraordinary vertices): an edge is "at" them when one of its ends
        is marked, so its crease angle is one between two faces around a
        marked vertex.
    angles : (E,) float, optional
        :func:`normal_angles` of the mesh, if already computed.

    Returns
    -------
    dict
        ``"at"``: the largest :func:`normal_angles` of the edges at the
        marked vertices, ``"elsewhere"``: of all the other edges (NaN where
        there is no such edge); degrees.
    """
    check_mesh(mesh, "crease_angles")
    m = np.asarray(marked)
    if m.dtype == bool:
        if m.shape != (mesh.n_vertices,):
            raise ValueError(f"marked must have one entry per vertex ({mesh.n_vertices})")
    else:
        idx = m.astype(np.int64).reshape(-1)
        if idx.size and (idx.min() < 0 or idx.max() >= mesh.n_vertices):
            raise ValueError(f"marked vertex out of range 0..{mesh.n_vertices - 1}")
        m = np.zeros(mesh.n_vertices, dtype=bool)
        m[idx] = True
    ends = mesh.edges
    at = m[ends[:, 0]] | m[ends[:, 1]]
    a = normal_angles(mesh) if angles is None else np.asarray(angles, dtype=float)
    return {
        "at": float(a[at].max()) if at.any() else float("nan"),
        "elsewhere": float(a[~at].max()) if (~at).any() else float("nan"),
    }


# ====================================================================== lateral artifact
#: The 12 edges of the box ``[-1, 1]^3``: ``(axis, s1, s2)``, the edge runs along
#: ``axis`` where the two other coordinates (in increasing order) are ``s1`` and ``s2``.
BOX_EDGES: tuple[tuple[int, int, int], ...] = tuple(
    (axis, s1, s2) for axis in range(3) for s1 in (1, -1) for s2 in (1, -1)
)


def _near_segments(mesh: Mesh, half: float) -> list[tuple[np.ndarray, ...]]:
    """For every edge of :data:`BOX_EDGES`, the segments of the surface
    :func:`ray_distances` sees (every face fanned from its centroid: the faces'
    sides and the spokes centroid -> corner) of the faces that reach near it.

    Returns
    -------
    list of 6-tuples of (s,) float
        One per box edge: ``(xa, ua, wa, xb, ub, wb)``, the two ends of every
        segment in coordinates turned to (along the edge, towards its first
        face, towards its second face).
    """
    v = mesh.vertices
    tail, head, hf = mesh.corners, mesh.head, mesh.halfedge_face
    offsets = mesh.offsets
    starts = offsets[:-1]
    # per half-edge: its tail, its head, its face's centroid; one column each
    cols = [np.ascontiguousarray(v[tail, k]) for k in range(3)]
    cols += [np.ascontiguousarray(v[head, k]) for k in range(3)]
    cols += [np.ascontiguousarray(mesh.face_centroids[hf, k]) for k in range(3)]
    lim = 0.6 * half
    # which faces reach past +-lim along x, y, z
    reach = {}
    for k in range(3):
        reach[k, 1] = np.maximum.reduceat(cols[k], starts) > lim
        reach[k, -1] = np.minimum.reduceat(cols[k], starts) < -lim
    out = []
    for axis, s1, s2 in BOX_EDGES:
        i, j = (k for k in range(3) if k != axis)
        faces = np.flatnonzero(reach[i, s1] & reach[j, s2])
        sizes = offsets[faces + 1] - offsets[faces]
        # the half-edges of those faces: offsets[f] .. offsets[f + 1] - 1, in a row
        first = np.repeat(offsets[faces] - np.cumsum(sizes) + sizes, sizes)
        hs = first + np.arange(int(sizes.sum()))
        ends = []
        for k, sign in ((axis, 1), (i, s1), (j, s2)):  # sides tail -> head, spokes centroid -> tail
            ends.append(sign * np.concatenate([cols[k][hs], cols[6 + k][hs]]))
        for k, sign in ((axis, 1), (i, s1), (j, s2)):
            ends.append(sign * np.concatenate([cols[3 + k][hs], cols[k][hs]]))
        out.append(tuple(ends))
    return out


def _profile(near: tuple[np.ndarray, ...], angle: float) -> tuple[np.ndarray, np.ndarray]:
    """(x, r) where the segments ``near`` (from :func:`_near_segments`) cross the
    half-plane at ``angle`` degrees from the edge's first face."""
    xa, ua, wa, xb, ub, wb = near
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    da, db = c * wa - s * ua, c * wb - s * ub  # signed distances from the plane
    cross = np.flatnonzero((da > 0) != (db > 0))
    da, db = da[cross], db[cross]
    t = da / (da - db)
    x = xa[cross] + t * (xb[cross] - xa[cross])
    ra = c * ua[cross] + s * wa[cross]
    r = ra + t * (c * ub[cross] + s * wb[cross] - ra)
    keep = r > 0
    order = np.argsort(x[keep], kind="stable")
    return x[keep][order], r[keep][order]


def edge_profile(
    mesh: Mesh,
    edge: tuple[int, int, int] = (0, 1, 1),
    angle: float = 45.0,
    half: float = 1.0,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The distance of a smoothed box's surface from an edge's axis, along the edge.

    The half-plane that holds the axis of the box ``[-half, half]^3``
    parallel to ``edge`` and makes the angle ``angle`` with the first of the
    edge's faces (45 degrees: the plane through the edge itself) cuts the
    surface in a curve; this is that curve, as the points where it crosses
    the surface's edges, ``(x, r)``: position along the edge and distance
    from the axis.  The surface is the one :func:`ray_distances` sees (every
    face fanned from its centroid), so ``r`` at ``x`` is the distance a ray
    from the axis would measure.  Along a straight edge without a wave
    (Section 1's "lateral artifact"), ``r`` is constant away from the
    corners.

    Parameters
    ----------
    mesh : Mesh
        A smoothed box, centred at the origin, with its edges along the axes.
    edge : (axis, s1, s2)
        One of :data:`BOX_EDGES`.
    angle : float
        Degrees, from 35 to 55 (the plane must cut the surface within
        0.6 ``half`` of the edge on both sides).
    half : float
        Half the box's size.

    Returns
    -------
    x, r : (k,) float
        Sorted by ``x``; the curve is straight between its points.  At the
        ends (``|x|`` near ``half``) the plane also cuts the box's end faces;
        :func:`lateral_amplitude` measures away from them.
    """
    check_mesh(mesh, "edge_profile")
    if not 35.0 <= angle <= 55.0:
        raise ValueError(f"angle must be from 35 to 55 degrees, got {angle}")
    if tuple(edge) not in BOX_EDGES:
        raise ValueError(f"edge must be one of BOX_EDGES, got {edge!r}")
    return _profile(_near_segments(mesh, half)[BOX_EDGES.index(tuple(edge))], angle)


def lateral_amplitude(
    mesh: Mesh,
    window: float,
    angles: Sequence[float] = (40.0, 45.0, 50.0),
    half: float = 1.0,
) -> NDArray[np.float64]:
    """The wave along every straight edge of a smoothed box (Section 1's "lateral artifact").

    For each of the box's 12 edges and each angle, the peak-to-peak
    variation of :func:`edge_profile` over ``|x| <= window`` (away from the
    box's corners, whose rounding is not a wave); the largest over the
    angles.  The default angles cut the rounded edge through its middle
    (45 degrees) and on either side of it, where a wave that sways sideways
    shows too.  A box whose edges stay straight gives 0; a wave pattern along
    the edge gives its peak-to-peak height, in the mesh's units.

    Parameters
    ----------
    mesh : Mesh
        A smoothed box ``[-half, half]^3`` (centred, edges along the axes).
    window : float
        Half the length of the stretch measured, in the mesh's units
        (``0 < window < half``).
    angles : sequence of float
        Degrees (see :func:`edge_profile`).
    half : float

    Returns
    -------
    (12,) float
        One value per edge of :data:`BOX_EDGES`.
    """
    check_mesh(mesh, "lateral_amplitude")
    if not 0.0 < window < half:
        raise ValueError(f"window must be in (0, {half}), got {window}")
    for angle in angles:
        if not 35.0 <= angle <= 55.0:
            raise ValueError(f"angles must be from 35 to 55 degrees, got {angle}")
    out = np.zeros(len(BOX_EDGES))
    for k, (edge, near) in enumerate(zip(BOX_EDGES, _near_segments(mesh, half))):
        for angle in angles:
            x, r = _profile(near, angle)
            r = r[np.abs(x) <= window]
            if r.size < 2:
                raise ValueError(
                    f"the surface does not cross edge {edge}'s {angle}-degree plane "
                    f"within |x| <= {window}: not a box [-{half}, {half}]^3?"
                )
            out[k] = max(out[k], float(np.ptp(r)))
    return out
